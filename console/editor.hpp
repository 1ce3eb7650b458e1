// The program editor of EDIT and MODIF modes: a program as a list of blocks
// (lines), a cursor, a mark for block ranges, a clipboard, search by N number
// or text, renumbering, and the syntax check before saving. Pure logic: the
// session wires it to the store and the keys, the EDIT page shows it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"

namespace pupitre::console {

class Editor {
  public:
    // `text`: the program as stored (its % line first).
    void open(int number, std::string_view text, int revision, bool is_new);
    void close() { open_ = false; }
    bool is_open() const { return open_; }

    int number = -1;
    int revision = 0;  // the store revision the text was loaded from (0: new)
    bool dirty = false;
    uint64_t changes = 0;  // counts every change (the recovery journal follows it)
    int cursor = 0;        // index in lines()
    int mark = -1;         // the other end of a block range, -1 when none
    int locked = 0;        // MODIF: lines [0, locked) are prepared and cannot change
    int error_line = -1;   // the line the last check stopped on

    const std::vector<std::string>& lines() const { return lines_; }
    std::string text() const;  // the lines joined, each ended by a newline

    // Editing; each returns "" or why it was refused.
    std::string insert_after(std::string block);  // the new block becomes current
    std::string replace(std::string block);       // the current block
    std::string set_header(std::string line);     // the % line, "%500 (TITLE)"
    std::string erase();                          // the current block or the marked range
    std::string copy();                           // to the clipboard
    std::string cut();
    std::string paste();  // after the cursor
    void toggle_mark() { mark = mark < 0 ? cursor : -1; }
    void move(int delta);
    // Searches; false when not found (the cursor stays).
    bool goto_n(long n);
    bool find(std::string_view text);  // from the line after the cursor, wrapping
    // Renumbers the N labels from `start` by `step` and rewrites the labels
    // that G77 and G79 blocks name. Returns how many blocks were renumbered.
    int renumber(long start, long step);
    // The first block that does not parse, error_line set and the cursor on
    // it; none when every block parses.
    std::optional<Diag> check();

  private:
    // Why a range of lines starting at `first` may not be changed, or "" when
    // it may: MODIF's prepared blocks and the % line both come first, so the
    // range's first line decides.
    std::string refusal(int first) const;
    void range(int& a, int& b) const;
    bool open_ = false;
    std::vector<std::string> lines_;
    std::vector<std::string> clipboard_;
};

}  // namespace pupitre::console
