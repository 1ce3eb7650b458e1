// The interpreter's control flow: fetching blocks, the G77 call stack, G79 jumps,
// M02 and error 20, the block budget (the named values and the E parameters:
// interp_values.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/caz.hpp"
#include "core/interp/gate.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

Interpreter::Interpreter(const MachineProfile& m, ProgramMemory& mem, MachineSink& sink,
                         RunOptions o)
    : m_(m),
      mem_(mem),
      sink_(sink),
      plain_(std::make_unique<PlainBlock>()),
      gate_(std::make_unique<GateSink>(sink)),
      out_(*gate_),
      opt_(o) {
    min_block_ = m_.min_block_time;
    power_on();
}

Interpreter::~Interpreter() = default;

void Interpreter::power_on() {
    modal_ = Modal{};
    modal_.plane = m_.lathe ? 18 : 17;
    modal_.radius_x = m_.lathe && !m_.x_diameter;
    frames_ = Frames{};
    frames_.pref = m_.pref;
    frames_.dec1 = m_.dec1;
    gauge_pending_.reset();
    mach_ = m_.home;
    rpm_ = 0;
    recompute_program_pos();
    // The power-on spindle state (stopped, no range) is not an event.
    last_sp_ = SpindleEvent{};
    sp_emitted_ = true;
    if (opt_.require_homing)
        homed_.reset();
    else
        homed_.set();
    update_travel();
    if (m_.dialect == Dialect::cazeneuve) caz_power_on();
}

// RAZ (000:1245, 000:13194; pupitre-iso(5), M02): the run is abandoned, the
// modal state is the one of M02, the alarms are acknowledged. Positions,
// origins, correctors and the L variables stay: RAZ moves nothing and forgets
// no setting.
void Interpreter::raz() {
    stack_.clear();
    main_ = nullptr;
    imd_ = false;
    gate_->holding = false;
    gate_->queue.clear();
    comp_ = Comp{};
    pgp_.start(pgp::V2(0, 0));
    pgp_ctx_.clear();
    g64_pending_ = false;
    g64_stock_.clear();
    cyc_ = CycleParams{};
    reset_modal_m02();
    diags_.clear();
    ended_ = true;
    first_move_ = true;
}

void Interpreter::text_changed(const ProgramText* p) {
    std::string_view all = *p->text;
    auto offset_of = [&](int line) {
        size_t pos = p->begin;
        for (int l = p->first_line; l < line && pos < p->end; ++l) {
            size_t eol = all.find('\n', pos);
            pos = eol == std::string_view::npos ? p->end : eol + 1;
        }
        return std::min(pos, p->end);
    };
    for (Frame& f : stack_) {
        if (f.prog != p) continue;
        f.pos = offset_of(f.line);
        f.range_pos = offset_of(f.range_line);
    }
}

long Interpreter::next_label(int* line) const {
    if (ended_ || stack_.empty()) return -1;
    const Frame& f = stack_.back();
    if (line) *line = f.line;
    if (f.pos >= f.prog->end) return -1;
    std::string_view all = *f.prog->text;
    size_t eol = all.find('\n', f.pos);
    if (eol == std::string_view::npos || eol > f.prog->end) eol = f.prog->end;
    return line_label(all.substr(f.pos, eol - f.pos));
}

bool Interpreter::start_imd(const ProgramText* p) {
    start(p);
    imd_ = true;
    return true;
}

Error Interpreter::jog(int axis, double delta) {
    if (!m_.has(axis)) return {1, strf(tr("the machine has no %c axis"), kAxisNames[size_t(axis)])};
    Axes to = mach_;
    to[size_t(axis)] += delta;
    size_t before = diags_.size();
    bool ended = ended_;
    auto homed = homed_;
    homed_.set();  // the operator may jog before the POM; programs may not
    bool ok = check_travel(to);
    homed_ = homed;
    if (!ok) {
        Error e{diags_.back().code, diags_.back().detail};
        diags_.resize(before);  // a refused jog is a message, not an alarm
        ended_ = ended;
        return e;
    }
    mach_ = to;
    recompute_program_pos();
    return {};
}

void Interpreter::home(int axis) {
    if (!m_.has(axis)) return;
    mach_[size_t(axis)] = m_.home[size_t(axis)];
    homed_.set(size_t(axis));
    recompute_program_pos();
}

// The travel checked on every move: the profile's, narrowed by the dynamic limits
// a program writes into E6x002 / E6x003.
void Interpreter::update_travel() {
    for (int a = 0; a < kAxes; ++a) {
        const AxisConfig& c = m_.axes[size_t(a)];
        travel_lo_[size_t(a)] = c.present ? c.min : -1e300;
        travel_hi_[size_t(a)] = c.present ? c.max : 1e300;
        double unit = is_rotary(a) ? 1e-4 : 1e-3;
        int base = 60000 + 1000 * a;
        if (auto it = e_raw_.find(base + 2); it != e_raw_.end())
            travel_lo_[size_t(a)] = std::max(travel_lo_[size_t(a)], double(it->second) * unit);
        if (auto it = e_raw_.find(base + 3); it != e_raw_.end())
            travel_hi_[size_t(a)] = std::min(travel_hi_[size_t(a)], double(it->second) * unit);
        travel_lo_tol_[size_t(a)] = travel_lo_[size_t(a)] - 1e-6;
        travel_hi_tol_[size_t(a)] = travel_hi_[size_t(a)] + 1e-6;
    }
    n_bounded_ = 0;
    for (int a = 0; a < kAxes; ++a)
        if (travel_lo_[size_t(a)] > -1e300 || travel_hi_[size_t(a)] < 1e300)
            bounded_[size_t(n_bounded_++)] = uint8_t(a);
}

bool Interpreter::has_errors() const {
    return std::any_of(diags_.begin(), diags_.end(), [](const Diag& d) { return d.is_error(); });
}

double Interpreter::to_display(int axis, double internal) const {
    if (axis == X && m_.lathe && m_.x_diameter && !modal_.radius_x) return internal * 2;
    return internal;
}

// The one place a Diag is built: what fail and warn record, at the block
// being read (its file, program, line and N).
Diag Interpreter::diag_here(Severity s, int code, std::string detail, int column) const {
    Diag d;
    d.severity = s;
    d.code = code;
    // Outside any call an error is the main program's; a warning names no file there.
    if (!stack_.empty())
        d.file = stack_.back().prog->file;
    else if (s == Severity::error && main_)
        d.file = main_->file;
    d.program = loc_.prog;
    d.line = loc_.line;
    d.n = loc_.n;
    d.column = column;
    d.detail = std::move(detail);
    return d;
}

bool Interpreter::fail(int code, std::string detail, int column) {
    if (caz_) {
        detail = caz::detail_of(code, std::move(detail));
        code = caz::error_of(code);
    }
    diags_.push_back(diag_here(Severity::error, code, std::move(detail), column ? column : col_));
    ended_ = true;
    return false;
}

bool Interpreter::fail(const Error& e) {
    return fail(e.code, e.detail, e.column);
}

void Interpreter::warn(int code, std::string detail) {
    Diag d = diag_here(Severity::warning, code, std::move(detail), 0);
    // One warning of a kind per line is enough (a loop would repeat it).
    for (const auto& o : diags_)
        if (o.code == d.code && o.line == d.line && o.file == d.file) return;
    diags_.push_back(std::move(d));
}

void Interpreter::recompute_program_pos() {
    prog_ = frames_.to_program(mach_);
}

double Interpreter::gauge_for(int d, int axis) const {
    if (d <= 0) return 0;
    const Corrector& c = corr_[size_t(d)];
    if (m_.lathe) {
        // Corrected X length = gauge X + DX/2 (000:879); Z = gauge Z + DZ.
        if (axis == X) return c.x + c.dx / 2;
        if (axis == Z) return c.z + c.dz;
        return 0;
    }
    if (axis != modal_.tool_axis) return 0;
    double len = c.l + c.dl;
    return modal_.tool_axis_neg ? -len : len;
}

// The gauge of a new corrector is applied on an axis at the first block that
// programs that axis (000:797, 000:843-865, 000:3813-3853; pupitre-iso(5), DECISIONS).
void Interpreter::apply_corrector_gauges(const std::bitset<kAxes>& programmed) {
    // Under a new D the axes no block programs stay pending: every move asks.
    if ((gauge_pending_ & programmed).none()) return;
    for (int a = 0; a < kAxes; ++a) {
        if (programmed[size_t(a)] && gauge_pending_[size_t(a)]) {
            frames_.gauge[size_t(a)] = gauge_for(modal_.d, a);
            gauge_pending_.reset(size_t(a));
        }
    }
}

void Interpreter::note_tool(int t) {
    if (std::find(tools_used_.begin(), tools_used_.end(), t) == tools_used_.end())
        tools_used_.push_back(t);
}

bool Interpreter::start(int program) {
    const ProgramText* p = mem_.find(program);
    if (!p) return fail(25, strf(tr("program %%%d is not in memory"), program));
    return start(p);
}

bool Interpreter::start(const ProgramText* p) {
    main_ = p;
    seen_states_.clear();  // a new run: states of the last one are no repetition
    imd_ = false;
    stack_.clear();
    loaded_size_ = mem_.size();
    Frame f;
    f.prog = p;
    f.pos = p->begin;
    f.line = p->first_line;
    stack_.push_back(f);
    ended_ = false;
    loc_ = Loc{p->number, p->first_line, -1};
    return true;
}

// The next line, read into block_ by the lane of plain blocks when it can
// (`parsed`): the lane finds the line's end as it reads it.
bool Interpreter::fetch(std::string_view& line, int& lineno, bool& parsed) {
    while (!stack_.empty()) {
        Frame& f = stack_.back();
        if (f.pos >= f.prog->end) {
            if (!end_of_frame()) return false;
            continue;
        }
        // The text ends with '\n' (load_text, Text::map) and a string's
        // with a '\0' past it: the lane never reads past the text's end.
        const Text& all = *f.prog->text;
        size_t len = 0;
        parsed = parse_plain_line(all.data() + f.pos, all.size() - f.pos, block_, len) &&
                 f.pos + len < f.prog->end;
        size_t eol = f.pos + len;
        if (!parsed) {
            eol = all.find('\n', f.pos);
            if (eol == std::string_view::npos || eol > f.prog->end) eol = f.prog->end;
        }
        line = all.view().substr(f.pos, eol - f.pos);
        lineno = f.line;
        f.pos = eol + 1;
        ++f.line;
        return true;
    }
    return false;
}

// The text of a frame's program has ended.
bool Interpreter::end_of_frame() {
    Frame& f = stack_.back();
    if (imd_ && (f.prog == main_ || stack_.size() == 1)) {
        // The end of an IMD fragment: the blocks typed are done, the state stays.
        stack_.clear();
        ended_ = true;
        out_.end(loc_, 0);
        return false;
    }
    if (f.prog == main_ || stack_.size() == 1) {
        // Error 20 only for the main program (pupitre-iso(5), DECISIONS, M02 in a called program).
        loc_.line = f.line - 1;
        loc_.n = -1;
        fail(20, strf(tr("end of program %%%d without M02"), main_->number));
        out_.end(loc_, 0);
        return false;
    }
    if (f.whole && --f.repeats > 0) {
        f.pos = f.range_pos;
        f.line = f.range_line;
        return true;
    }
    stack_.pop_back();
    after_block(stack_.back().line - 1);
    return true;
}

// After the block at `lineno` of the top frame: the end of a G77 range.
void Interpreter::after_block(int lineno) {
    while (stack_.size() > 1) {
        Frame& f = stack_.back();
        if (f.whole || lineno != f.end_line) return;
        if (--f.repeats > 0 && !f.emptied) {
            f.pos = f.range_pos;
            f.line = f.range_line;
            return;
        }
        Frame done = f;
        stack_.pop_back();
        if (done.prog != stack_.back().prog) {
            // External range: the state before the call is restored (000:6737).
            modal_.radcomp = done.saved_radcomp;
            bool changed = modal_.spindle_dir != done.saved_dir ||
                           modal_.range != done.saved_range || modal_.s != done.saved_s;
            modal_.spindle_dir = done.saved_dir;
            modal_.range = done.saved_range;
            modal_.s = done.saved_s;
            if (changed) set_spindle_event();
            if (modal_.m7 != done.saved_m7 || modal_.m8 != done.saved_m8) {
                modal_.m7 = done.saved_m7;
                modal_.m8 = done.saved_m8;
                out_.coolant(loc_, modal_.m7, modal_.m8);
            }
        }
        lineno = stack_.back().line - 1;
    }
}

bool Interpreter::call(const Plan& p) {
    const ProgramText* target = stack_.back().prog;
    if (p.g77.level > 0) {
        // G77 -i: the return block of level i (000:6921-6947; pupitre-iso(5),
        // DECISIONS, G77 limits and levels).
        int depth = int(stack_.size()) - 1;
        if (p.g77.level > depth)
            return fail(26, strf(tr("G77 -%d: there is no call level %d (depth %d)"), p.g77.level,
                                 p.g77.level, depth));
        const Frame& caller = stack_[size_t(p.g77.level - 1)];
        Frame f;
        f.prog = caller.prog;
        f.call = true;
        f.pos = f.range_pos = caller.pos;
        f.line = f.range_line = f.end_line = caller.line;
        stack_.push_back(f);
        return true;
    }
    if (p.g77.h >= 0) {
        target = mem_.find(p.g77.h);
        if (!target)
            return fail(25, strf(tr("G77 H%d: program %%%d is not in memory"), p.g77.h, p.g77.h));
    }
    if (stack_.size() > 8) return fail(26, tr("more than 8 nested G77 calls"));
    Frame f;
    f.prog = target;
    f.call = true;
    f.repeats = p.g77.s;
    f.saved_radcomp = modal_.radcomp;
    f.saved_dir = modal_.spindle_dir;
    f.saved_range = modal_.range;
    f.saved_s = modal_.s;
    f.saved_m7 = modal_.m7;
    f.saved_m8 = modal_.m8;
    if (p.g77.nn == 0) {
        if (p.g77.h < 0) return fail(25, tr("G77 needs H (a program) or N labels"));
        f.whole = true;
        f.pos = f.range_pos = target->begin;
        f.line = f.range_line = target->first_line;
    } else {
        const Label* a = target->find_label(p.g77.n[0]);
        const Label* b = target->find_label(p.g77.nn > 1 ? p.g77.n[1] : p.g77.n[0]);
        if (!a || !b) {
            long missing = !a ? p.g77.n[0] : p.g77.n[1];
            return fail(25, strf(tr("G77: block N%ld not found in %%%d"), missing, target->number));
        }
        // G77 N50 N30 runs the same range as G77 N30 N50, in file order (004:896).
        if (b->line < a->line) std::swap(a, b);
        f.pos = f.range_pos = a->offset;
        f.line = f.range_line = a->line;
        f.end_line = b->line;
    }
    stack_.push_back(f);
    return true;
}

bool Interpreter::jump(long label) {
    Frame& f = stack_.back();
    const Label* l = f.prog->find_label(label);
    if (!l) return fail(25, strf(tr("G79: block N%ld not found in %%%d"), label, f.prog->number));
    if (l->offset < f.pos) {
        f.pos = l->offset;  // the state as the jump leaves it
        f.line = l->line;
        if (!note_backward_jump(label)) return false;
    }
    f.pos = l->offset;
    f.line = l->line;
    return true;
}

StepResult Interpreter::step() {
    if (ended_) return has_errors() ? StepResult::error : StepResult::ended;
    std::string_view line;
    int lineno;
    bool parsed;
    for (;;) {
        if (!fetch(line, lineno, parsed))
            return ended_ ? (has_errors() ? StepResult::error : StepResult::ended)
                          : StepResult::ended;
        loc_ = Loc{stack_.back().prog->number, lineno, -1};
        col_ = 0;
        cur_text_ = line;
        cur_line_ = lineno;
        if (Error e = parsed ? Error{} : parse_block_general(line, block_)) {
            loc_.n = line_label(line);
            fail(e);
            return StepResult::error;
        }
        loc_.n = block_.n;
        if (block_.skip && opt_.block_skip) {
            // The Cazeneuve ends its CNP on a block skip mark (003:1804),
            // even when the switch skips the block.
            if (caz_ && modal_.radcomp != 40 && !CazState::end_comp(*this))
                return StepResult::error;
            after_block(lineno);
            continue;
        }
        if (block_.empty()) {
            after_block(lineno);
            continue;
        }
        break;
    }
    if (++blocks_ > opt_.max_blocks) {
        fail(err::kBlockBudget,
             strf(tr("more than %ld blocks executed: endless loop? (G79/G77)"), opt_.max_blocks));
        return StepResult::error;
    }
    // The work done, not only the blocks: one cycle block makes many moves,
    // and finish_move() stops the one that would pass the move budget.
    size_t depth = stack_.size();
    StepResult r = execute(block_);
    if (r == StepResult::error || ended_) return r;
    // A call pushed a frame: the range end of the caller is checked on return.
    if (stack_.size() == depth) after_block(cur_line_);
    return r;
}

StepResult Interpreter::run_to_end() {
    for (;;) {
        StepResult r = step();
        if (r == StepResult::running || r == StepResult::stopped) continue;
        return r;
    }
}

}  // namespace pupitre
