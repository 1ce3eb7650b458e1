// What the pages show differently for a machine of the Cazeneuve dialect
// (seed 003, pupitre-cazeneuve(5)): its T word, its functions in force, its
// one origin. The thesis's controller has no L or E variables, no DEC1, DEC3
// or G59, no mirror or scale: the pages show none of them.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/pages.hpp"

namespace pupitre::pages {

bool is_caz(const MachineProfile& m) {
    return m.dialect == Dialect::cazeneuve;
}

// NUM: "T2  D4"; Cazeneuve: T204, the turret position then the two digits of
// its corrector (003:1036-1039).
std::string tool_word(const MachineProfile& m, int tool, int corrector) {
    if (is_caz(m)) return strf("T%d%02d", tool, corrector);
    return "T" + std::to_string(tool) + "  D" + std::to_string(corrector);
}

namespace {

void kv(std::vector<Line>& lines, std::string k, std::string val) {
    Line l;
    l.add(" " + pad(std::move(k), 11), Style::dim).add(std::move(val), Style::value);
    lines.push_back(std::move(l));
}

std::string axes_text(const Sim& s, const Axes& v) {
    std::string out;
    for (int a = 0; a < kAxes; ++a)
        if (s.machine().has(a))
            out +=
                std::string(1, kAxisNames[size_t(a)]) + lpad(fmt_axis(a, v[size_t(a)]), 10) + "  ";
    return out;
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

}  // namespace

// The INFO page of this controller: its functions, F S T, the CNP, its
// origin and the gauge, the switches.
void caz_info_lines(const Sim& s, std::vector<Line>& lines) {
    const Interpreter& in = s.interp();
    const Modal& m = in.modal();
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
    kv(lines, tr("origin"), axes_text(s, in.frames().pref));
    kv(lines, tr("gauge"), axes_text(s, in.frames().gauge));
    lines.push_back(Line{});
    kv(lines, tr("Switches"),
       strf(tr("block skip %s   optional stop M01 %s"),
            in.options().block_skip ? tr("ON") : tr("off"),
            in.options().optional_stop ? tr("ON") : tr("off")));
}

}  // namespace pupitre::pages
