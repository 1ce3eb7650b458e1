// The look-ahead planner (issue 35): a bounded ring of moves whose speeds at
// the junctions are raised as far as the moves after them allow, as grbl's
// planner.c and LinuxCNC's tp.c do. Memory is constant: the oldest move is
// planned for good when the ring is full, or when the motion stops.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "core/plan/profile.hpp"

namespace pupitre::plan {

// One move as the planner sees it: a length along a path, and the limits on
// it. Speeds in mm/s (degrees/s for a move of rotary axes alone).
struct Segment {
    double length = 0;
    double vmax = 0;          // the cruise limit: the feed, the axes, an arc's centripetal limit
    Limits limits;            // along the path
    double entry_max_sq = 0;  // the square of the junction's limit with the move before
    double min_time = 0;      // E32000: the block lasts at least this long
    // 1 / vmax and 1 / limits.accel (0: none), which the caller may give when
    // it has them without a division; else the planner finds them.
    double inv_vmax = 0, inv_accel = 0;
    // The caller's, carried through: the tool, and whether the move cuts.
    int tool = 0;
    bool cut = false;
    // What the planner made of it.
    double entry = 0, exit = 0;
    Timing timing;
    // The planner's own, in squared speeds as grbl keeps them (the passes
    // then need no square root): what accelerating over the length adds, the
    // entry fixed once the move before is planned, and `back`, the highest
    // entry from which the moves after it, as far as they are known, can
    // still stop. (The cruise limit's square is the newest move's alone, kept
    // by the planner: a segment of 128 bytes is a shift from its index.)
    double gain_sq = 0, entry_sq = 0, back_sq = 0;
};
static_assert(sizeof(Segment) == 128);

class Planner {
  public:
    // LinuxCNC looks as far ahead (issue 35: "up to 50 segments").
    static constexpr size_t kDepth = 50;

    // Hears each move once planned, in order.
    struct Receiver {
        virtual ~Receiver() = default;
        virtual void planned(const Segment&) = 0;
    };
    // `jerk`: false when no move will have one (the machine has none), so that
    // the passes never ask.
    explicit Planner(Receiver& r, bool jerk = true) : out_(r), jerk_(jerk) {}

    // A move after the ones held: add() gives its slot, which the caller
    // fills, every one of these fields: length, vmax, inv_vmax (0: the
    // planner finds it), limits, inv_accel (likewise), min_time,
    // entry_max_sq (how fast the junction with the one before may be
    // passed), tool, cut; push() plans with it. Filled in place, a move is
    // never copied, and nothing is written twice.
    Segment& add();
    void push();
    void push(const Segment& s) {  // the same from a segment made apart (tests)
        add() = s;
        push();
    }
    // The motion stops at the end of the moves held: all are planned.
    void stop();
    size_t held() const { return count_; }
    // Plans the oldest move held with what is known after it (the ring is full,
    // or something other than moves waits behind it).
    void commit_oldest() {
        if (count_) out_.planned(plan_oldest());
    }
    // The same without the receiver: the oldest move planned and let go of,
    // for a caller that takes it at once (its slot is the next add()'s).
    // There must be one held.
    const Segment& plan_oldest();

  private:
    // The square of the speed reachable over `s` from one whose square is v_sq.
    // `jerk`: a move may have one (jerk_, read once by the caller: the stores
    // to the ring could otherwise touch it, for all the compiler knows).
    static double reach_sq(double v_sq, const Segment& s, bool jerk) {
        if (!jerk || s.limits.jerk <= 0) return v_sq + s.gain_sq;
        const double r = reach(std::sqrt(v_sq), s.length, s.limits);
        return r * r;
    }
    Segment& at(size_t i) {
        const size_t j = head_ + i;
        return ring_[j < kDepth ? j : j - kDepth];
    }
    Receiver& out_;
    std::array<Segment, kDepth> ring_{};
    size_t head_ = 0, count_ = 0;
    double last_vmax_sq_ = 0;  // the newest move's vmax_sq
    const bool jerk_;          // a move may have a jerk
};

// The planner's steps for every move are inline: a move is planned within
// the sink's call that adds it (issue 35 item 7, the 15% the planner may add).
inline Segment& Planner::add() {
    if (count_ == kDepth) commit_oldest();
    Segment& s = at(count_);
    // The rest of the slot is the planner's, written before it is read: the
    // entry when the move before is planned, or here after a stop (from rest).
    if (count_ == 0) s.entry = s.entry_sq = 0;
    return s;
}

// The fields a step reads are taken into locals once: the stores to the
// ring could otherwise touch them, for all the compiler knows.
inline void Planner::push() {
    Segment& s = at(count_);
    const double length = s.length, accel = s.limits.accel, min_time = s.min_time;
    double vmax = s.vmax, inv_vmax = s.inv_vmax;
    if (inv_vmax <= 0) inv_vmax = 1 / vmax;
    if (min_time > 0 && vmax * min_time > length) {
        vmax = length / min_time;
        inv_vmax = min_time / length;
    }
    s.vmax = vmax;
    s.inv_vmax = inv_vmax;
    if (s.inv_accel <= 0 && accel > 0) s.inv_accel = 1 / accel;
    const double vmax_sq = vmax * vmax;
    s.gain_sq = accel > 0 ? 2 * accel * length : HUGE_VAL;
    // After a stop, the move starts from rest; else no faster than either
    // move may go. The oldest's entry is fixed: from rest, or when the one
    // before it is planned.
    const double entry_max_sq =
        count_ == 0 ? 0 : std::min(std::min(s.entry_max_sq, vmax_sq), last_vmax_sq_);
    s.entry_max_sq = entry_max_sq;
    last_vmax_sq_ = vmax_sq;
    const bool jerk = jerk_;
    double back = std::min(entry_max_sq, reach_sq(0, s, jerk));
    s.back_sq = back;
    Segment* c = &s;
    for (size_t i = count_++; i-- > 1;) {  // the oldest's entry is fixed already
        c = c == ring_.data() ? c + (kDepth - 1) : c - 1;
        const double b = std::min(c->entry_max_sq, reach_sq(back, *c, jerk));
        if (b <= c->back_sq) break;
        c->back_sq = back = b;
    }
}

inline const Segment& Planner::plan_oldest() {
    Segment& s = ring_[head_];
    const size_t next_head = head_ + 1 < kDepth ? head_ + 1 : 0;
    const double next = count_ > 1 ? ring_[next_head].back_sq : 0;
    const double entry = s.entry, entry_sq = s.entry_sq;
    const double exit_sq = std::min(next, reach_sq(entry_sq, s, jerk_));
    const double exit = std::sqrt(exit_sq);
    s.exit = exit;
    const double length = s.length, accel = s.limits.accel, inv_accel = s.inv_accel;
    if (accel > 0 && s.limits.jerk <= 0) {
        // The trapezoid, from the squares the passes kept, without a division.
        const double vmax = s.vmax, vmax_sq = vmax * vmax, half = 0.5 * inv_accel;
        const double up = (vmax_sq - entry_sq) * half, down = (vmax_sq - exit_sq) * half;
        if (up + down <= length) {
            s.timing = {(2 * vmax - entry - exit) * inv_accel + (length - up - down) * s.inv_vmax,
                        vmax};
        } else {  // a triangle: (vp² - v0²) / 2a + (vp² - v1²) / 2a = length
            const double vp = std::sqrt(
                std::max(accel * length + (entry_sq + exit_sq) / 2, std::max(entry_sq, exit_sq)));
            s.timing = {(2 * vp - entry - exit) * inv_accel, vp};
        }
    } else {
        s.timing = timing(length, entry, exit, s.vmax, s.limits);
    }
    // E32000: the block lasts at least its minimum (004:1265); its speed was
    // already held to length / min_time.
    s.timing.seconds = std::max(s.timing.seconds, s.min_time);
    head_ = next_head;
    if (--count_) {
        ring_[next_head].entry = exit;
        ring_[next_head].entry_sq = exit_sq;
    }
    return s;
}

}  // namespace pupitre::plan
