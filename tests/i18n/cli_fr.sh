#!/usr/bin/env bash
# The command line in French (issue 20): --help's own words, CLI11's common
# errors with their exit status, an unknown language, the shipped profile's
# description in a plot; the same commands in English keep CLI11's texts.
#   cli_fr.sh PUPITRE SOURCE_DIR
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1 root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
# expect EXIT REGEX -- ARGS: the exit status, and REGEX in stdout+stderr.
# The tests run with LANGUAGE=en; the cases that want French say so.
expect() {
    local want=$1 re=$2 rc
    shift 3
    "$bin" "$@" >"$tmp/out" 2>&1
    rc=$?
    if [ "$rc" != "$want" ] || ! grep -Eq -- "$re" "$tmp/out"; then
        echo "FAIL: pupitre $* -> exit $rc (want $want), no /$re/ in:"; cat "$tmp/out"; fail=1
    fi
}
expect 0 '^Commandes:' -- --lang fr --help
expect 0 '^Utilisation: ' -- --lang fr run --help
expect 64 'files est obligatoire' -- --lang fr run
expect 64 'Lancer avec --help pour en savoir plus' -- --lang fr run
expect 66 "files: Le fichier n'existe pas : nothere.iso" -- --lang fr run nothere.iso
expect 64 'Conversion impossible : --max-blocks = abc' -- --lang fr run --max-blocks abc "$root/data/demo/lathe_p300.iso"
expect 64 'Argument inattendu : extra' -- --lang fr list extra
LANGUAGE=fr LANG=C.UTF-8 expect 64 "pas de catalogue pour la langue « de » \(disponibles : en, fr\)" -- --lang de --help
expect 64 "no catalogue for the language 'de' \(available: en, fr\)" -- --lang de --help
expect 0 "centre d&apos;usinage NUM 1060 M, 3 axes" -- --lang fr plot --machine mill --svg - "$root/data/demo/mill_p300_g19.iso"
# English: CLI11's own texts.
expect 0 '^Subcommands:' -- --help
expect 64 '^files is required' -- run
expect 66 'files: File does not exist: nothere.iso' -- run nothere.iso
expect 64 'The following argument was not expected: extra' -- list extra
exit $fail
