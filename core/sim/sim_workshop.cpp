// The Sim's side of the workshop (ARCHITECTURE.md, the workshop): each move meets the part as
// the machine starts it (see sim.hpp, set_workshop).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>

#include "core/sim/sim.hpp"
#include "core/workshop/report.hpp"

namespace pupitre {

void Sim::set_workshop(std::unique_ptr<workshop::Workshop> w) {
    shop_ = std::move(w);
    if (!shop_) return;
    // The turret and the spindle as they are now.
    shop_->tool(Loc{}, tool_, corr_, 0, true);
    shop_->spindle(sp_);
}

// The workshop meets the move as the machine starts it: a crash cuts it short
// and ends the run with an alarm once the axes have stopped; a jog stops at
// the first contact.
void Sim::through_workshop(Ev& e) {
    if (!shop_ || e.kind != Ev::move || mode_ == Mode::test) return;
    workshop::Outcome o = manual_ ? shop_->jog(e.m, mode_ == Mode::jog) : shop_->apply(e.m);
    if (!o.crashed && !o.touched) return;
    e.m = workshop::Workshop::truncated(e.m, o.stop, o.fraction);
    dur_ = duration(e);
    if (prof_.planned) {
        // The planned speed up to the contact, where the axes stop.
        prof_scale_ = std::clamp(o.fraction, 0.0, 1.0);
        dur_ = prof_.time_at(prof_.length * prof_scale_);
    }
    for (int a = 0; a < kAxes; ++a)
        op_off1_[size_t(a)] = e.m.to_mach[size_t(a)] - e.m.to_prog[size_t(a)];
    q_.clear();
    // What the interpreter ran ahead of the move is abandoned with the
    // queue: the workshop has not met it (it meets a move as it starts).
    if (!manual_) plan_reset(false);
    planned_ = o.stop;
    in_->place(o.stop);
    message_ = o.what;
    ++workshop_news_;
    if (o.touched) return;
    Diag d = workshop_diag(shop_->crashes().back());
    alarms_.push_back(Alarm{d, clock_});
    if (path_) path_->add_error(d);
    interp_done_ = true;
    pending_alarm_ = true;
    alarm_loc_ = Loc{};  // the crash is the move's, shown now
}

Diag Sim::workshop_diag(const workshop::Crash& c) const {
    Diag d = workshop::crash_diag(c);
    const ProgramText* p =
        c.loc.prog > 0 || (imd_ && c.loc.line > 0) ? text_of(c.loc.prog) : nullptr;
    // A crash in JOG or INC comes from no block: it is the mode's.
    d.file = p ? p->file : manual_ ? std::string(mode_name(mode_)) : "-";
    return d;
}

}  // namespace pupitre
