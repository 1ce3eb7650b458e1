// Training in the console (issue 16): an attempt on a hidden setup, the
// truth on no screen and not in the store's text before :submit, the grade
// stored and signed, the teacher's report as golden files.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "console/class_report.hpp"
#include "console/exercise.hpp"
#include "console/exercise_run.hpp"
#include "core/i18n.hpp"
#include "core/training/exercise.hpp"
#include "tests/console/fixture.hpp"

namespace pupitre::test {
namespace {

constexpr const char* kKey = "0123456789abcdef-test-class-key";

struct Attempt {
    std::string db;
    std::unique_ptr<Console> c;
    training::Exercise e;
    // A console on a store file, the attempt of `student` at `name` started.
    Attempt(const char* name, const char* student, const std::string& path) : db(path) {
        EXPECT_TRUE(training::builtin_exercise(name, e));
        auto st = store::Store::open(db);
        EXPECT_TRUE(st.ok()) << st.error.message;
        c = std::make_unique<Console>(
            e.machine, std::vector<std::string>{}, std::move(st.value),
            [&](console::Session& s) { EXPECT_EQ(s.start_exercise(e, student, kKey), ""); });
    }
};

std::string temp_db() {
    char tmpl[] = "/tmp/pupitre-training-XXXXXX";
    EXPECT_NE(mkdtemp(tmpl), nullptr);
    return std::string(tmpl) + "/store.db";
}

std::string every_page(Console& c) {
    std::string all;
    for (const char* p : {"op", "om", "pref", "corr", "shop", "graph", "info", "param", "exercise",
                          "alarm", "prog", "dir", "part"}) {
        c.type(std::string(":page ") + p);
        if (std::string(p) == "part") {  // the picture and its lines, once made
            c.s->resize(120, 40);
            c.s->view();
            c.s->part().wait();
        }
        all += c.screen(120, 40) + c.message() + "\n";
    }
    return all;
}

std::string bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(TrainingSession, TheExamDoneRightGetsFullMarksStoredAndSigned) {
    const std::string db = temp_db();
    {
        Attempt a("exam-2005", "alice", db);
        a.c->type(":exercise");
        EXPECT_NE(a.c->screen(100, 30).find("June 2005 exam"), std::string::npos);
        for (const char* set : {":set PREF.X=-135.477", ":set PREF.Z=-669.936",
                                ":set DEC1.Z=257.267", ":set D1.X=63.345", ":set D1.Z=38.237"})
            a.c->type(set);
        a.c->type(":submit");
        EXPECT_EQ(a.c->message(), "submitted: 100%; the report is on the EXERCISE page");
        const std::string report = a.c->screen(100, 30);
        EXPECT_NE(report.find("Score 100%"), std::string::npos) << report;
        EXPECT_NE(report.find("PREF Z = the jaws' face = -669.936"), std::string::npos) << report;
        a.c->type(":submit");
        EXPECT_EQ(a.c->message(), "submitted already: the report is on the EXERCISE page");
    }
    auto st = store::Store::open(db);
    ASSERT_TRUE(st.ok());
    auto all = st.value->attempts("exam-2005");
    ASSERT_EQ(all.value.size(), 1u);
    const store::Attempt& r = all.value[0];
    EXPECT_EQ(r.student, "alice");
    EXPECT_EQ(r.score, 100);
    EXPECT_EQ(r.mistakes, "");
    EXPECT_NE(r.found.find("PREF.X=-135.4770"), std::string::npos) << r.found;
    EXPECT_EQ(r.signature, console::sign_attempt(r, kKey));
    // An edited grade no longer matches its signature.
    store::Attempt edited = r;
    edited.score = 90;
    EXPECT_NE(edited.signature, console::sign_attempt(edited, kKey));
}

// What sqlite3(1) shows of the store: every value of every table as text,
// cut into words (a value stored as an integer, as the store keeps
// correctors and origins, is a word of its own).
std::set<std::string> store_words(const std::string& db) {
    std::set<std::string> words;
    sqlite3* h = nullptr;
    EXPECT_EQ(sqlite3_open_v2(db.c_str(), &h, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    std::vector<std::string> tables;
    sqlite3_exec(
        h, "SELECT name FROM sqlite_master WHERE type = 'table'",
        [](void* t, int, char** v, char**) {
            static_cast<std::vector<std::string>*>(t)->push_back(v[0]);
            return 0;
        },
        &tables, nullptr);
    for (const std::string& t : tables) {
        sqlite3_stmt* st = nullptr;
        if (sqlite3_prepare_v2(h, ("SELECT * FROM \"" + t + "\"").c_str(), -1, &st, nullptr))
            continue;
        while (sqlite3_step(st) == SQLITE_ROW)
            for (int i = 0; i < sqlite3_column_count(st); ++i) {
                const char* v = reinterpret_cast<const char*>(sqlite3_column_text(st, i));
                std::string w;
                for (const char* c = v ? v : "";; ++c) {
                    if (*c && !std::strchr(" \t\n,;:=()[]{}\"'", *c)) {
                        w += *c;
                        continue;
                    }
                    if (!w.empty()) words.insert(w);
                    w.clear();
                    if (!*c) break;
                }
            }
        sqlite3_finalize(st);
    }
    sqlite3_close(h);
    return words;
}

TEST(TrainingSession, XTakenAsADiameterFailsWithTheMistakeNamed) {
    Attempt a("exam-2005", "bob", temp_db());
    for (const char* set : {":set PREF.X=-165.466", ":set PREF.Z=-669.936", ":set DEC1.Z=257.267",
                            ":set D1.X=63.345", ":set D1.Z=38.237"})
        a.c->type(set);
    a.c->type(":submit");
    const std::string report = a.c->screen(120, 30);
    EXPECT_NE(report.find("Score 83%"), std::string::npos) << report;
    EXPECT_NE(report.find("X taken as a diameter instead of a radius"), std::string::npos)
        << report;
}

TEST(TrainingSession, TheTruthIsOnNoScreenAndNotInTheStoreBeforeSubmit) {
    const std::string db = temp_db();
    Attempt a("exam-2005-drawn", "carol", db);
    workshop::Setup truth;
    ASSERT_EQ(training::draw_setup(a.e, training::seed_of(a.e, "carol", kKey), truth), "");
    std::vector<std::string> secrets;
    for (const training::Target& t : a.e.find)
        if (double v = 0; training::expected(a.e, truth, t.name, v) && std::abs(v) > 0.5)
            secrets.push_back(strf("%.3f", v));
    ASSERT_EQ(secrets.size(), 5u);      // PREF X Z, DEC1 Z, D1 X Z (DEC1 X is 0)
    std::vector<std::string> internal;  // as the store keeps values: integer µm
    for (const std::string& s : secrets)
        internal.push_back(std::to_string(std::llround(std::stod(s) * 1000)));
    a.c->type(":part new");  // the part saved: the store holds the attempt's workshop
    const std::string screens = every_page(*a.c);
    a.c->type(":setup");
    EXPECT_EQ(a.c->message(), ":setup: not during an exercise (the setup is what you must find)");
    a.c->type(":part export /tmp/part.svg");
    EXPECT_EQ(a.c->message(),
              ":part export: not during an exercise (the setup is what you must find)");
    const std::string stored = bytes_of(db) + bytes_of(db + "-wal");
    const std::set<std::string> words = store_words(db);
    for (size_t i = 0; i < secrets.size(); ++i) {
        const std::string& s = secrets[i];
        EXPECT_EQ(screens.find(s), std::string::npos) << s << " on a screen";
        EXPECT_EQ(stored.find(s), std::string::npos) << s << " in the store";
        EXPECT_EQ(words.count(s), 0u) << s << " in the store's tables";
        EXPECT_EQ(words.count(internal[i]), 0u) << internal[i] << " in the store's tables";
    }
    // The check sees what the store holds: an origin entered shows there.
    a.c->type(":set PREF.X=" + secrets[0]);
    EXPECT_EQ(store_words(db).count(internal[0]), 1u) << internal[0];
    EXPECT_NE(screens.find("no coordinates during an exercise"), std::string::npos);
    // After :submit the report shows them.
    a.c->type(":submit");
    const std::string report = a.c->screen(120, 40);
    for (const std::string& s : secrets)
        EXPECT_NE(report.find(s), std::string::npos) << s << " not in the report\n" << report;
}

// The exercise's program takes its number in the store; a text of the
// class's there stays in the history, and the attempt names its revision.
TEST(TrainingSession, TheProgramTheExerciseReplacesIsKeptAndNamed) {
    const std::string db = temp_db();
    {
        auto st = store::Store::open(db);
        ASSERT_TRUE(st.ok());
        ASSERT_FALSE(
            st.value->save(20, "%20 (MY OWN PROGRAM)\nG0 X10\n", store::kNew, "import").error);
    }
    {
        Attempt a("wear", "gina", db);
        EXPECT_EQ(a.c->s->exercise()->program_note(),
                  "%20 is now the exercise's; the text it replaced is revision 1 (:history 20)");
    }
    Attempt again("wear", "gina", db);  // the same text: nothing replaced, nothing said
    EXPECT_EQ(again.c->s->exercise()->program_note(), "");
    auto st = store::Store::open(db);
    auto old = st.value->read(20, 1);
    ASSERT_FALSE(old.error);
    EXPECT_EQ(old.value.text, "%20 (MY OWN PROGRAM)\nG0 X10\n");
}

// exercise truth of an attempt in progress: the class key's owner only;
// anyone once it is submitted.
TEST(TrainingSession, TheTruthOfAnAttemptInProgress) {
    const std::string db = temp_db();
    const std::string key = db + ".key";
    std::ofstream(key) << kKey << "\n";
    ASSERT_EQ(setenv("PUPITRE_CLASS_KEY", key.c_str(), 1), 0);
    Attempt a("wear", "gina", db);
    store::Store& st = *a.c->s->store();
    EXPECT_EQ(console::truth_allowed(st, a.e, "gina", getuid()), "");
    EXPECT_EQ(console::truth_allowed(st, a.e, "gina", getuid() + 1),
              "gina's attempt at wear is in progress: its truth is shown to the owner of the "
              "class key " +
                  key + ", or once it is submitted");
    EXPECT_EQ(console::truth_allowed(st, a.e, "hugo", getuid() + 1), "");  // no attempt
    a.c->type(":submit");
    EXPECT_EQ(console::truth_allowed(st, a.e, "gina", getuid() + 1), "");
    unsetenv("PUPITRE_CLASS_KEY");
}

TEST(TrainingSession, ARestartContinuesTheAttemptWithItsValues) {
    const std::string db = temp_db();
    {
        Attempt a("lathe-first", "dave", db);
        a.c->type(":set PREF.Z=12.5");
    }
    Attempt b("lathe-first", "dave", db);
    double v = 0;
    b.c->s->sim().interp().get("PREF.Z", v);
    EXPECT_DOUBLE_EQ(v, 12.5);
    // The exercise's start values: D1 holds the true gauges.
    b.c->s->sim().interp().get("D1.X", v);
    EXPECT_GT(v, 40);
    // Not the machine's own state: a plain console on the same store has none of it.
    auto st = store::Store::open(db);
    ASSERT_TRUE(st.ok());
    auto plain = st.value->values("lathe");
    EXPECT_EQ(plain.value.count("PREF.Z"), 0u);
}

TEST(TrainingSession, AnAttemptOnAnEarlierTextIsNotContinued) {
    // Its truth was drawn from that text: the changed exercise starts afresh.
    const std::string db = temp_db();
    {
        Attempt a("lathe-first", "fay", db);
        a.c->type(":set PREF.Z=12.5");
    }
    Attempt b("lathe-first", "fay", db);
    b.e.source += "# changed by the teacher\n";
    auto st = store::Store::open(db);
    ASSERT_TRUE(st.ok());
    Console c(b.e.machine, {}, std::move(st.value),
              [&](console::Session& s) { EXPECT_EQ(s.start_exercise(b.e, "fay", kKey), ""); });
    double v = 0;
    c.s->sim().interp().get("PREF.Z", v);
    EXPECT_DOUBLE_EQ(v, 0);  // the new attempt's start value, not 12.5
    auto open = store::Store::open(db);
    ASSERT_TRUE(open.ok());
    EXPECT_EQ(open.value->attempts("lathe-first").value.size(), 2u);
}

// The teacher's report from attempts made up here, each signed with the key
// (one edited afterwards); the three formats are golden files.
std::vector<store::Attempt> class_attempts() {
    auto make = [](int id, const char* ex, const char* who, int score, double s, int crashes,
                   bool scrapped, const char* mistakes, bool done = true) {
        store::Attempt a;
        a.id = id, a.exercise = ex, a.student = who, a.machine = "lathe#x";
        a.exercise_sha = "sha", a.started_ms = 1000 * id, a.submitted_ms = done ? 2000 * id : 0;
        a.score = score, a.seconds = s, a.crashes = crashes, a.scrapped = scrapped;
        a.mistakes = mistakes, a.found = "PREF.X=1\n", a.report = "r\n";
        a.signature = console::sign_attempt(a, kKey);
        return a;
    };
    std::vector<store::Attempt> v = {
        make(1, "exam-2005", "alice", 100, 600, 0, false, ""),
        // DEC1 forgotten on X and Z: one mistake of this attempt's, counted once.
        make(2, "exam-2005", "bob", 50, 900, 0, false, "diameter dec1 dec1 sign"),
        make(3, "exam-2005", "bob", 83, 700, 0, false, "diameter"),
        make(4, "lathe-first", "alice", 50, 1800, 1, true, "shim"),
        make(5, "lathe-first", "carol", 0, 0, 0, false, "", false),
        make(6, "exam-2005", "<eve>", 100, 300, 0, false, ""),
    };
    v[5].score = 100;  // signed at 100, then "edited": the signature no longer matches
    v[5].report = "edited\n";
    return v;
}

void golden(const std::string& name, const std::string& text) {
    const std::string path = std::string(PUPITRE_SOURCE_DIR) + "/tests/console/expected/" + name;
    if (const char* b = std::getenv("PUPITRE_BLESS"); b && *b == '1') {
        std::ofstream(path, std::ios::binary) << text;
        return;
    }
    EXPECT_EQ(bytes_of(path), text) << "golden " << path << " differs (PUPITRE_BLESS=1 rewrites)";
}

console::ReportContext ctx(const std::string& key, const std::string& title) {
    console::ReportContext c;
    c.key = key;
    c.title = title;
    return c;
}

TEST(ClassReport, TableCsvAndHtmlAreGolden) {
    const auto all = class_attempts();
    golden("class_report.txt",
           console::class_report_text(all, console::ReportFormat::table, ctx(kKey, "class")));
    golden("class_report.csv",
           console::class_report_text(all, console::ReportFormat::csv, ctx(kKey, "class")));
    golden("class_report.html",
           console::class_report_text(all, console::ReportFormat::html,
                                      ctx(kKey, "pupitre: the class's attempts")));
    // The edited attempt counts for nothing: no best, no last, no time.
    const std::string csv =
        console::class_report_text(all, console::ReportFormat::csv, ctx(kKey, ""));
    EXPECT_NE(csv.find("\"exam-2005\",\"<eve>\",1,0,,,,0,0,1,\"\"\n"), std::string::npos) << csv;
    auto edited = all;
    edited[0].score = 100, edited[0].seconds = 60;  // alice's 100 in 10 min made 1 min
    const std::string alice =
        console::class_report_text(edited, console::ReportFormat::csv, ctx(kKey, ""));
    EXPECT_NE(alice.find("\"exam-2005\",\"alice\",1,0,,,,0,0,1,\"\"\n"), std::string::npos)
        << alice;
    const std::string nokey =
        console::class_report_text(all, console::ReportFormat::table, ctx("", ""));
    EXPECT_NE(nokey.find("Signatures not checked: no class key."), std::string::npos);
    EXPECT_EQ(nokey.find("TAMPERED"), std::string::npos);
}

// An attempt made on a text of the exercise that is not its current one is
// named by its text (issue 34: the report says which version each used).
TEST(ClassReport, AnAttemptOnAnEarlierTextIsNamed) {
    auto all = class_attempts();
    console::ReportContext c = ctx(kKey, "class");
    c.current["exam-2005"] = "sha";
    c.current["lathe-first"] = "0123456789abcdef";  // changed since alice's and carol's
    const std::string t = console::class_report_text(all, console::ReportFormat::table, c);
    std::istringstream lines(t);
    int earlier = 0;
    for (std::string l; std::getline(lines, l);) {
        if (l.find("EARLIER TEXT sha") != std::string::npos) {
            EXPECT_EQ(l.rfind("lathe-first", 0), 0u) << l;
            ++earlier;
        }
    }
    EXPECT_EQ(earlier, 2) << t;
}

// On a class's server an attempt submitted and not yet signed waits for the
// teacher's grading: UNGRADED, and it counts for nothing yet.
TEST(ClassReport, OnAServerAnUnsignedAttemptIsUngraded) {
    auto all = class_attempts();
    all[0].signature.clear();  // alice's 100, not graded yet
    console::ReportContext c = ctx(kKey, "class");
    c.on_server = true;
    const std::string csv = console::class_report_text(all, console::ReportFormat::csv, c);
    EXPECT_NE(csv.find("\"exam-2005\",\"alice\",1,0,,,,0,0,0,\"\"\n"), std::string::npos) << csv;
    const std::string t = console::class_report_text(all, console::ReportFormat::table, c);
    EXPECT_NE(t.find("UNGRADED 1"), std::string::npos) << t;
}

}  // namespace
}  // namespace pupitre::test
