#!/usr/bin/env bash
# Every text marked for translation has its translation in every catalogue
# (po/LANG.po): none missing, none untranslated, none fuzzy, msgfmt --check
# clean; and po/fr.po gives each NUM error the manual's own French text
# (data/errors.tsv, message_fr).   catalogue.sh SOURCE_DIR
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
root=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$root/scripts/lib/extract-pot" "$tmp/pupitre.pot"
status=0
for po in "$root"/po/*.po; do
    lang=$(basename "$po" .po)
    if ! stats=$(msgfmt --check --statistics -o /dev/null "$po" 2>&1); then
        echo "$lang: msgfmt --check fails:"; echo "$stats"; status=1; continue
    fi
    echo "$lang: $stats"
    case $stats in
        *untranslated*|*fuzzy*) echo "$lang: not 100% translated (scripts/update-po, then translate)"; status=1 ;;
    esac
    if ! msgcmp "$po" "$tmp/pupitre.pot" >"$tmp/cmp" 2>&1; then
        echo "$lang: texts of the sources missing from $po (scripts/update-po):"
        grep -A1 "used but not defined" "$tmp/cmp" | head -40 || cat "$tmp/cmp"
        status=1
    fi
done
python3 - "$root" <<'PY' || status=1
import re, sys
root = sys.argv[1]
def unq(s):
    return re.sub(r'\\(.)', lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)), s)
# msgid -> msgstr of po/fr.po (continuation lines joined).
entries, cur, key = {}, {}, None
for line in open(f"{root}/po/fr.po", encoding="utf-8"):
    line = line.rstrip("\n")
    m = re.match(r'^(msgid|msgstr) "(.*)"$', line)
    if m:
        key = m.group(1)
        cur[key] = unq(m.group(2))
    elif line.startswith('"') and key:
        cur[key] += unq(line[1:-1])
    else:
        key = None
    if key == "msgstr":
        entries[cur.get("msgid", "")] = cur["msgstr"]
bad, seen = 0, set()
for i, line in enumerate(open(f"{root}/data/errors.tsv", encoding="utf-8")):
    c = line.rstrip("\n").split("\t")
    if i == 0 or len(c) < 5 or not c[4] or c[4] in seen:
        continue
    seen.add(c[4])  # an English text shared by several numbers: the first one's French
    if entries.get(c[4]) != c[3]:
        print(f"fr.po: error {c[0]}: the translation is not errors.tsv's message_fr")
        bad += 1
sys.exit(1 if bad else 0)
PY
exit $status
