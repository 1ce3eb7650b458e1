// The level lines of the roughing cycles through the material region: the
// intervals m_intervals finds (near elements only, winding numbers by ray
// crossings) against the definition, Material::in_M (every element, winding
// numbers by summed angles), on loops of lines and arcs, with lines through
// vertices, arc tops and horizontal edges.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

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

// A closed loop through the points, with some edges bulged into arcs.
zone::Material loop(const std::vector<V2>& pts, const std::vector<double>& bulge) {
    zone::Material m;
    for (size_t i = 0; i < pts.size(); ++i) {
        V2 a = pts[i], b = pts[(i + 1) % pts.size()];
        double s = i < bulge.size() ? bulge[i] : 0;
        if (s == 0) {
            m.M.push_back(geom::line(a, b));
        } else {
            // The arc of sweep s from a to b: its centre on the bisector.
            V2 mid = (a + b) / 2, ab = b - a;
            double half = ab.norm() / 2, dist = half / std::tan(s / 2);
            V2 c = mid + V2(-ab.y(), ab.x()) / ab.norm() * dist;
            Elem e = arc_from(c, a, s);
            e.b = b;
            m.M.push_back(e);
        }
        m.kind.push_back(int(i % 3));
    }
    return m;
}

// Every interval lies inside M and every gap between them outside, at the
// midpoints of the sub-intervals between all crossings (as in_M decides).
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
        ASSERT_EQ(covered, m.in_M(V2(x, Y))) << "Y " << Y << " x " << x;
    }
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
