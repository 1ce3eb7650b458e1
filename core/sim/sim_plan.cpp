// The Sim's planned run (issue 35): the program's events go through the
// planner (core/plan) before they join the queue, so that each move is shown
// with the speed the plan gives it (rising from its entry, cruising, falling
// to its exit) and the cycle time is `run`'s. The interpreter then works up
// to the planner's look-ahead beyond the block shown: each event carries the
// state of its block, which the pages show (Sim::modal), and the
// interpreter's diagnostics join the queue in their place. The workshop is
// not fed here: it meets each move as the machine starts it (sim_workshop).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/sim/sim.hpp"

namespace pupitre {

namespace {
// A diagnostic's place among the events: a message on a channel no program
// writes, its text the diagnostic's index in Interpreter::diags().
constexpr int kNoteChannel = -1000;
}  // namespace

// ---- the speed along a planned move ----

SpeedProfile SpeedProfile::of(const MoveEvent& m) {
    SpeedProfile p;
    if (m.plan_seconds <= 0 || m.plan_peak <= 0 || m.length <= 0) return p;
    p.planned = true;
    p.length = m.length;
    p.T = m.plan_seconds;
    p.v0 = m.plan_entry / 60, p.vp = m.plan_peak / 60, p.v1 = m.plan_exit / 60;
    // The trapezoid's length in its time gives its acceleration a = 1 / k:
    // T = L / vp + k ((vp - v0)² + (vp - v1)²) / (2 vp).
    const double rise = p.vp - p.v0, fall = p.vp - p.v1;
    const double spread = rise * rise + fall * fall;
    const double k = spread > 1e-12 ? (p.T - p.length / p.vp) * 2 * p.vp / spread : 0;
    p.t1 = rise * k;
    p.t2 = p.T - fall * k;
    if (k <= 0 || p.t1 < 0 || p.t2 < p.t1 || p.t2 > p.T) {
        // No room for a trapezoid (no acceleration, or E32000 holds the move
        // longer than its speeds say): the move at its mean speed.
        p.v0 = p.vp = p.v1 = p.length / p.T;
        p.t1 = 0, p.t2 = p.T;
    }
    return p;
}

double SpeedProfile::speed(double t) const {
    if (t <= 0) return v0;
    if (t < t1) return v0 + (vp - v0) * t / t1;
    if (t <= t2) return vp;
    if (t >= T) return v1;
    return vp - (vp - v1) * (t - t2) / (T - t2);
}

double SpeedProfile::distance(double t) const {
    t = std::clamp(t, 0.0, T);
    const double a = std::min(t, t1);
    double d = (v0 + speed(a)) / 2 * a;
    if (t > t1) d += vp * (std::min(t, t2) - t1);
    if (t > t2) d += (vp + speed(t)) / 2 * (t - t2);
    return std::min(d, length);
}

double SpeedProfile::time_at(double d) const {
    double lo = 0, hi = T;
    for (int i = 0; i < 60; ++i) {  // the distance only grows: halve the interval
        const double mid = (lo + hi) / 2;
        (distance(mid) < d ? lo : hi) = mid;
    }
    return hi;
}

// ---- the playback: how long an event lasts, how fast a move goes ----

double Sim::duration(const Ev& e) const {
    switch (e.kind) {
        case Ev::move:
        case Ev::home:
            if (e.m.plan_seconds >= 0) return e.m.plan_seconds;  // as planned
            if (mode_ == Mode::dry && e.feed_move && !manual_ && e.m.length > 0)
                return e.m.length / m_.max_feed * 60.0;  // DRY RUN: feeds at the maximum
            return e.m.seconds;
        case Ev::dwell:
        case Ev::tool:
        case Ev::wait:
            return e.seconds;
        default:
            return 0;
    }
}

double Sim::rate(const Ev& e) const {
    if ((e.kind == Ev::move) && e.feed_move && !e.overrides_off) return feed_override / 100.0;
    return 1.0;
}

// A planned move follows its speed profile (its length may be cut short by a
// contact); any other at its one speed.
double Sim::fraction() const {
    if (cur_->kind == Ev::move && prof_.planned) {
        const double shown = prof_.length * prof_scale_;
        return shown > 0 ? std::clamp(prof_.distance(t_) / shown, 0.0, 1.0) : 1.0;
    }
    return dur_ > 0 ? std::clamp(t_ / dur_, 0.0, 1.0) : 1.0;
}

double Sim::feed() const {
    if (!cur_ || cur_->kind != Ev::move || state_ != RunState::running) return 0;
    double f = cur_->m.feed;
    // A planned move: the speed it moves at, rising and falling (under G95
    // the plan's speed is the move's mean, the time at the feed counting the
    // spindle's speed along it).
    if (prof_.planned) return prof_.speed(t_) * 60 * rate(*cur_);
    if (mode_ == Mode::dry && cur_->feed_move && !manual_)
        f = m_.max_feed;
    else if (modal().feed_mode == 95 && cur_->m.rpm > 0)
        f = f / cur_->m.rpm * rpm();  // mm/rev follows the spindle
    return f * rate(*cur_);
}

// ---- the events into the planner ----

class Sim::Front final : public MachineSink {
  public:
    explicit Front(Sim& s) : s_(s) {}

    void move(const MoveEvent& e) override {
        if (direct()) return s_.move(e);
        tag();
        if (s_.mode_ != Mode::dry || e.g == 0 || e.length <= 0) return s_.plan_->move(e);
        MoveEvent dry = e;  // DRY RUN: the feed moves planned at the machine's maximum
        dry.feed = s_.m_.max_feed;
        dry.seconds = e.length / s_.m_.max_feed * 60.0;
        s_.plan_->move(dry);
    }
    void dwell(const Loc& l, double seconds) override {
        if (direct()) return s_.dwell(l, seconds);
        tag(), s_.plan_->dwell(l, seconds);
    }
    void tool(const Loc& l, int t, int d, double seconds, bool m6) override {
        if (direct()) return s_.tool(l, t, d, seconds, m6);
        tag(), s_.plan_->tool(l, t, d, seconds, m6);
    }
    void spindle(const SpindleEvent& e) override {
        if (direct()) return s_.spindle(e);
        tag(), s_.plan_->spindle(e);
    }
    void coolant(const Loc& l, bool m7, bool m8) override {
        if (direct()) return s_.coolant(l, m7, m8);
        tag(), s_.plan_->coolant(l, m7, m8);
    }
    void stop(const Loc& l, int m) override {
        if (direct()) return s_.stop(l, m);
        tag(), s_.plan_->stop(l, m);
    }
    void message(const Loc& l, int channel, std::string_view text) override {
        if (direct()) return s_.message(l, channel, text);
        tag(), s_.plan_->message(l, channel, text);
    }
    void end(const Loc& l, int m) override {
        if (direct()) return s_.end(l, m);
        tag(), s_.plan_->end(l, m);
    }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) override {
        if (direct()) return s_.stock(l, zr);
        tag(), s_.plan_->stock(l, zr);
    }
    void exact_stop(const Loc& l) override {
        if (direct()) return;
        tag(), s_.plan_->exact_stop(l);
    }
    // The Sim draws no programmed profile: it need not wait for the planner.
    void profile(const Loc&, const ProfileElem&) override {}

    void forget() { state_.reset(); }

  private:
    // Not planned: POM, RNS searching, the interpreter's own setup.
    bool direct() const { return !s_.planning_ || s_.searching_ || !s_.in_; }
    // The event's block state: one for all the events of a block.
    void tag() {
        const Interpreter& in = *s_.in_;
        if (!state_ || blocks_ != in.blocks() || line_ != in.location().line) {
            blocks_ = in.blocks(), line_ = in.location().line;
            state_ = std::make_shared<const ShownState>(
                ShownState{in.modal(), in.frames(), s_.blocks_ + (in.blocks() - s_.step_before_)});
        }
        s_.tags_.push_back(state_);
    }
    Sim& s_;
    std::shared_ptr<const ShownState> state_;
    long blocks_ = -1;
    int line_ = -1;
};

std::unique_ptr<MachineSink> Sim::make_front() {
    return std::make_unique<Front>(*this);
}

std::shared_ptr<const ShownState> Sim::take_tag() {
    if (tags_.empty()) return nullptr;
    std::shared_ptr<const ShownState> t = std::move(tags_.front());
    tags_.pop_front();
    return t;
}

void Sim::plan_reset(bool on) {
    plan_ = std::make_unique<plan::PlanSink>(m_, static_cast<MachineSink*>(this));
    tags_.clear();
    static_cast<Front&>(*front_).forget();
    planning_ = on;
}

void Sim::plan_flush() {
    if (planning_) plan_->finish();
}

void Sim::wait(const Loc& l, double seconds) {
    Ev e = event(Ev::wait, l);
    e.seconds = seconds;
    push(std::move(e), false);
}

// The interpreter's new diagnostics: in a planned run after the events before
// them (an alarm shows at its block, a warning when its block is shown), else
// at once.
void Sim::note_diags() {
    const auto& d = in_->diags();
    if (!planning_ || searching_) {
        for (; diag_seen_ < d.size(); ++diag_seen_) raise(d[diag_seen_]);
        return;
    }
    for (; diag_seen_ < d.size(); ++diag_seen_)
        front_->message(in_->location(), kNoteChannel, std::to_string(diag_seen_));
}

bool Sim::note_of(int channel, std::string_view text, Ev& e) {
    if (channel != kNoteChannel) return false;
    e.kind = Ev::note;
    e.a = std::atoi(std::string(text).c_str());
    return true;
}

// ---- each block's time ----

void Sim::keep_block_time(const Ev& e, double seconds) {
    if (manual_ || e.loc.line <= 0 || e.kind == Ev::note) return;
    if (!block_times_.empty() && block_times_.back().loc.prog == e.loc.prog &&
        block_times_.back().loc.line == e.loc.line) {
        block_times_.back().seconds += seconds;
        return;
    }
    if (block_times_.size() == kBlockTimes) block_times_.pop_front();
    block_times_.push_back(BlockTime{e.loc, seconds});
}

// The block's latest time as shown; the one being shown adds its events still
// to come; one queued but not shown yet, its events queued.
double Sim::block_time(int prog, int line) const {
    auto same = [&](const Ev& e) { return e.loc.prog == prog && e.loc.line == line; };
    std::vector<const Ev*> pending;
    if (cur_) pending.push_back(cur_.get());
    for (const Ev& e : q_) pending.push_back(&e);
    auto run_from = [&](size_t i) {
        double t = 0;
        for (; i < pending.size() && same(*pending[i]); ++i) t += duration(*pending[i]);
        return t;
    };
    for (size_t i = block_times_.size(); i-- > 0;) {
        const BlockTime& b = block_times_[i];
        if (b.loc.prog != prog || b.loc.line != line) continue;
        return b.seconds + (i + 1 == block_times_.size() && in_cycle() ? run_from(0) : 0);
    }
    for (size_t i = 0; i < pending.size(); ++i)
        if (same(*pending[i]) && pending[i]->kind != Ev::home) return run_from(i);
    return -1;
}

}  // namespace pupitre
