#!/usr/bin/env bash
# The tree stays formatted with the repository's .clang-format (issue 13 item
# 8): clang-format --dry-run --Werror over every C++ source and header under
# core, console, pages, store and tests. A failure names the files; fix with
#   clang-format -i FILE...
# Needs clang-format (scripts/test installs it); exit 77 when it is missing.
#   format.sh SOURCE_DIR
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
root=$1
command -v clang-format >/dev/null || { echo "clang-format is not installed (scripts/test installs it)"; exit 77; }
cd "$root" || exit 1
mapfile -t files < <(find core console pages store tests \( -name '*.cpp' -o -name '*.hpp' \) | sort)
[ ${#files[@]} -gt 100 ] || { echo "FAIL: only ${#files[@]} sources found under $root"; exit 1; }
bad=$(clang-format --dry-run --Werror "${files[@]}" 2>&1 | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error:.*/\1/p' | sort -u)
if [ -n "$bad" ]; then
    echo "FAIL: not formatted with .clang-format (clang-format -i these files):"
    echo "$bad"
    exit 1
fi
echo "ok: ${#files[@]} files formatted"
