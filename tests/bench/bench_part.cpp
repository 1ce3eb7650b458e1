// The PART view's frames (issue 36): one frame of the machining centre's
// 3-D view (and of its view from above) of a 1,000,000-cell block cut by a
// pocket, and of the lathe's section after 10,000 passes, each within
// 16 ms on this machine; beside them what a frame costs around the picture:
// the copy of the workshop the console's loop makes (snapshot), the
// surfaces painted once per change of the material (prepare), and the
// picture turned into cells by libchafa on the worker.
//   build/tests/bench/bench_part --benchmark_filter=Frame
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/interp/interp.hpp"
#include "core/render/part_view.hpp"
#include "core/workshop/workshop.hpp"
#include "pages/cells.hpp"

using namespace pupitre;

namespace {

// The console's picture on a 200 x 60 terminal: the page's 200 x 52
// cells, four by eight pixels a cell.
constexpr int kW = 800, kH = 416;

// A 100 x 100 block at 0.1 mm (1000 x 1000 cells) in the shipped mill's
// vice, a Ø8 end mill clearing a pocket in two layers, zigzag, and a slot.
struct Mill {
    MachineProfile machine;
    ProgramMemory mem;
    workshop::Setup setup;
    std::unique_ptr<workshop::Workshop> shop;
    std::unique_ptr<Interpreter> in;
    Mill() {
        builtin_machine("mill", machine);
        workshop::builtin_setup("mill", setup);
        workshop::parse_setup(setup.source + "\nstock.length = 100\nstock.width = 100\n", setup);
        shop = std::make_unique<workshop::Workshop>(machine, setup, nullptr);
        std::string p = "%1\nT2 D2 M6\nS2000 M3\nG0 X5 Y5 Z5\n";
        for (int layer = 1; layer <= 2; ++layer) {
            p += "G0 X5 Y5\nG1 Z-" + std::to_string(2 * layer) + " F300\n";
            for (int k = 0; k <= 15; ++k) {
                const int y = 5 + 6 * k;
                p += "G1 Y" + std::to_string(y) + "\nX" + (k % 2 ? "5" : "95") + "\n";
            }
            p += "G0 Z5\n";
        }
        p += "G0 X-10 Y50\nG1 Z-7\nX110 Y60\nG0 Z50\nM2\n";
        mem.load_text("pocket.iso", p);
        in = std::make_unique<Interpreter>(machine, mem, *shop, RunOptions{});
        for (auto [k, v] : {std::pair{"PREF.X", 48.35},
                            {"PREF.Y", -131.72},
                            {"PREF.Z", -290.0},
                            {"D2.L", 117.645},
                            {"D2.R", 4.0}})
            in->set(k, v);
        in->start(mem.first());
        for (StepResult r = StepResult::running; r == StepResult::running;) r = in->step();
    }
};

Mill& mill() {
    static Mill m;
    return m;
}

// The lathe's bar after 10,000 plunges of T1 (r 0.8) 0.009 mm apart, each
// to its own depth: a wavy profile of about 2,000 points.
std::shared_ptr<render::PartScene> lathe_scene() {
    workshop::Setup s;
    workshop::builtin_setup("lathe", s);
    workshop::LatheWorld w(s.lathe);
    const workshop::ToolShape t = workshop::tool_shape(*s.tool(1));
    const double face = s.lathe.chuck_z + s.lathe.stickout, r0 = s.lathe.stock_diameter / 2;
    for (int k = 0; k < 10000; ++k) {
        const double z = face - 2 - 0.009 * k, r = r0 - 1.5 - std::sin(k / 40.0);
        w.cut(workshop::LatheWorld::sweep(t.insert, {{z, r0 + 1}, {z, r}, {z, r0 + 1}}));
    }
    auto sc = std::make_shared<render::PartScene>();
    render::LatheScene& l = sc->lathe;
    l.material = w.material(), l.chuck = w.chuck(), l.tailstock = w.tailstock();
    l.stock = workshop::LatheWorld(s.lathe).material();
    l.has_face = w.right_face(l.face_z);
    l.chuck_z = s.lathe.chuck_z;
    l.jaw_top = r0 + s.lathe.jaw_height;
    l.has_tool = true, l.tool = t, l.tip = {face + 5, r0 + 2};
    return sc;
}

const render::PartScene& lathe() {
    static std::shared_ptr<render::PartScene> sc = lathe_scene();
    return *sc;
}

void BM_FrameMill3d(benchmark::State& st) {
    const auto scene = render::snapshot(*mill().shop, mill().in->machine_pos(), nullptr);
    const auto sf = render::prepare(*scene, render::Paint::depth);
    render::Look look;
    look.mode = render::PartMode::iso;
    for (auto _ : st) benchmark::DoNotOptimize(render::render(*scene, *sf, look, kW, kH));
    st.counters["cells"] = double(scene->block.nx) * scene->block.ny;
}
BENCHMARK(BM_FrameMill3d)->Unit(benchmark::kMillisecond);

// The 3-D view zoomed 4 times: fewer cells a pixel, the same pixels.
void BM_FrameMill3dZoomed(benchmark::State& st) {
    const auto scene = render::snapshot(*mill().shop, mill().in->machine_pos(), nullptr);
    const auto sf = render::prepare(*scene, render::Paint::depth);
    render::Look look;
    look.mode = render::PartMode::iso;
    look.cam = render::zoomed(look.cam, 4);
    for (auto _ : st) benchmark::DoNotOptimize(render::render(*scene, *sf, look, kW, kH));
}
BENCHMARK(BM_FrameMill3dZoomed)->Unit(benchmark::kMillisecond);

void BM_FrameMillTop(benchmark::State& st) {
    const auto scene = render::snapshot(*mill().shop, mill().in->machine_pos(), nullptr);
    const auto sf = render::prepare(*scene, render::Paint::depth);
    render::Look look;
    look.mode = render::PartMode::top;
    for (auto _ : st) benchmark::DoNotOptimize(render::render(*scene, *sf, look, kW, kH));
}
BENCHMARK(BM_FrameMillTop)->Unit(benchmark::kMillisecond);

void BM_FrameLatheSection(benchmark::State& st) {
    const render::PartScene& scene = lathe();
    const auto sf = render::prepare(scene, render::Paint::depth);
    size_t points = 0;
    for (const auto& p : scene.lathe.material) points += p.size();
    for (auto _ : st) benchmark::DoNotOptimize(render::render(scene, *sf, render::Look{}, kW, kH));
    st.counters["points"] = double(points);
}
BENCHMARK(BM_FrameLatheSection)->Unit(benchmark::kMillisecond);

// The loop's own share when the material changed: the copy.
void BM_SnapshotMill(benchmark::State& st) {
    for (auto _ : st)
        benchmark::DoNotOptimize(render::snapshot(*mill().shop, mill().in->machine_pos(), nullptr));
}
BENCHMARK(BM_SnapshotMill)->Unit(benchmark::kMillisecond);

// The worker's, once per change of the material.
void BM_PrepareMill(benchmark::State& st) {
    const auto scene = render::snapshot(*mill().shop, mill().in->machine_pos(), nullptr);
    for (auto _ : st) benchmark::DoNotOptimize(render::prepare(*scene, render::Paint::depth));
}
BENCHMARK(BM_PrepareMill)->Unit(benchmark::kMillisecond);

void BM_PrepareLathe(benchmark::State& st) {
    for (auto _ : st) benchmark::DoNotOptimize(render::prepare(lathe(), render::Paint::depth));
}
BENCHMARK(BM_PrepareLathe)->Unit(benchmark::kMillisecond);

// The worker's, for each picture: the 200 x 52 cells in 256 colours.
void BM_CellsChafa(benchmark::State& st) {
    const auto scene = render::snapshot(*mill().shop, mill().in->machine_pos(), nullptr);
    const auto sf = render::prepare(*scene, render::Paint::depth);
    render::Look look;
    look.mode = render::PartMode::iso;
    const render::Picture p = render::render(*scene, *sf, look, kW, kH);
    for (auto _ : st)
        benchmark::DoNotOptimize(pages::to_cells(p.image, 200, 52, pages::Colours::c256, false));
}
BENCHMARK(BM_CellsChafa)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
