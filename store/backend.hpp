// Inside the store: the database engine behind a Store. One face, two
// backends: SQLite (store/sqlite.cpp, the embedded default) and PostgreSQL
// (store/postgres.cpp, a class server). Each backend keeps its own SQL in its
// own file (schema, pragmas or catalogue queries, transaction control); the
// statements the store runs on both (store/programs.cpp, values.cpp,
// training.cpp) are written once in the SQL both engines read, with ?N
// parameters. Not for use outside store/.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "store/store.hpp"

namespace pupitre::store::db {

// What a statement's step gives. Anything else is an error code that only the
// backend which gave it explains (explain()).
inline constexpr int kOk = 0;
inline constexpr int kRow = 100;
inline constexpr int kDone = 101;
// Not an engine's code: the store found its own data inconsistent (a revision
// its program row names is missing). Every backend explains it as damage.
inline constexpr int kCorrupt = 11;

// A prepared statement, kept by its backend and reused. Columns are numbered
// from 0, parameters from 1.
class Stmt {
  public:
    virtual ~Stmt() = default;
    virtual void bind(int i, int64_t v) = 0;
    virtual void bind(int i, double v) = 0;
    virtual void bind(int i, std::string_view text) = 0;
    // Program texts: stored and given back byte for byte, whatever their encoding.
    virtual void blob(int i, std::string_view bytes) = 0;
    virtual void null(int i) = 0;
    // Runs the statement on the first call, then moves to the next row.
    virtual int step() = 0;
    // Ready for the next use: bindings cleared, results released.
    virtual void reset() = 0;
    virtual bool is_null(int c) const = 0;
    virtual int64_t i64(int c) const = 0;
    virtual double f64(int c) const = 0;
    // The column's bytes as stored (text or blob); valid until the next step.
    virtual std::string_view view(int c) const = 0;
};

// A value of a row Backend::insert_rows writes: NULL, an integer (into a
// bigint column: every integer column of both schemas), a text, or bytes (a
// program's text). The characters stay the caller's until the call returns.
struct Value {
    enum class Kind { null, integer, text, bytes };
    Kind kind = Kind::null;
    int64_t integer = 0;
    std::string_view chars;
};

// The schema's version as the store keeps it.
struct Meta {
    bool blank = false;       // nothing in it yet: ours to create
    bool foreign = false;     // something else's database: never touched
    std::string foreign_why;  // what it is, for the refusal ("application_id 0x…")
    int64_t version = 0;
    bool may_change = true;  // this login may change the tables (a class's student may not)
};

class Backend {
  public:
    virtual ~Backend() = default;
    // The statement for `sql`, prepared once per connection (keyed by the
    // literal's address: pass string literals or strings that outlive the
    // store). Null with `rc` set when it cannot be prepared.
    virtual Stmt* prepare(const char* sql, int& rc) = 0;
    // The same for a statement without parameters whose many rows hold
    // integers and texts only (the list of 10,000 programs): PostgreSQL sends
    // them by COPY in its binary format, each row one piece that we cut
    // ourselves, rather than as a result whose 100,000 fields libpq takes one
    // by one. SQLite steps the statement as prepare gives it.
    virtual Stmt* prepare_many(const char* sql, int& rc) { return prepare(sql, rc); }
    // The list's statement when this engine keeps a program's integers
    // packed (PostgreSQL: listing, title, modified_by; schema_pg.hpp), or
    // null: the list then reads its columns as they are.
    virtual const char* packed_list() const { return nullptr; }
    // Runs one or several statements without results.
    virtual int exec(const char* sql) = 0;
    // Inserts rows into `table`'s `columns` ("a, b, c"), in a transaction:
    // `values` holds them one after another, `width` values each. Made for
    // many rows at once (an import): PostgreSQL receives them in one COPY,
    // with no statement to plan per row; SQLite steps one prepared INSERT.
    // `table` and `columns` are literals (statements are kept by address).
    virtual int insert_rows(const char* table, const char* columns, int width,
                            const std::vector<Value>& values) = 0;
    // A write transaction with the isolation every write needs: SQLite takes
    // the write lock at once (BEGIN IMMEDIATE); PostgreSQL runs SERIALIZABLE.
    virtual int begin_write() = 0;
    virtual int commit() = 0;
    virtual void rollback() = 0;
    // A read of several statements from one snapshot.
    virtual int begin_read() = 0;
    // The transaction that creates or upgrades the schema, once another
    // process doing the same has finished (it re-reads the version inside).
    virtual int begin_migration() = 0;
    // True when the failure `rc` was a serialization failure or a deadlock:
    // the whole transaction may be run again and may then succeed.
    virtual bool retryable(int rc) const = 0;
    // A StoreError a user can act on, beginning with `head` ("STORE: what: ").
    virtual StoreError explain(int rc, const std::string& head) const = 0;

    // Schema versions: what the store holds, the DDL of migration v (taking
    // a store from v to v + 1), and writing the new version (inside the
    // migration's transaction).
    virtual int read_meta(Meta& m) = 0;
    virtual int schema_version() const = 0;  // the one this pupitre writes
    // A store at an older `version` that this login may not upgrade (a
    // class's student on a server the teacher has not opened with this
    // pupitre yet): true when this pupitre works on it as it is, and then
    // does so; false when it needs the upgrade.
    virtual bool work_at(int64_t /*version*/) { return false; }
    virtual const char* migration(int v) const = 0;
    virtual int write_meta(int64_t version) = 0;

    // A number that changes when another connection commits a change.
    virtual int data_version(int64_t& out) = 0;
    // "ok" or the problems found.
    virtual int integrity(std::string& out) = 0;
    // After rows were copied in with their ids (store copy): the ids given
    // next continue after them.
    virtual int after_copy() = 0;
    // "sqlite" or "postgresql".
    virtual std::string_view engine() const = 0;
    // True when what is read crosses a network (a server): a long text is
    // then better compared where it is stored than read back (Store::save).
    virtual bool remote() const = 0;
};

// The store's address for people: a file path, or a PostgreSQL URI without
// its password.
std::string display_name(const std::string& target);

// True when `target` names a PostgreSQL server (a postgresql:// or
// postgres:// URI, or a key=value connection string) rather than a file.
bool is_server(std::string_view target);

}  // namespace pupitre::store::db
