#!/usr/bin/env bash
# `pupitre plot` end to end (issue 7): runs one case of cases.txt, checks that
# the SVG is well-formed XML, that it matches tests/plot/golden/NAME.svg (with
# --bless, rewrites it), that its exit status is the one of `run`, and that
# every feed move of `pupitre run --trace` ends on a point of the drawing (and
# every programmed point drawn is a point of the trace) to 1e-3 mm.
#   plot.sh PUPITRE NAME [--bless]
# PUPITRE_PLOT, when set, is the command that plots instead of "PUPITRE plot".
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
bin=$1 name=$2 bless=${3:-}
[ "${PUPITRE_BLESS:-}" = 1 ] && bless=--bless  # the one bless switch, as for the snapshots
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
shared=${PUPITRE_SHARED:-$root/../shared}
command -v python3 >/dev/null || { echo "plot: python3 is needed" >&2; exit 77; }
. "$root/tests/golden/case_args.sh"
golden_case "$name"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -n "${PUPITRE_PLOT:-}" ]; then read -r -a plot <<<"$PUPITRE_PLOT"; else plot=("$bin" plot); fi
set +e
"${plot[@]}" --machine "$machine" --svg "$work/out.svg" "${args[@]}" 2>"$work/plot.err"
plot_rc=$?
"$bin" run --trace --machine "$machine" "${args[@]}" >"$work/trace.jsonl" 2>"$work/run.err"
run_rc=$?
set -e
if [ "$plot_rc" != "$run_rc" ]; then
    echo "plot: exit $plot_rc, but run exits $run_rc" >&2
    cat "$work/plot.err" >&2
    exit 1
fi
if ! diff -u "$work/run.err" "$work/plot.err" >&2; then
    echo "plot: the diagnostics differ from run's" >&2
    exit 1
fi
python3 - "$work/out.svg" "$work/trace.jsonl" <<'PY'
import json, math, re, sys
import xml.etree.ElementTree as ET

svg, trace = sys.argv[1], sys.argv[2]
ns = {"s": "http://www.w3.org/2000/svg"}
root = ET.parse(svg).getroot()  # fails loudly on malformed XML
desc = root.find("s:desc", ns).text
plane = re.search(r"plane (XY|XZ|YZ|ZX)", desc).group(1)
lathe = "lathe:" in desc
h, v = plane[0], plane[1]

def project(to):
    """A trace point as the drawing's (x, y): y = -vertical, lathe X a radius."""
    val = lambda a: to[a] / 2 if (lathe and a == "X") else to[a]
    return (val(h), -val(v))

moves = [json.loads(l) for l in open(trace) if l.startswith('{"ev":"move"')]
trace_pts = [project(m["to"]) for m in moves]
close = lambda p, q: abs(p[0] - q[0]) <= 1e-3 and abs(p[1] - q[1]) <= 1e-3

def points(d):
    """[command, (x, y), start, arc] of each end point of a path's data; arc is
    (r, large, sweep) for an A."""
    toks = re.findall(r"[MLAHVZ]|-?\d+(?:\.\d+)?", d)
    out, i, cur = [], 0, (0.0, 0.0)
    while i < len(toks):
        c = toks[i]; i += 1
        start, arc = cur, None
        if c in "ML":
            cur = (float(toks[i]), float(toks[i + 1])); i += 2
        elif c == "A":
            arc = (float(toks[i]), int(toks[i + 3]), int(toks[i + 4]))
            cur = (float(toks[i + 5]), float(toks[i + 6])); i += 7
        elif c == "H":
            cur = (float(toks[i]), cur[1]); i += 1
        elif c == "V":
            cur = (cur[0], float(toks[i])); i += 1
        else:
            continue
        out.append([c, cur, start, arc])
    return out

def svg_centre(p0, p1, arc):
    """The centre of an SVG arc from its end points and flags (SVG 1.1 F.6.5)."""
    r, large, sweep = arc
    hx, hy = (p0[0] - p1[0]) / 2, (p0[1] - p1[1]) / 2
    d2 = hx * hx + hy * hy
    k = math.sqrt(max(0.0, (r * r - d2) / d2)) if d2 > 0 else 0.0
    if large == sweep:
        k = -k
    return (k * hy + (p0[0] + p1[0]) / 2, -k * hx + (p0[1] + p1[1]) / 2)

drawn, programmed, arcs = [], [], []
for layer in ("rapid", "feed", "comp", "travel", "gouge"):
    g = root.find(f".//s:g[@id='{layer}']", ns)
    assert g is not None, f"no layer {layer}"
    for path in g.findall("s:path", ns):
        pts = points(path.get("d"))
        drawn += [p[1] for p in pts]
        if layer == "rapid":
            continue
        if path.get("class") == "arc":  # an arc split or drawn as a polyline: its end only
            programmed.append(pts[-1][1])
            continue
        programmed += [p[1] for p in pts if p[0] in "LA"]
        arcs += [p for p in pts if p[0] == "A"]

def index(pts):
    grid = {}
    for p in pts:
        grid.setdefault((round(p[0], 2), round(p[1], 2)), []).append(p)
    return grid

def found(p, grid):
    for dx in (-0.01, 0, 0.01):
        for dy in (-0.01, 0, 0.01):
            for q in grid.get((round(p[0] + dx, 2), round(p[1] + dy, 2)), []):
                if close(p, q):
                    return True
    return False

dgrid, tgrid = index(drawn), index(trace_pts)
errors = []
prev = None
for m, p in zip(moves, trace_pts):
    flat = prev is not None and close(p, prev)
    if m["g"] in (1, 2, 3) and not flat and not found(p, dgrid):
        errors.append(f"trace line {m['line']}: feed move to {p} is not in the drawing")
    prev = p
for p in programmed:
    if not found(p, tgrid):
        errors.append(f"drawing point {p} is no move's end in the trace")
# Each SVG arc turns about the centre of an arc of the trace ending there (its
# flags give the side): the sweep is right, not only the end points.
centres = {}
for m, p in zip(moves, trace_pts):
    c = m.get("center")
    if c and h in c and v in c:
        centres.setdefault((round(p[0], 2), round(p[1], 2)), []).append(project(c))
for _, end, start, arc in arcs:
    if arc[0] < 1e-3 or close(start, end):
        continue
    c = svg_centre(start, end, arc)
    want = centres.get((round(end[0], 2), round(end[1], 2)), [])
    if not any(abs(c[0] - q[0]) <= 2e-3 and abs(c[1] - q[1]) <= 2e-3 for q in want):
        errors.append(f"arc to {end}: centre {c} on the drawing, {want} in the trace")
if errors:
    print("\n".join(errors[:20]), file=sys.stderr)
    sys.exit(1)
print(f"plot: {len(moves)} moves, {len(programmed)} programmed points drawn, plane {plane}: match")
PY
golden=$here/golden/$name.svg
if [ "$bless" = "--bless" ]; then
    cp "$work/out.svg" "$golden"
    echo "blessed $golden"
    exit 0
fi
[ -f "$golden" ] || { echo "plot: $golden missing (run with --bless after review)" >&2; exit 1; }
if ! diff -u "$golden" "$work/out.svg" >&2; then
    echo "plot: $name differs from $golden (rerun with --bless if the change is intended)" >&2
    exit 1
fi
