// The dot raster and the graphic page's geometry: braille encoding, strokes,
// arcs within a dot of their circle, clipping, the view transform and the keys'
// round trips, the ASCII fallback, and the cache that draws only new moves.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/output/toolpath.hpp"
#include "pages/page_graph.hpp"
#include "pages/raster.hpp"

using namespace pupitre;
using namespace pupitre::pages;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The identity view of a raster: one world unit a dot, world y up.
ViewXf unit_view(const DotRaster& r) {
    ViewXf v;
    v.w = r.w();
    v.h = r.h();
    v.scale = 1;
    v.cx = (v.w - 1) * 0.5;
    v.cy = -(v.h - 1) * 0.5;  // world (x, -y) is dot (x, y)
    return v;
}

std::vector<std::pair<int, int>> dots(const DotRaster& r) {
    std::vector<std::pair<int, int>> out;
    for (int y = 0; y < r.h(); ++y)
        for (int x = 0; x < r.w(); ++x)
            if (r.test(x, y)) out.push_back({x, y});
    return out;
}

MoveEvent line_to(Axes& at, double x, double y, int g = 1) {
    MoveEvent e;
    e.g = g;
    e.from_mach = at;
    at[X] = x;
    at[Y] = y;
    e.to_mach = e.to_prog = at;
    return e;
}

MoveEvent arc_to(Axes& at, double x, double y, double cx, double cy, double sweep) {
    MoveEvent e = line_to(at, x, y, sweep < 0 ? 2 : 3);
    e.plane_a0 = X;
    e.plane_a1 = Y;
    e.c0 = cx;
    e.c1 = cy;
    e.sweep = sweep;
    return e;
}

}  // namespace

TEST(Braille, DotsFollowTheUnicodeNumbering) {
    // Dots 1-2-3 down the left column, 4-5-6 down the right, 7 and 8 below.
    const int cols[8] = {0, 0, 0, 1, 1, 1, 0, 1}, rows[8] = {0, 1, 2, 0, 1, 2, 3, 3};
    for (int d = 0; d < 8; ++d) {
        DotRaster r;
        r.reset(1, 1);
        r.dot(cols[d], rows[d], Ink::feed);
        EXPECT_EQ(r.bits(0, 0), 1 << d) << "dot " << d + 1;
        EXPECT_EQ(braille_glyph(r.bits(0, 0)), char32_t(0x2800 + (1 << d)));
    }
    EXPECT_EQ(braille_glyph(0xff), U'⣿');
}

TEST(Braille, CellTakesTheStrongestInk) {
    DotRaster r;
    r.reset(2, 1);
    r.dot(0, 0, Ink::rapid);
    r.dot(1, 3, Ink::feed);
    r.dot(0, 1, Ink::rapid);
    r.dot(2, 0, Ink::error);
    r.dot(3, 0, Ink::mirror);
    EXPECT_EQ(r.ink(0, 0), Ink::feed);
    EXPECT_EQ(r.ink(1, 0), Ink::error);
    Canvas c(4, 1);
    InkStyles st{};
    st[size_t(Ink::feed)] = Style::value;
    st[size_t(Ink::error)] = Style::alarm;
    r.to_canvas(c, Rect{1, 0, 2, 1}, Glyphs::braille, st);
    EXPECT_EQ(c.at(1, 0).ch, char32_t(0x2800 + 0x01 + 0x02 + 0x80));
    EXPECT_EQ(c.at(1, 0).st, Style::value);
    EXPECT_EQ(c.at(2, 0).st, Style::alarm);
    EXPECT_EQ(c.at(0, 0).ch, U' ');
}

TEST(Raster, LineEndpointsAndStraightness) {
    DotRaster r;
    r.reset(20, 5);
    r.line(1, 2, 37, 17, Ink::feed);
    EXPECT_TRUE(r.test(1, 2));
    EXPECT_TRUE(r.test(37, 17));
    auto d = dots(r);
    EXPECT_EQ(d.size(), size_t(37));  // one dot a column along the major axis
    for (auto [x, y] : d) {
        double ideal = 2 + (x - 1) * 15.0 / 36.0;
        EXPECT_LE(std::fabs(y - ideal), 0.5 + 1e-9) << x << "," << y;
    }
}

TEST(Raster, DashedRapidsAreDashed) {
    DotRaster r;
    r.reset(16, 1);
    r.line(0, 0, 31, 0, Ink::rapid, kDashed);
    int on = 0;
    for (int x = 0; x < 32; ++x) {
        on += r.test(x, 0);
        EXPECT_EQ(r.test(x, 0), (x / 4) % 2 == 0) << x;
    }
    EXPECT_EQ(on, 16);
}

TEST(Raster, ClippingKeepsTheVisiblePartOnly) {
    DotRaster r;
    r.reset(10, 5);  // 20 x 20 dots
    r.line(-100, 10, 100, 10, Ink::feed);
    for (int x = 0; x < 20; ++x) EXPECT_TRUE(r.test(x, 10));
    EXPECT_EQ(dots(r).size(), size_t(20));
    r.clear();
    r.line(-50, -50, -10, 70, Ink::feed);  // entirely to the left
    r.line(1e6, 19 - 1e6, -1e6, 19 + 1e6, Ink::feed);
    r.line(NAN, 0, 5, 5, Ink::feed);
    r.line(0, INFINITY, 5, 5, Ink::feed);
    auto d = dots(r);
    // The long diagonal crosses the grid whole; nothing else shows, nothing breaks.
    EXPECT_EQ(d.size(), size_t(20));
    for (auto [x, y] : d) EXPECT_LE(std::abs(x + y - 19), 1);
    r.clear();
    r.line(1e300, -1e300, -1e300, 1e300, Ink::feed);  // through the corner dot (0, 0)
    for (auto [x, y] : dots(r)) EXPECT_LE(x + y, 1);
}

TEST(Raster, ArcsStayWithinOneDotOfTheirCircle) {
    for (double radius : {0.7, 3.0, 12.5, 30.0}) {
        DotRaster r;
        r.reset(40, 20);  // 80 x 80 dots
        ViewXf v = unit_view(r);
        double cx = 40, cy = -40;
        draw_arc(r, v, cx, cy, radius, radius, 0.3, 2 * kPi, Ink::feed);
        auto d = dots(r);
        ASSERT_FALSE(d.empty());
        for (auto [x, y] : d) {
            double dist = std::hypot(x - cx, -y - cy);
            EXPECT_LE(std::fabs(dist - radius), 1.0) << "r " << radius << " dot " << x << "," << y;
        }
        // And the circle is whole: every direction has a dot within a dot of it.
        for (int k = 0; k < 64; ++k) {
            double a = k * 2 * kPi / 64, px = cx + radius * std::cos(a),
                   py = -(cy + radius * std::sin(a));
            bool near = false;
            for (auto [x, y] : d) near = near || std::hypot(x - px, y - py) <= 1.0;
            EXPECT_TRUE(near) << "r " << radius << " angle " << a;
        }
    }
}

TEST(Raster, ArcChordsGrowWithTheRadius) {
    EXPECT_EQ(arc_chords(0.1, kPi), 2);
    EXPECT_GT(arc_chords(100, kPi), arc_chords(10, kPi));
    EXPECT_LE(arc_chords(1e12, 2 * kPi), 65536);
}

TEST(View, TransformRoundTrips) {
    ViewXf v;
    v.cx = 12.5;
    v.cy = -3;
    v.scale = 0.37;
    v.w = 160;
    v.h = 68;
    for (double x : {-100.0, 0.0, 12.5, 99.9}) EXPECT_NEAR(v.wx(v.dx(x)), x, 1e-9);
    for (double y : {-50.0, -3.0, 7.25}) EXPECT_NEAR(v.wy(v.dy(y)), y, 1e-9);
    EXPECT_NEAR(v.dx(12.5), 79.5, 1e-9);  // the centre is the grid's centre
    EXPECT_LT(v.dy(10), v.dy(0));         // y up in the world is up on screen
}

TEST(View, FitShowsTheBoxWithItsMargin) {
    ViewXf v = fit_view(-10, 5, 90, 45, 160, 68, 3);
    EXPECT_GE(v.dx(-10), 3 - 1e-9);
    EXPECT_LE(v.dx(90), 156 + 1e-9);
    EXPECT_GE(v.dy(45), 3 - 1e-9);
    EXPECT_LE(v.dy(5), 64 + 1e-9);
    // The limiting direction (here the height: 40 mm on 61 dots) touches its margins.
    EXPECT_NEAR(v.dy(5) - v.dy(45), 61, 1e-9);
    EXPECT_LT(v.dx(90) - v.dx(-10), 153);
    ViewXf p = fit_view(5, 5, 5, 5, 100, 40);
    EXPECT_GT(p.scale, 0);
    EXPECT_NEAR(p.dx(5), 49.5, 1e-9);
}

TEST(View, ZoomKeepsThePointAndRoundTrips) {
    ViewXf v = fit_view(0, 0, 100, 50, 160, 68);
    double px = 73.2, py = 11.9;
    ViewXf z = zoom_about(v, px, py, 8);
    EXPECT_NEAR(z.scale, v.scale / 8, 1e-12);
    EXPECT_NEAR(z.dx(px), v.dx(px), 1e-9);
    EXPECT_NEAR(z.dy(py), v.dy(py), 1e-9);
    ViewXf back = zoom_about(z, px, py, 1.0 / 8);
    EXPECT_NEAR(back.cx, v.cx, 1e-9);
    EXPECT_NEAR(back.cy, v.cy, 1e-9);
    EXPECT_NEAR(back.scale, v.scale, 1e-12);
    ViewXf p = pan_view(pan_view(v, 0.25, -0.5), -0.25, 0.5);
    EXPECT_NEAR(p.cx, v.cx, 1e-9);
    EXPECT_NEAR(p.cy, v.cy, 1e-9);
    EXPECT_NEAR(pan_view(v, 0.5, 0).cx - v.cx, 0.5 * v.w * v.scale, 1e-9);
    // Zoom is bounded: no division by zero, no loss of precision.
    EXPECT_GE(zoom_about(v, 0, 0, 1e30).scale, kMinScale);
    EXPECT_LE(zoom_about(v, 0, 0, 1e-30).scale, kMaxScale);
}

TEST(Ascii, EveryCellIsPrintableAscii) {
    for (int b = 0; b < 256; ++b) {
        char c = ascii_glyph(uint8_t(b));
        EXPECT_GE(c, 0x20) << b;
        EXPECT_LT(c, 0x7f) << b;
        EXPECT_EQ(c == ' ', b == 0) << b;
    }
    EXPECT_EQ(ascii_glyph(0x01 | 0x08), '-');  // the top row
    EXPECT_EQ(ascii_glyph(0x01 | 0x02 | 0x04 | 0x40), '|');
}

namespace {

// A 100 x 60 mm rectangle with a 0.5 mm fillet at its top right corner.
struct FilletPart {
    MachineProfile m;
    std::unique_ptr<Toolpath> path;
    FilletPart() {
        builtin_machine("mill", m);
        path = std::make_unique<Toolpath>(m);
        Axes at{};
        path->start_at(at);
        path->add(line_to(at, 0, 0, 0));
        path->add(line_to(at, 99.5, 0));
        path->add(arc_to(at, 100, 0.5, 99.5, 0.5, 90));
        path->add(line_to(at, 100, 60));
        path->add(line_to(at, 0, 60));
        path->add(line_to(at, 0, 0));
        path->add(line_to(at, -20, -10, 0));
    }
};

}  // namespace

TEST(Graph, AHalfMillimetreFilletIsRoundWhenZoomed) {
    FilletPart f;
    GraphView g;
    g.path = f.path.get();
    Rect page{0, 1, 80, 20};
    // Zoomed about the fillet until its radius is 25 dots, the fillet in the window's middle.
    g.has_cursor = true;
    g.cur_x = 99.5;
    g.cur_y = 0.5;
    double want = 0.02;  // mm a dot
    g = graph_zoom(g, page, graph_window(g, page).scale / want);
    ViewXf xf = graph_window(g, page);
    ASSERT_NEAR(xf.scale, want, 1e-9);
    EXPECT_NEAR(xf.dx(99.5), graph_window(graph_fit(g), page).dx(99.5),
                1e-6);  // the cursor kept its dot
    g.cx = 99.5;
    g.cy = 0.25;
    xf = graph_window(g, page);
    DotRaster r;
    Rect a = graph_area(page);
    r.reset(a.w, a.h);
    draw_moves(*f.path, PathPlane::xy, xf, false, 0, f.path->size(), r);
    double rd = 0.5 / xf.scale, ccx = xf.dx(99.5), ccy = xf.dy(0.5);
    int on_arc = 0;
    for (auto [x, y] : dots(r)) {
        double ang = std::atan2(ccy - y, x - ccx);
        if (ang > -0.05 || ang < -kPi / 2 + 0.05) continue;  // the fillet turns from -90° to 0°
        EXPECT_NEAR(std::hypot(x - ccx, y - ccy), rd, 1.0);
        ++on_arc;
    }
    EXPECT_GT(on_arc, 25);  // a quarter circle of 25 dots: round, not a corner
}

TEST(Graph, KeysRoundTrip) {
    FilletPart f;
    GraphView g;
    g.path = f.path.get();
    Rect page{0, 1, 80, 20};
    ViewXf fit = graph_window(g, page);
    GraphView in = graph_zoom(g, page, 4);
    EXPECT_FALSE(in.fit);
    GraphView out = graph_zoom(in, page, 0.25);
    ViewXf o = graph_window(out, page);
    EXPECT_NEAR(o.cx, fit.cx, 1e-9);
    EXPECT_NEAR(o.cy, fit.cy, 1e-9);
    EXPECT_NEAR(o.scale, fit.scale, 1e-12);
    GraphView pan = graph_pan(graph_pan(g, page, 0.25, 0.25), page, -0.25, -0.25);
    EXPECT_NEAR(graph_window(pan, page).cx, fit.cx, 1e-9);
    EXPECT_TRUE(graph_fit(in).fit);
    MachineProfile lathe;
    builtin_machine("lathe", lathe);
    EXPECT_EQ(graph_next_plane(g, f.m).plane, PathPlane::xz);
    EXPECT_EQ(graph_next_plane(graph_next_plane(g, f.m), f.m).plane, PathPlane::yz);
    EXPECT_EQ(graph_next_plane(graph_next_plane(graph_next_plane(g, f.m), f.m), f.m).plane,
              PathPlane::xy);
    GraphView lg = g;
    lg.plane = PathPlane::zx;
    EXPECT_EQ(graph_next_plane(lg, lathe).plane, PathPlane::zx);
    // The cursor moves by cells: 2 dots across, 4 down.
    GraphView c = graph_move_cursor(g, page, 3, 2);
    EXPECT_TRUE(c.has_cursor);
    EXPECT_NEAR(c.cur_x - fit.cx, 6 * fit.scale, 1e-9);
    EXPECT_NEAR(c.cur_y - fit.cy, -8 * fit.scale, 1e-9);
    // Far off the window, the window follows.
    GraphView far = graph_move_cursor(g, page, 200, 0);
    ViewXf fw = graph_window(far, page);
    EXPECT_GT(fw.cx, fit.cx);
}

TEST(Graph, AsciiCanvasHasOnlyAscii) {
    FilletPart f;
    GraphView g;
    g.path = f.path.get();
    Axes tool{};
    tool[X] = 50;
    g.tool = &tool;
    g.has_cursor = true;
    g.cur_x = 10;
    g.cur_y = 10;
    Canvas c(80, 24, true);
    page_graph(g, f.m, c, Rect{0, 1, 80, 20});
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 80; ++x) EXPECT_LT(c.at(x, y).ch, char32_t(0x80)) << x << "," << y;
    std::string t = c.to_text();
    EXPECT_NE(t.find('@'), std::string::npos);    // the tool
    EXPECT_NE(t.find("|--"), std::string::npos);  // the scale bar
}

TEST(Graph, CachedFramesEqualAFullDrawing) {
    FilletPart f;
    // More moves after the first frame, as a live run adds them.
    GraphCache cache;
    GraphView g;
    g.path = f.path.get();
    g.cache = &cache;
    Rect page{0, 1, 80, 20};
    ViewXf xf = graph_window(g, page);
    g.fit = false;  // a fixed window, as after a zoom
    g.cx = xf.cx;
    g.cy = xf.cy;
    g.scale = xf.scale;
    Canvas c1(80, 24), c2(80, 24);
    g.upto = 3;
    page_graph(g, f.m, c1, page);
    g.upto = SIZE_MAX;
    c1.clear();
    page_graph(g, f.m, c1, page);
    EXPECT_EQ(cache.full_draws, 1);
    GraphView nocache = g;
    nocache.cache = nullptr;
    page_graph(nocache, f.m, c2, page);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 80; ++x) EXPECT_EQ(c1.at(x, y), c2.at(x, y)) << x << "," << y;
    // A new window redraws everything.
    page_graph(graph_zoom(g, page, 2), f.m, c1, page);
    EXPECT_EQ(cache.full_draws, 2);
}

TEST(Graph, NoPathSaysSo) {
    MachineProfile m;
    builtin_machine("mill", m);
    GraphView g;
    Canvas c(80, 24);
    page_graph(g, m, c, Rect{0, 1, 80, 20});
    EXPECT_NE(c.to_text().find("No toolpath yet"), std::string::npos);
}

TEST(Graph, NiceLengths) {
    EXPECT_DOUBLE_EQ(nice_length(7.3), 5);
    EXPECT_DOUBLE_EQ(nice_length(0.031), 0.02);
    EXPECT_DOUBLE_EQ(nice_length(1.0), 1);
    EXPECT_DOUBLE_EQ(nice_length(199), 100);
}
