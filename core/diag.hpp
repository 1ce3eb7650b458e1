// Diagnostics: NUM error numbers with the place they come from (DESIGN §2.2).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace pupitre {

// Numbers >= 1000 are ours, for problems the NUM list does not number; they are
// documented in man/pupitre.1 (DIAGNOSTICS).
namespace err {
inline constexpr int kBlockBudget = 1001;    // endless loop: block budget exhausted
inline constexpr int kNotText = 1002;        // unreadable or non-text input
inline constexpr int kNoProgram = 1003;      // no program in the file
inline constexpr int kCannotRead = 1004;     // the file cannot be opened or read
inline constexpr int kProgramExists = 1005;  // G76+ H of a program already in memory
inline constexpr int kProgramInUse = 1006;   // G76- H of a program the run is executing
inline constexpr int kUnsupported = 1010;    // a NUM function pupitre does not run yet
// Warnings.
inline constexpr int wFeedClamped = 1101;
inline constexpr int wSpeedClamped = 1102;
inline constexpr int wUnknownM = 1103;
inline constexpr int wSpindleStopped = 1104;
inline constexpr int wIncrementalFirst = 1105;
inline constexpr int wDuplicateProgram = 1107;
inline constexpr int wUnsignedEB = 1108;
inline constexpr int wTinyFeed = 1109;
}  // namespace err

enum class Severity { error, warning };

struct Diag {
    Severity severity = Severity::error;
    int code = 0;
    std::string file;     // where the program text came from ("-" for none)
    int program = -1;     // %number, -1 when unknown
    int line = 0;         // 1-based line in `file`, 0 when unknown
    long n = -1;          // N number of the block, -1 when the block has none
    int column = 0;       // 1-based column in the line, 0 when unknown
    std::string detail;   // the specific message

    bool is_error() const { return severity == Severity::error; }
};

// "FILE:LINE: N<n>: error <code>: <message>" (DESIGN §2.2).
std::string format_diag(const Diag& d);

// The NUM text of an error number from data/errors.tsv (English), or "" if the
// number is not in the NUM list.
std::string_view num_error_text(int code);

}  // namespace pupitre
