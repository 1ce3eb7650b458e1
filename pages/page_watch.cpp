// The teacher's live view of a class (see page_watch.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/page_watch.hpp"

#include <algorithm>

#include "core/i18n.hpp"
#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

Style state_style(WatchState s) {
    switch (s) {
        case WatchState::working:
            return Style::ok;
        case WatchState::submitted:
        case WatchState::graded:
            return Style::value;
        case WatchState::late:
        case WatchState::disconnected:
            return Style::alarm;
        case WatchState::idle:
            break;
    }
    return Style::dim;
}

// Columns: student, exercise, time, status, crashes, scrapped, last action.
void row_line(Canvas& c, int y, const WatchRow& r, bool selected) {
    int x = 0;
    x += c.text(x, y, pad(r.student, 14), Style::normal, 15);
    x += c.text(x, y, " " + pad(r.exercise, 16), Style::normal, 17);
    x += c.text(x, y, " " + pad(r.time, 10), Style::value, 11);
    x += c.text(x, y, " " + pad(r.status, 16), state_style(r.state), 17);
    x += c.text(x, y, strf(" %3d %3d", r.crashes, r.scrapped), Style::value, 8);
    c.text(x, y, "  " + r.last_action, Style::dim);
    if (selected) c.style(Rect{0, y, c.width(), 1}, Style::select);
}

}  // namespace

void render_watch(const WatchView& v, Canvas& c) {
    c.clear();
    c.rule(0, v.title);
    c.text_right(0, 0, c.width() - 1, " " + v.clock + " ", Style::title);
    const int body = std::max(1, c.height() - 3);
    if (!v.detail_title.empty()) {
        c.text(0, 1, v.detail_title, Style::title);
        for (int i = 0; i < int(v.detail.size()) && i + 2 < body + 1; ++i)
            c.text(0, 2 + i, v.detail[size_t(i)]);
    } else {
        c.text(0, 1,
               pad(tr("STUDENT"), 14) + " " + pad(tr("EXERCISE"), 16) + " " + pad(tr("TIME"), 10) +
                   " " + pad(tr("STATUS"), 16) + " " + tr("CRA SCR  LAST ACTION"),
               Style::dim);
        if (v.rows.empty()) c.text(0, 2, tr("no student in this class yet"), Style::dim);
        // The selected line stays on screen.
        const int first = std::max(0, v.selected - (body - 2));
        for (int i = first, y = 2; i < int(v.rows.size()) && y <= body; ++i, ++y)
            row_line(c, y, v.rows[size_t(i)], i == v.selected);
    }
    c.hline(0, c.height() - 2, c.width());
    c.text(0, c.height() - 1, v.message, Style::status);
}

}  // namespace pupitre::pages
