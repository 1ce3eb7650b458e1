// The machining centre's material (issue 15): a pocket cut into a 300 x 200
// field at 0.1 mm, the contact search of a jog into a side and of a descent
// onto the top, and the instruments' lines through 100,000 strokes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/workshop/mill_part.hpp"

using namespace pupitre::workshop;

namespace {

const Box3 kBlock{{0, 0, 0}, {300, 200, 50}};

Cutter cutter(double radius, double corner) {
    Cutter c;
    c.radius = radius, c.corner = corner;
    return c;
}

// Splits a -> b into pieces no longer than `piece`.
void line(std::vector<P3>& path, const P3& b, double piece) {
    const P3 a = path.back();
    const double len = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    const int n = std::max(1, int(std::ceil(len / piece)));
    for (int k = 1; k <= n; ++k) {
        const double t = double(k) / n;
        path.push_back(
            {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
    }
}

// A pocket 100 x 60 with corners of R 10 at (100..200, 70..130), cleared
// from its wall inwards by a Ø8 at 4.8 of stepover in 3 layers of 2 mm,
// each entered by a ramp; the rounded corners in chords of 8 a quarter.
std::vector<P3> pocket(double piece) {
    std::vector<P3> path{{150, 100, 51}};
    for (int layer = 1; layer <= 3; ++layer) {
        const double z = 50 - 2 * layer;
        line(path, {110, 100, z + 2}, piece);
        line(path, {104, 100, z}, piece);  // the ramp
        for (double inset = 4; inset <= 30; inset += 4.8) {
            const double x0 = 100 + inset, x1 = 200 - inset, y0 = 70 + inset, y1 = 130 - inset;
            const double r = std::max(10 - inset, 0.0);
            const double cx[4] = {x1 - r, x1 - r, x0 + r, x0 + r};
            const double cy[4] = {y0 + r, y1 - r, y1 - r, y0 + r};
            line(path, {x0 + r, y0, z}, piece);
            for (int q = 0; q < 4; ++q) {
                // Along the side to the corner, then its quarter.
                const double a0 = (q - 1) * M_PI / 2;
                line(path, {cx[q] + r * std::cos(a0), cy[q] + r * std::sin(a0), z}, piece);
                for (int k = 1; k <= 8 && r > 0; ++k) {
                    const double a = a0 + k * M_PI / 16;
                    line(path, {cx[q] + r * std::cos(a), cy[q] + r * std::sin(a), z}, 10);
                }
            }
            line(path, {x0 + r, y0, z}, piece);
        }
        line(path, {path.back()[0], path.back()[1], 51}, piece);
    }
    return path;
}

void cut_pocket(benchmark::State& st) {
    const std::vector<P3> path = pocket(double(st.range(0)) / 100);
    const Cutter c = cutter(4, 0);
    double volume = 0;
    for (auto _ : st) {
        st.PauseTiming();
        MillWorld w(kBlock, 0.1);
        st.ResumeTiming();
        volume = 0;
        for (size_t k = 1; k < path.size(); ++k) volume += w.cut(c, path[k - 1], path[k]);
        benchmark::DoNotOptimize(volume);
    }
    st.counters["strokes"] = double(path.size() - 1);
    st.counters["mm3"] = volume;
}
void BM_MillPocket(benchmark::State& st) {
    cut_pocket(st);
}
// Pieces of at most 10 mm, and of at most 1.25 mm (some 3,000 strokes).
BENCHMARK(BM_MillPocket)->Arg(1000)->Arg(125)->Unit(benchmark::kMillisecond);

// A 50 mm jog of a Ø10 flat along X into the side of the fresh block, 25
// below its top: contact after 40.
void BM_MillJogIntoSide(benchmark::State& st) {
    MillWorld w(kBlock, 0.1);
    const Cutter c = cutter(5, 0);
    double f = 0;
    for (auto _ : st) {
        f = w.first_contact(c, {-45, 100, 25}, {5, 100, 25}, Part::flute, 0);
        benchmark::DoNotOptimize(f);
    }
    st.counters["travel"] = f * 50;
}
BENCHMARK(BM_MillJogIntoSide)->Unit(benchmark::kMicrosecond);

// A descent of 50 onto the top from 10 above it, on the fresh block and
// on the floor of the pocket (cut cells).
void BM_MillDescend(benchmark::State& st) {
    MillWorld w(kBlock, 0.1);
    const Cutter c = cutter(5, st.range(0) ? 5 : 0);
    double x = 150, y = 100, top = 50;
    if (st.range(1)) {
        const std::vector<P3> path = pocket(10);
        for (size_t k = 1; k < path.size(); ++k) w.cut(cutter(4, 0), path[k - 1], path[k]);
        x = 137.3, y = 96.1, top = 44;
    }
    double f = 0;
    for (auto _ : st) {
        f = w.first_contact(c, {x, y, top + 10}, {x, y, top - 40}, Part::flute, 0);
        benchmark::DoNotOptimize(f);
    }
    st.counters["travel"] = f * 50;
}
BENCHMARK(BM_MillDescend)->Args({0, 0})->Args({1, 0})->Args({0, 1})->Unit(benchmark::kMicrosecond);

// 100,000 inclined ball strokes (Ø6, 0.6 mm each, rows 1 mm apart) over a
// wavy surface, on 1 mm cells (the lines read the strokes, not the cells).
MillWorld& surfaced() {
    static MillWorld w = [] {
        MillWorld m(kBlock, 1.0);
        const Cutter c = cutter(3, 3);
        auto z = [](double x, double y) { return 45 + 2 * std::sin(x / 10) * std::cos(y / 15); };
        for (int row = 0; row < 200; ++row) {
            const double y = row + 0.5;
            for (int k = 0; k < 500; ++k) {
                const double x0 = k * 0.6, x1 = x0 + 0.6;
                m.cut(c, {x0, y, z(x0, y)}, {x1, y, z(x1, y)});
            }
        }
        return m;
    }();
    return w;
}

void BM_MillAlong100k(benchmark::State& st) {
    MillWorld& w = surfaced();
    const int axis = int(st.range(0));
    size_t n = 0;
    for (auto _ : st) {
        auto v = w.along(axis, {150.3, 100.2, axis == 2 ? 0 : 45.5});
        n = v.size();
        benchmark::DoNotOptimize(v.data());
    }
    st.counters["intervals"] = double(n);
}
BENCHMARK(BM_MillAlong100k)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
