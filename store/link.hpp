// The store as a run sees it: stored programs as program memory for G77 H, the
// stored correctors and origins of the machine seeded into the interpreter, and
// the program's writes to them (E50001-E55255, E6x000 PREF, E6x001 DEC1, E6x004
// DEC3) kept afterwards, as NUM keeps E parameters across programs
// (000:7590-7649; pupitre-iso(5), E parameters).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/interp/interp.hpp"
#include "store/store.hpp"

namespace pupitre::store {

// Adds the current text of every stored program to `mem`, named "store:%N". A
// number already in memory (from a file on the command line) is left to it.
// Returns how many programs were added.
Result<int> load_programs(Store& s, ProgramMemory& mem);

// Seeds the interpreter with the stored correctors and origins of its machine.
// Values for an axis or a field the machine does not have are skipped.
// Returns the values applied, by name.
// `key`: where the store keeps them ("": the machine's name; an exercise's
// attempt has its own).
Result<std::map<std::string, int64_t>> seed_machine(Store& s, Interpreter& in,
                                                    std::string_view key = "");

// The run's writes that persist, as store names and internal values, in E order.
std::vector<std::pair<std::string, int64_t>> persistent_writes(const Interpreter& in);

// Stores them in one transaction, one audit row per change, with `source` (e.g.
// "program %555 (tools.iso)").
Result<std::vector<Change>> persist_run(Store& s, const Interpreter& in, std::string_view source,
                                        std::string_view profile_text = "");

// The store's internal value of a setting given as --set names it: µm (lathe X
// radii, DX a diameter), 0.0001° for a rotary origin, the code for C.
int64_t internal_value(std::string_view name, double v);

// A value for people: "15.157" (mm), "180.1203" (degrees), "3" (C code).
std::string format_value(std::string_view name, int64_t internal);

}  // namespace pupitre::store
