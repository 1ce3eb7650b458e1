// The program editor: blocks, ranges, search, renumbering, the syntax check.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "console/editor.hpp"

using pupitre::Diag;
using pupitre::console::Editor;

namespace {

Editor open(const char* text) {
    Editor e;
    e.open(500, text, 3, false);
    return e;
}

}  // namespace

TEST(Editor, InsertReplaceDeleteKeepTheText) {
    Editor e = open("%500\nN10 G0 X0\nN20 G1 X10\nN30 M2\n");
    e.cursor = 1;
    EXPECT_EQ(e.insert_after("N15 G1 Y5"), "");
    EXPECT_EQ(e.cursor, 2);
    EXPECT_EQ(e.replace("N15 G1 Y6"), "");
    e.cursor = 3;
    EXPECT_EQ(e.erase(), "");
    EXPECT_EQ(e.text(), "%500\nN10 G0 X0\nN15 G1 Y6\nN30 M2\n");
    EXPECT_TRUE(e.dirty);
    e.cursor = 0;
    EXPECT_NE(e.replace("%501"), "");  // the % line names the program
}

TEST(Editor, CopyCutAndPasteARangeMovesBlocks) {
    Editor e = open("%500\nA\nB\nC\nD\n");
    e.cursor = 1;
    e.toggle_mark();
    e.cursor = 2;
    EXPECT_EQ(e.cut(), "");  // A and B
    EXPECT_EQ(e.text(), "%500\nC\nD\n");
    e.cursor = 2;
    EXPECT_EQ(e.paste(), "");
    EXPECT_EQ(e.text(), "%500\nC\nD\nA\nB\n");
    e.cursor = 1;
    EXPECT_EQ(e.copy(), "");
    EXPECT_EQ(e.paste(), "");
    EXPECT_EQ(e.text(), "%500\nC\nC\nD\nA\nB\n");
}

TEST(Editor, GotoAndFind) {
    Editor e = open("%500\nN10 G0 X0\nN20 G1 X10 (FACE)\nN30 M2\n");
    EXPECT_TRUE(e.goto_n(30));
    EXPECT_EQ(e.cursor, 3);
    EXPECT_TRUE(e.find("face"));
    EXPECT_EQ(e.cursor, 2);
    EXPECT_FALSE(e.goto_n(99));
    EXPECT_EQ(e.cursor, 2);
}

TEST(Editor, RenumberRewritesTheReferences) {
    Editor e = open(
        "%500\nN5 G0 X0\nN7 G1 X10\n/N8 G1 X20\nN9 G77 N7 N8 S2\nN11 G79 N5 (N5 AGAIN)\nN12 M2\n");
    EXPECT_EQ(e.renumber(10, 10), 6);
    EXPECT_EQ(e.text(),
              "%500\nN10 G0 X0\nN20 G1 X10\n/N30 G1 X20\nN40 G77 N20 N30 S2\nN50 G79 N10 (N5 "
              "AGAIN)\nN60 M2\n");
}

TEST(Editor, TheCheckStopsOnTheFirstBadBlock) {
    Editor e = open("%500\nN10 G0 X0\nN20 G1 X10 (NO END\nN30 G1 $9\nN40 M2\n");
    std::optional<Diag> d = e.check();
    ASSERT_TRUE(d);
    EXPECT_EQ(e.cursor, 2);
    EXPECT_EQ(e.error_line, 2);
    EXPECT_EQ(d->line, 3);
    EXPECT_EQ(d->n, 20);
    EXPECT_EQ(d->code, 17);  // end of block inside a comment
}

TEST(Editor, ModifLocksThePreparedBlocks) {
    Editor e = open("%500\nN10 G0 X0\nN20 G1 X10\nN30 G1 X20\nN40 M2\n");
    e.locked = 3;  // up to N20 read
    e.cursor = 2;
    EXPECT_NE(e.replace("N20 G1 X11"), "");
    EXPECT_NE(e.erase(), "");
    e.cursor = 3;
    EXPECT_EQ(e.replace("N30 G1 X25"), "");
    e.cursor = 2;
    EXPECT_EQ(e.insert_after("N25 G1 Y5"), "");  // between the prepared block and the next
    EXPECT_EQ(e.text(), "%500\nN10 G0 X0\nN20 G1 X10\nN25 G1 Y5\nN30 G1 X25\nN40 M2\n");
}
