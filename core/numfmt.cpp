// The "%.3f" number text of messages and pages (numfmt.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/numfmt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pupitre {

std::string fixed3(double v, size_t max_chars) {
    std::string s(max_chars + 1, '\0');
    int n = std::snprintf(s.data(), s.size(), "%.3f", v);
    s.resize(n < 0 ? 0 : std::min(size_t(n), max_chars));
    return s;
}

std::string fixed3_zeroed(double v, double zero, size_t max_chars) {
    return fixed3(std::fabs(v) < zero ? 0.0 : v, max_chars);
}

std::string clock_text(double seconds) {
    if (!(seconds >= 0)) seconds = 0;
    const double s = std::floor(seconds);
    char buf[400];  // 1e308 s is 305 digits of hours
    std::snprintf(buf, sizeof buf, "%.0f:%02d:%02d", std::floor(s / 3600),
                  int(std::fmod(s, 3600) / 60), int(std::fmod(s, 60)));
    return buf;
}

}  // namespace pupitre
