// The simulated machine: the interpreter's events are queued and played back on
// a simulated clock, with the operator's controls of a NUM panel (cycle start,
// feed hold, RAZ, single block, overrides, block search, IMD, JOG, POM).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/sim.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/parse/block.hpp"

namespace pupitre {

namespace {

using ::pupitre::geometry::kPi;

struct NullSink final : MachineSink {};

struct ModeInfo {
    Mode mode;
    std::string_view word, name, english, how;
};
// The NUM names on the status line, with the English the help page gives and
// what the operator does next. The order is the mode key's (F8).
// `english` and `how` are msgids: mode_english and mode_how return the English,
// the pages show it with tr().
constexpr ModeInfo kModes[] = {
    {Mode::automatic, "auto", "AUTO", N_("continuous run"),
     N_("Cycle Start (F9) runs the selected program")},
    {Mode::single, "seq", "SEQ", N_("single block"), N_("Cycle Start (F9) runs one block")},
    {Mode::dry, "dry", "DRY RUN", N_("dry run: feeds at the machine maximum"),
     N_("Cycle Start (F9) runs it")},
    {Mode::test, "test", "TEST", N_("program check, no motion"),
     N_("Cycle Start (F9) checks the program")},
    {Mode::rns, "rns", "RNS", N_("block search and resume"),
     N_("type the N to find, then Cycle Start (F9)")},
    {Mode::imd, "imd", "IMD", N_("manual data input"),
     N_("type a block, Enter, then Cycle Start (F9)")},
    {Mode::jog, "jog", "JOG", N_("continuous jog"),
     N_("hold an arrow key to move an axis (keys on OP)")},
    {Mode::inc, "inc", "INC", N_("incremental jog"),
     N_("an arrow key moves one step (keys on OP)")},
    {Mode::pom, "pom", "POM", N_("homing"), N_("Cycle Start (F9) homes the axes")},
};

std::string fmt_seconds(double seconds) {
    char buf[32];
    int m = int(seconds / 60);
    std::snprintf(buf, sizeof buf, "%d min %04.1f s", m, seconds - 60 * m);
    return buf;
}

}  // namespace

std::string_view mode_name(Mode m) {
    for (const auto& i : kModes)
        if (i.mode == m) return i.name;
    return "?";
}

std::string_view mode_english(Mode m) {
    for (const auto& i : kModes)
        if (i.mode == m) return i.english;
    return "?";
}

std::string_view mode_how(Mode m) {
    for (const auto& i : kModes)
        if (i.mode == m) return i.how;
    return "";
}

Mode next_mode(Mode m, int dir) {
    int n = int(std::size(kModes)), i = 0;
    while (i < n && kModes[i].mode != m) ++i;
    return kModes[((i + dir) % n + n) % n].mode;
}

bool parse_mode(std::string_view word, Mode& out) {
    for (const auto& i : kModes)
        if (i.word == word) {
            out = i.mode;
            return true;
        }
    return false;
}

std::string_view state_name(RunState state) {
    switch (state) {
        case RunState::idle:
            return "READY";
        case RunState::running:
            return "CYCLE";
        case RunState::hold:
            return "HOLD";
        case RunState::block:
            return "BLOCK";
        case RunState::stopped:
            return "STOP";
        case RunState::ended:
            return "END";
        case RunState::alarm:
            return "ALARM";
    }
    return "?";
}

Sim::Sim(const MachineProfile& m, ProgramMemory& mem)
    : m_(m), mem_(mem), null_(std::make_unique<NullSink>()) {
    RunOptions o;
    o.require_homing = m.homing_required;
    front_ = make_front();
    plan_reset(false);
    in_ = std::make_unique<Interpreter>(m_, mem_, *front_, o);
    om_ = in_->machine_pos();
    op_ = in_->program_pos();
}

Sim::~Sim() = default;

// ---- controls ----

std::string Sim::set_mode(Mode m) {
    if (in_cycle())
        return tr("a program is in cycle: let it end or press RAZ before changing mode");
    mode_ = m;
    if (state_ == RunState::ended) state_ = RunState::idle;
    if (m == Mode::rns && search_n_ < 0)
        message_ = tr("RNS: type the N number of the block to search, then Cycle Start");
    return {};
}

std::string Sim::select(int program) {
    if (in_cycle()) return tr("a program is in cycle: RAZ first");
    if (!mem_.find(program)) return strf(tr("program %%%d is not in memory"), program);
    if (selected_ != program) {
        // A new program: the status line and the OP page forget the old one's
        // block, count and cycle time.
        loc_ = Loc{};
        blocks_ = 0;
        run_seconds_ = 0;
        feed_seconds_ = -1;
        tool_times_.clear();
        ran_program_ = false;
        if (state_ == RunState::ended) state_ = RunState::idle;
    }
    selected_ = program;
    return {};
}

std::string Sim::imd(std::string_view blocks) {
    if (mode_ != Mode::imd) return tr("blocks are typed in IMD mode");
    if (in_cycle()) return tr("the previous IMD block is still running");
    // A block that does not read is refused now, as :save refuses it, not at
    // Cycle Start as an alarm that needs RAZ (a paste of 5,000 characters).
    if (Error e = parse_lines(blocks))
        // TRANSLATORS: an IMD block refused at Enter: the NUM error and its text.
        return strf(tr("error %d: %s (not taken)"), e.code, e.detail.c_str());
    imd_ = std::make_unique<ProgramText>();
    imd_->file = "IMD";
    imd_->text = std::make_shared<Text>(std::string(blocks) + "\n");
    imd_->end = imd_->text->size();
    invalidate_text_cache();  // the cache may know the old block's address
    if (state_ == RunState::ended) state_ = RunState::idle;
    return {};
}

std::string Sim::search(long n) {
    if (in_cycle()) return tr("a program is in cycle: RAZ first");
    if (n < 0) return tr("RNS needs a block number N");
    search_n_ = n;
    message_ = strf(tr("RNS N%ld: Cycle Start searches the block"), n);
    return {};
}

std::string Sim::cycle_start() {
    switch (state_) {
        case RunState::alarm:
            return strf(tr("alarm %d is active: RAZ first"), alarms_.back().diag.code);
        case RunState::running:
            return {};
        case RunState::hold:
        case RunState::block:
        case RunState::stopped:
            state_ = RunState::running;
            return {};
        case RunState::idle:
        case RunState::ended:
            // At rest a setting may have moved the program frame (a touch-off,
            // a gauge): the animation starts from the position shown now.
            op_ = in_->frames().to_program(om_);
            break;
    }
    return start_from_rest();
}

// Cycle Start at rest: the mode says what runs. POM runs no program: the
// last run's counters stay.
std::string Sim::start_from_rest() {
    message_.clear();
    // POM, JOG and INC leave the last run's counters; IMD is not a program.
    if (mode_ == Mode::imd) ran_program_ = false;
    if (mode_ == Mode::automatic || mode_ == Mode::single || mode_ == Mode::dry ||
        mode_ == Mode::test || mode_ == Mode::rns)
        ran_program_ = true;
    switch (mode_) {
        case Mode::automatic:
        case Mode::single:
        case Mode::dry:
            if (std::string why = need_program(); !why.empty()) return why;
            in_->start(selected_);
            new_path(op());
            break;
        case Mode::test:
            if (std::string why = need_program(); !why.empty()) return why;
            start_test();
            break;
        case Mode::rns:
            if (std::string why = need_program(); !why.empty()) return why;
            if (search_n_ < 0) return tr("RNS: type the N number of the block to search first");
            in_->start(selected_);
            searching_ = true;
            break;
        case Mode::imd:
            if (!imd_) return tr("IMD: type a block first");
            in_->start_imd(imd_.get());
            break;
        case Mode::pom:
            start_pom();
            return {};
        case Mode::jog:
        case Mode::inc:
            return tr("JOG/INC: move an axis with the jog keys or :jog AXIS DIST");
    }
    // The program's moves are planned (a TEST moves nothing; RNS plans from
    // the block found).
    plan_reset(mode_ != Mode::test);
    shown_.reset();
    block_times_.clear();
    alarm_loc_ = Loc{};
    feed_seconds_ = -1;
    tool_times_.clear();
    interp_done_ = false;
    pending_alarm_ = false;
    manual_ = false;
    seq_stop_ = false;
    blocks_ = 0;
    run_seconds_ = 0;
    run_warnings_.clear();
    run_warning_count_ = 0;
    state_ = RunState::running;
    return {};
}

std::string Sim::need_program() const {
    if (selected_ >= 0 && mem_.find(selected_)) return {};
    return tr("no program selected: choose one on the DIR page or with :load N");
}

// TEST changes nothing: its own correctors, frames, variables and program
// memory (a G76+/G76- it runs edits a copy).
void Sim::start_test() {
    RunOptions o = in_->options();
    o.require_homing = false;
    new_path(in_->program_pos());
    test_.reset();
    test_mem_ = std::make_unique<ProgramMemory>(mem_.clone());
    lc_ = LineCache{};
    // Its planner hands the drawing each move once planned.
    test_plan_ = std::make_unique<plan::PlanSink>(
        m_, path_ ? static_cast<MachineSink*>(path_) : null_.get());
    test_ = std::make_unique<Interpreter>(m_, *test_mem_, *test_plan_, o);
    for (int d = 0; d < 256; ++d) test_->corrector(d) = in_->corrector(d);
    test_->frames_mut() = in_->frames();
    test_->start(selected_);
    test_blocks_ = 0;
}

// POM: each axis to its home, one after the other.  Lathe: X retracts first;
// mill: Z (the tool axis) first (safe order).
void Sim::start_pom() {
    if (planning_) plan_reset(false);  // the axes' own moves, not a program's
    std::vector<int> order = m_.lathe ? std::vector<int>{X, Z} : std::vector<int>{Z, X, Y};
    for (int a = 0; a < kAxes; ++a)
        if (std::find(order.begin(), order.end(), a) == order.end()) order.push_back(a);
    Axes planned = in_->machine_pos();
    for (int a : order) {
        if (!m_.has(a)) continue;
        Axes to = planned;
        to[size_t(a)] = m_.home[size_t(a)];
        queue_move_to(to, 0, Loc{}, m_.axes[size_t(a)].rapid, true, a);
        planned = to;
    }
    manual_ = true;
    state_ = RunState::running;
}

// A run of the selected program starts a new drawing, with the program's EM+
// and EM- extremes when it gives them.
void Sim::new_path(const Axes& start) {
    if (!path_) return;
    path_->clear();
    path_->start_at(start);
    const ProgramText* p = mem_.find(selected_);
    // The GRAPH page's title and its `f` name the program, as the plot does.
    path_->program = p ? p->number : -1;
    path_->title = p ? p->title : std::string();
    Axes lo{}, hi{};
    uint16_t mlo = 0, mhi = 0;
    if (p && scan_extremes(*p, m_.lathe && m_.x_diameter, lo, hi, mlo, mhi))
        path_->set_extremes(lo, hi, mlo, mhi);
}

void Sim::feed_hold() {
    if (state_ == RunState::running) state_ = RunState::hold;
}

void Sim::raz() {
    if (shop_) {
        shop_->clear_crash();
        shop_->spindle(SpindleEvent{});
    }
    q_.clear();
    cur_.reset();
    test_.reset();
    plan_reset(false);  // what the planner held is abandoned with the queue
    shown_.reset();
    in_->raz();
    in_->place(om_);  // the axes stop where they are
    op_ = in_->program_pos();
    searching_ = false;
    pending_alarm_ = false;
    interp_done_ = true;
    manual_ = false;
    seq_stop_ = false;
    diag_seen_ = 0;
    sp_ = SpindleEvent{};
    m7_ = m8_ = false;
    message_.clear();
    state_ = RunState::idle;
}

std::string Sim::jog(int axis, double delta) {
    if (state_ == RunState::running && !manual_) return tr("a program is in cycle");
    if ((in_cycle() && !manual_) || state_ == RunState::alarm)
        return state_ == RunState::alarm ? tr("an alarm is active: RAZ first")
                                         : tr("a program is interrupted: RAZ before jogging");
    if (!m_.has(axis)) return strf(tr("the machine has no %c axis"), kAxisNames[size_t(axis)]);
    double internal = delta / in_->to_display(axis, 1.0);
    if (Error e = in_->jog(axis, internal))
        return strf(tr("error %d: %s"), e.code, e.detail.c_str());
    if (planning_) plan_reset(false);  // a jog is no program's move
    double feed = jog_feed > 0 ? jog_feed : m_.jog_feed;
    queue_move_to(in_->machine_pos(), 1, Loc{}, feed, false, axis);
    message_.clear();  // the last run's news is not the jog's
    manual_ = true;
    interp_done_ = true;
    if (state_ != RunState::running) state_ = RunState::running;
    return {};
}

// A move the interpreter did not make (POM, JOG): from the last queued point.
void Sim::queue_move_to(const Axes& mach, int g, Loc loc, double feed, bool home_axis, int axis) {
    Ev e;
    e.kind = home_axis ? Ev::home : Ev::move;
    e.a = axis;
    e.loc = loc;
    MoveEvent& m = e.m;
    m.loc = loc;
    m.g = g;
    m.from_mach = planned_;
    // Nothing moving or queued (an event that ended the last run may linger).
    if (q_.empty() && (!cur_ || (cur_->kind != Ev::move && cur_->kind != Ev::home))) {
        m.from_mach = om_;
        op_ = in_->frames().to_program(om_);  // a setting made at rest is in the frame now
    }
    m.to_mach = mach;
    m.to_prog = in_->frames().to_program(mach);
    double len = 0;
    for (int a = 0; a < kAxes; ++a) len += std::pow(mach[size_t(a)] - m.from_mach[size_t(a)], 2);
    m.length = std::sqrt(len);
    m.feed = feed;
    m.seconds = feed > 0 ? m.length / feed * 60.0 : 0;
    e.feed_move = g != 0;
    planned_ = mach;
    q_.push_back(std::move(e));
}

// ---- the interpreter's events ----

void Sim::push(Ev e, bool tagged) {
    if (tagged) e.shown = take_tag();
    e.overrides_off = e.shown ? e.shown->modal.overrides_off : in_->modal().overrides_off;
    if (searching_) {
        // RNS: the moves are not made; the state they leave is rebuilt.
        switch (e.kind) {
            case Ev::spindle:
                sp_ = e.sp;
                break;
            case Ev::coolant:
                m7_ = e.a, m8_ = e.b;
                break;
            case Ev::tool:
                tool_ = e.a, corr_ = e.b;
                break;
            default:
                break;
        }
        return;
    }
    if (e.kind == Ev::move) planned_ = e.m.to_mach;
    q_.push_back(std::move(e));
}

void Sim::move(const MoveEvent& m) {
    Ev e = event(Ev::move, m.loc);
    e.m = m;
    e.feed_move = m.g != 0;
    push(std::move(e));
}

void Sim::dwell(const Loc& l, double duration) {
    Ev e = event(Ev::dwell, l);
    e.seconds = duration;
    push(std::move(e));
}

void Sim::tool(const Loc& l, int t, int d, double duration, bool) {
    Ev e = event(Ev::tool, l);
    e.a = t, e.b = d, e.seconds = duration;
    push(std::move(e));
}

void Sim::spindle(const SpindleEvent& sp) {
    Ev e = event(Ev::spindle, sp.loc);
    e.sp = sp;
    push(std::move(e));
}

void Sim::coolant(const Loc& l, bool m7, bool m8) {
    Ev e = event(Ev::coolant, l);
    e.a = m7, e.b = m8;
    push(std::move(e));
}

void Sim::stop(const Loc& l, int m) {
    Ev e = event(Ev::stop, l);
    e.a = m;
    push(std::move(e));
}

void Sim::message(const Loc& l, int channel, std::string_view text) {
    Ev e = event(Ev::message, l);
    if (!note_of(channel, text, e)) e.text = std::string(text);
    push(std::move(e));
}

void Sim::end(const Loc& l, int m) {
    Ev e = event(Ev::end, l);
    e.a = m;
    push(std::move(e));
}

// ---- playback ----

bool Sim::begin_next() {
    if (q_.empty()) return false;
    cur_ = std::make_unique<Ev>(std::move(q_.front()));
    q_.pop_front();
    Ev& e = *cur_;
    if (e.loc.line > 0 && e.kind != Ev::note) loc_ = e.loc;
    if (e.shown) shown_ = e.shown;
    t_ = 0;
    dur_ = duration(e);
    switch (e.kind) {
        case Ev::move:
        case Ev::home:
            begin_move(e);
            break;
        case Ev::spindle:
            sp_ = e.sp;
            if (shop_) shop_->spindle(e.sp);
            break;
        case Ev::coolant:
            m7_ = e.a, m8_ = e.b;
            break;
        case Ev::tool:
            tool_ = e.a, corr_ = e.b;
            if (shop_) shop_->tool(e.loc, e.a, e.b, 0, true);
            break;
        case Ev::message:
            message_ = e.text;
            break;
        case Ev::stop:
            state_ = RunState::stopped;
            message_ = e.a == 88 ? std::string(tr("G88: operator check; Cycle Start goes on"))
                                 : strf(tr("M%02d: program stop; Cycle Start goes on"), e.a);
            break;
        case Ev::end:
            begin_end(e);
            break;
        case Ev::note:
            if (size_t(e.a) < in_->diags().size()) raise(in_->diags()[size_t(e.a)]);
            break;
        case Ev::dwell:
        case Ev::wait:
            break;
    }
    return true;
}

// A move or a homing starts: the offsets op() interpolates between, the
// workshop, and a program's move on the drawing.
void Sim::begin_move(Ev& e) {
    prof_ = SpeedProfile::of(e.m);
    prof_scale_ = 1;
    op_from_ = op_;
    for (int a = 0; a < kAxes; ++a) {
        op_off0_[size_t(a)] = e.m.from_mach[size_t(a)] - op_from_[size_t(a)];
        op_off1_[size_t(a)] = e.m.to_mach[size_t(a)] - e.m.to_prog[size_t(a)];
    }
    through_workshop(e);
    if (e.m.rpm > 0 && e.kind == Ev::move && !manual_) sp_.rpm = e.m.rpm;
    if (path_ && e.kind == Ev::move && !manual_ && e.loc.line > 0) {
        const auto& ew = in_->e_written();  // E31000/E31001: the drawing's line types
        auto r = ew.find(31000), f = ew.find(31001);
        path_->set_line_types(r == ew.end() ? -1 : int(r->second),
                              f == ew.end() ? -1 : int(f->second));
        // A turned table or a tilted tool: the path drawn on the part.
        std::vector<MoveEvent> pieces;
        if (!shop_ || !shop_->on_part(e.m, pieces)) return path_->add(e.m);
        for (const MoveEvent& p : pieces) path_->add(p);
    }
}

// The end of a program (M02) or of an IMD block: the message line sums it up.
void Sim::begin_end(const Ev& e) {
    state_ = RunState::ended;
    if (e.a != 2 && mode_ == Mode::imd)
        message_ =
            strf(trn("IMD done (%ld block): type the next block, or F8 for another mode",
                     "IMD done (%ld blocks): type the next block, or F8 for another mode", blocks_),
                 blocks_);
    if (e.a == 2) {
        if (planning_) {
            feed_seconds_ = plan_->report().feed_seconds;
            tool_times_ = plan_->report().tools.rows();
        }
        // TRANSLATORS: the second %s counts the blocks run ("%ld blocks").
        message_ = strf(tr("M02: end of program %%%d, %s, cycle time %s"), e.loc.prog,
                        strf(trn("%ld blocks", "%ld blocks", blocks_), blocks_).c_str(),
                        fmt_seconds(cycle_time()).c_str());
        // The warnings the run printed on the way must not vanish with it.
        if (run_warning_count_ > 0)
            message_ += strf(
                trn("; %zu warning (F7 ALARM)", "; %zu warnings (F7 ALARM)", run_warning_count_),
                run_warning_count_);
    }
}

void Sim::finish_current() {
    Ev& e = *cur_;
    keep_block_time(e, dur_);
    if (e.kind == Ev::move || e.kind == Ev::home) {
        om_ = e.m.to_mach;
        op_ = e.m.to_prog;
        if (e.kind == Ev::home) {
            in_->home(e.a);
            om_ = in_->machine_pos();
            op_ = in_->program_pos();
        }
    }
    cur_.reset();
}

Axes Sim::op() const {
    if (!cur_ || (cur_->kind != Ev::move && cur_->kind != Ev::home)) {
        if (in_cycle() || state_ == RunState::running) return op_;
        return in_->frames().to_program(om_);
    }
    const MoveEvent& m = cur_->m;
    const double f = fraction();
    Axes p{};
    for (int a = 0; a < kAxes; ++a)
        p[size_t(a)] = op_from_[size_t(a)] + (m.to_prog[size_t(a)] - op_from_[size_t(a)]) * f;
    if (m.g == 2 || m.g == 3) {
        int a0 = m.plane_a0, a1 = m.plane_a1;
        double s0 = op_from_[size_t(a0)] - m.c0, s1 = op_from_[size_t(a1)] - m.c1;
        double e0 = m.to_prog[size_t(a0)] - m.c0, e1 = m.to_prog[size_t(a1)] - m.c1;
        double r0 = std::hypot(s0, s1), r1 = std::hypot(e0, e1);
        double ang = std::atan2(s1, s0) + m.sweep * kPi / 180.0 * f;
        double r = r0 + (r1 - r0) * f;
        p[size_t(a0)] = m.c0 + r * std::cos(ang);
        p[size_t(a1)] = m.c1 + r * std::sin(ang);
    }
    return p;
}

void Sim::interpolate() {
    if (!cur_ || (cur_->kind != Ev::move && cur_->kind != Ev::home)) return;
    const double f = fraction();
    Axes p = op();
    for (int a = 0; a < kAxes; ++a)
        om_[size_t(a)] =
            p[size_t(a)] + op_off0_[size_t(a)] + (op_off1_[size_t(a)] - op_off0_[size_t(a)]) * f;
}

double Sim::queued_time() const {
    double t = cur_ ? std::max(0.0, dur_ - t_) : 0;
    for (const Ev& e : q_) t += duration(e);
    return t;
}

Axes Sim::to_go() const {
    Axes g{};
    if (!cur_ || (cur_->kind != Ev::move && cur_->kind != Ev::home)) return g;
    Axes p = op();
    for (int a = 0; a < kAxes; ++a) g[size_t(a)] = cur_->m.to_prog[size_t(a)] - p[size_t(a)];
    return g;
}

double Sim::rpm() const {
    if (sp_.dir != 3 && sp_.dir != 4) return 0;
    double n = sp_.rpm;
    if (sp_.css && sp_.vc > 0 && m_.lathe) {
        // G96: the speed follows the diameter being cut (000:1538-1551;
        // pupitre-iso(5), FEEDS AND SPINDLE).
        double d = 2 * std::abs(op()[X]);
        double limit = m_.spindle_max;
        if (sp_.range >= 40 && size_t(sp_.range - 40) < m_.ranges.size())
            limit = std::min(limit, m_.ranges[size_t(sp_.range - 40)].max);
        if (modal().smax > 0) limit = std::min(limit, modal().smax);
        n = d > 1e-6 ? std::min(limit, sp_.vc * 1000.0 / (kPi * d)) : limit;
    }
    if (modal().overrides_off) return n;
    return n * spindle_override / 100.0;
}

void Sim::raise(const Diag& x) {
    if (x.is_error()) {
        alarms_.push_back(Alarm{x, clock_});
        if (path_) path_->add_error(x);
    } else {
        message_ = strf(tr("warning %d: %s"), x.code, x.detail.c_str());
        if (run_warnings_.size() < kMaxRunWarnings) run_warnings_.push_back(x);
        ++run_warning_count_;
    }
}

// The queue is empty: runs the next block, or settles the state.
// RNS: the state is rebuilt up to the block; the axes rejoin its start.
void Sim::rns_found(int next_line) {
    searching_ = false;
    queue_move_to(in_->machine_pos(), 0, in_->location(), 0, false, X);
    Ev& rejoin = q_.back();
    rejoin.m.seconds = 0;
    for (int a = 0; a < kAxes; ++a)
        if (m_.has(a) && m_.axes[size_t(a)].rapid > 0)
            rejoin.m.seconds =
                std::max(rejoin.m.seconds, std::abs(rejoin.m.to_mach[size_t(a)] - om_[size_t(a)]) /
                                               m_.axes[size_t(a)].rapid * 60.0);
    rejoin.m.to_prog = in_->program_pos();
    rejoin.feed_move = false;
    mode_ = Mode::automatic;
    state_ = RunState::stopped;
    loc_ = Loc{in_->location().prog, next_line, search_n_};
    message_ = strf(tr("RNS: N%ld found, state rebuilt; Cycle Start rejoins it, AUTO"), search_n_);
}

bool Sim::step_interp(long& budget) {
    if (pending_alarm_) {
        pending_alarm_ = false;
        state_ = RunState::alarm;
        if (alarm_loc_.line > 0) loc_ = alarm_loc_;  // the block the error is in
        return false;
    }
    if (interp_done_) {
        if (state_ == RunState::running && manual_ && mode_ == Mode::pom)
            message_ = tr("POM done: every axis is homed; F8 to choose the next mode");
        if (state_ == RunState::running) state_ = manual_ ? RunState::idle : RunState::ended;
        manual_ = false;
        return false;
    }
    if (seq_stop_ && mode_ == Mode::single) {
        seq_stop_ = false;
        state_ = RunState::block;
        return false;
    }
    if (budget <= 0) return false;
    int next_line = 0;
    if (searching_ && in_->next_label(&next_line) == search_n_) {
        rns_found(next_line);
        return false;
    }
    --budget;
    step_before_ = in_->blocks();
    StepResult r = in_->step();
    blocks_ += in_->blocks() - step_before_;  // the end of an IMD text is not a block
    // The block shown is the interpreter's unless the planner holds moves
    // before it, or they wait in the queue.
    if ((!searching_ || in_->has_errors()) && !planner_holds() && q_.empty()) {
        loc_ = in_->location();
        shown_.reset();
    }
    note_diags();
    switch (r) {
        case StepResult::running:
        case StepResult::stopped:
            break;
        case StepResult::ended:
            interp_done_ = true;
            plan_flush();
            if (searching_) {
                searching_ = false;
                state_ = RunState::idle;
                message_ = strf(tr("RNS: N%ld is not in the program"), search_n_);
                return false;
            }
            break;
        case StepResult::error:
            interp_done_ = true;
            searching_ = false;
            pending_alarm_ = true;  // after the moves the block made
            alarm_loc_ = in_->location();
            plan_flush();
            break;
    }
    // SEQ: the block's moves end at rest, and show before the next is run.
    if (mode_ == Mode::single && !searching_) seq_stop_ = true, plan_flush();
    return true;
}

void Sim::test_advance(long budget) {
    while (budget-- > 0 && state_ == RunState::running) {
        StepResult r = test_->step();
        ++test_blocks_;
        loc_ = test_->location();
        if (r == StepResult::error || r == StepResult::ended) test_plan_->finish();
        if (r == StepResult::error) {
            for (const Diag& d : test_->diags())
                if (d.is_error()) {
                    alarms_.push_back(Alarm{d, clock_});
                    if (path_) path_->add_error(d);
                }
            state_ = RunState::alarm;
        } else if (r == StepResult::ended) {
            int warnings = 0;
            for (const Diag& d : test_->diags()) warnings += !d.is_error();
            // TRANSLATORS: the %s count the blocks ("%ld blocks") and the warnings ("%d warnings").
            message_ = strf(
                tr("TEST %%%d: no error, %s, %s, cycle time %s"), selected_,
                strf(trn("%ld blocks", "%ld blocks", test_->blocks()), test_->blocks()).c_str(),
                // TRANSLATORS: the English says "warnings" whatever the number.
                strf(trn("%d warnings", "%d warnings", warnings), warnings).c_str(),
                fmt_seconds(cycle_time()).c_str());
            state_ = RunState::ended;
        }
    }
}

void Sim::advance(double dt, long max_blocks) {
    if (state_ != RunState::running) return;
    if (mode_ == Mode::test && test_) return test_advance(max_blocks);
    long budget = max_blocks;
    while (state_ == RunState::running) {
        if (!cur_) {
            if (begin_next()) continue;
            if (!step_interp(budget)) break;
            continue;
        }
        double r = rate(*cur_);
        if (r <= 0) break;  // feed override at 0 %: the axes wait
        double need = (dur_ - t_) / r;
        if (dt >= need) {
            dt -= need;
            clock_ += need;
            if (!manual_) run_seconds_ += need;  // jogs and POM are not cycle time
            t_ = dur_;
            finish_current();
        } else {
            t_ += dt * r;
            clock_ += dt;
            if (!manual_) run_seconds_ += dt;
            interpolate();
            break;
        }
    }
}

const ProgramText* Sim::text_of(int prog) const {
    if (prog == 0 && imd_ && mode_ == Mode::imd) return imd_.get();
    // TEST shows its own copy, as its G76+/G76- left it.
    return (mode_ == Mode::test && test_mem_ ? *test_mem_ : mem_).find(prog);
}

std::string_view Sim::line_of(const ProgramText* p, int line) const {
    if (!p || line < p->first_line) return {};
    std::string_view all = *p->text;
    // Both memories' generations only grow; a new TEST copy resets the cache.
    const uint64_t generation = mem_.generation() + (test_mem_ ? test_mem_->generation() : 0);
    if (lc_.p != p || lc_.generation != generation)
        lc_ = LineCache{p, p->first_line, p->begin, generation};
    while (lc_.line > line) {  // backwards from the cached line, not from the top
        size_t prev = lc_.offset >= 2 ? all.rfind('\n', lc_.offset - 2) : std::string_view::npos;
        lc_.offset = prev == std::string_view::npos || prev + 1 < p->begin ? p->begin : prev + 1;
        --lc_.line;
    }
    while (lc_.line < line) {
        size_t eol = all.find('\n', lc_.offset);
        if (eol == std::string_view::npos || eol + 1 >= p->end) return {};
        lc_.offset = eol + 1;
        ++lc_.line;
    }
    size_t eol = all.find('\n', lc_.offset);
    if (eol == std::string_view::npos || eol > p->end) eol = p->end;
    std::string_view l = all.substr(lc_.offset, eol - lc_.offset);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    return l;
}

}  // namespace pupitre
