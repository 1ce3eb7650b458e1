// Key dispatch and the console's behaviour, without a terminal: what a student
// does at the panel, checked on the session and the simulated machine.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <set>
#include <sstream>

#include "console/bindings.hpp"
#include "console/commands.hpp"
#include "core/digest.hpp"
#include "tests/console/fixture.hpp"

using namespace pupitre;
using pupitre::test::Console;

namespace {

double x_display(const Console& c) {
    return c.s->sim().to_display(X, c.s->sim().op()[X]);
}

}  // namespace

TEST(Session, FunctionKeysSelectPages) {
    Console c;
    c.named("F6");
    EXPECT_EQ(c.s->page(), pages::PageId::dir);
    c.named("F1");
    EXPECT_EQ(c.s->page(), pages::PageId::help);
    c.named("F2");
    EXPECT_EQ(c.s->page(), pages::PageId::op);
    c.named("F2");  // toggles OP and OM
    EXPECT_EQ(c.s->page(), pages::PageId::om);
    c.type(":page alarm");
    EXPECT_EQ(c.s->page(), pages::PageId::alarm);
}

TEST(Session, TextGoesToTheInputLineUntilEnter) {
    Console c;
    c.key(":pa");
    EXPECT_EQ(c.input.text(), ":pa");
    c.key("ge info\r");
    EXPECT_EQ(c.s->page(), pages::PageId::info);
    EXPECT_EQ(c.input.text(), "");
}

TEST(Session, DirPageLoadsWithEnterAndDeletesOnlyWithAStore) {
    Console c("lathe", {"data/demo/lathe_p300.iso", "tests/golden/programs/css_lathe.iso"});
    c.named("F6");
    ASSERT_GE(c.s->programs().size(), 2u);
    c.named("Down");
    EXPECT_EQ(c.s->dir_cursor(), 1);
    c.named("Up");
    c.named("Enter");
    EXPECT_EQ(c.s->sim().selected(), 300);
    c.named("Del");
    c.named("Del");
    EXPECT_NE(c.message().find("no store"), std::string::npos);
}

TEST(Session, AutoRunsTheDemoToM02AfterPom) {
    Console c;
    c.type(":load 300");
    c.named("F9");  // Cycle Start in AUTO before the POM
    c.run_until_settled();
    ASSERT_EQ(c.s->sim().state(), RunState::alarm);
    EXPECT_EQ(c.s->sim().alarms().back().diag.code, 159);
    EXPECT_NE(c.message().find("ALARM 159"), std::string::npos);
    c.named("F12");  // RAZ
    EXPECT_EQ(c.s->sim().state(), RunState::idle);
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    EXPECT_TRUE(c.s->sim().interp().homed(X));
    c.type(":mode auto");
    c.type(":speed x10");
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::ended);
    EXPECT_NE(c.message().find("M02"), std::string::npos);
    EXPECT_NEAR(x_display(c), 150.0, 1e-6);  // N100 G00 X150 (a diameter)
    EXPECT_GT(c.s->sim().cycle_time(), 10.0);
}

TEST(Session, SingleBlockStopsAfterEachBlock) {
    Console c;
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 300");
    c.type(":mode seq");
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::block);
    int first = c.s->sim().loc().line;
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::block);
    EXPECT_EQ(c.s->sim().loc().line, first + 1);
}

TEST(Session, FeedHoldFreezesAndCycleStartResumes) {
    Console c;
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 300");
    c.type(":mode auto");
    c.named("F9");
    for (int i = 0; i < 30 * 8; ++i) c.s->tick(1.0 / 30);
    c.named("F10");
    EXPECT_EQ(c.s->sim().state(), RunState::hold);
    Axes before = c.s->sim().om();
    for (int i = 0; i < 30; ++i) c.s->tick(1.0 / 30);
    EXPECT_EQ(c.s->sim().om(), before);
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::ended);
}

TEST(Session, ImdBlockRunsOnCycleStart) {
    Console c("mill", {});
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":mode imd");
    c.type("G0 X10 Y20 Z30");
    EXPECT_EQ(c.s->sim().state(), RunState::idle);  // typed, not yet run
    c.named("F9");
    c.run_until_settled();
    Axes op = c.s->sim().op();
    EXPECT_NEAR(op[X], 10, 1e-9);
    EXPECT_NEAR(op[Y], 20, 1e-9);
    EXPECT_NEAR(op[Z], 30, 1e-9);
    EXPECT_EQ(c.s->sim().state(), RunState::ended);
    // The modal state carries over: an incremental block moves from there.
    c.type("G91 G1 X5 F1000");
    c.named("F9");
    c.run_until_settled();
    EXPECT_NEAR(c.s->sim().op()[X], 15, 1e-9);
    EXPECT_EQ(c.input.history().back(), "G91 G1 X5 F1000");
}

TEST(Session, ImdErrorIsAnAlarmWithItsNumber) {
    Console c("mill", {});
    c.type(":mode imd");
    c.type("G2 X10 Y0 R2");  // end point farther than 2 R: error 107
    c.named("F9");
    c.run_until_settled();
    ASSERT_EQ(c.s->sim().state(), RunState::alarm);
    EXPECT_NE(c.message().find("ALARM"), std::string::npos);
    c.named("F9");  // refused until RAZ
    EXPECT_NE(c.message().find("RAZ"), std::string::npos);
}

TEST(Session, JogKeysMoveOnlyInJogModes) {
    Console c;
    double x0 = x_display(c);
    c.named("Up");  // AUTO: Up is the input line's history, nothing moves
    c.run_until_settled();
    EXPECT_DOUBLE_EQ(x_display(c), x0);
    c.type(":mode inc");
    c.type(":inc 1");
    c.named("Down");
    c.run_until_settled();
    EXPECT_NEAR(x_display(c), x0 - 1, 1e-9);  // one step of the diameter
    c.named("M-i");
    EXPECT_DOUBLE_EQ(c.s->sim().increment, 10);
    c.type(":jog Z -2.5");
    c.run_until_settled();
    EXPECT_NEAR(c.s->sim().op()[Z], 200 - 2.5, 1e-9);
}

TEST(Session, JogBeyondTheTravelIsRefusedWithTheAxisError) {
    Console c("mill", {});
    c.type(":jog X 5000");
    EXPECT_NE(c.message().find("error 150"), std::string::npos);
    c.type(":jog Y -5000");
    EXPECT_NE(c.message().find("error 151"), std::string::npos);
}

TEST(Session, OverridesAndSwitches) {
    Console c;
    c.named("M--");
    EXPECT_EQ(c.s->sim().feed_override, 90);
    for (int i = 0; i < 20; ++i) c.named("M-=");
    EXPECT_EQ(c.s->sim().feed_override, 120);
    c.named("M-[");
    EXPECT_EQ(c.s->sim().spindle_override, 90);
    c.named("M-b");
    EXPECT_TRUE(c.s->sim().block_skip());
    c.type(":m01 on");
    EXPECT_TRUE(c.s->sim().optional_stop());
    c.type(":feed 200");
    EXPECT_NE(c.message().find("usage"), std::string::npos);
}

TEST(Session, RnsRebuildsTheStateAndRejoins) {
    Console c;
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 300");
    c.type(":mode rns");
    c.type("N90");
    c.named("F9");
    c.run_until_settled();
    ASSERT_EQ(c.s->sim().state(), RunState::stopped) << c.message();
    EXPECT_NE(c.message().find("N90 found"), std::string::npos);
    EXPECT_EQ(c.s->sim().tool(), 1);         // T01 M06 was read
    EXPECT_EQ(c.s->sim().spindle_dir(), 4);  // and the spindle state rebuilt
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::ended);
    EXPECT_EQ(c.s->sim().mode(), Mode::automatic);
}

TEST(Session, TestModeChecksWithoutMoving) {
    Console c("lathe", {"data/demo/lathe_p300.iso"});
    c.type(":load 300");
    c.type(":mode test");
    Axes before = c.s->sim().om();
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::ended);
    EXPECT_NE(c.message().find("TEST %300: no error"), std::string::npos) << c.message();
    EXPECT_EQ(c.s->sim().om(), before);
}

TEST(Session, ModeChangeIsRefusedInCycle) {
    Console c;
    c.type(":mode pom");
    c.named("F9");
    c.type(":mode auto");  // refused: the POM is in cycle
    EXPECT_EQ(c.s->sim().mode(), Mode::pom);
    c.run_until_settled();
    c.type(":load 300");
    c.type(":mode auto");
    c.named("F9");
    c.s->tick(0.1);
    c.named("F8");
    EXPECT_EQ(c.s->sim().mode(), Mode::automatic);
    EXPECT_NE(c.message().find("in cycle"), std::string::npos);
}

TEST(Session, SetValuesAsTheCommandLineNamesThem) {
    Console c;
    c.type(":set L5=2");
    EXPECT_EQ(c.s->sim().interp().lvars().v[5], 2);
    c.type(":page param");
    c.type("L100=7.5");
    EXPECT_EQ(c.s->sim().interp().lvars().v[100], 7.5);
    c.type(":set PREF.Z=-120.5");
    EXPECT_NEAR(c.s->sim().interp().frames().pref[Z], -120.5, 1e-9);
    c.type(":set NOPE=1");
    EXPECT_NE(c.message().find("NOPE"), std::string::npos);
}

TEST(Session, CtrlCQuits) {
    Console c;
    c.key("\x03");
    EXPECT_TRUE(c.s->quitting());
}

TEST(Session, UnknownCommandsSayHowToFindTheRightOne) {
    Console c;
    c.type(":frobnicate");
    EXPECT_NE(c.message().find("unknown command"), std::string::npos);
    c.type(":page nowhere");
    EXPECT_NE(c.message().find("usage: :page"), std::string::npos);
}

TEST(Session, CompletionOfCodesAndCommands) {
    Console c;
    auto g = c.s->complete("G4");
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(g.front().substr(0, 3), "G40");
    auto m = c.s->complete("m0");
    EXPECT_FALSE(m.empty());
    auto cmd = c.s->complete(":mo");
    ASSERT_EQ(cmd.size(), 1u);
    EXPECT_EQ(cmd[0], ":mode");
    // Every command completes, even one the HELP page tells of on another's
    // line (:restore); aliases and '!' forms do not (:q, :quit!).
    EXPECT_EQ(c.s->complete(":re"), (std::vector<std::string>{":renum", ":restore", ":recover"}));
    EXPECT_EQ(c.s->complete(":q"), std::vector<std::string>{":quit"});
}

TEST(Session, EveryNameOfTheCommandTableIsACommandOfItsOwn) {
    std::set<std::string> seen;
    for (const console::Command& cmd : console::commands()) {
        if (!cmd.run) {  // a further HELP line, for a command another row runs
            EXPECT_TRUE(cmd.names.empty()) << cmd.usage;
            EXPECT_FALSE(cmd.usage.empty());
            continue;
        }
        std::istringstream names{std::string(cmd.names)};
        for (std::string name; names >> name;) {
            EXPECT_TRUE(seen.insert(name).second) << ":" << name << " is in two rows";
            Console c;
            c.s->command(name);
            EXPECT_EQ(c.message().find("unknown command"), std::string::npos) << ":" << name;
        }
    }
    EXPECT_GE(seen.size(), 33u);
}

TEST(Bindings, TheShippedTableParsesAndNamesKnownActions) {
    console::Bindings b;
    EXPECT_EQ(b.parse(console::default_bindings(), "bindings"), "");
    EXPECT_GT(b.list().size(), 30u);
}

TEST(Bindings, ErrorsNameTheLine) {
    console::Bindings b;
    EXPECT_EQ(b.parse("F1 page help\nF99 page op\n", "user"), "user:2: 'F99' is not a key name");
    EXPECT_EQ(b.parse("F1 fly\n", "user"), "user:1: 'fly' is not an action");
    EXPECT_EQ(b.parse("F1 page op @planet=mars\n", "user"),
              "user:1: unknown context 'planet=mars'");
}

TEST(Bindings, UserLinesWinAndContextsAreMoreSpecific) {
    Console c;
    c.s->add_bindings("F1 page dir\n", "user");
    c.named("F1");
    EXPECT_EQ(c.s->page(), pages::PageId::dir);
    // On the DIR page, Down moves the cursor; elsewhere it is the history.
    c.named("Down");
    EXPECT_EQ(c.s->page(), pages::PageId::dir);
}

TEST(Bindings, HelpAndSoftKeysComeFromTheTable) {
    Console c;
    pages::View v = c.s->view();
    ASSERT_EQ(v.softkeys.size(), 10u);
    EXPECT_EQ(v.softkeys[8].label, "START");
    bool raz = false, cmd = false;
    for (const auto& h : v.help) {
        raz |= h.key == "F12" && h.what.find("RAZ") != std::string::npos;
        cmd |= h.key.rfind(":mode", 0) == 0;
    }
    EXPECT_TRUE(raz);
    EXPECT_TRUE(cmd);
}

// ---- setting: PREF, CORR, touch-off, measurement, undo, protection ----

namespace {}  // namespace

TEST(Setting, TouchOffThePrefOfZAndXAndTheOpPageAgrees) {
    Console c;
    setter_lathe(c);
    c.type(":jog Z -100");
    c.type(":jog X -80");  // the diameter shown
    c.run_until_settled();
    c.type(":page pref");
    c.type("Z 0");  // the tool touches the face
    EXPECT_NE(c.message().find("PREF.Z = OM"), std::string::npos) << c.message();
    c.type("X 59.978");  // and a turned diameter
    const Interpreter& in = c.s->sim().interp();
    // OM Z = 100, OM X = 150 - 40 = 110 (radius): PREF = OM - gauge - surface.
    EXPECT_NEAR(in.frames().pref[Z], 100 - 38.237 - 0, 1e-9);
    EXPECT_NEAR(in.frames().pref[X], 110 - 63.345 - 29.989, 1e-9);
    // A move to the touched surface, the gauges applied, leaves the turret
    // where it was when the tool touched.
    Axes touched = c.s->sim().om();
    EXPECT_NEAR(c.s->sim().op()[Z], 0, 1e-9);  // the OP page reads the surface at once
    EXPECT_NEAR(c.s->sim().to_display(X, c.s->sim().op()[X]), 59.978, 1e-9);
    c.type(":page op");
    c.type(":mode imd");
    c.type("G0 X59.978 Z0");
    c.named("F9");
    c.run_until_settled();
    EXPECT_NEAR(c.s->sim().om()[Z], touched[Z], 1e-9);
    EXPECT_NEAR(c.s->sim().om()[X], touched[X], 1e-9);
    EXPECT_NEAR(c.s->sim().op()[Z], 0, 1e-9);
}

TEST(Setting, MeasureAToolByATouchedDiameterOnTheCorrPage) {
    Console c;
    setter_lathe(c);
    c.type(":set PREF.X=0");
    c.type(":page corr");
    c.type("D2");
    EXPECT_EQ(c.s->setting().corrector(), 2);
    c.type("Z=41.5");  // presetter reading
    double z;
    ASSERT_TRUE(c.s->sim().interp().get("D2.Z", z));
    EXPECT_DOUBLE_EQ(z, 41.5);
    c.type("X 100");  // touching Ø100 with the turret at OM X 150 (radius): gauge 100
    // D2 is not the active corrector: the CORR page asks first (issue 12.5).
    EXPECT_NE(c.message().find("D2 is not the active corrector"), std::string::npos) << c.message();
    c.type("y");
    double x;
    ASSERT_TRUE(c.s->sim().interp().get("D2.X", x));
    EXPECT_NEAR(x, 100, 1e-9);
    c.type(":measure D3 Z 0");
    double z3;
    c.s->sim().interp().get("D3.Z", z3);
    EXPECT_NEAR(z3, 200, 1e-9);  // OM Z 200 with PREF Z 0
    EXPECT_EQ(c.s->setting().corrector(), 3);
}

TEST(Setting, UndoRestoresTheLastChange) {
    Console c;
    c.type(":set PREF.Z=-300");
    c.type(":set PREF.Z=-310");
    c.named("C-z");
    EXPECT_DOUBLE_EQ(c.s->sim().interp().frames().pref[Z], -300);
    c.type(":undo");
    EXPECT_DOUBLE_EQ(c.s->sim().interp().frames().pref[Z], 0);
    c.type(":undo");
    EXPECT_NE(c.message().find("nothing to undo"), std::string::npos);
}

TEST(Setting, ProtectionLocksOriginsAndCorrectors) {
    Console c;
    c.named("M-k");
    EXPECT_TRUE(c.s->setting().locked());
    c.type(":set PREF.Z=-300");
    EXPECT_NE(c.message().find("memory protection is on"), std::string::npos);
    EXPECT_DOUBLE_EQ(c.s->sim().interp().frames().pref[Z], 0);
    c.type(":touch Z 0");
    EXPECT_DOUBLE_EQ(c.s->sim().interp().frames().pref[Z], 0);
    c.type(":protect off");
    EXPECT_FALSE(c.s->setting().locked());
}

TEST(Setting, AGaugeChangedDuringARunIsPendingUntilItsAxisMoves) {
    Console c("lathe", {"tests/console/programs/gauge_change.iso"});
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 950");
    c.type(":mode seq");
    c.named("F9");
    c.run_until_settled();
    for (int i = 0; i < 3; ++i) {  // up to N40 G0 X40 Z40
        c.named("F9");
        c.run_until_settled();
    }
    c.type(":set D1.Z=5");
    EXPECT_TRUE(c.s->sim().interp().gauge_pending(Z));
    c.type(":page corr");
    EXPECT_NE(c.screen().find("5.000*"), std::string::npos);
    c.named("F9");  // N50 G0 X50: Z does not move, still pending
    c.run_until_settled();
    EXPECT_TRUE(c.s->sim().interp().gauge_pending(Z));
    c.named("F9");  // N60 G0 Z60: applied
    c.run_until_settled();
    EXPECT_FALSE(c.s->sim().interp().gauge_pending(Z));
    EXPECT_DOUBLE_EQ(c.s->sim().interp().frames().gauge[Z], 5);
}

// ---- EDIT and MODIF ----

TEST(Edit, ANewProgramTypedSavedAndRun) {
    Console c("mill", {});
    c.type(":edit 777");
    EXPECT_EQ(c.s->page(), pages::PageId::edit);
    c.type("N10 G0 X10 Y10 Z10");
    c.type("N20 M2");
    EXPECT_TRUE(c.s->editing().editor().dirty);
    c.type(":save");
    EXPECT_NE(c.message().find("%777 saved"), std::string::npos) << c.message();
    ASSERT_NE(c.s->memory().find(777), nullptr);
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":mode auto");
    c.type(":load 777");
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->sim().state(), RunState::ended);
    EXPECT_NEAR(c.s->sim().op()[X], 10, 1e-9);
}

// Six-digit line numbers are written whole in the EDIT margin (five columns
// cut 100004 to 10000).
TEST(Edit, LineNumbersPast99999AreWrittenWhole) {
    Console c("mill", {});
    std::string text = "%780\n";
    for (int i = 2; i <= 100010; ++i) text += "G1 X1 (L" + std::to_string(i) + ")\n";
    text += "M2\n";
    const std::optional<Diag> d = c.s->memory().load_text("long.iso", text);
    ASSERT_FALSE(d) << d->detail;
    c.type(":edit 780");
    ASSERT_EQ(c.s->page(), pages::PageId::edit);
    c.s->editing().editor().cursor = 100005;  // line 100006
    std::string screen = c.screen();
    EXPECT_NE(screen.find("100004  G1 X1 (L100004)"), std::string::npos) << screen;
    EXPECT_NE(screen.find("100006 >G1 X1 (L100006)"), std::string::npos) << screen;
}

TEST(Edit, SavingABadBlockPutsTheCursorOnItWithItsNumber) {
    Console c("mill", {});
    c.type(":edit 778");
    c.type("N10 G0 X10");
    c.type("N20 G1 X5 (NO END");
    c.type("N30 M2");
    c.type(":save");
    EXPECT_NE(c.message().find("line 3 N20: error 17"), std::string::npos) << c.message();
    EXPECT_EQ(c.s->editing().editor().cursor, 2);
    EXPECT_EQ(c.s->memory().find(778), nullptr);  // not saved
    // Enter puts the block on the input line; the corrected text replaces it.
    c.named("Enter");
    EXPECT_EQ(c.input.text(), "N20 G1 X5 (NO END");
    c.key(")");
    c.key("\r");
    EXPECT_EQ(c.s->editing().editor().lines()[2], "N20 G1 X5 (NO END)");
    c.type(":save");
    EXPECT_NE(c.s->memory().find(778), nullptr);
}

TEST(Edit, KeysMoveDeleteCopyAndPaste) {
    Console c("mill", {});
    c.type(":edit 779");
    c.type("A1");
    c.type("B2");
    c.named("Up");
    EXPECT_EQ(c.s->editing().editor().cursor, 1);
    c.named("M-w");  // copy A1
    c.named("End");
    c.named("C-y");  // paste after B2
    EXPECT_EQ(c.s->editing().editor().text(), "%779\nA1\nB2\nA1\n");
    c.named("Home");
    c.named("Down");
    c.named("Del");
    EXPECT_EQ(c.s->editing().editor().text(), "%779\nB2\nA1\n");
    c.type(":goto N1");
    EXPECT_NE(c.message().find("no block"), std::string::npos);
}

TEST(Modif, AChangedBlockRunsAfterSingleBlock) {
    Console c("lathe", {"tests/console/programs/gauge_change.iso"});
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 950");
    c.type(":mode seq");
    for (int i = 0; i < 4; ++i) {  // N10 .. N40
        c.named("F9");
        c.run_until_settled();
    }
    ASSERT_EQ(c.s->sim().state(), RunState::block);
    c.type(":mode modif");
    ASSERT_TRUE(c.s->editing().modif()) << c.message();
    EXPECT_EQ(c.s->editing().editor().lines()[size_t(c.s->editing().editor().cursor)],
              "N50 G0 X50");
    c.s->editing().editor().cursor = 3;  // N30: already run
    c.named("Enter");
    EXPECT_NE(c.message().find("already prepared"), std::string::npos);
    c.s->editing().editor().cursor = 5;
    c.named("Enter");
    c.key("\x15");  // Ctrl-U
    c.type("N50 G0 X56");
    c.named("F9");  // the changed N50 runs
    c.run_until_settled();
    EXPECT_FALSE(c.s->editing().modif());
    EXPECT_NEAR(c.s->sim().to_display(X, c.s->sim().op()[X]), 56, 1e-9);
    EXPECT_NE(std::string(*c.s->memory().find(950)->text).find("N50 G0 X56"), std::string::npos);
    c.named("F9");
    c.run_until_settled();
    EXPECT_NEAR(c.s->sim().op()[Z], 60, 1e-9);  // and the run goes on
}

TEST(Modif, M999ForbidsModifAndImd) {
    Console c("mill", {"tests/console/programs/m999.iso"});
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 951");
    c.type(":mode auto");
    c.named("F9");
    c.run_until_settled();
    ASSERT_EQ(c.s->sim().state(), RunState::stopped);  // the M00 after M999
    c.type(":mode modif");
    EXPECT_NE(c.message().find("M999"), std::string::npos);
    EXPECT_FALSE(c.s->editing().modif());
}

TEST(Setting, ThePinIsNeededToUnlockAndIsNotStoredInClear) {
    std::string path = ::testing::TempDir() + "/pin_test_" + std::to_string(::getpid()) + ".db";
    std::remove(path.c_str());
    // A file of an earlier process with this pid leaves no WAL behind.
    std::remove((path + "-wal").c_str()), std::remove((path + "-shm").c_str());
    auto opened = store::Store::open(path);
    ASSERT_FALSE(opened.error) << opened.error.message;
    {
        Console c("lathe", {}, std::move(opened.value));
        c.type(":protect pin 4321");
        c.type(":protect on");
        EXPECT_TRUE(c.s->setting().locked());
        c.type(":protect off 1234");
        EXPECT_TRUE(c.s->setting().locked());
        EXPECT_NE(c.message().find("wrong PIN"), std::string::npos);
        c.type(":rm 300");
        EXPECT_NE(c.message().find("memory protection is on"), std::string::npos);
        auto pin = c.s->store()->setting("protect.pin");
        ASSERT_TRUE(pin.value.has_value());
        // Kept as a random salt and the SHA-256 of salt and PIN, never the PIN:
        // the hex of a hash may happen to contain "4321", so the form is checked.
        const std::string& kept = *pin.value;
        ASSERT_EQ(kept.size(), 16u + 1u + 64u) << kept;
        ASSERT_EQ(kept[16], ':') << kept;
        std::string salt = kept.substr(0, 16);
        EXPECT_EQ(kept.substr(17), pupitre::sha256_hex(salt + "4321"));
        EXPECT_NE(kept.substr(17), pupitre::sha256_hex("4321"));
    }
    // The key stays turned across sessions.
    auto again = store::Store::open(path);
    ASSERT_FALSE(again.error);
    Console c("lathe", {}, std::move(again.value));
    EXPECT_TRUE(c.s->setting().locked());
    c.type(":protect off 4321");
    EXPECT_FALSE(c.s->setting().locked());
    std::remove(path.c_str());
}

// ---- GRAPH ----

TEST(Graph, TestDrawsTheWholeProgramAndKeysChangeTheWindow) {
    Console c;
    c.type(":load 300");
    c.type(":mode test");
    c.named("F9");
    c.run_until_settled();
    EXPECT_EQ(c.s->graph().path().size(), 7u);  // the demo's seven moves
    c.named("F3");
    c.named("F3");  // PROG, then GRAPH
    ASSERT_EQ(c.s->page(), pages::PageId::graph);
    c.key("+");
    EXPECT_FALSE(c.s->graph().window().fit);
    double scale = c.s->graph().window().scale;
    c.key("+");
    EXPECT_NEAR(c.s->graph().window().scale, scale / 2, 1e-12);
    c.key("f");
    EXPECT_TRUE(c.s->graph().window().fit);
    EXPECT_EQ(c.input.text(), "");  // the keys did not reach the input line
    EXPECT_NE(c.screen().find("GRAPH  ZX"), std::string::npos);
}

TEST(Graph, FitSaysWhatItFits) {
    Console c;
    c.named("F3");
    c.named("F3");
    ASSERT_EQ(c.s->page(), pages::PageId::graph);
    c.key("f");
    EXPECT_EQ(c.message(), "fit: the start point (no move yet)");
    c.type(":load 300");
    c.type(":mode test");
    c.named("F9");
    c.run_until_settled();
    c.key("+");
    c.key("f");
    // The demo cuts from X20 Z90 to X50 Z35; its four rapids, from and back to
    // X150 Z200, are left out, as the plot's frame leaves them out.
    EXPECT_EQ(c.message(), "fit: the cutting moves of %300 (4 rapids reach beyond)");
    EXPECT_NE(c.screen().find("GRAPH  ZX  %300"), std::string::npos);
    EXPECT_TRUE(c.s->graph().window().fit);
}

TEST(Graph, AutoDrawsAsTheMovesAreShown) {
    Console c;
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 300");
    c.type(":mode auto");
    c.named("F9");
    for (int i = 0; i < 30 * 3; ++i) c.s->tick(1.0 / 30);
    size_t partway = c.s->graph().path().size();
    EXPECT_GT(partway, 0u);
    EXPECT_LT(partway, 7u);
    c.run_until_settled();
    EXPECT_EQ(c.s->graph().path().size(), 7u);
}

// ---- G76+ / G76- in the console: the program memory is the store ----

TEST(G76, ProgramsAProgramCreatesAndDeletesAreStored) {
    // A fresh store: the database and what SQLite keeps beside it.
    std::string path = ::testing::TempDir() + "/g76_test_" + std::to_string(::getpid()) + ".db";
    auto wipe = [&] {
        for (const char* ext : {"", "-wal", "-shm", "-journal"}) std::remove((path + ext).c_str());
    };
    wipe();
    auto opened = store::Store::open(path);
    ASSERT_FALSE(opened.error) << opened.error.message;
    auto& st = *opened.value;
    ASSERT_FALSE(st.save(500,
                         "%500 (WRITES %501, DELETES %502)\nN10 L1=4.5\nN20 G76+ H501\n"
                         "N30 G76+ H501 N0 N10 G0 XL1 Y0\nN40 G76- H502\nN50 G77 H501\nN60 M2\n",
                         store::kNew, "test")
                     .error);
    ASSERT_FALSE(st.save(502, "%502\nN10 G0 X1\n", store::kNew, "test").error);
    {
        Console c("mill", {}, std::move(opened.value));
        c.type(":mode pom");
        c.named("F9");
        c.run_until_settled();
        c.type(":mode auto");
        c.type(":load 500");
        c.named("F9");
        c.run_until_settled();
        ASSERT_EQ(c.s->sim().state(), RunState::ended) << c.message();
        EXPECT_NEAR(c.s->sim().op()[X], 4.5, 1e-9);
        auto p501 = c.s->store()->read(501);
        ASSERT_FALSE(p501.error) << p501.error.message;
        EXPECT_EQ(p501.value.text, "%501\nN10 G0 X4.5 Y0\n");
        auto hist = c.s->store()->history(501);
        ASSERT_FALSE(hist.error);
        EXPECT_NE(hist.value.back().source.find("G76"), std::string::npos);
        auto list = c.s->store()->list();
        ASSERT_FALSE(list.error);
        for (const auto& info : list.value)
            if (info.number == 502) {
                EXPECT_TRUE(info.deleted);
            }
        // The DIR page shows the new program and no longer the deleted one.
        bool has501 = false, has502 = false;
        for (const auto& e : c.s->programs()) {
            has501 |= e.number == 501;
            has502 |= e.number == 502;
        }
        EXPECT_TRUE(has501);
        EXPECT_FALSE(has502);
    }
    wipe();
}

TEST(G76, UnderMemoryProtectionTheChangesStayInMemory) {
    std::string path = ::testing::TempDir() + "/g76_protect_" + std::to_string(::getpid()) + ".db";
    auto wipe = [&] {
        for (const char* ext : {"", "-wal", "-shm", "-journal"}) std::remove((path + ext).c_str());
    };
    wipe();
    {
        auto opened = store::Store::open(path);
        ASSERT_FALSE(opened.error) << opened.error.message;
        ASSERT_FALSE(
            opened.value->save(500, "%500\nN10 G76+ H501\nN20 M2\n", store::kNew, "test").error);
        Console c("mill", {}, std::move(opened.value));
        c.type(":protect on");
        c.type(":mode pom");
        c.named("F9");
        c.run_until_settled();
        c.type(":mode auto");
        c.type(":load 500");
        c.named("F9");
        c.run_until_settled();
        ASSERT_EQ(c.s->sim().state(), RunState::ended) << c.message();
        EXPECT_NE(c.s->memory().find(501), nullptr);
        EXPECT_NE(c.message().find("memory protection is on"), std::string::npos) << c.message();
        EXPECT_TRUE(c.s->store()->read(501).error);  // not stored
    }
    wipe();
}
