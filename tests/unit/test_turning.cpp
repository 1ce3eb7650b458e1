// Turning cycles (000:2434-2840, 000:3194-3294; pupitre-iso(5), TURNING CYCLES): expected points of
// the handbook programs, computed by hand or once with an independent script
// (polygons with densified arcs, scanning and bisection), and properties checked
// with an oracle that shares no code with the cycles: the passes never come
// closer to the finished profile than its allowance, stay inside the stock, and
// leave no material thicker than the depth of cut.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "core/cycles/turning.hpp"
#include "core/interp/interp.hpp"
#include "helpers.hpp"

using namespace pupitre;
using namespace pupitre::turning;
using comp::Elem;
using test::in_polygon;

namespace {
constexpr double kPi = std::numbers::pi;

// A cycle that answers no error; else its number and message.
testing::AssertionResult ok(const Error& e) {
    if (!e) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "error " << e.code << ": " << e.detail;
}

// Program coordinates (X as a diameter, Z) to internal (z, r).
V2 P(double x, double z) {
    return V2(z, x / 2);
}

Elem L(V2 a, V2 b) {
    Elem e;
    e.a = a;
    e.b = b;
    return e;
}

Elem Arc(V2 a, V2 b, V2 c, bool ccw) {
    Elem e = L(a, b);
    e.arc = true;
    e.c = c;
    double s = std::atan2(b.y() - c.y(), b.x() - c.x()) - std::atan2(a.y() - c.y(), a.x() - c.x());
    if (ccw && s <= 0) s += 2 * kPi;
    if (!ccw && s >= 0) s -= 2 * kPi;
    e.sweep = s;
    return e;
}

// A profile through points (program coordinates), straight elements.
Profile poly_profile(std::initializer_list<V2> pts) {
    Profile p;
    std::vector<V2> v(pts);
    for (size_t i = 0; i + 1 < v.size(); ++i) p.elems.push_back(L(v[i], v[i + 1]));
    return p;
}

// The profile translated by t (z, r): what G64 roughs when the allowance
// points into the part (docs/decisions.md, Roughing allowances are signed).
Profile shifted(const Profile& p, V2 t) {
    Profile out = p;
    for (Elem& e : out.elems) e.a += t, e.b += t, e.c += t;
    return out;
}

Profile reversed(const Profile& p) {
    Profile r;
    for (auto it = p.elems.rbegin(); it != p.elems.rend(); ++it) {
        Elem e = *it;
        std::swap(e.a, e.b);
        e.sweep = -e.sweep;
        r.elems.push_back(e);
    }
    return r;
}

// %555 finished profile N100..N190 (000:2474-2491).
Profile p555() {
    Profile p;
    p.elems.push_back(Arc(P(140, 0), P(120, 10), P(120, 0), false));
    for (auto [a, b] : std::vector<std::pair<V2, V2>>{{P(120, 10), P(60, 10)},
                                                      {P(60, 10), P(60, 20)},
                                                      {P(60, 20), P(40, 30)},
                                                      {P(40, 30), P(40, 40)},
                                                      {P(40, 40), P(60, 50)},
                                                      {P(60, 50), P(60, 60)},
                                                      {P(60, 60), P(25, 90)},
                                                      {P(25, 90), P(0, 90)}})
        p.elems.push_back(L(a, b));
    return p;
}
const std::vector<V2> kStock555{P(144, 0), P(144, 10), P(40, 94), P(0, 94)};

// A move of a cycle with its start point.
struct Seg {
    V2 a, b;
    int g;
    bool infeed;
};
// The moves as segments; an arc (G64's pass along the profile) as chords of
// at most 0.1 µm sagitta, so that sampling them stays on the arc.
std::vector<Seg> segs(V2 from, const std::vector<Move>& mv) {
    std::vector<Seg> out;
    for (const Move& m : mv) {
        if (m.g == 2 || m.g == 3) {
            const double r = (from - m.c).norm();
            const int n = std::max(1, int(std::ceil(std::fabs(m.sweep) / std::sqrt(8e-7 / r))));
            for (int k = 1; k <= n; ++k) {
                const double a = m.sweep * k / n;
                const V2 q = k == n ? m.to : V2(m.c + Eigen::Rotation2Dd(a) * (from - m.c));
                out.push_back({k == 1 ? from : out.back().b, q, m.g, false});
            }
            from = m.to;
            continue;
        }
        out.push_back({from, m.to, m.g, m.infeed});
        from = m.to;
    }
    return out;
}
std::vector<Seg> feeds(V2 from, const std::vector<Move>& mv) {
    std::vector<Seg> out;
    for (const Seg& s : segs(from, mv))
        if (s.g == 1) out.push_back(s);
    return out;
}

// ---- Oracle: polylines only, no code shared with core/turning_*.cpp ----
double cross(V2 o, V2 a, V2 b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}
double seg_point(V2 p, V2 a, V2 b) {
    V2 d = b - a;
    double l2 = d.squaredNorm(), t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0;
    return (a + t * d - p).norm();
}
bool segs_meet(V2 p, V2 q, V2 a, V2 b) {
    double d1 = cross(a, b, p), d2 = cross(a, b, q), d3 = cross(p, q, a), d4 = cross(p, q, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    return seg_point(p, a, b) < 1e-12 || seg_point(q, a, b) < 1e-12 || seg_point(a, p, q) < 1e-12 ||
           seg_point(b, p, q) < 1e-12;
}
double polyline_dist(const std::vector<V2>& pl, V2 q, bool closed) {
    double d = 1e300;
    for (size_t i = 0; i + 1 < pl.size(); ++i) d = std::min(d, seg_point(q, pl[i], pl[i + 1]));
    if (closed && pl.size() > 1) d = std::min(d, seg_point(q, pl.back(), pl.front()));
    return d;
}
std::vector<V2> densify(const Profile& p) {
    std::vector<V2> out{p.elems.front().a};
    for (const Elem& e : p.elems) {
        if (!e.arc) {
            out.push_back(e.b);
            continue;
        }
        int n = 400;
        double a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x()), r = (e.a - e.c).norm();
        for (int i = 1; i <= n; ++i) {
            double a = a0 + e.sweep * i / n;
            out.push_back(e.c + r * V2(std::cos(a), std::sin(a)));
        }
    }
    return out;
}

// Segment p-q meets element e (arcs exactly).
bool meets(V2 p, V2 q, const Elem& e) {
    if (!e.arc) return segs_meet(p, q, e.a, e.b);
    V2 d = q - p, w = p - e.c;
    double r = (e.a - e.c).norm(), A = d.squaredNorm(), B = 2 * w.dot(d),
           C = w.squaredNorm() - r * r;
    double disc = B * B - 4 * A * C;
    if (A < 1e-30 || disc < 0) return false;
    for (double sg : {-1.0, 1.0}) {
        double t = (-B + sg * std::sqrt(disc)) / (2 * A);
        if (t < -1e-12 || t > 1 + 1e-12) continue;
        V2 x = p + t * d;
        double a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x());
        double ang = std::atan2(x.y() - e.c.y(), x.x() - e.c.x()) - a0;
        ang = e.sweep > 0 ? ang : -ang;
        ang = std::fmod(ang + 4 * kPi, 2 * kPi);
        if (ang <= std::fabs(e.sweep) + 1e-12 || ang >= 2 * kPi - 1e-12) return true;
    }
    return false;
}
double elem_dist(V2 p, const Elem& e) {
    if (!e.arc) return seg_point(p, e.a, e.b);
    double r = (e.a - e.c).norm();
    double a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x());
    double ang = std::atan2(p.y() - e.c.y(), p.x() - e.c.x()) - a0;
    ang = e.sweep > 0 ? ang : -ang;
    ang = std::fmod(ang + 4 * kPi, 2 * kPi);
    if (ang <= std::fabs(e.sweep)) return std::fabs((p - e.c).norm() - r);
    return std::min((p - e.a).norm(), (p - e.b).norm());
}

struct Oracle {
    std::vector<Elem> fe;   // the finished profile, exact
    std::vector<V2> f;      // the finished profile
    std::vector<V2> m;      // the material: stock, then the profile backwards
    std::vector<V2> stock;  // the stock polyline
    V2 t{0, 0};             // paraxial allowance (K, I)
    double er = -1;         // normal allowance (G63), when >= 0

    Oracle(const Profile& p, std::vector<V2> b, V2 allowance)
        : fe(p.elems), f(densify(p)), stock(b), t(allowance) {
        // The stock runs from next to the profile's start to next to its end.
        if ((b.front() - f.back()).norm() + (b.back() - f.front()).norm() <
            (b.front() - f.front()).norm() + (b.back() - f.back()).norm())
            std::reverse(b.begin(), b.end());
        m = b;
        m.insert(m.end(), f.rbegin(), f.rend());
        closing = {{b.back(), f.back()}, {f.front(), b.front()}};
    }
    std::vector<std::pair<V2, V2>> closing;  // stock ends to profile ends
    double dist_f(V2 q) const {
        double d = 1e300;
        for (const Elem& e : fe) d = std::min(d, elem_dist(q, e));
        return d;
    }
    // q is in the closed zone: moving it back by a fraction of t meets the profile.
    bool in_closed_A(V2 q) const {
        V2 p = q - t;
        double lx = std::min(p.x(), q.x()), hx = std::max(p.x(), q.x());
        double ly = std::min(p.y(), q.y()), hy = std::max(p.y(), q.y());
        for (const Elem& e : fe) {
            if (!e.arc && (std::max(e.a.x(), e.b.x()) < lx || std::min(e.a.x(), e.b.x()) > hx ||
                           std::max(e.a.y(), e.b.y()) < ly || std::min(e.a.y(), e.b.y()) > hy))
                continue;
            if (meets(p, q, e)) return true;
        }
        return false;
    }
    // q lies deeper than 1 µm inside the finished part plus its allowance: its
    // neighbours 1 µm away all lie in the zone.
    bool in_A(V2 q) const {
        if (er >= 0) return dist_f(q) < er - 1e-6;
        for (int k = 0; k < 8; ++k) {
            double a = k * kPi / 4;
            if (!in_closed_A(q + 1e-6 * V2(std::cos(a), std::sin(a)))) return false;
        }
        return true;
    }
    bool in_M(V2 q, double tol) const {
        return in_polygon(m, q) || polyline_dist(m, q, true) <= tol;
    }
};

// No move, feed or rapid, enters A (the finished part swept by its allowance:
// issue 19 item 1) inside the material, sampled every 20 µm; feed moves stay inside the material
// region, or within the clearance c of its boundary (the pass starts c before
// the stock).
void check_clear(const Oracle& o, V2 tool, const std::vector<Move>& mv, double c,
                 const char* what) {
    int bad_a = 0, bad_m = 0;
    for (const Seg& s : segs(tool, mv)) {
        int n = std::max(50, int((s.b - s.a).norm() / 0.02));
        for (int i = 0; i <= n; ++i) {
            V2 q = s.a + (s.b - s.a) * (double(i) / n);
            // A rapid may graze the zone where it sticks out of the material
            // (at the stock's edge); inside the material it is a gouge.
            bool in_material = in_polygon(o.m, q) && polyline_dist(o.m, q, true) > 1e-6;
            if (o.in_A(q) && (s.g != 0 || in_material) && ++bad_a <= 2)
                ADD_FAILURE() << what << ": G" << s.g << " in A at Z" << q.x() << " r" << q.y()
                              << " on " << s.a.transpose() << " -> " << s.b.transpose();
            if (s.g != 0 && !o.in_M(q, c + 1e-6)) ++bad_m;
        }
    }
    EXPECT_EQ(bad_a, 0) << what << ": points inside the profile plus allowance";
    EXPECT_EQ(bad_m, 0) << what << ": feed points outside the stock";
}

// Every point of the material outside A is cut by a pass at most `step` below it
// (frame: x along the passes, y = s·level coordinate), or lies within `step`
// above A (the staircase the radial retract leaves), unless `skip` says so.
template <class Skip>
void check_cover(const Oracle& o, V2 tool, const std::vector<Move>& mv, bool swap, double s,
                 double step, double y_low, Skip skip, const char* what) {
    auto fx = [&](V2 p) { return swap ? p.y() : p.x(); };
    auto fy = [&](V2 p) { return s * (swap ? p.x() : p.y()); };
    auto unf = [&](double x, double y) { return swap ? V2(s * y, x) : V2(x, s * y); };
    std::vector<Seg> passes = feeds(tool, mv);
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (V2 p : o.m) {
        lo_x = std::min(lo_x, fx(p)), hi_x = std::max(hi_x, fx(p));
        lo_y = std::min(lo_y, fy(p)), hi_y = std::max(hi_y, fy(p));
    }
    int bad = 0, tried = 0;
    for (double y = lo_y + 0.0137; y < hi_y; y += 0.3713) {
        if (y < y_low) continue;
        for (double x = lo_x + 0.0191; x < hi_x; x += 0.4171) {
            V2 q = unf(x, y);
            if (!in_polygon(o.m, q) || polyline_dist(o.m, q, true) < 1e-3 || o.in_A(q) || skip(q))
                continue;
            // Where the profile meets a closing segment, its allowance leaves a
            // corner of at most t (the pass stops on the swept corner).
            bool corner = false;
            for (auto [a, b] : o.closing) corner = corner || seg_point(q, a, b) < o.t.norm() + 1e-3;
            if (corner) continue;
            ++tried;
            bool ok = false;
            for (const Seg& p : passes) {
                double py = fy(p.a);
                if (std::fabs(fy(p.b) - py) > 1e-9 || py > y + 1e-9 || py < y - step - 1e-9)
                    continue;
                double a = fx(p.a), b = fx(p.b);
                if (x >= std::min(a, b) - 1e-9 && x <= std::max(a, b) + 1e-9) ok = true;
            }
            for (int k = 0; k <= 20 && !ok; ++k) {
                V2 below = unf(x, y - step * k / 20);
                ok = o.in_A(below) || !in_polygon(o.m, below);
            }
            if (!ok && ++bad <= 3)
                ADD_FAILURE() << what << ": material left at Z" << q.x() << " X" << 2 * q.y();
        }
    }
    EXPECT_GT(tried, 0) << what;
    EXPECT_EQ(bad, 0) << what;
}

void check_cover(const Oracle& o, V2 tool, const std::vector<Move>& mv, bool swap, double s,
                 double step, double y_low, const char* what) {
    check_cover(
        o, tool, mv, swap, s, step, y_low, [](V2) { return false; }, what);
}

// Level, start (on the stock) and end of each pass.
struct Row {
    double level, start, end;
};

// The level passes come first; the pass along the profile plus allowance
// follows them (P555EndsAlongTheAllowanceProfile checks it).
void expect_passes(V2 tool, const std::vector<Move>& mv, bool swap, double c, int d,
                   const std::vector<Row>& rows) {
    std::vector<Seg> p = feeds(tool, mv);
    ASSERT_GE(p.size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        auto ax = [&](V2 v) { return swap ? v.y() : v.x(); };
        auto lv = [&](V2 v) { return swap ? v.x() : v.y(); };
        EXPECT_NEAR(lv(p[i].a), rows[i].level, 1e-6) << i;
        EXPECT_NEAR(lv(p[i].b), rows[i].level, 1e-6) << i;
        EXPECT_NEAR(ax(p[i].a) + d * c, rows[i].start, 1e-5) << i;
        EXPECT_NEAR(ax(p[i].b), rows[i].end, 1e-5) << i;
    }
}
}  // namespace

// ---------------------------------------------------------------- G64 ----

// %555 roughing along Z (000:2500-2519): G64 N100 N190 I.5 K.2 P2 from X200 Z150.
// Each pass starts 1 mm (the clearance) before the stock and ends on the profile
// translated by (K, I) = (0.2, 0.5); the groove Z20-Z50 is left for G65.
TEST(G64, P555AlongZ) {
    G64Args a;
    a.i = .5, a.k = .2, a.has_p = true, a.p = 2;
    std::vector<Move> mv;
    V2 tool = P(200, 150);
    ASSERT_TRUE(ok(g64(p555(), kStock555, tool, a, mv)));
    expect_passes(tool, mv, false, 1, -1,
                  {{70.0000, 13.230769, 3.322498},
                   {68.0000, 16.461538, 6.814378},
                   {66.0000, 19.692308, 8.551647},
                   {64.0000, 22.923077, 9.567497},
                   {62.0000, 26.153846, 10.086860},
                   {60.0000, 29.384615, 10.200000},
                   {58.0000, 32.615385, 10.200000},
                   {56.0000, 35.846154, 10.200000},
                   {54.0000, 39.076923, 10.200000},
                   {52.0000, 42.307692, 10.200000},
                   {50.0000, 45.538462, 10.200000},
                   {48.0000, 48.769231, 10.200000},
                   {46.0000, 52.000000, 10.200000},
                   {44.0000, 55.230769, 10.200000},
                   {42.0000, 58.461538, 10.200000},
                   {40.0000, 61.692308, 10.200000},
                   {38.0000, 64.923077, 10.200000},
                   {36.0000, 68.153846, 10.200000},
                   {34.0000, 71.384615, 10.200000},
                   {32.0000, 74.615385, 10.200000},
                   // The Ø60 lands plus I.5: over the groove, to the face N120.
                   {30.5000, 77.038462, 10.200000},
                   {30.0000, 77.846154, 61.057143},
                   {28.0000, 81.076923, 64.485714},
                   {26.0000, 84.307692, 67.914286},
                   {24.0000, 87.538462, 71.342857},
                   // The Ø40 groove bottom plus I.5, to the cone N180.
                   {22.0000, 90.769231, 74.771429},
                   {20.5000, 93.192308, 77.342857},
                   {20.0000, 94.000000, 78.200000},
                   {18.0000, 94.000000, 81.628571},
                   {16.0000, 94.000000, 85.057143},
                   {14.0000, 94.000000, 88.485714},
                   {12.0000, 94.000000, 90.200000},
                   {10.0000, 94.000000, 90.200000},
                   {8.0000, 94.000000, 90.200000},
                   {6.0000, 94.000000, 90.200000},
                   {4.0000, 94.000000, 90.200000},
                   {2.0000, 94.000000, 90.200000},
                   {0.5000, 94.000000, 90.200000}});
    // Approach along Z then down; each pass: rapid in, feed, retract 1 mm
    // radially, rapid back; then the pass along the profile plus allowance,
    // which ends at its start Z0 (r 70.5); at the end up to X200 then to Z150
    // (pupitre-iso(5), TURNING CYCLES).
    ASSERT_GE(mv.size(), 6u);
    EXPECT_TRUE(mv[0].g == 0 && mv[0].to.isApprox(V2(14.230769, 100), 1e-6));
    EXPECT_TRUE(mv[1].g == 0 && mv[1].to.isApprox(V2(14.230769, 70), 1e-6));
    EXPECT_TRUE(mv[3].g == 0 && mv[3].to.isApprox(V2(3.322498, 71), 1e-6));
    EXPECT_TRUE(mv[4].g == 0 && mv[4].to.isApprox(V2(14.230769, 71), 1e-6));
    EXPECT_TRUE(mv[mv.size() - 2].to.isApprox(V2(0, 100), 1e-9));
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
    // The groove between the two Ø60 lands is never entered.
    for (const Seg& s : feeds(tool, mv))
        EXPECT_FALSE(s.a.y() < 30 && std::min(s.a.x(), s.b.x()) < 50 &&
                     std::max(s.a.x(), s.b.x()) > 20);
}

// The same part roughed along X (000:2530-2545): G64 N190 N100 I.5 K.2 R3, the
// profile called backwards and the stock written from the axis.
TEST(G64, P555AlongX) {
    G64Args a;
    a.i = .5, a.k = .2, a.has_r = true, a.r = 3;
    std::vector<Move> mv;
    V2 tool = P(200, 150);
    std::vector<V2> stock{P(0, 94), P(40, 94), P(144, 10), P(144, 0)};
    ASSERT_TRUE(ok(g64(reversed(p555()), stock, tool, a, mv)));
    expect_passes(tool, mv, true, 1, -1,
                  {{91.0000, 21.857143, 0.000000},
                   {90.2000, 22.352381, 0.000000},  // the face N190 plus K.2, along it to the axis
                   {88.0000, 23.714286, 14.283333},
                   {85.0000, 25.571429, 16.033333},
                   {82.0000, 27.428571, 17.783333},
                   {79.0000, 29.285714, 19.533333},
                   {76.0000, 31.142857, 21.283333},
                   {73.0000, 33.000000, 23.033333},
                   {70.0000, 34.857143, 24.783333},
                   {67.0000, 36.714286, 26.533333},
                   {64.0000, 38.571429, 28.283333},
                   {61.0000, 40.428571, 30.033333},
                   {58.0000, 42.285714, 30.500000},
                   {55.0000, 44.142857, 30.500000},
                   {52.0000, 46.000000, 30.500000},
                   {49.0000, 47.857143, 30.500000},
                   {46.0000, 49.714286, 30.500000},
                   {43.0000, 51.571429, 30.500000},
                   {40.0000, 53.428571, 30.500000},
                   {37.0000, 55.285714, 30.500000},
                   {34.0000, 57.142857, 30.500000},
                   {31.0000, 59.000000, 30.500000},
                   {28.0000, 60.857143, 30.500000},
                   {25.0000, 62.714286, 30.500000},
                   {22.0000, 64.571429, 30.500000},
                   {19.0000, 66.428571, 30.500000},
                   {16.0000, 68.285714, 30.500000},
                   {13.0000, 70.142857, 30.500000},
                   {10.2000, 71.876190, 30.500000},  // the face N120 plus K.2, to the Ø60 land
                   {10.0000, 72.000000, 62.489974},
                   {7.0000, 72.000000, 67.832121},
                   {4.0000, 72.000000, 69.749865},
                   {1.0000, 72.000000, 70.467949},
                   {0.2000, 72.000000, 70.500000}});
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
}

namespace {
// G64 on the profile f over `stock` as a program calls it: P passes along Z,
// or R passes along X with the profile and the stock called from their other
// end (000:2530-2545).
Error g64_called(const Profile& f, const std::vector<V2>& stock, V2 tool, G64Args& a, bool along_x,
                 double step, std::vector<Move>& mv) {
    (along_x ? a.has_r : a.has_p) = true;
    (along_x ? a.r : a.p) = step;
    std::vector<V2> st = along_x ? std::vector<V2>(stock.rbegin(), stock.rend()) : stock;
    return g64(along_x ? reversed(f) : f, st, tool, a, mv);
}

// %555's G64 I.5 K.2 from `tool`: P2 along Z, or R3 along X.
void g64_p555(bool along_x, V2 tool, std::vector<Move>& mv) {
    G64Args a;
    a.i = .5, a.k = .2;
    ASSERT_TRUE(ok(g64_called(p555(), kStock555, tool, a, along_x, along_x ? 3 : 2, mv)));
}

}  // namespace

// [DECISION] of issue 19: G64 ends with a pass along the profile plus
// allowance over what the passes reached. On %555, along Z and along X, every
// point of the translated profile lies on that pass (a feed or an arc), but
// the groove Z20-Z50 left to G65: its flanks and bottom below the Ø60 lands.
TEST(G64, P555EndsAlongTheAllowanceProfile) {
    for (bool along_x : {false, true}) {
        const V2 tool = P(200, 150);
        std::vector<Move> mv;
        ASSERT_NO_FATAL_FAILURE(g64_p555(along_x, tool, mv));
        std::vector<Seg> cut;
        for (const Seg& s : segs(tool, mv))
            if (s.g != 0) cut.push_back(s);
        std::vector<V2> fp = densify(shifted(p555(), V2(.2, .5)));
        int on = 0, off = 0, groove = 0;
        for (size_t i = 0; i + 1 < fp.size(); ++i)
            // Along a line, ten points; on an arc, its vertices (they lie on it).
            for (int k = 0; k < ((fp[i + 1] - fp[i]).norm() > .2 ? 10 : 1); ++k) {
                V2 q = fp[i] + (fp[i + 1] - fp[i]) * (k / 10.0);
                if (q.x() > 20.2 + 1e-6 && q.x() < 50.2 - 1e-6 && q.y() < 30.5 - 1e-6) {
                    ++groove;
                    continue;
                }
                bool hit = false;
                for (const Seg& s : cut) hit = hit || seg_point(q, s.a, s.b) < 1e-6;
                (hit ? on : off)++;
                if (!hit && off <= 3)
                    ADD_FAILURE() << (along_x ? "X" : "Z") << ": not on the pass at Z" << q.x()
                                  << " r" << q.y();
            }
        EXPECT_GT(on, 100);
        EXPECT_GT(groove, 10);
        EXPECT_EQ(off, 0);
        // Where the profile plus allowance ends, the pass goes on along the
        // level to where the material ends: the K.2 strip at %555's Z0 along
        // Z (r 70.5), the I.5 one at the axis along X (Z90.2).
        const V2 end = along_x ? V2(90.2, 0) : V2(0, 70.5);
        bool reached = false;
        for (const Seg& s : cut) reached = reached || (s.b - end).norm() < 1e-9;
        EXPECT_TRUE(reached) << (along_x ? "X" : "Z");
    }
}

TEST(G64, P555Properties) {
    for (bool along_x : {false, true}) {
        const V2 tool = P(200, 150);
        std::vector<Move> mv;
        ASSERT_NO_FATAL_FAILURE(g64_p555(along_x, tool, mv));
        Oracle o(p555(), kStock555, V2(.2, .5));
        check_clear(o, tool, mv, 1, along_x ? "R3" : "P2");
        // The groove between the Ø60 lands is G65's work in both variants
        // (pupitre-iso(5), TURNING CYCLES). Along Z the level at r 30 stops on
        // the cone behind it, so the strip up to the level r 32 over the land
        // and the groove is left too; along X what the lands and the cone hide
        // from +Z is left: below the land's r 30.5 from the flank N140 to the
        // flank N160.
        auto groove = [&](V2 q) {
            if (along_x) return q.x() > 20 && q.x() < 50.2 && q.y() < 30.5;
            return q.x() > 10 && q.x() < 61.1 && q.y() < 32;
        };
        check_cover(o, tool, mv, along_x, 1, along_x ? 3 : 2, along_x ? .2 : .5, groove,
                    along_x ? "R3" : "P2");
    }
}

// %1 chuck (000:3457-3474): G64 N100 N170 I.6 K.5 P2.5, stock equal to the
// profile at both ends. Levels from Ø65 down by 2.5 (radius); the passes end on
// the translated shoulders at Z-44.25 and Z-20.25; the Ø24.194 end level finds
// only allowance and is skipped.
TEST(G64, P1Chuck) {
    Profile f = poly_profile({P(65, -46.75), P(61, -44.75), P(48.25, -44.75), P(48.25, -21.75),
                              P(46.75, -20.75), P(26.994, -20.75), P(26.994, -1), P(22.994, 1)});
    std::vector<V2> stock{P(65, -46.75), P(65, 1), P(22.994, 1)};
    G64Args a;
    a.i = .6, a.k = .5, a.has_p = true, a.p = 2.5;
    std::vector<Move> mv;
    V2 tool = P(200, 100);
    ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
    expect_passes(tool, mv, false, 1, -1,
                  {{30, 1, -44.25},
                   {27.5, 1, -44.25},
                   {25, 1, -44.25},
                   {24.725, 1, -44.25},  // the Ø48.25 land plus I.6
                   {22.5, 1, -20.25},
                   {20, 1, -20.25},
                   {17.5, 1, -20.25},
                   {15, 1, -20.25},
                   {14.097, 1, -20.25}});  // the Ø26.994 land plus I.6
    Oracle o(f, stock, V2(.5, .6));
    check_clear(o, tool, mv, 1, "%1");
    check_cover(o, tool, mv, false, 1, 2.5, 12.097, "%1");
}

// %2 cone (000:3483-3522): the cone Ø44.927 Z-94.8 to Ø25.258 Z-28.797 has a
// slope of 0.149; passes on it end on the translated cone.
TEST(G64, P2Cone) {
    Profile f = poly_profile({P(65, -96.8), P(61, -94.8), P(44.927, -94.8), P(25.258, -28.797),
                              P(25.258, -1), P(21.258, 1)});
    EXPECT_NEAR((44.927 - 25.258) / 2 / (94.8 - 28.797), 0.149, 1e-5);
    std::vector<V2> stock{P(65, -96.8), P(65, 1), P(21.258, 1)};
    G64Args a;
    a.i = .6, a.k = .5, a.has_p = true, a.p = 2.5;
    std::vector<Move> mv;
    V2 tool = P(200, 100);
    ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
    // Z = -94.3 + (23.0635 - r) / 9.8345 · 66.003 on the translated cone.
    expect_passes(tool, mv, false, 1, -1,
                  {{30, 1, -94.3},
                   {27.5, 1, -94.3},
                   {25, 1, -94.3},
                   {22.5, 1, -90.518141},
                   {20, 1, -73.739708},
                   {17.5, 1, -56.961275},
                   {15, 1, -40.182842},
                   {13.229, 1, -28.297},  // the Ø25.258 land plus I.6, to the cone's end
                   {12.5, 1, 0.229}});
    Oracle o(f, stock, V2(.5, .6));
    check_clear(o, tool, mv, 1, "%2");
    check_cover(o, tool, mv, false, 1, 2.5, 11.229, "%2");
}

// The palier family with the P1 set of %11 (L1=80 L3=10 L5=50 L6=29.987
// L7=49.8, computed by %123: L150=43.8 L151=104 L152=44 L153=56 L154=35.987
// L155=25.987). Each profile as called, each stock as written.
TEST(G64, PalierP1001) {
    // G64 N80 N50 I.5 K.4 P2: the profile called backwards from its shoulder.
    Profile f = poly_profile({P(104, 15), P(49.8, 15), P(49.8, 48.5), P(43.8, 51.5)});
    std::vector<V2> stock{P(104, 15), P(104, 51.5), P(43.8, 51.5)};
    G64Args a;
    a.i = .5, a.k = .4, a.has_p = true, a.p = 2;
    std::vector<Move> mv;
    V2 tool = P(104, 1.5);
    ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
    std::vector<Row> rows;
    for (double r = 50; r > 25; r -= 2) rows.push_back({r, 51.5, 15.4});
    rows.push_back({25.4, 51.5, 15.4});  // the Ø49.8 land plus I.5
    rows.push_back({24, 51.5, 50.3});
    expect_passes(tool, mv, false, 1, -1, rows);
    Oracle o(f, stock, V2(.4, .5));
    check_clear(o, tool, mv, 1, "%1001");
    check_cover(o, tool, mv, false, 1, 2, 22.4, "%1001");
}

TEST(G64, PalierP2000Face) {
    // G64 N100 N60 I.5 K.4 R2: a face with a G3 R3 corner, centre X56 Z-5.
    Profile f;
    f.elems = {L(P(44, 1.5), P(50, -1.5)), L(P(50, -1.5), P(50, -5)),
               Arc(P(50, -5), P(56, -8), P(56, -5), false), L(P(56, -8), P(104, -8))};
    std::vector<V2> stock{P(44, 1.5), P(104, 1.5), P(104, -8)};
    G64Args a;
    a.i = .5, a.k = .4, a.has_r = true, a.r = 2;
    std::vector<Move> mv;
    V2 tool = P(104, 1.5);
    ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
    // Passes along X towards the axis at Z-0.5 ... -6.5 and the last at Z-7.6.
    expect_passes(tool, mv, true, 1, -1,
                  {{-0.5, 52, 24.9},
                   {-2.5, 52, 25.5},
                   {-4.5, 52, 25.5},
                   {-6.5, 52, 26.178363},
                   {-7.6, 52, 28.5}});
    Oracle o(f, stock, V2(.4, .5));
    check_clear(o, tool, mv, 1, "%2000");
    check_cover(o, tool, mv, true, 1, 2, -7.6, "%2000");
}

namespace {
int check_out_of_part(const Oracle& o, const std::vector<V2>& part, V2 tool,
                      const std::vector<Move>& mv, const std::string& what);
}  // namespace

// %2001 roughs a bore with I.5, a positive allowance (docs/decisions.md,
// Roughing allowances are signed):
// the translation goes into the wall. The NUM cannot know which side is
// material, so the passes rough the translated profile as written, 0.5 into
// the wall, and the interpreter warns (1116); K.4 still leaves 0.4 on the
// bottom.
TEST(G64, PalierP2001BorePositiveI) {
    Profile f = poly_profile({P(25.987, -52), P(29.987, -52), P(29.987, -1.5), P(35.987, 1.5)});
    std::vector<V2> stock{P(25.987, -52), P(25.987, 1.5), P(35.987, 1.5)};
    G64Args a;
    a.i = .5, a.k = .4, a.has_p = true, a.p = 1;
    std::vector<Move> mv;
    V2 tool = P(35.987, 1.5);
    ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
    std::vector<Seg> p = feeds(tool, mv);
    ASSERT_FALSE(p.empty());
    EXPECT_NEAR(p[0].a.y(), 13.9935, 1e-9);  // the first level above the Ø25.987 hole
    EXPECT_NEAR(p[0].b.x(), -51.6, 1e-9);    // K.4 off the bottom
    EXPECT_TRUE(a.allowance_inside);
    Oracle moved(shifted(f, V2(.4, .5)), stock, V2(0, 0));
    check_clear(moved, tool, mv, .5, "%2001 as written");
    // Issue 39 item 1: started at the chamfer's outer end, in front of the
    // face outside the bore, the last pass rapided at X35.987 over the whole
    // Ø29.987 wall: no move enters the part (the wall, r 15 to 30).
    check_out_of_part(moved,
                      {P(35.987 + 1, 1.5 + .4), P(29.987 + 1, -1.5 + .4), P(29.987 + 1, -51.6),
                       P(60, -51.6), P(60, 1.9)},
                      tool, mv, "%2001 as written");
    // The level r 15.9935 ends on the translated chamfer at Z-0.6, 0.1 beyond
    // the finished chamfer (Z-0.5 at that radius): the allowance as written.
    int at = 0;
    for (const Seg& s : p)
        if (std::fabs(s.a.y() - 15.9935) < 1e-9) {
            EXPECT_NEAR(s.b.x(), -0.6, 1e-9);
            ++at;
        }
    EXPECT_EQ(at, 1);
}

// The cabestan programs write the stock from the end of the profile back to
// its start; the passes still run from the stock into the material.
TEST(G64, Cabestan) {
    struct Case {
        const char* name;
        Profile f;
        std::vector<V2> stock;
        V2 tool;
        G64Args a;
        bool swap;
        double s, low;
    };
    auto args = [](double i, double k, bool r, double step) {
        G64Args a;
        a.i = i, a.k = k;
        (r ? a.has_r : a.has_p) = true;
        (r ? a.r : a.p) = step;
        return a;
    };
    const double l13 = 47.5195 - 2, l3 = 47.5195, l9 = 14.6675;
    Profile p4200 = poly_profile(
        {P(l13, -4), P(82, -4), P(128.1332, -1.006601), P(130.15, 0.122), P(130.15, 2)});
    Profile p4300;
    p4300.elems = {L(P(46, 2), P(46, 0)),
                   L(P(46, 0), P(89.978, 0)),
                   L(P(89.978, 0), P(91.978, -1)),
                   L(P(91.978, -1), P(91.978, -3.075)),
                   L(P(91.978, -3.075), P(95.978, -3.075)),
                   Arc(P(95.978, -3.075), P(105.978, -8.075), P(105.978, -3.075), false),
                   L(P(105.978, -8.075), P(136, -9.388292)),
                   L(P(136, -9.388292), P(136, -16)),
                   L(P(136, -16), P(200, -16))};
    Profile p5300;
    p5300.elems = {L(P(0, 2), P(0, 0)),
                   L(P(0, 0), P(96.0175, 0)),
                   Arc(P(96.0175, 0), P(106.0175, -5), P(106.0175, 0), false),
                   L(P(106.0175, -5), P(136, -6.973636)),
                   L(P(136, -6.973636), P(136, -16)),
                   L(P(136, -16), P(200, -16))};
    std::vector<Case> cases{
        {"%4200",
         p4200,
         {P(130.15, 2), P(l13, 2), P(l13, -4)},
         P(20, 10),
         args(-.5, .5, true, 1),
         true,
         1,
         -3.5},
        {"%7300",
         poly_profile({P(l3, 2), P(l3, -l9)}),
         {P(l3, 2), P(20, 2), P(20, -l9), P(l3, -l9)},
         P(20, 5),
         args(-.5, 0, true, 2),
         true,
         1,
         -l9},
        {"%4300",
         p4300,
         {P(200, -16), P(200, 2), P(46, 2)},
         P(210, 5),
         args(.5, .5, false, 2),
         false,
         1,
         23.5},
        {"%5300 face",
         p5300,
         {P(200, -16), P(200, 2), P(0, 2)},
         P(210, 5),
         args(.5, .5, false, 2),
         false,
         1,
         .5},
        {"%5300 counterbore",
         poly_profile({P(46, -2.925), P(92.0175, -2.925), P(92.0175, 2)}),
         {P(92.0175, 2), P(46, 2), P(46, -2.925)},
         P(46, 5),
         args(.5, .5, true, 1),
         true,
         1,
         -2.425},
        {"%5200",
         poly_profile({P(0, 0), P(82.0175, 0), P(136, -5.8575), P(136, -5.9575), P(200, -5.8575)}),
         {P(200, -5.8575), P(200, 2), P(0, 2), P(0, 0)},
         P(210, 5),
         args(.5, .5, false, 2),
         false,
         1,
         .5},
    };
    for (const Case& c : cases) {
        std::vector<Move> mv;
        ASSERT_TRUE(ok(g64(c.f, c.stock, c.tool, c.a, mv))) << c.name;
        EXPECT_FALSE(feeds(c.tool, mv).empty()) << c.name;
        EXPECT_TRUE(mv.back().to.isApprox(c.tool, 1e-12)) << c.name;
        // The counterbore of %5300 writes I.5 into its wall: roughed as written,
        // the translated profile is the part the passes must not enter.
        V2 t(c.a.k, c.a.i);
        EXPECT_EQ(c.a.allowance_inside, std::string(c.name) == "%5300 counterbore") << c.name;
        Oracle o(c.a.allowance_inside ? shifted(c.f, t) : c.f, c.stock,
                 c.a.allowance_inside ? V2(0, 0) : t);
        double step = c.a.has_p ? c.a.p : c.a.r;
        check_clear(o, c.tool, mv, std::min(1.0, step / 2), c.name);
        // Only the stock is material: the translated wall rises above it.
        Oracle stock_only(c.f, c.stock, t);
        check_cover(
            o, c.tool, mv, c.swap, c.s, step, c.low,
            [&](V2 q) { return c.a.allowance_inside && !in_polygon(stock_only.m, q); }, c.name);
        // The stock written the other way round gives the same passes.
        std::vector<V2> back(c.stock.rbegin(), c.stock.rend());
        std::vector<Move> mv2;
        ASSERT_EQ(g64(c.f, back, c.tool, c.a, mv2).code, 0) << c.name;
        ASSERT_EQ(mv2.size(), mv.size()) << c.name;
        for (size_t i = 0; i < mv.size(); ++i) EXPECT_TRUE(mv2[i].to.isApprox(mv[i].to, 1e-9));
    }
    // %4200 on a fresh start: L13 = L3-2 is read before %7300 sets L3, so the
    // profile starts at X-2, beyond the spindle axis: error 874.
    std::vector<Move> mv;
    Profile fresh = poly_profile({P(-2, -4), P(82, -4), P(130.15, -.878), P(130.15, 2)});
    EXPECT_EQ(
        g64(fresh, {P(130.15, 2), P(-2, 2), P(-2, -4)}, P(20, 10), args(-.5, .5, true, 1), mv).code,
        874);
}

namespace {
void check_walls(const Oracle& o, V2 tool, const std::vector<Move>& mv, const std::string& what);
}  // namespace

// Random stepped shafts (shoulders, cylinders and cones), roughed along Z and
// along X with random allowances and depths.
TEST(G64, RandomShaftsProperties) {
    std::mt19937 rng(20240613);
    std::uniform_real_distribution<double> u(0, 1);
    for (int n = 0; n < 40; ++n) {
        std::vector<V2> pts{V2(0, 30 + 10 * u(rng))};
        double z = 0, r = pts[0].y();
        int steps = 2 + int(u(rng) * 4);
        for (int k = 0; k < steps; ++k) {
            z += 3 + 10 * u(rng);
            pts.push_back(V2(z, r));
            double nr = r - 2 - 6 * u(rng);
            if (nr < 3) break;
            double dz = u(rng) < .4 ? 2 + 5 * u(rng) : 0;  // a cone or a shoulder
            z += dz;
            r = nr;
            pts.push_back(V2(z, r));
        }
        z += 3 + 5 * u(rng);
        pts.push_back(V2(z, r));
        pts.push_back(V2(z, u(rng) < .5 ? 0 : r / 3));  // the end face
        Profile f;
        for (size_t i = 0; i + 1 < pts.size(); ++i) f.elems.push_back(L(pts[i], pts[i + 1]));
        double top = pts[0].y() + 1 + 4 * u(rng);
        std::vector<V2> stock{V2(0, top), V2(z + 2, top), V2(z + 2, pts.back().y())};
        bool along_x = n % 2;
        G64Args a;
        a.i = .8 * u(rng), a.k = .8 * u(rng);
        double step = .7 + 2.5 * u(rng);
        std::vector<Move> mv;
        V2 tool(z + 30, top + 20);
        ASSERT_TRUE(ok(g64_called(f, stock, tool, a, along_x, step, mv))) << n;
        Oracle o(f, stock, V2(a.k, a.i));
        std::string name = "shaft " + std::to_string(n);
        double c = std::min(1.0, step / 2);
        check_clear(o, tool, mv, c, name.c_str());
        double low = 1e300;
        for (V2 p : pts) low = std::min(low, (along_x ? p.x() + a.k : p.y() + a.i));
        check_cover(o, tool, mv, along_x, 1, step, low, name.c_str());
        check_walls(o, tool, mv, name);
        // A stepped profile with paraxial allowances: nothing nearer than the
        // smaller allowance (shoulders get K, cylinders I, cones more).
        for (const Seg& s : feeds(tool, mv))
            for (int i = 0; i <= 20; ++i)
                EXPECT_GE(o.dist_f(s.a + (s.b - s.a) * (i / 20.0)), std::min(a.i, a.k) - 1e-6);
    }
}

// Issue 19 item 1: generated profiles, outside and bore, with and without a
// groove, along Z and along X, allowances of both signs. No move, feed or
// rapid, enters the part plus its allowance (translated as written when the
// allowance points into the part); without a groove the material is covered.
namespace {
int check_out_of_part(const Oracle& o, const std::vector<V2>& part, V2 tool,
                      const std::vector<Move>& mv, const std::string& what);
}  // namespace

TEST(G64, RandomGroovesBoresAndSigns) {
    std::mt19937 rng(20261125);
    std::uniform_real_distribution<double> u(0, 1);
    int inside = 0, tried = 0;
    for (int n = 0; n < 48; ++n) {
        const int variant = n % 4;  // 0 groove, 1 bore, 2 bore with a groove, 3 wrong sign
        const bool along_x = (n / 4) % 2, bore = variant == 1 || variant == 2;
        const bool groove = variant == 0 || variant == 2;
        std::vector<V2> pts{V2(0, 30 + 10 * u(rng))};
        double z = 0, r = pts[0].y();
        for (int k = 0, steps = 2 + int(u(rng) * 3); k < steps; ++k) {
            double len = 8 + 10 * u(rng);
            if (groove && k == 0 && r > 8) {  // a groove in the first cylinder
                double w = 2 + 2 * u(rng), depth = 1 + 2 * u(rng),
                       at = z + 3 + (len - w - 6) * u(rng);
                pts.push_back(V2(at, r));
                pts.push_back(V2(at, r - depth));
                pts.push_back(V2(at + w, r - depth));
                pts.push_back(V2(at + w, r));
            }
            z += len;
            pts.push_back(V2(z, r));
            double nr = r - 2 - 5 * u(rng);
            if (nr < 3) break;
            z += u(rng) < .4 ? 2 + 4 * u(rng) : 0;
            r = nr;
            pts.push_back(V2(z, r));
        }
        z += 3 + 5 * u(rng);
        pts.push_back(V2(z, r));
        pts.push_back(V2(z, r / 3));
        double top = pts[0].y() + 1 + 4 * u(rng);
        std::vector<V2> stock{V2(0, top), V2(z + 2, top), V2(z + 2, pts.back().y())};
        V2 tool(z + 30, top + 20);
        const int start = (n / 8) % 3;  // a bore's start: inside, in front outside it, beyond
        if (bore) {                     // the mirror r -> 50 - r: a stepped bore opening towards +Z
            for (V2& q : pts) q.y() = 50 - q.y();
            for (V2& q : stock) q.y() = 50 - q.y();
            // Issue 39 item 1: started in front of the face outside the bore,
            // a G64 rapided through the wall at the start's radius.
            double mouth = 0;
            for (const V2& q : pts) mouth = std::max(mouth, q.y());
            tool = V2(z + 30, start == 0 ? 2 : start == 1 ? mouth - 2 * u(rng) : 70);
        }
        Profile f;
        for (size_t i = 0; i + 1 < pts.size(); ++i) f.elems.push_back(L(pts[i], pts[i + 1]));
        G64Args a;
        a.k = .8 * u(rng);
        a.i = .1 + .7 * u(rng);
        if (bore || variant == 3) a.i = -a.i;  // the right sign on a bore; wrong outside
        double step = .8 + 2 * u(rng);
        std::vector<Move> mv;
        std::string name = "profile " + std::to_string(n) + (bore ? " bore" : " outside") +
                           (groove ? " groove" : "") + (along_x ? " R" : " P") +
                           (bore ? (start == 0   ? " from inside"
                                    : start == 1 ? " from the face"
                                                 : " from beyond")
                                 : "");
        ASSERT_TRUE(ok(g64_called(f, stock, tool, a, along_x, step, mv))) << name;
        ASSERT_FALSE(feeds(tool, mv).empty()) << name;
        EXPECT_EQ(a.allowance_inside, variant == 3) << name;
        V2 t(a.k, a.i);
        inside += a.allowance_inside;
        Oracle o(a.allowance_inside ? shifted(f, t) : f, stock, a.allowance_inside ? V2(0, 0) : t);
        check_clear(o, tool, mv, std::min(1.0, step / 2), name.c_str());
        std::vector<V2> part = pts;
        part.push_back(V2(pts.back().x(), bore ? 60 : -1));
        part.push_back(V2(pts.front().x(), bore ? 60 : -1));
        if (variant != 3) {
            // No rapid through the part itself, beyond the allowance zone.
            check_out_of_part(o, part, tool, mv, name);
            if (!groove) check_walls(o, tool, mv, name);
            // The same profile with no allowance: the allowance zone is then
            // empty, so the part itself is the oracle (closed far inside it).
            G64Args bare = a;
            bare.i = bare.k = 0;
            std::vector<Move> mz;
            ASSERT_TRUE(ok(g64_called(f, stock, tool, bare, along_x, step, mz)))
                << name << " with no allowance: ";
            check_out_of_part(Oracle(f, stock, V2(0, 0)), part, tool, mz,
                              name + " with no allowance");
        }
        if (groove || variant == 3) continue;
        ++tried;
        double low = 1e300;
        for (V2 q : pts)
            low = std::min(low, along_x ? q.x() + a.k : (bore ? -(q.y() + a.i) : q.y() + a.i));
        check_cover(o, tool, mv, along_x, bore && !along_x ? -1 : 1, step, low, name.c_str());
    }
    EXPECT_EQ(inside, 12);
    EXPECT_EQ(tried, 12);
}

// Issue 39 item 1: a counterbore Ø40 x 30 in a Ø20 bore, started at X44 Z2
// in front of the face, outside the bore: the rapids went 2 mm into the Ø40
// wall, both ways, and the wall was never roughed below Ø38. Every wall is
// now at its allowance, and nothing enters the part.
TEST(G64, CounterboreFromInFrontOfTheFace) {
    Profile f = poly_profile({P(40, 0), P(40, -30), P(20, -30)});
    std::vector<V2> stock{P(20, -30), P(20, 0), P(40, 0)};
    for (const V2& tool : {P(44, 2), P(50, 2), P(18, 2)}) {
        G64Args a;
        a.i = -.25, a.k = .25, a.has_p = true, a.p = 2;
        std::vector<Move> mv;
        ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
        const std::string name = "counterbore from X" + std::to_string(2 * tool.y());
        Oracle o(f, stock, V2(a.k, a.i));
        check_clear(o, tool, mv, 1, name.c_str());
        check_out_of_part(o, {P(40, 0), P(40, -30), P(20, -30), P(20, -60), P(120, -60), P(120, 0)},
                          tool, mv, name);
        check_walls(o, tool, mv, name);
        EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12)) << name;
    }
}

// Issue 39 items 1 and 2: profiles that are one wall (a bore's or a shaft's
// cylinder alone, %7300's H8 bore), roughed along X and along Z, started
// inside the bore, in front of the face outside it and beyond the part: the
// way out goes away from the wall (it climbed the finished wall at feed),
// no rapid enters the part, and the wall keeps its allowance.
TEST(G64, OneWallProfiles) {
    int runs = 0;
    for (bool bore : {true, false})
        for (bool along_x : {true, false})
            for (int start = 0; start < 3; ++start) {
                // The wall at r 20 from Z1 to Z-20; the stock's other side at r 10
                // (the drilled hole) or r 30 (the bar).
                const double other = bore ? 10 : 30;
                Profile f = poly_profile({V2(1, 20), V2(-20, 20)});
                std::vector<V2> stock{V2(1, 20), V2(1, other), V2(-20, other), V2(-20, 20)};
                const V2 tool = bore ? V2(5, start == 0   ? 9
                                             : start == 1 ? 22
                                                          : 40)
                                     : V2(5, start == 0   ? 32
                                             : start == 1 ? 18
                                                          : 50);
                if (!bore && start == 1) continue;  // outside, "in front below the bar" is the part
                G64Args a;
                a.i = bore ? -.3 : .3, a.k = 0;
                (along_x ? a.has_r : a.has_p) = true;
                (along_x ? a.r : a.p) = 2;
                std::vector<Move> mv;
                const std::string name = std::string(bore ? "bore" : "shaft") +
                                         (along_x ? " R" : " P") + " start " +
                                         std::to_string(start);
                ASSERT_TRUE(ok(g64(f, stock, tool, a, mv))) << name;
                ASSERT_FALSE(feeds(tool, mv).empty()) << name;
                Oracle o(f, stock, V2(a.k, a.i));
                check_clear(o, tool, mv, 1, name.c_str());
                std::vector<V2> part{V2(1, 20), V2(-20, 20), V2(-20, bore ? 60 : 0),
                                     V2(1, bore ? 60 : 0)};
                check_out_of_part(o, part, tool, mv, name);
                for (const Seg& s : feeds(tool, mv)) {
                    for (int i = 0; i <= 20; ++i) {
                        const V2 q = s.a + (s.b - s.a) * (i / 20.0);
                        if (q.x() < 1 - 1e-9 && q.x() > -20 + 1e-9) {
                            EXPECT_GE(std::fabs(q.y() - 20), .3 - 1e-6)
                                << name << ": a feed on the wall at " << q.transpose();
                        }
                    }
                }
                EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12)) << name;
                ++runs;
            }
    EXPECT_EQ(runs, 10);
}

// %7300 N250 (issue 39 item 2): G64 N220 N230 I-.5 R2 on the H8 bore's wall
// alone, L3 = 47.5195 and L9 = 14.6675: the last pass ends on the wall plus
// allowance and leaves it along Z at X46.5195, never on the Ø47.5195 wall.
TEST(G64, Cabestan7300KeepsItsAllowance) {
    const double l3 = 48 - .5 + .0195, l9 = 7.81 * 1.75 + 1;
    Profile f = poly_profile({P(l3, 2), P(l3, -l9)});
    std::vector<V2> stock{P(l3, 2), P(20, 2), P(20, -l9), P(l3, -l9)};
    G64Args a;
    a.i = -.5, a.has_r = true, a.r = 2;
    std::vector<Move> mv;
    const V2 tool = P(20, 5);
    ASSERT_TRUE(ok(g64(f, stock, tool, a, mv)));
    for (const Seg& s : segs(tool, mv)) {
        EXPECT_LE(s.b.y(), l3 / 2 - .5 + 1e-9)
            << "G" << s.g << " to X" << 2 * s.b.y() << " Z" << s.b.x();
    }
}

// Every G64 of the handbook programs, run by the interpreter with the programs
// that call them: no move, feed or rapid, enters the part plus its allowance
// (issue 19 item 1). A sweep of the whole handbook corpus, which lives beside
// the repository (PUPITRE_SHARED/programs): skipped without it.
TEST(G64, HandbookProgramsNeverEnterThePart) {
    const std::string dir = std::string(PUPITRE_SHARED) + "/programs/";
    if (!std::filesystem::exists(dir + "INDEX.tsv")) GTEST_SKIP() << "no " << dir;
    const std::vector<std::vector<std::string>> runs{
        {"000_p555_cycles_x.iso"},
        {"000_p555_cycles_z.iso"},
        {"000_p555_jauges.iso"},
        {"004_p555.iso"},
        {"000_p1_mandrin_outil.iso"},
        {"000_p2_mandrin_cone.iso"},
        {"000_bride_p38_femelle.iso"},
        {"000_bride_p38_male.iso"},
        {"000_bride_p39.iso"},
        {"000_cabestan_p4200.iso", "000_cabestan_p7300.iso"},
        {"000_cabestan_p5200.iso", "000_cabestan_p7300.iso"},
        {"000_cabestan_p4300.iso"},
        {"000_cabestan_p5300.iso"},
        {"000_palier_p11.iso", "000_palier_p123.iso", "000_palier_p2000.iso",
         "000_palier_p2001.iso"},
        {"000_palier_p12.iso", "000_palier_p123.iso", "000_palier_p2000.iso",
         "000_palier_p2001.iso"},
        {"000_palier_p13.iso", "000_palier_p123.iso", "000_palier_p2000.iso",
         "000_palier_p2001.iso"},
    };
    int seen = 0;
    for (const auto& files : runs) {
        MachineProfile m;
        builtin_machine("lathe", m);
        ProgramMemory mem;
        for (const std::string& f : files) {
            std::ifstream in(dir + f);
            std::stringstream text;
            text << in.rdbuf();
            mem.load_text(f, text.str());
        }
        RunOptions o;
        o.on_g64 = [&](const Profile& fin, const std::vector<V2>& stock, V2 tool, const G64Args& a,
                       const std::vector<Move>& mv) {
            ++seen;
            V2 t(a.k, a.i);
            Oracle oracle(a.allowance_inside ? shifted(fin, t) : fin, stock,
                          a.allowance_inside ? V2(0, 0) : t);
            double step = a.has_p ? a.p : a.r;
            check_clear(oracle, tool, mv, std::min(1.0, step / 2), files.front().c_str());
        };
        struct Quiet final : MachineSink {
        } sink;
        Interpreter interp(m, mem, sink, o);
        interp.start(mem.first());
        interp.run_to_end();
    }
    EXPECT_GE(seen, 14);
}

TEST(G64, Errors) {
    std::vector<Move> mv;
    G64Args a;
    EXPECT_EQ(g64(p555(), kStock555, P(200, 150), a, mv).code, 873);  // neither P nor R
    a.has_p = a.has_r = true, a.p = a.r = 2;
    EXPECT_EQ(g64(p555(), kStock555, P(200, 150), a, mv).code, 889);  // both
    a.has_r = false, a.p = 0;
    EXPECT_EQ(g64(p555(), kStock555, P(200, 150), a, mv).code, 873);  // P0
    a.p = 2;
    EXPECT_EQ(g64(Profile{}, kStock555, P(200, 150), a, mv).code, 871);
    Profile broken = p555();
    broken.elems.erase(broken.elems.begin() + 3);
    EXPECT_EQ(g64(broken, kStock555, P(200, 150), a, mv).code, 871);  // not continuous
    EXPECT_EQ(g64(p555(), {}, P(200, 150), a, mv).code, 872);
    // A stock that crosses the profile, a profile beyond the axis (%100's
    // printed X-40), a stock that encloses nothing.
    EXPECT_EQ(
        g64(p555(), {P(144, 0), P(144, 10), P(40, 20), P(40, 94), P(0, 94)}, P(200, 150), a, mv)
            .code,
        874);
    EXPECT_EQ(g64(poly_profile({P(30, -20), P(-40, -25), P(40, -45)}), {P(30, -20), P(50, -45)},
                  P(200, 150), a, mv)
                  .code,
              874);
    EXPECT_EQ(
        g64(poly_profile({P(40, 0), P(40, 50)}), {P(40, 0), P(40, 50)}, P(200, 150), a, mv).code,
        874);
    EXPECT_TRUE(mv.empty());
}

// ---------------------------------------------------------------- G65 ----

// %555 groove (000:2593-2612, checked by hand): from X62 Z50, EA-135 P2 Z20
// I.5 K.2. The infeed line r = z - 19 runs parallel to the translated flank
// and meets the translated bottom at C (Z39.5, r 20.5); passes at r 29 ... 20.5
// from the EA line to the translated left flank, the limit Z20 never reached.
TEST(G65, P555Groove) {
    G65Args a;
    a.has_z = true, a.z = 20, a.has_p = true, a.p = 2, a.i = .5, a.k = .2, a.has_ea = true,
    a.ea = -135;
    std::vector<Move> mv;
    V2 tool = P(62, 50);
    ASSERT_TRUE(ok(g65(p555(), tool, a, mv)));
    std::vector<Seg> f = feeds(tool, mv);
    const double lv[] = {29, 27, 25, 23, 21, 20.5};
    ASSERT_EQ(f.size(), 12u);
    V2 e = tool;
    for (int k = 0; k < 6; ++k) {
        const Seg& in = f[2 * k];
        const Seg& cut = f[2 * k + 1];
        EXPECT_TRUE(in.infeed && !cut.infeed);
        EXPECT_TRUE(in.a.isApprox(e, 1e-9)) << k;  // from the previous infeed point
        e = V2(lv[k] + 19, lv[k]);                 // on the EA line
        EXPECT_TRUE(in.b.isApprox(e, 1e-9)) << k << ": " << in.b.transpose();
        EXPECT_NEAR(cut.b.y(), lv[k], 1e-9);
        EXPECT_NEAR(cut.b.x(), 20.2 + 30.5 - lv[k] - (lv[k] < 20.5 + 1e-9 ? 0 : 0), 1e-9) << k;
    }
    EXPECT_TRUE(f.back().a.isApprox(V2(39.5, 20.5), 1e-9));  // C
    // Each level: retract 1 mm, back along Z over the infeed point, down onto it;
    // at the end up to r 31, then back to Z50.
    EXPECT_TRUE(mv[2].to.isApprox(V2(21.7, 30), 1e-9));
    EXPECT_TRUE(mv[3].to.isApprox(V2(48, 30), 1e-9));
    EXPECT_TRUE(mv[4].to.isApprox(V2(48, 29), 1e-9));
    EXPECT_TRUE(mv[mv.size() - 2].to.isApprox(V2(39.5, 31), 1e-9));
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
    // Without allowance the line meets N150 (Ø40) at Z39 (by hand).
    a.i = a.k = 0;
    ASSERT_TRUE(ok(g65(p555(), tool, a, mv)));
    f = feeds(tool, mv);
    EXPECT_TRUE(f[f.size() - 2].b.isApprox(P(40, 39), 1e-9));
    Oracle o(p555(), kStock555, V2(.2, .5));
    a.i = .5, a.k = .2;
    ASSERT_EQ(g65(p555(), tool, a, mv).code, 0);
    check_clear(o, tool, mv, 1, "G65 %555");
    EXPECT_FALSE(a.allowance_inside);
    // I-.5 on this outside groove points into its bottom: roughed as written,
    // the last level is r 19.5, 0.5 below the Ø40 bottom (warning 1116).
    a.i = -.5;
    ASSERT_TRUE(ok(g65(p555(), tool, a, mv)));
    EXPECT_TRUE(a.allowance_inside);
    double low = 1e300;
    for (const Seg& s : feeds(tool, mv)) low = std::min(low, s.b.y());
    EXPECT_NEAR(low, 19.5, 1e-9);
    Oracle moved(shifted(p555(), V2(.2, -.5)), kStock555, V2(0, 0));
    check_clear(moved, tool, mv, 1, "G65 %555 I-.5");
}

// S4's %555 (004:1389-1434): G0 X52 Z55, G65 N1100 N1000 EA-160.201 P2 Z0 I1 K0.5.
// The EA line (slope 0.36) is parallel to the cone X50 Z55 - X32 Z30; the limit
// Z0 stops the passes above the translated face, the face stops those below.
TEST(G65, S4Groove) {
    Profile f = reversed(
        poly_profile({P(0, 100), P(40, 100), P(40, 75), P(50, 75), P(50, 55), P(32, 30), P(32, 0),
                      P(44, 0), P(60, -8), P(60, -14), P(65, -14), P(65, -17), P(80, -17)}));
    G65Args a;
    a.has_z = true, a.z = 0, a.has_p = true, a.p = 2, a.i = 1, a.k = .5, a.has_ea = true,
    a.ea = -160.201;
    std::vector<Move> mv;
    V2 tool = P(52, 55);
    ASSERT_TRUE(ok(g65(f, tool, a, mv)));
    std::vector<Seg> s = feeds(tool, mv);
    ASSERT_EQ(s.size(), 10u);
    const double lv[] = {24, 22, 20, 18, 17};
    const double ez[] = {49.444482, 43.888964, 38.333446, 32.777928, 30.000169};
    const double tz[] = {0, .5, .5, .5, .5};
    for (int k = 0; k < 5; ++k) {
        EXPECT_TRUE(s[2 * k].b.isApprox(V2(ez[k], lv[k]), 1e-5))
            << k << ": " << s[2 * k].b.transpose();
        EXPECT_TRUE(s[2 * k + 1].b.isApprox(V2(tz[k], lv[k]), 1e-9)) << k;
    }
    Oracle o(f, {P(80, -17), P(80, 105), P(40, 105)}, V2(.5, 1));
    check_clear(o, tool, mv, 1, "G65 S4");
}

// A frontal groove in a face (X with R): passes along X at levels stepping down
// Z, from an infeed line almost along -Z towards the inner wall.
TEST(G65, FaceGroove) {
    Profile f = poly_profile({P(80, 0), P(60, 0), P(60, -5), P(40, -5), P(40, 0), P(20, 0)});
    G65Args a;
    a.has_x = true, a.x = 8, a.has_r = true, a.r = 2, a.k = .3, a.has_ea = true, a.ea = -175;
    std::vector<Move> mv;
    V2 tool = P(58, 2);
    ASSERT_TRUE(ok(g65(f, tool, a, mv)));
    std::vector<Seg> s = feeds(tool, mv);
    ASSERT_EQ(s.size(), 8u);  // levels Z0, Z-2, Z-4 and K.3 off the bottom, Z-4.7
    const double lv[] = {0, -2, -4, -4.7};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(s[2 * k].b.x(), lv[k], 1e-9);
        EXPECT_NEAR(s[2 * k].b.y(), 29 - (2 - lv[k]) * std::tan(5 * kPi / 180), 1e-9);
        EXPECT_NEAR(s[2 * k + 1].b.y(), 20, 1e-9);  // the inner wall X40, no I
        EXPECT_NEAR(s[2 * k + 1].b.x(), lv[k], 1e-9);
    }
    Oracle o(f, {P(80, 2), P(20, 2)}, V2(.3, 0));
    check_clear(o, tool, mv, 1, "G65 face");
}

TEST(G65, Errors) {
    std::vector<Move> mv;
    G65Args a;
    a.has_ea = true, a.ea = -135, a.has_p = true, a.p = 2;
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 862);  // P without Z
    a.has_x = true, a.x = 10;
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 862);  // P with X
    a.has_z = true, a.z = 20;
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 889);  // X and Z
    a.has_x = false, a.has_r = true;
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 889);  // P and R
    a.has_r = false, a.has_ea = false;
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 2);  // no EA
    a.has_ea = true;
    EXPECT_EQ(g65(Profile{}, P(62, 50), a, mv).code, 871);
    a.z = 60;  // the limit behind the start, away from where EA leads
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 863);
    a.z = 20, a.ea = 180;  // along the passes
    EXPECT_EQ(g65(p555(), P(62, 50), a, mv).code, 863);
    a.ea = -135, a.i = .5, a.k = .2;
    EXPECT_EQ(g65(p555(), P(62, 150), a, mv).code, 875);     // the line misses the profile
    EXPECT_EQ(g65(p555(), P(40.6, 39.8), a, mv).code, 875);  // the start within the allowance
    EXPECT_TRUE(mv.empty());
}

// ------------------------------------------- G65, G63: issue 19 item 1 ----

namespace {
// A profile generated in a frame where the passes run along x, the levels step
// down y and the part lies below the profile, and its map to (z, r): axial
// (x = ±z, y = r, or 60 - r for a bore) or frontal (x = r, y = ±z).
struct FrameMap {
    bool frontal = false, bore = false;
    double sx = 1, sy = 1;
    V2 operator()(V2 p) const {
        if (frontal) return V2(sy * p.y(), sx > 0 ? 10 + p.x() : 120 - p.x());
        return V2(sx * p.x(), bore ? 60 - p.y() : p.y());
    }
    // The linear part (allowances, directions).
    V2 dir(V2 v) const { return (*this)(v) - (*this)(V2(0, 0)); }
    bool flips() const {  // orientation reversed
        V2 a = dir(V2(1, 0)), b = dir(V2(0, 1));
        return a.x() * b.y() - a.y() * b.x() < 0;
    }
};

// The n-th of the generated frames: outside or bore, frontal or not, each
// way along the passes (n / 7: the shape is n % 7).
FrameMap frame_of(int n) {
    FrameMap map;
    map.frontal = (n / 7) % 2;
    map.bore = !map.frontal && (n / 14) % 2;
    map.sx = (n / 28) % 2 ? -1 : 1;
    map.sy = map.frontal && (n / 14) % 2 ? -1 : 1;
    return map;
}

// A profile through frame points; arcs given as (end, centre, ccw in the frame).
struct FramePath {
    std::vector<V2> pts{};  // densified, for the part polygon
    Profile f{};
    const FrameMap* m = nullptr;
    V2 cur{0, 0};
    void start(V2 p) { cur = p, pts = {p}; }
    void line(V2 p) {
        f.elems.push_back(L((*m)(cur), (*m)(p)));
        pts.push_back(p);
        cur = p;
    }
    void arc(V2 p, V2 c, bool ccw) {
        f.elems.push_back(Arc((*m)(cur), (*m)(p), (*m)(c), ccw != m->flips()));
        double r = (cur - c).norm(), a0 = std::atan2(cur.y() - c.y(), cur.x() - c.x());
        double s = std::atan2(p.y() - c.y(), p.x() - c.x()) - a0;
        if (ccw && s <= 0) s += 2 * kPi;
        if (!ccw && s >= 0) s -= 2 * kPi;
        for (int i = 1; i <= 2000; ++i)
            pts.push_back(c + r * V2(std::cos(a0 + s * i / 2000), std::sin(a0 + s * i / 2000)));
        pts.back() = p;
        cur = p;
    }
    // The part: the profile closed far below its ends (frame), in (z, r).
    std::vector<V2> part(double below) const {
        std::vector<V2> out;
        for (V2 p : pts) out.push_back((*m)(p));
        out.push_back((*m)(V2(pts.back().x(), below)));
        out.push_back((*m)(V2(pts.front().x(), below)));
        return out;
    }
};

std::vector<V2> shifted_pts(std::vector<V2> v, V2 t) {
    for (V2& p : v) p += t;
    return v;
}

// No move, feed or rapid, of a cycle with no stock (G65, G63) comes deeper
// than 0.1 µm into the part (the polygon `part`) or into the
// allowance zone of the oracle (swept band or normal allowance).
// Every wall roughed down to its allowance (issue 39): each point of the
// profile plus allowance that the stock covers and no groove hides is met by
// a feed move within 1 µm, and no feed move comes nearer the finished profile
// than a quarter of the smaller allowance (none cuts a wall to size: a cone
// under a paraxial allowance keeps less than either of its components).
void check_walls(const Oracle& o, V2 tool, const std::vector<Move>& mv, const std::string& what) {
    const std::vector<Seg> fs = feeds(tool, mv);
    int far = 0, near = 0;
    const double least = std::min(std::fabs(o.t.x()), std::fabs(o.t.y()));
    for (const Seg& s : fs)
        for (int i = 0; i <= 20; ++i)
            if (o.dist_f(s.a + (s.b - s.a) * (i / 20.0)) < least / 4 - 1e-6 && ++near <= 2)
                ADD_FAILURE() << what << ": a feed nearer the profile than the allowance at "
                              << (s.a + (s.b - s.a) * (i / 20.0)).transpose();
    for (const Elem& e : o.fe) {
        for (int k = 1; k < 20; ++k) {
            const V2 q = e.a + (e.b - e.a) * (k / 20.0) + o.t;
            bool corner = false;  // near a closing segment: the swept corner
            for (auto [a, b] : o.closing) corner = corner || seg_point(q, a, b) < o.t.norm() + 1e-3;
            if (corner || !o.in_M(q, 0)) continue;
            double best = 1e300;
            for (const Seg& s : fs) best = std::min(best, seg_point(q, s.a, s.b));
            if (best > 1e-3 && ++far <= 2)
                ADD_FAILURE() << what << ": the wall at Z" << q.x() << " r" << q.y() << " is left "
                              << best << " above its allowance";
        }
    }
    EXPECT_EQ(far + near, 0) << what;
}
int check_out_of_part(const Oracle& o, const std::vector<V2>& part, V2 tool,
                      const std::vector<Move>& mv, const std::string& what) {
    int bad = 0;
    for (const Seg& s : segs(tool, mv)) {
        int n = std::max(50, int((s.b - s.a).norm() / 0.02));
        for (int i = 0; i <= n; ++i) {
            V2 q = s.a + (s.b - s.a) * (double(i) / n);
            // Deeper than 0.1 µm, measured on the exact profile (the polygon's
            // chords cut arcs by less than that).
            bool in_part =
                in_polygon(part, q) && polyline_dist(part, q, true) > 1e-6 && o.dist_f(q) > 1e-4;
            if ((in_part || o.in_A(q)) && ++bad <= 2)
                ADD_FAILURE() << what << ": G" << s.g
                              << (in_part ? " in the part" : " in the allowance") << " at Z"
                              << q.x() << " r" << q.y() << " on " << s.a.transpose() << " -> "
                              << s.b.transpose();
        }
    }
    EXPECT_EQ(bad, 0) << what << ": points inside the profile plus allowance";
    return bad;
}

const char* kGrooveShapes[] = {"square", "trapezoid", "round",    "stepped",
                               "ridge",  "dovetail",  "chamfered"};

// A groove of shape k in a land at height H, from x1 to x2 (frame).
void groove(FramePath& p, int k, double x1, double x2, double H, double h, double u1, double u2) {
    double w = x2 - x1, xm = x1 + w * (.35 + .3 * u1);
    switch (k) {
        case 0:
            p.line(V2(x1, H - h)), p.line(V2(x2, H - h));
            break;
        case 1:
            p.line(V2(x1 + w / 3 * u1, H - h)), p.line(V2(x2 - w / 3 * u2, H - h));
            break;
        case 2: {  // straight walls down to an arc bottom (a half circle at most)
            double h0 = std::max(0.0, h - w / 2) * u1, yc = H - h0;
            double r = w / 2, sag = std::min(r, h - h0 + 1e-9);
            if (h0 > 0) p.line(V2(x1, yc));
            // A circle through both walls' feet, its lowest point `sag` below them.
            double R = (r * r + sag * sag) / (2 * sag);
            p.arc(V2(x2, yc), V2((x1 + x2) / 2, yc - sag + R), true);
            break;
        }
        case 3:
            if (u2 < .5)
                p.line(V2(x1, H - h)), p.line(V2(xm, H - h)), p.line(V2(xm, H - h / 2)),
                    p.line(V2(x2, H - h / 2));
            else
                p.line(V2(x1, H - h / 2)), p.line(V2(xm, H - h / 2)), p.line(V2(xm, H - h)),
                    p.line(V2(x2, H - h));
            break;
        case 4:
            p.line(V2(x1, H - h)), p.line(V2(xm - 1, H - h)),
                p.line(V2(xm - 1, H - h / 2 * (1 + u2))), p.line(V2(xm + 1, H - h / 2 * (1 + u2))),
                p.line(V2(xm + 1, H - h)), p.line(V2(x2, H - h));
            break;
        case 5:
            p.line(V2(x1 - h / 2 * u1, H - h)), p.line(V2(x2 + h / 2 * u2, H - h));
            break;
        default:  // 45° chamfers at the groove's edges
            p.line(V2(x1 + .8, H - .8)), p.line(V2(x1 + .8, H - h)), p.line(V2(x2 - .8, H - h)),
                p.line(V2(x2 - .8, H - .8));
            break;
    }
    p.line(V2(x2, H));
}
}  // namespace

// A dovetail groove (both walls undercut by 1 mm over its 4 mm depth): the
// passes under the far overhang stop where it leaves less than the clearance
// above them, those under the near one start where it leaves it, and the way
// out goes back along the infeeds: no retract, return or exit rapid enters
// the part (issue 19 item 1; before, the retracts rose into the far overhang
// and the exit into the near one). And a round bottom without allowance whose
// EA line meets its far side: no pass runs from that point into the part.
TEST(G65, UndercutWallsAndRoundBottom) {
    Profile f = poly_profile({P(60, 0), P(60, 10), P(52, 9), P(52, 21), P(60, 20), P(60, 30)});
    std::vector<V2> part{P(60, 0),  P(60, 10), P(52, 9),   P(52, 21),
                         P(60, 20), P(60, 30), P(-60, 30), P(-60, 0)};
    G65Args a;
    a.has_z = true, a.z = 5, a.has_p = true, a.p = 1.5, a.i = .3, a.k = .2, a.has_ea = true,
    a.ea = -100;
    std::vector<Move> mv;
    V2 tool = P(64, 18);
    ASSERT_TRUE(ok(g65(f, tool, a, mv)));
    Oracle o(f, {tool}, V2(.2, .3));
    check_out_of_part(o, part, tool, mv, "dovetail");
    double low = 1e300;
    for (const Seg& s : feeds(tool, mv)) low = std::min(low, s.b.y());
    EXPECT_NEAR(low, 26.3, 1e-9);  // the bottom is roughed, I.3 above it
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
    // A half-round bottom R4 under a Ø62 land, the EA line from X70 Z18 at
    // -135° meeting the arc's left half at r ~28.2.
    Profile r;
    r.elems = {L(P(62, 0), P(62, 10)), Arc(P(62, 10), P(62, 18), P(62, 14), true),
               L(P(62, 18), P(62, 30))};
    std::vector<V2> rpart = densify(r);
    rpart.push_back(P(-60, 30)), rpart.push_back(P(-60, 0));
    a = G65Args{};
    a.has_z = true, a.z = 5, a.has_p = true, a.p = 1.3, a.has_ea = true, a.ea = -135;
    tool = P(70, 18);
    ASSERT_TRUE(ok(g65(r, tool, a, mv)));
    Oracle ro(r, {tool}, V2(0, 0));
    check_out_of_part(ro, rpart, tool, mv, "round bottom");
}

// %555's groove with the start point moved beyond its right flank, X62 Z55:
// the EA line (r = z - 24) meets the translated Ø60 land first, at Z54.5.
// The zone is bounded by the profile from there (000:2605-2612), so below
// the land each pass starts where its level leaves the part plus allowance,
// on the translated flank r = z - 19.7 (before, the cycle found its start
// inside the part at every level and ran nothing at all).
TEST(G65, StartBeyondTheWall) {
    G65Args a;
    a.has_z = true, a.z = 20, a.has_p = true, a.p = 2, a.i = .5, a.k = .2, a.has_ea = true,
    a.ea = -135;
    std::vector<Move> mv;
    V2 tool = P(62, 55);
    Profile f = poly_profile({P(60, 10), P(60, 20), P(40, 30), P(40, 40), P(60, 50), P(60, 60)});
    ASSERT_TRUE(ok(g65(f, tool, a, mv)));
    std::vector<Seg> s = feeds(tool, mv);
    ASSERT_FALSE(s.empty());
    double low = 1e300;
    int on_flank = 0;
    for (const Seg& g : s) {
        low = std::min(low, g.b.y());
        if (!g.infeed && g.a.y() < 30 && std::fabs(g.a.x() - (g.a.y() + 19.7)) < 1e-6) ++on_flank;
    }
    EXPECT_NEAR(low, 20.5, 1e-9);  // the translated bottom
    EXPECT_GE(on_flank, 4);        // levels 29, 27, 25, 23, 21 (and 20.5)
    std::vector<V2> part = densify(f);
    part.push_back(P(-60, 60)), part.push_back(P(-60, 10));
    Oracle o(f, {tool}, V2(.2, .5));
    check_out_of_part(o, part, tool, mv, "G65 beyond the wall");
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
}

// A square groove whose start point lies beyond its near wall, K pointing into
// that wall (the face takes no allowance): the EA line meets the land, so each
// level is reached along the last one and down the wall's face. Every level
// of P2 is cut (before, the way down the face counted as entering the part,
// the levels X58 and X54 were skipped and the bottom was cut in one pass 5 mm
// deep).
TEST(G65, StartBeyondASquareWall) {
    Profile f =
        poly_profile({P(60, 0), P(60, -10), P(50, -10), P(50, -20), P(60, -20), P(60, -30)});
    G65Args a;
    a.has_z = true, a.z = -20, a.has_p = true, a.p = 2, a.i = .5, a.k = .2, a.has_ea = true,
    a.ea = -135;
    std::vector<Move> mv;
    V2 tool = P(62, -5);
    ASSERT_TRUE(ok(g65(f, tool, a, mv)));
    std::vector<double> levels;
    for (const Seg& s : feeds(tool, mv))
        if (!s.infeed) levels.push_back(s.a.y());
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_NEAR(levels[0], 29, 1e-9);
    EXPECT_NEAR(levels[1], 27, 1e-9);
    EXPECT_NEAR(levels[2], 25.5, 1e-9);  // the bottom, I.5 above it
    std::vector<V2> part = densify(f);
    part.push_back(P(-60, -30)), part.push_back(P(-60, 0));
    Oracle o(f, {tool}, V2(.2, .5));
    check_out_of_part(o, part, tool, mv, "G65 beyond a square wall");
}

// Generated grooves of seven shapes (square, sloped walls, round bottom,
// stepped, a ridge, undercut walls, chamfered edges), axial (P) and frontal
// (R), outside and bore, cut towards both ends, allowances of both signs
// (a wrong I is roughed as written), start points over the groove or beyond
// its wall, EA from 25° to 90° off the passes: no move of G65, feed or rapid,
// enters the part plus its allowance; no feed passes the limit.
TEST(G65, GeneratedGroovesNeverEnterThePart) {
    std::mt19937 rng(20261126);
    std::uniform_real_distribution<double> u(0, 1);
    int runs = 0, inside = 0, failing = 0, idle = 0;
    for (int n = 0; n < 224; ++n) {
        const int shape = n % 7;
        const FrameMap map = frame_of(n);
        const bool wrong = (n / 56) % 4 == 3;
        double H = 30 + 8 * u(rng), x1 = 8 + 5 * u(rng), w = 6 + 8 * u(rng), h = 2 + 6 * u(rng);
        double x2 = x1 + w, Lx = x2 + 10;
        FramePath p;
        p.m = &map;
        p.start(V2(0, H));
        p.line(V2(x1, H));
        groove(p, shape, x1, x2, H, h, u(rng), u(rng));
        p.line(V2(Lx, H));
        // The profile called as written or backwards.
        Profile f = u(rng) < .5 ? p.f : reversed(p.f);
        V2 S(x2 - w / 4 + (w / 4 + 3) * u(rng), H + .5 + 3 * u(rng));
        double phi = (25 + 65 * u(rng)) * kPi / 180;
        V2 ea = map.dir(V2(-std::cos(phi), -std::sin(phi)));
        double xa = x1 - 3 + 4 * u(rng);
        // The allowance in the frame: along the passes either way, off the part
        // (or into it: a wrong I).
        V2 ty((u(rng) < .5 ? -1 : 1) * .6 * u(rng), (wrong ? -1 : 1) * (.1 + .6 * u(rng)));
        V2 t = map.dir(ty);
        G65Args a;
        if (map.frontal) {
            a.has_x = a.has_r = true, a.x = map(V2(xa, 0)).y(), a.r = .7 + 2 * u(rng);
        } else {
            a.has_z = a.has_p = true, a.z = map(V2(xa, 0)).x(), a.p = .7 + 2 * u(rng);
        }
        a.k = t.x(), a.i = t.y(), a.has_ea = true;
        a.ea = std::atan2(ea.y(), ea.x()) * 180 / kPi;
        V2 tool = map(S);
        std::string name = "groove " + std::to_string(n) + " " + kGrooveShapes[shape] +
                           (map.frontal ? " R" : " P") + (map.bore ? " bore" : "") +
                           (map.sx < 0 ? " mirrored" : "") + (wrong ? " wrong I" : "") + " EA" +
                           std::to_string(a.ea);
        std::vector<Move> mv;
        Error e = g65(f, tool, a, mv);
        if (e.code == 875) continue;  // the EA line passes the groove (a start beyond the wall)
        ASSERT_TRUE(ok(e)) << name;
        ++runs;
        idle += feeds(tool, mv).size() < 2;
        inside += a.allowance_inside;
        EXPECT_EQ(a.allowance_inside, wrong) << name;
        std::vector<V2> part = p.part(-20);
        Oracle o(a.allowance_inside ? shifted(f, t) : f, {tool}, a.allowance_inside ? V2(0, 0) : t);
        if (check_out_of_part(o, a.allowance_inside ? shifted_pts(part, t) : part, tool, mv, name))
            ++failing;
        for (const Seg& s : feeds(tool, mv)) {
            double lim = map.frontal ? a.x : a.z;
            auto along = [&](V2 q) { return map.frontal ? q.y() : q.x(); };
            double sgn = map.sx;  // the limit lies towards -x in the frame
            EXPECT_GE(sgn * (along(s.b) - lim), -1e-6) << name;
        }
    }
    EXPECT_EQ(failing, 0);
    EXPECT_GE(runs, 180);
    EXPECT_GE(inside, 20);
    // Every groove gets its passes, those whose start point lies beyond a
    // square wall that takes no allowance included: the way down to each
    // level slides along the wall's face, which touches the part without
    // entering it (before, seg_clear counted it as entering, and 3 of 224
    // grooves were left uncut).
    EXPECT_EQ(idle, 0);
}

// A dovetail groove in a Ø60 land, entered with EB150 and ER.4: each pass in
// it ends where its retract by the clearance stays clear of the overhang and
// of ER's rounded corners, and the groove is entered only where the climb out
// at that end is clear (issue 19 item 1; before, the retracts rose into the
// overhang's allowance).
TEST(G63, DovetailGrooveRetractsStayClear) {
    Profile f = poly_profile(
        {P(60, 0), P(60, 3), P(54, 2.5), P(54, 10), P(60, 9), P(60, 20), P(50, 20), P(50, 30)});
    std::vector<V2> part = densify(f);
    part.push_back(P(-60, 30)), part.push_back(P(-60, 0));
    G63Args a;
    a.has_x = a.has_z = true, a.x = 32, a.z = 31, a.has_p = true, a.p = 1.5, a.has_ez = true,
    a.ez = 0, a.has_eu = true, a.eu = 25, a.has_eb = true, a.eb = 150, a.er = .4;
    std::vector<Move> mv;
    V2 tool = P(72, 35);
    ASSERT_TRUE(ok(g63(f, tool, a, mv)));
    Oracle o(f, {tool}, V2(0, 0));
    o.er = .4;
    check_out_of_part(o, part, tool, mv, "G63 dovetail");
    int in_groove = 0;
    for (const Seg& s : feeds(tool, mv)) in_groove += s.b.y() < 30 - 1e-9 && s.b.x() < 9;
    EXPECT_GT(in_groove, 0);  // the groove is still roughed
}
// Generated profiles for G63: a land with a groove of each shape (or none),
// then one to three steps down (shoulders or cones) with a second groove half
// the time, axial (P, EZ, EU) and frontal (R, EX, EW), outside and bore, cut
// towards both ends, ER from 0 to 0.6 and EB from 60° to 150°: no move, feed
// or rapid, enters the part plus ER; the feeds stay above the last level.
TEST(G63, GeneratedProfilesNeverEnterThePart) {
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> u(0, 1);
    int failing = 0, entered = 0;
    const char* shapes[] = {"plain",   "square", "trapezoid", "round",
                            "stepped", "ridge",  "dovetail"};
    for (int n = 0; n < 112; ++n) {
        const int shape = n % 7;
        const FrameMap map = frame_of(n);
        FramePath p;
        p.m = &map;
        double Y0 = 30 + 8 * u(rng), y = Y0, x = 0;
        p.start(V2(0, Y0));
        for (int k = 0, steps = 1 + int(u(rng) * 3); k <= steps; ++k) {
            double len = 6 + 6 * u(rng);
            int gs = k == 0 ? shape : (u(rng) < .5 && shape ? 1 + int(u(rng) * 6) : 0);
            if (gs) {
                double x1 = x + 2 + 2 * u(rng), w = 4 + 4 * u(rng), h = 1.5 + 3 * u(rng);
                p.line(V2(x1, y));
                groove(p, gs - 1, x1, x1 + w, y, h, u(rng), u(rng));
                x = x1 + w;
            }
            x += len;
            p.line(V2(x, y));
            if (k == steps) break;
            double ny = y - 2 - 4 * u(rng);
            x += u(rng) < .4 ? 2 + 3 * u(rng) : 0;
            y = ny;
            p.line(V2(x, y));
        }
        const double y_u = y;
        V2 D(x + 1 + 2 * u(rng), Y0 + .5 + 2 * u(rng));
        V2 tool = map(D + V2(4, 4));
        G63Args a;
        double step = .8 + 2 * u(rng);
        V2 dz = map(D);
        a.has_x = a.has_z = true, a.x = dz.y(), a.z = dz.x();
        if (map.frontal) {
            a.has_r = a.has_ex = a.has_ew = true, a.r = step, a.ex = map(V2(0, 0)).y(),
            a.ew = map(V2(0, y_u)).x();
        } else {
            a.has_p = a.has_ez = a.has_eu = true, a.p = step, a.ez = map(V2(0, 0)).x(),
            a.eu = map(V2(0, y_u)).y();
        }
        a.er = n % 5 == 0 ? 0 : .1 + .5 * u(rng);
        a.has_eb = true, a.eb = 60 + 90 * u(rng);
        Profile f = u(rng) < .5 ? p.f : reversed(p.f);
        std::string name = "profile " + std::to_string(n) + " " + shapes[shape] +
                           (map.frontal ? " R" : " P") + (map.bore ? " bore" : "") +
                           (map.sx < 0 ? " mirrored" : "") + " ER" + std::to_string(a.er) + " EB" +
                           std::to_string(a.eb);
        std::vector<Move> mv;
        ASSERT_TRUE(ok(g63(f, tool, a, mv))) << name;
        ASSERT_FALSE(feeds(tool, mv).empty()) << name;
        Oracle o(f, {tool}, V2(0, 0));
        o.er = a.er;
        if (check_out_of_part(o, p.part(-20), tool, mv, name)) ++failing;
        // Issue 39 item 5: with no groove, every wall, land and cone is left
        // at ER by the last pass along the profile plus ER: each point at ER
        // from the profile on the material's side, away from its corners and
        // its ends, lies on a feed move.
        if (shape == 0 && a.er > 0) {
            const std::vector<V2> part = p.part(-20);
            const std::vector<Seg> fs = feeds(tool, mv);
            int left = 0;
            for (const Elem& e : f.elems) {
                if (e.arc) continue;
                const V2 t = (e.b - e.a).normalized(), nrm(-t.y(), t.x());
                for (int k = 1; k < 10; ++k) {
                    const V2 on = e.a + (e.b - e.a) * (k / 10.0);
                    if ((on - e.a).norm() < a.er + .1 || (on - e.b).norm() < a.er + .1) continue;
                    V2 q = on + a.er * nrm;
                    if (in_polygon(part, q)) q = on - a.er * nrm;
                    double best = 1e300;
                    for (const Seg& sg : fs) best = std::min(best, seg_point(q, sg.a, sg.b));
                    if (best > 1e-3 && ++left <= 2)
                        ADD_FAILURE() << name << ": the profile at " << on.transpose()
                                      << " is left " << best << " above ER";
                }
            }
            failing += left > 0;
        }
        for (const Seg& s : feeds(tool, mv)) {
            entered += s.infeed;
            V2 lv = map.dir(V2(0, 1));
            EXPECT_GE(s.b.dot(lv) - map(V2(0, y_u)).dot(lv), -1e-6) << name;
        }
    }
    EXPECT_EQ(failing, 0);
    EXPECT_GT(entered, 20);
}

// Every G65, G63 and G66 of the handbook programs (a corpus sweep), run by
// the interpreter: no move enters the part plus its allowance (issue 19 item
// 1). The part is the profile closed far away on the side the infeed (G65)
// or the levels (G63) go to; G66 stays inside the groove it is given.
TEST(G65, HandbookProgramsNeverEnterThePart) {
    const std::string dir = std::string(PUPITRE_SHARED) + "/programs/";
    if (!std::filesystem::exists(dir + "INDEX.tsv")) GTEST_SKIP() << "no " << dir;
    const std::vector<std::string> runs{"000_p555_cycles_x.iso", "000_p555_cycles_z.iso",
                                        "000_p555_jauges.iso",   "004_p555.iso",
                                        "000_p100_g63.iso",      "000_p2_mandrin_cone.iso"};
    int seen65 = 0, seen63 = 0, seen66 = 0;
    // The profile closed 1000 mm away along `away`.
    auto part_of = [](const Profile& f, V2 away) {
        Profile g = f;
        std::vector<V2> pts = densify(g);
        V2 a = pts.front(), b = pts.back();
        pts.push_back(b + 1000 * away);
        pts.push_back(a + 1000 * away);
        return pts;
    };
    for (const std::string& file : runs) {
        MachineProfile m;
        builtin_machine("lathe", m);
        ProgramMemory mem;
        std::ifstream in(dir + file);
        std::stringstream text;
        text << in.rdbuf();
        mem.load_text(file, text.str());
        RunOptions o;
        o.on_g65 = [&](const Profile& fin, V2 tool, const G65Args& a, const std::vector<Move>& mv) {
            ++seen65;
            V2 t(a.k, a.i), u(std::cos(a.ea * kPi / 180), std::sin(a.ea * kPi / 180));
            V2 away = a.has_p ? V2(0, u.y() < 0 ? -1 : 1) : V2(u.x() < 0 ? -1 : 1, 0);
            Profile f = a.allowance_inside ? shifted(fin, t) : fin;
            Oracle oracle(f, {tool}, a.allowance_inside ? V2(0, 0) : t);
            check_out_of_part(oracle, part_of(f, away), tool, mv, file + " G65");
        };
        o.on_g63 = [&](const Profile& fin, V2 tool, const G63Args& a, const std::vector<Move>& mv) {
            ++seen63;
            double lv = a.has_p ? a.x : a.z, lim = a.has_p ? a.eu : a.ew;
            V2 away = a.has_p ? V2(0, lim > lv ? 1 : -1) : V2(lim > lv ? 1 : -1, 0);
            Oracle oracle(fin, {tool}, V2(0, 0));
            oracle.er = a.er;
            check_out_of_part(oracle, part_of(fin, away), tool, mv, file + " G63");
        };
        o.on_g66 = [&](V2 tool, const G66Args& a, const std::vector<Move>& mv) {
            ++seen66;
            // The groove in the first corrector's terms: from A to B read by the
            // second corrector, down to the bottom line through it.
            V2 B = V2(a.z, a.x) + a.gauge_delta;
            double lo = std::min(a.has_r ? tool.x() : tool.y(), a.has_r ? B.x() : B.y());
            double hi = std::max(a.has_r ? tool.x() : tool.y(), a.has_r ? B.x() : B.y());
            for (const Seg& s : segs(tool, mv))
                for (V2 q : {s.a, s.b}) {
                    double along = a.has_r ? q.x() : q.y(), across = a.has_r ? q.y() : q.x();
                    double from = a.has_r ? tool.y() : tool.x(), bottom = a.has_r ? B.y() : B.x();
                    double slope = std::tan(a.ea * kPi / 180);
                    double bot = bottom + (along - (a.has_r ? B.x() : B.y())) * slope;
                    EXPECT_GE(along, lo - 1e-6) << file;
                    EXPECT_LE(along, hi + 1e-6) << file;
                    EXPECT_GE((across - bot) * (from - bot), -1e-9)
                        << file << ": beyond the bottom";
                }
        };
        struct Quiet final : MachineSink {
        } sink;
        Interpreter interp(m, mem, sink, o);
        interp.start(mem.first());
        interp.run_to_end();
    }
    EXPECT_EQ(seen65, 4);
    EXPECT_EQ(seen63, 1);
    EXPECT_EQ(seen66, 1);
}

// ---------------------------------------------------------------- G63 ----

// %100's interior profile (000:2708-2767) with its R2 fillets resolved: tangent
// points X40 Z-43.292 / X37.143 Z-45.208 and X37.143 Z-54.792 / X40 Z-56.708
// around the R5 semicircle centred X40 Z-50 (computed by hand).
Profile p100() {
    double zt = -50 + std::sqrt(45.0);
    V2 c0 = P(40, -50), c1(zt, 18), c2(-100 - zt, 18);
    V2 t1 = c1 + (c0 - c1).normalized() * 2, t2 = c2 + (c0 - c2).normalized() * 2;
    Profile p = poly_profile({P(50, 5), P(30, -5), P(30, -20), P(40, -25), V2(zt, 20)});
    p.elems.push_back(Arc(V2(zt, 20), t1, c1, true));
    p.elems.push_back(Arc(t1, t2, c0, false));
    p.elems.push_back(Arc(t2, V2(-100 - zt, 20), c2, true));
    for (auto [a, b] : std::vector<std::pair<V2, V2>>{{V2(-100 - zt, 20), P(40, -75)},
                                                      {P(40, -75), P(30, -80)},
                                                      {P(30, -80), P(30, -85)},
                                                      {P(30, -85), P(16, -92)}})
        p.elems.push_back(L(a, b));
    return p;
}

G63Args p100_args() {
    G63Args a;
    a.has_x = a.has_z = true, a.x = 8, a.z = 5, a.has_eu = true, a.eu = 25, a.has_ez = true,
    a.ez = -92, a.has_p = true, a.p = 2, a.has_eb = true, a.eb = 110, a.has_ec = true, a.ec = 70,
    a.er = .2, a.q = 1, a.eq = .5;
    return a;
}

TEST(G63, P100InteriorWithPockets) {
    Profile f = p100();
    EXPECT_TRUE(f.elems[4].b.isApprox(P(37.143, -45.208), 1e-3));
    EXPECT_TRUE(f.elems[6].a.isApprox(P(37.143, -54.792), 1e-3));
    std::vector<Move> mv;
    V2 tool = P(10, 10);
    ASSERT_TRUE(ok(g63(f, tool, p100_args(), mv)));
    EXPECT_TRUE(mv.front().to.isApprox(P(16, 5), 1e-12));  // rapid to D first
    EXPECT_TRUE(mv.back().to.isApprox(P(16, 5), 1e-12));   // and back to it
    std::vector<Seg> s = feeds(tool, mv);
    // Levels from the Ø16 hole by 2 (radius); the first three pass under the
    // Ø30 lands to the Ø16 cone at the bottom, offset 0.2 normal to it.
    ASSERT_GE(s.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        double r = 10 + 2 * k;
        EXPECT_TRUE(s[k].a.isApprox(V2(6, r), 1e-9)) << k;
        // The cone r = 8 + (-92 - z) ... offset by 0.2: z = -92 + (r - 8) - 0.2·√2.
        EXPECT_NEAR(s[k].b.x(), -92 + (r - 8) + .2 * std::sqrt(2.0), 1e-9) << k;
    }
    // Both pockets are entered at Ø32 and Ø36 over the Ø30 land and the ridge.
    int in_pocket = 0, infeeds = 0;
    for (const Seg& g : s) {
        if (g.infeed) ++infeeds;
        if (std::fabs(g.a.y() - g.b.y()) < 1e-9 && g.a.y() > 15.5 &&
            std::max(g.a.x(), g.b.x()) < -21)
            ++in_pocket;
    }
    // And at the levels of the lands plus ER (issue 39 item 5: the pockets
    // were left at Ø36, 1.8 above their allowance, the Ø30 lands at Ø28):
    // Ø39.6 in both pockets, Ø29.6 along the lands.
    EXPECT_EQ(in_pocket, 6);
    EXPECT_EQ(infeeds, 6);
    int pocket_floor = 0, land = 0;
    for (const Seg& g : s) {
        if (std::fabs(g.a.y() - g.b.y()) > 1e-9) continue;
        pocket_floor += std::fabs(g.a.y() - 19.8) < 1e-9 && std::max(g.a.x(), g.b.x()) < -21;
        land += std::fabs(g.a.y() - 14.8) < 1e-9;
    }
    EXPECT_EQ(pocket_floor, 2);
    EXPECT_GE(land, 1);
    // Never nearer than ER to the profile; inside the stock (hole Ø16 to EU50,
    // Z5 to EZ-92) but for the clearance Q.
    Oracle o(f, {P(50, 5), P(16, 5), P(16, -92)}, V2(0, 0));
    o.er = .2;
    check_clear(o, tool, mv, 1, "G63 %100");
    for (const Seg& g : s)
        for (V2 q : {g.a, g.b}) {
            EXPECT_GE(q.y(), 8 - 1 - 1e-9);
            EXPECT_LE(q.x(), 6 + 1e-9);
            EXPECT_GE(q.x(), -92 - 1e-9);
        }
}

// EB limits the pockets entered: a flank steeper than EB is not followed.
TEST(G63, EntryAngle) {
    G63Args a = p100_args();
    a.eb = 30;  // the pocket flanks are at 45° and the ridge's back at 37°
    std::vector<Move> mv;
    ASSERT_TRUE(ok(g63(p100(), P(10, 10), a, mv)));
    for (const Seg& g : feeds(P(10, 10), mv)) EXPECT_FALSE(g.infeed);
    // EQ drops a last level thinner than the minimum chip: EU46.8 leaves 1.4
    // above the level at Ø44.
    a = p100_args();
    a.eu = 23.4, a.eq = 1.5;
    ASSERT_EQ(g63(p100(), P(10, 10), a, mv).code, 0);
    // The deepest level: the lowest of the passes along Z (the last pass
    // along the profile plus ER goes deeper, down the cone at the start).
    auto deepest = [&] {
        double top = 0;
        for (const Seg& g : feeds(P(10, 10), mv))
            if (std::fabs(g.a.y() - g.b.y()) < 1e-9) top = std::max(top, g.a.y());
        return top;
    };
    EXPECT_NEAR(deepest(), 22, 1e-9);
    a.eq = .5;
    ASSERT_EQ(g63(p100(), P(10, 10), a, mv).code, 0);
    EXPECT_NEAR(deepest(), 23.4, 1e-9);
}

TEST(G63, Errors) {
    std::vector<Move> mv;
    G63Args a = p100_args();
    a.has_p = false;
    EXPECT_EQ(g63(p100(), P(10, 10), a, mv).code, 873);
    a.has_p = a.has_r = true;
    EXPECT_EQ(g63(p100(), P(10, 10), a, mv).code, 889);
    a = p100_args();
    a.has_ez = false;
    EXPECT_EQ(g63(p100(), P(10, 10), a, mv).code, 862);
    a = p100_args();
    a.eb = 190;
    EXPECT_EQ(g63(p100(), P(10, 10), a, mv).code, 876);
    a = p100_args();
    a.has_x = false;
    EXPECT_EQ(g63(p100(), P(10, 10), a, mv).code, 2);
    a = p100_args();
    EXPECT_EQ(g63(Profile{}, P(10, 10), a, mv).code, 871);
    a.has_ea = true, a.ea = 0;  // the start line along the passes
    EXPECT_EQ(g63(p100(), P(10, 10), a, mv).code, 875);
    // The printed N160 X-40 crosses the spindle axis: error 874.
    Profile bad =
        poly_profile({P(50, 5), P(30, -5), P(30, -20), P(-40, -25), P(40, -45), P(16, -92)});
    EXPECT_EQ(g63(bad, P(10, 10), p100_args(), mv).code, 874);
}

// ---------------------------------------------------------------- G66 ----

// %2's groove (000:3493-3494): D10 at X27 Z-32.3, G66 D11 X23 Z-27.8 R4 EF1.
// With equal gauges the width 4.5 takes 3 plunges 2.25 apart, each to Ø23 with
// a 1 s dwell.
TEST(G66, P2Groove) {
    G66Args a;
    a.d_first = 10, a.d = 11, a.has_x = a.has_z = true, a.x = 11.5, a.z = -27.8, a.has_r = true,
    a.r = 4, a.ef = 1;
    std::vector<Move> mv;
    V2 tool = P(27, -32.3);
    ASSERT_TRUE(ok(g66(tool, a, mv)));
    std::vector<Seg> s = feeds(tool, mv);
    const double z[] = {-32.3, -30.05, -27.8};
    ASSERT_EQ(s.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(s[i].a.isApprox(P(27, z[i]), 1e-9)) << i;
        EXPECT_TRUE(s[i].b.isApprox(P(23, z[i]), 1e-9)) << i;
    }
    for (const Move& m : mv) EXPECT_EQ(m.dwell, m.g == 1 ? 1.0 : 0.0);
    EXPECT_TRUE(mv.back().to.isApprox(P(27, -27.8), 1e-9));
    // Correctors 4 mm apart (the tool width): the turret travels 0.5 mm, two
    // plunges; the tool ends at Z-31.8 in D10's terms, which D11 reads as Z-27.8.
    a.gauge_delta = V2(-4, 0);
    ASSERT_TRUE(ok(g66(tool, a, mv)));
    s = feeds(tool, mv);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_NEAR(s[1].a.x(), -31.8, 1e-9);
    EXPECT_TRUE(mv.back().to.isApprox(P(27, -31.8), 1e-9));
}

// The handbook's example (000:2829-2840): from X66 Z30, G66 D15 X46 Z50 EA10 R5 EF1:
// a sloping bottom through B, 4 plunges 5 mm apart; with EP a 45° move back
// over the cut part of the groove after every plunge but the first.
TEST(G66, SlopeAndEp) {
    G66Args a;
    a.d_first = 1, a.d = 15, a.has_x = a.has_z = true, a.x = 23, a.z = 50, a.ea = 10,
    a.has_r = true, a.r = 5, a.ef = 1, a.ep = .5;
    std::vector<Move> mv;
    V2 tool = P(66, 30);
    ASSERT_TRUE(ok(g66(tool, a, mv)));
    std::vector<Seg> s = feeds(tool, mv);
    ASSERT_EQ(s.size(), 5u + 4u);
    double t10 = std::tan(10 * kPi / 180);
    int plunge = 0;
    for (const Seg& g : s) {
        if (g.a.y() != 33) continue;  // the 45° moves start at the bottom
        double z = 30 + 5 * plunge++;
        EXPECT_TRUE(g.b.isApprox(V2(z, 23 + (z - 50) * t10), 1e-9)) << z;
    }
    EXPECT_EQ(plunge, 5);
    for (size_t i = 1; i < s.size(); ++i)
        if (s[i].a.y() < 33 && s[i - 1].b == s[i].a) {
            V2 d = s[i].b - s[i].a;
            EXPECT_NEAR(d.x(), -.5 / std::sqrt(2.0), 1e-12);
            EXPECT_NEAR(d.y(), .5 / std::sqrt(2.0), 1e-12);
        }
}

// A frontal groove (P): plunges along Z spread along X.
TEST(G66, Frontal) {
    G66Args a;
    a.d_first = 1, a.d = 2, a.has_x = a.has_z = true, a.x = 30, a.z = -6, a.has_p = true, a.p = 3;
    std::vector<Move> mv;
    V2 tool = P(40, 2);  // r 20 to r 30: 10 mm, 4 plunges
    ASSERT_TRUE(ok(g66(tool, a, mv)));
    std::vector<Seg> s = feeds(tool, mv);
    ASSERT_EQ(s.size(), 5u);
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(s[i].b.isApprox(V2(-6, 20 + 2.5 * i), 1e-9)) << i;
}

// A 10 mm groove 5 deep with a 3 mm tool, plunges 1.75 apart and EP4: the
// 45° move after the second plunge would go 2.83 back, 1.08 into the first
// flank; it stops over the first plunge (issue 19 item 1).
TEST(G66, EpStopsOverTheFirstPlunge) {
    G66Args a;
    a.d_first = 1, a.d = 2, a.gauge_delta = V2(-3, 0), a.has_x = a.has_z = true, a.x = 20, a.z = 10,
    a.has_r = true, a.r = 2, a.ep = 4;
    std::vector<Move> mv;
    V2 tool = P(60, 0);
    ASSERT_TRUE(ok(g66(tool, a, mv)));
    for (const Seg& s : segs(tool, mv)) EXPECT_GE(s.b.x(), -1e-9) << s.b.transpose();
    std::vector<Seg> f = feeds(tool, mv);
    ASSERT_EQ(f.size(), 5u + 4u);
    EXPECT_TRUE(f[2].b.isApprox(V2(0, 21.75), 1e-9))
        << f[2].b.transpose();                       // after the plunge at Z1.75
    EXPECT_NEAR((f[4].b - f[4].a).norm(), 4, 1e-9);  // from the third plunge on, EP whole
}

// Generated grooves for G66 (issue 19 item 1): radial (R) and frontal (P),
// cut either way, tool widths 2 to 5 mm (the correctors' difference), bottoms
// sloped up to 15° either way, EP up to twice the spacing of the plunges. The
// groove is the rectangle from A's flank to B's, from the approach level to
// the bottom line: no move of the tool's reference edge (the first
// corrector's) leaves it below the approach level, and neither corner of the
// flat blade goes below the sloped bottom under it.
TEST(G66, GeneratedGroovesStayInTheGroove) {
    std::mt19937 rng(20261128);
    std::uniform_real_distribution<double> u(0, 1);
    int failing = 0;
    for (int n = 0; n < 64; ++n) {
        const bool frontal = n % 2, back = (n / 2) % 2, bore = (n / 4) % 2;
        // Frame: x along the groove's width, y the plunge (down into the part).
        auto to_zr = [&](V2 q) {
            double x = back ? -q.x() : q.x(), y = bore ? -q.y() : q.y();
            return frontal ? V2(y, 40 + x) : V2(x, 40 + y);
        };
        double w = 2 + 3 * u(rng), width = w + 2 + 8 * u(rng), depth = 2 + 6 * u(rng);
        double spacing = .5 + w * .8 * u(rng), slope = (u(rng) - .5) * 30;
        G66Args a;
        a.d_first = 1, a.d = 2;
        V2 A(0, 2), B(width, -depth);  // B for the second corrector: the far flank
        V2 Bzr = to_zr(B), Azr = to_zr(A);
        // The second corrector reads the tool's other edge: B in the first
        // corrector's terms is B - w along the width.
        a.gauge_delta = to_zr(V2(-w, 0)) - to_zr(V2(0, 0));
        a.has_x = a.has_z = true, a.x = Bzr.y(), a.z = Bzr.x();
        (frontal ? a.has_p : a.has_r) = true;
        (frontal ? a.p : a.r) = spacing;
        V2 ea =
            to_zr(V2(std::cos(slope * kPi / 180), std::sin(slope * kPi / 180))) - to_zr(V2(0, 0));
        a.ea = std::atan2(frontal ? ea.x() : ea.y(), frontal ? ea.y() : ea.x()) * 180 / kPi;
        a.ep = u(rng) < .3 ? 0 : 2 * spacing * u(rng);
        std::vector<Move> mv;
        std::string name = "G66 " + std::to_string(n) + (frontal ? " P" : " R") +
                           (back ? " back" : "") + (bore ? " bore" : "") + " EA" +
                           std::to_string(a.ea) + " EP" + std::to_string(a.ep);
        ASSERT_TRUE(ok(g66(Azr, a, mv))) << name;
        // The groove in the frame of the first corrector: x from 0 to width - w,
        // y from the approach (2) down to the bottom line through B - w.
        int bad = 0;
        V2 inv_o = to_zr(V2(0, 0)), ex = to_zr(V2(1, 0)) - inv_o, ey = to_zr(V2(0, 1)) - inv_o;
        auto frame = [&](V2 q) { return V2((q - inv_o).dot(ex), (q - inv_o).dot(ey)); };
        double t = std::tan(slope * kPi / 180);
        for (const Seg& sg : segs(Azr, mv))
            for (int i = 0; i <= 20; ++i) {
                V2 q = frame(sg.a + (sg.b - sg.a) * (i / 20.0));
                // The blade is flat from its first edge (q.x) to its second
                // (q.x + w): neither corner goes below the line under it
                // (issue 39 item 3: the second corner's alone was checked).
                double bottom =
                    std::max(-depth + (q.x() - width) * t, -depth + (q.x() + w - width) * t);
                bool below_top = q.y() < 0 - 1e-9;  // the land at y 0
                if ((q.y() < bottom - 1e-6 ||
                     (below_top && (q.x() < -1e-6 || q.x() > width - w + 1e-6))) &&
                    ++bad <= 2)
                    ADD_FAILURE() << name << ": G" << sg.g << " at x " << q.x() << " y " << q.y();
            }
        failing += bad > 0;
    }
    EXPECT_EQ(failing, 0);
}

// Issue 39 item 3: G66 D2 X30 Z-30 EA5 R3 from X44 Z-20 with D2.Z=4 (a 4 mm
// blade; the groove runs towards -Z, so D2's edge is 4 mm on: its gauge 4
// longer). The bottom rises towards A: the blade stops where its first
// corner meets it, 4 tan 5 = 0.35 mm above where the second corner would.
TEST(G66, SlopeUnderTheWholeBlade) {
    for (double ea : {5.0, 10.0}) {
        G66Args a;
        a.d_first = 1, a.d = 2, a.gauge_delta = V2(4, 0), a.has_x = a.has_z = true, a.x = 15,
        a.z = -30, a.ea = ea, a.has_r = true, a.r = 3;
        std::vector<Move> mv;
        const V2 tool = P(44, -20);
        ASSERT_TRUE(ok(g66(tool, a, mv)));
        const double t = std::tan(ea * kPi / 180);
        for (const Seg& s : feeds(tool, mv)) {
            const double z1 = s.b.x(), z2 = z1 - 4;  // the first and second corners
            const double under = std::max(15 + (z1 + 30) * t, 15 + (z2 + 30) * t);
            EXPECT_NEAR(s.b.y(), under, 1e-9) << "EA" << ea << " Z" << z1;
        }
        // At Z-20 the first plunge stops 4 tan EA above the second corner's line.
        const std::vector<Seg> f = feeds(tool, mv);
        ASSERT_FALSE(f.empty());
        EXPECT_NEAR(f[0].b.y() - (15 + (-24 + 30) * t), 4 * t, 1e-9);
    }
}

TEST(G66, Errors) {
    std::vector<Move> mv;
    G66Args a;
    a.d_first = 1, a.d = 2, a.has_x = a.has_z = true, a.x = 11.5, a.z = -27.8;
    EXPECT_EQ(g66(P(27, -32.3), a, mv).code, 862);  // no R or P
    a.has_r = a.has_p = true, a.r = a.p = 4;
    EXPECT_EQ(g66(P(27, -32.3), a, mv).code, 889);
    a.has_p = false, a.d = 0;
    EXPECT_EQ(g66(P(27, -32.3), a, mv).code, 898);
    a.d = 2, a.milling_tool = true;
    EXPECT_EQ(g66(P(27, -32.3), a, mv).code, 864);
    a.milling_tool = false, a.gauge_delta = V2(-6, 0);  // a tool wider than the groove
    EXPECT_EQ(g66(P(27, -32.3), a, mv).code, 863);
    a.gauge_delta = V2(0, 0), a.x = 13.5;  // the bottom at the approach radius
    EXPECT_EQ(g66(P(27, -32.3), a, mv).code, 863);
    EXPECT_TRUE(mv.empty());
}

// ---------------------------------------------------------------- G33 ----

// M20×2.5 (000:3226-3236, checked by hand): G33 X20 Z10 K2.5 P2.165 Q.05 S6 from X24 Z64.
TEST(G33, DegressivePasses) {
    G33Args a;
    a.has_x = a.has_z = a.has_k = a.has_p = a.has_q = a.has_s = true;
    a.x = 10, a.z = 10, a.k = 2.5, a.p = 2.165, a.q = .05, a.s = 6;
    std::vector<Move> mv;
    V2 tool = P(24, 64);
    ASSERT_TRUE(ok(g33(tool, a, mv)));
    const double depth[] = {0.863, 1.221, 1.496, 1.727, 1.931, 2.115, 2.165};
    std::vector<Seg> s = segs(tool, mv);
    std::vector<Seg> threads;
    for (const Seg& g : s)
        if (g.g == 33) threads.push_back(g);
    ASSERT_EQ(threads.size(), 7u);
    for (int i = 0; i < 7; ++i) {
        EXPECT_NEAR(10 - threads[i].a.y(), depth[i], 5e-4) << i;
        EXPECT_NEAR(threads[i].a.x(), 64, 1e-12);
        EXPECT_NEAR(threads[i].b.x(), 10, 1e-12);
        EXPECT_EQ(threads[i].a.y(), threads[i].b.y());
    }
    EXPECT_NEAR(2 * threads.back().b.y(), 15.67, 1e-9);  // the root diameter
    // One pass: rapid in radially, thread, rapid out to X24 at Z10, rapid back.
    ASSERT_EQ(mv.size(), 7u * 4u);
    EXPECT_EQ(mv[0].g, 0);
    EXPECT_TRUE(mv[2].g == 0 && mv[2].to.isApprox(P(24, 10), 1e-12));
    EXPECT_TRUE(mv[3].g == 0 && mv[3].to.isApprox(tool, 1e-12));
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
}

// Taper, 2 starts (000:3248-3262): G33 X90.507 Z-30 K4 EA-9.87 EB30 R3 P1.2 Q.06
// S4 F2 from X82.327 Z5. Values from a one-off script: the clearance line lies
// 1.999595 above the crest r = 45.2535 + (z + 30)·tan(-9.87°).
TEST(G33, TaperTwoStartsObliqueExit) {
    G33Args a;
    a.has_x = a.has_z = a.has_k = a.has_p = a.has_q = a.has_s = a.has_f = true;
    a.x = 90.507 / 2, a.z = -30, a.k = 4, a.ea = -9.87, a.eb = 30, a.r = 3, a.p = 1.2, a.q = .06,
    a.s = 4, a.f = 2;
    std::vector<Move> mv;
    V2 tool = P(82.327, 5);
    ASSERT_TRUE(ok(g33(tool, a, mv)));
    // 5 depths × 2 starts, each: to the clearance line (not needed for the
    // first, the tool is there), infeed, thread, exit slope, back; then to the start.
    ASSERT_EQ(mv.size(), 5u * 2u * 5u - 1u + 1u);
    std::vector<Move> full(1);  // the tool's position as a first rapid
    full[0].to = tool;
    full.insert(full.end(), mv.begin(), mv.end());
    std::vector<size_t> threads;
    for (size_t i = 1; i < full.size(); ++i)
        if (full[i].g == 33 && full[i - 1].g == 0) threads.push_back(i);
    ASSERT_EQ(threads.size(), 10u);
    auto pass = [&](int depth, int start) { return &full[threads[size_t(2 * depth + start)] - 2]; };
    struct Expect {
        int depth, start;
        V2 clear, in, end;
    } ex[] = {
        {0, 0, {5, 41.1635}, {5.329090, 38.593905}, {-27, 44.161535}},
        {0, 1, {7, 40.815523}, {7.329090, 38.245928}, {-27, 44.161535}},
        {4, 0, {5, 41.1635}, {5.692820, 37.963905}, {-27, 43.531535}},
        {4, 1, {7, 40.815523}, {7.692820, 37.615928}, {-27, 43.531535}},
    };
    for (const Expect& e : ex) {
        const Move* m = pass(e.depth, e.start);
        EXPECT_TRUE(m[0].g == 0 && m[0].to.isApprox(e.clear, 1e-6)) << m[0].to.transpose();
        EXPECT_TRUE(m[1].g == 0 && m[1].to.isApprox(e.in, 1e-6)) << m[1].to.transpose();
        EXPECT_TRUE(m[2].g == 33 && m[2].to.isApprox(e.end, 1e-6)) << m[2].to.transpose();
        EXPECT_TRUE(m[3].g == 33 && m[3].to.isApprox(V2(-30, 47.253095), 1e-6));  // exit slope
        EXPECT_TRUE(m[4].g == 0 && m[4].to.isApprox(e.clear, 1e-6));
    }
    EXPECT_TRUE(mv[0].to.isApprox(V2(5.329090, 38.593905), 1e-6));  // straight to the infeed
    EXPECT_TRUE(mv.back().to.isApprox(tool, 1e-12));
}

TEST(G33, ConstantPassesSpringPassInternalFace) {
    G33Args a;
    a.has_x = a.has_z = a.has_k = a.has_p = a.has_es = true;
    a.x = 10, a.z = 10, a.k = 2, a.p = 1.2, a.es = 4;
    std::vector<Move> mv;
    auto depths = [&](V2 tool, bool x_axis) {
        std::vector<double> d;
        for (const Seg& g : segs(tool, mv))
            if (g.g == 33) d.push_back(x_axis ? g.a.x() : g.a.y());
        return d;
    };
    // ES: equal steps, no finishing pass without Q.
    ASSERT_TRUE(ok(g33(P(24, 40), a, mv)));
    std::vector<double> d = depths(P(24, 40), false);
    ASSERT_EQ(d.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(10 - d[size_t(i)], .3 * (i + 1), 1e-12);
    // Q0: a spring pass at the full depth.
    a.has_q = true, a.q = 0;
    ASSERT_EQ(g33(P(24, 40), a, mv).code, 0);
    d = depths(P(24, 40), false);
    ASSERT_EQ(d.size(), 5u);
    EXPECT_NEAR(d[3], d[4], 1e-12);
    // An internal thread: the start inside the crest line, the depth outwards.
    a.has_q = false;
    ASSERT_EQ(g33(P(16, 40), a, mv).code, 0);
    d = depths(P(16, 40), false);
    EXPECT_NEAR(d.back(), 11.2, 1e-12);
    // A face thread (EA90): the lead along X, the depth along -Z.
    a.ea = 90, a.x = 40, a.z = 0;
    ASSERT_TRUE(ok(g33(P(20, 3), a, mv)));
    std::vector<Seg> t;
    for (const Seg& g : segs(P(20, 3), mv))
        if (g.g == 33) t.push_back(g);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_NEAR(t.back().a.x(), -1.2, 1e-12);
    EXPECT_NEAR(t.back().a.y(), 10, 1e-12);
    EXPECT_NEAR(t.back().b.y(), 40, 1e-12);
}

TEST(G33, Errors) {
    auto ok = [] {
        G33Args a;
        a.has_x = a.has_z = a.has_k = a.has_p = true;
        a.x = 10, a.z = 10, a.k = 2.5, a.p = 1.5;
        return a;
    };
    std::vector<Move> mv;
    V2 tool = P(24, 64);
    G33Args a = ok();
    ASSERT_EQ(g33(tool, a, mv).code, 0);
    a.has_k = false;
    EXPECT_EQ(g33(tool, a, mv).code, 832);
    a = ok(), a.has_s = a.has_es = true;
    EXPECT_EQ(g33(tool, a, mv).code, 889);
    a = ok(), a.k = -2.5;
    EXPECT_EQ(g33(tool, a, mv).code, 835);
    a = ok(), a.has_q = true, a.q = -.1;
    EXPECT_EQ(g33(tool, a, mv).code, 835);
    a = ok(), a.eb = 95;
    EXPECT_EQ(g33(tool, a, mv).code, 834);
    a = ok(), a.eb = -90;
    EXPECT_EQ(g33(tool, a, mv).code, 834);
    a = ok(), a.has_f = true, a.f = 12;
    EXPECT_EQ(g33(tool, a, mv).code, 884);
    a = ok(), a.has_f = true, a.f = 0;
    EXPECT_EQ(g33(tool, a, mv).code, 837);
    a = ok(), a.has_s = true, a.s = 0;
    EXPECT_EQ(g33(tool, a, mv).code, 837);
    a = ok(), a.has_q = true, a.q = 2;
    EXPECT_EQ(g33(tool, a, mv).code, 881);  // Q deeper than P
    a = ok(), a.r = 60;
    EXPECT_EQ(g33(tool, a, mv).code, 881);  // exit longer than the thread
    a = ok(), a.radius_comp = true;
    EXPECT_EQ(g33(tool, a, mv).code, 27);
    a = ok(), a.plane_ok = false;
    EXPECT_EQ(g33(tool, a, mv).code, 836);
    a = ok(), a.spindle_turning = false;
    EXPECT_EQ(g33(tool, a, mv).code, 831);
    a = ok();
    EXPECT_EQ(g33(P(20, 64), a, mv).code, 833);  // the start on the crest line
    EXPECT_TRUE(mv.empty());
}

// ---------------------------------------------------------------- G38 ----

// 000:3302-3310: a chain of synchronised moves, one per block, each its lead.
TEST(G38, Chain) {
    std::vector<Move> mv;
    G38Args a;
    a.to = P(30, 20), a.has_k = true, a.k = 4;
    ASSERT_TRUE(ok(g38(P(30, 60), a, mv)));
    ASSERT_EQ(mv.size(), 1u);
    EXPECT_EQ(mv[0].g, 33);
    EXPECT_TRUE(mv[0].to.isApprox(P(30, 20), 1e-12));
    EXPECT_EQ(thread_axis(P(30, 60), P(30, 20)), 0);
    // The next block keeps the chain's lead when it gives no K.
    a.has_k = false, a.prev_k = 4, a.to = P(40, 0);
    ASSERT_EQ(g38(P(30, 20), a, mv).code, 0);
    EXPECT_EQ(thread_axis(P(30, 20), P(40, 0)), 0);
    EXPECT_EQ(thread_axis(P(30, 20), P(90, 19)), 1);  // mostly along X
    a.prev_k = 0;
    EXPECT_EQ(g38(P(30, 20), a, mv).code, 883);
    a.has_k = true, a.k = -1;
    EXPECT_EQ(g38(P(30, 20), a, mv).code, 835);
    a.k = 4, a.radius_comp = true;
    EXPECT_EQ(g38(P(30, 20), a, mv).code, 27);
    a.radius_comp = false, a.spindle_turning = false;
    EXPECT_EQ(g38(P(30, 20), a, mv).code, 831);
}
