// Block parser: words, blank values, comments, assignments, tests, errors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/parse/block.hpp"

using namespace pupitre;

namespace {
Block parse_ok(std::string_view s) {
    Block b;
    const Error d = parse_block(s, b);
    EXPECT_FALSE(d) << s << ": " << d.detail;
    return b;
}
int parse_err(std::string_view s) {
    Block b;
    const Error d = parse_block(s, b);
    EXPECT_TRUE(d) << s;
    return d.code;
}
}  // namespace

TEST(Block, WordsAndLabel) {
    Block b = parse_ok("N10 G00 G52 X150 Z200");
    EXPECT_EQ(b.n, 10);
    ASSERT_EQ(b.words.size(), 5u);
    EXPECT_EQ(b.words[3].addr, addr1('X'));
    EXPECT_DOUBLE_EQ(b.words[3].v.num, 150);
}

TEST(Block, BlankAddressIsZero) {
    // S4 L1390: "G0 G52 XZ" = G0 G52 X0 Z0; "G" alone = G0.
    Block b = parse_ok("G X Y30");
    ASSERT_EQ(b.words.size(), 3u);
    EXPECT_EQ(b.words[0].v.kind, Operand::Blank);
    EXPECT_EQ(b.words[1].v.kind, Operand::Blank);
    EXPECT_DOUBLE_EQ(b.words[2].v.num, 30);
    Block c = parse_ok("N10 G0 G52 XZ");
    EXPECT_EQ(c.words.size(), 5u);
}

TEST(Block, SpacesInsideWordsAndLeadingZeros) {
    Block b = parse_ok("N 10 G0 X 330 Z 85 F.08 M03");
    EXPECT_EQ(b.n, 10);
    EXPECT_DOUBLE_EQ(b.words[2].v.num, 330);
    EXPECT_DOUBLE_EQ(b.words[4].v.num, 0.08);
    EXPECT_DOUBLE_EQ(b.words[5].v.num, 3);
}

TEST(Block, VariablesInAddresses) {
    Block b = parse_ok("G B-L10 XE80000 S L4");
    EXPECT_EQ(b.words[1].v.kind, Operand::LVar);
    EXPECT_TRUE(b.words[1].v.neg);
    EXPECT_EQ(b.words[2].v.kind, Operand::EParam);
    EXPECT_EQ(b.words[2].v.index, 80000);
    EXPECT_EQ(b.words[3].v.kind, Operand::LVar);
}

TEST(Block, SeveralAssignments) {
    Block b = parse_ok("L0= 80 L1= 30 L2= 0.1 L3= 5");
    EXPECT_EQ(b.assigns.size(), 4u);
    Block c = parse_ok("L14 = E60000/1000 -L14");
    ASSERT_EQ(c.assigns.size(), 1u);
    EXPECT_EQ(c.assigns[0].expr.count, 3u);
}

TEST(Block, G79Test) {
    Block b = parse_ok("N170 G79 L5<3 N160");
    EXPECT_EQ(b.test.cmp, Cmp::lt);
    Block c = parse_ok("G79 E69000=300 N200");
    EXPECT_EQ(c.test.cmp, Cmp::eq);
    EXPECT_TRUE(c.assigns.empty());
}

TEST(Block, SpecialGForms) {
    Block b = parse_ok("G77 -2");
    EXPECT_EQ(b.words[0].glevel, 2);
    Block c = parse_ok("G76+ H100");
    EXPECT_EQ(c.words[0].gsign, '+');
}

TEST(Block, MessageAndComment) {
    Block b = parse_ok("N100 $0 CONTROLER DIAMETRE 40 (note)");
    EXPECT_EQ(b.msg_channel, 0);
    EXPECT_EQ(b.msg, "CONTROLER DIAMETRE 40");
    Block c = parse_ok("/N20 X1 (skip me)");
    EXPECT_TRUE(c.skip);
}

TEST(Block, SyntaxErrors) {
    EXPECT_EQ(parse_err("N10 G1 X10 (COMMENT"), 17);
    EXPECT_EQ(parse_err("N10 G1 X10 #"), 1);
    EXPECT_EQ(parse_err("N10 g1 X10"), 1);
    EXPECT_EQ(parse_err("N10 GO X10"), 1);
    EXPECT_EQ(parse_err("L1 5"), 93);
    EXPECT_EQ(parse_err("L1=L2+X5"), 93);
    EXPECT_EQ(parse_err("WHILE L1<5 DO"), 4);
    EXPECT_EQ(parse_err(std::string(118, 'X')), 1);
}

TEST(Block, LongLineIsRejectedCheaply) {
    std::string huge(100'000'000, 'X');
    EXPECT_EQ(parse_err(huge), 1);
}
