#!/usr/bin/env bash
# The golden list of warnings (issue 19): `pupitre check` on every program of
# ../shared/programs (machine from its INDEX.tsv) and of tests/golden/programs
# (machine from cases.txt), one line per warning: FILE N<n> CODE. Compared
# with warnings.txt, reviewed by hand; --bless rewrites it.
#   warnings.sh PUPITRE [--bless]
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1 bless=${2:-}
[ "${PUPITRE_BLESS:-}" = 1 ] && bless=--bless  # the one bless switch, as for the snapshots
here=$(cd "$(dirname "$0")" && pwd)
shared=${PUPITRE_SHARED:-$here/../../../shared}/programs
[ -f "$shared/INDEX.tsv" ] || { echo "warnings: $shared missing (a corpus sweep)" >&2; exit 77; }
list() {  # DIR FILE MACHINE
    (cd "$1" && "$bin" check --machine "$3" "$2" 2>&1 >/dev/null || true) |
        sed -n -E 's/^([^:]*):[0-9]+:[0-9:]* (N[0-9]+: )?warning ([0-9]+):.*/\1 \2\3/p' | sed 's/: / /'
}
actual=$(mktemp)
trap 'rm -f "$actual"' EXIT
{
    tail -n +2 "$shared/INDEX.tsv" | while IFS=$'\t' read -r file _ _ machine _; do
        case $machine in lathe | mill) ;; 4axis) machine=mill4 ;; *) continue ;; esac
        list "$shared" "$file" "$machine"
    done
    grep -E '^[a-z]' "$here/cases.txt" | while read -r _ machine rest; do
        for w in $rest; do
            # The copies of shared programs are listed with the corpus above.
            case $w in local:*) [ -f "$shared/${w#local:}" ] || list "$here/programs" "${w#local:}" "$machine" ;; esac
        done
    done | sort -u
} >"$actual"
if [ "$bless" = --bless ]; then
    cp "$actual" "$here/warnings.txt"
    echo "blessed $here/warnings.txt"
    exit 0
fi
diff -u "$here/warnings.txt" "$actual"
