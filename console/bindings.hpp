// Key bindings are data (ARCHITECTURE.md, Conventions; ncmpcpp): a table of KEY ACTION [ARG]
// [@CONTEXT] lines, shipped in data/bindings.txt and overridable by the user's
// $XDG_CONFIG_HOME/pupitre/bindings. Actions have names, a can_run() and a
// help text; soft-key labels and the HELP page are generated from the table.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "console/keys.hpp"

namespace pupitre::console {

class Session;

enum class Effect { none, redraw, quit };

struct Action {
    std::string_view name;
    std::string_view help;  // "%s" is replaced by the argument
    bool (*can_run)(const Session&, std::string_view arg);
    Effect (*run)(Session&, std::string_view arg);
    std::string_view label;  // soft-key label; "%S" is the argument in capitals
};

const Action* find_action(std::string_view name);

struct Context {
    std::string page;  // "" = any
    std::string mode;  // "" = any
    std::string kind;  // "lathe", "mill" or "" = any
};

struct Binding {
    Key key;
    std::string key_text;  // as written in the file
    std::string action;
    std::string arg;
    Context when;
    int line = 0;
};

class Bindings {
  public:
    // Adds the lines of a bindings text. Returns "" or "NAME:LINE: problem".
    std::string parse(std::string_view text, std::string_view origin);
    void clear() { list_.clear(); }
    const std::vector<Binding>& list() const { return list_; }
    // The bindings of a key that apply in a context, the most specific first.
    std::vector<const Binding*> find(const Key& k, std::string_view page, std::string_view mode,
                                     std::string_view kind) const;

  private:
    std::vector<Binding> list_;
};

// The shipped table (data/bindings.txt, embedded).
std::string_view default_bindings();
std::string help_text(const Action& a, std::string_view arg);
std::string soft_label(const Action& a, std::string_view arg);
std::string context_text(const Context& c);
// A key as HELP names it: Enter, Del and Esc as the keyboard of the
// console's language labels them (Entrée, Suppr, Échap); others as written.
std::string key_label(const std::string& key_text);

}  // namespace pupitre::console
