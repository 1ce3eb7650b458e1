// Program memory: the text of the % programs loaded from files, split by header,
// with a lazily built index of block labels (N numbers) for G77/G79 and cycles.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"

namespace pupitre {

struct Label {
    long n;
    int line;       // 1-based line in the file
    size_t offset;  // offset of the line in the file text
};

// One % program. Blocks are parsed when executed, so a million-block program costs
// its text plus a few bytes a labelled line, and only if it jumps.
struct ProgramText {
    int number = 0;       // %number; 0 for a file with no % header
    int index = -1;       // %number.index, -1 if none
    std::string title;    // the header comment
    std::string file;     // where it was loaded from
    std::shared_ptr<std::string> text;  // the whole file (G76 rewrites value fields in place)
    size_t begin = 0;     // first byte of the first block line
    size_t end = 0;       // one past the last byte of the program
    int first_line = 1;   // line number at `begin`

    std::string_view body() const { return std::string_view(*text).substr(begin, end - begin); }
    // First block (in text order) whose label is n; nullptr if none.
    const Label* find_label(long n) const;

private:
    mutable std::vector<Label> labels_;  // sorted by (n, line)
    mutable bool indexed_ = false;
};

// Reads the label of a block line: the N number after an optional block-skip '/'.
// Returns -1 if the line has none.
long line_label(std::string_view line);

class ProgramMemory {
public:
    // Loads every % program of a file. Returns false and fills `d` when the file
    // cannot be read or is not text.
    bool load_file(const std::string& path, Diag& d);
    // Loads programs from text already in memory (tests, the store).
    bool load_text(std::string name, std::string text, Diag& d);

    // Replaces the text of program `number` in place (the editor's save, MODIF):
    // pointers to it stay valid, its labels are indexed again. Adds it when it
    // is not in memory. `text` must hold that one program.
    bool replace(int number, std::string name, std::string text, Diag& d);

    const ProgramText* find(int number) const;
    // The first program loaded from the first file: the main program of a run.
    const ProgramText* first() const { return progs_.empty() ? nullptr : progs_.front().get(); }
    const std::vector<std::unique_ptr<ProgramText>>& programs() const { return progs_; }
    std::vector<Diag>& warnings() { return warnings_; }

private:
    std::vector<std::unique_ptr<ProgramText>> progs_;
    std::vector<Diag> warnings_;
};

}  // namespace pupitre
