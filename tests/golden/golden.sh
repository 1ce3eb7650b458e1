#!/usr/bin/env bash
# Golden trace test (LinuxCNC tests/interp style): runs one case of cases.txt and
# compares `pupitre run --trace` (stdout), the diagnostics (stderr) and the exit
# status with tests/golden/expected/NAME.out. With --bless, rewrites the file.
#   golden.sh PUPITRE NAME [--bless]
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1 name=$2 bless=${3:-}
[ "${PUPITRE_BLESS:-}" = 1 ] && bless=--bless  # the one bless switch, as for the snapshots
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
shared=${PUPITRE_SHARED:-$root/../shared}
. "$here/case_args.sh"
golden_case "$name"
actual=$(mktemp)
trap 'rm -f "$actual" "$actual.err"' EXIT
set +e
(cd "$here" && "$bin" run --trace --machine "$machine" "${args[@]}") >"$actual" 2>"$actual.err"
rc=$?
set -e
{
    cat "$actual"
    # Paths in diagnostics are made relative so the files do not depend on the checkout.
    sed -e "s|$shared/programs/||g" -e "s|$here/programs/||g" "$actual.err" | sed 's/^/stderr: /'
    echo "exit: $rc"
} >"$actual.full"
mv "$actual.full" "$actual"
expected=$here/expected/$name.out
if [ "$bless" = "--bless" ]; then
    cp "$actual" "$expected"
    echo "blessed $expected"
    exit 0
fi
[ -f "$expected" ] || { echo "golden: $expected missing (run with --bless after review)" >&2; exit 1; }
if ! diff -u "$expected" "$actual" >&2; then
    echo "golden: $name differs from $expected (rerun with --bless if the change is intended)" >&2
    exit 1
fi
