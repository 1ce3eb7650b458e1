// Program texts as the store keeps them: a file cut into its % programs, and the
// header of one program. Pure functions, no SQLite: the command line and the
// tests use them too.
//
// The text of a program runs from its % line to just before the next % line, or
// to the end of the file. Text before a file's first % line (blank lines and
// comments, a tape leader) belongs to the first program. So the programs of a
// file, concatenated in file order, give the file back byte for byte, and each
// is stored exactly as written (line ends, trailing spaces, a missing final newline).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "store/store.hpp"

namespace pupitre::store {

struct Header {
    int number = -1;    // the %number; -1 for a text with no % line (a fragment)
    int index = -1;     // %number.index, -1 when none
    std::string title;  // the header comment
};

// A line whose first character other than space and tab is '%' (as ProgramMemory).
bool is_header_line(std::string_view line);

// Reads the header of one program's text. bad_data when the text holds a NUL
// byte, several % lines, or blocks before its % line. `name` prefixes messages.
StoreError parse_program(std::string_view text, std::string_view name, Header& h);

// Cuts a file into its programs (see above). A file with no % line is one
// program, stored as `number_if_headerless`; with -1 it is refused. Refused
// too: a NUL byte, blocks before the first % line, a number given twice.
// Each piece's source is "import NAME".
Result<std::vector<Piece>> split_file(std::string_view text, std::string_view name,
                                      int number_if_headerless = -1);

// Lines of a text: its newlines, plus one for a last line with no newline.
int64_t count_lines(std::string_view text);

}  // namespace pupitre::store
