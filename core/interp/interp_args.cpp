// Block decoding, the words a G function owns (000:13178; pupitre-iso(5), WORDS): G4 F, G59
// X.., G77 N.. N.. H.., the cycle words… one reader per function, picked by
// its number.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/i18n.hpp"
#include "core/interp/decode.hpp"

namespace pupitre {

const Interpreter::Decoder::ArgReader* Interpreter::Decoder::arg_reader(int g) {
    static constexpr ArgReader table[] = {
        {4, false, &Decoder::g4_dwell},
        {16, false, &Decoder::g16_arg},
        {51, false, &Decoder::g51_arg},
        {59, false, &Decoder::g59_arg},
        {92, false, &Decoder::g92_arg},
        {96, false, &Decoder::g96_arg},
        {97, false, &Decoder::g97_arg},
        {93, false, &Decoder::feed_mode_arg},
        {94, false, &Decoder::feed_mode_arg},
        {95, false, &Decoder::feed_mode_arg},
        {77, false, &Decoder::g77_arg},
        {79, false, &Decoder::label_arg},
        {75, false, &Decoder::label_arg},
        {10, false, &Decoder::label_arg},
        {76, false, &Decoder::g76_arg},
        {6, false, &Decoder::spline_arg},
        {48, false, &Decoder::spline_arg},
        {49, false, &Decoder::spline_arg},
        {78, false, &Decoder::g78_arg},
        {29, false, &Decoder::g29_normal},
        {23, false, nullptr},  // G23 X.. Z.. I.. K..: default meanings
        {46, true, &Decoder::g46_arg},
        {33, true, &Decoder::profile_cycle_arg},
        {38, true, &Decoder::profile_cycle_arg},
        {63, true, &Decoder::profile_cycle_arg},
        {64, true, &Decoder::profile_cycle_arg},
        {65, true, &Decoder::profile_cycle_arg},
        {66, true, &Decoder::profile_cycle_arg},
        {31, true, &Decoder::drill_arg},
        {45, true, &Decoder::drill_arg},
        {81, true, &Decoder::drill_arg},
        {82, true, &Decoder::drill_arg},
        {83, true, &Decoder::drill_arg},
        {84, true, &Decoder::drill_arg},
        {85, true, &Decoder::drill_arg},
        {86, true, &Decoder::drill_arg},
        {87, true, &Decoder::drill_arg},
        {88, true, &Decoder::drill_arg},
        {89, true, &Decoder::drill_arg},
    };
    // Arguments of functions not run yet (cycles, splines…).
    static constexpr ArgReader unused = {-1, false, &Decoder::unused_arg};
    for (const ArgReader& r : table)
        if (r.g == g) return &r;
    return &unused;
}

bool Interpreter::Decoder::unused_arg(const Word&) {
    return true;
}

// G4 F: dwell seconds.
bool Interpreter::Decoder::g4_dwell(const Word& w) {
    double v;
    if (!in.word_value(w, v)) return false;
    if (v < 0.01 || v > 99.99) return bad(1, tr("dwell must be 0.01 to 99.99 s"), w.col);
    p.dwell = v;
    return true;
}

bool Interpreter::Decoder::g16_arg(const Word& w) {
    if (w.v.kind != Operand::SignOnly)
        return bad(2, tr("G16 takes P, Q or R followed by a sign only (G16 R+)"), w.col);
    const char c = letter(w);
    p.g16.axis = c == 'P' ? X : c == 'Q' ? Y : Z;
    p.g16.neg = w.v.neg;
    return true;
}

bool Interpreter::Decoder::g51_arg(const Word& w) {
    int axis = -1;
    if (!axis_addr(w.addr, axis) || w.v.kind != Operand::SignOnly)
        return bad(3, tr("G51 takes axis letters with a sign only (G51 X- Y+)"), w.col);
    (w.v.neg ? p.g51.on : p.g51.off).set(size_t(axis));
    return true;
}

bool Interpreter::Decoder::g59_arg(const Word& w) {
    double v;
    int axis = -1;
    if (!in.word_value(w, v)) return false;
    if (axis_addr(w.addr, axis)) {
        if (!m.has(axis))
            return bad(1, strf(tr("axis %c is not on this machine"), letter(w)), w.col);
        // G52/G59 X on a lathe is a radius (000:1234, 000:1364; pupitre-iso(5),
        // COORDINATES AND OFFSETS).
        p.g59.axis.set(size_t(axis));
        p.g59.val[size_t(axis)] = is_rotary(axis) ? v : v * unit;
    } else if (w.addr == addrE('D')) {
        p.g59.has_ed = true;
        p.g59.ed = v;
    } else {
        int k = letter(w) - 'I';
        p.g59.ijk.set(size_t(k));
        p.g59.ijk_val[k] = (k == 0 && diam) ? v * unit / 2 : v * unit;
    }
    return true;
}

bool Interpreter::Decoder::g92_arg(const Word& w) {
    double v;
    int axis = -1;
    if (!in.word_value(w, v)) return false;
    const char c = letter(w);
    if (c == 'S') {
        p.g92.has_s = true;
        p.g92.s = v;
    } else if (c == 'R') {
        p.g92.has_r = true;
        p.g92.r = v * unit;
    } else if (axis_addr(w.addr, axis)) {
        if (!m.has(axis)) return bad(1, strf(tr("axis %c is not on this machine"), c), w.col);
        p.g92.axis.set(size_t(axis));
        p.g92.val[size_t(axis)] =
            is_rotary(axis) ? v : (axis == X && diam ? v * unit / 2 : v * unit);
    }
    return true;
}

bool Interpreter::Decoder::g96_arg(const Word& w) {
    double v;
    if (!in.word_value(w, v)) return false;
    if (letter(w) == 'X') {
        p.spindle.has_x = true;
        p.spindle.x = diam ? v * unit / 2 : v * unit;
    } else {
        p.spindle.g96_s = true;
        p.tech.has_s = true;
        p.tech.s = v;
    }
    return true;
}

bool Interpreter::Decoder::g97_arg(const Word& w) {
    double v;
    if (!in.word_value(w, v)) return false;
    p.spindle.g97_s = true;
    p.tech.has_s = true;
    p.tech.s = v;
    return true;
}

// F after G93/G94/G95.
bool Interpreter::Decoder::feed_mode_arg(const Word& w) {
    double v;
    if (!in.word_value(w, v)) return false;
    p.tech.f_with_mode = true;
    p.tech.has_f = true;
    p.tech.f = v;
    return true;
}

// G77 N.. N.. H.. S..
bool Interpreter::Decoder::g77_arg(const Word& w) {
    int iv;
    double v;
    const char c = letter(w);
    if (c == 'N') {
        if (!in.word_value(w, v, &iv)) return false;
        if (p.g77.nn >= 2) return bad(3, tr("G77 takes at most two N labels"), w.col);
        p.g77.n[p.g77.nn++] = iv;
    } else if (c == 'H') {
        if (!in.word_value(w, v, &iv)) return false;
        p.g77.h = iv;
    } else if (c == 'S') {
        if (!in.word_value(w, v, &iv)) return false;
        if (iv < 1 || iv > 100) return bad(1, tr("G77 S repeat count must be 1 to 100"), w.col);
        p.g77.s = iv;
    } else {  // P: PROFIL contour
        return bad(4, tr("G77 P (PROFIL contour) is an option this machine does not have"), w.col);
    }
    return true;
}

// G79 N.., G75 N.., G10 N..
bool Interpreter::Decoder::label_arg(const Word& w) {
    int iv;
    double v;
    if (letter(w) != 'N') return true;  // G10 EF: feed limit after interrupt, unused
    if (!in.word_value(w, v, &iv)) return false;
    if (owner_g == 79)
        p.flow.g79_n = iv;
    else if (owner_g == 75)
        p.flow.g75_n = iv;
    else
        p.flow.g10_n = iv;
    return true;
}

// G76 H.. N.. N..
bool Interpreter::Decoder::g76_arg(const Word& w) {
    int iv;
    double v;
    if (!in.word_value(w, v, &iv)) return false;
    if (letter(w) == 'H') {
        p.g76.h = iv;
    } else if (p.g76.nn < 2) {
        p.g76.n[p.g76.nn++] = iv;
    } else {
        return bad(3, tr("G76 takes at most two N labels"), w.col);
    }
    return true;
}

// G33 G38 G63-G66: the profile's two N labels and the cycle words (the end
// points keep their default meaning).
bool Interpreter::Decoder::profile_cycle_arg(const Word& w) {
    if (letter(w) == 'N') {
        int iv;
        double v;
        if (!in.word_value(w, v, &iv)) return false;
        if (p.spline.nn >= 2) return bad(3, tr("a cycle takes two N labels"), w.col);
        p.spline.n[p.spline.nn++] = iv;
        return true;
    }
    if (w.addr == addrE('P') && owner_g != 66)
        return bad(4, tr("EP (PROFIL contour) is an option this machine does not have"), w.col);
    return cyc_word(w);
}

// G48 / G06 / G49 NC.. H.. N.. N..
bool Interpreter::Decoder::spline_arg(const Word& w) {
    int iv;
    double v;
    if (!in.word_value(w, v, &iv)) return false;
    const char c = letter(w);
    if (w.addr == addrN('C'))
        p.spline.nc = iv;
    else if (c == 'H')
        p.spline.h = iv;
    else if (c == 'N' && p.spline.nn < 2)
        p.spline.n[p.spline.nn++] = iv;
    else
        return bad(3, tr("G48 takes NC, H and two N labels"), w.col);
    return true;
}

// G31 G45 G81-G89: the cycle words (positions and bottom keep their default
// meaning).
bool Interpreter::Decoder::drill_arg(const Word& w) {
    return cyc_word(w);
}

// G46 NU.. (000:6078-6369; pupitre-iso(5), POCKETS): NR+ / NR- keep their sign only.
bool Interpreter::Decoder::g46_arg(const Word& w) {
    if (w.addr != addrN('R')) return cyc_word(w);
    if (w.v.kind != Operand::SignOnly && w.v.kind != Operand::Blank)
        return bad(267, tr("NR takes a sign only (NR+ climb, NR- conventional)"), w.col);
    if (p.cycle_words.n >= 16) return bad(3, tr("too many cycle words in one block"), w.col);
    p.cycle_words.word[p.cycle_words.n++] = {w.addr, w.v.neg ? -1.0 : 1.0};
    return true;
}

// One axis group: G78 P1 synchronises with itself. Each digit of P names a
// group (000:13224: G78 P12345, G78 P3 -> 78).
bool Interpreter::Decoder::g78_arg(const Word& w) {
    int iv;
    double v;
    if (!in.word_value(w, v, &iv)) return false;
    if (iv != 1)
        return bad(78, strf(tr("G78 P%d: this machine has one axis group (P1)"), iv), w.col);
    p.flow.g78_p = true;
    return true;
}

}  // namespace pupitre
