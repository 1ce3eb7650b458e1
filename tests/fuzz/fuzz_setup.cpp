// libFuzzer target: setup text -> parse_setup, then the lathe's world built
// from it (stock, chuck, tailstock), every tool's true shape, a Workshop and
// the instruments' readings; a machining centre's: its Workshop, a jog, a
// plunge and a pass of each tool, the instruments, then the same under
// mill5's tilted head. Any crash, sanitizer report, hang or runaway
// allocation is a bug: a bad setup must end in "line N: ..." (pupitre-setup(5)).
// A text that reads as an exercise (pupitre-exercise(5)) is drawn, its
// targets worked out, graded with nothing entered and reported.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/interp/interp.hpp"
#include "core/training/exercise.hpp"
#include "core/training/grade.hpp"
#include "core/workshop/lathe_part.hpp"
#include "core/workshop/setup.hpp"
#include "core/workshop/workshop.hpp"

using namespace pupitre;
using namespace pupitre::workshop;

namespace {

MoveEvent move(const Axes& from, double dx, double dy, double dz, int g) {
    MoveEvent e;
    e.g = g;
    e.from_mach = from;
    e.to_mach = from;
    e.to_mach[X] += dx, e.to_mach[Y] += dy, e.to_mach[Z] += dz;
    e.to_prog = e.to_mach;
    return e;
}

// The block under mill5's head (the setup's head.pivot): the first tool
// swung to B30 above it, jogged down, a pass, a C turn, the instruments and
// the part's text read back (a tilted cutter's strokes).
int mill_tilted(const Setup& given) {
    static MachineProfile five;
    static bool init = builtin_machine("mill5", five);
    (void)init;
    // A tilted cutter's contacts read every column under it: cells coarse
    // enough for at most 250,000 of them.
    Setup s = given;
    MillSetup& m = s.mill;
    m.cell = std::max(m.cell, std::sqrt(m.length * m.width / 2.5e5));
    if (s.tools.empty()) return 0;
    Workshop w(five, s, nullptr);
    SpindleEvent on;
    on.dir = 3;
    on.rpm = 1000;
    w.spindle(on);
    const ToolTruth& t = s.tools.front();
    w.tool(Loc{}, t.position, t.position, 0, true);
    Axes at{};
    at[X] = m.stock_x + m.length / 2 + 0.5 * (m.pivot + t.length);
    at[Y] = m.stock_y + m.width / 2;
    at[Z] = m.stock_z + m.height + 20 + t.length;
    MoveEvent tilt = move(at, 0, 0, 0, 0);
    tilt.to_mach[B] = 30;
    (void)w.apply(tilt);
    at[B] = 30;
    Outcome o = w.jog(move(at, 0, 0, -40, 1), true);
    at = o.touched ? o.stop : at;
    (void)w.apply(move(at, m.length / 4, m.width / 3, -2, 1));
    MoveEvent turn = move(at, 0, 0, 0, 1);
    turn.to_mach[C] = 5;
    (void)w.jog(turn, true);
    w.clear_crash();
    Reading r;
    (void)w.measure("depth X1 Y1", r);
    (void)w.measure("width X X10 Y10 Z-1", r);
    (void)w.load_part(w.part_text());
    return 0;
}

int mill(const Setup& s) {
    static MachineProfile mill_m;
    static bool init = builtin_machine("mill", mill_m);
    (void)init;
    const MillSetup& m = s.mill;
    // A height field of more than a million cells is legal (pupitre-setup(5)
    // caps it at 25,000,000) but too slow for a fuzzing run.
    if (m.length / m.cell * m.width / m.cell > 1e6) return 0;
    Workshop w(mill_m, s, nullptr);
    SpindleEvent on;
    on.dir = 3;
    on.rpm = 1000;
    w.spindle(on);
    for (const ToolTruth& t : s.tools) {
        w.tool(Loc{}, t.position, t.position, 0, true);
        // Over the block's centre, 5 above its top, the tip's height: down.
        Axes at{};
        at[X] = m.stock_x + m.length / 2, at[Y] = m.stock_y + m.width / 2;
        at[Z] = m.stock_z + m.height + 5 + t.length;
        Outcome o = w.jog(move(at, 0, 0, -20, 1), true);
        at = o.touched ? o.stop : at;
        (void)w.jog(move(at, 0, 0, -1, 1), false);
        (void)w.apply(move(at, m.length / 3, m.width / 5, -2, 1));
        w.clear_crash();
    }
    static constexpr std::string_view kSpecs[] = {"depth X1 Y1",          "height X10 Y10",
                                                  "width X X10 Y10 Z-1",  "length Y X5 Z-0.5",
                                                  "width Y X1e300 Y0 Z0", "tool T1 L"};
    for (std::string_view spec : kSpecs) {
        Reading r;
        (void)w.measure(spec, r);
    }
    const std::string text = w.part_text();
    (void)w.load_part(text);
    return mill_tilted(s);
}

// An exercise: its truth drawn with two seeds, what must be found, a grade
// of nothing entered (no part: every dimension unread) and its report. Not
// rehearsed: that runs the exercise's program, the interpreter's own target.
int exercise(std::string_view text) {
    training::Exercise e;
    if (!training::parse_exercise(text, e).empty()) return 0;
    for (uint64_t seed : {uint64_t(1), uint64_t(0xfeedfacecafebeef)}) {
        Setup truth;
        if (!training::draw_setup(e, seed, truth).empty()) return 0;
        if (truth.kind == "mill" &&
            truth.mill.length / truth.mill.cell * truth.mill.width / truth.mill.cell > 1e6)
            return 0;
        training::Values found;
        for (const training::Target& t : e.find) {
            double v = 0;
            std::string how;
            if (training::expected(e, truth, t.name, v, &how)) found[t.name] = -v;
        }
        training::Context ctx;
        ctx.diameters = e.diameters;
        ctx.shims = e.shims;
        const training::Grade g = training::grade(e, truth, found, ctx, nullptr, 1, 60);
        (void)training::report_lines(e, g);
    }
    return 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16 * 1024) return 0;
    static MachineProfile lathe;
    static bool init = builtin_machine("lathe", lathe);
    (void)init;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    if (text.find("find") != std::string_view::npos ||
        text.find("dimension") != std::string_view::npos)
        return exercise(text);
    Setup s;
    if (!parse_setup(text, s).empty()) return 0;
    if (s.kind == "mill") return mill(s);
    for (const ToolTruth& t : s.tools) {
        ToolShape shape = tool_shape(t);
        (void)shape;
    }
    LatheWorld world(s.lathe);
    world.new_part();
    Workshop w(lathe, s, nullptr);
    static constexpr std::string_view kSpecs[] = {
        "dia Z-10", "dia Z0", "bore Z-5", "groove Z-5", "length", "dia Z-1e300", "bore Z-0.0001"};
    for (std::string_view spec : kSpecs) {
        Reading r;
        (void)w.measure(spec, r);
    }
    return 0;
}
