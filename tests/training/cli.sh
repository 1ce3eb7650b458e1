#!/usr/bin/env bash
# Training in batch (pupitre-exercise(5)): the shipped exercises listed and
# checked, a broken one refused with its line, a class's own added, a
# student's truth drawn again the same for the teacher (and another
# student's different), an exercise saved from a machine's setup, an
# exercise refused as a --setup, the class report of an empty class.
#   cli.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export LANGUAGE=en HOME=$work XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data
export PUPITRE_CLASS_KEY=$work/class.key
db=(--db "$work/store.db")

# Listed and checked: the six shipped ones, each rehearsed.
"$bin" "${db[@]}" exercise list > "$work/list" || fail "list"
[ "$(grep -c shipped "$work/list")" = 6 ] || fail "list: $(cat "$work/list")"
"$bin" exercise check "$root"/data/exercises/*.exercise > "$work/check" || fail "check: $(cat "$work/check")"
grep -q 'wear.exercise: exercise wear (machine lathe): values to find 1, dimensions 2' "$work/check" ||
    fail "check: $(cat "$work/check")"

# A drawing no one can meet: done right, the part is Ø40, not Ø39.
sed 's/dia Z-10 : 40 0.01/dia Z-10 : 39 0.01/' "$root/data/exercises/wear.exercise" > "$work/bad.exercise"
"$bin" exercise check "$work/bad.exercise" > "$work/out"
[ $? = 65 ] || fail "a broken exercise should exit 65"
line=$(grep -n 'dia Z-10 : 39' "$work/bad.exercise" | cut -d: -f1)
grep -q "done right at the ranges' low ends, the exercise fails: line $line: dimension dia Z-10: the part reads 40.000, outside 39.000" "$work/out" ||
    fail "bad: $(cat "$work/out")"
"$bin" "${db[@]}" exercise add "$work/bad.exercise" 2> "$work/err"
[ $? = 65 ] || fail "add should refuse a broken exercise"

# The class's own: stored, listed, started by name.
sed 's/^name = wear$/name = wear-ours/' "$root/data/exercises/wear.exercise" > "$work/ours.exercise"
"$bin" "${db[@]}" exercise add "$work/ours.exercise" | grep -q 'exercise wear-ours stored' || fail "add"
"$bin" "${db[@]}" exercise list | grep -Eq '^wear-ours +lathe +class' || fail "list after add"

# The teacher draws a student's truth again: the key is made on the first
# attempt; without it there is nothing to draw.
"$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann 2> "$work/err"
[ $? = 66 ] || fail "truth without a key should exit 66"
grep -q 'no class key' "$work/err" || fail "$(cat "$work/err")"
echo 0123456789abcdef0123456789abcdef > "$PUPITRE_CLASS_KEY"
"$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann > "$work/t1" || fail "truth"
"$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann > "$work/t2" || fail "truth"
"$bin" "${db[@]}" exercise truth exam-2005-drawn --student ben > "$work/t3" || fail "truth"
cmp -s "$work/t1" "$work/t2" || fail "a student's truth does not reproduce"
cmp -s "$work/t1" "$work/t3" && fail "two students drew the same truth"
grep -Eq '^PREF\.Z +-[0-9]+\.[0-9]{3} +# PREF Z = the jaws. face = ' "$work/t1" || fail "$(cat "$work/t1")"

# The store keeps its class key's fingerprint (the first truth drawn made
# it): another key is refused, for the teacher's command and for a student's
# attempt, and a student with no key file gets none made (a shared store).
grep -q '0123456789abcdef' "$work/store.db" && fail "the class key is in the store"
echo fedcba9876543210fedcba9876543210 > "$work/other.key"
PUPITRE_CLASS_KEY=$work/other.key "$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann 2> "$work/err"
[ $? = 66 ] || fail "truth with another key should exit 66"
grep -q "the class key $work/other.key is not the key of this store's class" "$work/err" || fail "$(cat "$work/err")"
PUPITRE_CLASS_KEY=$work/other.key "$bin" "${db[@]}" exercise wear --student gina < /dev/null > /dev/null 2> "$work/err"
[ $? = 66 ] || fail "an attempt with another key should exit 66"
grep -q "is not the key of this store's class" "$work/err" || fail "$(cat "$work/err")"
PUPITRE_CLASS_KEY=$work/none.key "$bin" "${db[@]}" exercise wear --student gina < /dev/null > /dev/null 2> "$work/err"
[ $? = 66 ] || fail "an attempt without the class's key should exit 66"
grep -q "no class key at $work/none.key" "$work/err" || fail "$(cat "$work/err")"
[ -e "$work/none.key" ] && fail "a key was made for a store that has one"

# An attempt in progress: its truth is the key file's owner's only (the
# refusal of anyone else is TrainingSession.TheTruthOfAnAttemptInProgress).
sqlite3 "$work/store.db" "INSERT INTO attempts (exercise, exercise_sha, student, machine, started_ms)
    VALUES ('wear', 'x', 'gina', 'lathe#wear#gina#1', 1)" 2> "$work/err" || fail "$(cat "$work/err")"
"$bin" "${db[@]}" exercise truth wear --student gina > /dev/null || fail "truth, as the key's owner"

# An exercise is not a setup: its truth is the student's to find.
"$bin" run --setup exam-2005 "$root/tests/workshop/turn.iso" 2> "$work/err"
[ $? = 64 ] || fail "run --setup with an exercise should exit 64"
grep -q "'exam-2005' is an exercise: its setup is hidden" "$work/err" || fail "$(cat "$work/err")"
"$bin" run --setup "$root/data/exercises/wear.exercise" "$root/tests/workshop/turn.iso" 2> "$work/err"
[ $? = 64 ] || fail "run --setup with an exercise file should exit 64"

# Saved from a machine's setup: none yet, then the lathe's.
"$bin" "${db[@]}" exercise save mine 2> "$work/err"
[ $? = 66 ] || fail "save without a workshop should exit 66"

# An empty class.
"$bin" "${db[@]}" class report > "$work/report" || fail "class report"
grep -q 'Mistakes most made:' "$work/report" || fail "$(cat "$work/report")"
"$bin" "${db[@]}" class report --csv | head -1 | grep -q '^exercise,student,attempts' || fail "csv"
"$bin" "${db[@]}" class report --html "$work/r.html" > /dev/null || fail "html"
grep -q '</html>' "$work/r.html" || fail "html file"
"$bin" "${db[@]}" class report --pdf "$work/r.pdf" > /dev/null || fail "pdf"
head -c 5 "$work/r.pdf" | grep -q '%PDF-' || fail "pdf file"
# Every output asked for is written (issue 38: --html F --pdf G wrote only
# the PDF, --csv --html F only the CSV); what went to a file is said on the
# standard error when the CSV is on the standard output.
rm -f "$work/r.html" "$work/r.pdf"
"$bin" "${db[@]}" class report --html "$work/r.html" --pdf "$work/r.pdf" > "$work/out" || fail "html and pdf"
grep -q '</html>' "$work/r.html" || fail "--html F --pdf G: no HTML"
head -c 5 "$work/r.pdf" | grep -q '%PDF-' || fail "--html F --pdf G: no PDF"
[ "$(grep -c 'the report written to' "$work/out")" = 2 ] || fail "$(cat "$work/out")"
rm -f "$work/r.html" "$work/r.pdf"
"$bin" "${db[@]}" class report --csv --html "$work/r.html" --pdf "$work/r.pdf" > "$work/out" 2> "$work/err" || fail "csv, html and pdf"
grep -q '</html>' "$work/r.html" || fail "--csv --html F: no HTML"
head -c 5 "$work/r.pdf" | grep -q '%PDF-' || fail "--csv --pdf G: no PDF"
head -1 "$work/out" | grep -q "^exercise,student,attempts," || fail "$(cat "$work/out")"
grep -q 'written' "$work/out" && fail "the CSV carries a message: $(cat "$work/out")"
[ "$(grep -c 'the report written to' "$work/err")" = 2 ] || fail "$(cat "$work/err")"
"$bin" "${db[@]}" class report --csv --html - > /dev/null 2>&1
[ $? = 64 ] || fail "--csv with --html - should be a usage error"
"$bin" "${db[@]}" class report --pdf /nonexistent/dir/r.pdf 2> /dev/null
[ $? = 73 ] || fail "a PDF that cannot be written should exit 73"
"$bin" "${db[@]}" class rapport 2> /dev/null
[ $? = 64 ] || fail "class rapport should be a usage error"
# On one PC, class init makes the teacher's key, apart from the class key:
# from then on exercise truth needs it, and a student's own key is refused.
"$bin" "${db[@]}" class init > "$work/out" || fail "class init on a file: $(cat "$work/out")"
grep -q "the teacher's key is $work/config/pupitre/teacher.key" "$work/out" || fail "$(cat "$work/out")"
[ "$(stat -c %a "$work/config/pupitre/teacher.key")" = 600 ] || fail "the teacher's key is not 0600"
"$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann > /dev/null || fail "truth with the teacher's key"
PUPITRE_TEACHER_KEY=$work/student.key "$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann 2> "$work/err"
[ $? = 77 ] || fail "truth without the teacher's key should exit 77"
grep -q "exercise truth needs this store's teacher's key" "$work/err" || fail "$(cat "$work/err")"
echo "0123456789abcdef0123" > "$work/student.key"
PUPITRE_TEACHER_KEY=$work/student.key "$bin" "${db[@]}" exercise truth exam-2005-drawn --student ann 2> /dev/null
[ $? = 77 ] || fail "truth with another key should exit 77"
echo "training cli: ok"
