// Executing one block in the order of pupitre-iso(5), MODAL STATE AND THE
// ORDER INSIDE A BLOCK (000:497-498; docs/decisions.md, Execution order inside a block):
// assignments, modal changes, avant M, motion, dwell, après M, then G77/G79.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/i18n.hpp"
#include "core/interp/gate.hpp"
#include "core/interp/plan.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

// An assignment to L: L100-L199 are the profile's and compensation's own
// variables, so they may not change under them.
bool Interpreter::assign_l(const Operand& t, double v, int col) {
    if (!LVars::valid(t.index))
        return fail(91, strf(tr("L%d does not exist (L0-L19, L100-L199, L900-L959)"), t.index),
                    col);
    if (t.index >= 100 && t.index <= 199 && modal_.radcomp != 40)
        return fail(140, strf(tr("writing L%d under radius compensation"), t.index), col);
    if (t.index >= 100 && t.index <= 199 && pgp_.pending())
        return fail(96, strf(tr("writing L%d after an incomplete profile block"), t.index), col);
    l_.v[size_t(t.index)] = v;
    l_.written.set(size_t(t.index));
    return true;
}

// An assignment to E, direct or through an L that holds the E number.
bool Interpreter::assign_e(const Operand& t, double v, int col) {
    int n = t.index;
    if (t.kind == Operand::EIndirect) {
        if (!LVars::valid(t.index)) return fail(91, strf(tr("L%d does not exist"), t.index), col);
        double nn = l_.v[size_t(t.index)];
        if (nn < 0 || nn > 99999 || nn != std::floor(nn))
            return fail(91, strf(tr("L%d does not hold an E number"), t.index), col);
        n = int(nn);
    }
    if (std::fabs(v) > 9.2e18) return fail(92, tr("value too large for an E parameter"), col);
    // A decimal stored into E is truncated toward zero (000:7651-7669; pupitre-iso(5), DECISIONS).
    if (Error e = write_e(n, int64_t(std::trunc(v)))) return fail(e.code, e.detail, col);
    return true;
}

// Left to right, each assignment seeing the ones before it (L1=2 L2=L1*3).
bool Interpreter::assign_all(const Block& b) {
    for (const Assign& a : b.assigns) {
        col_ = a.col;
        double v;
        if (Error e = eval_expr(b, a.expr, l_, *this, v)) return fail(e.code, e.detail, a.col);
        bool ok = a.target.kind == Operand::LVar ? assign_l(a.target, v, a.col)
                                                 : assign_e(a.target, v, a.col);
        if (!ok) return false;
    }
    return true;
}

// The blocks that do not go through the steps of an ordinary block: what they
// do is their whole effect. Empty for an ordinary block.
std::optional<StepResult> Interpreter::run_apart(const Block& b, const Plan& p) {
    if (g64_pending_) {
        // G64's rough stock until G80, which runs the roughing first
        // (000:2434-2458; pupitre-iso(5), TURNING CYCLES).
        if (p.mode.cycle != 80) return turning_stock(p) ? StepResult::running : StepResult::error;
        if (!turning_g64_run()) return StepResult::error;
    }
    if (p.unsupported.g >= 0) {
        const GCode* g = find_g(p.unsupported.g);
        fail(err::kUnsupported, strf(tr("G%d (%s) is not yet supported by pupitre"),
                                     p.unsupported.g, tr(std::string(g->text).c_str())));
        return StepResult::error;
    }
    // G76+/G76- edit the program memory and do nothing else.
    if (p.g76.sign) return edit_program(b, p) ? StepResult::running : StepResult::error;
    // G46 blocks, and the contour blocks of a G46 definition, move nothing but
    // what the pocket orders plan (000:6078-6369; pupitre-iso(5), POCKETS).
    // A definition left open by a run that stopped inside it (RAZ, an error
    // before this point) is dropped: its blocks are no longer consecutive.
    if (p46_.defining && blocks_ != p46_.last_block + 1) p46_.defining = false;
    if (p.g[46] || p46_.defining) {
        p46_.last_block = blocks_;
        if (pocket46(p)) return StepResult::running;
        p46_.defining = false;  // a definition with an error is not kept
        return StepResult::error;
    }
    return std::nullopt;
}

// The refusals that come before the block's modal words, M functions and
// moves take effect.
bool Interpreter::block_allowed(const Plan& p) {
    if (p.pgp.has_eb)
        for (int i = 0; i < p.tech.nm; ++i)
            if (p.tech.m[i] <= 2)
                return fail(131,
                            strf(tr("a fillet or chamfer (EB) in a block with M0%d"), p.tech.m[i]));
    if (pgp_.pending()) {
        // The held element needs the next blocks (000:8358-8564;
        // pupitre-iso(5), PROFILE GEOMETRY PROGRAMMING (PGP)).
        if (p.mode.plane >= 0 && p.mode.plane != modal_.plane)
            return fail(137, tr("plane change while a profile element is incomplete"));
        for (int i = 0; i < p.tech.nm; ++i)
            if (p.tech.m[i] == 2 && !pgp_close()) return false;  // the solver says why (101, 131)
    }
    if (p.g[78]) {
        for (int i = 0; i < p.tech.nm; ++i)
            if (p.tech.m[i] == 0 || p.tech.m[i] == 1)
                return fail(78, strf(tr("G78 with a program stop M0%d"), p.tech.m[i]));
    }
    // Radius compensation restrictions (000:3889-3938; pupitre-iso(5), TOOLS AND CORRECTORS).
    bool comp = modal_.radcomp != 40;
    if (comp && p.g[16]) return fail(140, tr("G16 under radius compensation"));
    return true;
}

bool Interpreter::do_dwell(const Plan& p) {
    if (p.dwell >= 0) {
        clock_ += p.dwell;
        out_.dwell(loc_, p.dwell);
    } else if (p.g[4]) {
        return fail(2, tr("G4 needs the dwell time in F (G4 F1.5)"));
    }
    return true;
}

// G79's condition is read once the rest of the block is done: it sees the
// block's own assignments.
bool Interpreter::do_g79(const Block& b, const Plan& p) {
    if (p.flow.g79_n < 0) return fail(2, tr("G79 needs the label to jump to (G79 N100)"));
    bool go = true;
    if (b.test.cmp != Cmp::none) {
        double lhs, rhs;
        if (Error e = eval_expr(b, b.test.lhs, l_, *this, lhs))
            return fail(e.code, e.detail, b.test.col);
        if (Error e = eval_expr(b, b.test.rhs, l_, *this, rhs))
            return fail(e.code, e.detail, b.test.col);
        go = compare(b.test.cmp, lhs, rhs);
        if (l_.any_unset_read) report_unset_reads();
    }
    return !go || jump(p.flow.g79_n);
}

// The functions that act on the program rather than the machine come last:
// a jump or a call leaves the block, so everything else in it must be done.
bool Interpreter::do_flow(const Block& b, const Plan& p) {
    if (p.g[79] && !p.flow.g79_sign && !do_g79(b, p)) return false;
    if (p.g[48] && !spline_define(p)) return false;
    if (p.g[49]) {
        if (modal_.radcomp != 40) return fail(140, tr("G49 must be programmed in G40"));
        if (p.spline.nc <= 0 || !splines_.erase(p.spline.nc))
            return fail(605, strf(tr("G49: curve NC%d is not defined"), p.spline.nc));
    }
    if (p.g[76] && !transfer(p)) return false;
    if (p.g[77] && !call(p)) return false;
    return true;
}

// The steps of that order (pupitre-iso(5), MODAL STATE AND THE ORDER INSIDE A
// BLOCK) in the order of block_steps() (codes.cpp;
// test BlockSteps.ExecuteFollowsTheCodesTable). Each step returns false once
// it has reported the error that stops the block. The steps an ordinary move
// does not need are called only when the block holds their words: this runs
// for every block, and a call costs more than the test.
StepResult Interpreter::execute(const Block& b) {
    cycle_last_ = -1;
    if (caz_) return execute_caz(b);
    if (opt_.fast_lane)
        if (std::optional<StepResult> plain = execute_plain(b)) return *plain;
    if (!assign_all(b)) return StepResult::error;
    Plan p;
    bool decoded = decode(b, p);
    if (l_.any_unset_read) report_unset_reads();
    if (!decoded) return StepResult::error;
    if (g64_pending_ || p.unsupported.g >= 0 || p.g76.sign || p.g[46] || p46_.defining)
        if (std::optional<StepResult> apart = run_apart(b, p)) return *apart;
    if ((p.pgp.has_eb || p.g[78] || p.g[16] || pgp_.pending()) && !block_allowed(p))
        return StepResult::error;
    if (!apply_modal(p) || !do_m_avant(p) || !apply_spindle(p)) return StepResult::error;
    if (b.msg_channel >= 0) out_.message(loc_, b.msg_channel, b.msg);
    if (!do_motion(p) || !do_dwell(p)) return StepResult::error;
    // G09: an exact stop at the end of its own block (000:10566-10595).
    if (p.g[9]) out_.exact_stop(loc_);
    StepResult r = StepResult::running;
    if (!do_m_apres(p, r)) return StepResult::error;
    if (ended_) return r;
    if ((p.g[79] || p.g[48] || p.g[49] || p.g[76] || p.g[77]) && !do_flow(b, p))
        return StepResult::error;
    return r;
}

// G0-G3, G90/G91, G17-G19, G70/G71. The plane cannot change under compensation:
// the offset contour is computed in it.
bool Interpreter::modal_interpolation(const Plan& p) {
    if (p.mode.motion >= 0) modal_.motion = p.mode.motion;
    if (p.mode.dist >= 0) modal_.incremental = p.mode.dist == 91;
    if (p.mode.plane >= 0 && p.mode.plane != modal_.plane) {
        if (modal_.radcomp != 40)
            return fail(138, tr("plane change under radius compensation (program G40 first)"));
        modal_.plane = p.mode.plane;
        out_.exact_stop(loc_);  // the moves before are in the old plane: they end at rest
    }
    if (p.mode.units >= 0) modal_.inch = p.mode.units == 70;
    return true;
}

// G31 and G80-G89. G16 is checked against the cycle this block leaves active.
bool Interpreter::modal_cycle(const Plan& p) {
    if (p.g[31] && modal_.cycle != 80)
        modal_.cycle = 80;  // G31 cancels an active drilling cycle, as G80 would
    if (p.mode.cycle >= 0 && p.mode.cycle != modal_.cycle) {
        if (p.mode.cycle == 80) {
            cyc_ = CycleParams{};
        } else {
            // Another cycle keeps Z, ER and EH and resets the rest
            // (000:5394-5411; pupitre-iso(5), DRILLING, BORING AND TAPPING
            // CYCLES).
            CycleParams keep;
            keep.has_z = cyc_.has_z, keep.z = cyc_.z;
            keep.has_er = cyc_.has_er, keep.er = cyc_.er;
            keep.has_eh = cyc_.has_eh, keep.eh = cyc_.eh;
            cyc_ = keep;
        }
        modal_.cycle = p.mode.cycle;
    }
    if (p.g[16] && modal_.cycle >= 81 && modal_.cycle <= 89)
        return fail(890, tr("G16 while a drilling cycle is active"));
    return true;
}

// G52/G53 and G73/G74 change the program point the position is read in.
bool Interpreter::modal_frame_switches(const Plan& p) {
    if (p.mode.prefdec >= 0 && (p.mode.prefdec == 53) != frames_.g53) {
        frames_.g53 = p.mode.prefdec == 53;
        recompute_program_pos();
    }
    if (p.mode.scale >= 0 && (p.mode.scale == 74) != frames_.scale_on) {
        if (modal_.radcomp != 40) return fail(143, tr("G73/G74 under radius compensation"));
        frames_.scale_on = p.mode.scale == 74;
        recompute_program_pos();
    }
    return true;
}

// G93-G95 and F.
bool Interpreter::modal_feed(const Plan& p) {
    // Feed: the handbook wants F in the block that changes the unit (000:2218,
    // 000:2267), but seven handbook programs write "G95 G92 S1500" or "G80 G40
    // G95" and give F later (000:9661, 10037, 10186…): the unit changes, and a
    // feed move made before a new F is the error (2, F being G95's mandatory
    // argument). Warning 1115 at every G94/G95 block without F (seed 000: "doit
    // être suivie obligatoirement de l'argument F"; pupitre-iso(5), DECISIONS,
    // changing the feed unit without F).
    if ((p.mode.feed == 94 || p.mode.feed == 95) && !p.tech.has_f && m_.strict)
        return fail(2,
                    strf(tr("G%d without F (seed 000: F is its mandatory argument)"), p.mode.feed));
    if ((p.mode.feed == 94 || p.mode.feed == 95) && !p.tech.has_f)
        warn(err::wFeedModeNoF, p.mode.feed != modal_.feed_mode
                                    ? strf(tr("G%d without F in its block: the feed unit changes "
                                              "and the next feed move needs F"),
                                           p.mode.feed)
                                    : strf(tr("G%d without F in its block: the feed stays F%s"),
                                           p.mode.feed, fixed3(modal_.feed).c_str()));
    if (p.mode.feed >= 0 && p.mode.feed != modal_.feed_mode) {
        modal_.feed_mode = p.mode.feed;
        if (!p.tech.has_f) modal_.feed_set = false;
    }
    if (p.tech.has_f) {
        modal_.feed = p.tech.f;
        modal_.feed_set = true;
        feed_programmed_ = true;
    }
    return true;
}

// T, D, G40-G42 and G29. A new D is announced at once unless M06 in the block
// announces the change itself.
bool Interpreter::modal_tool(const Plan& p) {
    if (p.tech.has_t) modal_.t = p.tech.t;
    if (p.tech.has_d && p.tech.d != modal_.d) {
        modal_.d = p.tech.d;
        gauge_pending_.set();
        if (!p.tech.nm || std::find(p.tech.m, p.tech.m + p.tech.nm, 6) == p.tech.m + p.tech.nm)
            out_.tool(loc_, modal_.tool_in_spindle, modal_.d, 0, false);
    }
    if (p.mode.radcomp >= 0 && p.mode.radcomp != modal_.radcomp) {
        // The radius is taken when G41/G42 is programmed; a change of D or R takes
        // effect after G40 and a new G41/G42 (000:898-906).
        if (p.mode.radcomp == 29 && comp_.on)
            return fail(140, tr("G29 under G41/G42: program G40 first (000:3932)"));
        if (p.mode.radcomp != 40 && p.mode.radcomp != 29 && !comp_engage(p.mode.radcomp))
            return false;
        modal_.radcomp = p.mode.radcomp;
        nonmotion_in_comp_ = 0;
    }
    if (p.g16.axis >= 0) {
        modal_.tool_axis = p.g16.axis;
        modal_.tool_axis_neg = p.g16.neg;
        gauge_pending_.set();
    } else if (p.g[16]) {
        return fail(2, tr("G16 needs P, Q or R with a sign (G16 R+)"));
    }
    return true;
}

// The axes ED turns about: the plane's two axes, (Z, X) on a lathe.
void Interpreter::ed_axes(int& a0, int& a1) const {
    a0 = m_.lathe ? Z : modal_.plane == 17 ? X : modal_.plane == 18 ? Z : Y;
    a1 = m_.lathe ? X : modal_.plane == 17 ? Y : modal_.plane == 18 ? X : Z;
}

// G59 offsets, modal per axis (000:1234, 000:1364; pupitre-iso(5), COORDINATES
// AND OFFSETS); G91 G59 adds.
bool Interpreter::modal_g59(const Plan& p) {
    if (p.g59.axis.none() && !p.g59.has_ed && p.g59.ijk.none())
        return fail(2, tr("G59 needs at least one axis offset"));
    for (int a = 0; a < kAxes; ++a)
        if (p.g59.axis[size_t(a)])
            frames_.g59[size_t(a)] = modal_.incremental
                                         ? frames_.g59[size_t(a)] + p.g59.val[size_t(a)]
                                         : p.g59.val[size_t(a)];
    int a0, a1;
    ed_axes(a0, a1);
    auto ijk_of = [](int axis) { return axis == X ? 0 : axis == Y ? 1 : 2; };
    if (p.g59.ijk[size_t(ijk_of(a0))]) frames_.ed_c0 = p.g59.ijk_val[ijk_of(a0)];
    if (p.g59.ijk[size_t(ijk_of(a1))]) frames_.ed_c1 = p.g59.ijk_val[ijk_of(a1)];
    if (p.g59.has_ed) {
        frames_.ed_a0 = a0;
        frames_.ed_a1 = a1;
        frames_.ed = modal_.incremental ? frames_.ed + p.g59.ed : p.g59.ed;
    }
    recompute_program_pos();
    return true;
}

// The frame words: G59, ED, G51. They come after G90/G91 and the plane, which
// say how they add up and about which axes ED turns.
bool Interpreter::modal_frame(const Plan& p) {
    if (p.g[59] && !modal_g59(p)) return false;
    if (p.tech.has_ed) {
        ed_axes(frames_.ed_a0, frames_.ed_a1);
        frames_.ed = modal_.incremental ? frames_.ed + p.tech.ed : p.tech.ed;
        recompute_program_pos();
    }
    if (p.g[51]) {
        if (p.g51.on.none() && p.g51.off.none())
            return fail(2, tr("G51 needs axes with a sign (G51 X- Y-)"));
        frames_.mirror |= p.g51.on;
        frames_.mirror &= ~p.g51.off;
        recompute_program_pos();
    }
    return true;
}

// G92: a preset of the axes, or the spindle limit S, or the tangential feed R.
bool Interpreter::modal_g92(const Plan& p) {
    if (p.g92.axis.any() && (p.g92.has_s || p.g92.has_r))
        return fail(3, tr("G92 presets axes or sets S or R, not both in one block"));
    if (p.g92.axis.none() && !p.g92.has_s && !p.g92.has_r)
        return fail(2, tr("G92 needs axes (preset), S (spindle limit) or R (tangential feed)"));
    // new PREF = PREF + (current point / OP) - programmed value (000:1173-1179).
    for (int a = 0; a < kAxes; ++a)
        if (p.g92.axis[size_t(a)])
            frames_.pref[size_t(a)] += prog_[size_t(a)] - p.g92.val[size_t(a)];
    if (p.g92.axis.any()) recompute_program_pos();
    if (p.g92.has_s) {
        if (!m_.lathe) return fail(2, tr("G92 S (spindle limit) is a lathe function"));
        limit_spindle(92, p.g92.s);
    }
    if (p.g92.has_r) modal_.g92r = p.g92.r;
    return true;
}

// The spindle's limit under G96: the NUM's G92 S, the Cazeneuve's G25 S
// (interp_caz.cpp); above the machine's maximum it is limited to it.
void Interpreter::limit_spindle(int g, double s) {
    modal_.smax = s;
    if (modal_.smax <= m_.spindle_max) return;
    // TRANSLATORS: G%d is G92 (NUM) or G25 (Cazeneuve).
    warn(err::wSpeedClamped,
         strf(tr("G%d S%s above the spindle maximum %s: limited to it"), g,
              fixed3(modal_.smax, 63).c_str(), fixed3(m_.spindle_max, 63).c_str()));
    modal_.smax = m_.spindle_max;
}

// The modal groups in the order they take effect: a later group reads what an
// earlier one set (G59 and ED read G90/G91 and the plane), and a refusal stops
// the block with the groups before it applied. A table of direct calls, each
// guarded by the words of its group, rather than an array of member pointers:
// this runs for every block, and a call costs more than the test.
bool Interpreter::apply_modal(const Plan& p) {
    const bool feed = p.mode.feed >= 0 || p.tech.has_f;
    const bool tool =
        p.tech.has_t || p.tech.has_d || p.mode.radcomp >= 0 || p.g16.axis >= 0 || p.g[16];
    if (!modal_interpolation(p) ||   // G0-G3, G90/G91, G17-G19, G70/G71
        !modal_cycle(p) ||           // G31, G80-G89
        !modal_frame_switches(p) ||  // G52/G53, G73/G74
        (feed && !modal_feed(p)) ||  // G93-G95, F
        (tool && !modal_tool(p)) ||  // T, D, G40-G42, G29, G16
        !modal_frame(p) ||           // G59, ED, G51
        (p.g[92] && !modal_g92(p)))  // G92
        return false;
    if (p.flow.g75_n >= -1) modal_.g75 = p.flow.g75_n == 0 ? -1 : p.flow.g75_n;
    if (p.tech.has_eg) modal_.eg = p.tech.eg;
    return true;
}

// Warning 1113: a speed in rev/min that is not a whole number. From a variable
// it is rounded (program-flow Q15), written with decimals it runs as written.
void Interpreter::warn_spindle_words(const Plan& p) {
    double raw = s_raw_;
    s_raw_ = 0;
    if (!p.tech.has_s || modal_.spindle_mode != 97) return;
    if (raw != 0 && raw != p.tech.s)
        warn(err::wFractionalRpm, strf(tr("S from a variable is %s rev/min, not a whole number: "
                                          "the spindle turns at %ld rev/min"),
                                       fixed3(raw).c_str(), std::lround(p.tech.s)));
    else if (p.tech.s != std::floor(p.tech.s))
        warn(err::wFractionalRpm,
             strf(tr("S%s rev/min is not a whole number: the spindle turns at %s rev/min; write "
                     "whole rev/min (S%ld)"),
                  fixed3(p.tech.s).c_str(), fixed3(p.tech.s).c_str(), std::lround(p.tech.s)));
}

// Warning 1111: an L read before anything set it reads 0 (set since
// power-on in the console; in this run or by --set in a batch run:
// docs/decisions.md, An L variable read before it is set).
void Interpreter::report_unset_reads() {
    if (!l_.any_unset_read) return;
    l_.any_unset_read = false;
    for (size_t i = 0; i < l_.unset_read.size(); ++i)
        if (l_.unset_read.test(i) && !l_unset_warned_.test(i)) {
            l_unset_warned_.set(i);
            warn(err::wLReadUnset,
                 strf(tr("L%zu is read before anything set it: it reads 0; assign it first "
                         "(L%zu=...) or give it with --set L%zu=..."),
                      i, i, i));
        }
    l_.unset_read.reset();
}

// Spindle speed after the avant M functions (M3/M4/M40-M45 act before S is used).
bool Interpreter::apply_spindle(const Plan& p) {
    if (p.mode.spindle == 96 || p.mode.spindle == 97) {
        bool s_given = p.mode.spindle == 96 ? p.spindle.g96_s : p.spindle.g97_s;
        if (!s_given) return fail(28, strf(tr("G%d must be followed by S"), p.mode.spindle));
    }
    if (p.mode.spindle == 96) {
        if (!p.spindle.has_x && !modal_.css_known)
            return fail(28, tr("G96: the starting diameter is unknown (program X first, or G96 X.. "
                               "S..)"));
        modal_.spindle_mode = 96;
        modal_.css_x0 = p.spindle.has_x ? p.spindle.x : prog_[X];
        modal_.css_pos0 = prog_[X];
        modal_.css_known = true;
    } else if (p.mode.spindle == 97) {
        modal_.spindle_mode = 97;
    }
    if (p.tech.has_s) modal_.s = p.tech.s;
    if (p.tech.has_s || s_raw_ != 0) warn_spindle_words(p);
    bool range_written = false;
    for (int i = 0; i < p.tech.nm; ++i)
        range_written = range_written || (p.tech.m[i] >= 40 && p.tech.m[i] <= 45);
    if (modal_.spindle_mode == 97 && p.tech.has_s && m_.auto_range && !range_written &&
        modal_.range < 0 && !m_.ranges.empty() && modal_.s > 0) {
        // Automatic range: with none in force, the first range holding S
        // (000:1698-1726; pupitre-iso(5), FEEDS AND SPINDLE); a range the
        // program chose stays in force.
        int found = -1;
        for (size_t i = 0; i < m_.ranges.size() && found < 0; ++i)
            if (modal_.s >= m_.ranges[i].min && modal_.s <= m_.ranges[i].max) found = int(i);
        if (found < 0)
            return fail(29, strf(tr("S%s is in no spindle range"), fixed3(modal_.s, 63).c_str()));
        modal_.range = found;
    }
    if (modal_.spindle_mode == 96 && !m_.ranges.empty() && modal_.range < 0 &&
        (p.mode.spindle == 96 || p.tech.has_s)) {
        // With automatic ranges the machine takes the range of the highest speeds.
        if (!m_.auto_range)
            return fail(29, tr("constant surface speed needs a spindle range (M40-M45)"));
        modal_.range = int(m_.ranges.size()) - 1;
    }
    if (modal_.spindle_mode == 97 && p.tech.has_s && modal_.range >= 0) {
        const SpindleRange& r = m_.ranges[size_t(modal_.range)];
        if (modal_.s != 0 && (modal_.s < r.min || modal_.s > r.max))
            return fail(29, strf(tr("S%s is outside range M%d (%s-%s rev/min)"),
                                 fixed3(modal_.s, 63).c_str(), 40 + modal_.range,
                                 fixed3(r.min, 63).c_str(), fixed3(r.max, 63).c_str()));
    }
    if (modal_.spindle_mode == 97 && p.tech.has_s && modal_.s > m_.spindle_max)
        warn(err::wSpeedClamped,
             strf(tr("S%s above the spindle maximum %s: limited to it"),
                  fixed3(modal_.s, 63).c_str(), fixed3(m_.spindle_max, 63).c_str()));
    if (p.mode.spindle == 96 && (modal_.spindle_dir != 3 && modal_.spindle_dir != 4))
        warn(err::wSpindleStopped,
             tr("G96 with the spindle stopped: the speed applies when it starts"));
    // The speed can only have changed with a spindle word, an M function, or X under G96.
    if (p.tech.has_s || p.mode.spindle >= 0 || p.tech.nm > 0 || p.g[92] || p.g[52] || p.g[59] ||
        (modal_.spindle_mode == 96 && p.to.axis[X]))
        set_spindle_event();
    return true;
}

bool Interpreter::do_m_avant(const Plan& p) {
    bool coolant = false;
    for (int i = 0; i < p.tech.nm; ++i) {
        int m = p.tech.m[i];
        const MCode* mc = find_m(m);
        if (!mc) {
            warn(err::wUnknownM, strf(tr("M%d has no meaning on this machine"), m));
            continue;
        }
        if (!mc->all_models && m_.model == 1020)
            return fail(4, strf(tr("M%d needs a NUM 1040 or 1060"), m));
        if (mc->when != MWhen::avant) continue;
        if (!m_avant(m, coolant)) return false;
    }
    if (coolant) out_.coolant(loc_, modal_.m7, modal_.m8);
    return true;
}

// One M function that acts before the moves of its block ("avant" in the
// codes table and pupitre-iso(5)); `coolant` is set when it turns one on.
bool Interpreter::m_avant(int m, bool& coolant) {
    switch (m) {
        case 3:
        case 4:
            modal_.spindle_dir = m;
            break;
        case 19:
            modal_.spindle_dir = 19;
            break;
        case 7:
            modal_.m7 = true;
            coolant = true;
            break;
        case 8:
            modal_.m8 = true;
            coolant = true;
            break;
        case 11:
            modal_.clamped = false;
            break;
        case 49:
            modal_.overrides_off = true;
            break;
        case 62:
        case 66:
        case 61:
            break;
        case 63:
        case 64:
        case 65:
        case 67:
        case 68:
        case 69:
            return fail(899, strf(tr("M%d: this machine has one spindle"), m));
        case 998:
            modal_.modif_inhibited = false;
            break;
        case 999:
            modal_.modif_inhibited = true;
            break;
        default:
            if (m >= 40 && m <= 45) {
                if (size_t(m - 40) >= m_.ranges.size() && !m_.ranges.empty())
                    return fail(29, strf(tr("range M%d does not exist on this machine"), m));
                modal_.range = m - 40;
            } else if (m >= 200 && m <= 899) {
                modal_.coded_m = m;
            }
    }
    return true;
}

bool Interpreter::do_m_apres(const Plan& p, StepResult& r) {
    bool comp = modal_.radcomp != 40;
    for (int i = 0; i < p.tech.nm; ++i) {
        int m = p.tech.m[i];
        const MCode* mc = find_m(m);
        if (mc && mc->when != MWhen::apres) continue;
        switch (m) {
            case 0:
            case 1:
                if (comp) return fail(140, strf(tr("M0%d under radius compensation"), m));
                if (m == 1 && !opt_.optional_stop) break;
                // M00 and M01 stop the spindle (000:1429).
                modal_.spindle_dir = 5;
                set_spindle_event();
                out_.stop(loc_, m);
                r = StepResult::stopped;
                break;
            case 12:
                out_.stop(loc_, 12);
                r = StepResult::stopped;
                break;
            case 2:
                if (comp) return fail(140, tr("M02 under radius compensation"));
                reset_modal_m02();
                out_.end(loc_, 2);
                ended_ = true;
                r = StepResult::ended;
                return true;
            case 5:
                modal_.spindle_dir = 5;
                set_spindle_event();
                break;
            case 6:
                if (comp) return fail(140, tr("tool change M06 under radius compensation"));
                modal_.tool_in_spindle = modal_.t;
                note_tool(modal_.t);
                clock_ += m_.tool_change_time;
                out_.tool(loc_, modal_.t, modal_.d, m_.tool_change_time, true);
                break;
            case 9:
                if (modal_.m7 || modal_.m8) {
                    modal_.m7 = modal_.m8 = false;
                    out_.coolant(loc_, false, false);
                }
                break;
            case 10:
                modal_.clamped = true;
                break;
            case 48:
                modal_.overrides_off = false;
                break;
            default:
                break;
        }
    }
    return true;
}

// M02 and RAZ (000:1245, 000:13194; pupitre-iso(5), M02): modal groups to
// power-on, D0, M05, M09; G59, ED, G51, G74, G75, G92 S, G92 R, EG cleared;
// PREF, T, correctors, E and L kept. D0 takes effect at once: no program is
// left to carry a pending gauge to its next move, and every page (OP, INFO,
// PREF, CORR) and the touch-off must see the gauge the machine applies, which
// is D0's (none) [DECISION, pupitre(1)].
void Interpreter::reset_modal_m02() {
    Modal fresh;
    fresh.plane = m_.lathe ? 18 : 17;
    fresh.t = modal_.t;
    fresh.tool_in_spindle = modal_.tool_in_spindle;
    fresh.radius_x = modal_.radius_x;
    fresh.css_known = modal_.css_known;
    bool coolant = modal_.m7 || modal_.m8;
    modal_ = fresh;
    if (coolant) out_.coolant(loc_, false, false);
    set_spindle_event();
    frames_.g59 = Axes{};
    frames_.ed = 0;
    frames_.mirror.reset();
    frames_.scale_on = false;
    frames_.g53 = false;
    frames_.gauge = Axes{};
    gauge_pending_.reset();
    recompute_program_pos();
}

// The spindle speed the machine runs at, at program X (radius) `x`.
double Interpreter::spindle_at(double x) const {
    if (modal_.spindle_dir != 3 && modal_.spindle_dir != 4) return 0;
    double limit = m_.spindle_max;
    if (modal_.smax > 0) limit = std::min(limit, modal_.smax);
    if (modal_.range >= 0 && size_t(modal_.range) < m_.ranges.size())
        limit = std::min(limit, m_.ranges[size_t(modal_.range)].max);
    double n;
    if (modal_.spindle_mode == 96) {
        double d = 2 * std::fabs(modal_.css_x0 + (x - modal_.css_pos0));
        n = d > 1e-9 ? 1000.0 * modal_.s / (std::numbers::pi * d) : limit;
    } else {
        n = modal_.s;
    }
    return std::min(n, limit);
}

void Interpreter::set_spindle_event() {
    double rpm = spindle_at(prog_[X]);
    rpm_ = rpm;
    SpindleEvent e;
    e.loc = loc_;
    e.rpm = rpm;
    e.dir = modal_.spindle_dir;
    e.css = modal_.spindle_mode == 96;
    e.vc = e.css ? modal_.s : 0;
    e.range = modal_.range >= 0 ? 40 + modal_.range : -1;
    if (sp_emitted_ && last_sp_.rpm == e.rpm && last_sp_.dir == e.dir &&
        last_sp_.range == e.range && last_sp_.css == e.css && last_sp_.vc == e.vc)
        return;
    sp_emitted_ = true;
    last_sp_ = e;
    out_.spindle(e);
}

}  // namespace pupitre
