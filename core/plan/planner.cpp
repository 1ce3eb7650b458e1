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

namespace pupitre::plan {

void Planner::stop() {
    while (count_) commit_oldest();
}

}  // namespace pupitre::plan
