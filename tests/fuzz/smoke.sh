#!/usr/bin/env bash
# A short fuzzing pass for CI: seeds from the golden programs and the handbook
# corpus, then SECONDS of mutation. Fails on any crash, leak or sanitizer report.
#   smoke.sh FUZZ_BINARY [SECONDS]
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1 secs=${2:-45}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp "$root"/tests/golden/programs/*.iso "$root"/data/demo/*.iso "$corpus"/
[ -d "$root/tests/bad" ] && cp "$root"/tests/bad/*.iso "$corpus"/ 2>/dev/null || true
[ -d "$root/../shared/programs" ] && cp "$root"/../shared/programs/*.iso "$corpus"/
"$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 "$corpus" 2>&1 | tail -n 15
echo "fuzz smoke: no crash in ${secs}s"
