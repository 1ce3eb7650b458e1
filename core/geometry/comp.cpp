// Tool radius compensation geometry. Offsets of lines and arcs, intersections at
// inside corners (trimmed), connecting circles about the programmed corner at
// outside corners (S4 L757), error 149 when the tool does not fit (000:13293).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/comp.hpp"

#include <cmath>
#include <cstring>
#include <numbers>

#include "core/geometry/geometry.hpp"

namespace pupitre::comp {

double area(const std::vector<Elem>& loop) {
    using geometry::cross;
    double a = 0;
    for (const Elem& e : loop) {
        if (e.arc) {
            double r = e.r();
            a += 0.5 * (cross(e.c, e.b - e.a) + r * r * e.sweep);
        } else {
            a += 0.5 * cross(e.a, e.b);
        }
    }
    return a;
}

namespace {
using ::pupitre::geometry::kPi;
constexpr double kEps = 1e-7;

using ::pupitre::geometry::cross;
using ::pupitre::geometry::perp;
double sgn(double v) {
    return v < 0 ? -1.0 : 1.0;
}

// The angles about an offset arc's centre that one join asks more than once
// (within() and piece() of an element share its start and `from`), each
// worked out once (issue 14: atan2 was a tenth of a compensated run). Keyed
// by the vector's bits: the same vector gives the same angle, and +0 and -0
// (whose atan2 differ) are two keys.
class Angles {
  public:
    double of(const V2& v) {
        for (int i = 0; i < n_; ++i)
            if (std::memcmp(&key_[i], v.data(), sizeof key_[i]) == 0) return val_[i];
        const double a = std::atan2(v.y(), v.x());
        if (n_ < kSize) {
            std::memcpy(&key_[n_], v.data(), sizeof key_[n_]);
            val_[n_++] = a;
        }
        return a;
    }

  private:
    static constexpr int kSize = 8;
    double key_[kSize][2];
    double val_[kSize];
    int n_ = 0;
};

// Angle travelled from u to v about the origin, turning in direction s (+1 ccw,
// -1 cw), in [0, 2π).
double turn(const V2& u, const V2& v, double s, Angles& angles) {
    double d = s * (angles.of(v) - angles.of(u));
    d = std::fmod(d, 2 * kPi);
    if (d < 0) d += 2 * kPi;
    if (d > 2 * kPi - 1e-12) d = 0;
    return d;
}

// Intersections of the supporting line or circle of two offset elements.
int intersect(const Elem& e, const Elem& f, V2 out[2]) {
    if (!e.arc && !f.arc) {
        V2 d1 = e.b - e.a, d2 = f.b - f.a;
        double den = cross(d1, d2);
        if (std::fabs(den) < 1e-12 * d1.norm() * d2.norm()) return 0;
        double t = cross(f.a - e.a, d2) / den;
        out[0] = e.a + t * d1;
        return 1;
    }
    if (e.arc != f.arc) {
        const Elem& l = e.arc ? f : e;
        const Elem& c = e.arc ? e : f;
        V2 d = (l.b - l.a).normalized();
        V2 w = l.a - c.c;
        double b = w.dot(d), cc = w.squaredNorm() - c.r() * c.r();
        double disc = b * b - cc;
        if (disc < -1e-9) return 0;
        double s = std::sqrt(std::max(0.0, disc));
        out[0] = l.a + (-b - s) * d;
        out[1] = l.a + (-b + s) * d;
        return s < 1e-12 ? 1 : 2;
    }
    V2 d = f.c - e.c;
    double dist = d.norm(), r1 = e.r(), r2 = f.r();
    if (dist < 1e-12) return 0;
    double a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist);
    double h2 = r1 * r1 - a * a;
    if (h2 < -1e-9) return 0;
    double h = std::sqrt(std::max(0.0, h2));
    V2 m = e.c + a * d / dist;
    out[0] = m + h * perp(d) / dist;
    out[1] = m - h * perp(d) / dist;
    return h < 1e-12 ? 1 : 2;
}

// Appends the part of offset element `o` from `from` to `to`.
void piece(const Elem& o, const V2& from, const V2& to, std::vector<Piece>& path, Angles& angles) {
    Piece p;
    p.to = to;
    if (o.arc) {
        double s = sgn(o.sweep);
        // turn() (two atan2) only where its angle is used.
        double skip_start = (from - o.a).norm() < kEps ? 0 : turn(o.a - o.c, from - o.c, s, angles);
        double cut_end = (to - o.b).norm() < kEps ? 0 : turn(to - o.c, o.b - o.c, s, angles);
        p.arc = true;
        p.c = o.c;
        p.sweep = s * std::max(0.0, std::fabs(o.sweep) - skip_start - cut_end);
        if (std::fabs(p.sweep) < 1e-12 && (to - from).norm() < kEps) return;
    } else if ((to - from).norm() < kEps) {
        return;
    }
    path.push_back(p);
}

// Is x on offset element o, after `from` and no further than its end?
bool within(const Elem& o, const V2& from, const V2& x, Angles& angles) {
    if (!o.arc) {
        V2 d = o.b - o.a;
        double len = d.norm();
        if (len < kEps) return (x - o.a).norm() < 1e-6;
        d /= len;
        double tf = (from - o.a).dot(d), tx = (x - o.a).dot(d);
        return tx >= tf - 1e-6 && tx <= len + 1e-6;
    }
    double s = sgn(o.sweep);
    double total = std::fabs(o.sweep);
    double af = (from - o.a).norm() < kEps ? 0 : turn(o.a - o.c, from - o.c, s, angles);
    double ax = (x - o.a).norm() < kEps ? 0 : turn(o.a - o.c, x - o.c, s, angles);
    double tol = 1e-6 / std::max(o.r(), 1e-9);
    return ax >= af - tol && ax <= total + tol;
}
}  // namespace

V2 start_tangent(const Elem& e) {
    if (!e.arc) return (e.b - e.a).normalized();
    return sgn(e.sweep) * perp(e.a - e.c).normalized();
}

V2 end_tangent(const Elem& e) {
    if (!e.arc) return (e.b - e.a).normalized();
    return sgn(e.sweep) * perp(e.b - e.c).normalized();
}

V2 normal(const V2& t, int side) {
    return double(side) * perp(t);
}

bool offset(const Elem& e, double radius, int side, Elem& out) {
    out = e;
    if (!e.arc) {
        V2 n = normal(start_tangent(e), side);
        out.a = e.a + radius * n;
        out.b = e.b + radius * n;
        return true;
    }
    double r = e.r();
    // The left normal of a counter-clockwise arc points to its centre.
    double r2 = r - double(side) * sgn(e.sweep) * radius;
    if (r2 <= 1e-9) return false;
    out.a = e.c + (e.a - e.c) * (r2 / r);
    out.b = e.c + (e.b - e.c) * (r2 / r);
    return true;
}

int join(const Elem& p, const V2& from, const Elem& next, double radius, int side,
         std::vector<Piece>& path, V2& next_from) {
    Angles angles;
    Elem po, no;
    if (!offset(p, radius, side, po) || !offset(next, radius, side, no)) return 149;
    V2 corner = p.b;
    V2 t1 = end_tangent(p), t2 = start_tangent(next);
    double cr = cross(t1, t2), dt = t1.dot(t2);
    if ((po.b - no.a).norm() < 1e-9) {  // tangent: the offsets meet
        if (!within(po, from, po.b, angles)) return 149;
        piece(po, from, po.b, path, angles);
        next_from = no.a;
        return 0;
    }
    bool outside = double(side) * cr < -1e-12 || (std::fabs(cr) <= 1e-12 && dt < 0);
    if (outside) {
        if (!within(po, from, po.b, angles)) return 149;
        piece(po, from, po.b, path, angles);
        Piece arc;
        arc.arc = true;
        arc.connecting = true;
        arc.to = no.a;
        arc.c = corner;
        double ang = std::fabs(
            std::atan2(cross(po.b - corner, no.a - corner), (po.b - corner).dot(no.a - corner)));
        if (std::fabs(cr) <= 1e-12 && dt < 0) ang = kPi;
        arc.sweep = -double(side) * ang;
        path.push_back(arc);
        next_from = no.a;
        return 0;
    }
    // Inside corner: both offsets are trimmed to their intersection nearest the corner.
    V2 pts[2];
    int n = intersect(po, no, pts);
    if (n == 0) return 149;
    V2 x = pts[0];
    if (n == 2 && (pts[1] - corner).norm() < (pts[0] - corner).norm()) x = pts[1];
    if (!within(po, from, x, angles) || !within(no, no.a, x, angles)) return 149;
    piece(po, from, x, path, angles);
    next_from = x;
    return 0;
}

int finish(const Elem& p, const V2& from, double radius, int side, std::vector<Piece>& path) {
    Angles angles;
    Elem po;
    if (!offset(p, radius, side, po)) return 149;
    if (!within(po, from, po.b, angles)) return 149;
    piece(po, from, po.b, path, angles);
    return 0;
}

}  // namespace pupitre::comp
