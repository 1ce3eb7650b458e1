#!/usr/bin/env bash
# What programs read never changes with the language (issue 20): every golden
# case's --trace and --json, and its exit status, are byte-identical under
# LANG=fr_FR.UTF-8 LC_NUMERIC=fr_FR.UTF-8 and in English; the diagnostics keep
# their shape "FILE:LINE: Nn: error CODE: " and only their message is French.
#   golden_fr.sh PUPITRE SOURCE_DIR
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1 root=$2
here=$root/tests/golden
shared=${PUPITRE_SHARED:-$root/../shared}
. "$here/case_args.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A French locale for LC_NUMERIC: the system's, else one generated into a
# private LOCPATH (no root needed); without either, only that part is skipped.
if locale -a 2>/dev/null | grep -qix 'fr_FR\.utf-\?8'; then
    echo "locale fr_FR.UTF-8: the system's"
elif command -v localedef >/dev/null && [ -f /usr/share/i18n/locales/fr_FR ] &&
     mkdir -p "$tmp/loc" && localedef -i fr_FR -f UTF-8 "$tmp/loc/fr_FR.UTF-8" >/dev/null 2>&1; then
    export LOCPATH=$tmp/loc
    echo "locale fr_FR.UTF-8: generated with localedef into $LOCPATH"
else
    echo "SKIP (part): no fr_FR.UTF-8 locale and no localedef with the locales data;" \
         "LC_NUMERIC=fr_FR.UTF-8 is set but not in effect"
fi
if env LC_ALL=fr_FR.UTF-8 locale -k decimal_point 2>/dev/null | grep -q '","'; then
    echo "fr_FR.UTF-8 is in effect: its decimal point is a comma"
fi

english() { env -u LANGUAGE -u LANG -u LC_MESSAGES -u LC_NUMERIC LC_ALL=C.UTF-8 "$@"; }
french() { env -u LANGUAGE -u LC_ALL -u LC_MESSAGES LANG=fr_FR.UTF-8 LC_NUMERIC=fr_FR.UTF-8 "$@"; }
shape() { sed -E 's/((error|warning) [0-9]+): .*/\1:/' "$1"; }

fail=0 cases=0 translated=0
for name in $(grep -E '^[a-z]' "$here/cases.txt" | awk '{print $1}'); do
    ( golden_case "$name" ) >/dev/null 2>&1 || continue   # shared/ missing: the golden test says so
    golden_case "$name"
    cases=$((cases + 1))
    for mode in --trace --json; do
        set +e
        (cd "$here" && english "$bin" run $mode --machine "$machine" "${args[@]}") >"$tmp/en" 2>"$tmp/en.err"
        rc_en=$?
        (cd "$here" && french "$bin" run $mode --machine "$machine" "${args[@]}") >"$tmp/fr" 2>"$tmp/fr.err"
        rc_fr=$?
        set -e
        if ! cmp -s "$tmp/en" "$tmp/fr"; then
            echo "$name run $mode: the output differs in French:"; diff "$tmp/en" "$tmp/fr" | head -5; fail=1
        fi
        [ "$rc_en" = "$rc_fr" ] || { echo "$name $mode: exit $rc_en in English, $rc_fr in French"; fail=1; }
        if ! diff <(shape "$tmp/en.err") <(shape "$tmp/fr.err") >/dev/null; then
            echo "$name $mode: the diagnostics' shape differs in French:"
            diff <(shape "$tmp/en.err") <(shape "$tmp/fr.err") | head -5; fail=1
        fi
        cmp -s "$tmp/en.err" "$tmp/fr.err" || translated=$((translated + 1))
    done
done
echo "$cases cases, $translated runs whose diagnostics were translated"
[ "$cases" -gt 0 ] || { echo "SKIP: no golden case could run (shared/ missing)"; exit 77; }
[ "$translated" -gt 0 ] || { echo "no diagnostic was translated: is the French catalogue built?"; fail=1; }
exit $fail
