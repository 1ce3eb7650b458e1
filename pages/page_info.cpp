// The INFO page: the G functions in force by group, the M functions, F S T D,
// the plane and the offsets in force (PREF, DEC1, DEC3, G59, gauge, mirror,
// scale, ED), as the controller prepares them.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>

#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

std::string g(int n) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "G%02d", n);
    return buf;
}

std::string axes_text(const Sim& s, const Axes& v) {
    std::string out;
    const MachineProfile& m = s.machine();
    for (int a = 0; a < kAxes; ++a) {
        if (!m.has(a)) continue;
        out += std::string(1, kAxisNames[size_t(a)]) + lpad(fmt_axis(a, v[size_t(a)]), 10) + "  ";
    }
    return out;
}

// One labelled line of the page.
void kv(std::vector<Line>& lines, std::string k, std::string val) {
    Line l;
    l.add(" " + pad(std::move(k), 11), Style::dim).add(std::move(val), Style::value);
    lines.push_back(std::move(l));
}

// The gauge applied, and the one waiting for the next move or touch-off
// (T1 D1 M6 in IMD has chosen it, no axis has moved yet).
void gauge_line(const Sim& s, const Axes& gauge, std::vector<Line>& lines) {
    kv(lines, tr("gauge"), axes_text(s, gauge));
    if (const std::string waiting = gauge_waiting_note(s); !waiting.empty())
        lines.push_back(Line{}.add(std::string(12, ' ')).add(waiting, Style::warn));
}

// The G functions in force, one a group, then G53, G51 and G74 when active.
std::string g_functions(const Modal& m, const Frames& f) {
    std::string gs = g(m.motion) + " " + g(m.plane) + " " + g(m.radcomp) + " " +
                     (m.incremental ? "G91" : "G90") + " " + g(m.feed_mode) + " " +
                     g(m.spindle_mode) + " " + (m.inch ? "G70" : "G71") + " " + g(m.cycle);
    if (f.g53) gs += " G53";
    if (f.mirror.any()) gs += " G51";
    if (f.scale_on) gs += " G74";
    return gs;
}

// The M functions in force: spindle, range, coolant, overrides, clamp, M999,
// the last coded M.
std::string m_functions(const Modal& m) {
    std::string ms = m.spindle_dir == 3    ? "M03"
                     : m.spindle_dir == 4  ? "M04"
                     : m.spindle_dir == 19 ? "M19"
                                           : "M05";
    if (m.range >= 0) ms += " M4" + std::to_string(m.range);
    ms += m.m7 ? " M07" : "";
    ms += m.m8 ? " M08" : "";
    if (!m.m7 && !m.m8) ms += " M09";
    ms += m.overrides_off ? " M49" : " M48";
    ms += m.clamped ? " M10" : " M11";
    if (m.modif_inhibited) ms += " M999";
    if (m.coded_m >= 0) ms += " M" + std::to_string(m.coded_m);
    return ms;
}

// G and M, then F S T D, the plane and the radius compensation.
void modal_lines(const Sim& s, std::vector<Line>& lines) {
    const Modal& m = s.modal();
    kv(lines, "G", g_functions(m, s.frames()));
    kv(lines, "M", m_functions(m));
    char buf[128];
    const char* unit = m.feed_mode == 95   ? tr("mm/rev")
                       : m.feed_mode == 93 ? tr("1/min (inverse time)")
                                           : "mm/min";
    std::snprintf(buf, sizeof buf, "F%g %s", m.feed, unit);
    // TRANSLATORS: INFO page labels (Feed, Spindle, Tool, Plane, Transform,
    // Switches): at most 10 columns each.
    kv(lines, tr("Feed"), buf);
    std::string sp = m.spindle_mode == 96 ? strf(tr("S%g m/min (G96 constant surface speed)"), m.s)
                                          : strf(tr("S%g rev/min"), m.s);
    if (m.smax > 0) sp += "   " + strf(tr("G92 S%g limit"), m.smax);
    kv(lines, tr("Spindle"), sp);
    kv(lines, tr("Tool"), strf(tr("T%d (in spindle T%d)  D%d"), m.t, m.tool_in_spindle, m.d));
    std::string plane = m.plane == 17 ? "XY (G17)" : m.plane == 18 ? "ZX (G18)" : "YZ (G19)";
    kv(lines, tr("Plane"),
       plane + "   " +
           (m.radcomp == 41   ? tr("radius comp. left (G41)")
            : m.radcomp == 42 ? tr("radius comp. right (G42)")
                              : tr("no radius compensation (G40)")));
}

// The offsets of each axis, the mirror, scale and rotation, the switches.
void offset_lines(const Sim& s, std::vector<Line>& lines) {
    const Interpreter& in = s.interp();
    const Modal& m = s.modal();
    const Frames& f = s.frames();
    lines.push_back(Line{}.add(
        std::string(" ") + (s.machine().lathe ? tr("Offsets (X as a radius)") : tr("Offsets")),
        Style::title));
    kv(lines, "PREF", axes_text(s, f.pref));
    kv(lines, "DEC1", axes_text(s, f.dec1));
    kv(lines, "DEC3", axes_text(s, f.dec3));
    kv(lines, "G59", axes_text(s, f.g59));
    gauge_line(s, f.gauge, lines);
    std::string mir;
    for (int a = 0; a < kAxes; ++a)
        if (f.mirror[size_t(a)]) mir += std::string(1, kAxisNames[size_t(a)]) + " ";
    std::string scale_off = f.scale_on ? "" : std::string(tr("(off)")) + " ";
    kv(lines, tr("Transform"),
       strf(tr("mirror %s  scale %s%.3f  ED %.4f deg"), mir.empty() ? tr("none") : mir.c_str(),
            scale_off.c_str(), f.scale, f.ed));
    lines.push_back(Line{});
    kv(lines, tr("Switches"),
       strf(tr("block skip %s   optional stop M01 %s   overrides %s"),
            in.options().block_skip ? tr("ON") : tr("off"),
            in.options().optional_stop ? tr("ON") : tr("off"),
            m.overrides_off ? tr("inhibited (M49)") : tr("active (M48)")));
}

// The functions in force of this controller (003:819-1123): motion, CNP,
// G90/G91, G94/G95, G96/G97; M3/M4/M5 and the coolant.
std::string caz_g(const Modal& m) {
    return strf("G%02d G%02d %s G%02d G%02d", m.motion, m.radcomp, m.incremental ? "G91" : "G90",
                m.feed_mode, m.spindle_mode);
}

std::string caz_m(const Modal& m) {
    std::string ms = m.spindle_dir == 3 ? "M03" : m.spindle_dir == 4 ? "M04" : "M05";
    return ms + (m.m8 ? " M08" : " M09");
}

// The INFO page of this controller: its functions, F S T, the CNP, its
// origin and the gauge, the switches.
void caz_info_lines(const Sim& s, std::vector<Line>& lines) {
    const Interpreter& in = s.interp();
    const Modal& m = s.modal();
    kv(lines, "G", caz_g(m));
    kv(lines, "M", caz_m(m));
    kv(lines, tr("Feed"),
       m.feed_mode == 95 ? strf(tr("F%g mm/rev (G95)"), m.feed)
                         : strf(tr("F%g mm/min (G94)"), m.feed));
    std::string sp = m.spindle_mode == 96 ? strf(tr("S%g m/min (G96 constant surface speed)"), m.s)
                                          : strf(tr("S%g rev/min"), m.s);
    // The variator's two ranges (003:903-906): the low one, "harnais", and
    // the high one, "volée".
    if (m.range == 0) sp += "   " + std::string(tr("low range (harnais)"));
    if (m.range == 1) sp += "   " + std::string(tr("high range (volée)"));
    kv(lines, tr("Spindle"), sp);
    // TRANSLATORS: INFO page of the Cazeneuve lathe: T204 is turret position 2, corrector 04.
    kv(lines, tr("Tool"),
       strf(tr("%s: turret position %d, corrector %02d"), tool_word(s.machine(), m.t, m.d).c_str(),
            m.t, m.d));
    kv(lines, tr("CNP"),
       m.radcomp == 41   ? tr("nose radius, tool left (G41)")
       : m.radcomp == 42 ? tr("nose radius, tool right (G42)")
                         : tr("no nose-radius compensation (G40)"));
    lines.push_back(Line{});
    lines.push_back(
        Line{}.add(std::string(" ") + tr("Origin and gauge (X as a radius)"), Style::title));
    kv(lines, tr("origin"), axes_text(s, s.frames().pref));
    gauge_line(s, s.frames().gauge, lines);
    lines.push_back(Line{});
    kv(lines, tr("Switches"),
       strf(tr("block skip %s   optional stop M01 %s"),
            in.options().block_skip ? tr("ON") : tr("off"),
            in.options().optional_stop ? tr("ON") : tr("off")));
}

// The last run's cycle time as the plan gives it (the OP page's), and the
// time at the feeds alone beside it once the program has ended (issue 35).
void cycle_line(const Sim& s, std::vector<Line>& lines) {
    if (!s.ran_program() || s.mode() == Mode::test) return;
    // TRANSLATORS: INFO page label, at most 10 columns.
    kv(lines, tr("Cycle"),
       s.feed_time() >= 0 ? strf(tr("%.1f s with the accelerations (%.1f s at the feeds alone)"),
                                 s.cycle_time(), s.feed_time())
                          : strf(tr("%.1f s with the accelerations, so far"), s.cycle_time()));
}

// The life of tool `t`'s edge in seconds, as the workshop's setup gives it
// (tool.N.life); 0 when it does not.
double edge_life(const Sim& s, int t) {
    if (!s.shop()) return 0;
    for (const workshop::ToolTruth& tt : s.shop()->setup().tools)
        if (tt.position == t) return tt.life * 60;
    return 0;
}

// Each tool's share of the program once it has ended, as `run`'s tool lines
// give it (issue 35): cutting time, passes, length cut, rapid time, and
// after how many parts its edge is changed where the setup gives its life.
void tool_lines(const Sim& s, std::vector<Line>& lines) {
    if (s.tool_times().empty() || s.mode() == Mode::test) return;
    // TRANSLATORS: the INFO page's table of each tool's time: the columns'
    // heads (cutting time, passes, length cut, rapid time, the edge's life),
    // each at most as wide as its column (9, 6, 11, 8 columns).
    bool lives = false;  // the edge's column only where the setup gives a life
    for (const plan::ToolRow& t : s.tool_times()) lives = lives || edge_life(s, t.tool) > 0;
    std::string head = strf("%-4s %9s %6s %11s %8s", "", tr("cutting"), tr("passes"),
                            tr("cut (mm)"), tr("rapids"));
    if (lives) head += std::string("  ") + tr("edge");
    kv(lines, tr("Tools"), std::move(head));
    for (const plan::ToolRow& t : s.tool_times()) {
        std::string row = strf("T%-3d %7.1f s %6ld %11.3f %6.1f s", t.tool, t.cut_seconds, t.passes,
                               t.cut_length, t.rapid_seconds);
        if (long n = plan::parts_per_edge(t.cut_seconds, edge_life(s, t.tool)))
            // TRANSLATORS: the INFO page's tool table: after how many parts the edge is changed.
            row += "  " + strf(trn("every %ld part", "every %ld parts", n), n);
        kv(lines, "", std::move(row));
    }
}

}  // namespace

void page_info(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    // TRANSLATORS: the INFO page's title: INFO is the page's name.
    c.rule(r.y, tr("INFO  functions in force"));
    std::vector<Line> lines;
    if (is_caz(s.machine())) {
        caz_info_lines(s, lines);
        cycle_line(s, lines);
        tool_lines(s, lines);
    } else {
        modal_lines(s, lines);
        cycle_line(s, lines);
        tool_lines(s, lines);
        lines.push_back(Line{});
        offset_lines(s, lines);
    }
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
