#!/usr/bin/env python3
# The layers of pupitre (ARCHITECTURE.md, Invariants): core/ knows neither the console
# nor the pages; pages/ are pure renderers that never call ncurses nor the
# console; only the store (store/) speaks SQL, and inside it only each engine's
# backend includes its library; the core links no Cairo.
# Inside the core, its folders stand in one order (CORE_ORDER, ARCHITECTURE.md):
# a folder includes its own headers and those of the folders below it.
# Fails, naming file and line, on a product #include that crosses the wrong way.
# Tests are not product code: the store's anomaly tests include sqlite3.h.
#   layering.py ROOT        check the source tree at ROOT
#   layering.py --selftest  prove that every rule fires on a bad include
# SPDX-License-Identifier: GPL-3.0-or-later
import os
import re
import sys
import tempfile

PRODUCT = ("core/", "store/", "pages/", "console/")
SOURCES = (".cpp", ".hpp", ".h")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"][^>"]+[>"])', re.M)

# (who is checked, who is exempt, what it may not include, why)
RULES = [
    ("core/", None, r'^"(console|pages|store)/', "the core knows neither the console, the pages nor the store"),
    ("store/", None, r'^"(console|pages)/', "the store knows neither the console nor the pages"),
    ("pages/", None, r'^"console/', "pages are pure renderers: the console calls them"),
    ("", "console/", r"^<(n?curses(w)?[./]|readline/)",
     "only console/ talks to the terminal (ncurses, readline)"),
    ("", "store/", r'^(<sqlite3\.h>|<libpq-fe\.h>|"store/(sql|backend)\.hpp")$',
     "only the store speaks SQL"),
    ("store/", "store/sqlite.cpp", r'^<sqlite3\.h>$', "only the SQLite backend includes sqlite3.h"),
    ("store/", "store/postgres.cpp", r'^<libpq-fe\.h>$',
     "only the PostgreSQL backend includes libpq-fe.h"),
    ("core/", None, r"^<cairo", "the core links no Cairo"),
    ("core/", None, r"^<png\.h>", "the core links no libpng"),
]

# The core's folders from the ground up: the files at core/'s top (diag, i18n,
# numfmt, keyvalue, digest) first, then each folder, which may include its own
# headers and those of the folders before it, never one after it.
CORE_ORDER = ("", "parse", "geometry", "cycles", "interp", "plan", "output", "workshop", "sim",
              "training", "render")
CORE_INCLUDE = re.compile(r'^"core/(?:([a-z_]+)/)?[^/"]+"$')
CORE_WHY = "core's folders include only downwards: " + " < ".join(f or "core/*" for f in CORE_ORDER)


def core_folder(rel):
    """The folder of a core/ file, "" for one at core/'s top."""
    parts = rel.split("/")
    return parts[1] if len(parts) > 2 else ""


def core_order(rel, header):
    """Why this include of a core/ file runs back up inside the core, or None."""
    m = CORE_INCLUDE.match(header)
    if not rel.startswith("core/") or not m:
        return None
    mine, theirs = core_folder(rel), m.group(1) or ""
    if mine in CORE_ORDER and theirs in CORE_ORDER and CORE_ORDER.index(theirs) > CORE_ORDER.index(mine):
        return CORE_WHY
    return None


# The plot back-end lives beside the scene it draws, under core/, but is a
# library of its own (pupitre_plot in CMakeLists.txt) that the interpreter and
# the rest of the core never link: the one file allowed to include Cairo.
# height_png.cpp (the mill's part as a 16-bit PNG) is in that library too.
EXCEPTIONS = {("core/output/cairo_plot.cpp", "the core links no Cairo"),
              ("core/output/height_png.cpp", "the core links no libpng")}


def product_files(root):
    for top in PRODUCT:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith(SOURCES):
                    path = os.path.join(dirpath, f)
                    yield os.path.relpath(path, root).replace(os.sep, "/"), path


def violations(root):
    found = []
    for rel, path in product_files(root):
        if rel.startswith("core/") and core_folder(rel) not in CORE_ORDER:
            found.append(f"{rel}: core/{core_folder(rel)}/ has no place in CORE_ORDER (layering.py)")
        text = open(path, encoding="utf-8", errors="replace").read()
        for m in INCLUDE.finditer(text):
            header = m.group(1)
            line = text.count("\n", 0, m.start()) + 1
            for who, exempt, banned, why in RULES:
                if not rel.startswith(who) or (exempt and rel.startswith(exempt)):
                    continue
                if re.search(banned, header) and (rel, why) not in EXCEPTIONS:
                    found.append(f"{rel}:{line}: includes {header}: {why}")
            why = core_order(rel, header)
            if why:
                found.append(f"{rel}:{line}: includes {header}: {why}")
    return found


def exception_still_separate(root):
    """The Cairo exception holds only while cairo_plot.cpp stays out of the core library."""
    cmake = open(os.path.join(root, "CMakeLists.txt")).read()
    # Named once, in pupitre_plot's own add_library, and in no source list.
    found = []
    for name, lib in (("cairo_plot", "Cairo"), ("height_png", "libpng")):
        uses = re.findall(r"^.*" + name + r"\.cpp.*$", cmake, re.M)
        if len(uses) != 1 or not uses[0].startswith("add_library(pupitre_plot"):
            found.append(f"CMakeLists.txt: core/output/{name}.cpp is in PUPITRE_CORE_SOURCES: "
                         f"the core links no {lib} (it belongs to pupitre_plot)")
    return found


def selftest():
    bad = {
        "core/parse/block.hpp": '#include "console/session.hpp"\n',
        "core/sim/sim.cpp": '#include "pages/view.hpp"\n',
        "core/output/scene.cpp": "#include <cairo.h>\n",
        "core/output/svg.cpp": "#include <png.h>\n",
        "core/output/trace.cpp": "#include <curses.h>\n",
        "pages/canvas.cpp": "#include <ncursesw/curses.h>\n",
        "pages/screen.cpp": '#include "console/keys.hpp"\n',
        "console/session.cpp": "#include <sqlite3.h>\n",
        "console/app.cpp": '#  include "store/sql.hpp"\n',
        "store/programs.cpp": "#include <sqlite3.h>\n",
        "store/values.cpp": "#include <libpq-fe.h>\n",
        "console/cli_store.cpp": '#include "store/backend.hpp"\n',
        "core/geometry/frames.hpp": '#include "core/interp/machine.hpp"\n',
        "core/workshop/setup.cpp": '#include "core/sim/sim.hpp"\n',
        "core/diag.cpp": '#include "core/parse/program.hpp"\n',
        "core/spare/new.hpp": '#include "core/diag.hpp"\n',
    }
    good = {
        "store/sqlite.cpp": "#include <sqlite3.h>\n",
        "store/postgres.cpp": "#include <libpq-fe.h>\n",
        "core/output/cairo_plot.cpp": "#include <cairo-pdf.h>\n#include <cairo.h>\n",
        "core/output/height_png.cpp": "#include <png.h>\n",
        "console/term.cpp": "#include <curses.h>\n#include <readline/readline.h>\n",
        "console/main.cpp": '#include "core/sim/sim.hpp"\n#include "pages/pages.hpp"\n',
        "pages/page_help.cpp": '#include "core/parse/codes.hpp"\n#include "pages/view.hpp"\n',
        "tests/store/anomalies.cpp": "#include <sqlite3.h>\n",
        "core/sim/sim.hpp": '#include "core/workshop/workshop.hpp"\n#include "core/diag.hpp"\n',
        "core/training/grade.cpp": '#include "core/interp/interp.hpp"\n#include "core/training/grade.hpp"\n',
        "core/i18n.cpp": '#include "core/i18n.hpp"\n',
    }
    with tempfile.TemporaryDirectory() as root:
        for rel, text in {**bad, **good}.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write("// a header line\n" + text)
        found = violations(root)
    flagged = {v.split(":")[0] for v in found}
    wrong = sorted(set(bad) - flagged) + sorted(flagged - set(bad))
    if wrong or len(found) != len(bad):
        print("layering.py --selftest: rules misfire on " + ", ".join(wrong or found))
        return 1
    print(f"layering.py --selftest: {len(bad)} bad includes caught, {len(good)} good files pass")
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--selftest"]:
        sys.exit(selftest())
    root = sys.argv[1]
    problems = violations(root) + exception_still_separate(root)
    if problems:
        print("\n".join(problems))
        sys.exit(1)
    n = sum(1 for _ in product_files(root))
    print(f"{n} files of core/, pages/ and console/ include across layers only downwards, "
          f"and core's folders in their order")
