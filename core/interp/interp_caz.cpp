// The Cazeneuve HB CNC dialect (seed 003, chapter VI; pupitre-cazeneuve(5)): its words
// are read into the interpreter's Plan in internal units (mm, X a radius), and
// the shared steps run it wherever the meaning is the NUM's. What differs is
// here: micrometres, G alone, a blank axis word, T<position><corrector>,
// G7XZ, G33, M30 and M50, and the dialect's error numbers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <array>
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/caz.hpp"
#include "core/interp/gate.hpp"
#include "core/interp/plan.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

// block -> [N] { word } ; word -> address [value] ; the value of a length is
// whole micrometres (003:857-885), an axis address without a value leaves its
// axis where it is (003:997, 1260), G without a value is G00 (003:993).
struct Interpreter::CazDecoder {
    using Reader = bool (CazDecoder::*)(const Word&);
    struct Address {
        char letter;
        int digits;  // most digits a value may have
        bool sign;   // a sign may be written
        bool blank;  // a blank value means something
        Reader read;
    };

    Interpreter& in;
    Plan& p;
    std::bitset<kAddrCount> seen;
    bool has_f = false, has_g7 = false;
    bool cycle = false;  // a fixed cycle's block: F, S, I, K and D are its words
    double f = 0;
    int f_col = 0;

    CazDecoder(Interpreter& i, Plan& plan) : in(i), p(plan) {}

    bool bad(int code, std::string detail) { return in.fail(code, std::move(detail)); }
    static const Address* address_of(Addr a);
    bool word(const Word& w);
    bool number(const Word& w, const Address& a, double& out);
    bool g_word(const Word& w);
    bool axis_word(const Word& w);
    bool centre_word(const Word& w);
    bool f_word(const Word& w);
    bool s_word(const Word& w);
    bool t_word(const Word& w);
    bool m_word(const Word& w);
    bool later_word(const Word& w);
    bool finish();
};

// The addresses of the dialect (003:812, 819, 857-874, 889-898, 1018, 1038,
// 1316, 1405): anything else is a syntax error.
const Interpreter::CazDecoder::Address* Interpreter::CazDecoder::address_of(Addr a) {
    using D = CazDecoder;
    static constexpr Address kTable[] = {
        {'G', 2, false, true, &D::g_word},     {'X', 7, true, true, &D::axis_word},
        {'Z', 7, true, true, &D::axis_word},   {'I', 7, true, true, &D::centre_word},
        {'K', 7, true, true, &D::centre_word}, {'F', 5, false, false, &D::f_word},
        {'S', 4, false, false, &D::s_word},    {'T', 4, false, false, &D::t_word},
        {'M', 2, false, false, &D::m_word},    {'D', 7, false, false, &D::later_word},
    };
    for (const Address& x : kTable)
        if (a == addr1(x.letter)) return &x;
    return nullptr;
}

bool Interpreter::CazDecoder::word(const Word& w) {
    in.col_ = w.col;
    const Address* a = address_of(w.addr);
    if (!a)
        return bad(caz::kSyntax, strf(tr("%s is not an address of this controller"),
                                      std::string(addr_name(w.addr)).c_str()));
    if (seen.test(w.addr) && w.addr != addr1('G') && w.addr != addr1('M'))
        return bad(caz::kTwice, strf(tr("%c written twice in the block"), a->letter));
    seen.set(w.addr);
    if (w.v.kind == Operand::Blank && !a->blank && !(has_g7 || p.g[33]))
        return bad(caz::kNumber, strf(tr("%c needs a value"), a->letter));
    return (this->*a->read)(w);
}

// A whole number within the address's digits: this controller has no decimal
// point (lengths in µm, 003:1115) and no variables.
bool Interpreter::CazDecoder::number(const Word& w, const Address& a, double& out) {
    const Operand& v = w.v;
    if (v.kind != Operand::Number && v.kind != Operand::Blank)
        return bad(caz::kSyntax, strf(tr("%c: this controller has no variables"), a.letter));
    if (v.frac_digits || (v.kind == Operand::Number && v.int_digits == 0))
        return bad(caz::kNumber,
                   strf(tr("%c: whole numbers only (lengths in micrometres)"), a.letter));
    if (v.int_digits > a.digits)
        return bad(caz::kNumber, strf(tr("%c: more than %d digits"), a.letter, a.digits));
    if (v.has_sign && !a.sign) return bad(caz::kNumber, strf(tr("%c takes no sign"), a.letter));
    out = v.neg ? -v.num : v.num;
    return true;
}

// G with two digits, leading zero optional (003:819); G alone is G00 (003:993).
bool Interpreter::CazDecoder::g_word(const Word& w) {
    double v = 0;
    if (!number(w, *address_of(w.addr), v)) return false;
    const int g = int(v);
    const GCode* gc = find_g(g, Dialect::cazeneuve);
    if (!gc) return bad(caz::kUnknownG, strf(tr("G%d is not a function of this controller"), g));
    if (gc->support == Support::later && p.unsupported.g < 0) p.unsupported.g = g;
    p.g.set(size_t(g));
    // The thesis draws the front turret's side with X towards the operator
    // (003:1791, 1915-1919); pupitre's frame has X up: left and right swap.
    p.mode.set(gc->group, g == 41 ? 42 : g == 42 ? 41 : g);
    if (g == 7) has_g7 = true;
    if (CazState::is_cycle(g)) cycle = true;
    return true;
}

// X (a radius) and Z in µm; without a value the axis stays (003:997, ex3
// N50 "G1 G95 X Z-8000"). In a G7 block they name the axes to return; in a
// G96 block X is the tool's radius for the speed (003:1113-1115).
bool Interpreter::CazDecoder::axis_word(const Word& w) {
    const int axis = w.addr == addr1('X') ? X : Z;
    if (has_g7) {
        if (w.v.kind != Operand::Blank)
            return bad(caz::kFunction, tr("G7XZ: X and Z are written without values (003:1083)"));
        p.g59.axis.set(size_t(axis));  // the axes G7 returns (G59 is no word of this dialect)
        return true;
    }
    if (w.v.kind == Operand::Blank) return true;
    double v = 0;
    if (!number(w, *address_of(w.addr), v)) return false;
    if (axis == X && p.g[96]) {
        // Signed: the rear turret works at negative x (003:1110-1119, "Signe
        // de x"), and the speed follows |x of G96 + the move| from there.
        p.spindle.has_x = true;
        p.spindle.x = v * caz::kUm;
        return true;
    }
    p.to.axis.set(size_t(axis));
    p.to.val[size_t(axis)] = v * caz::kUm;
    p.to.inc.set(size_t(axis), in.modal_.incremental || p.mode.dist == 91);
    return true;
}

// I and K: the centre of an arc from the origin, in µm (003:874); written
// without a value they are 0 ("programme K ou K0", 003:1326).
bool Interpreter::CazDecoder::centre_word(const Word& w) {
    double v = 0;
    if (w.v.kind != Operand::Blank && !number(w, *address_of(w.addr), v)) return false;
    const size_t i = w.addr == addr1('I') ? 0 : 2;
    p.to.ijk.set(i);
    p.to.ijk_val[i] = v * caz::kUm;
    CazState::Args& a = in.caz_->args;
    (i == 0 ? a.has_i : a.has_k) = true;
    (i == 0 ? a.i : a.k) = v;
    return true;
}

// F: a feed, a pitch or a dwell, read once the block's G functions are known.
bool Interpreter::CazDecoder::f_word(const Word& w) {
    has_f = true;
    f_col = w.col;
    if (!number(w, *address_of(w.addr), f)) return false;
    in.caz_->args.has_f = true;
    in.caz_->args.f = f;
    return true;
}

// S: rev/min under G97, m/min under G96; four digits (003:898).
bool Interpreter::CazDecoder::s_word(const Word& w) {
    double v = 0;
    if (!number(w, *address_of(w.addr), v)) return false;
    in.caz_->args.has_s = true;
    in.caz_->args.s = v;
    if (cycle) return true;  // G34's S is the pitch (003:1330)
    p.tech.has_s = true;
    p.tech.s = v;
    return true;
}

// T<position><corrector>: T101 is position 1, corrector 01 (003:1038-1039).
bool Interpreter::CazDecoder::t_word(const Word& w) {
    double v = 0;
    if (!number(w, *address_of(w.addr), v)) return false;
    const int t = int(v), pos = t / 100, corr = t % 100;
    const bool front = pos >= 1 && pos <= 4, rear = pos >= 11 && pos <= 14;
    if (!front && !rear)
        return bad(caz::kTool,
                   strf(tr("T%d: turret position %d does not exist (1-4 front, 11-14 rear; "
                           "T<position><corrector>, 003:1028-1039)"),
                        t, pos));
    p.tech.has_t = true;
    p.tech.t = pos;
    p.tech.has_d = true;
    p.tech.d = corr;
    return true;
}

bool Interpreter::CazDecoder::m_word(const Word& w) {
    double v = 0;
    if (!number(w, *address_of(w.addr), v)) return false;
    const int m = int(v);
    if (!find_m(m, Dialect::cazeneuve))
        return bad(caz::kUnknownM, strf(tr("M%d is not a function of this controller"), m));
    // M30 and M50 are this controller's own; the others run as the NUM's.
    if (m == 30) in.caz_->m30 = true;
    if (m == 30 || m == 50) return true;
    if (p.tech.nm >= int(std::size(p.tech.m)))
        return bad(caz::kTwice, tr("too many M functions in the block"));
    p.tech.m[p.tech.nm++] = m;
    return true;
}

// D: the total depth of a fixed cycle (003:1332, 1414).
bool Interpreter::CazDecoder::later_word(const Word& w) {
    double v = 0;
    if (!number(w, *address_of(w.addr), v)) return false;
    in.caz_->args.has_d = true;
    in.caz_->args.d = v;
    return true;
}

// F by what the block is: G4's tenths of a second (003:1018-1019), G33's pitch
// in µm (003:1161), or a feed: mm/min in G94 (003:890), µm/rev in G95
// (003:891, 894: F250 = 0.25 mm/rev).
bool Interpreter::CazDecoder::finish() {
    in.col_ = 0;
    if (p.tech.has_s) {
        p.spindle.g96_s = p.g[96];
        p.spindle.g97_s = p.g[97];
    }
    if (!has_f || cycle) return true;
    in.col_ = f_col;
    const int motion = p.mode.motion >= 0 ? p.mode.motion : in.modal_.motion;
    if (p.g[4]) {
        p.dwell = f * caz::kDwellUnit;
    } else if (motion == 33) {
        in.caz_->pitch = f * caz::kUm;
        if (in.caz_->pitch > caz::kMaxPitch)
            return bad(caz::kPitch,
                       strf(tr("pitch F%s micrometres: above the 60 mm maximum (003:1163)"),
                            fixed3(f, 63).c_str()));
    } else {
        const int mode = p.mode.feed >= 0 ? p.mode.feed : in.modal_.feed_mode;
        p.tech.has_f = true;
        p.tech.f = mode == 95 ? f * caz::kUm : f;
    }
    in.col_ = 0;
    return true;
}

// At power-on the motion is G00: the programs' first moves written without G
// are approaches at rapid (ex11 N50 "X 9500 Z 5000 M3", 003:1294; CNP ex1 N50,
// 003:1843; "un déplacement rapide d'approche", 003:1826); M2 and M30 bring it back.
void Interpreter::caz_power_on() {
    caz_ = std::make_unique<CazState>();
    modal_.motion = 0;
}

// A block of this dialect: decoded into a Plan, then the NUM steps where the
// meaning is the same (the order of pupitre-iso(5), MODAL STATE AND THE ORDER
// INSIDE A BLOCK), with this controller's own functions in their place. G25 S:
// the spindle's limit under constant surface speed, in rev/min. The thesis asks
// for a limit "programmed in the G96 block" and prints its word "G434"
// (003:1124-1126); the one program that limits the speed writes "N50 G25 S1500"
// in a block of its own just before its G96 (003:1571), and 1500 rev/min is the
// S max its example 7 gives (003:1135-1147): G25 S is that limit, as the NUM's
// G92 S. It takes the block's S, so not with G96.
bool Interpreter::caz_speed_limit(Plan& p) {
    if (!p.tech.has_s)
        return fail(caz::kFunction, tr("G25 needs S, the spindle limit in rev/min (003:1571)"));
    if (p.mode.spindle == 96 || p.mode.spindle == 97)
        return fail(caz::kFunction,
                    tr("G25 S in a block of its own, before G96 (003:1571): S is its limit"));
    limit_spindle(25, p.tech.s);
    p.tech.has_s = false;  // a limit, not a speed
    return true;
}

StepResult Interpreter::execute_caz(const Block& b) {
    if (!b.assigns.empty() || b.msg_channel >= 0 || b.test.cmp != Cmp::none) {
        col_ = b.assigns.empty() ? 0 : b.assigns[0].col;
        fail(caz::kSyntax, tr("this controller has no variables, tests or messages"));
        return StepResult::error;
    }
    Plan p;
    caz_->m30 = false;
    caz_->args = CazState::Args{};
    CazDecoder d(*this, p);
    const size_t first = (b.n >= 0 && !b.words.empty() && b.words[0].addr == addr1('N')) ? 1 : 0;
    for (size_t i = first; i < b.words.size(); ++i)
        if (!d.word(b.words[i])) return StepResult::error;
    if (!d.finish()) return StepResult::error;
    if (p.g[25] && !caz_speed_limit(p)) return StepResult::error;
    if (p.unsupported.g >= 0) {
        const GCode* g = find_g(p.unsupported.g, Dialect::cazeneuve);
        fail(caz::kLater, strf(tr("G%d (%s) is not yet run by pupitre"), p.unsupported.g,
                               tr(std::string(g->text).c_str())));
        return StepResult::error;
    }
    // A block skip mark ends the CNP too (003:1804), run or skipped (interp.cpp).
    if (modal_.radcomp != 40 && (b.skip || CazState::ends_comp(*this, p)) &&
        !CazState::end_comp(*this))
        return StepResult::error;
    // The variator changes range by itself (003:720-722): each S finds its own.
    if (p.tech.has_s && modal_.spindle_mode == 97 && p.mode.spindle != 96) modal_.range = -1;
    // T is this controller's own (caz_tool): the shared step sees no T or D.
    Plan shared = p;
    shared.tech.has_t = shared.tech.has_d = false;
    shared.g.reset(92);  // the NUM's origin preset: here a facing cycle
    if (!apply_modal(shared) || !caz_tool(p) || !do_m_avant(p) || !apply_spindle(p))
        return StepResult::error;
    const bool cycle = CazState::cycle_of(p) >= 0;
    if (cycle ? !CazState::cycle(*this, p) : p.g[7] ? !caz_g7(p) : !caz_motion(p))
        return StepResult::error;
    if (p.g[4] && p.dwell < 0) {
        fail(caz::kFunction, tr("G4 needs the time in F, tenths of a second (003:1018)"));
        return StepResult::error;
    }
    if (p.dwell >= 0) {
        clock_ += p.dwell;
        out_.dwell(loc_, p.dwell);
    }
    StepResult r = StepResult::running;
    if (!caz_m(p, r)) return StepResult::error;
    return r;
}

// T turns the turret at once (003:1034-1039): no M06 on this lathe. The tool
// is the position, its corrector the two last digits.
bool Interpreter::caz_tool(const Plan& p) {
    if (!p.tech.has_t) return true;
    if (p.tech.d > m_.correctors)
        return fail(caz::kCorrector,
                    strf(tr("corrector %d: this machine has %d"), p.tech.d, m_.correctors));
    modal_.t = modal_.tool_in_spindle = p.tech.t;
    if (p.tech.d != modal_.d) gauge_pending_.set();  // at each axis's next move, as the NUM
    modal_.d = p.tech.d;
    caz_->turret = p.tech.t;
    note_tool(p.tech.t);
    clock_ += m_.tool_change_time;
    out_.tool(loc_, p.tech.t, p.tech.d, m_.tool_change_time, true);
    return true;
}

// G33 (003:1158-1172): a straight move whose feed per revolution is the
// pitch; the spindle must turn, and the thread speed stays under 3.8 m/min.
bool Interpreter::caz_motion(const Plan& p) {
    if (modal_.motion != 33 || p.to.axis.none()) {
        if ((modal_.motion == 2 || modal_.motion == 3) && (p.to.axis.any() || p.to.ijk.any())) {
            // An arc names its centre by I and K (003:874): this controller has
            // no profile geometry to complete it. Its end is X Z, a blank axis
            // where the tool is.
            if (!p.to.ijk[0] || !p.to.ijk[2])
                return fail(caz::kArc,
                            strf(tr("G%d needs I and K, the centre (003:874)"), modal_.motion));
            Plan q = p;
            for (int a : {int(X), int(Z)})
                if (!q.to.axis[size_t(a)]) {
                    q.to.axis.set(size_t(a));
                    q.to.val[size_t(a)] = prog_[size_t(a)];
                    q.to.inc.reset(size_t(a));
                }
            return do_motion(q);
        }
        return do_motion(p);
    }
    Plan q = p;
    q.g.reset(33);  // the NUM's G33 is a cycle: this one is a plain move
    if (caz_->pitch <= 0) return fail(caz::kFunction, tr("G33 needs the pitch in F (003:1167)"));
    double rpm = spindle_at(prog_[X]);
    if (rpm <= 0) return fail(caz::kSpindleStopped, tr("G33 with the spindle stopped"));
    if (caz_->pitch * rpm > caz::kMaxThreadFeed + 1e-9)
        return fail(caz::kPitch,
                    strf(tr("thread speed %s mm/min above the 3800 mm/min maximum (003:1162)"),
                         fixed3(caz_->pitch * rpm, 63).c_str()));
    const Modal saved = modal_;
    modal_.motion = 1;
    modal_.feed_mode = 95;
    modal_.feed = caz_->pitch;
    modal_.feed_set = true;
    bool ok;
    {
        OwnFeed own(*this);
        ok = do_motion(q);
    }
    modal_.motion = saved.motion;
    modal_.feed_mode = saved.feed_mode;
    modal_.feed = saved.feed;
    modal_.feed_set = saved.feed_set;
    return ok;
}

// G7XZ: a rapid to the turret's indexing point on the axes named (003:1083,
// 1803); it ends the nose-radius compensation (003:1795-1803).
bool Interpreter::caz_g7(const Plan& p) {
    std::bitset<kAxes> axes = p.g59.axis;
    if (axes.none()) axes.set(X).set(Z);
    Axes mach = mach_;
    for (int a : {int(X), int(Z)})
        if (axes[size_t(a)]) mach[size_t(a)] = m_.home[size_t(a)];
    if (!check_travel(mach)) return false;
    first_move_ = false;
    prog_next_ = frames_.to_program(mach);
    if (!linear(0, mach, false, axes)) return false;
    modal_.css_x0 = modal_.css_pos0 = prog_[X];
    return true;
}

// M0 M1 M2 M5 M9 as on the NUM (the shared step); M30 ends the program and
// goes back to its start, which a dry run ends with (003:972); M50 gives the
// handwheel and the tailstock to the operator (003:968): nothing to simulate.
bool Interpreter::caz_m(const Plan& p, StepResult& r) {
    if (!do_m_apres(p, r)) return false;
    if (ended_) modal_.motion = 0;  // M2 reset the modal state to the NUM's power-on one
    if (ended_ || !caz_->m30) return true;
    reset_modal_m02();
    modal_.motion = 0;
    out_.end(loc_, 30);
    ended_ = true;
    r = StepResult::ended;
    return true;
}

}  // namespace pupitre
