// A tilted cutter's geometry (see tilt.hpp).
//
// The volume a flat end sweeps is the end's disc, square to u, added to the
// half strip {a + l u + t d : l >= 0, 0 <= t <= 1}: a point is in it when,
// for some t, it is above the end (axial) and within r of the axis (radial).
// Along a line o + s e that is a convex region of the plane (s, t): the
// radial condition an ellipse (or a strip), the axial one and 0 <= t <= 1
// half planes. So the line's interval is in closed form: the least and the
// greatest s of that region (swept_moving), without sampling.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/workshop/tilt.hpp"

#include <algorithm>
#include <cmath>

#include "core/workshop/narrow.hpp"

namespace pupitre::workshop::tilt {

namespace {

// Narrows [t0, t1] to the t where A t² + B t + C <= 0 (A >= 0); false when
// that is empty.
bool quad_le(double A, double B, double C, double& t0, double& t1) {
    if (A <= 0) {
        if (B == 0) return C <= 0 && t0 <= t1;
        return narrow(C, B, -kInf, 0, t0, t1);
    }
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return false;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    double r1 = q / A, r2 = q != 0 ? C / q : r1;
    if (r1 > r2) std::swap(r1, r2);
    t0 = std::max(t0, r1), t1 = std::min(t1, r2);
    return t0 <= t1;
}

P3 perp(const P3& v, const P3& u) {
    return sub(v, mul(u, dot(v, u)));
}

// The corner's balls: enough that between two of them the ring of balls
// falls short of the torus by at most 0.5 µm (the shortfall is about
// (pi / n)² inner r / (2 c)), up to 256 of them.
int ring_count(double inner, double radius, double corner) {
    const double step = std::sqrt(2 * 5e-4 * corner / (inner * radius));
    return std::clamp(int(std::ceil(M_PI / step)), 8, kRing);
}

// A bull nose standing still, below its corner's top: the points within c
// of the inner cylinder (radius - c, from c up the axis), in the slab
// 0 <= axial <= c. Along the line that is a bounded stretch where the
// distance to the inner cylinder, less c, is convex: its least by a golden
// search, its ends by bisection, to 1e-10 mm.
Span still_corner(double radius, double c, const P3& a, const P3& u, const Line& l) {
    const double inner = radius - c;
    auto gap = [&](double s) {
        const P3 q = sub(add(l.o, mul(l.e, s)), a), side = perp(q, u);
        const double h = dot(q, u) - c, e = std::sqrt(dot(side, side)) - inner;
        if (h >= 0) return std::max(0.0, e) - c;
        return (e <= 0 ? -h : std::hypot(h, e)) - c;
    };
    double s0 = -kInf, s1 = kInf;
    const P3 w = sub(l.o, a), pw = perp(w, u), pe = perp(l.e, u);
    if (!narrow(dot(w, u), dot(l.e, u), 0, c, s0, s1) ||
        !quad_le(dot(pe, pe), 2 * dot(pe, pw), dot(pw, pw) - radius * radius, s0, s1) ||
        !std::isfinite(s0) || !std::isfinite(s1))
        return {};
    constexpr double tol = 1e-10;
    const auto [sm, least] = golden_min(gap, s0, s1, tol);
    if (least > 0) return {};
    auto in = [&](double s) { return -gap(s); };
    return {gap(s0) <= 0 ? s0 : crossing(in, sm, s0, tol),
            gap(s1) <= 0 ? s1 : crossing(in, sm, s1, tol)};
}

// The line moving along the cylinder's axis: in it for the t where the
// line is within r of the axis, from the end up.
Span along_axis(const P3& pw, const P3& pd, double k, double m, double h0, double r, bool still) {
    Span out;
    double t0 = 0, t1 = still ? 0 : 1;
    if (!quad_le(dot(pd, pd), -2 * dot(pw, pd), dot(pw, pw) - r * r, t0, t1)) return out;
    // h0 + s k - t m >= 0 for some t of [t0, t1]; k is ±1.
    const double least = std::min(t0 * m, t1 * m);
    if (k > 0)
        out.lo = (least - h0) / k, out.hi = kInf;
    else
        out.lo = -kInf, out.hi = (least - h0) / k;
    return out;
}

}  // namespace

void frame(const P3& u, P3& e1, P3& e2) {
    P3 c = cross(u, {1, 0, 0});
    if (dot(c, c) < 1e-6) c = cross(u, {0, 1, 0});
    e1 = mul(c, 1 / std::sqrt(dot(c, c)));
    e2 = cross(u, e1);
}

namespace {

// The flat end moving (d != 0; its parts square to u: pd, and along u: m),
// the line's point s (pw + s pe square to u, h0 + s k along it): the
// region of (s, t) where the point is in the cylinder whose end is at
// a + t d, |pw + s pe - t pd| <= r, 0 <= t <= 1 and h0 + s k - t m >= 0, is
// convex and bounded (pe != 0). Its least and greatest s are at the
// ellipse's own extremes in s, its crossings with the three lines, or the
// lines' crossings: the interval is the span of those that are in it.
Span swept_moving(const P3& pw, const P3& pe, const P3& pd, double k, double m, double h0,
                  double r) {
    const double r2 = r * r;
    auto inside = [&](double s, double t) {
        const P3 v = sub(add(pw, mul(pe, s)), mul(pd, t));
        const double slack = 1e-9 * (1 + std::abs(h0) + std::abs(s * k) + std::abs(t * m));
        return std::isfinite(s) && t >= -1e-12 && t <= 1 + 1e-12 &&
               dot(v, v) <= r2 * (1 + 1e-9) + 1e-18 && h0 + s * k - t * m >= -slack;
    };
    Span out;
    auto keep = [&](double s, double t) {
        if (inside(s, t)) out.hull({s, s});
    };
    // Where |v0 + x v1| = r along a line of the plane, x its parameter.
    auto roots = [&](const P3& v0, const P3& v1, auto&& at) {
        double x0 = -kInf, x1 = kInf;
        const double A = dot(v1, v1);
        if (A > 1e-30 && quad_le(A, 2 * dot(v0, v1), dot(v0, v0) - r2, x0, x1)) at(x0), at(x1);
    };
    // The ellipse's extremes in s: where its tangent runs along t.
    if (const double pdd = dot(pd, pd); pdd > 1e-30) {
        auto off = [&](const P3& v) { return sub(v, mul(pd, dot(v, pd) / pdd)); };
        roots(off(pw), off(pe), [&](double s) { keep(s, dot(pd, add(pw, mul(pe, s))) / pdd); });
    }
    // Its crossings with t = 0, t = 1 and the axial line, and the lines'.
    roots(pw, pe, [&](double s) { keep(s, 0); });
    roots(sub(pw, pd), pe, [&](double s) { keep(s, 1); });
    if (std::abs(m) >= std::abs(k) && m != 0)
        roots(sub(pw, mul(pd, h0 / m)), sub(pe, mul(pd, k / m)),
              [&](double s) { keep(s, (h0 + s * k) / m); });
    else if (k != 0)
        roots(sub(pw, mul(pe, h0 / k)), sub(mul(pe, m / k), pd),
              [&](double t) { keep((t * m - h0) / k, t); });
    if (k != 0) keep(-h0 / k, 0), keep((m - h0) / k, 1);
    return out;
}

}  // namespace

Span swept_flat(const P3& a, const P3& d, const P3& u, double r, const Line& l) {
    Span out;
    if (!(r > 0)) return out;
    const P3 w = sub(l.o, a), pw = perp(w, u), pe = perp(l.e, u), pd = perp(d, u);
    const double k = dot(l.e, u), m = dot(d, u), h0 = dot(w, u), alpha = dot(pe, pe);
    const bool still = d[0] == 0 && d[1] == 0 && d[2] == 0;
    if (alpha < 1e-24) return along_axis(pw, pd, k, m, h0, r, still);
    const double b0 = dot(pe, pw);
    if (still) {
        double s0 = -kInf, s1 = kInf;
        if (!quad_le(alpha, 2 * b0, dot(pw, pw) - r * r, s0, s1) || !narrow(h0, k, 0, kInf, s0, s1))
            return out;
        return {s0, s1};
    }
    return swept_moving(pw, pe, pd, k, m, h0, r);
}

Span capsule(const P3& a, const P3& d, double r, const Line& l) {
    Span out;
    for (const P3& c : {a, add(a, d)}) {
        const P3 w = sub(l.o, c);
        double s0 = -kInf, s1 = kInf;
        if (quad_le(1, 2 * dot(w, l.e), dot(w, w) - r * r, s0, s1)) out.hull({s0, s1});
    }
    const double dd = dot(d, d);
    if (dd > 0) {
        const P3 w = sub(l.o, a);
        const double ed = dot(l.e, d), wd = dot(w, d);
        double s0 = -kInf, s1 = kInf;
        if (quad_le(std::max(0.0, 1 - ed * ed / dd), 2 * (dot(w, l.e) - wd * ed / dd),
                    dot(w, w) - wd * wd / dd - r * r, s0, s1) &&
            narrow(wd, ed, 0, dd, s0, s1))
            out.hull({s0, s1});
    }
    return out;
}

Span swept_cutter(double radius, double corner, const P3& a, const P3& d, const P3& u,
                  const Line& l) {
    const double c = std::clamp(corner, 0.0, radius);
    // A corner of 2 µm or less (a flat end grown by a contact's margin) is a
    // flat end's within 0.6 µm.
    if (c <= 2e-3) return swept_flat(a, d, u, radius, l);
    // Above the corner the cutter is a flat end of its full radius.
    const P3 centre = add(a, mul(u, c));
    Span out = swept_flat(centre, d, u, radius, l);
    const double inner = radius - c;
    if (inner <= 1e-9) {
        out.hull(capsule(centre, d, c, l));  // a ball end
        return out;
    }
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) {
        out.hull(still_corner(radius, c, a, u, l));  // exact, standing still
        return out;
    }
    out.hull(swept_flat(a, d, u, inner, l));  // the flat of the end
    // The corner's balls all lie within `radius` of the axis at the corner's
    // height: a line that misses that misses them.
    if (capsule(centre, d, radius, l).empty()) return out;
    P3 e1, e2;
    frame(u, e1, e2);
    const int n = ring_count(inner, radius, c);
    for (int i = 0; i < n; ++i) {
        const double phi = 2 * M_PI * i / n;
        const P3 off = add(mul(e1, inner * std::cos(phi)), mul(e2, inner * std::sin(phi)));
        out.hull(capsule(add(centre, off), d, c, l));
    }
    return out;
}

Span part_span(const Cutter& c, Part part, const P3& tip, const P3& u, const Line& l) {
    const PartSpan s = span_of(c, part);
    const P3 still{0, 0, 0};
    Span out = s.flute ? swept_cutter(c.radius, c.corner, tip, still, u, l)
                       : swept_flat(add(tip, mul(u, s.base)), still, u, s.radius, l);
    if (out.empty() || std::isinf(s.top)) return out;
    if (!narrow(dot(sub(l.o, tip), u), dot(l.e, u), -kInf, s.top, out.lo, out.hi)) return {};
    return out;
}

double inset(const PartSpan& s, const P3& tip, const P3& u, double x, double y) {
    const double wx = x - tip[0], wy = y - tip[1];
    // The common normal of the vertical line and the axis is horizontal.
    const double nx = -u[1], ny = u[0], nn = nx * nx + ny * ny;
    const double d = nn < 1e-24 ? std::hypot(wx, wy) : std::abs(wx * nx + wy * ny) / std::sqrt(nn);
    return s.radius - d;
}

Box3 part_box(const Cutter& c, Part part, const P3& tip, const P3& u, double top) {
    const PartSpan s = span_of(c, part);
    const double t1 = std::min(s.top, top);
    Box3 b;
    for (int k = 0; k < 3; ++k) {
        const double p0 = tip[k] + s.base * u[k], p1 = tip[k] + t1 * u[k];
        const double ext = s.radius * std::sqrt(std::max(0.0, 1 - u[k] * u[k]));
        b.lo[k] = std::min(p0, p1) - ext;
        b.hi[k] = std::max(p0, p1) + ext;
    }
    return b;
}

std::vector<P3> surface(const Cutter& c, Part part, const P3& u, double top) {
    const PartSpan s = span_of(c, part);
    const double t1 = std::min(s.top, top);
    P3 e1, e2;
    frame(u, e1, e2);
    std::vector<P3> out;
    static const P3 kDirs[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    // The unit circle in 48 and 24 steps, worked out once.
    static const auto circle = [](int n) {
        std::vector<std::array<double, 2>> unit;
        for (int i = 0; i < n; ++i)
            unit.push_back({std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)});
        return unit;
    };
    static const std::vector<std::array<double, 2>> c48 = circle(48), c24 = circle(24);
    auto ring = [&](double h, double rho, int n) {
        const P3 centre = mul(u, h);
        if (rho <= 0) {
            out.push_back(centre);
            return;
        }
        for (const auto& cs : n == 48 ? c48 : c24)
            out.push_back(add(centre, add(mul(e1, rho * cs[0]), mul(e2, rho * cs[1]))));
        for (const P3& dir : kDirs) {
            const P3 q = perp(dir, u);
            const double len = std::sqrt(dot(q, q));
            if (len > 1e-12) out.push_back(add(centre, mul(q, rho / len)));
        }
    };
    const double corner = s.flute ? std::clamp(c.corner, 0.0, c.radius) : 0;
    const double from = s.base + corner, step = s.flute ? 0.5 : 1.0;
    const int count = std::max(1, int(std::ceil((t1 - from) / step)));
    for (int k = 0; k <= count; ++k) ring(from + (t1 - from) * k / count, s.radius, 48);
    if (!s.flute) return out;
    // The end: its flat (rings every mm), the corner's profile, and the
    // corner's outermost points towards the axes' directions.
    const double inner = c.radius - corner;
    const int flat = int(std::ceil(inner));
    for (int j = 0; j < flat; ++j) ring(0, inner * j / flat, 24);
    if (corner <= 0) return out;
    for (int j = 0; j <= 8; ++j) ring(corner * j / 8, c.slice(corner * j / 8), 48);
    for (const P3& dir : kDirs) {
        if (dot(dir, u) >= 0) continue;  // the top ring holds it
        const P3 q = perp(dir, u);
        const double len = std::sqrt(dot(q, q));
        P3 p = mul(u, corner);
        if (len > 1e-12) p = add(p, mul(q, inner / len));
        out.push_back(add(p, mul(dir, corner)));
    }
    return out;
}

}  // namespace pupitre::workshop::tilt
