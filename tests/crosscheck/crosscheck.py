#!/usr/bin/env python3
# crosscheck: run random small milling programs through pupitre and through
# LinuxCNC's rs274 (tools/rs274-peer) and compare them move by move: end points
# and arc centres to 1 µm, arc direction, arc sweep, feed.
#
#   crosscheck.py --pupitre build/pupitre [--count 30] [--seed 1] [--keep DIR]
#   crosscheck.py --peer-only            check the harness: rs274 against the generator
#   crosscheck.py --selftest             check the two parsers on built-in samples
#   crosscheck.py --comp --pupitre build/pupitre [--count 30] [--radius-scale F] [--verbose]
#                                        tool radius compensation G41/G42 on random
#                                        closed contours (see README.md)
#
# Exit 0 all agree, 1 mismatch (report on stdout), 64 usage, 77 skip (rs274
# cannot be set up: no network, package unavailable). Standard library only.
import argparse
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

EXIT_OK, EXIT_FAIL, EXIT_USAGE, EXIT_SKIP = 0, 1, 64, 77
TOL_MM = 0.001 + 1e-6   # 1 µm, plus the last printed digit's rounding
TOL_DEG = 0.001         # sweep; both sides derive it from the same µm points
TOL_FEED = 1e-3

LIM = {"X": 400_000, "Y": 400_000, "Z": 200_000}  # µm
CENTRE_WORD = {"X": "I", "Y": "J", "Z": "K"}
# (first, second, normal) axes of each plane; CCW turns first towards second,
# seen from the normal's positive end (NUM 000:4276-4300; pupitre-iso(5), MOTION; same in RS274).
PLANES = {17: ("X", "Y", "Z"), 18: ("Z", "X", "Y"), 19: ("Y", "Z", "X")}
CANON_PLANE = {"CANON_PLANE_XY": 17, "CANON_PLANE_XZ": 18, "CANON_PLANE_YZ": 19}
NUM_HEADER = "%1"
NGC_HEADER = "G21 G90 G90.1 G17 G94"


def fmt(um):
    """Integer micrometres -> shortest decimal millimetres."""
    sign = "-" if um < 0 else ""
    whole, frac = divmod(abs(um), 1000)
    if frac == 0:
        return f"{sign}{whole}"
    return f"{sign}{whole}.{frac:03d}".rstrip("0")


def sweep_deg(start, end, centre, g):
    """Signed angle (degrees) from start to end about centre, points as (first, second)."""
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    if math.isclose(start[0], end[0], abs_tol=1e-9) and math.isclose(start[1], end[1], abs_tol=1e-9):
        d = 2 * math.pi
    elif g == 3:
        d = (a1 - a0) % (2 * math.pi)
    else:
        d = (a0 - a1) % (2 * math.pi)
    return math.degrees(d) * (1 if g == 3 else -1)


# ---------------------------------------------------------------- generator

class Program:
    """One random program: both dialects' text and the moves it should make."""

    def __init__(self, rng, nmoves):
        self.rng = rng
        self.pos = {}
        self.plane = 17
        self.feed = None
        self.lines = []      # block text, line 2 onwards of both files
        self.expected = []   # normalised moves (see normalise())
        self.nword = 0
        self._build(nmoves)

    def _emit(self, words, move=None):
        self.nword += 10
        self.lines.append(f"N{self.nword} " + " ".join(words))
        if move is not None:
            move["n"] = self.nword
            move["line"] = len(self.lines) + 1
            self.expected.append(move)

    def _feed_words(self, force=False):
        if force or self.feed is None or self.rng.random() < 0.2:
            f = self.rng.randrange(100, 3001, 50)
            if f != self.feed:
                self.feed = f
                return [f"F{f}"]
        return []

    def _mm(self):
        return {a: v / 1000 for a, v in self.pos.items()}

    def _plane_words(self):
        """Sometimes change plane, alone on a block or in front of the move."""
        if self.rng.random() >= 0.2:
            return []
        new = self.rng.choice([p for p in PLANES if p != self.plane])
        self.plane = new
        if self.rng.random() < 0.5:
            self._emit([f"G{new}"])
            return []
        return [f"G{new}"]

    def _target(self, axis, step_mm):
        v = self.pos[axis] + round(self.rng.uniform(-step_mm, step_mm) * 1000)
        return max(-LIM[axis], min(LIM[axis], v))

    def _build(self, nmoves):
        rng = self.rng
        # A known start: pupitre's mill starts at Z200, rs274 at Z0.
        self.pos = {a: rng.randrange(-100, 101) * 1000 for a in "XYZ"}
        self._emit(["G0"] + [f"{a}{fmt(v)}" for a, v in self.pos.items()],
                   {"g": 0, "to": self._mm()})
        for _ in range(nmoves - 1):
            pw = self._plane_words()
            r = rng.random()
            if r < 0.1:
                self._line(pw, 0)
            elif r < 0.5:
                self._line(pw, 1)
            elif not self._arc(pw, rng.choice((2, 3))):
                self._line(pw, 1)

    def _line(self, pw, g):
        axes = self.rng.sample("XYZ", self.rng.randint(1, 3))
        words = pw + [f"G{g}"]
        for a in "XYZ":
            if a in axes:
                self.pos[a] = self._target(a, 50)
                words.append(f"{a}{fmt(self.pos[a])}")
        move = {"g": g, "to": self._mm()}
        if g != 0:
            words += self._feed_words(force=self.feed is None)
            move["feed"] = float(self.feed)
        self._emit(words, move)

    def _arc(self, pw, g):
        rng = self.rng
        first, second, _ = PLANES[self.plane]
        s = (self.pos[first], self.pos[second])
        for _ in range(20):
            r0 = rng.uniform(2.0, 60.0) * 1000
            a = rng.uniform(0, 2 * math.pi)
            c = (s[0] + round(r0 * math.cos(a)), s[1] + round(r0 * math.sin(a)))
            r = math.hypot(s[0] - c[0], s[1] - c[1])
            if abs(c[0]) + r <= LIM[first] and abs(c[1]) + r <= LIM[second]:
                break
        else:
            return False
        sw = math.radians(rng.uniform(15.0, 345.0)) * (1 if g == 3 else -1)
        a0 = math.atan2(s[1] - c[1], s[0] - c[0])
        e = (c[0] + round(r * math.cos(a0 + sw)), c[1] + round(r * math.sin(a0 + sw)))
        self.pos[first], self.pos[second] = e
        # Word order is the same for every plane (X Y Z, I J K): neither dialect cares.
        words = pw + [f"G{g}"]
        words += [f"{a}{fmt(self.pos[a])}" for a in "XYZ" if a in (first, second)]
        cen = {first: c[0], second: c[1]}
        words += [f"{CENTRE_WORD[a]}{fmt(cen[a])}" for a in "XYZ" if a in cen]
        words += self._feed_words(force=self.feed is None)
        self._emit(words, {"g": g, "to": self._mm(),
                           "center": {first: c[0] / 1000, second: c[1] / 1000},
                           "sweep": sweep_deg(s, e, c, g), "feed": float(self.feed)})
        return True

    def num_text(self):
        return "\n".join([NUM_HEADER] + self.lines + ["M2"]) + "\n"

    def ngc_text(self):
        return "\n".join([NGC_HEADER] + self.lines + ["M2"]) + "\n"


# ------------------------------------------------------------------ parsers

# "   15 N20    ARC_FEED(...)"; "N....." when the block has no N; N100000 and
# above run into the call's name ("N100000STRAIGHT_TRAVERSE(").
CANON_RE = re.compile(r"^\s*\d+\s+N(\.+|\d+)\s*([A-Z][A-Z_0-9]*)\((.*)\)\s*$")


def parse_rs274(text):
    """rs274 canonical calls -> normalised moves.

    STRAIGHT_TRAVERSE(x, y, z, a, b, c[, u, v, w]) and STRAIGHT_FEED(same);
    ARC_FEED(first_end, second_end, first_centre, second_centre, rotation,
    normal_end, a, b, c[, u, v, w]) where (first, second, normal) follow the
    plane: XY -> (X, Y, Z), XZ -> (Z, X, Y), YZ -> (Y, Z, X). rotation is +1
    for G3, -1 for G2; |rotation| > 1 adds whole turns.
    """
    moves = []
    plane, feed = 17, None
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    for ln, raw in enumerate(text.splitlines(), 1):
        m = CANON_RE.match(raw)
        if not m:
            continue
        nfield, call, args = m.groups()
        n = int(nfield) if nfield.isdigit() else None
        if call == "SELECT_PLANE":
            plane = CANON_PLANE[args.strip()]
        elif call == "SET_FEED_RATE":
            feed = float(args)
        elif call in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            v = [float(x) for x in args.split(",")]
            pos = {"X": v[0], "Y": v[1], "Z": v[2]}
            mv = {"g": 0 if call == "STRAIGHT_TRAVERSE" else 1, "to": dict(pos), "n": n, "src": ln}
            if mv["g"] == 1:
                mv["feed"] = feed
            moves.append(mv)
        elif call == "ARC_FEED":
            v = [float(x) for x in args.split(",")]
            first, second, normal = PLANES[plane]
            rot = int(v[4])
            g = 3 if rot > 0 else 2
            start = (pos[first], pos[second])
            end, centre = (v[0], v[1]), (v[2], v[3])
            sw = sweep_deg(start, end, centre, g)
            sw += math.copysign(360.0 * (abs(rot) - 1), sw)
            pos = {first: v[0], second: v[1], normal: v[5]}
            moves.append({"g": g, "to": dict(pos), "center": {first: v[2], second: v[3]},
                          "sweep": sw, "feed": feed, "n": n, "src": ln})
        elif call in ("STRAIGHT_PROBE", "RIGID_TAP", "NURBS_FEED", "SPLINE_FEED"):
            raise ValueError(f"rs274 line {ln}: unexpected motion call {call}")
    return moves


def parse_trace(text):
    """pupitre --trace JSON lines (pupitre(1), OUTPUT, Trace) -> normalised moves."""
    moves = []
    for ln, raw in enumerate(text.splitlines(), 1):
        if not raw.strip():
            continue
        try:
            ev = json.loads(raw)
        except json.JSONDecodeError as e:
            raise ValueError(f"trace line {ln}: not JSON ({e.msg}): {raw[:120]}")
        if not isinstance(ev, dict) or "ev" not in ev:
            raise ValueError(f"trace line {ln}: not an event object: {raw[:120]}")
        if ev["ev"] != "move":
            continue
        try:
            mv = {"g": int(ev["g"]), "to": {k: float(x) for k, x in ev["to"].items()},
                  "n": ev.get("n"), "line": ev.get("line"), "src": ln}
            if mv["g"] in (2, 3):
                mv["center"] = {k: float(x) for k, x in ev["center"].items()}
                mv["sweep"] = float(ev["sweep"])
            if mv["g"] != 0 and ev.get("feed") is not None:
                mv["feed"] = float(ev["feed"])
        except (KeyError, TypeError, ValueError) as e:
            raise ValueError(f"trace line {ln}: bad move event ({e!r}): {raw[:120]}")
        moves.append(mv)
    return moves


# --------------------------------------------------------------- comparison

def compare(ref, got, ref_name, got_name, sweep_by_radius=False):
    """Differences between two normalised move lists, as (move index, message).

    sweep_by_radius: the sweep tolerance grows to the angle 1 µm subtends on the
    arc (for arcs of a few tenths of a millimetre, whose sweep rs274 only gives
    through end points printed to 0.1 µm).
    """
    out = []
    if len(ref) != len(got):  # first: a lost or extra move shifts all that follows
        out.append((min(len(ref), len(got)),
                    f"{len(ref)} moves in {ref_name}, {len(got)} in {got_name}"))
    for i, (r, g) in enumerate(zip(ref, got)):
        msgs = []
        if r.get("n") is not None and g.get("n") is not None and r["n"] != g["n"]:
            msgs.append(f"block N{r['n']} in {ref_name}, N{g['n']} in {got_name}")
        if r["g"] != g["g"]:
            msgs.append(f"G{r['g']} in {ref_name}, G{g['g']} in {got_name}")
        for a in "XYZ":
            rv, gv = r["to"].get(a), g["to"].get(a)
            if gv is None or abs(rv - gv) > TOL_MM:
                msgs.append(f"end {a}: {rv:.4f} vs {gv if gv is None else f'{gv:.4f}'}")
        if r["g"] in (2, 3) and g["g"] in (2, 3):
            rc, gc = r["center"], g["center"]
            if set(rc) != set(gc):
                msgs.append(f"centre axes {sorted(rc)} vs {sorted(gc)} (plane?)")
            else:
                for a in rc:
                    if abs(rc[a] - gc[a]) > TOL_MM:
                        msgs.append(f"centre {a}: {rc[a]:.4f} vs {gc[a]:.4f}")
            if (g["sweep"] < 0) != (g["g"] == 2):
                msgs.append(f"{got_name} G{g['g']} with sweep {g['sweep']:.4f}")
            tol = TOL_DEG
            if sweep_by_radius:
                rad = math.dist([g["to"][a] for a in gc], [gc[a] for a in gc]) if set(rc) == set(gc) else 0
                tol += math.degrees(2 * TOL_MM / max(rad, 1e-3))
            if abs(r["sweep"] - g["sweep"]) > tol:
                msgs.append(f"sweep {r['sweep']:.4f} vs {g['sweep']:.4f}")
        if r["g"] != 0 and "feed" in g and r.get("feed") is not None:
            if abs(r["feed"] - g["feed"]) > TOL_FEED:
                msgs.append(f"feed {r['feed']:.4f} vs {g['feed']:.4f}")
        if msgs:
            out.append((i, "; ".join(msgs)))
    return out


# ------------------------------------------------------------------ running

def find_peer(explicit):
    if explicit:
        return explicit if os.path.isfile(explicit) and os.access(explicit, os.X_OK) else None
    here = os.path.dirname(os.path.abspath(__file__))
    cands = [os.environ.get("RS274_PEER"), shutil.which("rs274-peer"),
             os.path.join(here, "..", "..", "scripts", "rs274-peer"),
             "/work/shared/tools/rs274-peer"]
    for c in cands:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    return None


def setup_peer(peer):
    """None if rs274 is ready, else the reason it is not."""
    if peer is None:
        return "rs274-peer not found (give --peer PATH or set RS274_PEER)"
    try:
        p = subprocess.run([peer, "--path"], capture_output=True, text=True, timeout=900)
    except (OSError, subprocess.TimeoutExpired) as e:
        return f"{peer} --path failed: {e}"
    if p.returncode != 0:
        tail = (p.stderr or p.stdout).strip().splitlines()[-5:]
        return f"{peer} --path exited {p.returncode}: " + " | ".join(tail)
    return None


def run(cmd, out_path=None, timeout=120):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        p = subprocess.CompletedProcess(cmd, 124, "", f"timed out after {timeout} s")
    except OSError as e:
        p = subprocess.CompletedProcess(cmd, 126, "", f"cannot run: {e}")
    if out_path:
        with open(out_path, "w") as f:
            f.write(p.stdout)
    return p


def excerpt(lines, line_no):
    if line_no and 1 <= line_no <= len(lines):
        return f"line {line_no}: {lines[line_no - 1]}"
    return ""


def check_one(k, prog, args, peer, work):
    """Run one program through both sides; a list of report lines (empty when they agree)."""
    base = os.path.join(work, f"prog{k:03d}")
    iso, ngc = base + ".iso", base + ".ngc"
    with open(iso, "w") as f:
        f.write(prog.num_text())
    with open(ngc, "w") as f:
        f.write(prog.ngc_text())
    text = [NUM_HEADER] + prog.lines + ["M2"]
    report = []

    p = run([peer, ngc, base + ".canon"])
    if p.returncode != 0:
        return [f"{ngc}: rs274 rejected the program (exit {p.returncode}): "
                + " | ".join(p.stderr.strip().splitlines()[-3:]), "  (a harness bug: fix the generator)"]
    with open(base + ".canon") as f:
        peer_moves = parse_rs274(f.read())
    # The harness itself: rs274 must do what the generator meant.
    for i, msg in compare(prog.expected, peer_moves, "generator", "rs274")[:5]:
        line = prog.expected[i]["line"] if i < len(prog.expected) else None
        report.append(f"{ngc}: harness: move {i + 1}: {msg}  [{excerpt(text, line)}]")
    if report or args.peer_only:
        return report

    p = run([args.pupitre, "run", "--machine", "mill", "--trace", iso], base + ".trace")
    if p.returncode != 0:
        return [f"{iso}: pupitre run exited {p.returncode}"] + \
               ["  " + l for l in p.stderr.strip().splitlines()[:8]]
    try:
        got = parse_trace(p.stdout)
    except ValueError as e:
        return [f"{base}.trace: {e}"]
    for i, msg in compare(peer_moves, got, "rs274", "pupitre")[:args.show]:
        line = prog.expected[i]["line"] if i < len(prog.expected) else None
        report.append(f"{iso}: move {i + 1}: {msg}  [{excerpt(text, line)}]")
    return report


# ------------------------------------------ radius compensation (--comp mode)
#
# Random closed contours in G17, each run once with G41 and once with G42 at a
# tool radius that fits: convex polygons, star-shaped (concave) polygons, and
# "mixed" contours of lines and arcs with tangent joints (exact) and corners.
# The program goes once round the contour and one element more (as
# tests/unit/test_comp.cpp does), so every corner of the contour is joined; the
# two interpreters' entries and exits differ (NUM: the entry ends on the normal
# of the NEXT element; LinuxCNC: on the normal of the entry move, then joins it
# to the first element like any corner), so only the pieces after the first
# element's offset are compared, up to the exit line: the pieces of every
# corner (trim point, connecting arc about the corner), the offset elements, and
# the last element's end on its normal. See README.md for what is left out.

# The standalone rs274 (src/emc/sai) has machine units of inches
# (GET_EXTERNAL_LENGTH_UNITS() = 0.03937007874016 per mm) and reads the tool
# table in machine units: D8 in the table is a radius of 101.6 mm under G21.
SAI_INCH_PER_MM = 0.03937007874016
# Non-tangent joints turn by at least MIN_CORNER: LinuxCNC treats a direction
# change under TOLERANCE_CONCAVE_CORNER = 0.05 rad (2.9°) as tangent (no
# connecting arc, no trim) where NUM joins it like any corner. Tangent joints
# are exact (integer coordinates on Pythagorean directions). Turns above
# MAX_CORNER (near reversals) are left out: LinuxCNC special-cases them ("h" and
# "m" shapes) and NUM's rule there is not documented.
MIN_CORNER = math.radians(4.0)
MAX_CORNER = math.radians(150.0)
COMP_KINDS = ("convex", "star", "mixed")


def _pyth_dirs(maxc=100):
    """Unit vectors (x/c, y/c) with integers x, y, c: the axes and the primitive
    Pythagorean triples up to c = maxc in all eight orientations, as (x, y, c)."""
    dirs = {(1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1)}
    for m in range(2, 11):
        for n in range(1, m):
            if (m - n) % 2 and math.gcd(m, n) == 1 and m * m + n * n <= maxc:
                a, b, c = m * m - n * n, 2 * m * n, m * m + n * n
                for x, y in ((a, b), (b, a)):
                    for sx in (1, -1):
                        for sy in (1, -1):
                            dirs.add((sx * x, sy * y, c))
    return sorted(dirs, key=lambda d: math.atan2(d[1], d[0]))


PYTH = _pyth_dirs()


def _wrap(a):
    """Angle into [-pi, pi)."""
    return (a + math.pi) % (2 * math.pi) - math.pi


def _ang(v):
    return math.atan2(v[1], v[0])


def _unit(v):
    n = math.hypot(v[0], v[1])
    return (v[0] / n, v[1] / n)


class Elem:
    """A contour element in integer micrometres: a line a->b, or an arc a->b
    about c, g 2 (clockwise) or 3 (counter-clockwise)."""

    def __init__(self, a, b, c=None, g=1):
        self.a, self.b, self.c, self.g = a, b, c, g
        self.arc = c is not None

    @property
    def r(self):
        return math.dist(self.a, self.c)

    def sweep(self):
        """Signed sweep in radians (positive counter-clockwise)."""
        a0 = _ang((self.a[0] - self.c[0], self.a[1] - self.c[1]))
        a1 = _ang((self.b[0] - self.c[0], self.b[1] - self.c[1]))
        d = (a1 - a0) % (2 * math.pi) if self.g == 3 else -((a0 - a1) % (2 * math.pi))
        return d if d != 0 else (2 * math.pi if self.g == 3 else -2 * math.pi)

    def _tangent(self, p):
        if not self.arc:
            return _unit((self.b[0] - self.a[0], self.b[1] - self.a[1]))
        v = _unit((p[0] - self.c[0], p[1] - self.c[1]))
        return (-v[1], v[0]) if self.g == 3 else (v[1], -v[0])

    def t_start(self):
        return self._tangent(self.a)

    def t_end(self):
        return self._tangent(self.b)

    def length(self):
        return abs(self.sweep()) * self.r if self.arc else math.dist(self.a, self.b)

    def reversed(self):
        return Elem(self.b, self.a, self.c, 5 - self.g) if self.arc else Elem(self.b, self.a)

    def words(self):
        """Block words (X Y, and I J absolute centre for arcs), millimetres."""
        w = [f"G{self.g}", f"X{fmt(self.b[0])}", f"Y{fmt(self.b[1])}"]
        if self.arc:
            w += [f"I{fmt(self.c[0])}", f"J{fmt(self.c[1])}"]
        return w

    def dist(self, p):
        """Distance (µm) from point p to the element."""
        if not self.arc:
            ax, ay = self.a
            dx, dy = self.b[0] - ax, self.b[1] - ay
            t = ((p[0] - ax) * dx + (p[1] - ay) * dy) / (dx * dx + dy * dy)
            t = max(0.0, min(1.0, t))
            return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)
        v = (p[0] - self.c[0], p[1] - self.c[1])
        a0 = _ang((self.a[0] - self.c[0], self.a[1] - self.c[1]))
        sw = self.sweep()
        off = (_ang(v) - a0) % (2 * math.pi) if sw > 0 else (a0 - _ang(v)) % (2 * math.pi)
        if off <= abs(sw):
            return abs(math.hypot(*v) - self.r)
        return min(math.dist(p, self.a), math.dist(p, self.b))


def joint_turn(e, f):
    """Signed direction change (radians, positive to the left) from e into f."""
    t1, t2 = e.t_end(), f.t_start()
    return math.atan2(t1[0] * t2[1] - t1[1] * t2[0], t1[0] * t2[0] + t1[1] * t2[1])


def contour_ok(elems):
    n = len(elems)
    for i, e in enumerate(elems):
        if e.length() < 3000 or max(abs(v) for p in (e.a, e.b) for v in p) > 300_000:
            return False
        if e.arc and not (math.radians(15) <= abs(e.sweep()) <= math.radians(175)):
            return False
        d = abs(joint_turn(e, elems[(i + 1) % n]))
        if not (d < 1e-9 or MIN_CORNER <= d <= MAX_CORNER):
            return False
    return True


def gen_polygon(rng, kind):
    """A convex or star-shaped polygon, counter-clockwise, integer µm vertices."""
    while True:
        cx, cy = rng.uniform(-60, 60) * 1000, rng.uniform(-60, 60) * 1000
        if kind == "convex":
            n = rng.randint(3, 9)
            r0 = rng.uniform(30, 80) * 1000
            angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
            rads = [r0] * n
        else:
            k = rng.randint(4, 8)
            ro = rng.uniform(50, 90) * 1000
            ri = ro * rng.uniform(0.35, 0.7)
            a0 = rng.uniform(0, 2 * math.pi)
            angs = [a0 + j * math.pi / k + rng.uniform(-0.15, 0.15) * math.pi / k for j in range(2 * k)]
            rads = [ro * rng.uniform(0.95, 1.05) if j % 2 == 0 else ri * rng.uniform(0.9, 1.1)
                    for j in range(2 * k)]
        pts = [(round(cx + r * math.cos(a)), round(cy + r * math.sin(a))) for a, r in zip(angs, rads)]
        elems = [Elem(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
        if contour_ok(elems):
            return elems


def _pick_dir(rng, theta, spread=3):
    """One of the `spread` Pythagorean directions nearest to angle theta."""
    near = sorted(PYTH, key=lambda d: abs(_wrap(_ang(d) - theta)))[:spread]
    return rng.choice(near)


def _multiple(rng, lo, hi, unit):
    """A random multiple of unit in [lo, hi], or None."""
    kmin, kmax = -(-lo // unit), hi // unit
    return rng.randint(kmin, kmax) * unit if kmin <= kmax else None


def gen_mixed(rng):
    """A closed contour of lines and arcs drawn as a turtle walk round a loop:
    lines along Pythagorean directions with lengths in whole multiples of the
    direction's denominator, fillets and tangent arcs (exactly tangent: their
    centres and ends are integer points), arcs meeting their neighbours at a
    corner, then a closing line back to the start. Counter-clockwise or not."""
    while True:
        orient = rng.choice((1, -1))
        m = rng.randint(5, 9)
        theta0 = rng.uniform(0, 2 * math.pi)
        p0 = (rng.randint(-40, 40) * 1000, rng.randint(-40, 40) * 1000)
        pos, head, elems = p0, None, []
        for k in range(m):
            target = theta0 + orient * 2 * math.pi * k / m + rng.uniform(-0.25, 0.25)
            act = rng.choice(("line", "fillet", "arc", "arc", "tarc") if head else ("line", "arc"))
            if act in ("fillet", "tarc"):
                u2 = _pick_dir(rng, target)
                phi = _wrap(_ang(u2) - _ang(head))
                rho = _multiple(rng, 4000, 25000, math.lcm(head[2], u2[2]))
                if rho is None or not (math.radians(15) <= abs(phi) <= math.radians(150)):
                    act = "line"
                else:
                    s = 1 if phi > 0 else -1
                    c = (pos[0] - s * rho // head[2] * head[1], pos[1] + s * rho // head[2] * head[0])
                    e = (c[0] + s * rho // u2[2] * u2[1], c[1] - s * rho // u2[2] * u2[0])
                    elems.append(Elem(pos, e, c, 3 if s > 0 else 2))
                    pos, head = e, u2
                    if act == "fillet":
                        q = _multiple(rng, 8000, 40000, u2[2]) // u2[2]
                        e = (pos[0] + q * u2[0], pos[1] + q * u2[1])
                        elems.append(Elem(pos, e))
                        pos = e
            if act == "line":
                u = _pick_dir(rng, target)
                q = _multiple(rng, 10000, 45000, u[2]) // u[2]
                e = (pos[0] + q * u[0], pos[1] + q * u[1])
                elems.append(Elem(pos, e))
                pos, head = e, u
            elif act == "arc":
                sw = rng.uniform(math.radians(30), math.radians(150)) * rng.choice((1, -1))
                s = 1 if sw > 0 else -1
                tau = target - sw / 2  # start tangent, so that the chord heads for target
                if head and rng.random() < 0.5:  # or a clear corner with what comes before
                    tau = _ang(head) + rng.uniform(math.radians(10), math.radians(100)) * rng.choice((1, -1))
                v1 = _pick_dir(rng, tau - s * math.pi / 2)
                v2 = _pick_dir(rng, _ang(v1) + sw)
                rho = _multiple(rng, 8000, 40000, math.lcm(v1[2], v2[2]))
                if rho is None:
                    break
                c = (pos[0] - rho // v1[2] * v1[0], pos[1] - rho // v1[2] * v1[1])
                e = (c[0] + rho // v2[2] * v2[0], c[1] + rho // v2[2] * v2[1])
                elems.append(Elem(pos, e, c, 3 if s > 0 else 2))
                pos, head = e, (-s * v2[1], s * v2[0], v2[2])
        else:
            if math.dist(pos, p0) >= 10000:
                elems.append(Elem(pos, p0))
                if contour_ok(elems):
                    return elems


def gen_contour(rng, kind):
    elems = gen_mixed(rng) if kind == "mixed" else gen_polygon(rng, kind)
    if rng.random() < 0.5:  # the other way round
        elems = [e.reversed() for e in reversed(elems)]
    k = rng.randrange(len(elems))  # any element first, an arc too
    return elems[k:] + elems[:k]


def max_radius(elems, side):
    """A tool radius (µm) the contour should take on `side` (+1 left/G41, -1
    right/G42): inside corners cut each element by R·tan(turn/2) at each end;
    an arc with the tool inside must stay well larger than R."""
    n = len(elems)
    turns = [joint_turn(elems[i], elems[(i + 1) % n]) for i in range(n)]
    lim = 12000.0
    for i, e in enumerate(elems):
        t = sum(math.tan(abs(d) / 2) for d in (turns[i - 1], turns[i]) if abs(d) > 1e-9 and d * side > 0)
        length = min(e.length(), math.dist(e.a, e.b)) if e.arc else e.length()
        if t:
            lim = min(lim, 0.6 * length / t)
        if e.arc and side * (1 if e.g == 3 else -1) > 0:
            lim = min(lim, 0.5 * e.r)
    return lim


class CompProgram:
    """One compensated run round a contour: both dialects' text and what the
    comparison needs to know."""

    def __init__(self, elems, g, radius, approach, away, dist_in, dist_out, feed):
        self.elems, self.g, self.radius = elems, g, radius
        seq = elems + [elems[0]]
        p0, t1 = elems[0].a, elems[0].t_start()
        ca, sa = math.cos(approach), math.sin(approach)
        d = (t1[0] * ca - t1[1] * sa, t1[0] * sa + t1[1] * ca)
        start = (round(p0[0] - dist_in * d[0]), round(p0[1] - dist_in * d[1]))
        pe, te = seq[-1].b, seq[-1].t_end()
        ca, sa = math.cos(away), math.sin(away)
        d = (te[0] * ca - te[1] * sa, te[0] * sa + te[1] * ca)
        self.exit = (round(pe[0] + dist_out * d[0]), round(pe[1] + dist_out * d[1]))
        self.blocks = []  # (N, NUM-only words, words)
        self._block([], ["G0", f"X{fmt(start[0])}", f"Y{fmt(start[1])}", "Z0"])
        self._block(["D1"], [f"G{g}", "G1", f"X{fmt(p0[0])}", f"Y{fmt(p0[1])}", f"F{feed}"])
        self.n_first = len(self.blocks) * 10 + 10
        for e in seq:
            self._block([], e.words())
        self.n_exit = len(self.blocks) * 10 + 10
        self._block([], ["G40", "G1", f"X{fmt(self.exit[0])}", f"Y{fmt(self.exit[1])}"])
        self.feed = float(feed)

    def _block(self, num_only, words):
        self.blocks.append((len(self.blocks) * 10 + 10, num_only, words))

    def num_lines(self):
        return [NUM_HEADER] + [" ".join([f"N{n}"] + extra + w) for n, extra, w in self.blocks] + ["M2"]

    def num_text(self):
        return "\n".join(self.num_lines()) + "\n"

    def ngc_text(self):
        # G41/G42 without D: the radius of the tool in the spindle (T1, from the table).
        return "\n".join([NGC_HEADER, "T1 M6"] + [" ".join([f"N{n}"] + w) for n, _, w in self.blocks]
                         + ["M2"]) + "\n"

    def tool_table(self):
        return f"T1 P1 D{2 * self.radius / 1000 * SAI_INCH_PER_MM!r} Z0 ;\n"


def _path_len(mv, prev):
    if mv["g"] in (2, 3):
        c = mv["center"]
        return abs(math.radians(mv["sweep"])) * math.dist([prev[a] for a in c], [c[a] for a in c])
    return math.dist([prev[a] for a in "XYZ"], [mv["to"][a] for a in "XYZ"])


def drop_tiny(moves):
    """Moves with their path shorter than 1 µm removed (a rounding's worth of
    connecting arc or trimmed line)."""
    out, prev = [], None
    for mv in moves:
        if prev is None or _path_len(mv, prev) > TOL_MM:
            out.append(mv)
        prev = mv["to"]
    return out


def _near(p, q):
    return all(abs(p[a] - q[a]) <= TOL_MM for a in "XYZ")


def comp_compare(prog, pup, peer, stats=None):
    """Report lines (empty when they agree) for one program: pupitre's and rs274's
    normalised moves. Also checks rs274 against the contour (the harness)."""
    out = []
    r_mm = prog.radius / 1000
    exit_mm = {"X": prog.exit[0] / 1000, "Y": prog.exit[1] / 1000, "Z": 0.0}
    # The harness: rs274 ends at the exit point, and every piece after its entry
    # ends at R from the contour (so it read the tool radius we meant).
    if not peer or not _near(peer[-1]["to"], exit_mm):
        return ["harness: rs274 does not end at the exit point"]
    for mv in peer[2:-1]:
        p = (mv["to"]["X"] * 1000, mv["to"]["Y"] * 1000)
        if min(abs(e.dist(p) - prog.radius) for e in prog.elems) > TOL_MM * 1000:
            return [f"harness: rs274 piece ending at X{p[0] / 1000:.4f} Y{p[1] / 1000:.4f} is not at "
                    f"R{r_mm:g} from the contour (tool table radius misread?)"]
    first = [i for i, mv in enumerate(pup) if mv.get("n") == prog.n_first]
    if not first:
        return [f"pupitre made no move for the first element N{prog.n_first}"]
    i1 = first[0]
    anchor = pup[i1]
    # rs274's piece of the first element: the first move after the entry that ends
    # where pupitre's does (their starts differ with the entries).
    j1 = next((j for j in range(2, len(peer) - 1) if peer[j]["g"] == anchor["g"]
               and _near(peer[j]["to"], anchor["to"])), None)
    if j1 is None:
        to = anchor["to"]
        return [f"first element N{prog.n_first}: pupitre's offset ends at X{to['X']:.4f} Y{to['Y']:.4f}, "
                "rs274 has no such piece: " + ", ".join(
                    f"G{m['g']} X{m['to']['X']:.4f} Y{m['to']['Y']:.4f}" for m in peer[2:6])]
    if anchor["g"] in (2, 3):
        for a, v in anchor["center"].items():
            if abs(v - peer[j1]["center"][a]) > TOL_MM:
                out.append(f"first element N{prog.n_first}: centre {a} {peer[j1]['center'][a]:.4f} vs {v:.4f}")
    if pup[-1]["n"] != prog.n_exit or not _near(pup[-1]["to"], exit_mm):
        out.append(f"pupitre's last move is not the G40 exit N{prog.n_exit} to X{exit_mm['X']:.4f} Y{exit_mm['Y']:.4f}")
    ref = [dict(m, n=None) for m in drop_tiny([peer[j1]] + peer[j1 + 1:-1])[1:]]
    got = [dict(m, n=None) for m in drop_tiny([pup[i1]] + pup[i1 + 1:-1])[1:]]
    if stats is not None:
        stats["pieces"] += len(ref)
    for i, msg in compare(ref, got, "rs274", "pupitre", sweep_by_radius=True):
        blk = got[i]["line"] if i < len(got) else None
        out.append(f"piece {i + 1} after the first element: {msg}"
                   + (f"  [pupitre block line {blk}]" if blk else ""))
    return out


def rs274_gouge(moves, elems, radius):
    """How rs274's path goes wrong where NUM's rule is error 149 (an offset
    element that vanishes or reverses once trimmed), or None: an arc piece of
    more than 180° (the programmed arcs and corners turn less: a near-full loop),
    or a line piece that runs backwards along the offset of a programmed line."""
    loops = [m for m in moves if m["g"] in (2, 3) and abs(m["sweep"]) > 180]
    if loops:
        return f"cuts an arc of {max(abs(m['sweep']) for m in loops):.1f}°"
    for prev, m in zip(moves[1:], moves[2:-1]):
        if m["g"] != 1:
            continue
        p = (prev["to"]["X"] * 1000, prev["to"]["Y"] * 1000)
        q = (m["to"]["X"] * 1000, m["to"]["Y"] * 1000)
        if math.dist(p, q) < 1:
            continue
        for e in elems:
            if e.arc:
                continue
            u = _unit((e.b[0] - e.a[0], e.b[1] - e.a[1]))
            off = [(x[0] - e.a[0]) * -u[1] + (x[1] - e.a[1]) * u[0] for x in (p, q)]
            if all(abs(abs(o) - radius) <= 1 for o in off) and (q[0] - p[0]) * u[0] + (q[1] - p[1]) * u[1] < 0:
                return (f"cuts the offset of the line to X{fmt(e.b[0])} Y{fmt(e.b[1])} backwards "
                        f"({math.dist(p, q) / 1000:.3f} mm)")
    return None


def tally_joints(elems, side, tally):
    """Counts the joints of a compared contour by kind: inside (trimmed), outside
    (connecting arc) or tangent, and the elements they join."""
    n = len(elems)
    for i, e in enumerate(elems):
        f = elems[(i + 1) % n]
        d = joint_turn(e, f)
        how = "tangent" if abs(d) < 1e-9 else "inside" if d * side > 0 else "outside"
        key = f"{how} {'arc' if e.arc else 'line'}-{'arc' if f.arc else 'line'}"
        tally[key] = tally.get(key, 0) + 1
        if e.arc and side * (1 if e.g == 3 else -1) > 0:
            tally["tool inside an arc"] = tally.get("tool inside an arc", 0) + 1


def peer_binary(peer):
    """(rs274 path, environment) from rs274-peer --path (LD_LIBRARY_PATH as rs274-peer sets it)."""
    p = subprocess.run([peer, "--path"], capture_output=True, text=True, timeout=900)
    binary = p.stdout.strip().splitlines()[-1]
    env = dict(os.environ, LD_LIBRARY_PATH=os.path.join(os.path.dirname(os.path.dirname(binary)), "lib"))
    return binary, env


def run_comp_once(prog, base, args, rs):
    """Writes and runs one program; returns (pupitre result, rs274 result), each
    (ok, moves or message)."""
    iso, ngc, tbl = base + ".iso", base + ".ngc", base + ".tbl"
    for path, text in ((iso, prog.num_text()), (ngc, prog.ngc_text()), (tbl, prog.tool_table())):
        with open(path, "w") as f:
            f.write(text)
    binary, env = rs
    try:
        p = subprocess.run([binary, "-t", tbl, "-n", "2", "-g", ngc, base + ".canon"],
                           capture_output=True, text=True, timeout=120, env=env)
        with open(base + ".canon") as f:
            canon = f.read()
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, (False, f"rs274 did not run: {e}")
    if p.returncode != 0:
        msg = " | ".join(l for l in (p.stdout + p.stderr).strip().splitlines()[-2:] if l != "executing")
        peer_res = (False, msg)
    else:
        peer_res = (True, parse_rs274(canon))
    if args.peer_only:
        return None, peer_res
    p = run([args.pupitre, "run", "--machine", "mill", "--trace", "--set", f"D1.R={fmt(prog.radius)}", iso],
            base + ".trace")
    if p.returncode != 0:
        pup_res = (False, " | ".join(p.stderr.strip().splitlines()[:3]))
    else:
        try:
            pup_res = (True, parse_trace(p.stdout))
        except ValueError as e:
            pup_res = (False, f"bad trace: {e}")
    return pup_res, peer_res


def check_comp(k, elems, kind, g, args, rs, work, rng, stats):
    """One contour with G41 or G42: report lines (empty when they agree)."""
    side = 1 if g == 41 else -1
    r0 = max(100, int(rng.uniform(0.2, 1.0) * args.radius_scale * max_radius(elems, side)))
    approach, away = math.radians(rng.uniform(-60, 60)), math.radians(rng.uniform(-60, 60))
    dist_in, dist_out = rng.uniform(20, 40) * 1000, rng.uniform(20, 40) * 1000
    feed = rng.randrange(200, 2001, 50)
    base = os.path.join(work, f"comp{k:03d}-{kind}-g{g}")
    # When a side refuses the program: the same radius with a straight-in entry
    # (along the first element: LinuxCNC's entry then ends where NUM's does, and
    # it no longer refuses an entry corner NUM does not have), then smaller radii.
    compared = None
    for attempt in range(3):
        radius = max(100, r0 >> attempt)
        for appr in ([approach, 0.0] if approach else [0.0]):
            din = max(dist_in, 2 * radius + 5000)  # LinuxCNC wants an entry longer than R
            prog = CompProgram(elems, g, radius, appr, away, din, dist_out, feed)
            pup, peer = run_comp_once(prog, base, args, rs)
            if pup is None and not args.peer_only:
                return [f"{base}: {peer[1] if peer else 'rs274 did not run'}"]
            if peer is None or (pup is not None and not pup[0] and "error 149" not in pup[1]):
                why = peer[1] if peer else "?"
                return [f"{base}.iso: pupitre failed: {pup[1] if pup else why}"]
            pup_ok = args.peer_only or pup[0]
            if pup_ok and peer[0]:
                compared = prog
                break
            if not pup_ok:
                break  # NUM's entry has no corner: another entry changes nothing for pupitre
        if compared:
            if appr != approach:  # refused by rs274 alone, with the other entry
                stats["refused_rs274_entry"] += 1
            break
        why = (f"pupitre: {pup[1]} " if not pup_ok else "") + (f"rs274: {peer[1]}" if not peer[0] else "")
        if (not pup_ok and not peer[0]) or args.peer_only:
            stats["refused_both"] += 1
        elif not pup_ok:
            # rs274 cuts the program: a "vanishing" offset arc (its trimmed start is
            # past its end) becomes a loop of nearly 360°; NUM's rule is error 149.
            gouge = rs274_gouge(peer[1], elems, prog.radius)
            if gouge:
                stats["refused_pupitre_loop"] += 1
                why += f"(rs274 {gouge} instead)"
            else:
                stats["disagree"].append(f"{base}.iso R{fmt(prog.radius)}: pupitre refuses what rs274 "
                                         f"cuts without a loop: {why}")
        else:
            stats["disagree"].append(f"{base}.ngc R{fmt(prog.radius)}: rs274 refuses, even with a "
                                     f"straight-in entry, what pupitre cuts: {why}")
        stats["notes"].append(f"{base} R{fmt(prog.radius)}: {why}")
    if not compared:
        stats["skipped"] += 1
        return []
    prog = compared
    stats["compared"] += 1
    if args.peer_only:
        # The harness alone: rs274's pieces lie at R from the contour.
        stats["pieces"] += max(0, len(peer[1]) - 3)
        report = [f"{base}.ngc: {m}" for m in comp_compare(prog, peer[1], peer[1]) if m.startswith("harness")]
        if not report:
            tally_joints(elems, side, stats["joints"])
        return report
    report = comp_compare(prog, pup[1], peer[1], stats)
    if report:
        lines = prog.num_lines()
        out = [f"{base}.iso ({kind}, G{g}, R{fmt(prog.radius)}): {m}" for m in report[:args.show]]
        shown = sorted({int(mt.group(1)) for m in report[:args.show]
                        for mt in [re.search(r"block line (\d+)", m)] if mt})
        out += ["    " + excerpt(lines, ln) for ln in shown]
        return out
    tally_joints(elems, side, stats["joints"])
    return []


def main_comp(args, peer):
    try:
        rs = peer_binary(peer)
    except (OSError, subprocess.TimeoutExpired, IndexError) as e:
        print(f"crosscheck: SKIP: LinuxCNC rs274 is not available: {e}")
        return EXIT_SKIP
    work = args.keep or tempfile.mkdtemp(prefix="pupitre-crosscheck-comp-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    stats = {"compared": 0, "skipped": 0, "pieces": 0, "refused_both": 0, "refused_pupitre_loop": 0,
             "refused_rs274_entry": 0, "notes": [], "disagree": [], "joints": {}}
    failed = 0
    kinds = {}
    elems = None
    for k in range(args.count):
        if k % 2 == 0:
            crng = random.Random(rng.getrandbits(64))
            kind = COMP_KINDS[(k // 2) % len(COMP_KINDS)]
            elems = gen_contour(crng, kind)
            kinds[kind] = kinds.get(kind, 0) + 1
        g = 41 if k % 2 == 0 else 42
        report = check_comp(k + 1, elems, kind, g, args, rs, work, crng, stats)
        if report:
            failed += 1
            if failed <= 3:
                print("\n".join(report))
    if args.verbose:
        for n in stats["notes"]:
            print(f"crosscheck: note: {n}")
    for d in stats["disagree"][:5]:
        print(f"crosscheck: {d}")
    what = "rs274 vs contour" if args.peer_only else "pupitre vs rs274"
    refusals = (f"; a first radius refused by both {stats['refused_both']} times, by pupitre alone "
                f"{stats['refused_pupitre_loop']} (rs274 loops or backs up), by rs274 alone at its entry "
                f"{stats['refused_rs274_entry']}")
    counts = ", ".join(f"{v} {k}" for k, v in kinds.items())
    joints = ", ".join(f"{v} {k}" for k, v in sorted(stats["joints"].items(), key=lambda kv: -kv[1]))
    if failed or stats["disagree"]:
        print(f"crosscheck: FAIL: {failed} of {args.count} compensated programs differ, "
              f"{len(stats['disagree'])} accepted by one side only ({what}, seed {args.seed}); "
              f"files kept in {work}{refusals}")
        return EXIT_FAIL
    print(f"crosscheck: ok: {stats['compared']} compensated programs ({counts} contours, G41 and G42), "
          f"{stats['pieces']} pieces, agree ({what}, seed {args.seed}); "
          f"{stats['skipped']} skipped as refused at every radius{refusals}")
    print(f"crosscheck: joints compared: {joints}")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    return EXIT_OK


# Real rs274 output (linuxcnc-uspace from Debian) for
#   G21 G90 G90.1 G17 G94 / N10 G0 X10 Y0 Z5 / N20 G2 X0 Y10 I0 J0 F100 /
#   G18 / G0 X0 Y0 Z0 / G2 X0 Z6 I4 K3 / G19 / G0 X0 Y0 Z0 / G3 Y6 Z0 J3 K4 / M2
# and the trace sample of pupitre(1), OUTPUT, for --selftest.
SELFTEST_CANON = """\
   13 N10    STRAIGHT_TRAVERSE(10.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   14 N20    SET_FEED_RATE(100.0000)
   15 N20    ARC_FEED(0.0000, 10.0000, 0.0000, 0.0000, -1, 5.0000, 0.0000, 0.0000, 0.0000)
   16 N..... SELECT_PLANE(CANON_PLANE_XZ)
   17 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   18 N..... ARC_FEED(6.0000, 0.0000, 3.0000, 4.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   19 N..... SELECT_PLANE(CANON_PLANE_YZ)
   20 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   21 N..... ARC_FEED(6.0000, 0.0000, 3.0000, 4.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
"""
SELFTEST_TRACE = """\
{"ev":"tool","prog":20,"line":3,"n":20,"t":1,"d":1}
{"ev":"spindle","prog":20,"line":4,"n":30,"rpm":1000.0000,"dir":"cw","css":null,"range":41}
{"ev":"move","prog":20,"line":5,"n":40,"g":0,"to":{"X":0.0000,"Y":0.0000,"Z":5.0000},"om":{"X":0.0000,"Y":0.0000,"Z":5.0000},"feed":20000.0000,"rpm":1000.0000,"t":0.5000}
{"ev":"move","prog":20,"line":6,"n":50,"g":2,"to":{"X":10.0000,"Y":10.0000,"Z":5.0000},"center":{"X":10.0000,"Y":0.0000},"sweep":-90.0000,"om":{"X":10.0000,"Y":10.0000,"Z":5.0000},"feed":100.0000,"rpm":1000.0000,"t":9.4248}
{"ev":"end","prog":20,"line":7,"n":60}
"""


# Real outputs for the compensated program of selftest_comp() (G42, R3, a
# contour with a tangent arc, outside corners and an inside one), for --selftest.
SELFTEST_COMP_CANON = """\
   17 N10    STRAIGHT_TRAVERSE(-17.3210, -10.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   18 N20    SET_FEED_RATE(500.0000)
   20 N30    STRAIGHT_FEED(0.8038, -3.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   21 N40    STRAIGHT_FEED(50.0000, -3.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   22 N50    ARC_FEED(63.0000, 10.0000, 50.0000, 10.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   23 N60    STRAIGHT_FEED(63.0000, 50.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   24 N60    ARC_FEED(58.3359, 52.4962, 60.0000, 50.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   25 N70    STRAIGHT_FEED(30.0000, 33.6056, 0.0000, 0.0000, 0.0000, 0.0000)
   26 N80    STRAIGHT_FEED(1.6641, 52.4962, 0.0000, 0.0000, 0.0000, 0.0000)
   27 N80    ARC_FEED(-3.0000, 50.0000, 0.0000, 50.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   28 N90    STRAIGHT_FEED(-3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   29 N90    ARC_FEED(-0.0000, -3.0000, 0.0000, 0.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   30 N100   STRAIGHT_FEED(50.0000, -3.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   32 N100   STRAIGHT_FEED(70.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
"""
SELFTEST_COMP_TRACE = """\
{"ev":"move","line":2,"n":10,"g":0,"to":{"X":-17.321,"Y":-10,"Z":0},"feed":15074.8166}
{"ev":"move","line":3,"n":20,"g":1,"to":{"X":0,"Y":-3,"Z":0},"feed":500}
{"ev":"move","line":4,"n":30,"g":1,"to":{"X":50,"Y":-3,"Z":0},"feed":500}
{"ev":"move","line":5,"n":40,"g":3,"to":{"X":63,"Y":10,"Z":0},"center":{"X":50,"Y":10},"sweep":90,"feed":500}
{"ev":"move","line":6,"n":50,"g":1,"to":{"X":63,"Y":50,"Z":0},"feed":500}
{"ev":"move","line":6,"n":50,"g":3,"to":{"X":58.3359,"Y":52.4962,"Z":0},"center":{"X":60,"Y":50},"sweep":123.6901,"feed":500}
{"ev":"move","line":7,"n":60,"g":1,"to":{"X":30,"Y":33.6056,"Z":0},"feed":500}
{"ev":"move","line":8,"n":70,"g":1,"to":{"X":1.6641,"Y":52.4962,"Z":0},"feed":500}
{"ev":"move","line":8,"n":70,"g":3,"to":{"X":-3,"Y":50,"Z":0},"center":{"X":0,"Y":50},"sweep":123.6901,"feed":500}
{"ev":"move","line":9,"n":80,"g":1,"to":{"X":-3,"Y":0,"Z":0},"feed":500}
{"ev":"move","line":9,"n":80,"g":3,"to":{"X":0,"Y":-3,"Z":0},"center":{"X":0,"Y":0},"sweep":90,"feed":500}
{"ev":"move","line":10,"n":90,"g":1,"to":{"X":50,"Y":-3,"Z":0},"feed":500}
{"ev":"move","line":11,"n":100,"g":1,"to":{"X":70,"Y":0,"Z":0},"feed":500}
"""


def selftest_comp():
    """The --comp comparison on built-in outputs: they agree, and planted
    mistakes (a trim point 2 µm off, a lost connecting arc) are reported."""
    el = [Elem((0, 0), (50000, 0)), Elem((50000, 0), (60000, 10000), (50000, 10000), 3),
          Elem((60000, 10000), (60000, 50000)), Elem((60000, 50000), (30000, 30000)),
          Elem((30000, 30000), (0, 50000)), Elem((0, 50000), (0, 0))]
    prog = CompProgram(el, 42, 3000, math.radians(30), 0.0, 20000, 20000, 500)
    peer, pup = parse_rs274(SELFTEST_COMP_CANON), parse_trace(SELFTEST_COMP_TRACE)
    errors = [f"comp: {m}" for m in comp_compare(prog, pup, peer)]
    shifted = [dict(m, to=dict(m["to"], Y=m["to"]["Y"] + 0.002)) if m["to"]["X"] == 30 else m for m in pup]
    lost = [m for m in pup if not (m["g"] == 3 and m["n"] == 70)]
    for name, bad in (("a trim point 2 µm off", shifted), ("a lost connecting arc", lost)):
        if not comp_compare(prog, bad, peer):
            errors.append(f"comp: {name} not reported")
    if prog.tool_table() != "T1 P1 D0.23622047244096 Z0 ;\n":
        errors.append(f"comp: tool table {prog.tool_table()!r}")
    return errors


def selftest():
    """Check both parsers on known outputs; 0 when they read them right."""
    errors = []
    canon = parse_rs274(SELFTEST_CANON)
    want = [
        {"g": 0, "to": {"X": 10, "Y": 0, "Z": 5}, "n": 10},
        # G2 from X10 Y0 about X0 Y0 to X0 Y10: clockwise, three quarters
        {"g": 2, "to": {"X": 0, "Y": 10, "Z": 5}, "center": {"X": 0, "Y": 0}, "sweep": -270,
         "feed": 100, "n": 20},
        {"g": 0, "to": {"X": 0, "Y": 0, "Z": 0}},
        # G18, plane axes (Z, X): from Z0 X0 about Z3 X4 to Z6 X0; G2 turns from X
        # towards Z, the long way round here
        {"g": 2, "to": {"X": 0, "Y": 0, "Z": 6}, "center": {"Z": 3, "X": 4},
         "sweep": -(360 - 2 * math.degrees(math.atan2(3, 4)))},
        {"g": 0, "to": {"X": 0, "Y": 0, "Z": 0}},
        # G19, plane axes (Y, Z): from Y0 Z0 about Y3 Z4 to Y6 Z0; G3 turns from Y
        # towards Z, the short way here
        {"g": 3, "to": {"X": 0, "Y": 6, "Z": 0}, "center": {"Y": 3, "Z": 4},
         "sweep": 2 * math.degrees(math.atan2(3, 4))},
    ]
    for w in want:
        w["to"] = {k: float(v) for k, v in w["to"].items()}
        if "center" in w:
            w["center"] = {k: float(v) for k, v in w["center"].items()}
    errors += [f"canon move {i + 1}: {m}" for i, m in compare(want, canon, "expected", "parsed")]
    trace = parse_trace(SELFTEST_TRACE)
    want = [{"g": 0, "to": {"X": 0.0, "Y": 0.0, "Z": 5.0}, "n": 40},
            {"g": 2, "to": {"X": 10.0, "Y": 10.0, "Z": 5.0}, "center": {"X": 10.0, "Y": 0.0},
             "sweep": -90.0, "feed": 100.0, "n": 50}]
    errors += [f"trace move {i + 1}: {m}" for i, m in compare(want, trace, "expected", "parsed")]
    for bad in ('{"ev":"move","g":1}', "not json", "[1, 2]", '{"ev":"move","g":2,"to":{"X":1}}'):
        try:
            parse_trace(bad)
            errors.append(f"trace accepted: {bad}")
        except ValueError:
            pass
    errors += selftest_comp()
    for e in errors:
        print(f"crosscheck: selftest: {e}")
    print("crosscheck: selftest " + ("FAILED" if errors else "ok"))
    return EXIT_FAIL if errors else EXIT_OK


def main():
    ap = argparse.ArgumentParser(description="Compare pupitre's moves with LinuxCNC rs274's on random programs.")
    ap.add_argument("--pupitre", help="path to the pupitre executable")
    ap.add_argument("--peer", help="path to rs274-peer (default: $RS274_PEER, PATH, /work/shared/tools)")
    ap.add_argument("--count", type=int, default=30, help="number of programs (default 30)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--keep", metavar="DIR", help="write the programs and outputs here and keep them")
    ap.add_argument("--show", type=int, default=5, help="mismatches shown per program (default 5)")
    ap.add_argument("--peer-only", action="store_true",
                    help="check only rs274 against the generator (no pupitre needed)")
    ap.add_argument("--comp", action="store_true",
                    help="tool radius compensation G41/G42 on random closed contours (G17)")
    ap.add_argument("--radius-scale", type=float, default=1.0, metavar="F",
                    help="--comp: first tool radius tried, times F (> 1 probes where the tool stops fitting)")
    ap.add_argument("--verbose", action="store_true",
                    help="--comp: list the programs a side refused at a first radius")
    ap.add_argument("--selftest", action="store_true",
                    help="check the rs274 and trace parsers on built-in samples, then exit")
    args = ap.parse_args()
    if args.selftest:
        return selftest()
    if not args.peer_only:
        if not args.pupitre:
            print("crosscheck: --pupitre PATH is required (or --peer-only)", file=sys.stderr)
            return EXIT_USAGE
        if not (os.path.isfile(args.pupitre) and os.access(args.pupitre, os.X_OK)):
            print(f"crosscheck: {args.pupitre}: not an executable", file=sys.stderr)
            return EXIT_USAGE
        args.pupitre = os.path.abspath(args.pupitre)

    peer = find_peer(args.peer)
    why = setup_peer(peer)
    if why:
        print(f"crosscheck: SKIP: LinuxCNC rs274 is not available: {why}")
        return EXIT_SKIP

    if args.comp:
        return main_comp(args, peer)
    work = args.keep or tempfile.mkdtemp(prefix="pupitre-crosscheck-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    failed, nmoves = 0, 0
    for k in range(1, args.count + 1):
        prog = Program(random.Random(rng.getrandbits(64)), rng.randint(20, 40))
        nmoves += len(prog.expected)
        report = check_one(k, prog, args, peer, work)
        if report:
            failed += 1
            if failed <= 3:
                print("\n".join(report))
    what = "rs274 vs generator" if args.peer_only else "pupitre vs rs274"
    if failed:
        print(f"crosscheck: FAIL: {failed} of {args.count} programs differ ({what}, seed {args.seed}); "
              f"files kept in {work}")
        return EXIT_FAIL
    print(f"crosscheck: ok: {args.count} programs, {nmoves} moves agree ({what}, seed {args.seed})")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
