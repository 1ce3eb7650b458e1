#!/usr/bin/env python3
# The codes table is the single source of the man pages' table of G functions
# (issue 13 item 4): each line of the FUNCTIONS table of pupitre-iso(5), and of
# its French translation, must be the one this script makes from kG in
# core/parse/codes.cpp (number, machines, 40/60, what pupitre does, the text;
# in French the text's translation in po/fr.po). A failure prints the lines
# that differ; `codes_table.py ROOT --write` rewrites both tables from kG.
# The M table keeps its notes, but each M runs before or after the motion as
# kM says; the numbered order within a block is block_steps()'s.
#   codes_table.py ROOT [--write]
# SPDX-License-Identifier: GPL-3.0-or-later
import re
import sys

root = sys.argv[1]
write = "--write" in sys.argv[2:]


def c_string(s):
    """The text of a C or PO string literal's body (\\" \\\\ \\n)."""
    return re.sub(r'\\(.)', lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)), s)


def g_table():
    src = open(f"{root}/core/parse/codes.cpp", encoding="utf-8").read()
    tab = src[src.index("constexpr GCode kG[] = {"):]
    tab = tab[:tab.index("\n};")]
    row = re.compile(r'\{(\d+),\s*G::\w+,\s*(\w+),\s*(\w+),\s*S::(\w+),\s*"[^"]*",\s*(?:N_\()?"((?:[^"\\]|\\.)*)"',
                     re.S)
    return [(int(n), mach, star, sup, c_string(text)) for n, mach, star, sup, text in row.findall(tab)]


def po_catalogue(path):
    """msgid -> msgstr of a gettext catalogue (plain entries, no plural)."""
    cat, key, cur, field = {}, None, [], None
    def flush():
        nonlocal key
        if field == "msgstr" and key is not None:
            cat[key] = "".join(cur)
    for line in open(path, encoding="utf-8"):
        line = line.rstrip("\n")
        m = re.match(r'(msgid|msgstr|msgctxt|msgid_plural|msgstr\[\d\]) "(.*)"$', line)
        if m:
            if m.group(1) == "msgid":
                flush()
                key = None
            elif m.group(1) == "msgstr" and field == "msgid":
                key = "".join(cur)
            field, cur = m.group(1), [c_string(m.group(2))]
        elif line.startswith('"') and field:
            cur.append(c_string(line[1:-1]))
        elif not line.strip():
            flush()
            field, key = None, None
    flush()
    return cat


def roff(text):
    return text.replace("\\", "\\e").replace("-", "\\-").replace("±", "\\(+-").replace("\u00f8", "\\(*f")


def lines(words, translate):
    out = []
    for n, mach, star, sup, text in g_table():
        t = "T" if mach in ("kLathe", "kBoth") else " "
        m = "M" if mach in ("kMill", "kBoth") else " "
        s = "40/60" if star == "kBoth" else " (M) " if star == "kMill" else " (T) " if star == "kLathe" else "     "
        out.append(f"G{n:02d}".ljust(6) + f"{t} {m} {s} " + words[sup].ljust(10) + " " + roff(translate(text)))
    return out


def table(path, words, translate):
    page = open(path, encoding="utf-8").read()
    start = page.index(".EX\n", page.index(".SH " + ("FONCTIONS" if "/fr/" in path else "FUNCTIONS"))) + 4
    end = page.index(".EE\n", start)
    want = lines(words, translate)
    have = page[start:end].rstrip("\n").split("\n")
    if write:
        open(path, "w", encoding="utf-8").write(page[:start] + "\n".join(want) + "\n" + page[end:])
        return 0
    bad = 0
    for i in range(max(len(want), len(have))):
        w = want[i] if i < len(want) else "(none)"
        h = have[i] if i < len(have) else "(none)"
        if w != h:
            bad += 1
            print(f"{path}: table line {i + 1}\n  codes table: {w}\n  man page:    {h}")
    return bad


def m_when(path, before, after):
    """The M table of the man page: each M runs before or after the motion as
    the codes table says (kM's MWhen)."""
    src = open(f"{root}/core/parse/codes.cpp", encoding="utf-8").read()
    tab = src[src.index("constexpr MCode kM[] = {"):]
    tab = tab[:tab.index("\n};")]
    km = [(int(a), int(b), w) for a, b, w in re.findall(r"\{(\d+), (\d+), MWhen::(\w+),", tab)]
    page = open(path, encoding="utf-8").read()
    sec = page[page.index(".SH " + ("FONCTIONS M" if "/fr/" in path else "M FUNCTIONS")):]
    block = sec[sec.index(".EX\n") + 4:sec.index(".EE\n")]
    bad = rows = 0
    for line in block.split("\n"):
        m = re.match(r"((?:M\d+(?:\\-M\d+)? ?)+)\s+(\S+)\s", line)
        if not m:
            continue
        rows += 1
        when = {before: "avant", after: "apres"}.get(m.group(2))
        for n in re.findall(r"M(\d+)", m.group(1)):
            entry = [w for a, b, w in km if a <= int(n) <= b]
            if not entry or entry[0] != when:
                bad += 1
                print(f"{path}: M{n} is '{m.group(2)}' in the man page, {entry or 'absent'} in kM")
    if rows < 10:
        print(f"{path}: the M table was not found")
        bad += 1
    return bad


def block_order(path):
    """The numbered list of the parts of a block in pupitre-iso(5): one item per
    step of block_steps() (codes.cpp), in its order, each starting with its text."""
    src = open(f"{root}/core/parse/codes.cpp", encoding="utf-8").read()
    tab = src[src.index("kSteps[] = {"):]
    steps = re.findall(r'\{ExecStep::\w+, "((?:[^"\\]|\\.)*)"\}', tab[:tab.index("};")])
    page = open(path, encoding="utf-8").read()
    sec = page[page.index(".IP 1. 4\n"):]
    sec = sec[:sec.index("\n.PP\n")]
    items = []
    for part in re.split(r"^\.IP \d+\.(?: \d+)?\n", sec, flags=re.M)[1:]:
        words = re.sub(r"^\.[BI] ", "", part, flags=re.M).replace("\\-", "-").split()
        items.append(" ".join(words))
    bad = 0
    if len(items) != len(steps):
        print(f"{path}: {len(items)} parts of a block listed, {len(steps)} in block_steps()")
        bad += 1
    for i, (item, step) in enumerate(zip(items, steps)):
        if not item.startswith(step):
            print(f"{path}: part {i + 1} of a block\n  codes table: {step}\n  man page:    {item}")
            bad += 1
    return bad


en = {"yes": "runs", "option": "error 4", "ignored": "no effect", "later": "error 1010"}
fr = {"yes": "exécutée", "option": "erreur 4", "ignored": "sans effet", "later": "erreur 1010"}
cat = po_catalogue(f"{root}/po/fr.po")
missing = [t for _, _, _, _, t in g_table() if t.isascii() and not cat.get(t)]
bad = table(f"{root}/man/pupitre-iso.5", en, lambda t: t)
bad += table(f"{root}/man/fr/pupitre-iso.5", fr, lambda t: cat.get(t) or t)
bad += m_when(f"{root}/man/pupitre-iso.5", "before", "after")
bad += block_order(f"{root}/man/pupitre-iso.5")
bad += m_when(f"{root}/man/fr/pupitre-iso.5", "avant", "après")
for t in missing:
    print(f"po/fr.po: no translation of the codes table's {t!r}")
if bad or missing:
    print(f"FAIL: {bad} lines differ from the codes table (codes_table.py ROOT --write rewrites them)")
    sys.exit(1)
if not write:
    print(f"ok: {len(g_table())} G functions, the M table's before/after and the order within a block")
