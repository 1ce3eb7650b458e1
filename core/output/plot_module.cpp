// The plot module's entry (plot_module.hpp): its table of the Cairo and
// libpng writers. Everything else in the module is hidden.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/plot_module.hpp"

#include "core/output/cairo_plot.hpp"
#include "core/output/height_png.hpp"
#include "core/output/part_sheet.hpp"

extern "C" __attribute__((visibility("default"))) const pupitre::PlotModule*
pupitre_plot_module_v2() {
    static const pupitre::PlotModule kModule{&pupitre::write_png,      &pupitre::write_pdf,
                                             &pupitre::write_text_pdf, &pupitre::write_gray16_png,
                                             &pupitre::write_part_png, &pupitre::write_part_pdf};
    return &kModule;
}
