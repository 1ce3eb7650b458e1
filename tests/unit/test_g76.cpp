// The G76 family: writing L/E values into a program (G76), creating and
// deleting programs (G76+ H / G76- H), inserting and deleting blocks
// (G76+ / G76- [H] N.. [+k]), 000:7018-7170, 7679-7735; pupitre-iso(5), PROGRAM FLOW.
// Expected texts are written by hand from the handbook's rules.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/parse/block.hpp"
#include "tests/unit/helpers.hpp"

using namespace pupitre;
using pupitre::test::Prog;

namespace {
std::string body(const Prog& p, int number) {
    const ProgramText* t = p.mem.find(number);
    return t ? std::string(t->body()) : std::string("<none>");
}
std::vector<double> xs(const Prog& p) {
    std::vector<double> out;
    for (const auto& m : p.cap.moves) out.push_back(m.to_prog[X]);
    return out;
}
const Diag& first_error(const Prog& p) {
    for (const Diag& d : p.in->diags())
        if (d.is_error()) return d;
    static Diag none;
    return none;
}
}  // namespace

TEST(G76Block, PointedBlockOffsetAndTextAreKeptApart) {
    Block b;
    Error d = parse_block("N100 G76+ H120 N100 +2 G1 X3 (here)", b);
    ASSERT_FALSE(d) << d.detail;
    EXPECT_EQ(b.n, 100);
    EXPECT_EQ(b.g76_k, 2);
    EXPECT_EQ(b.g76_block, "G1 X3 (here)");
    EXPECT_EQ(b.g76_block_col, 24);
    ASSERT_EQ(b.words.size(), 4u);  // N100 G76+ H120 N100: the block's own words only
    ASSERT_FALSE(parse_block("G76- N20", b));
    EXPECT_EQ(b.g76_k, -1);
    EXPECT_TRUE(b.g76_block.empty());
    // Without the sign the N words are G76's range, not a pointed block.
    ASSERT_FALSE(parse_block("G76 N100 N120", b));
    EXPECT_EQ(b.words.size(), 3u);
}

TEST(G76, TransferWritesTheValuesIntoTheReservedFields) {
    // 000:7703-7708: only assignments opening a block are written.
    Prog p(
        "%1\nN10 L101=2.5 L4=-3 E80001=42\nN80 G76 N100 N120\nN90 M2\n"
        "N100\nL101=__________ E80001=__________\nL4=__________ G4 F1 E80001=__________\nN120\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_NE(body(p, 1).find("L101=2.5        E80001=42        \n"), std::string::npos)
        << body(p, 1);
    EXPECT_NE(body(p, 1).find("L4=-3" + std::string(9, ' ') + "G4 F1 E80001=__________\n"),
              std::string::npos)
        << body(p, 1);
    EXPECT_EQ(p.mem.take_changed(), std::vector<int>{1});
}

TEST(G76, TransferNeedsTenCharactersAndAnEqualSign) {
    EXPECT_EQ(Prog("%1\nN10 G76 N100 N100\nN20 M2\nN100 L1=_____\n").error(), 97);
    EXPECT_EQ(Prog("%1\nN10 G76 H2\nN20 M2\n%2\nN100 L1 __________\n").error(), 97);
    EXPECT_EQ(Prog("%1\nN10 G76 H9\nN20 M2\n").error(), 25);
}

TEST(G76Plus, CreatesAnEmptyProgramThenFillsItFromTheStart) {
    Prog p(
        "%1\nN10 L1=12.5 L2=1/3\nN20 G76+ H300\n"
        "N30 G76+ H300 N0 N10 G1 XL1 YL2 (first)\n"  // N0 that no line carries: before the first
                                                     // line
        "N40 G76+ H300 N10 N20 L3=L1*2 G0 Z5\n"
        "N50 G77 H300\nN60 M2\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    // L values are written at the resolution of their address; assignments as values.
    EXPECT_EQ(body(p, 300), "N10 G1 X12.5 Y0.333 (first)\nN20 L3=25 G0 Z5\n");
    ASSERT_EQ(p.cap.moves.size(), 2u);
    EXPECT_NEAR(p.cap.moves[0].to_prog[Y], 0.333, 1e-9);
    EXPECT_DOUBLE_EQ(p.L(3), 25);
    EXPECT_EQ(p.cap.moves[0].loc.prog, 300);
    EXPECT_EQ(p.cap.moves[0].loc.line, 2);  // the lines of %300 as it is in memory
}

TEST(G76Plus, AProgramAlreadyInMemoryIsRefused) {
    Prog p("%1\nN10 G76+ H2\nN20 M2\n%2\nN10 G0 X1\n");
    EXPECT_EQ(p.error(), 1005);
    EXPECT_EQ(first_error(p).n, 10);
}

TEST(G76Plus, InsertedAfterTheRunningBlockRunsNext) {
    Prog p("%1\nN10 G0 X1\nN20 G76+ N20 G0 X2\nN30 G0 X3\nN40 M2\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(xs(p), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(body(p, 1), "N10 G0 X1\nN20 G76+ N20 G0 X2\nG0 X2\nN30 G0 X3\nN40 M2\n");
}

TEST(G76Plus, InsertedBehindTheRunningBlockShiftsTheLinesThatFollow) {
    // The next block is still N30, and an error later names its new line.
    Prog p("%1\nN10 G0 X1\nN20 G76+ N10 +0 G0 X2\nN30 G0 X3\nN40 G0 Q1\nN50 M2\n");
    EXPECT_EQ(xs(p), (std::vector<double>{1, 3}));
    EXPECT_EQ(p.error(), 3);  // Q without its G: the error shows where we are
    EXPECT_EQ(first_error(p).n, 40);
    EXPECT_EQ(first_error(p).line, 6);  // was line 5 of the file
}

TEST(G76Plus, PlusKCountsLinesFromThePointedBlock) {
    // The pointed block is line 0: +2 inserts after N120 (000:7103-7105).
    Prog p(
        "%1\nN10 G76+ H120 N100 +2 G0 X9\nN20 M2\n%120\nN100 G0 X1\n(note)\nN120 G0 X3\nN130 G0 "
        "X4\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(body(p, 120), "N100 G0 X1\n(note)\nN120 G0 X3\nG0 X9\nN130 G0 X4\n");
    EXPECT_EQ(Prog("%1\nN10 G76+ H120 N100 +9 G0 X9\nN20 M2\n%120\nN100 G0 X1\n").error(), 25);
    EXPECT_EQ(Prog("%1\nN10 G76+ H120 N200 G0 X9\nN20 M2\n%120\nN100 G0 X1\n").error(), 25);
    EXPECT_EQ(Prog("%1\nN10 G76+ H121 N100 G0 X9\nN20 M2\n%120\nN100 G0 X1\n").error(), 25);
}

TEST(G76Plus, OnlyTheWordsTheHandbookListsCanBeInserted) {
    // 000:7115: N G X Y Z U V W A B C I J K P Q R L0-L19.
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 G1 X1 F200\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 M3\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 X L100\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 XE80000\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 L100=2\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 $1 HELLO\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10\nN20 M2\n").error(), 2);              // nothing to insert
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 G1 X1.23456\nN20 M2\n").error(), 1);  // too many digits
    const Diag& d = first_error(Prog("%1\nN10 G76+ N10 G1 X1 F200\nN20 M2\n"));
    EXPECT_EQ(d.column, 20);  // the F
}

TEST(G76Plus, TheBlockHoldsOnlyTheEdit) {
    EXPECT_EQ(Prog("%1\nN10 G76+ X1 H300\nN20 M2\n").error(), 3);
    EXPECT_EQ(Prog("%1\nN10 G0 G76+ H300\nN20 M2\n").error(), 3);
    EXPECT_EQ(Prog("%1\nN10 G76+\nN20 M2\n").error(), 2);
    EXPECT_EQ(Prog("%1\nN10 G76- N10 G0 X1\nN20 M2\n").error(), 3);
    // Blocks without a label of their own.
    Prog p("%1\nG76+ H300\nG76+ H300 N0 G0 X1\nG76- N20\nN20 G0 X5\nG77 H300\nM2\n");
    EXPECT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(xs(p), std::vector<double>{1});
}

TEST(G76Minus, DeletesTheBlockKLinesAfterThePointedOne) {
    // The handbook's example (printed with G76+, 000:7167): N120 of %120 goes.
    Prog p(
        "%100\nN100 G76- H120 N100 +2\nN110 G77 H120\nN120 M2\n%120\nN100 G0 X1\nN110 G0 X2\nN120 "
        "G0 X3\nN130 G0 X4\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(body(p, 120), "N100 G0 X1\nN110 G0 X2\nN130 G0 X4\n");
    EXPECT_EQ(xs(p), (std::vector<double>{1, 2, 4}));
}

TEST(G76Minus, DeletingTheNextBlockSkipsIt) {
    Prog p("%1\nN10 G76- N20\nN20 G0 X7\nN30 G0 X1\nN40 M2\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(xs(p), std::vector<double>{1});
    EXPECT_EQ(Prog("%1\nN10 G76- N0\nN20 M2\n").error(), 25);  // before the first line: nothing
}

TEST(G76Minus, DeletesAProgramButNotOneThatRuns) {
    Prog p("%1\nN10 G76- H120\nN20 M2\n%120\nN100 G0 X1\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(p.mem.find(120), nullptr);
    EXPECT_EQ(p.mem.take_changed(), std::vector<int>{120});
    EXPECT_EQ(Prog("%1\nN10 G76- H1\nN20 M2\n").error(), 1006);
    EXPECT_EQ(Prog("%1\nN10 G77 H2\nN20 M2\n%2\nN10 G76- H1\n").error(), 1006);
    EXPECT_EQ(Prog("%1\nN10 G76- H5\nN20 M2\n").error(), 25);
    EXPECT_EQ(Prog("%1\nN10 G76- H5 N10\nN20 M2\n").error(), 25);
}

TEST(G76Plus, ARangeCallFollowsALineInsertedInsideIt) {
    // G77 N100 N120 runs N100, N110, the inserted block, N120 and returns.
    Prog p("%1\nN10 G77 N100 N120\nN20 M2\nN100 G76+ N110 G0 X5\nN110 G0 X1\nN120 G0 X2\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(xs(p), (std::vector<double>{1, 5, 2}));
}

TEST(G76Plus, ProgramsAfterTheChangeInTheSameFileStillRun) {
    Prog p(
        "%1\nN10 G76+ N10 G0 Y1\nN20 G76+ N10 G0 Y2\nN30 G77 H2\nN40 M2\n%2\nN10 G0 X3\nN20 G0 "
        "X4\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    // Y1 runs (inserted after the running block), Y2 does not (inserted behind).
    ASSERT_EQ(xs(p), (std::vector<double>{0, 3, 4}));
    EXPECT_EQ(body(p, 1),
              "N10 G76+ N10 G0 Y1\nG0 Y2\nG0 Y1\nN20 G76+ N10 G0 Y2\nN30 G77 H2\nN40 M2\n");
    EXPECT_EQ(body(p, 2), "N10 G0 X3\nN20 G0 X4\n");
    EXPECT_EQ(p.cap.moves[1].loc.line, 9);  // %2's N10 moved down two lines
    EXPECT_EQ(p.mem.find(2)->find_label(20)->line, 10);
}

TEST(G76Plus, TheProgramMemoryQuotaIsError36) {
    // A loop that inserts for ever fills the memory, not the machine.
    Prog p("%1\nN10 G76+ N20 G0 X1 Y2 Z3\nN20 G79 N10\n");
    MachineProfile m;
    builtin_machine("mill", m);
    EXPECT_EQ(p.error(), 36);
    EXPECT_LE(p.mem.size(), size_t(m.program_memory_kb * 1024));
}

// ---- the review's cases ----

TEST(G76Minus, ARepeatedRangeWhoseLinesAreAllDeletedEnds) {
    // G77 N100 N100 S2 whose only block deletes itself: the second pass runs
    // nothing and the caller goes on (it used to run the text after the range).
    Prog p("%1\nN10 G77 N100 N100 S2\nN20 G0 X20\nN30 M2\nN100 G76- N100\nN110 G0 X99\nN120 M2\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(xs(p), std::vector<double>{20});
}

TEST(G76Plus, AValueTheBlockCannotHoldIsRefusedAtTheG76Block) {
    // X takes 5 integer digits; a block takes 117 characters.
    Prog a("%1\nN5 L1=123456789\nN10 G76+ N10 G0 XL1\nN20 M2\n");
    EXPECT_EQ(a.error(), 1);
    EXPECT_EQ(first_error(a).n, 10);
    const std::string huge =
        "N5 L1=-99999*99999*99999*99999*99999*99999*99999*99999*99999*99999*99999*99999\n";
    Prog b("%1\n" + huge + "N10 G76+ N10 L3=L1 L4=L1\nN20 M2\n");  // 2 x 63 digits
    EXPECT_EQ(b.error(), 1);
    EXPECT_EQ(first_error(b).n, 10);
    EXPECT_EQ(body(b, 1), huge + "N10 G76+ N10 L3=L1 L4=L1\nN20 M2\n");  // nothing written
    // One of them fits, written in full (not cut by a short buffer).
    Prog c("%1\n" + huge + "N10 G76+ N10 L3=L1\nN20 M2\n");
    ASSERT_EQ(c.error(), 0) << first_error(c).detail;
    EXPECT_DOUBLE_EQ(c.L(3), c.L(1));
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 L3=L100+E80000\nN20 M2\n").error(), 1);
    EXPECT_EQ(Prog("%1\nN10 G76+ N10 +123456 G0 X1\nN20 M2\n").error(), 1);
}

TEST(G76Minus, ACommentMayFollowThePointedBlock) {
    Prog p("%1\nN10 G76- N20 (DELETE N20)\nN20 G0 X7\nN30 G0 X1\nN40 M2\n");
    ASSERT_EQ(p.error(), 0) << first_error(p).detail;
    EXPECT_EQ(xs(p), std::vector<double>{1});
}

TEST(G76Plus, TheBlockTakesNoAssignmentAndOneH) {
    EXPECT_EQ(Prog("%1\nN10 L1=5 G76+ N20 G0 XL1\nN20 M2\n").error(), 3);
    EXPECT_EQ(Prog("%1\nN10 G76- H2 L1=3\nN20 M2\n%2\nN1 G0 X1\n").error(), 3);
    EXPECT_EQ(Prog("%1\nN10 G76- H2 H3\nN20 M2\n%2\nN1 G0 X1\n%3\nN1 G0 X1\n").error(), 3);
}

TEST(G76Plus, BlocksWithoutMotionUnderCompensationAreCounted) {
    // Three G76 blocks in a row under G41 are three blocks without motion (140).
    Prog p(
        "%1\nN10 G0 X0 Y0 Z0\nN20 G1 G41 X10 Y0 F100\nN30 G76+ H5\nN40 G76+ H6\nN50 G76+ H7\n"
        "N60 X20\nN70 G40 X30\nN80 M2\n",
        "mill", {{"D1.R", 2}});
    EXPECT_EQ(p.error(), 140);
    EXPECT_EQ(first_error(p).n, 50);
}

TEST(G76Plus, ALoopOfEditsInALongProgramMeetsTheBlockBudget) {
    // Each edit counts a block per kilobyte it moves: 9,000 lines behind the
    // loop (about 230 KB, within the memory) end it long before 200,000 plain
    // blocks would.
    std::string text = "%1\nN10 G76+ N10 G0 X1\nN20 G76- N10 +1\nN30 G79 N10\n";
    for (int i = 0; i < 9000; ++i) text += "N" + std::to_string(1000 + i) + " G0 X2 Y3 (FILLER)\n";
    RunOptions o;
    o.max_blocks = 200000;
    Prog p(text, "mill", {}, o);
    EXPECT_EQ(p.error(), 1001);
    EXPECT_LT(p.cap.moves.size(), 1000u);
}
