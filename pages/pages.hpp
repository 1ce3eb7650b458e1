// The pages of the console: each renders the view into a rectangle of the
// canvas (ARCHITECTURE.md, Conventions: pages are pure renderers). One file per page.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/i18n.hpp"
#include "pages/canvas.hpp"
#include "pages/view.hpp"

namespace pupitre::pages {

void page_position(const View& v, Canvas& c, const Rect& r);  // OM and OP
void page_program(const View& v, Canvas& c, const Rect& r);   // the program around the block
void page_info(const View& v, Canvas& c, const Rect& r);
void page_param(const View& v, Canvas& c, const Rect& r);
void page_dir(const View& v, Canvas& c, const Rect& r);
void page_alarm(const View& v, Canvas& c, const Rect& r);
std::string alarm_place(const Diag& d);  // "%300 line 12 N20", "IMD line 3", "JOG"
void page_help(const View& v, Canvas& c, const Rect& r);
void page_pref(const View& v, Canvas& c, const Rect& r);      // origins, touch-off
void page_corr(const View& v, Canvas& c, const Rect& r);      // tool correctors, measurement
void page_edit(const View& v, Canvas& c, const Rect& r);      // EDIT and MODIF
void page_history(const View& v, Canvas& c, const Rect& r);   // a program's revisions
void page_shop(const View& v, Canvas& c, const Rect& r);      // the workshop, its instruments
void page_exercise(const View& v, Canvas& c, const Rect& r);  // the task, the report

// A line of a long page: styled parts, optionally the whole row restyled.
struct Line {
    std::vector<std::pair<std::string, Style>> parts;
    bool fill = false;
    Style fill_style = Style::select;
    Line& add(std::string s, Style st = Style::normal) {
        parts.emplace_back(std::move(s), st);
        return *this;
    }
};
void draw_lines(const std::vector<Line>& lines, int scroll, Canvas& c, const Rect& r);
std::string machine_word(const std::string& name);  // "tour" for the lathe in French
// `lead` (a label, a column) then `text` wrapped in the rest of `width`, its
// next lines under its first: a line of a page that is never cut unseen.
void add_wrapped(std::vector<Line>& out, Line lead, const std::string& text, int width,
                 Style st = Style::normal);

// A machine of the Cazeneuve dialect (page_caz.cpp): its T word ("T204"; the
// NUM's "T2  D4").
bool is_caz(const MachineProfile& m);
std::string tool_word(const MachineProfile& m, int tool, int corrector);
// The axes whose gauge the corrector just chosen has not applied yet ("X Z";
// empty: none): it applies at the next move or touch-off (page_pref.cpp).
std::string gauge_waiting(const Sim& s);
// That said on a page: empty when no gauge waits.
std::string gauge_waiting_note(const Sim& s);
// The columns a line number takes in a page's left margin: `least`, or the
// digits of `last`, the largest number shown (a CAM program has millions of
// lines).
inline int number_width(int last, int least) {
    return std::max(least, int(std::to_string(last).size()));
}
// Splits UTF-8 `text` into lines of at most `width` columns at spaces (none
// for an empty text).
std::vector<std::string> wrap_text(const std::string& text, int width);

// A text kept in English in a table (marked with N_ where it is written),
// in the chosen language; "" stays "" (gettext would answer its header).
inline std::string tr_text(std::string_view s) {
    return s.empty() ? std::string() : std::string(tr(std::string(s).c_str()));
}

// "%-6s"-style padding for the columns of a page, in columns (a translated
// text may hold "é", two bytes and one column).
inline std::string pad(std::string s, size_t w) {
    size_t n = size_t(columns(s));
    if (n < w) s.append(w - n, ' ');
    return s;
}
inline std::string lpad(std::string s, size_t w) {
    size_t n = size_t(columns(s));
    if (n < w) s.insert(0, w - n, ' ');
    return s;
}

}  // namespace pupitre::pages
