// The PREF page: the origins of each axis (PREF, DEC1, DEC3, entered as radii
// on the lathe's X like the gauges), with the G59 offset and the active gauge
// read only, the current point on OM and OP, and the touch-off help. Origins
// changed during a run are marked until the next move applies them.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <span>

#include "core/interp/value_name.hpp"
#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

// The origins of each axis, the G59 offset, the gauge, OM and OP; an origin
// changed during a run is marked. Returns the row after the table.
int origins_table(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    const MachineProfile& m = s.machine();
    const Frames& f = s.interp().frames();
    int y = r.y + 2;
    const int w = 10;
    // TRANSLATORS: a column header of the PREF page (the tool gauge): at most 9 columns.
    const char* heads[] = {"PREF", "DEC1", "DEC3", "G59", tr("gauge"), "OM", "OP"};
    // The Cazeneuve's controller has one origin and no DEC1, DEC3 or G59
    // (pupitre-cazeneuve(5)): its columns are PREF, the gauge, OM and OP.
    static constexpr int kNum[] = {0, 1, 2, 3, 4, 5, 6}, kCaz[] = {0, 4, 5, 6};
    std::span<const int> cols = is_caz(m) ? std::span<const int>(kCaz) : kNum;
    for (size_t k = 0; k < cols.size(); ++k)
        c.text_right(4 + int(k) * w, y, w, heads[cols[k]], cols[k] < 3 ? Style::title : Style::dim);
    ++y;
    Axes om = s.om(), op = s.op();
    for (int a = 0; a < kAxes && y < r.y + r.h - 6; ++a) {
        if (!m.has(a)) continue;
        std::string name(1, kAxisNames[size_t(a)]);
        c.text(2, y, name, Style::title);
        const double vals[] = {f.pref[size_t(a)],
                               f.dec1[size_t(a)],
                               f.dec3[size_t(a)],
                               f.g59[size_t(a)],
                               f.gauge[size_t(a)],
                               s.to_display(a, om[size_t(a)]),
                               s.to_display(a, op[size_t(a)])};
        for (size_t k = 0; k < cols.size(); ++k) {
            const int i = cols[k];
            bool pending = false;
            if (i < 3) {
                std::string n = format_value_name(ValueName::origin(i, a));
                pending = std::find(v.pending.begin(), v.pending.end(), n) != v.pending.end();
            }
            // OM and OP show the lathe's X as the OP page does: a diameter.
            bool dia = i >= 5 && a == X && m.lathe && s.to_display(X, 1.0) != 1.0;
            std::string t = (dia ? "\u00f8" : "") + fmt_axis(a, vals[i]) + (pending ? "*" : "");
            c.text_right(4 + int(k) * w, y, w, t,
                         pending ? Style::warn
                         : i < 3 ? Style::value
                                 : Style::normal);
        }
        ++y;
    }
    return y;
}

// The active corrector, the lathe's radii note, the last touch-off and the
// origins waiting for a move, from row y.
void setting_notes(const View& v, Canvas& c, const Rect& r, int y) {
    const Sim& s = *v.sim;
    const MachineProfile& m = s.machine();
    // The corrector the machine applies (D0 after M02 and RAZ, T kept); a
    // gauge not yet applied is named: a touch-off applies it first.
    std::string d =
        is_caz(m) ? strf(tr("active tool %s: turret position %d, corrector %02d"),
                         tool_word(m, s.tool(), s.corrector()).c_str(), s.tool(), s.corrector())
                  : strf(tr("active corrector D%d, tool T%d"), s.corrector(), s.tool());
    const std::string waiting = gauge_waiting(s);
    if (!waiting.empty())
        d += strf(tr("; its gauge on %s applies at the next move or touch-off"), waiting.c_str());
    for (const auto& part : wrap_text(d, r.w - 2))
        c.text(2, y++, part, waiting.empty() ? Style::dim : Style::warn);
    if (m.lathe && s.to_display(X, 1.0) != 1.0)
        c.text(
            2, y++,
            strf(tr("X: PREF, DEC1, DEC3, G59 and the gauge are radii; OM and OP diameters (%s)."),
                 "\u00f8"),
            Style::dim, r.w - 2);
    if (!v.last_setting.empty()) {
        // The last touch-off or measurement with its arithmetic, whole (the
        // message line may cut it at 80 columns).
        // TRANSLATORS: PREF page, before the last touch-off and its arithmetic.
        const char* last = tr("Last:");
        int lx = std::max(8, 3 + columns(last));
        c.text(2, ++y, last, Style::dim);
        for (const auto& part : wrap_text(v.last_setting, r.w - lx - 2))
            if (y < r.y + r.h - 6) c.text(lx, y++, part, Style::value);
    }
    if (!v.pending.empty())
        c.text(2, y++, tr("* changed during the run: applies at the next move"), Style::warn,
               r.w - 2);
}

// The memory protection's state, on the page's last row.
void protection_row(const View& v, Canvas& c, int y) {
    std::string state =
        v.protect ? tr("memory protection ON (:protect off)") : tr("memory protection off");
    if (v.undo_depth) state += "   " + strf(tr("%zu change(s) to undo"), v.undo_depth);
    c.text(2, y, state, v.protect ? Style::warn : Style::dim);
}

// The Cazeneuve's setting (003:802-808): one origin, and each tool's
// corrector from a witness cut it touches; X is a radius.
void caz_setting_help(const View& v, Canvas& c, const Rect& r, int by) {
    c.text(2, by,
           v.witness.empty()
               ? tr("Witness cut (003:804): turn a diameter and a face, measure the diameter,")
               : v.witness + ";",
           v.witness.empty() ? Style::dim : Style::value, r.w - 2);
    c.text(2, by + 1, tr(":witness DIA [FACE], then with each tool touching it: :tangent X|Z."),
           Style::dim, r.w - 2);
    c.text(2, by + 2, tr("Touch-off: Z 0, X 29.5 (a radius). Direct entry: PREF.Z=-300  D1.X=32.5"),
           Style::dim, r.w - 2);
    protection_row(v, c, by + 3);
}

// The touch-off help and the memory protection, on the page's last rows.
void touch_off_help(const View& v, Canvas& c, const Rect& r) {
    const MachineProfile& m = v.sim->machine();
    int by = r.y + r.h - 5;
    if (is_caz(m)) {
        caz_setting_help(v, c, r, by);
        return;
    }
    c.text(2, by, tr("Touch-off: jog the tool onto the part, then type the coordinate of the"),
           Style::dim, r.w - 2);
    c.text(2, by + 1,
           m.lathe ? tr("surface: Z 0 (the face), X 59.978 (a diameter), or :touch Z 0.")
                   : tr("surface: Z 0 (the face), X 0, or :touch Z 0."),
           Style::dim, r.w - 2);
    c.text(2, by + 2, tr("Direct entry: PREF.Z=-300  DEC1.X=2  DEC3.Z=0.5    Undo: C-z, :undo"),
           Style::dim, r.w - 2);
    protection_row(v, c, by + 3);
}

}  // namespace

std::string gauge_waiting(const Sim& s) {
    const Interpreter& in = s.interp();
    const MachineProfile& m = s.machine();
    const Frames& f = in.frames();
    std::string waiting;
    for (int a = 0; a < kAxes; ++a)
        if (m.has(a) && in.gauge_pending(a) &&
            std::abs(in.active_gauge(a) - f.gauge[size_t(a)]) > 5e-7)
            waiting += std::string(waiting.empty() ? "" : " ") + kAxisNames[size_t(a)];
    return waiting;
}

std::string gauge_waiting_note(const Sim& s) {
    const std::string waiting = gauge_waiting(s);
    if (waiting.empty()) return {};
    // TRANSLATORS: OP and INFO pages, after the tool or the gauge applied: %s are axes ("X Z").
    return strf(tr("gauge on %s not applied yet: at the next move or touch-off"), waiting.c_str());
}

void page_pref(const View& v, Canvas& c, const Rect& r) {
    // TRANSLATORS: the PREF page's title: PREF is the page's name.
    c.rule(r.y, tr("PREF  origins"));
    int y = origins_table(v, c, r);
    setting_notes(v, c, r, y + 1);
    touch_off_help(v, c, r);
}

}  // namespace pupitre::pages
