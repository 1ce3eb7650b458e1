// G46 in the planes G18 (ZX) and G19 (YZ): the same pocket written in each
// plane gives the G17 toolpath with its coordinates permuted (000:4276-4300, 000:4650:
// first, second, normal axis X Y Z, Z X Y, Y Z X), drilling NU10, roughing NU15
// and finishing NU20 alike; and the errors of a pocket in the wrong plane.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

namespace {

struct PlaneWords {
    int a0, a1, an;      // first, second and normal axis
    const char* words;   // the letters of {A} {B} {N} {I} {J}
    const char* select;  // the plane and the tool along its normal
};

PlaneWords plane_words(int plane) {
    if (plane == 18) return {Z, X, Y, "ZXYKI", "G18 G16 Q+"};
    if (plane == 19) return {Y, Z, X, "YZXJK", "G19 G16 P+"};
    return {X, Y, Z, "XYZIJ", "G17"};
}

// A program written once for any plane: {A} {B} are the first and second axis
// words of the plane, {N} the normal axis (the bottom, the approach), {I} {J}
// the centre words of {A} and {B}, {PLANE} selects the plane and points the
// tool along its normal.
std::string in_plane(std::string text, int plane) {
    const PlaneWords w = plane_words(plane);
    auto replace = [&](const std::string& key, const std::string& by) {
        for (size_t at; (at = text.find(key)) != std::string::npos;)
            text.replace(at, key.size(), by);
    };
    replace("{PLANE}", w.select);
    const char* keys[] = {"{A}", "{B}", "{N}", "{I}", "{J}"};
    for (int k = 0; k < 5; ++k) replace(keys[k], std::string(1, w.words[k]));
    return text;
}

// %100 POCHE AVEC ILOT (000:6538-6546): an island, G2 circles, EB5 fillets,
// G83 drilling, roughing and finishing; with an approach from {N}50.
const char* kIsland =
    "%100\nN5 {PLANE}\nN6 G0 {A}0 {B}0 {N}50\n"
    "N10 G46 NU0 NP1 ED8 Q5 J.5 NR+ LX25 LY0\n"
    "N100 G46 NU1\nN110 G1 {A}35 {B}0\nN120 {B}-15 EB5\nN130 {A}25\nN140 {B}-20 EB5\n"
    "N150 {A}-15\nN160 G2 {A}-15 {B}20 {I}-15 {J}0\nN170 G1 {A}25 EB5\nN180 {B}15\n"
    "N190 {A}35 EB5\nN200 {B}0\n"
    "N300 G46 NU2 LX15 LY0\nN310 G1 {A}15 {B}5\nN320 {B}-5\nN330 {A}-15\n"
    "N340 G2 {A}-15 {B}5 {I}-15 {J}0\nN350 G1 {A}15\n"
    "N400 G46 NU9\n"
    "N510 T1 D1 M6\nN520 M3 M40 S1200\nN530 G46 NU10 NP1 G83 {N}-9.5 P4 Q1 ER2 F300\n"
    "N600 T2 D2 M6\nN610 M3 M41 S1800\nN620 G46 NU15 NP1 {N}-10 P3 ER1 EP250 EQ350\n"
    "N700 T3 D3 M6\nN710 M3 M41 S2000\nN720 G46 NU20 NP1 {N}-10 P10 EH0 EI200 EJ300\n"
    "N800 G0 {N}150\nN810 M2\n";

// A pocket with an EB+6 fillet, a G3 quarter circle by its radius, an EB-3
// chamfer; conventional milling with M04 (NR- R04), the end point EX EY, G81
// drilling and a finishing allowance J.
const char* kArcs =
    "%2\nN5 {PLANE}\nN6 G0 {A}-10 {B}-10 {N}30\n"
    "N10 G46 NU0 NP2 ED10 Q6 J.3 NR- R04 LX20 LY15 EX-10 EY-10\n"
    "N20 G46 NU1 LX30 LY0\nN30 G1 {A}0 {B}0\nN40 {A}60 EB+6\nN50 {B}20\nN60 G3 {A}40 {B}40 R20\n"
    "N70 G1 {A}0 EB-3\nN80 {B}0\n"
    "N90 G46 NU9\n"
    "N510 T1 D1 M6\nN520 M4 M40 S1200\nN530 G46 NU10 NP2 G81 {N}-8 ER2 F200\n"
    "N600 T2 D2 M6\nN610 M4 M41 S1800\nN620 G46 NU15 NP2 {N}-8 P4 ER2 EH0 EP200 EQ300\n"
    "N700 T3 D3 M6\nN710 M4 M41 S2000\nN720 G46 NU20 NP2 {N}-8 P4 ER2 EI150 EJ250 J.1\n"
    "N800 G0 {N}100\nN810 M2\n";

Prog run(const char* text, int plane, std::vector<std::pair<std::string, double>> sets) {
    return Prog(in_plane(text, plane), "mill", std::move(sets));
}

// The moves of `other` (G18 or G19) are those of `g17` with X Y Z read as the
// first, second and normal axis of its plane, to 1 µm; arcs turn the same way
// about the same centre.
void expect_permuted(const Prog& g17, const Prog& other, int plane) {
    const PlaneWords w = plane_words(plane);
    ASSERT_EQ(g17.error(), 0);
    ASSERT_EQ(other.error(), 0);
    const auto& a = g17.cap.moves;
    const auto& b = other.cap.moves;
    ASSERT_EQ(a.size(), b.size());
    int n530 = 0, n620 = 0, n720 = 0, arcs = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const MoveEvent &p = a[i], &q = b[i];
        SCOPED_TRACE("move " + std::to_string(i) + " of N" + std::to_string(p.loc.n) + " in G" +
                     std::to_string(plane));
        ASSERT_EQ(p.loc.n, q.loc.n);
        ASSERT_EQ(p.g, q.g);
        EXPECT_NEAR(q.to_prog[size_t(w.a0)], p.to_prog[X], 1e-3);
        EXPECT_NEAR(q.to_prog[size_t(w.a1)], p.to_prog[Y], 1e-3);
        EXPECT_NEAR(q.to_prog[size_t(w.an)], p.to_prog[Z], 1e-3);
        if (p.g != 0) {
            EXPECT_NEAR(q.feed, p.feed, 1e-9);
        }
        if (p.g == 2 || p.g == 3) {
            EXPECT_EQ(p.plane_a0, X);
            EXPECT_EQ(p.plane_a1, Y);
            EXPECT_EQ(q.plane_a0, w.a0);
            EXPECT_EQ(q.plane_a1, w.a1);
            EXPECT_NEAR(q.c0, p.c0, 1e-3);
            EXPECT_NEAR(q.c1, p.c1, 1e-3);
            EXPECT_NEAR(q.sweep, p.sweep, 1e-6);
            ++arcs;
        }
        n530 += p.loc.n == 530;
        n620 += p.loc.n == 620;
        n720 += p.loc.n == 720;
    }
    // Drilling, roughing and finishing all moved, finishing along arcs.
    EXPECT_GT(n530, 3);
    EXPECT_GT(n620, 20);
    EXPECT_GT(n720, 5);
    EXPECT_GT(arcs, 4);
}

const std::vector<std::pair<std::string, double>> kIslandTools = {
    {"D1.R", 5}, {"D2.R", 4}, {"D3.R", 4}};
const std::vector<std::pair<std::string, double>> kArcsTools = {
    {"D1.R", 3}, {"D2.R", 5}, {"D3.R", 5}};

}  // namespace

TEST(Pocket46Planes, IslandPocketInG18IsTheG17PocketOnZX) {
    expect_permuted(run(kIsland, 17, kIslandTools), run(kIsland, 18, kIslandTools), 18);
}

TEST(Pocket46Planes, IslandPocketInG19IsTheG17PocketOnYZ) {
    expect_permuted(run(kIsland, 17, kIslandTools), run(kIsland, 19, kIslandTools), 19);
}

TEST(Pocket46Planes, ArcsFilletAndChamferInG18AndG19) {
    const Prog g17 = run(kArcs, 17, kArcsTools);
    expect_permuted(g17, run(kArcs, 18, kArcsTools), 18);
    expect_permuted(g17, run(kArcs, 19, kArcsTools), 19);
}

// The G17 template is the seed's %100 as the golden trace and the other tests
// run it: the template does not hide a change of the G17 toolpath.
TEST(Pocket46Planes, TheG17TemplateIsTheSeedPocket) {
    const Prog r = run(kIsland, 17, kIslandTools);
    ASSERT_EQ(r.error(), 0);
    bool hole = false, fin = false;
    for (const MoveEvent& m : r.cap.moves) {
        hole = hole || (m.loc.n == 530 && std::fabs(m.to_prog[X] - 25) < 1e-9 &&
                        std::fabs(m.to_prog[Y]) < 1e-9 && std::fabs(m.to_prog[Z] + 9.5) < 1e-9);
        fin = fin || (m.loc.n == 720 && std::fabs(m.to_prog[X] + 15) < 1e-9 &&
                      std::fabs(m.to_prog[Y] - 16) < 1e-9 && std::fabs(m.to_prog[Z] + 10) < 1e-9);
    }
    EXPECT_TRUE(hole);  // drilled at LX25 LY0
    EXPECT_TRUE(fin);   // the R20 half circle finished at R16
}

// LX LY are the first and second coordinates of the plane (Z X in G18), EX EY
// the end of roughing in the same order; the bottom, ER and EH are on the
// normal axis, and the tool gauge applies along it (G16 Q+).
TEST(Pocket46Planes, StartEndAndBottomWordsInG18) {
    auto tools = kArcsTools;
    tools.push_back({"D2.L", 100});
    const Prog r = run(kArcs, 18, tools);
    ASSERT_EQ(r.error(), 0);
    const MoveEvent* first_plunge = nullptr;
    const MoveEvent* last = nullptr;
    double deepest = 1e300;
    for (const MoveEvent& m : r.cap.moves) {
        if (m.loc.n != 620) continue;
        if (!first_plunge && m.g == 1) first_plunge = &m;
        last = &m;
        deepest = std::min(deepest, m.to_prog[Y]);
        EXPECT_NEAR(m.to_mach[Y] - m.to_prog[Y], 100, 1e-9);
        EXPECT_NEAR(m.to_mach[Z] - m.to_prog[Z], 0, 1e-9);
    }
    ASSERT_NE(first_plunge, nullptr);
    EXPECT_NEAR(first_plunge->to_prog[Z], 20, 1e-9);  // LX20
    EXPECT_NEAR(first_plunge->to_prog[X], 15, 1e-9);  // LY15
    EXPECT_NEAR(first_plunge->to_prog[Y], -4, 1e-9);  // EH0 to Y-8 by P4
    EXPECT_NEAR(deepest, -8, 1e-9);
    ASSERT_NE(last, nullptr);
    EXPECT_EQ(last->g, 0);
    EXPECT_NEAR(last->to_prog[Z], -10, 1e-9);  // EX-10
    EXPECT_NEAR(last->to_prog[X], -10, 1e-9);  // EY-10
    EXPECT_NEAR(last->to_prog[Y], 2, 1e-9);    // at ER2
}

TEST(Pocket46Planes, Errors) {
    // A square pocket in any plane, then the tool, then `tail`.
    const std::string def =
        "%1\nN5 {PLANE}\nN10 G46 NU0 NP1 ED8 Q5\nN20 G46 NU1 LX20 LY0\n"
        "N30 G1 {A}0 {B}0\nN40 {A}40\nN50 {B}40\nN60 {A}0\nN70 {B}0\nN80 G46 NU9\n"
        "N90 T2 D2 M6\nN95 M3 S1000\n";
    auto err = [&](int plane, const std::string& tail, const std::string& contour = "") {
        std::string text = def;
        if (!contour.empty()) text.replace(text.find("N80"), 0, contour + "\n");
        return Prog(in_plane(text + tail + "\nM2\n", plane), "mill", {{"D2.R", 4}}).error();
    };
    const std::string order = "N100 G46 NU15 NP1 {N}-5 P3 ER1 EP100 EQ100";
    for (int plane : {17, 18, 19}) {
        SCOPED_TRACE("G" + std::to_string(plane));
        EXPECT_EQ(err(plane, order), 0);
        EXPECT_EQ(err(plane, "N100 G46 NU10 NP1 G81 {N}-5 ER1 F100"), 0);
        EXPECT_EQ(err(plane, "N100 G46 NU20 NP1 {N}-5 P5 ER1 EI100 EJ100"), 0);
        // The plane changed between the definition and the order.
        for (int other : {17, 18, 19})
            if (other != plane) {
                EXPECT_EQ(err(plane, "N99 G" + std::to_string(other) + "\n" + order), 273);
            }
        // The bottom is the normal axis: a plane coordinate is 267, none is 268.
        EXPECT_EQ(err(plane, "N100 G46 NU15 NP1 {A}-5 P3 ER1 EP100 EQ100"), 267);
        EXPECT_EQ(err(plane, "N100 G46 NU15 NP1 {B}-5 P3 ER1 EP100 EQ100"), 267);
        EXPECT_EQ(err(plane, "N100 G46 NU10 NP1 G83 {A}-5 P2 ER1 F100"), 267);
        EXPECT_EQ(err(plane, "N100 G46 NU15 NP1 P3 ER1 EP100 EQ100"), 268);
        EXPECT_EQ(err(plane, "N100 G46 NU15 NP1 {N}2 P3 ER1 EP100 EQ100"), 276);
        // The tool along the negative normal is refused as in G17.
        EXPECT_EQ(
            err(plane, "N99 G16 " + std::string(1, "PQR"[plane_words(plane).an]) + "-\n" + order),
            271);
        // The normal axis and its centre word are outside the contouring plane.
        EXPECT_EQ(err(plane, order, "N75 G46 NU2\nN76 G1 {A}10 {B}10 {N}5\nN77 {A}20"), 264);
        const std::string normal_centre(1, "IJK"[plane_words(plane).an]);
        EXPECT_EQ(err(plane, order,
                      "N75 G46 NU2\nN76 G1 {A}10 {B}10\nN77 {A}20\n"
                      "N78 G2 {A}10 {B}10 {I}15 {J}10 " +
                          normal_centre + "0"),
                  264);
        EXPECT_EQ(err(plane, order, "N75 G46 NU2\nN76 G1 {A}10"), 280);
    }
    // The G17 words where they do not belong in G18 and G19.
    EXPECT_EQ(err(18, "N100 G46 NU15 NP1 Z-5 P3 ER1 EP100 EQ100"), 267);
    EXPECT_EQ(err(19, "N100 G46 NU15 NP1 Z-5 P3 ER1 EP100 EQ100"), 267);
    EXPECT_EQ(err(18, order, "N75 G46 NU2\nN76 G1 X10 Y10"), 264);
    // G18 and G19 without the tool along their normal (G16 R+ at power-on).
    for (const char* select : {"G18 G16 Q+", "G19 G16 P+"}) {
        std::string text = in_plane(def + order + "\nM2\n", select[2] == '8' ? 18 : 19);
        text.replace(text.find(select), std::string(select).size(), std::string(select, 3));
        EXPECT_EQ(Prog(text, "mill", {{"D2.R", 4}}).error(), 271) << select;
    }
}

// A plane in a G46 block would be ignored (G46 blocks run no modal function):
// it is refused unless it is the plane in force.
TEST(Pocket46Planes, PlaneInAG46Block) {
    const std::string square =
        "G46 NU1 LX20 LY0\nG1 {A}0 {B}0\n{A}40\n{B}40\n{A}0\n{B}0\nG46 NU9\n";
    const std::string order = "T2 D2 M6\nM3 S1000\n{P}G46 NU15 NP1 {N}-5 P3 ER1 EP100 EQ100\nM2\n";
    auto err = [&](int plane, const std::string& head, const std::string& p = "") {
        std::string text = in_plane("%1\n" + head + "G46 NU0 NP1 ED8 Q5\n" + square + order, plane);
        text.replace(text.find("{P}"), 3, p);
        return Prog(text, "mill", {{"D2.R", 4}}).error();
    };
    EXPECT_EQ(err(17, "G17 "), 0);
    EXPECT_EQ(err(17, "G18 "), 279);
    EXPECT_EQ(err(18, "{PLANE}\nG18 "), 0);
    EXPECT_EQ(err(18, "{PLANE}\nG19 "), 279);
    EXPECT_EQ(err(18, "{PLANE}\n", "G17 "), 279);
    // The plane in force in an order is another G there, as G17 G46 NU15 in G17.
    EXPECT_EQ(err(18, "{PLANE}\n", "G18 "), 267);
    EXPECT_EQ(err(17, "", "G17 "), 267);
}

// G46 is a machining-centre function: the lathe, whose only plane is G18,
// refuses it rather than running it in ZX.
TEST(Pocket46Planes, TheLatheHasNoG46) {
    EXPECT_EQ(Prog("%1\nG46 NU0 NP1 ED8 Q5\nM2\n", "lathe").error(), 2);
    EXPECT_EQ(Prog("%1\nG18\nG46 NU0 NP1 ED8 Q5\nM2\n", "lathe").error(), 2);
}
