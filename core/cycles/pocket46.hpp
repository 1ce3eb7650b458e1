// G46 pockets and facing with any contour (000:6078-6369; pupitre-iso(5), POCKETS): the geometric
// definition and the planning of its toolpaths — zig-zag roughing with a
// contour-parallel clean-up, finishing contours, plunge points. Pure plane
// geometry (first and second axis of the plane), no interpreter state.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/diag.hpp"
#include "core/geometry/comp.hpp"

namespace pupitre::p46 {

using V2 = comp::V2;
using comp::Elem;
using comp::Piece;

// One contour section: G46 NU1 (pocket), NU2 (island), NU3 (facing outline),
// NU4 (recess), NU5 (facing limit), NU6 (wall).
struct Section {
    int nu = 1;
    std::vector<Elem> elems;
    bool has_l = false;  // LX LY: the finishing start point
    V2 l{0, 0};
    int line = 0;  // where the section starts, for diagnostics
    long n = -1;
};

// A G46 definition, from NU0 to NU9.
struct Def {
    int np = 0;
    double ed = 0, q = 0, j = 0;
    int nr = 1;   // +1 climb (NR+), -1 conventional (NR-)
    int rot = 3;  // R03 / R04: the spindle sense the definition asks for
    bool has_l = false, has_e = false;
    V2 l{0, 0}, e{0, 0};
    int plane = 17;
    std::vector<Section> sections;
    bool facing() const;
    // +1 when the tool keeps the material on its right (climb with M03):
    // walls then lie on the right of the tool's travel.
    int sense() const { return nr * (rot == 4 ? -1 : 1); }
};

// Where the tool centre may go: inside the loops (even-odd), and at least
// `clear` from each wall element.
struct Bound {
    Elem e;
    double clear = 0;
};
struct Region {
    std::vector<std::vector<V2>> loops;
    std::vector<Bound> bounds;
    double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
};
using Spans = std::vector<std::pair<double, double>>;

// The region of tool-centre points for a tool of radius `clear` less its
// allowance: NU1/NU2/NU6 are walls, NU3/NU5 limits the centre may reach, NU4
// recesses are ignored (no material: the tool may cross them).
Region region(const Def& d, double clear);
bool inside(const Region& r, const V2& p, double tol = 1e-7);
// The intervals of the horizontal line at `y` inside the region.
Spans spans(const Region& r, double y);
double distance(const Elem& e, const V2& p);
// The smallest distance from p to a wall of the region, minus its clearance.
double margin(const Region& r, const V2& p);

// A stretch of toolpath: from `start`, the pieces; `linked` when it is reached
// from the end of the previous run by a move at feed inside the cleared region
// (otherwise: retract, rapid, plunge at `start`).
struct Run {
    V2 start{0, 0};
    std::vector<Piece> pieces;
    bool linked = false;
    bool cleanup = false;  // a clean-up contour of the roughing (after the passes)
};

// The errors below name the section they are about as their `item` (-1: the
// whole definition).

// Checks at NU9 (281, 283, 284, 285, 286, 287, 293).
Error check(const Def& d);
// Roughing at tool radius R leaving the allowance J of the definition:
// zig-zag passes at Q' <= Q, then the clean-up contours. `line_y` receives the
// ordinates of the passes.
Error roughing(const Def& d, double R, std::vector<Run>& runs, std::vector<double>& line_y);
// Finishing at tool radius R leaving J: each NU1/NU2 contour (at LX LY or its
// first point) and each NU6 wall, with engagement and release moves.
Error finishing(const Def& d, double R, double J, std::vector<Run>& runs);

// The closed or open offset of a chain of elements on `side` (comp::join).
bool offset_chain(const std::vector<Elem>& el, bool closed, double r, int side, V2& start,
                  std::vector<Piece>& out);
using comp::area;
using comp::reversed;

}  // namespace pupitre::p46
