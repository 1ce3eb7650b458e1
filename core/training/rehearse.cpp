// An exercise rehearsed (see exercise.hpp): what a student who finds every
// value would get, so that `pupitre exercise check` proves an exercise can be
// passed before a class meets it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/i18n.hpp"
#include "core/interp/interp.hpp"
#include "core/interp/value_name.hpp"
#include "core/training/exercise.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::training {

namespace {

struct Quiet final : MachineSink {};

// The values a perfect student leaves on the machine.
std::string set_right(const Exercise& e, const workshop::Setup& truth, Interpreter& in) {
    auto set = [&in](const std::string& name, double v) { return in.set(name, v); };
    std::string why;
    const bool lathe = truth.kind == "lathe";
    for (const workshop::ToolTruth& t : truth.tools) {
        auto d = [&](std::string_view field) {
            return format_value_name(ValueName::corrector(t.position, corr_field(field, lathe)));
        };
        if (lathe) {
            why += set(d("X"), t.x) + set(d("Z"), t.z) + set(d("R"), t.radius);
            why += set(d("C"), t.orientation);
        } else {
            why += set(d("L"), t.length) + set(d("R"), t.radius);
        }
    }
    for (const Start& s : e.start)
        if (double v = 0; start_value(e, truth, s.name, v)) why += set(s.name, v);
    for (int origin : {0, 1})  // PREF, DEC1
        for (int axis : {X, Y, Z}) {
            const std::string name = format_value_name(ValueName::origin(origin, axis));
            if (double v = 0; expected(e, truth, name, v)) why += set(name, v);
        }
    for (const Target& t : e.find)
        if (double v = 0; expected(e, truth, t.name, v)) why += set(t.name, v);
    return why;
}

}  // namespace

std::string rehearse(const Exercise& e, const workshop::Setup& truth) {
    MachineProfile m;
    if (!builtin_machine(e.machine, m)) return strf(tr("no machine %s"), e.machine.c_str());
    ProgramMemory mem;
    Quiet quiet;
    workshop::Workshop shop(m, truth, &quiet);
    if (!e.program.empty()) {
        if (std::optional<Diag> d = mem.load_text("exercise", e.program)) return d->detail;
    }
    Interpreter in(m, mem, shop);
    if (std::string why = set_right(e, truth, in); !why.empty()) return why;
    in.apply_gauges_now();
    if (const ProgramText* p = mem.find(e.program_number); p && !e.program.empty()) {
        in.start(p);
        for (StepResult r = StepResult::running;
             !shop.crashed() && (r == StepResult::running || r == StepResult::stopped);)
            r = in.step();
        if (shop.crashed()) return shop.crashes().back().what;
        if (in.has_errors())
            return strf(tr("the program stops with error %d at line %d"), in.diags().front().code,
                        in.diags().front().line);
    }
    std::string out;
    for (const Dimension& d : e.dimensions) {
        workshop::Reading r;
        if (std::string why = shop.measure(d.spec, r); !why.empty()) {
            out += strf(tr("line %d: dimension %s: %s\n"), d.line, d.spec.c_str(), why.c_str());
            continue;
        }
        if (r.value < d.nominal + d.lower - 1e-9 || r.value > d.nominal + d.upper + 1e-9)
            out +=
                strf(tr("line %d: dimension %s: the part reads %.3f, outside %.3f %+.3f %+.3f\n"),
                     d.line, d.spec.c_str(), r.value, d.nominal, d.lower, d.upper);
    }
    return out;
}

}  // namespace pupitre::training
