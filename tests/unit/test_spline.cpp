// Splines G48/G06/G49: the curve goes through every point, leaves along the start
// tangent, and the errors 600-605 (pupitre-iso(5), SPLINES).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/spline.hpp"
#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

TEST(Spline, ThroughThePointsAlongTheStartTangent) {
    spline::Curve c;
    c.axes = {X, Y};
    c.t0 = {-1, 0};
    c.pts = {{-13, 10}, {-50, 70}, {-78, 75}, {-104, 55}, {-140, 0}};
    c.t1 = {0, -1};
    Error err = spline::build(c);
    ASSERT_FALSE(err) << err.detail;
    for (size_t i = 0; i < c.pts.size(); ++i) {
        auto p = spline::at(c, c.s[i]);
        EXPECT_NEAR(p[0], c.pts[i][0], 1e-9);
        EXPECT_NEAR(p[1], c.pts[i][1], 1e-9);
    }
    // Clamped ends: the curve leaves D along -X and arrives at H along -Y.
    auto a = spline::at(c, 0), b = spline::at(c, 1e-4);
    EXPECT_NEAR((b[1] - a[1]) / (b[0] - a[0]), 0, 1e-3);
    auto e = spline::at(c, c.s.back()), f = spline::at(c, c.s.back() - 1e-4);
    EXPECT_NEAR((e[0] - f[0]) / (e[1] - f[1]), 0, 1e-3);
    // Sampled within the tolerance of the curve.
    auto pts = spline::sample(c, 0.002);
    EXPECT_NEAR(pts.back()[0], -140, 1e-12);
    EXPECT_GT(pts.size(), 20u);
}

TEST(Spline, RunFromTheProgram) {
    Prog r(
        "%1\nG0 X-13 Y10 Z0\nG1 F500\nG79 N100\nN10 X-1 Y0\nX-13 Y10\nX-50 Y70\nX-78 Y75\nX-104 "
        "Y55\n"
        "X-140 Y0\nN20 X0 Y-1\nN100 G48 NC1 N10 N20\nG06 NC1\nG49 NC1\nM2\n");
    ASSERT_EQ(r.error(), 0);
    ASSERT_FALSE(r.cap.moves.empty());
    EXPECT_NEAR(r.cap.moves.back().to_prog[X], -140, 1e-9);
    EXPECT_NEAR(r.cap.moves.back().to_prog[Y], 0, 1e-9);
}

TEST(Spline, Errors) {
    const std::string pts = "G79 N100\nN10 X1 Y0\nX0 Y0\nX10 Y5\nX20 Y0\nN20\n";
    EXPECT_EQ(Prog("%1\n" + pts + "N100 G48 NC0 N10 N20\nM2\n").error(), 600);
    EXPECT_EQ(Prog("%1\n" + pts + "N100 G48 NC1\nM2\n").error(), 601);
    EXPECT_EQ(
        Prog("%1\nG79 N100\nN10\nX0 Y0\nX10 Y5\nX20 Y0\nN20\nN100 G48 NC1 N10 N20\nM2\n").error(),
        602);
    EXPECT_EQ(Prog("%1\nG79 N100\nN10 X1 Y0\nX0 Y0\nX0 Y0\nX20 Y0\nN20\nN100 G48 NC1 N10 N20\nM2\n")
                  .error(),
              603);
    EXPECT_EQ(
        Prog("%1\nG79 N100\nN10 X1 Y0\nX0 Y0\nX10 Y5\nN20\nN100 G48 NC1 N10 N20\nM2\n").error(),
        604);
    EXPECT_EQ(Prog("%1\nG06 NC7\nM2\n").error(), 605);
    EXPECT_EQ(Prog("%1\n" + pts + "N100 G48 NC1 N10 N20\nG49 NC1\nG06 NC1\nM2\n").error(), 605);
}
