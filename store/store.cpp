// Opening the store: creating it atomically, checking that a file is a pupitre
// store of a schema we know before touching it, migrations, transactions, and
// turning SQLite's result codes into messages a user can act on.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/store.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/i18n.hpp"
#include "store/schema.hpp"
#include "store/sql.hpp"

namespace pupitre::store {

static_assert(kSchemaVersion == schema::kCount, "kSchemaVersion must match the migrations");

int exit_code(Fault f) {
    switch (f) {
        case Fault::none:
            return 0;
        case Fault::cannot_create:
            return 73;
        case Fault::io:
            return 74;
        case Fault::bad_data:
            return 65;
        case Fault::not_found:
            return 66;
    }
    return 70;
}

std::string os_user() {
    if (const char* u = std::getenv("USER"); u && *u) return u;
    if (struct passwd* pw = getpwuid(getuid()); pw && pw->pw_name) return pw->pw_name;
    return "uid " + std::to_string(getuid());
}

std::string default_path() {
    if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x == '/')
        return std::string(x) + "/pupitre/pupitre.db";
    std::string home;
    if (const char* h = std::getenv("HOME"); h && *h)
        home = h;
    else if (struct passwd* pw = getpwuid(getuid()); pw && pw->pw_dir)
        home = pw->pw_dir;
    if (home.empty()) return {};
    return home + "/.local/share/pupitre/pupitre.db";
}

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

StoreError Store::fail(int rc, std::string_view what) {
    int primary = rc & 0xff;
    std::string sqlmsg = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    // TRANSLATORS: the beginning of a store error: the store's file, what
    // could not be done ("cannot read the store"), then why follows.
    std::string head = strf(tr("%s: %s: "), path_.c_str(), std::string(what).c_str());
    Failure f{rc, head, sqlmsg, db_, path_, opt_.busy_timeout_ms};
    for (const Explain& x : kExplain)
        if (x.primary == primary) return x.explain(f);
    return {Fault::io, head + strf(tr("%s; nothing was changed"), sqlmsg.c_str())};
}

StoreError Store::exec(const char* sql) {
    int rc = sqlite3_exec(db_, sql, nullptr, nullptr, nullptr);
    return rc == SQLITE_OK ? StoreError{} : fail(rc, "SQL");
}

sqlite3_stmt* Store::prepare(const char* sql, StoreError& e) {
    auto it = stmts_.find(sql);
    if (it != stmts_.end()) return it->second;
    sqlite3_stmt* s = nullptr;
    int rc = sqlite3_prepare_v3(db_, sql, -1, SQLITE_PREPARE_PERSISTENT, &s, nullptr);
    if (rc != SQLITE_OK) {
        e = fail(rc, tr("cannot read the store"));
        return nullptr;
    }
    stmts_.emplace(sql, s);
    return s;
}

// One operator action, one transaction: BEGIN IMMEDIATE takes the write lock at
// once (waiting up to the busy timeout), so two writers never deadlock on an
// upgrade from a read lock.
StoreError Store::begin_write() {
    int rc = sqlite3_exec(db_, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr);
    return rc == SQLITE_OK ? StoreError{} : fail(rc, tr("cannot start a change"));
}

StoreError Store::commit() {
    int rc = sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK) return {};
    StoreError e = fail(rc, tr("cannot save the change"));
    rollback();
    return e;
}

void Store::rollback() {
    if (!sqlite3_get_autocommit(db_)) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

int64_t Store::now_ms() const {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

Store::~Store() {
    for (auto& [sql, s] : stmts_) sqlite3_finalize(s);
    if (db_) sqlite3_close_v2(db_);
}

// ---- opening ----

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

Result<std::unique_ptr<Store>> Store::open(const std::string& path, const Options& o) {
    Result<std::unique_ptr<Store>> r;
    if (path.empty()) {
        r.error = {Fault::cannot_create,
                   tr("no store path: set HOME or XDG_DATA_HOME, or give --db FILE")};
        return r;
    }
    std::unique_ptr<Store> st(new Store);
    st->path_ = path;
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
    int rc = sqlite3_open_v2(path.c_str(), &st->db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX,
                             nullptr);
    if (rc == SQLITE_OK) rc = configure(st->db_, o);
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
    if (query_text(st->db_, "PRAGMA journal_mode", mode) == SQLITE_OK && mode != "wal")
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
    sqlite3* db = nullptr;
    int rc =
        sqlite3_open_v2(tmp.c_str(), &db,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr);
    if (rc == SQLITE_OK) rc = configure(db, opt_);
    auto give_up = [&](StoreError e) {
        for (auto& [sql, s] : stmts_) sqlite3_finalize(s);
        stmts_.clear();
        sqlite3_close_v2(db);
        db_ = nullptr;
        remove_with_sidecars(tmp);
        return e;
    };
    if (rc != SQLITE_OK) {
        int e = db ? sqlite3_system_errno(db) : 0;
        std::string why = e ? std::strerror(e) : sqlite3_errstr(rc);
        if (rc == SQLITE_CANTOPEN && ::access(dir_of(path_).c_str(), W_OK) != 0)
            why = strf(tr("the directory %s is not writable"), dir_of(path_).c_str());
        return give_up({Fault::cannot_create,
                        strf(tr("%s: cannot create the store: %s"), path_.c_str(), why.c_str())});
    }
    db_ = db;
    bool fresh = false;
    StoreError e = validate_and_migrate(fresh);
    if (!e) e = exec("PRAGMA journal_mode = WAL");
    if (e) {
        // fail() began the message with "PATH: ".
        e.message = strf(tr("%s: cannot create the store: %s"), path_.c_str(),
                         e.message.substr(e.message.find(": ") + 2).c_str());
        return give_up(e);
    }
    for (auto& [sql, s] : stmts_) sqlite3_finalize(s);
    stmts_.clear();
    rc = sqlite3_close(db);  // checkpoints the log into the file and removes it
    db_ = nullptr;
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

// Refuses what is not ours or newer than us before any write; creates the schema
// of an empty database; applies the migrations a store written by an older
// pupitre needs. The check is repeated inside the write transaction: another
// process may have done the work meanwhile.
StoreError Store::validate_and_migrate(bool& fresh) {
    fresh = false;
    for (int attempt = 0; attempt < 2; ++attempt) {
        int64_t app = 0, version = 0, objects = 0;
        int rc = query_int(db_, "PRAGMA application_id", app);
        if (rc == SQLITE_OK) rc = query_int(db_, "PRAGMA user_version", version);
        if (rc == SQLITE_OK) rc = query_int(db_, "SELECT count(*) FROM sqlite_schema", objects);
        if (rc != SQLITE_OK) {
            if (attempt) rollback();
            return fail(rc, tr("cannot read the store"));
        }
        bool blank = app == 0 && version == 0 && objects == 0;
        if (!blank && uint32_t(app) != kApplicationId) {
            if (attempt) rollback();
            char id[16];
            std::snprintf(id, sizeof id, "0x%08X", unsigned(uint32_t(app)));
            return {Fault::bad_data,
                    strf(tr("%s: not a pupitre store (an SQLite database of another "
                            "application, application_id %s); left untouched"),
                         path_.c_str(), id)};
        }
        if (version > kSchemaVersion) {
            if (attempt) rollback();
            return {Fault::bad_data,
                    strf(tr("%s: written by a newer pupitre (schema %lld, this pupitre knows "
                            "up to %d); left untouched: use a newer pupitre"),
                         path_.c_str(), static_cast<long long>(version), int(kSchemaVersion))};
        }
        if (version == kSchemaVersion) {
            if (attempt) rollback();
            return {};
        }
        if (attempt == 0) {
            if (StoreError e = begin_write()) return e;
            continue;  // check again under the write lock
        }
        // Under the write lock and still behind: migrate (or create) now.
        for (int v = int(version); v < kSchemaVersion; ++v) {
            if (StoreError e = exec(schema::kMigrations[v])) {
                rollback();
                return e;
            }
        }
        std::string pragmas = "PRAGMA application_id = " + std::to_string(kApplicationId) +
                              "; PRAGMA user_version = " + std::to_string(kSchemaVersion) + ";";
        if (StoreError e = exec(pragmas.c_str())) {
            rollback();
            return e;
        }
        if (blank && opt_.seed) {
            if (StoreError e = seed()) {
                rollback();
                return e;
            }
        }
        if (StoreError e = commit()) return e;
        fresh = blank;
        return {};
    }
    return {};
}

// ---- integrity ----

Result<std::string> Store::integrity_check() {
    Result<std::string> r;
    sqlite3_stmt* s = nullptr;
    int rc = sqlite3_prepare_v2(db_, "PRAGMA integrity_check", -1, &s, nullptr);
    if (rc != SQLITE_OK) {
        r.error = fail(rc, tr("cannot check the store"));
        return r;
    }
    std::string out;
    while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
        if (!out.empty()) out += '\n';
        const unsigned char* t = sqlite3_column_text(s, 0);
        out += t ? reinterpret_cast<const char*>(t) : "";
    }
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) {
        r.error = fail(rc, tr("cannot check the store"));
        return r;
    }
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
    r.value = out;
    return r;
}

}  // namespace pupitre::store
