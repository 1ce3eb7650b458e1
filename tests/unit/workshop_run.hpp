// Test helper: a program run in the workshop of a shipped setup, changed by
// extra setup lines, with the operator's values; its readings and crash.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/interp/interp.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::test {

using Sets = std::vector<std::pair<std::string, double>>;

struct ShopRun {
    MachineProfile machine;
    ProgramMemory mem;
    workshop::Setup setup;
    std::unique_ptr<workshop::Workshop> shop;
    std::unique_ptr<Interpreter> in;
    std::string setup_error;  // of the shipped setup with `extra`

    // `kind`: lathe or mill, the machine profile and the shipped setup.
    ShopRun(const std::string& kind, const std::string& program, const Sets& sets,
            const std::string& extra) {
        builtin_machine(kind, machine);
        EXPECT_TRUE(workshop::builtin_setup(kind, setup));
        if (!extra.empty()) setup_error = workshop::parse_setup(setup.source + "\n" + extra, setup);
        shop = std::make_unique<workshop::Workshop>(machine, setup, nullptr);
        mem.load_text("test.iso", program);
        in = std::make_unique<Interpreter>(machine, mem, *shop, RunOptions{});
        for (auto& [k, v] : sets) in->set(k, v);
        in->start(mem.first());
        for (StepResult r = StepResult::running;
             !shop->crashed() && (r == StepResult::running || r == StepResult::stopped);)
            r = in->step();
    }
    double read(const std::string& spec) {
        workshop::Reading r;
        EXPECT_EQ(shop->measure(spec, r), "") << spec;
        return r.value;
    }
    std::string refused(const std::string& spec) {
        workshop::Reading r;
        return shop->measure(spec, r);
    }
    int crash() const { return shop->crashed() ? shop->crashes().front().code : 0; }
};

}  // namespace pupitre::test
