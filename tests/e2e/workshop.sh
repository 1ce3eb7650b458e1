#!/usr/bin/env bash
# The workshop in the real console (issue 15), driven by keys in tmux as a
# student would: a true part in the chuck (:setup lathe), touch-offs on a
# face and a diameter the tool really meets, a program that turns the part,
# the instruments, and the crashes.
#   workshop.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"
W=100 H=30

# Homed, the setup SETUP (default lathe) in the chuck, max speed, tool T in
# the turret (default T1 D1), then JOG over the bar.
ready() {
    local setup=${1:-lathe} tool=${2:-T1 D1 M6}
    start
    pom
    cmd ":setup $setup"
    cmd ":speed max"
    cmd ":mode imd"
    cmd "$tool"
    keys F9
    wait_for 'IMD done' 10
    cmd ":mode jog"
    cmd ":jog Z -150"
}

case $case in
touchoff)
    # T1 is the reference tool (D1 left at zero): PREF takes its gauge. The
    # shipped setup's truth: axis at X -20 (radius), the bar's face at Z 35,
    # T1 at X 52.347 Z 41.215 from the turret's reference (data/setups).
    "$bin" import "$(dirname "$0")/programs/turn_reference.iso" >/dev/null || fail "import"
    start
    pom
    cmd ":setup lathe"
    wait_for 'workshop: setup lathe'
    cmd ":speed max"
    cmd ":mode imd"
    cmd "T1 D1 M6"
    keys F9
    wait_for 'IMD done' 10
    cmd "S800 M3"
    keys F9
    wait_for 'IMD done' 10
    # The diameter: over the bar, down until the tool touches it.
    cmd ":mode jog"
    cmd ":jog Z -150"
    cmd ":jog X -200"
    wait_for 'T1 touched the part at ø60.000' 20
    [ "$(op_value X)" = "124.694" ] || fail "the touch should stop at OM X 124.694 (ø60 + 2 × 52.347 - 2 × 20)"
    # An increment from the contact cuts (the spindle turns): 0.5 deep, then
    # along +Z out of the bar, a skimmed diameter.
    cmd ":mode inc"
    cmd ":jog X -1"
    cmd ":jog Z 40"
    wait_for '^ +Z +90.000' 10
    cmd ":measure dia Z-10"
    wait_for 'micrometer: dia Z-10 = 59.000 mm'
    # The touch-off on the skimmed diameter: X moved only along Z since.
    # T1's true gauge is in PREF: -20 + 52.347.
    cmd ":touch X 59"
    wait_for 'PREF.X \(radius\) = OM ø123.694/2 - surface ø59.000/2 = 32.347' 5
    # The face: touched at ø39, then faced 0.5 from above the bar.
    cmd ":mode jog"
    cmd ":jog X -20"
    cmd ":jog Z -20"
    wait_for 'T1 touched the part at ø39.000, 0.000 mm from the stock' 10
    cmd ":jog X 24"
    cmd ":mode inc"
    cmd ":jog Z -0.5"
    cmd ":jog X -66"
    # The insert's trailing edge meets the skimmed ø59's corner first.
    wait_for 'T1 touched the part at ø58.882, -0.500 mm' 10
    cmd ":jog X -66"
    wait_for '^ +Xø +-7.118' 10
    cmd ":touch Z 0"
    wait_for 'PREF.Z = OM 75.715 - surface 0.000 = 75.715' 5
    cmd ":jog X 120"
    cmd ":measure length"
    wait_for 'depth gauge: length = 94.50 mm'
    # The program turns the drawing's diameters.
    cmd ":load 710"
    cmd ":mode auto"
    keys F9
    wait_for 'M02: end of program %710' 30
    cmd ":measure dia Z-10"
    wait_for 'micrometer: dia Z-10 = 50.000 mm'
    cmd ":measure dia Z-30"
    wait_for 'micrometer: dia Z-30 = 56.000 mm'
    cmd ":measure dia Z-60"
    wait_for 'micrometer: dia Z-60 = 60.000 mm'
    # GRAPH shows the part under the path.
    cmd ":page graph"
    wait_for '⣿⣿⣿'
    # The part as cut, exported from the console.
    cmd ":part export $work/part.svg"
    wait_for "the part written to"
    grep -q '<path' "$work/part.svg" || fail ":part export wrote no SVG path"
    # A restart shows the same part; :part new brings fresh stock.
    cmd ":quit!"
    wait_for '^EXIT=0' 10
    next_server
    start
    cmd ":measure dia Z-10"
    wait_for 'micrometer: dia Z-10 = 50.000 mm'
    cmd ":part new"
    wait_for 'fresh stock in the chuck'
    cmd ":measure dia Z-10"
    wait_for 'micrometer: dia Z-10 = 60.000 mm'
    ;;
corrtouch)
    # The threading tool T4 (C8, a V insert) touched off by keys on the CORR
    # page. :touch there sets PREF, as everywhere, and says so first; the
    # page's own "X 60" measures D4. Its face touch with the point low meets
    # the holder first, and the message says so.
    ready lathe "T4 D4 M6"
    cmd ":jog X -200"
    wait_for 'T4 touched the part at ø60.000' 20
    cmd ":page corr"
    cmd ":touch X 60"
    wait_for ':touch set PREF, not D4 \(here type X 60.000; :undo\): PREF.X' 5
    cmd ":undo"
    wait_for 'undone: PREF.X = 0.000' 5
    cmd "D4"
    cmd "X 60"
    wait_for 'D4.X \(radius\) = OM ø[0-9.]+/2 - surface ø60.000/2 = 30.774' 5
    cmd ":jog X 20"
    cmd ":jog Z 60"
    cmd ":jog X -40"
    cmd ":jog Z -100"
    wait_for 'the holder of T4 touched the part' 20
    cmd ":quit"
    ;;
crash)
    # The spindle stopped, an increment into the bar: a crash, not a cut.
    ready
    cmd ":jog X -200"
    wait_for 'T1 touched the part' 20
    # A held key goes no deeper than the contact.
    cmd ":jog X -5"
    [ "$(op_value X)" = "124.694" ] || fail "JOG from a contact must not go deeper: $(op_value X)"
    cmd ":mode inc"
    cmd ":jog X -0.2"
    wait_for 'ALARM 1201' 10
    sgr_line 'ALARM 1201' | grep -q $'\e\\[' || fail "the alarm is not coloured"
    keys F12
    wait_for 'READY' 10
    # A rapid through the bar in IMD: 1200, stopped at the contact.
    cmd ":mode imd"
    cmd "S800 M3"
    keys F9
    wait_for 'IMD done' 10
    cmd "G0 X100 Z0"
    keys F9
    wait_for 'ALARM 1200' 10
    cmd ":page alarm"
    wait_for 'crash: T1 rapid \(G0\) into the part'
    ;;
shim)
    # The paper test: a 0.05 shim on the bar; the jog stops 0.05 above it
    # (Ø60.1), and the touch-off subtracts it.
    ready
    cmd ":shim 0.05"
    wait_for 'a 0.050 mm shim on the part'
    cmd ":jog X -200"
    wait_for 'T1 touched the 0.050 mm shim on the part at ø60.100' 20
    [ "$(op_value X)" = "124.794" ] || fail "the shim should stop the tool at OM X 124.794"
    cmd ":mode inc"
    cmd ":jog X -0.1"
    wait_for 'the shim is between T1 and the part: :shim off before cutting'
    cmd ":touch X 60.1"
    wait_for 'PREF.X \(radius\) = OM ø124.794/2 - surface ø60.100/2 = 32.347' 5
    cmd ":shim off"
    wait_for 'no shim on the part'
    ;;
probe)
    # The electric probe's lamp on the OP page: out, then lit at the contact
    # (in the alarm colour), out again when the jog backs off.
    ready "$(realpath "$(dirname "$0")/../workshop/probe.setup")" "T5 D5 M6"
    cmd ":page op"
    wait_for '^  Probe +○ open'
    cmd ":jog X -200"
    wait_for 'T5 touched the part' 20
    wait_for '^  Probe +● contact'
    sgr_line '● contact' | grep -q $'\e\\[' || fail "the lamp is not coloured"
    cmd ":jog X 2"
    wait_for '^  Probe +○ open'
    # Driven on into the bar: a crash.
    cmd ":jog X -3"
    wait_for 'T5 touched the part' 10
    cmd ":mode inc"
    cmd ":jog X -0.5"
    wait_for 'ALARM 1205' 10
    # A crash of a manual move comes from no block: the mode is its place,
    # and the ALARM page explains the number.
    wait_for 'ALARM 1205 \(INC\): crash: the probe T5 was driven into the part' 5
    keys F7
    wait_for '^ ALARM 1205 +INC$' 5
    wait_for 'Crash: a touch probe driven into something' 5
    ;;
gauge)
    # Seed 004's exam: a 100 mm gauge block against the jaws' face (chuck.z
    # -60): T1 jogged along -Z over it stops on its end, P at Z 40, so OM Z
    # 40 + 41.215; an INC step is refused until :gauge off; the WORKSHOP page
    # lists it.
    start
    pom
    cmd ":setup lathe"
    cmd ":speed max"
    cmd ":mode imd"
    cmd "T1 D1 M6"
    keys F9
    wait_for 'IMD done' 10
    cmd ":gauge 100"
    wait_for 'a 100.000 mm gauge block against the jaws' 5
    cmd ":mode jog"
    # Over the block from above its end: P at R 35 (ø70), OM X 35 + 52.347
    # - 20 as a diameter.
    cmd ":jog X -$(awk -v x="$(op_value X)" 'BEGIN { printf "%.3f", x - 134.694 }')"
    wait_for '^ +Xø +134.694' 10
    cmd ":jog Z -200"
    wait_for "T1 touched the 100.000 mm gauge block on the jaws' face" 20
    [ "$(screen | awk '$1 == "Z" { print $3; exit }')" = "81.215" ] ||
        fail "the block's end should stop OM Z at 81.215 (40 + 41.215): $(screen)"
    cmd ":mode inc"
    cmd ":jog Z -0.1"
    wait_for 'the gauge block is between T1 and the chuck: :gauge off' 5
    keys M-w
    wait_for "^ Gauge +100.000 mm block against the jaws' face" 5
    cmd ":gauge off"
    wait_for 'no gauge block against the jaws' 5
    ;;
mill)
    # The machining centre as a setter sets it up: T2's length on the tool
    # setter, PREF Z on the block's top, PREF X and Y on its -X and -Y faces
    # (an Ø8 cutter: the axis 4 off the face), then the slot of slot.iso cut
    # and measured from the block's corner, the part shaded on GRAPH, and a
    # restart that shows the same part. The truth (data/setups/mill.setup):
    # the setter's top at Z -300, T2 L 117.645, the block's corner at X 48.35
    # Y -131.72, its top at Z -290; the program origin at the top's centre.
    "$bin" import "$(dirname "$0")/../workshop/slot.iso" >/dev/null || fail "import"
    start --machine mill
    pom
    cmd ":setup mill"
    wait_for 'workshop: setup mill, machine vice'
    cmd ":speed max"
    cmd ":mode imd"
    cmd "T2 D2 M6"
    keys F9
    wait_for 'IMD done' 10
    # The length: over the setter, down until the cutter touches it.
    cmd ":mode jog"
    cmd ":jog X -250"
    cmd ":jog Y -150"
    wait_for '^ +Y +-150.000' 10
    cmd ":jog Z -600"
    wait_for 'T2 touched the tool setter' 20
    [ "$(op_value Z)" = "-182.355" ] || fail "the setter should stop the gauge line at Z -182.355 (-300 + 117.645): $(op_value Z)"
    cmd ":measure D2 Z -300"
    wait_for 'D2.L = OM -182.355 - surface -300.000 = 117.645' 5
    # PREF Z on the top face, at the block's centre.
    cmd ":jog Z 100"
    cmd ":jog X 358.35"
    cmd ":jog Y 58.28"
    wait_for '^ +Y +-91.720' 10
    cmd ":jog Z -200"
    wait_for 'T2 touched the part at X60.000 Y40.000 Z0.000' 20
    cmd ":touch Z 0"
    wait_for 'PREF.Z = OM -172.355 - gauge 117.645 - surface 0.000 = -290.000' 5
    # PREF X on the -X face, 5 below the top.
    cmd ":jog Z 10"
    cmd ":jog X -70"
    wait_for '^ +X +38.350' 10
    cmd ":jog Z -15"
    wait_for '^ +Z +-5.000' 10
    cmd ":jog X 20"
    wait_for 'T2 touched the part at X-4.000 Y40.000 Z-5.000' 20
    cmd ":touch X -64"
    wait_for 'PREF.X = OM 44.350 - surface -64.000 = 108.350' 5
    # PREF Y on the -Y face: away from the -X face, round the corner.
    cmd ":jog X -10"
    wait_for '^ +X +-74.000' 10
    cmd ":jog Y -50"
    wait_for '^ +Y +-141.720' 10
    cmd ":jog X 74"
    wait_for '^ +X +0.000' 10
    cmd ":jog Y 20"
    wait_for 'T2 touched the part at X60.000 Y-4.000 Z-5.000' 20
    cmd ":touch Y -44"
    wait_for 'PREF.Y = OM -135.720 - surface -44.000 = -91.720' 5
    cmd ":jog Y -10"
    cmd ":jog Z 60"
    wait_for '^ +Z +55.000' 10
    # The slot and the pocket, in AUTO with the spindle turning (slot.iso).
    cmd ":mode auto"
    cmd ":load 30"
    keys F9
    wait_for 'M02: end of program %30' 60
    # The WORKSHOP page (Alt-w): what is typed there is an instrument's request.
    keys M-w
    wait_for '^─ WORKSHOP  setup mill' 5
    wait_for '^MEASURE>' 5
    cmd "depth X10 Y40"
    wait_for 'depth gauge: depth X10 Y40 = 3.00 mm' 10
    cmd ":measure width Y X10 Y40 Z-1"
    wait_for 'caliper: width Y X10 Y40 Z-1 = 8.00 mm' 10
    # Both readings listed on the page, newest first.
    screen | grep -A2 'Readings (newest first)' | tail -2 | head -1 | grep -q 'caliper: width Y' ||
        fail "the WORKSHOP page should list the caliper's reading first: $(screen)"
    # GRAPH: the block shaded, the slot through it.
    cmd ":page graph"
    wait_for '▓' 10
    screen | grep -q '░' || fail "GRAPH should shade the slot and the pocket (░): $(screen)"
    # A restart shows the same part.
    cmd ":quit!"
    wait_for '^EXIT=0' 10
    T kill-session -t e2e 2>/dev/null
    start --machine mill
    cmd ":measure depth X10 Y40"
    wait_for 'depth gauge: depth X10 Y40 = 3.00 mm' 10
    # A rapid into the block in IMD is a crash: the alarm, the machine
    # stopped at the contact (the slot is 3 deep, the rapid goes to 10).
    pom
    cmd ":mode imd"
    cmd "T2 D2 M6"
    keys F9
    wait_for 'IMD done' 10
    cmd "G0 X0 Y0 Z-10"
    keys F9
    wait_for 'ALARM 1200' 20
    wait_for 'crash: T2 rapid \(G0\) into the part' 5
    ;;
mill5_chamfer)
    # mill5's head at B45 (tests/workshop/chamfer.iso): T1's end cuts a 2 x 2
    # chamfer on the block's +X top edge, read with the depth gauge 1 in from
    # the face; GRAPH draws the path on the part, the B turns in pieces that
    # count as one move each (7 moves), and a restart keeps the chamfer.
    "$bin" import "$(dirname "$0")/../workshop/chamfer.iso" >/dev/null || fail "import"
    start --machine mill5
    pom
    cmd ":setup mill5"
    wait_for 'workshop: setup mill5' 5
    cmd ":speed max"
    cmd ":set PREF.Z=-280"
    cmd ":set D1.L=110.25"
    cmd ":set D1.R=5"
    cmd ":load 11"
    wait_for '%11 selected' 5
    cmd ":mode auto"
    keys F9
    wait_for 'M02: end of program %11' 30
    cmd ":measure depth X99 Y50"
    wait_for 'depth gauge: depth X99 Y50 = 1.00 mm' 5
    cmd ":page graph"
    wait_for ' 7 moves ' 10
    cmd ":quit!"
    wait_for '^EXIT=0' 10
    T kill-session -t e2e 2>/dev/null
    start --machine mill5
    cmd ":measure length X Y50 Z-1"
    wait_for 'caliper: length X Y50 Z-1 = 99.00 mm' 5
    ;;
mill5)
    # The five-axis centre's C table (data/setups/mill5.setup: the C axis at
    # X0 Y0 through a 100 x 100 block, its top at Z -280; T1 Ø10, L 110.25):
    # T1 down beside the -X face, 1 mm off; C jogged: the block swings into
    # the cutter and the jog stops at C 10.84 (56 cos C = 55). Then the B
    # head tilts the tool, and its end's rim touches the top.
    start --machine mill5
    pom
    cmd ":setup mill5"
    wait_for 'workshop: setup mill5' 5
    cmd ":speed max"
    cmd ":mode imd"
    cmd "T1 D1 M6"
    keys F9
    wait_for 'IMD done' 10
    cmd ":mode jog"
    cmd ":jog X -56"
    cmd ":jog Y 0"
    cmd ":jog Z -374.75"
    wait_for '^ +Z +-174.750' 10
    cmd ":jog C 90"
    wait_for 'T1 touched the part at X-5.000 Y39.4' 20
    [ "$(op_value C)" = "10.8420" ] || fail "the C jog should stop at C 10.8420: $(op_value C)"
    cmd ":jog Z 100"
    wait_for '^ +Z +-74.750' 10
    # The head tilted to B-10 swings the tip 62.56 to +X and 4.98 up, over
    # the block; jogged down, the end's lowest point (5 sin 10° under the
    # tip) meets the top at Z-280: the machine at Z -280 + 0.868 - 250 +
    # 360.25 cos 10° = -174.355.
    cmd ":jog B -10"
    wait_for '^ +B +-10.0000' 10
    cmd ":jog Z -200"
    # The Z it stops at, not the message: the C jog's "T1 touched the part"
    # is still on the message line until this jog meets the top.
    wait_for '^ +Z +-174.355' 20
    wait_for 'T1 touched the part' 5
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
cmd ":quit!"
wait_for '^EXIT=0' 10
