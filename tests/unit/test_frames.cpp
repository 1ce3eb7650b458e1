// The offset chain: forward and inverse round-trip, seed relations.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>

#include "core/geometry/frames.hpp"
#include "helpers.hpp"

using namespace pupitre;

TEST(Frames, RoundTripProperty) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-300, 300);
    for (int i = 0; i < 2000; ++i) {
        Frames f;
        for (int a = 0; a < kAxes; ++a) {
            f.pref[size_t(a)] = u(rng);
            f.dec1[size_t(a)] = u(rng) / 10;
            f.dec3[size_t(a)] = u(rng) / 100;
            f.g59[size_t(a)] = u(rng) / 10;
            f.gauge[size_t(a)] = u(rng) / 5;
        }
        f.g53 = i % 3 == 0;
        f.mirror[X] = i % 2;
        f.mirror[Z] = i % 5 == 0;
        f.scale_on = i % 4 == 0;
        f.scale = 0.5 + (i % 7) * 0.25;
        f.ed = u(rng);
        f.ed_c0 = u(rng) / 10;
        f.ed_c1 = u(rng) / 10;
        Axes p{};
        for (auto& v : p) v = u(rng);
        Axes back = f.to_program(f.to_machine(p));
        for (int a = 0; a < kAxes; ++a) EXPECT_NEAR(back[size_t(a)], p[size_t(a)], 1e-9);
    }
}

TEST(Frames, SeedG92Example) {
    // 000:1187-1211: PREF Z -300, DEC1 20, gauge 80, Z40 is -160 on OM; G92 Z60 -> PREF -320.
    test::Prog r("%1\nG0 D1 X0 Z40\nG92 Z60\nL1=E62000\nM2\n", "lathe",
                 {{"PREF.Z", -300}, {"DEC1.Z", 20}, {"D1.Z", 80}});
    ASSERT_EQ(r.error(), 0);
    ASSERT_EQ(r.cap.moves.size(), 1u);
    EXPECT_NEAR(r.cap.moves[0].to_mach[Z], -160, 1e-9);
    EXPECT_NEAR(r.L(1), -320000, 1e-6);
}

TEST(Frames, GaugeAppliedAtFirstMoveOfTheAxis) {
    // 000:843-865: the Z gauge of D02 at N40, the X gauge at N50.
    test::Prog r("%1\nN10 G00 G52 X150 Z200\nN20 T02 D02 M06\nN40 G00 Z100\nN50 X60\nM2\n", "lathe",
                 {{"D2.X", 20}, {"D2.Z", 50}});
    ASSERT_EQ(r.cap.moves.size(), 3u);
    EXPECT_NEAR(r.cap.moves[1].to_mach[Z], 150, 1e-9);  // 100 + 50
    EXPECT_NEAR(r.cap.moves[1].to_mach[X], 150, 1e-9);  // X untouched: radius 150
    EXPECT_NEAR(r.cap.moves[2].to_mach[X], 50, 1e-9);   // radius 30 + 20
}

TEST(Frames, G59G90ReplacesG91Adds) {
    test::Prog r("%1\nG59 X10\nG91 G59 X5\nG90 G0 X0 Y0 Z0\nM2\n");
    ASSERT_EQ(r.cap.moves.size(), 1u);
    EXPECT_NEAR(r.cap.moves[0].to_mach[X], 15, 1e-9);
}

TEST(Frames, LatheXIsADiameterIncrementalXARadius) {
    test::Prog r("%1\nG0 X40 Z10\nG91 X2\nM2\n", "lathe");
    ASSERT_EQ(r.cap.moves.size(), 2u);
    EXPECT_NEAR(r.cap.moves[0].to_mach[X], 20, 1e-9);
    EXPECT_NEAR(r.cap.moves[1].to_mach[X], 22, 1e-9);  // G91 X2 moves 2 mm radially
}
