#!/usr/bin/env bash
# The throughput guard of issue 14, without a timed test: callgrind counts the
# instructions `pupitre run` spends per block on a fixed generated program
# (20,000 blocks minus a 100-block run, so start-up does not count) and the
# test fails above the budget kept in tests/perf/budget.txt. Instruction
# counts are repeatable whatever else the machine is doing.
#   instructions.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
command -v valgrind >/dev/null || { echo "valgrind is not installed (scripts/test installs it)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() {  # count BLOCKS: callgrind's instruction total for a run of that size
    python3 "$root/scripts/gen-program" --blocks "$1" --seed 7 --num "$work/p$1.iso" --ngc "$work/p$1.ngc"
    valgrind --tool=callgrind --callgrind-out-file="$work/cg$1.out" \
        "$bin" run --machine mill "$work/p$1.iso" >/dev/null 2>"$work/vg$1.log" ||
        { cat "$work/vg$1.log"; exit 1; }
    sed -n 's/^summary: //p' "$work/cg$1.out"
}
big=$(count 20000)
small=$(count 100)
per_block=$(( (big - small) / 19900 ))
budget=$(sed -n 's/^instructions_per_block //p' "$here/budget.txt")
echo "instructions per block: $per_block (budget $budget; totals $big and $small)"
[ "$per_block" -le "$budget" ] || { echo "FAIL: above the budget in tests/perf/budget.txt"; exit 1; }
