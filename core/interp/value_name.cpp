// One vocabulary for a machine value (see value_name.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/interp/value_name.hpp"

#include <charconv>

namespace pupitre {

namespace {

using U = ValueUnit;
using G = GaugeAxis;

// The table (000:813-833, 000:3763-3791; pupitre-iso(5), TOOLS AND
// CORRECTORS). Lathe: X and Z gauges (X a radius), nose radius R, orientation
// C, dynamic DX (a diameter) and DZ. Mill: length L, radius R, dynamic DL and
// DR, end radius A (or TIP); its C is E55xxx's only.
//  text  member          lathe  unit         gauge          wear   E5x shown stored settable
constexpr CorrField kFields[] = {
    {"X", &Corrector::x, true, U::radius, G::x, false, 0, true, true, true},
    {"Z", &Corrector::z, true, U::radius, G::z, false, 1, true, true, true},
    {"R", &Corrector::r, true, U::radius, G::none, false, 2, true, true, true},
    {"C", nullptr, true, U::whole, G::none, false, 5, true, true, true},
    {"DX", &Corrector::dx, true, U::diameter, G::x, true, 3, true, true, true},
    {"DZ", &Corrector::dz, true, U::radius, G::z, true, 4, true, true, true},
    {"L", &Corrector::l, false, U::radius, G::tool_axis, false, 0, true, true, true},
    {"R", &Corrector::r, false, U::radius, G::none, false, 2, true, true, true},
    {"DL", &Corrector::dl, false, U::radius, G::tool_axis, true, 3, true, true, true},
    {"DR", &Corrector::dr, false, U::radius, G::none, true, 4, true, true, true},
    {"A", &Corrector::tip, false, U::radius, G::none, false, 1, false, true, true},
    {"TIP", &Corrector::tip, false, U::radius, G::none, false, -1, false, false, true},
    {"C", nullptr, false, U::whole, G::none, false, 5, false, true, false},
};

bool whole(std::string_view s, int& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
}

// "D<n>" with n from 1 to `last`.
bool corrector_number(std::string_view head, int last, int& d) {
    return head.size() >= 2 && head[0] == 'D' && whole(head.substr(1), d) && d >= 1 && d <= last;
}

}  // namespace

std::span<const CorrField> corr_fields() {
    return kFields;
}

const CorrField* corr_field(std::string_view text, bool lathe) {
    for (const CorrField& f : kFields)
        if (f.lathe == lathe && f.text == text) return &f;
    return nullptr;
}

const CorrField* corr_field_of_e(int family, bool lathe) {
    for (const CorrField& f : kFields)
        if (f.lathe == lathe && f.e_family == family) return &f;
    return nullptr;
}

const CorrField* gauge_field(GaugeAxis g, bool wear, bool lathe) {
    for (const CorrField& f : kFields)
        if (f.lathe == lathe && f.gauge == g && g != GaugeAxis::none && f.wear == wear) return &f;
    return nullptr;
}

const CorrField* any_corr_field(std::string_view text) {
    for (const CorrField& f : kFields)
        if (f.text == text && f.stored) return &f;
    return nullptr;
}

namespace {

// `stored`: only the store's names of a field (A, not TIP).
bool parse(std::string_view s, ValueName& n, bool stored) {
    size_t dot = s.find('.');
    if (dot == std::string_view::npos) {
        if (s.size() < 2 || (s[0] != 'L' && s[0] != 'E')) return false;
        ValueName v;
        v.kind = s[0] == 'L' ? ValueName::Kind::l_param : ValueName::Kind::e_param;
        if (!whole(s.substr(1), v.number) || v.number < 0) return false;
        n = v;
        return true;
    }
    std::string_view head = s.substr(0, dot), tail = s.substr(dot + 1);
    for (int k = 0; k < 3; ++k) {
        if (head != kOriginNames[k]) continue;
        if (tail.size() != 1 || axis_of(tail[0]) < 0) return false;
        n = ValueName{ValueName::Kind::origin, k, nullptr, axis_of(tail[0])};
        return true;
    }
    ValueName v;
    if (!corrector_number(head, 255, v.number)) return false;
    for (const CorrField& f : kFields)
        if (f.text == tail && (f.stored || !stored)) {
            v.field = &f;
            n = v;
            return true;
        }
    return false;
}

}  // namespace

bool parse_value_name(std::string_view s, ValueName& n) {
    return parse(s, n, true);
}

bool parse_value_name(std::string_view s, const MachineProfile& m, ValueName& n) {
    ValueName v;
    if (!parse(s, v, false)) return false;
    if (v.kind == ValueName::Kind::origin && !m.has(v.axis)) return false;
    if (v.kind == ValueName::Kind::corrector && parse_corrector_name(s, m, v) != NameFault::none)
        return false;
    n = v;
    return true;
}

NameFault parse_corrector_name(std::string_view s, const MachineProfile& m, ValueName& n) {
    size_t dot = s.find('.');
    ValueName v;
    if (dot == std::string_view::npos ||
        !corrector_number(s.substr(0, dot), m.correctors, v.number))
        return NameFault::number;
    if (!(v.field = corr_field(s.substr(dot + 1), m.lathe))) return NameFault::field;
    n = v;
    return NameFault::none;
}

std::string corrector_name(int d, std::string_view field) {
    return "D" + std::to_string(d) + "." + std::string(field);
}

std::string format_value_name(const ValueName& n) {
    switch (n.kind) {
        case ValueName::Kind::corrector:
            return corrector_name(n.number, n.field->text);
        case ValueName::Kind::origin:
            return std::string(kOriginNames[n.number]) + "." + kAxisNames[size_t(n.axis)];
        case ValueName::Kind::l_param:
            return "L" + std::to_string(n.number);
        case ValueName::Kind::e_param:
            return "E" + std::to_string(n.number);
    }
    return {};
}

ValueUnit value_unit(std::string_view name) {
    ValueName v;
    if (!parse_value_name(name, v)) return ValueUnit::radius;
    if (v.kind == ValueName::Kind::corrector && v.field->unit == ValueUnit::whole)
        return ValueUnit::whole;
    if (v.kind == ValueName::Kind::origin && is_rotary(v.axis)) return ValueUnit::angle;
    return ValueUnit::radius;
}

}  // namespace pupitre
