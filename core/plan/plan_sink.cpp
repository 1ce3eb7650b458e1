// The planner as a sink (plan_sink.hpp): the machine's limits on each move,
// the exact stops, and the events handed on in order once planned.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/plan/plan_sink.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <variant>

#include "core/geometry/geometry.hpp"

namespace pupitre::plan {

namespace {
using Dir = std::array<double, kAxes>;
constexpr double kTiny = 1e-12;
// On an arc the acceleration is shared between the tangent and the normal,
// as LinuxCNC does (tp.c: TP_ACC_RATIO_TANGENTIAL 0.5): half of it along the
// path, the rest (sqrt(3)/2, so that the two add up to it) towards the centre.
constexpr double kArcTangential = 0.5;
constexpr double kArcNormal = 0.8660254037844386;
// Events other than moves held behind a move: past this many in a row, the
// motion stops (a program that only talks for so long is not moving).
constexpr long kMaxOthers = 1000;

// The largest rate along a path whose axes travel `per` per unit of path that
// keeps each axis within its own limit (0 there: none); HUGE_VAL when no axis
// limits it. A diagonal of two equal axes gets sqrt(2) times each (LinuxCNC).
double along(const Dir& per, const Dir& lim) {
    double best = HUGE_VAL;
    for (size_t a = 0; a < kAxes; ++a) {
        const double c = std::fabs(per[a]);
        if (c > kTiny && lim[a] > 0) best = std::min(best, lim[a] / c);
    }
    return best;
}
double zero_if_none(double v) {  // Limits: 0 is no limit
    return v == HUGE_VAL ? 0 : v;
}
void normalize(Dir& d) {
    double n = 0;
    for (double v : d) n += v * v;
    n = std::sqrt(n);
    if (n > kTiny)
        for (double& v : d) v /= n;
}
double dot(const Dir& a, const Dir& b) {
    double s = 0;
    for (size_t i = 0; i < kAxes; ++i) s += a[i] * b[i];
    return s;
}

// An arc's direction at both ends and how its path splits between the plane
// and the other axes (a helix), in the machine's axes.
struct ArcShape {
    Dir in{}, out{}, rest{};
    double radius = 0, plane = 1;  // plane: the share of the path in the plane
};
ArcShape arc_shape(const MoveEvent& e) {
    ArcShape s;
    const size_t a0 = size_t(e.plane_a0), a1 = size_t(e.plane_a1);
    const double sx = e.from_mach[a0] - e.mc0, sy = e.from_mach[a1] - e.mc1;
    const double ex = e.to_mach[a0] - e.mc0, ey = e.to_mach[a1] - e.mc1;
    const double rs = std::hypot(sx, sy), re = std::hypot(ex, ey);
    s.radius = (rs + re) / 2;
    const double arclen = std::fabs(e.msweep) * geometry::kDeg * s.radius;
    double h2 = 0;
    for (size_t a = 0; a < kAxes; ++a)
        if (a != a0 && a != a1) {
            s.rest[a] = e.to_mach[a] - e.from_mach[a];
            h2 += s.rest[a] * s.rest[a];
        }
    const double total = std::sqrt(arclen * arclen + h2);
    if (rs < kTiny || re < kTiny || total < kTiny) return s;
    s.plane = arclen / total;
    const double turn = e.msweep >= 0 ? 1 : -1;  // counter-clockwise: the radius turned +90°
    for (size_t a = 0; a < kAxes; ++a) s.in[a] = s.out[a] = s.rest[a] / total;
    s.in[a0] = -turn * sy / rs * s.plane, s.in[a1] = turn * sx / rs * s.plane;
    s.out[a0] = -turn * ey / re * s.plane, s.out[a1] = turn * ex / re * s.plane;
    for (double& r : s.rest) r /= total;
    return s;
}

// Held events, as their values.
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
using Event = std::variant<MoveEvent, SpindleEvent, Dwell, Tool, Coolant, Stop, Message, End, Stock,
                           Profile, ExactStop>;

// Hands an event to the next sink; a move not planned (one of no length)
// starts at `clock` and takes no time.
struct Deliver {
    MachineSink& to;
    double clock;
    void operator()(MoveEvent& e) const {
        if (e.plan_seconds < 0) e.plan_start = clock, e.plan_seconds = 0, e.plan_peak = 0;
        to.move(e);
    }
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
};
}  // namespace

// The events waiting for the moves before them; the first is always a move
// not yet planned.
struct PlanSink::Queue {
    struct Entry {
        Event ev;
        bool pending = false;  // a move the planner holds
    };
    std::deque<Entry> q;
};

PlanSink::PlanSink(const MachineProfile& m, MachineSink* next)
    : m_(m), next_(next), planner_(*this), queue_(std::make_unique<Queue>()) {
    for (size_t a = 0; a < kAxes; ++a) {
        if (!m.has(int(a))) continue;
        const AxisConfig& ax = m.axes[a];
        rapid_[a] = ax.rapid / 60;
        feed_[a] = ax.feed_max() / 60;
        accel_[a] = ax.accel;
        jerk_[a] = ax.jerk;
    }
}

PlanSink::~PlanSink() = default;

Segment PlanSink::segment(const MoveEvent& e, Dir& in, Dir& out) const {
    Segment s;
    s.length = e.length;
    s.min_time = e.min_block;
    const double eg = e.eg / 100;
    const double at_feed = e.g != 0 && e.seconds > 0 ? e.length / e.seconds : HUGE_VAL;
    if (e.g == 2 || e.g == 3) {
        const ArcShape a = arc_shape(e);
        in = a.in, out = a.out;
        Dir per = a.rest;  // per unit of path: each plane axis may take all of the plane's share
        per[size_t(e.plane_a0)] = per[size_t(e.plane_a1)] = a.plane;
        const double acc = along(per, accel_);
        s.vmax = std::min(along(per, feed_), at_feed);
        if (acc != HUGE_VAL) {
            s.vmax = std::min(s.vmax, std::sqrt(kArcNormal * acc * a.plane * eg * a.radius) /
                                          std::max(a.plane, kTiny));
            s.limits.accel = kArcTangential * acc * eg;
        }
        s.limits.jerk = zero_if_none(along(per, jerk_));
    } else {
        Dir per{};
        for (size_t a = 0; a < kAxes; ++a) {
            in[a] = e.to_mach[a] - e.from_mach[a];
            per[a] = in[a] / e.length;
        }
        normalize(in);
        out = in;
        s.vmax = std::min(along(per, e.g == 0 ? rapid_ : feed_), at_feed);
        s.limits.accel = zero_if_none(along(per, accel_)) * eg;
        s.limits.jerk = zero_if_none(along(per, jerk_));
    }
    if (s.vmax == HUGE_VAL) s.vmax = e.seconds > 0 ? e.length / e.seconds : 1e9;
    return s;
}

// How fast the corner from the last move into `in` may be passed: on the arc
// that leaves the corner by the smoothing tolerance, at the acceleration
// along the change of direction (grbl's junction deviation). 0 turning back,
// HUGE_VAL going straight on.
double PlanSink::junction(const Dir& in, double eg) const {
    const double c = dot(last_dir_, in);
    if (c > 1 - 1e-9) return HUGE_VAL;
    if (c < -1 + 1e-9 || m_.smoothing <= 0) return 0;
    Dir w;
    for (size_t a = 0; a < kAxes; ++a) w[a] = in[a] - last_dir_[a];
    normalize(w);
    const double acc = along(w, accel_);
    if (acc == HUGE_VAL) return HUGE_VAL;
    const double sin_half = std::sqrt(0.5 * (1 + c));  // half the corner's angle
    return std::sqrt(acc * eg / 100 * m_.smoothing * sin_half / (1 - sin_half));
}

void PlanSink::move(const MoveEvent& e) {
    report_.feed_seconds += e.seconds;
    others_ = 0;
    if (e.length < 1e-9) {  // nothing to plan: it takes no time
        if (other()) pass(MoveEvent(e));
        return;
    }
    Dir in, out;
    Segment s = segment(e, in, out);
    s.entry_max = have_last_ ? junction(in, e.eg) : 0;
    s.tool = tool_;
    s.cut = e.g != 0;
    if (next_) queue_->q.push_back({e, true});
    planner_.push(s);
    last_dir_ = out;
    have_last_ = moved_ = true;
}

void PlanSink::planned(const Segment& s) {
    const double start = report_.seconds;
    report_.seconds += s.timing.seconds;
    report_.tools.add(s.tool, s.cut, s.length, s.timing.seconds);
    if (!next_) return;
    auto& q = queue_->q;
    MoveEvent& e = std::get<MoveEvent>(q.front().ev);
    e.plan_start = start;
    e.plan_seconds = s.timing.seconds;
    e.plan_peak = s.timing.peak * 60;
    next_->move(e);
    q.pop_front();
    while (!q.empty() && !q.front().pending) {
        std::visit(Deliver{*next_, report_.seconds}, q.front().ev);
        q.pop_front();
    }
}

bool PlanSink::other() {
    if (planner_.held() && ++others_ > kMaxOthers) halt(false);
    return next_ != nullptr;
}

template <class Ev>
void PlanSink::pass(Ev&& ev) {
    if (planner_.held() == 0) {
        Event now(std::forward<Ev>(ev));
        std::visit(Deliver{*next_, report_.seconds}, now);
    } else {
        queue_->q.push_back({Event(std::forward<Ev>(ev)), false});
    }
}

void PlanSink::halt(bool settle) {
    planner_.stop();
    have_last_ = false;
    if (settle && moved_) wait(m_.in_position);
    moved_ = false;
}

void PlanSink::wait(double seconds) {
    report_.seconds += seconds;
    report_.waits += seconds;
}

void PlanSink::dwell(const Loc& l, double seconds) {
    halt(true);
    report_.seconds += seconds;
    report_.feed_seconds += seconds;
    if (other()) pass(Dwell{l, seconds});
}

void PlanSink::tool(const Loc& l, int t, int d, double seconds, bool m6) {
    if (m6) {
        halt(true);
        report_.seconds += seconds;
        report_.feed_seconds += seconds;
        tool_ = t;
        report_.tools.change();
    }
    if (other()) pass(Tool{l, t, d, seconds, m6});
}

// A start, a stop, a reversal or a new speed waits for the spindle; under
// G96 the speed follows the diameter as the tool moves, without a stop.
void PlanSink::spindle(const SpindleEvent& e) {
    const bool turns = e.dir != sp_dir_;
    if (turns || (!e.css && e.rpm != sp_rpm_)) {
        halt(true);
        const bool reverses = (sp_dir_ == 3 && e.dir == 4) || (sp_dir_ == 4 && e.dir == 3);
        const double change = reverses ? sp_rpm_ + e.rpm : std::fabs(e.rpm - sp_rpm_);
        if (m_.spindle_accel > 0) wait(change / m_.spindle_accel);
    }
    sp_dir_ = e.dir;
    sp_rpm_ = e.rpm;
    if (other()) pass(SpindleEvent(e));
}

void PlanSink::coolant(const Loc& l, bool m7, bool m8) {
    if (other()) pass(Coolant{l, m7, m8});
}

void PlanSink::stop(const Loc& l, int m) {
    halt(true);
    if (other()) pass(Stop{l, m});
}

void PlanSink::message(const Loc& l, int channel, std::string_view text) {
    if (other()) pass(Message{l, channel, std::string(text)});
}

void PlanSink::end(const Loc& l, int m) {
    halt(false);
    if (other()) pass(End{l, m});
}

void PlanSink::stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) {
    if (other()) pass(Stock{l, zr});
}

void PlanSink::profile(const Loc& l, const ProfileElem& e) {
    if (other()) pass(Profile{l, e});
}

void PlanSink::exact_stop(const Loc& l) {
    halt(true);
    if (other()) pass(ExactStop{l});
}

void PlanSink::finish() {
    halt(false);
}

}  // namespace pupitre::plan
