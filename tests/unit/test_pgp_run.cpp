// PGP through the interpreter: seed examples run as programs, compensation of a
// PGP profile, and the errors the interpreter raises around the solver (72, 96,
// 131, 136, 137; pupitre-iso(5), PROFILE GEOMETRY PROGRAMMING (PGP)).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

namespace {
std::string prog(const std::string& start, const std::string& body) {
    return "%1\nG0 " + start + " Z0\nG1 F100\n" + body + "G0 Z50\nM2\n";
}
}  // namespace

TEST(PgpRun, SeedExampleE1) {
    Prog r(prog("X Y10", "G1 EA10 ES\nEA45 X50 Y50\n"));
    ASSERT_EQ(r.error(), 0);
    ASSERT_GE(r.cap.moves.size(), 3u);
    EXPECT_NEAR(r.cap.moves[1].to_prog[X], 12.141, 5e-4);
    EXPECT_NEAR(r.cap.moves[1].to_prog[Y], 12.141, 5e-4);
}

TEST(PgpRun, FilletThroughCompensation) {
    // E16 with a R2 tool on the left: every element stays at 2 from the profile.
    Prog r(prog("X-10 Y10",
                "D1 G41 G1 X-10 Y10\nEA160 ES- EB+12\nG3 I-50 J20 X-60 Y20\nG1 G40 X-80 Y0\n"),
           "mill", {{"D1.R", 2}});
    ASSERT_EQ(r.error(), 0);
    int arcs = 0;
    for (const MoveEvent& m : r.cap.moves) arcs += (m.g == 2 || m.g == 3);
    EXPECT_GE(arcs, 2);
}

TEST(PgpRun, EventsOfBlocksInBetweenComeAfterTheElement) {
    Prog r(prog("X Y10", "G1 EA10 ES\n$0 HELD\nEA45 X50 Y50\n"));
    ASSERT_EQ(r.error(), 0);
    EXPECT_EQ(r.cap.messages.size(), 1u);
}

TEST(PgpRun, InterpreterErrors) {
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 EA30 ES\nG91 EA60 X10 Y10\n")).error(), 72);
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 EA30 ES\nE80000=1\nEA60 X50 Y50\n")).error(), 96);
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 EA30 ES\nL100=1\nEA60 X50 Y50\n")).error(), 96);
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 EA30 ES\nM8\nM9\nS1000\nEA60 X50 Y50\n")).error(), 136);
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 EA30 ES\nG18\nEA60 X50 Y50\n")).error(), 137);
    EXPECT_EQ(Prog("%1\nG0 X0 Y0 Z0\nG1 EA30 ES F100\nM2\n").error(), 131);
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 X10 Y0 EB+2 M0\nX10 Y10\n")).error(), 131);
    EXPECT_EQ(Prog(prog("X0 Y0", "G1 EA30 ES ET\nEA60 X50 Y50\n")).error(), 110);
}
