// Store anomalies (ARCHITECTURE.md, Conventions: SQLite's own discipline): not a database, another
// application's database, a newer schema, a truncated or corrupt file, a
// read-only directory, a lock held by another process, a full disk. Each gives
// a clear error of the right kind and leaves the file as it was.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <sqlite3.h>
#include <sys/wait.h>

#include "store_helpers.hpp"

using namespace pupitre;
using namespace pupitre::store;
using test::TempDir;

namespace {

// A raw connection, as another program (or another pupitre) would hold it.
struct Raw {
    sqlite3* db = nullptr;
    explicit Raw(const std::string& path) { sqlite3_open(path.c_str(), &db); }
    ~Raw() { sqlite3_close(db); }
    int exec(const std::string& sql) {
        return sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
    }
    int64_t one(const std::string& sql) {
        sqlite3_stmt* s = nullptr;
        sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr);
        int64_t v = sqlite3_step(s) == SQLITE_ROW ? sqlite3_column_int64(s, 0) : -1;
        sqlite3_finalize(s);
        return v;
    }
};

// A store with `n` programs of about 1 KB, closed.
void make_store(const std::string& path, int n) {
    auto s = test::open_store(path);
    std::vector<Piece> pieces;
    for (int i = 1; i <= n; ++i) {
        std::string text = "%" + std::to_string(1000 + i) + " (P" + std::to_string(i) + ")\n";
        for (int b = 0; b < 40; ++b)
            text += "N" + std::to_string(b * 10) + " G1 X" + std::to_string(i) + " Y1\n";
        pieces.push_back({1000 + i, text, "t"});
    }
    ASSERT_TRUE(s->save_all(pieces).ok());
}

Fault open_fault(const std::string& path, Options o = {}) {
    auto r = Store::open(path, o);
    return r.error.fault;
}

}  // namespace

TEST(StoreAnomaly, NotADatabase) {
    TempDir t;
    std::string f = t / "part.iso";
    const std::string text = "%1\nN10 G0 X0 Y0\nM2\n" + std::string(200, ' ');
    test::spit(f, text);
    auto r = Store::open(f);
    EXPECT_EQ(r.error.fault, Fault::bad_data);
    EXPECT_EQ(exit_code(r.error.fault), 65);
    EXPECT_NE(r.error.message.find("not a pupitre store"), std::string::npos) << r.error.message;
    EXPECT_NE(r.error.message.find(f), std::string::npos);
    EXPECT_EQ(test::slurp(f), text);
    EXPECT_FALSE(test::exists(f + "-wal"));
    EXPECT_FALSE(test::exists(f + "-shm"));
    // Shorter than an SQLite header.
    test::spit(f, "SQLite");
    EXPECT_EQ(open_fault(f), Fault::bad_data);
    EXPECT_EQ(test::slurp(f), "SQLite");
}

TEST(StoreAnomaly, AnotherApplicationsDatabase) {
    TempDir t;
    std::string f = t / "other.db";
    {
        Raw raw(f);
        raw.exec("CREATE TABLE notes (x TEXT); INSERT INTO notes VALUES ('mine')");
    }
    std::string before = test::slurp(f);
    auto r = Store::open(f);
    EXPECT_EQ(r.error.fault, Fault::bad_data);
    EXPECT_NE(r.error.message.find("another application"), std::string::npos) << r.error.message;
    EXPECT_EQ(test::slurp(f), before);
    std::string g = t / "other2.db";
    {
        Raw raw(g);
        raw.exec("PRAGMA application_id = 305419896");  // 0x12345678, no table
    }
    before = test::slurp(g);
    EXPECT_EQ(open_fault(g), Fault::bad_data);
    EXPECT_EQ(test::slurp(g), before);
}

TEST(StoreAnomaly, NewerSchema) {
    TempDir t;
    std::string f = t / "new.db";
    make_store(f, 3);
    {
        Raw raw(f);
        raw.exec("PRAGMA user_version = 99");
    }
    std::string before = test::slurp(f);
    auto r = Store::open(f);
    EXPECT_EQ(r.error.fault, Fault::bad_data);
    EXPECT_NE(r.error.message.find("newer pupitre (schema 99"), std::string::npos)
        << r.error.message;
    EXPECT_EQ(test::slurp(f), before);
}

TEST(StoreAnomaly, Truncated) {
    TempDir t;
    std::string f = t / "cut.db";
    make_store(f, 300);
    std::string whole = test::slurp(f);
    ASSERT_GT(whole.size(), 100'000u);
    std::string half = whole.substr(0, whole.size() / 2);
    test::spit(f, half);
    auto r = Store::open(f);
    EXPECT_EQ(r.error.fault, Fault::bad_data);
    EXPECT_NE(r.error.message.find("truncated"), std::string::npos) << r.error.message;
    EXPECT_EQ(test::slurp(f), half);
    EXPECT_FALSE(test::exists(f + "-wal"));
}

TEST(StoreAnomaly, CorruptTablePage) {
    TempDir t;
    std::string f = t / "bad.db";
    make_store(f, 300);
    int64_t root = 0, page = 0;
    {
        Raw raw(f);
        root = raw.one("SELECT rootpage FROM sqlite_schema WHERE name = 'programs'");
        page = raw.one("PRAGMA page_size");
    }
    ASSERT_GT(root, 1);
    std::string bytes = test::slurp(f);
    for (int64_t i = 0; i < page; ++i) bytes[size_t((root - 1) * page + i)] = char(0xA5);
    test::spit(f, bytes);
    auto s = test::open_store(f);  // the schema page is sound: it opens
    ASSERT_TRUE(s);
    auto l = s->list();
    EXPECT_EQ(l.error.fault, Fault::bad_data);
    EXPECT_NE(l.error.message.find("damaged"), std::string::npos) << l.error.message;
    auto w = s->save(5, "%5\nN1\n", kNew, "");
    EXPECT_EQ(w.error.fault, Fault::bad_data) << w.error.message;
    EXPECT_NE(s->integrity_check().value, "ok");
    s.reset();
    EXPECT_EQ(test::slurp(f), bytes);
}

TEST(StoreAnomaly, CorruptSchemaPage) {
    TempDir t;
    std::string f = t / "bad1.db";
    make_store(f, 10);
    std::string bytes = test::slurp(f);
    for (size_t i = 100; i < 4096 && i < bytes.size(); ++i) bytes[i] = char(0x5A);
    test::spit(f, bytes);
    auto r = Store::open(f);
    EXPECT_EQ(r.error.fault, Fault::bad_data) << r.error.message;
    EXPECT_EQ(test::slurp(f), bytes);
}

TEST(StoreAnomaly, EmptyFileBecomesAStore) {
    TempDir t;
    std::string f = t / "empty.db";
    test::spit(f, "");
    auto s = test::open_store(f);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->created());
    EXPECT_EQ(s->list().value.size(), 2u);
}

TEST(StoreAnomaly, PathsThatCannotBeAStore) {
    TempDir t;
    auto r = Store::open(t.path);  // a directory
    EXPECT_EQ(r.error.fault, Fault::cannot_create);
    EXPECT_EQ(exit_code(r.error.fault), 73);
    r = Store::open(t / "no/such/dir/p.db");
    EXPECT_EQ(r.error.fault, Fault::cannot_create);
    EXPECT_NE(r.error.message.find("cannot create"), std::string::npos) << r.error.message;
    EXPECT_FALSE(test::exists(t / "no"));
    EXPECT_EQ(Store::open("").error.fault, Fault::cannot_create);
}

// Runs `f` in a child process that cannot write `dir` (as nobody when we are root,
// since root writes anywhere); returns the child's exit status.
template <class F>
int as_unprivileged(F f) {
    pid_t pid = fork();
    if (pid == 0) {
        if (geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(99);
        _exit(f());
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100;
}

TEST(StoreAnomaly, ReadOnlyDirectory) {
    TempDir t;
    ::chmod(t.path.c_str(), 0755);
    std::string ro = t / "ro";
    ::mkdir(ro.c_str(), 0755);
    make_store(ro + "/old.db", 5);
    std::string before = test::slurp(ro + "/old.db");
    ::chmod(ro.c_str(), 0555);
    // A new store there cannot be made.
    int rc = as_unprivileged([&] {
        auto r = Store::open(ro + "/new.db");
        if (r.error.message.find("not writable") == std::string::npos) return 98;
        return exit_code(r.error.fault);
    });
    EXPECT_EQ(rc, 73);
    EXPECT_FALSE(test::exists(ro + "/new.db"));
    // An existing store there cannot be used (SQLite needs its -wal and -shm).
    rc = as_unprivileged([&] {
        auto r = Store::open(ro + "/old.db");
        if (!r.ok()) return exit_code(r.error.fault);
        auto w = r.value->save(5, "%5\nN1\n", kNew, "");
        return exit_code(w.error.fault);
    });
    EXPECT_EQ(rc, 73);
    EXPECT_EQ(test::slurp(ro + "/old.db"), before);
}

TEST(StoreAnomaly, LockedByAnotherWriter) {
    TempDir t;
    std::string f = t / "locked.db";
    make_store(f, 3);
    Raw other(f);
    ASSERT_EQ(other.exec("BEGIN IMMEDIATE"), SQLITE_OK);  // another process is writing
    Options o;
    o.busy_timeout_ms = 200;
    auto s = test::open_store(f, o);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->list().value.size(), 5u);  // readers go on (WAL)
    auto w = s->save(5, "%5\nN1\n", kNew, "");
    EXPECT_EQ(w.error.fault, Fault::io);
    EXPECT_EQ(exit_code(w.error.fault), 74);
    EXPECT_NE(w.error.message.find("locked by another process (waited 0.2 s)"), std::string::npos)
        << w.error.message;
    EXPECT_EQ(s->set_values("mill", {{"D1.L", 5}}, "").error.fault, Fault::io);
    other.exec("ROLLBACK");
    EXPECT_TRUE(s->save(5, "%5\nN1\n", kNew, "").ok());  // and it works once the lock is gone
}

TEST(StoreAnomaly, LockedExclusively) {
    TempDir t;
    std::string f = t / "excl.db";
    make_store(f, 3);
    std::string before = test::slurp(f);
    Raw other(f);
    ASSERT_EQ(other.exec("PRAGMA locking_mode = EXCLUSIVE; BEGIN EXCLUSIVE"), SQLITE_OK);
    ASSERT_EQ(other.one("SELECT count(*) FROM programs"), 5);
    Options o;
    o.busy_timeout_ms = 200;
    auto r = Store::open(f, o);
    EXPECT_EQ(r.error.fault, Fault::io) << r.error.message;
    EXPECT_NE(r.error.message.find("locked"), std::string::npos) << r.error.message;
    other.exec("ROLLBACK");
}

TEST(StoreAnomaly, DiskFullWhileSaving) {
    TempDir t;
    std::string f = t / "full.db";
    make_store(f, 20);
    int64_t pages = 0;
    {
        Raw raw(f);
        pages = raw.one("PRAGMA page_count");
    }
    std::string before = test::slurp(f);
    {
        Options o;
        o.max_page_count = pages + 4;  // room for a little, not for a 1 MB program
        auto s = test::open_store(f, o);
        std::string big = "%77\n";
        while (big.size() < 1'000'000) big += "N10 G1 X12.345 Y67.890 F1000\n";
        auto w = s->save(77, big, kNew, "");
        EXPECT_EQ(w.error.fault, Fault::io);
        EXPECT_EQ(exit_code(w.error.fault), 74);
        EXPECT_NE(w.error.message.find("disk full"), std::string::npos) << w.error.message;
        // An import of several programs is refused whole.
        std::vector<Piece> many{{78, "%78\nN1\n", ""}, {79, big.replace(1, 2, "79"), ""}};
        EXPECT_EQ(s->save_all(many).error.fault, Fault::io);
        EXPECT_EQ(s->read(78).error.fault, Fault::not_found);
        EXPECT_EQ(s->list().value.size(), 22u);
        EXPECT_EQ(s->integrity_check().value, "ok");
        // Small changes still fit.
        EXPECT_TRUE(s->save(80, "%80\nN1\n", kNew, "").ok());
    }
    auto s = test::open_store(f);
    EXPECT_EQ(s->list().value.size(), 23u);
    EXPECT_EQ(s->integrity_check().value, "ok");
}

TEST(StoreAnomaly, DiskFullWhileCreating) {
    TempDir t;
    Options o;
    o.max_page_count = 3;
    auto r = Store::open(t / "tiny.db", o);
    EXPECT_EQ(r.error.fault, Fault::io);
    EXPECT_NE(r.error.message.find("cannot create the store"), std::string::npos)
        << r.error.message;
    EXPECT_NE(r.error.message.find("disk full"), std::string::npos) << r.error.message;
    // Nothing is left behind, not even the temporary file.
    EXPECT_TRUE(std::filesystem::is_empty(t.path));
}
