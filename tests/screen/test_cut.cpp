// Nothing cut unseen at the documented minimum, 80x24 (issue 38 item 8):
// every page of the lathe and the mill, in English and in French, in the
// states a student meets (power-on, a run, an alarm, the workshop, the
// editor), with the messages said on the way. A text cut by its room ends
// with a mark (Canvas::text); no text may be drawn over another's letters
// (which cuts it with no mark); and no page cuts its text at all but the
// editor's program lines (ALARM keeps the messages, which the message line
// may cut, in full).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/i18n.hpp"
#include "pages/canvas.hpp"
#include "tests/console/fixture.hpp"

using namespace pupitre;
using pupitre::test::Console;

namespace {

constexpr const char* kPages[] = {"om",   "op",   "prog", "info", "param", "dir",  "alarm",
                                  "help", "pref", "corr", "edit", "graph", "shop", "exercise"};

// Renders every page of `c` at 80x24 and checks it; `where` names the state.
void walk(Console& c, const std::string& where) {
    for (const char* p : kPages) {
        c.type(std::string(":page ") + p);
        pages::Canvas canvas(80, 24);
        pages::render_screen(c.s->view(), canvas);
        const std::string at = where + ", page " + p + " (" +
                               std::string(i18n::language().empty() ? "en" : i18n::language()) +
                               "):\n" + canvas.to_text();
        EXPECT_EQ(canvas.overwrites(), 0) << "a text drawn over another's letters, " << at;
        // The page alone (the message line is cut with its mark, and the
        // ALARM page shows it whole): only the editor's program lines, wider
        // than the screen, may be cut, with the mark.
        pages::View v = c.s->view();
        v.message.clear();
        const bool tall = std::string(p) == "alarm" || std::string(p) == "help";
        pages::Canvas page(80, tall ? 400 : 24);  // every line of the long ones
        pages::render_screen(v, page);
        if (std::string(p) != "edit") {
            EXPECT_EQ(page.cuts(), 0) << "a text cut, " << where << "\n" << page.to_text();
        }
    }
}

void walk_machine(const std::string& machine, const std::string& program) {
    Console c(machine, {program});
    walk(c, machine + " at power-on");
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":setup " + std::string(machine == "lathe" ? "lathe" : "mill"));
    c.type(":page shop");
    c.type(machine == "lathe" ? "dia Z-20" : "depth X10 Y40");
    walk(c, machine + " with a workshop");
    c.type(":mode imd");
    c.type(machine == "lathe" ? "G2 X10 Z0 R1" : "G2 X10 Y0 R2");
    c.named("F9");
    c.run_until_settled();
    c.type("G0 X10 (" + std::string(300, 'A') + ")");  // refused at Enter, a long message
    walk(c, machine + " after an alarm");
    c.type(":raz");
    c.type(":edit 300");
    c.type("N1 (A COMMENT THAT IS LONG ENOUGH TO REACH THE RIGHT EDGE OF THE SCREEN, AND MORE)");
    walk(c, machine + " in the editor");
}

class Cut : public ::testing::TestWithParam<const char*> {
  protected:
    void SetUp() override { i18n::init(GetParam(), PUPITRE_LOCALE_BUILD_DIR); }
    void TearDown() override { i18n::init("en", PUPITRE_LOCALE_BUILD_DIR); }
};

}  // namespace

TEST_P(Cut, NoWordIsCutWithoutAMarkAt80x24OnTheLathe) {
    walk_machine("lathe", "data/demo/lathe_p300.iso");
}

TEST_P(Cut, NoWordIsCutWithoutAMarkAt80x24OnTheMill) {
    walk_machine("mill", "data/demo/mill_p300_g19.iso");
}

INSTANTIATE_TEST_SUITE_P(Languages, Cut, ::testing::Values("en", "fr"));

TEST(CutMark, ACutTextEndsWithAMark) {
    pages::Canvas c(10, 1);
    c.text(0, 0, "abcdefghijkl");
    EXPECT_EQ(c.to_text(), "abcdefghi\u2026\n");
    EXPECT_EQ(c.cuts(), 1);
    c.clear();
    c.text(0, 0, "abc        ");  // only blanks cut: no mark
    EXPECT_EQ(c.cuts(), 0);
    c.text(2, 0, "XY");
    EXPECT_EQ(c.overwrites(), 1);  // the c of "abc"
}
