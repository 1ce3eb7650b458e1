// The plot module's interface (libpupitre-cairo.so): Cairo and libpng, with
// the twenty libraries they bring, are loaded only by the commands that draw
// a PNG or a PDF. Linked into the executable, they were half of the start of
// every command, `pupitre run` of a short program included (issue 14: 2 ms
// of a 44 ms run). console/plot_loader.cpp opens the module and forwards
// write_png, write_pdf, write_text_pdf, write_gray16_png, write_part_png and
// write_part_pdf to it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/output/part_sheet.hpp"
#include "core/output/scene.hpp"

namespace pupitre {

// The version in the entry's name changes with this table.
struct PlotModule {
    bool (*png)(const Scene& scene, int width, std::FILE* out);
    bool (*pdf)(const Scene& scene, std::FILE* out);
    bool (*text_pdf)(const std::string& title, const std::vector<std::string>& lines,
                     std::FILE* out);
    bool (*gray16_png)(const std::vector<uint16_t>& values, int width, int height, std::FILE* out);
    bool (*part_png)(const PartSheet& sheet, int width, std::FILE* out);
    bool (*part_pdf)(const PartSheet& sheet, std::FILE* out);
};

}  // namespace pupitre

// The module's one exported symbol.
#define PUPITRE_PLOT_ENTRY "pupitre_plot_module_v2"
#define PUPITRE_PLOT_FILE "libpupitre-cairo.so"
