// The parser's lane of plain blocks (parse_plain in core/parse/block.cpp,
// issue 14) against the general parser: every line of the repository's
// programs and hundreds of thousands of random lines near the lane's edges
// must give the same Block, field by field, or the same error.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "tests/unit/block_log.hpp"

using namespace pupitre;
namespace fs = std::filesystem;

namespace {

::testing::AssertionResult same(const std::string& line) {
    const std::string lane = test::parse_answer(line, true),
                      general = test::parse_answer(line, false);
    if (lane == general) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "line \"" << line << "\"\nlane:\n"
                                         << lane << "general:\n"
                                         << general;
}

// The lane as the interpreter calls it on a program's text (parse_plain_line:
// the line and its '\n', then the next line): when it reads the line, the
// same Block as parse_block, and the line's length.
::testing::AssertionResult same_in_text(const std::string& line) {
    const std::string text = line + "\nN99 X1\n";
    Block b;
    size_t len = 0;
    if (!parse_plain_line(text.c_str(), text.size(), b, len)) return ::testing::AssertionSuccess();
    const std::string lane = test::block_text(b), general = test::parse_answer(line, true);
    if (len != line.size())
        return ::testing::AssertionFailure() << "line \"" << line << "\": length " << len;
    if (lane == general) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "line \"" << line << "\"\nin text:\n"
                                         << lane << "parse_block:\n"
                                         << general;
}

}  // namespace

TEST(ParseLane, RepositoryLinesParseTheSameBothWays) {
    const fs::path root = PUPITRE_SOURCE_DIR;
    long lines = 0;
    for (const char* dir :
         {"tests/golden/programs", "tests/bad", "tests/warn", "tests/e2e/programs",
          "tests/workshop", "data/demo", "data/exercises"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file()) continue;
            std::ifstream in(e.path());
            for (std::string line; std::getline(in, line); ++lines)
                ASSERT_TRUE(same(line) && same_in_text(line)) << e.path();
        }
    }
    EXPECT_GT(lines, 5000);
}

// Lines made of what plain blocks are made of, and of what makes the lane
// give up: signs, points, spaces, blanks, variables, E and L words, long
// numbers, '/', '$', parentheses, G76/G77/G79, stray characters.
TEST(ParseLane, RandomLinesParseTheSameBothWays) {
    std::mt19937 rng(20261126);
    const std::string letters = "NGXYZIJKRFSTDMABCUVWELHPQO";
    const char* pieces[] = {"",    "-",      "+",     ".",      " ",
                            "  ",  "0",      "00",    "123",    "4.5",
                            "-6.", ".75",    "99999", "123456", "1234567890123456",
                            "L1",  "E80000", "L",     "=",      "*"};
    const char* tails[] = {"",        "(COMMENT)", " $1 TEXT", "\r", " ",  "/",
                           "G79 N10", "G77 N1 N2", "G76+ N10", ";",  "\t", "#"};
    std::uniform_int_distribution<int> nwords(0, 7), coin(0, 9);
    for (int k = 0; k < 200000; ++k) {
        std::string line;
        if (coin(rng) == 0) line += '/';
        if (coin(rng) < 6) line += "N" + std::to_string(rng() % 100000) + " ";
        for (int w = nwords(rng); w > 0; --w) {
            line += letters[rng() % letters.size()];
            const int parts = coin(rng) < 8 ? 1 : 2;
            for (int p = 0; p < parts; ++p) line += pieces[rng() % std::size(pieces)];
            if (coin(rng) < 7) line += ' ';
        }
        if (coin(rng) == 0) line += tails[rng() % std::size(tails)];
        ASSERT_TRUE(same(line) && same_in_text(line));
    }
}

// The lane reading a program's text stops at the line's '\n': a comment left
// open is not closed by the next line, and the text's end ('\0') is no block.
TEST(ParseLane, InTextTheLineEndsAtItsNewline) {
    Block b;
    size_t len = 0;
    EXPECT_FALSE(parse_plain_line("N10 X1 (OPEN\nN20 (X)\n", 21, b, len));
    EXPECT_FALSE(parse_plain_line("N10 X1", 6, b, len));
    ASSERT_TRUE(parse_plain_line("N10 X1 (C) \r\nN20 Y2\n", 20, b, len));
    EXPECT_EQ(len, 12u);
    EXPECT_EQ(b.words.size(), 2u);
    const std::string longest = "N1" + std::string(kMaxBlockChars, ' ') + "\n";
    EXPECT_FALSE(parse_plain_line(longest.c_str(), longest.size(), b, len));
}

// Every length of integer and fraction part up to the exact 15 digits, at
// every alignment, followed by a letter, a space, the line's end or a byte
// from 0xFA up, must give the value strtod gives (the lane and the general
// parser share the digit scanner, so the differential tests cannot see it).
TEST(ParseLane, NumbersOfEveryLengthAndAlignmentReadExactly) {
    std::mt19937_64 rng(14);
    const std::string after[] = {"", " Y1", "Y", "\xfa", "\xff", "(C)", "\xc3\xa9"};
    for (int pad = 0; pad < 8; ++pad)
        for (int whole = 0; whole <= 15; ++whole)
            for (int frac = -1; frac <= 15 - whole; ++frac) {
                if (whole == 0 && frac <= 0) continue;
                std::string num;
                for (int k = 0; k < whole; ++k) num += char('0' + rng() % 10);
                if (frac >= 0) num += '.';
                for (int k = 0; k < frac; ++k) num += char('0' + rng() % 10);
                const double want = std::strtod(num.c_str(), nullptr);
                for (const std::string& tail : after) {
                    const std::string line = std::string(size_t(pad), ' ') + "X" + num + tail;
                    Block b;
                    // A stray byte after it may be an error: the value is read first.
                    parse_block(line, b);
                    ASSERT_FALSE(b.words.empty()) << line;
                    EXPECT_EQ(b.words[0].v.num, want) << line;
                    EXPECT_EQ(b.words[0].v.int_digits, whole) << line;
                    EXPECT_EQ(b.words[0].v.frac_digits, std::max(frac, 0)) << line;
                    const std::string text = line + "\n";
                    size_t len = 0;
                    if (parse_plain_line(text.c_str(), text.size(), b, len)) {
                        EXPECT_EQ(b.words[0].v.num, want) << line;
                    }
                }
            }
}
