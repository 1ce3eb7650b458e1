// The machining centre's workshop with rotary axes (issue 15): a C table
// (mill5) turns the part under the vertical tool; B must stay at 0 (1206).
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

// B tilts the tool (mill5's head) or the part (mill4's table): the move is
// not made, with alarm 1206; back to B0 is let through.
TEST(MillRotary, BAwayFromZeroIsNotModelled) {
    const char* tilt = "%7\nN10 T1 D1 M6\nN20 G0 X-80 Y0 Z5\nN30 B10\nN40 M2\n";
    test::ShopRun r5("mill5", tilt, kRight, "");
    ASSERT_EQ(r5.crash(), kNotModelled);
    const Crash& c = r5.shop->crashes().front();
    EXPECT_EQ(c.loc.line, 4);
    EXPECT_DOUBLE_EQ(c.om[B], 0);  // stopped at its start
    EXPECT_NE(c.what.find("B10.000: the workshop models the tool vertical"), std::string::npos)
        << c.what;
    MachineProfile m4;
    builtin_machine("mill4", m4);
    workshop::Setup st;
    builtin_setup("mill", st);
    Workshop shop(m4, st, nullptr);
    MoveEvent e;
    e.g = 0;
    e.to_mach[B] = 30;
    EXPECT_TRUE(shop.apply(e).crashed);
    EXPECT_EQ(shop.crashes().front().code, kNotModelled);
    shop.clear_crash();
    std::swap(e.from_mach, e.to_mach);  // back to B0
    EXPECT_FALSE(shop.apply(e).crashed);
    // A jog of B too, even with no tool in the spindle.
    std::swap(e.from_mach, e.to_mach);
    EXPECT_TRUE(shop.jog(e, true).crashed);
    EXPECT_EQ(shop.crashes().front().code, kNotModelled);
}

}  // namespace
}  // namespace pupitre::workshop
