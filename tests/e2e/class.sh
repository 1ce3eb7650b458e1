#!/usr/bin/env bash
# The class across hosts (issue 34) on the test server scripts/test starts
# (scripts/lib/pg.sh): a teacher sets a class up, students log in as
# themselves and do the June 2005 exam at their consoles in tmux, each then
# looks at the server through psql with their own login, and the teacher's
# side grades and signs. Skipped without a server, failed under CI=true.
#   class.sh PUPITRE_BINARY CASE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(realpath "$1") case=$2
# Both: the server to use and how to stop and start it (scripts/lib/pg.sh).
if [ -z "${PUPITRE_TEST_PG:-}" ] || [ -z "${PUPITRE_TEST_PG_CTL:-}" ]; then
    [ "${CI:-}" = true ] && { echo "CI=true and no PostgreSQL test server"; exit 1; }
    echo "no PostgreSQL test server (scripts/test starts one)"
    exit 77
fi
. "$(dirname "$0")/lib.sh"

# A schema and logins of this run's own, dropped at the end.
schema="class_$$_$case"
alice="alice$$" bob="bob$$" group="c$$"
psql "$PUPITRE_TEST_PG" -qc "CREATE SCHEMA $schema" >/dev/null || exit 1
teacher_db="$PUPITRE_TEST_PG options='-csearch_path=$schema'"
sql() { psql "$PUPITRE_TEST_PG" -qtAc "SET search_path = $schema; $1"; }
cleanup_class() {
    psql "$PUPITRE_TEST_PG" -qc "DROP SCHEMA $schema CASCADE" >/dev/null 2>&1
    for r in "$alice" "$bob" "$group"; do psql "$PUPITRE_TEST_PG" -qc "DROP ROLE IF EXISTS \"$r\"" >/dev/null 2>&1; done
    cleanup
}
trap cleanup_class EXIT

# The teacher: the class, its two logins, their passwords printed once.
"$bin" --db "$teacher_db" class init --class "$group" > "$work/init" || fail "class init: $(cat "$work/init")"
grep -q "class $group set up" "$work/init" || fail "init: $(cat "$work/init")"
"$bin" --db "$teacher_db" class add-student --class "$group" "$alice" "$bob" > "$work/logins" ||
    fail "add-student"
pw() { awk -v n="$1" '$1 == n { print $2 }' "$work/logins"; }
[ -n "$(pw "$alice")" ] && [ -n "$(pw "$bob")" ] || fail "no passwords: $(cat "$work/logins")"
"$bin" --db "$teacher_db" class students --class "$group" > "$work/students" || fail "students"
[ "$(cat "$work/students")" = "$group $alice
$group $bob" ] || fail "students: $(cat "$work/students")"
# A student's own connection: their login and password, nothing else.
conn_of() {
    local host port
    host=$(sed -n 's/.*host=\([^ ]*\).*/\1/p' <<<"$PUPITRE_TEST_PG")
    port=$(sed -n 's/.*port=\([^ ]*\).*/\1/p' <<<"$PUPITRE_TEST_PG")
    echo "host=$host port=$port dbname=postgres user=$1 password=$(pw "$1") sslmode=require connect_timeout=5 options='-csearch_path=$schema'"
}
as() { local who=$1; shift; psql "$(conn_of "$who")" -qtA -v ON_ERROR_STOP=1 "$@"; }

# The server started here outlives the test: it keeps none of its files open.
pg_ctl_() {
    ${PUPITRE_TEST_PG_AS:-} $PUPITRE_TEST_PG_CTL "$@" >/dev/null 2>&1 </dev/null 3>&- 4>&- 5>&- \
        6>&- 7>&- 8>&- 9>&-
}
# The exam's values typed at a console, as `student`; DEC1 left out when $2
# is "nodec1"; not submitted.
exam_values() {
    E2E_ENV="PGPASSFILE=/dev/null" start --db "\"$(conn_of "$1")\"" exercise exam-2005
    wait_for 'exam-2005: June 2005 exam'
    keys M-p
    wait_for 'PREF'
    local values=("PREF.X=-135.477" "PREF.Z=-669.936")
    [ "${2:-}" = nodec1 ] || values+=("DEC1.Z=257.267")
    for v in "${values[@]}"; do
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
}
# The exam at a console, as `student`; DEC1 left out when $2 is "nodec1".
exam() {
    exam_values "$@"
    cmd ":submit"
    wait_for 'submitted: [0-9]+% \(provisional'
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
}

case $case in
grade)
    exam "$alice"
    exam "$bob" nodec1
    # Submitted, not graded: the teacher's report says so, and counts nothing.
    "$bin" --db "$teacher_db" class report > "$work/report" || fail "report"
    grep -Eq "^exam-2005 +$alice +1 +- +- .*UNGRADED 1" "$work/report" || fail "report: $(cat "$work/report")"
    # What each console graded at :submit, its time line aside (the server's
    # time is the grade's): the replay must give it again exactly.
    graded() { sql "SELECT student, score, mistakes, crashes, found, regexp_replace(report, '^([^\n]*\n)[^\n]*\n', '\1') FROM attempts ORDER BY id"; }
    graded > "$work/provisional"
    # The record: the actions with the simulated clock, the values entered.
    sql "SELECT record FROM attempts WHERE student = '$alice'" > "$work/record"
    head -1 "$work/record" | grep -qx 'pupitre-record 1' || fail "record: $(cat "$work/record")"
    grep -Eq '^[0-9]+\.[0-9]{6} key page pref$' "$work/record" || fail "record: $(cat "$work/record")"
    grep -Eq '^[0-9]+\.[0-9]{6} line DEC1\.Z=257\.267$' "$work/record" || fail "record: $(cat "$work/record")"
    grep -Eq '^[0-9]+\.[0-9]{6} line :submit$' "$work/record" || fail "record: $(cat "$work/record")"
    # bob writes the DEC1 he forgot into his attempt's machine by hand: the
    # grade is the replay's, his rows count for nothing.
    bm=$(sql "SELECT machine FROM attempts WHERE student = '$bob'")
    as "$bob" -c "INSERT INTO origins VALUES ('$bm', 'DEC1', 'Z', 257267) ON CONFLICT (machine, kind, axis) DO UPDATE SET value = 257267" ||
        fail "bob could not write his own machine"
    # The teacher's side grades by replaying each record, and signs.
    "$bin" --db "$teacher_db" class grade > "$work/grade" || fail "grade: $(cat "$work/grade")"
    grep -q "$alice, exam-2005: 100%" "$work/grade" || fail "grade: $(cat "$work/grade")"
    grep -Eq "$bob, exam-2005: [0-9]+% \(.*dec1" "$work/grade" || fail "grade: $(cat "$work/grade")"
    grep -q '2 attempts graded' "$work/grade" || fail "grade: $(cat "$work/grade")"
    grep -q 'the console said' "$work/grade" && fail "the replay is not the console's grade: $(cat "$work/grade")"
    graded > "$work/replayed"
    diff "$work/provisional" "$work/replayed" >&2 || fail "the replay's grades differ from the consoles'"
    "$bin" --db "$teacher_db" class grade | grep -q '0 attempts graded' || fail "graded twice"
    "$bin" --db "$teacher_db" class report > "$work/report" || fail "report"
    grep -Eq "^exam-2005 +$alice +1 +100 +100 " "$work/report" || fail "report: $(cat "$work/report")"
    grep -Eq "^exam-2005 +$bob +1 .*dec1" "$work/report" || fail "report: $(cat "$work/report")"
    # Each student reads their own graded report, and no one else's.
    [ "$(as "$alice" -c "SELECT count(*) FROM attempts")" = 1 ] || fail "alice sees others' attempts"
    as "$alice" -c "SELECT report FROM attempts" | grep -q 'Score 100%' || fail "alice's report"
    # A grade changed by the teacher's login without the key: TAMPERED.
    sql "UPDATE attempts SET score = 100 WHERE student = '$bob'"
    "$bin" --db "$teacher_db" class report | grep -Eq "^exam-2005 +$bob +1 .*TAMPERED" ||
        fail "tampered: $("$bin" --db "$teacher_db" class report)"
    ;;
hidden)
    exam "$alice"
    exam "$bob" nodec1
    # Everything alice's login can SELECT, dumped: nothing of bob's, no key.
    as "$alice" -c "SELECT tablename FROM pg_tables WHERE schemaname = '$schema'" > "$work/tables"
    : > "$work/dump"
    while read -r t; do
        as "$alice" -c "SELECT * FROM $t" >> "$work/dump" 2>/dev/null
    done < "$work/tables"
    key=$(sql "SELECT key FROM pupitre_class_key")
    [ -n "$key" ] || fail "no key on the server"
    grep -q "$key" "$work/dump" && fail "alice read the class key"
    grep -q "$bob" "$work/dump" && fail "alice read bob's rows: $(grep "$bob" "$work/dump" | head -3)"
    grep -q "$alice/lathe" "$work/dump" || fail "alice does not read her own machine"
    as "$alice" -c "SELECT key FROM pupitre_class_key" 2>/dev/null && fail "alice read the key table"
    # Writing a grade, an attempt or an exercise by hand: refused by the server.
    id=$(sql "SELECT id FROM attempts WHERE student = '$alice'")
    as "$alice" -c "UPDATE attempts SET score = 100 WHERE id = $id" 2>"$work/err" && fail "alice updated her grade"
    grep -q 'permission denied' "$work/err" || fail "update: $(cat "$work/err")"
    as "$alice" -c "INSERT INTO attempts (exercise, exercise_sha, student, machine, started_ms, score) VALUES ('exam-2005', '', '$alice', '$alice/x', 0, 100)" 2>/dev/null &&
        fail "alice inserted an attempt"
    as "$alice" -c "UPDATE exercises SET text = 'x'" 2>/dev/null && fail "alice changed an exercise"
    as "$alice" -c "INSERT INTO exercises VALUES ('mine', 'x', 0, '$alice')" 2>/dev/null && fail "alice added an exercise"
    as "$alice" -c "INSERT INTO correctors VALUES ('$bob/lathe', 1, 'X', 5)" 2>/dev/null && fail "alice wrote bob's machine"
    # bob's attempt submitted again through the function by alice: nothing.
    bid=$(sql "SELECT id FROM attempts WHERE student = '$bob'")
    [ "$(as "$alice" -c "SELECT pupitre_submit($bid, 100, 0, '', '', '', '')")" = "" ] || fail "alice submitted bob's"
    [ "$(sql "SELECT score FROM attempts WHERE id = $bid")" != 100 ] || fail "bob's score changed"
    # The truth comes only through an attempt opened, which the report shows.
    as "$alice" -c "SELECT seed FROM pupitre_open_attempt('wear', '$alice/lathe#wear#1')" >/dev/null || fail "open"
    "$bin" --db "$teacher_db" class report | grep -Eq "^wear +$alice +0\+" ||
        fail "an opened attempt is not in the report: $("$bin" --db "$teacher_db" class report)"
    # A seed at every attempt: the next one is another.
    sql "UPDATE attempts SET submitted_ms = 1 WHERE exercise = 'wear'"
    as "$alice" -c "SELECT seed FROM pupitre_open_attempt('wear', '$alice/lathe#wear#2')" >/dev/null
    [ "$(sql "SELECT count(DISTINCT seed) FROM attempts WHERE exercise = 'wear'")" = 2 ] || fail "the same seed twice"
    ;;
watch)
    # The teacher's live view: each student, and a status that changes
    # within a second of a student's :submit (the server's notification).
    T -f /dev/null new-session -d -s e2e -x 120 -y 24 \
        "env LANG=C.UTF-8 TERM=screen '$bin' --db \"$teacher_db\" class watch --class $group ; echo EXIT=\$? ; sleep 30"
    wait_for "WATCH class $group"
    wait_for "^$alice +no attempt"
    wait_for "^$bob +no attempt"
    id=$(as "$alice" -c "SELECT id FROM pupitre_open_attempt('exam-2005', '$alice/lathe#exam-2005#1')")
    # Opened from psql, whose session is over: open, and nobody at it.
    wait_for "^$alice +exam-2005 +0/45 min +disconnected" 1
    as "$alice" -c "SELECT pupitre_submit($id, 50, 0, '', '', '', '')" >/dev/null
    wait_for "^$alice +exam-2005 +0/45 min +submitted" 1
    # In colour: the submitted status on its own style, not plain.
    sgr_line "$alice +exam" | grep -q $'\e\\[' || fail "no colour: $(sgr_line "$alice +exam" | cat -v)"
    # A value set on the student's machine is their last action (written as
    # a console writes it, the commit announced on the store's channel).
    as "$alice" -c "INSERT INTO machines VALUES ('$alice/lathe', '', 0, 0)" >/dev/null
    as "$alice" -c "INSERT INTO audit (at_ms, who, machine, name, old, new, source) VALUES ((extract(epoch FROM now()) * 1000)::bigint, '$alice', '$alice/lathe', 'PREF.X', NULL, -135477, 'page PREF'); NOTIFY pupitre_store" >/dev/null
    wait_for "^$alice .*PREF.X -135.477" 2
    # The teacher grades: the watch says so.
    "$bin" --db "$teacher_db" class grade >/dev/null
    wait_for "^$alice +exam-2005 .*graded" 2
    # Enter: alice's attempts; Esc: the class; q quits.
    keys Enter
    wait_for "$alice's attempts"
    wait_for "exam-2005 .*graded"
    keys Escape
    wait_for "^$bob +no attempt"
    keys q
    wait_for '^EXIT=0'
    ;;
gone)
    # The server stopped before :submit: the attempt is kept on this PC and
    # handed in when the server is back, once.
    trap 'pg_ctl_ status || pg_ctl_ start -w; cleanup_class' EXIT
    exam_values "$alice"
    sleep 1
    pg_ctl_ stop -m immediate || fail "pg_ctl stop"
    cmd ":submit"
    wait_for 'submitted: 100%; the server does not answer: kept here until it does'
    [ -n "$(find "$work/data" -name '*.outbox')" ] || fail "no outbox on disk: $(find "$work/data" -type f)"
    pg_ctl_ start -w || fail "pg_ctl start"
    wait_for 'the store answers again.*the attempt' 20
    [ "$(sql "SELECT count(*) FROM attempts WHERE student = '$alice' AND submitted_ms IS NOT NULL")" = 1 ] ||
        fail "attempts: $(sql "SELECT id, submitted_ms FROM attempts")"
    cmd ":quit"
    wait_for '^EXIT=0'
    next_server
    # Nothing left to send, nothing sent twice.
    [ -z "$(find "$work/data" -name '*.outbox')" ] || fail "the outbox is still there"
    "$bin" --db "$teacher_db" class grade | grep -q "$alice, exam-2005: 100%" || fail "not graded"
    [ "$(sql "SELECT count(*) FROM attempts WHERE student = '$alice'")" = 1 ] || fail "two attempts"
    ;;
replay)
    # The teacher replays bob's attempt in a read-only console, action by action.
    exam "$bob" nodec1
    id=$(sql "SELECT id FROM attempts WHERE student = '$bob'")
    W=100 H=30 start --db "\"$teacher_db\"" class replay "$id"
    wait_for "REPLAY 0/7 .*attempt $id: $bob, exam-2005: read-only"
    wait_for 'Student .*, the attempt replayed'
    keys Right
    wait_for 'REPLAY 1/7 .*key page pref'
    wait_for '^─ PREF'
    keys Right
    wait_for 'REPLAY 2/7 .*entered: PREF.X=-135.477'
    screen | grep -Eq '^  X +-135\.477 ' || fail "PREF X is not on the PREF page"
    # The first action that produced the mistake named: DEC1 left at 0, from the start.
    keys m
    wait_for 'REPLAY 0/7 .*DEC1.Z: DEC1 forgotten, from the start'
    # To the end: the replay's grade, the mistake named.
    keys End
    wait_for 'REPLAY 7/7 '
    wait_for 'Score 83%'
    wait_for 'DEC1 forgotten: DEC1 Z left at 0'
    # Back one: the CORR page as the student had it, Z just entered.
    keys Left
    wait_for 'REPLAY 6/7 .*entered: Z=38.237'
    wait_for '^─ CORR'
    # Another page to look at, then the student's again; nothing of the machine moves.
    keys M-g
    wait_for '^─ GRAPH'
    keys Tab
    wait_for '^─ CORR'
    keys F12
    wait_for 'F12: the replay changes nothing'
    keys F1
    wait_for 'back one action'
    wait_for 'the first action that produced a mistake the grade names'
    keys q
    wait_for '^EXIT=0'
    # Not a terminal: refused; an attempt that is not there: named.
    "$bin" --db "$teacher_db" class replay "$id" </dev/null >/dev/null 2>"$work/err" && fail "replay without a terminal"
    grep -q 'the replay needs a terminal' "$work/err" || fail "message: $(cat "$work/err")"
    "$bin" --db "$teacher_db" class replay 999999 2>"$work/err" && fail "replay of no attempt"
    grep -q 'no attempt 999999' "$work/err" || fail "message: $(cat "$work/err")"
    ;;
student)
    # --student is refused on a server: a person is their login.
    "$bin" --db "$(conn_of "$alice")" exercise exam-2005 --student "$bob" 2>"$work/err" </dev/null && fail "--student taken"
    grep -q 'you are your login' "$work/err" || fail "message: $(cat "$work/err")"
    # On a class's server the exercises are the server's, not a file.
    echo 'name = x' > "$work/x.exercise"
    "$bin" --db "$(conn_of "$alice")" exercise "$work/x.exercise" 2>"$work/err" </dev/null && fail "a file taken"
    grep -q "the exercises are the server's" "$work/err" || fail "message: $(cat "$work/err")"
    ;;
*)
    echo "no case $case"
    exit 2
    ;;
esac
echo "ok ($case)"
