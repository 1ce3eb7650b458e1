// One vocabulary for a machine value (issue 37): a corrector's field
// ("D3.X"), an origin's axis ("PREF.Z", "DEC1.X", "DEC3.B"), an L or an E
// parameter ("L5", "E80000"). One table of corrector fields, one parser of the
// text people and the store write, one formatter that spells it back exactly.
// Interpreter::set/get, the store, the setting pages, the CORR page and the
// training read the table: a new corrector field is one row.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <span>
#include <string>
#include <string_view>

#include "core/interp/interp.hpp"

namespace pupitre {

// How a field's number reads: a radius (lathe X, and the lengths), a diameter
// (a lathe's DX: the CORR page's, 000:843-865), an angle (a rotary origin, in
// 0.0001 degree in the store), a whole number (a lathe's nose orientation C).
enum class ValueUnit { radius, diameter, angle, whole };

// The axis a field's gauge moves the tool point on: X, Z, the tool's axis
// (a mill's length, along G17-G19's), or none (a radius, the orientation).
enum class GaugeAxis { none, x, z, tool_axis };

// One field of a tool corrector (000:813-833, 000:3763-3791; pupitre-iso(5),
// TOOLS AND CORRECTORS).
struct CorrField {
    std::string_view text;      // after "D<n>."
    double Corrector::*member;  // nullptr: C, the int Corrector::c
    bool lathe;                 // a lathe's field, else a machining centre's
    ValueUnit unit;
    GaugeAxis gauge;
    bool wear;      // a dynamic correction (DX DZ, DL DR): what a worn tool adds to a gauge or R
    int e_family;   // E5x<nnn>: x, as write_e and e_value map them; -1: none
    bool shown;     // a column of the CORR page and a training target
    bool stored;    // a name the store keeps (TIP is A's other spelling)
    bool settable;  // Interpreter::set/get name it (a mill's C lives only in E55xxx)
};

// Every field, a lathe's then a mill's, in the CORR page's order.
std::span<const CorrField> corr_fields();
// The field `text` names on a lathe or a mill, or nullptr.
const CorrField* corr_field(std::string_view text, bool lathe);
// The field of E5<family><nnn> on a lathe or a mill, or nullptr.
const CorrField* corr_field_of_e(int family, bool lathe);
// The gauge (or, `wear`, its dynamic correction) that moves the tool point
// along `g` on a lathe or a mill: a lathe's X and DX on x, a mill's L and DL
// on its tool axis; nullptr for none.
const CorrField* gauge_field(GaugeAxis g, bool wear, bool lathe);
// The field `text` names on either machine (the store's names), or nullptr.
const CorrField* any_corr_field(std::string_view text);

// The origins as settings name them: PREF, DEC1, DEC3 (E6x000, E6x001, E6x004;
// store/link.cpp maps them).
constexpr std::string_view kOriginNames[] = {"PREF", "DEC1", "DEC3"};

// A machine value by name.
struct ValueName {
    enum class Kind { corrector, origin, l_param, e_param } kind = Kind::corrector;
    int number = 0;                    // Dn, the origin (0 PREF, 1 DEC1, 2 DEC3), Ln, En
    const CorrField* field = nullptr;  // a corrector's
    int axis = -1;                     // an origin's (axis_of)

    // Origin k (0 PREF, 1 DEC1, 2 DEC3) on an axis: PREF.Z.
    static ValueName origin(int k, int axis) { return {Kind::origin, k, nullptr, axis}; }
    // Corrector d's field f (corr_field, any_corr_field): D3.X.
    static ValueName corrector(int d, const CorrField* f) { return {Kind::corrector, d, f, -1}; }
};

// "D12.DX", "PREF.Z", "L5", "E80000" -> the value; false for anything else:
// an unknown field or axis letter, D0 or beyond D255, a number not whole.
// A corrector's field may be either machine's (the store keeps both).
bool parse_value_name(std::string_view text, ValueName& out);
// The same, refusing a field or an axis the machine does not have.
bool parse_value_name(std::string_view text, const MachineProfile& m, ValueName& out);
// The name as every room spells it: "D12.DX", "PREF.Z", "L5", "E80000".
std::string format_value_name(const ValueName& n);

// Which part of a corrector's name a refusal names.
enum class NameFault { none, number, field };
// "D<n>.<field>" on machine m, read as Interpreter::set refuses it: the
// number first (no "D<n>." with n from 1 to m.correctors: number), then the
// field (not one of m's: field).
NameFault parse_corrector_name(std::string_view text, const MachineProfile& m, ValueName& out);
// "D<d>.<field>" with the field as typed, known or not, for a refusal to quote
// whole (the CORR page's "Q=1" under D3); format_value_name spells a
// corrector so.
std::string corrector_name(int d, std::string_view field);

// A value's unit from its name, as the store reads it: C whole, a rotary
// origin an angle, the rest lengths. Unknown names read as lengths.
ValueUnit value_unit(std::string_view name);

}  // namespace pupitre
