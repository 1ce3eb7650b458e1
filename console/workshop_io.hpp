// The workshop's files: a setup read for `--setup` and `:setup`, the part
// written for `run --part-out` and `:part export` (pupitre-setup(5)).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

#include "console/refusal.hpp"
#include "core/plan/tools.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre {

// A shipped setup by name (lathe, mill) or a setup file, for the machine
// `m` (a lathe's setup on a lathe, a mill's on a machining centre). ""
// when read, else the message (the file and line named).
std::string read_setup(const std::string& name, const MachineProfile& m, workshop::Setup& s);

// Lathe: an SVG drawing (FILE.svg) or the (Z, R) outline as text ("-": the
// standard output). Machining centre: the height field as a 16-bit PNG
// (FILE.png, required) and the JSON that says how to read it beside it
// (FILE.json). Answers 0, or an exit status (64 a name the kind cannot
// take, 73 a file that cannot be created, 74 a write error) with the
// message in `why`.
Answer<int> write_part(const std::string& path, const workshop::Workshop& w,
                       const std::string& title);
// What is wrong with `path` (and the view named, "" for none) for the part
// of setup `s` ("" when nothing is or when there is no path): a machining
// centre's part needs a FILE.png or a FILE.pdf; a view is drawn as a
// picture (FILE.png or FILE.pdf) and must be one of the machine's.
std::string part_name_problem(const std::string& path, const std::string& view,
                              const workshop::Setup& s);

// The life of each tool's edge: the setup's (tool.N.life), then what the
// command line gives (--edge-life), which wins: its MINUTES for every tool
// replaces the setup's, its TN=MINUTES that one tool's (pupitre(1)).
plan::EdgeLife edge_life(const workshop::Setup& s, const plan::EdgeLife& given);

}  // namespace pupitre
