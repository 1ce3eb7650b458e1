// What the workshop tells a batch run: crashes as diagnostics, the readings
// asked for, and the part itself as (Z, R) points or an SVG drawing.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/diag.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::workshop {

// One measurement asked for: its reading, or why there is none.
struct Asked {
    Reading r;
    std::string error;
};

// A crash as a diagnostic of the block that ran into it (file and program
// filled by the caller, which knows where the program came from).
Diag crash_diag(const Crash& c);
// ,"workshop":{...} for the JSON summary (pupitre(1), JSON summary).
std::string workshop_json(const Workshop& w, const std::vector<Asked>& asked);
// The readings as text lines for the summary.
std::string readings_text(const std::vector<Asked>& asked);
// The half-section, Z from the part's right-hand face, R a radius: one
// "Z R" line per point, a blank line between outlines.
std::string part_zr(const LatheWorld& w);
// The half-section drawn in SVG, the chuck's jaws outlined, 1 unit = 1 mm.
std::string part_svg(const LatheWorld& w, const std::string& title);
// A machining centre's part as a height image: one 16-bit value per cell,
// rows from +Y (the image's top) down, 0 the stock's bottom and 65535 its
// top as loaded; `mm_per_unit` the scale of the values.
std::vector<uint16_t> height_image(const MillWorld& w, double& mm_per_unit);
// The block seen from above for a drawing: its outline, and the outlines of
// what is cut into it (the height field's cells below its top, merged), as
// (X, Y) polygons in the machine frame to fill even-odd.
std::vector<std::vector<Pt>> block_from_above(const MillWorld& w);
// The JSON that says how to read that image (pupitre-setup(5), THE CUT
// PART): its file, size, cell, origin and scale.
std::string height_json(const MillWorld& w, const std::string& png, double mm_per_unit,
                        const std::string& title);

}  // namespace pupitre::workshop
