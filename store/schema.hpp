// Inside the store: the schema as ordered migrations. Migration i (1-based)
// takes a store from user_version i-1 to i; a new version appends one, never
// edits an old one.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace pupitre::store::schema {

inline constexpr const char* kMigrations[] = {
    // 1: programs with their revisions, machines, correctors, origins, audit,
    // settings, IMD history.
    R"sql(
CREATE TABLE machines (
    name       TEXT PRIMARY KEY,
    profile    TEXT NOT NULL,                -- the .machine text ('' when not known)
    builtin    INTEGER NOT NULL DEFAULT 0 CHECK (builtin IN (0, 1)),
    updated_ms INTEGER NOT NULL
) STRICT;

CREATE TABLE programs (
    number      INTEGER PRIMARY KEY CHECK (number >= 0),
    idx         INTEGER,                     -- %number.index, NULL when none
    title       TEXT NOT NULL DEFAULT '',    -- the header comment of the current text
    head        INTEGER NOT NULL,            -- the current revision (a deletion when deleted = 1)
    last_rev    INTEGER NOT NULL,            -- the highest revision number given
    conflict    INTEGER,                     -- a revision kept aside by a conflicting save
    deleted     INTEGER NOT NULL DEFAULT 0 CHECK (deleted IN (0, 1)),
    size        INTEGER NOT NULL,            -- bytes of the current text
    lines       INTEGER NOT NULL,
    modified_ms INTEGER NOT NULL,
    modified_by TEXT NOT NULL,
    FOREIGN KEY (number, head) REFERENCES revisions (program, rev) DEFERRABLE INITIALLY DEFERRED
) STRICT;

CREATE TABLE revisions (
    program  INTEGER NOT NULL REFERENCES programs (number) DEFERRABLE INITIALLY DEFERRED,
    rev      INTEGER NOT NULL CHECK (rev >= 1),
    kind     TEXT NOT NULL CHECK (kind IN ('seed', 'import', 'save', 'restore', 'delete')),
    based_on INTEGER NOT NULL DEFAULT 0,     -- the revision the writer had loaded, 0 for none
    conflict INTEGER NOT NULL DEFAULT 0 CHECK (conflict IN (0, 1)),
    text     BLOB,                           -- exactly as written; NULL for a deletion
    size     INTEGER NOT NULL,
    lines    INTEGER NOT NULL,
    who      TEXT NOT NULL,
    at_ms    INTEGER NOT NULL,
    source   TEXT NOT NULL DEFAULT '',
    PRIMARY KEY (program, rev),
    CHECK ((kind = 'delete') = (text IS NULL))
) STRICT;

-- Values in the internal units of the E parameters: µm, 0.0001 degree, C code.
CREATE TABLE correctors (
    machine TEXT NOT NULL REFERENCES machines (name),
    d       INTEGER NOT NULL CHECK (d BETWEEN 1 AND 255),
    field   TEXT NOT NULL CHECK (field IN ('X', 'Z', 'R', 'C', 'DX', 'DZ', 'L', 'A', 'DL', 'DR')),
    value   INTEGER NOT NULL,
    PRIMARY KEY (machine, d, field)
) STRICT, WITHOUT ROWID;

CREATE TABLE origins (
    machine TEXT NOT NULL REFERENCES machines (name),
    kind    TEXT NOT NULL CHECK (kind IN ('PREF', 'DEC1', 'DEC3')),
    axis    TEXT NOT NULL CHECK (axis IN ('X', 'Y', 'Z', 'U', 'V', 'W', 'A', 'B', 'C')),
    value   INTEGER NOT NULL,
    PRIMARY KEY (machine, kind, axis)
) STRICT, WITHOUT ROWID;

CREATE TABLE audit (
    id      INTEGER PRIMARY KEY,
    at_ms   INTEGER NOT NULL,
    who     TEXT NOT NULL,
    machine TEXT NOT NULL REFERENCES machines (name),
    name    TEXT NOT NULL,                   -- D3.X, PREF.Z…
    old     INTEGER,                         -- NULL: not stored before (profile default)
    new     INTEGER,
    source  TEXT NOT NULL                    -- page CORR, program %555 (tools.iso)…
) STRICT;
CREATE INDEX audit_by_machine ON audit (machine, id);

CREATE TABLE settings (
    key   TEXT PRIMARY KEY,
    value TEXT NOT NULL
) STRICT;

CREATE TABLE imd_history (
    id      INTEGER PRIMARY KEY,
    at_ms   INTEGER NOT NULL,
    who     TEXT NOT NULL,
    machine TEXT NOT NULL REFERENCES machines (name),
    block   TEXT NOT NULL
) STRICT;
CREATE INDEX imd_by_machine ON imd_history (machine, id);
)sql",
    // 2: the workshop of each machine (issue 15): the setup in use, as its
    // text (pupitre-setup(5)), and the part as the tools left it.
    R"sql(
CREATE TABLE workshops (
    machine    TEXT PRIMARY KEY REFERENCES machines (name),
    setup      TEXT NOT NULL,                -- the setup file's text
    part       TEXT NOT NULL,                -- the half-section: "Z R" in 0.1 µm, one outline per line
    updated_ms INTEGER NOT NULL,
    who        TEXT NOT NULL
) STRICT;
)sql",
    // 3: training (issue 16): the class's own exercises, and every attempt
    // with its grade. The truth is not kept: it is drawn again from the seed
    // (pupitre-exercise(5), WHAT IS HIDDEN).
    R"sql(
CREATE TABLE exercises (
    name     TEXT PRIMARY KEY,
    text     TEXT NOT NULL,                  -- the exercise file (pupitre-exercise(5))
    added_ms INTEGER NOT NULL,
    who      TEXT NOT NULL
) STRICT;

CREATE TABLE attempts (
    id           INTEGER PRIMARY KEY,
    exercise     TEXT NOT NULL,
    exercise_sha TEXT NOT NULL,              -- SHA-256 of the exercise's text
    student      TEXT NOT NULL,
    machine      TEXT NOT NULL,              -- where the attempt's correctors and origins live
    started_ms   INTEGER NOT NULL,
    submitted_ms INTEGER,                    -- NULL while in progress
    seed         TEXT NOT NULL DEFAULT '',   -- hex; written when submitted
    score        INTEGER,
    seconds      REAL,
    crashes      INTEGER NOT NULL DEFAULT 0,
    scrapped     INTEGER NOT NULL DEFAULT 0 CHECK (scrapped IN (0, 1)),
    mistakes     TEXT NOT NULL DEFAULT '',   -- the mistakes' words, space-separated
    found        TEXT NOT NULL DEFAULT '',   -- NAME=VALUE lines, as entered
    report       TEXT NOT NULL DEFAULT '',   -- the report's lines
    signature    TEXT NOT NULL DEFAULT ''    -- HMAC-SHA-256 with the class key
) STRICT;
CREATE INDEX attempts_by_exercise ON attempts (exercise, student, id);
)sql",
    // 4: the class (issue 34): every text an exercise had before its current
    // one, so that an attempt made on it is graded and reported on it; and
    // each attempt's record of what the operator did that the grade reads.
    R"sql(
CREATE TABLE exercise_texts (
    sha      TEXT PRIMARY KEY,               -- SHA-256 of the text, as attempts.exercise_sha
    name     TEXT NOT NULL,
    text     TEXT NOT NULL,
    added_ms INTEGER NOT NULL,
    who      TEXT NOT NULL
) STRICT;
ALTER TABLE attempts ADD COLUMN record TEXT NOT NULL DEFAULT '';  -- readings and shims, a line each
)sql",
};

inline constexpr int kCount = int(sizeof kMigrations / sizeof kMigrations[0]);

}  // namespace pupitre::store::schema
