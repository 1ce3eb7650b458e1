// A sink that forwards events, or holds them while a compensated move waits for
// the next element (its end depends on that element): events of the blocks in
// between then reach the real sink after the move, in execution order.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/interp/interp.hpp"

namespace pupitre {

class GateSink final : public MachineSink {
  public:
    explicit GateSink(MachineSink& real) : real_(real) {}
    bool holding = false;
    std::vector<std::function<void()>> queue;

    // Not holding, an event goes straight on: the copy a held entry needs
    // (a MoveEvent is some 300 bytes) is made only when it is held.
    void move(const MoveEvent& e) override {
        if (!holding) return real_.move(e);
        hold([this, e] { real_.move(e); });
    }
    void dwell(const Loc& l, double s) override {
        if (!holding) return real_.dwell(l, s);
        hold([this, l, s] { real_.dwell(l, s); });
    }
    void tool(const Loc& l, int t, int d, double s, bool m6) override {
        if (!holding) return real_.tool(l, t, d, s, m6);
        hold([=, this] { real_.tool(l, t, d, s, m6); });
    }
    void spindle(const SpindleEvent& e) override {
        if (!holding) return real_.spindle(e);
        hold([this, e] { real_.spindle(e); });
    }
    void coolant(const Loc& l, bool m7, bool m8) override {
        if (!holding) return real_.coolant(l, m7, m8);
        hold([=, this] { real_.coolant(l, m7, m8); });
    }
    void stop(const Loc& l, int m) override {
        if (!holding) return real_.stop(l, m);
        hold([=, this] { real_.stop(l, m); });
    }
    void message(const Loc& l, int ch, std::string_view t) override {
        if (!holding) return real_.message(l, ch, t);
        hold([this, l, ch, text = std::string(t)] { real_.message(l, ch, text); });
    }
    void end(const Loc& l, int m) override {
        if (!holding) return real_.end(l, m);
        hold([=, this] { real_.end(l, m); });
    }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& s) override {
        if (!holding) return real_.stock(l, s);
        hold([this, l, s] { real_.stock(l, s); });
    }
    void profile(const Loc& l, const ProfileElem& e) override {
        if (!holding) return real_.profile(l, e);
        hold([=, this] { real_.profile(l, e); });
    }

    // Runs the held entries in order, with holding off.
    void release() {
        holding = false;
        auto q = std::move(queue);
        queue.clear();
        for (auto& f : q) f();
        // The storage goes back to the queue unless a running entry added to
        // it: under compensation every block holds and releases, and the queue
        // was allocated anew each time.
        q.clear();
        if (queue.empty()) queue.swap(q);
    }

  private:
    template <class F>
    void hold(F&& f) {
        queue.emplace_back(std::forward<F>(f));
    }
    MachineSink& real_;
};

}  // namespace pupitre
