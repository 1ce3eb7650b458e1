// Drilling, boring and tapping cycles G81-G89 (modal: each positioning block
// drills a hole) and the single-point thread cycle G31, on the machining centre
// and on the lathe axis (000:5330-5411, 000:2857-2869;
// pupitre-iso(5), DRILLING, BORING AND TAPPING CYCLES). A cycle is a
// sequence of elementary moves along the cycle axis.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/i18n.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

// The cycle axis: normal to the plane on the mill (Z in G17, Y in G18, X in G19);
// the G16 tool axis on the lathe (Z for R±, X for P±).
int Interpreter::cycle_axis() const {
    if (m_.lathe) return modal_.tool_axis == X ? X : Z;
    return modal_.plane == 17 ? Z : modal_.plane == 18 ? Y : X;
}

// One elementary move of a cycle along its axis, or in the plane.
bool Interpreter::cycle_move(int g, const Axes& target) {
    bool same = true;
    for (int a = 0; a < kAxes; ++a)
        same = same && std::fabs(target[size_t(a)] - prog_[size_t(a)]) < 1e-12;
    if (same) return true;  // a cycle never makes an empty move
    cycle_pass(g != 0);
    prog_next_ = target;
    Axes mach = frames_.to_machine(target);
    if (!check_travel(mach)) return false;
    return linear(g, mach, false, {});
}

bool Interpreter::cycle_axis_move(int g, double v) {
    Axes t = prog_;
    t[size_t(cycle_axis())] = v;
    return cycle_move(g, t);
}

bool Interpreter::cycle_dwell(double s) {
    if (s <= 0) return true;
    clock_ += s;
    out_.dwell(loc_, s);
    return true;
}

// Reads the cycle words of a block into the modal cycle parameters.
bool Interpreter::cycle_words(const Plan& p, int code) {
    CycleParams& c = cyc_;
    auto ax = cycle_axis();
    const bool diam = m_.lathe && m_.x_diameter && !modal_.radius_x && ax == X;
    for (int i = 0; i < p.cycle_words.n; ++i) {
        Addr a = p.cycle_words.word[i].a;
        double v = p.cycle_words.word[i].v;
        if (a == addrE('R'))
            c.er = diam ? v / 2 : v, c.has_er = true;
        else if (a == addrE('H'))
            c.eh = diam ? v / 2 : v, c.has_eh = true;
        else if (a == addrE('F'))
            c.ef = v, c.has_ef = true;
        else if (a == addr1('P'))
            c.p = v, c.has_p = true;
        else if (a == addr1('Q'))
            c.q = v, c.has_q = true;
        else if (a == addrE('S'))
            c.es = v, c.has_es = true;
        else if (a == addrE('P'))
            c.ep = v, c.has_ep = true;
        else if (a == addrE('C'))
            c.ec = v;
        else if (a == addrE('A'))
            c.ea = v;
        else if (a == addr1('K') || a == addr1('I') || a == addr1('J'))
            c.k = v, c.has_k = true;
        else if (a == addrE('K'))
            c.ek = v;
        else if (a == addr1('F'))
            c.starts = v, c.has_starts = true;
        if ((a == addr1('P') || a == addr1('Q') || a == addrE('S') || a == addr1('K')) && v < 0)
            return fail(
                835, strf(tr("%s must be positive in a cycle"), std::string(addr_name(a)).c_str()));
    }
    // The bottom is the cycle-axis word, absolute also in G91 (000:5394-5411;
    // pupitre-iso(5), DRILLING, BORING AND TAPPING CYCLES).
    if (p.to.axis[size_t(ax)]) {
        c.z =
            p.to.inc[size_t(ax)] ? prog_[size_t(ax)] + p.to.val[size_t(ax)] : p.to.val[size_t(ax)];
        c.has_z = true;
    }
    (void)code;
    return true;
}

// One execution of a cycle at the block's position: the checks, the approach
// and the machining of its code (000:6405-6439).
struct Interpreter::DrillRun {
    using Step = bool (DrillRun::*)();
    static Step machining(int code);

    Interpreter& in;
    CycleParams& c;
    const int code, ax;
    const double up;   // "up" is the direction of the tool vector (towards the spindle)
    double s0 = 0;     // where machining starts: EH, else ER
    double depth = 0;  // from S0 to the bottom

    double h(double v) const { return v * up; }
    bool move(int g, double v) { return in.cycle_axis_move(g, v); }
    bool dwell(double s) { return in.cycle_dwell(s); }
    bool check();
    bool check_code();
    bool approach(const Plan& p);
    bool plain();
    bool dwell_bottom();
    bool pecks(std::vector<double>& out);
    bool peck();
    bool tap();
    bool bore_feed_out();
    bool bore_oriented();
    bool bore_stop();
    bool bore_dwell();
    bool thread();
};

bool Interpreter::cycle_run(const Plan& p, int code) {
    const int ax = cycle_axis();
    const double up = (m_.lathe ? (modal_.tool_axis == ax && modal_.tool_axis_neg ? -1 : 1)
                                : (modal_.tool_axis_neg ? -1 : 1));
    DrillRun r{*this, cyc_, code, ax, up};
    if (!r.check() || !r.approach(p)) return false;
    // 4. Machining.
    r.s0 = cyc_.has_eh ? cyc_.eh : cyc_.er;
    r.depth = r.h(r.s0) - r.h(cyc_.z);
    DrillRun::Step run = DrillRun::machining(code);
    return !run || (r.*run)();
}

// The machining of each cycle code.
Interpreter::DrillRun::Step Interpreter::DrillRun::machining(int code) {
    static constexpr struct {
        int code;
        Step step;
    } table[] = {
        {81, &DrillRun::plain},         {82, &DrillRun::dwell_bottom},
        {83, &DrillRun::peck},          {87, &DrillRun::peck},
        {84, &DrillRun::tap},           {85, &DrillRun::bore_feed_out},
        {86, &DrillRun::bore_oriented}, {88, &DrillRun::bore_stop},
        {89, &DrillRun::bore_dwell},    {31, &DrillRun::thread},
    };
    for (const auto& e : table)
        if (e.code == code) return e.step;
    return nullptr;
}

// The bottom and the retract plane, for every code.
bool Interpreter::DrillRun::check() {
    if (!in.m_.lathe && in.modal_.tool_axis != ax)
        return in.fail(890, tr("the tool axis (G16) is not parallel to the cycle axis"));
    if (!c.has_z)
        return in.fail(code == 31 ? 883 : 882,
                       strf(tr("the hole bottom (%c) is not programmed"), kAxisNames[size_t(ax)]));
    const double s = in.prog_[size_t(ax)];
    if (!c.has_er) {
        c.er = s;  // the retract plane defaults to where the cycle starts
        c.has_er = true;
    }
    if (std::fabs(c.er - c.z) < 1e-9)
        return in.fail(891, tr("the retract plane ER is the hole bottom"));
    if (h(c.er) < h(c.z)) return in.fail(881, tr("the retract plane ER is below the hole bottom"));
    return check_code();
}

// The words and the spindle each code needs.
bool Interpreter::DrillRun::check_code() {
    if ((code == 81 || code == 86 || code == 88 || (code == 84 && c.has_k)) && c.has_ef)
        return in.fail(888, strf(tr("no dwell (EF) in G%d"), code));
    if ((code == 84 || code == 31) && in.modal_.spindle_dir != 3 && in.modal_.spindle_dir != 4)
        return in.fail(831, strf(tr("G%d with the spindle stopped"), code));
    if ((code == 83 || code == 87) && !c.has_p && !c.has_es)
        return in.fail(2, strf(tr("G%d needs P (first peck) or ES (number of pecks)"), code));
    if ((code == 83 || code == 87) && c.has_p && c.has_q && c.q > c.p)
        return in.fail(881, tr("the last peck Q is larger than the first P"));
    // A peck under the resolution, a negative one or a fraction of a peck
    // would loop or divide by zero (found by fuzzing): incompatible values.
    if ((code == 83 || code == 87) && ((c.has_p && c.p < 0.001) || (c.has_q && c.q < 0)))
        return in.fail(881, tr("the pecks P and Q must be positive, P at least 0.001 mm"));
    if ((code == 83 || code == 87) && c.has_es && (c.es < 1 || c.es != std::floor(c.es)))
        return in.fail(881, tr("ES must be a whole number of pecks, 1 or more"));
    if (code == 31 && (!c.has_k || !c.has_p))
        return in.fail(883, tr("G31 needs the pitch (K) and the retract (P)"));
    // A pitch of zero threads or taps at a feed of nothing, a retract of zero
    // leaves the tool in the thread (issue 40): K as G33 refuses it, 835 (seed
    // 000 l.13445); P "retract value too small", 833 (l.13443).
    if ((code == 31 || (code == 84 && c.has_k)) && !(c.k > 0))
        return in.fail(835, strf(tr("G%d: the pitch K must be more than 0"), code));
    if (code == 31 && !(c.p > 0)) return in.fail(833, tr("G31: the retract P must be more than 0"));
    if (code == 31 && c.has_starts &&
        (c.starts < 1 || c.starts > 9 || c.starts != std::floor(c.starts)))
        return in.fail(884, tr("G31: the number of starts F must be 1 to 9"));
    return true;
}

// Steps 1-3: up to ER, the positioning in the plane, down to EH.
bool Interpreter::DrillRun::approach(const Plan& p) {
    Axes& prog = in.prog_;
    // 1. Up to ER first if the tool is below it.
    if (h(prog[size_t(ax)]) < h(c.er) - 1e-9 && !move(0, c.er)) return false;
    // 2. Positioning in the plane with the modal interpolation (%333 moves by G2).
    std::bitset<kAxes> plane = p.to.axis;
    plane.reset(size_t(ax));
    if (plane.any()) {
        Target q = p.to;
        q.axis.reset(size_t(ax));
        Axes target = prog;
        for (int a = 0; a < kAxes; ++a)
            if (q.axis[size_t(a)])
                target[size_t(a)] =
                    q.inc[size_t(a)] ? prog[size_t(a)] + q.val[size_t(a)] : q.val[size_t(a)];
        bool ok;
        const int motion = in.modal_.motion;
        if (motion == 2 || motion == 3) {
            ok = in.arc(q, target);
        } else {
            ok = in.cycle_move(motion == 0 ? 0 : 1, target);
        }
        if (!ok) return false;
    }
    // 3. Rapid to ER, then to EH.
    if (std::fabs(prog[size_t(ax)] - c.er) > 1e-9 && !move(0, c.er)) return false;
    if (c.has_eh && !move(0, c.eh)) return false;
    return true;
}

bool Interpreter::DrillRun::plain() {
    return move(1, c.z) && move(0, c.er);
}

bool Interpreter::DrillRun::dwell_bottom() {
    return move(1, c.z) && dwell(c.ef) && move(0, c.er);
}

// Peck law (pupitre-iso(5), DRILLING, BORING AND TAPPING CYCLES, a [DECISION]).
bool Interpreter::DrillRun::pecks(std::vector<double>& out) {
    // More pecks than any hole needs: an input mistake, not hours of moves.
    constexpr double kMaxPecks = 100000;
    const double wanted = c.has_es && c.es >= 1 ? c.es : depth / std::max(c.p, 1e-300);
    if (!(wanted <= kMaxPecks))
        return in.fail(881, strf(tr("more than %d pecks for this hole"), int(kMaxPecks)));
    if (c.has_es && c.es >= 1) {
        int n = int(std::lround(c.es));
        double first = c.has_p ? c.p : -1, last = c.has_q ? c.q : -1;
        int fixed = (first > 0) + (last > 0 && n > 1);
        double rest = depth - std::max(0.0, first) - (n > 1 ? std::max(0.0, last) : 0.0);
        int shared = n - fixed;
        if (rest < -1e-9 || (shared == 0 && std::fabs(rest) > 1e-9 && fixed == 0))
            return in.fail(881, tr("ES, P and Q do not fit the depth of the hole"));
        for (int k = 0; k < n; ++k) {
            if (k == 0 && first > 0)
                out.push_back(first);
            else if (k == n - 1 && last > 0 && n > 1)
                out.push_back(last);
            else
                out.push_back(shared > 0 ? rest / shared : 0);
        }
        if (shared == 0 && !out.empty()) out.back() += rest;  // exact total
    } else if (c.has_q && c.q < c.p) {
        int n = std::max(2, int(std::ceil(2 * depth / (c.p + c.q))));
        double d = (c.p - c.q) / (n - 1);
        for (int k = 0; k < n; ++k) out.push_back(c.p - k * d);
    } else {
        int n = std::max(1, int(std::ceil(depth / c.p - 1e-9)));
        for (int k = 0; k < n; ++k) out.push_back(c.p);
    }
    return true;
}

// G83 (chip clearing: back to ER after each peck) and G87 (chip breaking).
bool Interpreter::DrillRun::peck() {
    std::vector<double> steps;
    if (!pecks(steps)) return false;
    double ep = c.has_ep ? c.ep : (code == 83 ? 1.0 : 0.0);
    double reached = 0;  // depth reached below S0
    for (size_t k = 0; k < steps.size() && reached < depth - 1e-9; ++k) {
        double next = std::min(depth, reached + steps[k]);
        if (k + 1 == steps.size()) next = depth;
        double v = (h(s0) - next) * up;
        if (code == 83 && k > 0) {
            // Back down to EP above the depth already reached.
            if (!move(0, (h(s0) - reached + ep) * up)) return false;
        } else if (code == 87 && k > 0 && ep > 0) {
            if (!move(0, (h(s0) - reached + ep) * up)) return false;
        }
        if (!move(1, v) || !dwell(c.ef)) return false;
        reached = next;
        if (reached < depth - 1e-9) {
            if (code == 83 && !move(0, c.er)) return false;  // chip clearing
        }
    }
    return move(0, c.er);
}

// G84 tapping, rigid with K.
bool Interpreter::DrillRun::tap() {
    Modal& modal = in.modal_;
    int dir = modal.spindle_dir;
    Modal saved = modal;
    std::optional<OwnFeed> own;
    if (c.has_k) {
        own.emplace(in);
        // Rigid tapping: feed = pitch x speed, out at EK x speed (000:5911-5934).
        double n = in.spindle_at(in.prog_[X]);
        modal.feed_mode = 94;
        modal.feed = c.k * n;
        modal.feed_set = true;
    }
    if (!move(1, c.z)) return false;
    if (!c.has_k && !dwell(c.has_ef ? c.ef : 1.0)) return false;
    modal.spindle_dir = dir == 3 ? 4 : 3;
    in.set_spindle_event();
    if (c.has_k) modal.feed = c.k * in.spindle_at(in.prog_[X]) * (c.ek > 0 ? c.ek : 1.0);
    if (!move(1, c.er)) return false;
    modal = saved;
    in.set_spindle_event();
    return true;
}

// G85: out at the feed EF.
bool Interpreter::DrillRun::bore_feed_out() {
    if (!move(1, c.z)) return false;
    double f = in.modal_.feed;
    if (c.has_ef) in.modal_.feed = c.ef;  // EF: the retract feed
    bool ok = move(1, c.er);
    in.modal_.feed = f;
    return ok;
}

// G86: oriented stop, away from the wall, out in rapid.
bool Interpreter::DrillRun::bore_oriented() {
    if (!move(1, c.z)) return false;
    Modal& modal = in.modal_;
    int dir = modal.spindle_dir;
    modal.spindle_dir = 19;  // oriented stop at EC
    in.set_spindle_event();
    // Away from the wall: EP opposite to the cutting edge at EC + EA.
    double ep = c.has_ep ? c.ep : 2.0;
    int a0 = in.m_.lathe ? Z : modal.plane == 17 ? X : modal.plane == 18 ? Z : Y;
    int a1 = in.m_.lathe ? X : modal.plane == 17 ? Y : modal.plane == 18 ? X : Z;
    double th = (c.ec + c.ea) * M_PI / 180;
    Axes t = in.prog_;
    Axes back = in.prog_;
    t[size_t(a0)] -= ep * std::cos(th);
    t[size_t(a1)] -= ep * std::sin(th);
    if (!in.cycle_move(0, t) || !move(0, c.er)) return false;
    back[size_t(ax)] = c.er;
    if (!in.cycle_move(0, back)) return false;
    modal.spindle_dir = dir;
    in.set_spindle_event();
    return true;
}

// G88: the operator validates the facing (004:932).
bool Interpreter::DrillRun::bore_stop() {
    if (!move(1, c.z)) return false;
    in.out_.stop(in.loc_, 88);
    return move(0, c.er);
}

bool Interpreter::DrillRun::bore_dwell() {
    return move(1, c.z) && dwell(c.has_ef ? c.ef : 1.0) && move(1, c.er);
}

// G31 single-point threading: per start, feed synchronised at K per revolution,
// retract P radially, back up to ER (docs/decisions.md, G31 retract).
bool Interpreter::DrillRun::thread() {
    Modal& modal = in.modal_;
    int starts = c.has_starts ? int(c.starts) : 1;
    Modal saved = modal;
    int a0 = modal.plane == 17 ? X : modal.plane == 18 ? Z : Y;
    int a1 = modal.plane == 17 ? Y : modal.plane == 18 ? X : Z;
    OwnFeed own(in);  // the lead times the speed
    for (int i = 0; i < starts; ++i) {
        modal.feed_mode = 94;
        modal.feed = c.k * in.spindle_at(in.prog_[X]);
        modal.feed_set = true;
        Axes axis_pos = in.prog_;
        if (!move(1, c.z) || !dwell(c.has_ef ? c.ef : 0)) return false;
        Axes t = in.prog_;
        double th = c.ec * M_PI / 180;
        t[size_t(a0)] -= c.p * std::cos(th);
        t[size_t(a1)] -= c.p * std::sin(th);
        if (!in.cycle_move(0, t) || !move(0, c.er)) return false;
        axis_pos[size_t(ax)] = c.er;
        if (!in.cycle_move(0, axis_pos)) return false;
    }
    modal = saved;
    return true;
}

// A block while a cycle is active, or a G31 block (000:5338-5344, 004:956).
bool Interpreter::cycle_block(const Plan& p) {
    if (modal_.radcomp != 40) return fail(140, tr("machining cycle under radius compensation"));
    const int code = p.g[31] ? 31 : modal_.cycle;
    if (!cycle_words(p, code)) return false;
    // Warning 1112: R positions along a circle between the holes under G2/G3
    // (seed 000's %333), and means nothing under G0/G1: a cycle's retract
    // plane is ER (pupitre-iso(5)), as in a G0/G1 block.
    if (p.to.has_r && (modal_.motion == 0 || modal_.motion == 1))
        warn(err::wIdleWord, strf(tr("word R has no effect in a G%d block under G0/G1: the retract "
                                     "plane of a cycle is ER"),
                                  code));
    const int ax = cycle_axis();
    std::bitset<kAxes> plane = p.to.axis;
    plane.reset(size_t(ax));
    bool written = p.mode.cycle == code || code == 31;
    if (written || plane.any()) return cycle_run(p, code);
    // ER alone: go to the new retract plane, no machining (004:956, 000:6393).
    bool er_only = false;
    for (int i = 0; i < p.cycle_words.n; ++i)
        er_only = er_only || p.cycle_words.word[i].a == addrE('R');
    if (er_only && !cycle_axis_move(0, cyc_.er)) return false;
    return true;
}

}  // namespace pupitre
