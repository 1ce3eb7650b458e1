// The EDIT page: the program being edited, block by block, with the cursor,
// the marked range, the block the last check stopped on, and in MODIF the
// blocks already prepared (locked). The input line inserts a block after the
// cursor, or replaces it after Enter (modify).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>

#include "pages/pages.hpp"

namespace pupitre::pages {

void page_edit(const View& v, Canvas& c, const Rect& r) {
    if (!v.edit_lines) {
        c.rule(r.y, "EDIT");
        c.text(2, r.y + 2,
               // xgettext:no-c-format
               tr("No program open: :edit N opens program %N (a new one if it does not exist),"),
               Style::dim);
        c.text(2, r.y + 3, tr("or choose one on the DIR page (F6) and type :edit."), Style::dim);
        return;
    }
    const auto& lines = *v.edit_lines;
    std::string title =
        std::string(v.edit_modif ? "MODIF" : "EDIT") + "  %" + std::to_string(v.edit_number);
    if (!v.edit_modif)
        title += "  " + (v.edit_revision > 0 ? strf(tr("revision %d"), v.edit_revision)
                                             : std::string(tr("new")));
    if (v.edit_dirty) title += std::string("  ") + tr("modified");
    c.rule(r.y, title);
    int rows = r.h - 2;
    int n = int(lines.size());
    int first = std::clamp(v.edit_cursor - rows / 3, 0, std::max(0, n - rows));
    int ma = v.edit_mark < 0 ? -1 : std::min(v.edit_mark, v.edit_cursor);
    int mb = v.edit_mark < 0 ? -1 : std::max(v.edit_mark, v.edit_cursor);
    const int w = number_width(std::min(n, first + rows), 5);
    for (int i = 0; i < rows && first + i < n; ++i) {
        int k = first + i;
        int y = r.y + 1 + i;
        bool locked = k < v.edit_locked;
        Style st = k == v.edit_error ? Style::alarm : locked ? Style::dim : Style::normal;
        c.text_right(r.x, y, w, std::to_string(k + 1), Style::dim);
        c.put(r.x + w, y,
              locked                            ? U'#'
              : (k >= ma && k <= mb && ma >= 0) ? U'|'
                                                : U' ',
              Style::dim);
        c.text(r.x + w + 2, y, lines[size_t(k)], st, r.w - w - 3);
        if (k == v.edit_cursor) {
            c.style(Rect{r.x, y, r.w, 1}, k == v.edit_error ? Style::alarm : Style::select);
            c.put(r.x + w + 1, y, U'>', k == v.edit_error ? Style::alarm : Style::select);
        }
    }
    std::string help =
        v.edit_modify ? tr("Enter replaces the block; Ctrl-U clears the line")
                      : tr("type a block: inserted after >   Enter: modify   Del: delete   :save");
    if (v.edit_modif && !v.edit_modify)
        help = tr("# blocks already prepared; Cycle Start runs the changed text, RAZ drops it");
    c.text(2, r.y + r.h - 1, help, Style::dim, r.w - 3);
}

}  // namespace pupitre::pages
