// The actions the key bindings name (ARCHITECTURE.md, Conventions; ncmpcpp):
// each has a name, a can_run() and a help text; soft-key labels and the HELP
// page are generated from the table (keymap.hpp) and these rows. An action
// acts on the Session: bindings.cpp stands above it and holds, beside the
// rows, the Session's routing of a key through them.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

#include "console/desk.hpp"
#include "console/keymap.hpp"

namespace pupitre::console {

class Session;

struct Action {
    std::string_view name;
    std::string_view help;  // "%s" is replaced by the argument
    bool (*can_run)(const Session&, std::string_view arg);
    Effect (*run)(Session&, std::string_view arg);
    std::string_view label;  // soft-key label; "%S" is the argument in capitals
};

const Action* find_action(std::string_view name);
bool is_action(std::string_view name);

// The keymap checked against the actions: a line naming no action is refused.
class Bindings : public Keymap {
  public:
    // Adds the lines of a bindings text. Returns "" or "NAME:LINE: problem".
    std::string parse(std::string_view text, std::string_view origin) {
        return Keymap::parse(text, origin, is_action);
    }
};

std::string help_text(const Action& a, std::string_view arg);
std::string soft_label(const Action& a, std::string_view arg);
std::string context_text(const Context& c);
// A key as HELP names it: Enter, Del and Esc as the keyboard of the
// console's language labels them (Entrée, Suppr, Échap); others as written.
std::string key_label(const std::string& key_text);

}  // namespace pupitre::console
