// Diagnostics: NUM error numbers with the place they come from (pupitre(1), DIAGNOSTICS).
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
// The quiet mistakes of the handbook audit (issue 19): what runs is named.
inline constexpr int wFeedBeforeF = 1110;      // a feed move before any F
inline constexpr int wLReadUnset = 1111;       // an L read before anything set it
inline constexpr int wIdleWord = 1112;         // R, I, J or K with no effect in a G0/G1 block
inline constexpr int wFractionalRpm = 1113;    // S in rev/min not a whole number
inline constexpr int wProfileL = 1114;         // L100-L199/L900-L959 read in a roughing profile
inline constexpr int wFeedModeNoF = 1115;      // G94/G95 without F in the block
inline constexpr int wAllowanceInside = 1116;  // G64/G65 allowance towards the inside of the part
inline constexpr int wNoToolWidth = 1117;      // G66 correctors that give no tool width
inline constexpr int wPlungeAway = 1118;  // G46 roughing plunges with the cutter away from the hole
}  // namespace err

// What a pure layer (parse, geometry, cycles) answers when it refuses its
// input: the error number and what is wrong, with where it is as far as that
// layer knows it. It has no program, line or N: the interpreter adds them when
// it turns an Error into a Diag (Interpreter::fail), at the boundary. A
// function that has nothing else to answer returns one, empty on success:
//     if (Error e = spline::build(curve)) return fail(e);
struct Error {
    int code = 0;        // NUM error number or one of ours (err::); 0: no error
    std::string detail;  // the specific message
    int column = 0;      // 1-based column in the block's line, 0 when unknown
    int item = -1;       // the piece of the layer's input it is about (a PGP
                         // block's tag, a G46 section), -1 for none

    explicit operator bool() const { return code != 0; }
};

enum class Severity { error, warning };

struct Diag {
    Severity severity = Severity::error;
    int code = 0;
    std::string file;    // where the program text came from ("-" for none)
    int program = -1;    // %number, -1 when unknown
    int line = 0;        // 1-based line in `file`, 0 when unknown
    long n = -1;         // N number of the block, -1 when the block has none
    int column = 0;      // 1-based column in the line, 0 when unknown
    std::string detail;  // the specific message

    bool is_error() const { return severity == Severity::error; }
};

// The Diag of what a layer answered; the caller fills in where it is (file,
// program, line, N).
Diag diag_of(const Error& e, Severity s = Severity::error);

// "FILE:LINE[:COL]: N<n>: error <code>: <message>" (pupitre(1), DIAGNOSTICS): the column
// of the word at fault when there is one, as GNU tools write it.
std::string format_diag(const Diag& d);

// The NUM text of an error number from data/errors.tsv (English), or "" if the
// number is not in the NUM list.
std::string_view num_error_text(int code);
// The short text of one of pupitre's own numbers (>= 1000), or "".
std::string_view pupitre_diag_text(int code);

}  // namespace pupitre
