// PGP elements (000:8358-8564; pupitre-iso(5), PROFILE GEOMETRY PROGRAMMING
// (PGP)): the supporting geometry, what one block fixes of its element (its
// syntax, its end, its centre or its radius), and the fillets and chamfers EB
// cuts into a corner. The solver is pgp.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/pgp_elements.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/numfmt.hpp"

namespace pupitre::pgp::detail {

using ::pupitre::geometry::cross;
using ::pupitre::geometry::kPi;
using ::pupitre::geometry::perp;

V2 dir(double deg) {
    double a = deg * kPi / 180;
    return V2(std::cos(a), std::sin(a));
}
V2 rot(const V2& v, double a) {
    return V2(v.x() * std::cos(a) - v.y() * std::sin(a), v.x() * std::sin(a) + v.y() * std::cos(a));
}

// Angle travelled from u to v turning in sense s (+1 counter-clockwise), in [0, 2π).
double turn(const V2& u, const V2& v, int s) {
    double a = s * std::atan2(cross(u, v), u.dot(v));
    if (a < 0) a += 2 * kPi;
    if (a > 2 * kPi - 1e-10) a = 0;
    return a;
}

Sup line(const V2& p, const V2& d) {
    Sup l;
    l.p = p;
    l.d = d;
    return l;
}
Sup circle(const V2& c, double r, int s) {
    Sup k;
    k.arc = true;
    k.p = c;
    k.r = r;
    k.s = s;
    return k;
}

// Travel direction of a support at one of its points.
V2 tangent(const Sup& e, const V2& q) {
    return e.arc ? V2(double(e.s) * perp(q - e.p).normalized()) : e.d;
}

// Points common to two supports.
std::vector<V2> meet(const Sup& a, const Sup& b) {
    std::vector<V2> out;
    if (!a.arc && !b.arc) {
        double den = cross(a.d, b.d);
        if (std::fabs(den) < 1e-12) return out;
        out.push_back(a.p + cross(b.p - a.p, b.d) / den * a.d);
        return out;
    }
    if (a.arc != b.arc) {
        const Sup& l = a.arc ? b : a;
        const Sup& c = a.arc ? a : b;
        V2 w = l.p - c.p;
        double k = w.dot(l.d), disc = k * k - (w.squaredNorm() - c.r * c.r);
        if (disc < -1e-9 * std::max(1.0, c.r * c.r)) return out;
        double h = std::sqrt(std::max(0.0, disc));
        out.push_back(l.p + (-k - h) * l.d);
        if (h > 1e-7) out.push_back(l.p + (-k + h) * l.d);
        return out;
    }
    V2 w = b.p - a.p;
    double dist = w.norm();
    if (dist < 1e-12) return out;
    double x = (a.r * a.r - b.r * b.r + dist * dist) / (2 * dist), h2 = a.r * a.r - x * x;
    if (h2 < -1e-9 * std::max(1.0, a.r * a.r)) return out;
    double h = std::sqrt(std::max(0.0, h2));
    V2 m = a.p + x / dist * w, n = perp(w) / dist;
    out.push_back(m + h * n);
    if (h > 1e-7) out.push_back(m - h * n);
    return out;
}

// Loci of the centre of a circle of radius r tangent to a support.
std::vector<Sup> loci(const Sup& e, double r) {
    if (!e.arc) return {line(e.p + r * perp(e.d), e.d), line(e.p - r * perp(e.d), e.d)};
    std::vector<Sup> out{circle(e.p, e.r + r, 0)};
    if (std::fabs(e.r - r) > kEq) out.push_back(circle(e.p, std::fabs(e.r - r), 0));
    return out;
}

// Where a support touches the circle of radius r about q tangent to it.
V2 contact(const Sup& e, const V2& q, double r) {
    if (!e.arc) return e.p + (q - e.p).dot(e.d) * e.d;
    V2 u = (q - e.p).normalized();
    V2 a = e.p + e.r * u, b = e.p - e.r * u;
    return std::fabs((a - q).norm() - r) <= std::fabs((b - q).norm() - r) ? a : b;
}

// Radii of the circles about q tangent to a support.
std::vector<double> radii(const Sup& e, const V2& q) {
    if (!e.arc) {
        double d = std::fabs(cross(e.d, q - e.p));
        if (d > kEq) return {d};
        return {};
    }
    double dist = (q - e.p).norm();
    if (dist < kEq) return {};
    std::vector<double> out{dist + e.r};
    if (std::fabs(dist - e.r) > kEq) out.push_back(std::fabs(dist - e.r));
    return out;
}

// Points of a circle where a line through q touches it.
std::vector<V2> touch_from(const Sup& c, const V2& q) {
    V2 w = q - c.p;
    double dist = w.norm();
    if (dist < c.r - kEq) return {};
    if (dist <= c.r + kEq) return {q};
    double a = std::acos(c.r / dist);
    return {c.p + c.r * rot(w / dist, a), c.p + c.r * rot(w / dist, -a)};
}

// Common tangents travelled from circle a to circle b in the circles' senses:
// a line of direction d touches a circle at p - s r perp(d) (no cusp), both on
// one line when cross(d, b.p - a.p) = b.s b.r - a.s a.r.
std::vector<Tangent> common(const Sup& a, const Sup& b) {
    V2 w = b.p - a.p;
    double dist = w.norm(), k = b.s * b.r - a.s * a.r;
    if (dist < kEq || std::fabs(k) > dist + kEq) return {};
    double phi = std::asin(std::clamp(k / dist, -1.0, 1.0));
    std::vector<Tangent> out;
    for (double f : {phi, kPi - phi}) {
        V2 d = rot(w / dist, -f);
        out.push_back({a.p - a.s * a.r * perp(d), b.p - b.s * b.r * perp(d), d});
    }
    return out;
}

// The point of a line through q of direction d at the given coordinate.
bool along(const V2& q, const V2& d, int axis, double val, V2& end) {
    if (std::fabs(d[axis]) < 1e-12) return false;
    end = q + (val - q[axis]) / d[axis] * d;
    end[axis] = val;
    return true;
}

// Part of a support from a to b, as an element.
comp::Elem piece(const Sup& s, const V2& a, const V2& b) {
    comp::Elem g;
    g.a = a;
    g.b = b;
    if (s.arc) {
        double sw = turn(a - s.p, b - s.p, s.s);
        if (sw > 0) {
            g.arc = true;
            g.c = s.p;
            g.sweep = s.s * sw;
        }
    }
    return g;
}

Sup support(const comp::Elem& g) {
    if (!g.arc) return line(g.a, (g.b - g.a).normalized());
    return circle(g.c, (g.a - g.c).norm(), g.sweep < 0 ? -1 : 1);
}

double length(const comp::Elem& g) {
    return g.arc ? std::fabs(g.sweep) * (g.a - g.c).norm() : (g.b - g.a).norm();
}

// ---------------------------------------------------------------------------
// What a block fixes of its element.

namespace {

int syntax_code(int pos) {
    return pos == 0 ? 110 : pos == 1 ? 111 : 121;
}

// Words that do not belong together, wherever the block stands in its entity.
Error syntax(const Spec& s, int pos) {
    if (s.link != 0 && s.link != 'S' && s.link != 'T')
        return Error{syntax_code(pos), tr("ES and ET in the same block")};
    if (s.g == 1 && (s.has_i || s.has_j || s.has_r))
        return Error{syntax_code(pos), tr("a line takes no centre I J nor radius R")};
    if (s.g != 1 && s.has_ea) return Error{syntax_code(pos), tr("a circle takes no angle EA")};
    if (s.g != 1 && s.has_i != s.has_j)
        return Error{101, tr("a circle centre needs both its coordinates")};
    if (s.g != 1 && s.has_r && s.r <= 0) return Error{107, tr("circle radius R must be positive")};
    return {};
}

// A complete arc from S to E by its radius: the centre on the left of the chord
// with E+, on the right with E-, the smaller arc without (000:8388, 004:622;
// pupitre-iso(5), DECISIONS, Arcs with R).
Error arc_by_radius(const Spec& s, int sense, const V2& S, const V2& E, Elt& e) {
    V2 ch = E - S;
    double d = ch.norm();
    if (d < 1e-9) return Error{107, tr("circle with R: the end point equals the start point")};
    if (d > 2 * s.r + kChordTol + 1e-9)
        return Error{107, strf(tr("circle end point too far: chord %s > 2R %s"), fixed3(d).c_str(),
                               fixed3(2 * s.r).c_str())};
    double h = std::sqrt(std::max(0.0, s.r * s.r - d * d / 4));
    int side = s.disc != 0 ? s.disc : sense;
    V2 c = (S + E) / 2 + side * h * perp(ch) / d;
    e.form = Form::Complete;
    e.geo = piece(circle(c, s.r, sense), S, E);
    return {};
}

}  // namespace

namespace {

// A line as the first block of an entity.
Error first_line(const Spec& s, const V2& S, const Sup* over, Elt& e) {
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    int axis = s.has_x ? 0 : 1;
    double val = s.has_x ? s.x : s.y;
    bool has_d = over || s.has_ea;
    V2 d = over ? over->d : dir(s.ea), end;
    if (end2) {
        end = V2(s.x, s.y);
    } else if (end1 && has_d) {
        if (!along(S, d, axis, val, end))
            return Error{102, tr("the angle EA does not give the other coordinate")};
    } else if (end1) {
        end = S;  // the classic meaning: the other coordinate is unchanged
        end[axis] = val;
    } else if (has_d) {
        e.sup = line(S, d);
        return {};
    } else if (s.link == 'T') {
        e.form = Form::Free;
        return {};
    } else {
        return Error{110, s.link == 'S' ? tr("ES on a line needs its angle EA")
                                        : tr("a line needs an end point, an angle EA or ET")};
    }
    e.form = Form::Complete;
    e.geo.a = S;
    e.geo.b = end;
    return {};
}

// A circle by its centre I J as the first block of an entity.
Error first_centre(const Spec& s, const V2& S, const V2& E, Elt& e) {
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    V2 c(s.i, s.j);
    double r0 = (S - c).norm();
    if (r0 < kEq) return Error{107, tr("circle centre on the start point")};
    if (s.has_r && std::fabs(s.r - r0) > kArcTol + 1e-9)
        return Error{107, strf(tr("radius R %s differs from the start radius %s"),
                               fixed3(s.r).c_str(), fixed3(r0).c_str())};
    e.sup = circle(c, r0, e.s);
    if (!end2 && !end1) return {};
    double r1 = (E - c).norm();
    if (std::fabs(r1 - r0) > kArcTol + 1e-9)
        return Error{107,
                     strf(tr("circle end point inconsistent: start radius %s, end radius %s (more "
                             "than 0.020 apart)"),
                          fixed3(r0).c_str(), fixed3(r1).c_str())};
    e.form = Form::Complete;
    e.geo = piece(e.sup, S, E);
    if ((E - S).norm() < 1e-7) {  // a full circle, as in classic programming
        e.geo.arc = true;
        e.geo.c = c;
        e.geo.sweep = e.s * 2 * kPi;
    }
    return {};
}

}  // namespace

// The first block of an entity: its start S is known. `over` is the support
// found while solving the previous entity.
Error first_elt(const Spec& s, const V2& S, const Sup* over, Elt& e) {
    if (Error f = syntax(s, 0)) return f;
    e = Elt{};
    e.s = s.g == 3 ? 1 : s.g == 2 ? -1 : 0;
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    if (s.g == 1) return first_line(s, S, over, e);
    V2 E(s.has_x ? s.x : S.x(), s.has_y ? s.y : S.y());
    if (over) {
        e.sup = circle(over->p, (S - over->p).norm(), e.s);
        if (!end2) return {};
        e.form = Form::Complete;
        e.geo = piece(e.sup, S, E);
        return {};
    }
    if (s.has_i) return first_centre(s, S, E, e);
    if (s.has_r) {
        if (end1 || end2) return arc_by_radius(s, e.s, S, E, e);
        e.form = Form::Radius;
        e.r = s.r;
        return {};
    }
    return Error{101, tr("a circle needs its centre I J or its radius R")};
}

namespace {

// A line after an incomplete element.
Error next_line(const Spec& s, int pos, Elt& e) {
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    V2 E(s.x, s.y);
    if (end1) {
        e.end_axis = s.has_x ? 0 : 1;
        e.end_val = s.has_x ? s.x : s.y;
    }
    if (s.has_ea) {
        V2 d = dir(s.ea);
        if (end2) {
            e.sup = line(E, d);
            e.has_end = true;
            e.end = E;
        } else {
            if (end1 && std::fabs(d[e.end_axis]) < 1e-12)
                return Error{102, tr("the angle EA does not give the other coordinate")};
            e.form = Form::Angle;
            e.d = d;
        }
    } else if (end2) {
        e.form = Form::Free;
        e.has_end = true;
        e.end = E;
    } else if (end1) {
        e.form = Form::Axis;
        e.d = s.has_x ? V2(1, 0) : V2(0, 1);
    } else if (s.link == 'T') {
        e.form = Form::Free;
    } else {
        return Error{syntax_code(pos), s.link == 'S'
                                           ? tr("ES on a line needs its angle EA")
                                           : tr("a line needs an end point, an angle EA or ET")};
    }
    return {};
}

// A circle by its centre I J after an incomplete element.
Error next_centre(const Spec& s, Elt& e) {
    bool end2 = s.has_x && s.has_y;
    V2 E(s.x, s.y);
    V2 c(s.i, s.j);
    if (end2) {
        double r = (E - c).norm();
        if (r < kEq) return Error{107, tr("circle centre on the end point")};
        if (s.has_r && std::fabs(s.r - r) > kArcTol + 1e-9)
            return Error{107, strf(tr("radius R %s differs from the end radius %s"),
                                   fixed3(s.r).c_str(), fixed3(r).c_str())};
        e.sup = circle(c, r, e.s);
        e.has_end = true;
        e.end = E;
    } else if (s.has_r) {
        e.sup = circle(c, s.r, e.s);
    } else {
        e.form = Form::Centre;
        e.c = c;
    }
    return {};
}

}  // namespace

// A block after an incomplete element (pos 1 or 2 in the entity): its start is
// not known yet.
Error next_elt(const Spec& s, int pos, Elt& e) {
    if (Error f = syntax(s, pos)) return f;
    e = Elt{};
    e.s = s.g == 3 ? 1 : s.g == 2 ? -1 : 0;
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    V2 E(s.x, s.y);
    if (s.g == 1) return next_line(s, pos, e);
    if (end1) return Error{101, tr("a circle whose start is computed needs both end coordinates")};
    if (s.has_i) return next_centre(s, e);
    if (s.has_r) {
        e.form = Form::Radius;
        e.r = s.r;
        e.has_end = end2;
        e.end = E;
        return {};
    }
    return Error{101, tr("a circle needs its centre I J or its radius R")};
}

// ---------------------------------------------------------------------------
// EB corners.

// Replaces the corner between h and e by a fillet (eb > 0) or a chamfer
// (eb < 0) `ins`, trimming both. Returns 0 or the error number.
Error corner(comp::Elem& h, double eb, comp::Elem& e, comp::Elem& ins) {
    V2 P = h.b, t1 = comp::end_tangent(h), t2 = comp::start_tangent(e);
    double cr = cross(t1, t2);
    if (eb < 0 && (h.arc || e.arc)) {
        return {135, tr("a chamfer joins two lines only")};
    }
    if (std::fabs(cr) < 1e-9) {
        return {113, t1.dot(t2) > 0 ? tr("EB between two tangent elements")
                                    : tr("EB where the path turns back")};
    }
    if (eb < 0) {
        double c = -eb, l1 = length(h), l2 = length(e);
        if (c > l1 + kEq || c > l2 + kEq) {
            return {113, strf(tr("chamfer %s longer than the lines (%s, %s)"), fixed3(c).c_str(),
                              fixed3(l1).c_str(), fixed3(l2).c_str())};
        }
        V2 a = c > l1 - kEq ? h.a : V2(P - c * t1), b = c > l2 - kEq ? e.b : V2(P + c * t2);
        h.b = a;
        e.a = b;
        ins = comp::Elem{};
        ins.a = a;
        ins.b = b;
        return {};
    }
    double r = eb;
    int sf = cr > 0 ? 1 : -1;  // G3 when the path turns left
    Sup s1 = support(h), s2 = support(e);
    double best = 1e300;
    V2 q0(0, 0), a0(0, 0), b0(0, 0);
    for (const Sup& l1 : loci(s1, r))
        for (const Sup& l2 : loci(s2, r))
            for (const V2& q : meet(l1, l2)) {
                V2 a = contact(s1, q, r), b = contact(s2, q, r);
                Sup fil = circle(q, r, sf);
                if (tangent(fil, a).dot(tangent(s1, a)) < 0.5 ||
                    tangent(fil, b).dot(tangent(s2, b)) < 0.5)
                    continue;
                double back = h.arc ? turn(a - h.c, h.b - h.c, s1.s) * s1.r : (h.b - a).dot(s1.d);
                double fwd = e.arc ? turn(e.a - e.c, b - e.c, s2.s) * s2.r : (b - e.a).dot(s2.d);
                if (back < -kEq || back > length(h) + kEq || fwd < -kEq || fwd > length(e) + kEq)
                    continue;
                if (back + fwd < best) {
                    best = back + fwd;
                    q0 = q;
                    a0 = a;
                    b0 = b;
                }
            }
    if (best > 1e299) {
        return {113, strf(tr("fillet radius %s too large for the elements it joins"),
                          fixed3(r).c_str())};
    }
    h = h.arc ? piece(s1, h.a, a0) : comp::Elem{false, h.a, a0};
    e = e.arc ? piece(s2, b0, e.b) : comp::Elem{false, b0, e.b};
    ins = piece(circle(q0, r, sf), a0, b0);
    return {};
}

}  // namespace pupitre::pgp::detail
