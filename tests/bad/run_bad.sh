#!/usr/bin/env bash
# Runs one bad program of tests/bad and checks the NUM error it states on its
# first line (ARCHITECTURE.md, Conventions): the living catalogue of the errors pupitre raises.
#
# Usage: run_bad.sh PUPITRE_BINARY FILE.iso
#
# Header: the comment-only lines before the first '%' line.
#   (EXPECT <code> [N<n>] [COL<c>])  required, on line 1: the error number, the N
#                               of the block that raises it when it has one, and
#                               the column of the word at fault when it names one
#   (MACHINE <name>)            lathe, mill, mill4, mill5, or a .machine file of
#                               this directory; default mill
#   (ARGS <words>)              more options for `pupitre check` (split on blanks)
#   (WITH <file.iso> ...)       companion files of this directory loaded as program
#                               memory (subprograms called by G77 H)
#   (COMPANION)                 on line 1 instead of EXPECT: not a test, skipped
#
# Passes iff `pupitre check` exits 1 (65 for 1002 and 1003, errors found while
# loading the file) and stderr has a diagnostic line of the file or one of its
# companions, `FILE:LINE[:COL]: [N<n>: ]error <code>: ...`, with `N<n>:` and the
# column on that same line when the header gives them (pupitre(1), DIAGNOSTICS).
set -u

if [[ $# -ne 2 ]]; then
    echo "usage: run_bad.sh PUPITRE_BINARY FILE.iso" >&2
    exit 2
fi
pupitre=$1
file=$2
[[ $pupitre == /* ]] || pupitre=$PWD/$pupitre
[[ -x $pupitre ]] || { echo "run_bad.sh: $pupitre is not an executable" >&2; exit 2; }
[[ -f $file ]] || { echo "run_bad.sh: no file $file" >&2; exit 2; }
dir=$(cd "$(dirname "$file")" && pwd)
base=$(basename "$file")

expect_code='' expect_n='' machine=mill
args=() with=()
lineno=0
# Read the header as bytes up to the first non-comment line; `tr` keeps a NUL
# byte (1002) from confusing `read`.
while IFS= read -r line; do
    lineno=$((lineno + 1))
    line=${line%$'\r'}
    [[ $line == '('*')' ]] || break
    body=${line#(}
    body=${body%)}
    read -r key rest <<<"$body"
    if [[ $lineno -eq 1 ]]; then
        case $key in
            COMPANION) echo "$base: companion file, not a test"; exit 0 ;;
            EXPECT) ;;
            *) echo "$base: line 1 must be (EXPECT <code> [N<n>] [COL<c>]) or (COMPANION)" >&2; exit 2 ;;
        esac
    fi
    case $key in
        EXPECT)
            read -r expect_code expect_n expect_col extra <<<"$rest"
            if [[ $expect_n == COL* ]]; then expect_col=$expect_n expect_n=''; fi
            if [[ ! $expect_code =~ ^[0-9]+$ || ( -n $expect_n && ! $expect_n =~ ^N[0-9]+$ ) ||
                  ( -n $expect_col && ! $expect_col =~ ^COL[0-9]+$ ) || -n $extra ]]; then
                echo "$base: bad header: $line" >&2
                exit 2
            fi
            ;;
        MACHINE) machine=$rest ;;
        ARGS) read -r -a more <<<"$rest"; args+=("${more[@]}") ;;
        WITH) read -r -a more <<<"$rest"; with+=("${more[@]}") ;;
        *) ;;  # an ordinary comment before the program
    esac
done < <(tr '\0' ' ' <"$file")

if [[ -z $expect_code ]]; then
    echo "$base: line 1 must be (EXPECT <code> [N<n>] [COL<c>])" >&2
    exit 2
fi
# A profile shipped with the tests (mill1020.machine) is found in this directory.
[[ -f $dir/$machine ]] && machine=$dir/$machine
for c in "${with[@]+"${with[@]}"}"; do
    [[ -f $dir/$c ]] || { echo "$base: companion $c not found in $dir" >&2; exit 2; }
done

case $expect_code in
    1002 | 1003) expect_status=65 ;;  # refused while loading (sysexits EX_DATAERR)
    *) expect_status=1 ;;
esac

cmd=("$pupitre" check --machine "$machine" "${args[@]+"${args[@]}"}" "$base" "${with[@]+"${with[@]}"}")
err=$(cd "$dir" && "${cmd[@]}" 2>&1 >/dev/null)
status=$?

# The diagnostic must name this file or one of its companions.
found=0
while IFS= read -r d; do
    for f in "$base" "${with[@]+"${with[@]}"}"; do
        [[ $d == "$f:"* ]] || continue
        rest=${d#"$f:"}
        [[ $rest =~ ^[0-9]+(:([0-9]+))?:\ (N([0-9]+):\ )?error\ ([0-9]+): ]] || continue
        [[ ${BASH_REMATCH[5]} == "$expect_code" ]] || continue
        if [[ -n $expect_n && "N${BASH_REMATCH[4]}" != "$expect_n" ]]; then continue; fi
        if [[ -n $expect_col && "COL${BASH_REMATCH[2]}" != "$expect_col" ]]; then continue; fi
        found=1
    done
done <<<"$err"

if [[ $status -eq $expect_status && $found -eq 1 ]]; then
    echo "$base: ok (error $expect_code${expect_n:+ at $expect_n}${expect_col:+ $expect_col})"
    exit 0
fi
{
    echo "FAIL $base"
    echo "  command:  (cd $dir && ${cmd[*]})"
    echo "  expected: exit $expect_status, a line '$base:LINE${expect_col:+:${expect_col#COL}}: ${expect_n:+$expect_n: }error $expect_code: ...'"
    echo "  actual:   exit $status, stderr:"
    if [[ -n $err ]]; then sed 's/^/    /' <<<"$err"; else echo "    (empty)"; fi
} >&2
exit 1
