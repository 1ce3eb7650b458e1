// The speed profile of one move (profile.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/plan/profile.hpp"

#include <algorithm>
#include <cmath>

namespace pupitre::plan {

// With a jerk J, a change dv that reaches the acceleration a takes dv/a + a/J
// (a rises in a/J, holds, falls in a/J); a smaller one never reaches a and
// takes 2 sqrt(dv/J).
double ramp_time(double dv, const Limits& l) {
    if (dv <= 0 || l.accel <= 0) return 0;
    if (l.jerk <= 0) return dv / l.accel;
    const double a = l.accel, j = l.jerk;
    return dv >= a * a / j ? dv / a + a / j : 2 * std::sqrt(dv / j);
}

double ramp_length(double va, double vb, const Limits& l) {
    return (va + vb) / 2 * ramp_time(std::fabs(vb - va), l);
}

double reach_jerk(double v, double length, const Limits& l) {
    // The S-curve's length grows with the end speed: halve the interval
    // between the trapezoid's answer (an upper bound) and v.
    double lo = v, hi = std::sqrt(v * v + 2 * l.accel * length);
    for (int i = 0; i < 60 && hi - lo > 1e-9 * hi; ++i) {
        const double mid = (lo + hi) / 2;
        (ramp_length(v, mid, l) <= length ? lo : hi) = mid;
    }
    return lo;
}

namespace {
// The length of up from v0 to vp and down to v1.
double up_down(double v0, double vp, double v1, const Limits& l) {
    return ramp_length(v0, vp, l) + ramp_length(vp, v1, l);
}
}  // namespace

// Without a jerk, the trapezoid's closed form; with one, the peak that fits
// the length is searched.
Timing timing(double length, double v0, double v1, double vmax, const Limits& l) {
    if (length <= 0) return {0, std::max(v0, v1)};
    if (l.accel <= 0) return {length / vmax, vmax};
    const double low = std::max(v0, v1);
    if (l.jerk <= 0) {
        const double half = 0.5 / l.accel;
        const double up = (vmax * vmax - v0 * v0) * half, down = (vmax * vmax - v1 * v1) * half;
        if (up + down <= length)
            return {(2 * vmax - v0 - v1) / l.accel + (length - up - down) / vmax, vmax};
        // A triangle: (vp² - v0²) / 2a + (vp² - v1²) / 2a = length.
        const double vp =
            std::clamp(std::sqrt((2 * l.accel * length + v0 * v0 + v1 * v1) / 2), low, vmax);
        return {(2 * vp - v0 - v1) / l.accel, vp};
    }
    const double full = up_down(v0, vmax, v1, l);
    if (full <= length)
        return {ramp_time(vmax - v0, l) + ramp_time(vmax - v1, l) + (length - full) / vmax, vmax};
    double lo = low, hi = vmax;
    if (up_down(v0, lo, v1, l) > length)  // the ends are too far apart for the jerk
        return {2 * length / (v0 + v1), low};
    for (int i = 0; i < 60 && hi - lo > 1e-9 * hi; ++i) {
        const double mid = (lo + hi) / 2;
        (up_down(v0, mid, v1, l) <= length ? lo : hi) = mid;
    }
    return {ramp_time(lo - v0, l) + ramp_time(lo - v1, l), lo};
}

}  // namespace pupitre::plan
