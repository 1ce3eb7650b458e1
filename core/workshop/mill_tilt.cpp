// The machining centre's material under a tilted cutter (B away from 0; see
// mill_part.hpp and tilt.hpp). A tilted cutter cuts a column of the height
// field from its side as well as from above: what it takes is the exact
// interval where the column's centre line crosses the volume it sweeps, and
// a column it went into under its top keeps its material as intervals
// (`under_`). Its contacts are found where it crosses the columns' centre
// lines, as a vertical cutter's on a face that was cut (to half a cell), and
// exactly on the stock's own faces where no cut came near.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/workshop/mill_part.hpp"
#include "core/workshop/narrow.hpp"
#include "core/workshop/tilt.hpp"

namespace pupitre::workshop {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Shorter than this (mm), what a cut leaves of a column is rounding.
constexpr double kSliver = 1e-9;

P3 lerp(const P3& a, const P3& b, double f) {
    return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

}  // namespace

void MillWorld::material(int i, int j, std::vector<std::array<double, 2>>& out) const {
    out.clear();
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return;
    const size_t cell = size_t(j) * size_t(nx_) + size_t(i);
    if (auto it = under_.find(cell); it != under_.end()) {
        out = it->second;
        return;
    }
    if (double(h_[cell]) > stock_.lo[2]) out.push_back({stock_.lo[2], double(h_[cell])});
}

double MillWorld::carve(size_t cell, double lo, double hi) {
    const double floor_z = stock_.lo[2];
    std::vector<std::array<double, 2>> was, left;
    if (auto it = under_.find(cell); it != under_.end())
        was = std::move(it->second);
    else if (double(h_[cell]) > floor_z)
        was.push_back({floor_z, double(h_[cell])});
    double taken = 0;
    for (const auto& g : was) {
        const double a = std::max(g[0], lo), b = std::min(g[1], hi);
        if (!(a < b)) {
            left.push_back(g);
            continue;
        }
        taken += b - a;
        if (a - g[0] > kSliver) left.push_back({g[0], a});
        if (g[1] - b > kSliver) left.push_back({b, g[1]});
    }
    h_[cell] = left.empty() ? float(floor_z) : float(left.back()[1]);
    if (left.empty() || (left.size() == 1 && left[0][0] <= floor_z))
        under_.erase(cell);
    else
        under_[cell] = std::move(left);
    return taken;
}

namespace {

// A lower bound of a tilted part's Z over a vertical line: a point of the
// part, tip + l u + w (w square to u, |w| <= radius), lies `delta` along the
// axis's lean from the tip horizontally with delta <= l |u_h| + radius u_z,
// and its Z is at least tip Z + l u_z - radius |u_h|. So a column whose top
// is under the bound at its place is clear of the part (u_z > 0; a part
// lying flat or pointing down has none).
struct Lowest {
    Lowest(const PartSpan& s, const P3& tip, const P3& u) : s_(s), tip_(tip), u_(u) {
        uh_ = std::hypot(u[0], u[1]);
    }
    // The least l of the part's points over the line.
    double least(double x, double y) const {
        double l = s_.base;
        if (uh_ > 1e-9) {
            const double delta = ((x - tip_[0]) * u_[0] + (y - tip_[1]) * u_[1]) / uh_;
            l = std::max(l, (delta - s_.radius * u_[2]) / uh_);
        }
        return l;
    }
    double at(double x, double y) const {
        if (!(u_[2] > 1e-6)) return -kInf;
        return tip_[2] + least(x, y) * u_[2] - s_.radius * uh_;
    }
    // Over a rectangle: the least of its corners' (the bound is monotonic
    // along the lean, the same across it).
    double over(double x0, double x1, double y0, double y1) const {
        return std::min({at(x0, y0), at(x0, y1), at(x1, y0), at(x1, y1)});
    }
    // Swept from this tip to the other's: each term at its least.
    double swept(const Lowest& o, double x, double y) const {
        if (!(u_[2] > 1e-6)) return -kInf;
        return std::min(tip_[2], o.tip_[2]) + std::min(least(x, y), o.least(x, y)) * u_[2] -
               s_.radius * uh_;
    }
    PartSpan s_;
    P3 tip_, u_;
    double uh_ = 0;
};

}  // namespace

double MillWorld::apply_tilted(const Stroke& s) {
    const double lox = stock_.lo[0], loy = stock_.lo[1], floor_z = stock_.lo[2];
    // The cells whose centres are within the stroke's reach.
    auto from = [&](double v, double lo, int n) {
        return std::clamp(int(std::floor((v - lo) / cell_ - 0.5)), 0, n - 1);
    };
    auto to = [&](double v, double lo, int n) {
        return std::clamp(int(std::ceil((v - lo) / cell_ - 0.5)), 0, n - 1);
    };
    const int i0 = from(s.reach.lo[0], lox, nx_), i1 = to(s.reach.hi[0], lox, nx_);
    const int j0 = from(s.reach.lo[1], loy, ny_), j1 = to(s.reach.hi[1], loy, ny_);
    const P3 d{s.b[0] - s.a[0], s.b[1] - s.a[1], s.b[2] - s.a[2]};
    // A column whose top is under the cutter all along is left alone.
    const PartSpan whole{s.radius, 0, kInf, true};
    const Lowest ends[2] = {Lowest(whole, s.a, s.u), Lowest(whole, s.b, s.u)};
    double removed = 0;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const size_t cell = size_t(j) * size_t(nx_) + size_t(i);
            const double top = h_[cell], x = xs_[size_t(i)], y = ys_[size_t(j)];
            if (top <= floor_z || top <= ends[0].swept(ends[1], x, y)) continue;
            tilt::Line l;
            l.o = {x, y, 0};
            const tilt::Span sp = tilt::swept_cutter(s.radius, s.corner, s.a, d, s.u, l);
            if (sp.empty() || sp.lo >= top || sp.hi <= floor_z) continue;
            touched_[cell] = 1;
            removed += carve(cell, sp.lo, sp.hi) * side(0, i) * side(1, j);
        }
    if (removed > 0) mark_stale(i0, i1, j0, j1);
    return removed;
}

namespace {

// How far above the tip a part is followed for the material: up to the
// stock's top (a part lying flat or pointing down, across the table).
double part_top(const Cutter& c, Part part, const P3& tip, const P3& u, double zmax) {
    const PartSpan s = span_of(c, part);
    if (u[2] <= 1e-6) return std::min(s.top, s.base + 2000);
    const double lean = s.radius * std::sqrt(std::max(0.0, 1 - u[2] * u[2]));
    return std::min(s.top, std::max(s.base, (zmax - tip[2] + lean) / u[2]));
}

}  // namespace

double MillWorld::tilted_depth(const Cutter& c, const P3& tip, const P3& u, Part part,
                               double above) const {
    const PartSpan sh = span_of(c, part);
    const double floor_z = stock_.lo[2];
    if (!(sh.radius > 0)) return 0;
    const Box3 bb = tilt::part_box(c, part, tip, u, part_top(c, part, tip, u, stock_.hi[2]));
    if (bb.lo[2] >= stock_.hi[2] || bb.hi[2] <= floor_z || bb.hi[0] < stock_.lo[0] ||
        bb.lo[0] > stock_.hi[0] || bb.hi[1] < stock_.lo[1] || bb.lo[1] > stock_.hi[1])
        return 0;
    auto cells = [&](double v, double lo, int n) {
        return std::clamp(int(std::floor((v - lo) / cell_)), 0, n - 1);
    };
    const int ci0 = cells(bb.lo[0], stock_.lo[0], nx_), ci1 = cells(bb.hi[0], stock_.lo[0], nx_);
    const int cj0 = cells(bb.lo[1], stock_.lo[1], ny_), cj1 = cells(bb.hi[1], stock_.lo[1], ny_);
    std::vector<std::array<double, 2>> segs;
    double best = stock_depth(surface_of(c, part, u), tip);
    if (best > above) return best;
    const Lowest low(sh, tip, u);
    for (int tj = cj0 / kTile; tj <= cj1 / kTile; ++tj)
        for (int ti = ci0 / kTile; ti <= ci1 / kTile; ++ti) {
            const int i0 = std::max(ci0, ti * kTile), i1 = std::min(ci1, ti * kTile + kTile - 1);
            const int j0 = std::max(cj0, tj * kTile), j1 = std::min(cj1, tj * kTile + kTile - 1);
            // A tile all below the part is clear of it.
            const double top = tile_max_[size_t(tj) * size_t(tx_) + size_t(ti)];
            if (top <= bb.lo[2] ||
                top <= low.over(xs_[size_t(i0)], xs_[size_t(i1)], ys_[size_t(j0)], ys_[size_t(j1)]))
                continue;
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    const double h = h_[size_t(j) * size_t(nx_) + size_t(i)];
                    const double x = xs_[size_t(i)], y = ys_[size_t(j)];
                    if (h <= floor_z || h <= bb.lo[2] || h <= low.at(x, y)) continue;
                    const double in = tilt::inset(sh, tip, u, x, y);
                    if (in <= best) continue;
                    tilt::Line l;
                    l.o = {x, y, 0};
                    const tilt::Span sp = tilt::part_span(c, part, tip, u, l);
                    if (sp.empty() || sp.lo >= h) continue;
                    material(i, j, segs);
                    for (const auto& g : segs) {
                        const double o = std::min(sp.hi, g[1]) - std::max(sp.lo, g[0]);
                        best = std::max(best, std::min(o, in));
                    }
                    if (best > above) return best;
                }
        }
    return best;
}

double MillWorld::tilted_first(const Cutter& c, const P3& a, const P3& b, const P3& u, Part part,
                               double depth, bool before) const {
    refresh();
    auto deeper = [&](double t) { return tilted_depth(c, lerp(a, b, t), u, part, depth) > depth; };
    if (deeper(0)) return 0;
    const double len = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    if (!(len > 0)) return 2;
    // Nothing to meet: the part stays above every top, or beside the stock.
    const double zmax = *std::max_element(tile_max_.begin(), tile_max_.end());
    const Box3 ba = tilt::part_box(c, part, a, u, part_top(c, part, a, u, zmax));
    const Box3 bb = tilt::part_box(c, part, b, u, part_top(c, part, b, u, zmax));
    if (std::min(ba.lo[2], bb.lo[2]) >= zmax) return 2;
    for (int k = 0; k < 2; ++k)
        if (std::max(ba.hi[k], bb.hi[k]) < stock_.lo[k] ||
            std::min(ba.lo[k], bb.lo[k]) > stock_.hi[k])
            return 2;
    // March in steps no longer than a cell, then halve the step between the
    // last clear place and the first deep one.
    const double step = std::min(cell_, 0.25) / len;
    return march(deeper, std::min(step, 1.0), 1.0, 0, step, len, kTravelTol, before);
}

const std::vector<P3>& MillWorld::surface_of(const Cutter& c, Part part, const P3& u) const {
    for (const Surface& s : surfaces_)
        if (!s.points.empty() && s.part == part && s.u == u && s.c.radius == c.radius &&
            s.c.corner == c.corner && s.c.flute == c.flute && s.c.reach == c.reach &&
            s.c.holder == c.holder)
            return s.points;
    Surface& s = surfaces_[next_surface_++ % surfaces_.size()];
    s.c = c, s.part = part, s.u = u;
    s.points = tilt::surface(c, part, u, followed(c, part));
    return s.points;
}

double MillWorld::stock_depth(const std::vector<P3>& points, const P3& tip) const {
    const Box3& b = stock_;
    double best = 0;
    for (const P3& q : points) {
        const double x = tip[0] + q[0], y = tip[1] + q[1], z = tip[2] + q[2];
        const double d = std::min(
            {x - b.lo[0], b.hi[0] - x, y - b.lo[1], b.hi[1] - y, z - b.lo[2], b.hi[2] - z});
        if (d <= best) continue;
        const int i = std::clamp(int(std::floor((x - b.lo[0]) / cell_)), 0, nx_ - 1);
        const int j = std::clamp(int(std::floor((y - b.lo[1]) / cell_)), 0, ny_ - 1);
        const size_t cell = size_t(j) * size_t(nx_) + size_t(i);
        if (touched_[cell] || cut_beside(i, j) || under_.count(cell)) continue;
        best = d;
    }
    return best;
}

double depth_into(const std::vector<P3>& points, const P3& tip, const Box3& b) {
    double best = 0;
    for (const P3& q : points) {
        const double x = tip[0] + q[0], y = tip[1] + q[1], z = tip[2] + q[2];
        best = std::max(best, std::min({x - b.lo[0], b.hi[0] - x, y - b.lo[1], b.hi[1] - y,
                                        z - b.lo[2], b.hi[2] - z}));
    }
    return best;
}

double depth_into(const std::vector<P3>& points, const P3& tip, const Cylinder& k) {
    double best = 0;
    for (const P3& q : points) {
        const double x = tip[0] + q[0], y = tip[1] + q[1], z = tip[2] + q[2];
        best =
            std::max(best, std::min({k.radius - std::hypot(x - k.x, y - k.y), z - k.z0, k.z1 - z}));
    }
    return best;
}

}  // namespace pupitre::workshop
