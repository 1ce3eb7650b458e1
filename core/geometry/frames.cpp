// Offset chain, forward and inverse, with Eigen for the ED rotation.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/frames.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace pupitre {

namespace {
Eigen::Rotation2Dd rotation(double deg) {
    return Eigen::Rotation2Dd(deg * std::numbers::pi / 180.0);
}
}  // namespace

Axes Frames::to_machine(const Axes& prog) const {
    Axes p = prog;
    if (translation_only()) {
        // Translations only: the common case, kept short for long programs.
        // Whole arrays, which Eigen adds two axes at a time (g++ -O2 leaves a
        // loop of 9 scalar); the sums are those of the loop below, in the
        // same order, and + 0.0 makes a -0 sum +0 as there.
        using Array = Eigen::Array<double, kAxes, 1>;
        auto in = [](const Axes& a) { return Eigen::Map<const Array>(a.data()); };
        Eigen::Map<Array> out(p.data());
        if (g53)
            out = in(prog) + (((in(g59) + in(dec3)) + in(gauge)) + 0.0);
        else
            out = in(prog) + (((in(g59) + in(dec3)) + in(gauge)) + (in(dec1) + in(pref)));
        return p;
    }
    for (int a = 0; a < kAxes; ++a)
        if (mirror[size_t(a)]) p[size_t(a)] = -p[size_t(a)];
    double k = scale_on ? scale : 1.0;
    if (scale_on)
        for (int a = X; a <= W; ++a) p[size_t(a)] *= k;
    if (ed != 0) {
        Eigen::Vector2d c(ed_c0, ed_c1);
        Eigen::Vector2d v(p[size_t(ed_a0)], p[size_t(ed_a1)]);
        v = c + rotation(ed) * (v - c);
        p[size_t(ed_a0)] = v.x();
        p[size_t(ed_a1)] = v.y();
    }
    for (int a = 0; a < kAxes; ++a) {
        double lin = (a <= W) ? k : 1.0;
        double m = p[size_t(a)] + lin * g59[size_t(a)] + dec3[size_t(a)] + gauge[size_t(a)];
        if (!g53) m += dec1[size_t(a)] + pref[size_t(a)];
        p[size_t(a)] = m;
    }
    return p;
}

Axes Frames::to_program(const Axes& mach) const {
    Axes p = mach;
    if (ed == 0 && !scale_on && mirror.none()) {
        // Translations only, as in to_machine (each compensated piece asks):
        // the differences of the loop below, in the same order.
        using Array = Eigen::Array<double, kAxes, 1>;
        auto in = [](const Axes& a) { return Eigen::Map<const Array>(a.data()); };
        Eigen::Map<Array> out(p.data());
        if (g53)
            out = ((in(mach)-in(g59)) - in(dec3)) - in(gauge);
        else
            out = (((in(mach)-in(g59)) - in(dec3)) - in(gauge)) - (in(dec1) + in(pref));
        return p;
    }
    double k = scale_on ? scale : 1.0;
    for (int a = 0; a < kAxes; ++a) {
        double lin = (a <= W) ? k : 1.0;
        double v = p[size_t(a)] - lin * g59[size_t(a)] - dec3[size_t(a)] - gauge[size_t(a)];
        if (!g53) v -= dec1[size_t(a)] + pref[size_t(a)];
        p[size_t(a)] = v;
    }
    if (ed != 0) {
        Eigen::Vector2d c(ed_c0, ed_c1);
        Eigen::Vector2d v(p[size_t(ed_a0)], p[size_t(ed_a1)]);
        v = c + rotation(-ed) * (v - c);
        p[size_t(ed_a0)] = v.x();
        p[size_t(ed_a1)] = v.y();
    }
    if (scale_on)
        for (int a = X; a <= W; ++a) p[size_t(a)] /= k;
    for (int a = 0; a < kAxes; ++a)
        if (mirror[size_t(a)]) p[size_t(a)] = -p[size_t(a)];
    return p;
}

}  // namespace pupitre
