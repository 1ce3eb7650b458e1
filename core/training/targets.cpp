// What a student must find, from the truth: PREF and DEC1 from where the
// part really is, the correctors from what each tool really measures, each
// with its arithmetic for the report (seed 004:552-580: the setting is the
// identification of the constants of the machine's equation).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/i18n.hpp"
#include "core/interp/value_name.hpp"
#include "core/training/exercise.hpp"

namespace pupitre::training {

namespace {

// A value a student must find, as the truth's arithmetic reads it.
struct Sought {
    enum Kind { pref, dec1, corr } kind = pref;
    char axis = 0;      // PREF and DEC1
    int d = 0;          // Dn
    std::string field;  // X, Z, R, DX, DZ, L, DL, DR
};

// PREF and DEC1 on an axis, D1 to D99 on a field of either machine.
bool split(std::string_view text, Sought& n) {
    ValueName v;
    if (!parse_value_name(text, v)) return false;
    if (v.kind == ValueName::Kind::origin && v.number < 2) {
        n.kind = v.number == 0 ? Sought::pref : Sought::dec1;
        n.axis = kAxisNames[size_t(v.axis)];
        return true;
    }
    if (v.kind != ValueName::Kind::corrector || v.number > 99) return false;
    n.kind = Sought::corr;
    n.d = v.number;
    n.field = std::string(v.field->text);
    return true;
}

std::string mm(double v) {
    return strf("%.3f", std::abs(v) < 5e-7 ? 0.0 : v);
}

// The lathe's origins: the spindle axis for X; for Z the part's face (origin
// = face) or the jaws' face with DEC1 Z the stick-out (origin = jaws, as
// seed 004's exam sets it: PREF on the work-holder, DEC1 to the part).
bool lathe_origin(const Exercise& e, const workshop::LatheSetup& l, const Sought& n, double& v,
                  std::string* how) {
    const bool jaws = e.origin == "jaws";
    std::string text;
    if (n.axis == 'X') {
        v = n.kind == Sought::pref ? l.axis_x : 0;
        text = n.kind == Sought::pref
                   ? strf(tr("PREF X = the spindle axis, as a tool point reads it = %s"),
                          mm(v).c_str())
                   : std::string(tr("DEC1 X = 0: the program's origin is on the axis"));
    } else if (n.axis == 'Z' && n.kind == Sought::pref) {
        v = jaws ? l.chuck_z : l.chuck_z + l.stickout;
        text = jaws ? strf(tr("PREF Z = the jaws' face = %s"), mm(v).c_str())
                    : strf(tr("PREF Z = the jaws' face + the stick-out = %s + %s = %s"),
                           mm(l.chuck_z).c_str(), mm(l.stickout).c_str(), mm(v).c_str());
    } else if (n.axis == 'Z') {
        v = jaws ? l.stickout : 0;
        text = jaws ? strf(tr("DEC1 Z = the part's face - the jaws' face = the stick-out = %s"),
                           mm(v).c_str())
                    : std::string(tr("DEC1 Z = 0: PREF is on the part's face"));
    } else {
        return false;
    }
    if (how) *how = text;
    return true;
}

bool mill_origin(const Exercise& e, const workshop::MillSetup& m, const Sought& n, double& v,
                 std::string* how) {
    const bool centre = e.origin == "centre";
    std::string text;
    if (n.kind == Sought::dec1) {
        if (n.axis != 'X' && n.axis != 'Y' && n.axis != 'Z') return false;
        v = 0;
        text = strf(tr("DEC1 %c = 0: PREF is the program's origin"), n.axis);
    } else if (n.axis == 'X' || n.axis == 'Y') {
        const double face = n.axis == 'X' ? m.stock_x : m.stock_y;
        const double half = (n.axis == 'X' ? m.length : m.width) / 2;
        v = centre ? face + half : face;
        text = centre
                   ? strf(tr("PREF %c = the block's -%c face + half its size = %s + %s = %s"),
                          n.axis, n.axis, mm(face).c_str(), mm(half).c_str(), mm(v).c_str())
                   : strf(tr("PREF %c = the block's -%c face = %s"), n.axis, n.axis, mm(v).c_str());
    } else if (n.axis == 'Z') {
        v = m.stock_z + m.height;
        text = strf(tr("PREF Z = the block's top face = its bottom + its height = %s + %s = %s"),
                    mm(m.stock_z).c_str(), mm(m.height).c_str(), mm(v).c_str());
    } else {
        return false;
    }
    if (how) *how = text;
    return true;
}

// A corrector's true value: the tool's gauge, radius or length; a wear
// field (DX…) what brings the given gauge to the truth.
bool corrector(const Exercise& e, const workshop::Setup& setup, const Sought& n, double& v,
               std::string* how) {
    const workshop::ToolTruth* t = setup.tool(n.d);
    if (!t) return false;
    const bool lathe = setup.kind == "lathe";
    const std::string& f = n.field;
    std::string text;
    if (any_corr_field(f)->wear) {
        // The gauge the wear corrects: DX's X, DL's L (only the spelling matters).
        const std::string base =
            format_value_name(ValueName::corrector(n.d, any_corr_field(f.substr(1))));
        double truth = 0, given = 0;
        expected(e, setup, base, truth);
        if (!start_value(e, setup, base, given)) given = truth;
        v = truth - given;
        text = strf(tr("D%d %s = T%d's true %s - D%d %s as given = %s - %s = %s"), n.d, f.c_str(),
                    n.d, f.c_str() + 1, n.d, f.c_str() + 1, mm(truth).c_str(), mm(given).c_str(),
                    mm(v).c_str());
        // A lathe's DX is a diameter (the NUM's CORR page; interp: X + DX / 2).
        if (lathe && f == "DX") {
            v *= 2;
            text = strf(tr("D%d DX = 2 \u00d7 (T%d's true X - D%d X as given), a diameter = 2 "
                           "\u00d7 (%s - %s) = %s"),
                        n.d, n.d, n.d, mm(truth).c_str(), mm(given).c_str(), mm(v).c_str());
        }
    } else if (lathe && (f == "X" || f == "Z")) {
        v = f == "X" ? t->x : t->z;
        text = f == "X"
                   ? strf(tr("D%d X = T%d's true gauge X (a radius) = %s"), n.d, n.d, mm(v).c_str())
                   : strf(tr("D%d Z = T%d's true gauge Z = %s"), n.d, n.d, mm(v).c_str());
    } else if (f == "R") {
        v = t->radius;
        text = strf(lathe ? tr("D%d R = T%d's nose radius = %s") : tr("D%d R = T%d's radius = %s"),
                    n.d, n.d, mm(v).c_str());
    } else if (!lathe && f == "L") {
        v = t->length;
        text =
            strf(tr("D%d L = T%d's true length from the gauge line = %s"), n.d, n.d, mm(v).c_str());
    } else {
        return false;
    }
    if (how) *how = text;
    return true;
}

}  // namespace

bool target_name(std::string_view name, bool lathe) {
    Sought n;
    if (!split(name, n)) return false;
    if (n.kind != Sought::corr)
        return lathe ? n.axis == 'X' || n.axis == 'Z'
                     : n.axis == 'X' || n.axis == 'Y' || n.axis == 'Z';
    // The CORR page's columns, but the orientation: a code, not a measure.
    const CorrField* f = corr_field(n.field, lathe);
    return f && f->shown && f->unit != ValueUnit::whole;
}

bool expected(const Exercise& e, const workshop::Setup& truth, const std::string& name, double& v,
              std::string* how) {
    Sought n;
    if (!split(name, n) || !target_name(name, truth.kind == "lathe")) return false;
    if (n.kind == Sought::corr) return corrector(e, truth, n, v, how);
    return truth.kind == "lathe" ? lathe_origin(e, truth.lathe, n, v, how)
                                 : mill_origin(e, truth.mill, n, v, how);
}

bool start_value(const Exercise& e, const workshop::Setup& truth, const std::string& name,
                 double& v) {
    for (const Start& st : e.start) {
        if (st.name != name) continue;
        v = st.value;
        if (st.from_truth) {
            double t = 0;
            if (!expected(e, truth, name, t)) return false;
            v += t;
        }
        return true;
    }
    return false;
}

}  // namespace pupitre::training
