// Google Benchmark: the program store against the targets of issue 4 — import
// 10,000 programs in <= 2 s; open a store of 10,000 programs and list them in
// <= 100 ms; save a 100,000-block program in <= 200 ms. The store lives in
// $TMPDIR (a real disk, fsync included: synchronous = FULL).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "store/store.hpp"
#include "store/text.hpp"

using namespace pupitre;
using namespace pupitre::store;

namespace {

std::string temp_dir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "pupitre-bench-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    return tmpl;
}

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

std::unique_ptr<Store> open_or_die(const std::string& path) {
    auto r = Store::open(path);
    if (!r.ok()) {
        std::fprintf(stderr, "%s\n", r.error.message.c_str());
        std::abort();
    }
    return std::move(r.value);
}

// `pupitre import` of one file holding 10,000 programs into a new store:
// cutting the file, checking each program, one transaction.
void BM_Import10000(benchmark::State& st) {
    const std::string file = many_programs(10000);
    std::string dir = temp_dir();
    int i = 0;
    for (auto _ : st) {
        st.PauseTiming();
        std::string path = dir + "/import" + std::to_string(i++) + ".db";
        auto s = open_or_die(path);
        st.ResumeTiming();
        auto pieces = split_file(file, "class.iso");
        auto r = s->save_all(pieces.value);
        if (!r.ok() || r.value.size() != 10000) st.SkipWithError("import failed");
    }
    std::filesystem::remove_all(dir);
    st.SetItemsProcessed(st.iterations() * 10000);
}
BENCHMARK(BM_Import10000)->Unit(benchmark::kMillisecond)->Iterations(5);

// `pupitre list` on a store of 10,000 programs: open (checks included) and list.
void BM_OpenAndList10000(benchmark::State& st) {
    std::string dir = temp_dir();
    const std::string path = dir + "/list.db";
    {
        auto s = open_or_die(path);
        auto pieces = split_file(many_programs(10000), "class.iso");
        if (!s->save_all(pieces.value).ok()) std::abort();
    }
    for (auto _ : st) {
        auto s = open_or_die(path);
        auto l = s->list();
        if (!l.ok() || l.value.size() != 10000)
            st.SkipWithError("list failed");  // %300, %301 replaced
        benchmark::DoNotOptimize(l.value.data());
    }
    std::filesystem::remove_all(dir);
}
BENCHMARK(BM_OpenAndList10000)->Unit(benchmark::kMillisecond)->Iterations(20);

// Saving a 100,000-block program (3 MB) over its previous revision.
void BM_Save100kBlocks(benchmark::State& st) {
    std::string dir = temp_dir();
    auto s = open_or_die(dir + "/big.db");
    const std::string text[2] = {big_program(100000, 0), big_program(100000, 1)};
    int rev = s->save(9000, text[1], kNew, "bench").value.revision;
    int i = 0;
    for (auto _ : st) {
        auto r = s->save(9000, text[i++ % 2], rev, "bench");
        if (!r.ok() || r.value.status != SaveStatus::saved) st.SkipWithError("save failed");
        rev = r.value.revision;
    }
    st.counters["MB"] = double(text[0].size()) / 1e6;
    s.reset();
    std::filesystem::remove_all(dir);
}
BENCHMARK(BM_Save100kBlocks)->Unit(benchmark::kMillisecond)->Iterations(10);

}  // namespace

BENCHMARK_MAIN();
