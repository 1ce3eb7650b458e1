// Interpreter: program flow, spindle, M functions, limits, never stuck.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>

#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

TEST(Flow, G77RangeEitherOrderAndRepeat) {
    Prog r("%1\nL1=0\nG79 N100\nN40 L1=L1+1\nN50\nN100 G77 N50 N40\nG77 N40 N50 S3\nM2\n");
    EXPECT_EQ(r.error(), 0);
    EXPECT_DOUBLE_EQ(r.L(1), 4);
}

TEST(Flow, SeedLoop6500) {
    // 000:10276-10298: N120..N150 run 34 times, L3 ends at 360.
    Prog r(
        "%6500\nL1=8.17 L2=9.95 L3=20 L4=20\n"
        "N120 G G54 G90 X56.02 Y-32.34 Z10\nN130 G1 Z-L1 F90\nN140 G1 X73.61 Y-42.5 Z-L2\n"
        "N150 G Z10\nN160 EDL3\nN170 G77 N120 N150\nN180 L3=L3+L4\nN190 G79 L3<=340 N120\n"
        "N200 G G52 X Y Z\nM2\n");
    EXPECT_EQ(r.error(), 0);
    EXPECT_DOUBLE_EQ(r.L(3), 360);
    EXPECT_EQ(r.cap.moves.size(), 34u * 4 + 1);
}

TEST(Flow, CallsAndNesting) {
    EXPECT_EQ(Prog("%1\nG77 H2\nM2\n%2\nG77 H1\n").error(), 26);  // runaway recursion
    EXPECT_EQ(Prog("%1\nG77 H9\nM2\n").error(), 25);
    EXPECT_EQ(Prog("%1\nG77 N10 N20\nM2\n").error(), 25);
    EXPECT_EQ(Prog("%1\nG79 N999\nM2\n").error(), 25);
    EXPECT_EQ(Prog("%1\nG77 -1\nM2\n").error(), 26);
}

TEST(Flow, M2InSubprogramEndsTheRun) {
    Prog r("%1\nG77 H2\nL1=5\nM2\n%2\nM2\n");
    EXPECT_EQ(r.error(), 0);
    EXPECT_DOUBLE_EQ(r.L(1), 0);
    EXPECT_EQ(r.cap.ends, 1);
}

TEST(Flow, Error20OnlyForTheMainProgram) {
    EXPECT_EQ(Prog("%1\nG77 H2\nM2\n%2\nL1=1\n").error(), 0);
    EXPECT_EQ(Prog("%1\nL1=1\n").error(), 20);
}

TEST(Flow, EndlessLoopIsStopped) {
    RunOptions o;
    o.max_blocks = 10000;
    Prog r("%1\nN10 G79 N10\n", "mill", {}, o);
    EXPECT_EQ(r.error(), err::kBlockBudget);
}

// Issue 14: the state repetition guard stops a loop whose state comes back at
// once, with the default budgets, however much work each pass does; a loop
// whose counter moves is not one.
TEST(Flow, EndlessLoopIsStoppedWhenItsStateComesBack) {
    Prog r("%1\nN10 G0 X10\nG1 X20 F100\nN20 G79 N10\n");
    EXPECT_EQ(r.error(), err::kBlockBudget);
    EXPECT_LT(r.in->blocks(), 10);  // the second backward jump, not 20,000,000 blocks
    Prog counted("%1\nL1=0\nN10 L1=L1+1\nG0 X10\nG0 X20\nG79 L1<5000 N10\nM2\n");
    EXPECT_EQ(counted.error(), 0);
    EXPECT_DOUBLE_EQ(counted.L(1), 5000);
}

TEST(Flow, MovesCountInTheWorkBudget) {
    // A G79 loop whose counter grows: no state repeats, the moves stop it.
    RunOptions o;
    o.max_blocks = 1000;
    // Drilling: three moves a block, more than two a block over the loop.
    Prog r(
        "%1\nG0 X0 Y0 Z50\nM3 M40 S800\nX10 Y20 Z22\nG81 Z10 ER32 F200\nL1=0\nN10 "
        "L1=L1+1\nX10\nX20\n"
        "X30\nX40\nX50\nX60\nG79 N10\n",
        "mill", {}, o);
    EXPECT_EQ(r.error(), err::kBlockBudget);
    EXPECT_LT(r.in->blocks(), 1000);  // the moves ran out first
    EXPECT_LE(r.in->moves(), 2 * 1000 + 8);
}

TEST(Flow, BlockSkip) {
    RunOptions on;
    on.block_skip = true;
    EXPECT_DOUBLE_EQ(Prog("%1\n/L1=7\nM2\n").L(1), 7);
    EXPECT_DOUBLE_EQ(Prog("%1\n/L1=7\nM2\n", "mill", {}, on).L(1), 0);
}

TEST(Spindle, ConstantSurfaceSpeedWithLimit) {
    // 000:1625-1684: G92 S1800, G96 S200: 509.3 rev/min at X125, 3183 limited to 1800 at X20.
    Prog r("%1\nG92 S1800\nG0 X150 Z200\nG96 S200 M3 M41\nG95 F.1\nG0 X125\nG1 X20\nZ100\nM2\n",
           "lathe");
    ASSERT_EQ(r.error(), 0);
    ASSERT_GE(r.cap.moves.size(), 4u);
    EXPECT_NEAR(r.cap.moves[2].rpm, 1000 * 200 / (std::numbers::pi * 125), 1e-6);
    EXPECT_NEAR(r.cap.moves[3].rpm, 1800, 1e-9);
}

TEST(Spindle, Errors) {
    EXPECT_EQ(Prog("%1\nG97\nM2\n").error(), 28);
    EXPECT_EQ(Prog("%1\nM3 M41\nG96 S100\nM2\n", "lathe").error(), 28);  // no diameter known
    EXPECT_EQ(Prog("%1\nG0 X50 Z10\nM3\nG96 S100\nM2\n", "lathe-manual").error(), 29);  // no range
    EXPECT_EQ(Prog("%1\nG0 X50 Z10\nM3\nG96 S100\nM2\n", "lathe").error(), 0);  // automatic ranges
    EXPECT_EQ(Prog("%1\nG0 X50 Z10\nM41 M3\nG97 S5000\nM2\n", "lathe").error(), 29);  // outside M41
    EXPECT_EQ(Prog("%1\nG95 F.1 G1 X10\nM2\n").error(), 831);  // G95 with the spindle stopped
    EXPECT_EQ(Prog("%1\nM64\nM2\n").error(), 899);
}

TEST(Spindle, M0StopsTheSpindle) {
    Prog r("%1\nS500 M3\nM0\nM2\n");
    ASSERT_EQ(r.cap.stops.size(), 1u);
    EXPECT_EQ(r.cap.spindles.back().dir, 5);
}

TEST(Motion, TimeModel) {
    // G1 at F100 over 10 mm: 6 s. Rapid: the slowest axis decides.
    Prog r("%1\nG0 X0 Y0 Z0\nG1 X10 F100\nG0 X10 Y0 Z-15\nM2\n");
    ASSERT_EQ(r.cap.moves.size(), 3u);
    EXPECT_NEAR(r.cap.moves[1].seconds, 6.0, 1e-9);
    EXPECT_NEAR(r.cap.moves[2].seconds, 15.0 / 15000 * 60, 1e-9);
}

// Issue 19: the warnings' branches that tests/warn does not reach.
TEST(Warnings, DecimalSpeedRunsAsWrittenAndNamesIt) {
    Prog r("%1\nG97 S333.5 M3\nM2\n", "lathe");
    std::string said;
    for (const Diag& d : r.in->diags())
        if (d.code == err::wFractionalRpm) said = d.detail;
    EXPECT_NE(said.find("turns at 333.500 rev/min"), std::string::npos) << said;
    ASSERT_FALSE(r.cap.spindles.empty());
    EXPECT_NEAR(r.cap.spindles[0].rpm, 333.5, 1e-9);
}

TEST(Warnings, AnLGivenBeforeTheRunIsSet) {
    // --set, the PARAM page and earlier programs (the console's power-on
    // lifetime) all count as setting it (docs/decisions.md, An L
    // variable read before it is set).
    const std::string text = "%1\nG0 XL2 Y0\nM2\n";
    Prog given(text, "mill", {{"L2", 5}});
    Prog unset(text, "mill");
    auto warned = [](const Prog& r) {
        int n = 0;
        for (const Diag& d : r.in->diags()) n += d.code == err::wLReadUnset;
        return n;
    };
    EXPECT_EQ(warned(given), 0);
    EXPECT_EQ(warned(unset), 1);
}

TEST(Motion, FeedIsClampedWithAWarning) {
    Prog r("%1\nG1 X10 F99999\nM2\n");
    EXPECT_EQ(r.error(), 0);
    bool warned = false;
    for (const Diag& d : r.in->diags()) warned = warned || d.code == err::wFeedClamped;
    EXPECT_TRUE(warned);
    EXPECT_NEAR(r.cap.moves[0].feed, r.machine.max_feed, 1e-9);
}

TEST(Motion, TravelLimits) {
    EXPECT_EQ(Prog("%1\nG0 X800\nM2\n").error(), 150);
    EXPECT_EQ(Prog("%1\nG0 Y-600\nM2\n").error(), 151);
    EXPECT_EQ(Prog("%1\nE60003=100000\nG0 X150\nM2\n").error(), 150);  // dynamic limit
    // An arc whose ends are inside but whose bulge is outside the travel.
    EXPECT_EQ(Prog("%1\nG0 X690 Y0 Z0\nG3 X690 Y20 I700 J10\nM2\n").error(), 150);
}

TEST(Motion, G52AndRadiusCompRestrictions) {
    EXPECT_EQ(Prog("%1\nG41 G1 X10 Y10\nG52 X0\nM2\n").error(), 27);
    EXPECT_EQ(Prog("%1\nG41 G1 X10 Y0\nM0\nM2\n").error(), 140);
    EXPECT_EQ(Prog("%1\nG41 G1 X10 Y0\nL100=1\nM2\n").error(), 140);
    EXPECT_EQ(Prog("%1\nG41 G1 X10 Y0\nL900=1\nG40 X0\nM2\n").error(), 0);
    EXPECT_EQ(Prog("%1\nG41 G1 X10 Y10\nG18\nM2\n").error(), 138);
    EXPECT_EQ(Prog("%1\nG41 G1 X10 Y0\nG74\nM2\n").error(), 143);
    EXPECT_EQ(Prog("%1\nD1 G41 G1 X10 Y0\nX20\nG40 X30\nM2\n", "mill", {{"D1.R", 5}}).error(), 0);
}

TEST(Codes, MachineAndModelAvailability) {
    EXPECT_EQ(Prog("%1\nG96 S100\nM2\n", "mill").error(), 2);
    EXPECT_EQ(Prog("%1\nG17\nM2\n", "lathe").error(), 2);
    EXPECT_EQ(Prog("%1\nG13\nM2\n").error(), 2);
    EXPECT_EQ(Prog("%1\nG7 X10 Z0\nM2\n", "lathe").error(), 4);
    EXPECT_EQ(Prog("%1\nT1 D300 M6\nM2\n").error(), 8);
    EXPECT_EQ(Prog("%1\nL1=300\nD L1\nM2\n").error(), 92);
    EXPECT_EQ(Prog("%1\nL1=-100\nS L1\nM2\n").error(), 92);
    EXPECT_EQ(Prog("%1\nM-3\nM2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nX1.23456789\nM2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nG0 X1 X2\nM2\n").error(), 3);
    EXPECT_EQ(Prog("%1\nG0 X1 G52 Z0\nM2\n").error(), 3);
}

TEST(Codes, FeedUnitChangeWithoutF) {
    // Handbook programs write G95 alone and F later (000:10037): accepted.
    EXPECT_EQ(Prog("%1\nG95\nS100 M3\nG1 X10 F.1\nM2\n").error(), 0);
    EXPECT_EQ(Prog("%1\nG95\nS100 M3\nG1 X10\nM2\n").error(), 2);
}

TEST(Text, SeveralProgramsAndNoHeader) {
    Prog r("G0 X1 Y1\nG1 X2\n");  // 004_rectangle: a fragment, error 20
    EXPECT_EQ(r.error(), 20);
    EXPECT_EQ(r.cap.moves.size(), 2u);
}

// EM- / EM+ (docs/decisions.md, EM- and EM+) give the part's extremes for the graphic
// display; their axis words do not move the machine.
TEST(Interp, ExtremesEmDoNotMove) {
    pupitre::test::Prog p("%1\nG0 X5 Y5 Z5\nEM- X0 Y0 Z-10\nEM+ X100 Y50 Z0\nM2\n", "mill");
    ASSERT_EQ(p.in->run_to_end(), pupitre::StepResult::ended);
    ASSERT_EQ(p.cap.moves.size(), 1u);
    EXPECT_DOUBLE_EQ(p.in->program_pos()[pupitre::X], 5);
    EXPECT_DOUBLE_EQ(p.in->program_pos()[pupitre::Z], 5);
}

// The parts of a block take effect in the order of the codes table's
// block_steps() (000:497-498; pupitre-iso(5), MODAL STATE AND THE ORDER INSIDE
// A BLOCK): a block with an assignment, M03 (before the motion), S, a $
// message, a move, G04 and M05 (after the motion) reports its events in that
// order.
TEST(BlockSteps, ExecuteFollowsTheCodesTable) {
    struct Order : MachineSink {
        std::vector<ExecStep> seen;
        void move(const MoveEvent&) override { seen.push_back(ExecStep::motion); }
        void dwell(const Loc&, double) override { seen.push_back(ExecStep::dwell); }
        void message(const Loc&, int, std::string_view) override {
            seen.push_back(ExecStep::message);
        }
        void spindle(const SpindleEvent& e) override {
            seen.push_back(e.dir == 5 ? ExecStep::m_after : ExecStep::spindle);
        }
    } order;
    std::vector<ExecStep> table;
    for (const BlockStep& s : block_steps()) table.push_back(s.step);
    ASSERT_EQ(table.size(), 9u);
    EXPECT_EQ(table.front(), ExecStep::assign);
    EXPECT_EQ(table.back(), ExecStep::flow);
    MachineProfile m;
    ASSERT_TRUE(builtin_machine("lathe", m));
    ProgramMemory mem;
    ASSERT_FALSE(mem.load_text(
        "t.iso", "%1\nN10 G0 X50 Z50 F100\nN20 L1=2 G1 X40 Z40 G4 F1 M3 S500 M5 $1 HI\nM2\n"));
    Interpreter in(m, mem, order);
    in.start(mem.first());
    in.run_to_end();
    ASSERT_FALSE(in.has_errors()) << format_diag(in.diags().front());
    order.seen.erase(order.seen.begin());  // N10's move
    const std::vector<ExecStep> want{ExecStep::spindle, ExecStep::message, ExecStep::motion,
                                     ExecStep::dwell, ExecStep::m_after};
    ASSERT_GE(order.seen.size(), want.size());
    order.seen.resize(want.size());  // the M2 block's stop
    EXPECT_EQ(order.seen, want);
    auto rank = [&](ExecStep s) {
        return std::find(table.begin(), table.end(), s) - table.begin();
    };
    for (size_t i = 1; i < want.size(); ++i) EXPECT_LT(rank(want[i - 1]), rank(want[i]));
}

// ARCHITECTURE.md (Conventions) promises that two interpreters on two threads are safe: nothing in
// the core is shared behind a flag (addr_name's table is built at compile
// time). Both runs, at once, give what one run alone gives.
TEST(Threads, TwoInterpretersOnTwoThreadsRunAsOneAlone) {
    std::string text = "%1\nG0 X0 Y0 Z10\n";
    for (int i = 0; i < 2000; ++i)
        text += "G1 X" + std::to_string(i % 50) + " Y" + std::to_string(i % 7) + " F500\n";
    text += "G1 X1.23456\nM2\n";  // error 1: too many digits after X
    auto run = [&] {
        test::Prog p(text);
        std::string out = std::to_string(p.cap.moves.size());
        for (const Diag& d : p.in->diags()) out += " " + format_diag(d);
        return out;
    };
    const std::string alone = run();
    ASSERT_NE(alone.find("too many digits after X"), std::string::npos) << alone;
    std::string a, b;
    std::thread t1([&] { a = run(); });
    std::thread t2([&] { b = run(); });
    t1.join();
    t2.join();
    EXPECT_EQ(a, alone);
    EXPECT_EQ(b, alone);
}

// A diagnostic names the column of the word at fault, and none for an error
// about the whole block (pupitre(1), DIAGNOSTICS: FILE:LINE[:COL]).
TEST(Diagnostics, ColumnOfTheWordOnlyWhenAWordIsAtFault) {
    test::Prog word("%1\nG0 X10 Y1.23456\nM2\n");
    ASSERT_EQ(word.error(), 1);
    EXPECT_EQ(word.in->diags().front().column, 8);  // Y1.23456: too many digits
    EXPECT_EQ(format_diag(word.in->diags().front()).substr(0, 11), "test.iso:2:");
    test::Prog block("%1\nG0 X10 Y5000 F100\nM2\n");
    ASSERT_EQ(block.error(), 151);  // Y travel: the block, not its last word
    EXPECT_EQ(block.in->diags().front().column, 0);
    EXPECT_EQ(format_diag(block.in->diags().front()).substr(0, 12), "test.iso:2: ");
}

// set() and get() read one table of corrector fields: what one writes, the
// other reads, a mill's end radius A (or TIP) included.
TEST(Settings, GetReadsEveryCorrectorFieldSetWrites) {
    test::Prog mill("%1\nM2\n");
    for (const char* f : {"L", "R", "DL", "DR", "A", "TIP"}) {
        std::string name = std::string("D4.") + f;
        ASSERT_EQ(mill.in->set(name, 12.5), "") << name;
        double v = 0;
        ASSERT_TRUE(mill.in->get(name, v)) << name;
        EXPECT_EQ(v, 12.5) << name;
    }
    EXPECT_NE(mill.in->set("D4.X", 1), "");  // a lathe's field
    test::Prog lathe("%1\nM2\n", "lathe");
    for (const char* f : {"X", "Z", "R", "C", "DX", "DZ"}) {
        std::string name = std::string("D4.") + f;
        ASSERT_EQ(lathe.in->set(name, 3), "") << name;
        double v = 0;
        ASSERT_TRUE(lathe.in->get(name, v)) << name;
        EXPECT_EQ(v, 3) << name;
    }
    double v = 0;
    ASSERT_EQ(lathe.in->set("PREF.Z", -250), "");
    ASSERT_TRUE(lathe.in->get("PREF.Z", v));
    EXPECT_EQ(v, -250);
    EXPECT_FALSE(lathe.in->get("PREF.ZZ", v));
}
