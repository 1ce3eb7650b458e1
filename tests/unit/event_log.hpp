// A sink that writes down every event with every field (doubles exactly, as
// %a) and a run's end state, so that two runs of a program compare as two
// strings: the differential tests of the plain blocks' lane (unit and fuzz).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/interp/interp.hpp"

namespace pupitre::test {

struct EventLog final : MachineSink {
    std::string out;

    void num(double v) {
        char b[48];
        std::snprintf(b, sizeof b, " %a", v);
        out += b;
    }
    void i(long v) {
        out += ' ';
        out += std::to_string(v);
    }
    void loc(const Loc& l) {
        i(l.prog);
        i(l.line);
        i(l.n);
    }
    void axes(const Axes& a) {
        for (double v : a) num(v);
    }
    void move(const MoveEvent& e) override {
        out += "\nmove";
        loc(e.loc);
        i(e.g);
        i(e.g52);
        axes(e.from_mach);
        axes(e.to_mach);
        axes(e.to_prog);
        i(e.plane_a0);
        i(e.plane_a1);
        for (double v : {e.c0, e.c1, e.sweep, e.length, e.feed, e.rpm, e.seconds}) num(v);
        i(e.x_diameter);
        i(e.comp);
    }
    void dwell(const Loc& l, double s) override {
        out += "\ndwell";
        loc(l);
        num(s);
    }
    void tool(const Loc& l, int t, int d, double s, bool m6) override {
        out += "\ntool";
        loc(l);
        i(t);
        i(d);
        num(s);
        i(m6);
    }
    void spindle(const SpindleEvent& e) override {
        out += "\nspindle";
        loc(e.loc);
        num(e.rpm);
        i(e.dir);
        i(e.css);
        num(e.vc);
        i(e.range);
    }
    void coolant(const Loc& l, bool m7, bool m8) override {
        out += "\ncoolant";
        loc(l);
        i(m7);
        i(m8);
    }
    void stop(const Loc& l, int m) override {
        out += "\nstop";
        loc(l);
        i(m);
    }
    void message(const Loc& l, int ch, std::string_view t) override {
        out += "\nmessage";
        loc(l);
        i(ch);
        out += ' ';
        out += t;
    }
    void end(const Loc& l, int m) override {
        out += "\nend";
        loc(l);
        i(m);
    }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& s) override {
        out += "\nstock";
        loc(l);
        for (const auto& p : s) num(p[0]), num(p[1]);
    }
    void profile(const Loc& l, const ProfileElem& e) override {
        out += "\nprofile";
        loc(l);
        i(e.a0);
        i(e.a1);
        for (double v : {e.from[0], e.from[1], e.to[0], e.to[1], e.c[0], e.c[1], e.sweep}) num(v);
        i(e.arc);
    }

    // What the run leaves: its diagnostics, the modal state, the positions
    // and the counters.
    void state(const Interpreter& in) {
        for (const Diag& d : in.diags()) {
            out += "\ndiag";
            i(long(d.severity));
            i(d.code);
            out += ' ' + d.file;
            i(d.program);
            i(d.line);
            i(d.n);
            i(d.column);
            out += ' ' + d.detail;
        }
        const Modal& m = in.modal();
        out += "\nmodal";
        for (long v : {long(m.motion), long(m.incremental), long(m.plane), long(m.radcomp),
                       long(m.feed_mode), long(m.feed_set), long(m.spindle_mode), long(m.css_known),
                       long(m.spindle_dir), long(m.d), long(m.t)})
            i(v);
        for (double v : {m.feed, m.s, m.css_x0, m.css_pos0}) num(v);
        out += "\nend state";
        axes(in.program_pos());
        axes(in.machine_pos());
        i(in.blocks());
        i(in.moves());
        num(in.path_length());
        num(in.seconds());
        num(in.spindle_rpm());
        i(in.comp_active());
    }
};

// Runs program text on a machine, settings first, with the plain lane on or
// off: everything the run reported and the state it ended in. `plain`, when
// given, receives the number of blocks the lane took.
inline std::string run_log(const MachineProfile& m, const std::string& text,
                           const std::vector<std::pair<std::string, double>>& sets, bool fast,
                           long max_blocks = 20000, long* plain = nullptr) {
    ProgramMemory mem;
    if (std::optional<Diag> d = mem.load_text("diff.iso", text))
        return "load " + std::to_string(d->code);
    EventLog log;
    RunOptions o;
    o.max_blocks = max_blocks;
    o.fast_lane = fast;
    Interpreter in(m, mem, log, o);
    for (const auto& [k, v] : sets) in.set(k, v);
    in.start(mem.first());
    in.run_to_end();
    log.state(in);
    if (plain) *plain = in.plain_blocks();
    return log.out;
}

}  // namespace pupitre::test
