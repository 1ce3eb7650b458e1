// One-dimensional searches shared by the machining centre's material
// (mill_part.cpp, mill_part_measure.cpp, mill_tilt.cpp): the parameter range
// of a linear motion within bounds, the minimum of a convex function, the
// zero of a function that changes sign once.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>

namespace pupitre::workshop {

// A contact's precision in travel (mm): 0.01 µm, ten times the promise.
inline constexpr double kTravelTol = 1e-5;

// Narrows [t0, t1] to the t where lo <= p + t dp <= hi; false when empty.
inline bool narrow(double p, double dp, double lo, double hi, double& t0, double& t1) {
    if (dp == 0) return p >= lo && p <= hi && t0 <= t1;
    double a = (lo - p) / dp, b = (hi - p) / dp;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
    return t0 <= t1;
}

// The minimum of a convex f on [lo, hi], golden section down to `tol`:
// {where, value}.
template <class F>
inline std::pair<double, double> golden_min(F f, double lo, double hi, double tol) {
    const double lo0 = lo, hi0 = hi;
    constexpr double kGolden = 0.6180339887498949;
    double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    while (hi - lo > tol) {
        if (f1 <= f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - kGolden * (hi - lo), f1 = f(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + kGolden * (hi - lo), f2 = f(x2);
        }
    }
    std::pair<double, double> best{x1, f1};
    if (f2 < best.second) best = {x2, f2};
    // A minimum at an end: the bracket closes on it without evaluating it.
    for (double t : {lo0, hi0})
        if (double v = f(t); v < best.second) best = {t, v};
    return best;
}

// Where a function that is >= 0 at `in` and < 0 at `out` crosses zero
// (the side where it is >= 0), to `tol`.
template <class F>
inline double crossing(F f, double in, double out, double tol) {
    while (std::abs(out - in) > tol) {
        double mid = 0.5 * (in + out);
        (f(mid) >= 0 ? in : out) = mid;
    }
    return in;
}

// The first t from t0 to t1, in steps of `step`, where `deep(t)` holds,
// then halved back towards the last t where it does not (`clear`, where it
// does not either) to `tol` of travel along a move `len` long: that last
// clear t (`before`) or the first deep one; 2 when it never holds.
template <class F>
inline double march(F deep, double t0, double t1, double clear, double step, double len, double tol,
                    bool before) {
    for (double t = t0;; t = std::min(t + step, t1)) {
        if (deep(t)) {
            double d = t;
            while ((d - clear) * len > tol) {
                const double mid = 0.5 * (clear + d);
                (deep(mid) ? d : clear) = mid;
            }
            return before ? clear : d;
        }
        clear = t;
        if (t >= t1) break;
    }
    return 2;
}

}  // namespace pupitre::workshop
