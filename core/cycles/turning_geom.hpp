// Plane geometry shared by the turning cycles (internal to core/turning_*.cpp):
// intersections of lines and arcs, winding numbers of closed element loops,
// distances, and the coordinate frames in which every roughing cycle is one
// algorithm (passes along x, levels stepping down y, material above).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <limits>
#include <vector>

#include "core/geometry/comp.hpp"

namespace pupitre::turning::geom {

using comp::Elem;
using V2 = comp::V2;

constexpr double kTol = 1e-9;  // coincidence of points, mm
constexpr double kUm = 1e-6;   // 1 µm, the internal resolution of lengths
constexpr double kInf = std::numeric_limits<double>::infinity();

Elem line(const V2& a, const V2& b);
using comp::reversed;
Elem translated(const Elem& e, const V2& t);

// Angle travelled from the start of arc e to the direction of p about its centre,
// in the sense of the sweep, in [0, 2π).
double arc_offset(const Elem& e, const V2& p);
// p (assumed on the circle) lies on the arc, `tol` in mm along the arc.
bool on_arc(const Elem& e, const V2& p, double tol = kTol);

// Intersection points of two elements (on both, ends included). Collinear lines
// and concentric equal arcs that overlap give the ends of the overlap.
void intersect(const Elem& e, const Elem& f, std::vector<V2>& pts);
// The x of the points where the horizontal line y = Y meets e (both ends of a
// horizontal segment lying on it).
void cross_h(const Elem& e, double Y, std::vector<double>& xs);
// Smallest s >= 0 with p + s·u on e (u need not be unit), kInf if none.
double ray_hit(const Elem& e, const V2& p, const V2& u);

double dist(const Elem& e, const V2& p);
// Closest point of e to p, and the unit tangent of e there (direction a -> b).
V2 closest(const Elem& e, const V2& p, V2* tangent = nullptr);

double min_y(const Elem& e);
double max_y(const Elem& e);
// Lowest / highest y of e over the part of it with x in [x0, x1]; kInf / -kInf
// when e has no point there.
double min_y_in(const Elem& e, double x0, double x1);
double max_y_in(const Elem& e, double x0, double x1);
// The box of e widened by pad (an arc's is its circle's); two elements whose
// boxes widened by 1 µm are apart do not intersect: intersect's points lie
// within kTol of both, or a rounding of that.
struct Box {
    double x0, x1, y0, y1;
    bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};
Box box(const Elem& e, double pad);
double length(const Elem& e);
V2 midpoint(const Elem& e);
V2 point_at(const Elem& e, double t);  // the point at t in [0, 1] along e

// Closed loops of elements (each b is the next a).
int winding(const std::vector<Elem>& loop, const V2& q);
bool on_loop(const std::vector<Elem>& loop, const V2& q, double tol = kTol);
using comp::area;  // signed, counter-clockwise > 0
// Two non-adjacent elements cross or overlap, or adjacent ones fold back.
bool self_intersects(const std::vector<Elem>& loop);

// A change of coordinates (z, r) <-> (x, y): x along the passes, y the level
// axis, s = -1 mirrors y so that the material always lies above the part.
struct Frame {
    bool swap = false;  // x = r, y = s·z (passes along X); else x = z, y = s·r
    double s = 1;
    V2 to(const V2& p) const { return swap ? V2(p.y(), s * p.x()) : V2(p.x(), s * p.y()); }
    V2 back(const V2& q) const { return swap ? V2(s * q.y(), q.x()) : V2(q.x(), s * q.y()); }
    double det() const { return swap ? -s : s; }
    Elem to(const Elem& e) const;
    std::vector<Elem> to(const std::vector<Elem>& es) const;
};

}  // namespace pupitre::turning::geom
