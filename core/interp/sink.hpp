// The machine boundary: where the interpreter reports what the machine does
// (moves, dwells, tools, the spindle, stops, messages), and the events it
// reports them with. A sink (the trace, the toolpath, the simulated machine,
// the workshop) compiles against this header alone, not the interpreter.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <string_view>
#include <vector>

#include "core/interp/machine.hpp"

namespace pupitre {

struct Loc {
    int prog = 0;  // %number
    int line = 0;
    long n = -1;  // N of the block, -1 if none
};

struct MoveEvent {
    Loc loc;
    int g = 1;  // 0, 1, 2, 3
    bool g52 = false;
    Axes from_mach{}, to_mach{};     // machine positions of the reference (internal units)
    Axes to_prog{};                  // program point reached (internal units)
    int plane_a0 = X, plane_a1 = Y;  // arc plane axes (first, second)
    double c0 = 0, c1 = 0;           // arc centre, program coordinates (internal units)
    double sweep = 0;                // degrees, negative for G2
    double mc0 = 0, mc1 = 0;         // arc centre, machine coordinates (internal units)
    double msweep = 0;               // the sweep as the machine turns (a mirror reverses it)
    double length = 0;               // mm (degrees for a rotary-only move)
    double feed = 0;                 // mm/min actually used, at the start
    double rpm = 0;                  // spindle speed at the start
    double seconds = 0;              // duration
    bool x_diameter = false;         // lathe X shown as a diameter
    bool comp = false;               // a piece of the radius-compensated tool path
    // A piece after the first of a move drawn on the part (a C turn, a B
    // tilt: Workshop::on_part): part of that move, not one of its own.
    bool piece = false;
    // What the planner needs (core/plan): the acceleration in % (EG, 004:1199)
    // and the shortest time of an interpolated block (s, E32000, 004:1265).
    double eg = 100;
    double min_block = 0;
    // What the planner made of the move, when one planned it (core/plan,
    // PlanSink): its start on the run's clock, its duration with the
    // machine's accelerations (s), its highest speed and its speeds at its
    // start and end (mm/min); -1 before.
    double plan_start = -1, plan_seconds = -1, plan_peak = -1;
    double plan_entry = 0, plan_exit = 0;
};

struct SpindleEvent {
    Loc loc;
    double rpm = 0;
    int dir = 5;  // 3 cw, 4 ccw, 5 stopped, 19 indexed
    bool css = false;
    double vc = 0;   // m/min under G96
    int range = -1;  // 40..45, -1 for none
};

// A programmed element in the plane of radius compensation (axes a0, a1):
// program frame, internal units (lathe X a radius); sweep in degrees, + for G3.
struct ProfileElem {
    int a0 = X, a1 = Y;
    double from[2] = {0, 0}, to[2] = {0, 0}, c[2] = {0, 0};
    double sweep = 0;
    bool arc = false;
};

class MachineSink {
  public:
    virtual ~MachineSink() = default;
    virtual void move(const MoveEvent&) {}
    virtual void dwell(const Loc&, double /*seconds*/) {}
    virtual void tool(const Loc&, int /*t*/, int /*d*/, double /*seconds*/, bool /*m6*/) {}
    virtual void spindle(const SpindleEvent&) {}
    virtual void coolant(const Loc&, bool /*m7*/, bool /*m8*/) {}
    virtual void stop(const Loc&, int /*m: 0, 1, 12*/) {}
    virtual void message(const Loc&, int /*channel*/, std::string_view) {}
    virtual void end(const Loc&, int /*m: 2, or 0 at the end of a fragment*/) {}
    // The motion stops exactly here, between the moves before and those after
    // (G09 at the end of its block, 000:10566; an E parameter read or written,
    // 000:7596; a change of plane; a canned cycle's pass): the planner
    // (core/plan) ends its look-ahead at rest.
    virtual void exact_stop(const Loc&) {}
    // The machine waits, its axes at rest: an exact stop settling, the spindle
    // reaching its speed. A planner's (core/plan) to the sink after it, so
    // that the moves' start, entry, peak and exit and these waits make the
    // whole timeline (the trace writes the moves' alone).
    virtual void wait(const Loc&, double /*seconds*/) {}
    // The rough stock of a G64 cycle, (Z, X as a radius) program points, for the
    // graphic test's stock outline.
    virtual void stock(const Loc&, const std::vector<std::array<double, 2>>& /*zr*/) {}
    // An element of the programmed profile while G41/G42 is on, before it is
    // offset: the moves then follow the tool centre, and a drawing shows both.
    virtual void profile(const Loc&, const ProfileElem&) {}
};

// Hands every event to two sinks, in order: `plot` draws the moves as the
// interpreter makes them while a planner (core/plan) times them.
class TeeSink final : public MachineSink {
  public:
    TeeSink(MachineSink& a, MachineSink& b) : a_(a), b_(b) {}
    void move(const MoveEvent& e) override { a_.move(e), b_.move(e); }
    void dwell(const Loc& l, double s) override { a_.dwell(l, s), b_.dwell(l, s); }
    void tool(const Loc& l, int t, int d, double s, bool m6) override {
        a_.tool(l, t, d, s, m6), b_.tool(l, t, d, s, m6);
    }
    void spindle(const SpindleEvent& e) override { a_.spindle(e), b_.spindle(e); }
    void coolant(const Loc& l, bool m7, bool m8) override {
        a_.coolant(l, m7, m8), b_.coolant(l, m7, m8);
    }
    void stop(const Loc& l, int m) override { a_.stop(l, m), b_.stop(l, m); }
    void message(const Loc& l, int c, std::string_view t) override {
        a_.message(l, c, t), b_.message(l, c, t);
    }
    void end(const Loc& l, int m) override { a_.end(l, m), b_.end(l, m); }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) override {
        a_.stock(l, zr), b_.stock(l, zr);
    }
    void profile(const Loc& l, const ProfileElem& p) override {
        a_.profile(l, p), b_.profile(l, p);
    }
    void exact_stop(const Loc& l) override { a_.exact_stop(l), b_.exact_stop(l); }
    void wait(const Loc& l, double s) override { a_.wait(l, s), b_.wait(l, s); }

  private:
    MachineSink& a_;
    MachineSink& b_;
};

}  // namespace pupitre
