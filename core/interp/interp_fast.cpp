// The lane of plain blocks (issue 14): a G0-G3 move whose words are X Y Z,
// I J K, R and F written as numbers within their format, in a state where no
// function family (cycle, profile geometry, pocket, G29, G64 stock) waits for
// the block. Such a block is read straight into a Target and moved by the
// same functions as every other block (move_to), without the Plan, the
// decoder's tables or the modal steps that have nothing to do. Anything else,
// and any doubt, goes to the general path before anything has been done; the
// differential tests (tests/unit/test_fast_lane.cpp, tests/fuzz/fuzz_interp.cpp)
// run every program both ways and compare every event and diagnostic.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/interp/plan.hpp"

namespace pupitre {

// No family of functions may claim the block, and nothing is left over from
// the last one: the conditions under which execute() would only change the
// motion and the feed, and do_motion() would reach move_to().
bool Interpreter::plain_state() const {
    return !first_move_ && modal_.radcomp != 29 && modal_.cycle == 80 && !g64_pending_ &&
           !p46_.defining && !pgp_.pending() && !(comp_.on && modal_.radcomp == 40) &&
           s_raw_ == 0 && !l_.any_unset_read;
}

namespace {
// A number written within the format of its address (format_rule in
// interp_words.cpp: lengths and F have 5 digits and 3 decimals, only lengths
// a sign; G 3 digits, no decimals, no sign).
inline bool plain_number(const Operand& v, bool is_signed) {
    return v.kind == Operand::Number && v.int_digits <= 5 && v.frac_digits <= 3 &&
           (!v.has_sign || is_signed);
}
}  // namespace

// The words as decode() reads them (interp_words.cpp: axis_word, ijk_word,
// r_word, feed_word), in G90/G91 and G70/G71 as they are in force; false at
// a word the lane does not take (it then reads nothing).
bool Interpreter::plain_words(const Block& b, PlainBlock& w) const {
    const double unit = modal_.inch ? 25.4 : 1.0;
    const bool inc = modal_.incremental;
    const bool diam = m_.lathe && m_.x_diameter && !modal_.radius_x;
    Target& to = w.to;
    size_t i = (b.n >= 0 && !b.words.empty() && b.words[0].addr == addr1('N')) ? 1 : 0;
    for (; i < b.words.size(); ++i) {
        const Word& word = b.words[i];
        const Operand& v = word.v;
        const double val = v.neg ? -v.num : v.num;
        const char c = word.addr < 26 ? char('A' + word.addr) : 0;
        if (c == 'G') {
            if (w.g >= 0 || v.kind != Operand::Number || v.has_sign || v.frac_digits ||
                v.int_digits > 3 || v.num > 3)
                return false;
            w.g = int(v.num);
        } else if (c == 'X' || c == 'Y' || c == 'Z') {
            const int axis = c - 'X';  // X Y Z are axes 0 1 2
            if (!plain_number(v, true) || !m_.has(axis) || to.axis[size_t(axis)]) return false;
            to.axis.set(size_t(axis));
            if (inc) to.inc.set(size_t(axis));
            const bool as_diam = axis == X && diam && !inc;
            to.val[size_t(axis)] = as_diam ? val * unit / 2 : val * unit;
        } else if (c == 'I' || c == 'J' || c == 'K') {
            const int k = c - 'I';
            if (!plain_number(v, true) || to.ijk[size_t(k)]) return false;
            to.ijk.set(size_t(k));
            if (inc) to.ijk_inc.set(size_t(k));
            to.ijk_val[k] = (k == 0 && diam && !inc) ? val * unit / 2 : val * unit;
        } else if (c == 'R') {
            if (!plain_number(v, true) || to.has_r) return false;
            to.has_r = true;
            to.r = val * unit;
        } else if (c == 'F') {
            if (!plain_number(v, false) || w.has_f) return false;
            w.has_f = true;
            w.f = val;
        } else {
            return false;
        }
    }
    return true;
}

// A plain block, or nothing. The words must make a whole move: a line
// without R I J K (warning 1112 is the general path's), a circle with both
// coordinates of its plane and either its centre or R (an incomplete one is
// profile geometry's).
std::optional<StepResult> Interpreter::execute_plain(const Block& b) {
    if (!b.assigns.empty() || b.msg_channel >= 0 || !plain_state()) return std::nullopt;
    PlainBlock& w = *plain_;
    w.clear();
    if (!plain_words(b, w)) return std::nullopt;
    const Target& to = w.to;
    const int motion = w.g >= 0 ? w.g : modal_.motion;
    if (to.axis.none() || motion < 0 || motion > 3) return std::nullopt;
    if (motion <= 1) {
        if (to.has_r || to.ijk.any()) return std::nullopt;
    } else {
        int a0, a1;
        plane_axes(a0, a1);
        const bool centre = to.ijk[size_t(a0 == X   ? 0
                                          : a0 == Y ? 1
                                                    : 2)] &&
                            to.ijk[size_t(a1 == X   ? 0
                                          : a1 == Y ? 1
                                                    : 2)];
        if (!to.axis[size_t(a0)] || !to.axis[size_t(a1)] || centre == to.has_r) return std::nullopt;
    }
    // What execute() does with these words, in its order: the modal groups
    // (motion, F), the spindle (G96 follows X), then the move.
    ++plain_blocks_;
    col_ = 0;
    modal_.motion = motion;
    if (w.has_f) {
        modal_.feed = w.f;
        modal_.feed_set = true;
        feed_programmed_ = true;
    }
    if (modal_.spindle_mode == 96 && to.axis[X]) set_spindle_event();
    if (modal_.radcomp != 40 && !count_plane_motion(to.axis)) return StepResult::error;
    if (to.axis[X]) modal_.css_known = true;
    return move_to(to, false) ? StepResult::running : StepResult::error;
}

}  // namespace pupitre
