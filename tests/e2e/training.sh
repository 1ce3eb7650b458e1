#!/usr/bin/env bash
# Training in the real console (issue 16), driven by keys in tmux as a
# student would: seed 004's June 2005 exam done right (full marks) and with X
# taken as a diameter (the mistake named), the truth of a drawn exercise on
# no screen and in no file before :submit, the teacher's report after.
#   training.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
. "$(dirname "$0")/lib.sh"
W=110 H=40
export PUPITRE_CLASS_KEY=$work/class.key
db=$work/store.db
dbflag="--db $db"
# PUPITRE_E2E_DB: the same cases on another store (a PostgreSQL server's,
# from tests/e2e/server.sh), named to the console by PUPITRE_DB.
# On a server a student is their login: no --student (it is refused there),
# and the report names the login.
student_flag() { echo "--student $1"; }
student_name() { echo "$1"; }
if [ -n "${PUPITRE_E2E_DB:-}" ]; then
    db=$PUPITRE_E2E_DB dbflag=""
    export PUPITRE_DB=$db
    login=$(psql "$db" -qtAc "SELECT current_user")
    student_flag() { :; }
    student_name() { echo "$login"; }
fi

# A block run in IMD.
imd() {
    cmd ":mode imd"
    cmd "$1"
    keys F9
    wait_for 'IMD done' 10
}
# Homed, at full speed, T1 D1 in the turret.
homed_with_t1() {
    pom
    cmd ":speed max"
    imd "T1 D1 M6"
}

# The exam's six values typed on the PREF and CORR pages, PREF X as given.
exam() {
    local pref_x=$1
    start $dbflag exercise exam-2005 $(student_flag "$2")
    wait_for 'exam-2005: June 2005 exam'
    wait_for 'Measure 2: after a test cut'
    keys M-p
    wait_for 'PREF'
    for v in "PREF.X=$pref_x" "PREF.Z=-669.936" "DEC1.Z=257.267"; do
        keys -l "$v"
        keys Enter
        sleep 0.2
    done
    keys M-c
    for v in "X=63.345" "Z=38.237"; do
        keys -l "$v"
        keys Enter
        sleep 0.2
    done
    cmd ":submit"
}

case $case in
right)
    exam -135.477 alice
    wait_for 'submitted: 100%'
    wait_for 'Score 100%'
    wait_for 'PREF X = the spindle axis, as a tool point reads it = -135.477'
    wait_for 'DEC1 Z = the part.s face - the jaws. face = the stick-out = 257.267'
    # The right values on the ok colour (a green ground), on the EXERCISE page.
    sgr_line 'PREF.Z +-669.936' | grep -q $'\e\\[[0-9;]*42m' || fail "ok is not on green: $(sgr_line 'PREF.Z +-669.936' | cat -v)"
    cmd ":quit"
    stty_after
    next_server
    "$bin" --db "$db" class report exam-2005 > "$work/report" || fail "class report"
    grep -Eq "^exam-2005 +$(student_name alice) +1 +100 +100" "$work/report" || fail "report: $(cat "$work/report")"
    # A second start is a new attempt: the task again, not the report.
    start $dbflag exercise exam-2005 $(student_flag alice)
    wait_for 'Enter the six values'
    ;;
diameter)
    # PREF X = -22.143 - 63.345 - (59.978 + 20): the diameter where its half belongs.
    exam -165.466 bob
    wait_for 'submitted: 83%'
    wait_for 'X taken as a diameter instead of a radius'
    wait_for 'off by -29.989 mm, half the Ø59.978'
    sgr_line 'PREF.X +-165.466' | grep -q $'\e\\[[0-9;]*41m' || fail "WRONG is not on red: $(sgr_line 'PREF.X +-165.466' | cat -v)"
    cmd ":quit"
    stty_after
    next_server
    "$bin" --db "$db" class report > "$work/report" || fail "class report"
    grep -q 'X taken as a diameter instead of a radius' "$work/report" || fail "report: $(cat "$work/report")"
    "$bin" --db "$db" class report --html "$work/class.html" > /dev/null || fail "html"
    grep -q '<td>bob</td>' "$work/class.html" || fail "html report"
    # bob's 83 made 100 in the store (issue 38): TAMPERED, and it counts for
    # nothing, neither the best nor the last nor the minutes.
    sqlite3 "$db" "UPDATE attempts SET score = 100 WHERE student = 'bob'" || fail "sqlite3"
    "$bin" --db "$db" class report > "$work/report" || fail "class report"
    grep -Eq '^exam-2005 +bob +1 +- +- +- +0 +0 +TAMPERED$' "$work/report" || fail "report: $(cat "$work/report")"
    ;;
hidden)
    # The drawn exam at the machine: presetter, gauge block, touch; every
    # page looked at, in colour; the truth (what the teacher's command
    # prints) nowhere on them nor in the store's files before :submit.
    start $dbflag exercise exam-2005-drawn --student carol
    wait_for 'exam-2005-drawn'
    "$bin" --db "$db" exercise truth exam-2005-drawn --student carol > "$work/truth" || fail "truth"
    mapfile -t secrets < <(awk '/^(PREF|DEC1|D1)\./ && ($2 > 0.5 || $2 < -0.5) { print $2 }' "$work/truth")
    [ ${#secrets[@]} -eq 5 ] || fail "expected 5 values to hide: $(cat "$work/truth")"
    homed_with_t1
    cmd ":measure tool T1 X"
    wait_for 'presetter: tool T1 X'
    cmd ":measure length"
    wait_for 'length: not allowed in this exercise \(allowed: dia, tool\)'
    cmd ":gauge 100"
    cmd ":mode jog"
    cmd ":jog Z -100"
    cmd ":setup"
    wait_for ':setup: not during an exercise'
    : > "$work/screens"
    for p in op om pref corr shop graph info param exercise alarm prog dir help; do
        cmd ":page $p"
        sleep 0.2
        screen_e >> "$work/screens"
    done
    grep -q 'no coordinates during an exercise' "$work/screens" || fail "GRAPH reads coordinates"
    for s in "${secrets[@]}"; do
        # A truth drawn equal to an instrument's size (DEC1 Z, the stick-out,
        # is 100 once in 41 draws, the gauge block is 100) is on the screen
        # as that instrument's size: the search proves nothing for it.
        case " 100.000 20.000 40.000 " in *" $s "*) continue ;; esac
        grep -qF -- "$s" "$work/screens" && fail "the truth $s is on a screen"
        cat "$db"* | grep -aqF -- "$s" && fail "the truth $s is in the store's files"
        # Nor in any file the console writes for the user (history, logs).
        grep -raqF -- "$s" "$HOME" "$XDG_DATA_HOME" "$XDG_CONFIG_HOME" 2> /dev/null &&
            fail "the truth $s is in a file of the user's: $(grep -rlaF -- "$s" "$HOME" "$XDG_DATA_HOME" "$XDG_CONFIG_HOME")"
    done
    cmd ":submit"
    wait_for 'submitted: '
    for s in "${secrets[@]}"; do wait_for "${s//./\\.}"; done
    ;;
instruments)
    # Issue 38: the WORKSHOP page offers only the instruments the exercise
    # allows (exam-2005-drawn: dia and tool; mill-pocket: no presetter).
    start $dbflag exercise exam-2005-drawn --student dave
    wait_for 'exam-2005-drawn'
    cmd ":page shop"
    wait_for '^ +dia Z-20 +micrometer'
    wait_for '^ +tool T1 X\|Z\|R +presetter'
    screen | grep -Eq '^ +(bore|groove|length) ' && fail "a forbidden instrument is offered"
    cmd ":quit"
    wait_for '^EXIT=0' 10
    next_server
    start $dbflag exercise mill-pocket --student dave
    wait_for 'mill-pocket'
    cmd ":page shop"
    wait_for '^ +depth X60 Y30 +depth gauge'
    screen | grep -Eq '^ +tool T1 L' && fail "the presetter is offered in mill-pocket"
    ;;
mill)
    # mill-pocket at the machine: the edge finder kicks on the block's -X and
    # -Y faces (PREF = OM + its radius), the probe's lamp on the top (PREF Z
    # = OM - its length), the pocket cut and measured. The truth (what the
    # teacher's command prints) is what the touch-offs must give. A fixed
    # key: the same truth on every run (the moves suit any draw of the ranges).
    echo 0123456789abcdef0123456789abcdef > "$PUPITRE_CLASS_KEY"
    start $dbflag exercise mill-pocket --student finn
    wait_for 'edge finder'
    "$bin" --db "$db" exercise truth mill-pocket --student finn > "$work/truth" || fail "truth"
    truth() { awk -v n="$1" '$1 == n { print $2 }' "$work/truth"; }
    pom
    cmd ":speed max"
    imd "T6 D6 M6"
    imd "M3 S800"
    cmd ":mode jog"
    cmd ":jog Y -100"
    cmd ":jog Z -400"
    cmd ":jog X 80"
    wait_for "the edge finder T6 kicks on the block's -X face" 10
    cmd ":touch X -5"
    wait_for "surface -5.000 = $(truth PREF.X)" 5
    cmd ":jog X -30"
    cmd ":jog Y -100"
    cmd ":jog X 90"
    cmd ":jog Y 120"
    wait_for "the edge finder T6 kicks on the block's -Y face" 10
    cmd ":touch Y -5"
    wait_for "surface -5.000 = $(truth PREF.Y)" 5
    cmd ":jog Y -20"
    cmd ":jog Z 300"
    imd "T4 D4 M6"
    imd "M5"
    cmd ":mode jog"
    cmd ":jog X -30"
    cmd ":jog Y 60"
    cmd ":jog Z -400"
    wait_for 'T4 touched the part$' 10
    cmd ":touch Z 0"
    wait_for "surface 0.000 = $(truth PREF.Z)" 5
    cmd ":jog Z 50"
    cmd ":mode auto"
    keys F9
    wait_for 'M02: end of program %40' 60
    cmd ":measure width X X60 Y40 Z-2.5"
    wait_for 'caliper: width X X60 Y40 Z-2.5 = 40.00 mm'
    cmd ":submit"
    wait_for 'submitted: 100%'
    wait_for 'depth X60 Y40 +5.000 +5.000 +4.950 .. 5.050 +ok'
    ;;
french)
    # A French class: the page, the task and the report in French.
    start --lang fr --db "$db" exercise wear --student chloé
    wait_for '─ EXERCICE'
    wait_for 'La machine est réglée'
    wait_for 'Élève chloé'
    cmd ":submit"
    wait_for 'rendu : 0 %|rendu'
    wait_for 'FAUX'
    ;;
restart)
    # :exercise NAME from a plain console: refused for an unknown name, then
    # the console starts again on the exercise, same store.
    start --db "$db"
    cmd ":exercise nosuch"
    wait_for 'no exercise named nosuch'
    cmd ":exercise exam-2005"
    wait_for 'Enter the six values' 10
    wait_for 'exercise exam-2005: the task is on this page'
    cmd ":exercise wear"
    wait_for 'an exercise is in progress: :submit ends it'
    ;;
first)
    # lathe-first at the machine, as a student does it: tool 1 is measured,
    # the bar's place is not. The touch-offs must give the truth the
    # teacher's command prints; the moves suit any draw of the ranges (the
    # face from Z -5 to 50, the jaws at Z -50 or further left).
    echo 0123456789abcdef0123456789abcdef > "$PUPITRE_CLASS_KEY"
    start $dbflag exercise lathe-first --student erin
    wait_for 'PREF Z on the face'
    "$bin" --db "$db" exercise truth lathe-first --student erin > "$work/truth" || fail "truth"
    truth() { awk -v n="$1" '$1 == n { print $2 }' "$work/truth"; }
    homed_with_t1
    imd "S800 M4"
    # Over the bar, down onto it, a 0.5 mm skim out past the face, measured.
    cmd ":mode jog"
    cmd ":jog Z -190"
    cmd ":jog X -200"
    # It says what it touched, not where on the part: that would give the
    # diameter (so PREF X) away.
    wait_for 'T1 touched the part$' 20
    cmd ":mode inc"
    cmd ":jog X -1"
    cmd ":jog Z 100"
    cmd ":measure dia Z-5"
    wait_for 'micrometer: dia Z-5 = 59.000 mm'
    cmd ":touch X 59"
    wait_for "surface ø59.000/2 = $(truth PREF.X)" 5
    # Below the bar's top, onto the face.
    cmd ":mode jog"
    cmd ":jog X 4"
    cmd ":jog Z 20"
    cmd ":jog X -14"
    cmd ":jog Z -100"
    wait_for 'T1 touched the part$' 10
    cmd ":touch Z 0"
    wait_for "surface 0.000 = $(truth PREF.Z)" 5
    cmd ":jog Z 10"
    cmd ":jog X 40"
    # The part, measured, handed in.
    cmd ":mode auto"
    keys F9
    wait_for 'M02: end of program %10' 60
    cmd ":measure dia Z-10"
    wait_for 'micrometer: dia Z-10 = 40.000 mm'
    cmd ":submit"
    wait_for 'submitted: 100%'
    wait_for 'dia Z-25 +50.000 +50.000 +49.980 .. 50.020 +ok'
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
cmd ":quit!"
exit 0
