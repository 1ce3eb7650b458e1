// The SQLite backend, pupitre's embedded default: one file, created
// atomically; checked before SQLite opens it; WAL; SQLite's result codes turned
// into messages a user can act on. All of pupitre's SQLite-only SQL is here and
// in store/schema.hpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <fcntl.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>

#include "core/i18n.hpp"
#include "store/backend.hpp"
#include "store/schema.hpp"
#include "store/store.hpp"

namespace pupitre::store {

static_assert(kSchemaVersion == schema::kCount, "kSchemaVersion must match the migrations");
static_assert(db::kRow == SQLITE_ROW && db::kDone == SQLITE_DONE && db::kOk == SQLITE_OK &&
                  db::kCorrupt == SQLITE_CORRUPT,
              "the backend's step codes are SQLite's");

namespace {

std::string dir_of(const std::string& path) {
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

bool exists(const std::string& p) {
    struct stat st;
    return ::stat(p.c_str(), &st) == 0;
}

// mkdir -p, new directories private to the user (XDG base directory spec).
int make_dirs(const std::string& dir) {
    if (dir.empty() || exists(dir)) return 0;
    if (int rc = make_dirs(dir_of(dir))) return rc;
    if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) return errno;
    return 0;
}

void remove_with_sidecars(const std::string& p) {
    for (const char* s : {"", "-journal", "-wal", "-shm"}) ::unlink((p + s).c_str());
}

uint32_t be32(const unsigned char* b) {
    return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}

off_t file_size(const std::string& p) {
    struct stat st;
    return ::stat(p.c_str(), &st) == 0 ? st.st_size : 0;
}

// Looks at the file's first 100 bytes before SQLite does: a file that is not an
// SQLite database, or one shorter than its header says, is refused without
// SQLite ever opening it. `empty` is set for a zero-length file.
StoreError precheck(const std::string& path, bool& empty) {
    empty = false;
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        return {Fault::cannot_create,
                strf(tr("%s: cannot open the store: %s"), path.c_str(), std::strerror(e))};
    }
    struct stat st;
    if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
        ::close(fd);
        return {Fault::cannot_create, strf(tr("%s: is a directory, not a store"), path.c_str())};
    }
    unsigned char h[100];
    ssize_t n = ::pread(fd, h, sizeof h, 0);
    ::close(fd);
    if (n < 0)
        return {Fault::io, strf(tr("%s: cannot read: %s"), path.c_str(), std::strerror(errno))};
    if (st.st_size == 0) {
        empty = true;
        return {};
    }
    if (n < 100 || std::memcmp(h, "SQLite format 3", 16) != 0)
        return {Fault::bad_data,
                strf(tr("%s: not a pupitre store (not an SQLite database); left untouched"),
                     path.c_str())};
    uint32_t page = uint32_t(h[16]) << 8 | h[17];
    if (page == 1) page = 65536;
    uint32_t pages = be32(h + 28);
    bool count_valid = std::memcmp(h + 24, h + 92, 4) == 0 && pages > 0;
    // With a write-ahead log or a hot journal the file may legitimately lag behind
    // its header: SQLite settles that itself.
    bool log = file_size(path + "-wal") > 0 || file_size(path + "-journal") > 0;
    if (count_valid && !log && uint64_t(st.st_size) < uint64_t(page) * pages)
        return {
            Fault::bad_data,
            strf(
                tr("%s: the store is truncated (%lld bytes, its header says %llu); left untouched: "
                   "restore a backup"),
                path.c_str(), static_cast<long long>(st.st_size),
                static_cast<unsigned long long>(uint64_t(page) * pages))};
    return {};
}

std::atomic<int> g_temp_counter{0};

}  // namespace

// ---- errors ----

namespace {
// What an SQLite failure is explained from: the result code, the start of the
// message (the store's file and what could not be done), SQLite's own text.
struct Failure {
    int rc;
    const std::string& head;
    const std::string& sqlmsg;
    sqlite3* db;
    const std::string& path;
    int busy_timeout_ms;
};

StoreError disk_full(const Failure& f) {
    return {Fault::io,
            f.head + tr("disk full (or the store reached its size limit); nothing was changed")};
}

StoreError locked(const Failure& f) {
    return {Fault::io,
            f.head + strf(tr("the store is locked by another process (waited %.1f s); nothing was "
                             "changed, try again"),
                          f.busy_timeout_ms / 1000.0)};
}

StoreError not_a_store(const Failure& f) {
    return {Fault::bad_data,
            f.head + tr("not a pupitre store (not an SQLite database); left untouched")};
}

StoreError damaged(const Failure& f) {
    return {Fault::bad_data,
            f.head + strf(tr("the store is damaged (%s); nothing was changed: restore a backup, or "
                             "try sqlite3's .recover on a copy"),
                          f.sqlmsg.c_str())};
}

// SQLite keeps its -wal and -shm files beside the store: an unwritable
// directory is the likely cause, else the system's errno.
StoreError cannot_open(const Failure& f) {
    std::string dir = dir_of(f.path);
    if (::access(dir.c_str(), W_OK) != 0)
        return {Fault::cannot_create,
                f.head + strf(tr("cannot open the store: its directory %s is not writable (SQLite "
                                 "keeps its -wal and -shm files there)"),
                              dir.c_str())};
    int e = f.db ? sqlite3_system_errno(f.db) : 0;
    return {Fault::cannot_create,
            f.head + (e ? strf(tr("cannot open the store: %s"), std::strerror(e))
                        : std::string(tr("cannot open the store")))};
}

StoreError cannot_write(const Failure& f) {
    return {Fault::cannot_create,
            f.head + strf(tr("cannot write the store (%s): check the permissions of the file and "
                             "its directory"),
                          f.sqlmsg.c_str())};
}

StoreError too_big(const Failure& f) {
    return {Fault::bad_data, f.head + strf(tr("too big for the store (%s)"), f.sqlmsg.c_str())};
}

StoreError refused(const Failure& f) {
    return {Fault::bad_data,
            f.head + strf(tr("refused by the store (%s); nothing was changed"), f.sqlmsg.c_str())};
}

StoreError io_error(const Failure& f) {
    int e = f.db ? sqlite3_system_errno(f.db) : 0;
    if (e == ENOSPC || e == EDQUOT || e == EFBIG)
        return {Fault::io,
                f.head + strf(tr("disk full (%s); nothing was changed"), std::strerror(e))};
    // errno is often gone by now (the rollback made other calls).
    if (f.rc == SQLITE_IOERR_WRITE || f.rc == SQLITE_IOERR_FSYNC || f.rc == SQLITE_IOERR_TRUNCATE)
        return {Fault::io,
                f.head + tr("cannot write the store (disk full, quota or file size limit "
                            "reached, or a device error); nothing was changed")};
    return {Fault::io,
            f.head + (e ? strf(tr("I/O error (%s: %s); nothing was changed"), f.sqlmsg.c_str(),
                               std::strerror(e))
                        : strf(tr("I/O error (%s); nothing was changed"), f.sqlmsg.c_str()))};
}

// The explanation of each primary result code; any other is an I/O fault with
// SQLite's text.
struct Explain {
    int primary;
    StoreError (*explain)(const Failure&);
};
constexpr Explain kExplain[] = {
    {SQLITE_FULL, disk_full},        {SQLITE_BUSY, locked},        {SQLITE_LOCKED, locked},
    {SQLITE_NOTADB, not_a_store},    {SQLITE_CORRUPT, damaged},    {SQLITE_CANTOPEN, cannot_open},
    {SQLITE_READONLY, cannot_write}, {SQLITE_PERM, cannot_write},  {SQLITE_AUTH, cannot_write},
    {SQLITE_TOOBIG, too_big},        {SQLITE_CONSTRAINT, refused}, {SQLITE_MISMATCH, refused},
    {SQLITE_IOERR, io_error},
};
}  // namespace

namespace {

int configure(sqlite3* db, const Options& o) {
    sqlite3_extended_result_codes(db, 1);
    sqlite3_busy_timeout(db, o.busy_timeout_ms);
    // FULL: a committed change survives a power cut, not only a crash.
    int rc = sqlite3_exec(db, "PRAGMA foreign_keys = ON; PRAGMA synchronous = FULL;", nullptr,
                          nullptr, nullptr);
    if (rc == SQLITE_OK && o.max_page_count > 0) {
        std::string p = "PRAGMA max_page_count = " + std::to_string(o.max_page_count);
        sqlite3_stmt* s = nullptr;  // the pragma returns a row
        rc = sqlite3_prepare_v2(db, p.c_str(), -1, &s, nullptr);
        if (rc == SQLITE_OK) rc = sqlite3_step(s) == SQLITE_ROW ? SQLITE_OK : sqlite3_errcode(db);
        sqlite3_finalize(s);
    }
    return rc;
}

// Reads one integer pragma or query; returns the SQLite result code.
int query_int(sqlite3* db, const char* sql, int64_t& out) {
    sqlite3_stmt* s = nullptr;
    int rc = sqlite3_prepare_v2(db, sql, -1, &s, nullptr);
    if (rc != SQLITE_OK) return rc;
    rc = sqlite3_step(s);
    if (rc == SQLITE_ROW) {
        out = sqlite3_column_int64(s, 0);
        rc = SQLITE_OK;
    }
    sqlite3_finalize(s);
    return rc;
}

int query_text(sqlite3* db, const char* sql, std::string& out) {
    sqlite3_stmt* s = nullptr;
    int rc = sqlite3_prepare_v2(db, sql, -1, &s, nullptr);
    if (rc != SQLITE_OK) return rc;
    rc = sqlite3_step(s);
    if (rc == SQLITE_ROW) {
        const unsigned char* t = sqlite3_column_text(s, 0);
        out = t ? reinterpret_cast<const char*>(t) : "";
        rc = SQLITE_OK;
    }
    sqlite3_finalize(s);
    return rc;
}

}  // namespace

// ---- the backend ----

namespace {

class SqliteStmt final : public db::Stmt {
  public:
    explicit SqliteStmt(sqlite3_stmt* s) : s_(s) {}
    ~SqliteStmt() override { sqlite3_finalize(s_); }
    void bind(int i, int64_t v) override { sqlite3_bind_int64(s_, i, v); }
    void bind(int i, double v) override { sqlite3_bind_double(s_, i, v); }
    void bind(int i, std::string_view t) override {
        sqlite3_bind_text(s_, i, t.data(), int(t.size()), SQLITE_TRANSIENT);
    }
    void blob(int i, std::string_view b) override {
        sqlite3_bind_blob64(s_, i, b.empty() ? "" : b.data(), b.size(), SQLITE_STATIC);
    }
    void null(int i) override { sqlite3_bind_null(s_, i); }
    int step() override { return sqlite3_step(s_); }
    void reset() override {
        sqlite3_reset(s_);
        sqlite3_clear_bindings(s_);
    }
    bool is_null(int c) const override { return sqlite3_column_type(s_, c) == SQLITE_NULL; }
    int64_t i64(int c) const override { return sqlite3_column_int64(s_, c); }
    double f64(int c) const override { return sqlite3_column_double(s_, c); }
    std::string_view view(int c) const override {
        const void* p = sqlite3_column_blob(s_, c);  // text or blob: the bytes as stored
        int n = sqlite3_column_bytes(s_, c);
        return p ? std::string_view(static_cast<const char*>(p), size_t(n)) : std::string_view();
    }

  private:
    sqlite3_stmt* s_;
};

// SQLite's own SQL: the schema (store/schema.hpp), the pragmas that hold the
// application id and the schema version, the checks.
class SqliteBackend final : public db::Backend {
  public:
    SqliteBackend(std::string path, int busy_timeout_ms)
        : path_(std::move(path)), busy_timeout_ms_(busy_timeout_ms) {}
    ~SqliteBackend() override { close(); }

    int open(int flags) {
        return sqlite3_open_v2(path_.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    }
    // Closes the connection (a clean close folds the log into the file).
    int close() {
        stmts_.clear();
        int rc = db_ ? sqlite3_close(db_) : SQLITE_OK;
        if (rc != SQLITE_OK) sqlite3_close_v2(db_);
        db_ = nullptr;
        return rc;
    }
    sqlite3* db() const { return db_; }

    db::Stmt* prepare(const char* sql, int& rc) override {
        auto it = stmts_.find(sql);
        if (it != stmts_.end()) return it->second.get();
        sqlite3_stmt* s = nullptr;
        rc = sqlite3_prepare_v3(db_, sql, -1, SQLITE_PREPARE_PERSISTENT, &s, nullptr);
        if (rc != SQLITE_OK) return nullptr;
        return stmts_.emplace(sql, std::make_unique<SqliteStmt>(s)).first->second.get();
    }
    int exec(const char* sql) override { return sqlite3_exec(db_, sql, nullptr, nullptr, nullptr); }
    // One operator action, one transaction: BEGIN IMMEDIATE takes the write
    int insert_rows(const char* table, const char* columns, int width,
                    const std::vector<db::Value>& values) override;
    // lock at once (waiting up to the busy timeout), so two writers never
    // deadlock on an upgrade from a read lock.
    int begin_write() override { return exec("BEGIN IMMEDIATE"); }
    int begin_migration() override { return begin_write(); }
    int begin_read() override { return exec("BEGIN"); }
    int commit() override { return exec("COMMIT"); }
    void rollback() override {
        if (db_ && !sqlite3_get_autocommit(db_)) exec("ROLLBACK");
    }
    bool retryable(int) const override { return false; }
    StoreError explain(int rc, const std::string& head) const override;

    int read_meta(db::Meta& m) override;
    int schema_version() const override { return kSchemaVersion; }
    const char* migration(int v) const override { return schema::kMigrations[v]; }
    int write_meta(int64_t version) override {
        std::string pragmas = "PRAGMA application_id = " + std::to_string(kApplicationId) +
                              "; PRAGMA user_version = " + std::to_string(version) + ";";
        return exec(pragmas.c_str());
    }
    int data_version(int64_t& out) override { return query_int(db_, "PRAGMA data_version", out); }
    int integrity(std::string& out) override;
    int after_copy() override { return SQLITE_OK; }
    std::string_view engine() const override { return "sqlite"; }
    bool remote() const override { return false; }

  private:
    std::string path_;
    int busy_timeout_ms_;
    sqlite3* db_ = nullptr;
    std::map<const char*, std::unique_ptr<SqliteStmt>> stmts_;  // keyed by the SQL literal
    std::map<std::pair<const char*, const char*>, std::string> inserts_;  // insert_rows' SQL
};

// One prepared INSERT stepped for each row: in the process, that is as fast
// as SQLite writes rows.
int SqliteBackend::insert_rows(const char* table, const char* columns, int width,
                               const std::vector<db::Value>& values) {
    std::string& sql = inserts_[{table, columns}];
    if (sql.empty()) {
        sql = std::string("INSERT INTO ") + table + " (" + columns + ") VALUES (";
        for (int i = 1; i <= width; ++i) sql += (i > 1 ? ", ?" : "?") + std::to_string(i);
        sql += ")";
    }
    int rc = SQLITE_OK;
    db::Stmt* s = prepare(sql.c_str(), rc);
    if (!s) return rc;
    for (size_t at = 0; at + size_t(width) <= values.size(); at += size_t(width)) {
        for (int i = 0; i < width; ++i) {
            const db::Value& v = values[at + size_t(i)];
            if (v.kind == db::Value::Kind::integer)
                s->bind(i + 1, v.integer);
            else if (v.kind == db::Value::Kind::text)
                s->bind(i + 1, v.chars);
            else if (v.kind == db::Value::Kind::bytes)
                s->blob(i + 1, v.chars);
            else
                s->null(i + 1);
        }
        rc = s->step();
        s->reset();
        if (rc != SQLITE_DONE) return rc;
    }
    return SQLITE_OK;
}

StoreError SqliteBackend::explain(int rc, const std::string& head) const {
    int primary = rc & 0xff;
    std::string sqlmsg = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    Failure f{rc, head, sqlmsg, db_, path_, busy_timeout_ms_};
    for (const Explain& x : kExplain)
        if (x.primary == primary) return x.explain(f);
    return {Fault::io, head + strf(tr("%s; nothing was changed"), sqlmsg.c_str())};
}

int SqliteBackend::read_meta(db::Meta& m) {
    int64_t app = 0, objects = 0;
    int rc = query_int(db_, "PRAGMA application_id", app);
    if (rc == SQLITE_OK) rc = query_int(db_, "PRAGMA user_version", m.version);
    if (rc == SQLITE_OK) rc = query_int(db_, "SELECT count(*) FROM sqlite_schema", objects);
    if (rc != SQLITE_OK) return rc;
    m.blank = app == 0 && m.version == 0 && objects == 0;
    if (!m.blank && uint32_t(app) != kApplicationId) {
        char id[16];
        std::snprintf(id, sizeof id, "0x%08X", unsigned(uint32_t(app)));
        m.foreign = true;
        m.foreign_why =
            strf(tr("an SQLite database of another application, application_id %s"), id);
    }
    return SQLITE_OK;
}

int SqliteBackend::integrity(std::string& out) {
    sqlite3_stmt* s = nullptr;
    int rc = sqlite3_prepare_v2(db_, "PRAGMA integrity_check", -1, &s, nullptr);
    if (rc != SQLITE_OK) return rc;
    out.clear();
    while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
        if (!out.empty()) out += '\n';
        const unsigned char* t = sqlite3_column_text(s, 0);
        out += t ? reinterpret_cast<const char*>(t) : "";
    }
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) return rc;
    // Foreign keys are not part of integrity_check.
    rc = sqlite3_prepare_v2(db_, "PRAGMA foreign_key_check", -1, &s, nullptr);
    if (rc == SQLITE_OK) {
        while (sqlite3_step(s) == SQLITE_ROW) {
            const unsigned char* t = sqlite3_column_text(s, 0);
            out += std::string("\nforeign key broken in ") +
                   (t ? reinterpret_cast<const char*>(t) : "?") + " row " +
                   std::to_string(sqlite3_column_int64(s, 1));
        }
        sqlite3_finalize(s);
    }
    return SQLITE_OK;
}

}  // namespace

// ---- opening ----

Result<std::unique_ptr<Store>> Store::open_sqlite(const std::string& path, const Options& o) {
    Result<std::unique_ptr<Store>> r;
    if (path.empty()) {
        r.error = {Fault::cannot_create,
                   tr("no store path: set HOME or XDG_DATA_HOME, or give --db FILE")};
        return r;
    }
    std::unique_ptr<Store> st(new Store);
    st->path_ = path;
    st->short_name_ = path;
    st->opt_ = o;
    st->user_ = o.user.empty() ? os_user() : o.user;

    if (!exists(path)) {
        if (!o.create) {
            r.error = {Fault::not_found, strf(tr("%s: no such store"), path.c_str())};
            return r;
        }
        if (o.create_parents) {
            if (int e = make_dirs(dir_of(path))) {
                r.error = {Fault::cannot_create,
                           strf(tr("%s: cannot create the directory %s: %s"), path.c_str(),
                                dir_of(path).c_str(), std::strerror(e))};
                return r;
            }
        }
        if ((r.error = st->create_file())) return r;
    }

    bool empty = false;
    if ((r.error = precheck(path, empty))) return r;
    auto backend = std::make_unique<SqliteBackend>(path, o.busy_timeout_ms);
    int rc = backend->open(SQLITE_OPEN_READWRITE);
    if (rc == SQLITE_OK) rc = configure(backend->db(), o);
    st->db_ = std::move(backend);
    if (rc != SQLITE_OK) {
        r.error = st->fail(rc, tr("cannot open the store"));
        return r;
    }
    if (empty) {
        // A zero-length file holds nothing to lose: make it a store in place.
        if ((r.error = st->exec("PRAGMA journal_mode = WAL"))) return r;
    }
    bool fresh = false;
    if ((r.error = st->validate_and_migrate(fresh))) return r;
    if (fresh) st->created_ = true;
    // The journal mode is kept in the file: set it again if something changed it.
    std::string mode;
    if (query_text(static_cast<SqliteBackend&>(*st->db_).db(), "PRAGMA journal_mode", mode) ==
            SQLITE_OK &&
        mode != "wal")
        if ((r.error = st->exec("PRAGMA journal_mode = WAL"))) return r;
    r.value = std::move(st);
    return r;
}

// A new store is built under a temporary name and linked into place only when
// complete and seeded, so no process ever sees a half-made store, and a crash
// or a full disk during creation leaves nothing behind under the real name.
StoreError Store::create_file() {
    std::string tmp = dir_of(path_) + "/." + path_.substr(path_.rfind('/') + 1) + ".new-" +
                      std::to_string(getpid()) + "-" + std::to_string(g_temp_counter++);
    auto backend = std::make_unique<SqliteBackend>(tmp, opt_.busy_timeout_ms);
    int rc = backend->open(SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    if (rc == SQLITE_OK) rc = configure(backend->db(), opt_);
    auto give_up = [&](StoreError e) {
        backend.reset();
        db_.reset();
        remove_with_sidecars(tmp);
        return e;
    };
    if (rc != SQLITE_OK) {
        int e = backend->db() ? sqlite3_system_errno(backend->db()) : 0;
        std::string why = e ? std::strerror(e) : sqlite3_errstr(rc);
        if (rc == SQLITE_CANTOPEN && ::access(dir_of(path_).c_str(), W_OK) != 0)
            why = strf(tr("the directory %s is not writable"), dir_of(path_).c_str());
        return give_up({Fault::cannot_create,
                        strf(tr("%s: cannot create the store: %s"), path_.c_str(), why.c_str())});
    }
    db_ = std::move(backend);
    bool fresh = false;
    StoreError e = validate_and_migrate(fresh);
    if (!e) e = exec("PRAGMA journal_mode = WAL");
    if (e) {
        // fail() began the message with "PATH: ".
        e.message = strf(tr("%s: cannot create the store: %s"), path_.c_str(),
                         e.message.substr(e.message.find(": ") + 2).c_str());
        return give_up(e);
    }
    rc =
        static_cast<SqliteBackend&>(*db_).close();  // checkpoints the log into the file, removes it
    db_.reset();
    if (rc != SQLITE_OK)
        return give_up({Fault::io, strf(tr("%s: cannot create the store: %s"), path_.c_str(),
                                        sqlite3_errstr(rc))});
    if (int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC); fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    bool linked = ::link(tmp.c_str(), path_.c_str()) == 0;
    if (!linked && errno != EEXIST) {
        int err = errno;  // EEXIST: another process created it meanwhile; we use theirs
        remove_with_sidecars(tmp);
        return {Fault::cannot_create,
                strf(tr("%s: cannot create the store: %s"), path_.c_str(), std::strerror(err))};
    }
    remove_with_sidecars(tmp);
    if (int fd = ::open(dir_of(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    created_ = linked;
    return {};
}

}  // namespace pupitre::store
