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

}  // namespace pupitre::workshop
