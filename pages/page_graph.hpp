// The GRAPH page (issue 7): the toolpath drawn in the terminal before or while
// metal is cut — braille dots (2x4 a cell) or an ASCII fallback, rapids dashed,
// arcs as arcs, moves beyond the travel and gouges highlighted, the tool, a
// cursor, a scale bar and the program's extents. The key functions are pure:
// they take a view and return the next one, so the console binds them as data.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/output/toolpath.hpp"
#include "core/workshop/mill_part.hpp"
#include "pages/canvas.hpp"
#include "pages/raster.hpp"

namespace pupitre::pages {

// The raster of the moves as the last frame drew them. Whoever owns the view
// keeps it between frames: while the window, the plane and the size stay the
// same, a frame draws only the moves added since (a live run, a 1,000,000-block
// TEST), and a new window redraws everything.
struct GraphCache {
    DotRaster raster;
    ViewXf xf;
    PathPlane plane = PathPlane::xy;
    const Toolpath* path = nullptr;
    uint32_t generation = 0;
    size_t drawn = 0;   // moves in the raster
    size_t errors = 0;  // errors of the path when drawn: a new one re-flags moves
    bool mirror = false;
    bool valid = false;
    long full_draws = 0;  // counts the complete redraws (tests, benchmarks)
};

struct GraphView {
    const Toolpath* path = nullptr;
    PathPlane plane = PathPlane::xy;
    // The window: with `fit` it follows the path's extents; else its centre and
    // scale (world units are mm; on the lathe the vertical is X as a radius).
    bool fit = true;
    double cx = 0, cy = 0;
    double scale = 0.5;  // mm per dot
    bool has_cursor = false;
    bool no_readout = false;      // an exercise: no coordinates read off the drawing
    double cur_x = 0, cur_y = 0;  // the cursor, world
    const Axes* tool = nullptr;   // the tool now, program frame, internal units; null: none shown
    size_t upto = SIZE_MAX;       // moves drawn: [0, upto)
    // The cycle time in the title (the console's Sim::cycle_time(), the M02
    // message's); < 0: the path's own count.
    double seconds = -1;
    bool mirror = true;               // lathe: the half-profile's mirror image below the axis
    Glyphs glyphs = Glyphs::braille;  // braille or quadrant blocks; ASCII when the canvas is ASCII
    GraphCache* cache = nullptr;      // null: every frame draws every move
    // The workshop's part (lathe): its half-section as polygons, (Z, X as a
    // radius) in the program frame; null: no workshop.
    const std::vector<std::vector<std::array<double, 2>>>* part = nullptr;
    // Its chuck's jaws and body (and tailstock), outlined, in the same frame.
    const std::vector<std::vector<std::array<double, 2>>>* chuck = nullptr;
    // The workshop's block (machining centre): its height field, shaded in
    // the XY plane where the program frame puts it (program = machine +
    // (block_dx, block_dy)); null: no workshop.
    const workshop::MillWorld* block = nullptr;
    double block_dx = 0, block_dy = 0;
};

void page_graph(const GraphView& g, const MachineProfile& m, Canvas& c, const Rect& r);

// The raster's cells in the page rectangle (below the title, above the two
// information lines).
Rect graph_area(const Rect& page);
// The window the page shows, fit resolved, in dots of graph_area(page).
ViewXf graph_window(const GraphView& g, const Rect& page);
// The world box that `fit` shows: the cutting moves (every move when there is
// none), the stock, EM± and, on the lathe, the mirror image (fit_box, the
// plot's rule).
void graph_extent(const GraphView& g, double& x0, double& y0, double& x1, double& y1);
// What `fit` shows, in words for the message line: "the cutting moves of %300
// (2 rapids reach beyond)".
std::string graph_fit_words(const GraphView& g);

// Keys. Zoom about the cursor (or the window's centre when there is none);
// `factor` > 1 magnifies.
GraphView graph_zoom(const GraphView& g, const Rect& page, double factor);
// Pan by a fraction of the window: fx > 0 shows more to the right, fy > 0 more above.
GraphView graph_pan(const GraphView& g, const Rect& page, double fx, double fy);
GraphView graph_fit(const GraphView& g);
// XY -> XZ -> YZ -> XY on a mill; the lathe has only ZX.
GraphView graph_next_plane(const GraphView& g, const MachineProfile& m);
// Moves the cursor by cells (drows > 0 goes down); the window follows it.
GraphView graph_move_cursor(const GraphView& g, const Rect& page, int dcols, int drows);

// The block (GraphView::block) in the XY plane: its outline into the
// frame's raster, and each cell of the area shaded by the height of the
// material under its centre (page_graph_block.cpp).
bool shows_block(const GraphView& g);
void block_outline(const GraphView& g, const ViewXf& xf, DotRaster& r);
void shade_block(const GraphView& g, const ViewXf& xf, Canvas& c, const Rect& a);

// Draws moves [from, to) of a path into a raster (the page's inner loop,
// public for the benchmarks).
void draw_moves(const Toolpath& p, PathPlane plane, const ViewXf& xf, bool mirror, size_t from,
                size_t to, DotRaster& r);
// A scale bar's round length (core/output/toolpath.hpp), shared with the plot.
using pupitre::nice_length;

}  // namespace pupitre::pages
