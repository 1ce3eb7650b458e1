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
    const char* dir = s.spindle_dir() == 3 ? "M03" : s.spindle_dir() == 4 ? "M04" : s.spindle_dir() == 19 ? "M19" : "M05";
    std::snprintf(buf, sizeof buf, "%.0f rev/min  %s", s.rpm(), dir);
    std::string out = buf;
    if (s.spindle_range() >= 40) out += "  M" + std::to_string(s.spindle_range());
    const Modal& m = s.interp().modal();
    if (m.spindle_mode == 96) {
        std::snprintf(buf, sizeof buf, "  G96 %.0f m/min", m.s);
        out += buf;
    }
    return out;
}

std::string feed_text(const Sim& s) {
    char buf[96];
    const Modal& m = s.interp().modal();
    const char* unit = m.feed_mode == 95 ? "mm/rev" : m.feed_mode == 93 ? "1/min" : "mm/min";
    std::snprintf(buf, sizeof buf, "%.0f mm/min now   programmed F%g %s (G%d)", s.feed(), m.feed, unit,
                  m.feed_mode);
    return buf;
}

}  // namespace

void page_position(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    const MachineProfile& m = s.machine();
    bool om_first = v.page == PageId::om;
    c.rule(r.y, om_first ? "OM  machine position" : "OP  program position");
    Axes op = s.op(), om = s.om(), go = s.to_go();
    int y = r.y + 2;
    const int cx[3] = {6, 26, 46};
    std::string h1 = om_first ? "OM machine" : "OP program", h2 = om_first ? "OP program" : "OM machine";
    c.text_right(cx[0], y, 14, h1, Style::dim);
    c.text_right(cx[1], y, 14, h2, Style::dim);
    c.text_right(cx[2], y, 14, "to go", Style::dim);
    ++y;
    for (int a = 0; a < kAxes && y < r.y + r.h; ++a) {
        if (!m.has(a)) continue;
        std::string name(1, kAxisNames[size_t(a)]);
        if (a == X && m.lathe && s.to_display(X, 1) == 2) name += "ø";
        c.text(2, y, name, Style::title);
        if (!s.interp().homed(a)) c.text(2 + int(name.size()) + 1, y, "*", Style::warn);
        double vo = s.to_display(a, op[size_t(a)]), vm = s.to_display(a, om[size_t(a)]);
        double vg = s.to_display(a, go[size_t(a)]);
        c.text_right(cx[0], y, 14, fmt_axis(a, om_first ? vm : vo), Style::big);
        c.text_right(cx[1], y, 14, fmt_axis(a, om_first ? vo : vm), Style::value);
        c.text_right(cx[2], y, 14, fmt_axis(a, vg), Style::value);
        ++y;
    }
    bool any_unhomed = false;
    for (int a = 0; a < kAxes; ++a) any_unhomed |= m.has(a) && !s.interp().homed(a);
    if (any_unhomed) c.text(cx[2] + 16, r.y + 3, "* not homed (POM)", Style::warn);
    ++y;
    auto row = [&](std::string_view label, const std::string& value, Style st = Style::value) {
        if (y >= r.y + r.h) return;
        c.text(2, y, label, Style::dim);
        c.text(12, y, value, st, r.w - 14);
        ++y;
    };
    row("Feed", feed_text(s));
    row("Spindle", spindle_text(s));
    std::string tool = "T" + std::to_string(s.tool()) + "  D" + std::to_string(s.corrector());
    if (s.m7() || s.m8()) tool += std::string("  ") + (s.m7() ? "M07 " : "") + (s.m8() ? "M08" : "");
    row("Tool", tool);
    const Loc& l = s.loc();
    std::string where = s.selected() >= 0 ? "%" + std::to_string(s.selected()) : "no program selected";
    if (l.line > 0) {
        const ProgramText* t = s.text_of(l.prog);
        bool imd = (t && t->file == "IMD") || l.prog == 0;
        where += (imd ? std::string("   at IMD") : "   at %" + std::to_string(l.prog)) + " line " + std::to_string(l.line);
        if (l.n >= 0) where += "  N" + std::to_string(l.n);
    }
    row("Program", where);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%ld block%s   cycle time %.1f s", s.blocks_done(), s.blocks_done() == 1 ? "" : "s",
                  s.cycle_time());
    row("Run", buf);
    // The mode's keys at all times: what Cycle Start does, the jog keys, the step.
    if (!v.mode_hint.empty()) row(mode_name(s.mode()), v.mode_hint, Style::normal);
    if (!v.mode_setting.empty()) row("", v.mode_setting, Style::normal);
    if (l.line > 0) row("Block", std::string(s.line_of(s.text_of(l.prog), l.line)), Style::select);
}

}  // namespace pupitre::pages
