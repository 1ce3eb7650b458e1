// Drilling cycles G81-G89 and G31: the motion skeleton, the peck law, tapping,
// modal behaviour (pupitre-iso(5), DRILLING, BORING AND TAPPING CYCLES).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

namespace {
// Depths (Z) reached by feed moves of the run, in order.
std::vector<double> feed_depths(const Prog& r) {
    std::vector<double> z;
    for (const MoveEvent& m : r.cap.moves)
        if (m.g == 1 && std::fabs(m.from_mach[X] - m.to_mach[X]) < 1e-9 &&
            m.to_mach[Z] < m.from_mach[Z])
            z.push_back(m.to_prog[Z]);
    return z;
}
}  // namespace

TEST(Cycles, G81SkeletonAndRetractPlaneDefault) {
    // 000:5392-5411: from Z3, G81 Z-10: feed to -10, rapid back to 3 (ER default).
    Prog r("%1\nS1000 M3\nG0 X15 Y50 Z3\nG81 Z-10 F100\nX35 Y50\nG80 G0 Z200\nM2\n");
    ASSERT_EQ(r.error(), 0);
    auto& m = r.cap.moves;
    ASSERT_EQ(m.size(), 7u);
    EXPECT_EQ(m[1].g, 1);
    EXPECT_NEAR(m[1].to_prog[Z], -10, 1e-9);
    EXPECT_EQ(m[2].g, 0);
    EXPECT_NEAR(m[2].to_prog[Z], 3, 1e-9);
    EXPECT_NEAR(m[3].to_prog[X], 35, 1e-9);  // to the second hole at ER
    EXPECT_NEAR(m[3].to_prog[Z], 3, 1e-9);
}

TEST(Cycles, PeckLawPAndQDecreases) {
    // P10 Q2.5 over 35 mm: 10, 8.5, 7, 5.5, 4 (the peck law of pupitre-iso(5),
    // DRILLING, BORING AND TAPPING CYCLES).
    Prog r("%1\nS1000 M3\nG0 X0 Y0 Z0\nG83 Z-35 P10 Q2.5 F100\nG80 G0 Z50\nM2\n");
    ASSERT_EQ(r.error(), 0);
    std::vector<double> want = {-10, -18.5, -25.5, -31, -35};
    EXPECT_EQ(feed_depths(r), want);
}

TEST(Cycles, PeckLawPOnlyAndES) {
    Prog p("%1\nS1000 M3\nG0 X0 Y0 Z0\nG83 Z-25 P10 F100\nG80 G0 Z50\nM2\n");
    std::vector<double> want = {-10, -20, -25};
    EXPECT_EQ(feed_depths(p), want);
    Prog e("%1\nS1000 M3\nG0 X0 Y0 Z0\nG87 Z-30 ES3 F100\nG80 G0 Z50\nM2\n");
    std::vector<double> want3 = {-10, -20, -30};
    EXPECT_EQ(feed_depths(e), want3);
}

TEST(Cycles, G83ComesBackToEPAboveTheDepthReached) {
    Prog r("%1\nS1000 M3\nG0 X0 Y0 Z4\nG83 Z-16 P10 F100\nG80 G0 Z50\nM2\n");
    ASSERT_EQ(r.error(), 0);
    bool seen = false;
    for (const MoveEvent& m : r.cap.moves)
        if (m.g == 0 && std::fabs(m.to_prog[Z] - (-6 + 1)) < 1e-9) seen = true;  // EP 1 above -6
    EXPECT_TRUE(seen);
}

TEST(Cycles, RigidTappingFeedsFromPitchAndSpeed) {
    // 000:5926-5934: M10x1.5, S200, EK2: in at 300 mm/min, out at 600.
    Prog r("%1\nS200 M41 M3\nG0 X20 Y20 Z10\nG84 ER10 Z-20 K1.5 EK2\nG80 G0 Z100\nM2\n");
    ASSERT_EQ(r.error(), 0);
    ASSERT_GE(r.cap.moves.size(), 3u);
    EXPECT_NEAR(r.cap.moves[1].feed, 300, 1e-9);
    EXPECT_NEAR(r.cap.moves[2].feed, 600, 1e-9);
    // The spindle reverses at the bottom and is restored at ER.
    ASSERT_GE(r.cap.spindles.size(), 3u);
    EXPECT_EQ(r.cap.spindles[1].dir, 4);
    EXPECT_EQ(r.cap.spindles[2].dir, 3);
}

TEST(Cycles, ParametersStayModalAndERAloneMoves) {
    // %222 (000:6379-6403): Z and ER changed between holes; ER alone moves.
    Prog r(
        "%222\nS1000 M3\nG0 X0 Y0 Z50\nG81 X10 Y20 ER22 Z10 F100\nER32\nX30 Z-3\nX50 ER22 Z10\nG80 "
        "G0 Z150\nM2\n");
    ASSERT_EQ(r.error(), 0);
    auto d = feed_depths(r);
    std::vector<double> want = {10, -3, 10};
    EXPECT_EQ(d, want);
}

TEST(Cycles, LatheAxialDrilling) {
    Prog r("%1\nG97 S800 M3 M40\nG0 X0 Z5\nG83 Z-30 P12 F50\nG80 G0 Z50\nM2\n", "lathe");
    ASSERT_EQ(r.error(), 0);
    auto d = feed_depths(r);
    ASSERT_FALSE(d.empty());
    EXPECT_NEAR(d.back(), -30, 1e-9);
}

TEST(Cycles, G31ThreadingStarts) {
    Prog r("%1\nS200 M3 M40\nG0 X30 Y30 Z10\nG31 Z-20 K3 P4 F2\nG0 Z100\nM2\n");
    ASSERT_EQ(r.error(), 0);
    int feeds = 0;
    for (const MoveEvent& m : r.cap.moves)
        if (m.g == 1) {
            ++feeds;
            EXPECT_NEAR(m.feed, 600, 1e-9);  // K3 x 200 rev/min
        }
    EXPECT_EQ(feeds, 2);
}
