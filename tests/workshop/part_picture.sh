#!/usr/bin/env bash
# The part on paper in batch (issue 36, pupitre(1) --part-out, --part-view):
# the lathe's section and the mill's 3-D view as an A4 sheet in PDF and PNG,
# the mill's FILE.png still its height field without a view, the usage
# errors before the run, and no file when the plot module is missing.
#   part_picture.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export LANGUAGE=en
cd "$here" || fail "cd $here"
lathe=(--setup lathe --set PREF.X=-20 --set PREF.Z=35 --set D1.X=52.347 --set D1.Z=41.215)
mill=(--machine mill --setup mill --set PREF.X=108.35 --set PREF.Y=-91.72 --set PREF.Z=-290
    --set D2.L=117.645 --set D2.R=4)
# The PNG's width, height and colour type from its header (IHDR).
png_head() { od -An -tu1 -j16 -N10 "$1" | awk '{ print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8, $10 }'; }

"$bin" run "${lathe[@]}" --part-out "$work/lathe.pdf" turn.iso >/dev/null 2>"$work/err" ||
    fail "lathe PDF: $(cat "$work/err")"
head -c 5 "$work/lathe.pdf" | grep -q '%PDF-' || fail "lathe.pdf is no PDF"
"$bin" run "${lathe[@]}" --part-out "$work/lathe.png" turn.iso >/dev/null 2>"$work/err" ||
    fail "lathe PNG: $(cat "$work/err")"
[ "$(png_head "$work/lathe.png")" = "2400 1697 2" ] ||
    fail "lathe.png should be the A4 sheet, 2400 x 1697 RGB: $(png_head "$work/lathe.png")"

"$bin" run "${mill[@]}" --part-out "$work/mill.png" --part-view 3d slot.iso >/dev/null 2>"$work/err" ||
    fail "mill 3d PNG: $(cat "$work/err")"
[ "$(png_head "$work/mill.png")" = "2400 1697 2" ] || fail "mill.png with a view is the sheet"
"$bin" run "${mill[@]}" --part-out "$work/top.pdf" --part-view top slot.iso >/dev/null 2>"$work/err" ||
    fail "mill top PDF: $(cat "$work/err")"
head -c 5 "$work/top.pdf" | grep -q '%PDF-' || fail "top.pdf is no PDF"
"$bin" run "${mill[@]}" --part-out "$work/height.png" slot.iso >/dev/null 2>"$work/err" ||
    fail "mill height field: $(cat "$work/err")"
[ "$(png_head "$work/height.png")" = "1200 800 0" ] || fail "a mill's FILE.png without a view is its height field"

# Usage errors, before the run (nothing on stdout).
"$bin" run "${mill[@]}" --part-out "$work/x.png" --part-view section slot.iso >"$work/out" 2>"$work/err"
[ $? -eq 64 ] || fail "a lathe's view on the mill should be a usage error"
grep -q "the machining centre's views are top and 3d" "$work/err" || fail "$(cat "$work/err")"
"$bin" run "${lathe[@]}" --part-out "$work/x.svg" --part-view section turn.iso >"$work/out" 2>"$work/err"
[ $? -eq 64 ] || fail "a view drawn into an SVG should be a usage error"
[ -s "$work/out" ] && fail "the usage error should come before the run"
"$bin" run "${lathe[@]}" --part-view section turn.iso >"$work/out" 2>"$work/err"
[ $? -eq 64 ] || fail "--part-view without --part-out should be a usage error"

# No module, no picture, no half-written file.
PUPITRE_PLOT_MODULE=$work/missing.so "$bin" run "${lathe[@]}" --part-out "$work/no.pdf" turn.iso \
    >/dev/null 2>"$work/err"
[ $? -eq 74 ] || fail "no plot module: exit 74"
grep -q "cannot write .*no.pdf: .*missing.so not found" "$work/err" || fail "$(cat "$work/err")"
[ -e "$work/no.pdf" ] && fail "a half-written PDF"
echo ok
