// The number text of messages and pages: "%.3f", 3 decimals (a micron on a
// length). One formatter instead of a copy per file.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <string>

namespace pupitre {

// "%.3f" of v, cut at `max_chars` as the fixed buffers of the copies it replaces
// cut huge values (|v| above 1e27): 31 characters, 47 in the drawings' legends,
// 63 in the spindle messages. Those texts stay byte-identical.
std::string fixed3(double v, size_t max_chars = 31);

// The same with |v| under `zero` shown as 0.000, never as "-0.000".
std::string fixed3_zeroed(double v, double zero, size_t max_chars = 31);

// A time as H:MM:SS, the seconds cut (as `run`, the drawings and the GRAPH
// page give a cycle time); negative or NaN as 0. The hours are a double: a
// profile's absurd limits (an acceleration of 1e-300) make times no integer
// holds, which are printed as they are.
std::string clock_text(double seconds);

}  // namespace pupitre
