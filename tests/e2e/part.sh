#!/usr/bin/env bash
# The PART page in the real console (issue 36), driven by keys in tmux: the
# part drawn in colour as cells (capture-pane -e), its keys, the cells in a
# terminal that takes no pictures (tmux answers the console's DA1 query but
# not the kitty one), mono and ASCII, and paper after :submit only.
#   part.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"
W=100 H=30

# The shipped lathe's truth as the operator's values, then %12 run to M02.
turned() {
    "$bin" import "$(dirname "$0")/programs/part_turn.iso" >/dev/null || fail "import"
    start "$@"
    pom
    cmd ":setup lathe"
    for v in PREF.X=-20 PREF.Z=35 D1.X=52.347 D1.Z=41.215; do cmd ":set $v"; done
    cmd ":speed max"
    cmd ":load 12"
    cmd ":mode auto"
    keys F9
    wait_for 'M02: end of program %12' 30
}

# The picture's rows: under the page's title, over its lines and the screen's
# last three.
picture() { screen | sed -n "3,$((H - 8))p"; }
picture_e() { screen_e | sed -n "3,$((H - 8))p"; }

case $case in
colour)
    # 256 colours: the cells carry the palette's colours; 8 (TERM=screen):
    # the ANSI ones.
    E2E_ENV="TERM=tmux-256color" turned
    keys M-v
    wait_for 'PART  section  painted by depth of cut'
    wait_for 'depth below the stock: 0 … 5 mm'
    n=$(picture_e | grep -o $'\e\[[0-9;]*48;5;[0-9]*m' | wc -l)
    [ "$n" -gt 50 ] || fail "the picture should be drawn in 256 colours (got $n backgrounds)"
    picture | grep -q '[▀▄█▌▐▖▗▘▙▚▛▜▝▞▟▁▂▃▅▆▇▉▊▋▍▎▏]' || fail "the picture should be drawn in block symbols"
    wait_for 'stick-out 95.00 mm'
    next_server
    turned
    cmd ":part"
    wait_for 'PART  section'
    n=$(picture_e | grep -oE $'\e\\[[0-9;]*4[0-7]m' | wc -l)
    [ "$n" -gt 20 ] || fail "TERM=screen: the picture should be drawn in its 8 colours (got $n)"
    ;;
keys)
    start --machine mill
    pom
    cmd ":setup mill"
    cmd ":part"
    wait_for 'PART  3d turned 60° tilted 35°'
    keys Right
    wait_for 'PART  3d turned 75° tilted 35°'
    keys Up
    wait_for 'PART  3d turned 75° tilted 45°'
    expect_message 'turned 75°, tilted 45°'
    keys +
    wait_for 'tilted 45° x1.5'
    keys S-Left
    keys f
    wait_for 'PART  3d turned 60° tilted 35°  painted'
    keys v
    wait_for 'PART  top  painted by depth of cut'
    keys Right
    expect_message 'the 3-D view turns and tilts'
    keys c
    expect_message 'there is no drawing'
    ;;
cells)
    # The console asked tmux for the kitty protocol and sixel: tmux answers
    # DA1 only, so the picture is cells, and nothing of the queries or of an
    # image shows.
    start
    cmd ":setup lathe"
    cmd ":part"
    wait_for 'PART  section'
    [ "$(picture | grep -c '[^ ]')" -gt 5 ] || fail "the picture should be cells"
    screen | grep -qE 'Gi=|_G|\[16t|\[\?1;2c|AAAA' && fail "a query or its answer shows"
    screen_e | grep -q $'\e_G' && fail "an image was sent to tmux"
    ;;
mono)
    start --theme mono
    cmd ":setup lathe"
    cmd ":part"
    wait_for 'PART  section'
    [ "$(picture | grep -c '[^ ]')" -gt 5 ] || fail "mono: the picture should be symbols"
    picture_e | grep -qE $'\e\\[[0-9;]*(3[0-7]|4[0-7]|38;5|48;5)' &&
        fail "mono: the picture should have no colour"
    next_server
    start --ascii
    cmd ":setup lathe"
    cmd ":part"
    wait_for 'PART  section'
    [ "$(picture | grep -c '[^ ]')" -gt 5 ] || fail "ascii: the picture should be symbols"
    picture | LC_ALL=C grep -q $'[\x80-\xff]' && fail "ascii: only ASCII symbols"
    ;;
paper)
    # An exercise: no paper before :submit; after it, a PDF.
    start exercise lathe-first --student eve
    cmd ":part export $work/before.pdf"
    expect_message ':part export: not during an exercise'
    [ -e "$work/before.pdf" ] && fail "a PDF before :submit"
    cmd ":submit"
    expect_message 'submitted'
    cmd ":part export $work/after.pdf"
    expect_message "the part written to $work/after.pdf"
    head -c 5 "$work/after.pdf" | grep -q '%PDF-' || fail "after.pdf is no PDF"
    cmd ":part"
    wait_for 'deviation from exercise lathe-first'
    wait_for 'dia Z-10: 60.000 \(40 ±0.02\), \+20000 µm, over'
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
echo ok
