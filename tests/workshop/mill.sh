#!/usr/bin/env bash
# The machining centre's workshop in batch (pupitre-setup(5)): slot.iso cut
# in the shipped mill setup and measured from the block's corner, with the
# numbers worked out by hand; a wrong PREF Z or tool length read by the
# depth gauge; a rapid into the block; the part exported as a 16-bit PNG
# height field with its JSON.
#   mill.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export LANGUAGE=en
cd "$here" || fail "cd $here"
# The true values of data/setups/mill.setup: the origin at the centre of
# the block's top face (X60 Y40 from its corner), T2's true length.
pref=(--set PREF.X=108.35 --set PREF.Y=-91.72)
d2=(--set D2.L=117.645 --set D2.R=4)
run() { "$bin" run --machine mill --setup mill "$@" slot.iso 2>"$work/err"; }

# (a) Right values: the slot along X at Y0 is 8 wide and 3 deep; the pocket
# (the Ø8 cutter round X20..40 Y20..26) is 28 x 14 and 5 deep; the block is
# 37 thick under the slot and 120 long beside it.
out=$(run "${pref[@]}" --set PREF.Z=-290 "${d2[@]}" --measure "width Y X10 Y40 Z-1" \
    --measure "depth X10 Y40" --measure "height X10 Y40" --measure "width X X90 Y63 Z-2" \
    --measure "width Y X90 Y63 Z-2" --measure "depth X90 Y63" --measure "length X Y10 Z-1")
rc=$?
[ $rc -eq 0 ] || fail "(a) exit $rc: $(cat "$work/err")"
expect() { grep -qxF -- "$1" <<<"$out" || fail "$2: expected '$1' in: $out"; }
expect 'width Y X10 Y40 Z-1: 8.00 mm (caliper)' "(a) the slot's width"
expect 'depth X10 Y40: 3.00 mm (depth gauge)' "(a) the slot's depth"
expect 'height X10 Y40: 37.000 mm (micrometer)' "(a) the block under the slot"
expect 'width X X90 Y63 Z-2: 28.00 mm (caliper)' "(a) the pocket's length"
expect 'width Y X90 Y63 Z-2: 14.00 mm (caliper)' "(a) the pocket's width"
expect 'depth X90 Y63: 5.00 mm (depth gauge)' "(a) the pocket's depth"
expect 'length X Y10 Z-1: 120.00 mm (caliper)' "(a) the block's length"

# (b) PREF Z 0.1 mm high: every depth 0.1 shallower; T2's length entered
# 0.1 mm short: 0.1 deeper.
out=$(run "${pref[@]}" --set PREF.Z=-289.9 "${d2[@]}" --measure "depth X10 Y40")
expect 'depth X10 Y40: 2.90 mm (depth gauge)' "(b) PREF Z 0.1 high"
out=$(run "${pref[@]}" --set PREF.Z=-290 --set D2.L=117.545 --set D2.R=4 --measure "depth X10 Y40")
expect 'depth X10 Y40: 3.10 mm (depth gauge)' "(b) L 0.1 short"

# (c) PREF Z 10 mm low: the rapid over the block at Z5 goes into it (1200).
run "${pref[@]}" --set PREF.Z=-300 "${d2[@]}" >"$work/out"
rc=$?
[ $rc -eq 1 ] || fail "(c) a crash should exit 1, not $rc"
grep -Eq '^slot\.iso:[0-9]+: N70: error 1200: crash: T2 rapid \(G0\) into the part at X' "$work/err" ||
    fail "(c) expected the rapid of N70 to crash: $(cat "$work/err")"
# The JSON crash gives the machine position where it stopped, Y included.
run "${pref[@]}" --set PREF.Z=-300 "${d2[@]}" --json >"$work/crash.json"
grep -q '"om":{"X":172.0266,"Y":-89.1906,"Z":-177.3550}' "$work/crash.json" ||
    fail "(c) the JSON crash should give OM X Y Z: $(cat "$work/crash.json")"

# The rotary axes: on mill4 the mill's setup cuts the same part while B stays
# at 0; mill5's tilted head cuts a chamfer; an A axis is refused.
run_on() { "$bin" run --machine "$1" --setup mill "${pref[@]}" --set PREF.Z=-290 "${d2[@]}" "${@:2}"; }
run_on mill --measure "width Y X60 Y40 Z-2" --json slot.iso >"$work/on_mill.json" 2>"$work/err" ||
    fail "(c) mill: $(cat "$work/err")"
run_on mill4 --measure "width Y X60 Y40 Z-2" --json slot.iso >"$work/on_mill4.json" 2>"$work/err" ||
    fail "(c) mill4: $(cat "$work/err")"
grep -o '"measurements":.*' "$work/on_mill.json" >"$work/m1"
grep -o '"measurements":.*' "$work/on_mill4.json" >"$work/m4"
cmp -s "$work/m1" "$work/m4" || fail "(c) mill4 should cut the mill's part: $(cat "$work/m4")"
# mill5's head at B45: T1's end cuts a 2 x 2 chamfer on the block's +X top
# edge (the tip at X49 Z-281 of the machine, the head's axis 250 above the
# gauge line: machine X 49 + 360.25 sin 45° = 303.735, Z -531 + 360.25 cos
# 45° = -276.265, so program Z -106.515 with PREF Z-280 and L 110.25:
# tests/workshop/chamfer.iso).
"$bin" run --machine mill5 --setup mill5 --set PREF.Z=-280 --set D1.L=110.25 --set D1.R=5 \
    --measure "depth X99 Y50" --measure "depth X98.5 Y0" --measure "length X Y50 Z-1" \
    --json chamfer.iso >"$work/chamfer.json" 2>"$work/err" || fail "(c) B45: $(cat "$work/err")"
grep -q '"crashes":\[\],"measurements":\[{"spec":"depth X99 Y50","instrument":"depth gauge","value":1.0000,.*"value":0.5000,.*"value":99.0000' \
    "$work/chamfer.json" || fail "(c) the B45 chamfer: $(cat "$work/chamfer.json")"
# Drawn on the part: the head at B45 puts the tip 254.735 to -X of the
# gauge line (X0 before N50: X-254.735), each B turn drawn in pieces that
# count as one move.
"$bin" plot --machine mill5 --setup mill5 --set PREF.Z=-280 --set D1.L=110.25 --set D1.R=5 \
    --svg "$work/chamfer.svg" chamfer.iso 2>"$work/err" || fail "(c) plot B45: $(cat "$work/err")"
grep -q '7 moves · path 1296.874 mm' "$work/chamfer.svg" || fail "(c) plot B45: the moves"
grep -q 'extents  X -254.735/303.735' "$work/chamfer.svg" || fail "(c) plot B45: the path on the part"
sed 's/\bB\b/A/g; s/travel\.B/travel.A/; s/rapid\.B/rapid.A/; s/home\.B/home.A/' \
    "$here/../../data/machines/mill4.machine" | grep -v "^kinematics" >"$work/a.machine"
"$bin" run --machine "$work/a.machine" --setup mill slot.iso >/dev/null 2>"$work/err"
[ $? -eq 64 ] || fail "(c) a setup on a machine with A should be a usage error: $(cat "$work/err")"
grep -qF "has an A axis: the workshop models a C table and a B head or table only" "$work/err" ||
    fail "(c) A: $(cat "$work/err")"

# plot --setup draws the block from above once (no lathe's mirror image),
# the slot and the pocket as holes, and frames the whole block (Y -40..40).
"$bin" plot --machine mill --setup mill "${pref[@]}" --set PREF.Z=-290 "${d2[@]}" --svg "$work/plot.svg" \
    slot.iso 2>"$work/err" || fail "(f) plot --setup: $(cat "$work/err")"
part=$(sed -n '/<g id="part"/,/<\/g>/p' "$work/plot.svg")
[ "$(grep -c '<path' <<<"$part")" -eq 1 ] || fail "(f) the block should be drawn once: $part"
grep -q 'd="M-60.0000 40.0000 L60.0000 40.0000 L60.0000 -40.0000 L-60.0000 -40.0000 Z M' <<<"$part" ||
    fail "(f) the block's outline, then its holes: $(head -c 300 <<<"$part")"
read -r y h < <(sed -n 's/.*<clipPath id="window"><rect x="[^"]*" y="\([^"]*\)" width="[^"]*" height="\([^"]*\)".*/\1 \2/p' \
    "$work/plot.svg")
awk -v y="$y" -v h="$h" 'BEGIN { exit !(y <= -40 && y + h >= 40) }' ||
    fail "(f) the frame should hold the block's Y -40..40, not y $y height $h"

# (e) The golden report (tests/workshop/slot.json): the same readings, the
# presetter's, and one that cannot be taken.
run "${pref[@]}" --set PREF.Z=-290 "${d2[@]}" --json --measure "width Y X10 Y40 Z-1" \
    --measure "depth X10 Y40" --measure "height X10 Y40" --measure "width X X90 Y63 Z-2" \
    --measure "width Y X90 Y63 Z-2" --measure "depth X90 Y63" --measure "tool T2 L" \
    --measure "width X X10 Y40 Z-1" >"$work/slot.json" || fail "(e) exit $?: $(cat "$work/err")"
diff -u slot.json "$work/slot.json" || fail "(e) the JSON report differs from tests/workshop/slot.json"

# (d) The part as a 16-bit greyscale PNG and its JSON.
run "${pref[@]}" --set PREF.Z=-290 "${d2[@]}" --part-out "$work/part.png" >/dev/null ||
    fail "(d) --part-out part.png: $(cat "$work/err")"
file "$work/part.png" 2>/dev/null | grep -q '16-bit grayscale' ||
    head -c 32 "$work/part.png" | od -An -tx1 | tr -d ' \n' | grep -q '^89504e470d0a1a0a0000000d49484452000004b0000003201000' ||
    fail "(d) part.png should be a 1200 x 800 16-bit greyscale PNG"
grep -q '"columns":1200,"rows":800,"cell":0.1000' "$work/part.json" ||
    fail "(d) part.json should give the image's size and cell: $(cat "$work/part.json")"
run "${pref[@]}" --set PREF.Z=-290 "${d2[@]}" --part-out "$work/part.svg" >"$work/out"
[ $? -eq 64 ] || fail "(d) a mill part as .svg should be a usage error"
grep -qF "a machining centre's part is a 16-bit PNG height field" "$work/err" ||
    fail "(d) the usage error should say why: $(cat "$work/err")"
[ -s "$work/out" ] && fail "(d) the usage error should come before the run: $(cat "$work/out")"
echo ok
