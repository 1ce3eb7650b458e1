// The HISTORY page (:history on an open program): every revision of a stored
// program, newest first, with who made it, when and from where; the current
// one marked "*", a revision kept aside by a conflicting save flagged.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/pages.hpp"

namespace pupitre::pages {

void page_history(const View& v, Canvas& c, const Rect& r) {
    if (v.history_number < 0) {
        c.rule(r.y, "HISTORY");
        c.text(2, r.y + 2, "Open a stored program (:edit N), then :history lists its revisions.", Style::dim);
        return;
    }
    c.rule(r.y, "HISTORY  %" + std::to_string(v.history_number) + " revisions, newest first");
    std::vector<Line> lines;
    lines.push_back(Line{}.add("  " + pad("rev", 7) + pad("kind", 9) + pad("when", 18) + pad("who", 12) +
                                   lpad("lines", 6) + "  source",
                               Style::dim));
    for (const HistoryRow& h : v.history) {
        bool cur = h.revision == v.history_current;
        Line l;
        l.add((cur ? "* r" : "  r") + pad(std::to_string(h.revision), 5), cur ? Style::value : Style::normal);
        l.add(pad(h.kind, 9) + pad(h.when, 18) + pad(h.who, 12) + lpad(std::to_string(h.lines), 6) + "  ");
        if (h.conflict) l.add("CONFLICT ", Style::warn);
        l.add(h.source, Style::dim);
        lines.push_back(std::move(l));
    }
    lines.push_back(Line{});
    lines.push_back(Line{}.add(" :restore REV makes a revision current again (a new revision: nothing is lost).",
                               Style::dim));
    lines.push_back(Line{}.add(" :page edit goes back to the editor.", Style::dim));
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
