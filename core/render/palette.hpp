// The PART view's colours (issue 36): the things of the workshop on a dark
// screen or on white paper, and the two scales a surface is painted by: its
// deviation from the drawing (inside the tolerance, over, under, in µm) or,
// with no drawing, its depth below the stock as loaded.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <vector>

#include "core/render/image.hpp"
#include "core/render/part_scene.hpp"

namespace pupitre::render {

struct Palette {
    Colour background, removed, section, hatch, chuck, chuck_edge, insert, holder, axis, drawing,
        table, vice, pin, cutter, cutter_holder, frame;
};
const Palette& palette(bool paper);

// Surfaces the drawing does not dimension, and uncut stock.
inline constexpr Colour kUnmarked = rgb(150, 158, 168);
inline constexpr Colour kUncut = rgb(176, 182, 190);
inline constexpr Colour kInside = rgb(46, 170, 78);
inline constexpr Colour kUnread = rgb(120, 120, 120);

// How a surface is painted.
enum class Paint : uint8_t { deviation, depth };

// The colour scale under the picture: what it shows and its range.
struct Legend {
    Paint paint = Paint::depth;
    // deviation: the scale runs from -span to +span µm; the first read
    // dimension's tolerance band is its green.
    double span_um = 0, lower_um = 0, upper_um = 0;
    double depth = 0;  // depth: mm at the scale's end
};
// The colour of the scale at `v` (µm for a deviation, mm for a depth).
Colour legend_colour(const Legend& l, double v);
// The colour of sample k of n along the scale, from its low end: the
// tolerance's green in every sample that holds some of the band, however
// narrow it is on the scale.
Colour legend_sample(const Legend& l, int k, int n);
// A deviation of `dev_um` for limits [lower_um, upper_um]: green inside,
// from orange to red over, from cyan to blue under, full at `span_um`
// beyond the limit.
Colour deviation_colour(double dev_um, double lower_um, double upper_um, double span_um);
Colour reading_colour(const DimReading& r, double span_um);
// A depth t from 0 (just cut) to 1 (the deepest).
Colour depth_colour(double t);
// The legend of the scene painted by `paint` (deviation needs a drawing),
// `depth` the deepest cut (mm).
Legend legend_of(const PartScene& s, Paint paint, double depth);
// A round number at least `v` (1, 2, 5 times a power of ten).
double round_up(double v);

}  // namespace pupitre::render
