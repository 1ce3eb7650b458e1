// The current point pages, OM and OP: the axes in the program frame (OP) and on
// the machine scale (OM), the distance to go, feed, spindle, tool, corrector,
// program and block. `:page om` puts the machine column first.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>

#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

std::string spindle_text(const Sim& s) {
    char buf[96];
    const char* dir = s.spindle_dir() == 3    ? "M03"
                      : s.spindle_dir() == 4  ? "M04"
                      : s.spindle_dir() == 19 ? "M19"
                                              : "M05";
    std::string out = strf(tr("%.0f rev/min  %s"), s.rpm(), dir);
    // The Cazeneuve's variator has two named ranges (003:720, 900-906).
    if (s.spindle_range() >= 40 && is_caz(s.machine()))
        out += std::string("  ") + (s.spindle_range() == 40 ? tr("harnais") : tr("volée"));
    else if (s.spindle_range() >= 40)
        out += "  M" + std::to_string(s.spindle_range());
    const Modal& m = s.modal();  // the block shown's
    if (m.spindle_mode == 96) {
        std::snprintf(buf, sizeof buf, "  G96 %.0f m/min", m.s);
        out += buf;
    }
    return out;
}

std::string feed_text(const Sim& s) {
    const Modal& m = s.modal();  // the block shown's
    const char* unit = m.feed_mode == 95 ? tr("mm/rev") : m.feed_mode == 93 ? "1/min" : "mm/min";
    return strf(tr("%.0f mm/min now   programmed F%g %s (G%d)"), s.feed(), m.feed, unit,
                m.feed_mode);
}

// Large digits for a big terminal, three rows high, as a panel's position
// display (issue 12.7): half blocks, 3 columns a glyph and 1 of space.
struct Glyph {
    char ch;
    const char* rows[3];
};
constexpr Glyph kGlyphs[] = {
    {'0', {"█▀█", "█ █", "▀▀▀"}}, {'1', {" ▀█", "  █", "  ▀"}}, {'2', {"▀▀█", "█▀▀", "▀▀▀"}},
    {'3', {"▀▀█", " ▀█", "▀▀▀"}}, {'4', {"█ █", "▀▀█", "  ▀"}}, {'5', {"█▀▀", "▀▀█", "▀▀▀"}},
    {'6', {"█▀▀", "█▀█", "▀▀▀"}}, {'7', {"▀▀█", "  █", "  ▀"}}, {'8', {"█▀█", "█▀█", "▀▀▀"}},
    {'9', {"█▀█", "▀▀█", "▀▀▀"}}, {'-', {"   ", "▀▀▀", "   "}}, {'.', {" ", " ", "▀"}},
};

const Glyph* glyph(char ch) {
    for (const Glyph& g : kGlyphs)
        if (g.ch == ch) return &g;
    return nullptr;
}

int big_width(const std::string& s) {
    int w = 0;
    for (char ch : s)
        if (const Glyph* g = glyph(ch)) w += columns(g->rows[0]) + 1;
    return w;
}

// `s` in large digits, right-aligned to end at column `right`.
void big_text(Canvas& c, int right, int y, const std::string& s, Style st) {
    int x = right - big_width(s);
    for (char ch : s) {
        const Glyph* g = glyph(ch);
        if (!g) continue;
        for (int row = 0; row < 3; ++row) c.text(x, y + row, g->rows[row], st);
        x += columns(g->rows[0]) + 1;
    }
}

// The axes: the first origin's column (in large digits on a big page), the
// other origin's, the distance to go; '*' marks an axis not homed. Returns the
// row after the table.
int axes_table(const View& v, Canvas& c, const Rect& r, bool om_first) {
    const Sim& s = *v.sim;
    const MachineProfile& m = s.machine();
    Axes op = s.op(), om = s.om(), go = s.to_go();
    int y = r.y + 2;
    // 160x48 and the like: the first column in large digits, the same layout.
    const bool big = r.w >= 120 && r.h >= 40 && !c.ascii();
    const int cx[3] = {6, big ? 50 : 26, big ? 70 : 46};
    const int w0 = big ? 40 : 14;
    // TRANSLATORS: column headers of the position page, at most 13 columns
    // each: the machine coordinates (OM), the program's (OP), the distance to go.
    std::string h1 = om_first ? tr("OM machine") : tr("OP program"),
                h2 = om_first ? tr("OP program") : tr("OM machine");
    c.text_right(cx[0], y, w0, h1, Style::dim);
    c.text_right(cx[1], y, 14, h2, Style::dim);
    c.text_right(cx[2], y, 14, tr("to go"), Style::dim);
    ++y;
    for (int a = 0; a < kAxes && y < r.y + r.h; ++a) {
        if (!m.has(a)) continue;
        std::string name(1, kAxisNames[size_t(a)]);
        if (a == X && m.lathe && s.to_display(X, 1) == 2) name += "ø";
        int row = big ? y + 1 : y;  // the small columns beside the middle of the digits
        c.text(2, row, name, Style::title);
        if (!s.interp().homed(a)) c.text(2 + columns(name) + 1, row, "*", Style::warn);
        double vo = s.to_display(a, op[size_t(a)]), vm = s.to_display(a, om[size_t(a)]);
        double vg = s.to_display(a, go[size_t(a)]);
        if (big)
            big_text(c, cx[0] + w0, y, fmt_axis(a, om_first ? vm : vo), Style::big);
        else
            c.text_right(cx[0], y, w0, fmt_axis(a, om_first ? vm : vo), Style::big);
        c.text_right(cx[1], row, 14, fmt_axis(a, om_first ? vo : vm), Style::value);
        c.text_right(cx[2], row, 14, fmt_axis(a, vg), Style::value);
        y += big ? 4 : 1;
    }
    bool any_unhomed = false;
    for (int a = 0; a < kAxes; ++a) any_unhomed |= m.has(a) && !s.interp().homed(a);
    if (any_unhomed) c.text(cx[2] + 16, r.y + 3, tr("* not homed (POM)"), Style::warn);
    return y;
}

// The labelled rows under the axes, as many as the page holds.
struct Rows {
    Canvas& c;
    const Rect& r;
    int y;
    void add(std::string_view label, const std::string& value, Style st = Style::value) {
        if (y >= r.y + r.h) return;
        c.text(2, y, label, Style::dim);
        c.text(12, y, value, st, r.w - 14);
        ++y;
    }
};

// The tool, its corrector and the coolant; the touch probe's lamp when the
// workshop's electric probe is in the spindle.
void tool_rows(const Sim& s, Rows& rows) {
    std::string tool = tool_word(s.machine(), s.tool(), s.corrector());
    if (s.m7() || s.m8())
        tool += std::string("  ") + (s.m7() ? "M07 " : "") + (s.m8() ? "M08" : "");
    rows.add(tr("Tool"), tool);
    // A corrector chosen whose gauge is not applied yet (T1 D1 M6 in IMD):
    // OP shows the position without it, and says so under the tool.
    if (const std::string waiting = gauge_waiting_note(s); !waiting.empty())
        rows.add("", waiting, Style::warn);
    if (const workshop::Workshop* w = s.shop(); w && w->probe_in_use()) {
        bool lit = w->probe_contact(s.om());
        const Canvas& c = rows.c;
        // TRANSLATORS: OP page: the touch probe's lamp, lit or not; at most 9 columns for the
        // label.
        rows.add(tr("Probe"),
                 lit ? (c.ascii() ? std::string("* ") : std::string("\u25cf ")) + tr("contact")
                     : (c.ascii() ? std::string("o ") : std::string("\u25cb ")) + tr("open"),
                 lit ? Style::alarm : Style::dim);
    }
}

// The selected program and where the run is, the blocks done and the cycle
// time, the mode's keys, the current block.
void program_rows(const View& v, Rows& rows) {
    const Sim& s = *v.sim;
    const Loc& l = s.loc();
    std::string where =
        s.selected() >= 0 ? "%" + std::to_string(s.selected()) : tr("no program selected");
    if (l.line > 0) {
        const ProgramText* t = s.text_of(l.prog);
        bool imd = (t && t->file == "IMD") || l.prog == 0;
        where += "   " + (imd ? strf(tr("at IMD line %d"), l.line)
                              : strf(tr("at %%%d line %d"), l.prog, l.line));
        if (l.n >= 0) where += "  N" + std::to_string(l.n);
    }
    rows.add(tr("Program"), where);
    rows.add(tr("Run"), strf(trn("%ld block   cycle time %.1f s", "%ld blocks   cycle time %.1f s",
                                 (unsigned long)s.blocks_done()),
                             s.blocks_done(), s.cycle_time()));
    // The mode's keys at all times: what Cycle Start does, the jog keys, the step.
    if (!v.mode_hint.empty()) rows.add(mode_name(s.mode()), v.mode_hint, Style::normal);
    if (!v.mode_setting.empty()) rows.add("", v.mode_setting, Style::normal);
    if (l.line > 0)
        rows.add(tr("Block"), std::string(s.line_of(s.text_of(l.prog), l.line)), Style::select);
}

}  // namespace

void page_position(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    bool om_first = v.page == PageId::om;
    // TRANSLATORS: the position page's title: OM (origine mesure) and OP
    // (origine programme) are the page's names.
    c.rule(r.y, om_first ? tr("OM  machine position") : tr("OP  program position"));
    Rows rows{c, r, axes_table(v, c, r, om_first) + 1};
    // TRANSLATORS: labels of the position page (Feed, Spindle, Tool, Program,
    // Run, Block): at most 9 columns each.
    rows.add(tr("Feed"), feed_text(s));
    rows.add(tr("Spindle"), spindle_text(s));
    tool_rows(s, rows);
    program_rows(v, rows);
}

}  // namespace pupitre::pages
