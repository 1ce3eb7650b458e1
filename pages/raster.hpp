// A dot raster for the graphic page: the terminal cell split into 2x4 dots
// (Unicode braille), a view transform between the world (mm, y up) and the
// dots, strokes with dash patterns, arcs drawn as arcs, clipping, and the
// cells written into a Canvas as braille, quadrant blocks or plain ASCII.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "pages/canvas.hpp"

namespace pupitre::pages {

// What a dot shows, weakest first: a cell takes the strongest ink of its dots,
// so a cutting move is never hidden by the rapid that shares its cell.
enum class Ink : uint8_t {
    none,
    part,  // the workshop's part, filled
    axis,
    mirror,
    stock,
    extremes,
    rapid,
    feed,
    comp,
    travel,
    error,
    count_
};
using InkStyles = std::array<Style, size_t(Ink::count_)>;

// World (x right, y up) to dots (x right, y down). Dot centres sit at integer
// coordinates 0..w-1, 0..h-1; the world point (cx, cy) is at the grid's centre.
struct ViewXf {
    double cx = 0, cy = 0;  // world point at the centre of the grid
    double scale = 1;       // world units (mm) per dot
    int w = 2, h = 4;       // dots

    double dx(double x) const { return (x - cx) / scale + (w - 1) * 0.5; }
    double dy(double y) const { return (h - 1) * 0.5 - (y - cy) / scale; }
    double wx(double d) const { return cx + (d - (w - 1) * 0.5) * scale; }
    double wy(double d) const { return cy - (d - (h - 1) * 0.5) * scale; }
    bool operator==(const ViewXf&) const = default;
};

// The scales a view may take: below a micrometre per dot or above a metre
// the drawing says nothing more (and doubles keep their precision).
inline constexpr double kMinScale = 1e-4, kMaxScale = 1e4;

// The view that shows the world box [x0, x1] x [y0, y1] whole, centred, with
// `margin` dots left free on each side. A box of zero size gets 0.05 mm a dot.
ViewXf fit_view(double x0, double y0, double x1, double y1, int w, int h, double margin = 2);
// Zoom by `factor` (> 1 magnifies) keeping the world point (x, y) on its dot.
ViewXf zoom_about(const ViewXf& v, double x, double y, double factor);
// Pan by a fraction of the window (fx = 0.25: a quarter of the width to the right).
ViewXf pan_view(const ViewXf& v, double fx, double fy);

// Dash patterns: dot k of a stroke is set when bit (k mod 16) is.
inline constexpr uint16_t kSolid = 0xffff;
inline constexpr uint16_t kDashed = 0x0f0f;   // 4 on, 4 off: rapids
inline constexpr uint16_t kDotted = 0x5555;   // every other dot: the spindle axis
inline constexpr uint16_t kDashDot = 0x27ff;  // long dash, dot

enum class Glyphs : uint8_t { braille, quadrant, ascii };

// The cell glyph of 8 dots (bit order of Unicode braille: dots 1-2-3 down the
// left column are bits 0-2, dots 4-5-6 down the right are bits 3-5, the bottom
// row is bits 6 (left) and 7 (right)).
char32_t braille_glyph(uint8_t bits);
char32_t quadrant_glyph(uint8_t bits);
char ascii_glyph(uint8_t bits);
// The bit of the dot at column dx (0, 1) and row dy (0..3) of a cell.
inline uint8_t dot_bit(int dx, int dy) {
    static constexpr uint8_t kBits[2][4] = {{0x01, 0x02, 0x04, 0x40}, {0x08, 0x10, 0x20, 0x80}};
    return kBits[dx][dy];
}

class DotRaster {
  public:
    void reset(int cols, int rows);  // cols x rows cells, all clear
    void clear();
    int cols() const { return cols_; }
    int rows() const { return rows_; }
    int w() const { return cols_ * 2; }  // dots
    int h() const { return rows_ * 4; }

    void dot(int x, int y, Ink ink) {
        if (unsigned(x) >= unsigned(w()) || unsigned(y) >= unsigned(h())) return;
        Cell& c = cells_[size_t((y >> 2) * cols_ + (x >> 1))];
        c.bits |= dot_bit(x & 1, y & 3);
        if (ink > c.ink) c.ink = ink;
    }
    bool test(int x, int y) const {
        if (unsigned(x) >= unsigned(w()) || unsigned(y) >= unsigned(h())) return false;
        return cells_[size_t((y >> 2) * cols_ + (x >> 1))].bits & dot_bit(x & 1, y & 3);
    }
    // A straight stroke between two points in dot coordinates, clipped to the
    // grid; the dash rhythm runs on across strokes (phase).
    void line(double x0, double y0, double x1, double y1, Ink ink, uint16_t dash = kSolid);
    uint32_t phase = 0;

    uint8_t bits(int col, int row) const { return cells_[size_t(row * cols_ + col)].bits; }
    Ink ink(int col, int row) const { return cells_[size_t(row * cols_ + col)].ink; }
    // The cells into r (its size is the raster's, clipped to both). Empty cells
    // are left as they are.
    void to_canvas(Canvas& c, const Rect& r, Glyphs g, const InkStyles& styles) const;

  private:
    struct Cell {
        uint8_t bits = 0;
        Ink ink = Ink::none;
    };
    void span(int x0, int y0, int x1, int y1, Ink ink, uint16_t dash);
    int cols_ = 0, rows_ = 0;
    std::vector<Cell> cells_;
};

// World-space strokes through a view.
void draw_line(DotRaster& r, const ViewXf& v, double x0, double y0, double x1, double y1, Ink ink,
               uint16_t dash = kSolid);
// An arc about (cx, cy) from angle a0 (radians, counter-clockwise from +x in the
// world) through `sweep` radians, its radius going from r0 to r1. Chords are
// chosen in dot space so that they stay within 0.2 dot of the curve: a 0.5 mm
// fillet is round once it is a few dots wide, and a big arc costs no more than
// its visible length needs.
void draw_arc(DotRaster& r, const ViewXf& v, double cx, double cy, double r0, double r1, double a0,
              double sweep, Ink ink, uint16_t dash = kSolid);
// The number of chords that keep an arc of radius `radius_dots` through
// `sweep` radians within `tol` dots of its curve.
int arc_chords(double radius_dots, double sweep, double tol = 0.2);

}  // namespace pupitre::pages
