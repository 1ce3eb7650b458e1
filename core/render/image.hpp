// A picture in memory for the PART view (issue 36): RGBA pixels, the few
// primitives the part's views need (polygons filled even-odd, thick lines,
// discs), a depth buffer beside it for the 3-D view. No library: the
// console turns it into cells (libchafa), a sixel or a kitty image; the plot
// module paints it on paper (Cairo).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pupitre::render {

// A colour as its bytes lie in memory: R, G, B, then A (libchafa's
// RGBA8_UNASSOCIATED, a PNG's RGBA).
using Colour = uint32_t;
constexpr Colour rgb(unsigned r, unsigned g, unsigned b) {
    return Colour(r & 0xff) | Colour(g & 0xff) << 8 | Colour(b & 0xff) << 16 | 0xff000000u;
}
constexpr unsigned red(Colour c) {
    return c & 0xff;
}
constexpr unsigned green(Colour c) {
    return (c >> 8) & 0xff;
}
constexpr unsigned blue(Colour c) {
    return (c >> 16) & 0xff;
}
// `c` lit by `k` (0 black, 1 itself, above 1 towards white).
Colour shade(Colour c, double k);
// From `a` (t = 0) to `b` (t = 1).
Colour mix(Colour a, Colour b, double t);

using V2 = std::array<double, 2>;  // pixels, x right, y down

class Image {
  public:
    void reset(int w, int h, Colour fill);
    int w() const { return w_; }
    int h() const { return h_; }
    bool empty() const { return w_ == 0 || h_ == 0; }
    const std::vector<Colour>& pixels() const { return px_; }
    Colour at(int x, int y) const { return px_[size_t(y) * size_t(w_) + size_t(x)]; }
    void set(int x, int y, Colour c) {
        if (unsigned(x) < unsigned(w_) && unsigned(y) < unsigned(h_))
            px_[size_t(y) * size_t(w_) + size_t(x)] = c;
    }
    // A horizontal run [x0, x1) of row y, clipped.
    void span(int y, int x0, int x1, Colour c);
    // Polygons filled by the even-odd rule (a hole inside an outline stays
    // empty), sampled at the pixels' centres.
    void fill(const std::vector<std::vector<V2>>& polys, Colour c);
    // The same with every other `period` pixels along a 45° diagonal: a
    // section's hatching.
    void hatch(const std::vector<std::vector<V2>>& polys, Colour c, int period);
    // A line `width` pixels wide; `dash` > 0: `dash` pixels on, `dash` off.
    void line(V2 a, V2 b, Colour c, double width = 1, int dash = 0);
    void disc(V2 centre, double radius, Colour c);
    void rect(int x0, int y0, int x1, int y1, Colour c);  // [x0, x1) x [y0, y1), clipped

  private:
    int w_ = 0, h_ = 0;
    std::vector<Colour> px_;
    std::vector<double> xs_;  // a row's crossings, kept between fills
    template <class Paint>
    void scan(const std::vector<std::vector<V2>>& polys, Paint paint);
};

}  // namespace pupitre::render
