#!/usr/bin/env bash
# Runs one warning program of tests/warn and its corrected twin (issue 19): the
# catalogue of the quiet mistakes pupitre names.
#
# Usage: run_warn.sh PUPITRE_BINARY FILE.iso
#
# Header: comment-only lines before the first '%' line.
#   (WARN <code> N<n>)   required, on line 1: the warning and the block raising it
#   (MACHINE <name>)     lathe, mill, mill4, mill5; default lathe
#   (ARGS <words>)       more options for `pupitre check` and `pupitre run`
#
# Passes iff `pupitre check FILE` exits 0 and prints that warning at that block,
# `pupitre run --json FILE` lists it, and the twin FILE with .ok.iso for .iso
# runs to its end with no diagnostic at all (check and run, empty stderr).
# SPDX-License-Identifier: GPL-3.0-or-later
set -u
pupitre=$1 file=$2
[[ $pupitre == /* ]] || pupitre=$PWD/$pupitre
dir=$(cd "$(dirname "$file")" && pwd)
base=$(basename "$file")
twin=${base%.iso}.ok.iso
code='' n='' machine=lathe args=()
while IFS= read -r line; do
    case $line in
        '(WARN '*) read -r _ code n <<<"${line#(}"; n=${n%)} ;;
        '(MACHINE '*) machine=${line#(MACHINE }; machine=${machine%)} ;;
        '(ARGS '*) a=${line#(ARGS }; read -r -a args <<<"${a%)}" ;;
        '%'*) break ;;
    esac
done <"$dir/$base"
[[ -n $code && -n $n ]] || { echo "$base: no (WARN <code> N<n>) header" >&2; exit 2; }
[[ -f $dir/$twin ]] || { echo "$base: no corrected twin $twin" >&2; exit 1; }
cd "$dir"
fail=0
err=$("$pupitre" check --machine "$machine" "${args[@]}" "$base" 2>&1 >/dev/null); rc=$?
[[ $rc -eq 0 ]] || { echo "$base: check exits $rc, not 0: $err"; fail=1; }
grep -Eq "^$base:[0-9]+:([0-9]+:)? $n: warning $code: " <<<"$err" ||
    { echo "$base: no 'warning $code' at $n in: $err"; fail=1; }
json=$("$pupitre" run --json --machine "$machine" "${args[@]}" "$base" 2>/dev/null)
grep -Eq "\"warnings\":\[.*\"code\":$code[,}]" <<<"$json" ||
    { echo "$base: run --json lists no warning $code: $json"; fail=1; }
for cmd in check run; do
    err=$("$pupitre" $cmd --machine "$machine" "${args[@]}" "$twin" 2>&1 >/dev/null); rc=$?
    [[ $rc -eq 0 && -z $err ]] || { echo "$twin: $cmd exits $rc with: $err"; fail=1; }
done
exit $fail
