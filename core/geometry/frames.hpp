// The offset chain between program coordinates and the machine position of the
// tool reference: mirror -> scale -> ED rotation -> G59 (scaled) -> DEC1 + PREF
// (not in G53) + DEC3 -> tool gauge (000:10681, 000:3982-4018, 000:292-299;
// pupitre-iso(5), COORDINATES AND OFFSETS and DECISIONS, the offset chain).
// Everything is in internal units: mm, lathe X as a radius, degrees.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <bitset>

#include "core/geometry/axis.hpp"

namespace pupitre {

struct Frames {
    Axes pref{}, dec1{}, dec3{}, g59{};
    bool g53 = false;             // PREF and DEC1 suspended
    std::bitset<kAxes> mirror;    // G51
    bool scale_on = false;        // G74
    double scale = 1.0;           // E69000 / 1000
    double ed = 0;                // angular offset, degrees, in the plane (a0, a1)
    int ed_a0 = X, ed_a1 = Y;     // plane axes of the rotation
    double ed_c0 = 0, ed_c1 = 0;  // rotation centre (program coordinates)
    Axes gauge{};                 // tool gauge applied on each axis

    // Program point -> machine position of the reference.
    Axes to_machine(const Axes& prog) const;
    // Only translations apply: to_machine adds shift(a) to each axis a, with
    // these sums in this order (the whole arrays' sums of to_machine).
    bool translation_only() const { return ed == 0 && !scale_on && mirror.none(); }
    double shift(int a) const {
        const size_t i = size_t(a);
        return ((g59[i] + dec3[i]) + gauge[i]) + (g53 ? 0.0 : dec1[i] + pref[i]);
    }
    // Machine position -> program point (inverse of to_machine).
    Axes to_program(const Axes& mach) const;
};

}  // namespace pupitre
