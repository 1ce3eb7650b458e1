// The speed profile of one move along its path (issue 35): the three phases
// of the course notes, "accélération, déplacement à la vitesse constante
// programmée, décélération" (004:358), each change of speed a trapezoid's
// ramp, or an S-curve's where a jerk is given.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cmath>

namespace pupitre::plan {

// A limit of 0 is no limit: an acceleration of 0 changes speed at once, a
// jerk of 0 changes the acceleration at once. Speeds in mm/s, lengths in mm.
struct Limits {
    double accel = 0;
    double jerk = 0;
};

// The time to change speed by `dv` (>= 0).
double ramp_time(double dv, const Limits& l);
// The length a change of speed from `va` to `vb` takes (symmetric ramps: the
// mean speed is the middle one).
double ramp_length(double va, double vb, const Limits& l);
// The speed reachable from `v` over `length` (either way: accelerating, or
// the highest speed from which `v` is reached braking). Inline: the planner
// asks it for every move, mostly without a jerk.
double reach_jerk(double v, double length, const Limits& l);
inline double reach(double v, double length, const Limits& l) {
    if (l.accel <= 0) return HUGE_VAL;
    if (l.jerk <= 0) return std::sqrt(v * v + 2 * l.accel * length);
    return reach_jerk(v, length, l);
}

struct Timing {
    double seconds = 0;
    double peak = 0;  // the highest speed reached
};
// The fastest way over `length` from `v0` to `v1` without passing `vmax`:
// up to the highest speed the length allows, at it, and down again. The
// speeds given are reachable from each other (the planner sees to it).
Timing timing(double length, double v0, double v1, double vmax, const Limits& l);

}  // namespace pupitre::plan
