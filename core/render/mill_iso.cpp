// The machining centre's block in 3-D (see part_view.hpp), seen along a
// direction turned by `yaw` and tilted `pitch` above the horizon, without
// perspective. The height field is marched from the front to the back
// along each column of pixels, as terrain renderers do: a sample fills the
// rows between the highest drawn so far and its own top, so the cost is
// the picture's size, not the block's cells (a level of detail of about a
// pixel is read). A depth buffer left beside it lets the cutter, drawn
// after as points of its surface, hide and be hidden.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/geometry.hpp"
#include "core/render/mill_sample.hpp"
#include "core/render/part_view.hpp"

namespace pupitre::render {

namespace {

using Eigen::Vector3d;
using geometry::kPi;

struct Cam {
    Vector3d a, r, u, v, light;  // look (level), right, up, into the picture, towards the light
    double sp = 0, cp = 1;       // sin and cos of the pitch
    double s = 1, csx = 0, csy = 0;
    int w = 1, h = 1;
    V2 px(const Vector3d& p) const {
        return {(p.dot(r) - csx) / s + w / 2.0, h / 2.0 - (p.dot(u) - csy) / s};
    }
    double row_y(int y) const { return csy - (y + 0.5 - h / 2.0) * s; }  // a row's screen height
};

Cam camera(const MillScene& m, const Look& look, int w, int h) {
    Cam c;
    const double yaw = look.cam.yaw * kPi / 180, pitch = look.cam.pitch * kPi / 180;
    c.sp = std::sin(pitch), c.cp = std::cos(pitch);
    c.a = Vector3d(std::cos(yaw), std::sin(yaw), 0);
    c.r = Vector3d(std::sin(yaw), -std::cos(yaw), 0);
    c.u = Vector3d(c.sp * c.a.x(), c.sp * c.a.y(), c.cp);
    c.v = Vector3d(c.cp * c.a.x(), c.cp * c.a.y(), -c.sp);
    c.light = (-0.45 * c.r + 0.8 * Vector3d::UnitZ() - 0.4 * c.a).normalized();
    c.w = w, c.h = h;
    double lo[3], hi[3];
    mill_box(m, lo, hi);
    lo[2] = std::min(lo[2], m.table_z);
    double x0 = 1e18, x1 = -1e18, y0 = 1e18, y1 = -1e18;
    for (int k = 0; k < 12; ++k) {
        const Vector3d p(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]);
        x0 = std::min(x0, p.dot(c.r)), x1 = std::max(x1, p.dot(c.r));
        y0 = std::min(y0, p.dot(c.u)), y1 = std::max(y1, p.dot(c.u));
    }
    c.s = std::max((x1 - x0) / w, (y1 - y0) / h) * 1.08 / look.cam.zoom;
    c.csx = (x0 + x1) / 2 - look.cam.pan_x * w * c.s;
    c.csy = (y0 + y1) / 2 - look.cam.pan_y * h * c.s;
    return c;
}

double lit(const Cam& c, const Vector3d& n) {
    return 0.3 + 0.8 * std::max(0.0, n.dot(c.light));
}

// The wall the march met between `t0` and `t1` along the column's line
// (x0 + t a): where it enters the top `t` (bisected), and which side of
// that cell it lies on, across X or Y.
Vector3d wall_normal(const Cam& c, const MillSampler& sample, double bx, double by, double t0,
                     double t1, const Top& t) {
    Top q;
    for (int k = 0; k < 12; ++k) {
        const double mid = (t0 + t1) / 2;
        const bool high =
            sample.at(bx + mid * c.a.x(), by + mid * c.a.y(), q) && q.h >= t.h - 1e-3f;
        (high ? t1 : t0) = mid;
    }
    const Level& l = *t.level;
    const int sx = c.a.x() > 0 ? 1 : -1, sy = c.a.y() > 0 ? 1 : -1;
    auto lower = [&](int i, int j) {
        return i < 0 || j < 0 || i >= l.nx || j >= l.ny || l.at(i, j) < t.h - 1e-3f;
    };
    const bool x = lower(t.i - sx, t.j), y = lower(t.i, t.j - sy);
    bool across_x = x;
    if (x == y) {
        const double fx = (bx + t1 * c.a.x() - l.x0) / l.cell;
        const double fy = (by + t1 * c.a.y() - l.y0) / l.cell;
        across_x = std::abs(fx - std::round(fx)) < std::abs(fy - std::round(fy));
    }
    return across_x ? Vector3d(-sx, 0, 0) : Vector3d(0, -sy, 0);
}

// The least integer not below v (std::ceil is a library call on a
// plain x86-64 build).
inline int ceil_int(double v) {
    const int i = int(v);
    return i + (v > i);
}

// One column of pixels, front to back.
void column(const Cam& c, const MillSampler& sample, double t0, double t1, double floor_z, int x,
            Image& img, std::vector<float>& zbuf) {
    const double sx = c.csx + (x + 0.5 - c.w / 2.0) * c.s;
    const double bx = sx * c.r.x(), by = sx * c.r.y();
    // A step moves the top's projection by at most 0.9 pixel (sp dt).
    const double dt = std::min(0.9 * c.s / c.sp, 3 * c.s);
    const double inv_s = 1 / c.s, row0 = c.csy * inv_s + c.h / 2.0 - 0.5;
    int filled = c.h;  // rows from here down are drawn
    float before = -std::numeric_limits<float>::infinity();
    Top t;
    // The last cell lit, and its colour: a cell spans several steps.
    const Level* lit_level = nullptr;
    int lit_i = -1, lit_j = -1;
    Colour top_c = 0;
    for (double tt = t0; tt <= t1 && filled > 0; tt += dt) {
        if (!sample.at(bx + tt * c.a.x(), by + tt * c.a.y(), t)) {
            before = -std::numeric_limits<float>::infinity();
            continue;
        }
        const int first = std::max(0, ceil_int(row0 - (c.sp * tt + c.cp * t.h) * inv_s));
        int last = filled;
        if (std::isinf(before))  // the scene's front: a slab, not a wall to the picture's foot
            last = std::min(last, ceil_int(row0 - (c.sp * tt + c.cp * floor_z) * inv_s));
        if (first < last) {
            if (t.level != lit_level || t.i != lit_i || t.j != lit_j) {
                sample.slope(t);
                top_c = shade(t.c, lit(c, Vector3d(-t.gx, -t.gy, 1).normalized()));
                lit_level = t.level, lit_i = t.i, lit_j = t.j;
            }
            const bool step = t.h - before > 1.5 * dt && last - first > 1;
            const Colour wall_c =
                step ? shade(t.c, lit(c, std::isinf(before)
                                             ? Vector3d(-c.a)
                                             : wall_normal(c, sample, bx, by, tt - dt, tt, t)))
                     : top_c;
            for (int y = first; y < last; ++y) {
                img.set(x, y, y == first ? top_c : wall_c);
                const double hy = (c.row_y(y) - c.sp * tt) / c.cp;
                zbuf[size_t(y) * size_t(c.w) + size_t(x)] = float(c.cp * tt - c.sp * hy);
            }
        }
        filled = std::min(filled, first);
        before = t.h;
    }
}

void terrain(const MillScene& m, const Surfaces& sf, const Cam& c, Image& img,
             std::vector<float>& zbuf) {
    const Level& ar = sf.around;
    double t0 = 1e18, t1 = -1e18;
    for (int k = 0; k < 4; ++k) {
        const double x = ar.x0 + (k & 1 ? ar.nx * ar.cell : 0);
        const double y = ar.y0 + (k & 2 ? ar.ny * ar.cell : 0);
        const double t = x * c.a.x() + y * c.a.y();
        t0 = std::min(t0, t), t1 = std::max(t1, t);
    }
    // Cells half a step wide: a wall seen aslant stays straight, not combed.
    // Only where a top can show on the picture: with every top between the
    // floor's and the highest, sp t + cp h lies within the picture's rows.
    double lo[3], hi[3];
    mill_box(m, lo, hi);
    const double floor_z = m.table_z - 15, top_z = std::max(hi[2], m.tip[2]);
    const double y_top = c.csy + c.h / 2.0 * c.s, y_bottom = c.csy - c.h / 2.0 * c.s;
    t0 = std::max(t0, (y_bottom - c.cp * top_z) / c.sp - c.s);
    t1 = std::min(t1, (y_top - c.cp * floor_z) / c.sp + c.s);
    const MillSampler sample(m, sf, c.s / 2, true);
    for (int x = 0; x < c.w; ++x) column(c, sample, t0, t1, floor_z, x, img, zbuf);
}

// The cutter and its holder as a solid of revolution about its axis u from
// the tip: the flute (a ball at its end when it is a ball end; a bull
// nose's corner is too small to tell), the shank, the holder, and their
// flat ends. Each pixel of its box casts the eye's ray at them.
struct Tool {
    Vector3d tip, u;
    double r, ball, reach, holder, top, flute;
};

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    Vector3d n;
    double h = 0;  // how far above the tip
};

// The ray p + t d against the cylinder of radius `rho` about the axis,
// between h0 and h1 above the tip.
void cylinder(const Tool& k, const Vector3d& p, const Vector3d& d, double rho, double h0, double h1,
              Hit& hit) {
    const Vector3d w = p - k.tip;
    const Vector3d dp = d - d.dot(k.u) * k.u, wp = w - w.dot(k.u) * k.u;
    const double a = dp.squaredNorm(), b = 2 * wp.dot(dp), cc = wp.squaredNorm() - rho * rho;
    const double disc = b * b - 4 * a * cc;
    if (a < 1e-12 || disc < 0) return;
    const double t = (-b - std::sqrt(disc)) / (2 * a);
    const double h = (w + t * d).dot(k.u);
    if (t >= hit.t || h < h0 || h > h1) return;
    hit.t = t, hit.h = h, hit.n = (wp + t * dp).normalized();
}

// The disc (or ring, from r0 to r1) square to the axis at h above the tip.
void disc(const Tool& k, const Vector3d& p, const Vector3d& d, double h, double r0, double r1,
          double facing, Hit& hit) {
    const double du = d.dot(k.u);
    if (std::abs(du) < 1e-12) return;
    const double t = (h - (p - k.tip).dot(k.u)) / du;
    if (t >= hit.t) return;
    const Vector3d q = p + t * d - k.tip - h * k.u;
    const double r = q.norm();
    if (r < r0 || r > r1) return;
    hit.t = t, hit.h = h, hit.n = facing * k.u;
}

void sphere(const Tool& k, const Vector3d& p, const Vector3d& d, Hit& hit) {
    const Vector3d w = p - (k.tip + k.ball * k.u);
    const double b = w.dot(d), cc = w.squaredNorm() - k.ball * k.ball, disc = b * b - cc;
    if (disc < 0) return;
    const double t = -b - std::sqrt(disc);
    const Vector3d q = w + t * d;
    if (t >= hit.t || q.dot(k.u) > 0) return;
    hit.t = t, hit.h = (p + t * d - k.tip).dot(k.u), hit.n = q.normalized();
}

void cutter(const MillScene& m, const Cam& c, const Palette& pal, Image& img,
            std::vector<float>& zbuf) {
    if (!m.has_cutter) return;
    Tool k;
    k.u = Vector3d(m.axis[0], m.axis[1], m.axis[2]).normalized();
    k.tip = Vector3d(m.tip[0], m.tip[1], m.tip[2]);
    k.r = m.cutter.radius, k.reach = m.cutter.reach, k.holder = m.cutter.holder;
    k.ball = m.cutter.corner >= m.cutter.radius - 1e-9 ? m.cutter.radius : 0;
    k.top = k.reach + 60, k.flute = m.cutter.flute;
    // Its box on the picture.
    const Vector3d e1 = k.u.unitOrthogonal(), e2 = k.u.cross(e1);
    double x0 = 1e18, x1 = -1e18, y0 = 1e18, y1 = -1e18;
    for (int n = 0; n < 8; ++n) {
        const V2 q = c.px(k.tip + (n & 4 ? k.top : 0) * k.u + (n & 1 ? 1 : -1) * k.holder * e1 +
                          (n & 2 ? 1 : -1) * k.holder * e2);
        x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]), y0 = std::min(y0, q[1]),
        y1 = std::max(y1, q[1]);
    }
    const double front = k.tip.dot(c.v) - k.top - 2 * k.holder;
    for (int y = std::max(0, int(y0)); y <= std::min(c.h - 1, int(y1)); ++y)
        for (int x = std::max(0, int(x0)); x <= std::min(c.w - 1, int(x1)); ++x) {
            const double sx = c.csx + (x + 0.5 - c.w / 2.0) * c.s;
            const Vector3d p = sx * c.r + c.row_y(y) * c.u + front * c.v;
            Hit hit;
            cylinder(k, p, c.v, k.r, k.ball, k.reach, hit);
            cylinder(k, p, c.v, k.holder, k.reach, k.top, hit);
            if (k.ball > 0)
                sphere(k, p, c.v, hit);
            else
                disc(k, p, c.v, 0, 0, k.r, -1, hit);
            disc(k, p, c.v, k.reach, k.r, k.holder, -1, hit);
            disc(k, p, c.v, k.top, 0, k.holder, 1, hit);
            if (!std::isfinite(hit.t)) continue;
            const double depth = (p + hit.t * c.v).dot(c.v);
            float& z = zbuf[size_t(y) * size_t(c.w) + size_t(x)];
            if (depth >= z) continue;
            z = float(depth);
            const Colour base = hit.h < k.flute   ? pal.cutter
                                : hit.h < k.reach ? shade(pal.cutter, 0.8)
                                                  : pal.cutter_holder;
            img.set(x, y, shade(base, 0.35 + 0.75 * std::max(0.0, hit.n.dot(c.light))));
        }
}

}  // namespace

void mill_iso(const PartScene& s, const Surfaces& sf, const Look& look, Picture& p) {
    const MillScene& m = s.block;
    Image& img = p.image;
    const Cam c = camera(m, look, img.w(), img.h());
    p.mm_per_px = c.s;
    std::vector<float> zbuf(size_t(img.w()) * size_t(img.h()),
                            std::numeric_limits<float>::infinity());
    terrain(m, sf, c, img, zbuf);
    cutter(m, c, palette(look.paper), img, zbuf);
    for (size_t i = 0; i < sf.anchor.size() && i < p.anchor.size(); ++i)
        if (!std::isnan(sf.anchor[i][0]))
            p.anchor[i] = c.px(Vector3d(sf.anchor[i][0], sf.anchor[i][1], sf.anchor[i][2]));
}

}  // namespace pupitre::render
