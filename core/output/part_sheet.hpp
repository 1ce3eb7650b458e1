// The part on paper (issue 36, `:part export`, `run --part-out` as PNG or
// PDF): a page a teacher hands back with the grade. The picture of the PART
// view, its title (the program, the exercise or the setup, the date), the
// dimensions of the drawing labelled where the part was read, the colour
// scale and the scale of the picture, laid out on A4 in landscape. Plain
// data: the plot module draws it with Cairo (cairo_plot.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/output/scene.hpp"

namespace pupitre {

struct SheetLabel {
    double x = 0, y = 0;  // the point labelled, in the picture's pixels
    std::string text;
    Rgb colour;  // the swatch beside the text: the surface's colour
};

struct PartSheet {
    std::string title;     // "%10 LATHE-FIRST: TURNED PART"
    std::string subtitle;  // "exercise lathe-first, student ana · 2025-03-04 · section"
    // The picture: w x h pixels, each the bytes R, G, B, A.
    int w = 0, h = 0;
    std::vector<uint32_t> pixels;
    double mm_per_px = 0;  // the part's millimetres per pixel, in the picture's plane
    std::vector<SheetLabel> labels;
    // Texts written on the picture itself, centred over their point (the
    // stick-out over its line).
    std::vector<SheetLabel> marks;
    // The colour scale, from its low end to its high end, with its title
    // and its numbers (at 0..1 along it).
    std::string scale_title;
    std::vector<Rgb> scale;
    std::vector<std::pair<double, std::string>> ticks;
    std::vector<std::string> notes;  // lines under the picture
    std::string generator = "pupitre";
};

// The page's size and the box the picture is fitted into (mm), for the
// caller that chooses a round ratio (picture mm per part mm).
inline constexpr double kSheetW = 297, kSheetH = 210;
inline constexpr double kSheetPictureW = 190, kSheetPictureH = 138;

// The sheet as a PNG `width` pixels across, or as a one-page PDF. False
// when Cairo or the stream fails.
bool write_part_png(const PartSheet& sheet, int width, std::FILE* out);
bool write_part_pdf(const PartSheet& sheet, std::FILE* out);

}  // namespace pupitre
