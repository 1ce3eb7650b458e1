// The PART page in the console (issue 36): the part drawn in colour as
// cells of the canvas, as many colours as the terminal shows and none in
// mono, ASCII symbols for --ascii; its keys turn, tilt, zoom and change the
// view; a run asks for a new picture only when the material changed; on
// paper after :submit only, during an exercise.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "console/exercise_run.hpp"
#include "core/training/exercise.hpp"
#include "pages/pages.hpp"
#include "tests/console/fixture.hpp"

namespace pupitre::test {
namespace {

// The screen once the worker made the picture asked for.
pages::Canvas drawn(Console& c, int w = 100, int h = 30, bool ascii = false) {
    c.s->resize(w, h);
    c.s->view();  // asks for the picture
    c.s->part().wait();
    pages::Canvas cv(w, h, ascii);
    pages::render_screen(c.s->view(), cv);
    return cv;
}

struct Count {
    int palette = 0, rgb = 0, shapes = 0, wide = 0;
};
// The picture's cells (under the page's title, over its three lines).
Count count(const pages::Canvas& cv) {
    Count n;
    for (int y = 2; y < cv.height() - 7; ++y)
        for (int x = 0; x < cv.width(); ++x) {
            const pages::Cell& cell = cv.at(x, y);
            for (uint32_t col : {cell.fg, cell.bg})
                if (col != pages::kNoColour) ++((col & pages::kPaletteBit) ? n.palette : n.rgb);
            if (cell.ch != U' ') ++n.shapes;
            if (cell.ch >= 0x80) ++n.wide;
        }
    return n;
}

std::string title(const pages::Canvas& cv) {
    std::string t = cv.to_text();
    t = t.substr(t.find('\n') + 1);
    return t.substr(0, t.find('\n'));
}

void screen(Console& c, pages::Colours colours, bool ascii = false) {
    console::Screen sc;
    sc.colours = colours;
    sc.ascii = ascii;
    c.s->set_screen(sc);
}

TEST(PartPage, TheBlockIn3DInTheTerminalsColoursTurnedByKeys) {
    Console c("mill", {});
    screen(c, pages::Colours::c256);
    c.type(":setup mill");
    c.type(":part");
    EXPECT_EQ(c.s->page(), pages::PageId::part);
    pages::Canvas cv = drawn(c);
    EXPECT_NE(title(cv).find("PART  3d turned 60° tilted 35°"), std::string::npos) << title(cv);
    const Count n = count(cv);
    EXPECT_GT(n.palette, 1000);
    EXPECT_EQ(n.rgb, 0);  // a 256-colour terminal gets its palette's
    c.named("Right");
    c.named("Up");
    EXPECT_EQ(c.message(), "turned 75°, tilted 45°");
    cv = drawn(c);
    EXPECT_NE(title(cv).find("3d turned 75° tilted 45°"), std::string::npos) << title(cv);
    c.named("v");
    cv = drawn(c);
    EXPECT_NE(title(cv).find("PART  top"), std::string::npos) << title(cv);
    c.key("+");
    EXPECT_NE(title(drawn(c)).find("top x1.5"), std::string::npos);
    c.type(":part view 3d");
    EXPECT_NE(title(drawn(c)).find("3d turned 75°"), std::string::npos);
    c.type(":part view section");
    EXPECT_EQ(c.message(), "the machining centre's views: top, 3d");
}

TEST(PartPage, TrueColourWhereTheTerminalHasIt) {
    Console c("lathe", {});
    screen(c, pages::Colours::direct);
    c.type(":setup lathe");
    c.named("M-v");
    EXPECT_EQ(c.s->page(), pages::PageId::part);
    const Count n = count(drawn(c));
    EXPECT_GT(n.rgb, 500);
    EXPECT_EQ(n.palette, 0);
}

// --theme mono and NO_COLOR: symbols only; --ascii: ASCII symbols only.
TEST(PartPage, MonoGetsSymbolsAndAsciiPlainOnes) {
    Console c("lathe", {});
    screen(c, pages::Colours::none);
    c.type(":setup lathe");
    c.type(":part");
    Count n = count(drawn(c));
    EXPECT_EQ(n.palette + n.rgb, 0);
    EXPECT_GT(n.shapes, 200);
    screen(c, pages::Colours::c16, true);
    n = count(drawn(c, 100, 30, true));
    EXPECT_EQ(n.wide, 0);
    EXPECT_GT(n.shapes, 200);
    EXPECT_GT(n.palette, 200);  // the colours stay: --ascii is about symbols
}

// A machining centre's FILE.png without a view is its height field, data
// for scripts that looks blank as a picture: the message says so and how
// to get the picture (a student exported one from the PART page and got a
// white page).
TEST(PartPage, AMillsPngWithoutAViewSaysItIsTheHeightField) {
    Console c("mill", {});
    c.type(":setup mill");
    c.type(":part");
    const std::string png = ::testing::TempDir() + "/heights_" + std::to_string(getpid()) + ".png";
    c.type(":part export " + png);
    EXPECT_EQ(c.message(), "the part's height field (16-bit data) written to " + png +
                               "; its picture: :part export " + png + " 3d");
    std::remove(png.c_str());
    c.type(":part export " + png + " 3d");
    EXPECT_EQ(c.message(), "the part written to " + png);
    std::ifstream in(png, std::ios::binary);
    EXPECT_TRUE(in.good());
    std::remove(png.c_str());
}

TEST(PartPage, WithoutAWorkshopItSaysHow) {
    Console c("lathe", {});
    c.type(":part");
    const std::string s = c.screen(100, 30);
    EXPECT_NE(s.find(":setup lathe puts a bar in the chuck"), std::string::npos) << s;
}

// An air move changes no material: no new picture while it runs; a cut
// asks for one.
TEST(PartPage, ARunAsksForAPictureOnlyWhenTheMaterialChanges) {
    Console c("mill", {});
    c.s->memory().load_text(
        "air.iso", "%40\nN10 T2 D2 M6\nN20 G0 X0 Y0 Z100\nN30 X50\nN40 Y50\nN50 X0\nN60 M2\n");
    c.type(":setup mill");
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":part");
    drawn(c);
    const uint64_t before = c.s->part().serial();
    c.type(":load 40");
    c.type(":mode auto");
    c.type(":cycle");
    int frames = 0;
    for (double t = 0; t < 120 && c.s->busy(); t += 1.0 / 30, ++frames) {
        c.s->tick(1.0 / 30);
        c.s->view();
        c.s->part().wait();
    }
    EXPECT_GT(frames, 10);
    c.s->view();
    // During the run nothing; at its end the tool stands elsewhere: one.
    EXPECT_LE(c.s->part().serial(), before + 2);
}

std::string bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// During an exercise the part goes on paper after :submit only; then with
// the drawing's dimensions.
TEST(PartPage, OnPaperOnlyAfterSubmit) {
    char dir[] = "/tmp/pupitre-part-XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    const std::string db = std::string(dir) + "/store.db";
    training::Exercise e;
    ASSERT_TRUE(training::builtin_exercise("lathe-first", e));
    auto st = store::Store::open(db);
    ASSERT_TRUE(st.ok());
    Console c("lathe", {}, std::move(st.value), [&](console::Session& s) {
        EXPECT_EQ(s.start_exercise(e, "dana", "0123456789abcdef-test-class-key"), "");
    });
    const std::string pdf = std::string(dir) + "/part.pdf", png = std::string(dir) + "/part.png";
    c.type(":part export " + pdf);
    EXPECT_EQ(c.message(),
              ":part export: not during an exercise (the setup is what you must find)");
    EXPECT_TRUE(bytes_of(pdf).empty());
    c.type(":part");
    EXPECT_NE(c.screen(100, 30).find("painted by depth of cut"), std::string::npos);
    c.type(":submit");
    c.type(":part export " + pdf);
    EXPECT_EQ(c.message(), "the part written to " + pdf);
    EXPECT_EQ(bytes_of(pdf).substr(0, 5), "%PDF-");
    c.type(":part export " + png);
    EXPECT_EQ(bytes_of(png).substr(1, 3), "PNG");
    c.type(":part");
    const std::string s = drawn(c).to_text();
    EXPECT_NE(s.find("deviation from exercise lathe-first"), std::string::npos) << s;
    EXPECT_NE(s.find("dia Z-10:"), std::string::npos) << s;
    std::remove(pdf.c_str());
    std::remove(png.c_str());
}

}  // namespace
}  // namespace pupitre::test
