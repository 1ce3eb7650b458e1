// The level lines of the roughing cycles through the material region: the
// intervals m_intervals finds and Material::in_M (near elements only,
// winding numbers by ray crossings) against the definition (every element,
// winding numbers by summed angles), on loops of lines and arcs, with lines
// through vertices, arc tops and horizontal edges; the indexes of the
// profile's elements (ExtentIndex, first_hidden's walk) against every element.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/cycles/turning_zone.hpp"

using namespace pupitre::turning;
using geom::Elem;
using geom::V2;

namespace {
constexpr double kPi = std::numbers::pi;

Elem arc_from(const V2& c, const V2& a, double sweep) {
    Elem e;
    e.arc = true;
    e.c = c;
    e.a = a;
    V2 u = a - c;
    e.b = c + V2(std::cos(sweep) * u.x() - std::sin(sweep) * u.y(),
                 std::sin(sweep) * u.x() + std::cos(sweep) * u.y());
    e.sweep = sweep;
    return e;
}

// The edge from a to b: a line, or the arc of sweep s (its centre on the bisector).
Elem edge(const V2& a, const V2& b, double s) {
    if (s == 0) return geom::line(a, b);
    V2 mid = (a + b) / 2, ab = b - a;
    double half = ab.norm() / 2, dist = half / std::tan(s / 2);
    V2 c = mid + V2(-ab.y(), ab.x()) / ab.norm() * dist;
    Elem e = arc_from(c, a, s);
    e.b = b;
    return e;
}

// A closed loop through the points, with some edges bulged into arcs.
zone::Material loop(const std::vector<V2>& pts, const std::vector<double>& bulge) {
    zone::Material m;
    for (size_t i = 0; i < pts.size(); ++i) {
        m.M.push_back(edge(pts[i], pts[(i + 1) % pts.size()], i < bulge.size() ? bulge[i] : 0));
        m.kind.push_back(int(i % 3));
    }
    return m;
}

// Inside M or on its boundary, by the definition: every element, the
// winding number by summed angles.
bool in_M_all(const zone::Material& m, const V2& q) {
    return geom::on_loop(m.M, q) || geom::winding(m.M, q) != 0;
}

// Every interval lies inside M and every gap between them outside, at the
// midpoints of the sub-intervals between all crossings, as the definition
// and in_M decide.
void check_level(const zone::Material& m, double Y) {
    auto ivs = zone::m_intervals(m, Y, 1);
    std::vector<double> xs;
    for (const Elem& e : m.M) geom::cross_h(e, Y, xs);
    std::sort(xs.begin(), xs.end());
    for (size_t j = 0; j + 1 < xs.size(); ++j) {
        if (xs[j + 1] - xs[j] <= geom::kTol) continue;
        double x = (xs[j] + xs[j + 1]) / 2;
        bool covered = false;
        for (const auto& iv : ivs) covered |= iv.a < x && x < iv.b;
        ASSERT_EQ(covered, in_M_all(m, V2(x, Y))) << "Y " << Y << " x " << x;
        ASSERT_EQ(covered, m.in_M(V2(x, Y))) << "Y " << Y << " x " << x;
    }
    // On the boundary: the crossings themselves.
    for (double x : xs) ASSERT_EQ(in_M_all(m, V2(x, Y)), m.in_M(V2(x, Y))) << "Y " << Y;
}
}  // namespace

TEST(TurningZone, LevelIntervalsAgreeWithTheWindingNumberOnPolygons) {
    // A comb: teeth whose tops and bottoms are at integer heights the levels hit.
    std::vector<V2> comb{{0, 0}, {40, 0}, {40, 10}};
    for (int k = 0; k < 10; ++k) {
        double x = 40 - 4 * k;
        comb.push_back({x - 1, 10});
        comb.push_back({x - 2, 4 + k % 3});
        comb.push_back({x - 3, 10});
    }
    comb.push_back({0, 10});
    zone::Material m = loop(comb, {});
    for (double Y = -1; Y <= 11; Y += 0.25) check_level(m, Y);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 11);
    for (int i = 0; i < 2000; ++i) check_level(m, u(rng));
}

TEST(TurningZone, LevelIntervalsAgreeWithTheWindingNumberWithArcs) {
    // Arcs bulging out and in, whose tops and bottoms some levels touch.
    std::vector<V2> pts{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {0, 10}};
    for (double s : {kPi / 2, -kPi / 2, kPi, -kPi, 1.0, -2.5}) {
        zone::Material m = loop(pts, {0, s, 0, -s, 0.3});
        for (double Y = -12; Y <= 22; Y += 0.5) check_level(m, Y);
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(-12, 22);
        for (int i = 0; i < 1000; ++i) check_level(m, u(rng));
    }
}

TEST(TurningZone, ALongWavyStockIsIndexed) {
    // 4,000 stock points: the intervals of a level in the waves and below them.
    std::vector<V2> pts{{0, 0}};
    for (int i = 0; i <= 4000; ++i) pts.push_back({i * 0.025, 100 - std::fabs(std::sin(i)) * 0.25});
    pts.push_back({100, 0});
    zone::Material m = loop(pts, {});
    check_level(m, 99.9);
    check_level(m, 50);
    EXPECT_EQ(zone::m_intervals(m, 50, 1).size(), 1u);
    EXPECT_GT(zone::m_intervals(m, 99.9, 1).size(), 100u);
}

namespace {
// Every pair of elements, as self_intersects did before it swept boxes.
bool self_intersects_all_pairs(const std::vector<Elem>& loop) {
    auto near_end = [](const Elem& e, const V2& p) {
        return (p - e.a).norm() < 1e-7 || (p - e.b).norm() < 1e-7;
    };
    size_t n = loop.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            std::vector<V2> pts;
            geom::intersect(loop[i], loop[j], pts);
            bool next = j == i + 1, wrap = i == 0 && j == n - 1;
            if (next || wrap) {
                V2 joint = next ? loop[i].b : loop[i].a;
                for (const V2& p : pts)
                    if (n > 2 && (p - joint).norm() > 1e-7) return true;
                continue;
            }
            if (pts.size() >= 2 && (pts[0] - pts[1]).norm() > 1e-7) return true;
            for (const V2& p : pts)
                if (!near_end(loop[i], p) && !near_end(loop[j], p)) return true;
        }
    return false;
}
}  // namespace

TEST(TurningZone, SelfIntersectionBySweptBoxesAgreesWithAllPairs) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 20);
    std::uniform_int_distribution<int> count(3, 25), coin(0, 3);
    int crossing = 0;
    for (int t = 0; t < 3000; ++t) {
        std::vector<V2> pts;
        int n = count(rng);
        // Star-shaped loops (simple) and random ones (mostly crossing), some on a grid
        // so that vertices and edges touch exactly.
        bool star = t % 2 == 0;
        for (int k = 0; k < n; ++k) {
            if (star) {
                double a = 2 * kPi * k / n, r = 5 + u(rng) / 2;
                pts.push_back({10 + r * std::cos(a), 10 + r * std::sin(a)});
            } else {
                pts.push_back({std::round(u(rng)), std::round(u(rng))});
            }
        }
        std::vector<double> bulge;
        for (int k = 0; k < n; ++k) {
            bool chord =
                (pts[size_t(k)] - pts[size_t(k + 1) % pts.size()]).norm() > 0;  // an arc needs one
            bulge.push_back(chord && coin(rng) == 0 ? (k % 2 ? 0.7 : -0.7) : 0);
        }
        zone::Material m = loop(pts, bulge);
        bool want = self_intersects_all_pairs(m.M);
        crossing += want;
        std::string desc;
        for (const Elem& e : m.M)
            desc += "(" + std::to_string(e.a.x()) + "," + std::to_string(e.a.y()) +
                    (e.arc ? " arc" : "") + ") ";
        ASSERT_EQ(geom::self_intersects(m.M), want) << "case " << t << ": " << desc;
    }
    EXPECT_GT(crossing, 500);
    EXPECT_LT(crossing, 2900);
}

TEST(TurningZone, ExtentIndexFindsEveryElementMeetingAnInterval) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 100), w(0, 8);
    std::vector<Elem> es;
    for (int i = 0; i < 300; ++i) {
        V2 a(u(rng), u(rng)), b = a + V2(w(rng) - 4, w(rng) - 4);
        es.push_back(i % 4 ? geom::line(a, b) : edge(a, b, 1.2));
    }
    for (int axis : {0, 1}) {
        zone::ExtentIndex ix;
        ix.build(es, 1e-6, axis);
        for (int t = 0; t < 500; ++t) {
            double lo = u(rng), hi = lo + (t % 5 ? w(rng) : 0);
            std::vector<int> got;
            ix.query(lo, hi, got);
            std::sort(got.begin(), got.end());
            std::vector<int> want;
            for (size_t i = 0; i < es.size(); ++i) {
                const geom::Box b = geom::box(es[i], 1e-6);
                if ((axis ? b.y0 : b.x0) <= hi && lo <= (axis ? b.y1 : b.x1))
                    want.push_back(int(i));
            }
            // The index may give more (an arc's extent holds its ends), never fewer.
            ASSERT_TRUE(std::includes(got.begin(), got.end(), want.begin(), want.end()))
                << "axis " << axis << " [" << lo << ", " << hi << "]";
            ASSERT_TRUE(std::adjacent_find(got.begin(), got.end()) == got.end());
        }
    }
}

namespace {
// first_hidden as it was first written: every cut of every element of U, and
// every element at the middle of every stretch between them.
double first_hidden_all(const zone::Material& m, double Y, double x0, double x1, int d) {
    using geom::kTol;
    if ((x1 - x0) * d <= kTol) return x1;
    const double lift = Y + geom::kUm;
    auto between = [&](double x) { return (x - x0) * d > kTol && (x1 - x) * d > kTol; };
    std::vector<double> cuts{x0, x1}, xs;
    for (const Elem& e : m.U) {
        xs.assign({e.a.x(), e.b.x()});
        if (e.arc)
            for (double sg : {-1.0, 1.0})
                if (geom::on_arc(e, e.c + V2(sg * e.r(), 0))) xs.push_back(e.c.x() + sg * e.r());
        geom::cross_h(e, lift, xs);
        for (double x : xs)
            if (between(x)) cuts.push_back(x);
    }
    std::sort(cuts.begin(), cuts.end(), [d](double a, double b) { return a * d < b * d; });
    for (size_t j = 0; j + 1 < cuts.size(); ++j) {
        double mid = (cuts[j] + cuts[j + 1]) / 2;
        if (std::fabs(cuts[j + 1] - cuts[j]) <= kTol) continue;
        for (const Elem& e : m.U)
            if (geom::max_y_in(e, mid, mid) > lift) return cuts[j];
    }
    return x1;
}
}  // namespace

TEST(TurningZone, FirstHiddenAsksOnlyTheElementsThatCanHideAndAgrees) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0, 1);
    std::uniform_int_distribution<int> count(2, 30), coin(0, 4);
    int hidden = 0, tries = 0;
    for (int t = 0; t < 400; ++t) {
        // A profile on a 0.5 mm grid going along x, now and then back (an
        // undercut), some edges arcs, with a paraxial allowance.
        zone::Material m;
        V2 p(0, std::round(u(rng) * 40) / 2);
        const int n = count(rng);
        for (int k = 0; k < n; ++k) {
            V2 q(p.x() + std::round((u(rng) * 12 - (coin(rng) == 0 ? 8 : 1)) * 2) / 2,
                 std::round(u(rng) * 40) / 2);
            if ((q - p).norm() < 0.5) q.x() += 1;
            m.F.push_back(edge(p, q, coin(rng) == 0 ? (k % 2 ? 0.8 : -0.8) : 0));
            p = q;
        }
        m.translate(t % 3 ? V2(std::round(u(rng) * 4) / 4, std::round(u(rng) * 4) / 4) : V2(0, 0));
        for (int k = 0; k < 60; ++k, ++tries) {
            const double Y = std::round(u(rng) * 88) / 4 - 1 + (k % 2 ? 0 : u(rng));
            const double x0 = u(rng) * 80 - 10, x1 = u(rng) * 80 - 10;
            const int d = x1 > x0 ? 1 : -1;
            const double want = first_hidden_all(m, Y, x0, x1, d);
            hidden += want != x1;
            ASSERT_EQ(zone::first_hidden(m, Y, x0, x1, d), want)
                << "case " << t << " Y " << Y << " x0 " << x0 << " x1 " << x1;
        }
    }
    EXPECT_GT(hidden, tries / 10);
    EXPECT_LT(hidden, tries * 9 / 10);
}
