// A picture in memory (see image.hpp). Polygons are filled by scanlines
// over an edge table: each edge is met only on the rows it crosses, so a
// part of 10,000 passes (tens of thousands of edges) fills in a few
// milliseconds.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/render/image.hpp"

#include <algorithm>
#include <cmath>

namespace pupitre::render {

Colour shade(Colour c, double k) {
    auto ch = [&](unsigned v) {
        const double x = k <= 1 ? v * std::max(0.0, k) : v + (255 - v) * std::min(1.0, k - 1);
        return unsigned(std::clamp(x + 0.5, 0.0, 255.0));  // x >= 0: no library round
    };
    return rgb(ch(red(c)), ch(green(c)), ch(blue(c)));
}

Colour mix(Colour a, Colour b, double t) {
    t = std::clamp(t, 0.0, 1.0);
    auto ch = [&](unsigned x, unsigned y) {
        return unsigned(x + (double(y) - x) * t + 0.5);  // never below 0
    };
    return rgb(ch(red(a), red(b)), ch(green(a), green(b)), ch(blue(a), blue(b)));
}

void Image::reset(int w, int h, Colour fill) {
    w_ = std::max(0, w), h_ = std::max(0, h);
    px_.assign(size_t(w_) * size_t(h_), fill);
}

void Image::span(int y, int x0, int x1, Colour c) {
    if (unsigned(y) >= unsigned(h_)) return;
    x0 = std::max(x0, 0), x1 = std::min(x1, w_);
    if (x0 >= x1) return;
    Colour* row = px_.data() + size_t(y) * size_t(w_);
    std::fill(row + x0, row + x1, c);
}

void Image::rect(int x0, int y0, int x1, int y1, Colour c) {
    for (int y = std::max(y0, 0); y < std::min(y1, h_); ++y) span(y, x0, x1, c);
}

// The rows' spans inside the polygons (even-odd), handed to `paint(y, x0,
// x1)`: an edge table bucketed by the first row each edge crosses.
template <class Paint>
void Image::scan(const std::vector<std::vector<V2>>& polys, Paint paint) {
    struct Edge {
        double x, dx;  // x at the current row's centre, per row
        int last;      // the last row it crosses
    };
    std::vector<std::vector<Edge>> starts(static_cast<size_t>(h_));
    for (const auto& p : polys)
        for (size_t i = 0; i < p.size(); ++i) {
            V2 a = p[i], b = p[(i + 1) % p.size()];
            if (a[1] == b[1]) continue;
            if (a[1] > b[1]) std::swap(a, b);
            // Rows whose centre y + 0.5 lies in [a.y, b.y).
            int r0 = int(std::ceil(a[1] - 0.5)), r1 = int(std::ceil(b[1] - 0.5)) - 1;
            r0 = std::max(r0, 0), r1 = std::min(r1, h_ - 1);
            if (r0 > r1) continue;
            const double dx = (b[0] - a[0]) / (b[1] - a[1]);
            starts[size_t(r0)].push_back({a[0] + (r0 + 0.5 - a[1]) * dx, dx, r1});
        }
    std::vector<Edge> active;
    for (int y = 0; y < h_; ++y) {
        active.insert(active.end(), starts[size_t(y)].begin(), starts[size_t(y)].end());
        if (active.empty()) continue;
        xs_.clear();
        for (const Edge& e : active) xs_.push_back(e.x);
        std::sort(xs_.begin(), xs_.end());
        for (size_t k = 0; k + 1 < xs_.size(); k += 2)
            paint(y, int(std::ceil(xs_[k] - 0.5)), int(std::ceil(xs_[k + 1] - 0.5)));
        size_t n = 0;
        for (Edge& e : active)
            if (e.last > y) {
                e.x += e.dx;
                active[n++] = e;
            }
        active.resize(n);
    }
}

void Image::fill(const std::vector<std::vector<V2>>& polys, Colour c) {
    scan(polys, [&](int y, int x0, int x1) { span(y, x0, x1, c); });
}

void Image::hatch(const std::vector<std::vector<V2>>& polys, Colour c, int period) {
    period = std::max(period, 2);
    scan(polys, [&](int y, int x0, int x1) {
        x0 = std::max(x0, 0), x1 = std::min(x1, w_);
        for (int x = x0; x < x1; ++x)
            if ((x + y) % period == 0) px_[size_t(y) * size_t(w_) + size_t(x)] = c;
    });
}

void Image::line(V2 a, V2 b, Colour c, double width, int dash) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len = std::hypot(dx, dy);
    const int steps = std::max(1, int(std::ceil(len)));
    const double r = width / 2;
    const int ri = int(std::ceil(r - 0.5));
    for (int k = 0; k <= steps; ++k) {
        if (dash > 0 && (k / dash) % 2 == 1) continue;
        const double x = a[0] + dx * k / steps, y = a[1] + dy * k / steps;
        if (width <= 1.5) {
            set(int(std::floor(x)), int(std::floor(y)), c);
            continue;
        }
        for (int oy = -ri; oy <= ri; ++oy)
            for (int ox = -ri; ox <= ri; ++ox)
                if (ox * ox + oy * oy <= r * r + 0.25)
                    set(int(std::floor(x)) + ox, int(std::floor(y)) + oy, c);
    }
}

void Image::disc(V2 centre, double radius, Colour c) {
    const int y0 = int(std::floor(centre[1] - radius)), y1 = int(std::ceil(centre[1] + radius));
    for (int y = std::max(y0, 0); y <= std::min(y1, h_ - 1); ++y) {
        const double dy = y + 0.5 - centre[1];
        const double h2 = radius * radius - dy * dy;
        if (h2 < 0) continue;
        const double hw = std::sqrt(h2);
        span(y, int(std::ceil(centre[0] - hw - 0.5)), int(std::ceil(centre[0] + hw - 0.5)), c);
    }
}

}  // namespace pupitre::render
