// Profile geometry programming (pgp.md §3-§8). Each block is classified by what
// it fixes of its element; an entity of 2 or 3 blocks is solved by enumerating
// every geometric candidate (intersections, tangent lines and circles), keeping
// those without a cusp at a tangency and with lines travelled forward, then
// choosing with the discriminants of pgp.md §5. EB corners are cut afterwards,
// when both elements are known.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/pgp.hpp"
#include "core/geometry/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace pupitre::pgp {

namespace {
using ::pupitre::geometry::kPi;
constexpr double kEq = 1e-6;         // mm: equal points (pgp.md §6.7)
constexpr double kArcTol = 0.020;    // mm: start and end radii of an I J arc (004:626)
constexpr double kChordTol = 0.001;  // mm: a chord up to 2R + 1 µm is a half circle
constexpr double kOverTol = 0.001;   // mm: a tangency between two fully programmed elements

using ::pupitre::geometry::perp;
using ::pupitre::geometry::cross;
V2 dir(double deg) {
    double a = deg * kPi / 180;
    return V2(std::cos(a), std::sin(a));
}
V2 rot(const V2& v, double a) {
    return V2(v.x() * std::cos(a) - v.y() * std::sin(a), v.x() * std::sin(a) + v.y() * std::cos(a));
}
std::string f3(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return b;
}

// Angle travelled from u to v turning in sense s (+1 counter-clockwise), in [0, 2π).
double turn(const V2& u, const V2& v, int s) {
    double a = s * std::atan2(cross(u, v), u.dot(v));
    if (a < 0) a += 2 * kPi;
    if (a > 2 * kPi - 1e-10) a = 0;
    return a;
}

// Supporting geometry: a line through p with unit travel direction d, or a
// circle about p of radius r travelled in sense s.
struct Sup {
    bool arc = false;
    V2 p{0, 0}, d{1, 0};
    double r = 0;
    int s = 0;
};

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
struct Tangent {
    V2 t1, t2, d;
};
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

struct Fail {
    int code = 0;
    std::string detail;
};

bool failed(Fail& f, int code, std::string detail) {
    f.code = code;
    f.detail = std::move(detail);
    return false;
}

int syntax_code(int pos) {
    return pos == 0 ? 110 : pos == 1 ? 111 : 121;
}

// Words that do not belong together, wherever the block stands in its entity.
bool syntax(const Spec& s, int pos, Fail& f) {
    if (s.link != 0 && s.link != 'S' && s.link != 'T')
        return failed(f, syntax_code(pos), "ES and ET in the same block");
    if (s.g == 1 && (s.has_i || s.has_j || s.has_r))
        return failed(f, syntax_code(pos), "a line takes no centre I J nor radius R");
    if (s.g != 1 && s.has_ea) return failed(f, syntax_code(pos), "a circle takes no angle EA");
    if (s.g != 1 && s.has_i != s.has_j)
        return failed(f, 101, "a circle centre needs both its coordinates");
    if (s.g != 1 && s.has_r && s.r <= 0) return failed(f, 107, "circle radius R must be positive");
    return true;
}

// A complete arc from S to E by its radius: the centre on the left of the chord
// with E+, on the right with E-, the smaller arc without (pgp.md §5.1).
bool arc_by_radius(const Spec& s, int sense, const V2& S, const V2& E, Elt& e, Fail& f) {
    V2 ch = E - S;
    double d = ch.norm();
    if (d < 1e-9) return failed(f, 107, "circle with R: the end point equals the start point");
    if (d > 2 * s.r + kChordTol + 1e-9)
        return failed(f, 107, "circle end point too far: chord " + f3(d) + " > 2R " + f3(2 * s.r));
    double h = std::sqrt(std::max(0.0, s.r * s.r - d * d / 4));
    int side = s.disc != 0 ? s.disc : sense;
    V2 c = (S + E) / 2 + side * h * perp(ch) / d;
    e.form = Form::Complete;
    e.geo = piece(circle(c, s.r, sense), S, E);
    return true;
}

// The first block of an entity: its start S is known. `over` is the support
// found while solving the previous entity.
bool first_elt(const Spec& s, const V2& S, const Sup* over, Elt& e, Fail& f) {
    if (!syntax(s, 0, f)) return false;
    e = Elt{};
    e.s = s.g == 3 ? 1 : s.g == 2 ? -1 : 0;
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    int axis = s.has_x ? 0 : 1;
    double val = s.has_x ? s.x : s.y;
    if (s.g == 1) {
        bool has_d = over || s.has_ea;
        V2 d = over ? over->d : dir(s.ea), end;
        if (end2) {
            end = V2(s.x, s.y);
        } else if (end1 && has_d) {
            if (!along(S, d, axis, val, end))
                return failed(f, 102, "the angle EA does not give the other coordinate");
        } else if (end1) {
            end = S;  // the classic meaning: the other coordinate is unchanged
            end[axis] = val;
        } else if (has_d) {
            e.sup = line(S, d);
            return true;
        } else if (s.link == 'T') {
            e.form = Form::Free;
            return true;
        } else {
            return failed(f, 110,
                          s.link == 'S' ? "ES on a line needs its angle EA"
                                        : "a line needs an end point, an angle EA or ET");
        }
        e.form = Form::Complete;
        e.geo.a = S;
        e.geo.b = end;
        return true;
    }
    V2 E(s.has_x ? s.x : S.x(), s.has_y ? s.y : S.y());
    if (over) {
        e.sup = circle(over->p, (S - over->p).norm(), e.s);
        if (!end2) return true;
        e.form = Form::Complete;
        e.geo = piece(e.sup, S, E);
        return true;
    }
    if (s.has_i) {
        V2 c(s.i, s.j);
        double r0 = (S - c).norm();
        if (r0 < kEq) return failed(f, 107, "circle centre on the start point");
        if (s.has_r && std::fabs(s.r - r0) > kArcTol + 1e-9)
            return failed(f, 107,
                          "radius R " + f3(s.r) + " differs from the start radius " + f3(r0));
        e.sup = circle(c, r0, e.s);
        if (!end2 && !end1) return true;
        double r1 = (E - c).norm();
        if (std::fabs(r1 - r0) > kArcTol + 1e-9)
            return failed(f, 107,
                          "circle end point inconsistent: start radius " + f3(r0) +
                              ", end radius " + f3(r1) + " (more than 0.020 apart)");
        e.form = Form::Complete;
        e.geo = piece(e.sup, S, E);
        if ((E - S).norm() < 1e-7) {  // a full circle, as in classic programming
            e.geo.arc = true;
            e.geo.c = c;
            e.geo.sweep = e.s * 2 * kPi;
        }
        return true;
    }
    if (s.has_r) {
        if (end1 || end2) return arc_by_radius(s, e.s, S, E, e, f);
        e.form = Form::Radius;
        e.r = s.r;
        return true;
    }
    return failed(f, 101, "a circle needs its centre I J or its radius R");
}

// A block after an incomplete element (pos 1 or 2 in the entity): its start is
// not known yet.
bool next_elt(const Spec& s, int pos, Elt& e, Fail& f) {
    if (!syntax(s, pos, f)) return false;
    e = Elt{};
    e.s = s.g == 3 ? 1 : s.g == 2 ? -1 : 0;
    bool end2 = s.has_x && s.has_y, end1 = s.has_x != s.has_y;
    V2 E(s.x, s.y);
    if (s.g == 1) {
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
                    return failed(f, 102, "the angle EA does not give the other coordinate");
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
            return failed(f, syntax_code(pos),
                          s.link == 'S' ? "ES on a line needs its angle EA"
                                        : "a line needs an end point, an angle EA or ET");
        }
        return true;
    }
    if (end1) return failed(f, 101, "a circle whose start is computed needs both end coordinates");
    if (s.has_i) {
        V2 c(s.i, s.j);
        if (end2) {
            double r = (E - c).norm();
            if (r < kEq) return failed(f, 107, "circle centre on the end point");
            if (s.has_r && std::fabs(s.r - r) > kArcTol + 1e-9)
                return failed(f, 107,
                              "radius R " + f3(s.r) + " differs from the end radius " + f3(r));
            e.sup = circle(c, r, e.s);
            e.has_end = true;
            e.end = E;
        } else if (s.has_r) {
            e.sup = circle(c, s.r, e.s);
        } else {
            e.form = Form::Centre;
            e.c = c;
        }
        return true;
    }
    if (s.has_r) {
        e.form = Form::Radius;
        e.r = s.r;
        e.has_end = end2;
        e.end = E;
        return true;
    }
    return failed(f, 101, "a circle needs its centre I J or its radius R");
}

// ---------------------------------------------------------------------------
// Entities.

// One geometric solution of an entity: the support of each element and the
// junctions between them.
struct Cand {
    Sup sup[3];
    V2 j[2];
    int branch = 0;  // which solution of the middle element (3 blocks)
};

enum class St { Ok, Need, Fail };

// Can the element be determined by the block after it (the middle of 3 blocks)?
bool middle(const Elt& e) {
    switch (e.form) {
        case Form::Angle:
        case Form::Axis:
        case Form::Centre:
            return true;
        case Form::Radius:
        case Form::Free:
            return !e.has_end;
        default:
            return false;
    }
}

std::vector<V2> dirs(const Elt& e) {
    if (e.form == Form::Axis) return {e.d, -e.d};
    return {e.d};
}

St stop(Fail& f, int code, std::string detail) {
    failed(f, code, std::move(detail));
    return St::Fail;
}

St undetermined(const Elt& b, Fail& f) {
    if (middle(b)) return St::Need;
    return stop(f, 113, "the second element does not determine the junction");
}

// Where two fully known elements touch (an over-determined tangency).
bool touching(const Sup& a, const Sup& b, V2& j) {
    if (a.arc && b.arc) {
        double dist = (b.p - a.p).norm();
        if (std::fabs(dist - (a.r + b.r)) > kOverTol &&
            std::fabs(dist - std::fabs(a.r - b.r)) > kOverTol)
            return false;
        j = contact(a, b.p, b.r);
        return true;
    }
    const Sup& l = a.arc ? b : a;
    const Sup& c = a.arc ? a : b;
    if (std::fabs(std::fabs(cross(l.d, c.p - l.p)) - c.r) > kOverTol) return false;
    j = contact(l, c.p, c.r);
    return true;
}

void add(std::vector<Cand>& out, const Sup& s1, const Sup& s2, const V2& j) {
    Cand c;
    c.sup[0] = s1;
    c.sup[1] = s2;
    c.j[0] = j;
    out.push_back(c);
}

// Junction of a first element whose support is known (a line through S at its
// angle, a circle through S) with the next element.
St from_fixed(const V2& S, const Sup& A, const Elt& b, bool tan, std::vector<Cand>& out, Fail& f) {
    if (b.form == Form::Fixed) {
        if (!tan) {
            if (!A.arc && !b.sup.arc) {
                if (std::fabs(cross(A.d, b.sup.d)) < 1e-9)
                    return stop(f, 112, "the two lines are parallel");
                if (b.has_end && (b.end - S).norm() < kEq)
                    return stop(f, 112, "the second line ends at the start of the first");
            }
            for (const V2& j : meet(A, b.sup)) add(out, A, b.sup, j);
            return St::Ok;
        }
        if (!A.arc && !b.sup.arc)
            return stop(f, 113, "two lines cannot be tangent (ES for their intersection)");
        V2 j;
        if (!touching(A, b.sup, j))
            return stop(f, 113, "the elements are not tangent (ES for their intersection)");
        add(out, A, b.sup, j);
        return St::Ok;
    }
    if (!tan) return undetermined(b, f);
    switch (b.form) {
        case Form::Centre:  // its radius from the tangency
            for (double r : radii(A, b.c)) add(out, A, circle(b.c, r, b.s), contact(A, b.c, r));
            return St::Ok;
        case Form::Radius:  // through its end point, tangent to A
            if (!b.has_end) return St::Need;
            for (const Sup& l : loci(A, b.r))
                for (const V2& q : meet(l, circle(b.end, b.r, 0)))
                    add(out, A, circle(q, b.r, b.s), contact(A, q, b.r));
            return St::Ok;
        case Form::Angle:  // tangent to the circle A at its angle
        case Form::Axis:
            if (!A.arc) return stop(f, 113, "a line cannot be tangent to a line");
            for (const V2& d : dirs(b))
                for (int sg : {1, -1}) {
                    V2 t = A.p + sg * A.r * perp(d);
                    add(out, A, line(t, d), t);
                }
            return St::Ok;
        case Form::Free:  // from the circle A to its end point
            if (!A.arc) return stop(f, 113, "a line cannot be tangent to a line");
            if (!b.has_end) return St::Need;
            for (const V2& t : touch_from(A, b.end)) {
                V2 d = b.end - t;
                add(out, A, line(t, d.norm() < kEq ? tangent(A, t) : V2(d.normalized())), t);
            }
            return St::Ok;
        default:
            return stop(f, 113, "the second element does not determine the junction");
    }
}

// Junction of a first element (start S) with the next one.
St solve2(const V2& S, const Elt& a, const Elt& b, char link, std::vector<Cand>& out, Fail& f) {
    bool tan = link != 'S';
    if (a.form == Form::Fixed) return from_fixed(S, a.sup, b, tan, out, f);
    if (b.form != Form::Fixed) return undetermined(b, f);
    if (a.form == Form::Free) {  // a line from S tangent to a circle
        if (!b.sup.arc)
            return stop(f, 113, "a line of unknown direction must be tangent to a circle");
        for (const V2& t : touch_from(b.sup, S)) {
            V2 d = t - S;
            add(out, line(S, d.norm() < kEq ? tangent(b.sup, t) : V2(d.normalized())), b.sup, t);
        }
        return St::Ok;
    }
    if (a.form == Form::Radius) {  // a circle through S tangent to b
        if (!tan) return stop(f, 113, "a circle known by its radius only cannot be secant");
        for (const Sup& l : loci(b.sup, a.r))
            for (const V2& q : meet(l, circle(S, a.r, 0)))
                add(out, circle(q, a.r, a.s), b.sup, contact(b.sup, q, a.r));
        return St::Ok;
    }
    return stop(f, 113, "the first element does not determine the junction");
}

// Three blocks: the middle element is found from the third one (its radius, its
// position) or together with both neighbours (a circle of given radius tangent
// to both, a common tangent line).
St solve3(const V2& S, const Elt* e, const char link[2], std::vector<Cand>& out, Fail& f) {
    const Elt &a = e[0], &b = e[1], &c = e[2];
    if (c.form != Form::Fixed)
        return stop(f, 123, "the third block must fix its element: EA X Y, or I J with R or X Y");
    const Sup& C3 = c.sup;
    if (link[1] == 'S') return stop(f, 123, "the middle element cannot be secant with the third");
    if (b.form == Form::Angle || b.form == Form::Axis || b.form == Form::Centre) {
        std::vector<std::pair<Sup, V2>> mids;
        if (b.form == Form::Centre) {
            for (double r : radii(C3, b.c))
                mids.push_back({circle(b.c, r, b.s), contact(C3, b.c, r)});
        } else {
            if (!C3.arc) return stop(f, 123, "a line cannot be tangent to a line");
            for (const V2& d : dirs(b))
                for (int sg : {1, -1}) {
                    V2 t = C3.p + sg * C3.r * perp(d);
                    mids.push_back({line(t, d), t});
                }
        }
        int branch = 0;
        for (const auto& [sup, t23] : mids) {
            Elt m = b;
            m.form = Form::Fixed;
            m.sup = sup;
            m.has_end = true;
            m.end = t23;
            std::vector<Cand> part;
            Fail f2;
            St st = solve2(S, a, m, link[0], part, f2);
            if (st == St::Fail && f2.code == 112)
                return stop(f, 122, "the first two blocks are parallel lines");
            if (st != St::Ok) continue;
            for (Cand& cd : part) {
                cd.j[1] = t23;
                cd.sup[2] = C3;
                cd.branch = branch;
                out.push_back(cd);
            }
            ++branch;
        }
        return St::Ok;
    }
    if (link[0] == 'S')
        return stop(f, 123, "the first element cannot be secant with this middle element");
    if (b.form == Form::Radius && !b.has_end) {
        if (a.form != Form::Fixed)
            return stop(f, 123, "the first element must be fixed for this construction");
        for (const Sup& l1 : loci(a.sup, b.r))
            for (const Sup& l3 : loci(C3, b.r))
                for (const V2& q : meet(l1, l3)) {
                    Cand cd;
                    cd.sup[0] = a.sup;
                    cd.sup[1] = circle(q, b.r, b.s);
                    cd.sup[2] = C3;
                    cd.j[0] = contact(a.sup, q, b.r);
                    cd.j[1] = contact(C3, q, b.r);
                    out.push_back(cd);
                }
        return St::Ok;
    }
    if (b.form == Form::Free && !b.has_end) {
        if (a.form != Form::Fixed || !a.sup.arc || !C3.arc)
            return stop(f, 123, "a line tangent at both ends needs two circles");
        for (const Tangent& t : common(a.sup, C3)) {
            Cand cd;
            cd.sup[0] = a.sup;
            cd.sup[1] = line(t.t1, t.d);
            cd.sup[2] = C3;
            cd.j[0] = t.t1;
            cd.j[1] = t.t2;
            out.push_back(cd);
        }
        return St::Ok;
    }
    return stop(f, 123, "these three blocks do not determine the tangency points");
}

// The entity being solved: its start, its blocks, their links and discriminants.
struct Entity {
    V2 S;
    Elt e[3];
    char link[2] = {0, 0};
    int disc[2] = {0, 0};
    int n = 2;

    // Start and end of element k in a candidate; false when the end is not known.
    bool ends(const Cand& c, int k, V2& a, V2& b) const {
        a = k == 0 ? S : c.j[k - 1];
        if (k < n - 1) {
            b = c.j[k];
            return true;
        }
        const Elt& x = e[k];
        if (x.has_end) {
            b = x.end;
            return true;
        }
        return !c.sup[k].arc && x.end_axis >= 0 && along(a, c.sup[k].d, x.end_axis, x.end_val, b);
    }

    // No cusp at a tangency (pgp.md §2 rule 2); lines are travelled forward.
    bool feasible(const Cand& c) const {
        for (int k = 0; k < n; ++k) {
            V2 a, b;
            if (!c.sup[k].arc && ends(c, k, a, b) && (b - a).dot(c.sup[k].d) < -kEq) return false;
        }
        for (int k = 0; k + 1 < n; ++k)
            if (link[k] != 'S' &&
                tangent(c.sup[k], c.j[k]).dot(tangent(c.sup[k + 1], c.j[k])) < 0.5)
                return false;
        return true;
    }

    // §5.1 on arc k: +1 when its centre is on the left of its chord; its sweep.
    bool arc_side(const Cand& c, int k, int& side, double& sweep) const {
        V2 a, b;
        if (k < 0 || !c.sup[k].arc || !ends(c, k, a, b)) return false;
        side = cross(b - a, c.sup[k].p - a) > 0 ? 1 : -1;
        sweep = turn(a - c.sup[k].p, b - c.sup[k].p, c.sup[k].s);
        return true;
    }

    // The candidates whose arc k lies on side `want` (all of them for 0), the
    // smallest arc first (000:8388: by default the smaller arc).
    std::vector<Cand> by_arc(const std::vector<Cand>& cs, int k, int want) const {
        std::vector<std::pair<double, const Cand*>> keep;
        for (const Cand& c : cs) {
            int side = 0;
            double sw = 1e300;
            bool known = arc_side(c, k, side, sw);
            if (want == 0 || (known && side == want)) keep.push_back({sw, &c});
        }
        std::stable_sort(keep.begin(), keep.end(),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<Cand> out;
        for (const auto& kc : keep) out.push_back(*kc.second);
        return out;
    }

    // ES±: the order along the line (first met = -, pgp.md §5.2 and §5.4), or the
    // side of the line of centres for two circles (§5.3).
    bool by_secant(const std::vector<Cand>& cs, Cand& pick, Fail& f) const {
        if (disc[0] == 0) return failed(f, 114, "two intersections: choose one with ES+ or ES-");
        auto key = [&](const Cand& c) {
            if (!c.sup[0].arc) return (c.j[0] - S).dot(c.sup[0].d);
            if (!c.sup[1].arc) return (c.j[0] - c.sup[1].p).dot(c.sup[1].d);
            return cross(c.sup[1].p - c.sup[0].p, c.j[0] - c.sup[0].p);
        };
        const Cand* best = &cs[0];
        for (const Cand& c : cs)
            if (disc[0] < 0 ? key(c) < key(*best) : key(c) > key(*best)) best = &c;
        pick = *best;
        return true;
    }

    // One candidate among the feasible ones; false on an ambiguity (114, 124).
    bool choose(const std::vector<Cand>& cs, Cand& pick, Fail& f, int& block) const {
        std::vector<int> branches;
        for (const Cand& c : cs)
            if (std::find(branches.begin(), branches.end(), c.branch) == branches.end())
                branches.push_back(c.branch);
        std::vector<Cand> per;  // one per solution of the middle element
        for (int b : branches) {
            std::vector<Cand> g;
            for (const Cand& c : cs)
                if (c.branch == b) g.push_back(c);
            Cand one = g[0];
            if (g.size() > 1) {
                if (link[0] == 'S') {
                    block = 0;
                    if (!by_secant(g, one, f)) return false;
                } else {
                    std::vector<Cand> m = by_arc(g,
                                                 g[0].sup[0].arc   ? 0
                                                 : g[0].sup[1].arc ? 1
                                                                   : -1,
                                                 disc[0]);
                    if (m.empty()) {
                        block = 0;
                        return failed(f, 114,
                                      std::string("ET") + (disc[0] > 0 ? '+' : '-') +
                                          " designates none of the tangent solutions");
                    }
                    one = m[0];
                }
            }
            per.push_back(one);
        }
        pick = per[0];
        if (per.size() > 1) {
            // ET± of the middle block (pgp.md §5.5) must designate one solution.
            block = 1;
            if (disc[1] == 0)
                return failed(f, 124,
                              "two tangencies between blocks 2 and 3: choose one with ET+ or ET-");
            std::vector<Cand> m = by_arc(per, 1, disc[1]);
            if (m.size() != 1)
                return failed(
                    f, 124,
                    std::string("ET") + (disc[1] > 0 ? '+' : '-') +
                        " does not designate one of the two tangencies between blocks 2 and 3");
            pick = m[0];
        }
        return true;
    }
};

enum class Step { Complete, Wait, Solved, Error };

// Solves the entity made of the waiting blocks (`count` of them, the first one
// starting at S, `over` its support if already known). Complete: the first
// block is an element by itself; Wait: one more block is needed; Solved: `pick`
// is the chosen solution of en.n blocks; Error: `f` for block number `block`.
Step entity(const V2& S, const Spec* const* specs, int count, const Sup* over, Entity& en,
            Cand& pick, Fail& f, int& block) {
    block = 0;
    if (!first_elt(*specs[0], S, over, en.e[0], f)) return Step::Error;
    if (en.e[0].form == Form::Complete) return Step::Complete;
    if (count < 2) return Step::Wait;
    block = 1;
    if (!next_elt(*specs[1], 1, en.e[1], f)) return Step::Error;
    en.S = S;
    for (int k = 0; k < 2; ++k) {
        en.link[k] = specs[k]->link;
        en.disc[k] = specs[k]->disc;
    }
    std::vector<Cand> cs;
    St st = solve2(S, en.e[0], en.e[1], en.link[0], cs, f);
    if (st == St::Need) {
        if (count < 3) return Step::Wait;
        block = 2;
        if (!next_elt(*specs[2], 2, en.e[2], f)) return Step::Error;
        en.n = 3;
        st = solve3(S, en.e, en.link, cs, f);
    }
    block = en.n - 1;
    if (st == St::Fail) return Step::Error;
    std::erase_if(cs, [&](const Cand& c) { return !en.feasible(c); });
    if (cs.empty()) {
        failed(f, en.n == 2 ? 113 : 123,
               en.n == 2 ? "no intersection or tangency between these two blocks"
                         : "these three blocks give no tangency points");
        return Step::Error;
    }
    return en.choose(cs, pick, f, block) ? Step::Solved : Step::Error;
}

// Replaces the corner between h and e by a fillet (eb > 0) or a chamfer
// (eb < 0) `ins`, trimming both. Returns 0 or the error number.
int corner(comp::Elem& h, double eb, comp::Elem& e, comp::Elem& ins, std::string& detail) {
    V2 P = h.b, t1 = comp::end_tangent(h), t2 = comp::start_tangent(e);
    double cr = cross(t1, t2);
    if (eb < 0 && (h.arc || e.arc)) {
        detail = "a chamfer joins two lines only";
        return 135;
    }
    if (std::fabs(cr) < 1e-9) {
        detail =
            t1.dot(t2) > 0 ? "EB between two tangent elements" : "EB where the path turns back";
        return 113;
    }
    if (eb < 0) {
        double c = -eb, l1 = length(h), l2 = length(e);
        if (c > l1 + kEq || c > l2 + kEq) {
            detail = "chamfer " + f3(c) + " longer than the lines (" + f3(l1) + ", " + f3(l2) + ")";
            return 113;
        }
        V2 a = c > l1 - kEq ? h.a : V2(P - c * t1), b = c > l2 - kEq ? e.b : V2(P + c * t2);
        h.b = a;
        e.a = b;
        ins = comp::Elem{};
        ins.a = a;
        ins.b = b;
        return 0;
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
        detail = "fillet radius " + f3(r) + " too large for the elements it joins";
        return 113;
    }
    h = h.arc ? piece(s1, h.a, a0) : comp::Elem{false, h.a, a0};
    e = e.arc ? piece(s2, b0, e.b) : comp::Elem{false, b0, e.b};
    ins = piece(circle(q0, r, sf), a0, b0);
    return 0;
}
}  // namespace

// ---------------------------------------------------------------------------

void Solver::start(const V2& p) {
    wait_.clear();
    held_ = false;
    idle_ = 0;
    pos_ = p;
}

bool Solver::pending() const {
    return !wait_.empty() || held_;
}

V2 Solver::position() const {
    return pos_;
}

bool Solver::fail(Error& err, int code, int tag, std::string detail) {
    err.code = code;
    err.tag = tag;
    err.detail = std::move(detail);
    wait_.clear();
    held_ = false;
    idle_ = 0;
    return false;
}

bool Solver::push(const Spec& s, std::vector<Elem>& out, Error& err) {
    idle_ = 0;
    if (s.stop && s.has_eb) return fail(err, 131, s.tag, "EB on a block with M0, M1 or M2");
    // The block's own words, checked where it stands in its entity (110, 111, 121).
    Fail f;
    Elt e;
    int pos = int(wait_.size());
    if (!(pos == 0 ? first_elt(s, pos_, nullptr, e, f) : next_elt(s, std::min(pos, 2), e, f)))
        return fail(err, f.code, s.tag, f.detail);
    wait_.push_back(Item{s});
    return resolve(out, err);
}

bool Solver::idle(Error& err) {
    if (!pending()) return true;
    if (++idle_ > 2)
        return fail(err, 136, wait_.empty() ? held_elem_.tag : wait_[0].spec.tag,
                    "more than 2 blocks without motion between elements to be joined");
    return true;
}

bool Solver::finish(std::vector<Elem>& out, Error& err) {
    idle_ = 0;
    if (!wait_.empty())
        return fail(err, 131, wait_[0].spec.tag,
                    "the profile ends before the end point of this element is known");
    if (held_) out.push_back(held_elem_);
    held_ = false;
    return true;
}

bool Solver::resolve(std::vector<Elem>& out, Error& err) {
    while (!wait_.empty()) {
        const Spec* specs[3] = {nullptr, nullptr, nullptr};
        int count = int(std::min<size_t>(wait_.size(), 3));
        for (int k = 0; k < count; ++k) specs[k] = &wait_[size_t(k)].spec;
        const Item& it = wait_[0];
        Sup over = it.arc ? circle(it.p, it.r, it.s) : line(it.p, it.d);
        Entity en;
        Cand pick;
        Fail f;
        int block = 0;
        switch (entity(pos_, specs, count, it.fixed ? &over : nullptr, en, pick, f, block)) {
            case Step::Error:
                return fail(err, f.code, wait_[size_t(block)].spec.tag, f.detail);
            case Step::Wait:
                return true;
            case Step::Complete: {
                Spec sp = it.spec;
                wait_.erase(wait_.begin());
                pos_ = en.e[0].geo.b;
                if (!deliver(Elem{en.e[0].geo, sp.tag, false}, sp, out, err)) return false;
                continue;
            }
            case Step::Solved:
                break;
        }
        // The entity's last block starts the next entity, its support known.
        int last = en.n - 1;
        std::vector<Spec> done;
        for (int k = 0; k < last; ++k) done.push_back(wait_[size_t(k)].spec);
        const Sup& ls = pick.sup[last];
        Item next = wait_[size_t(last)];
        next.fixed = true;
        next.arc = ls.arc;
        next.p = ls.p;
        next.d = ls.d;
        next.r = ls.r;
        next.s = ls.s;
        wait_.erase(wait_.begin(), wait_.begin() + last);
        wait_[0] = next;
        V2 from = pos_;
        pos_ = pick.j[last - 1];
        for (int k = 0; k < last; ++k) {
            Elem el{piece(pick.sup[k], k == 0 ? from : pick.j[k - 1], pick.j[k]),
                    done[size_t(k)].tag, false};
            if (!deliver(el, done[size_t(k)], out, err)) return false;
        }
    }
    return true;
}

bool Solver::deliver(Elem e, const Spec& s, std::vector<Elem>& out, Error& err) {
    double len = length(e.geo);
    if (held_) {
        if (len < kEq) return fail(err, 130, s.tag, "zero move in a block joined by EB");
        Elem ins;
        ins.tag = held_elem_.tag;
        ins.inserted = true;
        std::string detail;
        if (int code = corner(held_elem_.geo, held_eb_, e.geo, ins.geo, detail))
            return fail(err, code, held_elem_.tag, detail);
        held_ = false;
        if ((held_elem_.geo.b - held_elem_.geo.a).norm() > 0 || held_elem_.geo.arc)
            out.push_back(held_elem_);
        out.push_back(ins);
    }
    if (s.has_eb && s.eb != 0) {
        if (len < kEq) return fail(err, 130, s.tag, "zero move in a block joined by EB");
        held_ = true;
        held_elem_ = e;
        held_eb_ = s.eb;
        return true;
    }
    if ((e.geo.b - e.geo.a).norm() > 0 || e.geo.arc) out.push_back(e);
    return true;
}

}  // namespace pupitre::pgp
