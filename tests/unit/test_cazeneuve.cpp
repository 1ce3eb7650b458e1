// The Cazeneuve HB CNC dialect (seed 003, chapter VI; pupitre-cazeneuve(5)):
// one test per rule, with the seed line it comes from.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/interp/caz.hpp"
#include "core/parse/codes.hpp"
#include "helpers.hpp"

namespace pupitre {
namespace {

using test::Prog;

Prog caz(const std::string& text) {
    return Prog(text, "cazeneuve");
}

TEST(Cazeneuve, ProfileNamesItsDialect) {
    MachineProfile m;
    ASSERT_TRUE(builtin_machine("cazeneuve", m));
    EXPECT_EQ(m.dialect, Dialect::cazeneuve);
    EXPECT_FALSE(m.x_diameter);      // X a radius (003:857-871)
    ASSERT_EQ(m.ranges.size(), 2u);  // HB CNC 3: 50-325, 400-2100 (003:905-906)
    EXPECT_EQ(m.ranges[1].max, 2100);
    MachineProfile lathe;
    ASSERT_TRUE(builtin_machine("lathe", lathe));
    EXPECT_EQ(lathe.dialect, Dialect::num);  // the default
    MachineProfile bad;
    EXPECT_FALSE(
        parse_machine("name = x\nkind = lathe\naxes = X Z\ndialect = fanuc\n", bad).empty());
}

// The HB CNC 2 as a profile option (003:900-906): its spindle ranges.
TEST(Cazeneuve, HbCnc2ModelHasItsOwnRanges) {
    const std::string base =
        "name = hb\nkind = lathe\ndialect = cazeneuve\naxes = X Z\nx_programming = radius\n"
        "travel.X = -60 300\ntravel.Z = -1630 200\nspindle.auto_range = yes\n";
    MachineProfile three, two;
    ASSERT_EQ(parse_machine(base + "model = hbcnc3\n", three), "");
    ASSERT_EQ(parse_machine(base + "model = hbcnc2\n", two), "");
    EXPECT_EQ(three.model, kHbCnc3);
    EXPECT_EQ(two.model, kHbCnc2);
    ASSERT_EQ(two.ranges.size(), 2u);
    EXPECT_EQ(two.ranges[0].max, 375);
    EXPECT_EQ(two.ranges[1].max, 3000);
    EXPECT_EQ(two.spindle_max, 3000);
    EXPECT_EQ(three.spindle_max, 2100);
    // Only this dialect has them.
    MachineProfile num;
    EXPECT_NE(parse_machine("name = x\nkind = lathe\naxes = X Z\nmodel = hbcnc2\n", num), "");
    // S2500 fits the HB CNC 2's high range, not the HB CNC 3's (2053).
    const std::string text = "N10 M3 S2500\nN20 M2\n";
    ProgramMemory mem;
    mem.load_text("t.iso", text);
    test::Capture cap2, cap3;
    Interpreter in2(two, mem, cap2, RunOptions{}), in3(three, mem, cap3, RunOptions{});
    in2.start(mem.first());
    in2.run_to_end();
    in3.start(mem.first());
    in3.run_to_end();
    auto first_error = [](const Interpreter& in) {
        for (const Diag& e : in.diags())
            if (e.is_error()) return e.code;
        return 0;
    };
    EXPECT_EQ(first_error(in2), 0);
    EXPECT_EQ(first_error(in3), caz::kSpeed);
}

// The same number means something else per dialect (pupitre-cazeneuve(5)).
TEST(Cazeneuve, CodesTableHasItsOwnRows) {
    const GCode* num92 = find_g(92);
    const GCode* caz92 = find_g(92, Dialect::cazeneuve);
    ASSERT_TRUE(num92 && caz92);
    EXPECT_NE(num92->text, caz92->text);  // origin preset / facing cycle (003:1471)
    EXPECT_EQ(find_g(7)->support, Support::option);
    EXPECT_EQ(find_g(7, Dialect::cazeneuve)->support, Support::yes);  // G7XZ (003:1083)
    EXPECT_TRUE(find_m(50, Dialect::cazeneuve));                      // 003:968
    EXPECT_TRUE(find_g(25, Dialect::cazeneuve));                      // the G96 limit (003:1571)
    EXPECT_FALSE(find_g(50, Dialect::cazeneuve));
}

// Lengths in micrometres, X a radius (003:857-885): X15000 Z-30000 is r15 z-30.
TEST(Cazeneuve, MicrometresAndRadius) {
    Prog p = caz("N10 G X15000 Z-30000\nN20 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 1u);
    EXPECT_NEAR(p.cap.moves[0].to_prog[X], 15.0, 1e-9);
    EXPECT_NEAR(p.cap.moves[0].to_prog[Z], -30.0, 1e-9);
    EXPECT_FALSE(p.cap.moves[0].x_diameter);
}

// G alone is G00 (003:993).
TEST(Cazeneuve, GAloneIsRapid) {
    Prog p = caz("N10 G1 X1000 F100\nN20 G X2000\nN30 M2\n");
    ASSERT_EQ(p.cap.moves.size(), 2u);
    EXPECT_EQ(p.cap.moves[1].g, 0);
}

// An axis word without a value leaves the axis where it is (003:997).
TEST(Cazeneuve, BlankAxisStays) {
    Prog p = caz("N10 G X18000 Z3000\nN20 M3 S500\nN30 G1 G95 X Z-8000 F200\nN40 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 2u);
    EXPECT_NEAR(p.cap.moves[1].to_prog[X], 18.0, 1e-9);
    EXPECT_NEAR(p.cap.moves[1].to_prog[Z], -8.0, 1e-9);
}

// N has at most five digits (003:812).
TEST(Cazeneuve, NFiveDigits) {
    EXPECT_EQ(caz("N99999 M2\n").error(), 0);
    EXPECT_NE(caz("N100000 M2\n").error(), 0);
}

// G95: F in micrometres per revolution, F250 = 0.25 mm/rev (003:891, 894);
// G94: mm/min (003:890).
TEST(Cazeneuve, FeedUnits) {
    Prog p = caz("N10 M3 S1000\nN20 G1 G95 X1000 F250\nN30 G94 X2000 F100\nN40 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 2u);
    EXPECT_NEAR(p.cap.moves[0].feed, 250.0, 1e-6);  // 0.25 mm/rev at 1000 rev/min
    EXPECT_NEAR(p.cap.moves[1].feed, 100.0, 1e-6);
}

// G4: F in tenths of a second ("G4 F4,1 - avec Fmax 60000", 003:1018).
TEST(Cazeneuve, DwellTenths) {
    Prog p = caz("N10 G4 F50\nN20 M2\n");
    ASSERT_EQ(p.error(), 0);
    EXPECT_NEAR(p.in->seconds(), 5.0, 1e-9);
}

// T101: turret position 1, corrector 01 (003:1036-1039); 1-4 and 11-14 (003:1028-1030).
TEST(Cazeneuve, TurretAndCorrector) {
    Prog p = caz("N10 T101\nN20 T1104\nN30 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.tools.size(), 2u);
    EXPECT_EQ(p.cap.tools[0], std::make_pair(1, 1));
    EXPECT_EQ(p.cap.tools[1], std::make_pair(11, 4));
    EXPECT_EQ(caz("N10 T501\nN20 M2\n").error(), caz::kTool);
}

// G7XZ: a rapid back to the indexing point (003:1083).
TEST(Cazeneuve, G7XZReturnsToIndexingPoint) {
    Prog p = caz("N10 G X10000 Z5000\nN20 G7XZ\nN30 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 2u);
    EXPECT_EQ(p.cap.moves[1].g, 0);
    EXPECT_NEAR(p.cap.moves[1].to_mach[X], p.machine.home[X], 1e-9);
    EXPECT_NEAR(p.cap.moves[1].to_mach[Z], p.machine.home[Z], 1e-9);
}

// S in rev/min with the two ranges (003:903-906); M3 M4 M5 (003:910-914).
TEST(Cazeneuve, SpindleRanges) {
    Prog p = caz("N10 M3 S1500\nN20 M4 S135\nN30 M5\nN40 M2\n");
    ASSERT_EQ(p.error(), 0);
    EXPECT_EQ(caz("N10 M3 S9000\nN20 M2\n").error(), caz::kSpeed);
    EXPECT_EQ(caz("N10 M3 S350\nN20 M2\n").error(), caz::kSpeed);  // between the ranges
}

// G2/G3 with I K the centre from the origin (003:855, 874): ex1's R20 arc.
TEST(Cazeneuve, ArcCentreAbsolute) {
    Prog p = caz("N10 G1 X15000 Z-30000 F100\nN20 G2 X30000 Z-63229 I30000 K-43229\nN30 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 2u);
    EXPECT_NEAR(p.cap.moves[1].sweep, -131.4, 0.1);
    // A blank axis is where the tool is (003:997), in an arc too; I and K are
    // both needed, there is no profile geometry to complete a circle.
    Prog half = caz("N10 G1 X10000 Z0 F100\nN20 G2 X Z-10000 I10000 K-5000\nN30 M2\n");
    ASSERT_EQ(half.error(), 0);
    EXPECT_NEAR(half.cap.moves.back().to_prog[X], 10.0, 1e-9);
    EXPECT_NEAR(half.cap.moves.back().to_prog[Z], -10.0, 1e-9);
    EXPECT_EQ(caz("N10 G1 X10000 Z0 F100\nN20 G2 X20000 Z-10000 I20000\nN30 M2\n").error(),
              caz::kArc);
}

// G33: the pitch in micrometres (003:1161), the spindle turning.
TEST(Cazeneuve, G33Pitch) {
    Prog p = caz("N10 M3 S1000\nN20 G X9000 Z5000\nN30 G33 Z-30000 F1000\nN40 G X11000\nN50 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 3u);
    EXPECT_NEAR(p.cap.moves[1].feed, 1000.0, 1e-6);  // 1 mm/rev at 1000 rev/min
    EXPECT_EQ(caz("N10 G33 Z-30000 F1000\nN20 M2\n").error(), caz::kSpindleStopped);
}

// M0, M1, M2, M30 (003:958-972); the end of the text without them.
TEST(Cazeneuve, Ends) {
    EXPECT_EQ(caz("N10 M30\n").error(), 0);
    EXPECT_EQ(caz("N10 M2\n").error(), 0);
    EXPECT_EQ(caz("N10 G X1000\n").error(), caz::kNoEnd);
    EXPECT_EQ(caz("N10 M0\nN20 M2\n").cap.stops.size(), 1u);
}

// Error categories (003:798): syntax, function, capacity.
TEST(Cazeneuve, ErrorCategories) {
    EXPECT_EQ(caz("N10 G X1.5\nN20 M2\n").error(), caz::kNumber);
    EXPECT_EQ(caz("N10 G X1000 R5\nN20 M2\n").error(), caz::kSyntax);
    EXPECT_EQ(caz("N10 G X1000 F1 F2\nN20 M2\n").error(), caz::kTwice);
    EXPECT_EQ(caz("N10 G50 S100\nN20 M2\n").error(), caz::kUnknownG);
    EXPECT_EQ(caz("N10 G31 X1 Z1\nN20 M2\n").error(), caz::kFunction);
    EXPECT_EQ(caz("N10 G34 X1 Z1\nN20 M2\n").error(), caz::kFunction);
    EXPECT_EQ(caz("N10 G X999000\nN20 M2\n").error(), caz::kTravelX);
    EXPECT_EQ(caz::category_of(caz::kSyntax), "syntax");
    EXPECT_EQ(caz::category_of(caz::kArc), "function");
    EXPECT_EQ(caz::category_of(caz::kSpeed), "capacity");
}

// G34 X Z I K D F: passes I deeper each, from X + D to X, each plunge,
// thread, retract, return (003:1324-1342); ex12's first call.
TEST(Cazeneuve, G34ThreadingCycle) {
    Prog p =
        caz("N10 M3 S500\nN20 G X20000 Z2000\nN30 G34 X17400 Z-30000 I200 K D600 F1000\n"
            "N40 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 1u + 3 * 4);
    const double radii[] = {17.8, 17.6, 17.4};
    for (int k = 0; k < 3; ++k) {
        const MoveEvent& thread = p.cap.moves[size_t(2 + 4 * k)];
        EXPECT_NEAR(thread.to_prog[X], radii[k], 1e-9);
        EXPECT_NEAR(thread.to_prog[Z], -30.0, 1e-9);
        EXPECT_NEAR(thread.feed, 500.0, 1e-6);  // a 1 mm pitch at 500 rev/min
    }
    EXPECT_NEAR(p.cap.moves.back().to_prog[X], 20.0, 1e-9);  // back at the start
    EXPECT_NEAR(p.cap.moves.back().to_prog[Z], 2.0, 1e-9);
}

// G31, the threading cycle G71 generates and ex13's taper threading cycle
// (003:1160, 1393, 1418), runs as G34: here a taper, K the radius gained at Z.
TEST(Cazeneuve, G31RunsAsG34) {
    Prog p =
        caz("N10 M3 S500\nN20 G X20000 Z2000\nN30 G31 X17400 Z-30000 I300 K1000 D600 F1500\n"
            "N40 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 1u + 2 * 4);
    const double radii[] = {17.7, 17.4};
    for (int k = 0; k < 2; ++k) {
        const MoveEvent& plunge = p.cap.moves[size_t(1 + 4 * k)];
        const MoveEvent& thread = p.cap.moves[size_t(2 + 4 * k)];
        EXPECT_NEAR(plunge.to_prog[X], radii[k], 1e-9);
        EXPECT_NEAR(thread.to_prog[X], radii[k] + 1.0, 1e-9);  // the taper
        EXPECT_NEAR(thread.to_prog[Z], -30.0, 1e-9);
        EXPECT_NEAR(thread.feed, 750.0, 1e-6);  // a 1.5 mm pitch at 500 rev/min
    }
}

// G92 X Z I K is a facing cycle here (003:1467-1477), not an origin preset:
// ex16's 25 mm in passes of 4, at K100 = 0.1 mm/rev.
TEST(Cazeneuve, G92FacingCycle) {
    Prog p = caz("N10 M4 S800\nN20 G95 X52000 Z0\nN30 G92 X10000 Z-25000 I4000 K100\nN40 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 1u + 7 * 4);
    for (int k = 0; k < 7; ++k) {
        const MoveEvent& face = p.cap.moves[size_t(2 + 4 * k)];
        EXPECT_EQ(face.g, 1);
        EXPECT_NEAR(face.to_prog[X], 10.0, 1e-9);
        EXPECT_NEAR(face.to_prog[Z], k == 6 ? -25.0 : -4.0 * (k + 1), 1e-9);
        EXPECT_NEAR(face.feed, 80.0, 1e-6);
    }
    EXPECT_NEAR(p.in->program_pos()[X], 52.0, 1e-9);  // no preset: the position is the tool's
}

// G71 X Z I K D F, the turning cycle (003:1399-1418), also written G81
// (003:1307, 1798): passes I deep from X + D to X, each at F µm/rev.
TEST(Cazeneuve, G71TurningCycle) {
    for (const char* g : {"G71", "G81"}) {
        Prog p = caz(std::string("N10 M3 S1000\nN20 G X20000 Z2000\nN30 ") + g +
                     " X15000 Z-40000 I2000 K D5000 F200\nN40 M2\n");
        ASSERT_EQ(p.error(), 0) << g;
        ASSERT_EQ(p.cap.moves.size(), 1u + 3 * 4) << g;
        const double radii[] = {18.0, 16.0, 15.0};
        for (int k = 0; k < 3; ++k) {
            const MoveEvent& cut = p.cap.moves[size_t(2 + 4 * k)];
            EXPECT_EQ(cut.g, 1);
            EXPECT_NEAR(cut.to_prog[X], radii[k], 1e-9);
            EXPECT_NEAR(cut.to_prog[Z], -40.0, 1e-9);
            EXPECT_NEAR(cut.feed, 200.0, 1e-6);  // 0.2 mm/rev at 1000 rev/min
        }
    }
    EXPECT_EQ(caz("N10 M3 S1000\nN20 G71 X15000 Z-40000 I2000\nN30 M2\n").error(), caz::kFunction);
}

// G82 is the facing cycle as G92 (003:1308, 1799).
TEST(Cazeneuve, G82FacingAsG92) {
    Prog p = caz("N10 M4 S800\nN20 G X52000 Z0\nN30 G82 X10000 Z-8000 I4000 K100\nN40 M2\n");
    ASSERT_EQ(p.error(), 0);
    ASSERT_EQ(p.cap.moves.size(), 1u + 2 * 4);
    EXPECT_NEAR(p.cap.moves[6].to_prog[Z], -8.0, 1e-9);
}

// The CNP: G41 is the tool left of the profile as the thesis draws the front
// turret (003:1791, 1915-1919): turning an outside diameter towards the chuck,
// the nose centre runs r outside it. G7XZ ends it (003:1803).
TEST(Cazeneuve, NoseRadiusCompensationFrontTurret) {
    const std::string text =
        "N10 T101\nN20 M3 S800\nN30 G X10000 Z6000\nN40 G95 G41 Z0 F150\n"
        "N50 G1 Z-50000\nN60 G1 X20000\nN70 G7XZ\nN80 M2\n";
    Prog plain = caz(text);
    ASSERT_EQ(plain.error(), 0);
    EXPECT_FALSE(plain.in->comp_active());
    Prog p(text, "cazeneuve", {{"D1.R", 3}});
    ASSERT_EQ(p.error(), 0);
    bool outside = false;
    for (const MoveEvent& m : p.cap.moves)
        if (m.loc.n == 50) outside = std::abs(m.to_prog[X] - 13.0) < 1e-6;
    EXPECT_TRUE(outside);
    EXPECT_FALSE(p.in->comp_active());  // G7XZ ended it
}

// M2 ends the CNP (003:1801): no error 140 as on the NUM.
TEST(Cazeneuve, M2EndsCompensation) {
    Prog p(
        "N10 T101\nN20 M3 S800\nN30 G X10000 Z6000\nN40 G95 G41 Z0 F150\n"
        "N50 G1 Z-50000\nN60 M2\n",
        "cazeneuve", {{"D1.R", 3}});
    EXPECT_EQ(p.error(), 0);
}

// The gauges pilot the nose centre under the CNP (003:1912): no orientation C.
TEST(Cazeneuve, CorrectorsHaveNoOrientation) {
    Prog p("N10 M2\n", "cazeneuve");
    EXPECT_NE(p.in->set("D1.C", 3), "");
    EXPECT_EQ(p.in->set("D1.C", 0), "");
    EXPECT_EQ(p.in->set("D1.R", 0.8), "");
}

// G25 S limits the spindle under G96 (003:1124-1126; gorge_etroite's
// "N50 G25 S1500" before its G96, 003:1571; example 7's S max 1500).
// The speed of the last spindle event before the end's stop.
double running_rpm(const Prog& p) {
    double rpm = -1;
    for (const SpindleEvent& e : p.cap.spindles)
        if (e.dir == 3 || e.dir == 4) rpm = e.rpm;
    return rpm;
}

TEST(Cazeneuve, G25LimitsTheConstantSurfaceSpeed) {
    const std::string head = "N10 M4 S450\nN20 G X5000 Z1000\n";
    Prog free = caz(head + "N30 G96 S120 X5000\nN40 G1 G95 X1000 F200\nN50 M2\n");
    Prog limited = caz(head + "N25 G25 S1500\nN30 G96 S120 X5000\nN40 G1 G95 X1000 F200\nN50 M2\n");
    ASSERT_EQ(free.error(), 0);
    ASSERT_EQ(limited.error(), 0);
    EXPECT_NEAR(running_rpm(free), 2100, 1e-9);  // the machine's maximum
    EXPECT_NEAR(running_rpm(limited), 1500, 1e-9);
    // S is the limit, not a speed: the spindle keeps its 450 rev/min.
    Prog only = caz(head + "N25 G25 S1500\nN30 M2\n");
    EXPECT_NEAR(running_rpm(only), 450, 1e-9);
    EXPECT_EQ(caz("N10 G25\nN20 M2\n").error(), caz::kFunction);
    EXPECT_EQ(caz("N10 G96 G25 S1500 X5000\nN20 M2\n").error(), caz::kFunction);
}

// The VCC on the rear turret: x is signed (003:1110-1119), so the speed is
// 1000 V / (pi 2 |x of G96 + the move|), the front turret's mirror: the
// thesis's narrow-groove program plunges so (issue 39 item 4).
TEST(Cazeneuve, ConstantSurfaceSpeedOnTheRearTurret) {
    for (const char* sign : {"", "-"}) {
        const std::string s(sign);
        Prog p = caz("N10 M4 S450\nN20 T101\nN30 G00 X" + s + "52000 Z-43000\nN40 G25 S1500\n" +
                     "N50 G96 S120 X" + s + "52000\nN60 G1 G95 X" + s + "40000 F50\nN70 G1 X" + s +
                     "20000\nN80 M2\n");
        ASSERT_EQ(p.error(), 0) << sign;
        std::vector<double> rpm;
        for (const SpindleEvent& e : p.cap.spindles)
            if (e.dir == 3 || e.dir == 4) rpm.push_back(e.rpm);
        ASSERT_GE(rpm.size(), 2u) << sign;
        // 120 m/min on r40 and r20: 477.5 and 954.9 rev/min, on either side.
        EXPECT_NEAR(rpm[rpm.size() - 2], 120000 / (std::numbers::pi * 80), 0.05) << sign;
        EXPECT_NEAR(rpm.back(), 120000 / (std::numbers::pi * 40), 0.05) << sign;
    }
}

// G95 has a maximum of its own, 9.2 m/min, where G94 stops at 5.1 (003:890-891).
TEST(Cazeneuve, FeedPerRevolutionHasItsOwnMaximum) {
    const std::string head = "N10 M3 S1500\nN20 G X20000 Z1000\n";
    Prog rev = caz(head + "N30 G95 G1 Z-10000 F5000\nN40 G1 Z-20000 F9000\nN50 M2\n");
    ASSERT_EQ(rev.error(), 0);
    ASSERT_GE(rev.cap.moves.size(), 3u);
    EXPECT_NEAR(rev.cap.moves[1].feed, 7500, 1e-6);  // 5 mm/rev at 1500: above G94's 5100
    EXPECT_NEAR(rev.cap.moves[2].feed, 9200, 1e-6);  // 13.5 m/min: limited to 9.2
    Prog min = caz(head + "N30 G94 G1 Z-10000 F7500\nN40 M2\n");
    EXPECT_NEAR(min.cap.moves[1].feed, 5100, 1e-6);  // G94's own
}

// A block skip mark ends the CNP (003:1804: "I saut de bloc", the OCR's "/"),
// whether the switch skips the block or runs it: N60 then runs on the
// programmed X, not one nose radius outside it.
TEST(Cazeneuve, BlockSkipEndsCompensation) {
    const std::string text =
        "N10 T101\nN20 M3 S800\nN30 G X10000 Z6000\nN40 G95 G41 Z0 F150\n"
        "N50 G1 Z-20000\n/N55 G1 Z-30000\nN60 G1 Z-50000\nN70 G7XZ\nN80 M2\n";
    for (bool skip : {false, true}) {
        RunOptions o;
        o.block_skip = skip;
        Prog p(text, "cazeneuve", {{"D1.R", 3}}, o);
        ASSERT_EQ(p.error(), 0) << skip;
        double x50 = 0, x60 = 0;
        for (const MoveEvent& m : p.cap.moves) {
            if (m.loc.n == 50) x50 = m.to_prog[X];
            if (m.loc.n == 60) x60 = m.to_prog[X];
        }
        EXPECT_NEAR(x50, 13.0, 1e-6) << skip;  // under the CNP
        EXPECT_NEAR(x60, 10.0, 1e-6) << skip;  // ended by the mark
    }
}

}  // namespace
}  // namespace pupitre
