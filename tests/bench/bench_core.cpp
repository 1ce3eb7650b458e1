// Google Benchmark: the parser alone, and parser + interpreter on generated
// milling programs (G1/G2/G3), per block. Whole-program figures against LinuxCNC
// come from scripts/bench.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/interp/interp.hpp"
#include "core/plan/plan_sink.hpp"

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
            std::snprintf(buf, sizeof buf, "G%d X%.3f Y%.3f I%.3f J%.3f\n", i % 2 ? 2 : 3, ex, ey,
                          cx, cy);
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
    const std::string line = "N12345 G2 X-120.456 Y87.125 I-100.5 J60.25 F800";
    for (auto _ : st) {
        Error e = parse_block(line, b);
        benchmark::DoNotOptimize(e.code);
        benchmark::DoNotOptimize(b.words.data());
    }
    st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_ParseBlock);

// Loads and runs the text on the machine once per iteration; items: st.range(0).
void run_each_iteration(benchmark::State& st, const char* machine, const std::string& text) {
    MachineProfile m;
    builtin_machine(machine, m);
    struct Null final : MachineSink {
    } sink;
    for (auto _ : st) {
        ProgramMemory mem;
        mem.load_text("bench.iso", text);
        Interpreter in(m, mem, sink);
        in.start(mem.first());
        in.run_to_end();
        benchmark::DoNotOptimize(in.seconds());
    }
    st.SetItemsProcessed(st.iterations() * st.range(0));
}

void BM_RunProgram(benchmark::State& st) {
    run_each_iteration(st, "mill", program(int(st.range(0))));
}
BENCHMARK(BM_RunProgram)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// The planner alone (issue 35 item 7), as its own thread runs it: the moves
// of program(n) recorded once from the interpreter, then planned in one call
// per iteration by a new PlanSink; items: moves. One thread, no interpreter
// beside it, so its time per move is the planner's, whatever the machine's
// other processor is doing.
void BM_PlanMoves(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("mill", m);
    struct Record final : MachineSink {
        std::vector<plan::PlanMove> moves;
        void move(const MoveEvent& e) override { moves.emplace_back(e); }
    } rec;
    ProgramMemory mem;
    mem.load_text("bench.iso", program(int(st.range(0))));
    Interpreter in(m, mem, rec);
    in.start(mem.first());
    in.run_to_end();
    for (auto _ : st) {
        plan::PlanSink p(m);
        p.moves(rec.moves.data(), rec.moves.data() + rec.moves.size());
        p.finish();
        benchmark::DoNotOptimize(p.report().seconds);
    }
    st.SetItemsProcessed(st.iterations() * int64_t(rec.moves.size()));
}
BENCHMARK(BM_PlanMoves)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// G64 on a rough stock of n points (a wavy bar, 0.5 mm deep in diameter) over a
// 50-block profile, passes 0.01 mm apart: 20,000 level lines, a few hundred of
// them through the waves. Each level meets only the elements near it, so the
// time grows with the crossings, not with levels x stock points.
std::string g64_program(int n) {
    std::string s =
        "%1\nN10 G0 X200 Z10\nN20 S500 M3 M40\nN30 G95 F0.2\nN40 G64 N100 N149 P0.01\nX200 Z0\n";
    char buf[64];
    for (int i = 1; i < n; ++i) {
        std::snprintf(buf, sizeof buf, "X%.3f Z%.3f\n", 200 - std::fabs(std::sin(i)) * 0.5,
                      -100.0 * i / n);
        s += buf;
    }
    s += "X200 Z-100\nN70 G80\nN80 M2\n";
    for (int i = 0; i < 50; ++i) {
        std::snprintf(buf, sizeof buf, "N%d G1 X%d Z%d\n", 100 + i, 20 + 10 * (i % 2),
                      -100 + 2 * i);
        s += buf;
    }
    return s;
}

void BM_G64LongStock(benchmark::State& st) {
    run_each_iteration(st, "lathe", g64_program(int(st.range(0))));
}
BENCHMARK(BM_G64LongStock)->Arg(500)->Arg(2000)->Arg(8000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
