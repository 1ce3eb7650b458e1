// G64 paraxial roughing (000:2434-2458; pupitre-iso(5), TURNING CYCLES): passes
// parallel to Z (P) or X (R) between the stock and the finished profile
// translated by the allowances; and G63 roughing with grooves (000:2634-2707),
// the same passes entering grooves.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <functional>

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

int sgn(double v, double tol = kUm) {
    return v > tol ? 1 : v < -tol ? -1 : 0;
}

std::vector<Elem> polyline(const std::vector<V2>& pts) {
    std::vector<Elem> es;
    for (size_t i = 0; i + 1 < pts.size(); ++i)
        if ((pts[i + 1] - pts[i]).norm() > kTol) es.push_back(line(pts[i], pts[i + 1]));
    if (es.empty() && !pts.empty()) es.push_back(line(pts[0], pts[0]));
    return es;
}

// The stock is written from the profile's start towards its end (the
// handbook's first examples) or the other way round (the cabestan programs): true for the latter.
bool stock_reversed(const std::vector<V2>& b, const Profile& f) {
    V2 f0 = f.elems.front().a, fn = f.elems.back().b;
    return (b.front() - fn).norm() + (b.back() - f0).norm() <
           (b.front() - f0).norm() + (b.back() - fn).norm() - kTol;
}

// The closed material region: stock, closing segment to the profile's end, the
// profile backwards, closing segment to the stock's start (pupitre-iso(5), TURNING CYCLES).
void build_region(const std::vector<V2>& b, const Profile& f, Material& m) {
    for (const Elem& e : polyline(b)) {
        if ((e.b - e.a).norm() <= kTol) continue;
        m.M.push_back(e);
        m.kind.push_back(zone::kStock);
    }
    V2 f0 = f.elems.front().a, fn = f.elems.back().b;
    if ((fn - b.back()).norm() > kTol) {
        m.M.push_back(line(b.back(), fn));
        m.kind.push_back(zone::kClosing);
    }
    for (auto it = f.elems.rbegin(); it != f.elems.rend(); ++it) {
        if (length(*it) <= kTol) continue;
        m.M.push_back(reversed(*it));
        m.kind.push_back(zone::kProfile);
    }
    if ((b.front() - f0).norm() > kTol) {
        m.M.push_back(line(f0, b.front()));
        m.kind.push_back(zone::kClosing);
    }
}

Error check_region(const Material& m) {
    if (m.M.size() < 2 || std::fabs(area(m.M)) < 1e-9)
        return {874, tr("the stock and the finished profile enclose no material")};
    if (self_intersects(m.M)) return {874, tr("the stock crosses the finished profile")};
    return {};
}

Material to_frame(const Material& m, const Frame& fr) {
    Material f;
    f.M = fr.to(m.M);
    f.kind = m.kind;
    f.F = fr.to(m.F);
    return f;
}

// One pass at level y from x_s (in air, c before the stock) to x_e
// (pupitre-iso(5), TURNING CYCLES).
void pass(Emit& em, double y, double xs, double xe, int d, double c, bool first, double sy) {
    V2 start(xs - d * c, y);
    if (first) em.go(0, V2(start.x(), sy));  // from the tool: along the passes, then down
    em.go(0, start);
    em.go(1, V2(xe, y));
    em.go(0, V2(xe, y + c));
    em.go(0, V2(start.x(), y + c));
}

// The direction along x in which the level lines run from the stock into the
// material up to the profile, weighted by length; 0 when undecided.
int cut_direction(const Material& m, const std::vector<double>& ys) {
    double score[2] = {0, 0};
    for (double y : ys)
        for (const zone::Interval& iv : zone::m_intervals(m, y, 1)) {
            double len = iv.b - iv.a;
            auto weight = [](int from, int to) {
                if (from == zone::kProfile || to == zone::kStock) return 0.0;
                return from == zone::kStock && to == zone::kProfile ? 1.0 : 0.5;
            };
            score[1] += len * weight(iv.front, iv.back);  // from a towards b
            score[0] += len * weight(iv.back, iv.front);
        }
    if (score[1] > score[0] * (1 + 1e-9) + kTol) return 1;
    if (score[0] > score[1] * (1 + 1e-9) + kTol) return -1;
    return 0;
}

// More passes than any roughing needs: a depth of cut too small for the
// stock, refused (error 873, seed 000 l.13453 "P or R not programmed", the
// number of a missing P or R) before the levels are counted; 10,000 passes
// plan in a fraction of a second (issue 40: 250,000 took 17 s).
constexpr double kMaxLevels = 10000;

// Levels y_top - k·step down to y_min, the last one exactly at y_min.
std::vector<double> levels(double y_top, double y_min, double step) {
    std::vector<double> ys;
    for (int k = 1;; ++k) {
        double y = y_top - k * step;
        if (y <= y_min + kUm) {
            if (y_top > y_min + kUm) ys.push_back(y_min);
            break;
        }
        ys.push_back(y);
    }
    return ys;
}
// The arguments, the finished profile and the stock, in the order the NUM
// checks them (pupitre-iso(5), TURNING CYCLES): the first fault's error number, or 0.
Error check_g64(const Profile& fin, const std::vector<V2>& stock, const std::vector<Elem>& bs,
                const G64Args& a) {
    if (!a.has_p && !a.has_r)
        return {873, tr("G64 needs P (passes along Z) or R (passes along X)")};
    if (a.has_p && a.has_r) return {889, tr("G64 takes P or R, not both")};
    double step = a.has_p ? a.p : a.r;
    if (!(step > 0)) return {873, tr("the depth of cut must be positive")};
    if (Error e = zone::check_profile(fin)) return e;
    if (stock.empty()) return {872, tr("no stock point between G64 and G80")};
    if (Error e = zone::check_axis(fin.elems,
                                   N_("the finished profile crosses the spindle axis (X below 0)")))
        return e;
    if (Error e = zone::check_axis(bs, N_("the stock crosses the spindle axis (X below 0)")))
        return e;
    return {};
}

// The coordinate along which the levels step, and the one the passes run along.
double level_of(const Frame& fr, const V2& p) {
    return fr.swap ? p.x() : p.y();
}
double along(const Frame& fr, const V2& p) {
    return fr.swap ? p.y() : p.x();
}

// Frame: passes along x; the material above the profile (pupitre-iso(5), TURNING CYCLES). Its
// side is the mean normal of the profile towards the material, which is the
// profile's chord turned a quarter towards the side M lies on; when that
// says nothing along the level axis, the tool is on the side of the stock
// where the levels start.
Frame pass_frame(const Profile& fin, const Material& real, const std::vector<V2>& stock, V2 tool,
                 bool along_x) {
    Frame fr;
    fr.swap = along_x;
    V2 chord = fin.elems.back().b - fin.elems.front().a;
    V2 side = area(real.M) < 0 ? V2(-chord.y(), chord.x()) : V2(chord.y(), -chord.x());
    if (std::fabs(level_of(fr, side)) > kUm * std::max(1.0, chord.norm())) {
        fr.s = level_of(fr, side) > 0 ? 1 : -1;
    } else {
        double lo = kInf;
        for (const V2& p : stock) lo = std::min(lo, level_of(fr, p));
        fr.s = level_of(fr, tool) < lo - kUm ? -1 : 1;
    }
    return fr;
}

// The pass levels in the frame, from the stock's top down to the translated
// profile's lowest point; 873 when the step would make too many of them.
// [DECISION] (issue 19) A level at the height of each land: every line of
// the profile plus allowance that runs along the passes, between the top of
// the stock and the last level, gets a pass, so the lands are left at the
// allowance and not up to one depth of cut above it.  Seed 000:2597-2600:
// after "G64 ... I.5 K.2 P2", %555 places G65's start point at X62 Z50 in
// rapid, 0.5 mm above the ø60 lands plus allowance; lands left at ø64 by
// the levels alone would be in its way.
void add_land_levels(const Material& m, double y_top, std::vector<double>& ys) {
    if (ys.empty()) return;
    const double y_last = ys.back();
    for (const Elem& f : m.F) {
        const Elem e = translated(f, m.t);
        if (e.arc || std::fabs(e.a.y() - e.b.y()) > kTol || std::fabs(e.a.x() - e.b.x()) <= kUm)
            continue;
        const double y = e.a.y();
        if (y >= y_top - kUm || y <= y_last + kUm) continue;
        if (std::any_of(ys.begin(), ys.end(), [&](double l) { return std::fabs(l - y) <= kUm; }))
            continue;
        ys.insert(std::upper_bound(ys.begin(), ys.end(), y, std::greater<double>()), y);
    }
}

Error pass_levels(const Material& m, const std::vector<V2>& stock, const Frame& fr, double step,
                  std::vector<double>& ys) {
    double y_top = -kInf, y_min = kInf;
    for (const V2& p : stock) y_top = std::max(y_top, fr.to(p).y());
    for (const Elem& e : m.F) y_min = std::min(y_min, min_y(translated(e, m.t)));
    if (!((y_top - y_min) / step <= kMaxLevels))
        return {873, tr("the depth of cut is too small for the stock")};
    ys = levels(y_top, y_min, step);
    add_land_levels(m, y_top, ys);
    return {};
}

// Cutting direction: from the stock into the material, towards the profile
// (pupitre-iso(5), TURNING CYCLES: from the end of the called profile towards its start, when
// the stock is written from its start; the reverse when it is written from
// its end, as in the cabestan programs).
int pass_direction(const Material& m, const std::vector<double>& ys, const Profile& fin,
                   const std::vector<Elem>& bs, bool rev, const Frame& fr) {
    V2 f0 = fin.elems.front().a, fn = fin.elems.back().b;
    int d = cut_direction(m, ys);
    if (d == 0) d = rev ? sgn(along(fr, fn) - along(fr, f0)) : sgn(along(fr, f0) - along(fr, fn));
    if (d == 0) d = sgn(along(fr, zone::centroid(fin.elems)) - along(fr, zone::centroid(bs)));
    if (d == 0) d = -1;
    return d;
}

// The piece of e from t0 to t1 (t in [0, 1] along it).
Elem piece(const Elem& e, double t0, double t1) {
    Elem p = e;
    p.a = point_at(e, t0), p.b = point_at(e, t1);
    p.sweep = e.sweep * (t1 - t0);
    return p;
}

// The profile plus allowance that the passes reached: a point of it is
// reached when it lies in the material, the level line just above it runs clear of the part plus
// allowance from the stock side (it is not behind a bump), and the vertical
// above it too (it is not hidden from the retract side): what is neither is a
// groove, left to G65.
struct Reach {
    const Material& m;
    int d;
    double y_top, span;
    bool operator()(const V2& p) const {
        const V2 q(p.x(), p.y() + 1e-4);  // 0.1 µm above it
        return m.in_M(q) && zone::seg_clear(m, V2(p.x() - d * span, q.y()), q) &&
               zone::seg_clear(m, q, V2(p.x(), y_top));
    }
};

// The stretches of the profile plus allowance that the passes reached, in the
// order of the passes' direction, each as a list of elements.
std::vector<std::vector<Elem>> reached_stretches(const Material& m, const std::vector<Elem>& fp,
                                                 int d, double y_top) {
    double span = y_top;
    for (const Elem& e : fp) span = std::max({span, std::fabs(e.a.x()), std::fabs(e.b.x())});
    const Reach reach{m, d, y_top, 4 * span + 100};
    std::vector<std::vector<Elem>> out;
    bool open = false;
    for (const Elem& e : fp) {
        const int n = std::clamp(int(std::ceil(length(e) / 0.5)), 4, 64);
        double t0 = 0;
        bool in = reach(point_at(e, 0.5 / n));
        for (int k = 1; k <= n; ++k) {
            const bool next = k < n && reach(point_at(e, (k + 0.5) / n));
            if (k < n && next == in) continue;
            double t1 = 1;
            // Where reach changes, to 0.1 µm; also between the last sample
            // and the element's end when the end is not reached (an offset
            // curve's end on the normal lies beyond the material).
            const bool tail = k == n && in && !reach(point_at(e, 1));
            if (k < n || tail) {
                double lo = (k - 0.5) / n, hi = k < n ? (k + 0.5) / n : 1;
                while ((hi - lo) * length(e) > 1e-4) {
                    const double mid = (lo + hi) / 2;
                    (reach(point_at(e, mid)) == in ? lo : hi) = mid;
                }
                t1 = (lo + hi) / 2;
            }
            if (!in) {
                open = false;
            } else if ((t1 - t0) * length(e) > kUm) {
                if (!open) out.emplace_back();
                out.back().push_back(piece(e, t0, t1));
                open = true;
            }
            t0 = t1;
            in = next;
        }
    }
    return out;
}

// The highest point of the material region, -inf when it is empty.
double top_of_M(const Material& m) {
    double y_top = -kInf;
    for (const Elem& e : m.M) y_top = std::max(y_top, max_y(e));
    return y_top;
}

// The segment p-q runs along the finished profile (its middle lies on it).
bool along_F(const Material& m, const V2& p, const V2& q) {
    const V2 mid = (p + q) / 2;
    for (const Elem& e : m.F)
        if ((closest(e, mid) - mid).norm() <= kUm) return true;
    return false;
}

// The profile plus allowance (G64's paraxial one) in the passes' direction,
// and where the profile itself ends on the closing side of the material.
std::vector<Elem> translated_profile(const Material& m, int d, V2& end) {
    std::vector<Elem> fp;
    for (const Elem& e : m.F) fp.push_back(translated(e, m.t));
    end = m.F.back().b;
    if ((fp.back().b.x() - fp.front().a.x()) * d < 0) {
        std::reverse(fp.begin(), fp.end());
        for (Elem& e : fp) e = reversed(e);
        end = m.F.front().a;
    }
    return fp;
}

// [DECISION] (issue 19) G64 ends with a pass along the profile plus allowance
// over what the passes reached, in their direction: it takes off the steps
// the levels leave on cones and arcs (the seeds give no toolpath; seed
// 000:2626 has %555 rapid to X142 Z0 with G41 after the cycle, which
// the steps left on the N110 arc would be in the way of).  The way to each
// stretch and back runs at feed within the clearance of the material, in rapid
// above it.
// `fp` is the profile plus allowance in the passes' direction; with `strip`,
// the pass goes on along the level from fp's end to `end`, the profile's.
void contour_pass(Emit& em, const Material& m, const std::vector<Elem>& fp, V2 end, bool strip,
                  int d, double c, double y_safe) {
    double y_top = top_of_M(m);
    if (y_top == -kInf) y_top = y_safe;
    y_top = std::min(y_top, y_safe);
    // Above the material at x, by the clearance: the way down runs in rapid
    // to there (in the air above the stock), then at feed.
    // (Only the crossings up to y_top count: max_y_in would also take the
    // material's far side beyond the start level, as in a bore.)
    auto above = [&](const V2& p) {
        double y = -kInf;
        std::vector<V2> pts;
        for (const Elem& e : m.M) intersect(e, line(V2(p.x(), p.y()), V2(p.x(), y_top + 1)), pts);
        for (const V2& q : pts) y = std::max(y, q.y());
        return std::max(y, p.y()) + c;
    };
    for (const std::vector<Elem>& s : reached_stretches(m, fp, d, y_top)) {
        const V2 a = s.front().a;
        em.go(0, V2(em.cur.x(), y_safe));
        em.go(0, V2(a.x(), y_safe));
        em.go(0, V2(a.x(), above(a)));
        em.go(1, a);
        for (const Elem& e : s) {
            if (e.arc)
                em.arc(e);
            else
                em.go(1, e.b);
        }
        // At the end of the profile, on along the level to where the material
        // ends: the allowance along the passes leaves a strip there (%555 Z0);
        // not where the way out from there would run along the finished
        // profile (issue 39 item 2: a bore's wall alone, %7300's H8 bore,
        // was climbed at feed and cut to size).
        const V2 ext(end.x(), em.cur.y());
        if (strip && (s.back().b - fp.back().b).norm() <= kUm && (end.x() - em.cur.x()) * d > kUm &&
            !along_F(m, ext, V2(ext.x(), above(ext))))
            em.go(1, ext);
        em.go(1, V2(em.cur.x(), above(em.cur)));
    }
}

// The level the tool travels at to the passes, between the stretches of the
// last pass and back: its start's, or above the material when it started
// lower, as in front of a bore's face outside it (issue 39 item 1: a rapid
// at the start's level went through the bore's wall). It goes to it and back
// square to the passes where it stands.
double travel_level(const Material& m, const V2& s, double c) {
    const double y_top = top_of_M(m);
    return s.y() >= y_top - kUm ? s.y() : y_top + c;
}

// One pass per level, over the first interval met from the stock, up to where
// the profile hides the material (pupitre-iso(5), TURNING CYCLES); then back to the start point.
void rough_passes(Emit& em, const Material& m, const std::vector<double>& ys, int d, double c) {
    const V2 s = em.cur;
    const double y_travel = travel_level(m, s, c);
    bool first = true;
    for (double y : ys) {
        auto ivs = zone::m_intervals(m, y, d);
        if (d < 0) std::reverse(ivs.begin(), ivs.end());
        for (const zone::Interval& iv : ivs) {
            if (iv.front == zone::kProfile) continue;  // a groove behind a bump
            double xs = d > 0 ? iv.a : iv.b, far = d > 0 ? iv.b : iv.a;
            auto runs = zone::free_runs(m, y, xs, far, d);
            if (runs.empty() || std::fabs(runs[0].first - xs) > kTol) break;
            double end = zone::first_hidden(m, y, xs, runs[0].second, d);
            if (std::fabs(end - xs) <= kUm) break;
            if (first && y_travel > s.y() + kUm) em.go(0, V2(s.x(), y_travel));
            pass(em, y, xs, end, d, c, first, y_travel);
            first = false;
            break;  // one pass per level: the first interval met from the stock
        }
    }
    if (first) return;
    V2 end;
    const std::vector<Elem> fp = translated_profile(m, d, end);
    contour_pass(em, m, fp, end, true, d, c, y_travel);
    em.go(0, V2(em.cur.x(), y_travel));
    if (y_travel > s.y() + kUm) em.go(0, V2(s.x(), y_travel));
    em.go(0, s);
}
}  // namespace

Error g64(const Profile& fin, const std::vector<V2>& stock, V2 tool, const G64Args& a,
          std::vector<Move>& out) {
    out.clear();
    std::vector<Elem> bs = polyline(stock);
    if (Error e = check_g64(fin, stock, bs, a)) return e;
    double step = a.has_p ? a.p : a.r;

    bool rev = stock_reversed(stock, fin);
    std::vector<V2> b = stock;
    if (rev) std::reverse(b.begin(), b.end());
    Material real;
    real.F = fin.elems;
    build_region(b, fin, real);
    if (Error e = check_region(real)) return e;

    Frame fr = pass_frame(fin, real, stock, tool, a.has_r);
    Material m = to_frame(real, fr);
    m.translate(fr.to(V2(a.k, a.i)));
    std::vector<double> ys;
    if (Error e = pass_levels(m, stock, fr, step, ys)) return e;
    int d = pass_direction(m, ys, fin, bs, rev, fr);
    // The allowance is a signed translation (docs/decisions.md, Roughing
    // allowances are signed): the NUM cannot know which side is material. Where
    // it points into the part (a positive I on a bore, seed 000: "I et K
    // peuvent être munies du signe − (sur-épaisseur pour un alésage)"), the
    // passes rough the translated profile as written and cut into the part; the
    // caller warns (1116).
    if (m.t.y() < -kUm || m.t.x() * d > kUm) {
        a.allowance_inside = true;
        Profile moved;
        for (const Elem& e : fin.elems) moved.elems.push_back(translated(e, V2(a.k, a.i)));
        G64Args written = a;
        written.i = written.k = 0;
        return g64(moved, stock, tool, written, out);
    }
    double c = std::min(std::max(0.0, a.clearance), step / 2);

    Emit em{fr, out, fr.to(tool)};
    rough_passes(em, m, ys, d, c);
    return {};
}

namespace {
// G63 argument checks (000:2634-2707; docs/decisions.md, Cycle argument errors).
Error g63_check(const Profile& fin, const G63Args& a) {
    if (!a.has_p && !a.has_r)
        return {873, tr("G63 needs P (passes along Z) or R (passes along X)")};
    if ((a.has_p && a.has_r) || (a.has_ex && a.has_ez))
        return {889, tr("G63 takes P or R, and EZ or EX, not both")};
    if ((a.has_p && !a.has_ez) || (a.has_r && !a.has_ex))
        return {862, tr("G63 needs EZ with P or EX with R")};
    if (!a.has_x || !a.has_z) return {2, tr("G63 needs its start point X Z")};
    if (!((a.has_p ? a.p : a.r) > 0)) return {873, tr("the depth of cut must be positive")};
    if (a.er < 0 || a.eq < 0) return {889, tr("ER and EQ must not be negative")};
    if ((a.has_eb && !(a.eb > 0 && a.eb < 180)) || (a.has_ec && !(a.ec >= 0 && a.ec < 180)))
        return {876, tr("EB must lie in ]0, 180[ and EC in [0, 180[ degrees")};
    if (Error e = zone::check_profile(fin)) return e;
    return zone::check_axis(fin.elems,
                            N_("the finished profile crosses the spindle axis (X below 0)"));
}

// Angle of the profile where a pass enters a groove, from the pass direction
// (0: the profile goes on along the pass, 90: a wall, above 90: an undercut).
double entry_angle(const Material& m, const V2& q, int d, V2& down) {
    double best = kInf;
    V2 t(d, 0);
    for (const Elem& e : m.F) {
        V2 te;
        double dd = (closest(e, q, &te) - q).norm();
        if (dd < best) best = dd, t = te;
    }
    if (t.y() > 0) t = -t;
    if (std::fabs(t.y()) < 1e-12) t = V2(d, 0);
    down = t;
    return std::atan2(-t.y(), t.x() * d) / kDeg;
}

// Highest point of the allowance zone over [x0, x1].
double top_of_A(const Material& m, double x0, double x1) {
    double lo = std::min(x0, x1) - m.er, hi = std::max(x0, x1) + m.er, y = -kInf;
    for (const Elem& e : m.F) y = std::max(y, max_y_in(e, lo, hi));
    return y + m.er;
}

// Moves of one feed path if none enters A.
bool clear_path(const Material& m, V2 from, const std::vector<V2>& pts) {
    for (const V2& p : pts) {
        if (!zone::seg_clear(m, from, p)) return false;
        from = p;
    }
    return true;
}

// What the steps of G63 share: the frame, the start point D, the end and
// direction of the passes, the start line and the material plus ER.
struct G63Plan {
    Frame fr;
    V2 dr;          // start point D in (z, r)
    V2 D;           // D in the frame
    double xz = 0;  // end of the passes, EZ or EX
    int d = 0;      // direction of the passes along x
    bool has_lim = false;
    double lim = 0;  // EU (or EW): the lowest level
    V2 u{0, -1};     // start line of the passes, downwards
    double y_u = 0;  // the last level
    Material m;      // in the frame, offset by ER
    double c = 0;    // the retract clearance
    double eb = 90;  // the steepest groove entry
    // The point of the start line at level y.
    V2 on_start_line(double y) const { return V2(D.x() + u.x() * (D.y() - y) / -u.y(), y); }
};
using Runs = std::vector<std::pair<double, double>>;

// The frame of the passes, mirrored so that D lies above EU (EW), else above
// the profile; the passes run from D towards EZ (EX).
Error g63_frame(const Profile& fin, const G63Args& a, G63Plan& p) {
    p.fr.swap = a.has_r;
    p.dr = V2(a.z, a.x);
    auto lev = [&](const V2& q) { return p.fr.swap ? q.x() : q.y(); };
    p.has_lim = p.fr.swap ? a.has_ew : a.has_eu;
    p.lim = p.fr.swap ? a.ew : a.eu;
    double ref = p.has_lim ? p.lim : lev(zone::centroid(fin.elems));
    p.fr.s = lev(p.dr) < ref - kUm ? -1 : 1;
    p.D = p.fr.to(p.dr);
    p.xz = a.has_ez ? a.ez : a.ex;
    p.d = sgn(p.xz - p.D.x());
    if (p.d == 0) return {862, tr("the end of the passes is at the start point")};
    return {};
}

// Start line of the passes: EA, else towards the point EU EW, else square
// to the passes through D; the levels go down to EU (EW), else the profile.
Error g63_start_line(const Profile& fin, const G63Args& a, G63Plan& p) {
    const Frame& fr = p.fr;
    if (a.has_ea) {
        p.u = fr.to(V2(std::cos(a.ea * kDeg), std::sin(a.ea * kDeg)));
    } else if (a.has_eu || a.has_ew) {
        V2 pu = fr.to(V2(a.has_ew ? a.ew : a.z, a.has_eu ? a.eu : a.x)) - p.D;
        if (pu.norm() > kUm && std::fabs(pu.y()) > kUm) p.u = pu.normalized();
    }
    if (p.u.y() > 0) p.u = -p.u;
    if (std::fabs(p.u.y()) < 1e-9) return {875, tr("the start line EA runs along the passes")};
    std::vector<Elem> ff = fr.to(fin.elems);
    double y_min = kInf;
    for (const Elem& e : ff) y_min = std::min(y_min, min_y(e));
    p.y_u = p.has_lim ? fr.s * p.lim : y_min;
    if (a.has_ea) {
        bool met = false;
        for (const Elem& e : ff) met = met || ray_hit(e, p.D, p.u) < kInf;
        if (!met) return {875, tr("the EA line does not meet the finished profile")};
    }
    return {};
}

// Stock: the start line, the start level, the end of the passes (pupitre-iso(5), TURNING CYCLES);
// the material it closes with the profile, offset by ER (step 3).
Error g63_material(const Profile& fin, const G63Args& a, G63Plan& p) {
    std::vector<V2> b{p.fr.back(p.on_start_line(std::min(p.y_u, p.D.y()))), p.dr,
                      p.fr.back(V2(p.xz, p.D.y()))};
    bool rev = stock_reversed(b, fin);
    if (rev) std::reverse(b.begin(), b.end());
    Material real;
    real.F = fin.elems;
    build_region(b, fin, real);
    if (Error e = check_region(real)) return e;
    p.m = to_frame(real, p.fr);
    p.m.offset(a.er);
    return {};
}

// The levels every P (R) from D down to EU (EW) or the profile (pupitre-iso(5), TURNING CYCLES),
// none closer than EQ to the one above it.
// [DECISION] (issue 39 item 5) As G64's, a level at the height of each land
// plus ER between the start and the last level, so that a land or a pocket's
// bottom is left at ER and not up to a depth of cut above it (%100's G63 left
// the Ø40 pockets at Ø36 and the Ø30 lands at Ø28); EQ does not remove them.
std::vector<double> g63_levels(const G63Args& a, const G63Plan& p, double step) {
    std::vector<double> ys = levels(p.D.y(), p.y_u, step);
    if (ys.size() >= 2 && ys[ys.size() - 2] - ys.back() < a.eq - kTol) ys.pop_back();
    if (ys.size() == 1 && p.D.y() - ys.back() < a.eq - kTol) ys.pop_back();
    for (const Elem& e : p.m.F) {
        if (e.arc || std::fabs(e.a.y() - e.b.y()) > kTol || std::fabs(e.a.x() - e.b.x()) <= kUm)
            continue;
        const double y = e.a.y() + p.m.er;
        if (y >= p.D.y() - kUm || y <= p.y_u + kUm) continue;
        if (std::any_of(ys.begin(), ys.end(), [&](double l) { return std::fabs(l - y) <= kUm; }))
            continue;
        ys.insert(std::upper_bound(ys.begin(), ys.end(), y, std::greater<double>()), y);
    }
    return ys;
}

// The runs of level y outside the material plus ER, from the first interval
// met from the stock up to the end of the passes; false when the level cuts
// nothing. `xs` is where the pass starts.
bool level_runs(const G63Plan& p, double y, double& xs, Runs& runs) {
    const int d = p.d;
    auto ivs = zone::m_intervals(p.m, y, d);
    if (d < 0) std::reverse(ivs.begin(), ivs.end());
    size_t k = 0;
    while (k < ivs.size() && ivs[k].front == zone::kProfile) ++k;
    if (k == ivs.size()) return false;
    xs = d > 0 ? ivs[k].a : ivs[k].b;
    for (; k < ivs.size(); ++k) {
        double x0 = d > 0 ? ivs[k].a : ivs[k].b, x1 = d > 0 ? ivs[k].b : ivs[k].a;
        if ((x0 - p.xz) * d >= 0) break;
        if ((x1 - p.xz) * d > 0) x1 = p.xz;
        for (auto r : zone::free_runs(p.m, y, x0, x1, d)) runs.push_back(r);
    }
    if (runs.empty() || std::fabs(runs[0].first - xs) > kTol ||
        std::fabs(runs[0].second - xs) <= kUm)
        return false;
    // Each run ends where its retract by the clearance stays out of the
    // allowance (a rounded corner of ER, an undercut wall), a groove's run
    // at the farthest point whose climb out of it is clear: no retract
    // enters the part plus ER (issue 19 item 1).
    auto [f0, t0] = zone::clear_below(p.m, y, p.c, xs, runs[0].second, p.d);
    if (std::fabs(f0 - xs) > kTol || std::fabs(t0 - xs) <= kUm) return false;
    if (std::fabs(t0 - runs[0].second) > kTol) runs.resize(1);  // hidden beyond: no groove
    runs[0].second = t0;
    return true;
}

// Enters the grooves of the level one after the other (000:2634-2707: the passes enter
// grooves whose entry is no steeper than EB), over the land between them;
// returns where the pass ends, `entered` when it went into a groove.
double enter_grooves(Emit& em, const G63Plan& p, double y, double xs, Runs& runs, bool& entered) {
    const Material& m = p.m;
    const double c = p.c;
    double end = runs[0].second;
    for (size_t j = 1; j < runs.size(); ++j) {
        // The angle of the flank the pass goes down: measured 10 nm above
        // the level, where a land level at a groove's bottom plus ER starts
        // its run on the corner, nearer the flank than the bottom.
        V2 down, entry(runs[j].first, y);
        if (entry_angle(m, V2(entry.x(), y + 1e-5), p.d, down) > p.eb + 1e-9) break;
        // The run ends at the farthest point whose climb out is clear.
        double climb = std::max(y + c, top_of_A(m, xs, runs[j].second) + c);
        auto out_ok = zone::clear_runs(m, y, climb - y, runs[j].first, runs[j].second, p.d);
        if (out_ok.empty()) break;
        double tj = out_ok.back().second;
        if (std::fabs(tj - runs[j].first) <= kUm) break;
        runs[j].second = tj;
        double over = std::max(y + c, top_of_A(m, end, entry.x()) + c);
        if (std::fabs(down.y()) < std::sin(5 * kDeg)) down = V2(0, -1);
        double lean = (over - y) * down.x() / -down.y();
        std::vector<V2> path{V2(end, over), V2(entry.x() - lean, over), entry,
                             V2(runs[j].second, y)};
        if (!clear_path(m, V2(end, y + c), path)) {
            path[1] = V2(entry.x(), over);
            if (!clear_path(m, V2(end, y + c), path)) break;
        }
        em.go(0, V2(end, y + c));
        em.go(1, path[0]);
        em.go(1, path[1]);
        em.go(1, path[2], true);
        em.go(1, path[3]);
        end = runs[j].second;
        entered = true;
    }
    return end;
}

// The profile plus ER (G63's normal allowance) in the passes' direction: the
// profile offset on the material's side as the radius compensation offsets a
// contour (outside corners rounded, inside ones trimmed). False when an arc
// is smaller than ER on its inside, where there is no such curve.
bool offset_profile(const Material& m, int d, std::vector<Elem>& fp) {
    std::vector<Elem> f;
    for (const Elem& e : m.F)
        if (length(e) > kTol) f.push_back(e);
    if (f.empty()) return false;
    if ((f.back().b.x() - f.front().a.x()) * d < 0) {
        std::reverse(f.begin(), f.end());
        for (Elem& e : f) e = reversed(e);
    }
    V2 tangent;
    const V2 mid = midpoint(f.front());
    closest(f.front(), mid, &tangent);
    const int side = m.in_M(mid + 1e-4 * comp::normal(tangent, 1)) ? 1 : -1;
    Elem first;
    if (!comp::offset(f.front(), m.er, side, first)) return false;
    std::vector<comp::Piece> path;
    V2 from = first.a;
    for (size_t i = 0; i + 1 < f.size(); ++i)
        if (comp::join(f[i], from, f[i + 1], m.er, side, path, from) != 0) return false;
    if (comp::finish(f.back(), from, m.er, side, path) != 0) return false;
    V2 at = first.a;
    for (const comp::Piece& pc : path) {
        Elem e = line(at, pc.to);
        if (pc.arc) e.arc = true, e.c = pc.c, e.sweep = pc.sweep;
        if (length(e) > kTol) fp.push_back(e);
        at = pc.to;
    }
    return !fp.empty();
}

// One pass at level y (pupitre-iso(5), TURNING CYCLES): in from the start line, along the level
// and into the grooves it may enter, then out by the clearance and back over
// the part plus ER.
void g63_pass(Emit& em, const G63Plan& p, double y, bool& first) {
    double xs = 0;
    Runs runs;
    if (!level_runs(p, y, xs, runs)) return;
    const double c = p.c;
    V2 start(xs - p.d * c, y);
    if (first) em.go(0, V2(start.x(), p.D.y()));
    first = false;
    em.go(0, start);
    em.go(1, V2(runs[0].second, y));
    bool entered = false;
    double end = enter_grooves(em, p, y, xs, runs, entered);
    em.go(0, V2(end, y + c));
    if (entered) {
        double back = std::max(y + c, top_of_A(p.m, xs, end) + c);
        em.go(1, V2(end, back));
        em.go(1, V2(start.x(), back));
    }
    em.go(0, V2(start.x(), y + c));
}
}  // namespace

Error g63(const Profile& fin, V2 tool, const G63Args& a, std::vector<Move>& out) {
    out.clear();
    if (Error e = g63_check(fin, a)) return e;
    double step = a.has_p ? a.p : a.r;
    G63Plan p;
    if (Error e = g63_frame(fin, a, p)) return e;
    if (Error e = g63_start_line(fin, a, p)) return e;
    if (Error e = g63_material(fin, a, p)) return e;
    if (!((p.D.y() - p.y_u) / step <= kMaxLevels))
        return {873, tr("the depth of cut is too small for the stock")};
    p.c = std::min(a.q > 0 ? a.q : std::max(0.0, a.clearance), step / 2);
    p.eb = a.has_eb ? a.eb : 90;

    Emit em{p.fr, out, p.fr.to(tool)};
    em.go(0, p.D);
    bool first = true;
    for (double y : g63_levels(a, p, step)) g63_pass(em, p, y, first);
    // [DECISION] (issue 39 item 5) As G64, a last pass along the profile plus
    // ER over what the levels reached takes off the steps they leave on
    // cones, arcs and flanks (%100's were left up to a depth of cut above).
    std::vector<Elem> fp;
    if (!first && p.m.er >= kUm && offset_profile(p.m, p.d, fp))
        contour_pass(em, p.m, fp, V2(0, 0), false, p.d, p.c, p.D.y());
    em.go(0, V2(em.cur.x(), p.D.y()));
    em.go(0, p.D);
    return {};
}

}  // namespace pupitre::turning
