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

}  // namespace

void page_info(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    const Interpreter& in = s.interp();
    const Modal& m = in.modal();
    const Frames& f = in.frames();
    c.rule(r.y, "INFO  functions in force");
    std::vector<Line> lines;
    auto kv = [&](std::string k, std::string val) {
        Line l;
        l.add(" " + pad(std::move(k), 11), Style::dim).add(std::move(val), Style::value);
        lines.push_back(std::move(l));
    };
    std::string gs = g(m.motion) + " " + g(m.plane) + " " + g(m.radcomp) + " " + (m.incremental ? "G91" : "G90") +
                     " " + g(m.feed_mode) + " " + g(m.spindle_mode) + " " + (m.inch ? "G70" : "G71") + " " +
                     g(m.cycle);
    if (f.g53) gs += " G53";
    if (f.mirror.any()) gs += " G51";
    if (f.scale_on) gs += " G74";
    kv("G", gs);
    std::string ms = m.spindle_dir == 3 ? "M03" : m.spindle_dir == 4 ? "M04" : m.spindle_dir == 19 ? "M19" : "M05";
    if (m.range >= 0) ms += " M4" + std::to_string(m.range);
    ms += m.m7 ? " M07" : "";
    ms += m.m8 ? " M08" : "";
    if (!m.m7 && !m.m8) ms += " M09";
    ms += m.overrides_off ? " M49" : " M48";
    ms += m.clamped ? " M10" : " M11";
    if (m.modif_inhibited) ms += " M999";
    if (m.coded_m >= 0) ms += " M" + std::to_string(m.coded_m);
    kv("M", ms);
    char buf[128];
    const char* unit = m.feed_mode == 95 ? "mm/rev" : m.feed_mode == 93 ? "1/min (inverse time)" : "mm/min";
    std::snprintf(buf, sizeof buf, "F%g %s", m.feed, unit);
    kv("Feed", buf);
    if (m.spindle_mode == 96)
        std::snprintf(buf, sizeof buf, "S%g m/min (G96 constant surface speed)%s", m.s, m.smax > 0 ? "" : "");
    else
        std::snprintf(buf, sizeof buf, "S%g rev/min", m.s);
    std::string sp = buf;
    if (m.smax > 0) {
        std::snprintf(buf, sizeof buf, "   G92 S%g limit", m.smax);
        sp += buf;
    }
    kv("Spindle", sp);
    kv("Tool", "T" + std::to_string(m.t) + " (in spindle T" + std::to_string(m.tool_in_spindle) + ")  D" +
                   std::to_string(m.d));
    std::string plane = m.plane == 17 ? "XY (G17)" : m.plane == 18 ? "ZX (G18)" : "YZ (G19)";
    kv("Plane", plane + (m.radcomp == 41 ? "   radius comp. left (G41)"
                         : m.radcomp == 42 ? "   radius comp. right (G42)"
                                           : "   no radius compensation (G40)"));
    lines.push_back(Line{});
    lines.push_back(Line{}.add(s.machine().lathe ? " Offsets (X as a radius)" : " Offsets", Style::title));
    kv("PREF", axes_text(s, f.pref));
    kv("DEC1", axes_text(s, f.dec1));
    kv("DEC3", axes_text(s, f.dec3));
    kv("G59", axes_text(s, f.g59));
    kv("gauge", axes_text(s, f.gauge));
    std::string mir;
    for (int a = 0; a < kAxes; ++a)
        if (f.mirror[size_t(a)]) mir += std::string(1, kAxisNames[size_t(a)]) + " ";
    std::snprintf(buf, sizeof buf, "mirror %s  scale %s%.3f  ED %.4f deg", mir.empty() ? "none" : mir.c_str(),
                  f.scale_on ? "" : "(off) ", f.scale, f.ed);
    kv("Transform", buf);
    lines.push_back(Line{});
    std::snprintf(buf, sizeof buf, "block skip %s   optional stop M01 %s   overrides %s",
                  in.options().block_skip ? "ON" : "off", in.options().optional_stop ? "ON" : "off",
                  m.overrides_off ? "inhibited (M49)" : "active (M48)");
    kv("Switches", buf);
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
