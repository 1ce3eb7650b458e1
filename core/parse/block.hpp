// One NUM block, parsed: words in order, parametric assignments, a G79 test, a $
// message. Values that name L variables or E parameters stay symbolic; the
// interpreter resolves them when the block executes (000:362-385, 000:7444-7457;
// pupitre-iso(5), WORDS and PARAMETRIC PROGRAMMING).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/diag.hpp"

namespace pupitre {

// Address codes: a single letter is its index from 'A'; E + letter is 26 + index;
// N + letter (NC, NU, NP, NR) is 52 + index; the PGP discriminant E+ / E- is 78;
// L + letter (LX, LY of the G46 pocket) is 79 + index.
using Addr = uint8_t;
constexpr Addr addr1(char c) {
    return Addr(c - 'A');
}
constexpr Addr addrE(char c) {
    return Addr(26 + (c - 'A'));
}
constexpr Addr addrN(char c) {
    return Addr(52 + (c - 'A'));
}
constexpr Addr kAddrEsign = 78;
constexpr Addr addrL(char c) {
    return Addr(79 + (c - 'A'));
}
constexpr int kAddrCount = 105;
// "X", "EA", "NC", "E±".
std::string_view addr_name(Addr a);

struct Operand {
    enum Kind : uint8_t { Blank, SignOnly, Number, LVar, EParam, EIndirect };
    Kind kind = Blank;
    bool neg = false;         // a '-' sign was written
    bool has_sign = false;    // '+' or '-' was written
    uint8_t int_digits = 0;   // digits before the point (Number)
    uint8_t frac_digits = 0;  // digits after the point (Number)
    int32_t index = 0;        // L or E number; for EIndirect the L number
    double num = 0;           // the literal's value, unsigned
};

struct Word {
    Addr addr = 0;
    uint16_t col = 0;    // 1-based column of the address letter
    char gsign = 0;      // '+' or '-' glued to G76/G79 (G76+, G79-)
    int16_t glevel = 0;  // the i of "G77 -i"
    Operand v;
};

// A term of an expression: `op` applies it to the accumulator ('=' for the first
// term); `prefix` holds signs and the unary functions S C A R T, applied from the
// innermost (last) to the outermost (first).
struct Term {
    char op = '=';
    uint8_t nprefix = 0;
    char prefix[7] = {};
    Operand v;
};

struct Expr {
    uint16_t first = 0;
    uint16_t count = 0;
};

struct Assign {
    Operand target;  // LVar, EParam or EIndirect
    Expr expr;
    uint16_t col = 0;
};

enum class Cmp : uint8_t { none, eq, ne, lt, le, gt, ge };

struct Test {
    Cmp cmp = Cmp::none;
    Expr lhs, rhs;
    uint16_t col = 0;
};

struct Block {
    int line = 0;
    long n = -1;           // label, -1 if none
    bool skip = false;     // starts with '/'
    int msg_channel = -1;  // $0..$6, -1 if none
    std::string_view msg;  // text of the $ message (points into the program text)
    Test test;             // G79 condition
    std::vector<Word> words;
    std::vector<Assign> assigns;
    std::vector<Term> terms;  // storage for every Expr of the block
    // G76+ / G76- [H..] N.. [+k] <ISO block> (000:7098-7170): the
    // words after the pointed N are not this block's: the line offset k and the
    // raw text of the block to insert are kept apart.
    int g76_k = -1;              // the +k after the pointed block, -1 if none
    std::string_view g76_block;  // the text after N.. [+k], trimmed (points into the line)
    uint16_t g76_block_col = 0;  // its 1-based column

    void clear() {
        line = 0;
        n = -1;
        skip = false;
        msg_channel = -1;
        msg = {};
        test = Test{};
        words.clear();
        assigns.clear();
        terms.clear();
        g76_k = -1;
        g76_block = {};
        g76_block_col = 0;
    }
    bool empty() const { return words.empty() && assigns.empty() && msg_channel < 0; }
};

constexpr size_t kMaxBlockChars = 117;  // pupitre-iso(5), DECISIONS, 117 characters

// Parses one line of program text (without its '\n'). On a syntax error
// answers it (code, column, detail), empty on success. `out` is cleared
// first, and its vectors keep their capacity, so parsing a program allocates
// almost nothing (an empty Error holds no heap memory either).
Error parse_block(std::string_view line, Block& out);
// Why a line of `text` does not parse as a block, empty when every one does.
Error parse_lines(std::string_view text);
// The same with the general parser alone, without the lane of plain blocks
// that parse_block tries first: the reference its differential test
// (tests/unit/test_parse_lane.cpp) compares the lane with.
Error parse_block_general(std::string_view line, Block& out);
// The lane of plain blocks alone, on the text of a line that ends with '\n'
// (a program's text, `avail` bytes from `text` to its end): true when the
// lane reads the line, whose length before its '\n' it leaves in `len`;
// false when the line needs parse_block_general (`out` then holds nothing of
// use). The same Block as parse_block.
bool parse_plain_line(const char* text, size_t avail, Block& out, size_t& len);

}  // namespace pupitre
