// G65 groove roughing (000:2587-2612; pupitre-iso(5), TURNING CYCLES): passes
// from the infeed line at angle EA towards the programmed limit, inside the
// zone the finished profile closes; and G66 plunge roughing (000:2791-2840):
// plunges spread evenly between two correctors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/cycles/turning.hpp"
#include "core/cycles/turning_geom.hpp"
#include "core/cycles/turning_zone.hpp"
#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"

namespace pupitre::turning {

using namespace geom;
using zone::Emit;
using zone::Material;

namespace {
using ::pupitre::geometry::kDeg;

// The first point of the ray S + s·u (s in [0, limit]) on the profile or inside
// A, or false.
bool first_contact(const Material& m, const V2& s, const V2& u, double limit, V2& c) {
    double len = limit;
    Elem ray = line(s, s + len * u);
    std::vector<double> ts{0, len};
    std::vector<V2> pts;
    for (const Elem& e : m.F) {  // meeting the profile is a contact in any case
        pts.clear();
        intersect(e, ray, pts);
        for (const V2& p : pts)
            if ((p - s).dot(u) > kTol) len = std::min(len, (p - s).dot(u));
    }
    ts[1] = len;
    for (const Elem& e : m.U) {
        pts.clear();
        intersect(e, ray, pts);
        for (const V2& p : pts) ts.push_back((p - s).dot(u));
    }
    std::sort(ts.begin(), ts.end());
    for (size_t j = 0; j + 1 < ts.size(); ++j) {
        if (ts[j + 1] - ts[j] <= kTol) continue;
        if (m.zero() && ts[j] > kTol) {  // without allowance: the first point on the profile
            c = s + ts[j] * u;
            return true;
        }
        if (ts[j] > len) break;
        if (m.in_A(s + (ts[j] + ts[j + 1]) / 2 * u)) {
            c = s + ts[j] * u;
            return true;
        }
    }
    if (len < limit) {  // the profile itself comes first
        c = s + len * u;
        return true;
    }
    return false;
}

// Where the level y, followed from x0 towards x1 (direction d), leaves the
// part: x0 when it is not inside, else the first crossing of the profile
// after which the level is out of it (x1 when it never is).
double leave_part(const std::vector<Elem>& F, const std::vector<Elem>& loop, double y, double x0,
                  double x1, int d) {
    auto inside = [&](double x) {
        return !on_loop(loop, V2(x, y)) && winding(loop, V2(x, y)) != 0;
    };
    if (!inside(x0)) return x0;
    std::vector<double> xs;
    for (const Elem& e : F) cross_h(e, y, xs);
    xs.erase(std::remove_if(xs.begin(), xs.end(),
                            [&](double x) { return (x - x0) * d <= kTol || (x1 - x) * d < 0; }),
             xs.end());
    std::sort(xs.begin(), xs.end(), [d](double a, double b) { return a * d < b * d; });
    xs.push_back(x1);
    for (size_t i = 0; i + 1 < xs.size(); ++i)
        if ((xs[i + 1] - xs[i]) * d > kTol && !inside((xs[i] + xs[i + 1]) / 2)) return xs[i];
    return x1;
}

// Lowest point of the translated profile between x0 and x1.
double lowest(const Material& m, double x0, double x1) {
    double y = kInf;
    for (const Elem& e : m.F) y = std::min(y, min_y_in(translated(e, m.t), x0, x1));
    return y;
}

// G65 argument checks (000:2587-2612; docs/decisions.md, Cycle argument errors).
Error g65_check(const Profile& fin, const G65Args& a) {
    if ((a.has_p && a.has_r) || (a.has_x && a.has_z))
        return {889, tr("G65 takes P or R, and X or Z, not both")};
    bool axial = a.has_z && a.has_p, frontal = a.has_x && a.has_r;
    if (!axial && !frontal)
        return {862, tr("G65 needs Z with P (axial groove) or X with R (frontal groove)")};
    if (!a.has_ea) return {2, tr("G65 needs the infeed angle EA")};
    double step = axial ? a.p : a.r;
    if (!(step > 0)) return {862, tr("the depth of cut must be positive")};
    return zone::check_profile(fin);
}

// What the steps of G65 share: the frame, the infeed line from S, the limit of
// the passes, the material and the lowest level.
struct G65Plan {
    Frame fr;
    V2 u, s;        // the infeed direction EA and the start point S, in the frame
    double xa = 0;  // the limit of the passes
    int d = 0;      // direction of the passes along x
    double step = 0;
    Material m;              // in the frame, with the allowance I K
    V2 c;                    // C: where the EA line meets the profile plus the allowance
    double y_low = 0;        // the last level
    double cl = 0;           // the retract clearance
    std::vector<Elem> loop;  // the part, for "inside"
};

// The roughing as it goes: the last infeed point, and the infeed points as the
// way back out.
struct G65Walk {
    Emit em;
    V2 prev;
    std::vector<V2> path;
};

// The frame of the passes: the infeed EA goes down the level axis, and the
// passes run from S towards the limit Z (X) on the side EA leads to.
Error g65_frame(const G65Args& a, V2 tool, G65Plan& p) {
    bool axial = a.has_z && a.has_p, frontal = a.has_x && a.has_r;
    p.step = axial ? a.p : a.r;
    p.fr.swap = frontal;
    p.u = p.fr.to(V2(std::cos(a.ea * kDeg), std::sin(a.ea * kDeg)));
    if (std::fabs(p.u.y()) < 1e-9) return {863, tr("EA runs parallel to the passes")};
    p.fr.s = p.u.y() < 0 ? 1 : -1;  // the infeed goes down the level axis
    p.u = p.fr.to(V2(std::cos(a.ea * kDeg), std::sin(a.ea * kDeg)));
    p.s = p.fr.to(tool);
    p.xa = axial ? a.z : a.x;
    p.d = p.xa > p.s.x() + kUm ? 1 : p.xa < p.s.x() - kUm ? -1 : 0;
    if (p.d == 0 || p.u.x() * p.d < -1e-9)
        return {863, tr("the limit of the passes is not on the side EA leads to")};
    return {};
}

// S outside the part; C, the first contact of the EA line (pupitre-iso(5), TURNING CYCLES); the
// levels go down to C or to the profile's lowest point before the limit.
Error g65_contact(const G65Args& a, G65Plan& p) {
    const Material& m = p.m;
    if (m.in_A(p.s)) return {875, tr("the start point lies inside the finished profile")};
    double span = (p.s - m.F.front().a).norm();
    for (const Elem& e : m.F) span = std::max(span, (p.s - e.b).norm());
    if (!first_contact(m, p.s, p.u, 2 * span + 100, p.c))
        return {875, tr("the EA line does not meet the finished profile")};
    p.y_low = std::min(p.c.y(), lowest(m, std::min(p.xa, p.c.x()), std::max(p.xa, p.c.x())));
    p.cl = std::min(a.q > 0 ? a.q : std::max(0.0, a.clearance), p.step / 2);
    return {};
}

// Start of the pass at level y: on the EA line down to C, below it where the
// level leaves the profile towards the limit; false when nothing is left.
bool pass_start(const G65Plan& p, double y, V2& e) {
    double xe = p.s.x() + p.u.x() * (p.s.y() - y) / -p.u.y();
    e = V2(xe, y);
    if (y < p.c.y() - kTol) {
        // Below C the EA line may run inside the part (a start point
        // beyond the groove's wall, its line meeting the land first):
        // the zone's side there is the profile from C on, where the
        // level leaves the part (000:2605-2612: the zone is bounded by
        // the profile and the lines S-A and S-C).
        double from = leave_part(p.m.F, p.loop, y, xe, p.xa, p.d);
        auto runs = zone::free_runs(p.m, y, from, p.xa, p.d);
        if (runs.empty()) return false;
        e = V2(runs[0].first, y);
    }
    return true;
}

// One pass at level y from e (pupitre-iso(5), TURNING CYCLES): the infeed, along the level as far
// as its retract stays clear, the retract and back to e.
void g65_pass(G65Walk& w, const G65Plan& p, double y, V2 e) {
    const Material& m = p.m;
    auto runs = zone::free_runs(m, y, e.x(), p.xa, p.d);
    bool ok = !runs.empty() && std::fabs(runs[0].first - e.x()) <= kTol &&
              std::fabs(runs[0].second - e.x()) > kUm;
    if (ok) {
        auto [from, to] = zone::clear_below(m, y, p.cl, e.x(), runs[0].second, p.d);
        ok = std::fabs(to - from) > kUm;
        e = V2(from, y);
        runs[0] = {from, to};
    }
    std::vector<V2> infeed{e};
    if (ok && y < p.c.y() - kTol && !zone::seg_clear(m, w.prev, e)) {
        infeed = {V2(e.x(), w.prev.y()), e};  // along the last pass, then down
        ok = zone::seg_clear(m, w.prev, infeed[0]) && zone::seg_clear(m, infeed[0], e);
    }
    if (!ok) return;
    for (const V2& q : infeed) w.em.go(1, q, true);
    w.path.insert(w.path.end(), infeed.begin(), infeed.end());
    w.em.go(1, V2(runs[0].second, y));
    w.em.go(0, V2(runs[0].second, y + p.cl));
    w.em.go(0, V2(e.x(), y + p.cl));
    w.em.go(0, e);
    w.prev = e;
}

// The levels from S down every P (R), the last one at the lowest level
// (pupitre-iso(5), TURNING CYCLES).
void g65_passes(G65Walk& w, const G65Plan& p) {
    for (int k = 1;; ++k) {
        double y = p.s.y() - k * p.step;
        bool last = y <= p.y_low + kUm;
        if (last) y = p.y_low;
        if (y >= p.s.y() - kTol) break;
        V2 e;
        if (pass_start(p, y, e)) g65_pass(w, p, y, e);
        if (last) break;
    }
}

// Out: up to the start level, then to S (pupitre-iso(5), TURNING CYCLES); where an overhang
// on the start side hides that way, back along the infeeds.
void g65_out(G65Walk& w, const G65Plan& p) {
    Emit& em = w.em;
    const V2& s = p.s;
    if (zone::seg_clear(p.m, em.cur, V2(em.cur.x(), s.y())) &&
        zone::seg_clear(p.m, V2(em.cur.x(), s.y()), s)) {
        em.go(0, V2(em.cur.x(), s.y()));
    } else {
        for (size_t i = w.path.size(); i-- > 1;) em.go(0, w.path[i - 1]);
    }
    em.go(0, s);
}

// G66 argument checks (000:2791-2840; docs/decisions.md, Cycle argument errors).
Error g66_check(const G66Args& a) {
    if (a.has_p && a.has_r) return {889, tr("G66 takes P or R, not both")};
    if (!(a.has_p || a.has_r) || !a.has_x || !a.has_z)
        return {862, tr("G66 needs X, Z and P or R")};
    double step = a.has_p ? a.p : a.r;
    if (!(step > 0)) return {862, tr("the distance between plunges must be positive")};
    if (a.d_first == 0 || a.d == 0)
        return {898, a.d == 0 ? tr("G66 needs the second corrector D")
                              : tr("no corrector active before G66")};
    if (a.milling_tool) return {864, tr("G66 with a milling tool")};
    return {};
}
}  // namespace

Error g65(const Profile& fin, V2 tool, const G65Args& a, std::vector<Move>& out) {
    out.clear();
    if (Error e = g65_check(fin, a)) return e;
    G65Plan p;
    if (Error e = g65_frame(a, tool, p)) return e;
    p.m.F = p.fr.to(fin.elems);
    p.m.translate(p.fr.to(V2(a.k, a.i)));
    // The allowance as written (docs/decisions.md, Roughing allowances are
    // signed): pointing down the level axis it lies inside the part; the passes
    // rough the translated profile and cut into it, the caller warns (1116).
    // Along the passes a groove has walls facing both ways, so that component
    // alone says nothing.
    if (p.m.t.y() < -kUm) {
        a.allowance_inside = true;
        Profile moved;
        for (const Elem& e : fin.elems) moved.elems.push_back(translated(e, V2(a.k, a.i)));
        G65Args written = a;
        written.i = written.k = 0;
        return g65(moved, tool, written, out);
    }
    if (Error e = g65_contact(a, p)) return e;
    p.loop = zone::part_loop(p.m.F);
    G65Walk w{Emit{p.fr, out, p.s}, p.s, {p.s}};
    g65_passes(w, p);
    g65_out(w, p);
    return {};
}

Error g66(V2 tool, const G66Args& a, std::vector<Move>& out) {
    out.clear();
    if (Error e = g66_check(a)) return e;
    double step = a.has_p ? a.p : a.r;
    // Frame: plunges along y, spread along x (R: radial groove, plunges along X
    // spread along Z; P: frontal groove, plunges along Z spread along X).
    Frame fr;
    fr.swap = a.has_p;
    V2 A = fr.to(tool);
    V2 B = fr.to(V2(a.z, a.x));
    V2 Bt = B + fr.to(a.gauge_delta);  // B in the first corrector's terms
    double width = Bt.x() - A.x();
    if (width * (B.x() - A.x()) < 0) return {863, tr("the groove is narrower than the tool")};
    double slope = std::tan(a.ea * kDeg);
    // The blade is flat between its two corners: the first's point is the
    // one programmed, the second's lies -gauge_delta from it. A plunge stops
    // where the first corner meets the bottom line through B (issue 39 item
    // 3: on a slope the higher end of the bottom under the blade, not the
    // second corner's alone).
    const V2 delta = fr.to(a.gauge_delta);
    auto line_at = [&](double x) { return B.y() + (x - B.x()) * slope; };
    int dir = line_at(A.x()) < A.y() ? -1 : 1;  // plunge direction along y
    auto bottom = [&](double x) {
        const double first = line_at(x), second = line_at(x - delta.x()) + delta.y();
        return dir < 0 ? std::max(first, second) : std::min(first, second);
    };
    // More plunges than any groove needs: an input mistake, refused as a zero
    // distance is (issue 40), before their count becomes an int.
    constexpr double kMaxPlunges = 10000;
    if (!(std::fabs(width) / step <= kMaxPlunges))
        return {862, strf(tr("the distance between plunges makes more than %d plunges"),
                          int(kMaxPlunges))};
    int n = int(std::ceil(std::fabs(width) / step - 1e-9));
    for (int i = 0; i <= n; ++i) {
        double x = n ? A.x() + width * i / n : A.x();
        double depth = bottom(x) - A.y();
        if (std::fabs(depth) <= kUm || (depth < 0 ? -1 : 1) != dir)
            return {863, tr("the groove bottom does not lie beyond the approach point")};
    }
    Emit em{fr, out, A};
    int side = width < 0 ? -1 : 1;  // progression along x
    for (int i = 0; i <= n; ++i) {
        double x = n ? A.x() + width * i / n : A.x();
        em.go(0, V2(x, A.y()));
        em.go(1, V2(x, bottom(x)), false, a.ef);
        if (a.ep > 0 && i > 0) {
            // 45°, back over the cut part of the groove (000:2795: "EP..
            // Valeur du déplacement à 45° en fin de passe"), and no further
            // back than the first plunge: a longer EP would run into the
            // groove's start flank (issue 19 item 1, [DECISION]).
            double h = std::min(a.ep / std::sqrt(2.0), std::fabs(x - A.x()));
            em.go(1, V2(x - side * h, bottom(x) - dir * h));
        }
        em.go(0, V2(em.cur.x(), A.y()));
    }
    em.go(0, V2(Bt.x(), A.y()));
    return {};
}

}  // namespace pupitre::turning
