// The JSON that pupitre writes (the trace, the run summary, the workshop's
// report): fixed 4 decimals for lengths, degrees, seconds, feeds and speeds.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace pupitre {

// Appends v with exactly 4 decimals ("-0.0000" is written "0.0000").
void append_fixed4(std::string& out, double v);
// Appends a JSON string literal.
void append_json_string(std::string& out, std::string_view text);

}  // namespace pupitre
