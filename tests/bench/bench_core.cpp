// Google Benchmark: the parser alone, and parser + interpreter on generated
// milling programs (G1/G2/G3), per block. Whole-program figures against LinuxCNC
// come from scripts/bench.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "core/interp.hpp"

using namespace pupitre;

namespace {

std::string program(int blocks) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-200, 200), ang(0, 6.283);
    std::string s = "%1\nN10 G0 X0 Y0 Z5\nG1 F800\n";
    double x = 0, y = 0;
    char buf[128];
    for (int i = 0; i < blocks; ++i) {
        if (i % 3 == 2) {
            double r = 5 + std::fabs(u(rng)) / 10, a0 = ang(rng), a1 = ang(rng);
            double cx = x - r * std::cos(a0), cy = y - r * std::sin(a0);
            double ex = std::round((cx + r * std::cos(a1)) * 1000) / 1000;
            double ey = std::round((cy + r * std::sin(a1)) * 1000) / 1000;
            std::snprintf(buf, sizeof buf, "G%d X%.3f Y%.3f I%.3f J%.3f\n", i % 2 ? 2 : 3, ex, ey, cx, cy);
            x = ex;
            y = ey;
        } else {
            x = std::round(u(rng) * 1000) / 1000;
            y = std::round(u(rng) * 1000) / 1000;
            std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f\n", x, y);
        }
        s += buf;
    }
    return s + "M2\n";
}

void BM_ParseBlock(benchmark::State& st) {
    Block b;
    Diag d;
    const std::string line = "N12345 G2 X-120.456 Y87.125 I-100.5 J60.25 F800";
    for (auto _ : st) {
        parse_block(line, b, d);
        benchmark::DoNotOptimize(b.words.data());
    }
    st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_ParseBlock);

void BM_RunProgram(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("mill", m);
    const std::string text = program(int(st.range(0)));
    struct Null final : MachineSink {} sink;
    for (auto _ : st) {
        ProgramMemory mem;
        Diag d;
        mem.load_text("bench.iso", text, d);
        Interpreter in(m, mem, sink);
        in.start(mem.first());
        in.run_to_end();
        benchmark::DoNotOptimize(in.seconds());
    }
    st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_RunProgram)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
