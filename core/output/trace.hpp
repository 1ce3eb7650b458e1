// Output of a dry run: the JSON-lines trace (pupitre(1), OUTPUT, Trace) and the run summary,
// plain or JSON. Fixed 4 decimals for lengths, degrees, seconds, feeds and speeds.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdio>
#include <string>

#include "core/interp/interp.hpp"

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

  private:
    void head(const char* ev, const Loc& l);
    void axes(const char* key, const Axes& v, bool x_diam);
    // A diameter lathe's X is written as a diameter in every event, E11005=0
    // (X programmed as a radius) included: one unit for the whole trace.
    bool x_diameter() const { return m_.lathe && m_.x_diameter; }
    std::FILE* out_;
    const MachineProfile& m_;
    std::string buf_;
};

// Appends v with exactly 4 decimals ("-0.0000" is written "0.0000").
void append_fixed4(std::string& s, double v);
// Appends a JSON string literal.
void append_json_string(std::string& s, std::string_view v);

std::string summary_text(const Interpreter& in, const std::string& file);
// `more` are errors found outside the interpreter (the workshop's crashes);
// `fields` is JSON inserted before the closing brace (",\"workshop\":{…}").
std::string summary_json(const Interpreter& in, const std::string& file,
                         const std::vector<Diag>& more = {}, std::string_view fields = {});

}  // namespace pupitre
