// G46 pockets with islands (000:6078-6369; pupitre-iso(5), POCKETS): %100 POCHE AVEC ILOT
// (000:6538-6546) against its walls drawn by hand, the passes and layers
// computed by hand, and the errors 260-293.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "core/cycles/pocket46.hpp"
#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

namespace {

constexpr double kPi = std::numbers::pi;

const char* kP100 =
    "%100\nN10 G46 NU0 NP1 ED8 Q5 J.5 NR+ LX25 LY0\nN100 G46 NU1\nN110 G1 X35 Y\nN120 Y-15 "
    "EB5\nN130 X25\n"
    "N140 Y-20 EB5\nN150 X-15\nN160 G2 X-15 Y20 I-15 J\nN170 G1 X25 EB5\nN180 Y15\nN190 X35 "
    "EB5\nN200 Y\n"
    "N300 G46 NU2 LX15 LY\nN310 G1 X15 Y5\nN320 Y-5\nN330 X-15\nN340 G2 X-15 Y5 I-15 J\nN350 G1 "
    "X15\n"
    "N400 G46 NU9\nN510 T1 D1 M6\nN520 M3 M40 S1200\nN530 G46 NU10 NP1 G83 Z-9.5 P4 Q1 ER2 F300\n"
    "N600 T2 D2 M6\nN610 M3 M41 S1800\nN620 G46 NU15 NP1 Z-10 P3 ER1 EP250 EQ350\n"
    "N700 T3 D3 M6\nN710 M3 M41 S2000\nN720 G46 NU20 NP1 Z-10 P10 EH0 EI200 EJ300\nN800 G "
    "Z150\nN810 M2\n";

// The walls of %100 drawn by hand, the EB5 fillets placed on their corners:
// lines (a, b) and arcs (centre, radius, from and to angles in degrees).
struct Walls {
    struct Prim {
        bool arc;
        comp::V2 a, b;
        double r, a0, a1;
    };
    std::vector<Prim> prims;
    std::vector<comp::V2> outer, island;  // polygons every 0.05 mm for inside tests
    void line(std::vector<comp::V2>& v, double x0, double y0, double x1, double y1) {
        prims.push_back({false, {x0, y0}, {x1, y1}, 0, 0, 0});
        int n = int(std::ceil(std::hypot(x1 - x0, y1 - y0) / 0.05));
        for (int k = 0; k < n; ++k) v.emplace_back(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n);
    }
    void arc(std::vector<comp::V2>& v, double cx, double cy, double r, double a0, double a1) {
        prims.push_back({true, {cx, cy}, {0, 0}, r, a0, a1});
        int n = int(std::ceil(std::fabs(a1 - a0) * kPi / 180 * r / 0.05));
        for (int k = 0; k < n; ++k) {
            double a = (a0 + (a1 - a0) * k / n) * kPi / 180;
            v.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
        }
    }
    Walls() {
        line(outer, 35, 0, 35, -10);
        arc(outer, 30, -10, 5, 0, -90);  // N120 EB5
        line(outer, 30, -15, 25, -15);
        arc(outer, 20, -15, 5, 0, -90);  // N140 EB5 uses the whole 5 mm of N140
        line(outer, 20, -20, -15, -20);
        arc(outer, -15, 0, 20, -90, -270);  // N160, clockwise through X-35
        line(outer, -15, 20, 20, 20);
        arc(outer, 20, 15, 5, 90, 0);  // N170 EB5
        line(outer, 25, 15, 30, 15);
        arc(outer, 30, 10, 5, 90, 0);  // N190 EB5
        line(outer, 35, 10, 35, 0);
        line(island, 15, 5, 15, -5);
        line(island, 15, -5, -15, -5);
        arc(island, -15, 0, 5, -90, -270);
        line(island, -15, 5, 15, 5);
    }
    static bool in(const std::vector<comp::V2>& poly, const comp::V2& p) {
        bool c = false;
        for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
            if ((poly[i].y() > p.y()) != (poly[j].y() > p.y()) &&
                p.x() < poly[j].x() + (p.y() - poly[j].y()) * (poly[i].x() - poly[j].x()) /
                                          (poly[i].y() - poly[j].y()))
                c = !c;
        return c;
    }
    static double dist(const Prim& q, const comp::V2& p) {
        if (!q.arc) {
            comp::V2 ab = q.b - q.a;
            double t = std::clamp((p - q.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            return (q.a + t * ab - p).norm();
        }
        // Angle of p swept from a0 towards a1.
        double ang = std::atan2(p.y() - q.a.y(), p.x() - q.a.x()) * 180 / kPi;
        double lo = std::min(q.a0, q.a1), hi = std::max(q.a0, q.a1);
        while (ang < lo) ang += 360;
        while (ang > lo + 360) ang -= 360;
        if (ang <= hi) return std::fabs((p - q.a).norm() - q.r);
        auto end = [&](double a) {
            return comp::V2(q.a.x() + q.r * std::cos(a * kPi / 180),
                            q.a.y() + q.r * std::sin(a * kPi / 180));
        };
        return std::min((end(q.a0) - p).norm(), (end(q.a1) - p).norm());
    }
    double clearance(const comp::V2& p) const {
        double d = 1e300;
        for (const Prim& q : prims) d = std::min(d, dist(q, p));
        if (!in(outer, p) || in(island, p)) d = -d;
        return d;
    }
};

// Points every `step` mm along the plane path of a move, start excluded.
std::vector<comp::V2> along(const comp::V2& from, const MoveEvent& m, double step) {
    std::vector<comp::V2> pts;
    comp::V2 to(m.to_prog[X], m.to_prog[Y]);
    if (m.g == 2 || m.g == 3) {
        comp::V2 c(m.c0, m.c1);
        double r = (from - c).norm(), a0 = std::atan2(from.y() - c.y(), from.x() - c.x());
        double sw = m.sweep * kPi / 180;
        int n = std::max(1, int(std::ceil(std::fabs(sw) * r / step)));
        for (int k = 1; k <= n; ++k)
            pts.push_back(c + r * comp::V2(std::cos(a0 + sw * k / n), std::sin(a0 + sw * k / n)));
    } else {
        int n = std::max(1, int(std::ceil((to - from).norm() / step)));
        for (int k = 1; k <= n; ++k) pts.push_back(from + (to - from) * (double(k) / n));
    }
    return pts;
}

Prog p100() {
    return Prog(kP100, "mill", {{"D1.R", 5}, {"D2.R", 4}, {"D3.R", 4}});
}

}  // namespace

TEST(Pocket46, P100RunsToTheEnd) {
    Prog r = p100();
    ASSERT_EQ(r.error(), 0);
    EXPECT_EQ(r.cap.ends, 1);
    EXPECT_EQ(r.cap.tools.size(), 3u);
}

TEST(Pocket46, RoughingKeepsTheCutterOffTheWallsAndIsland) {
    Prog r = p100();
    ASSERT_EQ(r.error(), 0);
    Walls w;
    const double R = 4, J = 0.5;
    comp::V2 at(0, 0);
    int checked = 0;
    for (const MoveEvent& m : r.cap.moves) {
        comp::V2 to(m.to_prog[X], m.to_prog[Y]);
        if ((m.loc.n == 620 || m.loc.n == 720) && m.to_prog[Z] < 0 && m.g != 0) {
            const double need = m.loc.n == 620 ? R + J : R;
            for (const auto& p : along(at, m, 0.05)) {
                ASSERT_GE(w.clearance(p), need - 2e-3) << "N" << m.loc.n << " at " << p.transpose();
                ++checked;
            }
        }
        at = to;
    }
    EXPECT_GT(checked, 1000);
}

TEST(Pocket46, RoughingPassesAreEvenAndAtMostQApart) {
    Prog r = p100();
    ASSERT_EQ(r.error(), 0);
    // Tool centre band: Y from -20 + 4.5 to 20 - 4.5 = 31 mm; n = ceil(31/5) = 7
    // passes of 31/7 = 4.4286, rounded up to 4.429 (as G45), the last at 15.5.
    std::set<double> ys;
    std::set<double> zs;
    comp::V2 at(0, 0);
    for (const MoveEvent& m : r.cap.moves) {
        comp::V2 to(m.to_prog[X], m.to_prog[Y]);
        if (m.loc.n == 620 && m.g == 1 && m.to_prog[Z] < 0) {
            zs.insert(std::round(m.to_prog[Z] * 1000) / 1000);
            if (std::fabs(to.y() - at.y()) < 1e-9 && std::fabs(to.x() - at.x()) > 1e-6 &&
                std::fabs(to.y()) < 15.4)
                ys.insert(std::round(to.y() * 1000) / 1000);
        }
        at = to;
    }
    // Besides the passes, the clean-up runs straight at 9.5 about the island
    // (4.5 from its Y±5 sides) and at 10.5 in the tab (4.5 from its Y±15 sides).
    EXPECT_EQ(ys, (std::set<double>{-11.071, -10.5, -9.5, -6.642, -2.213, 2.216, 6.645, 9.5, 10.5,
                                    11.074}));
    double prev = -15.5;
    for (double y : {-11.071, -6.642, -2.213, 2.216, 6.645, 11.074}) {
        EXPECT_LE(y - prev, 5 + 1e-9);
        prev = y;
    }
    EXPECT_LE(15.5 - prev, 5 + 1e-9);
    // Layers from ER1 to Z-10 by P3: 11 mm in 4 layers of 2.75.
    EXPECT_EQ(zs, (std::set<double>{-1.75, -4.5, -7.25, -10}));
}

TEST(Pocket46, RoughingCoversTheRegion) {
    Prog r = p100();
    ASSERT_EQ(r.error(), 0);
    Walls w;
    std::vector<comp::V2> path;
    comp::V2 at(0, 0);
    for (const MoveEvent& m : r.cap.moves) {
        if (m.loc.n == 620 && m.g != 0 && std::fabs(m.to_prog[Z] + 10) < 1e-9)
            for (const auto& p : along(at, m, 0.1)) path.push_back(p);
        at = comp::V2(m.to_prog[X], m.to_prog[Y]);
    }
    ASSERT_FALSE(path.empty());
    // Every point the cutter centre may reach lies within Q/2 of the path.
    int points = 0;
    for (double x = -34.75; x <= 35; x += 1)
        for (double y = -19.75; y <= 20; y += 1) {
            comp::V2 p(x, y);
            if (w.clearance(p) < 4.5 + 0.01) continue;
            double d = 1e300;
            for (const auto& q : path) d = std::min(d, (q - p).norm());
            ASSERT_LE(d, 2.5 + 0.06) << p.transpose();
            ++points;
        }
    EXPECT_GT(points, 300);
}

TEST(Pocket46, FinishingFollowsTheContoursAtR) {
    Prog r = p100();
    ASSERT_EQ(r.error(), 0);
    std::vector<comp::V2> ends;
    int g3 = 0, g2 = 0;
    for (const MoveEvent& m : r.cap.moves) {
        if (m.loc.n != 720 || m.to_prog[Z] > -10 + 1e-9) continue;
        ends.emplace_back(m.to_prog[X], m.to_prog[Y]);
        g3 += m.g == 3;
        g2 += m.g == 2;
    }
    auto has = [&](double x, double y) {
        for (const auto& p : ends)
            if ((p - comp::V2(x, y)).norm() < 1e-6) return true;
        return false;
    };
    // Outer outline at 4 mm inside, climbing (counter-clockwise): from X31 Y0
    // (LX LY absent: the first point X35 Y0), the R20 half circle becomes R16.
    EXPECT_TRUE(has(31, 0));
    EXPECT_TRUE(has(31, 10));
    EXPECT_TRUE(has(-15, 16));
    EXPECT_TRUE(has(-15, -16));
    // The island from LX15 LY0, clockwise 4 mm outside: R5 becomes R9.
    EXPECT_TRUE(has(19, 0));
    EXPECT_TRUE(has(15, -9));
    EXPECT_TRUE(has(-15, 9));
    EXPECT_GT(g3, 3);
    EXPECT_GT(g2, 2);
}

TEST(Pocket46, DrillsAtTheStartPoint) {
    Prog r = p100();
    ASSERT_EQ(r.error(), 0);
    bool hole = false;
    for (const MoveEvent& m : r.cap.moves)
        if (m.loc.n == 530 && std::fabs(m.to_prog[Z] + 9.5) < 1e-9)
            hole = hole || (std::fabs(m.to_prog[X] - 25) < 1e-9 && std::fabs(m.to_prog[Y]) < 1e-9);
    EXPECT_TRUE(hole);
    // One hole, at LX LY of NU0 (seed 000: "the start and/or drilling point
    // for roughing"); the roughing starts there, and where it must plunge
    // elsewhere it does so with the cutter and warning 1118 says where.
    std::set<std::pair<long, long>> holes, plunges;
    comp::V2 at(0, 0);
    for (const MoveEvent& m : r.cap.moves) {
        comp::V2 to(m.to_prog[X], m.to_prog[Y]);
        auto key = std::make_pair(std::lround(to.x() * 1000), std::lround(to.y() * 1000));
        if (m.loc.n == 530 && std::fabs(m.to_prog[Z] + 9.5) < 1e-9) holes.insert(key);
        if (m.loc.n == 620 && m.g == 1 && (to - at).norm() < 1e-9 &&
            std::fabs(m.to_prog[Z] + 1.75) < 1e-9)
            plunges.insert(key);
        at = to;
    }
    EXPECT_EQ(holes, (std::set<std::pair<long, long>>{{25000, 0}}));
    EXPECT_TRUE(plunges.count({25000, 0}));
    std::string warned;
    for (const Diag& d : r.in->diags())
        if (d.code == err::wPlungeAway) warned = d.detail;
    EXPECT_EQ(plunges.size() > 1, !warned.empty()) << warned;
    if (plunges.size() > 1) {
        EXPECT_NE(warned.find("away from the hole at 25 0"), std::string::npos) << warned;
    }
}

TEST(Pocket46, PlanRespectsStepOverOnAnyRegion) {
    // A pocket with a triangular island and an arc wall, planned directly.
    p46::Def d;
    d.np = 1, d.ed = 10, d.q = 6, d.j = 0.3;
    p46::Section o;
    o.nu = 1;
    auto L = [](double x0, double y0, double x1, double y1) {
        comp::Elem e;
        e.a = {x0, y0}, e.b = {x1, y1};
        return e;
    };
    o.elems = {L(0, 0, 60, 0), L(60, 0, 60, 30)};
    comp::Elem a;
    a.arc = true, a.a = {60, 30}, a.b = {0, 30}, a.c = {30, 30}, a.sweep = kPi;
    o.elems.push_back(a);
    o.elems.push_back(L(0, 30, 0, 0));
    p46::Section t;
    t.nu = 2;
    t.elems = {L(20, 10, 40, 10), L(40, 10, 30, 30), L(30, 30, 20, 10)};
    d.sections = {o, t};
    Error err = p46::check(d);
    ASSERT_FALSE(err) << err.detail;
    std::vector<p46::Run> runs;
    std::vector<double> ys;
    err = p46::roughing(d, 5, runs, ys);
    ASSERT_FALSE(err) << err.detail;
    for (size_t i = 1; i < ys.size(); ++i) EXPECT_LE(ys[i] - ys[i - 1], 6 + 1e-9);
    EXPECT_NEAR(ys.front(), 5.3, 1e-6);
    EXPECT_NEAR(ys.back(), 60 - 5.3, 1e-6);
    p46::Region reg = p46::region(d, 5.3);
    for (const auto& run : runs) {
        comp::V2 from = run.start;
        EXPECT_GE(p46::margin(reg, from), -1e-6);
        for (const auto& pc : run.pieces) {
            if (!pc.arc) {
                for (int k = 0; k <= 100; ++k)
                    EXPECT_GE(p46::margin(reg, from + (pc.to - from) * (k / 100.0)), -1e-5);
            }
            from = pc.to;
        }
    }
}

TEST(Pocket46, FacingP200RunsToTheEnd) {
    Prog r(
        std::string(
            "%200\nN10 G46 NU0 NP1 ED16 Q10 J.5 NR+ R3\nN100 G46 NU3\nN110 G1 X Y-30\nN120 X-160 "
            "EB20\n"
            "N130 Y60 EB20\nN140 X-10 EB20\nN150 Y30 EB10\nN160 X\nN170 G2 X Y-30 I J\nN200 G46 "
            "NU4\n"
            "N210 G1 X-130 Y10\nN220 Y30 EB5\nN230 X-40 EB5\nN240 Y-10 EB5\nN250 X-130 EB5\nN260 "
            "Y10\n"
            "N300 G46 NU2\nN310 G1 X20 Y\nN320 G2 X20 Y I J\nN400 G46 NU9\nN510 T7 D7 M6\nN520 M3 "
            "M40 S1200\n"
            "N530 G46 NU15 NP1 Z-4.5 P4.5 ER2 EH0 EP300 EQ400\nN600 T8 D8 M6\nN610 M3 M41 S1500\n"
            "N620 G46 NU15 NP1 Z-5 P5 ER2 EP300 EQ400\nN700 G46 NU20 NP1 Z-5 P5 EH0 EI200 "
            "EJ300\nN800 G Z150\nN810 M2\n"),
        "mill", {{"D7.R", 8}, {"D8.R", 8}});
    ASSERT_EQ(r.error(), 0);
    // The facing reaches its outline (the cutter overruns it by its radius)
    // and keeps 8.5 from the R20 island; the island is finished at R8.
    double xmin = 0, rmin_rough = 1e300, rmin_fin = 1e300;
    comp::V2 at(0, 0);
    for (const MoveEvent& m : r.cap.moves) {
        comp::V2 from = at;
        at = comp::V2(m.to_prog[X], m.to_prog[Y]);
        if (m.g == 0 || m.to_prog[Z] > -1e-9) continue;
        for (const auto& p : along(from, m, 0.05)) {
            if (m.loc.n == 530 || m.loc.n == 620)
                xmin = std::min(xmin, p.x()), rmin_rough = std::min(rmin_rough, p.norm());
            if (m.loc.n == 700) rmin_fin = std::min(rmin_fin, p.norm());
        }
    }
    EXPECT_NEAR(xmin, -160, 1e-6);
    EXPECT_GE(rmin_rough, 28.5 - 1e-3);
    EXPECT_NEAR(rmin_fin, 28, 1e-3);
}

TEST(Pocket46, Errors) {
    const std::string def =
        "%1\nN10 G46 NU0 NP1 ED8 Q5\nN20 G46 NU1\nN30 G1 X0 Y0\nN40 X40\nN50 Y40\nN60 X0\nN70 Y0\n";
    auto run = [&](const std::string& body, const std::string& head = "") {
        return Prog(head + def + body + "\nM2\n", "mill", {{"D2.R", 4}, {"D3.R", 5}}).error();
    };
    const std::string tool = "N80 G46 NU9\nT2 D2 M6\nM3 S1000\n";
    EXPECT_EQ(run(tool + "G46 NU15 NP1 Z-5 P3 ER1 EP100 EQ100"), 0);
    EXPECT_EQ(run(tool + "G46 NU16 NP1"), 262);
    EXPECT_EQ(run(tool + "G46 NU15 NP2 Z-5 P3 ER1 EP100 EQ100"), 270);
    EXPECT_EQ(run(tool + "G46 NU15 NP1 Z-5 P3 ER1 EP100"), 268);
    EXPECT_EQ(run(tool + "G46 NU15 NP1 Z-5 P3 ER1 EI100 EP100 EQ100"), 267);
    EXPECT_EQ(run(tool + "G46 NU15 NP1 Z1 P3 ER1 EP100 EQ100"), 276);
    EXPECT_EQ(run("N80 G46 NU9\nT3 D3 M6\nM3 S1000\nG46 NU15 NP1 Z-5 P3 ER1 EP100 EQ100"), 272);
    EXPECT_EQ(run("N80 G46 NU9\nT2 D2 M6\nM4 S1000\nG46 NU15 NP1 Z-5 P3 ER1 EP100 EQ100"), 278);
    EXPECT_EQ(run(tool + "G19\nG46 NU15 NP1 Z-5 P3 ER1 EP100 EQ100"), 273);
    EXPECT_EQ(run("N80 G46 NU0 NP2 ED8 Q5"), 274);
    EXPECT_EQ(run("N80 G46 NU15 NP1 Z-5 P3 EP100 EQ100"), 270);
    EXPECT_EQ(run("N75 X5 Z3\nN80 G46 NU9"), 264);
    EXPECT_EQ(run("N75 G46 NU2\nN76 G1 X10 Y10\nN77 G0 X20 Y10\nN80 G46 NU9"), 292);
    EXPECT_EQ(run("N75 G46 NU2\nN76 G1 X10\nN80 G46 NU9"), 280);
    EXPECT_EQ(run("N75 G46 NU2\nN76 G3 X10 Y10 I5 J5\nN80 G46 NU9"), 265);
    EXPECT_EQ(run("N75 G46 NU2\nN76 G1 X10 Y10\nN77 X20\nN78 Y20\nN80 G46 NU9"), 281);
    EXPECT_EQ(run("N75 G46 NU2\nN76 G1 X10 Y10\nN77 G2 X20 Y10\nN80 G46 NU9"), 269);
    EXPECT_EQ(run("N75 G46 NU2\nN76 G1 X10 Y10\nN77 G2 X20 Y10 R4\nN80 G46 NU9"), 107);
    EXPECT_EQ(run("N75 G46 NU1\nN76 G1 X10 Y10\nN77 X20\nN78 Y20\nX10\nY10\nN80 G46 NU9"), 283);
    EXPECT_EQ(Prog("%1\nG59 X5\nG46 NU0 NP1 ED8 Q5\nM2\n").error(), 275);
    EXPECT_EQ(
        Prog("%1\nG46 NU0 NP1 ED8 Q5 EX0 EY0\nG46 NU3\nG1 X0 Y0\nX40\nY40\nX0\nY0\nG46 NU9\nM2\n")
            .error(),
        293);
    EXPECT_EQ(
        Prog("%1\nG46 NU0 NP1 ED8 Q9\nG46 NU1\nG1 X0 Y0\nX40\nY40\nX0\nY0\nG46 NU9\nM2\n").error(),
        286);
}

TEST(Pocket46, ARunStoppedInsideADefinitionDoesNotLeaveItOpen) {
    for (const char* bad : {"N40 G9 X40", "N40 x40"}) {
        Prog r(std::string("%1\nN10 G46 NU0 NP1 ED8 Q5\nN20 G46 NU1\nN30 G1 X0 Y0\n") + bad +
               "\nM2\n");
        const int first = r.error();
        EXPECT_NE(first, 0);
        r.in->raz();
        r.in->start(r.mem.first());
        r.in->run_to_end();
        for (const Diag& d : r.in->diags()) EXPECT_NE(d.code, 274) << bad;
    }
}

// %300 with N850 read as G2 X70 Y15 R5 (the seed's chord does not fit): the
// walls NU6 and the islands drawn by hand; the limits NU5 may be overrun.
TEST(Pocket46, FacingWithWallsKeepsOffTheWalls) {
    std::string text =
        "%301\nN10 G46 NU0 NP1 ED8 Q5 J.2 NR+ R3\nN100 G46 NU5\nN110 G1 X80 Y\nN120 X25\n"
        "N200 G46 NU6\nN210 X25 Y\nN220 Y10 EB-5\nN230 X\nN300 G46 NU5\nN310 X Y10\nN320 Y60\n"
        "N400 G46 NU6\nN410 X Y60\nN420 X10 Y50\nN430 X45\nN440 Y60\nN500 G46 NU5\nN510 X45 "
        "Y60\nN520 X60\n"
        "N600 G46 NU6\nN610 X60 Y60\nN620 G3 X80 Y40 I80 J60\nN700 G46 NU5\nN710 G1 X80 Y40\nN720 "
        "Y\n"
        "N800 G46 NU2\nN810 G1 X70 Y5\nN820 X45\nN830 G2 X45 Y15 R5\nN840 G1 X60 EB5\nN850 G2 X70 "
        "Y15 R5\n"
        "N860 G1 Y5\nN900 G46 NU2\nN910 G1 X30 Y30\nN920 G2 X30 Y40 R5\nN930 G1 X45\nN940 G2 X45 "
        "Y30 R5\n"
        "N950 G1 X30\nN990 G46 NU9\nN1000 T10 D10 M6\nN1010 M3 M40 S2000\n"
        "N1020 G46 NU15 NP1 Z-6 P4 ER1 EH0 EP250 EQ350\nN1100 T11 D8 M6\nN1110 M3 M41 S3000\n"
        "N1120 G46 NU20 NP1 Z-6 P6 ER1 EI350 EJ400\nN1200 G Z150\nN1210 M2\n";
    Prog r(text, "mill", {{"D10.R", 4}, {"D8.R", 4}});
    ASSERT_EQ(r.error(), 0);
    Walls w;  // reuse the distance of its primitives only
    w.prims.clear();
    auto L = [&](double x0, double y0, double x1, double y1) {
        w.prims.push_back({false, {x0, y0}, {x1, y1}, 0, 0, 0});
    };
    auto A = [&](double cx, double cy, double rr, double a0, double a1) {
        w.prims.push_back({true, {cx, cy}, {0, 0}, rr, a0, a1});
    };
    L(25, 0, 25, 5), L(25, 5, 20, 10), L(20, 10, 0, 10);     // wall 1, EB-5 chamfer
    L(0, 60, 10, 50), L(10, 50, 45, 50), L(45, 50, 45, 60);  // wall 2
    A(80, 60, 20, 180, 270);                                 // wall 3
    L(30, 40, 45, 40), L(45, 30, 30, 30), A(30, 35, 5, 90, 270), A(45, 35, 5, -90, 90);  // island 2
    // Island 1 without its EB5 fillet, which only adds material in its hollow.
    L(70, 5, 45, 5), A(45, 10, 5, 90, 270), L(45, 15, 60, 15), A(65, 15, 5, 0, 180),
        L(70, 15, 70, 5);
    comp::V2 at(0, 0);
    int n15 = 0, n20 = 0;
    for (const MoveEvent& m : r.cap.moves) {
        if ((m.loc.n == 1020 || m.loc.n == 1120) && m.to_prog[Z] < 0 && m.g != 0) {
            const double need = m.loc.n == 1020 ? 4.2 : 4;
            for (const auto& p : along(at, m, 0.05)) {
                double d = 1e300;
                for (const auto& q : w.prims) d = std::min(d, Walls::dist(q, p));
                ASSERT_GE(d, need - 2e-3) << "N" << m.loc.n << " at " << p.transpose();
                ++(m.loc.n == 1020 ? n15 : n20);
            }
        }
        at = comp::V2(m.to_prog[X], m.to_prog[Y]);
    }
    EXPECT_GT(n15, 1000);
    EXPECT_GT(n20, 300);
    // Coverage at the last roughing layer: every point of the stock (80 x 60)
    // where the cutter centre may go lies within Q/2 of its path.
    std::vector<comp::V2> path;
    at = comp::V2(0, 0);
    for (const MoveEvent& m : r.cap.moves) {
        if (m.loc.n == 1020 && m.g != 0 && std::fabs(m.to_prog[Z] + 6) < 1e-9)
            for (const auto& p : along(at, m, 0.1)) path.push_back(p);
        at = comp::V2(m.to_prog[X], m.to_prog[Y]);
    }
    auto hollow = [](const comp::V2& p) {  // inside an island or behind a wall
        bool in2 = (p.x() >= 30 && p.x() <= 45 && std::fabs(p.y() - 35) <= 5) ||
                   (p - comp::V2(30, 35)).norm() <= 5 || (p - comp::V2(45, 35)).norm() <= 5;
        bool in1 = (p.x() >= 45 && p.x() <= 70 && p.y() >= 5 && p.y() <= 15) ||
                   (p - comp::V2(45, 10)).norm() <= 5 || (p - comp::V2(65, 15)).norm() <= 5;
        bool w1 = p.y() <= 10 && p.x() <= 25 && p.x() + p.y() <= 30;
        bool w2 = p.y() >= 50 && p.x() <= 45 && p.y() >= 60 - p.x();
        bool w3 = (p - comp::V2(80, 60)).norm() <= 20;
        return in1 || in2 || w1 || w2 || w3;
    };
    int points = 0;
    for (double x = 0.25; x < 80; x += 1)
        for (double y = 0.25; y < 60; y += 1) {
            comp::V2 p(x, y);
            double d = 1e300;
            for (const auto& q : w.prims) d = std::min(d, Walls::dist(q, p));
            if (hollow(p) || d < 4.2 + 0.01) continue;
            double best = 1e300;
            for (const auto& q : path) best = std::min(best, (q - p).norm());
            ASSERT_LE(best, 2.5 + 0.06) << p.transpose();
            ++points;
        }
    EXPECT_GT(points, 1000);
}

TEST(Pocket46, RoughingEndsAtExEy) {
    Prog r(
        "%1\nG46 NU0 NP1 ED8 Q5 EX-10 EY-10\nG46 NU1\nG1 X0 Y0\nX40\nY40\nX0\nY0\nG46 NU9\nT2 D2 "
        "M6\nM3 S1000\n"
        "N50 G46 NU15 NP1 Z-5 P5 ER2 EP100 EQ100\nM2\n",
        "mill", {{"D2.R", 4}});
    ASSERT_EQ(r.error(), 0);
    const MoveEvent* last = nullptr;
    for (const MoveEvent& m : r.cap.moves)
        if (m.loc.n == 50) last = &m;
    ASSERT_NE(last, nullptr);
    EXPECT_EQ(last->g, 0);
    EXPECT_NEAR(last->to_prog[X], -10, 1e-9);
    EXPECT_NEAR(last->to_prog[Y], -10, 1e-9);
    EXPECT_NEAR(last->to_prog[Z], 2, 1e-9);
}
