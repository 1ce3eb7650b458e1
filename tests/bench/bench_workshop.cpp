// The workshop's budgets (issue 15): material removal on the run of the
// handbook's %555 (shared/programs/000_p555_cycles_x.iso, its G64 part on
// its blank, tests/workshop/p555.setup), the contact search of one jog step,
// and a GRAPH frame with the part filled at 160x48; on the machining centre,
// the handbook's %100 pocket (shared/programs/000_p100_poche_ilot.iso) cut
// in a 300 x 200 block at 0.1 mm, a jog's contact, the shaded GRAPH frame.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <cmath>
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
        mem.load_text("p555.iso", kP555);
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
        mem.load_text("arc.iso", text);
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
    mem.load_text("p555.iso", kP555);
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

// --- the machining centre ---

// The shipped mill setup with a 300 x 200 x 40 block (a 3000 x 2000 height
// field at 0.1 mm), centred where the shipped block is.
workshop::Setup big_block() {
    workshop::Setup s;
    workshop::builtin_setup("mill", s);
    workshop::parse_setup(s.source +
                              "\nstock.length = 300\nstock.width = 200\nstock.x = -41.65\n"
                              "stock.y = -191.72\nvice.jaw.width = 320\n",
                          s);
    return s;
}

// %100 (POCHE AVEC ILOT) as the handbook prints it (the OCR fixed).
const char* kP100 = R"(%100
N10 G46 NU0 NP1 ED8 Q5 J.5 NR+ LX25 LY0
N100 G46 NU1
N110 G1 X35 Y
N120 Y-15 EB5
N130 X25
N140 Y-20 EB5
N150 X-15
N160 G2 X-15 Y20 I-15 J
N170 G1 X25 EB5
N180 Y15
N190 X35 EB5
N200 Y
N300 G46 NU2 LX15 LY
N310 G1 X15 Y5
N320 Y-5
N330 X-15
N340 G2 X-15 Y5 I-15 J
N350 G1 X15
N400 G46 NU9
N510 T1 D1 M6
N520 M3 M40 S1200
N530 G46 NU10 NP1 G83 Z-9.5 P4 Q1 ER2 F300
N600 T2 D2 M6
N610 M3 M41 S1800
N620 G46 NU15 NP1 Z-10 P3 ER1 EP250 EQ350
N700 T3 D3 M6
N710 M3 M41 S2000
N720 G46 NU20 NP1 Z-10 P10 EH0 EI200 EJ300
N800 G Z150
N810 M2
)";

void mill_right(Interpreter& in) {
    for (auto [k, v] : {std::pair{"PREF.X", 108.35},
                        {"PREF.Y", -91.72},
                        {"PREF.Z", -290.0},
                        {"D1.L", 142.318},
                        {"D1.R", 5.0},
                        {"D2.L", 117.645},
                        {"D2.R", 4.0},
                        {"D3.L", 121.082},
                        {"D3.R", 4.0}})
        in.set(k, v);
}

void mill_run(benchmark::State& st, bool with_shop) {
    MachineProfile m;
    builtin_machine("mill", m);
    const workshop::Setup s = big_block();
    Null null;
    long moves = 0;
    for (auto _ : st) {
        ProgramMemory mem;
        mem.load_text("p100.iso", kP100);
        workshop::Workshop shop(m, s, &null);
        Interpreter in(m, mem, with_shop ? static_cast<MachineSink&>(shop) : null);
        mill_right(in);
        in.start(mem.first());
        in.run_to_end();
        moves = in.moves();
        if (with_shop && shop.crashed()) st.SkipWithError(shop.crashes().front().what.c_str());
        benchmark::DoNotOptimize(shop.generation());
    }
    st.counters["moves"] = double(moves);
}

void BM_P100Run(benchmark::State& st) {
    mill_run(st, false);
}
void BM_P100RunWorkshop(benchmark::State& st) {
    mill_run(st, true);
}
BENCHMARK(BM_P100Run)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_P100RunWorkshop)->Unit(benchmark::kMillisecond);

// A JOG of 50 mm along X towards the big block's -X face, T2 5 below its
// top: the contact search of the whole move.
void BM_MillJogContact(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("mill", m);
    workshop::Workshop shop(m, big_block(), nullptr);
    shop.tool(Loc{}, 2, 2, 0, true);
    MoveEvent e;
    e.g = 1;
    e.from_mach[X] = -41.65 - 30;
    e.to_mach[X] = e.from_mach[X] + 50;
    e.from_mach[Y] = e.to_mach[Y] = -91.72;
    e.from_mach[Z] = e.to_mach[Z] = -295 + 117.645;
    for (auto _ : st) {
        workshop::Outcome o = shop.jog(e, true);
        benchmark::DoNotOptimize(o.stop);
    }
}
BENCHMARK(BM_MillJogContact)->Unit(benchmark::kMicrosecond);

// A GRAPH frame at 160x48 with the big block shaded under %100's path.
void BM_GraphFrameBlock(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("mill", m);
    Toolpath path(m);
    ProgramMemory mem;
    mem.load_text("p100.iso", kP100);
    workshop::Workshop shop(m, big_block(), &path);
    Interpreter in(m, mem, shop);
    mill_right(in);
    in.start(mem.first());
    in.run_to_end();
    pages::GraphView g;
    g.path = &path;
    g.plane = PathPlane::xy;
    g.block = shop.mill();
    g.block_dx = -108.35, g.block_dy = 91.72;  // machine to program: - PREF
    pages::Canvas c(160, 48);
    for (auto _ : st) {
        pages::page_graph(g, m, c, pages::Rect{0, 1, 160, 44});
        benchmark::DoNotOptimize(c.at(0, 0));
    }
}
BENCHMARK(BM_GraphFrameBlock)->Unit(benchmark::kMillisecond);

// mill5's head at B30, T1 (Ø10) cutting with its end 1 mm under the top of
// the 100 x 100 block, fed 140 mm along Y across it: one tilted stroke,
// every column of its 10 mm band carved (100,000 cells), on fresh stock.
void BM_MillTiltedPass(benchmark::State& st) {
    MachineProfile m;
    builtin_machine("mill5", m);
    workshop::Setup setup;
    builtin_setup("mill5", setup);
    const double b = 30 * 3.14159265358979323846 / 180, reach = 250 + 110.25;
    MoveEvent e;
    e.g = 1;
    e.from_mach[X] = e.to_mach[X] = std::sin(b) * reach;
    e.from_mach[Y] = -70, e.to_mach[Y] = 70;
    e.from_mach[Z] = e.to_mach[Z] = -281 - 250 + std::cos(b) * reach;
    e.from_mach[B] = e.to_mach[B] = 30;
    e.to_prog = e.to_mach;
    SpindleEvent on;
    on.dir = 3, on.rpm = 1000;
    for (auto _ : st) {
        st.PauseTiming();
        workshop::Workshop shop(m, setup, nullptr);
        shop.tool(Loc{}, 1, 1, 0, true);
        shop.spindle(on);
        st.ResumeTiming();
        workshop::Outcome o = shop.apply(e);
        benchmark::DoNotOptimize(o.crashed);
    }
}
BENCHMARK(BM_MillTiltedPass)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
