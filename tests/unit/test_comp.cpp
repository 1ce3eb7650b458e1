// Radius compensation properties: every compensated element lies at exactly R
// from its programmed element (1 µm) and no point of the tool path comes closer
// than R to the programmed profile (no gouge), on random convex and star-shaped
// (concave) polygons, and on arcs; plus the joints of the seed's rules.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "helpers.hpp"

using namespace pupitre;
using test::Prog;

namespace {
struct Seg {
    double x0, y0, x1, y1;
};

double dist_to_seg(double px, double py, const Seg& s) {
    double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - s.x0) * dx + (py - s.y0) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (s.x0 + t * dx), py - (s.y0 + t * dy));
}

std::string f3(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return b;
}

// Points of a move of the trace (lines and arcs), sampled.
std::vector<std::pair<double, double>> samples(const MoveEvent& m, double fx, double fy) {
    std::vector<std::pair<double, double>> out;
    for (int i = 0; i <= 20; ++i) {
        double f = i / 20.0;
        if (m.g == 2 || m.g == 3) {
            double a0 = std::atan2(fy - m.c1, fx - m.c0), r = std::hypot(fx - m.c0, fy - m.c1);
            double a = a0 + m.sweep * M_PI / 180 * f;
            out.push_back({m.c0 + r * std::cos(a), m.c1 + r * std::sin(a)});
        } else {
            out.push_back({fx + (m.to_prog[X] - fx) * f, fy + (m.to_prog[Y] - fy) * f});
        }
    }
    return out;
}

// Runs a closed polygon (counter-clockwise points) with G41 or G42 and checks it.
void check_polygon(const std::vector<std::pair<double, double>>& pts, int g, double r) {
    std::string prog =
        "%1\nG0 X" + f3(pts[0].first - 30) + " Y" + f3(pts[0].second - 30) + " Z0\nG1 F500\n";
    prog += "D1 G" + std::to_string(g) + " X" + f3(pts[0].first) + " Y" + f3(pts[0].second) + "\n";
    std::vector<Seg> segs;
    // Once around and one element more, so every corner of the polygon is joined;
    // the last element ends on its normal before the G40 exit.
    for (size_t i = 1; i <= pts.size() + 1; ++i) {
        auto p = pts[i % pts.size()];
        prog += "X" + f3(p.first) + " Y" + f3(p.second) + "\n";
    }
    prog += "G40 X" + f3(pts[0].first - 30) + " Y" + f3(pts[0].second - 30) + "\nM2\n";
    for (size_t i = 0; i < pts.size(); ++i) {
        auto a = pts[i], b = pts[(i + 1) % pts.size()];
        segs.push_back({std::stod(f3(a.first)), std::stod(f3(a.second)), std::stod(f3(b.first)),
                        std::stod(f3(b.second))});
    }
    Prog run(prog, "mill", {{"D1.R", r}});
    if (run.error() == 149) return;  // a profile the tool does not fit: refused, fine
    ASSERT_EQ(run.error(), 0) << prog;
    const auto& mv = run.cap.moves;
    ASSERT_GE(mv.size(), pts.size() + 2);
    // Skip the approach (0), the entry (1), the overlapping last element and the
    // exit: they end on normals, not at a joint.
    for (size_t k = 2; k + 2 < mv.size(); ++k) {
        if (mv[k].loc.line == mv[mv.size() - 2].loc.line) continue;
        double fx = mv[k - 1].to_prog[X], fy = mv[k - 1].to_prog[Y];
        for (auto [px, py] : samples(mv[k], fx, fy)) {
            // The first element starts where the entry put the tool, on its normal at
            // the first point, where the closing edges may be nearer than R (000:3938):
            // it is only checked against its own edge.
            double best = 1e300;
            for (size_t j = 0; j < segs.size(); ++j)
                if (k != 2 || j == 0) best = std::min(best, dist_to_seg(px, py, segs[j]));
            EXPECT_GE(best, r - 1e-6) << "gouge at " << px << "," << py << " in\n" << prog;
            if (mv[k].g == 1) {
                EXPECT_NEAR(best, r, 1e-6) << "line piece not at R in\n" << prog;
            }
        }
    }
}
}  // namespace

TEST(Comp, ConvexPolygonsBothSides) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ang(0, 2 * M_PI), rad(30, 80), tool(0.5, 6);
    for (int i = 0; i < 60; ++i) {
        int n = 3 + i % 6;
        std::vector<double> a(static_cast<size_t>(n), 0.0);
        for (auto& v : a) v = ang(rng);
        std::sort(a.begin(), a.end());
        double R = rad(rng);
        std::vector<std::pair<double, double>> pts;
        for (double v : a) pts.push_back({R * std::cos(v), R * std::sin(v)});
        check_polygon(pts, 41, tool(rng));  // inside
        check_polygon(pts, 42, tool(rng));  // outside
    }
}

TEST(Comp, StarPolygonsConcave) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jit(-0.1, 0.1), tool(0.5, 3);
    for (int i = 0; i < 60; ++i) {
        int n = 5 + i % 4;
        std::vector<std::pair<double, double>> pts;
        for (int k = 0; k < 2 * n; ++k) {
            double a = k * M_PI / n + jit(rng);
            double R = (k % 2) ? 40 : 80;
            pts.push_back({R * std::cos(a), R * std::sin(a)});
        }
        check_polygon(pts, 41, tool(rng));
        check_polygon(pts, 42, tool(rng));
    }
}

TEST(Comp, ArcsKeepTheirCentreAndChangeRadiusByR) {
    // A rounded rectangle, outside (G42 on a counter-clockwise path): the arcs grow by R.
    Prog r(
        "%1\nG0 X-20 Y-20 Z0\nG1 F300\nD1 G42 X10 Y0\nX90\nG3 X100 Y10 I90 J10\nG1 Y50\n"
        "G3 X90 Y60 I90 J50\nG1 X10\nG3 X0 Y50 I10 J50\nG1 Y10\nG3 X10 Y0 I10 J10\nG1 G40 X-20 "
        "Y-20\nM2\n",
        "mill", {{"D1.R", 4}});
    ASSERT_EQ(r.error(), 0);
    int arcs = 0;
    for (size_t k = 1; k < r.cap.moves.size(); ++k) {
        const MoveEvent& m = r.cap.moves[k];
        if (m.g != 3) continue;
        ++arcs;
        EXPECT_NEAR(std::hypot(m.to_prog[X] - m.c0, m.to_prog[Y] - m.c1), 14, 1e-9);
        EXPECT_NEAR(m.sweep, 90, 1e-9);
    }
    EXPECT_EQ(arcs, 4);
}

TEST(Comp, EntryOnTheNormalOfTheNextElementAndEventsInOrder) {
    // 000:3938: at the end of the entry block the centre is on the normal of the next
    // element; the M08 of the next block comes after the entry move.
    Prog r("%1\nG0 X-10 Y-10 Z0\nG1 F200\nD1 G41 X0 Y0\nZ-2\nX50 M8\nY30\nG40 X70 Y40\nM2\n",
           "mill", {{"D1.R", 5}});
    ASSERT_EQ(r.error(), 0);
    ASSERT_GE(r.cap.moves.size(), 5u);
    EXPECT_NEAR(r.cap.moves[1].to_prog[X], 0, 1e-9);
    EXPECT_NEAR(r.cap.moves[1].to_prog[Y], 5, 1e-9);
    EXPECT_NEAR(r.cap.moves[2].to_prog[Z], -2, 1e-9);  // Z at the corner
    EXPECT_NEAR(r.cap.moves[3].to_prog[X], 45, 1e-9);  // trimmed at the inside corner
    EXPECT_NEAR(r.cap.moves[4].to_prog[X], 45, 1e-9);
    EXPECT_NEAR(r.cap.moves[4].to_prog[Y], 30, 1e-9);  // normal at the end before G40
}

TEST(Comp, LatheNoseRadiusAndOrientation) {
    // G42 towards -Z on the outside of a shaft (pupitre-iso(5), TOOLS AND
    // CORRECTORS): the nose centre is R above the profile and R from the face;
    // with C3 the driven point is R·(-1,-1) from the centre, so on paraxial
    // cuts it follows the profile as in G40.
    Prog r("%1\nG0 X60 Z10\nG1 F100\nD1 G42 X40 Z2\nZ-30\nX60\nG40 X80 Z-30\nM2\n", "lathe",
           {{"D1.R", 0.8}, {"D1.C", 3}});
    ASSERT_EQ(r.error(), 0);
    const MoveEvent& m = r.cap.moves[2];              // along Z-30 at Ø40
    EXPECT_NEAR(m.to_prog[X], 20 + 0.8 - 0.8, 1e-9);  // radius: 20 + R - R
    EXPECT_NEAR(m.to_prog[Z], -30, 1e-9);
}
