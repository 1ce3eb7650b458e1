// The machining centre's workshop against parts worked out by hand (issue
// 15): the setup, cuts measured from the block's corner, contacts, crashes.
// The shipped mill setup's truth (data/setups/mill.setup): the block's
// corner at X 48.35 Y -131.72, its top at Z -290, 120 x 80 x 40; T2 a Ø8
// flat end mill, L 117.645; a tool setter's top at Z -300 at X -250 Y -150.
// The program origin at the centre of the top face: PREF X 108.35 Y -91.72
// Z -290 (X60 Y40 from the corner).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/interp/interp.hpp"
#include "core/workshop/report.hpp"
#include "core/workshop/workshop.hpp"
#include "workshop_run.hpp"

namespace pupitre::workshop {
namespace {

using test::Sets;

Sets right(double pref_z = -290, double l2 = 117.645) {
    return {{"PREF.X", 108.35}, {"PREF.Y", -91.72}, {"PREF.Z", pref_z}, {"D2.L", l2}, {"D2.R", 4}};
}

// A program run in the shipped mill setup, changed by `extra` lines.
struct Mill : test::ShopRun {
    Mill(const std::string& program, const Sets& sets, const std::string& extra = "")
        : ShopRun("mill", program, sets, extra) {
        EXPECT_EQ(setup_error, "");
    }
};

// A slot 8 wide, 3 deep along X through the block at Y0 (Y40 from the
// corner), and a pocket: the Ø8 cutter round X20..40 Y20..26 at Z-5, so
// X16..44 Y16..30 (X76..104, Y56..70 from the corner).
const char* kSlot = R"(%30
N10 T2 D2 M6
N20 S2000 M3
N30 G0 X-70 Y0 Z5
N40 G1 Z-3 F300
N50 X70 F400
N60 G0 Z5
N70 X20 Y20
N80 G1 Z-5 F200
N90 X40 F300
N100 Y26
N110 X20
N120 Y20
N130 G0 Z50
N140 M2
)";

TEST(MillSetup, ShippedMillParses) {
    workshop::Setup s;
    ASSERT_TRUE(builtin_setup("mill", s));
    EXPECT_EQ(s.kind, "mill");
    EXPECT_DOUBLE_EQ(s.mill.stock_z + s.mill.height, -290);
    ASSERT_NE(s.tool(2), nullptr);
    EXPECT_DOUBLE_EQ(s.tool(2)->length, 117.645);
    EXPECT_EQ(s.tool(2)->spindle, 3);  // a cutter's default: M3
    EXPECT_TRUE(s.tool(4)->probe);
    EXPECT_TRUE(s.mill.setter);
}

TEST(MillSetup, ErrorsNameTheLine) {
    workshop::Setup s;
    EXPECT_EQ(parse_setup("kind = mill\nstock.diameter = 10\n", s),
              "line 2: stock.diameter: unknown key 'stock.diameter' for a mill");
    EXPECT_EQ(parse_setup("kind = mill\nholding = clamp\n", s),
              "line 2: holding: expected vice, plate or none");
    EXPECT_EQ(parse_setup("kind = mill\npin.0.x = 1\n", s),
              "line 2: pin.0.x: expected pin.N.FIELD with N from 1 to 9");
    EXPECT_EQ(parse_setup("kind = mill\ntool.1.radius = 4\n", s), "tool.1: length is missing");
    EXPECT_EQ(
        parse_setup("kind = mill\ntool.1.length = 90\ntool.1.radius = 4\ntool.1.corner = 5\n", s),
        "tool.1: corner must not exceed radius");
    EXPECT_EQ(parse_setup("kind = mill\nstock.x = 0\nstock.y = 0\npin.1.x = 10\npin.1.y = 5\n", s),
              "pin.1 stands inside the stock");
    EXPECT_EQ(parse_setup("kind = mill\ntable.z = 0\nstock.z = -1\n", s),
              "stock.z must not be below table.z");
    // 2000 x 2000 at 0.1 mm: 400,000,000 cells; at 0.4 mm 25,000,000 pass.
    EXPECT_EQ(parse_setup("kind = mill\nstock.length = 2000\nstock.width = 2000\n", s),
              "the height field would have 400000000 cells, at most 25000000: a larger zmap.cell");
    EXPECT_EQ(
        parse_setup("kind = mill\nstock.length = 2000\nstock.width = 2000\nzmap.cell = 0.4\n", s),
        "");
}

TEST(MillWorkshop, RightValuesCutTheDrawing) {
    Mill m(kSlot, right());
    ASSERT_EQ(m.crash(), 0) << m.shop->crashes().front().what;
    EXPECT_NEAR(m.read("width Y X10 Y40 Z-1"), 8, 1e-9);
    EXPECT_NEAR(m.read("depth X10 Y40"), 3, 1e-9);
    EXPECT_NEAR(m.read("height X10 Y40"), 37, 1e-9);
    EXPECT_NEAR(m.read("width X X90 Y63 Z-2"), 28, 1e-9);
    EXPECT_NEAR(m.read("width Y X90 Y63 Z-2"), 14, 1e-9);
    EXPECT_NEAR(m.read("depth X90 Y63"), 5, 1e-9);
    EXPECT_NEAR(m.read("length X Y10 Z-1"), 120, 1e-9);
    EXPECT_NEAR(m.read("length Y X30 Z-1"), 80, 1e-9);
    // Along the slot, through the block: no wall at either end.
    EXPECT_EQ(m.refused("width X X10 Y40 Z-1"), "no walls there: the gap opens out of the part");
    // Below the slot the block is whole.
    EXPECT_EQ(m.refused("width Y X10 Y40 Z-4"),
              "that point is in the material: width measures the gap around it");
    EXPECT_EQ(m.refused("width Y X10 Y10 Z-1"),
              "that point is in the material: width measures the gap around it");
}

TEST(MillWorkshop, PrefZOffMovesEveryDepthAndALengthOffTheOtherWay) {
    // PREF Z 0.1 high: the tip 0.1 higher everywhere.
    EXPECT_NEAR(Mill(kSlot, right(-289.9)).read("depth X10 Y40"), 2.9, 1e-9);
    // L entered 0.1 short: the interpreter takes the gauge line 0.1 lower.
    EXPECT_NEAR(Mill(kSlot, right(-290, 117.545)).read("depth X10 Y40"), 3.1, 1e-9);
}

TEST(MillWorkshop, PrefXOffMovesThePocketNotItsWidth) {
    Sets s = right();
    s[0].second = 108.45;  // PREF X 0.1 too far +X
    Mill m(kSlot, s);
    EXPECT_NEAR(m.read("width X X90 Y63 Z-2"), 28, 1e-9);
    // Its walls 0.1 further: the land from the block's +X face to the
    // pocket, 120 - 104.1 = 15.9, read across the pocket's wall at X110.
    const auto span = m.shop->mill()->along(0, {48.35 + 110, -131.72 + 63, -292});
    ASSERT_FALSE(span.empty());
    EXPECT_NEAR(span.back()[0] - 48.35, 104.1, 1e-6);
}

TEST(MillWorkshop, AWornCutterLeavesMaterial) {
    // T3 wears 5 µm of its length per metre of cut. It faces 1 mm off the
    // top in ten passes (about 1.3 m of cut), then slots 2 deep along Y0:
    // the slot's floor is short of -2 by 5 µm per metre faced.
    std::string face = "%31\nN10 T3 D3 M6\nN20 S2000 M3\nN30 G0 X-70 Y-36 Z5\nN40 G1 Z-1 F500\n";
    for (int i = 0; i < 10; ++i)
        face += std::string(i % 2 ? "X-70\n" : "X70\n") + "Y" + std::to_string(-28 + 8 * i) + "\n";
    const Sets sets{{"PREF.X", 108.35}, {"PREF.Y", -91.72}, {"PREF.Z", -290}, {"D3.L", 121.082}};
    Mill faced(face + "G0 Z50\nM2\n", sets);
    ASSERT_EQ(faced.crash(), 0);
    const double metres = faced.shop->cut_length(3) / 1000;
    EXPECT_GT(metres, 1.2);
    Mill m(face + "G0 Z5\nX-70 Y0\nG1 Z-2\nX70\nG0 Z50\nM2\n", sets);
    ASSERT_EQ(m.crash(), 0);
    // At X-50 from the centre (X10 from the corner), 10 mm into the slot.
    const auto span = m.shop->mill()->along(2, {48.35 + 10, -131.72 + 40, -300});
    ASSERT_FALSE(span.empty());
    EXPECT_NEAR(span.back()[1] - (-290), -2 + 0.005 * metres, 1e-5);
    // The faced top is a metre's wear short of -1 at its last pass.
    EXPECT_GT(m.shop->mill()->along(2, {48.35 + 10, -131.72 + 75, -300}).back()[1], -291);
}

TEST(MillWorkshop, RapidIntoTheBlockIsACrashThatStopsAtTheContact) {
    // PREF Z 10 low: the rapid of N70 at Z5 runs at the block's top - 5.
    Mill m(kSlot, right(-300));
    ASSERT_EQ(m.crash(), kCrashRapid);
    const Crash& c = m.shop->crashes().front();
    EXPECT_EQ(c.loc.n, 70);
    // From X70 Y0 (X130 Y40 from the corner) towards X20 Y20 (X80 Y60),
    // the tip 5 below the top. The slot, 13 deep with PREF Z 10 low, runs
    // out of the +X face at Y36..44: the cutter's side first meets the
    // slot's corner (X120, Y44), when its axis is 4 from it. A contact on a
    // face the tools cut is found within half a cell (0.05).
    const double ux = -50 / std::hypot(50, 20), uy = 20 / std::hypot(50, 20);
    // |(130 + s ux - 120, 40 + s uy - 44)| = 4, the smaller root.
    const double bx = 10, by = -4, pb = bx * ux + by * uy;
    const double s = -pb - std::sqrt(pb * pb - (bx * bx + by * by - 16));
    EXPECT_NEAR(c.om[X] - 48.35, 130 + s * ux, 0.05);
    EXPECT_NEAR(c.om[Y] + 131.72, 40 + s * uy, 0.05);
    EXPECT_NE(c.what.find("rapid (G0) into the part at X"), std::string::npos) << c.what;
}

TEST(MillWorkshop, FeedWithTheSpindleStoppedIsACrash) {
    std::string p = kSlot;
    p.replace(p.find("S2000 M3"), 8, "S2000 M5");
    EXPECT_EQ(Mill(p, right()).crash(), kCrashStopped);
}

TEST(MillWorkshop, M4IsTheWrongWayForARightHandCutter) {
    std::string p = kSlot;
    p.replace(p.find("S2000 M3"), 8, "S2000 M4");
    EXPECT_EQ(Mill(p, right()).crash(), kCrashDirection);
}

TEST(MillWorkshop, TheViceStopsTheCutter) {
    // Along Y across the fixed jaw (at +Y, Y40 + 25 from the block's
    // centre), 5 below the top: the jaws' top is 10 below it.
    const char* p =
        "%32\nN10 T2 D2 M6\nN20 S2000 M3\nN30 G0 X0 Y-80 Z5\nN40 G1 Z-5 F300\n"
        "N50 Y80\nN60 M2\n";
    Mill m(p, right());
    EXPECT_EQ(m.crash(), 0) << m.shop->crashes().front().what;
    Mill deep(p, right(-300));  // 10 lower: the cutter meets the moving jaw
    ASSERT_EQ(deep.crash(), kCrashChuck);
    EXPECT_NE(deep.shop->crashes().front().what.find("hit the vice"), std::string::npos)
        << deep.shop->crashes().front().what;
}

TEST(MillWorkshop, TooDeepAPassBringsTheShankIn) {
    // T2's flute is 20 long: a side pass 25 deep drags the shank.
    const char* p =
        "%33\nN10 T2 D2 M6\nN20 S2000 M3\nN30 G0 X-70 Y0 Z5\nN40 G1 Z-25 F300\n"
        "N50 X70\nN60 M2\n";
    Mill m(p, right());
    EXPECT_EQ(m.crash(), kCrashHolder);
    EXPECT_NE(m.shop->crashes().front().what.find("the shank of T2"), std::string::npos);
    // A plunge 25 deep goes down the hole the flute makes: no crash.
    const char* plunge =
        "%34\nN10 T2 D2 M6\nN20 S2000 M3\nN30 G0 X0 Y0 Z5\nN40 G1 Z-25 F100\n"
        "N50 G0 Z50\nN60 M2\n";
    EXPECT_EQ(Mill(plunge, right()).crash(), 0);
}

// The spindle with T`t` at the gauge-line position (X, Y, Z), jogged to
// (X, Y, Z - down) or along `axis` by `by`.
struct Jogged {
    MachineProfile m;
    workshop::Setup st;
    std::unique_ptr<Workshop> shop;
    explicit Jogged(int t, const std::string& extra = "") {
        builtin_machine("mill", m);
        builtin_setup("mill", st);
        if (!extra.empty()) parse_setup(st.source + "\n" + extra, st);
        shop = std::make_unique<Workshop>(m, st, nullptr);
        shop->tool(Loc{}, t, t, 0, true);
    }
    Outcome jog(Axes from, int axis, double by, bool continuous = true) {
        MoveEvent e;
        e.g = 1;
        e.from_mach = from;
        e.to_mach = from;
        e.to_mach[size_t(axis)] += by;
        e.to_prog = e.to_mach;
        e.length = std::abs(by);
        return shop->jog(e, continuous);
    }
};

Axes at(double x, double y, double z) {
    Axes a{};
    a[X] = x, a[Y] = y, a[Z] = z;
    return a;
}

TEST(MillContacts, AJogStopsOnTheTopFaceAndASideFaceExactly) {
    Jogged j(2);
    // Over the block's centre, the tip 10 above the top: down 20.
    Outcome o = j.jog(at(108.35, -91.72, -290 + 117.645 + 10), Z, -20);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Z], -290 + 117.645, 2e-4);  // the gauge line: top + L
    EXPECT_NE(o.what.find("T2 touched the part at X60.000 Y40.000 Z0.000"), std::string::npos)
        << o.what;
    // Beside the -X face, 5 below the top, towards +X: the axis stops 4
    // (the radius) from the face.
    o = j.jog(at(30, -91.72, -295 + 117.645), X, 30);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 48.35 - 4, 2e-4);
    // The paper test: a 0.05 shim on the top face.
    j.shop->set_shim(0.05);
    o = j.jog(at(108.35, -91.72, -290 + 117.645 + 10), Z, -20);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Z], -290 + 117.645 + 0.05, 2e-4);
    EXPECT_NE(o.what.find("0.050 mm shim"), std::string::npos) << o.what;
}

// Issue 38: a 40 mm gauge block lies between the cutter and the face it
// comes to, along the jog: 40 above the top, 40 before a side; coming down
// beside the block (the cutter's edge 6 from the -X face) it meets nothing,
// where a cutter grown all round rode on the block's edge.
TEST(MillContacts, AGaugeBlockLiesAlongTheJog) {
    Jogged j(2);
    j.shop->set_shim(40);
    Outcome o = j.jog(at(108.35, -91.72, -290 + 117.645 + 60), Z, -30);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Z], -290 + 117.645 + 40, 2e-4);
    EXPECT_NE(o.what.find("40.000 mm shim"), std::string::npos) << o.what;
    o = j.jog(at(-20, -91.72, -295 + 117.645), X, 40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 48.35 - 4 - 40, 2e-4);
    o = j.jog(at(48.35 - 10, -91.72, -290 + 117.645 + 60), Z, -30);
    EXPECT_FALSE(o.touched) << o.what;
}

// On a fixture plate 20 beyond the block, with a Ø10 locating pin at X40
// (the block's -X face is at 48.35), its top 20 above the block's bottom
// (Z -310).
const char* kPlate =
    "holding = plate\nplate.margin = 20\npin.1.x = 40\npin.1.y = -91.72\npin.1.diameter = 10\n";

TEST(MillContacts, ThePinAndThePlateStopAJogAndCrashAMove) {
    Jogged j(2, kPlate);
    // T2 (Ø8) along +X, its tip at Z -315: the pin's side at X35, the axis 4
    // before it.
    Outcome o = j.jog(at(0, -91.72, -315 + 117.645), X, 40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 31, 2e-4);
    EXPECT_NE(o.what.find("T2 touched a locating pin"), std::string::npos) << o.what;
    // Down beside the block, within the plate's margin: its top is the
    // block's bottom, Z -330.
    o = j.jog(at(30, -140, -300 + 117.645), Z, -50);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Z] - 117.645, -330, 2e-4);
    EXPECT_NE(o.what.find("T2 touched the plate"), std::string::npos) << o.what;
    // The same descent as a rapid: a crash into the work-holding.
    MoveEvent e;
    e.g = 0;
    e.from_mach = at(30, -140, -300 + 117.645);
    e.to_mach = at(30, -140, -350 + 117.645);
    e.to_prog = e.to_mach;
    o = j.shop->apply(e);
    ASSERT_TRUE(o.crashed);
    EXPECT_EQ(j.shop->crashes().front().code, kCrashChuck);
    EXPECT_NE(o.what.find("crash: T2 hit the plate"), std::string::npos) << o.what;
}

TEST(MillContacts, TheToolSetterGivesTheLength) {
    Jogged j(2);
    Outcome o = j.jog(at(-250, -150, -100), Z, -150);
    ASSERT_TRUE(o.touched);
    EXPECT_NE(o.what.find("the tool setter"), std::string::npos) << o.what;
    EXPECT_NEAR(o.stop[Z] - (-300), 117.645, 2e-4);  // L = gauge line - setter's top
}

TEST(MillContacts, TheProbesLampAndACrashIntoTheBlock) {
    Jogged j(4);
    ASSERT_TRUE(j.shop->probe_in_use());
    // The ball (Ø4, L 130.214) down onto the top face.
    Outcome o = j.jog(at(108.35, -91.72, -290 + 130.214 + 5), Z, -10);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Z], -290 + 130.214, 2e-4);
    EXPECT_TRUE(j.shop->probe_contact(o.stop));
    EXPECT_FALSE(j.shop->probe_contact(at(108.35, -91.72, -290 + 130.214 + 1)));
    // An increment from there drives it in: a crash.
    o = j.jog(o.stop, Z, -0.5, false);
    EXPECT_TRUE(o.crashed);
    EXPECT_EQ(j.shop->crashes().front().code, kCrashProbe);
}

// A Ø10 mechanical edge finder as T6, L 95.012, its lower part 12 long.
const char* kFinder =
    "tool.6.length = 95.012\ntool.6.radius = 5\ntool.6.flute = 12\ntool.6.reach = 50\n"
    "tool.6.holder.diameter = 32\ntool.6.finder = yes\n";
constexpr double kL6 = 95.012;

// The finder in the spindle, turning M3 at 800 rev/min (`turning`).
struct Finder : Jogged {
    explicit Finder(bool turning = true) : Jogged(6, kFinder) {
        SpindleEvent sp;
        sp.rpm = 800;
        sp.dir = turning ? 3 : 5;
        shop->spindle(sp);
    }
};

TEST(MillFinder, TheSetupSaysWhatItIs) {
    workshop::Setup s;
    ASSERT_TRUE(builtin_setup("mill", s));
    ASSERT_EQ(parse_setup(s.source + "\n" + kFinder, s), "");
    EXPECT_TRUE(s.tool(6)->finder);
    EXPECT_FALSE(s.tool(6)->probe);
    EXPECT_FALSE(s.tool(2)->finder);
    EXPECT_EQ(parse_setup("kind = mill\ntool.1.length = 90\ntool.1.finder = maybe\n", s),
              "line 3: tool.1.finder: expected yes or no");
    EXPECT_EQ(parse_setup("kind = mill\ntool.1.length = 90\ntool.1.probe = yes\n"
                          "tool.1.finder = yes\n",
                          s),
              "tool.1: a probe or an edge finder, not both");
    EXPECT_EQ(parse_setup("kind = lathe\ntool.1.finder = yes\n", s),
              "line 2: tool.1.finder: an edge finder is a machining centre's (kind = mill)");
}

TEST(MillFinder, ItKicksOneRadiusFromTheFaceInX) {
    Finder j;
    // Beside the -X face (X 48.35), its tip 5 below the top, towards +X:
    // the axis stops 5 (the radius) before the face.
    Outcome o = j.jog(at(20, -91.72, -295 + kL6), X, 40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 48.35 - 5, 1e-3);
    EXPECT_NE(o.what.find("the edge finder T6 kicks on the block's -X face at X-5.000 Y40.000 "
                          "Z-5.000 from the block's corner"),
              std::string::npos)
        << o.what;
    // And from beyond the +X face (X 168.35) towards -X, by increments.
    o = j.jog(at(190, -91.72, -295 + kL6), X, -20, false);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 168.35 + 5, 1e-3);
    EXPECT_NE(o.what.find("kicks on the block's +X face"), std::string::npos) << o.what;
    EXPECT_FALSE(j.shop->crashed());
}

TEST(MillFinder, ItKicksOneRadiusFromTheFaceInY) {
    Finder j;
    // Towards +Y onto the -Y face (Y -131.72), over the vice's moving jaw
    // (its top 10 below the block's).
    Outcome o = j.jog(at(108.35, -160, -295 + kL6), Y, 40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Y], -131.72 - 5, 1e-3);
    EXPECT_NE(o.what.find("kicks on the block's -Y face"), std::string::npos) << o.what;
    // The +Y face (Y -51.72) from behind, over the fixed jaw.
    o = j.jog(at(108.35, -30, -295 + kL6), Y, -40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[Y], -51.72 + 5, 1e-3);
    EXPECT_NE(o.what.find("kicks on the block's +Y face"), std::string::npos) << o.what;
}

TEST(MillFinder, ItKicksOnAPinAndOnAWallTheToolsCut) {
    Jogged j(6, std::string(kPlate) + kFinder);
    SpindleEvent sp;
    sp.dir = 4;  // either way
    j.shop->spindle(sp);
    // Along +X, its tip at Z -315: the Ø10 pin's side at X35.
    Outcome o = j.jog(at(0, -91.72, -315 + kL6), X, 40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 30, 1e-3);
    EXPECT_NE(o.what.find("the edge finder T6 kicks on a locating pin"), std::string::npos)
        << o.what;
    // Inside the pocket kSlot cuts (X76..104 from the corner), 2 below the
    // top, towards +X: a cut wall, found to half a cell (and the finder's
    // round side between the cells' centres).
    Mill m(kSlot, right(), kFinder);
    m.shop->tool(Loc{}, 6, 6, 0, true);
    m.shop->spindle(sp);
    MoveEvent e;
    e.g = 1;
    e.from_mach = at(48.35 + 90, -131.72 + 63, -292 + kL6);
    e.to_mach = e.from_mach;
    e.to_mach[X] += 20;
    e.to_prog = e.to_mach;
    o = m.shop->jog(e, true);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 48.35 + 104 - 5, 0.051);
    EXPECT_NE(o.what.find("the edge finder T6 kicks on a wall facing -X"), std::string::npos)
        << o.what;
}

TEST(MillFinder, WithTheSpindleStoppedItTouchesButDoesNotKick) {
    Finder j(false);
    Outcome o = j.jog(at(20, -91.72, -295 + kL6), X, 40);
    ASSERT_TRUE(o.touched);
    EXPECT_NEAR(o.stop[X], 48.35 - 5, 1e-3);
    EXPECT_EQ(o.what.find("T6 kicks"), std::string::npos) << o.what;
    EXPECT_NE(o.what.find("T6 touched the part at X-5.000"), std::string::npos) << o.what;
    EXPECT_NE(o.what.find("the spindle is not turning"), std::string::npos) << o.what;
}

TEST(MillFinder, PushedPastTheKickItGivesThenBends) {
    Finder j;
    const uint64_t fresh = j.shop->generation();
    Outcome o = j.jog(at(20, -91.72, -295 + kL6), X, 40);
    ASSERT_TRUE(o.touched);
    // An increment of 0.5 from the kick pushes its lower part aside.
    o = j.jog(o.stop, X, 0.5, false);
    ASSERT_TRUE(o.touched);
    EXPECT_FALSE(o.crashed);
    EXPECT_NEAR(o.stop[X], 48.35 - 4.5, 1e-3);
    EXPECT_NE(o.what.find("the edge finder T6 is pushed 0.500 mm aside"), std::string::npos)
        << o.what;
    // Back off: it runs true again, nothing said.
    Outcome back = j.jog(o.stop, X, -2, false);
    EXPECT_FALSE(back.touched || back.crashed) << back.what;
    // 0.6 more from 0.5 aside: bent 1 mm past the kick.
    o = j.jog(o.stop, X, 0.6, false);
    ASSERT_TRUE(o.crashed);
    EXPECT_EQ(j.shop->crashes().front().code, kCrashProbe);
    EXPECT_NEAR(o.stop[X], 48.35 - 5 + kFinderTravel, 1e-3);
    EXPECT_NE(o.what.find("crash: the edge finder T6 was bent against the part"), std::string::npos)
        << o.what;
    // It never cut.
    EXPECT_EQ(j.shop->generation(), fresh);
}

// The finder in a program: over the block at Z-5 from X-70 (X-10 from the
// corner), then `move`.
std::string finder_program(const std::string& move) {
    return "%37\nN10 T6 D6 M6\nN20 S800 M3\nN30 G0 X-70 Y0 Z5\nN40 Z-5\nN50 " + move +
           "\nN60 G0 Z50\nN70 M2\n";
}

TEST(MillFinder, AFeedIntoTheBlockBendsItARapidCrashesAsAnyTool) {
    Sets s = right();
    s.push_back({"D6.L", kL6});
    s.push_back({"D6.R", 5});
    Mill fed(finder_program("G1 X0 F200"), s, kFinder);
    ASSERT_EQ(fed.crash(), kCrashProbe);
    const Crash& c = fed.shop->crashes().front();
    EXPECT_EQ(c.loc.n, 50);
    EXPECT_NEAR(c.om[X], 48.35 - 5, kCrashDepth + 1e-3);
    EXPECT_NE(c.what.find("edge finder T6 was bent"), std::string::npos) << c.what;
    EXPECT_EQ(fed.shop->generation(), Mill("%38\nN10 M2\n", {}).shop->generation());
    EXPECT_NEAR(fed.read("length X Y40 Z-5"), 120, 1e-9);
    Mill rapid(finder_program("G0 X0"), s, kFinder);
    EXPECT_EQ(rapid.crash(), kCrashRapid);
    // Over the block it goes anywhere.
    Mill over(finder_program("G0 Z5\nG1 X70 F200"), s, kFinder);
    EXPECT_EQ(over.crash(), 0);
}

TEST(MillInstruments, PresetterAndBadRequests) {
    Mill m("%35\nN10 M2\n", {});
    Reading r;
    ASSERT_EQ(m.shop->measure("tool T2 L", r), "");
    EXPECT_NEAR(r.value, 117.645, 0.002 + 1e-9);
    EXPECT_DOUBLE_EQ(r.uncertainty, 0.002);
    ASSERT_EQ(m.shop->measure("tool T5 R", r), "");
    EXPECT_NEAR(r.value, 5, 0.002 + 1e-9);
    EXPECT_EQ(m.shop->measure("tool T2 X", r),
              "tool needs a tool and a field: tool T1 L or tool T1 R");
    EXPECT_EQ(m.shop->measure("tool T9 L", r), "there is no T9 in the magazine");
    EXPECT_EQ(m.refused("dia Z-20"),
              "expected length X|Y, width X|Y, depth, height (with X Y Z from the block's corner) "
              "or tool Tn L|R");
    EXPECT_EQ(m.refused("width X Y10 Z-1"),
              "expected width X X60 Y30 Z-5 (from the block's corner)");
    EXPECT_EQ(m.refused("depth X10 Y10 Z-1"), "expected depth X60 Y30 (from the block's corner)");
    EXPECT_EQ(m.refused("length X X10 Y10 Z-1"),
              "expected length X Y30 Z-5 (from the block's corner)");
    EXPECT_EQ(m.refused("length X Y10 Z1"),
              "Z is measured from the block's top face: 0 or negative (Z-5)");
    EXPECT_EQ(m.refused("depth X500 Y10"), "no material there");
    EXPECT_NEAR(m.read("height X1 Y1"), 40, 1e-9);
}

TEST(MillInstruments, PartTextRoundTripsAndTheImageScales) {
    Mill m(kSlot, right());
    const std::string text = m.shop->part_text();
    Mill fresh("%36\nN10 M2\n", {});
    ASSERT_TRUE(fresh.shop->load_part(text));
    EXPECT_NEAR(fresh.read("width Y X10 Y40 Z-1"), 8, 1e-9);
    EXPECT_NEAR(fresh.read("depth X90 Y63"), 5, 1e-9);
    EXPECT_FALSE(fresh.shop->load_part("1 2 3\n"));
    EXPECT_NEAR(fresh.read("depth X90 Y63"), 5, 1e-9);  // nothing changed
    double scale = 0;
    const std::vector<uint16_t> img = height_image(*m.shop->mill(), scale);
    const MillWorld& w = *m.shop->mill();
    ASSERT_EQ(img.size(), size_t(w.nx()) * size_t(w.ny()));
    EXPECT_DOUBLE_EQ(scale, 40.0 / 65535);
    EXPECT_EQ(img[0], 65535);  // the first row is +Y: the uncut corner
    // The slot's floor, 3 below the top: (37 / 40) of full scale.
    const int i = 100, j = 400;  // X10 Y40 (cell centres at 10.05, 40.05)
    EXPECT_EQ(img[size_t(w.ny() - 1 - j) * size_t(w.nx()) + size_t(i)],
              uint16_t(std::round(37 / scale)));
}

}  // namespace
}  // namespace pupitre::workshop
