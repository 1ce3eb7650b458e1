// A cutter tilted against the table (mill5's B head, mill4's B table): where
// a line crosses the cutter or the volume it sweeps, exactly for a flat or a
// ball end (a moving bull nose's torus is a ring of kRing balls at most:
// within 0.5 µm, or (pi / 256)² inner r / (2 c) for a small corner on a
// large cutter; standing still, exact), and the
// points of its surface that meet a box face first. Pure geometry for the
// material (mill_tilt.cpp): machine X, Y, Z in mm, the tool's axis `u` a
// unit vector from the tip towards the spindle.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <limits>
#include <vector>

#include "core/workshop/mill_part.hpp"

namespace pupitre::workshop::tilt {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
// The most balls a moving bull nose's corner is made of.
inline constexpr int kRing = 256;

// The line o + s e, e a unit vector.
struct Line {
    P3 o{}, e{0, 0, 1};
};

// The s where the line is in a body: an interval, empty when !(lo <= hi).
struct Span {
    double lo = kInf, hi = -kInf;
    bool empty() const { return !(lo <= hi); }
    void hull(const Span& o) {
        if (o.empty()) return;
        lo = std::min(lo, o.lo), hi = std::max(hi, o.hi);
    }
};

// The flat-ended cylinder of radius r about the axis u from the point a
// upwards without end, its end's centre going straight from a to a + d:
// where the line crosses the volume it sweeps (convex: one interval), in
// closed form. d = 0: the cylinder standing at a.
Span swept_flat(const P3& a, const P3& d, const P3& u, double r, const Line& l);
// The points within r of the segment from a to a + d.
Span capsule(const P3& a, const P3& d, double r, const Line& l);
// A cutter of `radius` with a `corner` radius, tip (the end's centre) going
// from a to a + d along the axis u, with everything above its end: the
// volume it sweeps, as the material counts a cut (the hull of the pieces:
// the flat of the end, the cylinder above the corner and the corner's balls;
// a corner of 2 µm or less is a flat end's).
Span swept_cutter(double radius, double corner, const P3& a, const P3& d, const P3& u,
                  const Line& l);
// `part` of the cutter standing with its tip at `tip` (the holder without
// end).
Span part_span(const Cutter& c, Part part, const P3& tip, const P3& u, const Line& l);
// How far a vertical line through (x, y) is inside the part's radius from
// its axis (negative: outside).
double inset(const PartSpan& s, const P3& tip, const P3& u, double x, double y);
// Where the part reaches: a box holding it, the holder cut off `top` mm
// above the tip.
Box3 part_box(const Cutter& c, Part part, const P3& tip, const P3& u, double top);
// Points of the part's surface, from its tip: rings along it with each
// ring's outermost points towards ±X, ±Y, ±Z (so that the first contact
// with a face square to an axis is exact), the end's face, the corner's
// outermost points. The holder ends `top` mm above the tip.
std::vector<P3> surface(const Cutter& c, Part part, const P3& u, double top);
// A frame square to u: e1, e2 with e1 x e2 = u.
void frame(const P3& u, P3& e1, P3& e2);

// Vector helpers.
inline P3 add(const P3& a, const P3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline P3 sub(const P3& a, const P3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline P3 mul(const P3& a, double k) {
    return {a[0] * k, a[1] * k, a[2] * k};
}
inline double dot(const P3& a, const P3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline P3 cross(const P3& a, const P3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace pupitre::workshop::tilt
