// The summary of a run, plain or JSON (pupitre(1)): counts, path length,
// cycle time, final positions, tools, parameters written, diagnostics.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"
#include "core/interp/interp.hpp"
#include "core/plan/plan_sink.hpp"

namespace pupitre {

// What the planner made of the run (core/plan): the cycle time with the
// machine's accelerations beside the time at the feeds alone, and each tool's
// share, with the parts an edge lasts when its life is given.
struct PlanSummary {
    const plan::Report* report = nullptr;
    plan::EdgeLife life;
};

std::string summary_text(const Interpreter& in, const std::string& file,
                         const PlanSummary& plan = {});
// `more` are errors found outside the interpreter (the workshop's crashes);
// `fields` is JSON inserted before the closing brace (",\"workshop\":{…}").
std::string summary_json(const Interpreter& in, const std::string& file,
                         const std::vector<Diag>& more = {}, std::string_view fields = {},
                         const PlanSummary& plan = {});
// One line per tool of the table (the summary's, the INFO page's): "T11: 141.8
// s of cutting a part (3 passes, 424.440 mm), 6.6 s of rapids, change the edge
// every 6 parts".
std::string tool_line(const plan::ToolRow& r, const plan::EdgeLife& life);

}  // namespace pupitre
