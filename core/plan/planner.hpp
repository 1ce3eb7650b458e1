// The look-ahead planner (issue 35): a bounded ring of moves whose speeds at
// the junctions are raised as far as the moves after them allow, as grbl's
// planner.c and LinuxCNC's tp.c do. Memory is constant: the oldest move is
// planned for good when the ring is full, or when the motion stops.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstddef>

#include "core/plan/profile.hpp"

namespace pupitre::plan {

// One move as the planner sees it: a length along a path, and the limits on
// it. Speeds in mm/s (degrees/s for a move of rotary axes alone).
struct Segment {
    double length = 0;
    double vmax = 0;       // the cruise limit: the feed, the axes, an arc's centripetal limit
    Limits limits;         // along the path
    double entry_max = 0;  // the junction's limit with the move before
    double min_time = 0;   // E32000: the block lasts at least this long
    // The caller's, carried through: the tool, and whether the move cuts.
    int tool = 0;
    bool cut = false;
    // What the planner made of it.
    double entry = 0, exit = 0;
    Timing timing;
    // The planner's own: the highest entry speed from which the moves after
    // it, as far as they are known, can still stop.
    double back = 0;
};

class Planner {
  public:
    // LinuxCNC looks as far ahead (issue 35: "up to 50 segments").
    static constexpr size_t kDepth = 50;

    // Hears each move once planned, in order.
    struct Receiver {
        virtual ~Receiver() = default;
        virtual void planned(const Segment&) = 0;
    };
    explicit Planner(Receiver& r) : out_(r) {}

    // A move after the ones held; its entry_max says how fast the junction
    // with the one before may be passed.
    void push(Segment s);
    // The motion stops at the end of the moves held: all are planned.
    void stop();
    size_t held() const { return count_; }
    // Plans the oldest move held with what is known after it (the ring is full,
    // or something other than moves waits behind it).
    void commit_oldest();

  private:
    Segment& at(size_t i) { return ring_[(head_ + i) % kDepth]; }
    Receiver& out_;
    std::array<Segment, kDepth> ring_{};
    size_t head_ = 0, count_ = 0;
};

}  // namespace pupitre::plan
