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

// One column of pixels, front to back.
void column(const Cam& c, const MillSampler& sample, double t0, double t1, double floor_z, int x,
            Image& img, std::vector<float>& zbuf) {
    const double sx = c.csx + (x + 0.5 - c.w / 2.0) * c.s;
    const double bx = sx * c.r.x(), by = sx * c.r.y();
    const double dt = c.s;
    int filled = c.h;  // rows from here down are drawn
    float before = -std::numeric_limits<float>::infinity();
    Top t;
    for (double tt = t0; tt <= t1 && filled > 0; tt += dt) {
        if (!sample.at(bx + tt * c.a.x(), by + tt * c.a.y(), t)) {
            before = -std::numeric_limits<float>::infinity();
            continue;
        }
        const double top = c.sp * tt + c.cp * t.h;
        const int first = std::max(0, int(std::ceil((c.csy - top) / c.s + c.h / 2.0 - 0.5)));
        int last = filled;
        if (std::isinf(before))  // the scene's front: a slab, not a wall to the picture's foot
            last = std::min(
                last, int(std::ceil((c.csy - c.sp * tt - c.cp * floor_z) / c.s + c.h / 2.0 - 0.5)));
        if (first < last) {
            const Vector3d n = Vector3d(-t.gx, -t.gy, 1).normalized();
            const Colour top_c = shade(t.c, lit(c, n));
            const bool step = t.h - before > 1.5 * dt;
            const Vector3d wn = step && !std::isinf(before)
                                    ? wall_normal(c, sample, bx, by, tt - dt, tt, t)
                                    : Vector3d(-c.a);
            const Colour wall_c = shade(t.c, lit(c, wn));
            for (int y = first; y < last; ++y) {
                img.set(x, y, y == first || !step ? top_c : wall_c);
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
    const MillSampler sample(m, sf, c.s / 2, true);
    for (int x = 0; x < c.w; ++x) column(c, sample, t0, t1, m.table_z - 15, x, img, zbuf);
}

// A point of a surface, drawn where it is the nearest.
void splat(const Cam& c, const Vector3d& p, Colour col, Image& img, std::vector<float>& zbuf) {
    const V2 q = c.px(p);
    const int x = int(std::floor(q[0])), y = int(std::floor(q[1]));
    if (x < 0 || y < 0 || x >= c.w || y >= c.h) return;
    float& z = zbuf[size_t(y) * size_t(c.w) + size_t(x)];
    const double d = p.dot(c.v);
    if (d >= z) return;
    z = float(d);
    img.set(x, y, col);
}

// The cutter and its holder as points of their surface (those facing the
// eye), half a pixel apart.
void cutter(const MillScene& m, const Cam& c, const Palette& pal, Image& img,
            std::vector<float>& zbuf) {
    if (!m.has_cutter) return;
    const Vector3d u = Vector3d(m.axis[0], m.axis[1], m.axis[2]).normalized();
    const Vector3d tip(m.tip[0], m.tip[1], m.tip[2]);
    const Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
    const double top = m.cutter.reach + 60;
    double step = c.s / 2;
    const double points = (top / step) * (kPi * m.cutter.holder / step);
    if (points > 2e6) step *= std::sqrt(points / 2e6);
    // The holder's top, where it faces the eye (seen from above).
    if (u.dot(c.v) < 0)
        for (double rho = 0; rho <= m.cutter.holder; rho += step) {
            const int n = std::max(8, int(std::ceil(2 * kPi * rho / step)));
            for (int k = 0; k < n; ++k) {
                const double phi = 2 * kPi * k / n;
                splat(c, tip + top * u + rho * (std::cos(phi) * e1 + std::sin(phi) * e2),
                      shade(pal.cutter_holder, 0.35 + 0.75 * std::max(0.0, u.dot(c.light))), img,
                      zbuf);
            }
        }
    for (double hh = 0; hh <= top; hh += step) {
        const double rho = hh < m.cutter.reach ? m.cutter.slice(hh) : m.cutter.holder;
        const Colour base = hh < m.cutter.flute   ? pal.cutter
                            : hh < m.cutter.reach ? shade(pal.cutter, 0.8)
                                                  : pal.cutter_holder;
        const int n = std::max(8, int(std::ceil(2 * kPi * rho / step)));
        for (int k = 0; k < n; ++k) {
            const double phi = 2 * kPi * k / n;
            const Vector3d dir = std::cos(phi) * e1 + std::sin(phi) * e2;
            if (dir.dot(c.v) > 0.05) continue;  // its back
            splat(c, tip + hh * u + rho * dir,
                  shade(base, 0.35 + 0.75 * std::max(0.0, dir.dot(c.light))), img, zbuf);
        }
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
