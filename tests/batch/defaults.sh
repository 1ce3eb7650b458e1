#!/usr/bin/env bash
# Batch defaults (issue 12.10): run, check and plot without --machine run on
# the lathe, as the console's first start does, and say so; plot writes no
# file when the run fails before its first move, and says why.
#   defaults.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# The lathe demo runs clean without --machine, and the summary names the lathe.
out=$("$bin" run "$root/data/demo/lathe_p300.iso") || fail "run without --machine: exit $?"
grep -q '^%300 (.*) on lathe: ' <<<"$out" || fail "the summary should name the lathe: $out"
"$bin" check "$root/data/demo/lathe_p300.iso" || fail "check without --machine: exit $?"

# A mill program on the default machine: the last line says which one ran.
"$bin" check "$root/data/demo/mill_p300_g19.iso" >/dev/null 2>"$work/err"
[ $? -eq 1 ] || fail "a mill program on the lathe should have errors"
tail -1 "$work/err" | grep -q 'ran on the lathe, the default machine (--machine mill' ||
    fail "check should say it ran on the lathe: $(tail -1 "$work/err")"
"$bin" check --machine mill "$root/data/demo/mill_p300_g19.iso" 2>"$work/err" || fail "mill program on the mill"
grep -q 'default machine' "$work/err" && fail "--machine given: no note"

# plot: a run that fails before any move leaves no file and says why.
printf '%%1\nN10 G2 X10 Z0 R2\nN20 M02\n' >"$work/early.iso"
"$bin" plot --svg "$work/early.svg" --png "$work/early.png" "$work/early.iso" 2>"$work/err"
[ $? -eq 1 ] || fail "plot of a failing program should exit 1"
[ -e "$work/early.svg" ] || [ -e "$work/early.png" ] && fail "plot left a file behind after failing before any move"
grep -q 'no drawing written: the program failed before its first move' "$work/err" || fail "plot should say why: $(cat "$work/err")"

# One that fails later draws what ran, with the error marked.
printf '%%2\nN10 G0 X40 Z10\nN20 G1 X50 F100\nN30 G2 X10 Z0 R2\nN40 M02\n' >"$work/late.iso"
"$bin" plot --svg "$work/late.svg" "$work/late.iso" 2>/dev/null
[ $? -eq 1 ] || fail "plot of a late failure should exit 1"
grep -q 'id="gouge"' "$work/late.svg" || fail "the late failure should be drawn with its error marked"
grep -q 'lathe' "$work/late.svg" || fail "the drawing should name the machine"
echo ok
