// A console session without a terminal: the demo programs in memory, a plain
// input line, keys and commands as the terminal would give them.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>

#include "console/session.hpp"
#include "pages/canvas.hpp"
#include "store/store.hpp"

namespace pupitre::test {

struct Console {
    MachineProfile machine;
    console::PlainLineInput input;
    std::unique_ptr<console::Session> s;

    // `programs`: files under the source tree loaded as program memory.
    Console(const Console&) = delete;  // the session holds a reference to `input`
    explicit Console(const std::string& machine_name = "lathe",
                     std::vector<std::string> programs = {"data/demo/lathe_p300.iso"},
                     std::unique_ptr<store::Store> st = nullptr,
                     const std::function<void(console::Session&)>& before_load = {}) {
        builtin_machine(machine_name, machine);
        s = std::make_unique<console::Session>(machine, std::move(st), input);
        for (const auto& p : programs) {
            const std::optional<Diag> d =
                s->memory().load_file(std::string(PUPITRE_SOURCE_DIR) + "/" + p);
            EXPECT_FALSE(d) << d->detail;
        }
        if (before_load) before_load(*s);  // an exercise's attempt: before the store's values
        s->load_store();
    }
    // Types a line and Enter, as on the input line.
    void type(const std::string& line) {
        for (char c : line) key(std::string(1, c));
        key("\r");
    }
    // The keys a terminal sends for these bytes.
    void key(const std::string& bytes) {
        console::KeyDecoder dec;
        std::vector<console::Key> keys;
        dec.feed(bytes, keys);
        dec.flush(keys);
        for (const auto& k : keys) s->on_key(k);
    }
    void named(const std::string& name) {
        console::Key k;
        ASSERT_TRUE(console::parse_key_name(name, k)) << name;
        // The raw bytes matter only when no binding takes the key.
        s->on_key(k);
    }
    // Lets simulated time pass in frames of 1/30 s until the run settles.
    void run_until_settled(double max_seconds = 600) {
        for (double t = 0; t < max_seconds && s->busy(); t += 1.0 / 30) s->tick(1.0 / 30);
    }
    std::string screen(int w = 80, int h = 24) const {
        pages::Canvas c(w, h);
        pages::render_screen(s->view(), c);
        return c.to_text();
    }
    std::string message() const { return s->view().message; }
};

// The lathe homed, T1 D1 (gauges X 63.345 Z 38.237, the exam's) active as
// typed in IMD, then JOG: where a setter starts.
inline void setter_lathe(Console& c) {
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":set D1.X=63.345");
    c.type(":set D1.Z=38.237");
    c.type(":mode imd");
    c.type("T1 D1 M6");
    c.named("F9");
    c.run_until_settled();
    c.type(":mode jog");
}

}  // namespace pupitre::test
