// The PART view's colours (see palette.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/render/palette.hpp"

#include <algorithm>
#include <cmath>

namespace pupitre::render {

const Palette& palette(bool paper) {
    static const Palette kScreen{
        rgb(16, 20, 26),    rgb(92, 70, 48),    rgb(112, 124, 138), rgb(78, 88, 100),
        rgb(58, 64, 74),    rgb(120, 128, 140), rgb(230, 180, 60),  rgb(96, 104, 114),
        rgb(200, 200, 120), rgb(240, 240, 240), rgb(40, 44, 50),    rgb(70, 86, 118),
        rgb(170, 170, 170), rgb(214, 218, 224), rgb(90, 96, 106),   rgb(90, 96, 106)};
    static const Palette kPaper{
        rgb(255, 255, 255), rgb(246, 226, 200), rgb(196, 204, 214), rgb(128, 138, 150),
        rgb(150, 156, 166), rgb(70, 76, 86),    rgb(214, 160, 40),  rgb(110, 118, 128),
        rgb(60, 60, 60),    rgb(0, 0, 0),       rgb(228, 230, 234), rgb(120, 136, 170),
        rgb(150, 150, 150), rgb(190, 196, 204), rgb(96, 102, 112),  rgb(60, 60, 60)};
    return paper ? kPaper : kScreen;
}

Colour deviation_colour(double dev_um, double lower_um, double upper_um, double span_um) {
    const double span = std::max(span_um, 1e-6);
    if (dev_um > upper_um + 1e-6)
        return mix(rgb(250, 190, 40), rgb(214, 30, 40), (dev_um - upper_um) / span);
    if (dev_um < lower_um - 1e-6)
        return mix(rgb(60, 200, 230), rgb(40, 60, 200), (lower_um - dev_um) / span);
    return kInside;
}

Colour reading_colour(const DimReading& r, double span_um) {
    if (!r.read) return kUnread;
    return deviation_colour(r.deviation() * 1000, r.dim.lower * 1000, r.dim.upper * 1000, span_um);
}

Colour depth_colour(double t) {
    // A ramp from pale to deep (viridis-like): the eye reads it in order.
    static const Colour kStops[] = {rgb(253, 231, 37), rgb(94, 201, 98), rgb(33, 145, 140),
                                    rgb(59, 82, 139), rgb(68, 1, 84)};
    t = std::clamp(t, 0.0, 1.0) * 4;
    const int k = std::min(3, int(t));
    return mix(kStops[k], kStops[k + 1], t - k);
}

Colour legend_colour(const Legend& l, double v) {
    if (l.paint == Paint::deviation) return deviation_colour(v, l.lower_um, l.upper_um, l.span_um);
    return depth_colour(l.depth > 0 ? v / l.depth : 0);
}

Colour legend_sample(const Legend& l, int k, int n) {
    if (l.paint != Paint::deviation) return legend_colour(l, l.depth * (k + 0.5) / n);
    const double v0 = -l.span_um + 2 * l.span_um * k / n, v1 = v0 + 2 * l.span_um / n;
    if (v1 >= l.lower_um && v0 <= l.upper_um) return kInside;
    return legend_colour(l, (v0 + v1) / 2);
}

double round_up(double v) {
    if (!(v > 0)) return 1;
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= v - 1e-9 * p) return m * p;
    return 10 * p;
}

Legend legend_of(const PartScene& s, Paint paint, double depth) {
    Legend l;
    l.depth = depth > 0 ? depth : 1;
    if (paint != Paint::deviation || s.dims.empty()) return l;
    l.paint = Paint::deviation;
    double widest = 0, beyond = 0;
    bool first = true;
    for (const DimReading& r : s.dims) {
        widest = std::max({widest, std::abs(r.dim.lower), std::abs(r.dim.upper)});
        if (!r.read) continue;
        const double dev = r.deviation();
        beyond = std::max({beyond, dev - r.dim.upper, r.dim.lower - dev});
        if (first) l.lower_um = r.dim.lower * 1000, l.upper_um = r.dim.upper * 1000;
        first = false;
    }
    if (first && !s.dims.empty())
        l.lower_um = s.dims[0].dim.lower * 1000, l.upper_um = s.dims[0].dim.upper * 1000;
    l.span_um = round_up(std::max(2 * widest, beyond) * 1000);
    return l;
}

}  // namespace pupitre::render
