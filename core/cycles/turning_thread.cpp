// G33 threading cycle (000:3194-3222; pupitre-iso(5), TURNING CYCLES): passes
// of decreasing (S) or constant (ES) depth, a last pass Q, oblique infeed EB,
// taper EA, exit slope R and multi-start F; and G38 chained threads
// (000:3270-3294), one synchronised move a block.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "core/cycles/turning.hpp"
#include "core/cycles/turning_geom.hpp"
#include "core/cycles/turning_zone.hpp"
#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"

namespace pupitre::turning {

using namespace geom;

namespace {
using ::pupitre::geometry::kDeg;

bool whole(double v) {
    return std::fabs(v - std::round(v)) < 1e-9;
}

// Syntax and argument checks, in the order a block is read (000:3194-3222).
Error g33_check(const G33Args& a) {
    if (!a.has_x || !a.has_z || !a.has_p || !a.has_k)
        return {832, tr("G33 needs the end point X Z, the depth P and the lead K")};
    if (a.has_s && a.has_es) return {889, tr("G33 takes S or ES, not both")};
    if (a.k < 0 || a.p < 0 || (a.has_q && a.q < 0) || a.r < 0 || a.k == 0 || a.p == 0)
        return {835, tr("P and K must be positive, Q and R not negative")};
    if (!(a.eb > -90 && a.eb < 90)) return {834, tr("EB must lie between -90 and 90 degrees")};
    if (a.has_f && a.f > 9) return {884, tr("more than 9 thread starts")};
    double n = a.has_es ? a.es : a.s;
    if ((a.has_f && (a.f < 1 || !whole(a.f))) || n < 1 || !whole(n))
        return {837,
                tr("the number of starts (F) and of passes (S, ES) must be whole and at least 1")};
    // More passes than any thread needs: an input mistake, not hours of moves
    // (issue 40, the cycle sweep's S1e6). 837 "inconsistent F or S value"
    // (seed 000 l.13447), as S0 is.
    constexpr double kMaxPasses = 10000;
    if (n > kMaxPasses)
        return {837, strf(tr("more than %d passes (S, ES) for one thread"), int(kMaxPasses))};
    if (a.has_q && a.q > a.p) return {881, tr("the last pass Q is deeper than the thread P")};
    if (std::fabs(a.ea) > 90) return {881, tr("EA must lie between -90 and 90 degrees")};
    if (a.radius_comp) return {27, tr("threading in radius compensation (G41/G42)")};
    if (!a.plane_ok) return {836, tr("threading needs the G18 or G20 plane")};
    if (!a.spindle_turning) return {831, tr("threading with the spindle stopped")};
    return {};
}

// Cumulative depths of the passes (pupitre-iso(5), TURNING CYCLES).
std::vector<double> depths(const G33Args& a) {
    std::vector<double> ds;
    double pr = a.p - (a.has_q ? a.q : 0);
    int n = int(std::lround(a.has_es ? a.es : a.s));
    for (int i = 1; i <= n; ++i) {
        double d = a.has_es ? pr * i / n : pr * std::sqrt(double(i) / n);
        if (d > kTol) ds.push_back(d);
    }
    if (a.has_q) ds.push_back(a.p);
    return ds;
}
}  // namespace

Error g33(V2 tool, const G33Args& a, std::vector<Move>& out) {
    out.clear();
    if (Error e = g33_check(a)) return e;
    // Frame: x along the threading axis (Z, or X for a face thread at EA = ±90).
    Frame fr;
    bool face = std::fabs(std::fabs(a.ea) - 90) < 1e-9;
    fr.swap = face;
    double slope = face ? 0 : std::tan(a.ea * kDeg);
    V2 s = fr.to(tool), e = fr.to(V2(a.z, a.x));
    auto crest = [&](double x) { return e.y() + (x - e.x()) * slope; };
    double len = e.x() - s.x();
    if (std::fabs(len) <= kUm) return {881, tr("the thread has no length along its axis")};
    int sigma = len > 0 ? 1 : -1;
    double h = s.y() - crest(s.x());  // clearance above the crest line at the start
    if (std::fabs(h) <= kUm) return {833, tr("the start point lies on the thread")};
    if (a.r >= std::fabs(len) - kUm) return {881, tr("the exit slope R is as long as the thread")};
    int ext = h > 0 ? 1 : -1;  // external thread: the depth goes down the level axis
    // The tool retracts to the line parallel to the crest through the start
    // point: the start's level at the thread's end for a cylindrical thread,
    // and clear of a cone.
    auto clear = [&](double x) { return V2(x, crest(x) + h); };
    int starts = a.has_f ? int(std::lround(a.f)) : 1;
    double tan_eb = std::tan(a.eb * kDeg);
    double x_end = e.x() - sigma * a.r;

    zone::Emit em{fr, out, s};
    for (double d : depths(a)) {
        for (int j = 0; j < starts; ++j) {
            double xj = s.x() - sigma * j * a.k / starts;
            em.go(0, clear(xj));
            em.go(0, V2(xj - sigma * d * tan_eb, crest(xj) - ext * d));
            em.go(33, V2(x_end, crest(x_end) - ext * d));
            em.go(a.r > 0 ? 33 : 0, clear(e.x()));
            em.go(0, clear(xj));
        }
    }
    em.go(0, s);
    return {};
}

Error g38(V2 tool, const G38Args& a, std::vector<Move>& out) {
    out.clear();
    if (a.radius_comp) return {27, tr("threading in radius compensation (G41/G42)")};
    if (a.has_k && !(a.k > 0)) return {835, tr("the lead K must be positive")};
    if (!a.has_k && !(a.prev_k > 0)) return {883, tr("G38 needs the lead K")};
    if (!a.spindle_turning) return {831, tr("threading with the spindle stopped")};
    if ((a.to - tool).norm() > kTol) {
        Move m;
        m.g = 33;
        m.to = a.to;
        out.push_back(m);
    }
    return {};
}

int thread_axis(V2 from, V2 to) {
    V2 d = to - from;
    return std::fabs(d.x()) >= std::fabs(d.y()) ? 0 : 1;
}

}  // namespace pupitre::turning
