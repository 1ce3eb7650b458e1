// The setter's arithmetic (000:292-294, 000:1187-1211, 000:3763-3853; the
// course notes' exam, 004:2050-2093; pupitre-iso(5), UNITS AND THE LATHE X AXIS): PREF by
// touch-off, tool gauges by touching a known surface or from a presetter.
// Everything in internal units: mm, lathe X as a radius.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

#include "core/interp/interp.hpp"

namespace pupitre::setting {

// The relation of the handbook, per axis, with no mirror, scale or rotation:
//   OM = OP + G59 + PREF + DEC1 + DEC3 + gauge            (000:292-294, 000:1187)
// where OM is the turret (or spindle nose) reference and OP the tool point.

// PREF that makes the tool point, touching a surface whose program coordinate
// is `surface`, read `surface`: PREF = OM - G59 - DEC1 - DEC3 - gauge - surface.
double touch_pref(double om, double g59, double dec1, double dec3, double gauge, double surface);

// The gauge of a tool touching a surface of known program coordinate, the
// origins being set: gauge = OM - G59 - PREF - DEC1 - DEC3 - surface.
double measure_gauge(double om, double g59, double pref, double dec1, double dec3, double surface);

struct Touch {
    int axis = -1;
    double before = 0, after = 0;  // the value changed (PREF or the gauge)
    std::string name;              // "PREF.Z", "D2.X"
    std::string formula;           // for the message line: how it was computed
};

// On the interpreter's current state: refuses (returns a reason) when a
// mirror, a scale factor or an angular offset is in force, since the simple
// relation no longer holds; otherwise fills `t`. `surface` is in display
// units (a diameter for the lathe's X).
std::string touch_off(const Interpreter& in, int axis, double surface, Touch& t);
// `field` is the corrector field the axis measures: lathe X or Z, mill L (Z).
std::string measure(const Interpreter& in, int d, int axis, double surface, Touch& t);

}  // namespace pupitre::setting
