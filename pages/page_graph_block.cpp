// GRAPH on a machining centre with a workshop (pupitre-setup(5)): the block
// seen from above, each cell shaded by the height of the material under its
// centre, its outline drawn with the stock's ink; the moves go over it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "pages/page_graph.hpp"

namespace pupitre::pages {

bool shows_block(const GraphView& g) {
    return g.block && g.plane == PathPlane::xy;
}

void block_outline(const GraphView& g, const ViewXf& xf, DotRaster& r) {
    const workshop::Box3& b = g.block->stock();
    const double x0 = b.lo[0] + g.block_dx, x1 = b.hi[0] + g.block_dx;
    const double y0 = b.lo[1] + g.block_dy, y1 = b.hi[1] + g.block_dy;
    draw_line(r, xf, x0, y0, x1, y0, Ink::stock);
    draw_line(r, xf, x1, y0, x1, y1, Ink::stock);
    draw_line(r, xf, x1, y1, x0, y1, Ink::stock);
    draw_line(r, xf, x0, y1, x0, y0, Ink::stock);
}

namespace {

// The material's top under a world point of the view; false off the block.
bool height_at(const GraphView& g, double x, double y, double& z) {
    const workshop::MillWorld& w = *g.block;
    const workshop::Box3& b = w.stock();
    const double mx = x - g.block_dx - b.lo[0], my = y - g.block_dy - b.lo[1];
    const int i = int(std::floor(mx / w.cell())), j = int(std::floor(my / w.cell()));
    if (mx < 0 || my < 0 || i >= w.nx() || j >= w.ny()) return false;
    z = w.height(i, j);
    return true;
}

}  // namespace

// Four shades: the top as loaded, the shallower and the deeper half of what
// is cut (of the deepest cut in view), cut through. Brighter is higher.
void shade_block(const GraphView& g, const ViewXf& xf, Canvas& c, const Rect& a) {
    static constexpr char32_t kShade[] = {U'▓', U'▒', U'░', U' '};
    static constexpr char kAscii[] = {'#', '+', '.', ' '};
    const workshop::Box3& b = g.block->stock();
    const double top = b.hi[2], bottom = b.lo[2];
    std::vector<float> z(size_t(a.w) * size_t(a.h), float(top + 1));  // above: off the block
    double deepest = 0;
    for (int row = 0; row < a.h; ++row)
        for (int col = 0; col < a.w; ++col) {
            double h = 0;
            if (!height_at(g, xf.wx(2 * col + 0.5), xf.wy(4 * row + 1.5), h)) continue;
            z[size_t(row) * size_t(a.w) + size_t(col)] = float(h);
            deepest = std::max(deepest, top - h);
        }
    for (int row = 0; row < a.h; ++row)
        for (int col = 0; col < a.w; ++col) {
            const double h = z[size_t(row) * size_t(a.w) + size_t(col)];
            if (h > top + 0.5) continue;
            const double cut = top - h;
            const int k = cut < 1e-3                  ? 0
                          : h <= bottom + 1e-6        ? 3
                          : cut <= deepest / 2 + 1e-9 ? 1
                                                      : 2;
            if (c.ascii())
                c.put(a.x + col, a.y + row, char32_t(kAscii[k]), Style::dim);
            else
                c.put(a.x + col, a.y + row, kShade[k], Style::dim);
        }
}

}  // namespace pupitre::pages
