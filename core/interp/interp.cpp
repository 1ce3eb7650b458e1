// The interpreter's control flow: fetching blocks, the G77 call stack, G79 jumps,
// M02 and error 20, the block budget, settings and E parameters.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <charconv>
#include <cmath>
#include <span>

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

namespace {
bool parse_double(std::string_view s, double& v) {
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}
}  // namespace

namespace {
// The fields of a corrector a setting names after "D<n>." (000:813-833,
// 000:3763-3791; pupitre-iso(5), TOOLS AND CORRECTORS); a lathe's C, the nose
// orientation, is a whole number.
struct CorrField {
    std::string_view name;
    double Corrector::*v;
};
constexpr CorrField kLatheFields[] = {{"X", &Corrector::x},
                                      {"Z", &Corrector::z},
                                      {"R", &Corrector::r},
                                      {"DX", &Corrector::dx},
                                      {"DZ", &Corrector::dz}};
constexpr CorrField kMillFields[] = {{"L", &Corrector::l},   {"R", &Corrector::r},
                                     {"DL", &Corrector::dl}, {"DR", &Corrector::dr},
                                     {"A", &Corrector::tip}, {"TIP", &Corrector::tip}};

double Corrector::*corr_field(bool lathe, std::string_view f) {
    for (const CorrField& c :
         lathe ? std::span<const CorrField>(kLatheFields) : std::span<const CorrField>(kMillFields))
        if (c.name == f) return c.v;
    return nullptr;
}

// PREF.X, DEC1.Z, DEC3.Y: which origin (0, 1, 2) and the axis letter's index,
// or -1 when the name is not one of them.
int origin_named(std::string_view name, int& axis) {
    static constexpr std::string_view kOrigins[] = {"PREF", "DEC1", "DEC3"};
    for (int k = 0; k < 3; ++k) {
        std::string_view prefix = kOrigins[k];
        if (name.size() != prefix.size() + 2 || name.substr(0, prefix.size()) != prefix ||
            name[prefix.size()] != '.')
            continue;
        axis = axis_of(name.back());
        return axis >= 0 ? k : -1;
    }
    return -1;
}
}  // namespace

std::string Interpreter::set(std::string_view name, double value, bool immediate) {
    int axis;
    if (int k = origin_named(name, axis); k >= 0) {
        if (!m_.has(axis)) return strf(tr("axis %c is not on %s"), name.back(), m_.name.c_str());
        Axes& which = k == 0 ? frames_.pref : k == 1 ? frames_.dec1 : frames_.dec3;
        which[size_t(axis)] = value;
        if (immediate) recompute_program_pos();
        return {};
    }
    if (name.size() >= 2 && name[0] == 'L') {
        double n;
        if (!parse_double(name.substr(1), n) || !LVars::valid(int(n)) || n != std::floor(n))
            return tr("no such L variable (L0-L19, L100-L199, L900-L959)");
        l_.v[size_t(n)] = value;
        l_.written.set(size_t(n));
        return {};
    }
    if (name.size() >= 2 && name[0] == 'E') {
        double n;
        if (!parse_double(name.substr(1), n) || n != std::floor(n))
            return tr("bad E parameter number");
        if (value != std::floor(value)) return tr("E parameters hold integers (internal units)");
        Error e = write_e(int(n), int64_t(value));
        e_written_.erase(int(n));  // a setting, not a write by the program
        return e.detail;
    }
    if (name.size() >= 4 && name[0] == 'D') return set_corrector(name, value);
    // TRANSLATORS: %s is an ellipsis (U+2026); msgids stay ASCII.
    return strf(tr("unknown setting (PREF.X, DEC1.Z, DEC3.Y, D1.R, L5, E80000%s)"), "\u2026");
}

// D<n>.<field> = value.
std::string Interpreter::set_corrector(std::string_view name, double value) {
    size_t dot = name.find('.');
    double d;
    if (dot == std::string_view::npos || !parse_double(name.substr(1, dot - 1), d) || d < 1 ||
        d > m_.correctors || d != std::floor(d))
        return strf(tr("corrector must be D1 to D%d"), int(m_.correctors));
    Corrector& c = corr_[size_t(d)];
    std::string_view f = name.substr(dot + 1);
    // The Cazeneuve's gauges pilot the nose centre under the CNP (003:1912,
    // "régler les jauges de façon à piloter l'axe du rayon de l'outil"): its
    // correctors have no orientation, which is C0, the centre.
    if (m_.lathe && f == "C" && caz_ && value != 0)
        return tr("this controller's gauges pilot the nose centre (003:1912): no orientation C");
    if (m_.lathe && f == "C")
        c.c = int(value);
    else if (double Corrector::*v = corr_field(m_.lathe, f))
        c.*v = value;
    else
        return m_.lathe ? tr("lathe correctors have X Z R C DX DZ")
                        : tr("mill correctors have L R DL DR and the end radius A");
    // The active corrector's new gauge applies at the next move of each of
    // its axes (000:797, 000:843-865; pupitre-iso(5), DECISIONS); a new radius at the next G41/G42.
    if (int(d) == modal_.d) {
        if (m_.lathe)
            gauge_pending_.set(X), gauge_pending_.set(Z);
        else
            gauge_pending_.set(size_t(modal_.tool_axis));
    }
    return {};
}

bool Interpreter::get(std::string_view name, double& out) const {
    int axis;
    if (int k = origin_named(name, axis); k >= 0) {
        out = (k == 0 ? frames_.pref : k == 1 ? frames_.dec1 : frames_.dec3)[size_t(axis)];
        return true;
    }
    if (name.size() >= 4 && name[0] == 'D') {
        size_t dot = name.find('.');
        double d;
        if (dot == std::string_view::npos || !parse_double(name.substr(1, dot - 1), d) || d < 1 ||
            d > 255)
            return false;
        const Corrector& c = corr_[size_t(d)];
        std::string_view f = name.substr(dot + 1);
        if (m_.lathe && f == "C")
            out = c.c;
        else if (double Corrector::*v = corr_field(m_.lathe, f))
            out = c.*v;
        else
            return false;
        return true;
    }
    return false;
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
        if (!parsed && !parse_block_general(line, block_, parse_error_)) {
            loc_.n = line_label(line);
            fail(parse_error_);
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

// ---- E parameters (000:7573-7735; pupitre-iso(5), E parameters) ----

Error Interpreter::e_rights(int n, bool write) const {
    auto ro = [&]() -> Error {
        if (!write) return {};
        return {95, strf(tr("E%d is read-only"), n)};
    };
    int type = n / 10000;
    int x = (n / 1000) % 10;  // axis index for E6x/E7x
    int k = n % 1000;
    if (n >= 10000 && n <= 10031) return {};
    if (n >= 20000 && n <= 20031) return ro();
    if (n >= 30000 && n <= 30127) return {};
    if (n >= 40000 && n <= 40127) return ro();
    if (n == 11000 || n == 11001 || n == 11003 || n == 11004 || n == 11005 || n == 11007 ||
        n == 11015)
        return {};
    if (n >= 21000 && n <= 21255) return ro();
    if (n == 31000 || n == 31001 || n == 32000) return {};
    if (n == 41000) return ro();
    if (n >= 50000 && n <= 50000) return ro();
    if (n == 51000 || n == 52000) return ro();
    if (type == 5 && k >= 1 && k <= 255 && n < 58000) return {};
    if (type == 6 && x <= 8 && k <= 5) return {};
    if (n == 69000) return {};
    if (type == 7 && x <= 8 && k <= 6) return (k == 5 || k == 6) ? Error{} : ro();
    if (n >= 79000 && n <= 79004) return n == 79003 ? Error{} : ro();
    if (n >= 80000 && n <= 80049) return {};
    if (n == 81000 || n == 82000) return {};
    if (n >= 90000 && n <= 93007 && (n % 1000) <= 7) return ro();
    return {91, strf(tr("E%d does not exist"), n)};
}

namespace {
int64_t um(double mm) {
    return int64_t(std::llround(mm * 1000.0));
}
double mm_of(int64_t v) {
    return double(v) / 1000.0;
}
}  // namespace

// An E access stops the block preparation: not under compensation (140) nor
// after an incomplete profile block (96) (000:7596-7642, 000:13236).
Error Interpreter::e_access() const {
    if (modal_.radcomp != 40)
        return {140, tr("E parameter access under radius compensation (G41/G42)")};
    if (pgp_.pending()) return {96, tr("E parameter access after an incomplete profile block")};
    return {};
}

Error Interpreter::read_e(int n, int64_t& out) {
    if (Error err = e_access()) return err;
    if (Error err = e_rights(n, false)) return err;
    out = e_value(n);
    return {};
}

// What E<n> reads (000:7573-7735; pupitre-iso(5), E parameters): the machine's state for
// the parameters that show it, else what was written or set.
int64_t Interpreter::e_value(int n) const {
    const int x = (n / 1000) % 10, k = n % 1000, type = n / 10000;
    switch (n) {
        case 11005:
            return (m_.lathe && m_.x_diameter && !modal_.radius_x) ? 1 : 0;
        case 11000:
            return frames_.ed != 0;
        case 11003:
            return frames_.mirror.any();
        case 11004:
            return frames_.scale_on;
        case 50000:
            return modal_.d;
        case 51000:
            return corr_[size_t(modal_.d)].c;
        case 52000:
            return um(corr_[size_t(modal_.d)].r);
        case 69000:
            return e_raw(n, 1000);
        case 73000:
        case 74000:
            return 0;
        case 79001:
            return int64_t(std::llround(rpm_));
        case 79002:
            return 100;
        default:
            break;
    }
    if (n >= 21000 && n <= 21255) return 1;
    if (type == 5 && k >= 1 && k <= 255 && n < 56000) {
        const Corrector& c = corr_[size_t(k)];
        if (x == 5) return c.c;
        const double lathe[] = {c.x, c.z, c.r, c.dx, c.dz};
        const double mill[] = {c.l, c.tip, c.r, c.dl, c.dr};
        return um(m_.lathe ? lathe[x] : mill[x]);
    }
    if ((type == 6 && x <= 8 && k <= 5) || (type == 7 && x <= 8 && k <= 6)) return e_axis(n);
    return e_raw(n, 0);
}

// E6xxxx and E7xxxx: an axis's origins, travel limits and position.
int64_t Interpreter::e_axis(int n) const {
    const int x = (n / 1000) % 10, k = n % 1000, type = n / 10000;
    auto unit = [&](double v) { return is_rotary(x) ? int64_t(std::llround(v * 1e4)) : um(v); };
    const AxisConfig& lim = m_.axes[size_t(x)];
    if (type == 6) {
        const Axes* src[] = {&frames_.pref, &frames_.dec1, nullptr,
                             nullptr,       &frames_.dec3, &frames_.g59};
        if (src[k]) return unit((*src[k])[size_t(x)]);
        return e_raw(n, unit(k == 2 ? lim.min : lim.max));
    }
    if (k == 0 || k == 1) return unit(prog_[size_t(x)]);
    if (k == 2) return unit(lim.min);
    if (k == 3) return unit(lim.max);
    return e_raw(n, 0);
}

// What was written to E<n> or set, or `none`.
int64_t Interpreter::e_raw(int n, int64_t none) const {
    auto it = e_raw_.find(n);
    return it == e_raw_.end() ? none : it->second;
}

Error Interpreter::write_e(int n, int64_t value) {
    if (Error err = e_access()) return err;
    if (Error err = e_rights(n, true)) return err;
    if (value > INT32_MAX || value < INT32_MIN)
        return {92, strf(tr("value %lld does not fit an E parameter"), (long long)value)};
    int x = (n / 1000) % 10, k = n % 1000, type = n / 10000;
    auto from = [&](int axis) { return is_rotary(axis) ? double(value) / 1e4 : mm_of(value); };
    e_written_[n] = value;
    if (n == 11005) {
        if (m_.lathe && m_.x_diameter) modal_.radius_x = value == 0;
        return {};
    }
    if (type == 5 && k >= 1 && k <= 255 && n < 56000) {
        Corrector& c = corr_[size_t(k)];
        int fam = (n / 1000) % 10;
        if (m_.lathe) {
            double* f[] = {&c.x, &c.z, &c.r, &c.dx, &c.dz};
            if (fam == 5)
                c.c = int(value);
            else
                *f[fam] = mm_of(value);
        } else {
            double* f[] = {&c.l, &c.tip, &c.r, &c.dl, &c.dr};
            if (fam == 5)
                c.c = int(value);
            else
                *f[fam] = mm_of(value);
        }
        if (k == modal_.d) gauge_pending_.set();
        return {};
    }
    if (type == 6 && x <= 8 && k <= 5 && k != 2 && k != 3) {
        Axes* dst[] = {&frames_.pref, &frames_.dec1, nullptr, nullptr, &frames_.dec3, &frames_.g59};
        (*dst[k])[size_t(x)] = from(x);
        recompute_program_pos();
        return {};
    }
    if (n == 69000) {
        if (value < 1 || value > 9999000)
            return {92, tr("scale factor E69000 must be 1 to 9999000 (0.001 to 9999)")};
        e_raw_[n] = value;
        frames_.scale = double(value) / 1000.0;
        recompute_program_pos();
        return {};
    }
    e_raw_[n] = value;
    if (type == 6 && (k == 2 || k == 3)) update_travel();
    return {};
}

}  // namespace pupitre
