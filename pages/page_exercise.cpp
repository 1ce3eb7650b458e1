// The EXERCISE page (pupitre-exercise(5)): the task, what to find, the
// drawing and the instruments while the attempt runs; after :submit the
// report: each value against the truth with its arithmetic, the mistakes
// named, the part against the drawing.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

Style style_of(ExLine k) {
    switch (k) {
        case ExLine::title:
            return Style::title;
        case ExLine::heading:
            return Style::value;
        case ExLine::note:
            return Style::dim;
        case ExLine::ok:
            return Style::ok;
        case ExLine::wrong:
            return Style::alarm;
        case ExLine::text:
            break;
    }
    return Style::normal;
}

}  // namespace

void page_exercise(const View& v, Canvas& c, const Rect& r) {
    // TRANSLATORS: the EXERCISE page's title; EXERCISE is the page's name.
    c.rule(r.y, tr("EXERCISE"));
    std::vector<Line> lines;
    const int width = std::max(20, r.w - 2);
    if (v.exercise.empty())
        add_wrapped(lines, Line{}.add(" "),
                    tr("No exercise in progress: pupitre exercise NAME starts one "
                       "(pupitre exercise list shows them)."),
                    width, Style::dim);
    for (const auto& [kind, text] : v.exercise) {
        // Report tables keep their columns; the rest wraps under its indent.
        const size_t indent = std::min(text.find_first_not_of(' '), text.size());
        const std::string lead(indent, ' ');
        const bool table = (kind == ExLine::ok || kind == ExLine::wrong) && indent == 0;
        std::vector<std::string> rows = table ? std::vector<std::string>{text.substr(indent)}
                                              : wrap_text(text.substr(indent), width - int(indent));
        if (rows.empty()) rows.emplace_back();
        for (const std::string& row : rows)
            lines.push_back(Line{}.add(" " + lead + row, style_of(kind)));
    }
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
