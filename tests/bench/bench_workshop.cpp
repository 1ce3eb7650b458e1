// The workshop's budgets (issue 15): material removal on the run of the
// handbook's %555 (shared/programs/000_p555_cycles_x.iso, its G64 part on
// its blank, tests/workshop/p555.setup), the contact search of one jog step,
// and a GRAPH frame with the part filled at 160x48.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "core/interp/interp.hpp"
#include "core/workshop/workshop.hpp"
#include "pages/canvas.hpp"
#include "pages/page_graph.hpp"

using namespace pupitre;

namespace {

// %555's roughing (N10-N250), as the handbook prints it, then M02.
const char* kP555 = R"(%555
N10 T1 D1 M6
N20 G92 S2000
N30 G X 200 Z150
N40 G96 S100 M3 M40
N50 G79 N200
N100 X140 Z
N110 G2 X120 Z 10 R10
N120 G1 X60
N130 Z20
N140 X40 Z30
N150 Z40
N160 X60 Z50
N170 Z60
N180 X25 Z90
N190 X
N200 G64 N100 N190 I.5 K.2 P2 F200
N210 X144 Z
N220 Z10
N230 X40 Z 94
N240 X
N250 G80 X200 Z150
N260 M2
)";

workshop::Setup p555_setup() {
    std::ifstream in(PUPITRE_SOURCE_DIR "/tests/workshop/p555.setup");
    std::stringstream ss;
    ss << in.rdbuf();
    workshop::Setup s;
    workshop::parse_setup(ss.str(), s);
    return s;
}

struct Null final : MachineSink {};

// The operator's values that match p555.setup's truth.
void set_right(Interpreter& in) {
    in.set("PREF.X", -20);
    in.set("PREF.Z", -54);
    in.set("D1.X", 52.347);
    in.set("D1.Z", 41.215);
}

void run(benchmark::State& st, bool with_shop) {
    MachineProfile m;
    builtin_machine("lathe", m);
    workshop::Setup s = p555_setup();
    Null null;
    long moves = 0;
    for (auto _ : st) {
        ProgramMemory mem;
        Diag d;
        mem.load_text("p555.iso", kP555, d);
        workshop::Workshop shop(m, s, &null);
        Interpreter in(m, mem, with_shop ? static_cast<MachineSink&>(shop) : null);
        set_right(in);
        in.start(mem.first());
        in.run_to_end();
        moves = in.moves();
        benchmark::DoNotOptimize(shop.world().material().size());
    }
    st.counters["moves"] = double(moves);
}

void BM_P555Run(benchmark::State& st) {
    run(st, false);
}
void BM_P555RunWorkshop(benchmark::State& st) {
    run(st, true);
}
BENCHMARK(BM_P555Run)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_P555RunWorkshop)->Unit(benchmark::kMillisecond);

// A half circle of R 300 through the bar (860 chords): met piece by piece.
void BM_LongArc(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("lathe", m);
    workshop::Setup s;
    workshop::builtin_setup("lathe", s);
    const char* text =
        "%20\nN10 T1 D1 M6\nN20 S1000 M3 G95 F0.2\nN30 G0 X600 Z100\nN40 G2 X600 Z-500 R300\nN50 "
        "M2\n";
    Null null;
    for (auto _ : st) {
        ProgramMemory mem;
        Diag d;
        mem.load_text("arc.iso", text, d);
        workshop::Workshop shop(m, s, &null);
        Interpreter in(m, mem, shop);
        in.set("PREF.X", -20);
        in.set("PREF.Z", 35);
        in.set("D1.X", 52.347);
        in.set("D1.Z", 41.215);
        in.start(mem.first());
        in.run_to_end();
        benchmark::DoNotOptimize(shop.world().material().size());
    }
}
BENCHMARK(BM_LongArc)->Unit(benchmark::kMillisecond);

// One INC step of 0.1 mm towards the bar's Ø60 from 0.05 mm above it: the
// contact search along the step (the shipped setup, T1).
void BM_JogContact(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("lathe", m);
    workshop::Setup s;
    workshop::builtin_setup("lathe", s);
    workshop::Workshop shop(m, s, nullptr);
    shop.tool(Loc{}, 1, 1, 0, true);
    MoveEvent e;
    e.g = 1;
    e.from_mach[Z] = e.to_mach[Z] = 20 + 41.215;
    e.from_mach[X] = 30.05 + 52.347 - 20;
    e.to_mach[X] = e.from_mach[X] - 0.1;
    for (auto _ : st) {
        workshop::Outcome o = shop.jog(e, false);
        benchmark::DoNotOptimize(o.stop);
    }
}
BENCHMARK(BM_JogContact)->Unit(benchmark::kMicrosecond);

// A GRAPH frame at 160x48 with the part of %555 filled under its path.
void BM_GraphFramePart(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("lathe", m);
    workshop::Setup s = p555_setup();
    Toolpath path(m);
    ProgramMemory mem;
    Diag d;
    mem.load_text("p555.iso", kP555, d);
    workshop::Workshop shop(m, s, &path);
    Interpreter in(m, mem, shop);
    set_right(in);
    in.start(mem.first());
    in.run_to_end();
    // The part in the program frame: the tool's truth and gauge agree here.
    std::vector<std::vector<std::array<double, 2>>> part;
    for (const auto& q : shop.world().material()) {
        part.emplace_back();
        for (const auto& v : q) {
            workshop::Pt p = workshop::to_mm(v);
            part.back().push_back({p[0] + 54, p[1]});
        }
    }
    pages::GraphView g;
    g.path = &path;
    g.plane = PathPlane::zx;
    g.part = &part;
    pages::Canvas c(160, 48);
    for (auto _ : st) {
        pages::page_graph(g, m, c, pages::Rect{0, 1, 160, 44});
        benchmark::DoNotOptimize(c.at(0, 0));
    }
    st.counters["outline_points"] = double(part.empty() ? 0 : part.front().size());
}
BENCHMARK(BM_GraphFramePart)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
