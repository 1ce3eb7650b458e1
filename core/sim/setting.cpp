// The setter's arithmetic (see setting.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/setting.hpp"

#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/value_name.hpp"
#include "core/numfmt.hpp"

namespace pupitre::setting {

namespace {

// Zero below half a micron, never "-0.000".
std::string num(double v) {
    return fixed3_zeroed(v, 5e-7);
}

// " - NAME value", or nothing for a zero term: the message line is short.
std::string term(const char* name, double v) {
    if (std::abs(v) < 5e-7) return {};
    return std::string(" - ") + name + " " + num(v);
}

// The lathe's X is shown as a diameter (OM, OP, the surface typed) but PREF,
// DEC1, DEC3, G59 and the gauges are radii (000:1187-1211): the formula shows
// the diameters as shown, halved, and names the result a radius.
bool diameter_x(const Interpreter& in, int axis) {
    return axis == X && in.to_display(X, 1.0) != 1.0;
}

std::string om_term(const Interpreter& in, int axis) {
    double om = in.machine_pos()[size_t(axis)];
    return diameter_x(in, axis) ? "OM \u00f8" + num(in.to_display(X, om)) + "/2" : "OM " + num(om);
}

std::string surface_term(const Interpreter& in, int axis, double typed) {
    // TRANSLATORS: a term of the touch-off formula on the message line: the surface the operator
    // typed.
    const char* surface = tr("surface");
    return diameter_x(in, axis) ? std::string(" - ") + surface + " \u00f8" + num(typed) + "/2"
                                : std::string(" - ") + surface + " " + num(typed);
}

std::string result_name(const Interpreter& in, const std::string& name, int axis) {
    // TRANSLATORS: %s is PREF.X or D1.X, a radius while the lathe's X is shown as a diameter.
    return diameter_x(in, axis) ? strf(tr("%s (radius)"), name.c_str()) : name;
}

std::string frame_problem(const Interpreter& in) {
    const Frames& f = in.frames();
    if (f.mirror.any() || f.scale_on || std::abs(f.ed) > 1e-12)
        return tr(
            "a mirror (G51), a scale factor (G74) or an angular offset (ED) is in force: RAZ "
            "first");
    if (f.g53) return tr("G53 is in force (PREF and DEC1 suspended): RAZ first");
    return {};
}

}  // namespace

double touch_pref(double om, double g59, double dec1, double dec3, double gauge, double surface) {
    return om - g59 - dec1 - dec3 - gauge - surface;
}

double measure_gauge(double om, double g59, double pref, double dec1, double dec3, double surface) {
    return om - g59 - pref - dec1 - dec3 - surface;
}

std::string touch_off(const Interpreter& in, int axis, double surface, Touch& t) {
    const MachineProfile& m = in.machine();
    if (!m.has(axis)) return strf(tr("the machine has no %c axis"), kAxisNames[size_t(axis)]);
    if (std::string p = frame_problem(in); !p.empty()) return p;
    const Frames& f = in.frames();
    size_t a = size_t(axis);
    double s = surface / in.to_display(axis, 1.0);  // a diameter typed for the lathe's X
    double gauge = in.active_gauge(axis);
    t.axis = axis;
    t.name = format_value_name(ValueName::origin(0, axis));
    t.before = f.pref[a];
    t.after = touch_pref(in.machine_pos()[a], f.g59[a], f.dec1[a], f.dec3[a], gauge, s);
    t.formula = result_name(in, t.name, axis) + " = " + om_term(in, axis) +
                term("DEC1", f.dec1[a]) +
                // TRANSLATORS: a term of the touch-off formula on the message line: the tool gauge.
                term("DEC3", f.dec3[a]) + term("G59", f.g59[a]) + term(tr("gauge"), gauge) +
                surface_term(in, axis, surface) + " = " + num(t.after);
    return {};
}

std::string measure(const Interpreter& in, int d, int axis, double surface, Touch& t) {
    const MachineProfile& m = in.machine();
    if (d < 1 || d > m.correctors)
        return strf(tr("corrector must be D1 to D%d"), int(m.correctors));
    if (!m.has(axis)) return strf(tr("the machine has no %c axis"), kAxisNames[size_t(axis)]);
    if (!m.lathe && axis != in.modal().tool_axis)
        return strf(tr("on a machining centre a gauge is measured along the tool axis (%c)"),
                    kAxisNames[size_t(in.modal().tool_axis)]);
    if (m.lathe && axis != X && axis != Z) return tr("a lathe gauge is measured on X or Z");
    if (std::string p = frame_problem(in); !p.empty()) return p;
    const Frames& f = in.frames();
    size_t a = size_t(axis);
    double s = surface / in.to_display(axis, 1.0);
    // The gauge measured and its dynamic correction: X and DX, Z and DZ, L and DL.
    const GaugeAxis along = !m.lathe    ? GaugeAxis::tool_axis
                            : axis == X ? GaugeAxis::x
                                        : GaugeAxis::z;
    const CorrField* wear = gauge_field(along, true, m.lathe);
    t.axis = axis;
    t.name = format_value_name(ValueName::corrector(d, gauge_field(along, false, m.lathe)));
    in.get(t.name, t.before);
    // The dynamic correction stays what it is: the measured length is gauge + dynamic.
    double dyn = 0;
    in.get(format_value_name(ValueName::corrector(d, wear)), dyn);
    if (wear->unit == ValueUnit::diameter) dyn /= 2;  // a lathe's DX
    double total = measure_gauge(in.machine_pos()[a], f.g59[a], f.pref[a], f.dec1[a], f.dec3[a], s);
    if (!m.lathe && in.modal().tool_axis_neg) total = -total;
    t.after = total - dyn;
    t.formula = result_name(in, t.name, axis) + " = " + om_term(in, axis) +
                term("PREF", f.pref[a]) + term("DEC1", f.dec1[a]) + term("DEC3", f.dec3[a]) +
                term("G59", f.g59[a]) +
                // TRANSLATORS: a term of the measure formula on the message line: the dynamic
                // correction (DX, DZ, DL).
                surface_term(in, axis, surface) + term(tr("dynamic"), dyn) + " = " + num(t.after);
    return {};
}

}  // namespace pupitre::setting
