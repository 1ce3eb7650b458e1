// The lathe's physical world in its half-section (Z, R): the stock as the
// tools leave it, the chuck and the tailstock, the tools' true shapes. Exact
// 2-D Booleans by Clipper (libpolyclipping) on integers of 0.1 µm; arcs and
// nose radii become polygons within 0.5 µm (issue 15: ≤ 1 µm chord error).
// Z is the machine's, R the distance from the spindle axis.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <clipper.hpp>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/workshop/setup.hpp"

namespace pupitre::workshop {

using CPath = ClipperLib::Path;
using CPaths = ClipperLib::Paths;

inline constexpr double kUnit = 1e-4;   // mm per Clipper unit
inline constexpr double kChord = 5e-4;  // mm: the largest chord error of a polygonised arc

ClipperLib::IntPoint to_int(Pt p);  // (Z, R) mm -> units
Pt to_mm(const ClipperLib::IntPoint& p);

// A polygon of `r` around `c` (mm) within kChord of the circle.
CPath circle(Pt c, double r);
// Points along an arc from `a` about `c` by `sweep` radians (+: towards +R
// from +Z, counter-clockwise in (Z, R)), within kChord; `a` is not included.
void arc_points(Pt a, Pt c, double sweep, std::vector<Pt>& out);

// The direction from the nose centre to the tool point P of orientation C
// (geometry::kNose), C0 taken as C3 for the insert's shape.
void nose_direction(int c, int& sx, int& sz);

// A tool's true shape relative to its tool point P: the insert (nose circle
// and its two cutting edges) and the holder that carries it.
struct ToolShape {
    CPath insert, holder;
};
ToolShape tool_shape(const ToolTruth& t);

// What a move ran into.
enum class Obstacle { none, material, chuck, tailstock, gauge };

class LatheWorld {
  public:
    explicit LatheWorld(const LatheSetup& s);
    LatheWorld() = default;  // nothing: no part, no chuck (a machining centre's workshop)
    void new_part();         // fresh stock from the setup
    const CPaths& material() const { return part_; }
    const CPaths& chuck() const { return chuck_; }
    const CPaths& tailstock() const { return tail_; }
    // A gauge block the operator holds against the jaws' face (seed 004's
    // exam: "a 100 mm gauge block on the work-holder face"): `length` mm
    // along Z from chuck.z, on a jaw, 2 to 11 mm above the bar; 0: none.
    void set_gauge_block(double length);
    double gauge_block() const { return gauge_length_; }
    const CPaths& gauge() const { return gauge_; }
    const LatheSetup& setup() const { return s_; }

    // The area a shape sweeps along a tool point's path (mm; at least one
    // point), mirrored about the axis so that a tool past the centre cuts
    // what it meets on the other side.
    static CPaths sweep(const CPath& shape, const std::vector<Pt>& path);
    // How deep `swept` goes into an obstacle (mm): twice the area over the
    // perimeter of the largest overlap, 0 when it only touches.
    double depth_into(const CPaths& swept, Obstacle what) const;
    // Whether `what` comes into the box Z [z0, z1], R [r0, r1] (mm, R a
    // distance from the axis): when not, a shape swept there meets nothing
    // of it, and the sweep need not be made.
    bool near(Obstacle what, double z0, double r0, double z1, double r1) const;
    // Removes `swept` from the material; returns the area removed (mm²).
    double cut(const CPaths& swept);
    // Counts the changes of the material (a cut, fresh stock).
    uint64_t generation() const { return generation_; }
    // The material as text for the store: one outline per line, "Z R" pairs
    // of integers in 0.1 µm; and back (false, and nothing changed, when the
    // text is not one).
    std::string to_text() const;
    bool from_text(std::string_view text);

    // --- what the instruments read, from the material itself ---
    bool right_face(double& z) const;  // the part's right-hand face
    // The outside and inside radius of the material at machine Z `z`; false
    // when there is no material there (inside: false too when it is solid).
    bool outer_radius(double z, double& r) const;
    bool inner_radius(double z, double& r) const;
    // The Z extent of the groove whose bottom is at `z`; false if `z` is not
    // on a bottom (the profile leaves the level on both sides).
    bool groove(double z, double& left, double& right) const;

  private:
    struct Box {
        ClipperLib::cInt x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // empty when x1 < x0
        bool meets(const Box& o) const {
            return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1;
        }
    };
    static Box box(const CPaths& p);
    const CPaths& obstacle(Obstacle what) const;
    const Box& box_of(Obstacle what) const;
    mutable Box part_box_;
    mutable uint64_t part_box_gen_ = ~uint64_t(0);
    Box chuck_box_, tail_box_, gauge_box_;
    CPaths gauge_;
    double gauge_length_ = 0;
    LatheSetup s_;
    CPaths part_, chuck_, tail_;
    uint64_t generation_ = 0;
    void crossings(double z, std::vector<double>& rs) const;
};

}  // namespace pupitre::workshop
