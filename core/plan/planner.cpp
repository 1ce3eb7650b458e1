// The look-ahead planner (planner.hpp). Each move keeps `back`, the highest
// speed it may enter at and still stop at the end of the moves known after
// it: a new move raises the `back` of those before it (the backward pass)
// until one does not change or is at its junction's limit, so a push costs
// little where moves are long (grbl's planned pointer, LinuxCNC's "rising
// tide" over its look-ahead). The forward pass is done one move at a time,
// when the oldest is planned: its entry is fixed, and its exit is the lower of
// what the moves after it allow and what it can reach accelerating.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/plan/planner.hpp"

#include <algorithm>

namespace pupitre::plan {

void Planner::push(Segment s) {
    if (s.min_time > 0) s.vmax = std::min(s.vmax, s.length / s.min_time);
    if (count_ == kDepth) commit_oldest();
    // After a stop, the move starts from rest; else no faster than either
    // move may go.
    s.entry_max = count_ == 0 ? 0 : std::min({s.entry_max, s.vmax, at(count_ - 1).vmax});
    s.entry = 0;  // the oldest's is fixed: from rest, or set when the one before is planned
    s.back = std::min(s.entry_max, reach(0, s.length, s.limits));
    at(count_) = s;
    ++count_;
    for (size_t i = count_ - 1; i-- > 1;) {  // the oldest's entry is fixed already
        Segment& c = at(i);
        const double b = std::min(c.entry_max, reach(at(i + 1).back, c.length, c.limits));
        if (b <= c.back) break;
        c.back = b;
    }
}

void Planner::commit_oldest() {
    if (count_ == 0) return;
    Segment& s = at(0);
    const double next = count_ > 1 ? at(1).back : 0;
    s.exit = std::min(next, reach(s.entry, s.length, s.limits));
    s.timing = timing(s.length, s.entry, s.exit, s.vmax, s.limits);
    // E32000: the block lasts at least its minimum (004:1265); its speed was
    // already held to length / min_time.
    s.timing.seconds = std::max(s.timing.seconds, s.min_time);
    const double exit = s.exit;
    out_.planned(s);
    head_ = (head_ + 1) % kDepth;
    --count_;
    if (count_) at(0).entry = exit;
}

void Planner::stop() {
    while (count_) commit_oldest();
}

}  // namespace pupitre::plan
