// The machining centre's material measured (see mill_part.hpp): the
// instruments' lines through the strokes, how deep a cutter is into the
// material or a fixture, and where a move first comes into it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/workshop/mill_part.hpp"
#include "core/workshop/narrow.hpp"

namespace pupitre::workshop {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One part of the cutter: its radius, its lowest surface above the tip (the
// flute adds bottom(d)) and its top above the tip.
// How deep the part is into a column of material from below up to `h`
// whose nearest point is `d` from the axis (`inside`: the axis is in the
// column's footprint, `edge` from its nearest side, which adds to the
// horizontal overlap).
double column(const Cutter& c, const PartSpan& s, const P3& tip, double h, double d,
              double edge = 0) {
    if (d >= s.radius) return 0;
    const double base = tip[2] + s.base + (s.flute ? c.bottom(std::min(d, c.radius)) : 0);
    const double v = h - base;
    if (v <= 0) return 0;
    const double u = std::min(h - tip[2], s.top);
    const double w = (s.flute ? c.slice(u) : s.radius) - d + edge;
    return w > 0 ? std::min(v, w) : 0;
}

double sq(double v) {
    return v * v;
}

// The distance from (x, y) to the rectangle [x0, x1] x [y0, y1] (0 inside).
double to_rect(double x, double y, double x0, double x1, double y0, double y1) {
    const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
    return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

std::vector<std::array<double, 2>> MillWorld::along(int axis, const P3& at) const {
    if (axis < 0 || axis > 2) return {};
    for (int k = 0; k < 3; ++k)
        if (k != axis && !(at[k] >= stock_.lo[k] && at[k] <= stock_.hi[k])) return {};
    const double s0 = stock_.lo[axis], s1 = stock_.hi[axis];
    auto bucket = [&](int k, int n) {
        return std::clamp(int(std::floor((at[k] - stock_.lo[k]) / bucket_)), 0, n - 1);
    };
    // The buckets the line crosses: a row, a column, or one.
    const int bi = bucket(0, bx_), bj = bucket(1, by_);
    int i0 = bi, i1 = bi, j0 = bj, j1 = bj;
    if (axis == 0) i0 = 0, i1 = bx_ - 1;
    if (axis == 1) j0 = 0, j1 = by_ - 1;
    std::vector<std::array<double, 2>> cuts;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            for (uint32_t k : buckets_[size_t(j) * size_t(bx_) + size_t(i)]) {
                const Stroke& s = strokes_[k];
                // Once per line: in the first of its buckets the line meets.
                if ((axis == 0 && std::max(s.bi, i0) != i) ||
                    (axis == 1 && std::max(s.bj, j0) != j))
                    continue;
                if (axis != 2 && at[2] < s.reach.lo[2]) continue;
                double lo, hi;
                if (removal(s, axis, at, lo, hi) && lo < s1 && hi > s0) cuts.push_back({lo, hi});
            }
    std::sort(cuts.begin(), cuts.end());
    // The stock's interval minus the (merged) removals.
    std::vector<std::array<double, 2>> out;
    double from = s0;
    for (size_t n = 0; n < cuts.size() && from < s1;) {
        double lo = cuts[n][0], hi = cuts[n][1];
        for (++n; n < cuts.size() && cuts[n][0] <= hi; ++n) hi = std::max(hi, cuts[n][1]);
        if (lo > from) out.push_back({from, lo});
        from = std::max(from, hi);
    }
    if (from < s1) out.push_back({from, s1});
    return out;
}

bool MillWorld::cut_beside(int i, int j) const {
    for (int b = std::max(0, j - 1); b <= std::min(ny_ - 1, j + 1); ++b)
        for (int a = std::max(0, i - 1); a <= std::min(nx_ - 1, i + 1); ++a)
            if (touched_[size_t(b) * size_t(nx_) + size_t(a)]) return true;
    return false;
}

PartSpan span_of(const Cutter& c, Part part) {
    switch (part) {
        case Part::flute:
            break;
        case Part::shank:
            return {c.radius, c.flute, c.reach, false};
        case Part::holder:
            return {c.holder, c.reach, kInf, false};
    }
    return {c.radius, 0, c.flute, true};
}

// A column a tilted cutter went under is its pieces: a vertical part wholly
// under one (in the void) is clear of it.
double MillWorld::column_depth(const Cutter& c, const PartSpan& sh, const P3& tip, size_t cell,
                               double h, double d) const {
    const auto it = under_.empty() ? under_.end() : under_.find(cell);
    if (it == under_.end()) return column(c, sh, tip, h, d);
    double best = 0;
    for (const auto& g : it->second)
        if (tip[2] + sh.top > g[0]) best = std::max(best, column(c, sh, tip, g[1], d));
    return best;
}

double MillWorld::depth_into(const Cutter& c, const P3& tip, Part part, const P3& u) const {
    refresh();
    if (leans(u)) return tilted_depth(c, tip, u, part, kInf);
    return penetration(c, tip, part, kInf);
}

double MillWorld::penetration(const Cutter& c, const P3& tip, Part part, double above) const {
    const PartSpan sh = span_of(c, part);
    const double lox = stock_.lo[0], loy = stock_.lo[1], floor_z = stock_.lo[2];
    if (!(sh.radius > 0) || tip[2] + sh.top <= floor_z) return 0;
    auto cells = [&](double v, double lo, int n) {
        return std::clamp(int(std::floor((v - lo) / cell_)), 0, n - 1);
    };
    const int ci0 = cells(tip[0] - sh.radius, lox, nx_), ci1 = cells(tip[0] + sh.radius, lox, nx_);
    const int cj0 = cells(tip[1] - sh.radius, loy, ny_), cj1 = cells(tip[1] + sh.radius, loy, ny_);
    auto x_edge = [&](int i) { return std::min(lox + i * cell_, stock_.hi[0]); };
    auto y_edge = [&](int j) { return std::min(loy + j * cell_, stock_.hi[1]); };
    double best = 0;
    for (int tj = cj0 / kTile; tj <= cj1 / kTile; ++tj)
        for (int ti = ci0 / kTile; ti <= ci1 / kTile; ++ti) {
            // A tile that cannot beat what is found (or what is asked) is skipped.
            const double need = std::isinf(above) ? best : std::max(best, above);
            const double top = tile_max_[size_t(tj) * size_t(tx_) + size_t(ti)];
            const int i0 = std::max(ci0, ti * kTile), i1 = std::min(ci1, ti * kTile + kTile - 1);
            const int j0 = std::max(cj0, tj * kTile), j1 = std::min(cj1, tj * kTile + kTile - 1);
            if (top <= floor_z || i0 > i1 || j0 > j1) continue;
            const double dmin =
                to_rect(tip[0], tip[1], x_edge(i0), x_edge(i1 + 1), y_edge(j0), y_edge(j1 + 1));
            if (column(c, sh, tip, top, dmin) <= need) continue;
            for (int j = j0; j <= j1; ++j) {
                const size_t row = size_t(j) * size_t(nx_);
                const double y0 = y_edge(j), y1 = y_edge(j + 1), yc = ys_[size_t(j)];
                for (int i = i0; i <= i1; ++i) {
                    const double h = h_[row + size_t(i)];
                    if (h <= floor_z) continue;
                    // A cut cell is its centre. An uncut one is its square
                    // (so the stock's faces and top as loaded are exact),
                    // unless a neighbour is cut: a cut may have taken part
                    // of its square, so it is its centre too.
                    const double d =
                        touched_[row + size_t(i)] || cut_beside(i, j)
                            ? std::sqrt(sq(xs_[size_t(i)] - tip[0]) + sq(yc - tip[1]))
                            : to_rect(tip[0], tip[1], x_edge(i), x_edge(i + 1), y0, y1);
                    const double p = column_depth(c, sh, tip, row + size_t(i), h, d);
                    if (p > best) {
                        best = p;
                        if (best > above) return best;
                    }
                }
            }
        }
    return best;
}

// The stretches of the move (fractions, in order) where the part's box can
// meet a tile whose highest top is more than `depth` above the part's
// lowest surface: outside them the part is no deeper than `depth`.
std::vector<std::array<double, 2>> MillWorld::spans(const Cutter& c, const P3& a, const P3& b,
                                                    Part part, double depth) const {
    const PartSpan sh = span_of(c, part);
    const double lox = stock_.lo[0], loy = stock_.lo[1], floor_z = stock_.lo[2];
    const double r = sh.radius + 1e-9;
    std::vector<std::array<double, 2>> out;
    if (!(sh.radius > 0)) return out;
    auto tiles = [&](double v0, double v1, double lo, int n) {
        const double w = kTile * cell_;
        return std::array<int, 2>{std::clamp(int(std::floor((v0 - lo) / w)), 0, n - 1),
                                  std::clamp(int(std::floor((v1 - lo) / w)), 0, n - 1)};
    };
    const auto ti = tiles(std::min(a[0], b[0]) - r, std::max(a[0], b[0]) + r, lox, tx_);
    const auto tj = tiles(std::min(a[1], b[1]) - r, std::max(a[1], b[1]) + r, loy, ty_);
    const double zb = a[2] + sh.base, dz = b[2] - a[2];
    for (int j = tj[0]; j <= tj[1]; ++j)
        for (int i = ti[0]; i <= ti[1]; ++i) {
            const double top = tile_max_[size_t(j) * size_t(tx_) + size_t(i)];
            if (top <= floor_z) continue;
            const double x0 = lox + i * kTile * cell_, y0 = loy + j * kTile * cell_;
            const double x1 = std::min(x0 + kTile * cell_, stock_.hi[0]);
            const double y1 = std::min(y0 + kTile * cell_, stock_.hi[1]);
            double t0 = 0, t1 = 1;
            if (narrow(a[0], b[0] - a[0], x0 - r, x1 + r, t0, t1) &&
                narrow(a[1], b[1] - a[1], y0 - r, y1 + r, t0, t1) &&
                narrow(zb, dz, -kInf, top - depth + 1e-9, t0, t1) &&
                (std::isinf(sh.top) || narrow(a[2] + sh.top, dz, floor_z - 1e-9, kInf, t0, t1)))
                out.push_back({t0, t1});
        }
    std::sort(out.begin(), out.end());
    size_t m = 0;
    for (const auto& s : out)
        if (m > 0 && s[0] <= out[m - 1][1])
            out[m - 1][1] = std::max(out[m - 1][1], s[1]);
        else
            out[m++] = s;
    out.resize(m);
    return out;
}

double MillWorld::first_contact(const Cutter& c, const P3& a, const P3& b, Part part, double depth,
                                bool before, const P3& u) const {
    if (leans(u)) return tilted_first(c, a, b, u, part, depth, before);
    const double len = std::sqrt(sq(b[0] - a[0]) + sq(b[1] - a[1]) + sq(b[2] - a[2]));
    auto deeper = [&](double t) {
        const P3 p{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
        return penetration(c, p, part, depth) > depth;
    };
    refresh();
    if (deeper(0)) return 0;
    if (!(len > 0)) return 2;
    // March where the part can meet material, in steps no longer than a
    // cell (a wall a cell thick is not stepped over), then halve the step
    // between the last clear place and the first deep one.
    const double step = std::min(cell_, 0.25) / len;
    for (const auto& s : spans(c, a, b, part, depth))
        if (const double f = march(deeper, s[0], s[1], std::max(0.0, s[0] - step), step, len,
                                   kTravelTol, before);
            f <= 1)
            return f;
    return 2;
}

double depth_into(const Cutter& c, const P3& tip, Part part, const Box3& b) {
    const PartSpan sh = span_of(c, part);
    if (tip[2] + sh.top <= b.lo[2]) return 0;
    const double x = tip[0], y = tip[1];
    const double d = to_rect(x, y, b.lo[0], b.hi[0], b.lo[1], b.hi[1]);
    // The axis over the box: the part's section reaches past the nearest side.
    const double edge = d > 0 ? 0 : std::min({x - b.lo[0], b.hi[0] - x, y - b.lo[1], b.hi[1] - y});
    return column(c, sh, tip, b.hi[2], d, edge);
}

double depth_into(const Cutter& c, const P3& tip, Part part, const Cylinder& k) {
    const PartSpan sh = span_of(c, part);
    if (tip[2] + sh.top <= k.z0) return 0;
    const double axes = std::sqrt(sq(tip[0] - k.x) + sq(tip[1] - k.y));
    const double d = std::max(0.0, axes - k.radius);
    return column(c, sh, tip, k.z1, d, d > 0 ? 0 : k.radius - axes);
}

}  // namespace pupitre::workshop
