// The PART view's pictures (issue 36), drawn from the workshop's material:
// the lathe's half-section (the stock as loaded, what was removed, the
// jaws, the stick-out, the drawing's lines, the tool where it stands) with
// the part seen from outside, revolved, below the axis; the machining
// centre's block seen from above, shaded, and in 3-D (turned, tilted,
// zoomed, panned), with its vice or plate, its pins and the cutter. Each
// surface is painted as surfaces.hpp says. Pure: the same scene, surfaces,
// look and size give the same pixels (the golden images rely on it).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string_view>
#include <vector>

#include "core/render/image.hpp"
#include "core/render/surfaces.hpp"

namespace pupitre::render {

enum class PartMode : uint8_t { section, top, iso };
std::string_view mode_word(PartMode m);  // section, top, 3d
bool parse_mode(std::string_view word, PartMode& m);
// Whether the machine's views include `m` (the lathe: section; the
// machining centre: top and 3d).
bool mode_fits(PartMode m, bool mill);
PartMode first_mode(bool mill);
PartMode next_mode(PartMode m, bool mill);

// Where the picture is seen from. Angles in degrees: `yaw` the horizontal
// direction looked along (90: towards +Y, from the front), `pitch` above
// the horizon; `zoom` 1 fits the part, pan in fractions of the picture.
struct Camera {
    double yaw = 60, pitch = 35, zoom = 1, pan_x = 0, pan_y = 0;
    bool operator==(const Camera&) const = default;
};
inline constexpr double kMinPitch = 10, kMaxPitch = 85, kMinZoom = 0.25, kMaxZoom = 256;
Camera turned(Camera c, double degrees);  // yaw, kept in [0, 360)
Camera tilted(Camera c, double degrees);  // pitch, within [kMinPitch, kMaxPitch]
Camera zoomed(Camera c, double factor);   // within [kMinZoom, kMaxZoom]
// Pan by fractions of the picture; the view follows, so that a step moves
// the part by the same part of the screen at any zoom.
Camera panned(Camera c, double fx, double fy);

struct Look {
    PartMode mode = PartMode::section;
    Camera cam;
    bool paper = false;  // white paper (an export), else the dark screen
    bool operator==(const Look&) const = default;
};

struct Picture {
    Image image;
    double mm_per_px = 0;  // in the picture's plane
    // Where each dimension's surface shows (pixels); NaN when it does not.
    std::vector<V2> anchor;
    // The lathe's stick-out, from the jaws' face to the part's face, drawn
    // from `stick[0]` to `stick[1]`.
    bool has_stickout = false;
    double stickout = 0;
    std::array<V2, 2> stick{};
    Legend legend;
};

// The picture `w` x `h` pixels (square pixels) of the scene `s` painted as
// `sf` (prepare(s, ...)).
Picture render(const PartScene& s, const Surfaces& sf, const Look& look, int w, int h);

// Each view (lathe_view.cpp, mill_view.cpp, mill_iso.cpp).
void lathe_section(const PartScene& s, const Surfaces& sf, const Look& look, Picture& p);
void mill_top(const PartScene& s, const Surfaces& sf, const Look& look, Picture& p);
void mill_iso(const PartScene& s, const Surfaces& sf, const Look& look, Picture& p);

}  // namespace pupitre::render
