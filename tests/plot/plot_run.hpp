// Test helper: a program run to its end with a Toolpath as the sink, as
// `pupitre plot` does it (console/cli_plot.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/interp/interp.hpp"
#include "core/output/toolpath.hpp"

namespace pupitre::test {

struct PlotRun {
    MachineProfile machine;
    ProgramMemory mem;
    std::unique_ptr<Toolpath> path;
    std::unique_ptr<Interpreter> in;
    std::string load_error;

    // `files`: paths; the first program of the first file runs.
    PlotRun(const std::string& machine_name, const std::vector<std::string>& files,
            const std::vector<std::pair<std::string, double>>& sets = {}) {
        builtin_machine(machine_name, machine);
        for (const auto& f : files) {
            if (std::optional<Diag> d = mem.load_file(f)) load_error = f + ": " + d->detail;
        }
        path = std::make_unique<Toolpath>(machine);
        in = std::make_unique<Interpreter>(machine, mem, *path);
        for (const auto& [k, v] : sets) in->set(k, v);
        const ProgramText* main = mem.first();
        if (!main) return;
        path->start_at(in->program_pos());
        path->program = main->number;
        path->title = main->title;
        in->start(main);
        in->run_to_end();
        for (const Diag& d : in->diags()) path->add_error(d);
    }
};

// `text` written to a file of its own (CTest runs the tests of one binary in
// parallel processes), then run as above; `prefix` names the test binary.
inline PlotRun run_text(const std::string& prefix, const std::string& machine,
                        const std::string& text,
                        const std::vector<std::pair<std::string, double>>& sets = {}) {
    std::string path = ::testing::TempDir() + "/" + prefix + "_" +
                       ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                       std::to_string(::getpid()) + ".iso";
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    return PlotRun(machine, {path}, sets);
}

}  // namespace pupitre::test
