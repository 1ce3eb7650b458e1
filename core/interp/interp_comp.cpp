// Tool radius compensation G41/G42 in the interpreter: one element of look-ahead.
// A compensated element is held until the next one is known (its end depends on
// the joint); the events of the blocks in between are held with it (GateSink) so
// the trace keeps the order of execution. Entry: a line ending on the normal of
// the next element; exit (G40): a line from the normal at the end of the last one
// (000:3889-3938; pupitre-iso(5), TOOLS AND CORRECTORS, 004:756-757).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/interp/gate.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

using geometry::kNose;

bool Interpreter::comp_engage(int g) {
    const Corrector& c = corr_[size_t(modal_.d)];
    double r = c.r + (m_.lathe ? 0 : c.dr);
    if (comp_.on) {
        // G41 <-> G42 without G40 (000:1020): the last element ends on its normal,
        // then a new entry starts from there.
        if (!comp_exit(nullptr)) return false;
    }
    if (r <= 1e-9) return true;  // R0: the programmed path is the tool path
    comp_ = Comp{};
    comp_.on = true;
    comp_.waiting_entry = true;
    comp_.radius = r;
    comp_.a0 = m_.lathe ? Z : modal_.plane == 17 ? X : modal_.plane == 18 ? Z : Y;
    comp_.a1 = m_.lathe ? X : modal_.plane == 17 ? Y : modal_.plane == 18 ? X : Z;
    comp_.side = g == 41 ? 1 : -1;
    // A mirror on one axis of the plane swaps left and right (000:10627-10646;
    // pupitre-iso(5), COORDINATES AND OFFSETS).
    if (frames_.mirror[size_t(comp_.a0)] != frames_.mirror[size_t(comp_.a1)])
        comp_.side = -comp_.side;
    if (m_.lathe) {
        int code = (c.c >= 0 && c.c <= 8) ? c.c : 0;
        comp_.shift = comp::V2(kNose[code][1] * r, kNose[code][0] * r);  // (Z, X)
    }
    return true;
}

// Emits pieces of the tool-centre path with the context of the block they come from.
bool Interpreter::comp_emit(const std::vector<comp::Piece>& pieces, const CompCtx& ctx) {
    Loc saved_loc = loc_;
    Modal saved_modal = modal_;
    Axes saved_prog = prog_;
    loc_ = ctx.loc;
    modal_ = ctx.modal;
    const int a0 = comp_.a0, a1 = comp_.a1;
    const int an = m_.lathe ? -1 : modal_.plane == 17 ? Z : modal_.plane == 18 ? Y : X;
    bool ok = true;
    comp_emitting_ = comp_.radius > 0;
    for (const comp::Piece& pc : pieces) {
        prog_ = frames_.to_program(mach_);  // where the tool is
        Axes tgt = ctx.target;
        tgt[size_t(a0)] = pc.to.x() + comp_.shift.x();
        tgt[size_t(a1)] = pc.to.y() + comp_.shift.y();
        if (!pc.arc) {
            prog_next_ = tgt;
            Axes mach = frames_.to_machine(tgt);
            ok = check_travel(mach) && linear(ctx.g == 0 ? 0 : 1, mach, false, {});
        } else {
            double c0 = pc.c.x() + comp_.shift.x(), c1 = pc.c.y() + comp_.shift.y();
            const double d0 = prog_[size_t(a0)] - c0, d1 = prog_[size_t(a1)] - c1;
            double r = std::sqrt(d0 * d0 + d1 * d1);  // hypot was 4% of a compensated run
            double feed = modal_.feed;
            // G92 R: F at the contact point on arcs of radius >= R (000:5205-5241),
            // never on the connecting circles (S4 L992).
            if (!pc.connecting && ctx.rp > 0 && modal_.g92r > 0 && ctx.rp >= modal_.g92r)
                modal_.feed = feed * r / ctx.rp;
            if (pc.connecting) {
                // The corner circle leaves the other axes where they are.
                for (int a = 0; a < kAxes; ++a)
                    if (a != a0 && a != a1) tgt[size_t(a)] = prog_[size_t(a)];
            }
            ok = emit_arc(pc.sweep > 0 ? 3 : 2, tgt, a0, a1, c0, c1, pc.sweep, r, r,
                          pc.connecting ? -1 : an);
            modal_.feed = feed;
        }
        if (!ok) break;
    }
    comp_emitting_ = false;
    loc_ = saved_loc;
    modal_ = saved_modal;
    prog_ = saved_prog;
    return ok;
}

bool Interpreter::comp_element(const comp::Elem& e, int g, const Axes& target, double rp) {
    CompCtx ctx{loc_, modal_, g, target, rp};
    // The drawing's programmed profile: reported before the offset, so that a
    // gouge (149) shows the element the tool could not follow.
    ProfileElem pe{comp_.a0,
                   comp_.a1,
                   {e.a.x(), e.a.y()},
                   {e.b.x(), e.b.y()},
                   {e.c.x(), e.c.y()},
                   e.sweep * 180 / std::numbers::pi,
                   e.arc};
    out_.profile(loc_, pe);
    if (comp_.waiting_entry) {
        if (e.arc)
            return fail(140,
                        tr("the first block in radius compensation must be a line (G00 or G01)"));
        Axes tp = frames_.to_program(mach_);
        comp_.tc = comp::V2(tp[size_t(comp_.a0)], tp[size_t(comp_.a1)]) - comp_.shift;
        comp_.waiting_entry = false;
        comp_.has_pending = true;
        comp_.pending_is_entry = true;
        comp_.pending = e;
        comp_.ctx = ctx;
        prog_ = target;
        gate_->holding = true;
        return true;
    }
    std::vector<comp::Piece>& pieces = comp_pieces_;
    pieces.clear();
    comp::V2 next_from;
    gate_->holding = false;
    if (comp_.pending_is_entry) {
        // The entry ends on the normal to the next element at its start (000:3938).
        next_from =
            comp_.pending.b + comp_.radius * comp::normal(comp::start_tangent(e), comp_.side);
        comp::Piece p;
        p.to = next_from;
        pieces.push_back(p);
    } else if (int rc = comp::join(comp_.pending, comp_.tc, e, comp_.radius, comp_.side, pieces,
                                   next_from)) {
        return fail(rc, strf(tr("the tool radius %s does not fit the profile here (an offset "
                                "element vanishes or reverses)"),
                             std::to_string(comp_.radius).substr(0, 7).c_str()));
    }
    if (!comp_emit(pieces, comp_.ctx)) return false;
    gate_->release();
    comp_.pending = e;
    comp_.pending_is_entry = false;
    comp_.ctx = ctx;
    comp_.tc = next_from;
    prog_ = target;
    gate_->holding = true;
    return true;
}

// A move with no displacement in the plane (Z alone in G17): made at the corner,
// when the held element has been joined to the next.
bool Interpreter::comp_other_axes(const Axes& target, const std::bitset<kAxes>& axes) {
    CompCtx ctx{loc_, modal_, modal_.motion == 0 ? 0 : 1, target, 0};
    auto move = [this, ctx, axes]() {
        Loc saved_loc = loc_;
        Modal saved_modal = modal_;
        Axes saved_prog = prog_;
        loc_ = ctx.loc;
        modal_ = ctx.modal;
        prog_ = frames_.to_program(mach_);
        Axes tgt = prog_;
        for (int a = 0; a < kAxes; ++a)
            if (axes[size_t(a)] && a != comp_.a0 && a != comp_.a1)
                tgt[size_t(a)] = ctx.target[size_t(a)];
        prog_next_ = tgt;
        Axes mach = frames_.to_machine(tgt);
        bool ok = check_travel(mach) && linear(ctx.g, mach, false, axes);
        loc_ = saved_loc;
        if (ok) modal_ = saved_modal;
        prog_ = saved_prog;
        return ok;
    };
    for (int a = 0; a < kAxes; ++a)
        if (axes[size_t(a)] && a != comp_.a0 && a != comp_.a1) prog_[size_t(a)] = target[size_t(a)];
    if (!gate_->holding) return move();
    gate_->later([this, move]() {
        if (!ended_) move();
    });
    return true;
}

// G40: the held element ends on the normal at its end point; the G40 move (a
// line) goes from there to the programmed point.
bool Interpreter::comp_exit(const Axes* target) {
    if (target && (modal_.motion == 2 || modal_.motion == 3))
        return fail(140, tr("the block that ends radius compensation (G40) must be a line"));
    if (comp_.has_pending) {
        std::vector<comp::Piece>& pieces = comp_pieces_;
        pieces.clear();
        gate_->holding = false;
        if (comp_.pending_is_entry) {
            comp::Piece p;
            p.to = comp_.pending.b;
            pieces.push_back(p);
        } else if (int rc =
                       comp::finish(comp_.pending, comp_.tc, comp_.radius, comp_.side, pieces)) {
            return fail(rc, tr("the tool radius does not fit the last element of the profile"));
        }
        if (!comp_emit(pieces, comp_.ctx)) return false;
        gate_->release();
    }
    gate_->holding = false;
    comp_ = Comp{};
    if (!target) return true;
    prog_next_ = *target;
    Axes mach = frames_.to_machine(*target);
    if (!check_travel(mach)) return false;
    return linear(modal_.motion, mach, false, {});
}

}  // namespace pupitre
