#!/usr/bin/env python3
# crosscheck: run random small milling programs through pupitre and through
# LinuxCNC's rs274 (tools/rs274-peer) and compare them move by move: end points
# and arc centres to 1 µm, arc direction, arc sweep, feed.
#
#   crosscheck.py --pupitre build/pupitre [--count 30] [--seed 1] [--keep DIR]
#   crosscheck.py --peer-only            check the harness: rs274 against the generator
#   crosscheck.py --selftest             check the two parsers on built-in samples
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
# seen from the normal's positive end (NUM milling.md §5.1; same in RS274).
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
    """pupitre --trace JSON lines (DESIGN.md §2.3) -> normalised moves."""
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

def compare(ref, got, ref_name, got_name):
    """Differences between two normalised move lists, as (move index, message)."""
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
            if abs(r["sweep"] - g["sweep"]) > TOL_DEG:
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


# Real rs274 output (linuxcnc-uspace from Debian) for
#   G21 G90 G90.1 G17 G94 / N10 G0 X10 Y0 Z5 / N20 G2 X0 Y10 I0 J0 F100 /
#   G18 / G0 X0 Y0 Z0 / G2 X0 Z6 I4 K3 / G19 / G0 X0 Y0 Z0 / G3 Y6 Z0 J3 K4 / M2
# and the DESIGN.md §2.3 trace sample, for --selftest.
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
