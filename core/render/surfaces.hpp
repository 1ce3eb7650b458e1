// The part's surfaces painted (issue 36): each surface a dimension of the
// drawing reads takes that reading's colour (inside the tolerance, over,
// under); with no drawing every surface takes its depth below the stock as
// loaded. Made once for a scene and a way of painting, then drawn from any
// side (lathe_view.cpp, mill_view.cpp, mill_iso.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "core/render/palette.hpp"
#include "core/render/part_scene.hpp"

namespace pupitre::render {

using Poly = std::vector<workshop::Pt>;  // (Z, R) mm

// A height field and its colours, at one level of detail.
struct Level {
    int nx = 0, ny = 0;
    double cell = 0;
    double x0 = 0, y0 = 0;  // its -X -Y corner (machine mm)
    std::vector<float> h;   // the highest top under each cell
    std::vector<Colour> c;  // that top's colour
    float at(int i, int j) const { return h[size_t(j) * size_t(nx) + size_t(i)]; }
    Colour colour(int i, int j) const { return c[size_t(j) * size_t(nx) + size_t(i)]; }
};

struct Surfaces {
    Paint paint = Paint::depth;
    Legend legend;
    // lathe: the material's outlines (mm) and each edge's colour (edge k
    // from point k to k + 1; 0: not drawn, an edge on the spindle axis);
    // the stock as loaded; the drawing's nominal lines, (Z, R) pairs.
    std::vector<Poly> outline, stock;
    std::vector<std::vector<Colour>> edge;
    std::vector<std::array<workshop::Pt, 2>> nominal;
    // machining centre: the block from fine to coarse (each level half the
    // cells of the one before), and the work-holding and table around it
    // as one coarse height field.
    std::vector<Level> block;
    Level around;
    // Where each dimension's surface is (lathe: Z, R, 0; mill: X, Y, Z);
    // NaN when it was not found.
    std::vector<std::array<double, 3>> anchor;
};

// The surfaces of `s` painted by `paint` (deviation falls back to depth
// when the scene has no drawing); the work-holding in the colours of the
// screen or of `paper`.
std::shared_ptr<const Surfaces> prepare(const PartScene& s, Paint paint, bool paper = false);

// The lathe's and the mill's halves of prepare() (surfaces_lathe.cpp,
// surfaces_mill.cpp).
void lathe_surfaces(const PartScene& s, Surfaces& out);
void mill_surfaces(const PartScene& s, Surfaces& out, bool paper);
// The radii at which the outlines cross machine Z `z`, sorted.
void crossings(const std::vector<Poly>& outline, double z, std::vector<double>& rs);

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace pupitre::render
