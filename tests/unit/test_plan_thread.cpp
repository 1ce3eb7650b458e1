// The planner on a thread of its own (core/plan/plan_thread.hpp, issue 35
// item 7): the same plan, to the bit, as the planner on the interpreter's
// thread, over several batches and with every kind of event among the moves.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/interp/interp.hpp"
#include "core/plan/plan_sink.hpp"
#include "core/plan/plan_thread.hpp"

namespace pupitre {
namespace {

const char* const kMachine =
    "name = t\nkind = mill\naxes = X Y Z\nfeed.max = 10002\n"
    "rapid.X = 10002\nrapid.Y = 10002\nrapid.Z = 10002\n"
    "accel.X = 500\naccel.Y = 500\naccel.Z = 800\nsmoothing = 0.01\n"
    "in_position = 0.02\nspindle.accel = 2000\ntool_change_time = 3\n";

// Some thousands of moves, lines and arcs, with tool changes, dwells, the
// spindle, coolant, messages and exact stops among them, and a pass of
// moves too short to reach their feed.
std::string program() {
    std::string p = "%1\nG0 X0 Y0 Z5\nT1 D1 M6\nS1000 M3 M8\n";
    char b[128];
    for (int i = 0; i < 2000; ++i) {
        const double x = std::fmod(i * 7.3, 90.0), y = std::fmod(i * 3.1, 60.0);
        if (i % 5 == 3)
            std::snprintf(b, sizeof b, "G3 X%.3f Y%.3f R%.3f F%d\n", x, y, 60.0, 800 + i % 7 * 300);
        else
            std::snprintf(b, sizeof b, "G1 X%.3f Y%.3f Z%.3f F%d\n", x, y, -(i % 3) * 0.5,
                          600 + i % 11 * 250);
        p += b;
        if (i % 397 == 0) p += "G4 F0.5\n";
        if (i % 613 == 1) p += "T2 D2 M6\nS1500 M4\n";
        if (i % 251 == 2) p += "G09 G1 X0 Y0\n";
        if (i % 701 == 5) p += "(un message)\nM9\n";
    }
    return p + "G0 Z50\nM5\nM02\n";
}

// The machine of the tests, with jerks or without.
class PlanThreadOn : public testing::TestWithParam<const char*> {};

TEST_P(PlanThreadOn, PlansExactlyAsThePlannerOnTheInterpretersThread) {
    MachineProfile m;
    ASSERT_EQ(parse_machine(std::string(kMachine) + GetParam(), m), "");
    ProgramMemory mem;
    mem.load_text("t.iso", program());

    plan::PlanSink here(m);
    Interpreter a(m, mem, here);
    a.start(mem.first());
    a.run_to_end();
    here.finish();
    for (const Diag& d : a.diags()) ADD_FAILURE() << d.detail;

    plan::PlanThread apart(m);
    Interpreter b(m, mem, apart);
    b.start(mem.first());
    b.run_to_end();
    apart.finish();

    const plan::Report &x = here.report(), &y = apart.report();
    EXPECT_GT(x.seconds, x.feed_seconds);  // the accelerations count
    EXPECT_GT(x.waits, 0);                 // exact stops and the spindle
    EXPECT_EQ(x.seconds, y.seconds);
    EXPECT_EQ(x.feed_seconds, y.feed_seconds);
    EXPECT_EQ(x.waits, y.waits);
    ASSERT_EQ(x.tools.rows().size(), 2u);
    ASSERT_EQ(y.tools.rows().size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        const plan::ToolRow &r = x.tools.rows()[i], &s = y.tools.rows()[i];
        EXPECT_EQ(r.tool, s.tool);
        EXPECT_EQ(r.cut_seconds, s.cut_seconds);
        EXPECT_EQ(r.rapid_seconds, s.rapid_seconds);
        EXPECT_EQ(r.cut_length, s.cut_length);
        EXPECT_EQ(r.passes, s.passes);
    }
}

INSTANTIATE_TEST_SUITE_P(Machines, PlanThreadOn,
                         testing::Values("", "jerk.X = 5000\njerk.Y = 5000\njerk.Z = 8000\n"));

// More events that are not moves than a batch holds, between two moves: the
// batch is handed over on them too, and the plan is the same.
TEST(PlanThread, ABatchOfOtherEventsIsHandedOverLikeOneOfMoves) {
    MachineProfile m;
    ASSERT_EQ(parse_machine(kMachine, m), "");
    std::string p = "%1\nG0 X0 Y0 Z5\nG1 X10 F1000\n";
    for (int i = 0; i < 5000; ++i) p += "M8\nM9\n";
    p += "G1 X20\nY10\nM02\n";
    ProgramMemory mem;
    mem.load_text("t.iso", p);
    plan::PlanSink here(m);
    Interpreter a(m, mem, here);
    a.start(mem.first());
    a.run_to_end();
    here.finish();
    plan::PlanThread apart(m);
    Interpreter b(m, mem, apart);
    b.start(mem.first());
    b.run_to_end();
    apart.finish();
    EXPECT_GT(here.report().seconds, 0);
    EXPECT_EQ(here.report().seconds, apart.report().seconds);
    EXPECT_EQ(here.report().feed_seconds, apart.report().feed_seconds);
}

TEST(PlanThread, NothingHandedOverIsNoTime) {
    MachineProfile m;
    ASSERT_EQ(parse_machine(kMachine, m), "");
    plan::PlanThread apart(m);
    apart.finish();
    apart.finish();  // a second finish changes nothing
    EXPECT_EQ(apart.report().seconds, 0);
}

TEST(PlanThread, LeftUnfinishedItStopsWithoutWaitingForMore) {
    MachineProfile m;
    ASSERT_EQ(parse_machine(kMachine, m), "");
    ProgramMemory mem;
    mem.load_text("t.iso", program());
    auto apart = std::make_unique<plan::PlanThread>(m);
    Interpreter in(m, mem, *apart);
    in.start(mem.first());
    for (int i = 0; i < 1500; ++i) in.step();  // a run given up half-way (an exception)
    apart.reset();                             // joins: no hang, no crash
    SUCCEED();
}

}  // namespace
}  // namespace pupitre
