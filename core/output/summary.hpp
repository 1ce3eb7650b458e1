// The summary of a run, plain or JSON (pupitre(1)): counts, path length,
// cycle time, final positions, tools, parameters written, diagnostics.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"
#include "core/interp/interp.hpp"

namespace pupitre {

std::string summary_text(const Interpreter& in, const std::string& file);
// `more` are errors found outside the interpreter (the workshop's crashes);
// `fields` is JSON inserted before the closing brace (",\"workshop\":{…}").
std::string summary_json(const Interpreter& in, const std::string& file,
                         const std::vector<Diag>& more = {}, std::string_view fields = {});

}  // namespace pupitre
