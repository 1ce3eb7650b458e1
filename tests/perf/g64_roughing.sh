#!/usr/bin/env bash
# The roughing guard of issue 35 item 7, without a timed test: callgrind
# counts the instructions `pupitre run` spends per move on one cycle of
# scripts/bench's g64_roughing (tests/perf/g64_roughing.iso: G64 on a 600 mm
# profile of 50 blocks, 1,800 passes, 7,208 moves), a two-block run
# subtracted (start-up, profile, summary), and the test fails above the
# budget kept in tests/perf/budget.txt. The cycle's safety checks (no pass,
# retract or last pass enters the part plus its allowance) once took 95% of
# it, checking every element of the profile for every cut of every pass.
#   g64_roughing.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
command -v valgrind >/dev/null || { echo "valgrind is not installed (scripts/test installs it)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() {  # count PROGRAM: callgrind's instruction total for its run
    valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
        "$bin" run --machine lathe "$1" >"$work/run.txt" 2>"$work/vg.log" ||
        { cat "$work/vg.log"; exit 1; }
    sed -n 's/^summary: //p' "$work/cg.out"
}
printf '%%1\nN10 T1 D1 M6\nN20 M2\n' >"$work/small.iso"
big=$(count "$here/g64_roughing.iso")
moves=$(sed -n 's/.* blocks, \([0-9]*\) moves,.*/\1/p' "$work/run.txt")
small=$(count "$work/small.iso")
[ -n "$moves" ] && [ "$moves" -gt 0 ] || { echo "FAIL: no moves in the run's summary"; exit 1; }
per_move=$(( (big - small) / moves ))
budget=$(sed -n 's/^g64_roughing_instructions_per_move //p' "$here/budget.txt")
echo "g64_roughing: instructions per move: $per_move (budget $budget; $moves moves; totals $big and $small)"
[ "$per_move" -le "$budget" ] || { echo "FAIL: above the budget in tests/perf/budget.txt"; exit 1; }
