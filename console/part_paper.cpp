// The part on paper (see part_paper.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/part_paper.hpp"

#include <cmath>
#include <cstdio>

#include "console/plot_loader.hpp"
#include "console/wall_clock.hpp"
#include "core/i18n.hpp"
#include "core/output/part_sheet.hpp"

namespace pupitre {

namespace {

bool ends_with(const std::string& s, const char* tail) {
    const std::string t(tail);
    return s.size() > t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

std::string mm(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

Rgb rgb_of(render::Colour c) {
    return Rgb{uint8_t(render::red(c)), uint8_t(render::green(c)), uint8_t(render::blue(c))};
}

std::string today() {
    return local_time(wall_ms(), "%Y-%m-%d");
}

// The picture rendered so that it prints at a round ratio (2:1, 1:1, 1:2,
// 1:5…) in the sheet's box: drawn once to learn its scale, then zoomed out
// to the round ratio just under it.
render::Picture paper_picture(const render::PartScene& s, const render::Surfaces& sf,
                              render::Look look) {
    const int w = 1900, h = int(std::lround(w * kSheetPictureH / kSheetPictureW));
    look.paper = true;
    render::Picture p = render::render(s, sf, look, w, h);
    const double ratio = (kSheetPictureW / w) / p.mm_per_px;  // paper mm per part mm
    double nice = 1;
    for (double r : {20.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01})
        if (r <= ratio * (1 + 1e-9)) {
            nice = r;
            break;
        }
    if (std::abs(nice / ratio - 1) < 1e-6) return p;
    look.cam.zoom *= nice / ratio;
    look.cam.pan_x *= nice / ratio, look.cam.pan_y *= nice / ratio;
    return render::render(s, sf, look, w, h);
}

// The colour scale of the sheet: 64 colours and its numbers.
void sheet_scale(const render::Legend& l, PartSheet& sheet) {
    const bool dev = l.paint == render::Paint::deviation;
    sheet.scale_title = dev ? tr("deviation from the drawing (µm): green in tolerance, red over, "
                                 "blue under, grey not on the drawing")
                            : tr("depth below the stock as loaded (mm); grey uncut");
    for (int k = 0; k < 64; ++k) sheet.scale.push_back(rgb_of(render::legend_sample(l, k, 64)));
    for (int k = 0; k <= 4; ++k) {
        const double t = k / 4.0;
        const double v = dev ? -l.span_um + 2 * l.span_um * t : l.depth * t;
        char buf[32];
        std::snprintf(buf, sizeof buf, dev && v > 0 ? "%+g" : "%g", v);
        sheet.ticks.emplace_back(t, buf);
    }
}

}  // namespace

std::string dim_text(const render::DimReading& r) {
    const render::DrawnDim& d = r.dim;
    const std::string limits = d.lower == -d.upper
                                   ? mm(d.nominal) + " \u00b1" + mm(d.upper)
                                   : mm(d.nominal) + " " + mm(d.lower) + "/+" + mm(d.upper);
    if (!r.read)
        return strf(tr("%s (%s): no reading: %s"), d.spec.c_str(), limits.c_str(), r.why.c_str());
    char value[32], dev[32];
    std::snprintf(value, sizeof value, "%.3f", r.value);
    std::snprintf(dev, sizeof dev, "%+.0f", r.deviation() * 1000);
    const render::Verdict v = r.verdict();
    // TRANSLATORS: a dimension read on the part: "dia Z-10: 40.052 (40 ±0.02), +52 µm, over".
    return strf(tr("%s: %s (%s), %s µm, %s"), d.spec.c_str(), value, limits.c_str(), dev,
                v == render::Verdict::over    ? tr("over")
                : v == render::Verdict::under ? tr("under")
                                              : tr("in tolerance"));
}

bool wants_picture(const std::string& path, bool mill, bool view_named) {
    if (ends_with(path, ".pdf")) return true;
    return ends_with(path, ".png") && (!mill || view_named);
}

Answer<int> write_part_picture(const std::string& path, const workshop::Workshop& w, const Axes& om,
                               const render::Drawing* drawing, render::Look look,
                               const PaperTitle& title) {
    const auto scene = render::snapshot(w, om, drawing);
    const auto sf =
        render::prepare(*scene, drawing ? render::Paint::deviation : render::Paint::depth, true);
    const render::Picture p = paper_picture(*scene, *sf, look);
    PartSheet sheet;
    sheet.title = title.title;
    sheet.subtitle =
        title.where + " \u00b7 " + today() + " \u00b7 " + std::string(render::mode_word(look.mode));
    sheet.w = p.image.w(), sheet.h = p.image.h();
    sheet.pixels = p.image.pixels();
    sheet.mm_per_px = p.mm_per_px;
    for (size_t i = 0; i < scene->dims.size(); ++i) {
        const render::DimReading& r = scene->dims[i];
        const render::V2 at = i < p.anchor.size() ? p.anchor[i] : render::V2{NAN, NAN};
        sheet.labels.push_back(
            {at[0], at[1], dim_text(r), rgb_of(render::reading_colour(r, p.legend.span_um))});
    }
    sheet_scale(p.legend, sheet);
    if (p.has_stickout)
        sheet.marks.push_back(
            {(p.stick[0][0] + p.stick[1][0]) / 2, p.stick[0][1], strf("%.2f", p.stickout), Rgb{}});
    if (p.has_stickout)
        sheet.notes.push_back(
            strf(tr("stick-out %.2f mm, from the jaws' face to the part's face"), p.stickout));
    sheet.notes.push_back(drawing
                              ? strf(tr("held against the drawing of %s"), drawing->name.c_str())
                              : std::string(tr("no drawing: each surface painted by its depth "
                                               "below the stock as loaded")));
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return {73, strf(tr("cannot write %s"), path.c_str())};
    bool ok = ends_with(path, ".pdf") ? write_part_pdf(sheet, f) : write_part_png(sheet, 2400, f);
    ok = std::fclose(f) == 0 && ok;
    if (!ok) {
        std::remove(path.c_str());
        const std::string module = plot_module_error();
        return {74, module.empty() ? strf(tr("cannot write %s"), path.c_str())
                                   : strf(tr("cannot write %s: %s"), path.c_str(), module.c_str())};
    }
    return {};
}

}  // namespace pupitre
