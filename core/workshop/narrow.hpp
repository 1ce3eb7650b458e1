// The parameter range of a linear motion within bounds: shared by the
// machining centre's material (mill_part.cpp, mill_part_measure.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <algorithm>

namespace pupitre::workshop {

// Narrows [t0, t1] to the t where lo <= p + t dp <= hi; false when empty.
inline bool narrow(double p, double dp, double lo, double hi, double& t0, double& t1) {
    if (dp == 0) return p >= lo && p <= hi && t0 <= t1;
    double a = (lo - p) / dp, b = (hi - p) / dp;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
    return t0 <= t1;
}

}  // namespace pupitre::workshop
