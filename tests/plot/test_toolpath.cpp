// The toolpath record and the SVG writer: what a run leaves (kinds, blocks,
// bounds, travel and error flags, EM±), memory per move, and SVG details a
// viewer depends on (arc flags, escaping, layers).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>

#include "core/output/svg.hpp"
#include "core/output/toolpath.hpp"
#include "tests/plot/plot_run.hpp"

using namespace pupitre;

namespace {

test::PlotRun run_text(const std::string& machine, const std::string& text,
                       const std::vector<std::pair<std::string, double>>& sets = {}) {
    return test::run_text("toolpath", machine, text, sets);
}

}  // namespace

TEST(Toolpath, RecordsMovesKindsAndBlocks) {
    auto r = run_text("mill",
                      "%12 (T)\nN10 G0 X10 Y0 Z5\nN20 G1 Z-1 F200\nN30 G2 X20 Y10 I20 J0\nN40 G1 "
                      "X30\nN50 G0 Z50\nM2\n");
    const Toolpath& p = *r.path;
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(p[0].kind, PathKind::rapid);
    EXPECT_EQ(p[1].kind, PathKind::feed);
    EXPECT_NE(p[2].arc, PathMove::kNoArc);
    EXPECT_EQ(p.loc(2).n, 30);
    EXPECT_EQ(p.loc(2).line, 4);
    EXPECT_EQ(p.loc(4).n, 50);
    const PathArc& a = p.arcs()[p[2].arc];
    EXPECT_NEAR(a.sweep, -90, 1e-4);
    EXPECT_NEAR(a.c0, 20, 1e-9);
    // G2 from (10,0) about (20,0) to (20,10) bulges towards (12.93, 7.07), inside the box.
    EXPECT_NEAR(p.bounds().lo[X], 0, 1e-9);  // the start at the program origin
    EXPECT_NEAR(p.bounds().hi[X], 30, 1e-9);
    EXPECT_NEAR(p.cut_bounds().lo[Z], -1, 1e-9);
    EXPECT_EQ(p.default_plane(), PathPlane::xy);
    double q[3];
    arc_point(p, 2, 0.5, q);
    EXPECT_NEAR(std::hypot(q[X] - 20, q[Y]), 10, 1e-9);
    EXPECT_NEAR(q[X], 20 - 10 * std::sqrt(0.5), 1e-9);
}

TEST(Toolpath, ArcExtremesWidenTheBounds) {
    auto r = run_text("mill", "%1\nG0 X-10 Y0\nG1 F100\nG3 X10 Y0 I0 J0\nM2\n");
    EXPECT_NEAR(r.path->bounds().hi[Y], 0, 1e-9);  // G3 from -X to +X about 0 goes through -Y
    EXPECT_NEAR(r.path->bounds().lo[Y], -10, 1e-9);
}

TEST(Toolpath, LatheIsZxAndDiameter) {
    auto r = run_text("lathe", "%1\nG0 X40 Z5\nG1 Z-20 F100\nX60\nM2\n");
    EXPECT_EQ(r.path->default_plane(), PathPlane::zx);
    EXPECT_TRUE(r.path->x_diameter());
    EXPECT_NEAR(r.path->cut_bounds().hi[X], 30, 1e-9);  // radius internally
}

TEST(Toolpath, ErrorsAreKeptWhereTheToolStopped) {
    auto r = run_text("mill", "%1\nN10 G0 X5 Y5\nN20 G1 X800 F100\nM2\n");
    const Toolpath& p = *r.path;
    ASSERT_EQ(p.errors().size(), 1u);
    EXPECT_EQ(p.errors()[0].code, 150);
    EXPECT_EQ(p.errors()[0].loc.n, 20);
    EXPECT_EQ(p.errors()[0].moves, p.size());
}

TEST(Toolpath, TravelFlagsMovesBeyondTheProfile) {
    MachineProfile m;
    builtin_machine("mill", m);
    Toolpath p(m);
    MoveEvent e;
    e.g = 1;
    e.to_prog[X] = e.to_mach[X] = 650;
    p.add(e);
    e.to_prog[X] = e.to_mach[X] = 750;  // beyond 700
    p.add(e);
    EXPECT_EQ(p[0].flags & pathflag::travel, 0);
    EXPECT_NE(p[1].flags & pathflag::travel, 0);
    EXPECT_EQ(p.travel_moves(), 1u);
    Diag d;
    d.code = 149;
    d.program = 0;
    d.line = 0;
    p.add_error(d);
    EXPECT_NE(p[1].flags & pathflag::error, 0);  // the failing block's moves
}

// A move drawn on the part in pieces (a C turn, Workshop::on_part) is one
// move: counted once among the moves, beyond travel and outside the frame.
TEST(Toolpath, APieceOfAMoveIsNotAMove) {
    MachineProfile m;
    builtin_machine("mill", m);
    Toolpath p(m);
    MoveEvent e;
    e.g = 0;
    for (int k = 1; k <= 3; ++k) {  // one rapid in three pieces, all beyond 700
        e.piece = k > 1;
        e.to_prog[X] = e.to_mach[X] = 700 + 10 * k;
        p.add(e);
    }
    e.piece = false;
    e.to_prog[X] = e.to_mach[X] = 760;  // a move of its own
    p.add(e);
    EXPECT_EQ(p.size(), 4u);
    EXPECT_EQ(p.moves_made(), 2u);
    EXPECT_EQ(p.moves_made(3), 1u);
    EXPECT_EQ(p.count(PathKind::rapid), 2u);
    EXPECT_EQ(p.travel_moves(), 2u);
    PathFit f;
    f.x0 = -1, f.x1 = 1, f.y0 = -1, f.y1 = 1;
    count_outside(p, PathPlane::xy, p.size(), f);
    EXPECT_EQ(f.outside, 2u);
}

TEST(Toolpath, LineTypesApplyToLaterMoves) {
    MachineProfile m;
    builtin_machine("mill", m);
    Toolpath p(m);
    MoveEvent e;
    e.g = 0;
    p.add(e);
    p.set_line_types(2, 3);
    p.add(e);
    e.g = 1;
    p.add(e);
    EXPECT_EQ(p[0].ltype, -1);
    EXPECT_EQ(p[1].ltype, 2);
    EXPECT_EQ(p[2].ltype, 3);
}

TEST(Toolpath, ExtremesFromTheProgramText) {
    ProgramMemory mem;
    ASSERT_FALSE(mem.load_text("em.iso", "%5\nEM- X-10 Y-20 Z-30\nEM+ X110 Y80 Z0\nM2\n"));
    Axes lo{}, hi{};
    uint16_t ml = 0, mh = 0;
    ASSERT_TRUE(scan_extremes(*mem.first(), false, lo, hi, ml, mh));
    EXPECT_EQ(ml, 7);
    EXPECT_EQ(mh, 7);
    EXPECT_EQ(lo[X], -10);
    EXPECT_EQ(lo[Z], -30);
    EXPECT_EQ(hi[Y], 80);
    ProgramMemory none;
    ASSERT_FALSE(none.load_text("n.iso", "%6\nG0 X1\nM2\n"));
    EXPECT_FALSE(scan_extremes(*none.first(), false, lo, hi, ml, mh));
}

TEST(Toolpath, AMillionMovesFitWellUnder100MB) {
    MachineProfile m;
    builtin_machine("mill", m);
    Toolpath p(m);
    MoveEvent e;
    for (int i = 0; i < 1'000'000; ++i) {
        e.g = i % 10 == 0 ? 3 : 1;
        e.to_prog[X] = i % 1000;
        e.to_prog[Y] = i / 1000;
        e.loc.line = i + 2;
        p.add(e);
    }
    EXPECT_LT(p.memory_bytes(), size_t(70) << 20) << p.memory_bytes();
}

TEST(Svg, ArcsAreArcsWithTheRightSweepFlag) {
    auto r = run_text("mill",
                      "%7 (A & B <C>)\nG0 X10 Y0\nG1 F100\nG3 X0 Y10 I0 J0\nG2 X10 Y0 I0 J0\nG3 "
                      "X-10 Y0 I0 J0\nM2\n");
    SvgOptions o;
    std::string s = svg_document(*r.path, o);
    // G3 is counter-clockwise on paper with +Y up: SVG sweep-flag 0 (its y runs down).
    EXPECT_NE(s.find("A10.0000 10.0000 0 0 0 0.0000 -10.0000"), std::string::npos) << s;
    EXPECT_NE(s.find("A10.0000 10.0000 0 0 1 10.0000 0.0000"), std::string::npos) << s;
    EXPECT_NE(s.find("A10.0000 10.0000 0 0 0 -10.0000 0.0000"), std::string::npos)
        << s;  // a half turn
    EXPECT_NE(s.find("<title>%7 A &amp; B &lt;C&gt;</title>"), std::string::npos);
    for (const char* id : {"\"rapid\"", "\"feed\"", "\"comp\"", "\"travel\"", "\"gouge\""})
        EXPECT_NE(s.find(std::string("<g id=") + id), std::string::npos) << id;
}

TEST(Svg, FullCirclesAreSplit) {
    auto r = run_text("mill", "%8\nG0 X10 Y0\nG1 F100\nG2 X10 Y0 I0 J0\nM2\n");
    std::string s = svg_document(*r.path, SvgOptions{});
    EXPECT_NE(
        s.find("A10.0000 10.0000 0 0 1 -10.0000 0.0000 A10.0000 10.0000 0 0 1 10.0000 0.0000"),
        std::string::npos)
        << s;
}

TEST(Svg, EscapesAndRepairsText) {
    EXPECT_EQ(xml_escape("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&apos;");
    EXPECT_EQ(xml_escape("x\x01y"), "xy");
    EXPECT_EQ(xml_escape("caf\xe9"), "caf\xef\xbf\xbd");                            // Latin-1 é
    EXPECT_EQ(xml_escape("\xc3\xa9t\xc3\xa9"), "\xc3\xa9t\xc3\xa9");                // UTF-8 kept
    EXPECT_EQ(xml_escape("\xed\xa0\x80"), "\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd");  // a surrogate
    std::string s;
    append_mm(s, -0.00001);
    append_mm(s, 1.23456);
    EXPECT_EQ(s, "0.00001.2346");
}
