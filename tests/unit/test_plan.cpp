// The planner against closed forms (issue 35, Tests): a move from rest, one
// too short to reach its feed, a square in exact stop and smoothed, a full
// circle at its centripetal limit, rapids at each axis' own limit, EG, E32000,
// G09 inside a smoothed chain; and the events handed on in order.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/interp/interp.hpp"
#include "core/plan/plan_sink.hpp"
#include "core/plan/planner.hpp"
#include "core/plan/profile.hpp"

namespace pupitre {
namespace {

// The machine of the LinuxCNC comparisons (issue 35): X Y Z at 166.7 mm/s
// (10002 mm/min) and 500 mm/s2, no settling, no minimum block time, and no
// interpolation period: the textbook's closed forms (the ticks are tested
// apart, InterpolationTicks).
std::string machine_text(const std::string& more = {}) {
    return "name = t\nkind = mill\naxes = X Y Z\nfeed.max = 10002\n"
           "rapid.X = 10002\nrapid.Y = 10002\nrapid.Z = 10002\n"
           "accel.X = 500\naccel.Y = 500\naccel.Z = 500\nsmoothing = 0.01\n"
           "interpolation_period = 0\n" +
           more;
}

struct Planned {
    MachineProfile m;
    ProgramMemory mem;
    std::unique_ptr<plan::PlanSink> sink;
    std::unique_ptr<Interpreter> in;
    Planned(const std::string& program, const std::string& more = {}, MachineSink* next = nullptr) {
        EXPECT_EQ(parse_machine(machine_text(more), m), "");
        mem.load_text("t.iso", "%1\n" + program + "M02\n");
        sink = std::make_unique<plan::PlanSink>(m, next);
        in = std::make_unique<Interpreter>(m, mem, *sink);
        in->start(mem.first());
        in->run_to_end();
        sink->finish();
        for (const Diag& d : in->diags()) ADD_FAILURE() << d.detail;
    }
    double seconds() const { return sink->report().seconds; }
    double feed_seconds() const { return sink->report().feed_seconds; }
};

std::string mm(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return b;
}

// From v0 to v1 over d, cruising at v at most, accelerating at a.
double trapezoid(double d, double v0, double v1, double v, double a) {
    const double up = (v * v - v0 * v0) / (2 * a), down = (v * v - v1 * v1) / (2 * a);
    if (up + down <= d) return (v - v0) / a + (v - v1) / a + (d - up - down) / v;
    const double vp = std::sqrt((2 * a * d + v0 * v0 + v1 * v1) / 2);
    return (vp - v0) / a + (vp - v1) / a;
}

TEST(Plan, OneMoveFromRestIsDOverVPlusVOverA) {
    Planned r("G1 X100 F6000\n");
    EXPECT_NEAR(r.seconds(), 100.0 / 100 + 100.0 / 500, 1e-9);  // 1.2 s, as LinuxCNC's G61.1
    EXPECT_NEAR(r.feed_seconds(), 1.0, 1e-9);
}

TEST(Plan, AMoveTooShortForItsFeedIsATriangle) {
    Planned r("G1 X1 F6000\n");
    EXPECT_NEAR(r.seconds(), 2 * std::sqrt(1.0 / 500), 1e-9);
}

TEST(Plan, ASquareInExactStopIsFourTrapezoids) {
    Planned r("G1 G9 X50 F6000\nG9 Y50\nG9 X0\nG9 Y0\n");
    EXPECT_NEAR(r.seconds(), 4 * (0.5 + 0.2), 1e-9);  // 2.8 s, as LinuxCNC's G61.1
}

TEST(Plan, ASmoothedSquareIsShorterByItsCorners) {
    Planned r("G1 X50 F6000\nY50\nX0\nY0\n");
    // Each corner turns 90°: on the arc 0.01 mm from the corner, at the
    // acceleration along the change of direction (X and Y at 500 each: 500√2).
    const double s = std::sqrt(0.5), vj = std::sqrt(500 * std::sqrt(2.0) * 0.01 * s / (1 - s));
    const double expect = trapezoid(50, 0, vj, 100, 500) + 2 * trapezoid(50, vj, vj, 100, 500) +
                          trapezoid(50, vj, 0, 100, 500);
    EXPECT_NEAR(r.seconds(), expect, 1e-9);
    EXPECT_LT(r.seconds(), 2.8);
}

TEST(Plan, ASmoothingOfZeroStopsAtEachCorner) {
    Planned r("G1 X50 F6000\nY50\nX0\nY0\n", "smoothing = 0\n");
    EXPECT_NEAR(r.seconds(), 2.8, 1e-9);
}

TEST(Plan, AFullCircleRunsAtItsCentripetalLimit) {
    // R1 at F6000: the centre pulls at most √3/2 of 500 mm/s2, so the speed is
    // sqrt(433 × 1) ≈ 20.8 mm/s; along the path half of 500 (LinuxCNC's split).
    Planned r("G1 G9 X-1 F6000\nG2 X-1 Y0 I0 J0\n");
    const double first = 2 * std::sqrt(1.0 / 500);  // the line to the circle, from rest to rest
    const double v = std::sqrt(std::sqrt(3.0) / 2 * 500 * 1), at = 250;
    const double circle = 2 * std::numbers::pi / v + v / at;
    EXPECT_NEAR(r.seconds(), first + circle, 1e-9);
}

TEST(Plan, AFullCircleBelowItsLimitGetsHalfTheAcceleration) {
    // LinuxCNC's case: R10 at F3000 in exact stop, 1.457 s (scripts/lcnc-compare,
    // exact/circle_r10).
    Planned r("G1 G9 X-10 F3000\nG2 X-10 Y0 I0 J0\n");
    const double line = trapezoid(10, 0, 0, 50, 500);
    EXPECT_NEAR(r.seconds() - line, 2 * std::numbers::pi * 10 / 50 + 50.0 / 250, 1e-9);
}

TEST(Plan, ARapidRunsAtEachAxisOwnLimit) {
    const std::string slow_y = "rapid.Y = 5001\n";
    Planned x("G0 X100\n", slow_y), y("G0 Y100\n", slow_y);
    EXPECT_NEAR(x.seconds(), trapezoid(100, 0, 0, 166.7, 500), 1e-9);
    EXPECT_NEAR(y.seconds(), trapezoid(100, 0, 0, 83.35, 500), 1e-9);
    // A diagonal of two equal axes gets √2 times each, in speed and in
    // acceleration: 0.933 s, as LinuxCNC (scripts/lcnc-compare,
    // exact/rapid_xy).
    Planned xy("G0 X100 Y100\n");
    const double r2 = std::sqrt(2.0);
    EXPECT_NEAR(xy.seconds(), trapezoid(100 * r2, 0, 0, 166.7 * r2, 500 * r2), 1e-9);
    EXPECT_NEAR(xy.seconds(), 0.9333, 1e-3);
}

TEST(Plan, EG50HalvesTheAcceleration) {
    Planned full("G1 X100 F6000\n"), half("EG50 G1 X100 F6000\n");
    EXPECT_NEAR(half.seconds(), 1 + 100.0 / 250, 1e-9);
    EXPECT_GT(half.seconds(), full.seconds());
}

TEST(Plan, E32000IsTheFloorOfEachBlock) {
    std::string p = "E32000=10\nG1 F600\n";  // 10 ms a block
    for (int i = 1; i <= 1000; ++i) p += "X" + mm(i * 0.01) + "\n";
    Planned r(p);
    EXPECT_NEAR(r.feed_seconds(), 1.0, 1e-6);  // 10 mm at 10 mm/s
    // Each 0.01 mm block takes 10 ms: 1 mm/s, which the first block reaches
    // in 2 ms and the last leaves in as much (1/500 s at 500 mm/s2: 1 µm).
    EXPECT_NEAR(r.seconds(), 10.0 + 0.001 + 0.001, 1e-6);
}

TEST(Plan, G09StopsAtTheEndOfItsOwnBlockOnly) {
    Planned chain("G1 X10 F6000\nX20\nX30\n"), stop("G1 X10 F6000\nG9 X20\nX30\n");
    EXPECT_NEAR(chain.seconds(), trapezoid(30, 0, 0, 100, 500), 1e-9);
    EXPECT_NEAR(stop.seconds(), trapezoid(20, 0, 0, 100, 500) + trapezoid(10, 0, 0, 100, 500),
                1e-9);
}

// The trajectory generator computes a setpoint every period (004:338): a
// motion comes to rest on one of its ticks, as LinuxCNC's does on its servo
// period of 1 ms (scripts/lcnc-compare: its exact stops last whole milliseconds).
TEST(Plan, InterpolationTicksEndEachMotionAtRestOnATick) {
    const std::string ms = "interpolation_period = 0.001\n";
    // 2 sqrt(1/500) = 89.44 ms, to the next millisecond.
    Planned one("G1 X1 F6000\n", ms);
    EXPECT_NEAR(one.seconds(), 0.090, 1e-9);
    // 30 diagonals of 0.707 mm in exact stop, 63.25 ms each at √2 × 500
    // mm/s2: 64 ms each, LinuxCNC's 1.920 s where the textbook gives 1.897.
    std::string diag = "G1 F6000\n";
    for (int i = 1; i <= 30; ++i) diag += "G9 X" + mm(i * 0.5) + " Y" + mm(i * 0.5) + "\n";
    Planned d(diag, ms), textbook(diag);
    EXPECT_NEAR(textbook.seconds(), 30 * 2 * std::sqrt(std::sqrt(0.5) / (500 * std::sqrt(2.0))),
                1e-9);
    EXPECT_NEAR(d.seconds(), 1.920, 1e-9);
    // Chained, the motion stops once: only its end goes to a tick.
    Planned chain("G1 X1 F6000\nX2\n", ms);
    EXPECT_NEAR(chain.seconds(), std::ceil(2 * std::sqrt(2.0 / 500) * 1000) / 1000, 1e-9);
    // A time already on a tick stays: 1.2 s, not 1.201.
    Planned exact("G1 X100 F6000\n", ms);
    EXPECT_NEAR(exact.seconds(), 1.2, 1e-9);
}

TEST(Plan, ATickLengthensTheMoveThatEndsOnIt) {
    struct Times final : MachineSink {
        std::vector<std::array<double, 2>> moves;  // start, seconds
        void move(const MoveEvent& e) override { moves.push_back({e.plan_start, e.plan_seconds}); }
    } t;
    Planned r("G1 G9 X1 F6000\nX2\nX3\n", "interpolation_period = 0.01\n", &t);
    ASSERT_EQ(t.moves.size(), 3u);
    EXPECT_NEAR(t.moves[0][1], 0.09, 1e-9);  // 89.44 ms at rest: to 90 ms
    EXPECT_NEAR(t.moves[1][0], 0.09, 1e-9);  // the next starts on the tick
    // The chain of two: only its second move, which ends at rest, is lengthened.
    const double two = 2 * std::sqrt(2.0 / 500);
    EXPECT_NEAR(t.moves[1][1] + t.moves[2][1], std::ceil((0.09 + two) * 100) / 100 - 0.09, 1e-9);
    EXPECT_NEAR(t.moves[1][1], std::sqrt(2.0 / 500), 1e-9);  // half the triangle, untouched
    EXPECT_NEAR(r.seconds(), t.moves[2][0] + t.moves[2][1], 1e-12);
}

TEST(Plan, ExactStopsSettle) {
    Planned r("G1 X10 F6000\nG9 X20\nX30\nG4 F1\nX40\n", "in_position = 0.05\n");
    const double moves = trapezoid(20, 0, 0, 100, 500) + trapezoid(10, 0, 0, 100, 500) +
                         trapezoid(10, 0, 0, 100, 500);
    EXPECT_NEAR(r.seconds(), moves + 1 + 2 * 0.05, 1e-9);  // G09 and G04; not the end
}

TEST(Plan, TheSpindleIsWaitedFor) {
    Planned r("S3000 M3\nG1 X10 F6000\nM5\n", "spindle.accel = 1500\n");
    EXPECT_NEAR(r.seconds(), 2 + trapezoid(10, 0, 0, 100, 500) + 2, 1e-9);
}

TEST(Plan, AJerkRoundsTheRamps) {
    Planned r("G1 X100 F6000\n", "jerk.X = 5000\n");
    // Each ramp to 100 mm/s: 100/500 + 500/5000 = 0.3 s over 15 mm; 70 mm at 100.
    EXPECT_NEAR(r.seconds(), 2 * 0.3 + 0.7, 1e-6);
}

TEST(Plan, TheLookAheadIsBounded) {
    // 1000 collinear steps of 0.1 mm: the planner holds 50 of them, so it
    // never leaves one faster than it can stop within the 49 after it.
    std::string p = "G1 F6000\n";
    for (int i = 1; i <= 1000; ++i) p += "X" + mm(i / 10.0) + "\n";
    Planned r(p);
    const double v = std::sqrt(2 * 500 * 0.1 * double(plan::Planner::kDepth - 1));
    EXPECT_GT(r.seconds(), trapezoid(100, 0, 0, 100, 500));
    EXPECT_NEAR(r.seconds(), trapezoid(100, 0, 0, v, 500), 0.01);
}

TEST(Plan, NoAccelerationIsTheTimeAtTheFeeds) {
    MachineProfile m;
    ASSERT_EQ(parse_machine("name = n\naxes = X Y Z\n", m), "");
    ProgramMemory mem;
    mem.load_text("t.iso", "%1\nG1 X10 F600\nY10\nG0 X0 Y0\nM02\n");
    plan::PlanSink sink(m);
    Interpreter in(m, mem, sink);
    in.start(mem.first());
    in.run_to_end();
    sink.finish();
    EXPECT_NEAR(sink.report().seconds, in.seconds(), 1e-9);
    EXPECT_NEAR(sink.report().feed_seconds, in.seconds(), 1e-9);
}

// The next sink hears every event, in order, each move once planned.
struct Order final : MachineSink {
    std::string seen;
    std::vector<MoveEvent> moves;
    void move(const MoveEvent& e) override {
        seen += 'm';
        moves.push_back(e);
    }
    void coolant(const Loc&, bool, bool) override { seen += 'c'; }
    void message(const Loc&, int, std::string_view) override { seen += 'M'; }
    void dwell(const Loc&, double) override { seen += 'd'; }
    void end(const Loc&, int) override { seen += 'e'; }
};

TEST(Plan, EventsGoOnInOrderWithTheirTimes) {
    Order o;
    Planned r("G1 X10 F6000\nM8\nX20\n$0 A\nX30\nG4 F0.5\nX30\nX40\n", {}, &o);
    EXPECT_EQ(o.seen, "mcmMmdmmce");  // M02 turns the coolant off
    ASSERT_EQ(o.moves.size(), 5u);
    double t = 0;
    for (const MoveEvent& e : o.moves) {
        EXPECT_NEAR(e.plan_start, t + (&e == &o.moves[3] ? 0.5 : 0), 1e-9);
        t = e.plan_start + e.plan_seconds;
        EXPECT_LE(e.plan_peak, 6000 + 1e-9);
    }
    EXPECT_EQ(o.moves[3].plan_seconds, 0);  // X30 again: no length
    EXPECT_NEAR(t, r.seconds(), 1e-9);
    EXPECT_NEAR(o.moves[0].plan_peak, 6000, 1e-9);
}

// The moves' starts and durations, the dwells and tool changes, and the
// waits the planner tells the next sink make the whole cycle time.
struct Timeline final : MachineSink {
    double end = 0, busy = 0;
    bool in_order = true;
    void move(const MoveEvent& e) override {
        in_order = in_order && e.plan_start >= end - 1e-9;
        end = std::max(end, e.plan_start + e.plan_seconds);
        busy += e.plan_seconds;
    }
    void dwell(const Loc&, double s) override { busy += s; }
    void tool(const Loc&, int, int, double s, bool m6) override { busy += m6 ? s : 0; }
    void wait(const Loc&, double s) override { busy += s; }
};

TEST(Plan, TheWaitsCompleteTheTimeline) {
    Timeline t;
    Planned r("G1 X10 F6000\nS2000 M3\nG9 X20\nT1 M6\nG4 F1\nX30\nM5\n",
              "in_position = 0.05\nspindle.accel = 1000\n", &t);
    EXPECT_TRUE(t.in_order);
    EXPECT_NEAR(t.busy, r.seconds(), 1e-9);
    EXPECT_GT(r.sink->report().waits, 4.0);  // 2 s to reach S2000 and 2 s to stop, settling
}

TEST(Profile, RampsAndTimings) {
    plan::Limits l{500, 0};
    EXPECT_NEAR(plan::ramp_time(100, l), 0.2, 1e-12);
    EXPECT_NEAR(plan::ramp_length(0, 100, l), 10, 1e-12);
    EXPECT_NEAR(plan::reach(0, 10, l), 100, 1e-12);
    plan::Timing t = plan::timing(100, 0, 0, 100, l);
    EXPECT_NEAR(t.seconds, 1.2, 1e-12);
    EXPECT_NEAR(t.peak, 100, 1e-12);
    plan::Limits j{500, 5000};
    EXPECT_NEAR(plan::ramp_time(100, j), 0.3, 1e-12);
    EXPECT_NEAR(plan::ramp_time(20, j), 2 * std::sqrt(20.0 / 5000), 1e-12);
    EXPECT_NEAR(plan::ramp_length(0, plan::reach(0, 15, j), j), 15, 1e-6);
}

}  // namespace
}  // namespace pupitre
