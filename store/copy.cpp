// `store copy FROM TO`: a whole store moved to another, either engine to
// either, row for row with the ids and revision numbers as they are, in one
// transaction on the target; then both sides are read again and compared,
// table by table, by row count and checksum.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>
#include <string>
#include <vector>

#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "store/sql.hpp"
#include "store/store.hpp"

namespace pupitre::store {

namespace {

// A column's kind: i integer, t text, b bytes (program texts), f real.
struct Table {
    const char* name;
    const char* select;  // every column, in key order
    const char* insert;  // the same columns as ?1…?n
    const char* kinds;   // one letter per column
};

// Parents before children: machines before their values; a program's
// revisions before its row (a server checks its current revision as the row
// is written; the revisions' own key on their program, at commit).
constexpr Table kTables[] = {
    {"machines", "SELECT name, profile, builtin, updated_ms FROM machines ORDER BY name",
     "INSERT INTO machines (name, profile, builtin, updated_ms) VALUES (?1, ?2, ?3, ?4)", "ttii"},
    {"revisions",
     "SELECT program, rev, kind, based_on, conflict, text, size, lines, who, at_ms, source FROM "
     "revisions ORDER BY program, rev",
     "INSERT INTO revisions (program, rev, kind, based_on, conflict, text, size, lines, who, "
     "at_ms, source) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)",
     "iitiibiitit"},
    {"programs",
     "SELECT number, idx, title, head, last_rev, conflict, deleted, size, lines, modified_ms, "
     "modified_by FROM programs ORDER BY number",
     "INSERT INTO programs (number, idx, title, head, last_rev, conflict, deleted, size, lines, "
     "modified_ms, modified_by) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)",
     "iitiiiiiiit"},
    {"correctors", "SELECT machine, d, field, value FROM correctors ORDER BY machine, d, field",
     "INSERT INTO correctors (machine, d, field, value) VALUES (?1, ?2, ?3, ?4)", "titi"},
    {"origins", "SELECT machine, kind, axis, value FROM origins ORDER BY machine, kind, axis",
     "INSERT INTO origins (machine, kind, axis, value) VALUES (?1, ?2, ?3, ?4)", "ttti"},
    {"audit", "SELECT id, at_ms, who, machine, name, old, new, source FROM audit ORDER BY id",
     "INSERT INTO audit (id, at_ms, who, machine, name, old, new, source) VALUES (?1, ?2, ?3, "
     "?4, ?5, ?6, ?7, ?8)",
     "iitttiit"},
    {"settings", "SELECT key, value FROM settings ORDER BY key",
     "INSERT INTO settings (key, value) VALUES (?1, ?2)", "tt"},
    {"imd_history", "SELECT id, at_ms, who, machine, block FROM imd_history ORDER BY id",
     "INSERT INTO imd_history (id, at_ms, who, machine, block) VALUES (?1, ?2, ?3, ?4, ?5)",
     "iittt"},
    {"workshops", "SELECT machine, setup, part, updated_ms, who FROM workshops ORDER BY machine",
     "INSERT INTO workshops (machine, setup, part, updated_ms, who) VALUES (?1, ?2, ?3, ?4, ?5)",
     "tttit"},
    {"exercises", "SELECT name, text, added_ms, who FROM exercises ORDER BY name",
     "INSERT INTO exercises (name, text, added_ms, who) VALUES (?1, ?2, ?3, ?4)", "ttit"},
    {"exercise_texts", "SELECT sha, name, text, added_ms, who FROM exercise_texts ORDER BY sha",
     "INSERT INTO exercise_texts (sha, name, text, added_ms, who) VALUES (?1, ?2, ?3, ?4, ?5)",
     "tttit"},
    {"attempts",
     "SELECT id, exercise, exercise_sha, student, machine, started_ms, submitted_ms, seed, score, "
     "seconds, crashes, scrapped, mistakes, found, report, signature, record FROM attempts "
     "ORDER BY id",
     "INSERT INTO attempts (id, exercise, exercise_sha, student, machine, started_ms, "
     "submitted_ms, seed, score, seconds, crashes, scrapped, mistakes, found, report, signature, "
     "record) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17)",
     "itttiiitifiittttt"},
};

// One row as bytes the checksum reads the same on both engines: each column
// its kind, N for null, then its length and value.
std::string row_bytes(const sql::Use& u, const char* kinds) {
    std::string out;
    for (int c = 0; kinds[c]; ++c) {
        if (u.is_null(c)) {
            out += "N;";
            continue;
        }
        std::string v;
        if (kinds[c] == 'i') {
            v = std::to_string(u.i64(c));
        } else if (kinds[c] == 'f') {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.17g", u.f64(c));
            v = buf;
        } else {
            v = u.str(c);
        }
        out += kinds[c] + std::to_string(v.size()) + ":" + v + ";";
    }
    return out;
}

void bind_column(sql::Use& to, const sql::Use& from, int c, char kind) {
    if (from.is_null(c))
        to.null(c + 1);
    else if (kind == 'i')
        to.bind(c + 1, from.i64(c));
    else if (kind == 'f')
        to.bind(c + 1, from.f64(c));
    else if (kind == 'b')
        to.blob(c + 1, from.view(c));
    else
        to.bind(c + 1, from.view(c));
}

}  // namespace

// Rows and checksum of one table, read from this store.
Result<CopyReport::Table> Store::table_sum(const char* name, const char* select,
                                           const char* kinds) {
    Result<CopyReport::Table> r;
    r.value.name = name;
    sql::Use u = use(select);
    if ((r.error = u.error)) return r;
    std::string digests;
    int rc;
    while ((rc = u.step()) == db::kRow) {
        digests += sha256_hex(row_bytes(u, kinds));
        ++r.value.rows;
    }
    if (rc != db::kDone) r.error = fail(rc, strf(tr("cannot read the table %s"), name));
    r.value.checksum = sha256_hex(digests);
    return r;
}

Result<CopyReport> Store::copy_to(Store& target) {
    Result<CopyReport> r;
    // The target must be empty: a copy never merges two stores.
    for (const Table& t : kTables) {
        Result<CopyReport::Table> there = target.table_sum(t.name, t.select, t.kinds);
        if ((r.error = there.error)) return r;
        if (there.value.rows)
            return {{},
                    {Fault::bad_data,
                     strf(tr("%s: not empty (%lld rows in %s); copy into a new store"),
                          target.path_.c_str(), static_cast<long long>(there.value.rows), t.name)}};
    }
    if ((r.error = begin_read())) return r;  // one snapshot of the source
    r.error = target.in_write([&]() -> StoreError {
        for (const Table& t : kTables) {
            sql::Use from = use(t.select);
            if (from.error) return from.error;
            int rc;
            while ((rc = from.step()) == db::kRow) {
                sql::Use to = target.use(t.insert);
                if (to.error) return to.error;
                for (int c = 0; t.kinds[c]; ++c) bind_column(to, from, c, t.kinds[c]);
                if (int w = to.step(); w != db::kDone)
                    return target.fail(w, strf(tr("cannot copy the table %s"), t.name));
            }
            if (rc != db::kDone) return fail(rc, strf(tr("cannot read the table %s"), t.name));
        }
        int rc = target.db_->after_copy();
        return rc == db::kOk ? StoreError{} : target.fail(rc, tr("cannot save the change"));
    });
    rollback();
    if (r.error) return r;
    // Both sides read again, each from its own committed state.
    for (const Table& t : kTables) {
        Result<CopyReport::Table> here = table_sum(t.name, t.select, t.kinds);
        Result<CopyReport::Table> there = target.table_sum(t.name, t.select, t.kinds);
        if ((r.error = here.error) || (r.error = there.error)) return r;
        if (here.value.rows != there.value.rows || here.value.checksum != there.value.checksum)
            return {{},
                    {Fault::io,
                     strf(tr("%s: the copy of %s differs from its source (%lld rows, "
                             "%lld copied); the target keeps what was committed"),
                          target.path_.c_str(), t.name, static_cast<long long>(here.value.rows),
                          static_cast<long long>(there.value.rows))}};
        r.value.tables.push_back(here.value);
    }
    return r;
}

}  // namespace pupitre::store
