// The machining centre's block seen from above (see part_view.hpp): each
// pixel the top of the material under it in its surface's colour, lit from
// the north-west so that walls and floors stand out; the vice or the plate,
// the pins and the table around it; the cutter's circle where it stands.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/geometry/geometry.hpp"
#include "core/render/mill_sample.hpp"
#include "core/render/part_view.hpp"

namespace pupitre::render {

namespace {

// Lambert's law for a slope, 1 on the flat.
double hillshade(const Top& t) {
    const double nx = -t.gx, ny = -t.gy, n = std::sqrt(nx * nx + ny * ny + 1);
    const double dot = (-0.5 * nx + 0.5 * ny + 0.7071) / n;
    return 0.2 + 0.8 * std::max(0.0, dot) / 0.7071;
}

}  // namespace

void mill_top(const PartScene& s, const Surfaces& sf, const Look& look, Picture& p) {
    const MillScene& m = s.block;
    Image& img = p.image;
    double lo[3], hi[3];
    mill_box(m, lo, hi);
    const double sc =
        std::max((hi[0] - lo[0]) / img.w(), (hi[1] - lo[1]) / img.h()) * 1.08 / look.cam.zoom;
    const double cx = (lo[0] + hi[0]) / 2 - look.cam.pan_x * img.w() * sc;
    const double cy = (lo[1] + hi[1]) / 2 - look.cam.pan_y * img.h() * sc;
    p.mm_per_px = sc;
    auto px = [&](double x, double y) {
        return V2{(x - cx) / sc + img.w() / 2.0, img.h() / 2.0 - (y - cy) / sc};
    };
    const MillSampler sample(m, sf, sc);
    Top t;
    for (int y = 0; y < img.h(); ++y) {
        const double wy = cy + (img.h() / 2.0 - y - 0.5) * sc;
        for (int x = 0; x < img.w(); ++x) {
            const double wx = cx + (x + 0.5 - img.w() / 2.0) * sc;
            if (!sample.at(wx, wy, t)) continue;
            sample.slope(t);
            img.set(x, y, shade(t.c, hillshade(t)));
        }
    }
    const Palette& pal = palette(look.paper);
    if (m.has_cutter) {
        const V2 c = px(m.tip[0], m.tip[1]);
        const double unit = std::max(1.0, img.h() / 240.0);
        for (int k = 0; k < 96; ++k) {
            const double a0 = k * 2 * geometry::kPi / 96, a1 = (k + 1) * 2 * geometry::kPi / 96;
            for (double r : {m.cutter.radius, m.cutter.holder}) {
                const double rp = r / sc;
                img.line({c[0] + rp * std::cos(a0), c[1] + rp * std::sin(a0)},
                         {c[0] + rp * std::cos(a1), c[1] + rp * std::sin(a1)},
                         r == m.cutter.radius ? pal.insert : pal.cutter_holder, unit * 1.5);
            }
        }
        img.disc(c, 1.5 * unit, pal.insert);
    }
    for (size_t i = 0; i < sf.anchor.size() && i < p.anchor.size(); ++i)
        if (!std::isnan(sf.anchor[i][0])) p.anchor[i] = px(sf.anchor[i][0], sf.anchor[i][1]);
}

}  // namespace pupitre::render
