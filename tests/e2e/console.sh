#!/usr/bin/env bash
# End-to-end tests of the real console in tmux: a private tmux server (-L),
# no tmux configuration (-f /dev/null), a fixed 80x24 window, an isolated
# HOME and XDG directories, LANG=C.UTF-8. Every wait polls the screen with a
# timeout; a failure prints the screen.
#   console.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"

case $case in
start)
    start
    wait_for '^ AUTO '
    wait_for 'OP  program position'
    wait_for '1HELP +2OP/OM +3PRG/GR'
    keys F1
    wait_for 'HELP  keys and commands'
    keys F6
    wait_for '%300'
    # The two demos tell themselves apart on DIR by their titles (issue 38).
    wait_for '^[* ] %300 .*LATHE DEMO: TURNING WITH G02 G03'
    wait_for '^[* ] %301 .*MILL DEMO: G02 G03 IN THE G19 PLANE'
    # Tab completes a command on the readline input line.
    keys -l ":mo"
    keys Tab
    wait_for '^> :mode$'
    ;;
gauge_pending)
    # Issue 38: after T1 D1 M6 in IMD the gauge is chosen, not applied: OP
    # and INFO show the position without it and say so, as PREF does; the
    # note goes axis by axis as they move; in French too.
    pending() {
        start
        cmd ":set D1.X=63.345"
        cmd ":set D1.Z=38.237"
        cmd ":mode pom"
        keys F9
        wait_for '^ POM .*(READY|PRÊT)' 20
        cmd ":mode imd"
        cmd "T1 D1 M6"
        keys F9
        wait_for "$1" 10
    }
    pending 'IMD done'
    cmd ":page op"
    wait_for 'Tool +T1 +D1$'
    wait_for '^ {12}gauge on X Z not applied yet: at the next move or touch-off'
    sgr_line 'gauge on X Z not applied' | grep -q $'\e\\[' || fail "the note is not coloured"
    cmd ":page info"
    wait_for '^ gauge +X +[0-9.-]+ +Z +[0-9.-]+ *$'
    wait_for '^ {12}gauge on X Z not applied yet: at the next move or touch-off'
    cmd "G0 Z100"
    keys F9
    wait_for 'IMD done' 10
    wait_for '^ {12}gauge on X not applied yet'
    cmd "G0 X200"
    keys F9
    wait_for 'IMD done' 10
    cmd ":page op"
    sleep 0.3
    screen | grep -q 'not applied yet' && fail "the note stays after both axes moved"
    cmd ":quit"
    wait_for '^EXIT=0' 10
    next_server
    E2E_ENV="LANGUAGE= LANG=fr_FR.UTF-8" pending 'IMD terminé'
    cmd ":page op"
    wait_for 'jauge sur X Z non appliquée : au prochain mouvement ou tangentage'
    ;;
themes)
    start --theme mono --ascii
    wait_for '^- OP  program position'
    screen | LC_ALL=C grep -q '[^ -~]' && fail "--ascii drew a non-ASCII character"
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    start --theme phosphor
    wait_for 'OP  program position'
    cmd ":quit"
    wait_for '^EXIT=0'
    "$bin" --theme neon </dev/null >/dev/null 2>&1
    [ $? -eq 64 ] || fail "an unknown theme should exit with 64"
    "$bin" </dev/null >/dev/null 2>"$work/err"
    [ $? -eq 66 ] && grep -q 'needs a terminal' "$work/err" || fail "no terminal: exit 66 with a message"
    ;;
crash)
    # A crash signal: the terminal is restored before the default action.
    start
    # This test's own console, not another test's running at the same time.
    pid=$(pgrep -P "$(T list-panes -t e2e -F '#{pane_pid}')" -f "$bin" -n)
    kill -SEGV "$pid"
    wait_for '^EXIT=139' 10
    wait_for 'crashed; the terminal is restored'
    stty_after
    grep -Eq '(^| )icanon' "$work/stty" && grep -Eq '(^| )echo ' "$work/stty" ||
        fail "the terminal is not restored after SIGSEGV"
    ;;
imd)
    start
    pom
    cmd ":mode imd"
    keys -l "G0 X40 Z25"
    wait_for '^IMD> G0 X40 Z25'
    keys Enter
    keys F9
    wait_for '^ IMD .*END' 20
    cmd ":page op"
    wait_for 'OP  program position'
    [ "$(op_value X)" = "40.000" ] || fail "X should read 40.000"
    [ "$(op_value Z)" = "25.000" ] || fail "Z should read 25.000"
    ;;
auto)
    start
    pom
    cmd ":load 300"
    cmd ":mode auto"
    cmd ":speed x10"
    keys F9
    wait_for 'CYCLE'
    wait_for 'M02: end of program %300' 30
    [ "$(op_value X)" = "150.000" ] || fail "the final X should read 150.000"
    [ "$(op_value Z)" = "200.000" ] || fail "the final Z should read 200.000"
    ;;
seq)
    start
    pom
    cmd ":load 300"
    cmd ":mode seq"
    keys F9
    wait_for '^ SEQ +%300 N10 +BLOCK' 20
    keys F9
    wait_for '^ SEQ +%300 N20 +BLOCK' 20
    keys F9
    wait_for '^ SEQ +%300 N30 +BLOCK' 20
    ;;
plan_feed)
    # Issue 35: the animation follows the plan. On a mill whose X accelerates
    # at 5 mm/s² a move at F300 (5 mm/s) takes 1 s to reach its feed: at x1
    # the OP page's feed now is below F as the move starts and at F in the
    # middle; the M02 message's cycle time is the one `run` prints.
    sed 's/^accel.X = .*/accel.X = 5/' "$(dirname "$0")/../../data/machines/mill.machine" \
        > "$work/slow.machine"
    printf '%%1\nG0 G9 X0 Y0 Z100\nG1 X30 F300\nM2\n' > "$work/slow.iso"
    "$bin" import "$work/slow.iso" >/dev/null || fail "import of the program"
    start --machine "$work/slow.machine"
    pom
    cmd ":load 1"
    cmd ":mode auto"
    keys F9
    wait_for 'at %1 line 3' 20
    # The feed now as the coloured screen shows it (capture-pane -e).
    feed_now() { sgr_line 'mm/min now' | sed 's/\x1b\[[0-9;]*m//g' | awk '{ print $2 }'; }
    f=$(feed_now)
    [ -n "$f" ] && [ "$f" -lt 300 ] || fail "feed now at the start of the move: '$f', not below F300"
    sleep 2
    wait_for 'at %1 line 3'
    f=$(feed_now)
    [ "$f" = 300 ] || fail "feed now in the middle of the move: '$f', not F300"
    wait_for 'M02: end of program %1' 20
    console=$(message | grep -o 'cycle time [0-9]* min [0-9.]* s')
    batch=$("$bin" run --machine "$work/slow.machine" "$work/slow.iso" | grep -o 'cycle time [^;]*')
    secs=$(echo "$console" | awk '{ printf "%.1f", $3 * 60 + $5 }')
    run_secs=$(echo "$batch" | sed 's/.*(\([0-9.]*\) s.*/\1/' | awk '{ printf "%.1f", $1 }')
    [ -n "$secs" ] && [ "$secs" = "$run_secs" ] ||
        fail "console: $console ($secs s); run: $batch ($run_secs s)"
    ;;
hold)
    start
    pom
    cmd ":load 300"
    cmd ":mode auto"
    keys F9
    wait_for 'N80 .*CYCLE' 30
    keys F10
    wait_for 'HOLD'
    a=$(op_value Z)
    sleep 1
    b=$(op_value Z)
    [ "$a" = "$b" ] || fail "Z moved during the feed hold ($a -> $b)"
    keys F9
    wait_for 'CYCLE'
    cmd ":speed max"
    wait_for 'M02: end of program' 30
    ;;
alarm)
    start
    cmd ":mode imd"
    cmd "G2 X10 Z0 R2"
    keys F9
    wait_for 'ALARM 107' 10
    keys F7
    wait_for '^ ALARM 107 +IMD line 1'
    keys F12
    wait_for 'IMD .*READY'
    ;;
resize)
    start
    T resize-window -t e2e -x 120 -y 40
    sleep 0.3
    [ "$(screen | wc -l)" -eq 40 ] || fail "the screen should have 40 lines"
    screen | tail -n 1 | grep -q '^1HELP' || fail "the soft keys should be on the last line"
    T resize-window -t e2e -x 80 -y 24
    sleep 0.3
    screen | sed -n 24p | grep -q '^1HELP' || fail "the soft keys should be on line 24"
    T resize-window -t e2e -x 60 -y 20
    wait_for 'needs at least 80x24'
    ;;
quit)
    start
    keys C-c
    wait_for '^EXIT=0' 10
    sleep 0.2
    stty_after
    grep -Eq '(^| )icanon' "$work/stty" && grep -Eq '(^| )echo ' "$work/stty" ||
        fail "the terminal is not restored: $(cat "$work/stty")"
    next_server
    start
    cmd ":quit"
    wait_for '^EXIT=0' 10
    ;;
signal)
    start
    # This test's own console, not another test's running at the same time.
    pid=$(pgrep -P "$(T list-panes -t e2e -F '#{pane_pid}')" -f "$bin" -n)
    [ -n "$pid" ] || fail "no pupitre process"
    kill -TERM "$pid"
    wait_for '^EXIT=0' 10
    stty_after
    grep -Eq '(^| )icanon' "$work/stty" || fail "the terminal is not restored after SIGTERM"
    ;;
history)
    # An IMD block typed in one session is in the input line's history of the next.
    start
    cmd ":mode imd"
    cmd "G0 X12 Z34"
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    start
    cmd ":mode imd"
    keys Up Up  # the newest line is ':mode imd' itself
    wait_for '^IMD> G0 X12 Z34'
    ;;
setting)
    # A gauge set, the tool moved, touch-off on Z0 and a diameter; after a
    # restart the values are there; then a tool measured on a touched diameter.
    start
    pom
    cmd ":set D1.X=63.345"
    cmd ":set D1.Z=38.237"
    cmd ":mode imd"
    cmd "T1 D1 M6"
    keys F9
    wait_for '^ IMD .*END' 10
    cmd ":mode jog"
    cmd ":jog Z -100"
    cmd ":jog X -80"
    wait_for 'READY'
    cmd ":page pref"
    cmd "Z 0"
    wait_for 'PREF.Z = OM 100.000 .* = 61.763'
    cmd "X 59.978"
    wait_for 'PREF.X \(radius\) = OM ø220.000/2 .* = 16.666'
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    start
    cmd ":page pref"
    wait_for '^  Z +61.763 '
    wait_for '^  X +16.666 '
    cmd ":page corr"
    wait_for '^  1 +63.345 +38.237 '
    cmd "D2"
    cmd "X 100"
    # D2 is not the active corrector (D0 after the restart): asked first.
    wait_for 'D2 is not the active corrector \(D0\)'
    cmd "y"
    wait_for 'D2.X \(radius\) = OM ø300.000/2 - PREF 16.666 .* = 83.334'
    wait_for '^  2 +83.334 '
    ;;
french)
    # The console in French (issue 20), as a student in a French lab finds it:
    # LANG and LC_NUMERIC French, no French locale needed. Home, a tool by
    # IMD, a touch-off typed with a decimal comma, an alarm with the manual's
    # own text, the help page; the colours still reach the screen; numbers
    # keep the decimal point. Then --lang en wins over the environment, and
    # --ascii keeps the letters of accented words.
    E2E_ENV="LANGUAGE= LANG=fr_FR.UTF-8 LC_NUMERIC=fr_FR.UTF-8" start
    wait_for 'OP  position programme'
    wait_for '1AIDE +2OP/OM'
    wait_for 'F1 aide, F6 programmes, F8 mode, F9 Départ cycle'
    cmd ":set D1.X=63.345"
    cmd ":set D1.Z=38.237"
    cmd ":mode pom"
    keys F9
    wait_for '^ POM .*PRÊT' 20
    wait_for 'POM faite'
    cmd ":mode imd"
    cmd "T1 D1 M6"
    keys F9
    wait_for '^ IMD .*FIN' 10
    wait_for 'IMD terminé \(1 bloc\)'
    cmd ":mode jog"
    cmd ":jog Z -100"
    cmd ":jog X -80"
    wait_for '^ JOG .*PRÊT' 20
    cmd ":page pref"
    wait_for 'PREF  origines'
    wait_for 'correcteur actif D1, outil T1'
    cmd "Z 0"
    wait_for 'PREF.Z = OM 100.000 - jauge 38.237 - surface 0.000 = 61.763'
    cmd "X 59,978"
    wait_for 'X 59,978 lu comme 59.978'
    wait_for 'PREF.X \(rayon\) = OM ø220.000/2 - jauge 63.345 - surface ø59.978/2'
    wait_for '^ +(= )?16.666 \(avant 0.000\)'
    status=$(screen_e | head -1)
    [[ $status == *'[37m'*'[44m'* || $status == *'37;44'* ]] || fail "the status line is not white on blue: $status"
    cmd ":page op"
    wait_for 'OP  position programme'
    [ "$(op_value X)" = "59.978" ] || fail "after the touch-off X should read 59.978"
    [ "$(op_value Z)" = "0.000" ] || fail "after the touch-off Z should read 0.000"
    cmd ":mode imd"
    cmd "G2 X10 Z0 R2"
    keys F9
    wait_for 'ALARME 107' 10
    row=$(sgr_line 'ALARME 107')
    [[ $row == *'[41m'* ]] || fail "the alarm is not on red: $row"
    keys F7
    wait_for 'ALARME  1 depuis la mise sous tension'
    wait_for 'PGP : cercle défini par rayon'
    keys F12
    keys F1
    wait_for 'AIDE  touches et commandes'
    wait_for 'Premiers pas'
    screen | grep -q 'Cycle Start' && fail "the help page still says Cycle Start in French"
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    E2E_ENV="LANGUAGE= LANG=fr_FR.UTF-8" start --lang en
    wait_for 'OP  program position'
    wait_for '1HELP +2OP/OM'
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    E2E_ENV="LANGUAGE=fr LANG=C.UTF-8" start --ascii
    wait_for '^ AUTO .* PRET '
    wait_for '9DEPART'
    screen | LC_ALL=C grep -q '[^ -~]' && fail "--ascii drew a non-ASCII character in French"
    cmd ":quit"
    wait_for '^EXIT=0'
    ;;
edit)
    # A program typed in the editor, saved with an error: the cursor stands on
    # the faulty block with its NUM number; corrected, saved, in the store.
    start --machine mill
    cmd ":edit 778"
    wait_for 'EDIT  %778  new'
    cmd "N10 G0 X10 Y10 Z5"
    cmd "N20 G1 Z-2 F100 (NO END"
    cmd "N30 M2"
    cmd ":save"
    wait_for 'line 3 N20: error 17'
    wait_for '^    3 >N20 G1 Z-2 F100 \(NO END'
    keys Enter
    wait_for '^MODIFY> N20 G1 Z-2 F100 \(NO END'
    keys -l ")"
    keys Enter
    cmd ":save"
    wait_for '%778 saved as revision 1'
    cmd ":quit"
    wait_for '^EXIT=0'
    "$bin" export 778 | grep -q '^N20 G1 Z-2 F100 (NO END)$' || fail "the store does not hold the corrected block"
    ;;
modif)
    # Single block, MODIF on the next block, Cycle Start runs the new text.
    "$bin" import "$(dirname "$0")/../console/programs/gauge_change.iso" >/dev/null || fail "import"
    start
    pom
    cmd ":load 950"
    cmd ":mode seq"
    for n in 10 20 30 40; do
        keys F9
        wait_for "^ SEQ +%950 N$n +BLOCK" 20
    done
    cmd ":mode modif"
    wait_for 'MODIF  %950'
    wait_for '^    6 >N50 G0 X50'
    keys Enter
    keys C-u
    cmd "N50 G0 X56"
    wait_for '^    6 >N50 G0 X56'
    keys F9
    wait_for '^ SEQ +%950 N50 +BLOCK' 20
    cmd ":page op"
    [ "$(op_value X)" = "56.000" ] || fail "the changed block should have moved X to 56"
    ;;
g76)
    # A program that writes a program: the new %761 runs, shows in DIR and is
    # in the store after the session, its revision named after G76.
    "$bin" import "$(dirname "$0")/../console/programs/g76_writes.iso" >/dev/null || fail "import"
    start --machine mill
    pom
    cmd ":load 760"
    cmd ":mode auto"
    keys F9
    wait_for '^ AUTO +%760 .*END' 20
    cmd ":page op"
    [ "$(op_value X)" = "42.500" ] || fail "%761 should have moved X to 42.5"
    keys F6
    wait_for '%761'
    cmd ":quit"
    wait_for '^EXIT=0'
    "$bin" export 761 | grep -q '^N10 G0 X42.5 Y5 Z10$' || fail "the store does not hold %761"
    "$bin" history 761 | grep -q 'G76 in %760' || fail "the revision does not name G76"
    ;;
long)
    # A program of a million lines (CAM output): TEST runs it while the pages
    # answer, and PROG numbers its lines in full (they were cut to 6 digits).
    awk 'BEGIN { print "%1"; for (i = 2; i <= 1000011; i++) printf "G1 X%d F1000 (L%d)\n", i % 97, i; print "M2" }' \
        > "$work/long.iso"
    "$bin" import "$work/long.iso" >/dev/null || fail "import of the long program"
    start
    pom
    cmd ":load 1"
    cmd ":mode test"
    keys F9
    wait_for '^ TEST +%1 line [0-9]+ +CYCLE' 10
    keys F3
    wait_for 'PROG  %1'
    wait_for 'TEST %1: no error' 60
    wait_for '^1000008 +G1 X[0-9]+ F1000 \(L1000008\)'
    ;;
graph)
    # The toolpath drawn in braille: after TEST, zoomed, then live in AUTO
    # with the tool marker moving.
    start
    pom
    cmd ":load 300"
    cmd ":mode test"
    keys F9
    wait_for 'TEST %300: no error'
    keys M-g
    wait_for 'GRAPH  ZX'
    screen | LC_ALL=C.UTF-8 grep -qP '[\x{2801}-\x{28ff}]' || fail "no braille cell on the graphic page"
    before=$(screen | LC_ALL=C.UTF-8 grep -cP '[\x{2801}-\x{28ff}]')
    keys +
    wait_for 'mm'
    cmd ":mode auto"
    cmd ":speed x1"
    keys F9
    wait_for '◆' 20
    a=$(screen | grep -n '◆' | head -1)
    sleep 2
    b=$(screen | grep -n '◆' | head -1)
    [ -n "$a" ] && [ "$a" != "$b" ] || fail "the tool marker did not move ($a / $b)"
    [ "$before" -gt 3 ] || fail "too few braille rows ($before)"
    ;;
cycle_time)
    # Issue 38: one cycle time everywhere. The lathe demo takes 38.037 s
    # with its tool change and the machine's accelerations (the batch
    # summary's 0:00:38; 35.778 s at the feeds alone, which the console
    # showed before it followed the plan, issue 35): the M02 message, the OP
    # page's run line and the GRAPH title say the same, and so do TEST's
    # message and title. The GRAPH title left the tool change out (0:00:33
    # at the feeds alone).
    W=100 start
    pom
    cmd ":load 300"
    cmd ":speed max"
    cmd ":mode auto"
    keys F9
    wait_for 'M02: end of program %300, 12 blocks, cycle time 0 min 38.0 s' 30
    wait_for 'Run +12 blocks +cycle time 38.0 s'
    keys M-g
    wait_for 'GRAPH .* 7 moves +0:00:38'
    cmd ":mode test"
    keys F9
    wait_for 'TEST %300: no error, 12 blocks, 0 warnings, cycle time 0 min 38.0 s' 20
    wait_for 'GRAPH .* 7 moves +0:00:38'
    ;;
warnings)
    # Issue 19: a warning printed during a run is not lost with M02: the end
    # message counts it and the ALARM page lists it with its block.
    "$bin" import "$(dirname "$0")/../warn/1110_feed_before_f.iso" >/dev/null || fail "import"
    W=100 start
    pom
    cmd ":load 10"
    cmd ":mode auto"
    cmd ":speed x10"
    keys F9
    wait_for 'M02: end of program %10, .*; 1 warning \(F7 ALARM\)' 30
    keys F7
    wait_for 'Warnings of the last run \(1\)'
    wait_for '1110  %10 line 6 N30'
    wait_for 'feed move before any F: it runs at F1000.000 mm/min'
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
echo "ok ($case)"
