// The teacher's report (issue 16, pupitre class report): the class's
// attempts summed up per exercise and student (attempts, best and last
// score, time, crashes, scrapped parts), the mistakes most made, each
// signature checked; as a table, CSV or one printable HTML file.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "store/store.hpp"

namespace pupitre::console {

enum class ReportFormat { table, csv, html };

// `key`: the class key, to check each attempt's signature ("": not
// checked, and the report says so). `title` heads the HTML page.
// `on_server`: a class's server, where an attempt submitted and not yet
// signed waits for the teacher's grading (UNGRADED), and counts for nothing.
std::string class_report_text(const std::vector<store::Attempt>& attempts, ReportFormat f,
                              const std::string& key, const std::string& title,
                              bool on_server = false);

}  // namespace pupitre::console
