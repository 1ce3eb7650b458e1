// The CORR page (the manual's CORR OUT): the tool correctors around the one
// under the cursor. Lathe: X and Z gauges (radii), nose radius R, orientation
// C, dynamic DX (a diameter) and DZ; machining centre: length L, radius R,
// dynamic DL and DR. The active corrector is marked, and a gauge changed on it
// during a run shows as pending until the move that applies it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cstdio>

#include "core/interp/value_name.hpp"
#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

std::string num(double v, int decimals = 3) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < 5e-7 ? 0.0 : v);
    return buf;
}

// A gauge of the active corrector not yet applied on its axis.
bool pending(const Sim& s, bool active, const CorrField& field, double val) {
    const Interpreter& in = s.interp();
    return active && s.in_cycle() &&
           ((field.gauge == GaugeAxis::x && in.gauge_pending(X)) ||
            (field.gauge == GaugeAxis::z && in.gauge_pending(Z)) ||
            (field.gauge == GaugeAxis::tool_axis && in.gauge_pending(in.modal().tool_axis)) ||
            (field.text == "R" && in.comp_active() && std::abs(in.comp_radius() - val) > 1e-9));
}

// How a corrector is measured on a known surface: the Cazeneuve's (and any
// lathe's with one) from the witness cut (003:802-806).
std::string touch_hint(const View& v) {
    const MachineProfile& m = v.sim->machine();
    if (!v.witness.empty()) return v.witness + "; " + tr("touching it: :tangent X|Z");
    if (is_caz(m))
        return tr("Witness cut (003:804): :witness DIA [FACE], then :tangent X|Z with each tool.");
    return m.lathe ? tr("Touch a known surface: X 59.978 (a diameter) or Z 0, or :measure D2 Z 0.")
                   : tr("Touch a known surface: Z 10 (a block on Z0), or :measure D2 Z 0.");
}

// The foot of the page: the last measurement, how to set a corrector, what a
// star means, the memory protection.
void corr_foot(const View& v, Canvas& c, const Rect& r) {
    const MachineProfile& m = v.sim->machine();
    int by = r.y + r.h - 4;
    // The last measurement with its arithmetic (X gauges are radii, the
    // diameters shown and typed are halved).
    if (!v.last_setting.empty())
        c.text(2, by - 1, strf(tr("Last: %s"), v.last_setting.c_str()), Style::value, r.w - 3);
    c.text(2, by,
           m.lathe
               ? strf(tr("Presetter: X=63.345 or Z=38.237 sets D%d; Up/Down or D5 choose another."),
                      v.corr_cursor)
               : strf(tr("Presetter: L=120.5 or R=5 sets D%d; Up/Down or D5 choose another."),
                      v.corr_cursor),
           Style::dim, r.w - 2);
    c.text(2, by + 1, touch_hint(v), v.witness.empty() ? Style::dim : Style::value, r.w - 2);
    c.text(2, by + 2,
           tr("* changed in a run: gauge at the next move of its axis, radius at G41/G42"),
           Style::dim, r.w - 2);
    std::string state =
        v.protect ? tr("memory protection ON (:protect off)") : tr("memory protection off");
    c.text(2, by + 3, state, v.protect ? Style::warn : Style::dim);
}

}  // namespace

void page_corr(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    const Interpreter& in = s.interp();
    const MachineProfile& m = s.machine();
    c.rule(r.y, is_caz(m) ? tr("CORR  correctors 01-99, the last two digits of T (X Z R radii, DX "
                               "a diameter)")
                : m.lathe ? tr("CORR  tool correctors (X Z R as radii, DX a diameter)")
                          : tr("CORR  tool correctors"));
    // The Cazeneuve's correctors have no orientation: its gauges pilot the
    // nose centre (003:1912).
    std::vector<const CorrField*> fields;
    for (const CorrField& f : corr_fields())
        if (f.lathe == m.lathe && f.shown && !(is_caz(m) && f.unit == ValueUnit::whole))
            fields.push_back(&f);
    int y = r.y + 1;
    c.text(2, y, "D", Style::dim);
    for (size_t i = 0; i < fields.size(); ++i)
        c.text_right(6 + int(i) * 10, y, 10, std::string(fields[i]->text), Style::title);
    ++y;
    int rows = r.h - 6 - (v.last_setting.empty() ? 0 : 1);
    int active = s.corrector();
    int first = std::clamp(v.corr_cursor - rows / 2, 1, std::max(1, m.correctors - rows + 1));
    for (int i = 0; i < rows && first + i <= m.correctors; ++i) {
        int d = first + i;
        bool cur = d == v.corr_cursor;
        c.text(2, y + i, std::to_string(d), cur ? Style::select : Style::dim);
        for (size_t k = 0; k < fields.size(); ++k) {
            double val = 0;
            in.get(format_value_name({ValueName::Kind::corrector, d, fields[k]}), val);
            bool star = pending(s, d == active, *fields[k], val);
            std::string t =
                fields[k]->unit == ValueUnit::whole ? std::to_string(int(val)) : num(val);
            c.text_right(6 + int(k) * 10, y + i, 10, t + (star ? "*" : " "),
                         star       ? Style::warn
                         : val != 0 ? Style::value
                                    : Style::dim);
        }
        if (d == active)
            c.text(8 + int(fields.size()) * 10, y + i,
                   is_caz(m) ? strf(tr("active %s"), tool_word(m, s.tool(), d).c_str())
                             : strf(tr("active T%d"), s.tool()),
                   Style::ok);
        if (cur) c.style(Rect{r.x, y + i, r.w, 1}, Style::select);
    }
    corr_foot(v, c, r);
}

}  // namespace pupitre::pages
