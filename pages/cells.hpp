// A picture as character cells (issue 36), through libchafa: each cell's
// symbol and its two colours, as many colours as the terminal shows (its
// own 24-bit colours, 256, 16 or 8 of its palette) or none (symbols only:
// `--theme mono`, NO_COLOR); plain ASCII symbols for `--ascii`. The cells
// go into the Canvas like any page's: chafa's own escape strings never
// reach the terminal.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <vector>

#include "core/render/image.hpp"
#include "pages/canvas.hpp"

namespace pupitre::pages {

// The colours a terminal shows.
enum class Colours : uint8_t { none, c8, c16, c256, direct };

struct CellImage {
    int cols = 0, rows = 0;
    std::vector<Cell> cells;  // row by row
    const Cell& at(int x, int y) const { return cells[size_t(y) * size_t(cols) + size_t(x)]; }
};

// The picture into `cols` x `rows` cells (a cell is taken twice as tall
// as it is wide: a picture of cols x 4 by rows x 8 square pixels keeps its
// proportions).
CellImage to_cells(const render::Image& img, int cols, int rows, Colours colours, bool ascii);

// Copies the cells into the canvas at (x, y).
void put_cells(const CellImage& ci, Canvas& c, int x, int y);

}  // namespace pupitre::pages
