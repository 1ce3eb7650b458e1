// The workshop's files (see workshop_io.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/workshop_io.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "console/plot_loader.hpp"
#include "core/i18n.hpp"
#include "core/output/height_png.hpp"
#include "core/render/part_view.hpp"
#include "core/training/exercise.hpp"
#include "core/workshop/report.hpp"

namespace pupitre {

namespace {

const char* const kNotPng =
    N_("a machining centre's part is a 16-bit PNG height field (FILE.png) or a picture "
       "(FILE.pdf)");

bool ends_with(const std::string& s, const char* tail) {
    const std::string t(tail);
    return s.size() > t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

// Writes `text` to `path` ("-": stdout).
Answer<int> write_text(const std::string& path, const std::string& text) {
    std::FILE* f = path == "-" ? stdout : std::fopen(path.c_str(), "w");
    if (!f) return {73, strf(tr("cannot write %s"), path.c_str())};
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    ok = (f == stdout ? std::fflush(f) : std::fclose(f)) == 0 && ok;
    if (!ok) return {74, strf(tr("cannot write %s"), path.c_str())};
    return {};
}

Answer<int> write_mill(const std::string& path, const workshop::MillWorld& m,
                       const std::string& title) {
    if (!ends_with(path, ".png")) return {64, tr(kNotPng)};
    double scale = 0;
    const std::vector<uint16_t> v = workshop::height_image(m, scale);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return {73, strf(tr("cannot write %s"), path.c_str())};
    bool ok = write_gray16_png(v, m.nx(), m.ny(), f);
    ok = std::fclose(f) == 0 && ok;
    if (!ok) {
        std::remove(path.c_str());  // no half-written picture
        const std::string module = plot_module_error();
        return {74, module.empty() ? strf(tr("cannot write %s"), path.c_str())
                                   : strf(tr("cannot write %s: %s"), path.c_str(), module.c_str())};
    }
    const std::string json = path.substr(0, path.size() - 4) + ".json";
    const size_t slash = path.rfind('/');
    const std::string png = slash == std::string::npos ? path : path.substr(slash + 1);
    return write_text(json, workshop::height_json(m, png, scale, title));
}

}  // namespace

std::string read_setup(const std::string& name, const MachineProfile& m, workshop::Setup& s) {
    if (!workshop::builtin_setup(name, s)) {
        std::ifstream in(name);
        training::Exercise e;
        if (!in && training::builtin_exercise(name, e))
            return strf(tr("'%s' is an exercise: its setup is hidden (pupitre exercise %s starts "
                           "it)"),
                        name.c_str(), name.c_str());
        if (!in)
            return strf(tr("unknown setup '%s' (lathe, mill, mill5, cazeneuve, or a .setup file)"),
                        name.c_str());
        std::ostringstream text;
        text << in.rdbuf();
        // An exercise's file is not a setup: its truth is for the student
        // to find (docs/decisions.md, Exercises hide the truth: run --setup refuses it).
        if (training::parse_exercise(text.str(), e).empty())
            return strf(tr("%s is an exercise: its setup is hidden (pupitre exercise %s starts "
                           "it)"),
                        name.c_str(), name.c_str());
        if (std::string why = workshop::parse_setup(text.str(), s); !why.empty())
            return strf(tr("%s: %s"), name.c_str(), why.c_str());
    }
    if ((s.kind == "lathe") != m.lathe) {
        std::string why =
            m.lathe ? strf(tr("setup '%s' is a machining centre's, the machine is a lathe"),
                           name.c_str())
                    : strf(tr("setup '%s' is a lathe's, the machine is a machining centre"),
                           name.c_str());
        s = workshop::Setup{};
        return why;
    }
    if (!m.lathe && m.has(A)) {
        // The workshop turns the part with a C table (mill5) and tilts the
        // cutter with a B head (mill5) or table (mill4), about Y: an A axis
        // would tilt it about X, which it does not model.
        s = workshop::Setup{};
        return strf(tr("machine '%s' has an A axis: the workshop models a C table and a B head "
                       "or table only"),
                    m.name.c_str());
    }
    return {};
}

std::string part_name_problem(const std::string& path, const std::string& view,
                              const workshop::Setup& s) {
    const bool mill = s.kind == "mill";
    if (!view.empty()) {
        render::PartMode m;
        if (!render::parse_mode(view, m) || !render::mode_fits(m, mill))
            return mill ? tr("--part-view: the machining centre's views are top and 3d")
                        : tr("--part-view: the lathe's view is section");
        if (path.empty() || !(ends_with(path, ".png") || ends_with(path, ".pdf")))
            return tr("--part-view draws a picture: --part-out FILE.png or FILE.pdf");
    }
    if (path.empty() || !mill || ends_with(path, ".png") || ends_with(path, ".pdf")) return {};
    return tr(kNotPng);
}

Answer<int> write_part(const std::string& path, const workshop::Workshop& w,
                       const std::string& title) {
    if (const workshop::MillWorld* m = w.mill()) return write_mill(path, *m, title);
    const bool svg = ends_with(path, ".svg");
    return write_text(path,
                      svg ? workshop::part_svg(w.world(), title) : workshop::part_zr(w.world()));
}

plan::EdgeLife edge_life(const workshop::Setup& s, const plan::EdgeLife& given) {
    plan::EdgeLife life;
    for (const workshop::ToolTruth& t : s.tools)
        if (t.life > 0) life.tool[t.position] = t.life * 60;
    if (given.all > 0) {
        life.tool.clear();
        life.all = given.all;
    }
    for (const auto& [tool, seconds] : given.tool) life.tool[tool] = seconds;
    return life;
}

}  // namespace pupitre
