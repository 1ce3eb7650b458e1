// The graphic test's budgets (issue 7): rasterising a 1,000,000-segment
// toolpath on a 200x60 terminal in <= 50 ms a frame, zoomed out and zoomed in;
// a live frame that adds 20,000 moves to the cached raster; the SVG export of
// 200,000 segments in <= 2 s; and the memory a move costs.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "core/output/svg.hpp"
#include "core/output/toolpath.hpp"
#include "pages/page_graph.hpp"

using namespace pupitre;

namespace {

// A zig-zag pocket of 100 x 100 mm in short feed moves, each row entered by a
// rapid and every tenth move a 0.5 mm fillet (an arc): dense everywhere, so the
// zoomed-out frame paints every dot many times over.
std::unique_ptr<Toolpath> synthetic(const MachineProfile& m, size_t moves) {
    auto p = std::make_unique<Toolpath>(m);
    Axes at{};
    p->start_at(at);
    size_t per_row = 1000;
    double step = 100.0 / double(per_row);
    double row_gap = 100.0 / double(moves / per_row + 1);
    MoveEvent e;
    for (size_t i = 0; i < moves; ++i) {
        size_t row = i / per_row, k = i % per_row;
        Axes to = at;
        e.g = k == 0 ? 0 : 1;
        if (k == 0) {
            to[X] = row % 2 ? 100 : 0;
            to[Y] = double(row) * row_gap;
        } else {
            to[X] += row % 2 ? -step : step;
        }
        if (k % 10 == 5) {
            // A half circle of radius step/2 sideways: an arc the raster must draw round.
            e.g = 3;
            e.plane_a0 = X;
            e.plane_a1 = Y;
            e.c0 = (at[X] + to[X]) / 2;
            e.c1 = at[Y];
            e.sweep = row % 2 ? -180 : 180;
        }
        e.from_mach = at;
        e.to_mach = e.to_prog = to;
        e.loc = Loc{1, int(i + 2), -1};
        e.length = step;
        e.seconds = 0.01;
        p->add(e);
        at = to;
    }
    return p;
}

struct Fixture {
    MachineProfile m;
    std::unique_ptr<Toolpath> path;
    explicit Fixture(size_t n) {
        builtin_machine("mill", m);
        path = synthetic(m, n);
    }
};

Fixture& million() {
    static Fixture f(1'000'000);
    return f;
}

// Rasterising every move into the 200x60 page's raster, window fitted.
void BM_Raster1MZoomedOut(benchmark::State& st) {
    Fixture& f = million();
    pages::GraphView g;
    g.path = f.path.get();
    pages::Rect page{0, 1, 200, 56};
    pages::ViewXf xf = pages::graph_window(g, page);
    pages::DotRaster r;
    for (auto _ : st) {
        r.reset(200, pages::graph_area(page).h);
        pages::draw_moves(*f.path, PathPlane::xy, xf, false, 0, f.path->size(), r);
        benchmark::DoNotOptimize(r.bits(0, 0));
    }
    st.counters["segments"] = double(f.path->size());
}
BENCHMARK(BM_Raster1MZoomedOut)->Unit(benchmark::kMillisecond);

// The same, zoomed in about the centre (the argument is the factor): most moves
// are clipped away, the fillets near the centre are drawn with many chords.
void BM_Raster1MZoomedIn(benchmark::State& st) {
    Fixture& f = million();
    pages::GraphView g;
    g.path = f.path.get();
    pages::Rect page{0, 1, 200, 56};
    g = pages::graph_zoom(g, page, double(st.range(0)));
    pages::ViewXf xf = pages::graph_window(g, page);
    pages::DotRaster r;
    for (auto _ : st) {
        r.reset(200, pages::graph_area(page).h);
        pages::draw_moves(*f.path, PathPlane::xy, xf, false, 0, f.path->size(), r);
        benchmark::DoNotOptimize(r.bits(0, 0));
    }
}
BENCHMARK(BM_Raster1MZoomedIn)->Arg(40)->Arg(1000)->Unit(benchmark::kMillisecond);

// Zoomed out with the lathe's mirror image: every cutting move drawn twice.
void BM_Raster1MMirror(benchmark::State& st) {
    Fixture& f = million();
    pages::GraphView g;
    g.path = f.path.get();
    pages::Rect page{0, 1, 200, 56};
    pages::ViewXf xf = pages::graph_window(g, page);
    pages::DotRaster r;
    for (auto _ : st) {
        r.reset(200, pages::graph_area(page).h);
        pages::draw_moves(*f.path, PathPlane::xy, xf, true, 0, f.path->size(), r);
        benchmark::DoNotOptimize(r.bits(0, 0));
    }
}
BENCHMARK(BM_Raster1MMirror)->Unit(benchmark::kMillisecond);

// A whole frame of the page at 200x60 with no cache: raster, marks, text.
void BM_PageFrame1M(benchmark::State& st) {
    Fixture& f = million();
    pages::GraphView g;
    g.path = f.path.get();
    pages::Canvas c(200, 60);
    for (auto _ : st) {
        c.clear();
        pages::page_graph(g, f.m, c, pages::Rect{0, 1, 200, 56});
        benchmark::DoNotOptimize(c.at(0, 0));
    }
}
BENCHMARK(BM_PageFrame1M)->Unit(benchmark::kMillisecond);

// A live frame: the window fixed, 20,000 new moves added to the cached raster
// (the session's TEST mode runs up to 50,000 blocks a frame).
void BM_PageFrameLive(benchmark::State& st) {
    Fixture& f = million();
    pages::GraphCache cache;
    pages::GraphView g;
    g.path = f.path.get();
    g.cache = &cache;
    pages::Rect page{0, 1, 200, 56};
    pages::ViewXf xf = pages::graph_window(g, page);
    g.fit = false;
    g.cx = xf.cx;
    g.cy = xf.cy;
    g.scale = xf.scale;
    pages::Canvas c(200, 60);
    size_t upto = 0;
    for (auto _ : st) {
        upto += 20'000;
        if (upto > f.path->size()) {
            st.PauseTiming();
            upto = 20'000;
            cache.valid = false;
            st.ResumeTiming();
        }
        g.upto = upto;
        c.clear();
        pages::page_graph(g, f.m, c, page);
        benchmark::DoNotOptimize(c.at(0, 0));
    }
}
BENCHMARK(BM_PageFrameLive)->Unit(benchmark::kMillisecond);

void BM_Svg200k(benchmark::State& st) {
    static Fixture f(200'000);
    SvgOptions o;
    o.machine = "mill";
    size_t bytes = 0;
    for (auto _ : st) {
        std::string s = svg_document(*f.path, o);
        bytes = s.size();
        benchmark::DoNotOptimize(s.data());
    }
    st.counters["MB"] = double(bytes) / 1e6;
}
BENCHMARK(BM_Svg200k)->Unit(benchmark::kMillisecond);

// Not a timing: the bytes a move costs in a 1,000,000-move toolpath.
void BM_MemoryPerMove(benchmark::State& st) {
    Fixture& f = million();
    for (auto _ : st) benchmark::DoNotOptimize(f.path->memory_bytes());
    st.counters["bytes/move"] = double(f.path->memory_bytes()) / double(f.path->size());
    st.counters["MB"] = double(f.path->memory_bytes()) / 1e6;
}
BENCHMARK(BM_MemoryPerMove)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
