// Snapshots of the GRAPH page (issue 7): the lathe program 004_p555.iso and the
// milling program with G45 pockets 000_p200_boitier.iso at 80x24 and 160x48,
// the ASCII fallback, a zoom with the cursor and the tool, and a gouge (error
// 149) with the page's styles. Compared with tests/plot/expected/NAME.txt; run
// with PUPITRE_BLESS=1 to rewrite them after an intended change, and review the diff.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cstdio>

#include "pages/page_graph.hpp"
#include "tests/plot/plot_run.hpp"
#include "tests/screen/snapshot.hpp"

using namespace pupitre;
using namespace pupitre::pages;

namespace {

// The handbook programs the snapshots draw, copied into the tests.
const std::string kPrograms = std::string(PUPITRE_SOURCE_DIR) + "/tests/golden/programs";
const std::string kSource = PUPITRE_SOURCE_DIR;

void snapshot(const std::string& name, const std::string& screen) {
    test::snapshot("tests/plot/expected", name, screen);
}

// The page as the console lays it out: status line above, message, input and
// soft keys below (pupitre(1), THE CONSOLE).
Canvas draw(const GraphView& g, const MachineProfile& m, int w, int h, bool ascii = false) {
    Canvas c(w, h, ascii);
    page_graph(g, m, c, Rect{0, 1, w, h - 4});
    return c;
}

// One letter a cell for the styles that matter on this page, '.' for the others.
std::string styles(const Canvas& c) {
    std::string out;
    for (int y = 0; y < c.height(); ++y) {
        std::string line;
        for (int x = 0; x < c.width(); ++x) {
            Style s = c.at(x, y).st;
            line += s == Style::alarm    ? 'A'
                    : s == Style::warn   ? 'W'
                    : s == Style::value  ? 'V'
                    : s == Style::select ? 'S'
                                         : '.';
        }
        out += line + '\n';
    }
    return out;
}

struct Lathe555 : test::PlotRun {
    Lathe555() : PlotRun("lathe", {kPrograms + "/004_p555.iso"}) {}
};
struct Mill200 : test::PlotRun {
    Mill200() : PlotRun("mill", {kPrograms + "/000_p200_boitier.iso"}, {{"D3.R", 8}}) {}
};

GraphView view_of(const test::PlotRun& r) {
    GraphView g;
    g.path = r.path.get();
    g.plane = r.path->default_plane();
    return g;
}

}  // namespace

TEST(GraphSnapshot, LatheP555) {
    Lathe555 r;
    ASSERT_TRUE(r.load_error.empty()) << r.load_error;
    ASSERT_FALSE(r.in->has_errors());
    GraphView g = view_of(r);
    EXPECT_EQ(g.plane, PathPlane::zx);
    snapshot("lathe_p555_80x24", draw(g, r.machine, 80, 24).to_text());
    snapshot("lathe_p555_160x48", draw(g, r.machine, 160, 48).to_text());
    snapshot("lathe_p555_80x24_ascii", draw(g, r.machine, 80, 24, true).to_text());
}

TEST(GraphSnapshot, MillPocketP200) {
    Mill200 r;
    ASSERT_TRUE(r.load_error.empty()) << r.load_error;
    ASSERT_FALSE(r.in->has_errors());
    GraphView g = view_of(r);
    EXPECT_EQ(g.plane, PathPlane::xy);
    snapshot("mill_p200_80x24", draw(g, r.machine, 80, 24).to_text());
    snapshot("mill_p200_160x48", draw(g, r.machine, 160, 48).to_text());
    // The side view, as the plane key gives it.
    snapshot("mill_p200_xz_80x24",
             draw(graph_next_plane(g, r.machine), r.machine, 80, 24).to_text());
}

TEST(GraphSnapshot, MillZoomCursorAndTool) {
    Mill200 r;
    ASSERT_TRUE(r.load_error.empty()) << r.load_error;
    GraphView g = view_of(r);
    Rect page{0, 1, 80, 20};
    // The cursor on the circular pocket, zoomed 4x about it, the tool half-way.
    g = graph_move_cursor(g, page, 0, 0);
    g = graph_zoom(g, page, 4);
    Axes tool{};
    const double* mid = r.path->moves()[r.path->size() / 2].p;
    tool[X] = mid[0];
    tool[Y] = mid[1];
    tool[Z] = mid[2];
    g.tool = &tool;
    g.upto = r.path->size() / 2;
    Canvas c = draw(g, r.machine, 80, 24);
    snapshot("mill_p200_zoom_80x24", c.to_text() + "-- styles --\n" + styles(c));
}

TEST(GraphSnapshot, GougeIsHighlighted) {
    test::PlotRun r("mill", {kSource + "/tests/bad/149_tool_larger_than_concave_arc.iso"},
                    {{"D1.R", 8}});
    ASSERT_TRUE(r.in->has_errors());
    ASSERT_EQ(r.path->errors().size(), 1u);
    EXPECT_EQ(r.path->errors()[0].code, 149);
    Canvas c = draw(view_of(r), r.machine, 80, 24);
    std::string text = c.to_text();
    EXPECT_NE(text.find("error 149 N80"), std::string::npos);
    snapshot("gouge_149_80x24", text + "-- styles --\n" + styles(c));
}

// One move is "1 move" in the title (found on the console: " 1 moves  0:00:04 ").
TEST(GraphSnapshot, OneMoveIsOneMove) {
    const std::string file = testing::TempDir() + "/one_move.iso";
    FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("%1\nG0 X10 Y10 Z5\nM2\n", f);
    std::fclose(f);
    test::PlotRun r("mill", {file});
    ASSERT_TRUE(r.load_error.empty()) << r.load_error;
    const std::string page = draw(view_of(r), r.machine, 80, 24).to_text();
    EXPECT_NE(page.find(" 1 move  0:00:0"), std::string::npos) << page;
    EXPECT_EQ(page.find("1 moves"), std::string::npos) << page;
}
