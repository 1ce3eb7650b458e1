#!/usr/bin/env python3
# The man page says what the console does: every key of the shipped bindings,
# every action a user file may name and every ':' command must appear in
# pupitre(1) (rendered as plain text).
# SPDX-License-Identifier: GPL-3.0-or-later
import re
import subprocess
import sys

root = sys.argv[1]
text = subprocess.run(["groff", "-man", "-Tascii", "-P-cbou", f"{root}/man/pupitre.1"],
                      capture_output=True, text=True, check=True).stdout
console = text[text.index("THE CONSOLE"):text.index("\nCOMMANDS\n")]
missing = []
for line in open(f"{root}/data/bindings.txt"):
    line = line.split("#")[0].strip() if not line.startswith("#") else ""
    if not line:
        continue
    key = line.split()[0]
    if not re.search(r"(^|[\s,(])" + re.escape(key) + r"($|[\s,)])", console):
        missing.append(f"key {key}")
src = open(f"{root}/console/bindings.cpp").read()
for action in re.findall(r'^\s*\{"([a-z-]+)", "', src, re.M):
    if action not in console:
        missing.append(f"action {action}")
# The rows of the command table, kCommands in console/commands.cpp: each starts
# a line with {"names", "usage", ... and its names are separated by spaces.
src = open(f"{root}/console/commands.cpp").read()
table = re.search(r"kCommands\[\] = \{\n(.*?)\n\};", src, re.S)
rows = re.split(r"^    (?=\{)", table.group(1), flags=re.M)[1:] if table else []
names = []
for row in rows:
    m = re.match(r'\{"([a-z0-9! ]*)",\s*"([^"]*)"', row)
    if not m:
        sys.exit(f"man_sync.py cannot read this row of the command table:\n{row}")
    names += m.group(1).split()
if len(names) < 10:
    sys.exit(f"man_sync.py found {len(names)} command names in console/commands.cpp: "
             "has the table kCommands changed shape?")
for cmd in names:
    if not re.search(r"(^|[\s,(]):" + re.escape(cmd) + r"($|[\s,).])", console):
        missing.append(f"command :{cmd}")
if missing:
    print("pupitre(1) does not mention: " + ", ".join(sorted(set(missing))))
    sys.exit(1)
print("pupitre(1) names every key, action and command of the console")
