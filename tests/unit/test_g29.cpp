// G29, tool correction in space (000:3545, 004:697-699; pupitre-iso(5), G29):
// the tool tip for a contact point and a surface normal, with expected points
// computed by hand.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/helpers.hpp"

using namespace pupitre;
using pupitre::test::Prog;

namespace {

const char* kProgram =
    "%1\nN10 G0 X0 Y0 Z50\nN20 T1 D1 M6\n"
    "N30 G1 G29 X10 Y0 Z0 P0 Q0 R1 F500\n"  // flat bottom: the tip on the point
    "N40 X20 Y0 Z0 P.707 Q0 R.707\n"        // a 45-degree slope
    "N50 X30 Y5 Z-1 P0 Q-1 R0\n"            // a wall facing -Y
    "N60 G40 G0 Z50\nN70 M2\n";

}  // namespace

TEST(G29, TipOfATorusCutterTouchingThePoint) {
    // R 5, end radius @ 2, tool along +Z.
    Prog p(kProgram, "mill", {{"D1.R", 5}, {"D1.A", 2}});
    ASSERT_EQ(p.in->run_to_end(), StepResult::ended)
        << (p.in->diags().empty() ? "" : p.in->diags()[0].detail);
    const auto& m = p.cap.moves;
    ASSERT_EQ(m.size(), 5u);
    EXPECT_NEAR(m[1].to_prog[X], 10, 1e-9);
    EXPECT_NEAR(m[1].to_prog[Z], 0, 1e-9);
    // N = (1, 0, 1)/sqrt2: Ct = Pc + 2N, w = (1, 0, 0), Oc = Ct + 3w, tip = Oc - 2u.
    double s = std::sqrt(0.5);
    EXPECT_NEAR(m[2].to_prog[X], 20 + 2 * s + 3, 1e-9);
    EXPECT_NEAR(m[2].to_prog[Z], 0 + 2 * s - 2, 1e-9);
    // N = (0, -1, 0): Ct = (30, 3, -1), w = N, Oc = (30, 0, -1), tip = (30, 0, -3).
    EXPECT_NEAR(m[3].to_prog[X], 30, 1e-9);
    EXPECT_NEAR(m[3].to_prog[Y], 5 - 2 - 3, 1e-9);
    EXPECT_NEAR(m[3].to_prog[Z], -1 - 2, 1e-9);
}

TEST(G29, ABallCutterStaysAtItsRadiusFromThePoint) {
    // A ball end mill (@ = R): the ball centre is on the normal at R, whatever N.
    Prog p(kProgram, "mill", {{"D1.R", 4}, {"D1.A", 4}});
    ASSERT_EQ(p.in->run_to_end(), StepResult::ended);
    const auto& m = p.cap.moves;
    const double pts[3][3] = {{10, 0, 0}, {20, 0, 0}, {30, 5, -1}};
    for (int i = 0; i < 3; ++i) {
        const Axes& t = m[size_t(i + 1)].to_prog;
        double cx = t[X], cy = t[Y], cz = t[Z] + 4;  // the ball's centre above the tip
        double d = std::sqrt(std::pow(cx - pts[i][0], 2) + std::pow(cy - pts[i][1], 2) +
                             std::pow(cz - pts[i][2], 2));
        EXPECT_NEAR(d, 4, 1e-3) << "block " << i;
    }
}

TEST(G29, ErrorsOfTheBlock) {
    Prog a("%1\nG0 X0 Y0 Z5\nG1 G29 X1 Y0 Z0 P0 Q0 F100\nM2\n", "mill");
    a.in->run_to_end();
    ASSERT_FALSE(a.in->diags().empty());
    EXPECT_EQ(a.in->diags()[0].code, 146);  // R missing
    Prog b("%1\nG0 X0 Y0 Z5\nG1 G29 X1 Y0 Z0 P.5 Q0 R.5 F100\nM2\n", "mill");
    b.in->run_to_end();
    ASSERT_FALSE(b.in->diags().empty());
    EXPECT_EQ(b.in->diags()[0].code, 145);  // not a unit vector
}
