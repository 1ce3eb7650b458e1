// The "key = value" text files' small readers, shared by the machine
// profiles (interp/machine.cpp) and the workshop's setups (workshop/setup.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <charconv>
#include <cmath>
#include <string_view>

namespace pupitre::kv {

// Without the blanks around it (and a CR left by a DOS line end).
inline std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// The whole of `s` (blanks around it allowed) read as a decimal number, a
// finite one: from_chars also reads "inf" and "nan", which no key means.
inline bool number(std::string_view s, double& v) {
    s = trim(s);
    if (s.empty()) return false;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

// A number of a workshop's setup or of an exercise's: below 100 km in size
// (no workshop is larger).
inline bool workshop_number(std::string_view s, double& v) {
    return number(s, v) && std::abs(v) < 1e5;
}

// The next line of `text` that holds something, without its '#' comment and
// its blanks; `lineno` counts the lines read (1-based). False at the end.
inline bool next_line(std::string_view& text, std::string_view& line, int& lineno) {
    while (!text.empty()) {
        ++lineno;
        size_t eol = text.find('\n');
        line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        if (size_t hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        line = trim(line);
        if (!line.empty()) return true;
    }
    return false;
}

}  // namespace pupitre::kv
