#!/usr/bin/env bash
# The throughput guard of issue 14, without a timed test: callgrind counts the
# instructions `pupitre run` spends per block on a fixed generated program
# (20,000 blocks minus a 100-block run, so start-up does not count) and the
# test fails above the budget kept in tests/perf/budget.txt. The same run with
# --no-plan gives the planner's share (issue 35 item 7), which has a budget of
# its own there, all threads counted, and the share of it left on the
# interpreter's thread (the planner runs on its own), which has another.
# Instruction counts are repeatable whatever else the machine is doing.
#   instructions.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
command -v valgrind >/dev/null || { echo "valgrind is not installed (scripts/test installs it)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# count BLOCKS [OPTION...]: callgrind's instruction total for a run of that
# size, every thread counted, then the first thread's (the interpreter's).
count() {
    local n=$1
    shift
    [ -s "$work/p$n.iso" ] ||
        python3 "$root/scripts/gen-program" --blocks "$n" --seed 7 --num "$work/p$n.iso" --ngc "$work/p$n.ngc"
    rm -f "$work/cg$n.out"*
    valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$work/cg$n.out" \
        "$bin" run --machine mill "$@" "$work/p$n.iso" >/dev/null 2>"$work/vg$n.log" ||
        { cat "$work/vg$n.log" >&2; exit 1; }
    echo "$(cat "$work/cg$n.out"* | sed -n 's/^summary: //p' | awk '{ t += $1 } END { print t }')" \
        "$(sed -n 's/^summary: //p' "$work/cg$n.out-01")"
}
# per_block [OPTION...]: the instructions of a block, start-up left out: all
# threads', then the interpreter's thread's.
per_block() {
    local big small
    read -r big big1 < <(count 20000 "$@")
    read -r small small1 < <(count 100 "$@")
    echo $(((big - small) / 19900)) $(((big1 - small1) / 19900))
}
budget() { sed -n "s/^$1 //p" "$here/budget.txt"; }
read -r with with_interp < <(per_block)
read -r without _ < <(per_block --no-plan)
planner=$((with - without))
share=$((100 * planner / without))
# The planner runs on a thread of its own: what the interpreter's thread does
# more for it (the moves handed over) is what a run waits for.
waits=$((with_interp - without))
wait_share=$((100 * waits / without))
echo "instructions per block: $with (budget $(budget instructions_per_block))"
echo "the planner's: $planner, $share% of the $without of a run with --no-plan (at most $(budget planner_percent)%)"
echo "the interpreter's thread's share of it: $waits, $wait_share% (at most $(budget planner_wait_percent)%)"
[ "$with" -le "$(budget instructions_per_block)" ] || { echo "FAIL: above the budget in tests/perf/budget.txt"; exit 1; }
[ "$share" -le "$(budget planner_percent)" ] ||
    { echo "FAIL: the planner's share is above planner_percent in tests/perf/budget.txt"; exit 1; }
[ "$wait_share" -le "$(budget planner_wait_percent)" ] ||
    { echo "FAIL: the interpreter's thread's share is above planner_wait_percent in tests/perf/budget.txt"; exit 1; }
