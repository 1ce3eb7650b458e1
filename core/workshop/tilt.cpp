// A tilted cutter's geometry (see tilt.hpp).
//
// The volume a flat end sweeps is the end's disc, square to u, added to the
// half strip {a + l u + t d : l >= 0, 0 <= t <= 1}: a point is in it when,
// for some t, it is above the end (axial) and within r of the axis (radial).
// Along a line o + s e that is a convex region of the plane (s, t): for each
// t the radial condition is a quadratic in s, whose lower root is convex in
// t and upper root concave, and the axial one a half plane. So the line's
// interval is found by one-dimensional convex searches over t
// (golden_min, narrow.hpp), without sampling.
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
// (pi / n)² inner r / (2 c)).
int ring_count(double inner, double radius, double corner) {
    const double step = std::sqrt(2 * 5e-4 * corner / (inner * radius));
    return std::clamp(int(std::ceil(M_PI / step)), 8, 1000);
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

Span swept_flat(const P3& a, const P3& d, const P3& u, double r, const Line& l, double tol) {
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
    // For each t the radial roots are (-beta(t) -+ sqrt(disc(t))) / alpha,
    // beta(t) = b0 - t b1 and disc(t) = A0 + A1 t + A2 t² (A2 <= 0).
    const double b1 = dot(pe, pd), pww = dot(pw, pw), pwd = dot(pw, pd), pdd = dot(pd, pd);
    const double A2 = b1 * b1 - alpha * pdd, A1 = 2 * (alpha * pwd - b0 * b1),
                 A0 = b0 * b0 - alpha * (pww - r * r);
    double t0 = 0, t1 = 1;
    if (!quad_le(std::max(0.0, -A2), -A1, -A0, t0, t1)) return out;
    const double tt = std::max(1e-15, tol / std::sqrt(dot(d, d)));
    auto root = [&](double t) { return std::sqrt(std::max(0.0, A0 + t * (A1 + t * A2))); };
    auto low = [&](double t) { return (t * b1 - b0 - root(t)) / alpha; };
    auto high = [&](double t) { return (t * b1 - b0 + root(t)) / alpha; };
    auto top = [&](double f0, double f1, auto f) {
        return -golden_min([&](double t) { return -f(t); }, f0, f1, tt).second;
    };
    if (std::abs(k) < 1e-12) {
        // The line square to the axis: only the t where it is above the end.
        if (!narrow(h0, -m, 0, kInf, t0, t1)) return out;
        return {golden_min(low, t0, t1, tt).second, top(t0, t1, high)};
    }
    // s >= bound(t) (k > 0) or s <= bound(t) (k < 0): the axial half plane.
    auto bound = [&](double t) { return (t * m - h0) / k; };
    auto room = [&](double t) { return k > 0 ? high(t) - bound(t) : bound(t) - low(t); };
    const auto [tm, least] = golden_min([&](double t) { return -room(t); }, t0, t1, tt);
    if (least > 0) return out;
    const double f0 = room(t0) >= 0 ? t0 : crossing(room, tm, t0, tt);
    const double f1 = room(t1) >= 0 ? t1 : crossing(room, tm, t1, tt);
    if (k > 0)
        return {golden_min([&](double t) { return std::max(low(t), bound(t)); }, f0, f1, tt).second,
                top(f0, f1, high)};
    return {golden_min(low, f0, f1, tt).second,
            top(f0, f1, [&](double t) { return std::min(high(t), bound(t)); })};
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
                  const Line& l, double tol) {
    const double c = std::clamp(corner, 0.0, radius);
    if (c <= 0) return swept_flat(a, d, u, radius, l, tol);
    // Above the corner the cutter is a flat end of its full radius.
    const P3 centre = add(a, mul(u, c));
    Span out = swept_flat(centre, d, u, radius, l, tol);
    const double inner = radius - c;
    if (inner <= 1e-9) {
        out.hull(capsule(centre, d, c, l));  // a ball end
        return out;
    }
    out.hull(swept_flat(a, d, u, inner, l, tol));  // the flat of the end
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
    Span out = s.flute ? swept_cutter(c.radius, c.corner, tip, still, u, l, 0)
                       : swept_flat(add(tip, mul(u, s.base)), still, u, s.radius, l, 0);
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
    auto ring = [&](double h, double rho, int n) {
        const P3 centre = mul(u, h);
        if (rho <= 0) {
            out.push_back(centre);
            return;
        }
        for (int i = 0; i < n; ++i) {
            const double phi = 2 * M_PI * i / n;
            out.push_back(
                add(centre, add(mul(e1, rho * std::cos(phi)), mul(e2, rho * std::sin(phi)))));
        }
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
