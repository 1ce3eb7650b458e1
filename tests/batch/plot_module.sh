#!/usr/bin/env bash
# The plot module (issue 14, pupitre(1) FILES): Cairo's libraries are loaded by
# the commands that write a PNG or a PDF only; without the module those say
# why and write nothing, and the SVG is still written.
#   plot_module.sh PUPITRE_BINARY
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
prog=$root/data/demo/lathe_p300.iso

# The executable itself needs no Cairo, and a run loads none.
ldd "$bin" | grep -q 'libcairo' && fail "the executable links Cairo: $(ldd "$bin" | grep cairo)"
LD_DEBUG=files "$bin" run "$prog" >/dev/null 2>"$work/ld" || fail "run: exit $?"
grep -q 'libcairo' "$work/ld" && fail "pupitre run loaded Cairo"

# plot --png and --pdf load it and write real pictures.
"$bin" plot --png "$work/p.png" --pdf "$work/p.pdf" "$prog" 2>"$work/err" || fail "plot: $(cat "$work/err")"
[ "$(head -c 8 "$work/p.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "not a PNG"
head -c 5 "$work/p.pdf" | grep -q '%PDF-' || fail "not a PDF"

# Without the module: the PNG is refused with the reason, the SVG is written.
PUPITRE_PLOT_MODULE=$work/missing.so "$bin" plot --svg "$work/q.svg" --png "$work/q.png" "$prog" 2>"$work/err"
[ $? -ne 0 ] || fail "plot --png without the module should fail"
grep -q "cannot write the PNG: .*missing.so not found (PUPITRE_PLOT_MODULE)" "$work/err" ||
    fail "the reason should be given: $(cat "$work/err")"
[ -s "$work/q.svg" ] || fail "the SVG needs no module and should be written"
[ -e "$work/q.png" ] && fail "no PNG should be left behind"
# A file that is not the module: dlopen's reason.
echo 'not a library' >"$work/bad.so"
PUPITRE_PLOT_MODULE=$work/bad.so "$bin" plot --pdf "$work/r.pdf" "$prog" 2>"$work/err"
[ $? -ne 0 ] || fail "plot --pdf with a broken module should fail"
grep -q "cannot write the PDF: .*bad.so" "$work/err" || fail "dlopen's reason: $(cat "$work/err")"
# The machining centre's part as a PNG (--part-out; :part export in the
# console): without the module, the reason, and no file.
printf '%%1\nN10 G0 X0 Y0 Z50\nN20 M2\n' >"$work/m.iso"
PUPITRE_PLOT_MODULE=$work/missing.so "$bin" run --machine mill --setup mill --part-out "$work/part.png" \
    "$work/m.iso" >/dev/null 2>"$work/err"
[ $? -ne 0 ] || fail "--part-out PNG without the module should fail"
grep -q "cannot write .*part.png: .*missing.so not found" "$work/err" || fail "--part-out: $(cat "$work/err")"
[ -e "$work/part.png" ] && fail "no part PNG should be left behind"
"$bin" run --machine mill --setup mill --part-out "$work/part.png" "$work/m.iso" >/dev/null 2>"$work/err" ||
    fail "--part-out with the module: $(cat "$work/err")"
[ -s "$work/part.png" ] || fail "--part-out with the module wrote no PNG"
echo ok
