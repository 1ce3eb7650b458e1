// Block decoding: words to a Plan (which G owns which word, units, lathe
// diameters): the value of a word, the G words and the default meaning of each
// address (000:362-500, 000:510-587; pupitre-iso(5), WORDS). The words a G function owns
// are read in interp_args.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <array>
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/decode.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

namespace {

enum class Fmt : uint8_t { length, angle, feed, speed, integer, label, prog, time, other };

struct AddrFormat {
    Fmt fmt;
    uint8_t max_int, max_frac;
    bool is_signed;
};

// The format of each address (block.hpp: A-Z, EA-EZ, NA-NZ, E+, LA-LZ).
constexpr AddrFormat format_rule(Addr a) {
    if (a < 26) {
        switch (char('A' + a)) {
            case 'X':
            case 'Y':
            case 'Z':
            case 'U':
            case 'V':
            case 'W':
            case 'I':
            case 'J':
            case 'K':
            case 'R':
            case 'P':
            case 'Q':
                return {Fmt::length, 5, 3, true};
            case 'A':
            case 'B':
            case 'C':
                return {Fmt::angle, 5, 4, true};
            case 'F':
                return {Fmt::feed, 5, 3, false};
            case 'S':
                return {Fmt::speed, 5, 3, false};
            case 'G':
            case 'M':
                return {Fmt::integer, 3, 0, false};
            case 'T':
            case 'D':
                return {Fmt::integer, 3, 0, false};
            case 'N':
                return {Fmt::label, 5, 0, false};
            case 'H':
                return {Fmt::prog, 4, 0, false};
            default:
                return {Fmt::other, 5, 4, true};
        }
    }
    if (a < 52) {
        switch (char('A' + a - 26)) {
            case 'A':
            case 'B':
            case 'C':
            case 'D':
                return {Fmt::angle, 5, 4, true};
            case 'F':
                return {Fmt::time, 5, 3, false};
            case 'G':
                return {Fmt::integer, 3, 0, false};
            case 'S':
            case 'K':
                return {Fmt::other, 5, 3, false};
            default:
                return {Fmt::length, 5, 3, true};
        }
    }
    if (a < 78) return {Fmt::integer, 4, 0, false};
    if (a >= 79) return {Fmt::length, 5, 3, true};  // LX LY: the G46 start point
    return {Fmt::other, 0, 0, true};
}

// By table: word_value and Decoder::value look it up for every word.
constexpr std::array<AddrFormat, kAddrCount> kFormats = [] {
    std::array<AddrFormat, kAddrCount> t{};
    for (int a = 0; a < kAddrCount; ++a) t[size_t(a)] = format_rule(Addr(a));
    return t;
}();
AddrFormat format_of(Addr a) {
    return a < kAddrCount ? kFormats[a] : format_rule(a);
}

double e_scale(Fmt f) {
    switch (f) {
        case Fmt::length:
            return 1e-3;  // µm
        case Fmt::angle:
            return 1e-4;  // 0.0001°
        case Fmt::feed:
            return 1e-2;  // 0.01 mm/min (000:7602-7604)
        case Fmt::time:
            return 1e-2;
        default:
            return 1.0;
    }
}

double round_to(double v, double step) {
    return std::round(v / step) * step;
}

}  // namespace

bool Interpreter::word_value(const Word& w, double& out, int* int_out) {
    AddrFormat f = format_of(w.addr);
    const Operand& v = w.v;
    col_ = w.col;
    if (v.kind == Operand::Number && v.int_digits <= f.max_int && v.frac_digits <= f.max_frac &&
        (!v.has_sign || f.is_signed)) {
        out = v.neg ? -v.num : v.num;
        if (!int_out) return true;
        if (v.frac_digits == 0) {
            *int_out = int(out);
            return true;
        }
    }
    switch (v.kind) {
        case Operand::Blank:
        case Operand::SignOnly:
            out = 0;
            break;
        case Operand::Number:
            if (v.int_digits > f.max_int || v.frac_digits > f.max_frac)
                return fail(
                    1, strf(tr("too many digits after %s"), std::string(addr_name(w.addr)).c_str()),
                    w.col);
            if (v.has_sign && !f.is_signed)
                return fail(1,
                            strf(tr("sign after %s, which takes none"),
                                 std::string(addr_name(w.addr)).c_str()),
                            w.col);
            out = v.neg ? -v.num : v.num;
            break;
        case Operand::LVar:
        case Operand::EParam:
        case Operand::EIndirect:
            if (!variable_value(w, out)) return false;
            break;
    }
    if (int_out) {
        if (out != std::floor(out) || std::fabs(out) > 99999)
            return fail(v.kind == Operand::Number ? 1 : 92,
                        strf(tr("%s needs a whole number"), std::string(addr_name(w.addr)).c_str()),
                        w.col);
        *int_out = int(out);
    }
    return true;
}

// A word whose value is an L or E variable: L values are rounded to the
// address's resolution, E values are in its internal unit.
bool Interpreter::variable_value(const Word& w, double& out) {
    AddrFormat f = format_of(w.addr);
    const Operand& v = w.v;
    double raw;
    if (Error e = eval_operand(v, l_, *this, raw)) return fail(e.code, e.detail, w.col);
    if (v.kind == Operand::LVar) {
        switch (f.fmt) {
            case Fmt::length:
                raw = round_to(raw, 1e-3);
                break;
            case Fmt::angle:
                raw = round_to(raw, 1e-4);
                break;
            case Fmt::integer:
            case Fmt::speed:
            case Fmt::label:
            case Fmt::prog:
                // S T D M from a variable: rounded to an integer (program-flow Q15).
                if (f.fmt == Fmt::speed) s_raw_ = raw;  // warning 1113
                raw = std::round(raw);
                break;
            default:
                break;
        }
    } else {
        raw *= e_scale(f.fmt);
    }
    if (!f.is_signed && raw < 0)
        return fail(92,
                    strf(tr("negative value %s for %s, which takes none"), fixed3(raw).c_str(),
                         std::string(addr_name(w.addr)).c_str()),
                    w.col);
    out = raw;
    return true;
}

// Words are scanned left to right. A G function with arguments owns the words that
// follow it while they are in its argument set (000:13178; pupitre-iso(5), WORDS);
// the other words take their default meaning. G90/G91 act positionally.
bool Interpreter::decode(const Block& b, Plan& p) {
    Decoder d(*this, p, b);
    size_t first = (b.n >= 0 && !b.words.empty() && b.words[0].addr == addr1('N')) ? 1 : 0;
    for (size_t i = first; i < b.words.size(); ++i)
        if (!d.word(b.words[i])) return false;
    col_ = 0;  // what is wrong from here on is the block's, not one word's
    return d.finish();
}

// A number written within its address's format, most words, is read here;
// anything else (a variable, a blank, too many digits, a sign where none
// goes) by word_value, which says what is wrong.
bool Interpreter::Decoder::value(const Word& w, double& out, int* int_out) {
    const AddrFormat f = format_of(w.addr);
    const Operand& v = w.v;
    if (v.kind == Operand::Number && v.int_digits <= f.max_int && v.frac_digits <= f.max_frac &&
        (!v.has_sign || f.is_signed) && (!int_out || v.frac_digits == 0)) {
        in.col_ = w.col;
        out = v.neg ? -v.num : v.num;
        if (int_out) *int_out = int(out);
        return true;
    }
    return in.word_value(w, out, int_out);
}

Interpreter::Decoder::Decoder(Interpreter& interp, Plan& plan, const Block& b)
    : in(interp),
      p(plan),
      m(in.m_),
      lathe(m.lathe),
      diam(lathe && m.x_diameter && !in.modal_.radius_x),
      inc(in.modal_.incremental) {
    // G70/G71 written in the block set the unit of all its lengths. Is a
    // drilling cycle active for this block (written here, or modal and not
    // cancelled here)? Its words (ER, P, EF…) then have their cycle meaning.
    bool inch = in.modal_.inch;
    int cycle_code = -1;
    for (const Word& w : b.words) {
        if (w.addr != addr1('G') || w.v.kind != Operand::Number) continue;
        const double g = w.v.num;
        if (g == 70 || g == 71) inch = g == 70;
        const int gi = g >= 0 && g < 1e6 ? int(g) : -1;  // no UB on G1e41
        if (gi == 80 || (gi >= 81 && gi <= 89) || gi == 31) cycle_code = gi;
    }
    unit = inch ? 25.4 : 1.0;
    const int modal_cycle = in.modal_.cycle;
    p.cycle_words.active = cycle_code == 31 || (cycle_code >= 81 && cycle_code <= 89) ||
                           (cycle_code < 0 && modal_cycle >= 81 && modal_cycle <= 89);
}

bool Interpreter::Decoder::bad(int code, std::string detail, int column) {
    return in.fail(code, std::move(detail), column);
}

bool Interpreter::Decoder::axis_addr(Addr a, int& axis) {
    if (a >= 26) return false;
    axis = axis_of(char('A' + a));
    return axis >= 0;
}

// word -> G word | owned word (the owner's reader) | plain word
bool Interpreter::Decoder::word(const Word& w) {
    in.col_ = w.col;
    if (w.addr == addr1('G')) return g_word(w);
    owned = owner && g_owns(*owner, w.addr);
    if (!owned) {
        owner = nullptr;
        owner_g = -1;
        return plain_word(w);
    }
    const ArgReader* r = arg_reader(owner_g);
    int axis;
    if (!r->read || (r->axes_plain && axis_addr(w.addr, axis))) return plain_word(w);
    return (this->*r->read)(w);
}

// Checks that need the whole block.
bool Interpreter::Decoder::finish() {
    if (p.g[16] && p.g16.axis < 0 && pqr_sign_col)
        return bad(3, tr("the argument of G16 must follow it (G16 R+)"), pqr_sign_col);
    if (p.g[78] && !p.flow.g78_p) return bad(2, tr("G78 needs P (the axis groups to synchronise)"));
    // The axis values after EM+/EM- are the part's extremes for the graphic
    // display, not a move (docs/decisions.md, EM- and EM+).
    if (p.to.em) {
        p.to.axis.reset();
        p.to.inc.reset();
    }
    return true;
}

// ---------------------------------------------------------------------------
// G words.

bool Interpreter::Decoder::g_word(const Word& w) {
    int g;
    double gv;
    if (!value(w, gv, &g)) return false;
    const GCode* gc = find_g(g);
    if (!g_known(g, gc, w)) return false;
    if (gc->support == Support::later && p.unsupported.g < 0) p.unsupported.g = g;
    p.g.set(size_t(g));
    g_group(g, gc->group);
    if (!g_marks(g, w)) return false;
    owner = gc->args.empty() ? nullptr : gc;
    owner_g = g;
    return true;
}

// Whether this machine and model have G`g`.
bool Interpreter::Decoder::g_known(int g, const GCode* gc, const Word& w) {
    if (!gc || !(gc->machines & (lathe ? kLathe : kMill))) {
        const char* what;
        if (lathe)
            what = gc ? tr("G%d is not a function of the NUM lathe (a machining-centre function: "
                           "--machine mill?)")
                      : tr("G%d is not a function of the NUM lathe");
        else
            what = gc ? tr("G%d is not a function of the NUM machining centre (a lathe function: "
                           "--machine lathe?)")
                      : tr("G%d is not a function of the NUM machining centre");
        return bad(2, strf(what, g), w.col);
    }
    if ((gc->starred & (lathe ? kLathe : kMill)) && m.model == 1020)
        return bad(2, strf(tr("G%d needs a NUM 1040 or 1060"), g), w.col);
    if (gc->support == Support::option)
        return bad(4,
                   strf(tr("G%d (%s) is an option this machine does not have"), g,
                        tr(std::string(gc->text).c_str())),
                   w.col);
    return true;
}

// The G that the block keeps for a modal group (the last one written).
void Interpreter::Decoder::g_group(int g, Group group) {
    p.mode.set(group, g);
    if (group == Group::dist) inc = (g == 91);
}

// What G52, G77 -i, G79± and G76± say by where or how they are written.
bool Interpreter::Decoder::g_marks(int g, const Word& w) {
    if (g == 52) {
        if (axis_seen) return bad(3, tr("G52 must come before the axis words of the block"), w.col);
        g52_seen = true;
    }
    if (g == 77) p.g77.level = w.glevel;
    if (g == 77 && w.glevel && m.model == 1020)
        return bad(4, tr("G77 -i needs a NUM 1040 or 1060"), w.col);
    if (g == 79 && w.gsign && m.model == 1020)
        return bad(4, strf(tr("G79%c needs a NUM 1040 or 1060 (000:560)"), w.gsign), w.col);
    if (g == 79 && w.gsign) p.flow.g79_sign = w.gsign;
    if (g == 76) p.g76.sign = w.gsign;
    return true;
}

// ---------------------------------------------------------------------------
// Default meanings.

bool Interpreter::Decoder::plain_word(const Word& w) {
    // In G29 every block gives the surface normal with P Q R.
    const char c = letter(w);
    if ((c == 'P' || c == 'Q' || c == 'R') && w.v.kind != Operand::SignOnly &&
        (p.mode.radcomp == 29 || (p.mode.radcomp < 0 && in.modal_.radcomp == 29)))
        return g29_normal(w);
    if (seen.test(w.addr) && w.addr != addr1('M') && w.addr != addr1('G'))
        return bad(
            3, strf(tr("%s written twice in the block"), std::string(addr_name(w.addr)).c_str()),
            w.col);
    seen.set(w.addr);
    return (this->*plain_readers()[w.addr])(w);
}

// The reader of each address outside the arguments of a G function.
const std::array<Interpreter::Decoder::Reader, kAddrCount>& Interpreter::Decoder::plain_readers() {
    static constexpr std::array<Reader, kAddrCount> table = [] {
        std::array<Reader, kAddrCount> t{};
        t.fill(&Decoder::no_meaning);
        for (char c : std::string_view("XYZUVWABC")) t[addr1(c)] = &Decoder::axis_word;
        t[addr1('I')] = t[addr1('J')] = t[addr1('K')] = &Decoder::ijk_word;
        t[addr1('R')] = &Decoder::r_word;
        t[addr1('F')] = &Decoder::feed_word;
        t[addr1('S')] = &Decoder::speed_word;
        t[addr1('T')] = &Decoder::tool_word;
        t[addr1('D')] = &Decoder::corrector_word;
        t[addr1('M')] = &Decoder::m_word;
        t[addrE('D')] = &Decoder::ed_word;
        t[addrE('G')] = &Decoder::eg_word;
        t[addrE('C')] = &Decoder::ec_word;
        t[addrE('M')] = &Decoder::em_word;
        for (Addr a :
             {addr1('P'), addr1('Q'), addrE('R'), addrE('H'), addrE('F'), addrE('P'), addrE('K')})
            t[a] = &Decoder::cycle_or_sign;
        t[addrE('S')] = t[addrE('A')] = &Decoder::cycle_or_pgp;
        t[addrE('B')] = t[addrE('T')] = t[kAddrEsign] = &Decoder::pgp_word;
        return t;
    }();
    return table;
}

bool Interpreter::Decoder::axis_word(const Word& w) {
    const int axis = axis_of(letter(w));
    if (!m.has(axis))
        return bad(1, strf(tr("axis %c is not on this machine (%s)"), letter(w), m.name.c_str()),
                   w.col);
    double v;
    if (!value(w, v)) return false;
    axis_seen = true;
    p.to.axis.set(size_t(axis));
    if (inc && !g52_seen) p.to.inc.set(size_t(axis));
    if (is_rotary(axis)) {
        p.to.val[size_t(axis)] = v;
    } else if (axis == X && lathe) {
        // Absolute X is a diameter; incremental X and G52 X are radii
        // (pupitre-iso(5), UNITS AND THE LATHE X AXIS).
        bool as_diam = diam && !inc && !g52_seen;
        p.to.val[size_t(axis)] = as_diam ? v * unit / 2 : v * unit;
    } else {
        p.to.val[size_t(axis)] = v * unit;
    }
    return true;
}

bool Interpreter::Decoder::ijk_word(const Word& w) {
    if (p.g[23] && !owned)
        return bad(3, tr("the arguments of G23 must not be separated by another address"), w.col);
    double v;
    if (!value(w, v)) return false;
    int k = letter(w) - 'I';
    p.to.ijk.set(size_t(k));
    if (inc) p.to.ijk_inc.set(size_t(k));
    p.to.ijk_val[k] = (k == 0 && diam && !inc) ? v * unit / 2 : v * unit;
    return true;
}

bool Interpreter::Decoder::r_word(const Word& w) {
    if (w.v.kind == Operand::SignOnly) {
        p.to.r_sign = w.v.neg ? -1 : 1;
        if (!pqr_sign_col) pqr_sign_col = w.col;
        return true;
    }
    double v;
    if (!value(w, v)) return false;
    p.to.has_r = true;
    p.to.r = v * unit;
    return true;
}

bool Interpreter::Decoder::feed_word(const Word& w) {
    double v;
    if (!value(w, v)) return false;
    p.tech.has_f = true;
    p.tech.f = v;
    return true;
}

bool Interpreter::Decoder::speed_word(const Word& w) {
    double v;
    if (!value(w, v)) return false;
    p.tech.has_s = true;
    p.tech.s = v;
    return true;
}

bool Interpreter::Decoder::tool_word(const Word& w) {
    int iv;
    double v;
    if (!value(w, v, &iv)) return false;
    if (iv > m.tools)
        return bad(
            1, strf(tr("tool T%d does not exist (the turret has %d stations)"), iv, int(m.tools)),
            w.col);
    p.tech.has_t = true;
    p.tech.t = iv;
    return true;
}

bool Interpreter::Decoder::corrector_word(const Word& w) {
    int iv;
    double v;
    if (!value(w, v, &iv)) return false;
    if (iv > m.correctors)
        return bad(w.v.kind == Operand::Number ? 8 : 92,
                   strf(tr("corrector D%d above D%d"), iv, int(m.correctors)), w.col);
    p.tech.has_d = true;
    p.tech.d = iv;
    return true;
}

bool Interpreter::Decoder::m_word(const Word& w) {
    int iv;
    double v;
    if (!value(w, v, &iv)) return false;
    if (p.tech.nm >= 8) return bad(3, tr("too many M functions in one block"), w.col);
    // At most one modal and one non-modal coded M per block (004:1063).
    if ((iv >= 200 && iv <= 899 && ++coded_modal > 1) ||
        (iv >= 100 && iv <= 199 && ++coded_nonmodal > 1))
        return bad(3, strf(tr("two coded M functions of the same kind in one block (M%d)"), iv),
                   w.col);
    p.tech.m[p.tech.nm++] = iv;
    return true;
}

bool Interpreter::Decoder::ed_word(const Word& w) {
    double v;
    if (!value(w, v)) return false;
    p.tech.has_ed = true;
    p.tech.ed = v;
    return true;
}

bool Interpreter::Decoder::eg_word(const Word& w) {
    double v;
    if (!value(w, v)) return false;
    // xgettext:no-c-format
    if (v < 1 || v > 100) return bad(1, tr("EG (acceleration) must be 1 to 100 %"), w.col);
    p.tech.has_eg = true;
    p.tech.eg = v;
    return true;
}

bool Interpreter::Decoder::ec_word(const Word& w) {
    double v;
    if (!value(w, v)) return false;
    p.tech.has_ec = true;
    p.tech.ec = v;
    return true;
}

bool Interpreter::Decoder::em_word(const Word&) {  // EM+/EM-: part extremes for the graphic
    p.to.em = true;
    return true;
}

// P Q ER EH EF EP EK: words of the active drilling cycle; else P± Q± alone.
bool Interpreter::Decoder::cycle_or_sign(const Word& w) {
    if (p.cycle_words.active) return cyc_word(w);
    const char c = letter(w);
    if ((c == 'P' || c == 'Q') && w.v.kind == Operand::SignOnly) {
        if (!pqr_sign_col) pqr_sign_col = w.col;
        return true;
    }
    return no_meaning(w);
}

// ES EA: words of the active drilling cycle, else of the profile geometry.
bool Interpreter::Decoder::cycle_or_pgp(const Word& w) {
    return p.cycle_words.active ? cyc_word(w) : pgp_word(w);
}

// EA EB ES ET E±: profile geometry; ES± ET± carry the discriminant as their
// sign (000:8378-8388; pupitre-iso(5), PROFILE GEOMETRY PROGRAMMING (PGP)).
bool Interpreter::Decoder::pgp_word(const Word& w) {
    p.pgp.any = true;
    double v;
    if (w.addr == addrE('A')) {
        if (!value(w, v)) return false;
        p.pgp.has_ea = true;
        p.pgp.ea = v;
    } else if (w.addr == addrE('B')) {
        if (!value(w, v)) return false;
        p.pgp.has_eb = true;
        p.pgp.eb = v * unit;
        p.pgp.eb_unsigned = !w.v.has_sign;
    } else {
        if (w.addr == addrE('S')) p.pgp.link = p.pgp.link == 'T' ? 'X' : 'S';
        if (w.addr == addrE('T')) p.pgp.link = p.pgp.link == 'S' ? 'X' : 'T';
        if (w.v.has_sign) p.pgp.disc = w.v.neg ? -1 : 1;
        if (w.v.kind == Operand::Number || w.v.kind == Operand::LVar)
            return bad(w.addr == kAddrEsign ? 3 : 110,
                       strf(tr("%s takes a sign only"), std::string(addr_name(w.addr)).c_str()),
                       w.col);
    }
    return true;
}

bool Interpreter::Decoder::no_meaning(const Word& w) {
    return bad(3,
               strf(tr("%s has no meaning here (no function in the block takes it)"),
                    std::string(addr_name(w.addr)).c_str()),
               w.col);
}

// A word of a cycle, kept for the cycle to read (lengths ER EH in mm).
bool Interpreter::Decoder::cyc_word(const Word& w) {
    double cv;
    if (!value(w, cv)) return false;
    if (p.cycle_words.n >= 16) return bad(3, tr("too many cycle words in one block"), w.col);
    p.cycle_words.word[p.cycle_words.n++] = {
        w.addr, w.addr == addrE('R') || w.addr == addrE('H') ? cv * unit : cv};
    return true;
}

// G29: the surface normal P Q R (000:3545, 004:697-699; pupitre-iso(5), G29).
bool Interpreter::Decoder::g29_normal(const Word& w) {
    double v;
    if (!value(w, v)) return false;
    p.g29.has.set(size_t(letter(w) - 'P'));
    p.g29.n[letter(w) - 'P'] = v;
    return true;
}

}  // namespace pupitre
