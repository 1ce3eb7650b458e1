// G45 pockets: the BOÎTIER test vector of 000:6514 and the
// errors G45 raises (pupitre-iso(5), POCKETS).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <set>

#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

TEST(Pocket, BoitierSquareLayersAndContours) {
    Prog r(
        "%200\nT3 D3 M6\nM3 M40 S1000\nG X Y\nZ10\n"
        "N240 G45 X Y Z-20 ER3 EX80 EY80 EB10 P10 Q8 I.5 J.5 EP150 EQ350 EJ150\nZ100\nM2\n",
        "mill", {{"D3.R", 8}});
    ASSERT_EQ(r.error(), 0);
    std::set<double> layers, contours;
    for (const MoveEvent& m : r.cap.moves) {
        if (m.loc.n != 240) continue;
        if (m.g == 1 && std::fabs(m.to_prog[X]) < 1e-9 && std::fabs(m.to_prog[Y]) < 1e-9)
            layers.insert(m.to_prog[Z]);
        if (m.g == 1 && std::fabs(m.to_prog[Y]) < 1e-9 && m.to_prog[X] > 0)
            contours.insert(m.to_prog[X]);
    }
    // Roughing layers of 7.5 leaving I = 0.5, then the floor at -20 (000:6514).
    EXPECT_EQ(layers, (std::set<double>{-4.5, -12, -19.5, -20}));
    // Contours at 7.875, 15.75, 23.625, 31.5 (leaving J), finishing at 32.
    for (double x : {7.875, 15.75, 23.625, 31.5, 32.0}) EXPECT_TRUE(contours.count(x)) << x;
}

TEST(Pocket, CircularPocketKeepsTheFeeds) {
    // N330: Ø30, Q8 >= d = 7: one circle of radius 7; layers of 8.25 from -17.
    Prog r(
        "%200\nT3 D3 M6\nM3 M40 S1000\nG X Y Z10\nG45 X Y Z-20 ER3 EX80 EY80 EB10 P10 Q8 EP150 "
        "EQ350\n"
        "G X Y Z-15\nN330 G45 X Y Z-34 ER-17 EB15 P10 Q8 I.5\nZ100\nM2\n",
        "mill", {{"D3.R", 8}});
    ASSERT_EQ(r.error(), 0);
    std::set<double> layers;
    int circles = 0;
    for (const MoveEvent& m : r.cap.moves) {
        if (m.loc.n != 330) continue;
        if (m.g == 1 && std::fabs(m.to_prog[X]) < 1e-9 && std::fabs(m.to_prog[Y]) < 1e-9)
            layers.insert(m.to_prog[Z]);
        if (m.g == 3) {
            ++circles;
            EXPECT_NEAR(std::fabs(m.sweep), 360, 1e-9);
        }
    }
    EXPECT_EQ(layers, (std::set<double>{-25.25, -33.5, -34}));
    EXPECT_GE(circles, 3);
}

TEST(Pocket, Errors) {
    const std::string head = "%1\nT3 D3 M6\nM3 M40 S1000\nG0 X0 Y0 Z10\n";
    auto run = [&](const std::string& b, double r = 8) {
        return Prog(head + b + "\nM2\n", "mill", {{"D3.R", r}}).error();
    };
    EXPECT_EQ(run("G18 G45 Z-5 EB15 P5 Q5 EP100 EQ100"), 885);
    EXPECT_EQ(run("G45 Z-5 EX40 EY40 EB5 P5 Q5 EP100 EQ100"), 886);
    EXPECT_EQ(run("G45 Z-5 EB15 P5 Q20 EP100 EQ100"), 887);
    EXPECT_EQ(run("G45 Z-5 EX14 EY40 P5 Q5 EP100 EQ100"), 896);
    EXPECT_EQ(run("G45 Z-5 EX20 EB15 P5 Q5 EP100 EQ100"), 897);
    EXPECT_EQ(run("G45 Z-5 EB15 P5 Q5 EP100 EQ100", 0), 898);
    EXPECT_EQ(Prog("%1\nT3 D3 M6\nM3 S1000\nG0 X0 Y0 Z10\nG45 Z-5 EB15 P5 Q5 EQ100\nM2\n", "mill",
                   {{"D3.R", 8}})
                  .error(),
              892);
}
