// A sink that forwards events, or holds them while a compensated move waits for
// the next element (its end depends on that element): events of the blocks in
// between then reach the real sink after the move, in execution order.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/interp/held.hpp"
#include "core/interp/interp.hpp"

namespace pupitre {

class GateSink final : public MachineSink {
  public:
    explicit GateSink(MachineSink& real) : real_(real) {}
    bool holding = false;

    // A held event is kept as its values, not as a closure: under
    // compensation every block holds one (its profile element) and a
    // std::function of it was an allocation each time (issue 14). `Later`
    // is work of the interpreter's own that must wait its turn
    // (Interpreter::comp_other_axes).
    using Later = std::function<void()>;
    using Held =
        std::variant<MoveEvent, held::Dwell, held::Tool, SpindleEvent, held::Coolant, held::Stop,
                     held::Message, held::End, held::Stock, held::Profile, held::ExactStop, Later>;
    std::vector<Held> queue;

    // Not holding, an event goes straight on: the copy a held entry needs
    // (a MoveEvent is some 300 bytes) is made only when it is held.
    void move(const MoveEvent& e) override {
        if (!holding) return real_.move(e);
        queue.emplace_back(e);
    }
    void dwell(const Loc& l, double s) override {
        if (!holding) return real_.dwell(l, s);
        queue.emplace_back(held::Dwell{l, s});
    }
    void tool(const Loc& l, int t, int d, double s, bool m6) override {
        if (!holding) return real_.tool(l, t, d, s, m6);
        queue.emplace_back(held::Tool{l, t, d, s, m6});
    }
    void spindle(const SpindleEvent& e) override {
        if (!holding) return real_.spindle(e);
        queue.emplace_back(e);
    }
    void coolant(const Loc& l, bool m7, bool m8) override {
        if (!holding) return real_.coolant(l, m7, m8);
        queue.emplace_back(held::Coolant{l, m7, m8});
    }
    void stop(const Loc& l, int m) override {
        if (!holding) return real_.stop(l, m);
        queue.emplace_back(held::Stop{l, m});
    }
    void message(const Loc& l, int ch, std::string_view t) override {
        if (!holding) return real_.message(l, ch, t);
        queue.emplace_back(held::Message{l, ch, std::string(t)});
    }
    void end(const Loc& l, int m) override {
        if (!holding) return real_.end(l, m);
        queue.emplace_back(held::End{l, m});
    }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& s) override {
        if (!holding) return real_.stock(l, s);
        queue.emplace_back(held::Stock{l, s});
    }
    void profile(const Loc& l, const ProfileElem& e) override {
        if (!holding) return real_.profile(l, e);
        queue.emplace_back(held::Profile{l, e});
    }
    void exact_stop(const Loc& l) override {
        if (!holding) return real_.exact_stop(l);
        queue.emplace_back(held::ExactStop{l});
    }
    // Work that must come after the events held so far.
    void later(Later f) { queue.emplace_back(std::move(f)); }

    // Runs the held entries in order, with holding off.
    void release() {
        holding = false;
        auto q = std::move(queue);
        queue.clear();
        for (Held& h : q) std::visit([this](auto& e) { deliver(e); }, h);
        // The storage goes back to the queue unless a running entry added to
        // it: under compensation every block holds and releases, and the queue
        // was allocated anew each time.
        q.clear();
        if (queue.empty()) queue.swap(q);
    }

  private:
    void deliver(Later& f) { f(); }
    template <class Ev>
    void deliver(Ev& e) {
        held::Deliver{real_}(e);
    }
    MachineSink& real_;
};

}  // namespace pupitre
