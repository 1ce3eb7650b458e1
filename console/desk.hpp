// What a desk of the console sees of the Session it sits at (ARCHITECTURE.md,
// console): the machine, its program memory and its store, the message line,
// the page shown, a question on the input line. The desks (setting, editing,
// the exercise run) keep their own state and reach the rest through this
// face alone, so they stand below the Session and never include session.hpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/sim/sim.hpp"
#include "pages/view.hpp"

namespace pupitre::store {
class Store;
struct Attempt;
}  // namespace pupitre::store

namespace pupitre::console {

// What a key, a command or a typed line asks of the event loop.
enum class Effect { none, redraw, quit };

class Bench {
  public:
    virtual Sim& sim() = 0;
    virtual const Sim& sim() const = 0;
    virtual const MachineProfile& machine() const = 0;
    virtual ProgramMemory& memory() = 0;
    // Null: nothing is persisted (tests, or a store that cannot be opened).
    virtual store::Store* store() const = 0;
    // Where the store keeps this console's machine state (an exercise's
    // attempt has its own).
    virtual const std::string& store_key() const = 0;

    // The message line; an error counts as a refusal (an IMD block waiting
    // is dropped). message() is its text, to be reworded where it stands:
    // what was said stays said (the ALARM page keeps it).
    virtual void say(std::string text, bool error = false) = 0;
    virtual std::string& message() = 0;
    virtual bool message_is_error() const = 0;

    virtual pages::PageId page() const = 0;
    virtual void show_page(pages::PageId p) = 0;
    // Asks "y/n" on the input line; `then` runs on "y".
    virtual void confirm(std::string question, std::function<void()> then) = 0;
    // The DIR page's list, read again from the store (or the memory).
    virtual void refresh_dir() = 0;
    // The memory-protect key (the setting desk's): true when `what` may
    // change, else says why.
    virtual bool unprotected(std::string_view what) = 0;
    // Stores correctors and origins of this console's machine with `source`
    // for the audit. When a server is out of reach they are kept here and
    // written when it answers again.
    struct Stored {
        std::string why;    // "" when stored, else what to say
        bool kept = false;  // not stored yet, but kept to be
    };
    virtual Stored store_values(const std::vector<std::pair<std::string, int64_t>>& values,
                                std::string_view source) = 0;
    // An attempt's :submit that the server did not take (it is gone): kept
    // here after the values set before it, and sent when it answers again,
    // once (the server refuses a second submit of one attempt).
    virtual void keep_submission(const store::Attempt& a, bool on_class) = 0;

  protected:
    ~Bench() = default;
};

}  // namespace pupitre::console
