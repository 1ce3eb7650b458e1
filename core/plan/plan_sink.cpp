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
#include "core/interp/held.hpp"

namespace pupitre::plan {

namespace {
constexpr double kTiny = 1e-12;
// On an arc the acceleration is shared between the tangent and the normal,
// as LinuxCNC does (tp.c: TP_ACC_RATIO_TANGENTIAL 0.5): half of it along the
// path, the rest (sqrt(3)/2, so that the two add up to it) towards the centre.
constexpr double kArcTangential = 0.5;
constexpr double kArcNormal = 0.8660254037844386;
// Events other than moves held behind a move: past this many in a row, the
// motion stops (a program that only talks for so long is not moving).
constexpr long kMaxOthers = 1000;

bool has_jerk(const MachineProfile& m) {
    for (int a = 0; a < kAxes; ++a)
        if (m.has(a) && m.axes[size_t(a)].jerk > 0) return true;
    return false;
}

// Hands an event to the next sink; a move not planned (one of no length)
// starts at `clock` and takes no time.
struct Deliver {
    MachineSink& to;
    double clock;
    void operator()(MoveEvent& e) const {
        if (e.plan_seconds < 0) e.plan_start = clock, e.plan_seconds = 0, e.plan_peak = 0;
        to.move(e);
    }
    template <class Ev>
    void operator()(Ev& e) const {
        held::Deliver{to}(e);
    }
};
}  // namespace

// The events waiting for the moves before them; the first is always a move
// not yet planned.
struct PlanSink::Queue {
    struct Entry {
        held::Event ev;
        bool pending = false;  // a move the planner holds
    };
    std::deque<Entry> q;
};

PlanSink::PlanSink(const MachineProfile& m, MachineSink* next)
    : m_(m),
      next_(next),
      planner_(*this, has_jerk(m)),
      queue_(std::make_unique<Queue>()),
      jerk_(has_jerk(m)),
      smoothing_(m.smoothing),
      period_(m.interpolation_period) {
    auto inv = [](double v) { return v > 0 ? 1 / v : 0; };
    for (size_t a = 0; a < kAxes; ++a) {
        if (!m.has(int(a))) continue;
        axes_[naxes_++] = a;
        const AxisConfig& ax = m.axes[a];
        inv_rapid_[a] = inv(ax.rapid / 60);
        inv_feed_[a] = inv(ax.feed_max() / 60);
        inv_accel_[a] = inv(ax.accel);
        inv_jerk_[a] = inv(ax.jerk);
    }
}

PlanSink::~PlanSink() = default;

// A line's or an arc's limits and corner, one axis at a time, in locals: the
// axis's share `c` of the path (|u|, or the plane's share on an arc) over
// its speed and acceleration; the direction `u` against the last move's `l`.
struct PlanSink::Binds {
    double v = 0, a = 0, cos = 0, turn = 0;
    void axis(double c, double u, double l, double inv_speed, double inv_accel) {
        v = std::max(v, c * inv_speed);
        a = std::max(a, c * inv_accel);
        cos += l * u;
        turn = std::max(turn, std::fabs(u - l) * inv_accel);
    }
    void into(Along& lim, Corner& k) const {
        lim.v = v, lim.a = a;
        k.cos = cos, k.turn = turn;
    }
};

// How much each limit binds a path whose axes travel `per` over it: the
// largest travel over an axis's own limit (0: none binds). The limit along the
// path is the path's length over it, so that a diagonal of two equal axes gets
// sqrt(2) times each (LinuxCNC). The axes' limits are kept as inverses (0: no
// limit), and no division is made per axis.
PlanSink::Along PlanSink::along(const Dir& per, const Dir& inv_speed) const {
    Along r;
    for (size_t k = 0; k < naxes_; ++k) {
        const size_t i = axes_[k];
        const double c = std::fabs(per[i]);
        r.v = std::max(r.v, c * inv_speed[i]);
        r.a = std::max(r.a, c * inv_accel_[i]);
        if (jerk_) r.j = std::max(r.j, c * inv_jerk_[i]);
    }
    return r;
}

// An arc: its direction at both ends, its limits and the corner with the
// last move's direction: each plane axis may take all of the plane's share of
// the path (the tangent turns), the other axes (a helix) their own; the speed
// is then held where the centre pulls at the arc's share of the acceleration
// (move()).
template <class Mv>
PlanSink::Bend PlanSink::arc(const Mv& e, Along& lim, Dir& in, Dir& out, Corner& k) const {
    const size_t a0 = size_t(e.plane_a0), a1 = size_t(e.plane_a1);
    const double sx = e.from_mach[a0] - e.mc0, sy = e.from_mach[a1] - e.mc1;
    const double ex = e.to_mach[a0] - e.mc0, ey = e.to_mach[a1] - e.mc1;
    const double rs = std::sqrt(sx * sx + sy * sy), re = std::sqrt(ex * ex + ey * ey);
    const double radius = (rs + re) / 2;
    const double arclen = std::fabs(e.msweep) * geometry::kDeg * radius;
    double h2 = 0;
    for (size_t j = 0; j < naxes_; ++j) {
        const size_t i = axes_[j];
        if (i == a0 || i == a1) continue;
        const double d = e.to_mach[i] - e.from_mach[i];
        h2 += d * d;
    }
    const double total = h2 > 0 ? std::sqrt(arclen * arclen + h2) : arclen;
    const bool round = rs > kTiny && re > kTiny && total > kTiny;
    const double inv_total = round ? 1 / total : 1 / e.length;
    // Per unit of path: the helix's axes go evenly, the plane's share turns
    // with the radius (counter-clockwise: the radius +90°).
    const double plane = round ? arclen * inv_total : 0;
    if (round) {
        const double turn = e.msweep >= 0 ? plane : -plane;
        const double ks = turn / rs, ke = turn / re;
        in[a0] = -ks * sy, in[a1] = ks * sx;
        out[a0] = -ke * ey, out[a1] = ke * ex;
    }
    const Dir& last = dir_[last_];
    Binds b;
    for (size_t j = 0; j < naxes_; ++j) {
        const size_t i = axes_[j];
        double p = plane;
        if (i != a0 && i != a1) {
            p = (e.to_mach[i] - e.from_mach[i]) * inv_total;
            in[i] = out[i] = p;
        } else if (!round) {
            in[i] = out[i] = 0;
        }
        b.axis(std::fabs(p), in[i], last[i], inv_feed_[i], inv_accel_[i]);
    }
    b.into(lim, k);
    if (jerk_) {
        for (size_t j = 0; j < naxes_; ++j) {
            const size_t i = axes_[j];
            const double p =
                i == a0 || i == a1 ? plane : (e.to_mach[i] - e.from_mach[i]) * inv_total;
            lim.j = std::max(lim.j, std::fabs(p) * inv_jerk_[i]);
        }
    }
    if (!round) return {};
    return {true, radius, plane};
}

namespace {
// A move's limits along its path, in locals until its segment is written
// once (the stores to the ring could otherwise touch them, for all the
// compiler knows).
struct PathLimits {
    double vmax = 1e9, inv_vmax = 1e-9, accel = 0, inv_accel = 0;
};
// From how much its axes bind a move (Along: v, a): the speed no more than
// the feed's (the length over the time at the feed), EG on the acceleration.
template <class Mv>
PathLimits limits(const Mv& e, double inv_len, double v, double a) {
    PathLimits r;
    // The longest of the times at the axes' limits, at the feed (a rapid
    // has none of its own), and E32000's.
    const double t = std::max({v * e.length, e.g != 0 ? e.seconds : 0, e.min_block});
    if (t > 0) {
        r.vmax = e.length / t;
        r.inv_vmax = t * inv_len;
    }
    if (a > 0) {
        r.inv_accel = e.eg == 100 ? a : a * 100 / e.eg;
        r.accel = 1 / r.inv_accel;
    }
    return r;
}
}  // namespace

// A line: its direction, its limits and the corner with the last move's
// direction in one pass over the axes (a move's steps are counted, issue 35
// item 7).
template <class Mv>
void PlanSink::line(const Mv& e, double inv_len, Along& lim, Dir& dir, Corner& k) const {
    const Dir& inv_speed = e.g == 0 ? inv_rapid_ : inv_feed_;
    const Dir& last = dir_[last_];
    // Kept in locals, which the stores to `dir` cannot touch.
    double n2 = 0;
    Binds b;
    for (size_t j = 0; j < naxes_; ++j) {
        const size_t i = axes_[j];
        const double d = e.to_mach[i] - e.from_mach[i];
        const double u = d * inv_len;  // per unit of path
        n2 += d * d;
        dir[i] = u;
        b.axis(std::fabs(u), u, last[i], inv_speed[i], inv_accel_[i]);
    }
    b.into(lim, k);
    if (jerk_) lim.j = along(dir, inv_speed).j;
    // The interpreter's length is the axes' travel unless rotary axes turn
    // with linear ones (then it is the linear part): then the direction is
    // scaled to a unit one.
    if (std::fabs(n2 * inv_len * inv_len - 1) > 1e-9) {
        const double unit = e.length / std::sqrt(n2);
        for (size_t j = 0; j < naxes_; ++j) dir[axes_[j]] *= unit;
        k = corner(last, dir);
    }
}

PlanSink::Corner PlanSink::corner(const Dir& last, const Dir& in) const {
    double cos = 0, turn = 0;
    for (size_t j = 0; j < naxes_; ++j) {
        const size_t i = axes_[j];
        cos += last[i] * in[i];
        turn = std::max(turn, std::fabs(in[i] - last[i]) * inv_accel_[i]);
    }
    return {cos, turn};
}

// The square of how fast the corner from the last move into the next may be
// passed: on the arc that leaves the corner by the smoothing tolerance, at
// the acceleration along the change of direction (grbl's junction
// deviation). 0 turning back, HUGE_VAL going straight on.
double PlanSink::junction_sq(const Corner& k, double eg) const {
    const double c = k.cos;
    if (c > 1 - 1e-9) return HUGE_VAL;
    if (c < -1 + 1e-9 || smoothing_ <= 0) return 0;
    if (k.turn <= 0) return HUGE_VAL;
    // acc·tolerance·s/(1 − s), acc = sqrt(2 − 2c)/turn (the change of
    // direction's length over it), s = sqrt((1 + c)/2) (the sine of half the
    // corner's angle); with sqrt(2 − 2c)·s = sqrt(1 − c²) and
    // 1/(1 − s) = 2(1 + s)/(1 − c): two square roots side by side and one
    // division, and no 1 − s that cancels near a straight line.
    const double sin_half = std::sqrt(0.5 * (1 + c));
    const double q = std::sqrt((1 - c) * (1 + c));
    return eg * 0.02 * smoothing_ * q * (1 + sin_half) / (k.turn * (1 - c));
}

[[gnu::flatten]] void PlanSink::move(const MoveEvent& e) {
    report_.feed_seconds += e.seconds;
    others_ = 0;
    if (e.length < 1e-9) {  // nothing to plan: it takes no time
        if (other()) pass(MoveEvent(e));
        return;
    }
    if (next_) queue_->q.push_back({e, true});
    plan(e);
}

[[gnu::flatten]] void PlanSink::moves(const PlanMove* first, const PlanMove* last) {
    for (const PlanMove* e = first; e < last; ++e) {
        report_.feed_seconds += e->seconds;
        others_ = 0;
        if (e->length < 1e-9) {  // nothing to plan; no next sink to hand it to
            other();
            continue;
        }
        plan(*e);
    }
}

template <class Mv>
void PlanSink::plan(const Mv& e) {
    // The ring full, its oldest move is planned here rather than through the
    // receiver's virtual call: inline, as every step of a move is.
    if (planner_.held() == Planner::kDepth) PlanSink::planned(planner_.plan_oldest());
    Segment& s = planner_.add();  // filled in place, every field add() names
    Dir& out = dir_[1 - last_];   // its direction at its end, the last one's next time
    Along lim;
    Corner k;
    Bend bend;
    const double inv_len = 1 / e.length;
    if (e.g == 2 || e.g == 3) {
        bend = arc(e, lim, entry_, out, k);
    } else {
        line(e, inv_len, lim, out, k);
    }
    PathLimits pl = limits(e, inv_len, lim.v, lim.a);
    if (bend.round && pl.accel > 0) {
        // The centre pulls at most sqrt(3)/2 of the plane's acceleration
        // (pl.accel is the path's: plane / share); half goes along.
        const double centre = kArcNormal * pl.accel * bend.plane;
        const double v = std::sqrt(centre * bend.radius) / std::max(bend.plane, kTiny);
        if (v < pl.vmax) {
            pl.vmax = v;
            pl.inv_vmax = 1 / v;
        }
        pl.accel *= kArcTangential;
        pl.inv_accel /= kArcTangential;
    }
    s.length = e.length;
    s.min_time = e.min_block;
    s.vmax = pl.vmax;
    s.inv_vmax = pl.inv_vmax;
    s.limits.accel = pl.accel;
    s.inv_accel = pl.inv_accel;
    s.limits.jerk = lim.j > 0 ? 1 / lim.j : 0;  // 0 when no axis has a jerk
    s.entry_max_sq = have_last_ ? junction_sq(k, e.eg) : 0;
    s.tool = tool_;
    s.cut = e.g != 0;
    planner_.push();
    last_ = 1 - last_;
    have_last_ = moved_ = true;
}

// A move that ends at rest ends on a tick of the trajectory generator, which
// computes a setpoint every period (004:338, "une consigne toutes les T
// secondes"): its time runs to the next tick, the clock counted from the
// run's start. Where the tick is within a millionth of a period, it is the
// tick: rounding does not cost a whole period.
void PlanSink::planned(const Segment& s) {
    const double start = report_.seconds;
    double seconds = s.timing.seconds;
    if (s.exit == 0 && period_ > 0) {
        const double end = start + seconds;
        const double tick = std::ceil(end / period_ - 1e-6) * period_;
        seconds += std::max(0.0, tick - end);
    }
    report_.seconds += seconds;
    report_.tools.add(s.tool, s.cut, s.length, seconds);
    if (next_) hand_on(s, start, seconds);
}

void PlanSink::hand_on(const Segment& s, double start, double seconds) {
    auto& q = queue_->q;
    MoveEvent& e = std::get<MoveEvent>(q.front().ev);
    e.plan_start = start;
    e.plan_seconds = seconds;
    e.plan_peak = s.timing.peak * 60;
    e.plan_entry = s.entry * 60;
    e.plan_exit = s.exit * 60;
    next_->move(e);
    q.pop_front();
    while (!q.empty() && !q.front().pending) {
        std::visit(Deliver{*next_, report_.seconds}, q.front().ev);
        q.pop_front();
    }
}

bool PlanSink::other() {
    if (planner_.held() && ++others_ > kMaxOthers) halt(false, Loc{});
    return next_ != nullptr;
}

template <class Ev>
void PlanSink::pass(Ev&& ev) {
    if (planner_.held() == 0) {
        held::Event now(std::forward<Ev>(ev));
        std::visit(Deliver{*next_, report_.seconds}, now);
    } else {
        queue_->q.push_back({held::Event(std::forward<Ev>(ev)), false});
    }
}

void PlanSink::halt(bool settle, const Loc& l) {
    planner_.stop();
    have_last_ = false;
    if (settle && moved_) rest(l, m_.in_position);
    moved_ = false;
}

// The axes wait at rest: counted, and told to the next sink (the console
// waits as long).
void PlanSink::rest(const Loc& l, double seconds) {
    if (seconds <= 0) return;
    report_.seconds += seconds;
    report_.waits += seconds;
    if (next_) pass(held::Wait{l, seconds});
}

void PlanSink::dwell(const Loc& l, double seconds) {
    halt(true, l);
    report_.seconds += seconds;
    report_.feed_seconds += seconds;
    if (other()) pass(held::Dwell{l, seconds});
}

void PlanSink::tool(const Loc& l, int t, int d, double seconds, bool m6) {
    if (m6) {
        halt(true, l);
        report_.seconds += seconds;
        report_.feed_seconds += seconds;
        tool_ = t;
        report_.tools.change();
    }
    if (other()) pass(held::Tool{l, t, d, seconds, m6});
}

// A start, a stop, a reversal or a new speed waits for the spindle; under
// G96 the speed follows the diameter as the tool moves, without a stop.
void PlanSink::spindle(const SpindleEvent& e) {
    const bool turns = e.dir != sp_dir_;
    double change = 0;
    if (turns || (!e.css && e.rpm != sp_rpm_)) {
        halt(true, e.loc);
        const bool reverses = (sp_dir_ == 3 && e.dir == 4) || (sp_dir_ == 4 && e.dir == 3);
        change = reverses ? sp_rpm_ + e.rpm : std::fabs(e.rpm - sp_rpm_);
    }
    sp_dir_ = e.dir;
    sp_rpm_ = e.rpm;
    if (other()) pass(SpindleEvent(e));
    if (m_.spindle_accel > 0) rest(e.loc, change / m_.spindle_accel);
}

void PlanSink::coolant(const Loc& l, bool m7, bool m8) {
    if (other()) pass(held::Coolant{l, m7, m8});
}

void PlanSink::stop(const Loc& l, int m) {
    halt(true, l);
    if (other()) pass(held::Stop{l, m});
}

void PlanSink::message(const Loc& l, int channel, std::string_view text) {
    if (other()) pass(held::Message{l, channel, std::string(text)});
}

void PlanSink::end(const Loc& l, int m) {
    halt(false, l);
    if (other()) pass(held::End{l, m});
}

void PlanSink::stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) {
    if (other()) pass(held::Stock{l, zr});
}

void PlanSink::profile(const Loc& l, const ProfileElem& e) {
    if (other()) pass(held::Profile{l, e});
}

void PlanSink::exact_stop(const Loc& l) {
    halt(true, l);
    if (other()) pass(held::ExactStop{l});
}

void PlanSink::finish() {
    halt(false, Loc{});
}

}  // namespace pupitre::plan
