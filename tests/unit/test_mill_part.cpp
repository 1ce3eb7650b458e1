// The machining centre's material against parts worked out by hand (issue
// 15): the cutters' shapes, slots, grooves, pockets and ramps measured by the
// instruments' lines, the height field, contacts with the material and the
// fixtures, the store's text. Unless said otherwise the stock is a block
// 100 x 60 x 30 from the machine's origin, at 0.1 mm cells.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/workshop/mill_part.hpp"

namespace pupitre::workshop {
namespace {

using Intervals = std::vector<std::array<double, 2>>;

Cutter cutter(double radius, double corner, double flute = 20, double reach = 40,
              double holder = 20) {
    Cutter c;
    c.radius = radius, c.corner = corner, c.flute = flute, c.reach = reach, c.holder = holder;
    return c;
}

MillWorld block() {
    return MillWorld(Box3{{0, 0, 0}, {100, 60, 30}}, 0.1);
}

void expect_intervals(const Intervals& got, const Intervals& want, double tol, const char* what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t k = 0; k < got.size(); ++k) {
        EXPECT_NEAR(got[k][0], want[k][0], tol) << what << " interval " << k;
        EXPECT_NEAR(got[k][1], want[k][1], tol) << what << " interval " << k;
    }
}

TEST(MillCutter, FlatBullAndBallEnds) {
    const Cutter flat = cutter(5, 0), bull = cutter(5, 1), ball = cutter(5, 5);
    EXPECT_EQ(flat.bottom(0), 0);
    EXPECT_EQ(flat.bottom(5), 0);
    EXPECT_EQ(flat.slice(0), 5);
    // Bull: the flat to 4, then a quarter circle of 1 about (4, 1):
    // bottom(4.6) = 1 - sqrt(1 - 0.6²) = 0.2; slice(0.2) = 4 + sqrt(0.2 * 1.8) = 4.6.
    EXPECT_EQ(bull.bottom(4), 0);
    EXPECT_NEAR(bull.bottom(4.6), 0.2, 1e-12);
    EXPECT_NEAR(bull.bottom(5), 1, 1e-12);
    EXPECT_NEAR(bull.slice(0), 4, 1e-12);
    EXPECT_NEAR(bull.slice(0.2), 4.6, 1e-12);
    EXPECT_EQ(bull.slice(1), 5);
    EXPECT_EQ(bull.slice(3), 5);
    // Ball of 5: bottom(3) = 5 - 4, bottom(4) = 5 - 3; slice(1) = sqrt(1 * 9), slice(2) = sqrt(2 *
    // 8).
    EXPECT_EQ(ball.bottom(0), 0);
    EXPECT_NEAR(ball.bottom(3), 1, 1e-12);
    EXPECT_NEAR(ball.bottom(4), 2, 1e-12);
    EXPECT_NEAR(ball.slice(1), 3, 1e-12);
    EXPECT_NEAR(ball.slice(2), 4, 1e-12);
    EXPECT_EQ(ball.slice(5), 5);
    EXPECT_EQ(ball.slice(7), 5);
}

TEST(MillPart, FlatSlotAlongX) {
    // Ø8 flat, 2 deep, along X at Y 30 right across: walls at 26 and 34, floor at 28.
    MillWorld w = block();
    EXPECT_EQ(w.nx(), 1000);
    EXPECT_EQ(w.ny(), 600);
    const uint64_t g = w.generation();
    const double v = w.cut(cutter(4, 0), {-10, 30, 28}, {110, 30, 28});
    EXPECT_GT(w.generation(), g);
    // 8 x 2 x 100 = 1600 mm³; the field's 80 rows (centres 26.05..33.95) of
    // 1000 cells lowered 2 make the same.
    EXPECT_NEAR(v, 1600, 1e-6);
    EXPECT_EQ(w.height(500, 259), 30.0f);  // centre Y 25.95
    EXPECT_EQ(w.height(500, 260), 28.0f);  // 26.05
    EXPECT_EQ(w.height(500, 339), 28.0f);  // 33.95
    EXPECT_EQ(w.height(500, 340), 30.0f);  // 34.05
    expect_intervals(w.along(1, {50, 30, 29}), {{0, 26}, {34, 60}}, 1e-6, "Y at mid-depth");
    expect_intervals(w.along(2, {50, 30, 0}), {{0, 28}}, 1e-9, "Z in the slot");
    expect_intervals(w.along(2, {50, 25.9, 0}), {{0, 30}}, 1e-9, "Z beside it");
    expect_intervals(w.along(0, {50, 30, 29}), {}, 1e-9, "X in the slot");
    expect_intervals(w.along(0, {50, 30, 27}), {{0, 100}}, 1e-9, "X under it");
    EXPECT_TRUE(w.along(0, {50, 70, 10}).empty());  // misses the block
}

TEST(MillPart, BallGroove) {
    // Ø10 ball, 3 deep (tip at 27) along X at Y 30: its width u above the
    // bottom is 2 sqrt(25 - (5 - u)²): 6 at u = 1, 2 sqrt(21) at u = 3.
    MillWorld w = block();
    const double v = w.cut(cutter(5, 5), {-10, 30, 27}, {110, 30, 27});
    expect_intervals(w.along(1, {50, 30, 28}), {{0, 27}, {33, 60}}, 1e-6, "u = 1");
    const double h = std::sqrt(21.0);
    expect_intervals(w.along(1, {50, 30, 30}), {{0, 30 - h}, {30 + h, 60}}, 1e-6, "u = 3");
    // Off the centre by 2 the floor is bottom(2) = 5 - sqrt(21) above the tip.
    expect_intervals(w.along(2, {50, 32, 0}), {{0, 32 - h}}, 1e-9, "Z off centre");
    // Cell centre Y 30.05: 27 + 5 - sqrt(25 - 0.05²).
    EXPECT_NEAR(w.height(500, 300), 32 - std::sqrt(25 - 0.0025), 1e-5);
    // The section is a circular segment of r 5 and height 3:
    // 25 acos(2/5) - 2 sqrt(21) = 19.81683 mm², over 100 mm. The field
    // samples it at 0.1 mm: within 0.2 % (the two edge cells).
    const double section = 25 * std::acos(0.4) - 2 * h;
    EXPECT_NEAR(v, section * 100, section * 100 * 2e-3);
}

TEST(MillPart, PocketOfLevelStrokes) {
    // Ø10 flat at Z 25 round the rectangle (20,20)-(60,40) and along its
    // middle: the pocket is [15, 65] x [15, 45] with corners of R 5.
    MillWorld w = block();
    const Cutter c = cutter(5, 0);
    const P3 p[] = {{20, 20, 25}, {60, 20, 25}, {60, 40, 25}, {20, 40, 25}, {20, 20, 25}};
    for (int k = 0; k < 4; ++k) w.cut(c, p[k], p[k + 1]);
    w.cut(c, {20, 30, 25}, {60, 30, 25});
    expect_intervals(w.along(0, {0, 30, 27}), {{0, 15}, {65, 100}}, 1e-6, "X");
    expect_intervals(w.along(1, {40, 0, 27}), {{0, 15}, {45, 60}}, 1e-6, "Y");
    // At Y 16, 4 from the corners' centres: sqrt(25 - 16) = 3 in from them.
    expect_intervals(w.along(0, {0, 16, 27}), {{0, 17}, {63, 100}}, 1e-6, "X by the corners");
    expect_intervals(w.along(2, {40, 35, 0}), {{0, 25}}, 1e-9, "Z");
}

TEST(MillPart, FlatRamp) {
    // Ø10 flat from (20, 30, 30) down to (50, 30, 27): 3 over 30. At X 35
    // the disc covers it for t in [1/3, 2/3] (tip X 30..40) and the floor is
    // where the tip left it, at 30 - 3 * 2/3 = 28 (not the tip's 28.5 over
    // it: the flat end still covers the point lower down the ramp).
    MillWorld w = block();
    w.cut(cutter(5, 0), {20, 30, 30}, {50, 30, 27});
    expect_intervals(w.along(2, {35, 30, 0}), {{0, 28}}, 1e-9, "Z middle");
    expect_intervals(w.along(2, {52, 30, 0}), {{0, 27}}, 1e-9, "Z past the end");
    // At X 18 the disc covers it while the tip is within 20..23: t <= 0.1.
    expect_intervals(w.along(2, {18, 30, 0}), {{0, 29.7}}, 1e-9, "Z before the start");
    // At Z 29 the cutter is below for t >= 1/3: the stadium of R 5 about
    // (30, 30)-(50, 30). Along X: [25, 55]. Along Y at X 27, 3 from (30, 30):
    // half width sqrt(25 - 9) = 4.
    expect_intervals(w.along(0, {0, 30, 29}), {{0, 25}, {55, 100}}, 1e-6, "X at 29");
    expect_intervals(w.along(1, {27, 0, 29}), {{0, 26}, {34, 60}}, 1e-6, "Y at 29");
}

// The lowest of a stroke's cutter at (x, y), sampled over 200,001 places.
double brute_lowest(const Cutter& c, const P3& a, const P3& b, double x, double y) {
    double best = 1e9;
    for (int n = 0; n <= 200000; ++n) {
        const double t = n / 200000.0;
        const double d = std::hypot(x - a[0] - t * (b[0] - a[0]), y - a[1] - t * (b[1] - a[1]));
        if (d <= c.radius) best = std::min(best, a[2] + t * (b[2] - a[2]) + c.bottom(d));
    }
    return best;
}

TEST(MillPart, InclinedBallAndBullAgreeWithSampling) {
    // Inclined strokes of a ball and a bull end: the floor (along Z) against
    // a dense sampling of the stroke, and the ends of a line along X at a
    // height: the floor there is that height (two searches, one answer).
    for (const Cutter& c : {cutter(5, 5), cutter(5, 2)}) {
        MillWorld w = block();
        const P3 a{30, 20, 28}, b{60, 35, 24};
        w.cut(c, a, b);
        for (const auto& q : {std::array<double, 2>{45, 27.5}, {47, 26}, {33, 23}, {62, 33}}) {
            auto z = w.along(2, {q[0], q[1], 0});
            ASSERT_EQ(z.size(), 1u);
            EXPECT_NEAR(z[0][1], brute_lowest(c, a, b, q[0], q[1]), 2e-4) << q[0] << " " << q[1];
        }
        for (double y : {29.0, 31.0, 33.0}) {
            // Just inside an end the floor is at or below the line, just
            // outside above it (the bull's side is upright there).
            const double z0 = 26.5;
            auto x = w.along(0, {0, y, z0});
            ASSERT_EQ(x.size(), 2u) << y;
            auto floor = [&](double e) { return w.along(2, {e, y, 0}).back()[1]; };
            EXPECT_LE(floor(x[0][1] + 1e-7), z0 + 1e-5) << y;
            EXPECT_GE(floor(x[0][1] - 1e-7), z0 - 1e-5) << y;
            EXPECT_LE(floor(x[1][0] - 1e-7), z0 + 1e-5) << y;
            EXPECT_GE(floor(x[1][0] + 1e-7), z0 - 1e-5) << y;
            if (c.corner == c.radius) {
                EXPECT_NEAR(floor(x[0][1] + 1e-7), z0, 1e-5);
            }
        }
    }
}

TEST(MillPart, HeightFieldIsTheFloorAtTheCentres) {
    // Random strokes of every kind: each cell's height is what the exact
    // line along Z reads at its centre (the index finds every stroke).
    MillWorld w = block();
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> x(-5, 105), y(-5, 65), z(20, 31), r(1, 6), f(0, 1);
    for (int k = 0; k < 60; ++k) {
        const double rad = r(rng);
        const double corner = k % 3 == 0 ? 0 : k % 3 == 1 ? rad : rad * f(rng);
        P3 a{x(rng), y(rng), z(rng)}, b{x(rng), y(rng), k % 4 == 0 ? a[2] : z(rng)};
        w.cut(cutter(rad, corner), a, b);
    }
    for (int n = 0; n < 400; ++n) {
        const int i = int(f(rng) * w.nx()), j = int(f(rng) * w.ny());
        const double cx = (i + 0.5) * 0.1, cy = (j + 0.5) * 0.1;
        auto col = w.along(2, {cx, cy, 0});
        const double top = col.empty() ? 0 : col.back()[1];
        EXPECT_NEAR(w.height(i, j), top, 2e-5) << i << " " << j;
    }
}

TEST(MillContact, DescendOntoTheTop) {
    // From 10 above the top (Z 40) down to Z 20: contact after 10 of 20.
    for (double corner : {0.0, 5.0}) {
        MillWorld w = block();
        const Cutter c = cutter(5, corner);
        const double f = w.first_contact(c, {50, 30, 40}, {50, 30, 20}, Part::flute, 0);
        EXPECT_NEAR(f * 20, 10, 1e-4) << corner;
        const double g = w.first_contact(c, {50, 30, 40}, {50, 30, 20}, Part::flute, 0, true);
        EXPECT_LE(g, f);
        EXPECT_NEAR(g * 20, 10, 1e-4);
        EXPECT_EQ(w.depth_into(c, {50, 30, 30}, Part::flute), 0);
        EXPECT_NEAR(w.depth_into(c, {50, 30, 29.7}, Part::flute), 0.3, 1e-9);
        // Clear above it, and past it in the air.
        EXPECT_EQ(w.first_contact(c, {-20, 30, 31}, {120, 30, 31}, Part::flute, 0), 2);
    }
}

TEST(MillContact, ApproachTheSide) {
    // Along X at Z 20 from X -30 into the face X 0: contact when the axis is
    // 5 from it, at X -5: after 25 of 50.
    MillWorld w = block();
    const Cutter c = cutter(5, 0);
    const double f = w.first_contact(c, {-30, 30, 20}, {20, 30, 20}, Part::flute, 0);
    EXPECT_NEAR(f * 50, 25, 1e-4);
    EXPECT_EQ(w.depth_into(c, {-5, 30, 20}, Part::flute), 0);
    EXPECT_NEAR(w.depth_into(c, {-4.7, 30, 20}, Part::flute), 0.3, 1e-9);
    // Allowed 0.3 in: contact 0.3 later.
    const double g = w.first_contact(c, {-30, 30, 20}, {20, 30, 20}, Part::flute, 0.3);
    EXPECT_NEAR(g * 50, 25.3, 1e-4);
}

TEST(MillContact, ThinWallOnALongMove) {
    // A slot Ø10 at Y 30, Z 25, in two pieces that leave a wall from X 49.82
    // to 50.18; a Ø4 cutter moving 80 along it at Z 27 meets the wall when
    // its axis is at 47.82 (37.82 from X 10). The wall's cells are the
    // stock's own squares from 49.8: the field finds it half a cell early.
    MillWorld w = block();
    w.cut(cutter(5, 0), {-10, 30, 25}, {44.82, 30, 25});
    w.cut(cutter(5, 0), {55.18, 30, 25}, {110, 30, 25});
    const Cutter c = cutter(2, 0);
    const double f = w.first_contact(c, {10, 30, 27}, {90, 30, 27}, Part::flute, 0);
    EXPECT_NEAR(f * 80, 37.82, 0.05);
    // The instrument reads the wall exactly.
    expect_intervals(w.along(0, {0, 30, 27}), {{49.82, 50.18}}, 1e-6, "the wall");
}

TEST(MillContact, ShankAboveTheFlute) {
    // A Ø10 with 5 of flute, tip at Z 22 in the fresh block: the flute is
    // in by its radius (5 < 8 of height), the shank by 30 - 27 = 3; the
    // holder (40 above the tip) is clear.
    MillWorld w = block();
    const Cutter c = cutter(5, 0, 5);
    EXPECT_NEAR(w.depth_into(c, {50, 30, 22}, Part::flute), 5, 1e-9);
    EXPECT_NEAR(w.depth_into(c, {50, 30, 22}, Part::shank), 3, 1e-9);
    EXPECT_EQ(w.depth_into(c, {50, 30, 22}, Part::holder), 0);
    // Coming down from Z 40 the shank meets the top when the tip is at 25.
    const double f = w.first_contact(c, {50, 30, 40}, {50, 30, 10}, Part::shank, 0);
    EXPECT_NEAR(f * 30, 15, 1e-4);
    // The holder (20 of radius, 40 above the tip) at a tip 12 below the top.
    EXPECT_NEAR(w.depth_into(c, {50, 30, -12}, Part::holder), 2, 1e-9);
}

TEST(MillContact, Fixtures) {
    // A vice jaw Y -20..0, Z 0..40 and a pin of R 3 at (80, 30), Z 0..10.
    const Box3 jaw{{0, -20, 0}, {100, 0, 40}};
    const Cylinder pin{80, 30, 3, 0, 10};
    const Cutter flat = cutter(5, 0), ball = cutter(5, 5);
    EXPECT_NEAR(depth_into(flat, {50, 4.7, 20}, Part::flute, jaw), 0.3, 1e-9);
    EXPECT_EQ(depth_into(flat, {50, 5, 20}, Part::flute, jaw), 0);
    // Over the jaw, 10 from its nearest side: 0.5 down, 15 across.
    EXPECT_NEAR(depth_into(flat, {50, -10, 39.5}, Part::flute, jaw), 0.5, 1e-9);
    EXPECT_EQ(depth_into(flat, {50, -10, 40}, Part::flute, jaw), 0);
    // A ball 3 off the edge, tip at 38: its surface there is 1 above the tip
    // (v = 1); at the jaw's top, 2 above the tip, its section is 4 (w = 1).
    EXPECT_NEAR(depth_into(ball, {50, 3, 38}, Part::flute, jaw), 1, 1e-9);
    // The holder (R 20, 40 up) 15 from the jaw: touches at tip Z 0, in by 1 at -1.
    EXPECT_EQ(depth_into(flat, {50, 15, 0}, Part::holder, jaw), 0);
    EXPECT_NEAR(depth_into(flat, {50, 15, -1}, Part::holder, jaw), 1, 1e-9);
    EXPECT_EQ(depth_into(flat, {50, 15, -1}, Part::flute, jaw), 0);
    // The pin: beside it 0.3 in, on its top 0.5 in (w = 5 + 3).
    EXPECT_NEAR(depth_into(flat, {87.7, 30, 5}, Part::flute, pin), 0.3, 1e-9);
    EXPECT_EQ(depth_into(flat, {88, 30, 5}, Part::flute, pin), 0);
    EXPECT_NEAR(depth_into(flat, {80, 30, 9.5}, Part::flute, pin), 0.5, 1e-9);
    // The first contact is where the depth leaves 0: exact, so a µm past
    // the touching place is a µm deep.
    EXPECT_NEAR(depth_into(flat, {50, 5 - 1e-3, 20}, Part::flute, jaw), 1e-3, 1e-9);
    EXPECT_NEAR(depth_into(flat, {88 - 1e-3, 30, 5}, Part::flute, pin), 1e-3, 1e-9);
    EXPECT_NEAR(depth_into(ball, {80, 30, 10 - 1e-3}, Part::flute, pin), 1e-3, 1e-9);
}

TEST(MillPart, TextRoundTrip) {
    MillWorld w = block();
    w.cut(cutter(4, 0), {-10, 30, 28}, {110, 30, 28});
    w.cut(cutter(5, 5), {20, 10, 29}, {70, 50, 26.5});
    w.cut(cutter(3, 1), {80, 10, 31}, {80, 10, 20});
    w.cut(cutter(3, 1), {-40, 10, 20}, {-30, 10, 20});  // far from the block: not kept
    const std::string text = w.to_text();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
    MillWorld r = block();
    ASSERT_TRUE(r.from_text(text));
    EXPECT_EQ(r.to_text(), text);
    for (int j = 0; j < w.ny(); ++j)
        for (int i = 0; i < w.nx(); ++i) ASSERT_EQ(r.height(i, j), w.height(i, j)) << i << " " << j;
    EXPECT_EQ(r.along(1, {45, 0, 28.5}), w.along(1, {45, 0, 28.5}));
}

TEST(MillPart, BadTextChangesNothing) {
    MillWorld w = block();
    w.cut(cutter(4, 0), {-10, 30, 28}, {110, 30, 28});
    const std::string before = w.to_text();
    const uint64_t g = w.generation();
    const float h = w.height(500, 300);
    for (const char* bad :
         {"1 2 3\n", "1 2 3 4 5 6 7 8 9\n", "1 2 3 4 5 6 -4 0\n", "1 2 3 4 5 6 0 0\n",
          "1 2 3 4 5 6 4 5\n", "1 2 3 4 5 6 4 -1\n", "1 2 3 4 5 6 4 x\n", "nan 2 3 4 5 6 4 0\n",
          "1 2 inf 4 5 6 4 0\n", "0 0 0 1 1 1 4 0\n1 2 3 4 5 6 4 0 junk\n"}) {
        EXPECT_FALSE(w.from_text(bad)) << bad;
        EXPECT_EQ(w.to_text(), before);
        EXPECT_EQ(w.generation(), g);
        EXPECT_EQ(w.height(500, 300), h);
    }
    // Too many lines: refused before anything is read.
    EXPECT_FALSE(w.from_text(std::string(5'000'001, '\n')));
    EXPECT_EQ(w.generation(), g);
    // Blank lines are nothing; an empty text is fresh stock.
    ASSERT_TRUE(w.from_text("\n\n"));
    EXPECT_EQ(w.to_text(), "");
    EXPECT_EQ(w.height(500, 300), 30.0f);
}

}  // namespace
}  // namespace pupitre::workshop
