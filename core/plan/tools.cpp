// Each tool's time in a part (tools.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/plan/tools.hpp"

#include <cmath>

#include "core/i18n.hpp"
#include "core/keyvalue.hpp"

namespace pupitre::plan {

ToolRow& ToolTable::row(int tool) {
    last_ = 0;  // a handful of tools: a search is enough
    while (last_ < rows_.size() && rows_[last_].tool != tool) ++last_;
    if (last_ == rows_.size()) rows_.push_back(ToolRow{.tool = tool});
    return rows_[last_];
}

std::string read_edge_life(std::string_view text, EdgeLife& life) {
    int tool = 0;
    if (size_t eq = text.find('='); eq != std::string_view::npos) {
        std::string_view t = kv::trim(text.substr(0, eq));
        double n;
        if (t.size() < 2 || (t[0] != 'T' && t[0] != 't') || !kv::number(t.substr(1), n) || n < 1 ||
            n != std::floor(n) || n > 9999)
            return tr("expected MINUTES or TN=MINUTES (T11=15)");
        tool = int(n);
        text = text.substr(eq + 1);
    }
    double minutes;
    if (!kv::number(text, minutes) || !(minutes > 0))
        return tr("the life of an edge is a number of minutes above 0");
    (tool ? life.tool[tool] : life.all) = minutes * 60;
    return {};
}

long parts_per_edge(double cut_seconds, double life_seconds) {
    if (cut_seconds <= 0 || life_seconds <= 0) return 0;
    const double parts = std::floor(life_seconds / cut_seconds + 1e-9);
    // At most 1e18, which a long holds: a cut of a nanosecond is no reason to overflow.
    return parts < 1e18 ? long(parts) : long(1e18);
}

}  // namespace pupitre::plan
