// Internal to the PGP solver (pgp.cpp): the supporting geometry of elements,
// what one block fixes of its element, and the EB corners (pgp_elements.cpp).
// Plane geometry in (abscissa, ordinate), internal units.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/geometry/pgp.hpp"

namespace pupitre::pgp::detail {

constexpr double kEq = 1e-6;         // mm: equal points (pupitre-iso(5), DECISIONS, Arcs with R)
constexpr double kArcTol = 0.020;    // mm: start and end radii of an I J arc (004:626)
constexpr double kChordTol = 0.001;  // mm: a chord up to 2R + 1 µm is a half circle
constexpr double kOverTol = 0.001;   // mm: a tangency between two fully programmed elements

V2 dir(double deg);
V2 rot(const V2& v, double a);
// Angle travelled from u to v turning in sense s (+1 counter-clockwise), in [0, 2π).
double turn(const V2& u, const V2& v, int s);

// Supporting geometry: a line through p with unit travel direction d, or a
// circle about p of radius r travelled in sense s.
struct Sup {
    bool arc = false;
    V2 p{0, 0}, d{1, 0};
    double r = 0;
    int s = 0;
};

Sup line(const V2& p, const V2& d);
Sup circle(const V2& c, double r, int s);
// Travel direction of a support at one of its points.
V2 tangent(const Sup& e, const V2& q);
// Points common to two supports.
std::vector<V2> meet(const Sup& a, const Sup& b);
// Loci of the centre of a circle of radius r tangent to a support.
std::vector<Sup> loci(const Sup& e, double r);
// Where a support touches the circle of radius r about q tangent to it.
V2 contact(const Sup& e, const V2& q, double r);
// Radii of the circles about q tangent to a support.
std::vector<double> radii(const Sup& e, const V2& q);
// Points of a circle where a line through q touches it.
std::vector<V2> touch_from(const Sup& c, const V2& q);
// Common tangents travelled from circle a to circle b in the circles' senses.
struct Tangent {
    V2 t1, t2, d;
};
std::vector<Tangent> common(const Sup& a, const Sup& b);
// The point of a line through q of direction d at the given coordinate.
bool along(const V2& q, const V2& d, int axis, double val, V2& end);
// Part of a support from a to b, as an element.
comp::Elem piece(const Sup& s, const V2& a, const V2& b);
Sup support(const comp::Elem& g);
double length(const comp::Elem& g);

// What a block fixes of its element.
enum class Form {
    Complete,  // start known, end known: an element
    Fixed,     // support known (line through a point with its angle, circle)
    Angle,     // line of known angle, position unknown
    Axis,      // line parallel to an axis (one coordinate), position and sense unknown
    Free,      // line of unknown direction (ET, or an end point only)
    Centre,    // circle of known centre, radius unknown
    Radius,    // circle of known radius, centre unknown
};

struct Elt {
    Form form = Form::Fixed;
    int s = 0;             // arcs: +1 G3, -1 G2
    comp::Elem geo;        // Complete
    Sup sup;               // Fixed
    V2 d{1, 0};            // Angle: direction; Axis: the axis
    V2 c{0, 0};            // Centre
    double r = 0;          // Radius
    bool has_end = false;  // end point known
    V2 end{0, 0};
    int end_axis = -1;  // Angle, Axis: the one end coordinate given
    double end_val = 0;
};

// The first block of an entity: its start S is known. `over` is the support
// found while solving the previous entity. Answers why the block does not
// make an element (110, 101, 102, 107), empty when `e` is what it fixes.
Error first_elt(const Spec& s, const V2& S, const Sup* over, Elt& e);
// A block after an incomplete element (pos 1 or 2 in the entity): its start is
// not known yet. Answers as first_elt (111, 121 for 110).
Error next_elt(const Spec& s, int pos, Elt& e);

// Replaces the corner between h and e by a fillet (eb > 0) or a chamfer
// (eb < 0) `ins`, trimming both.
Error corner(comp::Elem& h, double eb, comp::Elem& e, comp::Elem& ins);

}  // namespace pupitre::pgp::detail
