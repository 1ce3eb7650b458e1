// Store under process-level stress: a child importing thousands of programs is
// killed with SIGKILL at random points, and two processes write the same store
// at once. After each kill the file is sound and every import is wholly there or
// wholly absent; with two writers nothing is lost and every conflict is reported.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <thread>

#include "store_helpers.hpp"

using namespace pupitre;
using namespace pupitre::store;
using test::TempDir;

namespace {

constexpr int kBatch = 25;     // programs per import (one transaction)
constexpr int kBatches = 200;  // 5,000 programs in all

std::string batch_text(int batch, int i) {
    int number = 10000 + batch * kBatch + i;
    std::string t = "%" + std::to_string(number) + " (BATCH " + std::to_string(batch) + ")\n";
    for (int b = 1; b <= 30; ++b)
        t += "N" + std::to_string(b * 10) + " G1 X" + std::to_string(batch) + "." +
             std::to_string(i) + " Y" + std::to_string(b) + " F500\n";
    return t + "M2\n";
}

// The child: imports batch after batch, from the first one not yet stored.
[[noreturn]] void importer(const std::string& db) {
    Options o;
    o.user = "crash";
    auto r = Store::open(db, o);
    if (!r.ok()) _exit(2);
    auto listed = r.value->list();
    if (!listed.ok()) _exit(3);
    int start = 0;
    for (const auto& p : listed.value)
        if (p.number >= 10000) start = std::max(start, (p.number - 10000) / kBatch + 1);
    for (int b = start; b < kBatches; ++b) {
        std::vector<Piece> pieces;
        for (int i = 0; i < kBatch; ++i)
            pieces.push_back({10000 + b * kBatch + i, batch_text(b, i), "import"});
        if (!r.value->save_all(pieces).ok()) _exit(4);
    }
    _exit(0);
}

}  // namespace

TEST(StoreProcess, KilledImportsAreAllOrNothing) {
    TempDir t;
    const std::string db = t / "crash.db";
    std::mt19937 rng(20261122);
    int kills = 0, finished_batches = 0;
    for (int round = 0; round < 40 && finished_batches < kBatches; ++round) {
        pid_t pid = fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) importer(db);
        // The first rounds may kill it while it creates the store.
        // Short enough that a fast machine is still interrupted many times.
        int ms = round < 3 ? int(rng() % 15) : 1 + int(rng() % 12);
        // On a loaded machine (a parallel build) no batch may finish in 12 ms:
        // later rounds wait longer until one does, still killing mid-import.
        if (finished_batches == 0 && round >= 10) ms += 5 * (round - 9);
        std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        if (kill(pid, SIGKILL) == 0) ++kills;
        int status = 0;
        waitpid(pid, &status, 0);
        if (WIFEXITED(status)) {
            ASSERT_EQ(WEXITSTATUS(status), 0) << "the importer failed";
        }

        if (!test::exists(db)) continue;  // killed before the store was complete: nothing there
        Options o;
        o.create = false;
        auto r = Store::open(db, o);
        ASSERT_TRUE(r.ok()) << "round " << round << ": " << r.error.message;
        Store& s = *r.value;
        ASSERT_EQ(s.integrity_check().value, "ok") << "round " << round;
        std::vector<int> per_batch(kBatches, 0);
        ASSERT_FALSE(s.each_program([&](int n, std::string_view text) {
            if (n < 10000) return;
            int b = (n - 10000) / kBatch, i = (n - 10000) % kBatch;
            ++per_batch[size_t(b)];
            EXPECT_EQ(text, batch_text(b, i)) << "program " << n;
        }));
        finished_batches = 0;
        for (int b = 0; b < kBatches; ++b) {
            ASSERT_TRUE(per_batch[size_t(b)] == 0 || per_batch[size_t(b)] == kBatch)
                << "round " << round << ": batch " << b << " is partly there ("
                << per_batch[size_t(b)] << ")";
            if (per_batch[size_t(b)] == kBatch) {
                ASSERT_EQ(b, finished_batches) << "batches are imported in order";
                ++finished_batches;
            }
        }
    }
    std::printf("%d kills; %d of %d imports of %d programs done\n", kills, finished_batches,
                kBatches, kBatch);
    EXPECT_GE(kills, 10);
    EXPECT_GT(finished_batches, 0);
}

TEST(StoreProcess, TwoWritersLoseNothingAndReportConflicts) {
    TempDir t;
    const std::string db = t / "two.db";
    constexpr int kPrograms = 4, kRounds = 150;
    {
        auto s = test::open_store(db);
        for (int p = 1; p <= kPrograms; ++p)
            ASSERT_TRUE(s->save(p, "%" + std::to_string(p) + "\nV0\n", kNew, "").ok());
    }
    // Each writer loads a program, thinks a little, saves what it loaded plus its
    // line, and logs "program status revision" for each save.
    auto writer = [&](const std::string& who, unsigned seed) {
        Options o;
        o.user = who;
        o.busy_timeout_ms = 10000;
        auto r = Store::open(db, o);
        if (!r.ok()) _exit(2);
        std::FILE* log = std::fopen((t / (who + ".log")).c_str(), "w");
        std::mt19937 rng(seed);
        for (int i = 0; i < kRounds; ++i) {
            int p = 1 + i % kPrograms;
            auto cur = r.value->read(p);
            if (!cur.ok()) _exit(3);
            std::this_thread::sleep_for(std::chrono::microseconds(rng() % 1500));
            std::string text = cur.value.text + who + " " + std::to_string(i) + "\n";
            auto sv = r.value->save(p, text, cur.value.revision, "test");
            if (!sv.ok()) _exit(4);
            std::fprintf(log, "%d %d %d\n", p, int(sv.value.status), sv.value.revision);
        }
        std::fclose(log);
        _exit(0);
    };
    pid_t a = fork();
    if (a == 0) writer("alice", 1);
    pid_t b = fork();
    if (b == 0) writer("bob", 2);
    for (pid_t pid : {a, b}) {
        int status = 0;
        waitpid(pid, &status, 0);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a writer failed: " << status;
    }
    auto s = test::open_store(db);
    ASSERT_EQ(s->integrity_check().value, "ok");
    int reported_conflicts = 0, saves = 0;
    for (std::string who : {"alice", "bob"}) {
        std::FILE* log = std::fopen((t / (who + ".log")).c_str(), "r");
        ASSERT_TRUE(log);
        int p, status, rev;
        while (std::fscanf(log, "%d %d %d", &p, &status, &rev) == 3) {
            ++saves;
            reported_conflicts += status == int(SaveStatus::conflict);
            // Nothing lost: the revision each writer was given holds its text.
            auto text = s->read(p, rev);
            ASSERT_TRUE(text.ok()) << text.error.message;
            EXPECT_NE(text.value.text.find(who + " "), std::string::npos)
                << who << " %" << p << " r" << rev;
        }
        std::fclose(log);
    }
    EXPECT_EQ(saves, 2 * kRounds);
    int flagged = 0, revisions = 0;
    for (int p = 1; p <= kPrograms; ++p)
        for (const auto& h : s->history(p).value) {
            ++revisions;
            flagged += h.conflict;
        }
    EXPECT_EQ(revisions, kPrograms + saves);  // one per save, none overwritten
    EXPECT_EQ(flagged, reported_conflicts);   // every conflict kept is reported, and no other
    EXPECT_GT(reported_conflicts, 0);
}

TEST(StoreProcess, FirstUseByManyProcessesMakesOneStore) {
    TempDir t;
    const std::string db = t / "first.db";
    std::vector<pid_t> pids;
    for (int i = 0; i < 6; ++i) {
        pid_t pid = fork();
        if (pid == 0) {
            auto r = Store::open(db);
            _exit(r.ok() && r.value->list().value.size() == 2 ? 0 : 1);
        }
        pids.push_back(pid);
    }
    for (pid_t pid : pids) {
        int status = 0;
        waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    auto s = test::open_store(db);
    EXPECT_EQ(s->history(300).value.size(), 1u);  // seeded once
    EXPECT_EQ(s->machines().value.size(), 4u);
    s.reset();  // closed: its -wal and -shm go
    int files = 0;
    for (auto& e : std::filesystem::directory_iterator(t.path)) files += e.is_regular_file();
    EXPECT_EQ(files, 1) << "a temporary file was left behind";
}
