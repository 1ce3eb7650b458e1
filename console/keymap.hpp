// Key bindings are data (ARCHITECTURE.md, Conventions; ncmpcpp): a table of KEY ACTION [ARG]
// [@CONTEXT] lines, shipped in data/bindings.txt and overridable by the user's
// $XDG_CONFIG_HOME/pupitre/bindings. This is the table alone; the actions it
// names, and what they do to the Session, are bindings.cpp's (Bindings: the
// keymap checked against them).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "console/keys.hpp"

namespace pupitre::console {

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

class Keymap {
  public:
    // Adds the lines of a bindings text; `is_action` tells the action names.
    // Returns "" or "NAME:LINE: problem".
    std::string parse(std::string_view text, std::string_view origin,
                      bool (*is_action)(std::string_view name));
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

}  // namespace pupitre::console
