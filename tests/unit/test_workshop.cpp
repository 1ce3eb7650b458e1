// The workshop against parts worked out by hand (issue 15): the setup file,
// the material, contacts and crashes, the instruments. The shipped lathe
// setup's truth: the axis at X -20 (radius), the stock's face at Z 35, T1's
// gauge X 52.347 Z 41.215, nose radius 0.8, C3 (data/setups/lathe.setup).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/interp/interp.hpp"
#include "core/training/exercise.hpp"
#include "core/workshop/report.hpp"
#include "core/workshop/workshop.hpp"
#include "workshop_run.hpp"

namespace pupitre {
namespace data {
std::string_view setup_lathe();
}

namespace workshop {
namespace {

// A program run in the workshop of the shipped lathe setup, changed by
// `extra` setup lines, with the operator's values `sets`.
struct Shop : test::ShopRun {
    Shop(const std::string& program, const test::Sets& sets, const std::string& extra = "")
        : ShopRun("lathe", program, sets, extra) {}
};

// The operator's values that match the truth.
std::vector<std::pair<std::string, double>> right(double pref_x = -20, double pref_z = 35,
                                                  double d1x = 52.347, double d1z = 41.215) {
    return {{"PREF.X", pref_x}, {"PREF.Z", pref_z}, {"D1.X", d1x}, {"D1.Z", d1z}};
}

const char* kTurn = R"(%10
N10 T1 D1 M6
N20 S1000 M3
N30 G95 F0.2
N40 G0 X56 Z2
N50 G1 Z-40
N60 X62
N70 G0 Z2
N80 X50
N90 G1 Z-20
N100 X58
N110 G0 X100 Z50
N120 M2
)";

TEST(Setup, ShippedLatheParses) {
    workshop::Setup s;
    ASSERT_TRUE(builtin_setup("lathe", s));
    EXPECT_EQ(s.name, "lathe");
    EXPECT_DOUBLE_EQ(s.lathe.axis_x, -20);
    EXPECT_DOUBLE_EQ(s.lathe.chuck_z + s.lathe.stickout, 35);
    ASSERT_NE(s.tool(1), nullptr);
    EXPECT_DOUBLE_EQ(s.tool(1)->x, 52.347);
    EXPECT_EQ(s.tool(3)->orientation, 2);
    EXPECT_EQ(s.tool(9), nullptr);
}

// The Cazeneuve's: both turrets (003:1028-1030), the rear one beyond the
// axis on the same cross-slide, each rear nose touching above its centre.
TEST(Setup, ShippedCazeneuveHasBothTurrets) {
    workshop::Setup s;
    ASSERT_TRUE(builtin_setup("cazeneuve", s));
    EXPECT_EQ(s.kind, "lathe");
    EXPECT_DOUBLE_EQ(s.lathe.axis_x, 0);
    EXPECT_DOUBLE_EQ(s.lathe.chuck_z + s.lathe.stickout, 35);
    for (int t : {1, 2, 3, 4, 11, 12, 13, 14}) {
        ASSERT_NE(s.tool(t), nullptr) << t;
        if (t > 10) {
            EXPECT_GT(s.tool(t)->x, 300) << t;
            EXPECT_EQ(s.tool(t)->orientation, 2) << t;
        }
    }
    EXPECT_EQ(s.tool(5), nullptr);
}

// tool.N = none takes a tool out (an exercise's truth, after the built-in
// setup: seed 004's exam has one tool).
TEST(Setup, AToolTakenOut) {
    workshop::Setup base, s;
    ASSERT_TRUE(builtin_setup("lathe", base));
    ASSERT_EQ(parse_setup(base.source + "tool.2 = none\ntool.4 = none\n", s), "");
    EXPECT_NE(s.tool(1), nullptr);
    EXPECT_EQ(s.tool(2), nullptr);
    EXPECT_NE(s.tool(3), nullptr);
    EXPECT_EQ(s.tool(4), nullptr);
    EXPECT_EQ(parse_setup("kind = lathe\ntool.2 = gone\n", s),
              "line 2: tool.2: expected tool.N = none, or tool.N.FIELD = value");
    EXPECT_EQ(parse_setup("kind = lathe\ntool.0 = none\n", s),
              "line 2: tool.0: expected tool.N.FIELD with N from 1 to 99");
    training::Exercise e;
    workshop::Setup exam;
    ASSERT_TRUE(training::builtin_exercise("exam-2005", e));
    ASSERT_EQ(training::draw_setup(e, 1, exam), "");
    ASSERT_EQ(exam.tools.size(), 1u);
    EXPECT_EQ(exam.tools[0].position, 1);
}

TEST(Setup, ErrorsNameTheLine) {
    workshop::Setup s;
    EXPECT_EQ(parse_setup("kind = lathe\nstock.diameter = abc\n", s),
              "line 2: stock.diameter: expected a number");
    EXPECT_EQ(parse_setup("kind = lathe\nfoo = 1\n", s), "line 2: foo: unknown key 'foo'");
    EXPECT_EQ(parse_setup("kind = lathe\ntool.0.x = 1\n", s),
              "line 2: tool.0.x: expected tool.N.FIELD with N from 1 to 99");
    EXPECT_EQ(parse_setup("kind = lathe\ntool.1.orientation = 2.5\n", s),
              "line 2: tool.1.orientation: must be a whole number from 0 to 8");
    EXPECT_EQ(parse_setup("kind = lathe\nstock.bore = 70\n", s),
              "stock.bore must be smaller than stock.diameter");
    // The kind says what the keys mean, so it comes first (name and
    // description may precede it).
    EXPECT_EQ(parse_setup("stock.diameter = 10\n", s),
              "line 1: stock.diameter: kind = lathe or kind = mill must come first");
    EXPECT_EQ(parse_setup("name = x\n", s), "kind = lathe or kind = mill is missing");
    EXPECT_EQ(parse_setup("kind = drill\n", s), "line 1: kind: expected lathe or mill");
    EXPECT_EQ(parse_setup("kind = lathe\nkind = mill\n", s),
              "line 2: kind: kind is given twice, differently");
    EXPECT_EQ(parse_setup("kind = lathe\ntool.1.radius = 12\n", s),
              "line 2: tool.1.radius: must be from 0 to 10");
    EXPECT_EQ(parse_setup("kind = lathe\njaw.height\n", s), "line 2: expected key = value");
    EXPECT_EQ(parse_setup("kind = lathe\ntool.2.holder = 1,2 3\n", s),
              "line 2: tool.2.holder: expected points as Z,X Z,X Z,X");
    EXPECT_EQ(s.name, "");  // nothing half-read
}

TEST(Workshop, RightValuesTurnTheDrawing) {
    Shop s(kTurn, right());
    EXPECT_EQ(s.crash(), 0);
    EXPECT_DOUBLE_EQ(s.read("dia Z-10"), 50.000);
    EXPECT_DOUBLE_EQ(s.read("dia Z-30"), 56.000);
    EXPECT_DOUBLE_EQ(s.read("dia Z-50"), 60.000);
    EXPECT_DOUBLE_EQ(s.read("length"), 95.00);
}

TEST(Workshop, PrefXWrongByATenthMakesEveryDiameterTwoTenthsLarger) {
    // PREF X is a radius: +0.1 puts the tool 0.1 further from the axis.
    Shop s(kTurn, right(-19.9));
    EXPECT_DOUBLE_EQ(s.read("dia Z-10"), 50.200);
    EXPECT_DOUBLE_EQ(s.read("dia Z-30"), 56.200);
}

TEST(Workshop, ZGaugeOffMovesEveryFace) {
    // Facing 1 mm off the stock, then a shoulder 20 mm from the program's Z0.
    const char* face = R"(%11
N10 T1 D1 M6
N20 S1000 M3 G95 F0.2
N30 G0 X64 Z-1
N40 G1 X-2
N50 G0 Z2
N60 X50
N70 G1 Z-20
N80 X62
N90 G0 X100 Z50
N100 M2
)";
    Shop good(face, right());
    EXPECT_DOUBLE_EQ(good.read("length"), 94.00);
    // The gauge entered 0.05 too long: the tool really stops 0.05 short (+Z).
    Shop off(face, right(-20, 35, 52.347, 41.265));
    EXPECT_DOUBLE_EQ(off.read("length"), 94.05);
    // The shoulder moved with the face: 19 mm from it, Ø50 before, Ø60 after.
    EXPECT_DOUBLE_EQ(off.read("dia Z-18"), 50.000);
    EXPECT_DOUBLE_EQ(off.read("dia Z-20"), 60.000);
    EXPECT_EQ(off.crash(), 0);
}

TEST(Workshop, UncompensatedNoseLeavesItsCuspOnATaper) {
    // A 45° chamfer followed by the tool point P with no G41/G42: the nose
    // (r 0.8, C3) stands r·(√2 - 1) off the line, R + r·(2 - √2) at any Z:
    // the diameter is 2·0.8·(2 - √2) = 0.937 too large in the middle.
    const char* taper = R"(%12
N10 T1 D1 M6
N20 S1000 M3 G95 F0.2
N30 G0 X48 Z2
N40 G1 Z0
N50 X56 Z-4
N60 Z-30
N70 X62
N80 G0 X100 Z50
N90 M2
)";
    Shop s(taper, right());
    ASSERT_EQ(s.crash(), 0);
    // The nose is a polygon inscribed within kChord: on a 45° flank the
    // surface may stand kChord·√2 higher on the radius, plus the rounding.
    EXPECT_NEAR(s.read("dia Z-2"), 52 + 1.6 * (2 - std::sqrt(2.0)),
                2 * std::sqrt(2.0) * kChord + 0.0005);
    EXPECT_DOUBLE_EQ(s.read("dia Z-20"), 56.000);
}

TEST(Workshop, WornToolLeavesMaterial) {
    // 1000 µm per metre: the first pass (G1 Z2 -> Z-50, 52 mm) wears 0.052 mm,
    // along C3's bisector: R + 0.052/√2 on the second pass.
    const char* two = R"(%13
N10 T1 D1 M6
N20 S1000 M3 G95 F0.2
N30 G0 X56 Z2
N40 G1 Z-50
N50 G0 X62
N60 Z2
N70 X50
N80 G1 Z-20
N90 G0 X100 Z50
N100 M2
)";
    Shop s(two, right(), "tool.1.wear = 1000\n");
    ASSERT_EQ(s.setup_error, "");
    EXPECT_NEAR(s.shop->cut_length(1), 52 + 50.0 / 1, 60);  // both passes cut
    EXPECT_NEAR(s.read("dia Z-10"), 50 + 2 * 0.052 / std::sqrt(2.0), 0.0006);
}

TEST(Workshop, RapidIntoThePartIsACrashThatStopsAtTheContact) {
    // PREF Z entered as 25 instead of 35: the approach X56 Z2 ends 8 mm
    // inside the bar, and the rapid from the turret's start position (tool
    // point R 97.6, Z 158.8) enters it through Ø60.
    Shop s(kTurn, right(-20, 25));
    ASSERT_EQ(s.crash(), kCrashRapid);
    const Crash& c = s.shop->crashes().front();
    EXPECT_EQ(c.loc.n, 40);
    // G0 X56 Z2 from the home position: the tool point reaches the bar's
    // Ø60 first; the machine stops with the insert just into it.
    Pt p = s.shop->tip(c.om);
    // Stopped as the nose entered the bar through its Ø60: P, the nose's
    // lowest point for C3, is on the line to Z 27 R 28, just below R 30.
    EXPECT_NEAR(p[1], 30, 0.01);
    EXPECT_GT(p[0], 27);
    EXPECT_NE(c.what.find("rapid (G0) into the part"), std::string::npos);
}

TEST(Workshop, FeedWithTheSpindleStoppedIsACrash) {
    std::string p = kTurn;
    p.replace(p.find("S1000 M3"), 8, "S1000 M5");
    p.replace(p.find("G95 F0.2"), 8, "G94 F100");
    Shop s(p, right());
    EXPECT_EQ(s.crash(), kCrashStopped);
    EXPECT_EQ(s.shop->crashes().front().loc.n, 50);
}

TEST(Workshop, WrongSpindleDirectionForTheToolIsACrash) {
    Shop s(kTurn, right(), "tool.1.spindle = M4\n");
    EXPECT_EQ(s.crash(), kCrashDirection);
}

TEST(Workshop, TheChuckStopsTheTool) {
    std::string p = kTurn;
    p.replace(p.find("G1 Z-40"), 7, "G1 Z-99");
    Shop s(p, right());
    ASSERT_EQ(s.crash(), kCrashChuck);
    // The jaws grip the bar at Ø60, their face 95 mm from the stock's face:
    // the insert's leading edge, square above the nose, meets it when P
    // reaches it.
    Pt at = s.shop->tip(s.shop->crashes().front().om);
    EXPECT_NEAR(at[0] - 35, -95.0, 0.003);
}

TEST(Workshop, TooDeepACutBringsTheHolderIn) {
    // Ø60 -> Ø34 in one pass: 13 mm of radius, more than the insert's 10.8.
    std::string p = kTurn;
    p.replace(p.find("X56 Z2"), 6, "X34 Z2");
    Shop s(p, right());
    EXPECT_EQ(s.crash(), kCrashHolder);
}

TEST(Workshop, TheTailstockStopsTheTool) {
    // A centre at Z 45 (10 mm beyond the bar's face); the approach rapid
    // X20 Z12 would take the insert through the centre's cone.
    const char* p = R"(%15
N10 T1 D1 M6
N20 S1000 M3 G95 F0.2
N30 G0 X20 Z12
N40 M2
)";
    Shop s(p, right(), "tailstock.z = 45\n");
    ASSERT_EQ(s.setup_error, "");
    ASSERT_EQ(s.crash(), kCrashChuck);
    EXPECT_NE(s.shop->crashes().front().what.find("the tailstock"), std::string::npos)
        << s.shop->crashes().front().what;
}

TEST(Workshop, ProbeDrivenIntoThePartIsACrash) {
    Shop s(kTurn, right(), "tool.1.probe = yes\n");
    EXPECT_EQ(s.crash(), kCrashProbe);
}

TEST(Workshop, SharpToolFollowsAnArcExactly) {
    // A point tool (r 0) traces the programmed arc: G2 (clockwise, X up)
    // from Ø50 Z0 to Ø60 Z-5 with R5 is the concave quarter about Ø60 Z0:
    // R(z) = 30 - √(25 - z²), at z = -2.5: 30 - √18.75.
    const char* arc = R"(%14
N10 T1 D1 M6
N20 S1000 M3 G95 F0.2
N30 G0 X50 Z2
N40 G1 Z0
N50 G2 X60 Z-5 R5
N60 G1 X62
N70 G0 X100 Z50
N80 M2
)";
    Shop s(arc, right(), "tool.1.radius = 0\n");
    ASSERT_EQ(s.crash(), 0);
    // Within the path's chord error (0.5 µm on the radius, 1 µm on the
    // diameter) and the micrometer's rounding (0.5 µm).
    EXPECT_NEAR(s.read("dia Z-2.5"), 2 * (30 - std::sqrt(18.75)), 2 * kChord + 0.0005 + 1e-9);
}

TEST(Instruments, BoreGrooveAndErrors) {
    workshop::Setup st;
    ASSERT_EQ(parse_setup(std::string(data::setup_lathe()) + "\nstock.bore = 20\n", st), "");
    MachineProfile m;
    builtin_machine("lathe", m);
    Workshop w(m, st, nullptr);
    // A groove 4 mm wide, 3 deep, 10 mm from the face (Z 35).
    CPaths g{{to_int({21, 27}), to_int({25, 27}), to_int({25, 31}), to_int({21, 31})}};
    w.world().cut(g);
    Reading r;
    EXPECT_EQ(w.measure("bore Z-5", r), "");
    EXPECT_DOUBLE_EQ(r.value, 20.000);
    EXPECT_EQ(w.measure("groove Z-12", r), "");
    EXPECT_DOUBLE_EQ(r.value, 4.00);
    EXPECT_EQ(r.instrument, "caliper");
    EXPECT_EQ(w.measure("dia Z-12", r), "");
    EXPECT_DOUBLE_EQ(r.value, 54.000);
    EXPECT_EQ(w.measure("groove Z-5", r), "no groove there: Z must be on a groove's bottom");
    EXPECT_EQ(w.measure("dia Z5", r),
              "Z is measured from the part's right-hand face: a negative distance (Z-20)");
    EXPECT_EQ(w.measure("dia", r), "dia needs a Z: how far from the part's right-hand face (Z-20)");
    EXPECT_EQ(w.measure("dia Z-200", r), "no material there");
    EXPECT_EQ(w.measure("weight", r),
              "expected dia Z-n, bore Z-n, groove Z-n, length or tool Tn X|Z|R");
    EXPECT_EQ(w.measure("length Z-3", r), "length takes no Z");
}

// A jog of T1 straight down onto the bar's Ø60, 20 mm from its face.
MoveEvent jog_down(double from_r, double to_r) {
    MoveEvent e;
    e.g = 1;
    e.from_mach[Z] = e.to_mach[Z] = 35 - 20 + 41.215;
    e.from_mach[X] = from_r + 52.347 - 20;
    e.to_mach[X] = to_r + 52.347 - 20;
    e.to_prog = e.to_mach;
    e.length = std::abs(from_r - to_r);
    return e;
}

// The shipped lathe's workshop with T1 in place, the spindle stopped.
struct T1OnTheLathe {
    workshop::Setup st;
    MachineProfile m;
    std::unique_ptr<Workshop> shop;
    T1OnTheLathe() {
        builtin_setup("lathe", st);
        builtin_machine("lathe", m);
        shop = std::make_unique<Workshop>(m, st, nullptr);
        shop->tool(Loc{}, 1, 1, 0, true);
    }
};

// T1's point at radius r, from Z z0 to z1 (the shipped lathe's truth).
MoveEvent jog_along_z(double r, double z0, double z1) {
    MoveEvent e;
    e.g = 1;
    e.from_mach[X] = e.to_mach[X] = r + 52.347 - 20;
    e.from_mach[Z] = z0 + 41.215;
    e.to_mach[Z] = z1 + 41.215;
    e.to_prog = e.to_mach;
    e.length = std::abs(z1 - z0);
    return e;
}

// Issue 38: a 40 mm gauge block on the bar's face (Z 35) is a body between
// the point and the face along the jog, not the insert grown all round: the
// point stops 40 before the face wherever it stands over the face, and a
// point beside the bar (radius 31, the bar's 30) meets nothing.
TEST(Contacts, AShimLiesAlongTheApproachNotAllRound) {
    T1OnTheLathe t1;
    Workshop& w = *t1.shop;
    w.set_shim(40);
    for (double r : {5.0, 20.0, 29.0}) {
        Outcome o = w.jog(jog_along_z(r, 100, 60), true);
        ASSERT_TRUE(o.touched) << r;
        EXPECT_NEAR(w.tip(o.stop)[0], 75, 3e-4) << r;
        EXPECT_NE(o.what.find("touched the 40.000 mm shim"), std::string::npos) << o.what;
    }
    EXPECT_FALSE(w.jog(jog_along_z(31, 100, 60), true).touched);
    // A step back from the block is no step into it.
    Outcome back = w.jog(jog_along_z(20, 75, 76), false);
    EXPECT_FALSE(back.touched) << back.what;
}

TEST(Contacts, AJogStopsAtTheDiameterAndAShimStopsItAShimEarly) {
    T1OnTheLathe t1;
    Workshop& w = *t1.shop;
    Outcome o = w.jog(jog_down(40, 20), true);
    ASSERT_TRUE(o.touched);
    // P (the nose's bottom for C3) stops before entering, within the
    // contact's resolution (0.1 µm of thickness, about 0.2 µm deep).
    EXPECT_NEAR(w.tip(o.stop)[1], 30, 3e-4);
    EXPECT_NE(o.what.find("T1 touched the part at \u00f860.000, -20.000 mm"), std::string::npos)
        << o.what;
    // The paper test: a 0.05 shim on the part.
    w.set_shim(0.05);
    o = w.jog(jog_down(40, 20), true);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(w.tip(o.stop)[1], 30.05, 3e-4);
    EXPECT_NE(o.what.find("touched the 0.050 mm shim"), std::string::npos) << o.what;
    // From there an increment does not cut through the shim.
    Outcome inc = w.jog(jog_down(w.tip(o.stop)[1], w.tip(o.stop)[1] - 0.1), false);
    EXPECT_TRUE(inc.touched);
    EXPECT_EQ(inc.fraction, 0);
    EXPECT_NE(inc.what.find(":shim off"), std::string::npos);
    // Without the shim the same increment cuts (the spindle turns).
    w.set_shim(0);
    SpindleEvent on;
    on.dir = 3;
    on.rpm = 800;
    w.spindle(on);
    double r = w.tip(o.stop)[1];
    inc = w.jog(jog_down(r, 29.9), false);  // an increment stops at the part first
    ASSERT_TRUE(inc.touched);
    r = w.tip(inc.stop)[1];
    inc = w.jog(jog_down(r, 29.9), false);  // then cuts
    EXPECT_FALSE(inc.touched);
    EXPECT_FALSE(inc.crashed);
    // The nose (r 0.8) is lowest under its centre, 0.8 from P along +Z.
    Reading rd;
    ASSERT_EQ(w.measure("dia Z-19.2", rd), "");
    EXPECT_DOUBLE_EQ(rd.value, 59.8);
}

// T1's P at R 35, over a gauge block on the jaws, from Z 120 to Z 20 (G`g`).
MoveEvent over_the_gauge_block(int g) {
    MoveEvent e;
    e.g = g;
    e.from_mach[X] = e.to_mach[X] = 35 + 52.347 - 20;
    e.from_mach[Z] = 120 + 41.215;
    e.to_mach[Z] = 20 + 41.215;
    e.to_prog = e.to_mach;
    return e;
}

// Seed 004's exam: a 100 mm gauge block against the jaws' face (chuck.z
// -60, so its end is at Z 40), 2 to 11 mm above the Ø60 bar (R 32 to 41).
TEST(Contacts, AGaugeBlockOnTheJawsStopsTheJogAtItsEnd) {
    T1OnTheLathe t1;
    Workshop& w = *t1.shop;
    w.set_gauge_block(100);
    // T1 (C3: P is the nose's lowest Z) at R 35, from Z 120 towards the chuck.
    const MoveEvent e = over_the_gauge_block(1);
    Outcome o = w.jog(e, true);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(w.tip(o.stop)[0], 40, 3e-4);
    EXPECT_NE(o.what.find("T1 touched the 100.000 mm gauge block on the jaws' face"),
              std::string::npos)
        << o.what;
    // An increment from there does not go through it.
    MoveEvent inc = e;
    inc.from_mach = o.stop;
    inc.to_mach[Z] = o.stop[Z] - 0.1;
    Outcome step = w.jog(inc, false);
    EXPECT_TRUE(step.touched);
    EXPECT_EQ(step.fraction, 0);
    EXPECT_NE(step.what.find(":gauge off"), std::string::npos) << step.what;
    // Taken away, the same jog goes on to Z 20, over the bar: nothing there.
    w.set_gauge_block(0);
    o = w.jog(e, true);
    EXPECT_FALSE(o.touched);
}

TEST(Workshop, AProgramMoveIntoTheGaugeBlockIsACrash) {
    MachineProfile m;
    builtin_machine("lathe", m);
    workshop::Setup st;
    builtin_setup("lathe", st);
    Workshop w(m, st, nullptr);
    w.tool(Loc{}, 1, 1, 0, true);
    w.set_gauge_block(100);
    Outcome o = w.apply(over_the_gauge_block(0));
    ASSERT_TRUE(o.crashed);
    EXPECT_EQ(w.crashes().front().code, kCrashChuck);
    EXPECT_NE(o.what.find("T1 hit the gauge block on the jaws' face"), std::string::npos) << o.what;
}

TEST(Contacts, FromAContactAnIncrementWithTheSpindleStoppedIsACrash) {
    T1OnTheLathe t1;
    Workshop& w = *t1.shop;
    Outcome o = w.jog(jog_down(40, 20), false);
    ASSERT_TRUE(o.touched);
    double r = w.tip(o.stop)[1];
    o = w.jog(jog_down(r, r - 0.2), false);
    EXPECT_TRUE(o.crashed);
    EXPECT_EQ(w.crashes().front().code, kCrashStopped);
}

TEST(Instruments, PresetterReadsTheTruthWithinItsUncertainty) {
    workshop::Setup st;
    ASSERT_TRUE(builtin_setup("lathe", st));
    MachineProfile m;
    builtin_machine("lathe", m);
    Workshop w(m, st, nullptr);
    Reading r;
    for (const char* f : {"X", "Z", "R"}) {
        for (int t : {1, 2, 3, 4}) {
            ASSERT_EQ(w.measure("tool T" + std::to_string(t) + " " + f, r), "");
            const ToolTruth& tt = *st.tool(t);
            double truth = f[0] == 'X' ? tt.x : f[0] == 'Z' ? tt.z : tt.radius;
            EXPECT_LE(std::abs(r.value - truth), r.uncertainty + 1e-9) << t << f;
            EXPECT_EQ(r.uncertainty, 0.002);
            EXPECT_EQ(r.instrument, "presetter");
        }
    }
    // The same reading every time: the presetter's error is fixed.
    Reading again;
    w.measure("tool T1 X", r);
    w.measure("tool T1 X", again);
    EXPECT_EQ(r.value, again.value);
    EXPECT_EQ(w.measure("tool T9 X", r), "there is no T9 on the turret");
    EXPECT_EQ(w.measure("tool T1 Q", r),
              "tool needs a tool and a field: tool T1 X, tool T1 Z or tool T1 R");
}

TEST(Instruments, PartTextRoundTrips) {
    Shop s(kTurn, right());
    std::string text = s.shop->world().to_text();
    LatheWorld w(s.setup.lathe);
    ASSERT_TRUE(w.from_text(text));
    EXPECT_EQ(w.to_text(), text);
    EXPECT_EQ(w.material(), s.shop->world().material());
    uint64_t g = w.generation();
    EXPECT_FALSE(w.from_text("1 2 3\n"));
    EXPECT_FALSE(w.from_text("1 2 x 4 5 6\n"));
    EXPECT_EQ(w.generation(), g);  // nothing changed
    EXPECT_EQ(w.to_text(), text);
}

TEST(Instruments, PartExportIsTheHalfSection) {
    Shop s(kTurn, right());
    std::string zr = part_zr(s.shop->world());
    EXPECT_EQ(zr.rfind("# pupitre part", 0), 0u);
    EXPECT_NE(zr.find("\n0.000 25.000\n"), std::string::npos);
    std::string svg = part_svg(s.shop->world(), "t<1>");
    EXPECT_NE(svg.find("<title>t&lt;1></title>"), std::string::npos);
}

}  // namespace
}  // namespace workshop
}  // namespace pupitre
