#!/usr/bin/env bash
# End-to-end tests of issue 12 ("setting you can trust") on the real console
# in tmux: one corrector everywhere after a program run, colours that reach the
# screen, an input line that says where text goes, decimal commas and
# implausible settings. Same harness as console.sh (tests/e2e/lib.sh).
#   trust.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"

# tool1: T1 D1 in the turret by IMD, Cycle Start, wait for its end.
tool1() {
    cmd ":mode imd"
    cmd "T1 D1 M6"
    keys F9
    wait_for '^ IMD .*END' 10
}

case $case in
gauge)
    # The issue's sequence: a gauge, POM, T1 D1, %300 to M02, then touch-off.
    # M02 leaves D0 (T kept): every page says D0 and applies no gauge, the
    # touch-off asks first (no corrector), and OP reads what was typed.
    start
    cmd ":set D1.X=10"
    pom
    tool1
    cmd ":load 300"
    cmd ":mode auto"
    cmd ":speed max"
    keys F9
    wait_for 'M02: end of program %300' 30
    cmd ":page op"
    wait_for '^  Tool +T1  D0'
    cmd ":page info"
    wait_for 'T1 .*D0'
    wait_for '^ gauge +X +0\.000'
    cmd ":page pref"
    wait_for 'active corrector D0, tool T1'
    cmd "X 150"
    wait_for "D0, no tool gauge \\(T1\\)"
    wait_for '^y/n>'
    cmd "y"
    wait_for 'PREF.X \(radius\) = OM ø'
    cmd "Z 0"
    cmd "y"
    wait_for 'PREF.Z = OM '
    cmd ":page op"
    wait_for 'OP  program position'
    [ "$(op_value X)" = "150.000" ] || fail "after touch-off X 150 the OP page should read 150.000"
    [ "$(op_value Z)" = "0.000" ] || fail "after touch-off Z 0 the OP page should read 0.000"
    # With the tool's corrector selected again (no move yet: its gauge is
    # pending), the touch-off applies the gauge and OP still reads the value.
    tool1
    cmd ":page pref"
    wait_for 'active corrector D1, tool T1; its gauge on X applies at the next move'
    cmd "X 120"
    wait_for 'PREF.X \(radius\) = OM ø.* - gauge 10.000 - surface ø120.000/2'
    cmd ":page op"
    wait_for '^  Tool +T1  D1'
    [ "$(op_value X)" = "120.000" ] || fail "after touch-off X 120 with D1 the OP page should read 120.000"
    # RAZ: D0 again, and OP shows the point without the gauge (20 mm more on
    # the diameter: the 10 mm radius gauge).
    keys F12
    wait_for '^  Tool +T1  D0'
    [ "$(op_value X)" = "140.000" ] || fail "after RAZ (D0) X should read 140.000"
    ;;
colours)
    # Each style of the colour theme reaches the screen as SGR sequences.
    start
    status=$(screen_e | head -1)
    [[ $status == *'[37m'*'[44m'* || $status == *'37;44'* ]] || fail "the status line is not white on blue: $status"
    soft=$(screen_e | tail -1)
    [[ $soft == *'[30m'*'[46m'* || $soft == *'30;46'* ]] || fail "the soft keys are not black on cyan: $soft"
    # The soft key of the page on screen (F2, OP) stands out: white on blue.
    [[ $soft == *'44m2OP/OM'* || $soft == *'44m'*'OP/OM'* ]] || fail "F2 should stand out on the OP page: $soft"
    title=$(sgr_line 'OP  program position')
    [[ $title == *'[1m'* ]] || fail "the page title is not bold: $title"
    cmd ":page dir"
    wait_for '%300'
    row=$(sgr_line '%300')
    [[ $row == *'[46m'* ]] || fail "the DIR cursor row is not highlighted: $row"
    cmd ":page corr"
    row=$(sgr_line '^.{0,20}  1 ')
    [[ $row == *'[46m'* ]] || fail "the CORR cursor row is not highlighted: $row"
    cmd ":page op"
    cmd ":mode imd"
    cmd "G2 X10 Z0 R2"
    keys F9
    wait_for 'ALARM 107' 10
    row=$(sgr_line 'ALARM 107')
    [[ $row == *'[41m'* ]] || fail "the alarm is not on red: $row"
    cmd ":quit"
    wait_for '^EXIT=0'
    # Phosphor: green on black.
    next_server
    start --theme phosphor
    [[ $(screen_e) == *'[32m'* ]] || fail "phosphor shows no green"
    cmd ":quit"
    wait_for '^EXIT=0'
    # NO_COLOR (no-color.org): mono, bold and reverse only, unless --theme.
    next_server
    E2E_ENV="NO_COLOR=1" start
    s=$(screen_e)
    grep -Eq $'\e\\[[0-9;]*(3[0-7]|4[0-7])m' <<<"$s" && fail "NO_COLOR: colours reached the screen"
    [[ $s == *'[7m'* ]] || fail "NO_COLOR: the status line should be in reverse video"
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    E2E_ENV="NO_COLOR=1" start --theme colour
    [[ $(screen_e) == *'[44m'* ]] || fail "--theme colour should win over NO_COLOR"
    ;;
target)
    # The prompt names where text goes, and it goes there; a refused entry
    # drops the IMD block typed before, so Cycle Start cannot run it.
    start
    pom
    cmd ":mode imd"
    wait_for '^IMD>'
    cmd ":page pref"
    wait_for '^PREF>'
    cmd ":page corr"
    wait_for '^D1>'
    cmd "D5"
    wait_for '^D5>'
    cmd ":page param"
    wait_for '^L/E='
    cmd ":page op"
    wait_for '^IMD>'
    cmd "G0 X40 Z25"
    wait_for 'Cycle Start \(F9\) executes: G0 X40 Z25'
    cmd ":page pref"
    cmd "G0 X10"
    wait_for '^ IMD block dropped: ISO blocks are typed in IMD on the OP page'
    keys F9
    wait_for 'IMD: type a block first'
    cmd ":page op"
    [ "$(op_value X)" = "300.000" ] || fail "the dropped IMD block moved X"
    cmd ":page edit"
    wait_for '^EDIT>'
    ;;
plausible)
    # A decimal comma is read and echoed; a negative radius is refused; a
    # gauge longer than the travel and a measurement of a corrector that is
    # not the active one ask first; :measure never asks.
    start
    pom
    tool1
    cmd ":page pref"
    cmd "Z 1,5"
    wait_for 'read Z 1,5 as 1.500'
    cmd ":page op"
    [ "$(op_value Z)" = "1.500" ] || fail "Z 1,5 should make OP read 1.500"
    cmd ":page corr"
    cmd "R=-0,4"
    wait_for 'never negative'
    cmd "X=99999"
    wait_for 'longer than the X travel'
    wait_for '^y/n>'
    cmd "n"
    wait_for 'cancelled: nothing changed'
    wait_for '^  1 +0\.000 '
    cmd "D5"
    cmd "X 100"
    wait_for 'D5 is not the active corrector \(D1\)'
    cmd "y"
    wait_for 'D5.X \(radius\) = OM ø'
    cmd ":measure D6 X 100"
    wait_for 'D6.X \(radius\) = OM ø'
    ;;
guide)
    # First contact: the mode key says what comes next and what to do; the
    # OP page keeps the jog keys and the INC step; unbound keys never leak
    # into the input line; Escape empties it; HELP starts with "Getting
    # started"; below 80x24 a "Terminal too small" screen, gone after.
    start
    wait_for '^ AUTO .*F8→SEQ'
    wait_for '^  AUTO +home first: F8 to POM'
    for i in 1 2 3 4 5 6 7 8; do keys F8; done
    wait_for 'POM: homing; Cycle Start \(F9\) homes the axes'
    wait_for '^ POM .*F8→AUTO'
    keys F9
    wait_for 'POM done: every axis is homed' 20
    cmd ":mode inc"
    wait_for '^  INC +Left Z-, Right Z\+, Up X\+, Down X-'
    wait_for 'step 1\.000 mm \(Alt-i: next step\)'
    cmd ":mode imd"
    for k in F11 S-F1 C-F5 M-F9; do keys $k; done
    wait_for 'M-F9 does nothing here'
    keys -l "G0 X1"
    wait_for '^IMD> G0 X1$'
    keys Escape
    wait_for 'input cancelled'
    screen | grep -q '^IMD> *$' || fail "Escape should empty the input line"
    keys -l "G0 X2"
    wait_for '^IMD> G0 X2$'
    keys F1
    wait_for '^ Getting started'
    wait_for '1\. Home: F8 until the status line shows POM'
    T resize-window -t e2e -x 60 -y 20
    wait_for 'Terminal too small'
    wait_for 'this terminal is 60x20'
    T resize-window -t e2e -x 160 -y 48
    wait_for '^ Getting started'
    screen | grep -q 'Terminal too small\|terminal is 60x20' && fail "the small-terminal text stayed after the resize"
    # At 160 columns the room is used: a step of "Getting started" on one line.
    screen | grep -Eq '^   2\. Jog: F8 to JOG, .* INC moves one step\.' ||
        fail "at 160 columns step 2 should fit on one line"
    ;;
stale)
    # Texts that must follow what happened: the status line after :load, one
    # IMD block counted once, jogs not counted as cycle time, the mill's INFO
    # page, :history on its own page, a CONFLICT revision marked on DIR.
    start
    pom
    cmd ":load 300"
    cmd ":mode auto"
    cmd ":speed max"
    keys F9
    wait_for 'M02: end of program %300'
    wait_for '^ AUTO +%300 N120 +END'
    cmd ":mode jog"
    cmd ":load 301"
    wait_for '%301 selected: F8 to AUTO \(or SEQ, DRY RUN, TEST\), then Cycle Start'
    cmd ":mode auto"
    wait_for '^ AUTO +%301 +READY'
    screen | grep -q 'N120' && fail "the status line kept N120 of %300 after :load 301"
    cmd ":mode imd"
    cmd "G0 X100"
    keys F9
    wait_for '^ IMD .*END'
    wait_for 'IMD done \(1 block\): type the next block'
    wait_for '^  Run +1 block +cycle time'
    cmd ":mode jog"
    for i in 1 2 3 4 5 6 7 8 9 10; do keys Left; done
    sleep 0.5
    wait_for '^  Run +1 block +cycle time 0\.[0-9] s'
    # :history gets a page; a save over a revision made meanwhile is a
    # conflict, marked on DIR.
    cmd ":edit 300"
    cmd "N999 G0 X10"
    printf '%%300 (FROM ELSEWHERE)\nN10 G0 X20\nN20 M02\n' >"$work/other.iso"
    "$bin" import "$work/other.iso" >/dev/null || fail "import from a shell failed"
    cmd ":save"
    wait_for 'conflict: .*:history 300'
    cmd ":history"
    wait_for '^─ HISTORY  %300 revisions'
    wait_for 'CONFLICT'
    cmd ":page dir"
    wait_for '%300 .*CONFLICT r[0-9]+ '
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    start --machine mill
    cmd ":page info"
    wait_for '^ Offsets$'
    ;;
journal)
    # kill -9 loses at most the line being typed: the journal brings the rest
    # back at the next start; :quit and Ctrl-C ask before dropping changes.
    start
    cmd ":edit 300"
    wait_for '^─ EDIT  %300'
    cmd "N5 G0 X111"
    wait_for 'N5 G0 X111'
    keys -l "N6 G0 X2"
    pid=$(pgrep -P "$(T list-panes -t e2e -F '#{pane_pid}')" -f "$bin" -n)
    kill -KILL "$pid"
    wait_for 'EXIT=137'
    next_server
    start
    wait_for 'unsaved work recovered for %300: :edit 300, then :recover'
    cmd ":edit 300"
    wait_for '%300 has unsaved changes from an earlier session: :recover'
    screen | grep -q 'N5 G0 X111' && fail ":edit should show the stored text until :recover"
    cmd ":recover"
    wait_for 'recovered text loaded'
    wait_for 'N5 G0 X111'
    # :quit and Ctrl-C ask; "n" keeps the console and the text.
    cmd ":quit"
    wait_for 'unsaved changes: quit and drop them'
    cmd "n"
    wait_for 'cancelled: nothing changed'
    keys C-c
    wait_for 'unsaved changes: quit and drop them'
    keys Escape
    wait_for 'cancelled: nothing changed'
    cmd ":save"
    wait_for '%300 saved as revision'
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    start
    screen | grep -q 'recovered' && fail "a saved program should leave no journal"
    cmd ":edit 300"
    cmd "N7 G0 X3"
    cmd ":quit!"
    wait_for '^EXIT=0'
    ;;
two)
    # Two consoles on one store (a classroom server): what one changes, the
    # other shows within a second or two; opening a program the other edits
    # says so.
    start
    start2
    wait2 'F1 help|1HELP'
    cmd2 ":page corr"
    wait2 '^─ CORR'
    cmd ":set D1.X=12.5"
    wait2 'another console changed: D1.X 12.5' 5
    wait2 '^  1 +12\.500 ' 5
    cmd ":set PREF.Z=-250"
    cmd2 ":page pref"
    wait2 '^  Z +-250\.000 ' 5
    # A program saved in one is the current text in the other.
    cmd ":edit 300"
    cmd2 ":edit 300"
    wait2 '%300 is open in another console' 5
    cmd "N1 (FROM CONSOLE A)"
    cmd ":save"
    wait_for '%300 saved as revision'
    wait2 'another console changed: %300 r2 \(open here' 5
    cmd2 ":close!"
    cmd2 ":page dir"
    wait2 '%300 +14 +2 +LATHE DEMO' 5
    cmd2 ":edit 300"
    wait2 'FROM CONSOLE A'
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
echo "ok ($case)"
