// The machining centre's workshop with rotary axes (issue 15): a C table
// (mill5) turns the part under the tool, mill5's B head tilts the tool,
// mill4's B table tilts the part.
// The shipped mill5 setup (data/setups/mill5.setup): the C axis at machine
// X0 Y0 through the centre of a 100 x 100 x 50 block, its corner at X-50
// Y-50, its top at Z-280; T1 a Ø10 flat end mill, L 110.25. Values worked
// out by hand below.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/workshop/workshop.hpp"
#include "workshop_run.hpp"

namespace pupitre::workshop {
namespace {

using test::Sets;

const Sets kRight = {{"PREF.Z", -280}, {"D1.L", 110.25}, {"D1.R", 5}};

// The shipped mill5 workshop alone, T1 in the spindle.
struct Mill5 {
    MachineProfile m;
    workshop::Setup st;
    std::unique_ptr<Workshop> shop;
    Mill5() {
        builtin_machine("mill5", m);
        builtin_setup("mill5", st);
        shop = std::make_unique<Workshop>(m, st, nullptr);
        shop->tool(Loc{}, 1, 1, 0, true);
    }
};

// The same slot, 10 wide, 2 deep, 30 long from outside the -X face, cut at C0
// and again at C90.
const char* kTwoSlots = R"(%5
N10 T1 D1 M6
N20 S1000 M3
N30 G0 X-60 Y0 Z5
N40 G1 Z-2 F200
N50 X-30
N60 G0 Z5
N70 C90
N80 X-60 Y0
N90 G1 Z-2
N100 X-30
N110 G0 Z50
N120 M2
)";

TEST(MillRotary, ShippedMill5Parses) {
    workshop::Setup s;
    ASSERT_TRUE(builtin_setup("mill5", s));
    EXPECT_EQ(s.kind, "mill");
    EXPECT_DOUBLE_EQ(s.mill.c_x, 0);
    EXPECT_DOUBLE_EQ(s.mill.c_y, 0);
    EXPECT_DOUBLE_EQ(s.mill.stock_z + s.mill.height, -280);
    EXPECT_EQ(s.mill.holding, "plate");
    ASSERT_NE(s.tool(1), nullptr);
    EXPECT_DOUBLE_EQ(s.tool(1)->length, 110.25);
}

// The table turned +90° carries the part's -Y side to where the -X side was
// (Rot_Z(C) of the tool in the part): the second slot is cut there.
TEST(MillRotary, ACTableTurnsThePartUnderTheTool) {
    test::ShopRun r("mill5", kTwoSlots, kRight, "");
    ASSERT_EQ(r.crash(), 0) << r.shop->crashes().front().what;
    // From the block's corner: the first slot at X0..20 Y45..55, the second
    // at X45..55 Y0..20; the +X and +Y sides are whole.
    EXPECT_NEAR(r.read("depth X10 Y50"), 2, 0.01);
    EXPECT_NEAR(r.read("depth X50 Y10"), 2, 0.01);
    EXPECT_NEAR(r.read("depth X90 Y50"), 0, 0.01);
    EXPECT_NEAR(r.read("depth X50 Y90"), 0, 0.01);
    // The second slot's width along X, exact: the cutter's diameter.
    EXPECT_NEAR(r.read("width X X50 Y10 Z-1"), 10, 1e-3);
}

// A C move with the tool down beside the part: the block swings into it.
// The cutter's axis at X-56 Y0 (1 mm from the -X face) goes round on a
// circle of 56 in the part; its side meets the -X face when 56 cos C = 55.
TEST(MillRotary, AJogOfCStopsWhereTheBlockReachesTheCutter) {
    Mill5 five;
    Workshop& shop = *five.shop;
    MoveEvent e;
    e.g = 1;
    e.from_mach[X] = -56;
    e.from_mach[Z] = -285 + 110.25;  // the tip 5 below the top
    e.to_mach = e.from_mach;
    e.to_mach[C] = 90;
    e.to_prog = e.to_mach;
    Outcome o = shop.jog(e, true);
    ASSERT_TRUE(o.touched) << o.what;
    // C about 10.844°; the face nearly tangent to the cutter's path there, a
    // micrometre across it is 0.005° along: the distance is what is exact.
    const double deg = std::acos(-1.0) / 180;
    EXPECT_NEAR(o.stop[C], std::acos(55.0 / 56.0) / deg, 0.01);
    EXPECT_NEAR(56 * std::cos(o.stop[C] * deg), 55, 1e-3);
    EXPECT_NE(o.what.find("T1 touched the part"), std::string::npos) << o.what;
    // The same as a program's rapid: a crash there.
    const char* rapid = "%6\nN10 T1 D1 M6\nN20 G0 X-56 Y0 Z5\nN30 G1 Z-5 F100\nN40 G0 C90\nM2\n";
    test::ShopRun r("mill5", rapid, kRight, "");
    EXPECT_EQ(r.crash(), kCrashRapid);
    const double gap = 56 * std::cos(r.shop->crashes().front().om[C] * deg) - 55;
    EXPECT_LE(gap, 0);  // into the face by about the crash depth
    EXPECT_GE(gap, -kCrashDepth - 1e-3);
}

// The tool in the table's frame: at C90 the machine point X-56 Y0 is at
// X0 Y-56 of the part as it lies at C0; not turned, where GRAPH and plot
// place the block under the path they draw (pupitre-setup(5), LIMITATIONS).
TEST(MillRotary, TheToolInTheTablesFrame) {
    Mill5 five;
    Workshop& shop = *five.shop;
    Axes om{};
    om[X] = -56, om[Z] = -170, om[C] = 90;
    const P3 t = shop.tip3(om), u = shop.tip3(om, false);
    EXPECT_NEAR(t[0], 0, 1e-9);
    EXPECT_NEAR(t[1], -56, 1e-9);
    EXPECT_NEAR(t[2], -170 - 110.25, 1e-9);
    EXPECT_NEAR(u[0], -56, 1e-9);
    EXPECT_NEAR(u[1], 0, 1e-9);
}

// A move of the machine as the workshop makes it.
Outcome go(Workshop& w, const Axes& from, const Axes& to, int g, bool jog = false) {
    MoveEvent e;
    e.g = g;
    e.from_mach = from;
    e.to_mach = to;
    e.to_prog = to;
    return jog ? w.jog(e, true) : w.apply(e);
}

Axes at(double x, double y, double z, double b = 0, double c = 0) {
    Axes a{};
    a[X] = x, a[Y] = y, a[Z] = z, a[B] = b, a[C] = c;
    return a;
}

// mill5's head turns about its B axis, 250 above the gauge line (the
// setup's head.pivot, the profile's kinematics.lz): at B45 T1's tip is
// 360.25 (250 + 110.25) from it along the tool's axis (sin 45°, 0, cos 45°).
// The machine at X303.7347 Z-276.2653 puts the tip at X49 Z-281, 1 from the
// +X face and 1 under the top: fed along Y, the end cuts the chamfer
// X + Z = -232, 2 x 2 on the edge, read with the depth gauge 1 in from the
// face (from the block's corner: X99) as 1.000.
TEST(MillRotary, ATiltedHeadCutsAChamferWithTheEnd) {
    Mill5 five;
    Workshop& shop = *five.shop;
    const double k = std::sqrt(0.5) * 360.25;
    const Axes up = at(49 + k, -80, -100, 45), start = at(49 + k, -80, -281 - 250 + k, 45),
               end = at(49 + k, 80, -281 - 250 + k, 45);
    const P3 tip = shop.tip3(start), u = shop.axis3(start);
    EXPECT_NEAR(tip[0], 49, 1e-9);
    EXPECT_NEAR(tip[2], -281, 1e-9);
    EXPECT_NEAR(u[0], std::sqrt(0.5), 1e-12);
    // The head swings to B45 above the part, comes down beside it and feeds.
    EXPECT_FALSE(go(shop, at(49 + k, -80, -100), up, 0).crashed);
    EXPECT_FALSE(go(shop, up, start, 0).crashed);
    SpindleEvent on;
    on.dir = 3, on.rpm = 1000;
    shop.spindle(on);
    Outcome o = go(shop, start, end, 1);
    ASSERT_FALSE(o.crashed) << o.what;
    Reading r;
    ASSERT_EQ(shop.measure("depth X99 Y50", r), "");
    EXPECT_NEAR(r.value, 1, 1e-9);
    ASSERT_EQ(shop.measure("depth X98.5 Y50", r), "");
    EXPECT_NEAR(r.value, 0.5, 1e-9);
    ASSERT_EQ(shop.measure("depth X97 Y50", r), "");
    EXPECT_NEAR(r.value, 0, 1e-9);
    // The height X-Z=... along X at Z-1 under the top: the face now at X99.
    ASSERT_EQ(shop.measure("length X Y50 Z-1", r), "");
    EXPECT_NEAR(r.value, 99, 1e-9);
}

// A rapid of the tilted tool into the block is a crash, stopped where the
// end's lowest point (r (cos 45°, 0, -sin 45°) from the tip: 3.536 under
// it) reaches the top: the tip at Z-276.464.
TEST(MillRotary, ATiltedToolCrashesWhereItsRimMeetsTheTop) {
    Mill5 five;
    Workshop& shop = *five.shop;
    const double k = std::sqrt(0.5) * 360.25, rim = 5 * std::sqrt(0.5);
    // The rim's lowest point over X0.05 Y0.05, a cell's centre.
    const double x = 0.05 - rim + k;
    Outcome o = go(shop, at(x, 0.05, -100, 45), at(x, 0.05, -300, 45), 0);
    ASSERT_TRUE(o.crashed);
    EXPECT_EQ(shop.crashes().front().code, kCrashRapid);
    const P3 tip = shop.tip3(o.stop);
    EXPECT_NEAR(tip[2], -280 + rim, kCrashDepth + 1e-4);
    EXPECT_NE(o.what.find("T1 rapid (G0) into the part"), std::string::npos) << o.what;
    // A jog stops there instead.
    shop.clear_crash();
    Outcome j = go(shop, at(x, 0.05, -100, 45), at(x, 0.05, -300, 45), 0, true);
    ASSERT_TRUE(j.touched) << j.what;
    EXPECT_NEAR(shop.tip3(j.stop)[2], -280 + rim, 2e-4);
}

// A jog of B swings the tool: held down beside the block, the tool's end
// comes round into its -X face and stops there. The tip 5 under the top,
// its side 10 from the face at B0 (axis at X-65); B negative swings the tip
// towards +X by 360.25 sin |B| about the pivot, and the end's rim, 5 cos |B|
// further, meets the face at about |B| = 1.59°.
TEST(MillRotary, AJogOfBStopsAtTheFace) {
    Mill5 five;
    Workshop& shop = *five.shop;
    const Axes from = at(-65, 0, -285 + 110.25), to = at(-65, 0, -285 + 110.25, -10);
    Outcome o = go(shop, from, to, 1, true);
    ASSERT_TRUE(o.touched) << o.what;
    const P3 tip = shop.tip3(o.stop);
    const double b = -o.stop[B] * std::acos(-1.0) / 180;
    EXPECT_NEAR(tip[0], -65 + 360.25 * std::sin(b), 1e-9);
    // The rim at the face, within 9 µm (the piece is cut with its middle's axis).
    EXPECT_GT(b, 0);
    EXPECT_NEAR(tip[0] + 5 * std::cos(b), -50, 0.009);
}

// A C turn with the tool tilted by B turns its axis by C sin B. With the
// tip on the C axis (B30: 360.25 sin 30° = 180.125 from the gauge line) the
// tip does not move, and the pieces are those of the axis alone: 0.2° of it,
// 0.4° of C, 25 for a turn of 10°.
TEST(MillRotary, ATiltedCTurnGoesInPiecesOfTheAxis) {
    Mill5 five;
    Workshop& shop = *five.shop;
    MoveEvent e;
    e.g = 1;
    e.from_mach = at(0.5 * 360.25, 0, -100, 30);
    e.to_mach = at(0.5 * 360.25, 0, -100, 30, 10);
    e.to_prog = e.to_mach;
    EXPECT_NEAR(shop.tip3(e.from_mach)[0], 0, 1e-9);
    std::vector<MoveEvent> pieces;
    ASSERT_TRUE(shop.on_part(e, pieces));
    EXPECT_EQ(pieces.size(), 25u);
    for (const MoveEvent& p : pieces) {
        const P3 u = shop.axis3(p.from_mach), v = shop.axis3(p.to_mach);
        const double turn = std::acos(std::min(1.0, u[0] * v[0] + u[1] * v[1] + u[2] * v[2]));
        EXPECT_LE(turn * 180 / std::acos(-1.0), kAxisStep + 1e-9);
    }
}

// mill4's B table tilts the part about its axis (the setup's table.b.x
// and .b.z): seen from the part the vertical tool leans by B the other way
// round (Rot_Y(B) of forward4), and its tip turns about that axis.
TEST(MillRotary, ABTableTiltsThePart) {
    MachineProfile m4;
    builtin_machine("mill4", m4);
    workshop::Setup st;
    builtin_setup("mill", st);
    Workshop shop(m4, st, nullptr);
    const Axes om = at(st.mill.b_x + 10, 0, st.mill.b_z, 90);
    const P3 tip = shop.tip3(om), u = shop.axis3(om);
    EXPECT_NEAR(u[0], 1, 1e-12);
    EXPECT_NEAR(u[2], 0, 1e-12);
    // No tool: the gauge line's point 10 from the axis along X goes under it.
    EXPECT_NEAR(tip[0], st.mill.b_x, 1e-9);
    EXPECT_NEAR(tip[2], st.mill.b_z - 10, 1e-9);
}

}  // namespace
}  // namespace pupitre::workshop
