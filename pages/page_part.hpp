// The PART page (issue 36): the workshop's part as the console's worker
// drew it (console/part_window.cpp), as cells in colour, or left blank for
// the terminal to draw the picture itself (sixel, kitty); under it the
// colour scale and the dimensions of the drawing read on the part.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/render/palette.hpp"
#include "pages/canvas.hpp"
#include "pages/cells.hpp"

namespace pupitre::pages {

struct PartLine {
    uint32_t swatch = kNoColour;  // the surface's colour (render::Colour), kNoColour: none
    std::string text;
};

struct PartView {
    bool workshop = false;             // else the page says how to get one
    const CellImage* cells = nullptr;  // the picture; null: being drawn
    bool image = false;                // the terminal draws it: the rectangle is left blank
    Colours colours = Colours::none;   // what the terminal shows
    std::string title;                 // the view and how it is painted
    std::string note;                  // "drawing…", why there are no deviations
    render::Legend legend;
    bool numbers = true;  // the scale's numbers (not in an exercise before :submit)
    std::vector<PartLine> lines;
    std::string keys;  // the page's keys
    int info = 3;      // the lines under the picture: the scale, `lines`, the keys
};

struct View;
void page_part(const View& v, Canvas& c, const Rect& r);
// The picture's cells on the page: under the title, over the `info` lines
// of the scale, the dimensions and the keys.
Rect part_area(const Rect& page, int info);
// Those lines for `lines` lines of dimensions and notes: the scale, them,
// the keys; at most six.
int part_info(size_t lines);
// An RGB colour as the terminal shows it: itself, or the nearest entry of
// its palette (the xterm 256 colours, or the 16 or 8 of ANSI).
uint32_t terminal_colour(render::Colour c, Colours colours);

}  // namespace pupitre::pages
