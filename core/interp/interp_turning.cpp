// The turning cycles in the interpreter (pupitre-iso(5), TURNING CYCLES): the finished profile is
// read from its blocks N<a>..N<b> (PGP included, without running them), the rough
// stock of G64 from the blocks up to G80, and the moves the cycle functions of
// core/cycles/turning.cpp return are run like programmed ones.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/cycles/turning.hpp"
#include "core/i18n.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

double Interpreter::cyc(const Plan& p, Addr a, double dflt, bool* has) {
    for (int i = 0; i < p.cycle_words.n; ++i)
        if (p.cycle_words.word[i].a == a) {
            if (has) *has = true;
            return p.cycle_words.word[i].v;
        }
    if (has) *has = false;
    return dflt;
}

// Reads the finished profile N<a>..N<b> of the current program into lines and
// arcs in (z, r), in the order written (the profile may be called backwards).
namespace {
// The first L100-L199 or L900-L959 a block reads, or -1.
int high_l_read(const Block& b) {
    auto high = [](const Operand& o) {
        return (o.kind == Operand::LVar || o.kind == Operand::EIndirect) && o.index >= 100;
    };
    for (const Word& w : b.words)
        if (high(w.v)) return w.v.index;
    for (const Term& t : b.terms)
        if (high(t.v)) return t.v.index;
    return -1;
}
}  // namespace

// Warning 1116: a G64/G65 allowance that points into the part, cut as written.
void Interpreter::warn_allowance_inside(int g, double i, double k) {
    char ik[64];
    std::snprintf(ik, sizeof ik, "I%g K%g", i, k);
    warn(err::wAllowanceInside,
         strf(tr("G%d allowance %s points into the finished part: the passes cut it into the part "
                 "as written (a bore takes a negative I)"),
              g, ik));
}

// What the reading of a finished profile carries from one block to the next.
struct Interpreter::ProfileRead {
    const ProgramText* prog = nullptr;
    int first_line = 0;  // of the profile as written
    pgp::Solver solver;
    std::vector<pgp::Elem> elems;
    comp::V2 pos;
    comp::V2 start;  // the profile's first point, as written
    bool started = false;
    int count = 0;  // blocks after the start point
};

// 000:2464 forbids L100-L199 and L900-L959 in the finished profile, yet the
// handbook's own %2000 reads L151-L153 in one (000:8839-8866): writes are
// refused (96); a read is warning 1114, or the NUM's error 96 under the
// machine setting `strict`.
bool Interpreter::profile_l_words(const Block& blk) {
    for (const Assign& as : blk.assigns)
        if (as.target.kind == Operand::LVar && as.target.index >= 100)
            return fail(96, strf(tr("writing L%d in a roughing-cycle profile"), as.target.index));
    if (int high = high_l_read(blk); high >= 0) {
        // The handbook's words, quoted as written (not translated).
        const char* seed =
            "ne peuvent pas \u00eatre employ\u00e9es dans la d\u00e9finition du profil fini";
        // TRANSLATORS: the second %s is a quotation of the French handbook; keep it as it is.
        if (m_.strict)
            return fail(96, strf(tr("L%d read in a roughing-cycle profile (seed 000: L100-L199 and "
                                    "L900-L959 \"%s\")"),
                                 high, seed));
        // TRANSLATORS: the second %s is a quotation of the French handbook; keep it as it is.
        warn(err::wProfileL,
             strf(tr("L%d read in a roughing-cycle profile (seed 000: L100-L199 and L900-L959 "
                     "\"%s\"): "
                     "the NUM stops with error 96; copy it into L0-L19 before the cycle"),
                  high, seed));
    }
    return true;
}

// The first block of the profile is its start point. A coordinate it
// does not write is the one in force there: the nearest block above
// that writes it (%555: G65 N120 N170 starts at N120 G1 X60).
bool Interpreter::profile_start(Plan& q, ProfileRead& r) {
    for (int ax : {X, Z}) {
        if (q.to.axis[size_t(ax)]) continue;
        double v;
        if (!coordinate_above(r.prog, r.first_line, ax, v))
            return fail(871, tr("the first block of the profile needs X and Z"));
        q.to.axis.set(size_t(ax));
        q.to.inc.reset(size_t(ax));
        q.to.val[size_t(ax)] = v;
    }
    r.pos = comp::V2(q.to.inc[Z] ? r.pos.x() + q.to.val[Z] : q.to.val[Z],
                     q.to.inc[X] ? r.pos.y() + q.to.val[X] : q.to.val[X]);
    r.start = r.pos;
    r.solver.start(r.pos);
    r.started = true;
    return true;
}

// A profile block in the solver's plane: Z is its first axis, X its second
// (I and K the centre's), as the PGP of the lathe writes them.
pgp::Spec Interpreter::profile_spec(const Plan& q, const comp::V2& cur, int line) const {
    pgp::Spec s;
    s.g = (modal_.motion == 2 || modal_.motion == 3) ? modal_.motion : 1;
    s.has_x = q.to.axis[Z];
    s.x = q.to.inc[Z] ? cur.x() + q.to.val[Z] : q.to.val[Z];
    s.has_y = q.to.axis[X];
    s.y = q.to.inc[X] ? cur.y() + q.to.val[X] : q.to.val[X];
    s.has_ea = q.pgp.has_ea;
    s.ea = q.pgp.ea;
    s.has_i = q.to.ijk[2];
    s.i = q.to.ijk_val[2] + (q.to.ijk_inc[2] ? cur.x() : 0);
    s.has_j = q.to.ijk[0];
    s.j = q.to.ijk_val[0] + (q.to.ijk_inc[0] ? cur.y() : 0);
    s.has_r = q.to.has_r;
    s.r = q.to.r;
    s.link = q.pgp.link == 'X' ? 'S' : q.pgp.link;
    s.disc = q.pgp.disc;
    s.has_eb = q.pgp.has_eb;
    s.eb = q.pgp.eb;
    s.eb_unsigned = q.pgp.eb_unsigned;
    s.tag = line;
    return s;
}

// One block of the profile, decoded: its modal words, then the element it adds.
// A block that moves nothing still goes to the solver, which allows only two
// of them while an element is incomplete (error 136).
bool Interpreter::profile_block(Plan& q, int line, ProfileRead& r) {
    if (q.mode.motion >= 0) modal_.motion = q.mode.motion;
    if (q.mode.dist >= 0) modal_.incremental = q.mode.dist == 91;
    if (q.tech.has_f && profile_feed_ <= 0) profile_feed_ = q.tech.f;
    if (!r.started) return profile_start(q, r);
    bool motion = q.to.axis[X] || q.to.axis[Z] || q.pgp.any || q.to.ijk.any() || q.to.has_r;
    if (!motion) {
        if (Error e = r.solver.idle()) return fail(e);
        return true;
    }
    // Error 72 before any intersection is sought (issue 39 item 6): the NUM
    // reads a block before it solves the incomplete one above it, and a
    // relative word leaves it nothing to solve with (%5200 N300, "G91 Z-.1"
    // after N290's chamfer EB-1, was answered 113), as outside a cycle.
    if (r.solver.pending() && (q.to.inc[X] || q.to.inc[Z] || q.to.ijk_inc.any()))
        return fail(72, tr("relative programming (G91) after an incomplete profile block"));
    if (Error e = r.solver.push(profile_spec(q, r.solver.position(), line), r.elems))
        return fail(e);
    ++r.count;
    return true;
}

// The elements in the order the cycle calls them: written N<b> before N<a>,
// the same elements from the last point to the first.
void Interpreter::profile_as_called(const std::vector<pgp::Elem>& elems, bool reversed,
                                    turning::Profile& out, comp::V2& first) {
    out.elems.clear();
    for (const auto& el : elems) out.elems.push_back(el.geo);
    if (!reversed) return;
    std::reverse(out.elems.begin(), out.elems.end());
    for (auto& el : out.elems) {
        std::swap(el.a, el.b);
        el.sweep = -el.sweep;
    }
    first = out.elems.front().a;
}

bool Interpreter::turning_profile(long na, long nb, turning::Profile& out, comp::V2& first) {
    const ProgramText* prog = stack_.back().prog;
    const Label* a = prog->find_label(na);
    const Label* b = prog->find_label(nb);
    if (!a || !b)
        return fail(871, strf(tr("the profile block N%ld is not in the program"), !a ? na : nb));
    bool reversed = b->line < a->line;
    profile_feed_ = 0;
    const Label* lo = reversed ? b : a;
    const Label* hi = reversed ? a : b;
    std::string_view text = *prog->text;
    Loc saved = loc_;
    Modal saved_modal = modal_;
    Block blk;
    ProfileRead r;
    r.prog = prog;
    r.first_line = lo->line;
    r.pos = comp::V2(prog_[Z], prog_[X]);
    size_t pos_off = lo->offset;
    for (int line = lo->line; line <= hi->line && pos_off < prog->end; ++line) {
        size_t eol = std::min(text.find('\n', pos_off), prog->end);
        std::string_view l = text.substr(pos_off, eol - pos_off);
        pos_off = eol + 1;
        loc_ = Loc{prog->number, line, line_label(l)};
        if (Error e = parse_block(l, blk)) return fail(e);
        if (blk.empty()) continue;
        if (!profile_l_words(blk)) return false;
        Plan q;
        if (!decode(blk, q) || !profile_block(q, line, r)) return false;
    }
    if (Error e = r.solver.finish(r.elems)) return fail(e);
    loc_ = saved;
    modal_ = saved_modal;
    if (!r.started || r.elems.empty())
        return fail(871, strf(tr("the profile N%ld..N%ld has no element"), na, nb));
    if (r.count > 50) return fail(871, tr("a profile has at most 50 blocks"));
    first = r.start;
    profile_as_called(r.elems, reversed, out, first);
    return true;
}

// The absolute value of `axis` written by the nearest block above `line`.
bool Interpreter::coordinate_above(const ProgramText* prog, int line, int axis, double& v) {
    std::string_view text = *prog->text;
    // Line start offsets of the program, up to `line`.
    std::vector<size_t> starts;
    size_t pos = prog->begin;
    for (int l = prog->first_line; l < line && pos < prog->end; ++l) {
        starts.push_back(pos);
        pos = text.find('\n', pos) + 1;
    }
    Block blk;
    for (size_t i = starts.size(); i-- > 0;) {
        size_t eol = std::min(text.find('\n', starts[i]), prog->end);
        if (Error e = parse_block(text.substr(starts[i], eol - starts[i]), blk)) return false;
        Plan q;
        if (!decode(blk, q)) return false;
        if (q.to.axis[size_t(axis)] && !q.to.inc[size_t(axis)] && !q.g[52]) {
            v = q.to.val[size_t(axis)];
            return true;
        }
    }
    return false;
}

// Runs the moves of a cycle. Threading moves (g 1 of G33/G38) are at `lead` mm per
// revolution when lead > 0; infeed moves at `infeed` mm/min or per rev when > 0.
bool Interpreter::turning_emit(const std::vector<turning::Move>& moves, double lead,
                               double infeed) {
    Modal saved = modal_;
    std::optional<OwnFeed> own;
    if (lead > 0) own.emplace(*this);  // threading runs at its lead
    for (const turning::Move& m : moves) {
        Axes t = prog_;
        t[Z] = m.to.x();
        t[X] = m.to.y();
        modal_.feed = saved.feed;
        modal_.feed_mode = saved.feed_mode;
        modal_.feed_set = saved.feed_set;
        if (!saved.feed_set && profile_feed_ > 0) {
            // No F since G95 (%5300 writes G64 with no F after "G80 G40 G95"): the
            // cutting feed is the first F of the finished profile (000:10470).
            modal_.feed = profile_feed_;
            modal_.feed_set = true;
            feed_programmed_ = true;
        }
        if (lead > 0 && (m.g == 33 || m.g == 1)) {
            modal_.feed_mode = 95;
            modal_.feed = lead;
            modal_.feed_set = true;
        } else if (m.infeed && infeed > 0) {
            modal_.feed = infeed;
            modal_.feed_set = true;
        }
        bool ok;
        if (m.g == 2 || m.g == 3) {
            double r0 = std::hypot(prog_[Z] - m.c.x(), prog_[X] - m.c.y());
            double r1 = (m.to - m.c).norm();
            ok = emit_arc(m.g, t, Z, X, m.c.x(), m.c.y(), m.sweep, r0, r1, -1);
        } else {
            ok = cycle_move(m.g == 0 ? 0 : 1, t);  // g33: a line at the lead per revolution
        }
        if (!ok) return false;
        if (m.dwell > 0) cycle_dwell(m.dwell);
        if (m.spindle == 3 || m.spindle == 4) {
            modal_.spindle_dir = m.spindle;
            saved.spindle_dir = m.spindle;
            set_spindle_event();
        }
    }
    saved.spindle_dir = modal_.spindle_dir;
    modal_ = saved;
    return true;
}

namespace {
// The X and Z of a cycle's arguments, as the block writes them.
template <class Args, class P>
void block_end(Args& a, const P& p) {
    a.has_x = p.to.axis[X];
    a.x = p.to.val[X];
    a.has_z = p.to.axis[Z];
    a.z = p.to.val[Z];
}
}  // namespace

// G64 only records its arguments: its rough stock is in the blocks that follow,
// up to the G80 that runs it (turning_g64_run).
bool Interpreter::turning_g64(const Plan& p) {
    if (p.spline.nn < 2) return fail(871, tr("G64 needs the profile blocks N.. N.."));
    g64_ = turning::G64Args{};
    g64_.i = cyc(p, addr1('I'), 0);
    g64_.k = cyc(p, addr1('K'), 0);
    g64_.p = cyc(p, addr1('P'), 0, &g64_.has_p);
    g64_.r = cyc(p, addr1('R'), 0, &g64_.has_r);
    if (!g64_.has_p && !g64_.has_r)
        return fail(873, tr("G64 needs P (passes along Z) or R (passes along X)"));
    if (g64_.has_p && g64_.has_r) return fail(889, tr("G64 takes P or R, not both"));
    if (g64_.p < 0 || g64_.r < 0) return fail(835, tr("G64: P and R are positive"));
    g64_na_ = p.spline.n[0];
    g64_nb_ = p.spline.n[1];
    g64_tool_ = comp::V2(prog_[Z], prog_[X]);
    g64_stock_.clear();
    g64_loc_ = loc_;
    g64_pending_ = true;
    return true;
}

turning::G65Args Interpreter::g65_args(const Plan& p) {
    turning::G65Args a;
    block_end(a, p);
    a.i = cyc(p, addr1('I'), 0);
    a.k = cyc(p, addr1('K'), 0);
    a.ea = cyc(p, addrE('A'), 0, &a.has_ea);
    a.p = cyc(p, addr1('P'), 0, &a.has_p);
    a.r = cyc(p, addr1('R'), 0, &a.has_r);
    a.q = cyc(p, addr1('Q'), 0);
    return a;
}

// EX and EU are diameters when the machine shows X as a diameter.
turning::G63Args Interpreter::g63_args(const Plan& p) const {
    const bool diam = m_.x_diameter && !modal_.radius_x;
    auto xpos = [&](Addr a, bool& has) {
        double v = cyc(p, a, 0, &has);
        return diam ? v / 2 : v;
    };
    turning::G63Args a;
    block_end(a, p);
    a.ex = xpos(addrE('X'), a.has_ex);
    a.ez = cyc(p, addrE('Z'), 0, &a.has_ez);
    a.p = cyc(p, addr1('P'), 0, &a.has_p);
    a.r = cyc(p, addr1('R'), 0, &a.has_r);
    a.ea = cyc(p, addrE('A'), 0, &a.has_ea);
    a.eu = xpos(addrE('U'), a.has_eu);
    a.ew = cyc(p, addrE('W'), 0, &a.has_ew);
    a.eb = cyc(p, addrE('B'), 90, &a.has_eb);
    a.ec = cyc(p, addrE('C'), 0, &a.has_ec);
    a.er = cyc(p, addrE('R'), 0);
    a.q = cyc(p, addr1('Q'), 0);
    a.eq = cyc(p, addrE('Q'), 0);
    return a;
}

// The moves of G65, G63 and G66 run with the infeed at EF when the block gives it.
bool Interpreter::turning_emit_ef(const Plan& p, const std::vector<turning::Move>& moves) {
    bool has_ef;
    double ef = cyc(p, addrE('F'), 0, &has_ef);
    return turning_emit(moves, 0, has_ef ? ef : 0);
}

// G65 and G63 cut along the finished profile N<a>..N<b>, read first: its errors
// come before those of the arguments.
bool Interpreter::turning_g65_g63(const Plan& p) {
    if (p.spline.nn < 2)
        return fail(871, strf(tr("G%d needs the profile N.. N.."), p.g[65] ? 65 : 63));
    const comp::V2 tool(prog_[Z], prog_[X]);
    turning::Profile prof;
    comp::V2 first;
    if (!turning_profile(p.spline.n[0], p.spline.n[1], prof, first)) return false;
    std::vector<turning::Move> moves;
    Error e;
    if (p.g[65]) {
        turning::G65Args a = g65_args(p);
        if (!a.has_ea) return fail(2, tr("G65 needs the infeed angle EA"));
        e = turning::g65(prof, tool, a, moves);
        if (!e && opt_.on_g65) opt_.on_g65(prof, tool, a, moves);
        if (!e && a.allowance_inside) warn_allowance_inside(65, a.i, a.k);
    } else {
        turning::G63Args a = g63_args(p);
        e = turning::g63(prof, tool, a, moves);
        if (!e && opt_.on_g63) opt_.on_g63(prof, tool, a, moves);
    }
    if (e) return fail(e);
    if (!turning_emit_ef(p, moves)) return false;
    modal_.motion = 0;  // the state is G00 after the cycle (000:2462)
    return true;
}

namespace {
// Warning 1117 too: the second corrector's edge lies on the start side of the
// first's, so the blade reaches back over A at the first plunge and the last
// one runs the width past B (issue 39 item 3). Empty when it does not.
std::string g66_swapped(const turning::G66Args& a, const comp::V2& tool) {
    if (!a.has_x || !a.has_z || (!a.has_p && !a.has_r)) return {};
    const double edge =
        a.has_p ? -a.gauge_delta.y() : -a.gauge_delta.x();           // D's edge from the first
    const double ahead = a.has_p ? a.x - tool.y() : a.z - tool.x();  // B from A
    if (std::fabs(edge) <= 1e-6 || edge * ahead >= 0) return {};
    return strf(tr("G66: the edge of D%d lies on the start side of the edge of D%d: the groove is "
                   "cut %.3f mm beyond B and before A; swap the correctors"),
                a.d, a.d_first, std::fabs(edge));
}
}  // namespace

// G66 cuts a groove with the tool's two edges, the active corrector and D:
// the difference of their gauges is the tool's width.
bool Interpreter::turning_g66(const Plan& p) {
    turning::G66Args a;
    a.d_first = modal_.d;
    // D is a corrector number: one past the table was read outside it (issue
    // 40, the cycle sweep's D1e6), refused as D300 is in any block (error 8).
    const double dv = cyc(p, addr1('D'), 0);
    if (!(dv <= m_.correctors))
        return fail(
            8, strf(tr("corrector D%d above D%d"), int(std::min(dv, 1e9)), int(m_.correctors)));
    a.d = int(dv);
    if (a.d > 0 && a.d <= m_.correctors && modal_.d > 0) {
        const Corrector& c1 = corr_[size_t(modal_.d)];
        const Corrector& c2 = corr_[size_t(a.d)];
        a.gauge_delta =
            comp::V2((c2.z + c2.dz) - (c1.z + c1.dz), (c2.x + c2.dx / 2) - (c1.x + c1.dx / 2));
    }
    block_end(a, p);
    a.ea = cyc(p, addrE('A'), 0);
    a.p = cyc(p, addr1('P'), 0, &a.has_p);
    a.r = cyc(p, addr1('R'), 0, &a.has_r);
    a.ep = cyc(p, addrE('P'), 0);
    a.ef = cyc(p, addrE('F'), 0);
    // Warning 1117: the two correctors are the tool's two edges; their
    // difference is its width (seed 000, G66).
    if (a.d > 0 && a.d_first > 0 && a.gauge_delta.norm() < 1e-6)
        warn(err::wNoToolWidth,
             strf(tr("G66: D%d and D%d have the same gauges, so the tool has no width: the "
                     "far side of the groove is cut one tool width off; measure D%d on the "
                     "other edge of the tool"),
                  a.d_first, a.d, a.d));
    std::vector<turning::Move> moves;
    const comp::V2 tool(prog_[Z], prog_[X]);
    if (std::string why = g66_swapped(a, tool); !why.empty()) warn(err::wNoToolWidth, why);
    if (Error e = turning::g66(tool, a, moves)) return fail(e);
    if (opt_.on_g66) opt_.on_g66(tool, a, moves);
    if (!turning_emit_ef(p, moves)) return false;
    // The second corrector is active afterwards; the tool has not moved
    // (000:2791-2840; pupitre-iso(5), TURNING CYCLES).
    modal_.d = a.d;
    frames_.gauge[X] = gauge_for(a.d, X);
    frames_.gauge[Z] = gauge_for(a.d, Z);
    gauge_pending_.reset();
    recompute_program_pos();
    modal_.motion = 0;
    return true;
}

// G33: one thread, its passes planned by the cycle, at the lead K.
bool Interpreter::turning_g33(const Plan& p) {
    turning::G33Args a;
    block_end(a, p);
    a.k = cyc(p, addr1('K'), 0, &a.has_k);
    a.ea = cyc(p, addrE('A'), 0);
    a.eb = cyc(p, addrE('B'), 0);
    a.p = cyc(p, addr1('P'), 0, &a.has_p);
    a.q = cyc(p, addr1('Q'), 0, &a.has_q);
    a.r = cyc(p, addr1('R'), 0);
    a.f = cyc(p, addr1('F'), 1, &a.has_f);
    a.s = cyc(p, addr1('S'), 1, &a.has_s);
    a.es = cyc(p, addrE('S'), 1, &a.has_es);
    a.spindle_turning = modal_.spindle_dir == 3 || modal_.spindle_dir == 4;
    a.plane_ok = true;
    a.radius_comp = modal_.radcomp != 40;
    std::vector<turning::Move> moves;
    if (Error e = turning::g33(comp::V2(prog_[Z], prog_[X]), a, moves)) return fail(e);
    return turning_emit(moves, a.k, 0);
}

// G38: chained threading, modal in the motion group. A block without K keeps
// the lead of the previous one, so that the chain is one thread.
bool Interpreter::turning_g38(const Plan& p) {
    turning::G38Args a;
    a.to = comp::V2(p.to.axis[Z] ? (p.to.inc[Z] ? prog_[Z] + p.to.val[Z] : p.to.val[Z]) : prog_[Z],
                    p.to.axis[X] ? (p.to.inc[X] ? prog_[X] + p.to.val[X] : p.to.val[X]) : prog_[X]);
    bool has_k;
    double k = cyc(p, addr1('K'), 0, &has_k);
    if (!has_k && p.to.ijk[2]) k = p.to.ijk_val[2], has_k = true;  // K in a following G38 block
    if (!has_k) k = g38_lead_, has_k = g38_lead_ > 0;
    a.has_k = has_k;
    a.k = k;
    a.prev_k = g38_lead_;
    a.spindle_turning = modal_.spindle_dir == 3 || modal_.spindle_dir == 4;
    a.radius_comp = modal_.radcomp != 40;
    std::vector<turning::Move> moves;
    if (Error e = turning::g38(comp::V2(prog_[Z], prog_[X]), a, moves)) return fail(e);
    g38_lead_ = k;
    return turning_emit(moves, k, 0);
}

// A block that programs G63, G64, G65, G66, G33 or G38 (G64: the stock follows).
// The first function present in this order is the block's cycle.
bool Interpreter::turning_block(const Plan& p) {
    if (modal_.radcomp != 40) return fail(140, tr("a turning cycle under radius compensation"));
    static constexpr struct {
        int g;
        bool (Interpreter::*run)(const Plan&);
    } kCycles[] = {{64, &Interpreter::turning_g64},
                   {65, &Interpreter::turning_g65_g63},
                   {63, &Interpreter::turning_g65_g63},
                   {66, &Interpreter::turning_g66},
                   {33, &Interpreter::turning_g33}};
    for (const auto& c : kCycles)
        if (p.g[size_t(c.g)]) return (this->*c.run)(p);
    return turning_g38(p);
}

// While a G64 waits for its G80: the blocks are the rough stock, not moves.
bool Interpreter::turning_stock(const Plan& p) {
    if (p.g[2] || p.g[3] || p.pgp.any || p.mode.motion == 2 || p.mode.motion == 3)
        return fail(889, tr("the rough stock of G64 is made of points, no circle or PGP"));
    comp::V2 last = g64_stock_.empty() ? comp::V2(NAN, NAN) : g64_stock_.back();
    if (!p.to.axis[X] && !p.to.axis[Z]) return true;  // a comment or a label: no point
    if (g64_stock_.empty() && (!p.to.axis[X] || !p.to.axis[Z]))
        return fail(872, tr("the first point of the rough stock needs X and Z"));
    comp::V2 pt(p.to.axis[Z] ? p.to.val[Z] : last.x(), p.to.axis[X] ? p.to.val[X] : last.y());
    g64_stock_.push_back(pt);
    return true;
}

// The G80 that ends a G64: the roughing runs before the rest of the block.
bool Interpreter::turning_g64_run() {
    g64_pending_ = false;
    if (g64_stock_.empty()) return fail(872, tr("G64 without a rough stock before G80"));
    std::vector<std::array<double, 2>> zr;
    for (const auto& q : g64_stock_) zr.push_back({q.x(), q.y()});
    out_.stock(g64_loc_, zr);
    Loc saved = loc_;
    loc_ = g64_loc_;
    turning::Profile prof;
    comp::V2 first;
    if (!turning_profile(g64_na_, g64_nb_, prof, first)) return false;
    std::vector<turning::Move> moves;
    if (Error e = turning::g64(prof, g64_stock_, g64_tool_, g64_, moves)) return fail(e);
    if (opt_.on_g64) opt_.on_g64(prof, g64_stock_, g64_tool_, g64_, moves);
    if (g64_.allowance_inside) warn_allowance_inside(64, g64_.i, g64_.k);
    bool ok = turning_emit(moves, 0, 0);
    loc_ = saved;
    modal_.motion = 0;
    return ok;
}

}  // namespace pupitre
