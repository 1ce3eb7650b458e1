// The part on paper (issue 36): the PART view's picture laid on a sheet
// (core/output/part_sheet.hpp) with its title, the drawing's dimensions
// labelled where they were read, the colour scale and the picture's scale,
// written as PNG or PDF through the plot module; for `:part export` and
// `pupitre run --part-out`.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

#include "console/refusal.hpp"
#include "core/render/part_view.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre {

// Whether `path` asks for the picture: FILE.pdf, or FILE.png on a lathe
// or with a view named (a machining centre's FILE.png without one is its
// height field, workshop_io.hpp).
bool wants_picture(const std::string& path, bool mill, bool view_named);

struct PaperTitle {
    std::string title;  // the program
    std::string where;  // the exercise and the student, or the setup
};

// The picture of the workshop `w` (its tool at machine position `om`),
// painted against `drawing` (null: by depth), seen as `look` says, on a
// sheet written to `path` (.png or .pdf). 0 or an exit status with the
// message (73 a file that cannot be created, 74 a write error).
Answer<int> write_part_picture(const std::string& path, const workshop::Workshop& w, const Axes& om,
                               const render::Drawing* drawing, render::Look look,
                               const PaperTitle& title);

// A dimension read, in words: "dia Z-10: 40.052 (40 ±0.02), +52 µm, over".
std::string dim_text(const render::DimReading& r);

}  // namespace pupitre
