// The teacher's live view of a class (pupitre class watch, issue 34): a line
// per student, or one student's attempts. A pure renderer: the console fills
// the WatchView from the server and calls it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "pages/canvas.hpp"

namespace pupitre::pages {

// How a student stands, as the watch colours it.
enum class WatchState { idle, working, submitted, graded, late, disconnected };

struct WatchRow {
    std::string student, exercise;
    std::string time;  // "12/45 min", "12 min"
    WatchState state = WatchState::idle;
    std::string status;       // "working", "graded 83%"…, in the console's language
    std::string last_action;  // "PREF.X -135.477, 2 min ago"
    int crashes = 0, scrapped = 0;
};

struct WatchView {
    std::string title;  // "class 2a on …"
    std::string clock;  // the server's time "10:42"
    std::vector<WatchRow> rows;
    int selected = 0;
    // One student's attempts (Enter), a line each; empty: the class.
    std::string detail_title;
    std::vector<std::string> detail;
    std::string message;  // the last error, or how to use the keys
};

void render_watch(const WatchView& v, Canvas& c);

}  // namespace pupitre::pages
