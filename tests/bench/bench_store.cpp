// Google Benchmark: the program store on both engines (issues 4 and 33). The
// targets of issue 4, on SQLite: import 10,000 programs in <= 2 s; open a
// store of 10,000 programs and list them in <= 100 ms; save a 100,000-block
// program in <= 200 ms. Issue 33: each of those, and the class report over
// 30 students x 20 exercises x 5 attempts, within 2x of SQLite on a
// PostgreSQL server over loopback TCP. scripts/bench prints the ratios.
//
// Every benchmark runs on SQLite (a file in $TMPDIR: a real disk, fsync
// included, synchronous = FULL) and, when PUPITRE_TEST_PG names a server
// (scripts/lib/pg.sh: an admin login over 127.0.0.1, the password from
// PGPASSFILE), on PostgreSQL, each store in a schema of its own that is
// dropped afterwards. Both engines get the same data and the same calls.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>
#include <libpq-fe.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "console/class_report.hpp"
#include "core/training/grade.hpp"
#include "store/store.hpp"
#include "store/text.hpp"

using namespace pupitre;
using namespace pupitre::store;

namespace {

[[noreturn]] void die(const std::string& why) {
    std::fprintf(stderr, "bench_store: %s\n", why.c_str());
    std::exit(1);
}

// Where one benchmark's stores live: files in a temporary directory, or
// schemas on the server. fresh() gives the target of a new, empty store.
class Place {
  public:
    explicit Place(bool pg) : pg_(pg) {
        if (!pg_) {
            std::string tmpl =
                (std::filesystem::temp_directory_path() / "pupitre-bench-XXXXXX").string();
            if (!mkdtemp(tmpl.data())) die("cannot make a temporary directory");
            dir_ = tmpl;
            return;
        }
        admin_ = PQconnectdb(std::getenv("PUPITRE_TEST_PG"));
        if (PQstatus(admin_) != CONNECTION_OK) die(PQerrorMessage(admin_));
        PQsetNoticeProcessor(
            admin_, [](void*, const char*) {}, nullptr);
    }
    ~Place() {
        if (!pg_) {
            std::filesystem::remove_all(dir_);
            return;
        }
        for (const std::string& s : schemas_) run("DROP SCHEMA " + s + " CASCADE");
        PQfinish(admin_);
    }
    Place(const Place&) = delete;
    Place& operator=(const Place&) = delete;

    std::string fresh() {
        const int n = next_++;
        if (!pg_) return dir_ + "/store" + std::to_string(n) + ".db";
        const std::string schema =
            "pupitre_bench_" + std::to_string(getpid()) + "_" + std::to_string(serial_++);
        run("CREATE SCHEMA " + schema);
        schemas_.push_back(schema);
        return std::string(std::getenv("PUPITRE_TEST_PG")) + " options='-csearch_path=" + schema +
               "'";
    }

    // Attempts made over a class's session, as the server knows them when the
    // teacher asks for the report: the planner's statistics made, as
    // autovacuum does after so many new rows. SQLite needs nothing. (The
    // programs are listed right after their import: Store::list asks
    // nothing of the planner's statistics.)
    void settle() {
        if (pg_)
            for (const std::string& s : schemas_) run("ANALYZE " + s + ".attempts");
    }

  private:
    void run(const std::string& sql) {
        PGresult* r = PQexec(admin_, sql.c_str());
        if (PQresultStatus(r) != PGRES_COMMAND_OK) die(sql + ": " + PQerrorMessage(admin_));
        PQclear(r);
    }
    bool pg_;
    std::string dir_;
    PGconn* admin_ = nullptr;
    std::vector<std::string> schemas_;
    int next_ = 0;
    static inline int serial_ = 0;
};

// A file of `n` programs of about 30 blocks (1 KB) each, as a class would keep them.
std::string many_programs(int n) {
    std::string s;
    char buf[96];
    for (int p = 1; p <= n; ++p) {
        std::snprintf(buf, sizeof buf, "%%%d (PIECE %d)\n", p, p);
        s += buf;
        for (int b = 1; b <= 30; ++b) {
            std::snprintf(buf, sizeof buf, "N%d G1 X%d.%03d Y-%d.%03d F800\n", b * 10, p % 400, b,
                          b, p % 1000);
            s += buf;
        }
        s += "M2\n";
    }
    return s;
}

std::string big_program(int blocks, int variant) {
    std::string s = "%9000 (BIG)\n";
    s.reserve(size_t(blocks) * 32);
    char buf[96];
    for (int b = 1; b <= blocks; ++b) {
        std::snprintf(buf, sizeof buf, "N%d G1 X%d.%03d Y%d.%03d\n", b, (b + variant) % 500,
                      b % 1000, b % 300, (b * 7) % 1000);
        s += buf;
    }
    return s + "M2\n";
}

std::unique_ptr<Store> open_or_die(const std::string& target) {
    auto r = Store::open(target);
    if (!r.ok()) die(r.error.message);
    return std::move(r.value);
}

// `pupitre import` of one file holding 10,000 programs into a new store:
// cutting the file, checking each program, one transaction.
void import10000(benchmark::State& st, bool pg) {
    const std::string file = many_programs(10000);
    Place place(pg);
    for (auto _ : st) {
        st.PauseTiming();
        auto s = open_or_die(place.fresh());
        st.ResumeTiming();
        auto pieces = split_file(file, "class.iso");
        auto r = s->save_all(pieces.value);
        if (!r.ok() || r.value.size() != 10000) st.SkipWithError("import failed");
        st.PauseTiming();
        s.reset();
        st.ResumeTiming();
    }
    st.SetItemsProcessed(st.iterations() * 10000);
}

// A store of 10,000 programs for the list benchmarks.
std::string store_of_10000(Place& place) {
    const std::string target = place.fresh();
    auto s = open_or_die(target);
    auto pieces = split_file(many_programs(10000), "class.iso");
    if (!s->save_all(pieces.value).ok()) die("cannot fill the store");
    place.settle();
    return target;
}

// Listing a store of 10,000 programs that is open (the console's PROGRAMS
// page; on a server, the connection is made already).
void list10000(benchmark::State& st, bool pg) {
    Place place(pg);
    auto s = open_or_die(store_of_10000(place));
    // Once before the clock: an open store has listed before (the page shows
    // on every key), and a first list pays what it pays once (on a server,
    // preparing the statement and the first read of the imported rows);
    // open_list10000 measures that cold path.
    if (!s->list().ok()) st.SkipWithError("list failed");
    for (auto _ : st) {
        auto l = s->list();
        if (!l.ok() || l.value.size() != 10000)
            st.SkipWithError("list failed");  // %300, %301 replaced
        benchmark::DoNotOptimize(l.value.data());
    }
}

// `pupitre list` on a store of 10,000 programs: open (checks included; on a
// server, connecting: TCP, TLS, SCRAM, a server process) and list.
void open_list10000(benchmark::State& st, bool pg) {
    Place place(pg);
    const std::string target = store_of_10000(place);
    for (auto _ : st) {
        auto s = open_or_die(target);
        auto l = s->list();
        if (!l.ok() || l.value.size() != 10000) st.SkipWithError("list failed");
        benchmark::DoNotOptimize(l.value.data());
    }
}

// Saving a 100,000-block program (3 MB) over its previous revision.
void save100k(benchmark::State& st, bool pg) {
    Place place(pg);
    auto s = open_or_die(place.fresh());
    const std::string text[2] = {big_program(100000, 0), big_program(100000, 1)};
    int rev = s->save(9000, text[1], kNew, "bench").value.revision;
    int i = 0;
    for (auto _ : st) {
        auto r = s->save(9000, text[i++ % 2], rev, "bench");
        if (!r.ok() || r.value.status != SaveStatus::saved) st.SkipWithError("save failed");
        rev = r.value.revision;
    }
    st.counters["MB"] = double(text[0].size()) / 1e6;
}

// The class report as `pupitre class report` makes it (console/cli_exercise.cpp)
// from an open store: every attempt read (Store::attempts, one query) and
// summed up as the table, over 30 students x 20 exercises x 5 submitted
// attempts. No class key: the signatures are not checked, so the time is the
// store's and the summing's.
void class_report(benchmark::State& st, bool pg) {
    Place place(pg);
    const std::string target = place.fresh();
    {
        auto s = open_or_die(target);
        using training::Mistake;
        const std::vector<Mistake> kinds = {Mistake::none, Mistake::diameter, Mistake::radius,
                                            Mistake::sign, Mistake::dec1};
        for (int e = 1; e <= 20; ++e) {
            const std::string ex = "ex" + std::to_string(e);
            if (StoreError err = s->put_exercise(ex, "exercise " + ex + "\n")) die(err.message);
            for (int u = 1; u <= 30; ++u)
                for (int k = 1; k <= 5; ++k) {
                    Attempt a;
                    a.exercise = ex;
                    a.exercise_sha = std::string(64, 'a');
                    a.student = "student" + std::to_string(u);
                    a.machine = "lathe";
                    if (StoreError err = s->start_attempt(a)) die(err.message);
                    a.submitted_ms = a.started_ms + 60000 * k;
                    a.seed = std::to_string(e * 1000 + u * 10 + k);
                    a.score = (e * 7 + u * 3 + k * 11) % 101;
                    a.seconds = 60.0 * k + u;
                    a.crashes = (u + k) % 3;
                    a.scrapped = (e + u + k) % 4 == 0;
                    Mistake m = kinds[size_t(e + u + k) % kinds.size()];
                    a.mistakes = m == Mistake::none ? "" : training::mistake_id(m);
                    a.found = "D1.X=12.5 DEC1.Z=-3.2";
                    a.report = "graded";
                    a.signature = "unsigned";
                    if (StoreError err = s->submit_attempt(a)) die(err.message);
                }
        }
    }
    place.settle();
    auto s = open_or_die(target);
    for (auto _ : st) {
        auto r = s->attempts();
        if (!r.ok() || r.value.size() != 3000) st.SkipWithError("attempts failed");
        console::ReportContext c;
        c.title = "the class's attempts";
        std::string text = console::class_report_text(r.value, console::ReportFormat::table, c);
        benchmark::DoNotOptimize(text.data());
    }
}

}  // namespace

int main(int argc, char** argv) {
    // Names: store/OPERATION/ENGINE, which scripts/bench pairs up; each
    // operation on SQLite then on PostgreSQL, so that the two runs are close
    // in time on a busy machine.
    std::vector<std::pair<std::string, bool>> engines = {{"sqlite", false}};
    if (const char* pg = std::getenv("PUPITRE_TEST_PG"); pg && *pg)
        engines.emplace_back("postgresql", true);
    struct Op {
        const char* name;
        void (*run)(benchmark::State&, bool);
        int iterations;
    };
    const Op ops[] = {{"import10000", import10000, 5},
                      {"list10000", list10000, 20},
                      {"open_list10000", open_list10000, 20},
                      {"save100k", save100k, 10},
                      {"class_report", class_report, 20}};
    for (const Op& op : ops)
        for (const auto& [engine, pg] : engines) {
            const bool on_pg = pg;
            auto run = op.run;
            benchmark::RegisterBenchmark((std::string("store/") + op.name + "/" + engine).c_str(),
                                         [run, on_pg](benchmark::State& s) { run(s, on_pg); })
                ->Unit(benchmark::kMillisecond)
                ->Iterations(op.iterations);
        }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
