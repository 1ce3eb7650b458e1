#!/usr/bin/env bash
# The console on a class's PostgreSQL store (issue 33), in tmux: two consoles
# on one server follow each other; the server stopped under a console leaves
# its keys live, keeps what the operator set and stores it when the server is
# back. Needs the test server scripts/test starts (scripts/lib/pg.sh): skipped
# without one, failed under CI=true. `gone` stops that server: it runs alone.
#   server.sh PUPITRE_BINARY CASE
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

# A schema of its own on the test server, dropped at the end.
schema="e2e_$$_$case"
psql "$PUPITRE_TEST_PG" -qc "CREATE SCHEMA $schema" >/dev/null || exit 1
export PUPITRE_DB="$PUPITRE_TEST_PG options='-csearch_path=$schema'"
sql() { psql "$PUPITRE_TEST_PG" -qtAc "SET search_path = $schema; $1"; }
# The server started here outlives the test: it keeps none of its files open.
pg_ctl_() {
    ${PUPITRE_TEST_PG_AS:-} $PUPITRE_TEST_PG_CTL "$@" >/dev/null 2>&1 </dev/null 3>&- 4>&- 5>&- \
        6>&- 7>&- 8>&- 9>&-
}
cleanup_server() {
    pg_ctl_ status || pg_ctl_ start
    psql "$PUPITRE_TEST_PG" -qc "DROP SCHEMA $schema CASCADE" >/dev/null 2>&1
    cleanup
}
trap cleanup_server EXIT

case $case in
two)
    # What one console sets, the other shows: the server tells it (NOTIFY).
    start
    start2
    wait2 'F1 help|1HELP'
    cmd2 ":page corr"
    wait2 '^─ CORR'
    cmd ":set D1.X=12.5"
    wait2 'another console changed: D1.X 12.5' 5
    wait2 '^  1 +12\.500 ' 5
    # A program saved in one is the current text in the other.
    cmd ":edit 300"
    cmd "N1 (FROM CONSOLE A)"
    cmd ":save"
    wait_for '%300 saved as revision'
    wait2 'another console changed: %300 r2' 5
    [ "$(sql "SELECT value FROM correctors WHERE machine = 'lathe' AND d = 1 AND field = 'X'")" = 12500 ] ||
        fail "D1.X is not on the server"
    cmd ":close"
    cmd ":quit"
    wait_for '^EXIT=0'
    ;;
gone)
    # The server stopped under the console: keys and pages stay live, a value
    # set meanwhile is kept and stored when the server is back, once.
    start
    cmd ":page corr"
    wait_for '^─ CORR'
    cmd ":set D1.X=12.5"
    expect_message 'D1.X 0.000 -> 12.500$'
    pg_ctl_ stop -m immediate || fail "cannot stop the test server"
    cmd ":set D1.Z=7"
    expect_message 'D1.Z 0.000 -> 7.000; the store does not answer: kept here, stored when it does'
    sgr_line 'the store does not answer' | grep -q $'\e\[' || fail "the message is not coloured"
    # The server's own notices ("terminating connection…") never reach the screen.
    screen | grep -q 'terminating connection' && fail "a server notice was printed over the console"
    # The console answers at once: a page, the typed line.
    t0=$(date +%s%N)
    cmd ":page pref"
    wait_for '^─ PREF' 2
    keys -l "G0 X1"
    wait_for '> *G0 X1' 2
    t1=$(date +%s%N)
    [ $(((t1 - t0) / 1000000)) -lt 3000 ] || fail "the console waited for the server"
    keys C-u
    cmd ":page corr"
    wait_for '^  1 +12\.500 +7\.000' 2
    pg_ctl_ start || fail "cannot start the test server again"
    wait_for 'the store answers again: 1 values kept here are stored \(D1.Z\)' 15
    [ "$(sql "SELECT value FROM correctors WHERE machine = 'lathe' AND d = 1 AND field = 'Z'")" = 7000 ] ||
        fail "D1.Z is not on the server"
    [ "$(sql "SELECT count(*) FROM audit WHERE name = 'D1.Z'")" = 1 ] || fail "D1.Z stored twice"
    cmd ":quit"
    wait_for '^EXIT=0'
    # A new console reads it from the server.
    next_server
    start
    cmd ":page corr"
    wait_for '^  1 +12\.500 +7\.000' 5
    cmd ":quit"
    wait_for '^EXIT=0'
    ;;
outbox)
    # A :save and a value the server could not take are made when it answers;
    # a value kept when the console quits is sent by the next one.
    start
    cmd ":page corr"
    wait_for '^─ CORR'
    pg_ctl_ stop -m immediate || fail "cannot stop the test server"
    cmd ":set D1.Z=7"
    expect_message 'kept here, stored when it does'
    # A program the store cannot give is not opened as a new one; the
    # message names the store by host and database, not its whole URI.
    cmd ":edit 301"
    expect_message 'cannot open %301: 127\.0\.0\.1/postgres: cannot'
    pg_ctl_ start || fail "cannot start the test server again"
    wait_for 'the store answers again: 1 values kept here are stored \(D1.Z\)' 15
    [ "$(sql "SELECT value FROM correctors WHERE machine = 'lathe' AND d = 1 AND field = 'Z'")" = 7000 ] ||
        fail "D1.Z is not on the server"
    cmd ":edit 300"
    wait_for '^─ EDIT  %300  revision 1'
    pg_ctl_ stop -m immediate || fail "cannot stop the test server"
    cmd "N5 G0 X111"
    cmd ":save"
    expect_message 'not saved yet: the store does not answer; kept here, saved when it does'
    pg_ctl_ start || fail "cannot start the test server again"
    wait_for '%300 saved as revision 2' 15
    cmd ":close"
    pg_ctl_ stop -m immediate || fail "cannot stop the test server"
    cmd ":page corr"
    cmd ":set D2.X=3"
    expect_message 'kept here, stored when it does'
    cmd ":quit"
    wait_for '^EXIT=0' 15
    ls "$XDG_DATA_HOME"/pupitre/servers/*.outbox >/dev/null 2>&1 || fail "no outbox kept on the PC"
    pg_ctl_ start || fail "cannot start the test server again"
    next_server
    start
    wait_for 'the store answers again: 1 values kept here are stored \(D2.X\)' 15
    cmd ":page corr"
    wait_for '^  2 +3\.000 ' 5
    [ "$(sql "SELECT count(*) FROM audit WHERE name = 'D2.X'")" = 1 ] || fail "D2.X not stored once"
    [ "$(sql "SELECT count(*) FROM revisions WHERE program = 300")" = 2 ] || fail "%300 saved twice"
    ls "$XDG_DATA_HOME"/pupitre/servers/*.outbox >/dev/null 2>&1 && fail "the outbox stays after it was sent"
    cmd ":quit"
    wait_for '^EXIT=0'
    ;;
journal)
    # The editor's journal of a server's store lives on this PC: kill -9
    # loses at most the line being typed, and the next start offers it.
    start
    cmd ":edit 300"
    wait_for '^─ EDIT  %300'
    cmd "N5 G0 X111"
    wait_for 'N5 G0 X111'
    pid=$(pgrep -P "$(T list-panes -t e2e -F '#{pane_pid}')" -f "$bin" -n)
    kill -KILL "$pid"
    wait_for 'EXIT=137'
    ls "$XDG_DATA_HOME"/pupitre/servers/*.recover/300.iso >/dev/null 2>&1 ||
        fail "no journal under \$XDG_DATA_HOME/pupitre/servers"
    next_server
    start
    wait_for 'unsaved work recovered for %300: :edit 300, then :recover'
    cmd ":edit 300"
    cmd ":recover"
    wait_for 'recovered text loaded'
    cmd ":save"
    wait_for '%300 saved as revision 2'
    sql "SELECT convert_from(text, 'UTF8') FROM revisions WHERE program = 300 AND rev = 2" |
        grep -q 'N5 G0 X111' || fail "the recovered line is not on the server"
    cmd ":close"
    cmd ":quit"
    wait_for '^EXIT=0'
    ;;
training)
    # Training on the server's store: the exam done right, graded, and the
    # teacher's report read from the server (training.sh's own case).
    trap - EXIT
    PUPITRE_E2E_DB=$PUPITRE_DB bash "$(dirname "$0")/training.sh" "$bin" right
    rc=$?
    cleanup_server
    exit $rc
    ;;
*)
    echo "unknown case $case"
    exit 2
    ;;
esac
echo "ok ($case)"
