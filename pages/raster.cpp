// The dot raster (see raster.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/raster.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/geometry.hpp"

namespace pupitre::pages {

namespace {

using ::pupitre::geometry::kPi;

double clamp_scale(double s) {
    return std::clamp(s, kMinScale, kMaxScale);
}

// Rows (bit 0 = top) and columns (bit 0 = left) of a cell's dots.
int rows_of(uint8_t b) {
    int r = 0;
    for (int y = 0; y < 4; ++y)
        if (b & (dot_bit(0, y) | dot_bit(1, y))) r |= 1 << y;
    return r;
}
int cols_in(uint8_t b, int row_lo, int row_hi) {
    int c = 0;
    for (int y = row_lo; y <= row_hi; ++y) {
        if (b & dot_bit(0, y)) c |= 1;
        if (b & dot_bit(1, y)) c |= 2;
    }
    return c;
}

char ascii_of(uint8_t b) {
    if (!b) return ' ';
    int n = __builtin_popcount(b);
    int rows = rows_of(b), cols = cols_in(b, 0, 3);
    int top = cols_in(b, 0, 1), bottom = cols_in(b, 2, 3);
    bool both_halves = (rows & 3) && (rows & 12);
    if (n == 1) return (rows & 3) ? '\'' : '.';
    if (n >= 6) return '#';
    if (rows == 8) return '_';
    if (rows == 1 || rows == 2 || rows == 4 || rows == 3 || rows == 6) return '-';
    if (rows == 12) return '_';
    if (cols != 3) return both_halves ? '|' : ((rows & 3) ? '\'' : '.');
    if (both_halves && top == 1 && bottom == 2) return '\\';
    if (both_halves && top == 2 && bottom == 1) return '/';
    return n >= 5 ? '#' : ':';
}

struct AsciiTable {
    char c[256];
    AsciiTable() {
        for (int i = 0; i < 256; ++i) c[i] = ascii_of(uint8_t(i));
    }
};

// Liang-Barsky: clips p + t·d, t in [0, 1], to the box; false if nothing is left.
bool clip(double& x0, double& y0, double& x1, double& y1, double xmin, double ymin, double xmax,
          double ymax) {
    double t0 = 0, t1 = 1, dx = x1 - x0, dy = y1 - y0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - xmin, xmax - x0, y0 - ymin, ymax - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        double t = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    double ox = x0, oy = y0;
    x0 = ox + t0 * dx;
    y0 = oy + t0 * dy;
    x1 = ox + t1 * dx;
    y1 = oy + t1 * dy;
    return true;
}

}  // namespace

ViewXf fit_view(double x0, double y0, double x1, double y1, int w, int h, double margin) {
    ViewXf v;
    v.w = std::max(w, 2);
    v.h = std::max(h, 2);
    v.cx = (x0 + x1) / 2;
    v.cy = (y0 + y1) / 2;
    double uw = std::max(v.w - 1 - 2 * margin, 1.0), uh = std::max(v.h - 1 - 2 * margin, 1.0);
    double s = std::max((x1 - x0) / uw, (y1 - y0) / uh);
    v.scale = (s > 0 && std::isfinite(s)) ? clamp_scale(s) : 0.05;
    return v;
}

ViewXf zoom_about(const ViewXf& v, double x, double y, double factor) {
    ViewXf z = v;
    if (!(factor > 0)) return z;
    z.scale = clamp_scale(v.scale / factor);
    double f = v.scale / z.scale;  // the factor actually applied
    z.cx = x - (x - v.cx) / f;
    z.cy = y - (y - v.cy) / f;
    return z;
}

ViewXf pan_view(const ViewXf& v, double fx, double fy) {
    ViewXf p = v;
    p.cx += fx * v.w * v.scale;
    p.cy += fy * v.h * v.scale;
    return p;
}

char32_t braille_glyph(uint8_t bits) {
    return char32_t(0x2800 + bits);
}

char32_t quadrant_glyph(uint8_t b) {
    // Quadrants from the top two and bottom two dot rows of each column.
    int q = 0;
    if (b & (dot_bit(0, 0) | dot_bit(0, 1))) q |= 1;  // top left
    if (b & (dot_bit(1, 0) | dot_bit(1, 1))) q |= 2;  // top right
    if (b & (dot_bit(0, 2) | dot_bit(0, 3))) q |= 4;  // bottom left
    if (b & (dot_bit(1, 2) | dot_bit(1, 3))) q |= 8;  // bottom right
    static constexpr char32_t kQ[16] = {U' ', U'▘', U'▝', U'▀', U'▖', U'▌', U'▞', U'▛',
                                        U'▗', U'▚', U'▐', U'▜', U'▄', U'▙', U'▟', U'█'};
    return kQ[q];
}

char ascii_glyph(uint8_t bits) {
    static const AsciiTable t;
    return t.c[bits];
}

void DotRaster::reset(int cols, int rows) {
    cols_ = std::max(cols, 1);
    rows_ = std::max(rows, 1);
    cells_.assign(size_t(cols_) * size_t(rows_), Cell{});
    phase = 0;
}

void DotRaster::clear() {
    std::fill(cells_.begin(), cells_.end(), Cell{});
    phase = 0;
}

// Bresenham between two dots, both known to be on the grid or near it.
void DotRaster::span(int x0, int y0, int x1, int y1, Ink ink, uint16_t dash) {
    int dx = std::abs(x1 - x0), sx = x0 < x1 ? 1 : -1;
    int dy = -std::abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
    int err = dx + dy;
    for (;;) {
        if (dash & (1u << (phase++ & 15))) dot(x0, y0, ink);
        if (x0 == x1 && y0 == y1) return;
        int e2 = 2 * err;
        if (e2 >= dy) {
            err += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            err += dx;
            y0 += sy;
        }
    }
}

void DotRaster::line(double x0, double y0, double x1, double y1, Ink ink, uint16_t dash) {
    const double xm = w() - 0.5, ym = h() - 0.5;
    // Most strokes of a frame lie inside the grid (NaN fails these tests too).
    bool inside = x0 >= -0.5 && x0 <= xm && x1 >= -0.5 && x1 <= xm && y0 >= -0.5 && y0 <= ym &&
                  y1 >= -0.5 && y1 <= ym;
    if (!inside) {
        // Both ends beyond the same side: nothing to draw (most strokes of a zoomed-in frame).
        if ((x0 < -0.5 && x1 < -0.5) || (x0 > xm && x1 > xm) || (y0 < -0.5 && y1 < -0.5) ||
            (y0 > ym && y1 > ym))
            return;
        if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
            return;
        if (!clip(x0, y0, x1, y1, -0.5, -0.5, xm, ym)) return;
    }
    // The points are now within [-0.5, size - 0.5]: truncation rounds them (no
    // floor(), which costs a call on the baseline x86-64).
    auto ix = [&](double v) { return std::min(int(v + 0.5), w() - 1); };
    auto iy = [&](double v) { return std::min(int(v + 0.5), h() - 1); };
    span(ix(x0), iy(y0), ix(x1), iy(y1), ink, dash);
}

void DotRaster::to_canvas(Canvas& c, const Rect& r, Glyphs g, const InkStyles& styles) const {
    int cols = std::min(cols_, r.w), rows = std::min(rows_, r.h);
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < cols; ++x) {
            const Cell& cell = cells_[size_t(y * cols_ + x)];
            if (!cell.bits) continue;
            char32_t ch = g == Glyphs::braille    ? braille_glyph(cell.bits)
                          : g == Glyphs::quadrant ? quadrant_glyph(cell.bits)
                                                  : char32_t(ascii_glyph(cell.bits));
            c.put(r.x + x, r.y + y, ch, styles[size_t(cell.ink)]);
        }
}

void draw_line(DotRaster& r, const ViewXf& v, double x0, double y0, double x1, double y1, Ink ink,
               uint16_t dash) {
    r.line(v.dx(x0), v.dy(y0), v.dx(x1), v.dy(y1), ink, dash);
}

int arc_chords(double radius_dots, double sweep, double tol) {
    sweep = std::fabs(sweep);
    if (!(radius_dots > tol)) return std::max(1, int(std::ceil(sweep / (kPi / 2))));
    double step = 2 * std::acos(1 - tol / radius_dots);
    double n = std::ceil(sweep / step);
    return int(std::clamp(n, 1.0, 65536.0));
}

void draw_arc(DotRaster& r, const ViewXf& v, double cx, double cy, double r0, double r1, double a0,
              double sweep, Ink ink, uint16_t dash) {
    double rd = std::max(r0, r1) / v.scale;
    double ccx = v.dx(cx), ccy = v.dy(cy);
    if (!std::isfinite(rd) || !std::isfinite(ccx) || !std::isfinite(ccy)) return;
    // The whole circle is off the grid: nothing of the arc shows.
    if (ccx + rd < -1 || ccx - rd > r.w() || ccy + rd < -1 || ccy - rd > r.h()) return;
    int n = arc_chords(rd, sweep);
    double px = ccx + r0 / v.scale * std::cos(a0), py = ccy - r0 / v.scale * std::sin(a0);
    for (int k = 1; k <= n; ++k) {
        double t = double(k) / n;
        double a = a0 + sweep * t, rr = (r0 + (r1 - r0) * t) / v.scale;
        double qx = ccx + rr * std::cos(a), qy = ccy - rr * std::sin(a);
        // The joint dot belongs to both chords: step the dash back so it counts once.
        uint32_t before = r.phase;
        r.line(px, py, qx, qy, ink, dash);
        if (r.phase != before) --r.phase;
        px = qx;
        py = qy;
    }
}

}  // namespace pupitre::pages
