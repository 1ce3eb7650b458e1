// The store with many writers at once, on both engines; and what only a server
// has: a schema version kept in a table, connection failures said in one line,
// a copy from one engine to the other and back, byte for byte.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <atomic>
#include <chrono>
#include <set>
#include <thread>

#include "core/training/exercise.hpp"
#include "store/text.hpp"
#include "store_helpers.hpp"

using namespace pupitre;
using namespace pupitre::store;

namespace {

constexpr int kClients = 30;

std::string program_text(int number, const std::string& line) {
    return "%" + std::to_string(number) + " (CLIENT)\nN10 G1 X1 F100\n(" + line + ")\nM2\n";
}

// A schema's name inside one of Place's connection strings.
std::string schema_of(const std::string& target) {
    size_t at = target.find("search_path=");
    return target.substr(at + 12, target.find('\'', at) - at - 12);
}

bool one_line(const std::string& s) {
    return !s.empty() && s.find('\n') == std::string::npos;
}

}  // namespace

using StoreMany = test::OnBothEngines;
PUPITRE_ON_BOTH_ENGINES(StoreMany);

// 30 consoles at once, each saving programs of its own, its own machine's
// correctors and an attempt, and all of them saving over the same revision of
// one shared program: nothing lost, nothing doubled, one save wins and every
// other one is a CONFLICT revision.
TEST_P(StoreMany, ThirtyWritersLoseNothingAndReportConflicts) {
    test::Place t(GetParam());
    const std::string db = t / "many.db";
    {
        auto s = test::open_store(db);
        ASSERT_TRUE(s->save(500, program_text(500, "FIRST"), kNew, "").ok());
    }
    std::atomic<int> ready{0}, saved{0}, conflicts{0}, failures{0};
    std::atomic<int64_t> retried{0};
    auto client = [&](int i) {
        Options o;
        o.user = "client" + std::to_string(i);
        o.busy_timeout_ms = 30000;
        auto r = Store::open(db, o);
        if (!r.ok()) {
            ++failures;
            return;
        }
        Store& s = *r.value;
        ++ready;
        while (ready < kClients) std::this_thread::yield();
        auto shared = s.save(500, program_text(500, o.user), 1, "shared");
        if (!shared.ok()) {
            ++failures;
            ADD_FAILURE() << "shared: " << shared.error.message;
        } else if (shared.value.status == SaveStatus::conflict)
            ++conflicts;
        else if (shared.value.status == SaveStatus::saved)
            ++saved;
        for (int k = 0; k < 5; ++k) {
            int n = 1000 + i * 10 + k;
            if (auto own = s.save(n, program_text(n, o.user), kNew, "own"); !own.ok()) {
                ++failures;
                ADD_FAILURE() << "own: " << own.error.message;
            }
        }
        const std::string machine = "m" + std::to_string(i);
        for (int k = 1; k <= 3; ++k)
            if (!s.set_values(machine, {{"D" + std::to_string(k) + ".X", 1000 * i + k}},
                              "page CORR")
                     .ok())
                ++failures;
        Attempt a;
        a.exercise = "e1";
        a.exercise_sha = "sha";
        a.student = o.user;
        a.machine = "attempt-" + o.user;
        if (auto e = s.start_attempt(a)) {
            ++failures;
            ADD_FAILURE() << "start: " << e.message;
        }
        a.submitted_ms = 1;
        a.score = i;
        if (auto e = s.submit_attempt(a)) {
            ++failures;
            ADD_FAILURE() << "submit: " << e.message;
        }
        if (s.submit_attempt(a).fault != Fault::not_found) ++failures;  // never twice
        retried += s.retried();
    };
    std::vector<std::thread> threads;
    for (int i = 0; i < kClients; ++i) threads.emplace_back(client, i);
    for (auto& th : threads) th.join();
    ASSERT_EQ(failures.load(), 0);
    EXPECT_EQ(saved.load(), 1);
    EXPECT_EQ(conflicts.load(), kClients - 1);

    auto s = test::open_store(db);
    auto h = s->history(500).value;
    ASSERT_EQ(h.size(), size_t(kClients + 1));
    std::set<std::string> texts;
    for (const auto& rev : h) texts.insert(s->read(500, rev.revision).value.text);
    EXPECT_EQ(texts.size(), h.size());  // each client's text once
    int flagged = 0;
    for (const auto& rev : h) flagged += rev.conflict;
    EXPECT_EQ(flagged, kClients - 1);
    EXPECT_EQ(s->list().value.size(), size_t(2 + 1 + kClients * 5));
    for (int i = 0; i < kClients; ++i) {
        auto v = s->values("m" + std::to_string(i)).value;
        ASSERT_EQ(v.size(), 3u);
        EXPECT_EQ(v["D2.X"], 1000 * i + 2);
    }
    EXPECT_EQ(s->audit().value.size(), size_t(kClients * 3));
    auto attempts = s->attempts("e1").value;
    ASSERT_EQ(attempts.size(), size_t(kClients));
    for (const auto& a : attempts) EXPECT_EQ(a.submitted_ms, 1);
    EXPECT_EQ(s->integrity_check().value, "ok");
    // On a server the losers were refused and ran again; SQLite queued them.
    if (GetParam() == "postgresql") {
        EXPECT_GT(retried.load(), 0);
    }
}

// Imports at once, of the same numbers and of numbers of their own, each
// hundreds of programs (in bulk, COPY on a server): each import whole, once,
// its programs new or a new revision of the others', never mixed.
TEST_P(StoreMany, ImportsAtOnceEachLandWhole) {
    test::Place t(GetParam());
    const std::string db = t / "imports.db";
    test::open_store(db);
    constexpr int kImporters = 8, kShared = 150, kOwn = 150;
    std::atomic<int> ready{0}, failures{0};
    std::atomic<int64_t> retried{0};
    auto importer = [&](int i) {
        Options o;
        o.user = "importer" + std::to_string(i);
        o.busy_timeout_ms = 30000;
        auto r = Store::open(db, o);
        if (!r.ok()) {
            ++failures;
            return;
        }
        std::vector<Piece> pieces;
        for (int n = 2000; n < 2000 + kShared; ++n)
            pieces.push_back({n, program_text(n, o.user), "import shared.iso"});
        for (int n = 0; n < kOwn; ++n) {
            const int number = 10000 + i * 1000 + n;
            pieces.push_back({number, program_text(number, o.user), "import own.iso"});
        }
        ++ready;
        while (ready < kImporters) std::this_thread::yield();
        auto saved = r.value->save_all(pieces);
        if (!saved.ok()) {
            ++failures;
            ADD_FAILURE() << saved.error.message;
        }
        retried += r.value->retried();
    };
    std::vector<std::thread> threads;
    for (int i = 0; i < kImporters; ++i) threads.emplace_back(importer, i);
    for (auto& th : threads) th.join();
    ASSERT_EQ(failures.load(), 0);
    auto s = test::open_store(db);
    EXPECT_EQ(s->list().value.size(), size_t(2 + kShared + kImporters * kOwn));
    // The imports one after the other: every shared program has a revision
    // of each, in the same order for all of them.
    std::vector<std::string> first_order;
    for (int n = 2000; n < 2000 + kShared; ++n) {
        auto h = s->history(n).value;
        ASSERT_EQ(h.size(), size_t(kImporters)) << n;
        std::vector<std::string> order;
        for (const auto& rev : h) {
            EXPECT_EQ(rev.based_on, rev.revision - 1);
            order.push_back(rev.who);
        }
        if (first_order.empty()) first_order = order;
        EXPECT_EQ(order, first_order) << n;
        EXPECT_EQ(s->read(n).value.text, program_text(n, h.back().who));
    }
    for (int i = 0; i < kImporters; ++i)
        EXPECT_EQ(s->history(10000 + i * 1000 + kOwn - 1).value.size(), 1u);
    EXPECT_EQ(s->integrity_check().value, "ok");
    if (GetParam() == "postgresql") {
        EXPECT_GT(retried.load(), 0);
    }
}

// A console follows the others' commits, not its own.
TEST_P(StoreMany, AnotherConsolesCommitIsHeard) {
    test::Place t(GetParam());
    const std::string db = t / "dv.db";
    auto a = test::open_store(db);
    auto b = test::open_store(db);
    int64_t before = a->data_version().value;
    ASSERT_TRUE(a->save(20, "%20\nA\n", kNew, "").ok());
    EXPECT_EQ(a->data_version().value, before);
    ASSERT_TRUE(b->save(21, "%21\nB\n", kNew, "").ok());
    // A server's notification arrives a moment after the commit: the console
    // polls every half second; here, up to 5 s.
    int64_t now = a->data_version().value;
    for (int i = 0; i < 500 && now == before; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        now = a->data_version().value;
    }
    EXPECT_NE(now, before);
}

// Stores that share a server (a schema each, or a database) do not hear each
// other: a class's commits do not make another class's consoles read again.
TEST_P(StoreMany, AnotherStoresCommitIsNotHeard) {
    test::Place t(GetParam());
    auto a = test::open_store(t / "mine.db");
    auto b = test::open_store(t / "mine.db");
    auto other = test::open_store(t / "other.db");
    int64_t before = a->data_version().value;
    ASSERT_TRUE(other->save(30, "%30\nO\n", kNew, "").ok());
    ASSERT_TRUE(b->save(31, "%31\nB\n", kNew, "").ok());
    // One server delivers a channel's notifications in the order of the
    // commits: once something is heard, a moment more and all of it is.
    int64_t now = a->data_version().value;
    for (int i = 0; i < 500 && now == before; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        now = a->data_version().value;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_EQ(a->data_version().value, before + 1);
}

// ---- the server's own ----

// SQL that takes a store of schema 5 back to 4 (run in its schema).
const std::string kBackTo4 =
    "DROP TRIGGER heads_exist_insert ON programs; DROP TRIGGER heads_exist_update ON programs; "
    "DROP TRIGGER revisions_stay ON revisions; DROP TRIGGER revisions_stay_whole ON revisions; "
    "DROP FUNCTION pupitre_heads_exist(); DROP FUNCTION pupitre_revisions_stay(); "
    "ALTER TABLE programs DROP COLUMN listing; ALTER TABLE programs ADD FOREIGN KEY (number, "
    "head) REFERENCES revisions (program, rev) DEFERRABLE INITIALLY DEFERRED; "
    "UPDATE pupitre_meta SET value = 4 WHERE key = 'schema_version'; ";

class StoreServer : public ::testing::Test {
  protected:
    void SetUp() override {
        if (std::getenv("PUPITRE_TEST_PG")) return;
        const char* ci = std::getenv("CI");
        if (ci && std::string(ci) == "true")
            FAIL() << "CI=true and no PostgreSQL test server: scripts/test starts one";
        GTEST_SKIP() << "no PostgreSQL test server (scripts/test starts one)";
    }
};

TEST_F(StoreServer, ANewerSchemaIsRefusedAnOlderOneUpgraded) {
    test::Place t("postgresql");
    const std::string db = t / "v.db";
    test::open_store(db);
    const std::string schema = schema_of(db);
    ASSERT_EQ(test::pg_admin("UPDATE " + schema +
                             ".pupitre_meta SET value = 99 WHERE key = 'schema_version'"),
              "");
    auto r = Store::open(db);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error.fault, Fault::bad_data);
    EXPECT_NE(r.error.message.find("schema 99"), std::string::npos) << r.error.message;
    EXPECT_NE(r.error.message.find("up to " + std::to_string(kServerSchemaVersion)),
              std::string::npos);
    // A store of schema 2 (before training, the class and the packed list)
    // gets its tables and its column, in one transaction.
    ASSERT_EQ(test::pg_admin("SET search_path = " + schema + "; " + kBackTo4 +
                             "DROP TABLE attempts; DROP TABLE exercises; DROP TABLE "
                             "exercise_texts; UPDATE pupitre_meta SET value = 2 WHERE key = "
                             "'schema_version'"),
              "");
    auto s = test::open_store(db);
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->put_exercise("x", "text"));
    auto l = s->list();
    ASSERT_EQ(l.value.size(), 2u);  // nothing seeded twice
    // The rows written before the column have it too.
    EXPECT_EQ(l.value[0].number, 300);
    EXPECT_EQ(l.value[0].revision, 1);
    EXPECT_EQ(l.value[0].size, int64_t(s->read(300).value.text.size()));
}

// A class server made by the pupitre before the packed list (schema 4): a
// student, who may not change the tables, works on it as it is, the list
// read column by column; the teacher's pupitre, the tables' owner, upgrades
// it, and the student's next console lists the packed way.
TEST_F(StoreServer, AStudentWorksOnAClassServerOneSchemaBehind) {
    test::Place t("postgresql");
    const std::string db = t / "older";
    const std::string group = "o" + std::to_string(::getpid());
    {
        auto teacher = test::open_store(db);
        training::Exercise e;
        ASSERT_TRUE(training::builtin_exercise("exam-2005", e));
        ASSERT_FALSE(teacher->class_init(group, {{e.name, e.source}}));
    }
    ASSERT_EQ(test::pg_admin("SET search_path = " + schema_of(db) + "; " + kBackTo4), "");
    auto teacher_then = test::open_store(db);  // to add a student only
    ASSERT_TRUE(teacher_then);
    // Back to 4: the teacher's open upgraded it.
    ASSERT_EQ(test::pg_admin("SET search_path = " + schema_of(db) + "; " + kBackTo4), "");
    auto logins = teacher_then->add_students(group, {group + "s1"});
    ASSERT_TRUE(logins.ok()) << logins.error.message;
    teacher_then.reset();
    const store::Login& l = logins.value[0];
    const std::string as_student = db + " user=" + l.name + " password=" + l.password;
    {
        auto r = Store::open(as_student);
        ASSERT_TRUE(r.ok()) << r.error.message;
        auto list = r.value->list();
        ASSERT_TRUE(list.ok()) << list.error.message;
        EXPECT_EQ(list.value.size(), 2u);
        EXPECT_EQ(list.value[0].number, 300);
        EXPECT_GT(list.value[0].size, 0);
    }
    auto teacher = test::open_store(db);
    ASSERT_TRUE(teacher);
    auto r = Store::open(as_student);
    ASSERT_TRUE(r.ok()) << r.error.message;
    auto list = r.value->list();
    ASSERT_TRUE(list.ok()) << list.error.message;
    EXPECT_EQ(list.value.size(), 2u);
    EXPECT_EQ(test::pg_admin("SELECT listing FROM " + schema_of(db) + ".programs"), "");
}

// A program's current revision exists, on a server as on a file: a row
// that names a missing one is refused, and a revision is never deleted,
// renumbered or emptied out from under its program.
TEST_F(StoreServer, AProgramsCurrentRevisionAlwaysExists) {
    test::Place t("postgresql");
    const std::string db = t / "heads.db";
    auto s = test::open_store(db);
    ASSERT_TRUE(s->save(7, "%7\nM2\n", kNew, "").ok());
    const std::string in = "SET search_path = " + schema_of(db) + "; ";
    EXPECT_NE(test::pg_admin(in + "UPDATE programs SET head = 9 WHERE number = 7")
                  .find("its current revision is missing"),
              std::string::npos);
    EXPECT_NE(test::pg_admin(in + "INSERT INTO programs (number, head, last_rev, size, lines, "
                                  "modified_ms, modified_by) VALUES (8, 1, 1, 0, 0, 0, 'x')"),
              "");
    EXPECT_NE(test::pg_admin(in + "DELETE FROM revisions WHERE program = 7"), "");
    EXPECT_NE(test::pg_admin(in + "UPDATE revisions SET rev = 5 WHERE program = 7"), "");
    EXPECT_NE(test::pg_admin(in + "TRUNCATE revisions CASCADE"), "");
    // A revision's other fields are not its key.
    EXPECT_EQ(test::pg_admin(in + "UPDATE revisions SET source = 'x' WHERE program = 7"), "");
    EXPECT_EQ(s->integrity_check().value, "ok");
    EXPECT_EQ(s->read(7).value.text, "%7\nM2\n");
    // Deleting and restoring, as the store does them, are still allowed.
    ASSERT_TRUE(s->remove(7).ok());
    ASSERT_TRUE(s->restore(7, 1).ok());
    EXPECT_EQ(s->read(7).value.text, "%7\nM2\n");
}

// A damaged packed list value is refused, never read past.
TEST_F(StoreServer, AShortListingIsRefused) {
    test::Place t("postgresql");
    const std::string db = t / "short.db";
    auto s = test::open_store(db);
    ASSERT_TRUE(s->list().ok());
    ASSERT_EQ(test::pg_admin("SET search_path = " + schema_of(db) +
                             "; ALTER TABLE programs DROP COLUMN listing; ALTER TABLE programs "
                             "ADD COLUMN listing bytea GENERATED ALWAYS AS (int8send(number)) "
                             "STORED"),
              "");
    auto l = s->list();
    EXPECT_EQ(l.error.fault, Fault::bad_data);
    EXPECT_NE(l.error.message.find("list entry is not 56 bytes"), std::string::npos)
        << l.error.message;
    EXPECT_TRUE(l.value.empty());
    // The rest of the copy was read away: the connection serves the next.
    EXPECT_EQ(s->read(300).value.info.number, 300);
}

TEST_F(StoreServer, AnotherApplicationsTablesAreLeftUntouched) {
    test::Place t("postgresql");
    const std::string db = t / "other.db";
    ASSERT_EQ(test::pg_admin("CREATE TABLE " + schema_of(db) + ".invoices (id int)"), "");
    auto r = Store::open(db);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error.fault, Fault::bad_data);
    EXPECT_NE(r.error.message.find("holds other tables"), std::string::npos) << r.error.message;
    EXPECT_EQ(test::pg_admin("SELECT * FROM " + schema_of(db) + ".invoices"), "");
}

TEST_F(StoreServer, ConnectionFailuresAreOneLine) {
    std::string base = std::getenv("PUPITRE_TEST_PG");
    auto with = [&](const std::string& key, const std::string& value) {
        std::string s = base;
        size_t at = s.find(key + "=");
        size_t end = s.find(' ', at);
        return s.replace(at, end == std::string::npos ? std::string::npos : end - at,
                         key + "=" + value);
    };
    auto missing = Store::open(with("dbname", "no_such_db"));
    EXPECT_EQ(missing.error.fault, Fault::not_found);
    EXPECT_TRUE(one_line(missing.error.message)) << missing.error.message;
    EXPECT_NE(missing.error.message.find("no_such_db does not exist"), std::string::npos);
    auto stranger = Store::open(with("user", "nobody_here"));
    ASSERT_TRUE(stranger.error);
    EXPECT_TRUE(one_line(stranger.error.message)) << stranger.error.message;
    EXPECT_NE(stranger.error.message.find("authentication failed for nobody_here"),
              std::string::npos)
        << stranger.error.message;
    EXPECT_EQ(stranger.error.message.find("password="), std::string::npos);
    auto closed = Store::open(with("port", "1"));
    EXPECT_EQ(closed.error.fault, Fault::io);
    EXPECT_TRUE(one_line(closed.error.message)) << closed.error.message;
    EXPECT_NE(closed.error.message.find("does not answer"), std::string::npos);
}

// The server's unix socket, as a class server's own PC reaches it.
TEST_F(StoreServer, OverTheUnixSocket) {
    const char* dir = std::getenv("PUPITRE_TEST_PG_SOCKET");
    if (!dir) GTEST_SKIP() << "no socket directory given (PUPITRE_TEST_PG_SOCKET)";
    std::string base = std::getenv("PUPITRE_TEST_PG");
    size_t at = base.find("host=");
    std::string target = base.substr(0, at) + "host=" + dir + base.substr(base.find(' ', at));
    size_t ssl = target.find("sslmode=require");
    if (ssl != std::string::npos) target.replace(ssl, 15, "sslmode=disable");
    test::Place t("postgresql");
    const std::string tcp = t / "sock";
    const std::string sock = target + tcp.substr(tcp.find(" options="));
    auto s = test::open_store(sock);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->path().rfind("postgresql://pupitre_admin@/", 0), 0u) << s->path();
    EXPECT_TRUE(s->save(9, "%9\nN1\n", kNew, "").ok());
    EXPECT_EQ(test::open_store(tcp)->read(9).value.text, "%9\nN1\n");
}

// SQLite -> PostgreSQL -> SQLite: every table's rows and checksums agree at
// each step, and every program exports byte for byte as imported.
TEST_F(StoreServer, CopyRoundTripsBetweenTheEngines) {
    test::TempDir d;
    test::Place server("postgresql");
    auto a = test::open_store(d / "a.db");
    std::string dir = test::shared_programs();
    std::vector<std::string> originals;
    for (int n = 0; n < 40; ++n) {
        // Accents, a byte that is no UTF-8 and a CR LF: stored as they are.
        std::string text = program_text(2000 + n, "ETE " + std::to_string(n)) + "(ÉTÉ \xff)\r\n";
        ASSERT_TRUE(a->save(2000 + n, text, kNew, "import").ok());
        ASSERT_TRUE(a->save(2000 + n, text + "N99\n", 1, "page EDIT").ok());
        originals.push_back(text + "N99\n");
    }
    ASSERT_TRUE(a->save(2000, "%2000\nCONFLICT\n", 1, "").ok());  // a CONFLICT revision
    ASSERT_TRUE(a->set_values("lathe", {{"D1.X", 15157}, {"PREF.Z", -200000}}, "page CORR").ok());
    ASSERT_FALSE(a->add_imd("lathe", "G0 X10"));
    ASSERT_FALSE(a->set_setting("machine", "lathe"));
    ASSERT_FALSE(a->put_workshop("lathe", "setup text", "part text"));
    ASSERT_FALSE(a->put_exercise("ex", "exercise text"));
    Attempt at;
    at.exercise = "ex";
    at.student = "ann";
    at.machine = "attempt-ann";
    at.seconds = 12.345678901234567;
    ASSERT_FALSE(a->start_attempt(at));
    at.submitted_ms = 77;
    at.signature = "sig";
    ASSERT_FALSE(a->submit_attempt(at));

    Options fresh;
    fresh.seed = false;
    auto b = test::open_store(server / "b", fresh);
    auto ab = a->copy_to(*b);
    ASSERT_TRUE(ab.ok()) << ab.error.message;
    auto c = test::open_store(d / "c.db", fresh);
    auto bc = b->copy_to(*c);
    ASSERT_TRUE(bc.ok()) << bc.error.message;
    ASSERT_EQ(ab.value.tables.size(), bc.value.tables.size());
    for (size_t i = 0; i < ab.value.tables.size(); ++i) {
        EXPECT_EQ(ab.value.tables[i].rows, bc.value.tables[i].rows) << ab.value.tables[i].name;
        EXPECT_EQ(ab.value.tables[i].checksum, bc.value.tables[i].checksum);
    }
    for (int n = 0; n < 40; ++n) {
        EXPECT_EQ(b->read(2000 + n).value.text, n ? originals[size_t(n)] : originals[0]);
        EXPECT_EQ(c->read(2000 + n, 2).value.text, originals[size_t(n)]);
    }
    EXPECT_EQ(b->read(2000).value.info.conflict, 3);
    EXPECT_EQ(b->attempts("ex").value.at(0).seconds, at.seconds);
    // The server's ids go on after the copied ones.
    ASSERT_FALSE(b->add_imd("lathe", "G0 X20"));
    EXPECT_EQ(b->imd_history("lathe").value.size(), 2u);
    // A copy never merges into a store that holds something.
    auto again = a->copy_to(*b);
    EXPECT_EQ(again.error.fault, Fault::bad_data);
    EXPECT_NE(again.error.message.find("not empty"), std::string::npos);
}

// A year of a class's work: 10,000 programs with two revisions each, from a
// file to the server and back, every text and every history the same.
TEST_F(StoreServer, TenThousandProgramsWithHistoryRoundTrip) {
    test::TempDir d;
    test::Place server("postgresql");
    Options fresh;
    fresh.seed = false;
    auto a = test::open_store(d / "a.db", fresh);
    constexpr int kPrograms = 10000;
    for (int rev = 0; rev < 2; ++rev) {
        std::vector<Piece> pieces;
        for (int n = 1; n <= kPrograms; ++n)
            pieces.push_back({n,
                              program_text(n, "R" + std::to_string(rev)) + "N20 X" +
                                  std::to_string(n * 7 + rev) + "\r\n",
                              "import"});
        ASSERT_TRUE(a->save_all(pieces).ok());
    }
    auto b = test::open_store(server / "year", fresh);
    auto ab = a->copy_to(*b);
    ASSERT_TRUE(ab.ok()) << ab.error.message;
    auto c = test::open_store(d / "c.db", fresh);
    auto bc = b->copy_to(*c);
    ASSERT_TRUE(bc.ok()) << bc.error.message;
    for (size_t i = 0; i < ab.value.tables.size(); ++i)
        EXPECT_EQ(ab.value.tables[i].checksum, bc.value.tables[i].checksum);
    std::vector<std::string> before, after;
    EXPECT_FALSE(a->each_program([&](int, std::string_view t) { before.emplace_back(t); }));
    EXPECT_FALSE(c->each_program([&](int, std::string_view t) { after.emplace_back(t); }));
    ASSERT_EQ(before.size(), size_t(kPrograms));
    EXPECT_TRUE(before == after);
    EXPECT_EQ(c->history(kPrograms).value.size(), 2u);
    EXPECT_EQ(c->read(kPrograms, 1).value.text, a->read(kPrograms, 1).value.text);
}
