// A tilted cutter in the machining centre's material (issue 15): the line
// through the volume a tilted cutter sweeps, against a membership test in
// closed form; cuts from the side that leave material above (a slot in a
// face), a chamfer cut with the end of a cutter at 45°, a tilted ball end,
// the store's text, and the first contact of a tilted end with the top.
// Values worked out by hand in the comments.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/workshop/mill_part.hpp"
#include "core/workshop/narrow.hpp"
#include "core/workshop/tilt.hpp"

namespace pupitre::workshop {
namespace {

using tilt::Line;
using tilt::Span;

// Whether p is in the volume a flat end (radius r, axis u) sweeps, its tip
// going from a to a + d: the t of [0, 1] with p above the end (t m <= h)
// and within r of the axis (a quadratic in t) meet.
bool in_swept_flat(const P3& p, const P3& a, const P3& d, const P3& u, double r) {
    const P3 w = tilt::sub(p, a);
    const double h = tilt::dot(w, u), m = tilt::dot(d, u);
    const P3 pw = tilt::sub(w, tilt::mul(u, h)), pd = tilt::sub(d, tilt::mul(u, m));
    double t0 = 0, t1 = 1;
    if (m > 0) t1 = std::min(t1, h / m);
    if (m < 0) t0 = std::max(t0, h / m);
    if (m == 0 && h < 0) return false;
    if (t0 > t1) return false;
    // |pw - t pd|² <= r²: its minimum over [t0, t1].
    const double dd = tilt::dot(pd, pd);
    const double t = dd > 0 ? std::clamp(tilt::dot(pw, pd) / dd, t0, t1) : t0;
    const P3 e = tilt::sub(pw, tilt::mul(pd, t));
    return tilt::dot(e, e) <= r * r;
}

P3 unit(P3 v) {
    return tilt::mul(v, 1 / std::sqrt(tilt::dot(v, v)));
}

// A line's interval through a flat end's sweep against the membership
// test: when empty, nothing of the line within `reach` of its origin is in
// the sweep; else just outside each finite end is out and just inside in
// (an end without end: 1 mm along). Whether the line crossed it.
bool check_flat(const Span& sp, const P3& a, const P3& d, const P3& u, double r, const Line& l,
                double reach, const std::string& what) {
    auto in = [&](double s) {
        return in_swept_flat(tilt::add(l.o, tilt::mul(l.e, s)), a, d, u, r);
    };
    if (sp.empty()) {
        for (double s = -reach; s <= reach; s += 0.02) {
            if (!in(s)) continue;
            ADD_FAILURE() << what << ": in the sweep at s " << s << ", the line missing it";
            break;
        }
        return false;
    }
    constexpr double e = 1e-6;
    if (std::isfinite(sp.lo)) {
        EXPECT_FALSE(in(sp.lo - e)) << what;
    }
    if (std::isfinite(sp.hi)) {
        EXPECT_FALSE(in(sp.hi + e)) << what;
    }
    const double lo = std::isfinite(sp.lo) ? sp.lo : sp.hi - 1;
    const double hi = std::isfinite(sp.hi) ? sp.hi : sp.lo + 1;
    if (hi - lo > 4 * e) {
        EXPECT_TRUE(in(lo + e)) << what;
        EXPECT_TRUE(in(hi - e)) << what;
    }
    return true;
}

TEST(TiltGeometry, SweptFlatMatchesMembership) {
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> c(-10, 10), tiltang(0, 1.6), rad(0.5, 6);
    int crossed = 0;
    for (int n = 0; n < 3000; ++n) {
        const double b = tiltang(rng), az = c(rng);
        const P3 u{std::sin(b) * std::cos(az), std::sin(b) * std::sin(az), std::cos(b)};
        const P3 a{c(rng), c(rng), c(rng)}, d{c(rng), c(rng), n % 7 == 0 ? 0 : c(rng)};
        const double r = rad(rng);
        Line l;
        l.o = {c(rng), c(rng), c(rng)};
        l.e = n % 3 == 0 ? P3{0, 0, 1} : unit({c(rng), c(rng), c(rng)});
        crossed += check_flat(tilt::swept_flat(a, d, u, r, l), a, d, u, r, l, 60,
                              "case " + std::to_string(n));
    }
    EXPECT_GT(crossed, 500);
}

// The cases a workshop meets all the time, where the closed form's lines
// and ellipse degenerate: the axis in the XZ plane (B alone) or square to
// it, moves along an axis, lines along the axes.
TEST(TiltGeometry, SweptFlatOnTheAxes) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> c(-8, 8);
    const double tilts[] = {0.3, 0.5, M_PI / 4, 1.2, M_PI / 2, 2.0};
    const P3 dirs[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 0}, {0, 0, 0}};
    int crossed = 0;
    for (double b : tilts)
        for (int turn = 0; turn < 2; ++turn)
            for (const P3& dir : dirs)
                for (int axis = 0; axis < 3; ++axis)
                    for (int n = 0; n < 40; ++n) {
                        const P3 u = turn ? P3{0, std::sin(b), std::cos(b)}
                                          : P3{std::sin(b), 0, std::cos(b)};
                        const P3 a{c(rng), c(rng), c(rng)}, d = tilt::mul(dir, c(rng));
                        const double r = 5;
                        Line l;
                        l.o = {c(rng), c(rng), c(rng)};
                        l.e = {0, 0, 0};
                        l.e[size_t(axis)] = 1;
                        crossed +=
                            check_flat(tilt::swept_flat(a, d, u, r, l), a, d, u, r, l, 40,
                                       "tilt " + std::to_string(b) + " case " + std::to_string(n));
                    }
    EXPECT_GT(crossed, 1000);
}

// Whether p is in the volume a bull nose (radius r, corner c, axis u)
// sweeps, its tip from a to a + d: within c of the flat cylinder of radius
// r - c that starts c up the axis, for some t (the distance is convex in t).
double bull_gap(const P3& p, const P3& a, const P3& d, const P3& u, double r, double c) {
    auto dist = [&](double t) {
        const P3 q = tilt::sub(p, tilt::add(a, tilt::mul(d, t)));
        const double h = tilt::dot(q, u) - c;
        const P3 side = tilt::sub(q, tilt::mul(u, tilt::dot(q, u)));
        const double e = std::sqrt(tilt::dot(side, side)) - (r - c);
        if (h >= 0) return std::max(0.0, e);
        return e <= 0 ? -h : std::hypot(h, e);
    };
    return golden_min(dist, 0, 1, 1e-12).second - c;
}

bool in_swept_bull(const P3& p, const P3& a, const P3& d, const P3& u, double r, double c) {
    return bull_gap(p, a, d, u, r, c) <= 0;
}

// The ring of balls stands for the torus within 0.5 µm (or what 256 balls
// give): the line's ends are that close inside the surface (along a line
// that meets it at a slant, a few µm: 2 µm each way is checked by
// membership). Standing still, the corner is exact.
TEST(TiltGeometry, SweptBullNoseMatchesMembership) {
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> c(-10, 10), tiltang(0, 1.6), rad(1, 6), frac(0.2, 0.8);
    int crossed = 0;
    for (int n = 0; n < 300; ++n) {
        const double b = tiltang(rng), az = c(rng);
        const P3 u{std::sin(b) * std::cos(az), std::sin(b) * std::sin(az), std::cos(b)};
        const P3 a{c(rng) / 2, c(rng) / 2, c(rng) / 2}, d{c(rng), c(rng), c(rng)};
        const double r = rad(rng), k = r * frac(rng);
        Line l;
        l.o = {c(rng), c(rng), c(rng)};
        l.e = n % 2 ? P3{0, 0, 1} : unit({c(rng), c(rng), c(rng)});
        const Span sp = tilt::swept_cutter(r, k, a, d, u, l);
        if (sp.empty()) continue;
        ++crossed;
        auto at = [&](double s) { return tilt::add(l.o, tilt::mul(l.e, s)); };
        constexpr double e = 2e-3;
        for (double end : {sp.lo, sp.hi}) {
            if (!std::isfinite(end)) continue;
            const double gap = bull_gap(at(end), a, d, u, r, k);
            EXPECT_LE(gap, 1e-6) << n;
            // 256 balls at most: (pi / 256)² inner r / (2 c) short at worst.
            const double x = M_PI / tilt::kRing;
            EXPECT_GE(gap, -std::max(5e-4, x * x * (r - k) * r / (2 * k)) - 1e-7) << n;
        }
        if (std::isfinite(sp.lo)) {
            EXPECT_FALSE(in_swept_bull(at(sp.lo - e), a, d, u, r, k)) << n;
        }
        if (std::isfinite(sp.hi)) {
            EXPECT_FALSE(in_swept_bull(at(sp.hi + e), a, d, u, r, k)) << n;
        }
        if (sp.hi - sp.lo > 4 * e) {
            EXPECT_TRUE(in_swept_bull(at(sp.lo + e), a, d, u, r, k)) << n;
            EXPECT_TRUE(in_swept_bull(at(sp.hi - e), a, d, u, r, k)) << n;
        }
    }
    EXPECT_GT(crossed, 50);
    // Standing still (d = 0): the ends are on the surface, to 1e-8.
    int still = 0;
    for (int n = 0; n < 300; ++n) {
        const double b = tiltang(rng), az = c(rng);
        const P3 u{std::sin(b) * std::cos(az), std::sin(b) * std::sin(az), std::cos(b)};
        const P3 a{c(rng) / 2, c(rng) / 2, c(rng) / 2}, d{0, 0, 0};
        const double r = rad(rng), k = r * frac(rng);
        Line l;
        l.o = {c(rng) / 2, c(rng) / 2, c(rng) / 2};
        l.e = n % 2 ? P3{0, 0, 1} : unit({c(rng), c(rng), c(rng)});
        const Span sp = tilt::swept_cutter(r, k, a, d, u, l);
        if (sp.empty()) continue;
        ++still;
        for (double end : {sp.lo, sp.hi}) {
            if (!std::isfinite(end)) continue;
            EXPECT_NEAR(bull_gap(tilt::add(l.o, tilt::mul(l.e, end)), a, d, u, r, k), 0, 1e-8) << n;
        }
    }
    EXPECT_GT(still, 50);
}

// The stock of these tests: 100 x 100 x 50 from the origin, cells of 0.1.
MillWorld block() {
    return MillWorld(Box3{{0, 0, 0}, {100, 100, 50}}, 0.1);
}

Cutter flat(double r) {
    Cutter c;
    c.radius = r;
    c.corner = 0;
    c.flute = 30;
    c.reach = 45;
    c.holder = 16;
    return c;
}

void expect_spans(const std::vector<std::array<double, 2>>& got,
                  const std::vector<std::array<double, 2>>& want, double tol = 1e-6) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t k = 0; k < got.size(); ++k) {
        EXPECT_NEAR(got[k][0], want[k][0], tol) << k;
        EXPECT_NEAR(got[k][1], want[k][1], tol) << k;
    }
}

// B90: a Ø10 end mill lying along +X, its end 2 mm inside the +X face at
// Z30, fed along Y across the block: a slot 2 deep from Z25 to Z35 in the
// face, the material above it kept.
TEST(MillTilt, SideSlotKeepsTheMaterialAbove) {
    MillWorld w = block();
    const double v = w.cut(flat(5), {98, -10, 30}, {98, 110, 30}, {1, 0, 0});
    EXPECT_NEAR(v, 2 * 10 * 100, 2 * 100 * 0.1 + 1);  // to the cells
    expect_spans(w.along(2, {99, 50, 0}), {{0, 25}, {35, 50}});
    expect_spans(w.along(0, {0, 50, 30}), {{0, 98}});
    expect_spans(w.along(0, {0, 50, 36}), {{0, 100}});
    // The height field keeps the top; the column keeps both pieces.
    const int i = 990, j = 500;  // the cell whose centre is X99.05 Y50.05
    EXPECT_FLOAT_EQ(w.height(i, j), 50);
    std::vector<std::array<double, 2>> col;
    w.material(i, j, col);
    expect_spans(col, {{0, 25}, {35, 50}});
    // A vertical Ø2 cutter (its flute 5 long) standing in the slot, its tip
    // at Z27: the flute is in the void, its shank in the material above.
    Cutter small = flat(1);
    small.flute = 5;
    EXPECT_EQ(w.depth_into(small, {99.05, 50.05, 27}, Part::flute), 0);
    EXPECT_GT(w.depth_into(small, {99.05, 50.05, 27}, Part::shank), 0.5);
    // Plunged there to Z20 it takes the top piece and the top of the lower one.
    w.cut(small, {99.05, 50.05, 60}, {99.05, 50.05, 20});
    w.material(i, j, col);
    expect_spans(col, {{0, 20}});
    EXPECT_FLOAT_EQ(w.height(i, j), 20);
    expect_spans(w.along(2, {99, 50, 0}), {{0, 20}});
}

// B45: the end of a Ø10 end mill square to (1, 0, 1)/√2, its centre at X99
// Z49, fed along Y: the plane X + Z = 148 cuts a 2 x 2 chamfer off the edge
// of the +X face and the top (every point of it within 1.42 of the axis).
TEST(MillTilt, ChamferWithTheEnd) {
    MillWorld w = block();
    const double s = std::sqrt(0.5);
    w.cut(flat(5), {99, -10, 49}, {99, 110, 49}, {s, 0, s});
    for (double x : {98.2, 98.75, 99.5, 99.9}) {
        const auto z = w.along(2, {x, 40, 0});
        ASSERT_EQ(z.size(), 1u) << x;
        EXPECT_NEAR(z[0][1], 148 - x, 1e-6) << x;
    }
    expect_spans(w.along(2, {97.9, 40, 0}), {{0, 50}});
    expect_spans(w.along(0, {0, 40, 49}), {{0, 99}});
    // The height field at a cell's centre: X99.05 -> 48.95.
    EXPECT_NEAR(w.height(990, 400), 48.95, 1e-4);
}

// A Ø6 ball end leaning 30° towards +X, its tip at X50 Z45, fed along Y:
// the ball's centre is 3 up the axis, at X51.5 Z47.598; under it the
// groove's bottom is 3 lower, Z44.598.
TEST(MillTilt, TiltedBallEnd) {
    MillWorld w = block();
    Cutter ball = flat(3);
    ball.corner = 3;
    const double b = 30 * M_PI / 180;
    w.cut(ball, {50, 20, 45}, {50, 80, 45}, {std::sin(b), 0, std::cos(b)});
    const double cz = 45 + 3 * std::cos(b), cx = 50 + 3 * std::sin(b);
    const auto z = w.along(2, {cx, 50, 0});
    ASSERT_EQ(z.size(), 1u);
    EXPECT_NEAR(z[0][1], cz - 3, 1e-6);
    // Beside the centre, on the ball: sqrt(9 - 1) below the centre.
    EXPECT_NEAR(w.along(2, {cx + 1, 50, 0})[0][1], cz - std::sqrt(8.0), 1e-6);
}

// Pointing up (B150: the axis (sin 150°, 0, cos 150°), the body going down
// towards +X), the cutter takes what its sweep holds, below its tip too: a
// line along X reads the material as the membership test says.
TEST(MillTilt, PointingUpCutsBelowTheTip) {
    MillWorld w = block();
    const double b = 150 * M_PI / 180;
    const P3 u{std::sin(b), 0, std::cos(b)}, a{97, 20, 30}, c{97, 80, 30};
    w.cut(flat(5), a, c, u);
    int cut = 0;
    for (double z = 10; z <= 40; z += 0.5) {
        bool solid = false;
        for (const auto& s : w.along(0, {0, 50, z}))
            solid = solid || (s[0] <= 99.5 && s[1] >= 99.5);
        const bool taken = in_swept_flat({99.5, 50, z}, a, tilt::sub(c, a), u, 5);
        EXPECT_NE(solid, taken) << z;
        cut += taken;
    }
    EXPECT_GT(cut, 4);
}

// The store's text keeps the axis: read back, the part is the same.
TEST(MillTilt, TextRoundTrip) {
    MillWorld w = block();
    const double s = std::sqrt(0.5);
    w.cut(flat(5), {98, -10, 30}, {98, 110, 30}, {1, 0, 0});
    w.cut(flat(5), {99, -10, 49}, {99, 110, 49}, {s, 0, s});
    w.cut(flat(2), {20, 20, 60}, {20, 20, 40});
    // An axis whose last digit a second rounding to a unit vector would move.
    const double b = -33.2 * M_PI / 180;
    w.cut(flat(3), {10, -10, 45}, {10, 110, 45}, {std::sin(b), 0, std::cos(b)});
    const std::string text = w.to_text();
    MillWorld v = block();
    ASSERT_TRUE(v.from_text(text));
    EXPECT_EQ(v.to_text(), text);
    for (int j = 0; j < v.ny(); j += 7)
        for (int i = 0; i < v.nx(); i += 7)
            ASSERT_EQ(v.height(i, j), w.height(i, j)) << i << ' ' << j;
    expect_spans(v.along(2, {99, 50, 0}), {{0, 25}, {35, 49}});
    // Nine numbers are not a stroke.
    EXPECT_FALSE(v.from_text("1 2 3 4 5 6 7 0 1\n"));
}

// A Ø10 end mill leaning 30° towards +X comes down on the top: its rim's
// lowest point, r (cos 30°, 0, -sin 30°) from the tip, meets Z50 when the
// tip is at Z52.5. The tip is placed so that point is over a cell's centre.
TEST(MillTilt, FirstContactOfTheRim) {
    MillWorld w = block();
    const double b = 30 * M_PI / 180;
    const P3 u{std::sin(b), 0, std::cos(b)};
    const double x = 50.05 - 5 * std::cos(b);
    const P3 a{x, 50.05, 60}, c{x, 50.05, 40};
    const double f = w.first_contact(flat(5), a, c, Part::flute, 1e-4, true, u);
    ASSERT_LE(f, 1);
    EXPECT_NEAR(60 - 20 * f, 52.5, 1e-4);
    // Upright, the same cutter meets the top with its whole end at Z50.
    const double g = w.first_contact(flat(5), a, c, Part::flute, 1e-4, true);
    EXPECT_NEAR(60 - 20 * g, 50, 1e-4);
    // Beside the block, clear of it all the way down to Z40.
    EXPECT_GT(w.first_contact(flat(5), {120, 50, 60}, {120, 50, 40}, Part::flute, 1e-4, true, u),
              1);
}

}  // namespace
}  // namespace pupitre::workshop
