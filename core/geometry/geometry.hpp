// One set of plane-geometry primitives for the whole core (issue 13.3):
// compensation, PGP, pockets, turning cycles, the simulator and the drawings
// share these instead of their own copies. Vectors are Eigen's.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace pupitre::geometry {

using V2 = Eigen::Vector2d;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = std::numbers::pi / 180;  // radians in a degree

// The z of the 3-D cross product: > 0 when b turns left of a.
inline double cross(const V2& a, const V2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// A quarter turn to the left (counter-clockwise).
inline V2 perp(const V2& v) {
    return V2(-v.y(), v.x());
}

// The lathe tool's nose orientation C0-C8 (a table pupitre chose, the handbook's
// figures being lost: pupitre-iso(5), TOOLS AND CORRECTORS): the tool point P =
// nose centre + R·(sx, sz), {sx, sz} here; C0 puts P at the centre. The
// interpreter's compensation and the workshop's true tools read the same table.
inline constexpr int kNose[9][2] = {{0, 0}, {1, 1}, {1, -1}, {-1, -1}, {-1, 1},
                                    {0, 1}, {1, 0}, {0, -1}, {-1, 0}};

// Rounded up to the micrometre, a micrometre's millionth forgiven (pass counts
// of cycles: 3.0000000001 passes are 3).
inline double ceil_um(double v) {
    return std::ceil(v * 1000 - 1e-6) / 1000;
}

}  // namespace pupitre::geometry
