// The machining centre's physical world (issue 15): a block of stock on the
// table, held in a vice or on a plate, with locating pins and a tool setter;
// the cutters' true shapes. The material is kept two ways:
//  - the strokes: every straight piece the cutter's tip swept while cutting,
//    exactly; the instruments cast rays against them (exact to 0.1 µm);
//  - a height field (z-map) of `cell` mm over the stock's top, the top of the
//    material at each cell's centre, for the screen, the export and the
//    contacts (a contact on a face the tools have cut is found to half a
//    cell; the stock's own faces, the floor of a cut, the fixtures are exact).
// Everything is in machine coordinates, mm; a cutter is a solid of
// revolution about its axis (vertical, or tilted along u: then a cell whose
// column it cuts from the side keeps the material above and below, as
// intervals, and its contacts are found at the cells' centres), its tip
// (the end's centre) at `tip`.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace pupitre::workshop {

using P3 = std::array<double, 3>;  // machine X, Y, Z (mm)

// A cutter's axis, a unit vector from its tip towards the spindle: up,
// unless the head or the table is tilted (B, mill_tilt.cpp).
inline constexpr P3 kUp{0, 0, 1};
// Whether the axis leans away from the vertical (by more than 1e-9 rad).
bool leans(const P3& u);

// A milling cutter as it really is, below the gauge line.
struct Cutter {
    double radius = 5;   // mm
    double corner = 0;   // corner radius: 0 a flat end mill, == radius a ball end
    double flute = 20;   // cutting length from the tip; above it, the shank
    double holder = 20;  // the holder's radius; it begins `reach` above the tip
    double reach = 40;   // mm from the tip to the holder's face
    // The bottom surface's height above the tip at a distance d from the
    // axis (0 <= d <= radius): 0 on the flat, rising along the corner.
    double bottom(double d) const;
    // The radius of the cutter's cross-section `u` mm above the tip (u >= 0).
    double slice(double u) const;
};

struct Box3 {
    P3 lo{}, hi{};
};

// A vertical cylinder (a locating pin, the tool setter's plunger).
struct Cylinder {
    double x = 0, y = 0, radius = 3, z0 = 0, z1 = 10;
};

// Which part of the cutter meets something.
enum class Part { flute, shank, holder };

// Where a part of the cutter is: from `base` to `top` mm above the tip
// (the holder's top is +inf), `radius` wide; the flute's bottom is the
// cutter's profile (Cutter::bottom), the others' are flat.
struct PartSpan {
    double radius, base, top;
    bool flute;
};
PartSpan span_of(const Cutter& c, Part part);
// How far above the tip a tilted part is followed (mm): the holder for
// 150 mm above its face (nothing in the workshop stands higher above the
// block), the flute and the shank to their ends.
inline double followed(const Cutter& c, Part part) {
    return span_of(c, part).base + 150;
}

class MillWorld {
  public:
    // The stock as loaded, and the height field's cell (mm, > 0).
    explicit MillWorld(const Box3& stock, double cell = 0.1);
    void new_part();  // fresh stock
    const Box3& stock() const { return stock_; }

    // The height field: nx() x ny() cells from the stock's lo corner; the
    // machine Z of the material's top at cell (i, j)'s centre, or
    // stock().lo[2] where it is cut through.
    int nx() const { return nx_; }
    int ny() const { return ny_; }
    double cell() const { return cell_; }
    float height(int i, int j) const { return h_[size_t(j) * size_t(nx_) + size_t(i)]; }

    // Removes what the cutter sweeps with its tip moving straight from `a`
    // to `b` (the flute and everything above it: the material is a height
    // field, cut from above). Returns the volume removed (mm³, from the
    // height field), 0 when the move cut nothing.
    double cut(const Cutter& c, const P3& a, const P3& b, const P3& u = kUp);

    // How deep `part` of the cutter, tip at `tip`, is into the material (mm:
    // the largest height of material above that part's surface), 0 when it
    // only touches or is clear.
    double depth_into(const Cutter& c, const P3& tip, Part part, const P3& u = kUp) const;
    // The first fraction of the straight move a->b (0..1) where `part` comes
    // deeper than `depth` into the material, within 0.1 µm of travel; 2 when
    // it never does. `before`: the last fraction where it does not yet.
    double first_contact(const Cutter& c, const P3& a, const P3& b, Part part, double depth,
                         bool before = false, const P3& u = kUp) const;
    // A tilted part's surface points from its tip (tilt::surface; the holder
    // followed 150 mm), kept for the last few parts asked for.
    const std::vector<P3>& surface_of(const Cutter& c, Part part, const P3& u) const;
    // The material in cell (i, j)'s column: sorted, disjoint intervals of
    // machine Z (one, from the stock's bottom to height(), unless a tilted
    // cutter went under the top).
    void material(int i, int j, std::vector<std::array<double, 2>>& out) const;

    // What an instrument reads: the material along the line through `at`
    // parallel to `axis` (0 X, 1 Y, 2 Z), as sorted, disjoint intervals of
    // that coordinate, exact from the strokes.
    std::vector<std::array<double, 2>> along(int axis, const P3& at) const;

    // Counts the changes of the material (a cut, fresh stock): every stroke
    // kept counts, even one that takes only a sliver between cell centres.
    uint64_t generation() const { return generation_; }
    // The strokes as text for the store, one per line ("ax ay az bx by bz
    // radius corner", µm integers would lose nothing: %.4f; then "ux uy uz"
    // to 1e-9 when the cutter was tilted); and back: the
    // height field is rebuilt from them (false, and nothing changed, when
    // the text is not one).
    std::string to_text() const;
    bool from_text(std::string_view text);

  private:
    struct Stroke {
        P3 a, b;
        double radius, corner;
        P3 u = kUp;
        bool tilt = false;
        Box3 reach;          // where it can remove material (tilted: within the stock)
        int bi = 0, bj = 0;  // its first bucket of the index (each is listed once per line)
    };
    static constexpr int kTile = 16;  // cells a side of the tiles that keep the highest top
    static bool make_stroke(const P3& a, const P3& b, double radius, double corner, const P3& u,
                            Stroke& s);
    void bound(Stroke& s) const;  // its reach
    bool meets_stock(const Stroke& s) const;
    void record(const Stroke& s);
    double apply(const Stroke& s);
    double side(int axis, int k) const;               // cell k's width along X (0) or Y (1)
    void mark_stale(int i0, int i1, int j0, int j1);  // cells cut: their tiles
    // --- a tilted cutter (mill_tilt.cpp) ---
    double apply_tilted(const Stroke& s);
    // Takes [lo, hi] out of a cell's column: the length taken.
    double carve(size_t cell, double lo, double hi);
    double tilted_depth(const Cutter& c, const P3& tip, const P3& u, Part part, double above) const;
    double tilted_first(const Cutter& c, const P3& a, const P3& b, const P3& u, Part part,
                        double depth, bool before) const;
    // The stock's own faces and top, exact: how deep the part's surface
    // points are in the stock as loaded, where no cut came near.
    double stock_depth(const std::vector<P3>& points, const P3& tip) const;
    struct Surface {
        Cutter c;
        Part part = Part::flute;
        P3 u{};
        std::vector<P3> points;
    };
    // The last parts' (a cutter and the same grown by a contact's margin,
    // three parts each), kept: a contact search asks for them often.
    mutable std::array<Surface, 6> surfaces_;
    mutable size_t next_surface_ = 0;
    // Brings the tiles' highest tops up to date (kept lazily: a pocket's
    // thousands of strokes would each rescan the tiles they cross).
    void refresh() const;
    bool cut_beside(int i, int j) const;  // a neighbour of cell (i, j) is cut
    // The lowest the stroke removes at (x, y) (+inf when it does not reach
    // it), within `tol` mm; and the interval it removes along a line.
    static double lowest(const Stroke& s, double x, double y, double tol);
    static bool removal(const Stroke& s, int axis, const P3& at, double& lo, double& hi);
    // The deepest column (as depth_into), or any value above `above` as
    // soon as one is found.
    double penetration(const Cutter& c, const P3& tip, Part part, double above) const;
    double column_depth(const Cutter& c, const PartSpan& sh, const P3& tip, size_t cell, double h,
                        double d) const;
    std::vector<std::array<double, 2>> spans(const Cutter& c, const P3& a, const P3& b, Part part,
                                             double depth) const;
    Box3 stock_;
    double cell_;
    int nx_ = 0, ny_ = 0;
    std::vector<float> h_;
    // The columns a tilted cutter went into under their top: their material.
    std::unordered_map<size_t, std::vector<std::array<double, 2>>> under_;
    std::vector<Stroke> strokes_;
    uint64_t generation_ = 0;
    std::vector<double> xs_, ys_;              // the cells' centres (clamped into the stock)
    std::vector<uint8_t> touched_;             // a stroke reached the cell's centre
    int tx_ = 0, ty_ = 0;                      // tiles
    mutable std::vector<float> tile_max_;      // the highest top in each tile
    mutable std::vector<uint8_t> tile_stale_;  // cut since it was last refreshed
    mutable bool stale_ = false;
    double bucket_ = 5;  // mm a side of the strokes' index buckets
    int bx_ = 0, by_ = 0;
    std::vector<std::vector<uint32_t>> buckets_;
};

// The same contact test against a fixture (exact): how deep `part` of the
// cutter with its tip at `tip` is into a box or a vertical cylinder (with
// the axis over it, the horizontal overlap is the section's radius plus the
// distance to the nearest side). Exact and piecewise smooth along a move, so
// the caller finds a first contact by bisecting on it.
double depth_into(const Cutter& c, const P3& tip, Part part, const Box3& b);
double depth_into(const Cutter& c, const P3& tip, Part part, const Cylinder& k);
// A tilted part, as points of its surface (tilt::surface) from its tip at
// `tip`: how deep the deepest of them is inside a box or a cylinder (exact
// for a face square to an axis, the points holding the outermost ones).
double depth_into(const std::vector<P3>& points, const P3& tip, const Box3& b);
double depth_into(const std::vector<P3>& points, const P3& tip, const Cylinder& k);

}  // namespace pupitre::workshop
