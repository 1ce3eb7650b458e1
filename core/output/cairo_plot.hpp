// The plot's scene through Cairo (`pupitre plot --png`, `--pdf`): the same
// picture as the SVG, antialiased, as a PNG or as a one-page vector PDF for
// printing. Built into the pupitre_plot library, not the core: the
// interpreter does not depend on Cairo (ARCHITECTURE.md).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "core/output/scene.hpp"

namespace pupitre {

// The scene as a PNG `width` pixels across (64 to 8000), on white paper.
// False when Cairo or the stream fails.
bool write_png(const Scene& scene, int width, std::FILE* out);
// The scene as a one-page PDF, the page the scene's (paper mm), the drawing at
// its scale on paper (Scene::ratio) when printed at 100 %. False on failure.
bool write_pdf(const Scene& scene, std::FILE* out);
// Lines of monospaced text as a PDF on A4 landscape pages, `title` and the
// page's number at the head of each (the teacher's report, pupitre class
// report --pdf). False on failure.
bool write_text_pdf(const std::string& title, const std::vector<std::string>& lines,
                    std::FILE* out);

}  // namespace pupitre
