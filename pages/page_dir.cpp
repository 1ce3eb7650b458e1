// The DIR page: the programs in the store with their titles, the selected one
// marked, a revision kept aside by a conflicting save flagged. Up and Down
// move the cursor, Enter loads, Del deletes (asking twice); a number typed
// on the input line loads that program; the last lines say how to create
// and edit one.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>

#include "pages/pages.hpp"

namespace pupitre::pages {

void page_dir(const View& v, Canvas& c, const Rect& r) {
    // TRANSLATORS: the DIR page's title: DIR is the page's name.
    c.rule(r.y, strf(tr("DIR  programs in memory (%zu)"), v.programs.size()));
    int y = r.y + 1;
    // TRANSLATORS: DIR page column headers: "program" at most 11 columns,
    // "lines" at most 7 (right-aligned numbers under it), "rev" at most 4.
    c.text(2, y, pad(tr("program"), 12) + pad(tr("lines"), 8) + pad(tr("rev"), 5) + tr("title"),
           Style::dim);
    ++y;
    int rows = r.h - 4;
    int by = r.y + r.h - 2;
    c.text(2, by, tr("Enter selects the program (or type its number); Del twice deletes it."),
           Style::dim);
    c.text(2, by + 1,
           // xgettext:no-c-format
           tr(":edit N edits or creates %N; Alt-e edits the selected program."), Style::dim);
    if (v.programs.empty()) {
        c.text(2, y,
               // xgettext:no-c-format
               tr("No program yet: :edit 1 creates %1 (or, from a shell, pupitre import FILE)."),
               Style::dim);
        return;
    }
    int cur = std::clamp(v.dir_cursor, 0, int(v.programs.size()) - 1);
    int first = std::max(0, std::min(cur - rows / 2, int(v.programs.size()) - rows));
    for (int i = 0; i < rows && first + i < int(v.programs.size()); ++i) {
        const DirEntry& e = v.programs[size_t(first + i)];
        bool sel = v.sim->selected() == e.number;
        std::string line = (sel ? "* %" : "  %") + pad(std::to_string(e.number), 9) +
                           lpad(std::to_string(e.lines), 6) + "  " +
                           lpad(std::to_string(e.revision), 4) + "  ";
        int x = c.text(0, y + i, line, sel ? Style::value : Style::normal, r.w);
        if (e.conflict > 0)
            x += c.text(x, y + i, strf(tr("CONFLICT r%d"), e.conflict) + " ", Style::warn, r.w - x);
        c.text(x, y + i, e.title, sel ? Style::value : Style::normal, r.w - x);
        if (first + i == cur) c.style(Rect{r.x, y + i, r.w, 1}, Style::select);
    }
}

}  // namespace pupitre::pages
