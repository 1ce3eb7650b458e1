// The wall clock, for what people read (a list's dates, the date on paper,
// the teacher's view) and what the store stamps (leases, attempts). The core
// never reads it: the Sim's clock is its own (ARCHITECTURE.md, Invariants).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>

namespace pupitre {

// Milliseconds since 1970.
int64_t wall_ms();
// `ms` in the local time zone, as strftime's `format` writes it.
std::string local_time(int64_t ms, const char* format);

}  // namespace pupitre
