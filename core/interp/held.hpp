// The machine's events held as values, not as closures: the events the
// interpreter's gate holds while a compensated move waits for its next
// element (gate.hpp), and the planner's queue of events waiting for the
// moves before them (core/plan). Deliver hands one to a sink.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <string>
#include <variant>
#include <vector>

#include "core/interp/sink.hpp"

namespace pupitre::held {

struct Dwell {
    Loc l;
    double s;
};
struct Tool {
    Loc l;
    int t, d;
    double s;
    bool m6;
};
struct Coolant {
    Loc l;
    bool m7, m8;
};
struct Stop {
    Loc l;
    int m;
};
struct Message {
    Loc l;
    int ch;
    std::string text;
};
struct End {
    Loc l;
    int m;
};
struct Stock {
    Loc l;
    std::vector<std::array<double, 2>> zr;
};
struct Profile {
    Loc l;
    ProfileElem e;
};
struct ExactStop {
    Loc l;
};
struct Wait {
    Loc l;
    double s;
};
using Event = std::variant<MoveEvent, SpindleEvent, Dwell, Tool, Coolant, Stop, Message, End, Stock,
                           Profile, ExactStop, Wait>;

struct Deliver {
    MachineSink& to;
    void operator()(MoveEvent& e) const { to.move(e); }
    void operator()(SpindleEvent& e) const { to.spindle(e); }
    void operator()(Dwell& e) const { to.dwell(e.l, e.s); }
    void operator()(Tool& e) const { to.tool(e.l, e.t, e.d, e.s, e.m6); }
    void operator()(Coolant& e) const { to.coolant(e.l, e.m7, e.m8); }
    void operator()(Stop& e) const { to.stop(e.l, e.m); }
    void operator()(Message& e) const { to.message(e.l, e.ch, e.text); }
    void operator()(End& e) const { to.end(e.l, e.m); }
    void operator()(Stock& e) const { to.stock(e.l, e.zr); }
    void operator()(Profile& e) const { to.profile(e.l, e.e); }
    void operator()(ExactStop& e) const { to.exact_stop(e.l); }
    void operator()(Wait& e) const { to.wait(e.l, e.s); }
};

}  // namespace pupitre::held
