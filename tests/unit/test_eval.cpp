// Expressions: strictly left to right (000:7444-7457; pupitre-iso(5),
// PARAMETRIC PROGRAMMING), seed examples.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "helpers.hpp"

using pupitre::test::Prog;

TEST(Eval, LeftToRight) {
    Prog r("%1\nL1=2+3*5\nL2=10 L3=L2+4/2\nL4=-L2/2\nM2\n");
    EXPECT_EQ(r.error(), 0);
    EXPECT_DOUBLE_EQ(r.L(1), 25);  // 004:1353
    EXPECT_DOUBLE_EQ(r.L(3), 7);
    EXPECT_DOUBLE_EQ(r.L(4), -5);
}

TEST(Eval, Functions) {
    Prog r("%1\nL1=S30 L2=C60 L3=R2 L4=T-3.7 L5=A1 L6=S30/C30\nM2\n");
    EXPECT_NEAR(r.L(1), 0.5, 1e-12);
    EXPECT_NEAR(r.L(2), 0.5, 1e-12);
    EXPECT_NEAR(r.L(3), std::sqrt(2.0), 1e-12);
    EXPECT_DOUBLE_EQ(r.L(4), -3);
    EXPECT_NEAR(r.L(5), 45, 1e-12);
    EXPECT_NEAR(r.L(6), std::tan(M_PI / 6), 1e-12);
}

TEST(Eval, SeedFrameChange) {
    // 004 %170 (004:2006-2012): standard precedence would give 169.7299.
    Prog r(
        "%1\nL10=30 L11=70 L12=75 L13=34.225 L14=197.783 L15=-339.662\n"
        "L16= L11+L14 * C L10\nL16=-L13-L15 * S L10 + L16 - L14\n"
        "L17= L11+L14 * S L10\nL17= L13+L15 * C L10 + L17 - L15\nM2\n");
    EXPECT_NEAR(r.L(16), 186.8424, 5e-5);
    EXPECT_NEAR(r.L(17), 209.0373, 5e-5);
}

TEST(Eval, SeedIrregularOblong) {
    // %780 (000:8323): L100 = L8-L9/L1 is (L8-L9)/L1.
    Prog r(
        "%1\nL1=100 L8=30 L9=20\nL100=L8-L9/L1\nL101=L1*L1\nL102=L8-L9\nL103=L102*L102\n"
        "L104=L101-L103\nL105=RL104\nL106=L105/L1\nM2\n");
    EXPECT_NEAR(r.L(100), 0.1, 1e-12);
    EXPECT_NEAR(r.L(105), 99.4987, 5e-5);
    EXPECT_NEAR(r.L(106), 0.99499, 5e-6);
}

TEST(Eval, Errors) {
    EXPECT_EQ(Prog("%1\nL1=-4\nL2=RL1\nM2\n").error(), 94);
    EXPECT_EQ(Prog("%1\nL1=5/0\nM2\n").error(), 94);
    EXPECT_EQ(Prog("%1\nL20=1\nM2\n").error(), 91);
    EXPECT_EQ(Prog("%1\nE20000=1\nM2\n").error(), 95);
    EXPECT_EQ(Prog("%1\nE70000=0\nM2\n").error(), 95);
    EXPECT_EQ(Prog("%1\nE99999=0\nM2\n").error(), 91);
}

TEST(Eval, EParametersAreIntegersInInternalUnits) {
    // 000:7651-7669 with the printed inputs: 3000/2000.
    Prog r(
        "%1\nE80002=3000 "
        "E80016=2000\nL1=E80002/E80016\nE80005=E80002/E80016\nE80006=L1*1000\nM2\n");
    EXPECT_DOUBLE_EQ(r.L(1), 1.5);
    EXPECT_EQ(r.in->e_written().at(80005), 1);
    EXPECT_EQ(r.in->e_written().at(80006), 1500);
}

TEST(Eval, EInAddressKeepsItsUnit) {
    // 000:7602-7604: XE80000 with 18000 = X18 mm, FE80000 = F180 mm/min.
    Prog r("%1\nE80000=18000\nG1 XE80000 Y0 Z0 FE80000\nM2\n");
    ASSERT_EQ(r.cap.moves.size(), 1u);
    EXPECT_NEAR(r.cap.moves[0].to_prog[pupitre::X], 18, 1e-9);
    EXPECT_NEAR(r.cap.moves[0].feed, 180, 1e-9);
}

TEST(Eval, GaugesByProgram) {
    // %555 (000:7620-7649): E50001=15157 is a 15.157 mm X gauge of D1.
    Prog r("%555\nE50001=15157 E51001=42126\nM2\n", "lathe");
    EXPECT_NEAR(r.in->corrector(1).x, 15.157, 1e-12);
    EXPECT_NEAR(r.in->corrector(1).z, 42.126, 1e-12);
}
