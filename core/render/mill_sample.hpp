// What the machining centre's views read of the surfaces (mill_view.cpp,
// mill_iso.cpp): the top at a point and its colour, from the block's level
// of detail that suits the picture's scale, else from the work-holding and
// the table around it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <algorithm>
#include <cmath>

#include "core/render/surfaces.hpp"

namespace pupitre::render {

struct Top {
    float h = 0;
    Colour c = 0;
    float gx = 0, gy = 0;  // the slope along X and Y
    int i = 0, j = 0;      // its cell, at its level
    const Level* level = nullptr;
};

class MillSampler {
  public:
    // The block's level whose cells are no wider than `mm` (the finest
    // when none is).
    // `cliffs`: a wall between two cells leaves both their tops flat (the
    // 3-D view draws walls itself); else the slope takes it (from above,
    // the wall shows as a line lit or in shadow).
    MillSampler(const MillScene& m, const Surfaces& sf, double mm, bool cliffs = false)
        : m_(m), sf_(sf), cliffs_(cliffs) {
        size_t l = 0;
        while (l + 1 < sf.block.size() && sf.block[l + 1].cell <= mm) ++l;
        level_ = &sf.block[l];
        inv_ = 1 / level_->cell, inv_around_ = 1 / sf.around.cell;
    }
    const Level& level() const { return *level_; }
    // The top at (x, y) and its cell: false beyond the table's part drawn.
    bool at(double x, double y, Top& t) const {
        const bool in =
            x >= m_.stock.lo[0] && x < m_.stock.hi[0] && y >= m_.stock.lo[1] && y < m_.stock.hi[1];
        const Level& l = in ? *level_ : sf_.around;
        const double fx = (x - l.x0) * (in ? inv_ : inv_around_),
                     fy = (y - l.y0) * (in ? inv_ : inv_around_);
        if (!(fx >= 0 && fy >= 0)) return false;
        const int i = int(fx), j = int(fy);
        if (i >= l.nx || j >= l.ny) return false;
        t.h = l.at(i, j);
        t.c = l.colour(i, j);
        t.i = i, t.j = j, t.level = &l;
        return true;
    }
    // The slope at the top `t` found (gx, gy), asked only where it is drawn.
    void slope(Top& t) const {
        const Level& l = *t.level;
        const int i = t.i, j = t.j;
        const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, l.nx - 1);
        const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, l.ny - 1);
        const float c = float(l.cell), h = t.h;
        if (cliffs_) {
            t.gx = minmod((l.at(i1, j) - h) / c, (h - l.at(i0, j)) / c);
            t.gy = minmod((l.at(i, j1) - h) / c, (h - l.at(i, j0)) / c);
        } else {
            t.gx = i1 > i0 ? float((l.at(i1, j) - l.at(i0, j)) / ((i1 - i0) * l.cell)) : 0;
            t.gy = j1 > j0 ? float((l.at(i, j1) - l.at(i, j0)) / ((j1 - j0) * l.cell)) : 0;
        }
    }

  private:
    // The gentler of the two one-sided slopes, none when they disagree.
    static float minmod(float a, float b) {
        if (a * b <= 0) return 0;
        return std::abs(a) < std::abs(b) ? a : b;
    }
    const MillScene& m_;
    const Surfaces& sf_;
    bool cliffs_ = false;
    const Level* level_;
    double inv_ = 1, inv_around_ = 1;  // cells per mm
};

// The box the views fit: the block and its work-holding.
inline void mill_box(const MillScene& m, double lo[3], double hi[3]) {
    for (int a = 0; a < 3; ++a) lo[a] = m.stock.lo[a], hi[a] = m.stock.hi[a];
    for (const workshop::Box3& b : m.boxes)
        for (int a = 0; a < 3; ++a)
            lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    for (const workshop::Cylinder& k : m.pins) {
        lo[0] = std::min(lo[0], k.x - k.radius), hi[0] = std::max(hi[0], k.x + k.radius);
        lo[1] = std::min(lo[1], k.y - k.radius), hi[1] = std::max(hi[1], k.y + k.radius);
        hi[2] = std::max(hi[2], k.z1);
    }
}

}  // namespace pupitre::render
