// Profile geometry programming in the interpreter: blocks with EA, EB, ES, ET,
// E± or an incomplete circle go to the PGP solver (core/geometry/pgp.cpp),
// which gives back lines and arcs once their entity is determined; those are
// run like programmed elements (through radius compensation when it is on). The
// events of the blocks met meanwhile are held with them (pupitre-iso(5),
// PROFILE GEOMETRY PROGRAMMING (PGP); 000:8358-8564).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/gate.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

namespace {
int ijk_of(int axis) {
    return axis == X ? 0 : axis == Y ? 1 : 2;
}
}  // namespace

void Interpreter::plane_axes(int& a0, int& a1) const {
    a0 = m_.lathe ? Z : modal_.plane == 17 ? X : modal_.plane == 18 ? Z : Y;
    a1 = m_.lathe ? X : modal_.plane == 17 ? Y : modal_.plane == 18 ? X : Z;
}

bool Interpreter::pgp_wanted(const Plan& p) const {
    if (p.pgp.any || pgp_.pending()) return true;
    if (modal_.motion != 2 && modal_.motion != 3) return false;
    // An incomplete circle: PGP completes it from the next block
    // (000:8358-8564; pupitre-iso(5), PROFILE GEOMETRY PROGRAMMING (PGP)).
    int a0, a1;
    plane_axes(a0, a1);
    bool words = p.to.axis[size_t(a0)] || p.to.axis[size_t(a1)] || p.to.ijk.any() || p.to.has_r;
    bool centre = p.to.ijk[size_t(ijk_of(a0))] && p.to.ijk[size_t(ijk_of(a1))];
    bool complete = p.to.axis[size_t(a0)] && p.to.axis[size_t(a1)] && (centre != p.to.has_r);
    return words && !complete && (p.mode.motion == 2 || p.mode.motion == 3 || p.mode.motion < 0);
}

bool Interpreter::pgp_fail(const Error& e) {
    auto it = pgp_ctx_.find(e.item);
    if (it != pgp_ctx_.end()) loc_ = it->second.loc;
    return fail(e.code ? e.code : 113, e.detail);
}

// Runs resolved elements with the context of the block each comes from.
bool Interpreter::pgp_emit(const std::vector<pgp::Elem>& elems) {
    if (elems.empty()) return true;
    int a0, a1;
    plane_axes(a0, a1);
    gate_->holding = false;
    for (const pgp::Elem& e : elems) {
        auto it = pgp_ctx_.find(e.tag);
        CompCtx ctx = it != pgp_ctx_.end() ? it->second : CompCtx{loc_, modal_, 1, prog_, 0};
        Loc saved_loc = loc_;
        Modal saved_modal = modal_;
        loc_ = ctx.loc;
        modal_ = ctx.modal;
        Axes target = ctx.target;
        target[size_t(a0)] = e.geo.b.x();
        target[size_t(a1)] = e.geo.b.y();
        if (!e.inserted && !e.geo.arc && it != pgp_ctx_.end()) {
            // The block's other axes (Z…) move with its element.
        } else if (e.inserted) {
            for (int a = 0; a < kAxes; ++a)
                if (a != a0 && a != a1) target[size_t(a)] = prog_[size_t(a)];
        }
        int g = e.geo.arc ? (e.geo.sweep > 0 ? 3 : 2) : (ctx.g == 0 ? 0 : 1);
        double r = e.geo.arc ? e.geo.r() : 0;
        bool ok;
        if (comp_.on) {
            ok = comp_element(e.geo, g, target, r);
        } else if (!e.geo.arc) {
            prog_next_ = target;
            Axes mach = frames_.to_machine(target);
            ok = check_travel(mach) && linear(g, mach, false, {});
        } else {
            ok = emit_arc(g, target, a0, a1, e.geo.c.x(), e.geo.c.y(), e.geo.sweep, r,
                          (e.geo.b - e.geo.c).norm(), -1);
        }
        loc_ = saved_loc;
        modal_ = saved_modal;
        if (!ok) return false;
        prog_ = target;
        // Contexts of blocks whose elements are all out are no longer needed.
        while (!pgp_ctx_.empty() && pgp_ctx_.begin()->first < e.tag)
            pgp_ctx_.erase(pgp_ctx_.begin());
    }
    if (!comp_.on) gate_->release();
    return true;
}

// A block that goes to the solver.
bool Interpreter::pgp_block(const Plan& p, const Axes& target) {
    int a0, a1;
    plane_axes(a0, a1);
    const int i0 = ijk_of(a0), i1 = ijk_of(a1);
    const bool pending = pgp_.pending();
    // PGP is programmed in absolute; relative words after an incomplete block: 72.
    if (pending && (p.to.inc[size_t(a0)] || p.to.inc[size_t(a1)] || p.to.ijk_inc.any()))
        return fail(72, tr("relative programming (G91) after an incomplete profile block"));
    if (p.pgp.link == 'X') return fail(110, tr("ES and ET together in one block"));
    if (!pending) pgp_.start(pgp::V2(prog_[size_t(a0)], prog_[size_t(a1)]));
    pgp::Spec s;
    s.g = (modal_.motion == 2 || modal_.motion == 3) ? modal_.motion : 1;
    s.has_x = p.to.axis[size_t(a0)];
    s.x = target[size_t(a0)];
    s.has_y = p.to.axis[size_t(a1)];
    s.y = target[size_t(a1)];
    s.has_ea = p.pgp.has_ea;
    s.ea = p.pgp.ea;
    s.has_i = p.to.ijk[size_t(i0)];
    s.i = p.to.ijk_val[i0] + (p.to.ijk_inc[size_t(i0)] ? prog_[size_t(a0)] : 0);
    s.has_j = p.to.ijk[size_t(i1)];
    s.j = p.to.ijk_val[i1] + (p.to.ijk_inc[size_t(i1)] ? prog_[size_t(a1)] : 0);
    s.has_r = p.to.has_r;
    s.r = p.to.r;
    s.link = p.pgp.link;
    s.disc = p.pgp.disc;
    s.has_eb = p.pgp.has_eb;
    s.eb = p.pgp.eb;
    s.eb_unsigned = p.pgp.eb_unsigned;
    s.tag = ++pgp_tag_;
    if (p.pgp.has_eb && p.pgp.eb_unsigned)
        warn(err::wUnsignedEB, tr("EB without a sign is taken as a fillet (EB+): write EB+ or EB- "
                                  "(pupitre-iso(5), PGP)"));
    pgp_ctx_[s.tag] = CompCtx{loc_, modal_, modal_.motion, target, 0};
    std::vector<pgp::Elem> out;
    if (Error e = pgp_.push(s, out)) return pgp_fail(e);
    if (!pgp_emit(out)) return false;
    if (pgp_.pending()) {
        gate_->holding = true;
        // The end point is not known yet: the program position is where the
        // resolved profile stops.
        prog_[size_t(a0)] = pgp_.position().x();
        prog_[size_t(a1)] = pgp_.position().y();
    }
    return true;
}

// The profile ends (G40, a plane change, the end of the program…): what is still
// held is resolved or refused.
bool Interpreter::pgp_close() {
    if (!pgp_.pending()) return true;
    std::vector<pgp::Elem> out;
    if (Error e = pgp_.finish(out)) return pgp_fail(e);
    return pgp_emit(out);
}

}  // namespace pupitre
