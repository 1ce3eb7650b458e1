// The HISTORY page (:history on an open program): every revision of a stored
// program, newest first, with who made it, when and from where; the current
// one marked "*", a revision kept aside by a conflicting save flagged.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

// The kinds of revision the store records (store::kind_name), as the HISTORY
// page shows them.
// TRANSLATORS: a kind of revision on the HISTORY page: at most 8 columns.
[[maybe_unused]] const char* const kKinds[] = {N_("seed"), N_("import"), N_("save"), N_("restore"),
                                               N_("delete")};

}  // namespace

void page_history(const View& v, Canvas& c, const Rect& r) {
    if (v.history_number < 0) {
        c.rule(r.y, "HISTORY");
        c.text(2, r.y + 2,
               tr("Open a stored program (:edit N), then :history lists its revisions."),
               Style::dim);
        return;
    }
    // TRANSLATORS: the HISTORY page's title: HISTORY is the page's name, %%%d the program (%300).
    c.rule(r.y, strf(tr("HISTORY  %%%d revisions, newest first"), v.history_number));
    std::vector<Line> lines;
    // TRANSLATORS: HISTORY page column headers: rev at most 6 columns, kind 8,
    // when 17, who 11, lines 6.
    lines.push_back(Line{}.add("  " + pad(tr("rev"), 7) + pad(tr("kind"), 9) + pad(tr("when"), 18) +
                                   pad(tr("who"), 12) + lpad(tr("lines"), 6) + "  " + tr("source"),
                               Style::dim));
    for (const HistoryRow& h : v.history) {
        bool cur = h.revision == v.history_current;
        Line l;
        l.add((cur ? "* r" : "  r") + pad(std::to_string(h.revision), 5),
              cur ? Style::value : Style::normal);
        l.add(pad(tr_text(h.kind), 9) + pad(h.when, 18) + pad(h.who, 12) +
              lpad(std::to_string(h.lines), 6) + "  ");
        if (h.conflict) l.add(std::string(tr("CONFLICT")) + " ", Style::warn);
        l.add(h.source, Style::dim);
        lines.push_back(std::move(l));
    }
    lines.push_back(Line{});
    lines.push_back(Line{}.add(
        std::string(" ") +
            tr(":restore REV makes a revision current again (a new revision: nothing is lost)."),
        Style::dim));
    lines.push_back(
        Line{}.add(std::string(" ") + tr(":page edit goes back to the editor."), Style::dim));
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
