#!/usr/bin/env bash
# The throughput guard of issue 14, without a timed test: callgrind counts the
# instructions `pupitre run` spends per block on a fixed generated program
# (20,000 blocks minus a 100-block run, so start-up does not count) and the
# test fails above the budget kept in tests/perf/budget.txt. The same run with
# --no-plan gives the planner's share (issue 35 item 7), which has a budget of
# its own there. Instruction counts are repeatable whatever else the machine
# is doing.
#   instructions.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
command -v valgrind >/dev/null || { echo "valgrind is not installed (scripts/test installs it)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() {  # count BLOCKS [OPTION...]: callgrind's instruction total for a run of that size
    local n=$1
    shift
    [ -s "$work/p$n.iso" ] ||
        python3 "$root/scripts/gen-program" --blocks "$n" --seed 7 --num "$work/p$n.iso" --ngc "$work/p$n.ngc"
    valgrind --tool=callgrind --callgrind-out-file="$work/cg$n.out" \
        "$bin" run --machine mill "$@" "$work/p$n.iso" >/dev/null 2>"$work/vg$n.log" ||
        { cat "$work/vg$n.log" >&2; exit 1; }
    sed -n 's/^summary: //p' "$work/cg$n.out"
}
per_block() {  # per_block [OPTION...]: the instructions of a block, start-up left out
    local big small
    big=$(count 20000 "$@")
    small=$(count 100 "$@")
    echo $(((big - small) / 19900))
}
budget() { sed -n "s/^$1 //p" "$here/budget.txt"; }
with=$(per_block)
without=$(per_block --no-plan)
planner=$((with - without))
share=$((100 * planner / without))
echo "instructions per block: $with (budget $(budget instructions_per_block))"
echo "the planner's: $planner, $share% of the $without of a run with --no-plan (at most $(budget planner_percent)%)"
[ "$with" -le "$(budget instructions_per_block)" ] || { echo "FAIL: above the budget in tests/perf/budget.txt"; exit 1; }
[ "$share" -le "$(budget planner_percent)" ] ||
    { echo "FAIL: the planner's share is above planner_percent in tests/perf/budget.txt"; exit 1; }
