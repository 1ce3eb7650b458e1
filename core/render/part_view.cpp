// The PART view's pictures (see part_view.hpp): the modes, the camera's
// steps and the dispatch to each view.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/render/part_view.hpp"

#include <algorithm>
#include <cmath>

namespace pupitre::render {

namespace {

struct ModeRow {
    PartMode mode;
    std::string_view word;
    bool mill;
};
constexpr ModeRow kModes[] = {
    {PartMode::section, "section", false},
    {PartMode::top, "top", true},
    {PartMode::iso, "3d", true},
};

}  // namespace

std::string_view mode_word(PartMode m) {
    for (const ModeRow& r : kModes)
        if (r.mode == m) return r.word;
    return "?";
}

bool parse_mode(std::string_view word, PartMode& m) {
    for (const ModeRow& r : kModes)
        if (r.word == word) {
            m = r.mode;
            return true;
        }
    return false;
}

bool mode_fits(PartMode m, bool mill) {
    for (const ModeRow& r : kModes)
        if (r.mode == m) return r.mill == mill;
    return false;
}

PartMode first_mode(bool mill) {
    return mill ? PartMode::iso : PartMode::section;
}

PartMode next_mode(PartMode m, bool mill) {
    const size_t n = std::size(kModes);
    size_t i = 0;
    while (i < n && kModes[i].mode != m) ++i;
    for (size_t k = 1; k <= n; ++k) {
        const ModeRow& r = kModes[(i + k) % n];
        if (r.mill == mill) return r.mode;
    }
    return m;
}

Camera turned(Camera c, double degrees) {
    c.yaw = std::fmod(c.yaw + degrees, 360.0);
    if (c.yaw < 0) c.yaw += 360;
    return c;
}

Camera tilted(Camera c, double degrees) {
    c.pitch = std::clamp(c.pitch + degrees, kMinPitch, kMaxPitch);
    return c;
}

Camera zoomed(Camera c, double factor) {
    const double z = std::clamp(c.zoom * factor, kMinZoom, kMaxZoom);
    // The point at the picture's centre stays there.
    c.pan_x *= z / c.zoom, c.pan_y *= z / c.zoom;
    c.zoom = z;
    return c;
}

Camera panned(Camera c, double fx, double fy) {
    c.pan_x += fx, c.pan_y += fy;
    return c;
}

Picture render(const PartScene& s, const Surfaces& sf, const Look& look, int w, int h) {
    Picture p;
    p.image.reset(std::max(w, 8), std::max(h, 8), palette(look.paper).background);
    p.legend = sf.legend;
    p.anchor.assign(s.dims.size(), V2{kNaN, kNaN});
    if (!s.mill)
        lathe_section(s, sf, look, p);
    else if (look.mode == PartMode::top)
        mill_top(s, sf, look, p);
    else
        mill_iso(s, sf, look, p);
    return p;
}

}  // namespace pupitre::render
