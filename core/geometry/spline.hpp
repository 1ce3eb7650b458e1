// Spline curves G48/G06/G49 (000:4854-4888; pupitre-iso(5), SPLINES): a cubic spline
// through the programmed points, parametrised by chord length, with the start
// and end tangents when given (clamped) or free (natural) when their block is
// empty. Executed as short lines within a chord tolerance.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/diag.hpp"

namespace pupitre::spline {

struct Curve {
    std::vector<int> axes;                 // axis indexes used (from the first block)
    std::vector<std::vector<double>> pts;  // points, one value per axis
    std::vector<double> t0, t1;            // end tangents (direction), empty if free
    // Second derivatives per axis at each point (after build()).
    std::vector<std::vector<double>> m;
    std::vector<double> s;  // chord-length parameter of each point
};

// Checks and prepares the curve: errors 603, 604.
Error build(Curve& c);
// The point at parameter u (0 .. total chord length).
std::vector<double> at(const Curve& c, double u);
// Points along the curve (the first point excluded, the last included), close
// enough that no line leaves the curve by more than `tol` mm.
std::vector<std::vector<double>> sample(const Curve& c, double tol);

}  // namespace pupitre::spline
