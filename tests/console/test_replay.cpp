// An attempt's record and its replay (issue 34): the record's lines written
// and read back; an attempt made at a console by keys and lines, then
// replayed from its record alone on a store of its own, gives the grade the
// console gave (score, mistakes, values, dimensions): the test of
// determinism. Seed 004's exam done right and with DEC1 forgotten, and a
// part cut on the lathe with a feed hold in the middle of the run.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "console/exercise.hpp"
#include "console/exercise_run.hpp"
#include "console/record.hpp"
#include "console/replay.hpp"
#include "core/i18n.hpp"
#include "core/training/exercise.hpp"
#include "tests/console/fixture.hpp"

namespace pupitre::test {
namespace {

constexpr const char* kKey = "0123456789abcdef-test-replay-key";

std::string temp_db() {
    char tmpl[] = "/tmp/pupitre-replay-test-XXXXXX";
    EXPECT_NE(mkdtemp(tmpl), nullptr);
    return std::string(tmpl) + "/store.db";
}

struct Attempt {
    std::string db = temp_db();
    training::Exercise e;
    std::unique_ptr<Console> c;
    Attempt(const char* name, const char* student) {
        EXPECT_TRUE(training::builtin_exercise(name, e));
        open(student);
    }
    // A console on the store, on the student's attempt (a new one, or the
    // one they left), its size given as the terminal does.
    void open(const char* student) {
        c.reset();
        auto st = store::Store::open(db);
        ASSERT_TRUE(st.ok()) << st.error.message;
        c = std::make_unique<Console>(
            e.machine, std::vector<std::string>{}, std::move(st.value),
            [&](console::Session& s) { EXPECT_EQ(s.start_exercise(e, student, kKey), ""); });
        // As app.cpp starts an attempt: its program selected, its task shown.
        if (e.program_number > 0) c->s->sim().select(e.program_number);
        c->s->show_page(pages::PageId::exercise);
        c->s->resize(110, 40);
    }
    ~Attempt() {
        c.reset();
        std::error_code ec;
        std::filesystem::remove_all(std::filesystem::path(db).parent_path(), ec);
    }
    store::Attempt stored() {
        c.reset();  // the console's last record kept
        auto st = store::Store::open(db);
        EXPECT_TRUE(st.ok());
        auto all = st.value->attempts(e.name);
        EXPECT_FALSE(all.value.empty());
        return all.value.empty() ? store::Attempt{} : all.value.back();  // the last
    }
};

// The report's lines but its time (the console's wall clock; the replay
// takes the server's).
std::string report_but_time(const std::string& report) {
    std::string out;
    size_t n = 0;
    for (size_t at = 0; at < report.size(); ++n) {
        size_t eol = report.find('\n', at);
        if (n != 1) out += report.substr(at, eol - at) + "\n";
        at = eol == std::string::npos ? report.size() : eol + 1;
    }
    return out;
}

// The replay of `a` gives its grade exactly.
std::unique_ptr<console::Replay> replayed(const training::Exercise& e, const store::Attempt& a) {
    auto r = console::Replay::open(e, a);
    EXPECT_EQ(r.why, "");
    if (!r.value) return nullptr;
    EXPECT_EQ(r.value->problem(), "");
    r.value->run_to_end();
    const store::Attempt& g = r.value->run().attempt();
    EXPECT_EQ(g.score, a.score);
    EXPECT_EQ(g.mistakes, a.mistakes);
    EXPECT_EQ(g.found, a.found);
    EXPECT_EQ(g.scrapped, a.scrapped);
    EXPECT_EQ(g.crashes, a.crashes);
    EXPECT_EQ(report_but_time(g.report), report_but_time(a.report)) << g.report;
    return std::move(r.value);
}

TEST(Record, EachLineReadsBackAsWritten) {
    using V = console::record::Verb;
    std::vector<console::record::Action> in = {
        {.verb = V::session},
        {.clock = 0, .verb = V::size, .a = 110, .b = 40},
        {.clock = 1.5, .verb = V::key, .text = "page", .arg = "pref"},
        {.clock = 1.5, .verb = V::key, .text = "cycle-start"},
        {.clock = 2.25, .verb = V::line, .text = ":set PREF.X=-135.477  (two blanks)"},
        {.clock = 3, .verb = V::answer, .a = 1},
        {.clock = 3, .verb = V::escape},
        {.clock = 4, .verb = V::program, .text = "%10 (A\\B)\r\nN10 G0 X1\nN20 M2\n", .a = 10},
        {.clock = 4, .verb = V::select, .a = 10},
        {.clock = 4, .verb = V::protect, .a = 1},
        {.clock = 5.123456, .verb = V::dia, .value = 59.978},
        {.clock = 6, .verb = V::shim, .value = 0.1},
    };
    std::string text(console::record::kHeader);
    text += "\n";
    for (const auto& a : in) {
        const std::string l = console::record::format(a);
        EXPECT_EQ(l.find('\n'), std::string::npos) << l;
        text += l + "\n";
    }
    std::vector<console::record::Action> out;
    ASSERT_EQ(console::record::parse(text, out), "");
    ASSERT_EQ(out.size(), in.size());
    for (size_t i = 0; i < in.size(); ++i) {
        EXPECT_EQ(out[i].verb, in[i].verb) << i;
        EXPECT_NEAR(out[i].clock, in[i].clock, 1e-6) << i;
        EXPECT_EQ(out[i].text, in[i].text) << i;
        EXPECT_EQ(out[i].arg, in[i].arg) << i;
        EXPECT_EQ(out[i].a, in[i].a) << i;
        EXPECT_EQ(out[i].b, in[i].b) << i;
        EXPECT_NEAR(out[i].value, in[i].value, 1e-4) << i;
    }
    // The readings and shims the grade reads, in either version.
    training::Context c = console::record_context(text);
    EXPECT_EQ(c.diameters, std::vector<double>{59.978});
    EXPECT_EQ(c.shims, std::vector<double>{0.1});
    c = console::record_context("dia 40.0120\nshim 10.0000\n");
    EXPECT_EQ(c.diameters, std::vector<double>{40.012});
    EXPECT_EQ(c.shims, std::vector<double>{10});
    // A line it cannot read is named; the lines before it count.
    EXPECT_NE(console::record::parse(text + "1.0 jump 3\n", out).find("line 14"),
              std::string::npos);
    EXPECT_EQ(out.size(), in.size());
}

// The exam by keys, as tests/e2e/training.sh types it: PREF, then CORR.
void exam(Attempt& a, bool dec1) {
    a.c->named("M-p");
    for (std::string v : {"PREF.X=-135.477", "PREF.Z=-669.936", "DEC1.Z=257.267"})
        if (dec1 || v[0] != 'D') a.c->type(v);
    a.c->named("M-c");
    a.c->type("X=63.345");
    a.c->type("Z=38.237");
    a.c->type(":submit");
}

TEST(Replay, TheExamDoneRightGetsFullMarksByReplay) {
    Attempt a("exam-2005", "alice");
    exam(a, true);
    EXPECT_EQ(a.c->message(), "submitted: 100%; the report is on the EXERCISE page");
    const store::Attempt s = a.stored();
    EXPECT_EQ(s.record.rfind(console::record::kHeader, 0), 0u) << s.record;
    EXPECT_NE(s.record.find(" key page pref\n"), std::string::npos) << s.record;
    EXPECT_NE(s.record.find(" line PREF.X=-135.477\n"), std::string::npos) << s.record;
    auto r = replayed(a.e, s);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->run().attempt().score, 100);
    EXPECT_TRUE(r->named().empty());
    EXPECT_EQ(r->steps(), 8u);  // M-p, three values, M-c, two values, :submit
}

TEST(Replay, DEC1ForgottenIsNamedByReplayFromTheStart) {
    Attempt a("exam-2005", "bob");
    exam(a, false);
    const store::Attempt s = a.stored();
    EXPECT_NE(s.mistakes.find("dec1"), std::string::npos) << s.mistakes;
    auto r = replayed(a.e, s);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->named().size(), 1u);
    EXPECT_EQ(r->named()[0].value, "DEC1.Z");
    EXPECT_EQ(r->named()[0].mistake, "dec1");
    EXPECT_EQ(r->named()[0].line, 1u);  // left at 0 from the start
}

TEST(Replay, AWrongValueIsNamedFromTheLineThatEnteredIt) {
    Attempt a("exam-2005", "carol");
    a.c->type(":set D1.X=126.69");  // the diameter, not the radius
    a.c->type(":set D1.X=63.345");
    a.c->type(":set D1.X=126.69");
    a.c->type(":submit");
    const store::Attempt s = a.stored();
    auto r = replayed(a.e, s);
    ASSERT_TRUE(r);
    bool found = false;
    for (const auto& n : r->named()) {
        if (n.value != "D1.X") continue;
        found = true;
        EXPECT_EQ(n.mistake, "diameter");
        // The third :set, not the first: the mistake held from there.
        const auto& l = r->lines()[n.line - 1];
        EXPECT_EQ(l.text, ":set D1.X=126.69");
        size_t sets = 0;
        for (size_t i = 0; i < n.line; ++i) sets += r->lines()[i].text.rfind(":set", 0) == 0;
        EXPECT_EQ(sets, 3u);
    }
    EXPECT_TRUE(found);
}

TEST(Replay, AnAttemptTakenUpAgainReplaysBothConsoles) {
    Attempt a("exam-2005", "dave");
    a.c->named("M-p");
    a.c->type("PREF.X=-135.477");
    a.open("dave");  // the console stops; another starts on the same attempt
    a.c->named("M-p");
    a.c->type("PREF.Z=-669.936");
    a.c->type("DEC1.Z=257.267");
    a.c->named("M-c");
    a.c->type("X=63.345");
    a.c->type("Z=38.237");
    a.c->type(":submit");
    EXPECT_EQ(a.c->message(), "submitted: 100%; the report is on the EXERCISE page");
    const store::Attempt s = a.stored();
    size_t sessions = 0;
    for (size_t at = 0; (at = s.record.find(" session\n", at)) != std::string::npos; ++at)
        ++sessions;
    EXPECT_EQ(sessions, 2u) << s.record;
    auto r = replayed(a.e, s);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->run().attempt().score, 100);
}

TEST(Replay, ValuesWrittenInTheStoreByHandCountForNothing) {
    Attempt a("exam-2005", "eve");
    a.c->type(":submit");  // nothing entered: DEC1.X at 0 is right, nothing else
    store::Attempt s = a.stored();
    EXPECT_LT(s.score, 20);
    // The right values written into the attempt's machine afterwards.
    {
        auto st = store::Store::open(a.db);
        ASSERT_TRUE(st.ok());
        auto w =
            st.value->set_values(s.machine, {{"PREF.X", -135477}, {"PREF.Z", -669936}}, "psql");
        EXPECT_FALSE(w.error) << w.error.message;
    }
    auto r = replayed(a.e, s);
    ASSERT_TRUE(r);
    EXPECT_LT(r->run().attempt().score, 20);
}

// lathe-first: homed, T1 called, PREF from the truth (as a student who
// worked it out would type it), %10 run at the console's real speed with
// a feed hold in the middle (unless `cut` is false), the diameters read,
// :submit.
void lathe_first(Attempt& a, const char* student, bool cut) {
    workshop::Setup truth;
    ASSERT_EQ(training::draw_setup(a.e, training::seed_of(a.e, student, kKey), truth), "");
    double px = 0, pz = 0;
    ASSERT_TRUE(training::expected(a.e, truth, "PREF.X", px));
    ASSERT_TRUE(training::expected(a.e, truth, "PREF.Z", pz));
    Console& c = *a.c;
    c.type(strf(":set PREF.X=%.4f", px));
    c.type(strf(":set PREF.Z=%.4f", pz));
    if (cut) {
        c.type(":mode pom");
        c.named("F9");
        c.run_until_settled();
        c.type(":mode imd");
        c.type("T1 D1 M6");
        c.named("F9");
        c.run_until_settled();
        c.type(":mode auto");
        c.named("F9");  // %10, selected at the start
        for (int i = 0; i < 200 && c.s->busy(); ++i) c.s->tick(1.0 / 30);
        ASSERT_TRUE(c.s->busy());
        c.named("F10");  // feed hold
        c.s->tick(1.0 / 30);
        c.named("F9");  // resumes
        for (int i = 0; i < 100000 && c.s->busy(); ++i) c.s->tick(i % 3 ? 1.0 / 30 : 0.2);
    }
    c.type(":measure dia Z-10");
    c.type(":submit");
}

TEST(Replay, APartCutWithAFeedHoldIsCutAgainTheSame) {
    Attempt a("lathe-first", "frank");
    lathe_first(a, "frank", true);
    const store::Attempt s = a.stored();
    EXPECT_NE(s.record.find(" key feed-hold\n"), std::string::npos) << s.record;
    EXPECT_NE(s.record.find(" dia "), std::string::npos) << s.record;
    EXPECT_EQ(s.score, 100) << s.report;
    auto r = replayed(a.e, s);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->run().attempt().score, 100);
}

// The part a first attempt cut, written by hand into a second attempt's
// workshop (the same seed: the same student on a store file): the console
// shows it and grades it, the replay cuts nothing and grades that.
TEST(Replay, APartWrittenByHandIsNotTheReplaysPart) {
    Attempt a("lathe-first", "gina");
    lathe_first(a, "gina", true);
    const store::Attempt first = a.stored();
    ASSERT_EQ(first.score, 100);
    a.open("gina");  // a new attempt
    const store::Attempt second = a.stored();
    ASSERT_NE(second.id, first.id);
    {
        auto st = store::Store::open(a.db);
        ASSERT_TRUE(st.ok());
        auto cut = st.value->workshop(first.machine);
        ASSERT_TRUE(cut.value);
        EXPECT_FALSE(st.value->put_workshop(second.machine, cut.value->setup, cut.value->part));
    }
    a.open("gina");
    lathe_first(a, "gina", false);
    const store::Attempt s = a.stored();
    EXPECT_EQ(s.id, second.id);
    EXPECT_EQ(s.score, 100) << s.report;  // the console graded the part it was given
    auto r = console::Replay::open(a.e, s);
    ASSERT_EQ(r.why, "");
    r.value->run_to_end();
    const store::Attempt& g = r.value->run().attempt();
    EXPECT_EQ(g.score, 50) << g.report;  // the values right, the diameters never cut
    EXPECT_EQ(g.found, s.found);
}

}  // namespace
}  // namespace pupitre::test
