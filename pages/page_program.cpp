// The PROG page: the program text around the block being executed, the block
// highlighted, with line numbers (the manual's display of the current program),
// and beside each block of the run its time as planned.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <vector>

#include "pages/pages.hpp"

namespace pupitre::pages {

void page_program(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    const Loc& l = s.loc();
    int prog = l.line > 0 ? l.prog : s.selected();
    const ProgramText* p = s.text_of(prog);
    std::string title = "PROG";
    if (p) {
        title += "  %" + std::to_string(p->number);
        if (!p->title.empty()) title += "  " + p->title;
    }
    c.rule(r.y, title);
    if (!p) {
        c.text(2, r.y + 2,
               tr("No program selected: choose one on the DIR page (F6) or type :load N."),
               Style::dim);
        return;
    }
    int rows = r.h - 1;
    int current = (l.line > 0 && l.prog == prog) ? l.line : 0;
    // The current block a third of the way down, or the top of the program.
    int first = current ? current - rows / 3 : p->first_line;
    first += v.scroll;
    if (first < p->first_line) first = p->first_line;
    const int w = number_width(first + rows - 1, 6);
    // Each block's time as planned, on the right, for the blocks of the run
    // shown or about to be (issue 35): a column only when there is one.
    std::vector<double> times(size_t(std::max(rows, 0)), -1);
    bool timed = false;
    for (int i = 0; i < rows; ++i) {
        times[size_t(i)] = s.block_time(p->number, first + i);
        timed = timed || times[size_t(i)] >= 0;
    }
    const int tw = timed && r.w >= 40 ? 11 : 0;
    for (int i = 0; i < rows; ++i) {
        int line = first + i;
        std::string_view text = s.line_of(p, line);
        if (text.data() == nullptr) break;  // past the end of the program
        int y = r.y + 1 + i;
        bool cur = line == current;
        c.text_right(r.x, y, w, std::to_string(line), cur ? Style::select : Style::dim);
        c.text(r.x + w + 1, y, text, cur ? Style::select : Style::normal, r.w - w - 2 - tw);
        if (tw && times[size_t(i)] >= 0)
            c.text_right(r.x + r.w - tw, y, tw - 1, strf(tr("%.2f s"), times[size_t(i)]),
                         cur ? Style::select : Style::dim);
        if (cur) {
            c.style(Rect{r.x, y, r.w, 1}, Style::select);
            c.put(r.x + w, y, U'>', Style::select);
        }
    }
}

}  // namespace pupitre::pages
