// write_png, write_pdf, write_text_pdf, write_gray16_png, write_part_png and
// write_part_pdf for the
// executable: forwarded to the plot module (core/output/plot_module.hpp),
// opened at the first call. The module is the file PUPITRE_PLOT_MODULE names,
// or else it is looked for next to the executable
// (the build tree), in ../lib/pupitre from it (an installation), then in the
// build tree it was built in. When none loads, each writer fails and
// plot_module_error() says why, for the caller's message.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/plot_loader.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "console/refusal.hpp"
#include "core/i18n.hpp"
#include "core/output/cairo_plot.hpp"
#include "core/output/height_png.hpp"
#include "core/output/part_sheet.hpp"
#include "core/output/plot_module.hpp"

#ifndef PUPITRE_PLOT_BUILD_DIR
#define PUPITRE_PLOT_BUILD_DIR ""
#endif

namespace pupitre {
namespace {

namespace fs = std::filesystem;

Answer<const PlotModule*> open_file(const fs::path& file) {
    void* h = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) return {nullptr, dlerror()};
    using Entry = const PlotModule* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(h, PUPITRE_PLOT_ENTRY));
    if (!entry) {
        Answer<const PlotModule*> no{nullptr, dlerror()};
        dlclose(h);
        return no;
    }
    return {entry(), {}};  // kept open: the writers live in it
}

Answer<const PlotModule*> open_module() {
    std::error_code ec;
    // PUPITRE_PLOT_MODULE: that file and no other (a package's own place).
    if (const char* file = std::getenv("PUPITRE_PLOT_MODULE"); file && *file) {
        if (!fs::exists(file, ec))
            return {nullptr, strf(tr("%s not found (PUPITRE_PLOT_MODULE)"), file)};
        return open_file(file);
    }
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    std::vector<fs::path> dirs;
    if (!ec) {
        dirs.push_back(exe.parent_path());
        dirs.push_back(exe.parent_path().parent_path() / "lib" / "pupitre");
    }
    if (*PUPITRE_PLOT_BUILD_DIR) dirs.push_back(PUPITRE_PLOT_BUILD_DIR);
    for (const fs::path& d : dirs) {
        const fs::path file = d / PUPITRE_PLOT_FILE;
        if (fs::exists(file, ec)) return open_file(file);
    }
    return {nullptr, strf(tr("%s not found next to the executable or in ../lib/pupitre"),
                          PUPITRE_PLOT_FILE)};
}

// The module and why it did not load, opened once (the batch commands and the console's thread).
const Answer<const PlotModule*>& loaded() {
    static const Answer<const PlotModule*> a = open_module();
    return a;
}

const PlotModule* module() {
    return loaded().value;
}

}  // namespace

std::string plot_module_error() {
    return module() ? std::string() : loaded().why;
}

bool write_png(const Scene& scene, int width, std::FILE* out) {
    const PlotModule* m = module();
    return m && m->png(scene, width, out);
}

bool write_pdf(const Scene& scene, std::FILE* out) {
    const PlotModule* m = module();
    return m && m->pdf(scene, out);
}

bool write_text_pdf(const std::string& title, const std::vector<std::string>& lines,
                    std::FILE* out) {
    const PlotModule* m = module();
    return m && m->text_pdf(title, lines, out);
}

bool write_gray16_png(const std::vector<uint16_t>& values, int width, int height, std::FILE* out) {
    const PlotModule* m = module();
    return m && m->gray16_png(values, width, height, out);
}

bool write_part_png(const PartSheet& sheet, int width, std::FILE* out) {
    const PlotModule* m = module();
    return m && m->part_png(sheet, width, out);
}

bool write_part_pdf(const PartSheet& sheet, std::FILE* out) {
    const PlotModule* m = module();
    return m && m->part_pdf(sheet, out);
}

}  // namespace pupitre
