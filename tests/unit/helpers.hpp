// Test helpers: run program text on a machine and capture the events.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/comp.hpp"
#include "core/interp/interp.hpp"

namespace pupitre::test {

// The test oracles' point-in-polygon (even-odd rule), independent of the
// product's geometry.
inline bool in_polygon(const std::vector<comp::V2>& poly, comp::V2 q) {
    bool c = false;
    for (size_t i = 0, n = poly.size(); i < n; ++i) {
        comp::V2 a = poly[i], b = poly[(i + 1) % n];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()) > q.x())
            c = !c;
    }
    return c;
}

struct Capture final : MachineSink {
    std::vector<MoveEvent> moves;
    std::vector<SpindleEvent> spindles;
    std::vector<std::pair<int, int>> tools;
    std::vector<int> stops;
    std::vector<std::string> messages;
    int ends = 0;
    void move(const MoveEvent& e) override { moves.push_back(e); }
    void spindle(const SpindleEvent& e) override { spindles.push_back(e); }
    void tool(const Loc&, int t, int d, double, bool) override { tools.push_back({t, d}); }
    void stop(const Loc&, int m) override { stops.push_back(m); }
    void message(const Loc&, int, std::string_view t) override { messages.emplace_back(t); }
    void end(const Loc&, int) override { ++ends; }
};

struct Prog {
    MachineProfile machine;
    ProgramMemory mem;
    Capture cap;
    std::unique_ptr<Interpreter> in;

    explicit Prog(const std::string& text, const std::string& machine_name = "mill",
                  std::vector<std::pair<std::string, double>> sets = {}, RunOptions o = {}) {
        // "lathe-manual": the shipped lathe without automatic spindle ranges.
        builtin_machine(machine_name == "lathe-manual" ? "lathe" : machine_name, machine);
        if (machine_name == "lathe-manual") machine.auto_range = false;
        mem.load_text("test.iso", text);
        in = std::make_unique<Interpreter>(machine, mem, cap, o);
        for (auto& [k, v] : sets) in->set(k, v);
        in->start(mem.first());
        in->run_to_end();
    }
    // First error code, 0 if none.
    int error() const {
        for (const Diag& d : in->diags())
            if (d.is_error()) return d.code;
        return 0;
    }
    double L(int n) const { return in->lvars().v[size_t(n)]; }
};

}  // namespace pupitre::test
