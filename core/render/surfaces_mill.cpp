// The machining centre's surfaces painted (see surfaces.hpp): the block's
// cells coloured, then gathered into coarser levels for the views that
// see it from afar; the work-holding and the table as one coarse height
// field. A dimension's surface is found from where its instrument reads:
// the floor or top around the depth gauge's or the micrometer's point
// (flooded while level), the walls a caliper's width rests on, the outer
// faces of a length.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/render/surfaces.hpp"

namespace pupitre::render {

namespace {

constexpr float kLevel = 1.5e-3f;  // mm: cells this close in height are one floor

struct Grid {
    const MillScene& m;
    bool in(int i, int j) const { return i >= 0 && j >= 0 && i < m.nx && j < m.ny; }
    size_t at(int i, int j) const { return size_t(j) * size_t(m.nx) + size_t(i); }
    int ci(double x) const { return int(std::floor((x - m.stock.lo[0]) / m.cell)); }
    int cj(double y) const { return int(std::floor((y - m.stock.lo[1]) / m.cell)); }
};

// Cells 4-connected to (i, j) for which `keep(cell)` holds.
template <class Keep>
std::vector<size_t> flood(const Grid& g, int i, int j, Keep keep) {
    std::vector<size_t> out;
    if (!g.in(i, j) || !keep(g.at(i, j))) return out;
    std::vector<uint8_t> seen(size_t(g.m.nx) * size_t(g.m.ny), 0);
    std::vector<std::array<int, 2>> todo{{i, j}};
    seen[g.at(i, j)] = 1;
    while (!todo.empty()) {
        auto [a, b] = todo.back();
        todo.pop_back();
        out.push_back(g.at(a, b));
        for (auto [da, db] : {std::array{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            const int x = a + da, y = b + db;
            if (!g.in(x, y) || seen[g.at(x, y)] || !keep(g.at(x, y))) continue;
            seen[g.at(x, y)] = 1;
            todo.push_back({x, y});
        }
    }
    return out;
}

// The cells of the surface a mill dimension reads.
std::vector<size_t> mill_surface(const MillScene& m, const DimReading& d) {
    const Grid g{m};
    const std::string& w = d.place.word;
    const auto& p = d.place.at;
    const int i = g.ci(p[0]), j = g.cj(p[1]);
    if (w == "depth" || w == "height") {
        if (!g.in(i, j)) return {};
        const float h0 = m.h(i, j);
        return flood(g, i, j, [&](size_t c) { return std::abs(m.height[c] - h0) <= kLevel; });
    }
    const int axis = d.place.axis;
    const float z = float(p[2]);
    std::vector<size_t> out;
    auto material = [&](int a, int b) { return g.in(a, b) && m.h(a, b) >= z; };
    if (w == "width") {
        const auto gap = flood(g, i, j, [&](size_t c) { return m.height[c] < z; });
        for (size_t c : gap) {
            const int a = int(c % size_t(m.nx)), b = int(c / size_t(m.nx));
            for (int s : {-1, 1}) {
                const int x = a + (axis == 0 ? s : 0), y = b + (axis == 1 ? s : 0);
                if (material(x, y)) out.push_back(g.at(x, y));
            }
        }
    } else if (w == "length") {
        // The outer faces: material cells with nothing beyond them along
        // the axis, at the first and last material of the line read.
        int first = -1, last = -1;
        const int n = axis == 0 ? m.nx : m.ny;
        for (int k = 0; k < n; ++k)
            if (axis == 0 ? material(k, j) : material(i, k)) {
                if (first < 0) first = k;
                last = k;
            }
        if (first < 0) return {};
        for (int b = 0; b < m.ny; ++b)
            for (int a = 0; a < m.nx; ++a) {
                if (!material(a, b)) continue;
                const int k = axis == 0 ? a : b;
                const bool low = !(axis == 0 ? material(a - 1, b) : material(a, b - 1));
                const bool high = !(axis == 0 ? material(a + 1, b) : material(a, b + 1));
                if ((low && std::abs(k - first) <= 1) || (high && std::abs(k - last) <= 1))
                    out.push_back(g.at(a, b));
            }
    }
    return out;
}

// Each level half the cells of the one before, its highest top and that
// top's colour.
void coarser(std::vector<Level>& levels) {
    while (levels.back().nx > 1 || levels.back().ny > 1) {
        const Level& f = levels.back();
        Level c;
        c.nx = (f.nx + 1) / 2, c.ny = (f.ny + 1) / 2;
        c.cell = f.cell * 2, c.x0 = f.x0, c.y0 = f.y0;
        c.h.resize(size_t(c.nx) * size_t(c.ny));
        c.c.resize(c.h.size());
        for (int j = 0; j < c.ny; ++j)
            for (int i = 0; i < c.nx; ++i) {
                float best = -1e30f;
                Colour col = 0;
                for (int b = 2 * j; b < std::min(2 * j + 2, f.ny); ++b)
                    for (int a = 2 * i; a < std::min(2 * i + 2, f.nx); ++a)
                        if (f.at(a, b) > best) best = f.at(a, b), col = f.colour(a, b);
                c.h[size_t(j) * size_t(c.nx) + size_t(i)] = best;
                c.c[size_t(j) * size_t(c.nx) + size_t(i)] = col;
            }
        levels.push_back(std::move(c));
    }
}

// The vice or the plate, the pins and the table around the block: one
// height field of about 1 mm cells, 60 mm beyond the block at most.
void work_holding(const MillScene& m, Level& a, const Palette& pal) {
    const double margin = 60;
    double x0 = m.stock.lo[0] - margin, y0 = m.stock.lo[1] - margin;
    double x1 = m.stock.hi[0] + margin, y1 = m.stock.hi[1] + margin;
    a.cell = std::max(0.5, std::max(x1 - x0, y1 - y0) / 400);
    a.x0 = x0, a.y0 = y0;
    a.nx = int(std::ceil((x1 - x0) / a.cell)), a.ny = int(std::ceil((y1 - y0) / a.cell));
    a.h.assign(size_t(a.nx) * size_t(a.ny), float(m.table_z));
    a.c.assign(a.h.size(), pal.table);
    auto put = [&](double bx0, double by0, double bx1, double by1, double top, Colour c,
                   const workshop::Cylinder* pin) {
        for (int j = std::max(0, int((by0 - y0) / a.cell)); j < a.ny; ++j) {
            const double y = y0 + (j + 0.5) * a.cell;
            if (y > by1) break;
            for (int i = std::max(0, int((bx0 - x0) / a.cell)); i < a.nx; ++i) {
                const double x = x0 + (i + 0.5) * a.cell;
                if (x > bx1) break;
                if (x < bx0 || y < by0) continue;
                if (pin && std::hypot(x - pin->x, y - pin->y) > pin->radius) continue;
                const size_t k = size_t(j) * size_t(a.nx) + size_t(i);
                if (top > a.h[k]) a.h[k] = float(top), a.c[k] = c;
            }
        }
    };
    for (const workshop::Box3& b : m.boxes)
        put(b.lo[0], b.lo[1], b.hi[0], b.hi[1], b.hi[2], pal.vice, nullptr);
    for (const workshop::Cylinder& k : m.pins)
        put(k.x - k.radius, k.y - k.radius, k.x + k.radius, k.y + k.radius, k.z1, pal.pin, &k);
}

}  // namespace

void mill_surfaces(const PartScene& s, Surfaces& out, bool paper) {
    const MillScene& m = s.block;
    const double top = m.stock.hi[2], bottom = m.stock.lo[2];
    double deepest = 0;
    for (float h : m.height) deepest = std::max(deepest, top - h);
    out.legend = legend_of(s, out.paint, round_up(std::min(deepest, top - bottom)));
    Level l0;
    l0.nx = m.nx, l0.ny = m.ny, l0.cell = m.cell, l0.x0 = m.stock.lo[0], l0.y0 = m.stock.lo[1];
    l0.h = m.height;
    l0.c.resize(l0.h.size());
    // The depth scale in 1024 steps (a table: a million cells).
    std::array<Colour, 1025> ramp;
    for (size_t k = 0; k < ramp.size(); ++k) ramp[k] = depth_colour(double(k) / 1024);
    const double per_step = 1024 / out.legend.depth;
    for (size_t k = 0; k < l0.h.size(); ++k) {
        const double d = top - l0.h[k];
        l0.c[k] = out.paint == Paint::deviation ? kUnmarked
                  : d < 5e-4                    ? kUncut
                             : ramp[size_t(std::min(d * per_step + 0.5, 1024.0))];
    }
    out.anchor.assign(s.dims.size(), {kNaN, kNaN, kNaN});
    for (size_t i = 0; out.paint == Paint::deviation && i < s.dims.size(); ++i) {
        const DimReading& d = s.dims[i];
        if (!d.read) continue;
        const std::vector<size_t> cells = mill_surface(m, d);
        const Colour c = reading_colour(d, out.legend.span_um);
        for (size_t k : cells) l0.c[k] = c;
        // The label points where the instrument read: on the material's top
        // there (a width: at its Z, in the gap).
        const auto& p = d.place.at;
        const int ci = std::clamp(int((p[0] - m.stock.lo[0]) / m.cell), 0, m.nx - 1);
        const int cj = std::clamp(int((p[1] - m.stock.lo[1]) / m.cell), 0, m.ny - 1);
        double z = double(m.h(ci, cj)), x = p[0], y = p[1];
        if (d.place.word == "width") {
            // On the wall the caliper's jaw rests on, along +X or +Y.
            z = p[2];
            int a = ci, b = cj;
            const int ax = d.place.axis == 0 ? 1 : 0, ay = 1 - ax;
            while (a + ax < m.nx && b + ay < m.ny && m.h(a, b) < z) a += ax, b += ay;
            if (ax) x = m.stock.lo[0] + a * m.cell;
            if (ay) y = m.stock.lo[1] + b * m.cell;
        }
        out.anchor[i] = {x, y, z};
    }
    out.block.push_back(std::move(l0));
    coarser(out.block);
    work_holding(m, out.around, palette(paper));
}

}  // namespace pupitre::render
