// The planner as a sink (issue 35): it hears the interpreter's events as the
// trace and the workshop do, turns each move into a segment with the
// machine's limits (per axis, as LinuxCNC combines them), stops exactly where
// the program or the machine asks, and keeps the cycle time with
// accelerations, the time at the feeds alone, and each tool's share. With a
// next sink (the trace), it hands every event on in order, each move with its
// start, duration and peak speed, once planned: at most the look-ahead late.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <memory>

#include "core/interp/sink.hpp"
#include "core/plan/planner.hpp"
#include "core/plan/tools.hpp"

namespace pupitre::plan {

struct Report {
    double seconds = 0;       // the cycle time: moves planned, dwells, tool changes, waits
    double feed_seconds = 0;  // the same with each move at its feed alone, no wait
    double waits = 0;         // exact stops settling and the spindle reaching its speed
    ToolTable tools;
};

class PlanSink final : public MachineSink, private Planner::Receiver {
  public:
    explicit PlanSink(const MachineProfile& m, MachineSink* next = nullptr);
    ~PlanSink() override;
    PlanSink(const PlanSink&) = delete;
    PlanSink& operator=(const PlanSink&) = delete;

    void move(const MoveEvent&) override;
    void dwell(const Loc&, double seconds) override;
    void tool(const Loc&, int t, int d, double seconds, bool m6) override;
    void spindle(const SpindleEvent&) override;
    void coolant(const Loc&, bool m7, bool m8) override;
    void stop(const Loc&, int m) override;
    void message(const Loc&, int channel, std::string_view) override;
    void end(const Loc&, int m) override;
    void stock(const Loc&, const std::vector<std::array<double, 2>>&) override;
    void profile(const Loc&, const ProfileElem&) override;
    void exact_stop(const Loc&) override;

    // The run is over (its end, an error, a crash): what is held is planned
    // and handed on.
    void finish();
    // The seconds planned so far (the cycle time once finished).
    const double& clock() const { return report_.seconds; }
    const Report& report() const { return report_; }

    // A move's limits, as the planner takes them (tests).
    Segment segment(const MoveEvent& e, std::array<double, kAxes>& in,
                    std::array<double, kAxes>& out) const;

  private:
    struct Queue;
    void planned(const Segment&) override;
    // The motion stops at rest; `settle`: an exact stop the program or the
    // machine asks for, which waits the profile's in-position time.
    void halt(bool settle);
    void wait(double seconds);
    double junction(const std::array<double, kAxes>& in, double eg) const;
    // An event that is no move: counted against the look-ahead's limit; true
    // when there is a next sink to hand it to.
    bool other();
    template <class Ev>
    void pass(Ev&& ev);  // to the next sink: now, or after the moves held

    const MachineProfile& m_;
    MachineSink* next_;
    Planner planner_;
    std::unique_ptr<Queue> queue_;
    Report report_;
    // Per axis, in mm/s (degrees/s): rapid, feed, acceleration, jerk.
    std::array<double, kAxes> rapid_{}, feed_{}, accel_{}, jerk_{};
    std::array<double, kAxes> last_dir_{};  // the last move's direction at its end
    bool have_last_ = false;                // a move held or just planned
    bool moved_ = false;                    // a move since the last stop
    long others_ = 0;                       // events but moves since the last move
    int tool_ = 0;
    int sp_dir_ = 5;
    double sp_rpm_ = 0;
};

}  // namespace pupitre::plan
