// The planner on a thread of its own (issue 35 item 7): in a batch run that
// only wants the cycle time (`pupitre run` without --trace), the interpreter
// hands its events over in batches and goes on with the next blocks while a
// second thread plans them, as a controller's interpreter runs ahead of its
// motion planner (LinuxCNC's task and motion are apart likewise). The plan is
// the same event for event as PlanSink's on the interpreter's thread: the
// events reach it in the order they were made. Memory is bounded by the
// batches, whatever the program's length.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "core/interp/held.hpp"
#include "core/plan/plan_sink.hpp"

namespace pupitre::plan {

class PlanThread final : public MachineSink {
  public:
    explicit PlanThread(const MachineProfile& m);
    ~PlanThread() override;  // stops the thread, whatever was handed over
    PlanThread(const PlanThread&) = delete;
    PlanThread& operator=(const PlanThread&) = delete;

    // What the planner reads of a move is copied into the batch being
    // filled: the interpreter's thread does no more than that for it.
    void move(const MoveEvent& e) override {
        fill_->moves.emplace_back(e);
        if (fill_->moves.size() == kBatch) hand_over();
    }
    void dwell(const Loc& l, double s) override { other(held::Dwell{l, s}); }
    void tool(const Loc& l, int t, int d, double s, bool m6) override {
        other(held::Tool{l, t, d, s, m6});
    }
    void spindle(const SpindleEvent& e) override { other(SpindleEvent(e)); }
    void coolant(const Loc& l, bool m7, bool m8) override { other(held::Coolant{l, m7, m8}); }
    void stop(const Loc& l, int m) override { other(held::Stop{l, m}); }
    void message(const Loc& l, int channel, std::string_view text) override;
    void end(const Loc& l, int m) override { other(held::End{l, m}); }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) override {
        other(held::Stock{l, zr});
    }
    void profile(const Loc& l, const ProfileElem& e) override { other(held::Profile{l, e}); }
    void exact_stop(const Loc& l) override { other(held::ExactStop{l}); }

    // The run is over: what was handed over is planned to its end (PlanSink::
    // finish) and the thread has stopped. The report is read after it.
    void finish();
    const Report& report() const { return planner_.report(); }

  private:
    // Moves in a batch: a hand-over wakes the other thread, which costs tens
    // of microseconds on a virtual machine (512 a batch once cost a fifth of
    // the run; measured again later, no difference either way), and 4096
    // moves of 216 bytes stay within the processors' caches.
    static constexpr size_t kBatch = 4096;
    // What is not a move waits in the batch with the number of moves before
    // it, so that the planner hears everything in its order.
    struct Batch {
        std::vector<PlanMove> moves;
        std::vector<std::pair<size_t, held::Event>> others;
    };
    // A batch is handed over when its moves or its other events are
    // kBatch: a program that only talks holds no more than one that moves.
    void other(held::Event ev) {
        fill_->others.emplace_back(fill_->moves.size(), std::move(ev));
        if (fill_->others.size() == kBatch) hand_over();
    }
    void hand_over();  // the batch being filled to the planner's thread; an empty one to fill
    void work();       // the planner's thread
    void plan(Batch& b);

    PlanSink planner_;  // the planner's thread's alone while it runs
    std::vector<std::unique_ptr<Batch>> batches_;
    Batch* fill_ = nullptr;
    std::mutex mu_;
    std::condition_variable cv_;
    std::vector<Batch*> full_, free_;  // under mu_: in the order handed over; ready to fill
    bool closing_ = false;             // under mu_: nothing more comes
    std::thread thread_;
};

}  // namespace pupitre::plan
