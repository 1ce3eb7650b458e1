// The console's animated run follows the plan (issue 35 item 3): the feed
// shown rises from rest, reaches F and falls before a corner or an exact
// stop; the cycle time is the planner's, `run`'s; the pages read the state of
// the block shown while the interpreter works ahead of it; an alarm shows at
// its block.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/plan/plan_sink.hpp"
#include "core/sim/sim.hpp"

using namespace pupitre;

namespace {

// A slow mill (100 mm/s² on every axis): F600, 10 mm/s, takes 0.1 s and
// 0.5 mm to reach.
struct Slow {
    MachineProfile m;
    ProgramMemory mem;
    std::unique_ptr<Sim> sim;
    explicit Slow(const std::string& text, const std::string& name = "mill", double accel = 100) {
        builtin_machine(name, m);
        m.homing_required = false;
        for (auto& a : m.axes)
            if (a.accel > 0) a.accel = accel;
        mem.load_text("t.iso", text);
        sim = std::make_unique<Sim>(m, mem);
        sim->select(mem.programs().front()->number);
    }
    void settle(double step = 0.01) {
        for (double t = 0; t < 3600 && sim->state() == RunState::running; t += step)
            sim->advance(step);
    }
    // The cycle time `pupitre run` gives: the same machine, the planner
    // after the interpreter (console/cli_run.cpp without a workshop).
    double run_seconds() {
        ProgramMemory m2 = mem.clone();
        plan::PlanSink planner(m);
        RunOptions o;
        Interpreter in(m, m2, planner, o);
        in.start(m2.programs().front()->number);
        in.run_to_end();
        planner.finish();
        return planner.report().seconds;
    }
};

struct Sample {
    double x, feed;
};

}  // namespace

TEST(SimPlan, FeedNowRisesFromRestReachesFAndFallsBeforeTheCorner) {
    Slow k("%1\nG0 G9 X0 Y0 Z0\nG1 X100 F600\nY100\nG4 F1\nM2\n");
    ASSERT_EQ(k.sim->cycle_start(), "");
    std::vector<Sample> first;  // along G1 X100
    double after_corner = -1;
    for (int i = 0; i < 100000 && k.sim->state() == RunState::running; ++i) {
        k.sim->advance(0.001);
        if (k.sim->motion() != 1) continue;
        const Axes p = k.sim->op();
        if (k.sim->loc().line == 3) first.push_back({p[X], k.sim->feed()});
        if (k.sim->loc().line == 4 && after_corner < 0) after_corner = k.sim->feed();
    }
    ASSERT_GT(first.size(), 1000u);
    // From rest: the first millisecond is at 100 mm/s² (0.1 mm/s, 6 mm/min).
    EXPECT_LT(first.front().feed, 60);
    EXPECT_GT(first.front().feed, 0);
    double peak = 0;
    for (const Sample& s : first) peak = std::max(peak, s.feed);
    EXPECT_NEAR(peak, 600, 1e-6);
    auto at = [&](double x) {
        for (const Sample& s : first)
            if (s.x >= x) return s.feed;
        return -1.0;
    };
    EXPECT_LT(at(0.1), 600 * 0.75);  // still rising: v² = 2 a x
    EXPECT_NEAR(at(50), 600, 1e-6);  // mid-move: at F
    // Before the corner the speed falls to what the turn allows (the
    // smoothing tolerance), from which the next move starts.
    EXPECT_LT(first.back().feed, 300);
    EXPECT_GT(first.back().feed, 0);
    EXPECT_LT(after_corner, 300);
    EXPECT_GT(after_corner, 0);
    EXPECT_EQ(k.sim->state(), RunState::ended);
}

TEST(SimPlan, FeedFallsToRestBeforeAnExactStop) {
    Slow k("%1\nG0 G9 X0 Y0 Z0\nG1 G9 X100 F600\nX200\nM2\n");
    ASSERT_EQ(k.sim->cycle_start(), "");
    double last = -1;
    for (int i = 0; i < 100000 && k.sim->state() == RunState::running; ++i) {
        k.sim->advance(0.001);
        if (k.sim->motion() == 1 && k.sim->loc().line == 3) last = k.sim->feed();
    }
    EXPECT_GE(last, 0);
    EXPECT_LT(last, 10);  // the last millisecond before G09's stop: 0.1 mm/s left at most
}

TEST(SimPlan, TheCycleTimeIsRunsTime) {
    const char* programs[] = {
        "%1\nG0 X0 Y0 Z0\nG1 X100 F600\nY100\nX0 Y0\nG4 F1\nM2\n",
        "%2\nG0 X0 Y0 Z0\nS1000 M3\nG1 X10 F300\nG2 X30 Y0 I20 J0\nG1 G9 X40\nX50 Y5\n"
        "T2 D2 M6\nG0 Z50\nM5\nM2\n",
    };
    for (const char* text : programs) {
        Slow k(text);
        ASSERT_EQ(k.sim->cycle_start(), "");
        k.settle();
        ASSERT_EQ(k.sim->state(), RunState::ended) << k.sim->message();
        const double run = k.run_seconds();
        EXPECT_NEAR(k.sim->cycle_time(), run, 1e-6) << text;
        // The feeds alone, as `run` prints beside it, are shorter.
        EXPECT_LT(k.sim->feed_time(), run) << text;
    }
}

TEST(SimPlan, TheCycleTimeIsRunsTimeOnTheLathe) {
    Slow k("%1\nG0 X50 Z5\nS800 M4\nG1 Z-20 F200\nX60\nG4 F0.5\nG0 X100 Z100\nM2\n", "lathe", 200);
    ASSERT_EQ(k.sim->cycle_start(), "");
    k.settle();
    ASSERT_EQ(k.sim->state(), RunState::ended) << k.sim->message();
    EXPECT_NEAR(k.sim->cycle_time(), k.run_seconds(), 1e-6);
}

TEST(SimPlan, ThePagesReadTheStateOfTheBlockShown) {
    // Each block its own feed: the interpreter reads ahead, the block shown
    // keeps its F.
    std::string text = "%1\nG0 X0 Y0 Z0\n";
    for (int i = 1; i <= 60; ++i)
        text += "G1 X" + std::to_string(i) + " F" + std::to_string(100 + i) + "\n";
    text += "M2\n";
    Slow k(text);
    ASSERT_EQ(k.sim->cycle_start(), "");
    bool ahead = false;
    for (int i = 0; i < 200000 && k.sim->state() == RunState::running; ++i) {
        k.sim->advance(0.01);
        if (k.sim->motion() != 1 || k.sim->state() != RunState::running) continue;
        const int line = k.sim->loc().line;  // line 3 is X1 F101
        EXPECT_DOUBLE_EQ(k.sim->modal().feed, 100 + line - 2);
        EXPECT_EQ(k.sim->blocks_done(), line - 1);
        ahead = ahead || k.sim->interp().modal().feed != k.sim->modal().feed;
    }
    EXPECT_TRUE(ahead);  // the interpreter did read ahead
    EXPECT_EQ(k.sim->state(), RunState::ended);
}

TEST(SimPlan, AnAlarmShowsAtItsBlock) {
    Slow k("%1\nG0 X0 Y0 Z0\nG1 X50 F600\nX100\nG77 H999\nM2\n");
    ASSERT_EQ(k.sim->cycle_start(), "");
    k.sim->advance(0.5);
    EXPECT_EQ(k.sim->state(), RunState::running);
    EXPECT_TRUE(k.sim->alarms().empty());  // the interpreter found it; not shown yet
    k.settle();
    ASSERT_EQ(k.sim->state(), RunState::alarm);
    ASSERT_EQ(k.sim->alarms().size(), 1u);
    EXPECT_EQ(k.sim->alarms().back().diag.code, 25);
    EXPECT_EQ(k.sim->loc().line, 5);
    EXPECT_NEAR(k.sim->op()[X], 100, 1e-9);  // after the moves before it
}

TEST(SimPlan, FeedHoldFreezesAPlannedMoveAndResumes) {
    Slow k("%1\nG0 X0 Y0 Z0\nG1 X100 F600\nM2\n");
    ASSERT_EQ(k.sim->cycle_start(), "");
    for (int i = 0; i < 100000 && !(k.sim->motion() == 1 && k.sim->op()[X] > 20); ++i)
        k.sim->advance(0.001);
    k.sim->feed_hold();
    const double x = k.sim->op()[X];
    k.sim->advance(5);
    EXPECT_EQ(k.sim->op()[X], x);
    EXPECT_EQ(k.sim->feed(), 0);
    ASSERT_EQ(k.sim->cycle_start(), "");
    k.sim->advance(0.1);
    EXPECT_NEAR(k.sim->feed(), 600, 1e-6);
    k.settle();
    EXPECT_NEAR(k.sim->cycle_time(), k.run_seconds(), 1e-6);
}

TEST(SimPlan, TheOverrideScalesThePlannedSpeeds) {
    Slow k("%1\nG0 X0 Y0 Z0\nG1 X100 F600\nM2\n");
    k.sim->feed_override = 50;
    ASSERT_EQ(k.sim->cycle_start(), "");
    for (int i = 0; i < 100000 && !(k.sim->motion() == 1 && k.sim->op()[X] > 20); ++i)
        k.sim->advance(0.001);
    EXPECT_NEAR(k.sim->feed(), 300, 1e-6);  // the plan's 600 at half speed
}

TEST(SimPlan, SeqEndsEachBlockAtRest) {
    Slow k("%1\nG0 X0 Y0 Z0\nG1 X50 F600\nX100\nM2\n");
    ASSERT_EQ(k.sim->set_mode(Mode::single), "");
    double before_stop = -1;
    for (int n = 0; n < 10 && k.sim->state() != RunState::ended; ++n) {
        ASSERT_EQ(k.sim->cycle_start(), "");
        for (int i = 0; i < 100000 && k.sim->state() == RunState::running; ++i) {
            k.sim->advance(0.001);
            if (k.sim->motion() == 1 && k.sim->loc().line == 3) before_stop = k.sim->feed();
        }
        if (k.sim->loc().line == 3) {
            EXPECT_EQ(k.sim->state(), RunState::block);
        }
    }
    EXPECT_GE(before_stop, 0);
    EXPECT_LT(before_stop, 10);  // X50 ends at rest, though X100 goes on straight
}

TEST(SimPlan, TheProgPageTimesAreThePlannedOnes) {
    Slow k("%1\nG0 G9 X0 Y0 Z0\nG1 X100 F600\nG4 F2\nM2\n");
    ASSERT_EQ(k.sim->cycle_start(), "");
    EXPECT_EQ(k.sim->block_time(1, 3), -1);  // nothing run yet
    k.settle();
    // 100 mm at 10 mm/s from rest to rest at 100 mm/s²: 10 s + 0.1 s.
    EXPECT_NEAR(k.sim->block_time(1, 3), 10.1, 1e-6);
    EXPECT_NEAR(k.sim->block_time(1, 4), 2 + k.m.in_position, 1e-6);  // the dwell after the stop
}

// Each tool's share once the program has ended: `run`'s tool lines.
TEST(SimPlan, EachToolsTimeIsRunsOnceTheProgramHasEnded) {
    Slow k("%1\nG0 X0 Y0 Z0\nT1 D1 M6\nG1 X100 F600\nG0 X0\nT2 D2 M6\nG1 Y50 F300\nY0\nM2\n");
    ASSERT_EQ(k.sim->cycle_start(), "");
    EXPECT_TRUE(k.sim->tool_times().empty());
    k.settle();
    ASSERT_EQ(k.sim->state(), RunState::ended) << k.sim->message();
    ProgramMemory m2 = k.mem.clone();
    plan::PlanSink planner(k.m);
    Interpreter in(k.m, m2, planner, RunOptions{});
    in.start(m2.programs().front()->number);
    in.run_to_end();
    planner.finish();
    const auto& want = planner.report().tools.rows();
    const auto& got = k.sim->tool_times();
    ASSERT_EQ(got.size(), 2u);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].tool, want[i].tool);
        EXPECT_DOUBLE_EQ(got[i].cut_seconds, want[i].cut_seconds);
        EXPECT_DOUBLE_EQ(got[i].rapid_seconds, want[i].rapid_seconds);
        EXPECT_DOUBLE_EQ(got[i].cut_length, want[i].cut_length);
        EXPECT_EQ(got[i].passes, want[i].passes);
    }
    EXPECT_DOUBLE_EQ(got[1].cut_length, 100);  // T2: Y50 and back
}
