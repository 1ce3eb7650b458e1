#!/usr/bin/env python3
# fake_pupitre: a stand-in for `pupitre run --machine mill --trace FILE.iso`
# that understands only what crosscheck.py generates (G0-G3, G17-G19, X Y Z,
# absolute I J K centres, F, N), so the harness can be tested without pupitre:
#   crosscheck.py --pupitre tests/crosscheck/fake_pupitre.py
# --bug NAME plants a mistake the harness must catch: g18-sense (G2/G3 swapped
# in G18), centre (I J K read as relative), feed (F ignored), drop (last move lost).
import json
import math
import re
import sys

PLANES = {17: ("X", "Y"), 18: ("Z", "X"), 19: ("Y", "Z")}
CENTRE = {"X": "I", "Y": "J", "Z": "K"}
WORD = re.compile(r"([A-Z])(-?\d+(?:\.\d*)?)")


def main(argv):
    bug = None
    if "--bug" in argv:
        i = argv.index("--bug")
        bug = argv[i + 1]
        del argv[i:i + 2]
    if len(argv) < 5 or argv[:4] != ["run", "--machine", "mill", "--trace"]:
        print("usage: fake_pupitre.py [--bug NAME] run --machine mill --trace FILE", file=sys.stderr)
        return 64
    pos = {"X": 0.0, "Y": 0.0, "Z": 200.0}
    plane, motion, feed = 17, None, 0.0
    out = []
    with open(argv[4]) as f:
        for line_no, text in enumerate(f, 1):
            text = text.strip()
            if text.startswith("%") or not text:
                continue
            words = WORD.findall(text)
            n = None
            vals = {}
            for letter, num in words:
                v = float(num)
                if letter == "N":
                    n = int(v)
                elif letter == "G" and int(v) in PLANES:
                    plane = int(v)
                elif letter == "G":
                    motion = int(v)
                elif letter == "M" and int(v) == 2:
                    out.append({"ev": "end", "prog": 1, "line": line_no, "n": n})
                elif letter == "F":
                    if bug != "feed":
                        feed = v
                else:
                    vals[letter] = v
            if not any(a in vals for a in "XYZ"):
                continue
            start = dict(pos)
            for a in "XYZ":
                if a in vals:
                    pos[a] = vals[a]
            ev = {"ev": "move", "prog": 1, "line": line_no, "n": n, "g": motion,
                  "to": {a: round(pos[a], 4) for a in "XYZ"}}
            if motion in (2, 3):
                p, q = PLANES[plane]
                c = {a: vals[CENTRE[a]] + (start[a] if bug == "centre" else 0) for a in (p, q)}
                g = motion
                if bug == "g18-sense" and plane == 18:
                    g = 5 - g
                a0 = math.atan2(start[q] - c[q], start[p] - c[p])
                a1 = math.atan2(pos[q] - c[q], pos[p] - c[p])
                d = (a1 - a0) % (2 * math.pi) if g == 3 else -((a0 - a1) % (2 * math.pi))
                ev["center"] = {a: round(c[a], 4) for a in (p, q)}
                ev["sweep"] = round(math.degrees(d), 4)
                ev["g"] = g
            ev["om"] = dict(ev["to"])
            ev["feed"] = 20000.0 if motion == 0 else feed
            ev["rpm"] = 0.0
            ev["t"] = 0.0
            out.append(ev)
    if bug == "drop":
        del out[-2]  # the last move (out[-1] is the end event)
    for e in out:
        # fixed 4 decimals as the trace prints them (pupitre(1), OUTPUT)
        print(re.sub(r"(-?\d+\.\d+)", lambda m: f"{float(m.group(1)):.4f}", json.dumps(e, separators=(",", ":"))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
