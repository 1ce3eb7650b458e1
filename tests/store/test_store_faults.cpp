// The server stopped under its clients (pg_ctl stop -m immediate) and started
// again: every save a client was told succeeded is there once, no other one
// is, a refused one says so in one line, and a store connection made before
// the stop works again once the server is back. Run alone (RUN_SERIAL): it
// stops the test server every other test uses.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <map>
#include <mutex>
#include <thread>

#include "core/training/exercise.hpp"
#include "store_helpers.hpp"

using namespace pupitre;
using namespace pupitre::store;

namespace {

// pg_ctl as the server's owner, as scripts/lib/pg.sh made it.
int pg_ctl(const std::string& what) {
    const char* as = std::getenv("PUPITRE_TEST_PG_AS");
    const char* ctl = std::getenv("PUPITRE_TEST_PG_CTL");
    // The server started here outlives the test: it must not keep the files
    // the test inherited open (a build lock, a pipe of the test runner).
    std::string cmd = std::string(as ? as : "") + " " + ctl + " " + what +
                      " >/dev/null 2>&1 </dev/null 3>&- 4>&- 5>&- 6>&- 7>&- 8>&- 9>&-";
    return std::system(cmd.c_str());
}

class StoreFault : public ::testing::Test {
  protected:
    void SetUp() override {
        if (std::getenv("PUPITRE_TEST_PG") && std::getenv("PUPITRE_TEST_PG_CTL")) return;
        const char* ci = std::getenv("CI");
        if (ci && std::string(ci) == "true")
            FAIL() << "CI=true and no PostgreSQL test server: scripts/test starts one";
        GTEST_SKIP() << "no PostgreSQL test server (scripts/test starts one)";
    }
    // Whatever happened, the server runs again for the tests after this one.
    void TearDown() override {
        if (std::getenv("PUPITRE_TEST_PG_CTL") && pg_ctl("status") != 0) pg_ctl("start");
    }
};

std::string text_of(int number, int round) {
    return "%" + std::to_string(number) + "\nN10 G1 X" + std::to_string(round) + "\nM2\n";
}

}  // namespace

TEST_F(StoreFault, ServerKilledUnderThirtyClientsLosesAndDoublesNothing) {
    test::Place t("postgresql");
    const std::string db = t / "fault";
    test::open_store(db);
    constexpr int kClients = 30, kRounds = 40;
    std::mutex m;
    std::map<int, std::vector<int>> told_saved;  // program -> rounds the client was told were saved
    std::atomic<int> refused{0}, bad_messages{0};
    std::atomic<int> opened{0};
    auto client = [&](int i) {
        Options o;
        o.user = "c" + std::to_string(i);
        auto r = Store::open(db, o);
        ++opened;
        if (!r.ok()) {
            ++refused;
            return;
        }
        while (opened < kClients) std::this_thread::yield();  // all connected, then go
        const int number = 3000 + i;
        int based = kNew;
        for (int round = 0; round < kRounds; ++round) {
            auto s = r.value->save(number, text_of(number, round), based, "fault");
            if (s.ok()) {
                based = s.value.revision;
                std::lock_guard<std::mutex> lock(m);
                told_saved[number].push_back(round);
            } else {
                ++refused;
                if (s.error.message.find('\n') != std::string::npos) ++bad_messages;
                based = kHead;  // as a console does: reload and go on
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    };
    std::vector<std::thread> threads;
    for (int i = 0; i < kClients; ++i) threads.emplace_back(client, i);
    // Once every client is connected and saving (a quarter of its rounds),
    // whatever became of any one of them.
    while (opened < kClients) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::this_thread::sleep_for(std::chrono::milliseconds(5 * kRounds / 4));
    ASSERT_EQ(pg_ctl("stop -m immediate"), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_EQ(pg_ctl("start"), 0);
    for (auto& th : threads) th.join();
    EXPECT_GT(refused.load(), 0);  // the stop was felt
    EXPECT_EQ(bad_messages.load(), 0);

    auto s = test::open_store(db);
    for (int i = 0; i < kClients; ++i) {
        const int number = 3000 + i;
        auto h = s->history(number);  // not_found: none of its saves got through
        ASSERT_TRUE(h.ok() || h.error.fault == Fault::not_found) << h.error.message;
        std::vector<int> stored;
        for (const auto& rev : h.value) {
            std::string text = s->read(number, rev.revision).value.text;
            stored.push_back(std::atoi(text.c_str() + text.find('X') + 1));
        }
        // Every save the client was told about is there, in order, once; a
        // refused one is not (a commit whose answer was lost may be: then it
        // is there once too, never twice).
        std::vector<int> told = told_saved[number];
        size_t k = 0;
        for (int round : stored)
            if (k < told.size() && told[k] == round) ++k;
        EXPECT_EQ(k, told.size()) << "program " << number;
        for (size_t j = 1; j < stored.size(); ++j) EXPECT_LT(stored[j - 1], stored[j]);
    }
    EXPECT_EQ(s->integrity_check().value, "ok");
}

TEST_F(StoreFault, AConnectionMadeBeforeARestartWorksAfterIt) {
    test::Place t("postgresql");
    const std::string db = t / "restart";
    auto s = test::open_store(db);
    ASSERT_TRUE(s->save(40, "%40\nA\n", kNew, "").ok());
    ASSERT_EQ(pg_ctl("stop -m immediate"), 0);
    auto down = s->save(40, "%40\nB\n", 1, "");
    ASSERT_TRUE(down.error);
    EXPECT_EQ(down.error.fault, Fault::io);
    EXPECT_EQ(down.error.message.find('\n'), std::string::npos) << down.error.message;
    EXPECT_TRUE(s->data_version().error);
    ASSERT_EQ(pg_ctl("start"), 0);
    auto up = s->save(40, "%40\nB\n", 1, "");
    ASSERT_TRUE(up.ok()) << up.error.message;
    EXPECT_EQ(up.value.revision, 2);
    EXPECT_EQ(s->read(40).value.text, "%40\nB\n");
    EXPECT_FALSE(s->data_version().error);
}

// Issue 34: 30 students of a class, each as their own login, submit their
// attempt while the server is killed and started again. Each client hands
// its attempt in until the server takes it or says it has it; every attempt
// is then submitted once, and the teacher's side grades each once.
TEST_F(StoreFault, ThirtyStudentsSubmitThroughAKillAndEachIsGradedOnce) {
    test::Place t("postgresql");
    const std::string db = t / "classfault";
    auto teacher = test::open_store(db);
    ASSERT_TRUE(teacher);
    const std::string group = "f" + std::to_string(::getpid());
    training::Exercise e;
    ASSERT_TRUE(training::builtin_exercise("exam-2005", e));
    ASSERT_FALSE(teacher->class_init(group, {{e.name, e.source}}));
    constexpr int kStudents = 30;
    std::vector<std::string> names;
    for (int i = 0; i < kStudents; ++i) names.push_back(group + "s" + std::to_string(i));
    auto logins = teacher->add_students(group, names);
    ASSERT_TRUE(logins.ok()) << logins.error.message;
    std::atomic<int> opened{0}, refused{0}, bad_messages{0}, unsent{0};
    std::atomic<bool> stopped{false};
    auto student = [&](int i) {
        const store::Login& l = logins.value[size_t(i)];
        auto r = Store::open(db + " user=" + l.name + " password=" + l.password);
        if (!r.ok()) {
            ++opened, ++unsent;
            return;
        }
        auto a = r.value->open_class_attempt("exam-2005", "lathe#exam-2005#1");
        ++opened;
        if (!a.ok()) {
            ++unsent;
            return;
        }
        while (opened < kStudents) std::this_thread::yield();
        // Half hand in as the server is stopped, half while it is down.
        if (i % 2)
            while (!stopped) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        a.value.score = i, a.value.record = "dia 40.0000\n";
        for (int tries = 0;; ++tries) {
            StoreError err = r.value->submit_class_attempt(a.value);
            if (!err || err.fault == Fault::not_found) break;  // taken, or taken before
            ++refused;
            if (err.message.find('\n') != std::string::npos) ++bad_messages;
            if (tries == 400) {
                ++unsent;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
        }
    };
    std::vector<std::thread> threads;
    for (int i = 0; i < kStudents; ++i) threads.emplace_back(student, i);
    while (opened < kStudents) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const int stop = pg_ctl("stop -m immediate");
    stopped = true;
    ASSERT_EQ(stop, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_EQ(pg_ctl("start"), 0);
    for (auto& th : threads) th.join();
    EXPECT_GT(refused.load(), 0);  // the stop was felt
    EXPECT_EQ(unsent.load(), 0);
    EXPECT_EQ(bad_messages.load(), 0);

    auto s = test::open_store(db);
    auto all = s->attempts("exam-2005");
    ASSERT_TRUE(all.ok()) << all.error.message;
    std::map<std::string, int> per_student;
    for (const Attempt& a : all.value) {
        ++per_student[a.student];
        EXPECT_NE(a.submitted_ms, 0) << a.student;
        EXPECT_EQ(a.record, "dia 40.0000\n");
    }
    EXPECT_EQ(per_student.size(), size_t(kStudents));
    for (const auto& [who, n] : per_student) EXPECT_EQ(n, 1) << who;
    // Graded once each: a second grading finds nothing left to grade.
    int graded = 0, again = 0;
    for (Attempt a : all.value) {
        a.signature = "signed";
        if (!s->grade_attempt(a)) ++graded;
        if (s->grade_attempt(a).fault == Fault::not_found) ++again;
    }
    EXPECT_EQ(graded, kStudents);
    EXPECT_EQ(again, kStudents);
    for (const std::string& n : names) test::pg_admin("DROP ROLE IF EXISTS \"" + n + "\"");
    test::pg_admin("DROP ROLE IF EXISTS \"" + group + "\"");
}
