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

// The part of a move the planner reads, under the MoveEvent's names: what a
// planner on a thread of its own is handed (plan_thread.hpp), half a
// MoveEvent's size.
struct PlanMove {
    int g = 1, plane_a0 = X, plane_a1 = Y;
    double length = 0, seconds = 0, eg = 100, min_block = 0;
    double mc0 = 0, mc1 = 0, msweep = 0;
    Axes from_mach{}, to_mach{};
    PlanMove() = default;
    explicit PlanMove(const MoveEvent& e)
        : g(e.g),
          plane_a0(e.plane_a0),
          plane_a1(e.plane_a1),
          length(e.length),
          seconds(e.seconds),
          eg(e.eg),
          min_block(e.min_block),
          mc0(e.mc0),
          mc1(e.mc1),
          msweep(e.msweep),
          from_mach(e.from_mach),
          to_mach(e.to_mach) {}
};

class PlanSink final : public MachineSink, private Planner::Receiver {
  public:
    explicit PlanSink(const MachineProfile& m, MachineSink* next = nullptr);
    ~PlanSink() override;
    PlanSink(const PlanSink&) = delete;
    PlanSink& operator=(const PlanSink&) = delete;

    void move(const MoveEvent&) override;
    // The same moves without their events, in order: for a planner with no
    // next sink (plan_thread.hpp), a batch's run of them in one call.
    void moves(const PlanMove* first, const PlanMove* last);
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

  private:
    struct Queue;
    void planned(const Segment&) override;
    // To the next sink, and what waited on it; `seconds`: the move's time
    // to the tick it ends on.
    void hand_on(const Segment&, double start, double seconds);
    // The motion stops at rest; `settle`: an exact stop the program or the
    // machine asks for, which waits the profile's in-position time.
    void halt(bool settle, const Loc& l);
    // The axes wait at rest (not the MachineSink's wait event, which it
    // sends on: named apart so as not to take that event's place).
    void rest(const Loc& l, double seconds);
    using Dir = std::array<double, kAxes>;
    // How much the axes bind a path: each its travel over its own limit, the
    // largest (0: none binds).
    struct Along {
        double v = 0, a = 0, j = 0;
    };
    Along along(const Dir& per, const Dir& inv_speed) const;
    // The corner from the last move's direction into the next one's: the
    // cosine of its angle, and the change of direction over the acceleration
    // on the axis that limits it.
    struct Corner {
        double cos = 0, turn = 0;
    };
    Corner corner(const Dir& last, const Dir& in) const;
    struct Binds;  // the two, axis by axis, as a line or an arc goes over its axes
    double junction_sq(const Corner& c, double eg) const;
    // An arc's centripetal limit, when the arc is round: its radius and the
    // share of its path in the plane.
    struct Bend {
        bool round = false;
        double radius = 0, plane = 0;
    };
    // A move's direction (at an arc's start and end), how the axes bind it
    // and its corner with the last move, in one pass over the axes.
    // Mv: a MoveEvent or a PlanMove.
    template <class Mv>
    void line(const Mv& e, double inv_len, Along& lim, Dir& dir, Corner& k) const;
    template <class Mv>
    Bend arc(const Mv& e, Along& lim, Dir& in, Dir& out, Corner& k) const;
    template <class Mv>
    void plan(const Mv& e);  // a move of some length: its segment, pushed
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
    // The profile's axes, and per axis the inverses of its rapid and feed
    // (mm/s or degrees/s), its acceleration and jerk (0: no limit).
    std::array<size_t, kAxes> axes_{};
    size_t naxes_ = 0;
    bool jerk_ = false;  // an axis has a jerk
    double smoothing_;   // the profile's, read at every corner
    double period_;      // the interpolation period (0: none)
    std::array<double, kAxes> inv_rapid_{}, inv_feed_{}, inv_accel_{}, inv_jerk_{};
    // The directions at the end of the last move (dir_[last_]) and of the
    // one being added; an arc's at its start.
    std::array<Dir, 2> dir_{};
    int last_ = 0;
    Dir entry_{};
    bool have_last_ = false;  // a move held or just planned
    bool moved_ = false;      // a move since the last stop
    long others_ = 0;         // events but moves since the last move
    int tool_ = 0;
    int sp_dir_ = 5;
    double sp_rpm_ = 0;
};

}  // namespace pupitre::plan
