#!/usr/bin/env bash
# End-to-end tests of issue 38 ("what a student and a newcomer found") on the
# real console in tmux, by keys: work that could still be lost, the program
# selected after a kill, a signal over unsaved work, and a console that
# guides. Same harness as console.sh (tests/e2e/lib.sh).
#   newcomer.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"

journal() { cat "$XDG_DATA_HOME/pupitre/pupitre.db.recover/$1.iso" 2>/dev/null; }
console_pid() { pgrep -P "$(T list-panes -t e2e -F '#{pane_pid}')" -f "$bin" -n; }

case $case in
edit_again)
    # Item 5: :edit 500 again over unsaved work asks; n keeps it, and the
    # journal holds both blocks.
    start
    cmd ":edit 500"
    cmd "N50 M2 (IMPORTANT WORK)"
    wait_for 'IMPORTANT WORK'
    cmd ":edit 500"
    wait_for 'load the stored text and drop them\? y/n'
    keys n
    wait_for 'cancelled: nothing changed'
    cmd "N60 M5"
    wait_for 'N60 M5'
    journal 500 | grep -q 'IMPORTANT WORK' || fail "the journal lost N50: $(journal 500)"
    journal 500 | grep -q 'N60 M5' || fail "the journal lacks N60: $(journal 500)"
    ;;
selected)
    # Item 6: the program selected survives a kill -9.
    start
    cmd ":load 300"
    wait_for '%300 selected'
    kill -KILL "$(console_pid)"
    wait_for 'EXIT=137'
    next_server
    start
    wait_for '^ [A-Z ]+ +%300 '
    ;;
sigterm)
    # Item 7: SIGTERM over unsaved work: 143, and stderr names the journal.
    start
    cmd ":edit 500"
    cmd "N50 M2"
    wait_for 'not saved'
    kill -TERM "$(console_pid)"
    wait_for '^EXIT=143' 10
    wait_for 'SIGTERM: the unsaved changes of %500 are in the recovery journal'
    ;;
wrong_page)
    # Item 12: an IMD block typed on CORR is refused there.
    start
    cmd ":mode imd"
    cmd ":page corr"
    cmd "T1 D1 M6 S500 M3"
    expect_message 'ISO blocks are typed in IMD on the OP page \(F2\), not here'
    ;;
answer)
    # Item 13: y alone answers; F2 cancels a question.
    start
    cmd ":page pref"
    cmd "Z 0"
    wait_for '^y/n>'
    keys F2
    expect_message 'question cancelled: the page changed'
    screen | grep -q '^y/n>' && fail "the question stayed after F2"
    cmd ":page pref"
    cmd "Z 0"
    wait_for '^y/n>'
    keys y
    wait_for 'PREF.Z = OM'
    ;;
small)
    # Item 14: at 60x20 F9 in AUTO starts nothing; :quit quits.
    start
    pom
    cmd ":load 300"
    cmd ":mode auto"
    T resize-window -t e2e -x 60 -y 20
    wait_for 'Terminal too small'
    keys F9
    sleep 0.5
    T resize-window -t e2e -x 80 -y 24
    wait_for '^ AUTO +%300 '
    screen | grep -Eq '^ AUTO .*(CYCLE|END)' && fail "F9 started %300 on the too small screen"
    T resize-window -t e2e -x 60 -y 20
    wait_for 'Terminal too small'
    keys -l ":quit"
    wait_for '^> :quit'
    keys Enter
    wait_for '^EXIT=0'
    ;;
long_imd)
    # Item 15: a paste of 5,499 characters is refused at Enter.
    start
    pom
    cmd ":mode imd"
    keys -l "G0 X10 ($(printf 'A%.0s' $(seq 5490)))"
    keys Enter
    expect_message 'error 1: block longer than 117 characters'
    keys F9
    sleep 0.3
    screen | grep -q 'ALARM [0-9]' && fail "Cycle Start raised an alarm"
    ;;
header)
    # Item 18: %500 (TEST) typed in a new %500 is its header.
    start
    cmd ":edit 500"
    cmd "%500 (TEST)"
    cmd "N10 M2"
    cmd ":save"
    expect_message '%500 saved as revision 1'
    "$bin" export 500 | head -1 | grep -qx '%500 (TEST)' || fail "the header was not kept"
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
echo "ok ($case)"
