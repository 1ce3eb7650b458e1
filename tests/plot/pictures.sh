#!/usr/bin/env bash
# `pupitre plot --svg --png --pdf` end to end (issue 12.11): one scene, three
# files. A lathe and a mill program (copies of the handbook programs 004_p555.iso
# and 000_p200_boitier.iso in tests/plot/programs/) give a PNG of the width
# asked, a one-page PDF and an SVG with its layers and the marks around them
# (title, axis arrows, scale bar, legend, notes); each file alone works; an
# output that cannot be created exits 73 and leaves the others alone.
#   pictures.sh PUPITRE
# SPDX-License-Identifier: GPL-3.0-or-later
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
command -v python3 >/dev/null || { echo "pictures: python3 is needed" >&2; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

check_files() {  # NAME: the three files of one run
    local n=$1
    python3 - "$work/$n" <<'PY' || exit 1
import struct, sys
import xml.etree.ElementTree as ET
base = sys.argv[1]
png = open(base + ".png", "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = struct.unpack(">II", png[16:24])
assert w == 1600 and 200 < h < 4000, f"PNG {w}x{h}"
pdf = open(base + ".pdf", "rb").read()
assert pdf.startswith(b"%PDF-") and b"%%EOF" in pdf[-32:], "not a PDF"
assert b"/Count 1" in pdf, "one page"
ns = {"s": "http://www.w3.org/2000/svg"}
root = ET.parse(base + ".svg").getroot()
for gid in ("rapid", "feed", "comp", "travel", "gouge", "title", "axes", "scale-bar", "legend", "notes"):
    assert root.find(f".//s:g[@id='{gid}']", ns) is not None, f"SVG: no group {gid}"
words = " ".join(t.text or "" for t in root.iter("{http://www.w3.org/2000/svg}text"))
for want in ("legend", "feed G1 G2 G3", "rapid G0", "frame fitted to the cutting moves", " mm"):
    assert want in words, f"SVG: no text '{want}'"
assert root.find(".//s:clipPath[@id='window']", ns) is not None, "SVG: no clip path"
print(f"{base}: PNG {w}x{h}, PDF {len(pdf)} bytes, SVG with its marks")
PY
}

"$bin" plot --machine lathe --svg "$work/p555.svg" --png "$work/p555.png" --pdf "$work/p555.pdf" \
    "$here/programs/p555.iso" 2>"$work/err" || fail "p555: exit $? $(cat "$work/err")"
check_files p555
grep -q 'id="mirror"' "$work/p555.svg" || fail "p555: the lathe's mirror image"
grep -q '>spindle axis<' "$work/p555.svg" || fail "p555: the spindle axis in the legend"
grep -q '>stock (G64)<' "$work/p555.svg" || fail "p555: the stock in the legend"

"$bin" plot --machine mill --set D3.R=8 --svg "$work/p200.svg" --png "$work/p200.png" \
    --pdf "$work/p200.pdf" "$here/programs/p200_boitier.iso" 2>"$work/err" ||
    fail "p200: exit $? $(cat "$work/err")"
check_files p200

# Each picture alone; the PDF's page is the scene's, in points (A4-ish).
"$bin" plot --pdf "$work/alone.pdf" "$here/programs/p555.iso" 2>/dev/null || fail "--pdf alone: exit $?"
[ -s "$work/alone.pdf" ] && [ ! -e "$work/alone.svg" ] || fail "--pdf alone"
"$bin" plot --png "$work/alone.png" "$here/programs/p555.iso" 2>/dev/null || fail "--png alone: exit $?"
cmp -s "$work/alone.png" "$work/p555.png" || fail "the same PNG from the same run"

# An output that cannot be created: 73, and a message naming it.
"$bin" plot --svg "$work/ok.svg" --pdf "$work/no/such/dir.pdf" "$here/programs/p555.iso" 2>"$work/err"
[ $? -eq 73 ] || fail "--pdf into a missing directory should exit 73"
grep -q 'no/such/dir.pdf: cannot create' "$work/err" || fail "the message: $(cat "$work/err")"
# No picture asked: usage.
"$bin" plot "$here/programs/p555.iso" 2>"$work/err"
[ $? -eq 64 ] || fail "plot without an output should exit 64"
grep -q 'needs --svg, --png or --pdf' "$work/err" || fail "the usage message: $(cat "$work/err")"
echo ok
