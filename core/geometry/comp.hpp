// Tool radius compensation geometry (G41/G42): offset elements, the joints
// between consecutive offset elements, and the checks that raise error 149
// (000:3889-3938; pupitre-iso(5), TOOLS AND CORRECTORS, 004:756-758). Pure 2-D geometry in the
// plane of the compensation, with Eigen.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <Eigen/Core>
#include <utility>
#include <vector>

namespace pupitre::comp {

using V2 = Eigen::Vector2d;

// A programmed element in the plane: a line a->b, or an arc a->b about c.
struct Elem {
    bool arc = false;
    V2 a{0, 0}, b{0, 0};
    V2 c{0, 0};
    double sweep = 0;  // radians, signed (positive counter-clockwise); arcs only
    double r() const { return (a - c).norm(); }
};

// The element travelled the other way.
inline Elem reversed(const Elem& e) {
    Elem r = e;
    std::swap(r.a, r.b);
    r.sweep = -e.sweep;
    return r;
}
// Signed area of a closed loop of elements (each b the next a), exact on arcs:
// counter-clockwise > 0.
double area(const std::vector<Elem>& loop);

// A piece of the tool-centre path: to `to`, straight or about `c`.
struct Piece {
    bool arc = false;
    V2 to{0, 0};
    V2 c{0, 0};
    double sweep = 0;
    bool connecting = false;  // a circle the system inserted at an outside corner
};

V2 start_tangent(const Elem& e);
V2 end_tangent(const Elem& e);
// Unit normal on the compensation side (side +1: left, G41; -1: right, G42).
V2 normal(const V2& tangent, int side);

// The element offset by `radius` on `side`. Returns false when it vanishes (an
// arc whose radius is smaller than the tool's on its inside: error 149).
bool offset(const Elem& e, double radius, int side, Elem& out);

// Joins the offset of `p` (already started at `from`) with the offset of `next`
// at their common programmed point. Appends to `path` the end of p's offset and
// the connecting circle if any; returns the start point of next's offset
// (through `next_from`). Returns 0 or the NUM error number (149).
int join(const Elem& p, const V2& from, const Elem& next, double radius, int side,
         std::vector<Piece>& path, V2& next_from);

// Ends p's offset on the normal at its end point (before a G40 exit or a move
// out of the plane). Returns 0 or 149.
int finish(const Elem& p, const V2& from, double radius, int side, std::vector<Piece>& path);

}  // namespace pupitre::comp
