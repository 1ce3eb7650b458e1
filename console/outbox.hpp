// What a console set while its server store did not answer: correctors and
// origins, in the order they were set, kept in a file on this PC beside the
// editor's journal (Store::local_path() + ".outbox") so that quitting loses
// nothing, and sent when the store answers again (pupitre(1), On a
// PostgreSQL server). Sending a value the store already holds changes
// nothing there (set_values skips it), so a send whose answer was lost is
// never a second change.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::store {
class Store;
struct Attempt;
}  // namespace pupitre::store

namespace pupitre::console {

class Outbox {
  public:
    struct Unsent {
        std::string key, name;  // the machine's key in the store, "D1.X"
        int64_t value = 0;      // the store's internal value
        std::string source;     // for the audit
    };
    // Reads what an earlier console left in `path` ("" for none).
    void open(std::string path);
    void add(std::string_view key, std::string_view name, int64_t value, std::string_view source);
    // An attempt's :submit, sent after the values before it; its line holds
    // the attempt's fields (key "#attempt", name "class" or "signed").
    void add_submission(const store::Attempt& a, bool on_class);
    bool empty() const { return q_.empty(); }
    const std::vector<Unsent>& unsent() const { return q_; }
    // Sends in order until the store refuses one; the names sent (an
    // attempt's as "the attempt").
    std::vector<std::string> send(store::Store& s);

  private:
    void save() const;
    std::vector<Unsent> q_;
    std::string path_;
};

}  // namespace pupitre::console
