// Program memory: the text of the % programs loaded from files, split by header,
// with a lazily built index of block labels (N numbers) for G77/G79 and cycles.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"
#include "core/parse/text.hpp"

namespace pupitre {

struct Label {
    long n;
    int line;       // 1-based line in the file
    size_t offset;  // offset of the line in the file text
};

// One % program. Blocks are parsed when executed, so a million-block program costs
// its text plus a few bytes a labelled line, and only if it jumps.
struct ProgramText {
    int number = 0;              // %number; 0 for a file with no % header
    int index = -1;              // %number.index, -1 if none
    std::string title;           // the header comment
    std::string file;            // where it was loaded from
    std::shared_ptr<Text> text;  // the whole file (G76 rewrites value fields in place)
    size_t begin = 0;            // first byte of the first block line
    size_t end = 0;              // one past the last byte of the program
    int first_line = 1;          // line number at `begin`

    std::string_view body() const { return std::string_view(*text).substr(begin, end - begin); }
    // First block (in text order) whose label is n; nullptr if none.
    const Label* find_label(long n) const;

  private:
    friend class ProgramMemory;
    mutable std::vector<Label> labels_;  // sorted by (n, line)
    mutable bool indexed_ = false;
};

// The program as a store keeps it: its header line, then its blocks.
std::string program_text(const ProgramText& p);

// Reads the label of a block line: the N number after an optional block-skip '/'.
// Returns -1 if the line has none.
long line_label(std::string_view line);

// What a splice did: `del` bytes and `del_lines` lines at `at` (line `line`)
// became `ins` bytes and `ins_lines` lines.
struct Splice {
    size_t at = 0, del = 0, ins = 0;
    int line = 0, del_lines = 0, ins_lines = 0;
};

class ProgramMemory {
  public:
    // Loads every % program of a file. Answers why not when the file cannot
    // be read or is not text (1002-1004), nothing when it is loaded.
    std::optional<Diag> load_file(const std::string& path);
    // Loads programs from text already in memory (tests, the store).
    std::optional<Diag> load_text(std::string name, std::string text);
    // A file of this size or more is mapped, not read (text.hpp).
    static constexpr size_t kMapFrom = size_t(1) << 20;

    // Replaces the text of program `number` in place (the editor's save, MODIF):
    // pointers to it stay valid, its labels are indexed again. Adds it when it
    // is not in memory. `text` must hold that one program: answers why not.
    std::optional<Diag> replace(int number, std::string name, std::string text);

    const ProgramText* find(int number) const;
    // A deep copy (the TEST mode's): programs that shared a text share its copy.
    ProgramMemory clone() const;

    // G76+ H (000:7020-7050): adds the empty program %number. nullptr if
    // a program with that number is in memory.
    const ProgramText* create(int number);
    // G76- H (000:7053-7097): forgets program %number. The object stays alive, so a
    // pointer to it stays valid, but find() no longer returns it.
    bool remove(int number);
    // G76+/G76- N (000:7098-7170): replaces `del` bytes at `at` in the text of `p`
    // by `ins`. The programs that share the text (one file) move with it; their
    // label indexes follow. `at` and `at + del` must be line starts of `p`.
    Splice splice(const ProgramText* p, size_t at, size_t del, std::string_view ins);
    // Bytes of program text in memory (the quota of G76+, error 36).
    size_t size() const;
    // Numbers of the programs whose text a run changed (G76, G76+, G76-) since
    // the last call, in order and without repeats; the console stores them.
    std::vector<int> take_changed();
    void mark_changed(int number);
    // Grows with every change of a text (caches of line offsets compare it).
    uint64_t generation() const { return generation_; }
    // The first program loaded from the first file: the main program of a run.
    const ProgramText* first() const { return progs_.empty() ? nullptr : progs_.front().get(); }
    const std::vector<std::unique_ptr<ProgramText>>& programs() const { return progs_; }
    std::vector<Diag>& warnings() { return warnings_; }

  private:
    std::optional<Diag> load_shared(const std::string& name, std::shared_ptr<Text> text);
    std::vector<std::unique_ptr<ProgramText>> progs_;
    std::vector<std::unique_ptr<ProgramText>> removed_;  // G76-: kept for the pointers
    std::vector<int> changed_;
    uint64_t generation_ = 0;
    std::vector<Diag> warnings_;
};

}  // namespace pupitre
