#!/usr/bin/env bash
# A short fuzzing pass for CI: seeds from the golden programs, the handbook
# corpus and the inputs fuzzing once found (tests/fuzz/programs) (or, for the
# key decoder, terminal key sequences; for the workshop's setup files, the
# shipped setups and tests/fuzz/setups), then SECONDS of mutation. Fails on
# any crash, leak or sanitizer report.
#   smoke.sh FUZZ_BINARY [SECONDS] [programs|keys|setups]
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1 secs=${2:-45} kind=${3:-programs}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
if [ "$kind" = keys ]; then
    # Four bytes of chunk sizes, then what xterm, the Linux console and rxvt send.
    i=0
    for seq in '\033OP' '\033[15~' '\033[1;5C' '\033[[A' '\033[Z' 'G0 X10\r' '\303\251\342\202\254' \
               '\033\033[A' '\033[24;2~' '\033Oa' '\033[200~x' '\x7f\x03\x1b'; do
        printf "\x03\x05\x81\x02$seq" >"$corpus/seed$i"
        i=$((i + 1))
    done
elif [ "$kind" = setups ]; then
    # The shipped setup, the handbook's %555 blank and small bad files.
    cp "$root"/data/setups/*.setup "$root"/tests/workshop/*.setup "$here"/setups/*.setup "$corpus"/
else
    cp "$root"/tests/golden/programs/*.iso "$root"/data/demo/*.iso "$here"/programs/*.iso "$corpus"/
    [ -d "$root/tests/bad" ] && cp "$root"/tests/bad/*.iso "$corpus"/ 2>/dev/null || true
    [ -d "$root/../shared/programs" ] && cp "$root"/../shared/programs/*.iso "$corpus"/
fi
# Crash, leak and slow-unit artifacts go beside the binary, not into the
# working copy (libFuzzer writes them to the current directory by default).
artifacts=$(dirname "$bin")/fuzz-artifacts/
mkdir -p "$artifacts"
dict=()
[ "$kind" = programs ] && dict=(-dict="$here/num.dict")
[ "$kind" = setups ] && dict=(-dict="$here/setup.dict")
"$bin" "${dict[@]}" -artifact_prefix="$artifacts" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 "$corpus" 2>&1 | tail -n 15
echo "fuzz smoke: no crash in ${secs}s"
