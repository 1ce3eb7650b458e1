// A toolpath's arcs, point by point (toolpath.hpp): apart from the rest of
// the toolpath, as the plot module (plot_module.hpp) holds its own copy.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "core/geometry/geometry.hpp"
#include "core/output/toolpath.hpp"

namespace pupitre {

using ::pupitre::geometry::kPi;

void arc_radii(const Toolpath& path, size_t i, double& r0, double& r1) {
    const PathMove& mv = path[i];
    const PathArc& a = path.arcs()[mv.arc];
    const double* s = path.from(i);
    r0 = std::hypot(s[a.a0] - a.c0, s[a.a1] - a.c1);
    r1 = std::hypot(mv.p[a.a0] - a.c0, mv.p[a.a1] - a.c1);
}

void arc_point(const Toolpath& path, size_t i, double t, double out[3]) {
    const PathMove& mv = path[i];
    const double* s = path.from(i);
    if (t >= 1) {
        for (int k = 0; k < 3; ++k) out[k] = mv.p[k];
        return;
    }
    const PathArc& a = path.arcs()[mv.arc];
    double r0, r1;
    arc_radii(path, i, r0, r1);
    double ang = std::atan2(s[a.a1] - a.c1, s[a.a0] - a.c0) + double(a.sweep) * kPi / 180 * t;
    double r = r0 + (r1 - r0) * t;
    for (int k = 0; k < 3; ++k) out[k] = s[k] + (mv.p[k] - s[k]) * t;
    out[a.a0] = a.c0 + r * std::cos(ang);
    out[a.a1] = a.c1 + r * std::sin(ang);
}

}  // namespace pupitre
