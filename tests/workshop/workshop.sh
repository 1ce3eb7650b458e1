#!/usr/bin/env bash
# The workshop in batch (pupitre-setup(5)): turn.iso cut in the shipped lathe
# setup and measured (golden JSON in turn.json), a wrong PREF read by the
# micrometer, a wrong PREF Z that crashes, the usage errors, --part-out, and
# the handbook's %555 on its blank.
#   workshop.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export LANGUAGE=en
# The program's name as the report gives it: run from here, "turn.iso".
cd "$here" || fail "cd $here"
# The true values of data/setups/lathe.setup: the origin on the axis at the
# bar's face, T1's true gauge.
truth=(--set PREF.X=-20 --set PREF.Z=35 --set D1.X=52.347 --set D1.Z=41.215)

# (a) The golden report: Ø50 and Ø56 as programmed, 95 mm out of the jaws,
# no groove to read.
"$bin" run --json --setup lathe "${truth[@]}" --measure "dia Z-10" --measure "dia Z-30" --measure length \
    --measure "groove Z-5" turn.iso >"$work/turn.json" 2>"$work/err"
rc=$?
[ $rc -eq 0 ] || fail "(a) exit $rc: $(cat "$work/err")"
diff -u turn.json "$work/turn.json" || fail "(a) the JSON report differs from tests/workshop/turn.json"

# (b) PREF X 0.1 mm (a radius) too far from the axis: the part is 0.2 larger.
out=$("$bin" run --setup lathe --set PREF.X=-19.9 --set PREF.Z=35 --set D1.X=52.347 --set D1.Z=41.215 \
    --measure "dia Z-10" turn.iso 2>"$work/err")
rc=$?
[ $rc -eq 0 ] || fail "(b) exit $rc: $(cat "$work/err")"
grep -qx 'dia Z-10: 50.200 mm (micrometer)' <<<"$out" || fail "(b) expected Ø50.200: $out"

# (c) PREF Z 10 mm short: the approach rapid runs into the bar.
"$bin" run --setup lathe --set PREF.X=-20 --set PREF.Z=25 --set D1.X=52.347 --set D1.Z=41.215 \
    turn.iso >"$work/out" 2>"$work/err"
rc=$?
[ $rc -eq 1 ] || fail "(c) a crash should exit 1, not $rc"
grep -Eq '^turn\.iso:[0-9]+: N[0-9]+: error 1200: crash:' "$work/err" ||
    fail "(c) expected an error 1200 crash diagnostic: $(cat "$work/err")"

# (d) Usage errors: exit 64 and say what is wrong.
usage() {  # usage CASE EXPECTED-TEXT ARGS...
    local what=$1 text=$2
    shift 2
    "$bin" run "$@" >"$work/out" 2>"$work/err"
    local rc=$?
    [ $rc -eq 64 ] || fail "(d) $what: exit $rc, expected 64"
    grep -qF -- "$text" "$work/err" || fail "(d) $what: expected '$text' in: $(cat "$work/err")"
}
usage "--measure without --setup" "--measure and --part-out need a --setup" --measure "dia Z-10" turn.iso
usage "--part-out without --setup" "--measure and --part-out need a --setup" --part-out "$work/p.svg" turn.iso
usage "a lathe setup on the mill" "setup 'lathe' is a lathe's, the machine is a machining centre" --machine mill --setup lathe turn.iso
usage "a mill setup on the lathe" "setup 'mill' is a machining centre's, the machine is a lathe" --setup mill turn.iso
usage "an unknown setup" "unknown setup 'nosuch'" --setup nosuch turn.iso
printf '# a setup with a bad line\nkind = lathe\nstock.diameter = 60\nchuck.z = banana\n' >"$work/bad.setup"
usage "a bad value" "$work/bad.setup: line 4: chuck.z: expected a number" --setup "$work/bad.setup" turn.iso
printf 'kind = lathe\nthis line has no equals sign\n' >"$work/noeq.setup"
usage "a line without =" "$work/noeq.setup: line 2: expected key = value" --setup "$work/noeq.setup" turn.iso
printf 'kind = lathe\ntool.1.angle = 10\n' >"$work/range.setup"
usage "a value out of range" "$work/range.setup: line 2: tool.1.angle: must be from 20 to 175" \
    --setup "$work/range.setup" turn.iso
[ -e "$work/p.svg" ] && fail "(d) a usage error left a part file behind"

# (e) The cut part: SVG, and (Z, R) points after a comment line.
"$bin" run --setup lathe "${truth[@]}" --part-out "$work/x.svg" turn.iso >/dev/null 2>"$work/err" ||
    fail "(e) --part-out x.svg: $(cat "$work/err")"
grep -q '<svg' "$work/x.svg" && grep -q '<path' "$work/x.svg" || fail "(e) x.svg should be an SVG with a <path"
"$bin" run --setup lathe "${truth[@]}" --part-out "$work/x.zr" turn.iso >/dev/null 2>"$work/err" ||
    fail "(e) --part-out x.zr: $(cat "$work/err")"
head -1 "$work/x.zr" | grep -q '^# ' || fail "(e) x.zr should start with a comment: $(head -1 "$work/x.zr")"
bad=$(tail -n +2 "$work/x.zr" | grep -Ev '^(-?[0-9]+\.[0-9]{3} -?[0-9]+\.[0-9]{3})?$' | head -3)
[ -z "$bad" ] || fail "(e) x.zr lines should be 'Z R': $bad"
# The turned diameters are on the outline: R 25 from the face, the Ø56 from
# the shoulder at Z-20, the bar's Ø60 from Z-40.
grep -qx '0.000 25.000' "$work/x.zr" || fail "(e) x.zr should start the Ø50 at the face"
grep -qx -- '-20.000 28.000' "$work/x.zr" || fail "(e) x.zr should have the Ø56 from the shoulder at Z-20"
grep -qx -- '-40.000 30.000' "$work/x.zr" || fail "(e) x.zr should have the Ø60 from Z-40"

# (f) plot --setup draws the part under the path; a crash is drawn and exits 1.
"$bin" plot --setup lathe "${truth[@]}" --svg "$work/plot.svg" turn.iso 2>"$work/err" ||
    fail "(f) plot --setup: $(cat "$work/err")"
grep -q '<g id="part"' "$work/plot.svg" || fail "(f) the plot should have the part's layer"
grep -q 'the part as cut (workshop)' "$work/plot.svg" || fail "(f) the legend should name the part"
"$bin" plot turn.iso --svg "$work/plain.svg" 2>/dev/null
grep -q 'id="part"' "$work/plain.svg" && fail "(f) no part without --setup"
"$bin" plot --setup lathe --set PREF.X=-20 --set PREF.Z=25 --set D1.X=52.347 --set D1.Z=41.215 \
    --svg "$work/crash.svg" turn.iso 2>"$work/err"
[ $? -eq 1 ] || fail "(f) a crash in plot should exit 1"
grep -Eq 'error 1200: crash:' "$work/err" || fail "(f) plot should print the crash: $(cat "$work/err")"
# (g) The handbook's %555 (G64 then G65, a copy of the handbook
# program 000_p555_cycles_x.iso) on its blank: G64 leaves the Ø60 lands at Ø61 (I.5),
# so N340's rapid to X62 Z50 and the G65 after it run clear of the part
# (issue 19: before, the lands stayed at Ø64 and N340 crashed).
p555=(--set PREF.X=-20 --set PREF.Z=-54 --set D1.X=52.347 --set D1.Z=41.215 --set D1.R=0.8 --set D1.C=3
    --set D3.X=48.112 --set D3.Z=44.730 --set D3.R=0.4 --set D3.C=8)
out=$("$bin" run --setup p555.setup "${p555[@]}" --measure "dia Z-40" --measure "dia Z-80" p555_x.iso 2>"$work/err")
grep -Eq ': N3[45]0: error 12' "$work/err" && fail "(g) %555 crashed at N340/N350: $(cat "$work/err")"
grep -qx 'dia Z-40: 61.000 mm (micrometer)' <<<"$out" || fail "(g) the Ø60 land by Z50-Z60 should be Ø61: $out"
grep -qx 'dia Z-80: 61.000 mm (micrometer)' <<<"$out" || fail "(g) the Ø60 land by Z10-Z20 should be Ø61: $out"
# (h) The life of an edge from the setup (tool.N.life, issue 35): the
# summary's tool line says after how many parts the edge is changed; the
# command line's --edge-life wins, for every tool or for one.
{ cat ../../data/setups/lathe.setup; echo 'tool.1.life = 15'; } >"$work/life.setup"
parts() {  # parts ARGS...: the "change the edge every N parts" of T1's line
    "$bin" run --setup "$work/life.setup" "${truth[@]}" "$@" turn.iso 2>"$work/err" |
        sed -n 's/^T1: .*change the edge every \([0-9]*\) parts$/\1/p'
}
n15=$(parts)
[ -n "$n15" ] || fail "(h) the setup's tool.1.life should give T1's parts per edge: $(cat "$work/err")"
n30=$(parts --edge-life 30)
[ -n "$n30" ] && [ "$n30" -ge $((2 * n15)) ] && [ "$n30" -le $((2 * n15 + 1)) ] ||
    fail "(h) --edge-life 30 should double the setup's 15 minutes: $n15 then $n30"
[ "$(parts --edge-life T1=30)" = "$n30" ] || fail "(h) --edge-life T1=30 should win over the setup's"
[ "$(parts --edge-life T2=30)" = "$n15" ] || fail "(h) --edge-life T2 should leave T1's life from the setup"
echo ok
