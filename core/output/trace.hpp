// The JSON-lines trace of a dry run (pupitre(1), OUTPUT, Trace), one line per event: a sink
// that compiles against the machine boundary alone (sink.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdio>
#include <string>

#include "core/interp/sink.hpp"

namespace pupitre {

class TraceWriter final : public MachineSink {
  public:
    TraceWriter(std::FILE* out, const MachineProfile& m) : out_(out), m_(m) {}
    void move(const MoveEvent&) override;
    void dwell(const Loc&, double) override;
    void tool(const Loc&, int t, int d, double, bool m6) override;
    void spindle(const SpindleEvent&) override;
    void coolant(const Loc&, bool m7, bool m8) override;
    void stop(const Loc&, int m) override;
    void message(const Loc&, int channel, std::string_view) override;
    void end(const Loc&, int m) override;
    double seconds = 0;  // running total, reported with "end"
    // The planner's clock (core/plan, PlanSink::clock), which "end" reports
    // instead: it counts the waits of the exact stops and the spindle too.
    void follow(const double* clock) { clock_ = clock; }

  private:
    void head(const char* ev, const Loc& l);
    void axes(const char* key, const Axes& v, bool x_diam);
    // A diameter lathe's X is written as a diameter in every event, E11005=0
    // (X programmed as a radius) included: one unit for the whole trace.
    bool x_diameter() const { return m_.lathe && m_.x_diameter; }
    std::FILE* out_;
    const MachineProfile& m_;
    std::string buf_;
    const double* clock_ = nullptr;
};

}  // namespace pupitre
