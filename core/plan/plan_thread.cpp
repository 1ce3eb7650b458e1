// The planner on a thread of its own (plan_thread.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/plan/plan_thread.hpp"

#include <string>

namespace pupitre::plan {

namespace {
// Three batches: one filled, one planned, one ready for the filler, so that
// neither thread waits for the other while both keep pace.
constexpr int kBatches = 3;
}  // namespace

PlanThread::PlanThread(const MachineProfile& m) : planner_(m) {
    for (int i = 0; i < kBatches; ++i) {
        batches_.push_back(std::make_unique<Batch>());
        batches_.back()->moves.reserve(kBatch);  // others grow as a program needs
        if (i > 0) free_.push_back(batches_.back().get());
    }
    fill_ = batches_.front().get();
    thread_ = std::thread([this] { work(); });
}

PlanThread::~PlanThread() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard lock(mu_);
        closing_ = true;
    }
    cv_.notify_all();
    thread_.join();
}

void PlanThread::message(const Loc& l, int channel, std::string_view text) {
    other(held::Message{l, channel, std::string(text)});
}

void PlanThread::hand_over() {
    std::unique_lock lock(mu_);
    full_.push_back(fill_);
    cv_.notify_all();
    cv_.wait(lock, [this] { return !free_.empty(); });
    fill_ = free_.back();
    free_.pop_back();
}

void PlanThread::finish() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard lock(mu_);
        full_.push_back(fill_);
        closing_ = true;
    }
    cv_.notify_all();
    thread_.join();
    fill_ = nullptr;
    planner_.finish();
}

void PlanThread::work() {
    for (;;) {
        Batch* b = nullptr;
        {
            std::unique_lock lock(mu_);
            cv_.wait(lock, [this] { return !full_.empty() || closing_; });
            if (full_.empty()) return;  // closing, everything planned
            b = full_.front();
            full_.erase(full_.begin());
        }
        plan(*b);
        {
            std::lock_guard lock(mu_);
            free_.push_back(b);
        }
        cv_.notify_all();
    }
}

// The batch's events to the planner in the order they were made, each other
// event before the move that followed it.
void PlanThread::plan(Batch& b) {
    held::Deliver to{planner_};
    const PlanMove* m = b.moves.data();
    const PlanMove* const end = m + b.moves.size();
    for (auto& [before, ev] : b.others) {  // the moves up to the next other event, then it
        const PlanMove* stop = b.moves.data() + before;
        planner_.moves(m, stop);
        m = stop;
        std::visit(to, ev);
    }
    planner_.moves(m, end);
    b.moves.clear();
    b.others.clear();
}

}  // namespace pupitre::plan
