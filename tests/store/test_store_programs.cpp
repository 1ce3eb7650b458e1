// Store: creating and seeding, program operations, conflicts, cutting files into
// programs, and the byte-exact round trip on every shared program.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "store/text.hpp"
#include "store_helpers.hpp"

using namespace pupitre;
using namespace pupitre::store;
using test::TempDir;

using StorePrograms = test::OnBothEngines;
using StoreRoundTrip = test::OnBothEngines;
using StoreValues = test::OnBothEngines;
PUPITRE_ON_BOTH_ENGINES(StorePrograms);
PUPITRE_ON_BOTH_ENGINES(StoreRoundTrip);
PUPITRE_ON_BOTH_ENGINES(StoreValues);

namespace {

uint32_t be32_at(const std::string& bytes, size_t off) {
    auto b = [&](size_t i) { return uint32_t(static_cast<unsigned char>(bytes[off + i])); };
    return b(0) << 24 | b(1) << 16 | b(2) << 8 | b(3);
}

std::vector<int> numbers(Store& s) {
    std::vector<int> out;
    for (const auto& p : s.list().value) out.push_back(p.number);
    return out;
}

// Makes the engine refuse the programs row of each of `numbers` (a trigger,
// as a server may refuse a row for a reason of its own: a constraint, a
// policy, a full disk), so that an import fails past its first writes.
void refuse_programs(const std::string& engine, const std::string& target,
                     const std::string& numbers) {
    if (engine == "sqlite") {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open(target.c_str(), &db), SQLITE_OK);
        const std::string sql =
            "CREATE TRIGGER refuse BEFORE INSERT ON programs WHEN NEW.number IN (" + numbers +
            ") BEGIN SELECT RAISE(ABORT, 'refused'); END";
        char* err = nullptr;
        EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err), SQLITE_OK)
            << (err ? err : "");
        sqlite3_free(err);
        sqlite3_close(db);
        return;
    }
    const size_t at = target.find("search_path=") + 12;
    const std::string schema = target.substr(at, target.find('\'', at) - at);
    ASSERT_EQ(
        test::pg_admin("CREATE FUNCTION " + schema +
                       ".refuse() RETURNS trigger LANGUAGE plpgsql AS $$BEGIN IF "
                       "NEW.number IN (" +
                       numbers +
                       ") THEN RAISE EXCEPTION 'refused'; END IF; RETURN NEW; END$$; "
                       "CREATE TRIGGER refuse BEFORE INSERT ON " +
                       schema + ".programs FOR EACH ROW EXECUTE FUNCTION " + schema + ".refuse()"),
        "");
}

}  // namespace

TEST(StoreOpen, CreatesSeedsAndMarksTheFile) {
    TempDir t;
    std::string db = t / "p.db";
    {
        auto s = test::open_store(db);
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->created());
        EXPECT_EQ(numbers(*s), (std::vector<int>{300, 301}));
        auto lathe = s->read(300);
        ASSERT_TRUE(lathe.ok());
        EXPECT_EQ(lathe.value.text.substr(0, 6), "%300 (");
        // Both demos are %300 in the handbooks: the second is stored as %301.
        auto mill = s->read(301);
        ASSERT_TRUE(mill.ok());
        EXPECT_EQ(mill.value.text.substr(0, 6), "%301 (");
        // DIR tells the lathe's demo from the mill's by their titles (issue 38).
        const auto all = s->list().value;
        ASSERT_EQ(all.size(), 2u);
        EXPECT_EQ(all[0].title, "LATHE DEMO: TURNING WITH G02 G03");
        EXPECT_EQ(all[1].title, "MILL DEMO: G02 G03 IN THE G19 PLANE");
        EXPECT_NE(mill.value.text.find("G19"), std::string::npos);
        EXPECT_EQ(s->machines().value,
                  (std::vector<std::string>{"lathe", "mill", "mill4", "mill5"}));
        EXPECT_NE(s->machine_profile("lathe").value.find("kind = lathe"), std::string::npos);
        EXPECT_EQ(s->integrity_check().value, "ok");
        EXPECT_EQ(s->history(300).value.front().kind, RevisionKind::seed);
    }
    // Closed: the log is folded into the file, whose header says what it is.
    std::string bytes = test::slurp(db);
    ASSERT_GE(bytes.size(), 100u);
    EXPECT_EQ(be32_at(bytes, 68), kApplicationId);
    EXPECT_EQ(be32_at(bytes, 60), uint32_t(kSchemaVersion));
    EXPECT_EQ(bytes[18], 2);  // WAL
    EXPECT_FALSE(test::exists(db + "-wal"));
    // No temporary file is left beside it.
    int files = 0;
    for (auto& e : std::filesystem::directory_iterator(t.path)) files += e.is_regular_file();
    EXPECT_EQ(files, 1);
    // Opened again: not created, not seeded twice.
    auto s = test::open_store(db);
    EXPECT_FALSE(s->created());
    EXPECT_EQ(s->history(300).value.size(), 1u);
}

TEST(StoreOpen, WithoutSeedAndWithoutCreate) {
    TempDir t;
    Options o;
    o.seed = false;
    auto s = test::open_store(t / "a.db", o);
    EXPECT_TRUE(s->list().value.empty());
    EXPECT_TRUE(s->machines().value.empty());
    Options nc;
    nc.create = false;
    auto r = Store::open(t / "missing.db", nc);
    EXPECT_EQ(r.error.fault, Fault::not_found);
    EXPECT_FALSE(test::exists(t / "missing.db"));
}

TEST(StoreOpen, MakesTheDirectoriesOfTheDefaultStore) {
    TempDir t;
    Options o;
    o.create_parents = true;
    auto s = test::open_store(t / "x/y/pupitre.db", o);
    ASSERT_TRUE(s);
    struct stat st;
    ASSERT_EQ(::stat((t / "x/y").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700u);
}

TEST(StoreOpen, DefaultPathFollowsXdg) {
    const char* old_xdg = std::getenv("XDG_DATA_HOME");
    const char* old_home = std::getenv("HOME");
    std::string sx = old_xdg ? old_xdg : "", sh = old_home ? old_home : "";
    setenv("XDG_DATA_HOME", "/data/x", 1);
    EXPECT_EQ(default_path(), "/data/x/pupitre/pupitre.db");
    setenv("XDG_DATA_HOME", "relative/ignored", 1);  // the spec says: absolute only
    setenv("HOME", "/home/h", 1);
    EXPECT_EQ(default_path(), "/home/h/.local/share/pupitre/pupitre.db");
    unsetenv("XDG_DATA_HOME");
    EXPECT_EQ(default_path(), "/home/h/.local/share/pupitre/pupitre.db");
    if (old_xdg) setenv("XDG_DATA_HOME", sx.c_str(), 1);
    if (old_home)
        setenv("HOME", sh.c_str(), 1);
    else
        unsetenv("HOME");
}

TEST(StoreOpen, UserComesFromTheEnvironment) {
    const char* old = std::getenv("USER");
    std::string keep = old ? old : "";
    setenv("USER", "alice", 1);
    EXPECT_EQ(os_user(), "alice");
    TempDir t;
    auto r = Store::open(t / "u.db");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.value->user(), "alice");
    EXPECT_EQ(r.value->history(300).value.front().who, "alice");
    unsetenv("USER");
    EXPECT_FALSE(os_user().empty());  // the password entry, or "uid N"
    if (old) setenv("USER", keep.c_str(), 1);
}

TEST_P(StorePrograms, SaveReadListHistory) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    const std::string v1 = "%12.3 (BRIDE)\r\nN10 G0 X0\r\nM2";  // CRLF, no final newline
    auto r = s->save(12, v1, kNew, "test");
    ASSERT_TRUE(r.ok()) << r.error.message;
    EXPECT_EQ(r.value.status, SaveStatus::created);
    EXPECT_EQ(r.value.revision, 1);
    auto p = s->read(12);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p.value.text, v1);
    EXPECT_EQ(p.value.info.title, "BRIDE");
    EXPECT_EQ(p.value.info.index, 3);
    EXPECT_EQ(p.value.info.lines, 3);
    EXPECT_EQ(p.value.info.size, int64_t(v1.size()));
    EXPECT_EQ(p.value.info.modified_by, "tester");

    const std::string v2 = "%12 (BRIDE 2)\nN10 G0 X1\nM2\n";
    r = s->save(12, v2, 1, "test");
    EXPECT_EQ(r.value.status, SaveStatus::saved);
    EXPECT_EQ(r.value.revision, 2);
    EXPECT_EQ(s->read(12).value.text, v2);
    EXPECT_EQ(s->read(12).value.info.index, -1);
    EXPECT_EQ(s->read(12, 1).value.text, v1);  // every revision is kept

    r = s->save(12, v2, 2, "test");
    EXPECT_EQ(r.value.status, SaveStatus::unchanged);
    EXPECT_EQ(r.value.revision, 2);

    auto h = s->history(12);
    ASSERT_EQ(h.value.size(), 2u);
    EXPECT_EQ(h.value[0].revision, 1);
    EXPECT_EQ(h.value[1].based_on, 1);
    EXPECT_EQ(h.value[1].source, "test");
    EXPECT_EQ(h.value[1].who, "tester");
    EXPECT_GT(h.value[1].at_ms, 1'600'000'000'000);

    auto l = s->list();
    auto it = std::find_if(l.value.begin(), l.value.end(), [](auto& i) { return i.number == 12; });
    ASSERT_NE(it, l.value.end());
    EXPECT_EQ(it->title, "BRIDE 2");
    EXPECT_EQ(it->revision, 2);

    int seen = 0;
    EXPECT_FALSE(s->each_program([&](int n, std::string_view text) {
        if (n == 12) {
            EXPECT_EQ(text, v2);
        }
        ++seen;
    }));
    EXPECT_EQ(seen, 3);
}

// A text of the current one's size is compared with it (by the server on
// PostgreSQL, as it writes the revision): long texts, stored compressed,
// differing in their last byte.
TEST_P(StorePrograms, SaveTellsTextsOfTheSameSizeApart) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    std::string a = "%40 (LONG)\n";
    for (int b = 1; b <= 4000; ++b)
        a += "N" + std::to_string(b) + " G1 X" + std::to_string(b % 97) + "\n";
    a += "M2\n";
    std::string b = a;
    b[b.size() - 2] = '3';  // M3
    ASSERT_EQ(s->save(40, a, kNew, "").value.status, SaveStatus::created);
    auto r = s->save(40, a, 1, "");
    EXPECT_EQ(r.value.status, SaveStatus::unchanged);
    EXPECT_EQ(r.value.revision, 1);
    r = s->save(40, b, 1, "");
    EXPECT_EQ(r.value.status, SaveStatus::saved);
    EXPECT_EQ(r.value.revision, 2);
    // Based on r1, the current text: unchanged; another text: a conflict.
    EXPECT_EQ(s->save(40, b, 1, "").value.status, SaveStatus::unchanged);
    r = s->save(40, a, 1, "");
    EXPECT_EQ(r.value.status, SaveStatus::conflict);
    EXPECT_EQ(r.value.revision, 3);
    EXPECT_EQ(s->read(40).value.info.conflict, 3);
    // The current text saved on the current revision settles the conflict.
    r = s->save(40, b, 2, "");
    EXPECT_EQ(r.value.status, SaveStatus::unchanged);
    EXPECT_EQ(s->read(40).value.info.conflict, 0);
    ASSERT_TRUE(s->remove(40).ok());  // r4
    r = s->save(40, b, kNew, "");
    EXPECT_EQ(r.value.status, SaveStatus::created);
    EXPECT_EQ(r.value.revision, 5);
    EXPECT_EQ(s->read(40).value.text, b);
    EXPECT_EQ(s->read(40, 3).value.text, a);
    EXPECT_EQ(s->history(40).value.size(), 5u);
    EXPECT_EQ(s->integrity_check().value, "ok");
}

TEST_P(StorePrograms, ConflictKeepsBothAndIsResolvedByRestore) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    ASSERT_EQ(s->save(7, "%7\nN1 X1\n", kNew, "a").value.revision, 1);
    // Alice and Bob both load r1. Bob saves first.
    ASSERT_EQ(s->save(7, "%7\nN1 X2 (BOB)\n", 1, "bob").value.status, SaveStatus::saved);
    // Alice saves over r1, older than Bob's r2: a conflict, nothing overwritten.
    auto c = s->save(7, "%7\nN1 X3 (ALICE)\n", 1, "alice");
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c.value.status, SaveStatus::conflict);
    EXPECT_EQ(c.value.revision, 3);
    EXPECT_EQ(c.value.current, 2);
    EXPECT_EQ(s->read(7).value.text, "%7\nN1 X2 (BOB)\n");
    EXPECT_EQ(s->read(7, 3).value.text, "%7\nN1 X3 (ALICE)\n");
    EXPECT_EQ(s->read(7).value.info.conflict, 3);
    auto h = s->history(7).value;
    ASSERT_EQ(h.size(), 3u);
    EXPECT_TRUE(h[2].conflict);
    EXPECT_EQ(h[2].based_on, 1);
    // A new program saved by two people: the second one conflicts.
    EXPECT_EQ(s->save(8, "%8\nA\n", kNew, "").value.status, SaveStatus::created);
    EXPECT_EQ(s->save(8, "%8\nB\n", kNew, "").value.status, SaveStatus::conflict);
    EXPECT_EQ(s->read(8).value.text, "%8\nA\n");
    // The same text as the current one is no conflict.
    EXPECT_EQ(s->save(8, "%8\nA\n", kNew, "").value.status, SaveStatus::unchanged);
    // Restoring Alice's revision makes it current and clears the mark.
    auto r = s->restore(7, 3);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.value.status, SaveStatus::saved);
    EXPECT_EQ(r.value.revision, 4);
    EXPECT_EQ(s->read(7).value.text, "%7\nN1 X3 (ALICE)\n");
    EXPECT_EQ(s->read(7).value.info.conflict, 0);
    EXPECT_EQ(s->history(7).value.back().kind, RevisionKind::restore);
    // A save based on the current revision clears a mark too.
    s->save(7, "%7\nC\n", 1, "");
    EXPECT_NE(s->read(7).value.info.conflict, 0);
    EXPECT_EQ(s->save(7, "%7\nD\n", 4, "").value.status, SaveStatus::saved);
    EXPECT_EQ(s->read(7).value.info.conflict, 0);
}

// The list gives of each program what a read gives (a server sends it in
// another way: a binary COPY), deleted programs left out, in number order.
TEST_P(StorePrograms, ListHasWhatReadHas) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    ASSERT_TRUE(s->save(6, "%6 (SIX)\nM2\n", kNew, "bob").ok());
    ASSERT_TRUE(s->save(6, "%6 (SIX 2)\nM2\n", 1, "bob").ok());
    EXPECT_EQ(s->save(6, "%6 (SIX 3)\nM2\n", 1, "ann").value.status, SaveStatus::conflict);
    ASSERT_TRUE(
        s->save(5, "%5.7 (A LONG TITLE WITH \\ AND \t AND \xc3\xa9)\nN10 G0 X0\nM2\n", kNew, "a")
            .ok());
    ASSERT_TRUE(s->save(9, "%9 (GONE)\nM2\n", kNew, "c").ok());
    ASSERT_TRUE(s->remove(9).ok());
    auto l = s->list();
    ASSERT_TRUE(l.ok()) << l.error.message;
    EXPECT_EQ(numbers(*s), (std::vector<int>{5, 6, 300, 301}));
    for (const ProgramInfo& i : l.value) {
        const ProgramInfo r = s->read(i.number).value.info;
        EXPECT_EQ(i.index, r.index) << i.number;
        EXPECT_EQ(i.title, r.title) << i.number;
        EXPECT_EQ(i.revision, r.revision) << i.number;
        EXPECT_EQ(i.conflict, r.conflict) << i.number;
        EXPECT_FALSE(i.deleted);
        EXPECT_EQ(i.size, r.size) << i.number;
        EXPECT_EQ(i.lines, r.lines) << i.number;
        EXPECT_EQ(i.modified_ms, r.modified_ms) << i.number;
        EXPECT_EQ(i.modified_by, r.modified_by) << i.number;
    }
    EXPECT_EQ(l.value[0].index, 7);
    EXPECT_NE(l.value[1].conflict, 0);
    // Listed again, on the same connection: the same.
    EXPECT_EQ(s->list().value.size(), 4u);
}

TEST_P(StorePrograms, DeleteKeepsTheHistory) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    s->save(5, "%5\nN1\n", kNew, "");
    auto d = s->remove(5);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.value.revision, 2);
    EXPECT_EQ(s->read(5).error.fault, Fault::not_found);
    EXPECT_EQ(s->remove(5).error.fault, Fault::not_found);
    EXPECT_EQ(s->remove(55).error.fault, Fault::not_found);
    EXPECT_EQ(numbers(*s), (std::vector<int>{300, 301}));
    auto h = s->history(5).value;
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[1].kind, RevisionKind::remove);
    EXPECT_EQ(s->read(5, 1).value.text, "%5\nN1\n");
    EXPECT_EQ(s->restore(5, 2).error.fault, Fault::bad_data);  // the deletion itself
    EXPECT_EQ(s->restore(5, 9).error.fault, Fault::not_found);
    ASSERT_TRUE(s->restore(5, 1).ok());
    EXPECT_EQ(s->read(5).value.text, "%5\nN1\n");
    // A save of a new program over a deleted one is clean; one based on a revision
    // older than the deletion is a conflict and leaves it deleted.
    s->remove(5);
    EXPECT_EQ(s->save(5, "%5\nNEW\n", kNew, "").value.status, SaveStatus::created);
    s->remove(5);
    auto c = s->save(5, "%5\nOLD EDIT\n", 1, "");
    EXPECT_EQ(c.value.status, SaveStatus::conflict);
    EXPECT_TRUE(c.value.deleted);
    EXPECT_EQ(s->read(5).error.fault, Fault::not_found);
    // Deleting what changed since it was loaded is refused.
    s->save(6, "%6\nA\n", kNew, "");
    s->save(6, "%6\nB\n", 1, "");
    auto rd = s->remove(6, 1);
    EXPECT_EQ(rd.value.status, SaveStatus::conflict);
    EXPECT_TRUE(s->read(6).ok());
}

TEST_P(StorePrograms, RefusedTexts) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    EXPECT_EQ(s->save(9, "%8\nN1\n", kNew, "").error.fault, Fault::bad_data);  // says %8
    EXPECT_EQ(s->save(9, "%9\nN1\n%10\n", kNew, "").error.fault, Fault::bad_data);
    EXPECT_EQ(s->save(9, std::string("%9\nN1\0X\n", 9), kNew, "").error.fault, Fault::bad_data);
    EXPECT_EQ(s->save(9, "N5 G0\n%9\nN1\n", kNew, "").error.fault, Fault::bad_data);
    EXPECT_EQ(s->save(-1, "N1\n", kNew, "").error.fault, Fault::bad_data);
    EXPECT_EQ(s->read(9).error.fault, Fault::not_found);
    // Comments before the % line, and a fragment with no % line, are fine.
    EXPECT_TRUE(s->save(9, "(LEADER)\n\n%9\nN1\n", kNew, "").ok());
    EXPECT_TRUE(s->save(11, "N1 G0 X0\nN2 X1\n", kNew, "").ok());
}

TEST_P(StorePrograms, SaveAllIsAllOrNothing) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "p.db");
    std::vector<Piece> good{{20, "%20\nA\n", "import a"}, {21, "%21\nB\n", "import a"}};
    auto r = s->save_all(good);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.value.size(), 2u);
    EXPECT_EQ(r.value[1].status, SaveStatus::created);
    std::vector<Piece> bad{{22, "%22\nC\n", ""}, {23, "%24\nD\n", ""}};
    EXPECT_EQ(s->save_all(bad).error.fault, Fault::bad_data);
    EXPECT_EQ(s->read(22).error.fault, Fault::not_found);
    // Importing again: unchanged; changed: a new revision, never a conflict.
    r = s->save_all({{20, "%20\nA\n", ""}, {21, "%21\nB2\n", ""}});
    EXPECT_EQ(r.value[0].status, SaveStatus::unchanged);
    EXPECT_EQ(r.value[1].status, SaveStatus::saved);
    EXPECT_EQ(s->history(21).value.back().kind, RevisionKind::import);
}

// An import meets what the store holds: programs unchanged (one with a
// conflict kept aside, which the import settles), changed (one of the same
// size), deleted, new, and a number given twice; more pieces than one
// multi-row statement carries. Each piece ends as a save of its own would.
TEST_P(StorePrograms, ImportOfManyMeetsWhatIsStored) {
    test::Place t(GetParam());
    Options o;
    o.seed = false;
    auto s = test::open_store(t / "many.db", o);
    auto text = [](int n, const std::string& body) {
        return "%" + std::to_string(n) + " (P" + std::to_string(n) + ")\n" + body + "\n";
    };
    std::vector<Piece> first;
    for (int n = 1; n <= 300; ++n) first.push_back({n, text(n, "N10 G0 X1"), "import a.iso"});
    auto r = s->save_all(first);
    ASSERT_TRUE(r.ok()) << r.error.message;
    ASSERT_EQ(r.value.size(), 300u);
    EXPECT_EQ(r.value[299].status, SaveStatus::created);
    ASSERT_TRUE(s->save(5, text(5, "N10 G0 X2"), 1, "").ok());  // r2 current
    ASSERT_EQ(s->save(5, text(5, "N10 G0 X3"), 1, "").value.status, SaveStatus::conflict);
    ASSERT_TRUE(s->remove(7).ok());  // r2: deleted
    std::vector<Piece> again{
        {5, text(5, "N10 G0 X2"), "import b.iso"}, {6, text(6, "N10 G0 X1"), "import b.iso"},
        {7, text(7, "N10 G0 X1"), "import b.iso"}, {8, text(8, "N10 G0 X1 Y1"), "import b.iso"},
        {9, text(9, "N10 G0 X9"), "import b.iso"},  // same size
        {2000, text(2000, "A"), "import b.iso"},   {2000, text(2000, "B"), "import b.iso"},
        {2001, text(2001, "C"), "import b.iso"},   {2001, text(2001, "C"), "import b.iso"}};
    for (int n = 1000; n < 1270; ++n) again.push_back({n, text(n, "N1"), "import b.iso"});
    r = s->save_all(again);
    ASSERT_TRUE(r.ok()) << r.error.message;
    ASSERT_EQ(r.value.size(), again.size());
    struct Want {
        int number;
        SaveStatus status;
        int revision;
    };
    const Want want[] = {{5, SaveStatus::unchanged, 2},   {6, SaveStatus::unchanged, 1},
                         {7, SaveStatus::created, 3},     {8, SaveStatus::saved, 2},
                         {9, SaveStatus::saved, 2},       {2000, SaveStatus::created, 1},
                         {2000, SaveStatus::saved, 2},    {2001, SaveStatus::created, 1},
                         {2001, SaveStatus::unchanged, 1}};
    for (size_t i = 0; i < std::size(want); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(r.value[i].number, want[i].number);
        EXPECT_EQ(r.value[i].status, want[i].status);
        EXPECT_EQ(r.value[i].revision, want[i].revision);
        EXPECT_EQ(r.value[i].current, want[i].revision);
        EXPECT_EQ(r.value[i].current_by, "tester");
        EXPECT_FALSE(r.value[i].deleted);
    }
    EXPECT_EQ(r.value.back().status, SaveStatus::created);
    // The conflict kept aside is settled; the deleted program is back.
    // In number order, rows the import moved in the table (%5 to %9) included.
    const std::vector<ProgramInfo> all = s->list().value;
    EXPECT_TRUE(std::is_sorted(all.begin(), all.end(),
                               [](const auto& a, const auto& b) { return a.number < b.number; }));
    std::map<int, ProgramInfo> listed;
    for (const ProgramInfo& p : all) listed[p.number] = p;
    EXPECT_EQ(listed.size(), 300u + 2 + 270);
    EXPECT_EQ(listed[5].conflict, 0);
    EXPECT_EQ(listed[5].revision, 2);
    EXPECT_EQ(listed[7].revision, 3);
    EXPECT_EQ(listed[2000].revision, 2);
    EXPECT_EQ(listed[9].title, "P9");
    EXPECT_EQ(listed[1269].size, int64_t(text(1269, "N1").size()));
    EXPECT_EQ(s->read(2000).value.text, text(2000, "B"));
    EXPECT_EQ(s->read(2000, 1).value.text, text(2000, "A"));
    EXPECT_EQ(s->read(9).value.text, text(9, "N10 G0 X9"));
    EXPECT_EQ(s->read(7).value.text, text(7, "N10 G0 X1"));
    auto h = s->history(7).value;
    ASSERT_EQ(h.size(), 3u);
    EXPECT_EQ(h[2].kind, RevisionKind::import);
    EXPECT_EQ(h[2].based_on, 2);
    EXPECT_EQ(h[2].source, "import b.iso");
    EXPECT_EQ(s->history(5).value.size(), 3u);  // nothing written for it
    EXPECT_EQ(s->history(2001).value.size(), 1u);
    EXPECT_EQ(s->history(1100).value[0].lines, 2);
    EXPECT_EQ(s->integrity_check().value, "ok");
    // The same import again: each number's last text is current.
    r = s->save_all(again);
    ASSERT_TRUE(r.ok()) << r.error.message;
    EXPECT_EQ(r.value[0].status, SaveStatus::unchanged);
    EXPECT_EQ(r.value[5].status, SaveStatus::saved);  // A over B
    EXPECT_EQ(r.value[5].revision, 3);
    EXPECT_EQ(r.value[6].revision, 4);
    EXPECT_EQ(r.value.back().status, SaveStatus::unchanged);
}

// An import the engine refuses at one of its programs, after it wrote the
// revisions and other programs' rows, leaves the store as it was: first at
// a new program (a COPY on a server), then at a stored one (a multi-row
// upsert, after both COPYs went through).
TEST_P(StorePrograms, ImportRefusedMidwayLeavesTheStore) {
    test::Place t(GetParam());
    const std::string db = t / "p.db";
    Options o;
    o.seed = false;
    auto piece = [](int n, const std::string& body) {
        return Piece{n, "%" + std::to_string(n) + "\n" + body + "\n", "class.iso"};
    };
    std::vector<Piece> before;
    for (int n = 1; n <= 10; ++n) before.push_back(piece(n, "N1 G0 X" + std::to_string(n)));
    ASSERT_TRUE(test::open_store(db, o)->save_all(before).ok());
    refuse_programs(GetParam(), db, "1250, 5");
    auto s = test::open_store(db, o);
    std::vector<Piece> changed;
    for (int n = 1; n <= 10; ++n) changed.push_back(piece(n, "N1 G1 X" + std::to_string(n)));
    std::vector<Piece> at_new = changed, at_stored = changed;
    for (int n = 1000; n < 1300; ++n) at_new.push_back(piece(n, "N1"));
    for (int n = 2000; n < 2100; ++n) at_stored.push_back(piece(n, "N1"));
    for (const auto* import : {&at_new, &at_stored}) {
        auto r = s->save_all(*import);
        EXPECT_TRUE(r.error) << import->size();
        EXPECT_NE(r.error.message.find("refused"), std::string::npos) << r.error.message;
        EXPECT_TRUE(r.value.empty());
        EXPECT_EQ(s->list().value.size(), 10u);
        for (const Piece& p : before) {
            auto now = s->read(p.number);
            ASSERT_TRUE(now.ok()) << now.error.message;
            EXPECT_EQ(now.value.text, p.text);
            EXPECT_EQ(s->history(p.number).value.size(), 1u);
        }
        EXPECT_EQ(s->read(1000).error.fault, Fault::not_found);
        EXPECT_EQ(s->read(2000).error.fault, Fault::not_found);
        EXPECT_EQ(s->integrity_check().value, "ok");
    }
    // What the engine accepts still goes in, in one piece.
    EXPECT_TRUE(s->save_all({piece(3, "N2"), piece(3000, "N1")}).ok());
    EXPECT_EQ(s->list().value.size(), 11u);
}

TEST(StoreText, SplitsAFileIntoPrograms) {
    const std::string file = "(TAPE LEADER)\n\n%1 (ONE)\nN10 G0\n  %2\nN20\r\n%3.1\nM2";
    auto r = split_file(file, "f.iso");
    ASSERT_TRUE(r.ok()) << r.error.message;
    ASSERT_EQ(r.value.size(), 3u);
    EXPECT_EQ(r.value[0].number, 1);
    EXPECT_EQ(r.value[0].text, "(TAPE LEADER)\n\n%1 (ONE)\nN10 G0\n");
    EXPECT_EQ(r.value[1].text, "  %2\nN20\r\n");
    EXPECT_EQ(r.value[2].text, "%3.1\nM2");
    EXPECT_EQ(r.value[2].source, "import f.iso");
    std::string joined;
    for (auto& p : r.value) joined += p.text;
    EXPECT_EQ(joined, file);
    Header h;
    EXPECT_FALSE(parse_program(r.value[0].text, "x", h));
    EXPECT_EQ(h.title, "ONE");
    EXPECT_EQ(count_lines(""), 0);
    EXPECT_EQ(count_lines("a"), 1);
    EXPECT_EQ(count_lines("a\n"), 1);
    EXPECT_EQ(count_lines("a\nb"), 2);
}

TEST(StoreText, RefusesWhatCannotBeStoredFaithfully) {
    auto e = split_file("N1 G0\n", "frag.iso").error;
    EXPECT_EQ(e.fault, Fault::bad_data);
    EXPECT_NE(e.message.find("--number"), std::string::npos);
    auto ok = split_file("N1 G0\n", "frag.iso", 77);
    ASSERT_TRUE(ok.ok());
    EXPECT_EQ(ok.value[0].number, 77);
    EXPECT_EQ(split_file("%1\nN1\n", "f.iso", 77).error.fault, Fault::bad_data);
    e = split_file("%1\nA\n%2\nB\n%1\nC\n", "dup.iso").error;
    EXPECT_EQ(e.fault, Fault::bad_data);
    EXPECT_NE(e.message.find("dup.iso:5"), std::string::npos) << e.message;
    e = split_file("N5 G0\n%1\nA\n", "pre.iso").error;
    EXPECT_NE(e.message.find("pre.iso:2: blocks before"), std::string::npos) << e.message;
    e = split_file(std::string("%1\nA\n\0", 7), "bin.iso").error;
    EXPECT_NE(e.message.find("bin.iso:3: not a program text"), std::string::npos) << e.message;
    EXPECT_EQ(split_file("(ONLY A COMMENT)\n", "c.iso", 5).error.fault, Fault::bad_data);
}

// export(import(x)) == x for every program of every shared file, and the
// programs of a file exported one after the other give the file back.
TEST_P(StoreRoundTrip, EverySharedProgram) {
    std::string dir = test::shared_programs();
    if (dir.empty()) GTEST_SKIP() << "../shared/programs not beside the repository";
    test::Place t(GetParam());
    Options o;
    o.seed = false;
    auto s = test::open_store(t / "rt.db", o);
    std::vector<std::string> files;
    for (auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".iso") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    ASSERT_GT(files.size(), 50u);
    int fragment = 900000, programs = 0;
    for (const auto& f : files) {
        std::string text = test::slurp(f);
        auto r = split_file(text, f);
        if (r.error && r.error.message.find("--number") != std::string::npos)
            r = split_file(text, f, ++fragment);
        ASSERT_TRUE(r.ok()) << r.error.message;
        // Files share numbers (several %100): each import is a new revision, read back by it.
        std::vector<Piece> pieces = r.value;
        auto saved = s->save_all(pieces);
        ASSERT_TRUE(saved.ok()) << f << ": " << saved.error.message;
        std::string again;
        for (size_t i = 0; i < pieces.size(); ++i) {
            auto p = s->read(pieces[i].number, saved.value[i].revision);
            ASSERT_TRUE(p.ok()) << p.error.message;
            EXPECT_EQ(p.value.text, pieces[i].text) << f;
            again += p.value.text;
            ++programs;
        }
        EXPECT_EQ(again, text) << f;
    }
    EXPECT_GE(programs, int(files.size()));
    EXPECT_EQ(s->integrity_check().value, "ok");
}

TEST_P(StoreValues, CorrectorsAndOriginsWithAudit) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "v.db");
    auto r =
        s->set_values("lathe", {{"D1.X", 15157}, {"D1.Z", 42126}, {"PREF.X", 12235}}, "page CORR");
    ASSERT_TRUE(r.ok()) << r.error.message;
    ASSERT_EQ(r.value.size(), 3u);
    EXPECT_FALSE(r.value[0].old_value);
    r = s->set_values("lathe", {{"D1.X", 15157}, {"D1.Z", 42000}}, "program %555 (t.iso)");
    ASSERT_EQ(r.value.size(), 1u);  // D1.X did not change
    EXPECT_EQ(r.value[0].name, "D1.Z");
    EXPECT_EQ(*r.value[0].old_value, 42126);
    auto v = s->values("lathe").value;
    EXPECT_EQ(v.size(), 3u);
    EXPECT_EQ(v["D1.Z"], 42000);
    EXPECT_EQ(v["PREF.X"], 12235);
    EXPECT_TRUE(s->values("mill").value.empty());
    auto a = s->audit("lathe").value;
    ASSERT_EQ(a.size(), 4u);
    EXPECT_EQ(a[3].name, "D1.Z");
    EXPECT_EQ(*a[3].old_value, 42126);
    EXPECT_EQ(*a[3].new_value, 42000);
    EXPECT_EQ(a[3].who, "tester");
    EXPECT_EQ(a[3].source, "program %555 (t.iso)");
    EXPECT_EQ(s->audit("", 1).value.size(), 1u);
    // Unknown names are refused, and nothing of the call is written.
    EXPECT_EQ(s->set_values("lathe", {{"D1.X", 1}, {"D0.X", 2}}, "").error.fault, Fault::bad_data);
    EXPECT_EQ(s->set_values("lathe", {{"PREF.Q", 2}}, "").error.fault, Fault::bad_data);
    EXPECT_EQ(s->values("lathe").value["D1.X"], 15157);
    // A machine the store does not know is added with its profile.
    ASSERT_TRUE(s->set_values("mymill", {{"D2.L", 100000}}, "", "name = mymill\n").ok());
    EXPECT_EQ(s->machine_profile("mymill").value, "name = mymill\n");
    ASSERT_FALSE(s->put_machine("mymill", "name = mymill\nkind = mill\n"));
    EXPECT_EQ(s->machine_profile("mymill").value, "name = mymill\nkind = mill\n");
    EXPECT_EQ(s->machine_profile("nope").error.fault, Fault::not_found);
}

TEST_P(StoreValues, SettingsAndImdHistory) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "v.db");
    EXPECT_FALSE(s->setting("page").value);
    ASSERT_FALSE(s->set_setting("page", "om"));
    ASSERT_FALSE(s->set_setting("page", "corr"));
    EXPECT_EQ(*s->setting("page").value, "corr");
    ASSERT_FALSE(s->add_imd("mill", "G0 X10"));
    ASSERT_FALSE(s->add_imd("mill", "M3 S1000"));
    ASSERT_FALSE(s->add_imd("lathe", "T1 D1 M6"));
    ASSERT_FALSE(s->add_imd("newmachine", "G0 Z5"));
    auto h = s->imd_history("mill").value;
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[0].block, "G0 X10");
    EXPECT_EQ(h[1].block, "M3 S1000");
    EXPECT_EQ(s->imd_history("mill", 1).value[0].block, "M3 S1000");
    EXPECT_EQ(s->imd_history("newmachine").value.size(), 1u);
}

// The workshop of a machine (issue 15): kept, replaced, removed; a machine
// the store did not know is added.
TEST_P(StoreValues, WorkshopIsKeptPerMachine) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "w.db");
    EXPECT_FALSE(s->workshop("lathe").value);
    ASSERT_FALSE(s->put_workshop("lathe", "kind = lathe\n", "0 0 10 0 10 10\n"));
    ASSERT_FALSE(s->put_workshop("lathe", "kind = lathe\nname = b\n", "1 1 2 1 2 2\n"));
    auto w = s->workshop("lathe").value;
    ASSERT_TRUE(w);
    EXPECT_EQ(w->setup, "kind = lathe\nname = b\n");
    EXPECT_EQ(w->part, "1 1 2 1 2 2\n");
    ASSERT_FALSE(s->put_workshop("lathe2", "kind = lathe\n", ""));
    EXPECT_TRUE(s->workshop("lathe2").value);
    EXPECT_FALSE(s->workshop("mill").value);
    ASSERT_FALSE(s->put_workshop("lathe", "", ""));
    EXPECT_FALSE(s->workshop("lathe").value);
}

// Every attempt (the class report's read: one COPY on a server) has what the
// read of one exercise's has, field for field, NULLs and fractions included.
TEST_P(StorePrograms, AllAttemptsHaveWhatOneExercisesHave) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "a.db");
    for (int i = 0; i < 4; ++i) {
        Attempt at;
        at.exercise = i % 2 ? "ex-b" : "ex-a";
        at.exercise_sha = std::string(64, char('a' + i));
        at.student = "student" + std::to_string(i);
        at.machine = "lathe#" + std::to_string(i);
        ASSERT_FALSE(s->start_attempt(at));
        if (i == 3) continue;  // in progress: no submission, no score, no seconds
        at.submitted_ms = at.started_ms + 1000 * (i + 1);
        at.seed = "5eed" + std::to_string(i);
        at.score = 40 + i;
        at.seconds = 61.25 + i / 3.0;
        at.crashes = i;
        at.scrapped = i == 1;
        at.mistakes = i == 2 ? "dec1 sign" : "";
        at.found = "D1.X=12.5\nDEC1.Z=-3.2 \xc3\xa9";
        at.report = "line one\nline two";
        at.record = "dia 40.0000\n";
        ASSERT_FALSE(s->submit_attempt(at));
    }
    auto all = s->attempts();
    ASSERT_TRUE(all.ok()) << all.error.message;
    ASSERT_EQ(all.value.size(), 4u);
    std::vector<Attempt> each = s->attempts("ex-a").value;
    for (const Attempt& b : s->attempts("ex-b").value) each.push_back(b);
    ASSERT_EQ(each.size(), 4u);
    for (const Attempt& a : all.value) {
        auto same =
            std::find_if(each.begin(), each.end(), [&](const Attempt& b) { return b.id == a.id; });
        ASSERT_NE(same, each.end()) << a.id;
        const Attempt& b = *same;
        EXPECT_EQ(a.exercise, b.exercise);
        EXPECT_EQ(a.exercise_sha, b.exercise_sha);
        EXPECT_EQ(a.student, b.student);
        EXPECT_EQ(a.machine, b.machine);
        EXPECT_EQ(a.started_ms, b.started_ms);
        EXPECT_EQ(a.submitted_ms, b.submitted_ms);
        EXPECT_EQ(a.seed, b.seed);
        EXPECT_EQ(a.score, b.score);
        EXPECT_EQ(a.seconds, b.seconds);
        EXPECT_EQ(a.crashes, b.crashes);
        EXPECT_EQ(a.scrapped, b.scrapped);
        EXPECT_EQ(a.mistakes, b.mistakes);
        EXPECT_EQ(a.found, b.found);
        EXPECT_EQ(a.report, b.report);
        EXPECT_EQ(a.signature, b.signature);
        EXPECT_EQ(a.record, b.record);
    }
    EXPECT_GT(all.value[0].seconds, 0);
    EXPECT_EQ(all.value[3].submitted_ms, 0);
}

// An attempt is submitted once and graded once (Store::one_row): a second
// submit or grade is refused as already done, on both engines.
TEST_P(StorePrograms, AnAttemptIsSubmittedOnceAndGradedOnce) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "a.db");
    Attempt at;
    at.exercise = "ex";
    at.student = "ann";
    at.machine = "attempt-ann";
    ASSERT_FALSE(s->start_attempt(at));
    at.submitted_ms = 77;
    ASSERT_FALSE(s->submit_attempt(at));
    StoreError again = s->submit_attempt(at);
    EXPECT_EQ(again.fault, Fault::not_found);
    EXPECT_EQ(again.message, "the attempt was submitted already");
    at.signature = "sig";
    ASSERT_FALSE(s->grade_attempt(at));
    StoreError twice = s->grade_attempt(at);
    EXPECT_EQ(twice.fault, Fault::not_found);
    EXPECT_EQ(twice.message, "the attempt was graded already");
}
