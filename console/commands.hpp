// The table of the ':' commands (pupitre(1), COMMANDS): one row per command, read by the
// dispatch (Session::command, which commands.cpp holds beside the rows), the
// HELP page, completion and the man-page check (tests/console/man_sync.py
// parses the rows in console/commands.cpp). A row routes its command to the
// Session or to the desk that owns it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <span>
#include <string_view>

#include "console/desk.hpp"

namespace pupitre::console {

class Session;
struct CommandCall;  // the line typed, split into words (console/commands.cpp)

struct Command {
    // The words it answers to, separated by spaces: "quit q quit! q!". The
    // first is the one Tab completes; a '!' variant does not ask first.
    std::string_view names;
    // Its line on the HELP page; "" when another row's line tells of it
    // (":history / :restore REV").
    std::string_view usage;
    std::string_view help;
    // Null in a row that only adds a line to the HELP page, for another use of
    // a command (":protect pin [NEWPIN]", ":mode modif" among the editor's).
    Effect (*run)(Session&, const CommandCall&);
};

// In the order the HELP page lists them.
std::span<const Command> commands();

}  // namespace pupitre::console
