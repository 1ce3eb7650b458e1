// Block decoding: words to a Plan (which G owns which word, units, lathe
// diameters), modal changes, spindle, and the M functions before and after the
// motion (turning.md §1.4, §1.7, §5; milling.md §1, §2.4).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstdio>

#include "core/interp/plan.hpp"

namespace pupitre {

namespace {

enum class Fmt : uint8_t { length, angle, feed, speed, integer, label, prog, time, other };

struct AddrFormat {
    Fmt fmt;
    uint8_t max_int, max_frac;
    bool is_signed;
};

AddrFormat format_of(Addr a) {
    if (a < 26) {
        switch (char('A' + a)) {
            case 'X': case 'Y': case 'Z': case 'U': case 'V': case 'W':
            case 'I': case 'J': case 'K': case 'R': case 'P': case 'Q':
                return {Fmt::length, 5, 3, true};
            case 'A': case 'B': case 'C':
                return {Fmt::angle, 5, 4, true};
            case 'F': return {Fmt::feed, 5, 3, false};
            case 'S': return {Fmt::speed, 5, 3, false};
            case 'G': case 'M': return {Fmt::integer, 3, 0, false};
            case 'T': case 'D': return {Fmt::integer, 3, 0, false};
            case 'N': return {Fmt::label, 5, 0, false};
            case 'H': return {Fmt::prog, 4, 0, false};
            default: return {Fmt::other, 5, 4, true};
        }
    }
    if (a < 52) {
        switch (char('A' + a - 26)) {
            case 'A': case 'B': case 'C': case 'D': return {Fmt::angle, 5, 4, true};
            case 'F': return {Fmt::time, 5, 3, false};
            case 'G': return {Fmt::integer, 3, 0, false};
            case 'S': case 'K': return {Fmt::other, 5, 3, false};
            default: return {Fmt::length, 5, 3, true};
        }
    }
    if (a < 78) return {Fmt::integer, 4, 0, false};
    if (a >= 79) return {Fmt::length, 5, 3, true};  // LX LY: the G46 start point
    return {Fmt::other, 0, 0, true};
}

double e_scale(Fmt f) {
    switch (f) {
        case Fmt::length: return 1e-3;   // µm
        case Fmt::angle: return 1e-4;    // 0.0001°
        case Fmt::feed: return 1e-2;     // 0.01 mm/min (000:7602-7604)
        case Fmt::time: return 1e-2;
        default: return 1.0;
    }
}

double round_to(double v, double step) { return std::round(v / step) * step; }

bool is_axis_addr(Addr a, int& axis) {
    if (a >= 26) return false;
    axis = axis_of(char('A' + a));
    return axis >= 0;
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
    std::string why;
    switch (v.kind) {
        case Operand::Blank:
        case Operand::SignOnly:
            out = 0;
            break;
        case Operand::Number:
            if (v.int_digits > f.max_int || v.frac_digits > f.max_frac) {
                fail(1, "too many digits after " + std::string(addr_name(w.addr)), w.col);
                return false;
            }
            if (v.has_sign && !f.is_signed) {
                fail(1, "sign after " + std::string(addr_name(w.addr)) + ", which takes none", w.col);
                return false;
            }
            out = v.neg ? -v.num : v.num;
            break;
        case Operand::LVar:
        case Operand::EParam:
        case Operand::EIndirect: {
            double raw;
            if (int rc = eval_operand(v, l_, *this, raw, why)) {
                fail(rc, why, w.col);
                return false;
            }
            if (v.kind == Operand::LVar) {
                switch (f.fmt) {
                    case Fmt::length: raw = round_to(raw, 1e-3); break;
                    case Fmt::angle: raw = round_to(raw, 1e-4); break;
                    case Fmt::integer: case Fmt::speed: case Fmt::label: case Fmt::prog:
                        // S T D M from a variable: rounded to an integer (program-flow Q15).
                        if (f.fmt == Fmt::speed) s_raw_ = raw;  // warning 1113
                        raw = std::round(raw);
                        break;
                    default: break;
                }
            } else {
                raw *= e_scale(f.fmt);
            }
            if (!f.is_signed && raw < 0) {
                char num[32];
                std::snprintf(num, sizeof num, "%.3f", raw);
                fail(92, std::string("negative value ") + num + " for " +
                             std::string(addr_name(w.addr)) + ", which takes none", w.col);
                return false;
            }
            out = raw;
            break;
        }
    }
    if (int_out) {
        if (out != std::floor(out) || std::fabs(out) > 99999) {
            fail(v.kind == Operand::Number ? 1 : 92,
                 std::string(addr_name(w.addr)) + " needs a whole number", w.col);
            return false;
        }
        *int_out = int(out);
    }
    return true;
}

// Words are scanned left to right. A G function with arguments owns the words that
// follow it while they are in its argument set (turning.md §1.7.2 parser model);
// the other words take their default meaning. G90/G91 act positionally.
bool Interpreter::decode(const Block& b, Plan& p) {
    const bool lathe = m_.lathe;
    const bool diam = lathe && m_.x_diameter && !modal_.radius_x;
    // G70/G71 written in the block set the unit of all its lengths.
    bool inch = modal_.inch;
    for (const Word& w : b.words)
        if (w.addr == addr1('G') && w.v.kind == Operand::Number && (w.v.num == 70 || w.v.num == 71))
            inch = w.v.num == 70;
    const double unit = inch ? 25.4 : 1.0;
    // Is a drilling cycle active for this block (written here, or modal and not
    // cancelled here)? Its words (ER, P, EF…) then have their cycle meaning.
    int cycle_code = -1;
    for (const Word& w : b.words)
        if (w.addr == addr1('G') && w.v.kind == Operand::Number) {
            int g = int(w.v.num);
            if (g == 80 || (g >= 81 && g <= 89) || g == 31) cycle_code = g;
        }
    p.cycle_words = cycle_code == 31 || (cycle_code >= 81 && cycle_code <= 89) ||
                    (cycle_code < 0 && modal_.cycle >= 81 && modal_.cycle <= 89);
    auto cyc_word = [&](const Word& w) {
        double cv;
        if (!word_value(w, cv)) return false;
        if (p.ncyc >= 16) {
            fail(3, "too many cycle words in one block", w.col);
            return false;
        }
        p.cyc[p.ncyc++] = {w.addr, w.addr == addrE('R') || w.addr == addrE('H') ? cv * unit : cv};
        return true;
    };
    bool inc = modal_.incremental;
    const GCode* owner = nullptr;
    int owner_g = -1;
    std::bitset<kAddrCount> seen;
    size_t first = (b.n >= 0 && !b.words.empty() && b.words[0].addr == addr1('N')) ? 1 : 0;
    bool g52_seen = false, axis_seen = false;
    int pqr_sign_col = 0;  // a P± Q± R± met before any G16 (turning.md §1.7.2: error 3)
    int coded_modal = 0, coded_nonmodal = 0;

    for (size_t i = first; i < b.words.size(); ++i) {
        const Word& w = b.words[i];
        col_ = w.col;
        if (w.addr == addr1('G')) {
            int g;
            double gv;
            if (!word_value(w, gv, &g)) return false;
            const GCode* gc = find_g(g);
            if (!gc || !(gc->machines & (lathe ? kLathe : kMill))) {
                std::string hint;
                if (gc && !lathe) hint = " (a lathe function: --machine lathe?)";
                if (gc && lathe) hint = " (a machining-centre function: --machine mill?)";
                fail(2, "G" + std::to_string(g) + " is not a function of the NUM " +
                            (lathe ? "lathe" : "machining centre") + hint, w.col);
                return false;
            }
            if ((gc->starred & (lathe ? kLathe : kMill)) && m_.model == 1020) {
                fail(2, "G" + std::to_string(g) + " needs a NUM 1040 or 1060", w.col);
                return false;
            }
            if (gc->support == Support::option) {
                fail(4, "G" + std::to_string(g) + " (" + std::string(gc->text) +
                            ") is an option this machine does not have", w.col);
                return false;
            }
            if (gc->support == Support::later && p.unsupported < 0) p.unsupported = g;
            p.g.set(size_t(g));
            switch (gc->group) {
                case Group::motion: p.motion = g; break;
                case Group::dist: p.dist = g; inc = (g == 91); break;
                case Group::plane: p.plane = g; break;
                case Group::radcomp: p.radcomp = g; break;
                case Group::prefdec: p.prefdec = g; break;
                case Group::feed: p.feed_mode = g; break;
                case Group::spindle: p.spindle_mode = g; break;
                case Group::units: p.units = g; break;
                case Group::scale: p.scale = g; break;
                case Group::cycle: p.cycle = g; break;
                default: break;
            }
            if (g == 52) {
                if (axis_seen) {
                    fail(3, "G52 must come before the axis words of the block", w.col);
                    return false;
                }
                g52_seen = true;
            }
            if (g == 77) p.g77_level = w.glevel;
            if (g == 77 && w.glevel && m_.model == 1020) {
                fail(4, "G77 -i needs a NUM 1040 or 1060", w.col);
                return false;
            }
            if (g == 79 && w.gsign && m_.model == 1020) {
                fail(4, std::string("G79") + w.gsign + " needs a NUM 1040 or 1060 (000:560)", w.col);
                return false;
            }
            if (g == 79 && w.gsign) p.g79_sign = w.gsign;
            if (g == 76) p.g76_sign = w.gsign;
            owner = gc->args.empty() ? nullptr : gc;
            owner_g = g;
            continue;
        }
        bool owned = owner && g_owns(*owner, w.addr);
        if (!owned) {
            owner = nullptr;
            owner_g = -1;
        }
        char letter = w.addr < 26 ? char('A' + w.addr) : 0;
        double v = 0;
        int axis = -1;
        if (owned) {
            switch (owner_g) {
                case 4:  // G4 F: dwell seconds
                    if (!word_value(w, v)) return false;
                    if (v < 0.01 || v > 99.99) {
                        fail(1, "dwell must be 0.01 to 99.99 s", w.col);
                        return false;
                    }
                    p.dwell = v;
                    continue;
                case 16:
                    if (w.v.kind != Operand::SignOnly) {
                        fail(2, "G16 takes P, Q or R followed by a sign only (G16 R+)", w.col);
                        return false;
                    }
                    p.g16_axis = letter == 'P' ? X : letter == 'Q' ? Y : Z;
                    p.g16_neg = w.v.neg;
                    continue;
                case 51:
                    if (!is_axis_addr(w.addr, axis) || w.v.kind != Operand::SignOnly) {
                        fail(3, "G51 takes axis letters with a sign only (G51 X- Y+)", w.col);
                        return false;
                    }
                    (w.v.neg ? p.g51_on : p.g51_off).set(size_t(axis));
                    continue;
                case 59:
                    if (!word_value(w, v)) return false;
                    if (is_axis_addr(w.addr, axis)) {
                        if (!m_.has(axis)) {
                            fail(1, std::string("axis ") + letter + " is not on this machine", w.col);
                            return false;
                        }
                        // G52/G59 X on a lathe is a radius (turning.md §2.8).
                        p.g59_axis.set(size_t(axis));
                        p.g59_val[size_t(axis)] = is_rotary(axis) ? v : v * unit;
                    } else if (w.addr == addrE('D')) {
                        p.g59_ed = true;
                        p.g59_ed_val = v;
                    } else {
                        int k = letter - 'I';
                        p.g59_ijk.set(size_t(k));
                        p.g59_ijk_val[k] = (k == 0 && diam) ? v * unit / 2 : v * unit;
                    }
                    continue;
                case 92:
                    if (!word_value(w, v)) return false;
                    if (letter == 'S') {
                        p.g92_s = true;
                        p.g92_s_val = v;
                    } else if (letter == 'R') {
                        p.g92_r = true;
                        p.g92_r_val = v * unit;
                    } else if (is_axis_addr(w.addr, axis)) {
                        if (!m_.has(axis)) {
                            fail(1, std::string("axis ") + letter + " is not on this machine", w.col);
                            return false;
                        }
                        p.g92_axis.set(size_t(axis));
                        p.g92_val[size_t(axis)] =
                            is_rotary(axis) ? v : (axis == X && diam ? v * unit / 2 : v * unit);
                    }
                    continue;
                case 96:
                    if (!word_value(w, v)) return false;
                    if (letter == 'X') {
                        p.g96_x = true;
                        p.g96_x_val = diam ? v * unit / 2 : v * unit;
                    } else {
                        p.g96_s = true;
                        p.has_s = true;
                        p.s = v;
                    }
                    continue;
                case 97:
                    if (!word_value(w, v)) return false;
                    p.g97_s = true;
                    p.has_s = true;
                    p.s = v;
                    continue;
                case 93: case 94: case 95:
                    if (!word_value(w, v)) return false;
                    p.g94_f = true;
                    p.has_f = true;
                    p.f = v;
                    continue;
                case 77: {
                    int iv;
                    if (letter == 'N') {
                        if (!word_value(w, v, &iv)) return false;
                        if (p.g77_nn >= 2) {
                            fail(3, "G77 takes at most two N labels", w.col);
                            return false;
                        }
                        p.g77_n[p.g77_nn++] = iv;
                    } else if (letter == 'H') {
                        if (!word_value(w, v, &iv)) return false;
                        p.g77_h = iv;
                    } else if (letter == 'S') {
                        if (!word_value(w, v, &iv)) return false;
                        if (iv < 1 || iv > 100) {
                            fail(1, "G77 S repeat count must be 1 to 100", w.col);
                            return false;
                        }
                        p.g77_s = iv;
                    } else {  // P: PROFIL contour
                        fail(4, "G77 P (PROFIL contour) is an option this machine does not have", w.col);
                        return false;
                    }
                    continue;
                }
                case 79: case 75: case 10: {
                    int iv;
                    if (letter != 'N') continue;  // G10 EF: feed limit after interrupt, unused
                    if (!word_value(w, v, &iv)) return false;
                    if (owner_g == 79) p.g79_n = iv;
                    else if (owner_g == 75) p.g75_n = iv;
                    else p.g10_n = iv;
                    continue;
                }
                case 76: {
                    int iv;
                    if (!word_value(w, v, &iv)) return false;
                    if (letter == 'H') {
                        p.g76_h = iv;
                    } else if (p.g76_nn < 2) {
                        p.g76_n[p.g76_nn++] = iv;
                    } else {
                        fail(3, "G76 takes at most two N labels", w.col);
                        return false;
                    }
                    continue;
                }
                case 33: case 38: case 63: case 64: case 65: case 66:
                    if (is_axis_addr(w.addr, axis)) break;  // end points: below
                    if (letter == 'N') {
                        int iv;
                        if (!word_value(w, v, &iv)) return false;
                        if (p.spl_nn >= 2) {
                            fail(3, "a cycle takes two N labels", w.col);
                            return false;
                        }
                        p.spl_n[p.spl_nn++] = iv;
                        continue;
                    }
                    if (w.addr == addrE('P') && owner_g != 66) {
                        fail(4, "EP (PROFIL contour) is an option this machine does not have", w.col);
                        return false;
                    }
                    if (!cyc_word(w)) return false;
                    continue;
                case 6: case 48: case 49: {
                    int iv;
                    if (!word_value(w, v, &iv)) return false;
                    if (w.addr == addrN('C')) p.spl_nc = iv;
                    else if (letter == 'H') p.spl_h = iv;
                    else if (letter == 'N' && p.spl_nn < 2) p.spl_n[p.spl_nn++] = iv;
                    else {
                        fail(3, "G48 takes NC, H and two N labels", w.col);
                        return false;
                    }
                    continue;
                }
                case 23:
                    break;  // G23 X.. Z.. I.. K..: default meanings below
                case 31: case 45: case 81: case 82: case 83: case 84: case 85: case 86: case 87: case 88: case 89:
                    if (is_axis_addr(w.addr, axis)) break;  // positions and bottom: below
                    if (owner_g == 31 && (letter == 'I' || letter == 'J')) {
                        if (!cyc_word(w)) return false;
                        continue;
                    }
                    if (!cyc_word(w)) return false;
                    continue;
                case 46:  // G46 NU.. (milling.md §7.2): NR+ / NR- keep their sign only
                    if (is_axis_addr(w.addr, axis)) break;
                    if (w.addr == addrN('R')) {
                        if (w.v.kind != Operand::SignOnly && w.v.kind != Operand::Blank) {
                            fail(267, "NR takes a sign only (NR+ climb, NR- conventional)", w.col);
                            return false;
                        }
                        if (p.ncyc >= 16) {
                            fail(3, "too many cycle words in one block", w.col);
                            return false;
                        }
                        p.cyc[p.ncyc++] = {w.addr, w.v.neg ? -1.0 : 1.0};
                        continue;
                    }
                    if (!cyc_word(w)) return false;
                    continue;
                case 78: {
                    // One axis group: G78 P1 synchronises with itself. Each digit of P
                    // names a group (errors.md §3.1: G78 P12345, G78 P3 -> 78).
                    int iv;
                    if (!word_value(w, v, &iv)) return false;
                    if (iv != 1) {
                        fail(78, "G78 P" + std::to_string(iv) + ": this machine has one axis group (P1)", w.col);
                        return false;
                    }
                    p.g78_p = true;
                    continue;
                }
                case 29:  // the surface normal P Q R (milling.md §4.6)
                    if (!word_value(w, v)) return false;
                    p.g29_has.set(size_t(letter - 'P'));
                    p.g29_n[letter - 'P'] = v;
                    continue;
                default:
                    // Arguments of functions not run yet (cycles, splines…).
                    continue;
            }
        }
        // In G29 every block gives the surface normal with P Q R.
        if ((letter == 'P' || letter == 'Q' || letter == 'R') && w.v.kind != Operand::SignOnly &&
            (p.radcomp == 29 || (p.radcomp < 0 && modal_.radcomp == 29))) {
            if (!word_value(w, v)) return false;
            p.g29_has.set(size_t(letter - 'P'));
            p.g29_n[letter - 'P'] = v;
            continue;
        }
        // Default meanings.
        if (seen.test(w.addr) && w.addr != addr1('M') && w.addr != addr1('G')) {
            fail(3, std::string(addr_name(w.addr)) + " written twice in the block", w.col);
            return false;
        }
        seen.set(w.addr);
        if (is_axis_addr(w.addr, axis)) {
            if (!m_.has(axis)) {
                fail(1, std::string("axis ") + letter + " is not on this machine (" + m_.name + ")",
                     w.col);
                return false;
            }
            if (!word_value(w, v)) return false;
            axis_seen = true;
            p.axis.set(size_t(axis));
            if (inc && !g52_seen) p.inc.set(size_t(axis));
            if (is_rotary(axis)) {
                p.val[size_t(axis)] = v;
            } else if (axis == X && lathe) {
                // Absolute X is a diameter; incremental X and G52 X are radii (DESIGN §3).
                bool as_diam = diam && !inc && !g52_seen;
                p.val[size_t(axis)] = as_diam ? v * unit / 2 : v * unit;
            } else {
                p.val[size_t(axis)] = v * unit;
            }
            continue;
        }
        switch (letter) {
            case 'I': case 'J': case 'K': {
                if (p.g[23] && !owned) {
                    fail(3, "the arguments of G23 must not be separated by another address", w.col);
                    return false;
                }
                if (!word_value(w, v)) return false;
                int k = letter - 'I';
                p.ijk.set(size_t(k));
                if (inc) p.ijk_inc.set(size_t(k));
                p.ijk_val[k] = (k == 0 && diam && !inc) ? v * unit / 2 : v * unit;
                continue;
            }
            case 'R':
                if (w.v.kind == Operand::SignOnly) {
                    p.r_sign = w.v.neg ? -1 : 1;
                    if (!pqr_sign_col) pqr_sign_col = w.col;
                    continue;
                }
                if (!word_value(w, v)) return false;
                p.has_r = true;
                p.r = v * unit;
                continue;
            case 'F':
                if (!word_value(w, v)) return false;
                p.has_f = true;
                p.f = v;
                continue;
            case 'S':
                if (!word_value(w, v)) return false;
                p.has_s = true;
                p.s = v;
                continue;
            case 'T': {
                int iv;
                if (!word_value(w, v, &iv)) return false;
                if (iv > m_.tools) {
                    fail(1, "tool T" + std::to_string(iv) + " does not exist (the turret has " +
                                std::to_string(m_.tools) + " stations)", w.col);
                    return false;
                }
                p.has_t = true;
                p.t = iv;
                continue;
            }
            case 'D': {
                int iv;
                if (!word_value(w, v, &iv)) return false;
                if (iv > m_.correctors) {
                    fail(w.v.kind == Operand::Number ? 8 : 92,
                         "corrector D" + std::to_string(iv) + " above D" + std::to_string(m_.correctors),
                         w.col);
                    return false;
                }
                p.has_d = true;
                p.d = iv;
                continue;
            }
            case 'M': {
                int iv;
                if (!word_value(w, v, &iv)) return false;
                if (p.nm >= 8) {
                    fail(3, "too many M functions in one block", w.col);
                    return false;
                }
                // At most one modal and one non-modal coded M per block (004:1063).
                if ((iv >= 200 && iv <= 899 && ++coded_modal > 1) ||
                    (iv >= 100 && iv <= 199 && ++coded_nonmodal > 1)) {
                    fail(3, "two coded M functions of the same kind in one block (M" + std::to_string(iv) + ")",
                         w.col);
                    return false;
                }
                p.m[p.nm++] = iv;
                continue;
            }
            default:
                break;
        }
        if (w.addr == addrE('D')) {
            if (!word_value(w, v)) return false;
            p.has_ed = true;
            p.ed = v;
            continue;
        }
        if (w.addr == addrE('G')) {
            if (!word_value(w, v)) return false;
            if (v < 1 || v > 100) {
                fail(1, "EG (acceleration) must be 1 to 100 %", w.col);
                return false;
            }
            p.has_eg = true;
            p.eg = v;
            continue;
        }
        if (w.addr == addrE('C')) {
            if (!word_value(w, v)) return false;
            p.has_ec = true;
            p.ec = v;
            continue;
        }
        if (w.addr == addrE('M')) {  // EM+/EM-: part extremes for the graphic
            p.em = true;
            continue;
        }
        if (p.cycle_words && (letter == 'P' || letter == 'Q' || w.addr == addrE('R') || w.addr == addrE('H') ||
                              w.addr == addrE('F') || w.addr == addrE('S') || w.addr == addrE('P') ||
                              w.addr == addrE('C') || w.addr == addrE('A') || w.addr == addrE('K'))) {
            if (!cyc_word(w)) return false;
            continue;
        }
        if (w.addr == addrE('A') || w.addr == addrE('B') || w.addr == addrE('S') ||
            w.addr == addrE('T') || w.addr == kAddrEsign) {
            // PGP: ES± ET± carry the discriminant as their sign (pgp.md §2).
            p.pgp = true;
            if (w.addr == addrE('A')) {
                if (!word_value(w, v)) return false;
                p.has_ea = true;
                p.ea = v;
            } else if (w.addr == addrE('B')) {
                if (!word_value(w, v)) return false;
                p.has_eb = true;
                p.eb = v * unit;
                p.eb_unsigned = !w.v.has_sign;
            } else {
                if (w.addr == addrE('S')) p.link = p.link == 'T' ? 'X' : 'S';
                if (w.addr == addrE('T')) p.link = p.link == 'S' ? 'X' : 'T';
                if (w.v.has_sign) p.disc = w.v.neg ? -1 : 1;
                if (w.v.kind == Operand::Number || w.v.kind == Operand::LVar) {
                    fail(w.addr == kAddrEsign ? 3 : 110, std::string(addr_name(w.addr)) + " takes a sign only", w.col);
                    return false;
                }
            }
            continue;
        }
        if ((letter == 'P' || letter == 'Q') && w.v.kind == Operand::SignOnly) {
            if (!pqr_sign_col) pqr_sign_col = w.col;
            continue;
        }
        fail(3, std::string(addr_name(w.addr)) + " has no meaning here (no function in the block takes it)",
             w.col);
        return false;
    }
    if (p.g[16] && p.g16_axis < 0 && pqr_sign_col) {
        fail(3, "the argument of G16 must follow it (G16 R+)", pqr_sign_col);
        return false;
    }
    if (p.g[78] && !p.g78_p) {
        fail(2, "G78 needs P (the axis groups to synchronise)");
        return false;
    }
    // milling.md §8.6 (impl): the axis values after EM+/EM- are the part's
    // extremes for the graphic display, not a move.
    if (p.em) {
        p.axis.reset();
        p.inc.reset();
    }
    return true;
}

}  // namespace pupitre
