#!/usr/bin/env bash
# Process-level tests of the store commands (CTest label "store"): the real
# binary, a private HOME and XDG_DATA_HOME, exit codes and files checked byte
# for byte.   store_cli.sh PUPITRE CASE
# Cases: roundtrip commands default run anomalies concurrent copy server
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
case_name=$2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
shared=${PUPITRE_SHARED:-$root/../shared}

work=$(mktemp -d)
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
chmod 755 "$work"
export HOME=$work/home XDG_DATA_HOME=$work/xdg TZ=UTC USER=tester
mkdir -p "$HOME"
cd "$work" || exit 1

fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
# expect CODE CMD...: runs CMD, checks its exit status.
expect() {
    local want=$1
    shift
    "$@" >"$work/out" 2>"$work/err"
    local rc=$?
    [ "$rc" = "$want" ] || fail "$* -> exit $rc, expected $want; stderr: $(cat "$work/err")"
}
stderr_has() { grep -qF -- "$1" "$work/err" || fail "stderr lacks '$1': $(cat "$work/err")"; }
stdout_has() { grep -qF -- "$1" "$work/out" || fail "stdout lacks '$1': $(cat "$work/out")"; }
P() { "$bin" "$@"; }
need() { command -v "$1" >/dev/null || { echo "skipped: $1 not installed" >&2; exit 77; }; }

case $case_name in
roundtrip)
    # Several programs in one file, a leader, CRLF lines, no final newline.
    printf '(LEADER)\r\n%%1 (ONE)\r\nN10 G0 X0\r\n %%2\nN20 G1 X1   \n\n%%3.2 (THREE)\nM2' >multi.iso
    expect 0 P --db s.db import multi.iso
    stdout_has "%1: created as r1 from multi.iso"
    expect 0 P --db s.db export 1 2 3 -o back.iso
    cmp multi.iso back.iso || fail "export 1 2 3 differs from the imported file"
    expect 0 P --db s.db export 2
    printf ' %%2\nN20 G1 X1   \n\n' | cmp - out || fail "export 2 is not its text"
    expect 0 P --db s.db import multi.iso
    stdout_has "%3: unchanged (r1)"
    # Every shared program, exactly (fragments need --number).
    if [ -d "$shared/programs" ]; then
        n=0
        for f in "$shared"/programs/*.iso; do
            n=$((n + 1))
            if grep -q '^[[:space:]]*%' "$f"; then
                P --db rt.db import "$f" >imp.out 2>imp.err || { fail "import $f: $(cat imp.err)"; continue; }
                nums=$(sed -n 's/^%\([0-9]*\): .*/\1/p' imp.out)
            else
                P --db rt.db import --number $((800000 + n)) "$f" >imp.out 2>imp.err ||
                    { fail "import --number $f: $(cat imp.err)"; continue; }
                nums=$((800000 + n))
            fi
            # shellcheck disable=SC2086
            P --db rt.db export $nums -o "rt.iso" || fail "export $nums"
            cmp -s "$f" rt.iso || fail "round trip of $f"
        done
        [ "$n" -gt 50 ] || fail "only $n shared programs"
    else
        echo "note: $shared/programs absent, shared round trip skipped" >&2
    fi
    ;;
commands)
    expect 0 P --db s.db list
    stdout_has "%300"
    stdout_has "%301"
    printf '%%12 (BRIDE)\nN10 G0 X0\nM2\n' >p12.iso
    expect 0 P --db s.db import p12.iso
    printf '%%12 (BRIDE)\nN10 G0 X5\nM2\n' >p12.iso
    expect 0 P --db s.db import p12.iso
    stdout_has "%12: saved as r2 from p12.iso"
    expect 0 P --db s.db list
    stdout_has "(BRIDE)"
    expect 0 P --db s.db history %12
    stdout_has "* r2"
    stdout_has "tester"
    stdout_has "import p12.iso"
    expect 0 P --db s.db rm 12
    stdout_has "%12: deleted (r3)"
    expect 66 P --db s.db export 12
    stderr_has "%12 was deleted"
    expect 0 P --db s.db list
    grep -q '^%12 ' out && fail "a deleted program is listed"
    expect 0 P --db s.db restore 12 1
    stdout_has "%12: r1 restored as r4"
    expect 0 P --db s.db export 12
    grep -q X0 out || fail "restore did not bring r1 back"
    expect 65 P --db s.db restore 12 3
    expect 66 P --db s.db restore 12 99
    expect 66 P --db s.db rm 999
    expect 66 P --db s.db history 999
    expect 64 P --db s.db rm twelve
    # Import is all or nothing: a bad file among good ones changes nothing.
    printf '%%20\nA\n' >a.iso
    printf 'N5 G0\n%%21\nB\n' >bad.iso
    expect 65 P --db s.db import a.iso bad.iso
    stderr_has "bad.iso:2: blocks before the % line"
    expect 66 P --db s.db export 20
    printf 'N1 G0 X0\n' >frag.iso
    expect 65 P --db s.db import frag.iso
    stderr_has "--number"
    expect 0 P --db s.db import --number 500 frag.iso
    expect 0 P --db s.db export 500
    cmp -s frag.iso out || fail "fragment round trip"
    printf '%%20\nA2\n' >a2.iso
    expect 65 P --db s.db import a.iso a2.iso
    stderr_has "also in a.iso"
    expect 66 P --db s.db import nosuch.iso
    expect 73 P --db s.db export 300 -o "$work/no/dir/out.iso"
    ;;
default)
    # The default store: $XDG_DATA_HOME/pupitre/pupitre.db, made on first use.
    expect 0 P list
    [ -f "$XDG_DATA_HOME/pupitre/pupitre.db" ] || fail "no store under XDG_DATA_HOME"
    stdout_has "%300"
    # Without XDG_DATA_HOME: ~/.local/share.
    (unset XDG_DATA_HOME; P list >/dev/null) || fail "list with HOME only"
    [ -f "$HOME/.local/share/pupitre/pupitre.db" ] || fail "no store under ~/.local/share"
    # run and check use a store only when given --db.
    rm -rf "$XDG_DATA_HOME" "$HOME/.local"
    expect 0 P run --machine lathe "$root/data/demo/lathe_p300.iso"
    expect 0 P check --machine lathe "$root/data/demo/lathe_p300.iso"
    [ -e "$XDG_DATA_HOME" ] && fail "run without --db touched the default store"
    [ -e "$HOME/.local" ] && fail "run without --db touched ~/.local"
    ;;
run)
    printf '%%555 (TOOLS)\nE50001=15157\nE51001=42126\nE60000=12235\nE62004=-500\nM2\n' >tools.iso
    printf '%%556\nL1=E50001\nL2=E60000\nG77 H777\nM2\n' >main.iso
    printf '%%777\nL3=E62004\n' >sub.iso
    expect 0 P --db s.db import sub.iso
    # Before: nothing stored.
    expect 0 P run --db s.db --machine lathe --json main.iso
    stdout_has '"L":{"L1":0,"L2":0,"L3":0}'
    # check never stores the writes.
    expect 0 P check --db s.db --machine lathe tools.iso
    expect 0 P run --db s.db --machine lathe --json main.iso
    stdout_has '"L":{"L1":0,"L2":0,"L3":0}'
    # run does, with an audit row naming the program.
    expect 0 P run --db s.db --machine lathe tools.iso
    stderr_has "stored D1.X = 15.157 (was not set) on lathe"
    stderr_has "stored DEC3.Z = -0.500 (was not set) on lathe"
    expect 0 P --db s.db run --machine lathe --json main.iso
    stdout_has '"L":{"L1":15157,"L2":12235,"L3":-500}'
    # --set overrides for one run and is not stored.
    expect 0 P run --db s.db --machine lathe --set D1.X=1 --json main.iso
    stdout_has '"L1":1000,'
    expect 0 P run --db s.db --machine lathe --json main.iso
    stdout_has '"L1":15157,'
    # The mill has its own correctors.
    expect 0 P run --db s.db --machine mill --json main.iso
    stdout_has '"L":{"L1":0,"L2":0,"L3":0}'
    # A stored program called without being given: G77 H with the demo %301 (mill).
    printf '%%1\nG77 H301\nM2\n' >call.iso
    expect 0 P run --db s.db --machine mill call.iso
    expect 1 P run --machine mill call.iso
    if command -v sqlite3 >/dev/null; then
        [ "$(sqlite3 s.db "SELECT count(*) FROM audit WHERE source = 'program %555 (tools.iso)'")" = 4 ] ||
            fail "audit rows"
    fi
    ;;
anomalies)
    need sqlite3
    printf '%%1\nN10 G0 X0\nM2\n' >part.iso
    cp part.iso keep.iso
    expect 65 P --db part.iso list
    stderr_has "not a pupitre store"
    cmp -s part.iso keep.iso || fail "a non-database was modified"
    [ -e part.iso-wal ] && fail "a -wal file was made beside a non-database"
    # Another application's database.
    sqlite3 other.db "CREATE TABLE t (x); INSERT INTO t VALUES (1);"
    cp other.db other.keep
    expect 65 P --db other.db import part.iso
    stderr_has "another application"
    cmp -s other.db other.keep || fail "another application's database was modified"
    # A newer schema.
    P --db new.db list >/dev/null
    sqlite3 new.db "PRAGMA user_version = 42"
    cp new.db new.keep
    expect 65 P --db new.db import part.iso
    stderr_has "newer pupitre (schema 42"
    cmp -s new.db new.keep || fail "a newer store was modified"
    # Truncated and corrupt.
    for i in $(seq 1 200); do printf '%%%d\n' $((1000 + i)); for b in $(seq 1 30); do echo "N$b G1 X$i Y$b"; done; done >many.iso
    P --db big.db import many.iso >/dev/null || fail "import many"
    size=$(stat -c %s big.db)
    head -c $((size / 2)) big.db >cut.db
    cp cut.db cut.keep
    expect 65 P --db cut.db list
    stderr_has "truncated"
    cmp -s cut.db cut.keep || fail "a truncated store was modified"
    cp big.db bad.db
    root_page=$(sqlite3 bad.db "SELECT rootpage FROM sqlite_schema WHERE name = 'programs'")
    page=$(sqlite3 bad.db "PRAGMA page_size")
    head -c "$page" /dev/urandom | dd of=bad.db bs="$page" seek=$((root_page - 1)) conv=notrunc status=none
    cp bad.db bad.keep
    expect 65 P --db bad.db list
    stderr_has "damaged"
    expect 65 P --db bad.db import part.iso
    cmp -s bad.db bad.keep || fail "a damaged store was modified"
    # A read-only directory (as nobody when we are root: root writes anywhere).
    mkdir ro
    P --db ro/old.db list >/dev/null
    cp ro/old.db old.keep
    chmod 555 ro
    as_user=()
    if [ "$(id -u)" = 0 ]; then
        cp "$bin" "$work/pupitre"
        chmod 755 "$work/pupitre"
        as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups env HOME="$work")
        runbin=$work/pupitre
    else
        runbin=$bin
    fi
    expect 73 "${as_user[@]}" "$runbin" --db ro/new.db list
    stderr_has "not writable"
    [ -e ro/new.db ] && fail "a store appeared in a read-only directory"
    expect 73 "${as_user[@]}" "$runbin" --db ro/old.db import part.iso
    cmp -s ro/old.db old.keep || fail "a store in a read-only directory was modified"
    chmod 755 ro
    # Locked by another writer for longer than the busy timeout (3 s).
    P --db lock.db list >/dev/null
    sqlite3 lock.db "BEGIN IMMEDIATE;" ".shell sleep 5" "ROLLBACK;" &
    holder=$!
    sleep 0.5
    expect 74 P --db lock.db import part.iso
    stderr_has "locked by another process"
    expect 0 P --db lock.db list   # readers go on
    wait $holder
    expect 0 P --db lock.db import part.iso
    # A full disk (the file size limit, SIGXFSZ ignored: writes fail with EFBIG).
    P --db full.db list >/dev/null
    P --db full.db export 300 301 >before.txt
    cp full.db full.keep
    { echo "%9000"; for i in $(seq 1 60000); do echo "N$i G1 X$i.123 Y-$i.456 F1000"; done; } >huge.iso
    (trap '' XFSZ; ulimit -f 1024; "$bin" --db full.db import huge.iso) >out 2>err
    rc=$?
    [ "$rc" = 74 ] || fail "full disk: exit $rc, expected 74: $(cat err)"
    grep -q "disk full" err || fail "full disk message: $(cat err)"
    cmp -s full.db full.keep || fail "the store changed on a full disk"
    expect 66 P --db full.db export 9000
    [ "$(sqlite3 full.db 'PRAGMA integrity_check')" = ok ] || fail "integrity after a full disk"
    ;;
concurrent)
    # Two processes importing into one store at once: every import is there.
    P --db c.db list >/dev/null
    for w in a b; do
        (
            for i in $(seq 1 25); do
                n=$([ $w = a ] && echo $((2000 + i)) || echo $((3000 + i)))
                printf '%%%d (%s)\nN10 G0 X%d\n' "$n" "$w" "$i" >"$w$i.iso"
                printf '%%4000\nN10 (%s %d)\n' "$w" "$i" >"${w}same$i.iso"
                "$bin" --db c.db import "$w$i.iso" "${w}same$i.iso" >/dev/null 2>"$w.err" || echo "$w $i failed" >>fails.txt
            done
        ) &
    done
    wait
    [ -s fails.txt ] && fail "imports failed: $(cat fails.txt) $(cat a.err b.err)"
    expect 0 P --db c.db list
    [ "$(grep -c '^%[23]0[0-9][0-9] ' out)" = 50 ] || fail "not 50 programs: $(cat out)"
    expect 0 P --db c.db history 4000
    [ "$(grep -c '^[ *] r' out)" = 50 ] || fail "%4000 does not have 50 revisions: $(cat out)"
    if command -v sqlite3 >/dev/null; then
        [ "$(sqlite3 c.db 'PRAGMA integrity_check')" = ok ] || fail "integrity"
    fi
    ;;
copy)
    # store copy between two files: everything, checked, and never into a
    # store that holds something.
    printf '%%1 (ONE)\r\nN10 G0 X0\r\n' >one.iso
    expect 0 P --db a.db import one.iso
    printf '%%1 (ONE)\nN10 G0 X1\n' >one.iso
    expect 0 P --db a.db import one.iso
    printf 'N10 E50001=15157\nN20 M02\n' >gauge.iso
    expect 0 P --db a.db run gauge.iso
    expect 0 P store copy a.db b.db
    stdout_has "counts and checksums agree"
    grep -qE '^revisions +4 ' out || fail "revisions not copied: $(cat out)"
    grep -qE '^correctors +1 ' out || fail "the corrector not copied: $(cat out)"
    grep -qE '^audit +1 ' out || fail "the audit not copied: $(cat out)"
    expect 0 P --db b.db history 1
    [ "$(grep -c '^[ *] r' out)" = 2 ] || fail "%1 has not its 2 revisions: $(cat out)"
    expect 0 P --db b.db export 1 -o back.iso
    cmp -s back.iso one.iso || fail "export after copy differs"
    expect 65 P store copy a.db b.db
    stderr_has "not empty"
    expect 66 P store copy missing.db c.db
    [ -e c.db ] && fail "a copy from nothing made c.db"
    expect 0 P store copy b.db c.db
    expect 0 P --db c.db list
    stdout_has "%1 "
    ;;
server)
    # The same commands on the test server (scripts/lib/pg.sh), named by
    # PUPITRE_DB: import, list, export byte for byte, a copy there and back.
    if [ -z "${PUPITRE_TEST_PG:-}" ]; then
        [ "${CI:-}" = true ] && { echo "CI=true and no PostgreSQL test server" >&2; exit 1; }
        echo "skipped: no PostgreSQL test server (scripts/test starts one)" >&2
        exit 77
    fi
    schema="cli_$$"
    psql "$PUPITRE_TEST_PG" -qc "CREATE SCHEMA $schema" >/dev/null || exit 1
    trap 'psql "$PUPITRE_TEST_PG" -qc "DROP SCHEMA $schema CASCADE" >/dev/null 2>&1; chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
    server="$PUPITRE_TEST_PG options='-csearch_path=$schema'"
    printf '%%7 (SEVEN)\r\nN10 G0 X7\r\n(\xc9T\xc9 \xff)\r\n' >seven.iso
    PUPITRE_DB="$server" expect 0 P import seven.iso
    PUPITRE_DB="$server" expect 0 P list
    stdout_has "%7 "
    stdout_has "(SEVEN)"
    PUPITRE_DB="$server" expect 0 P export 7 -o seven.back
    cmp -s seven.back seven.iso || fail "export from the server differs"
    expect 0 P store copy "$server" back.db
    expect 0 P --db back.db export 7 -o seven.file
    cmp -s seven.file seven.iso || fail "export after copy from the server differs"
    # A password never appears: the store is named by its URI without one.
    expect 66 P --db "${PUPITRE_TEST_PG/dbname=postgres/dbname=nosuch}" list
    stderr_has "the database nosuch does not exist"
    [ "$(wc -l <"$work/err")" = 1 ] || fail "not one line: $(cat "$work/err")"
    ;;
*)
    echo "store_cli.sh: unknown case $case_name" >&2
    exit 2
    ;;
esac
[ $fails = 0 ] || { echo "$fails failure(s) in $case_name" >&2; exit 1; }
echo "ok $case_name"
