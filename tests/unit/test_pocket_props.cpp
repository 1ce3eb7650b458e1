// Issue 19 item 1 for the milling pockets: generated G46 pockets (rectangles,
// rounded rectangles, L shapes, either sense) with islands (circles,
// rectangles, triangles), cutters and allowances of several sizes. No move of
// the roughing or the finishing brings the cutter into a wall or an island
// plus the allowance, checked point by point with an oracle of its own
// (distances to lines and arcs, even-odd inside tests on polygons).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/cycles/pocket46.hpp"
#include "helpers.hpp"

using namespace pupitre;
using comp::Elem;
using comp::V2;
using test::in_polygon;

namespace {
constexpr double kPi = std::numbers::pi;

Elem line(V2 a, V2 b) {
    Elem e;
    e.a = a, e.b = b;
    return e;
}
Elem arc(V2 a, V2 b, V2 c, double sweep) {
    Elem e = line(a, b);
    e.arc = true, e.c = c, e.sweep = sweep;
    return e;
}

double seg_dist(V2 p, V2 a, V2 b) {
    V2 d = b - a;
    double l2 = d.squaredNorm(), t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0;
    return (a + t * d - p).norm();
}
double dist(const Elem& e, V2 p) {
    if (!e.arc) return seg_dist(p, e.a, e.b);
    double r = (e.a - e.c).norm(), a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x());
    double ang = std::atan2(p.y() - e.c.y(), p.x() - e.c.x()) - a0;
    ang = e.sweep > 0 ? ang : -ang;
    ang = std::fmod(ang + 4 * kPi, 2 * kPi);
    if (ang <= std::fabs(e.sweep)) return std::fabs((p - e.c).norm() - r);
    return std::min((p - e.a).norm(), (p - e.b).norm());
}
std::vector<V2> polygon(const std::vector<Elem>& es) {
    std::vector<V2> out;
    for (const Elem& e : es) {
        if (!e.arc) {
            out.push_back(e.a);
            continue;
        }
        double r = (e.a - e.c).norm(), a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x());
        for (int i = 0; i < 64; ++i)
            out.push_back(e.c +
                          r * V2(std::cos(a0 + e.sweep * i / 64), std::sin(a0 + e.sweep * i / 64)));
    }
    return out;
}

std::vector<Elem> rect(V2 lo, V2 hi, double round, bool ccw) {
    std::vector<Elem> es;
    if (round <= 0) {
        std::vector<V2> p{lo, V2(hi.x(), lo.y()), hi, V2(lo.x(), hi.y())};
        for (int i = 0; i < 4; ++i) es.push_back(line(p[size_t(i)], p[size_t((i + 1) % 4)]));
    } else {
        double r = round;
        es = {line(V2(lo.x() + r, lo.y()), V2(hi.x() - r, lo.y())),
              arc(V2(hi.x() - r, lo.y()), V2(hi.x(), lo.y() + r), V2(hi.x() - r, lo.y() + r),
                  kPi / 2),
              line(V2(hi.x(), lo.y() + r), V2(hi.x(), hi.y() - r)),
              arc(V2(hi.x(), hi.y() - r), V2(hi.x() - r, hi.y()), V2(hi.x() - r, hi.y() - r),
                  kPi / 2),
              line(V2(hi.x() - r, hi.y()), V2(lo.x() + r, hi.y())),
              arc(V2(lo.x() + r, hi.y()), V2(lo.x(), hi.y() - r), V2(lo.x() + r, hi.y() - r),
                  kPi / 2),
              line(V2(lo.x(), hi.y() - r), V2(lo.x(), lo.y() + r)),
              arc(V2(lo.x(), lo.y() + r), V2(lo.x() + r, lo.y()), V2(lo.x() + r, lo.y() + r),
                  kPi / 2)};
    }
    if (!ccw) {
        std::reverse(es.begin(), es.end());
        for (Elem& e : es) e = comp::reversed(e);
    }
    return es;
}
std::vector<Elem> poly(std::vector<V2> p, bool ccw) {
    if (!ccw) std::reverse(p.begin(), p.end());
    std::vector<Elem> es;
    for (size_t i = 0; i < p.size(); ++i) es.push_back(line(p[i], p[(i + 1) % p.size()]));
    return es;
}

struct Pocket {
    std::vector<Elem> outer;
    std::vector<std::vector<Elem>> islands;
    std::vector<V2> outer_poly;
    std::vector<std::vector<V2>> island_polys;
    void close() {
        outer_poly = polygon(outer);
        for (const auto& is : islands) island_polys.push_back(polygon(is));
    }
    // The cutter centre at p keeps `need` from every wall and island, inside
    // the pocket and outside the islands (less 0.1 µm): "" when it does, else why not.
    std::string problem(V2 p, double need) const {
        double d = 1e300;
        for (const Elem& e : outer) d = std::min(d, dist(e, p));
        for (const auto& is : islands)
            for (const Elem& e : is) d = std::min(d, dist(e, p));
        if (!in_polygon(outer_poly, p)) return "outside the pocket";
        for (const auto& is : island_polys)
            if (in_polygon(is, p)) return "inside an island";
        if (d < need - 1e-4)
            return "at " + std::to_string(d) + " from a wall, " + std::to_string(need) + " needed";
        return {};
    }
};

// Points every 0.05 mm along a piece from `from`.
std::vector<V2> along(V2 from, const comp::Piece& pc) {
    std::vector<V2> pts;
    if (pc.arc) {
        double r = (from - pc.c).norm(), a0 = std::atan2(from.y() - pc.c.y(), from.x() - pc.c.x());
        int n = std::max(4, int(std::ceil(std::fabs(pc.sweep) * r / .05)));
        for (int k = 1; k <= n; ++k)
            pts.push_back(pc.c +
                          r * V2(std::cos(a0 + pc.sweep * k / n), std::sin(a0 + pc.sweep * k / n)));
    } else {
        int n = std::max(1, int(std::ceil((pc.to - from).norm() / .05)));
        for (int k = 1; k <= n; ++k) pts.push_back(from + (pc.to - from) * (double(k) / n));
    }
    return pts;
}

int check_runs(const Pocket& pk, const std::vector<p46::Run>& runs, double need,
               const std::string& what) {
    int bad = 0;
    V2 at(0, 0);
    bool have = false;
    for (const p46::Run& r : runs) {
        std::vector<V2> pts{r.start};
        if (r.linked && have) {  // at feed from the previous run's end
            for (int k = 1; k <= 200; ++k) pts.push_back(at + (r.start - at) * (k / 200.0));
        }
        V2 from = r.start;
        for (const comp::Piece& pc : r.pieces) {
            for (V2 q : along(from, pc)) pts.push_back(q);
            from = pc.to;
        }
        for (V2 q : pts)
            if (std::string why = pk.problem(q, need); !why.empty() && ++bad <= 2)
                ADD_FAILURE() << what << (r.cleanup ? " clean-up" : "")
                              << (r.linked ? " linked" : "") << ": " << q.transpose() << " " << why;
        at = from;
        have = true;
    }
    return bad;
}
}  // namespace

TEST(Pocket46, GeneratedPocketsNeverEnterTheWallsOrIslands) {
    std::mt19937 rng(20261129);
    std::uniform_real_distribution<double> u(0, 1);
    int planned = 0, failing = 0, finished = 0;
    for (int n = 0; n < 60; ++n) {
        const bool ccw = n % 2;
        const int shape = (n / 2) % 3;
        const double R = 2 + 3 * u(rng), J = .2 + .8 * u(rng);
        double W = 50 + 30 * u(rng), H = 35 + 25 * u(rng);
        Pocket pk;
        if (shape == 2) {  // an L: the top right corner cut away
            double cx = W * (.5 + .2 * u(rng)), cy = H * (.5 + .2 * u(rng));
            pk.outer = poly({V2(0, 0), V2(W, 0), V2(W, cy), V2(cx, cy), V2(cx, H), V2(0, H)}, ccw);
        } else {
            pk.outer = rect(V2(0, 0), V2(W, H), shape == 1 ? R + 1 + 5 * u(rng) : 0, ccw);
        }
        // Islands in free places: each kept 2R + J + 2 from the walls and the others.
        std::vector<std::pair<V2, double>> placed;  // centre, radius of a bounding circle
        int islands = int(u(rng) * 3);
        for (int k = 0, tries = 0; k < islands && tries < 50; ++tries) {
            double s = 3 + 4 * u(rng), gap = 2 * R + J + 2;
            V2 c(gap + s + (W - 2 * (gap + s)) * u(rng), gap + s + (H - 2 * (gap + s)) * u(rng));
            if (shape == 2) {
                double cx = W * .7, cy = H * .7;
                if (c.x() + s + gap > cx * .7 && c.y() + s + gap > cy * .7) continue;
            }
            bool free = true;
            for (auto [q, r] : placed) free = free && (q - c).norm() > r + s + gap;
            if (!free) continue;
            placed.push_back({c, s});
            int kind = int(u(rng) * 3);
            bool iccw = u(rng) < .5;
            if (kind == 0) {
                std::vector<Elem> circ{arc(c + V2(s, 0), c - V2(s, 0), c, kPi),
                                       arc(c - V2(s, 0), c + V2(s, 0), c, kPi)};
                if (!iccw)
                    circ = {arc(c + V2(s, 0), c - V2(s, 0), c, -kPi),
                            arc(c - V2(s, 0), c + V2(s, 0), c, -kPi)};
                pk.islands.push_back(circ);
            } else if (kind == 1) {
                pk.islands.push_back(rect(c - V2(s, s * .6), c + V2(s, s * .6), 0, iccw));
            } else {
                pk.islands.push_back(
                    poly({c + V2(-s, -s * .7), c + V2(s, -s * .7), c + V2(0, s * .9)}, iccw));
            }
            ++k;
        }
        pk.close();
        p46::Def d;
        d.np = 1, d.ed = 10, d.q = R * (.8 + 1.1 * u(rng)), d.j = J, d.nr = u(rng) < .5 ? 1 : -1;
        p46::Section o;
        // LX LY: the finishing starts in the middle of the first element, a
        // circle where it starts (finishing from a corner is error 288).
        auto start_of = [](const std::vector<Elem>& es) {
            return es[0].arc ? es[0].a : V2((es[0].a + es[0].b) / 2);
        };
        o.nu = 1, o.elems = pk.outer, o.has_l = true, o.l = start_of(pk.outer);
        d.sections.push_back(o);
        for (const auto& is : pk.islands) {
            p46::Section t;
            t.nu = 2, t.elems = is, t.has_l = true, t.l = start_of(is);
            d.sections.push_back(t);
        }
        std::string name = "pocket " + std::to_string(n) +
                           (shape == 2   ? " L"
                            : shape == 1 ? " rounded"
                                         : " square") +
                           (ccw ? " ccw" : " cw") + " islands " +
                           std::to_string(pk.islands.size()) + " R" + std::to_string(R) + " J" +
                           std::to_string(J);
        if (Error err = p46::check(d)) {
            ADD_FAILURE() << name << ": " << err.code << " " << err.detail;
            continue;
        }
        std::vector<p46::Run> runs;
        std::vector<double> ys;
        if (Error err = p46::roughing(d, R, runs, ys)) {
            ADD_FAILURE() << name << ": roughing " << err.code << " " << err.detail;
            continue;
        }
        ++planned;
        int bad = check_runs(pk, runs, R + J, name + " roughing");
        std::vector<p46::Run> fin;
        // The finishing may refuse to engage where the roughing left material
        // (288): a refusal, not a gouge.
        if (!p46::finishing(d, R, 0, fin))
            bad += check_runs(pk, fin, R, name + " finishing"), ++finished;
        failing += bad > 0;
    }
    EXPECT_EQ(failing, 0);
    EXPECT_GE(planned, 55);
    EXPECT_GE(finished, 40);
}

// G45 (000:5943-6076; pupitre-iso(5), POCKETS): generated rectangular pockets with corner radii,
// circles and oblongs, cutters R3 to R8, step-overs from R/2 to 1.9R, layers,
// allowances I and J, run by the interpreter. The cutter centre keeps R from
// every wall (R + J but for the finishing contour) and never goes below the
// floor: each point of each move of the cycle's block, against the shape's
// exact signed distance, to the µm the cycle rounds its contours to.
TEST(Pocket, GeneratedPocketsNeverEnterTheWalls) {
    std::mt19937 rng(20261130);
    std::uniform_real_distribution<double> u(0, 1);
    int ran = 0, failing = 0;
    for (int n = 0; n < 45; ++n) {
        const int shape = n % 3;  // rectangle, circle, oblong
        const double R = 3 + 5 * u(rng), Q = R * (.5 + 1.4 * u(rng)), P = 3 + 7 * u(rng),
                     Z = -5 - 15 * u(rng);
        const double I = .2 + .6 * u(rng), J = .2 + .6 * u(rng), cx = 40 * u(rng) - 20,
                     cy = 40 * u(rng) - 20;
        double ex = 0, ey = 0, eb = 0;
        char buf[160];
        if (shape == 0) {
            ex = 2 * R + 6 + 60 * u(rng), ey = 2 * R + 6 + 60 * u(rng);
            eb = std::min(R + 6 * u(rng), std::min(ex, ey) / 2);
            std::snprintf(buf, sizeof buf, "EX%.3f EY%.3f EB%.3f", ex, ey, eb);
        } else if (shape == 1) {
            eb = R + 3 + 25 * u(rng);
            std::snprintf(buf, sizeof buf, "EB%.3f", eb);
        } else {
            eb = R + 3 + 15 * u(rng), ex = 2 * eb + 2 + 30 * u(rng);
            std::snprintf(buf, sizeof buf, "EX%.3f EB%.3f", ex, eb);
        }
        // The values as the program writes them (3 decimals).
        auto r3 = [](double v) { return std::round(v * 1000) / 1000; };
        ex = r3(ex), ey = r3(ey), eb = r3(eb);
        char block[400];
        std::snprintf(block, sizeof block,
                      "%%1\nT3 D3 M6\nM3 M40 S1000\nG0 X%.3f Y%.3f Z10\n"
                      "N100 G45 X%.3f Y%.3f Z%.3f ER3 %s P%.3f Q%.3f I%.3f J%.3f EP150 EQ350 "
                      "EJ150\nZ100\nM2\n",
                      cx, cy, cx, cy, Z, buf, P, Q, I, J);
        test::Prog r(block, "mill", {{"D3.R", R}});
        std::string name = "G45 " + std::to_string(n) + " " + buf + " R" + std::to_string(R);
        if (r.error()) {
            ADD_FAILURE() << name << ": error " << r.error();
            continue;
        }
        ++ran;
        auto sdf = [&](V2 p) {
            p -= V2(r3(cx), r3(cy));
            if (shape == 1) return p.norm() - eb;
            if (shape == 2)
                return V2(std::max(std::fabs(p.x()) - (ex / 2 - eb), 0.0), p.y()).norm() - eb;
            V2 q(std::fabs(p.x()) - (ex / 2 - eb), std::fabs(p.y()) - (ey / 2 - eb));
            return V2(std::max(q.x(), 0.0), std::max(q.y(), 0.0)).norm() +
                   std::min(std::max(q.x(), q.y()), 0.0) - eb;
        };
        int bad = 0;
        V2 at(r3(cx), r3(cy));
        for (const MoveEvent& m : r.cap.moves) {
            V2 to(m.to_prog[X], m.to_prog[Y]);
            if (m.loc.n == 100) {
                comp::Piece pc;
                pc.to = to;
                if (m.g == 2 || m.g == 3)
                    pc.arc = true, pc.c = V2(m.c0, m.c1), pc.sweep = m.sweep * kPi / 180;
                for (V2 q : along(at, pc))
                    // 1 µm: the cycle's contours are whole µm (ceil_um).
                    if (sdf(q) > -R + 1e-3 && ++bad <= 2)
                        ADD_FAILURE() << name << ": G" << m.g << " at " << q.transpose() << ", "
                                      << -sdf(q) << " from the wall";
                if (m.to_prog[Z] < r3(Z) - 1e-6 && ++bad <= 2)
                    ADD_FAILURE() << name << ": below the floor";
            }
            at = to;
        }
        failing += bad > 0;
    }
    EXPECT_EQ(failing, 0);
    EXPECT_EQ(ran, 45);
}
