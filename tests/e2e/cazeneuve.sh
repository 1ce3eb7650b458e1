#!/usr/bin/env bash
# The Cazeneuve HB CNC 3 lathe (issue 17) in the real console, driven by keys
# in tmux as a setter would: its T word, its pages, the tool setting from a
# witness cut each tool touches (seed 003:802-808), then a program in its
# dialect that turns the part to the size the correctors promise.
#   cazeneuve.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"
W=100 H=30

case $case in
witness)
    # The Cazeneuve's own setup (data/setups/cazeneuve.setup): the spindle
    # axis at machine X 0, the bar's face at Z 35, T1's point at X 52.347
    # Z 41.215 from the turret's reference, T11's (rear turret) at X 310.412
    # Z 41.808. The correctors carry the origin (PREF stays 0): after a
    # 0.5 mm facing cut D1 is X 52.347 Z 75.715 and D11 X 310.412 Z 76.308.
    "$bin" import "$(dirname "$0")/programs/caz_witness.iso" >/dev/null || fail "import"
    start --machine cazeneuve
    pom
    cmd ":setup"
    expect_message 'no workshop: the machine moves a point \(:setup cazeneuve\)'
    cmd ":setup cazeneuve"
    cmd ":speed max"
    cmd ":mode imd"
    cmd "T101"
    keys F9
    wait_for 'IMD done' 10
    wait_for 'Tool +T101' 5
    cmd "M3 S500"
    keys F9
    wait_for 'IMD done' 10
    cmd ":mode jog"
    cmd ":jog Z -150"
    cmd ":jog X -200"
    wait_for 'touched the part' 10
    # The witness diameter: 1 mm deeper in X (a radius here), 40 mm along.
    cmd ":mode inc"
    cmd ":jog X -1"
    cmd ":jog Z 40"
    cmd ":measure dia Z-60"
    wait_for 'micrometer: dia Z-60 = 58.000' 5
    cmd ":tangent X"
    expect_message 'no witness cut yet'
    cmd ":witness 58"
    expect_message 'witness cut: .58.000, face at Z 0.000'
    cmd ":tangent X"
    wait_for 'D1.X = OM 81.347 - surface 29.000 = 52.347' 5
    # The witness face: over the bar, past its face, down, onto it, then
    # 0.5 mm deeper and across to the centre.
    cmd ":mode jog"
    cmd ":jog X 6"
    cmd ":jog Z 50"
    cmd ":jog X -10"
    cmd ":jog Z -30"
    wait_for 'touched the part' 10
    cmd ":mode inc"
    cmd ":jog Z -0.5"
    cmd ":jog X -27"
    cmd ":tangent Z"
    wait_for 'D1.Z = OM 75.715 - surface 0.000 = 75.715' 5
    cmd ":mode jog"
    cmd ":jog X 40"
    cmd ":measure length"
    wait_for 'length = 94.50 mm' 5
    # The rear turret's T11 touches the same witness behind the axis.
    cmd ":mode imd"
    cmd "G7XZ"
    keys F9
    wait_for 'IMD done' 10
    cmd "T1111"
    keys F9
    wait_for 'IMD done' 10
    cmd ":mode jog"
    cmd ":jog Z -130"
    cmd ":jog X 100"
    wait_for 'T11 touched the part' 10
    cmd ":tangent X"
    wait_for 'D11.X = OM 281.412 - surface -29.000 = 310.412' 5
    cmd ":jog X -20"
    cmd ":jog Z 60"
    cmd ":jog X 25"
    cmd ":jog Z -30"
    wait_for 'T11 touched the part' 10
    cmd ":tangent Z"
    wait_for 'D11.Z = OM 76.308 - surface 0.000 = 76.308' 5
    # The pages speak this controller's language.
    cmd ":page corr"
    wait_for 'correctors 01-99' 5
    wait_for '52.347 +75.715 ' 5
    wait_for 'witness cut: .58.000' 5
    cmd ":page pref"
    wait_for 'PREF +gauge +OM +OP' 5
    screen | grep -q DEC1 && fail "the Cazeneuve has no DEC1"
    wait_for 'active tool T1111: turret position 11, corrector 11' 5
    cmd ":page info"
    wait_for 'T1111: turret position 11, corrector 11' 5
    screen | grep -Eq 'DEC3|G59|M48' && fail "INFO shows the NUM's functions"
    # The program turns X27000 with T1 and X-28000 with T11 (radii): the
    # micrometer reads what the correctors promise.
    cmd ":load 360"
    cmd ":mode auto"
    keys F9
    wait_for '^ AUTO .*END' 20
    cmd ":measure dia Z-10"
    wait_for 'micrometer: dia Z-10 = 54.000' 5
    cmd ":measure dia Z-25"
    # (the jog stops on the contact to the micrometre: 1 µm either way)
    wait_for 'micrometer: dia Z-25 = (55.999|56.000|56.001)' 5
    # The witness is kept with the machine's state.
    cmd ":quit!"
    next_server
    start --machine cazeneuve
    cmd ":witness"
    expect_message 'witness cut: .58.000, face at Z 0.000'
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
exit 0
