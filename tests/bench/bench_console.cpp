// The console's frame budget: one animation tick at "max" speed on a
// 1,000,000-block program, one TEST tick, and drawing a whole screen. The event
// loop stays responsive as long as these stay well under a 30 ms frame.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "console/session.hpp"
#include "pages/canvas.hpp"
#include "store/store.hpp"

using namespace pupitre;

namespace {

std::string big_program(int blocks) {
    std::string t = "%1\nG0 X0 Y0 Z0\nF2000\n";
    t.reserve(size_t(blocks) * 20);
    for (int i = 0; i < blocks; ++i) {
        t += "G1 X";
        t += std::to_string(i % 200);
        t += " Y";
        t += std::to_string((i * 7) % 150);
        t += '\n';
    }
    t += "M2\n";
    return t;
}

struct Bench {
    MachineProfile m;
    console::PlainLineInput input;
    std::unique_ptr<console::Session> s;
    explicit Bench(Mode mode) {
        builtin_machine("mill", m);
        m.homing_required = false;
        s = std::make_unique<console::Session>(m, nullptr, input);
        s->memory().load_text("big.iso", big_program(1'000'000));
        s->load_store();
        s->sim().select(1);
        s->sim().set_mode(mode);
        s->set_speed(console::Speed::max);
        s->sim().cycle_start();
    }
};

// One frame of AUTO at max speed: up to 20,000 blocks executed and played back.
void BM_TickMax(benchmark::State& st) {
    auto b = std::make_unique<Bench>(Mode::automatic);
    for (auto _ : st) {
        if (!b->s->busy()) {
            st.PauseTiming();
            b = std::make_unique<Bench>(Mode::automatic);
            st.ResumeTiming();
        }
        b->s->tick(1.0 / 30);
    }
    st.counters["blocks/frame"] = 20000;
}
BENCHMARK(BM_TickMax)->Unit(benchmark::kMillisecond);

// One frame of TEST: up to 50,000 blocks checked.
void BM_TickTest(benchmark::State& st) {
    auto b = std::make_unique<Bench>(Mode::test);
    for (auto _ : st) {
        if (!b->s->busy()) {
            st.PauseTiming();
            b = std::make_unique<Bench>(Mode::test);
            st.ResumeTiming();
        }
        b->s->tick(1.0 / 30);
    }
}
BENCHMARK(BM_TickTest)->Unit(benchmark::kMillisecond);

// Drawing the PROG page (the program text around the block) on a 200x60 screen.
void BM_RenderProg(benchmark::State& st) {
    Bench b(Mode::automatic);
    for (int i = 0; i < 10; ++i) b.s->tick(1.0 / 30);
    b.s->show_page(pages::PageId::prog);
    pages::Canvas c(200, 60);
    for (auto _ : st) {
        b.s->tick(1.0 / 30);
        pages::render_screen(b.s->view(), c);
        benchmark::DoNotOptimize(c.at(0, 0));
    }
}
BENCHMARK(BM_RenderProg)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
