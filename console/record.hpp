// An attempt's record (issue 34, pupitre-exercise(5), THE RECORD): what the
// operator did at the console during an exercise, one action a line, with
// the simulated clock (the Sim's, never the wall clock), so that the
// teacher's side replays it against the truth (replay.hpp) and grades what
// the replay leaves. The actions are those that change the machine, the
// workshop, a value or where typed text goes: a key's action by name (not
// the key: the student's own bindings do not travel), a line entered, a
// question answered, Escape. Notes beside them say what the replay cannot
// know by itself: the text of a program run, the program selected, the
// memory protection, the readings and shims (which the grade reads).
//   pupitre-record 1
//   0.000000 session
//   0.000000 size 110 40
//   0.000000 key page pref
//   0.000000 line PREF.X=-135.477
//   12.250000 dia 59.9780
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::console::record {

inline constexpr std::string_view kHeader = "pupitre-record 1";

enum class Verb {
    session,  // a console began (or took up again) the attempt: a new clock from 0
    size,     // the terminal's size: a = columns, b = rows
    key,      // a key's action: text = its name, arg = its argument
    line,     // a line entered on the input line: text
    answer,   // a question answered by one key: a = 1 yes, 0 no
    escape,   // Escape: the input line, MODIFY or a question cancelled
    program,  // note: the text of program %a, as it was run
    select,   // note: program %a is the one selected
    protect,  // note: the memory protection, a = 1 on
    dia,      // note: a diameter read (value), for the grade's mistakes
    shim,     // note: a shim or gauge block placed (value)
};

struct Action {
    double clock = 0;  // the Sim's, seconds since this console's session began
    Verb verb = Verb::key;
    std::string text = {}, arg = {};
    int a = 0, b = 0;
    double value = 0;
    // An operator's action (what the replay steps through), not a note.
    bool step() const {
        return verb == Verb::key || verb == Verb::line || verb == Verb::answer ||
               verb == Verb::escape;
    }
};

// One line, without its '\n'; a program's text has its line ends escaped.
std::string format(const Action& a);
// A record's text: its header and its actions (records before version 1
// held only "dia V" and "shim V" lines: they read as notes at clock 0).
// "" or "line N: what is wrong".
std::string parse(std::string_view text, std::vector<Action>& out);
// An action as the replay's message line shows it: "PREF.X=-135.477 entered".
std::string describe(const Action& a);

// The record as an attempt grows it in a console: the text so far (earlier
// consoles' first), and what this console last noted, so that a note is
// written only when it changes.
class Recorder {
  public:
    // Takes up `earlier` (the record the store keeps, "" for a new attempt)
    // and begins this console's session.
    void begin(const std::string& earlier);
    void add(const Action& a);
    const std::string& text() const { return text_; }
    bool changed() const { return changed_; }  // since kept()
    void kept() { changed_ = false; }

    // What this console last told the replay (the notes written once).
    int cols = 0, rows = 0;
    int selected = -2;  // -2: not said yet this session
    int protect = -1;
    std::map<int, std::string> programs;  // the text of each program as last written

  private:
    std::string text_;
    bool changed_ = false;
};

}  // namespace pupitre::console::record
