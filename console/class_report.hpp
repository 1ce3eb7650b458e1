// The teacher's report (issue 16, pupitre class report): the class's
// attempts summed up per exercise and student (attempts, best and last
// score, time, crashes, scrapped parts), the mistakes most made, each
// signature checked; as a table, CSV or one printable HTML file.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <map>
#include <string>
#include <vector>

#include "store/store.hpp"

namespace pupitre::console {

enum class ReportFormat { table, csv, html };

// What the report checks and says besides the attempts.
struct ReportContext {
    std::string key;    // the class key, to check each signature ("": not checked, and said)
    std::string title;  // heads the HTML page
    // A class's server: an attempt submitted and not yet signed waits for
    // the teacher's grading (UNGRADED), and counts for nothing yet.
    bool on_server = false;
    // Each exercise's current text's SHA-256: an attempt made on another
    // (the exercise was changed since) is named by its text's.
    std::map<std::string, std::string> current;
};

std::string class_report_text(const std::vector<store::Attempt>& attempts, ReportFormat f,
                              const ReportContext& c);

}  // namespace pupitre::console
