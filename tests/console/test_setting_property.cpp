// Issue 12.1 as a property: whatever a student does before (tool changes,
// program runs to M02, RAZ, jogs, gauges set or measured), a touch-off makes
// the OP page read the value typed, to 1 µm, and every page names the
// corrector the machine applies.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <random>

#include "tests/console/fixture.hpp"

using namespace pupitre;
using pupitre::test::Console;

namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

double shown(const Console& c, int axis) {
    return c.s->sim().to_display(axis, c.s->sim().op()[size_t(axis)]);
}

// Runs what Cycle Start starts, to its end.
void cycle(Console& c) {
    c.named("F9");
    c.run_until_settled();
}

// Answers "y" when the console asks (a touch-off with D0).
void answer(Console& c) {
    if (!c.s->question().empty()) c.type("y");
}

struct Step {
    const char* name;
    void (*run)(Console&, std::mt19937&, std::string& log);
};

int pick(std::mt19937& g, int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(g);
}
double pick_mm(std::mt19937& g, double lo, double hi) {
    return std::round(std::uniform_real_distribution<double>(lo, hi)(g) * 1000) / 1000;
}

void tool_change(Console& c, std::mt19937& g, std::string& log) {
    int t = pick(g, 1, 4), d = pick(g, 0, 4);
    std::string block = "T" + std::to_string(t) + " D" + std::to_string(d) + " M6";
    log += " [" + block + "]";
    c.type(":mode imd");
    c.type(block);
    cycle(c);
}

void set_gauge(Console& c, std::mt19937& g, std::string& log) {
    std::string s = ":set D" + std::to_string(pick(g, 1, 4)) + (pick(g, 0, 1) ? ".X=" : ".Z=") +
                    num(pick_mm(g, -20, 60));
    log += " [" + s + "]";
    c.type(s);
}

void run_program(Console& c, std::mt19937&, std::string& log) {
    log += " [run %300]";
    c.type(":mode auto");
    c.type(":load 300");
    c.type(":speed max");
    cycle(c);
    if (c.s->sim().alarm_active()) c.named("F12");
}

void raz(Console& c, std::mt19937&, std::string& log) {
    log += " [RAZ]";
    c.named("F12");
}

void jog(Console& c, std::mt19937& g, std::string& log) {
    std::string s = std::string(":jog ") + (pick(g, 0, 1) ? "X " : "Z ") + num(pick_mm(g, -40, 40));
    log += " [" + s + "]";
    c.type(":mode jog");
    c.type(s);
    c.run_until_settled();
}

void measure(Console& c, std::mt19937& g, std::string& log) {
    int d = pick(g, 1, 4), axis = pick(g, 0, 1) ? X : Z;
    double v = pick_mm(g, -50, 200);
    std::string s = ":measure D" + std::to_string(d) + (axis == X ? " X " : " Z ") + num(v);
    log += " [" + s + "]";
    c.type(s);
    // Measuring the active corrector puts its tool point on the surface too.
    if (d == c.s->sim().corrector() && c.message().find(" = OM ") != std::string::npos) {
        EXPECT_NEAR(shown(c, axis), v, 1e-3) << log;
    }
}

int g_checked = 0;  // touch-offs whose result was checked

void touch(Console& c, std::mt19937& g, std::string& log) {
    int axis = pick(g, 0, 1) ? X : Z;
    double v = pick_mm(g, -50, 250);
    std::string s = std::string(axis == X ? "X " : "Z ") + num(v);
    log += " [PREF " + s + "]";
    c.type(":page pref");
    c.type(s);
    answer(c);
    if (c.message().find("PREF.") == std::string::npos ||
        c.message().find(" = OM ") == std::string::npos) {
        return;  // refused (an alarm, travel): nothing to check
    }
    ++g_checked;
    EXPECT_NEAR(shown(c, axis), v, 1e-3) << log;
    // Every page names the corrector applied.
    std::string screen = c.screen(100, 30);
    std::string d = "D" + std::to_string(c.s->sim().corrector());
    EXPECT_NE(screen.find("active corrector " + d), std::string::npos) << log << "\n" << screen;
    EXPECT_EQ(c.s->sim().corrector(), c.s->sim().interp().modal().d) << log;
}

const Step kSteps[] = {
    {"tool", tool_change}, {"gauge", set_gauge}, {"run", run_program}, {"raz", raz},
    {"jog", jog},          {"measure", measure}, {"touch", touch},     {"touch", touch},
};

}  // namespace

TEST(SettingProperty, TouchOffReadsWhatWasTypedAfterAnySequence) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        Console c;
        std::mt19937 g(seed);
        c.type(":mode pom");
        cycle(c);
        std::string log = "seed " + std::to_string(seed) + ":";
        for (int i = 0; i < 40; ++i) {
            const Step& s = kSteps[size_t(pick(g, 0, int(std::size(kSteps)) - 1))];
            s.run(c, g, log);
            if (::testing::Test::HasFailure()) return;
        }
    }
    EXPECT_GT(g_checked, 60);  // most touch-offs are accepted and checked
}

TEST(SettingProperty, M02AndRazLeaveD0WithTheToolKept) {
    Console c;
    c.type(":set D1.X=10");
    c.type(":mode pom");
    cycle(c);
    c.type(":mode imd");
    c.type("T1 D1 M6");
    cycle(c);
    c.type(":mode auto");
    c.type(":load 300");
    c.type(":speed max");
    cycle(c);
    ASSERT_EQ(c.s->sim().state(), RunState::ended);
    EXPECT_EQ(c.s->sim().corrector(), 0);
    EXPECT_EQ(c.s->sim().tool(), 1);
    EXPECT_EQ(c.s->sim().interp().frames().gauge[X], 0);
    EXPECT_NEAR(shown(c, X), 150.0 + 20.0,
                1e-6);  // ends at X150 with a 10 mm radius gauge, now removed
    c.type(":page pref");
    c.type("X 150");
    EXPECT_NE(c.message().find("D0, no tool gauge (T1)"), std::string::npos) << c.message();
    EXPECT_NE(c.screen().find("y/n>"), std::string::npos) << c.screen();
    c.type("y");
    EXPECT_NEAR(shown(c, X), 150.0, 1e-6);
}

// A gauge set at rest moves the program frame at once: a jog that follows
// must not blend the old frame into OP while only Z moves (seen in tmux: OP
// X drifted from ø300 to ø173 during a Z jog).
TEST(SettingProperty, AJogAfterAGaugeChangeKeepsOpXStill) {
    Console c;
    c.type(":mode pom");
    cycle(c);
    c.type(":mode imd");
    c.type("T1 D1 M6");
    cycle(c);
    c.type(":set D1.X=63.345");
    double x0 = shown(c, X);
    EXPECT_NEAR(x0, 300 - 2 * 63.345, 1e-6);
    c.type(":mode jog");
    c.type(":jog Z -50");
    for (int i = 0; i < 10; ++i) {
        c.s->tick(0.2);
        EXPECT_NEAR(shown(c, X), x0, 1e-6) << "frame " << i;
    }
}

// A ':' command typed while the console asks y/n drops the question: it is
// never taken as "yes", and the prompt names the target again.
TEST(SettingProperty, ACommandDropsAPendingQuestion) {
    Console c;
    c.type(":page pref");
    c.type("X 150");  // D0: asks first
    ASSERT_FALSE(c.s->question().empty());
    double before = c.s->sim().interp().frames().pref[X];
    c.type(":page op");
    EXPECT_TRUE(c.s->question().empty());
    EXPECT_EQ(c.s->sim().interp().frames().pref[X], before);
    c.type("y");  // no question any more: not a confirmation
    EXPECT_EQ(c.s->sim().interp().frames().pref[X], before);
}

// Two consoles on one store (issue 12.9): a console's own writes (its edit
// lease) must not hide the other's commits from its next poll, even when its
// DIR page already listed the new revision.
TEST(SettingProperty, AnOwnLeaseDoesNotHideTheOtherConsolesSave) {
    std::string path = ::testing::TempDir() + "/two_" + std::to_string(::getpid()) + ".db";
    std::remove(path.c_str());
    // A file of an earlier process with this pid leaves no WAL behind.
    std::remove((path + "-wal").c_str()), std::remove((path + "-shm").c_str());
    auto sa = store::Store::open(path);
    ASSERT_FALSE(sa.error) << sa.error.message;
    Console a("lathe", {}, std::move(sa.value));
    auto sb = store::Store::open(path);
    ASSERT_FALSE(sb.error) << sb.error.message;
    Console b("lathe", {}, std::move(sb.value));
    a.type(":edit 300");
    a.type("N1 (FROM A)");
    a.type(":save");
    ASSERT_NE(a.message().find("saved as revision"), std::string::npos) << a.message();
    b.type(":page dir");  // lists r2 before any poll
    b.type(":edit 301");  // takes a lease: a write of its own
    b.s->tick(1.0);       // the poll
    const ProgramText* p = b.s->memory().find(300);
    ASSERT_NE(p, nullptr);
    EXPECT_NE(program_text(*p).find("FROM A"), std::string::npos) << program_text(*p);
    std::remove(path.c_str());
}

// The y/n of a touch-off with D0 answered after Cycle Start (a key, so the
// question stays): the touch-off checks again that the axes are at rest.
TEST(SettingProperty, ALateYesDoesNotTouchOffWhileTheAxesMove) {
    Console c;
    c.type(":page pref");
    c.type("Z 0");  // D0: asks first
    ASSERT_FALSE(c.s->question().empty());
    c.type(":mode pom");  // drops the question (a command); ask again
    c.type(":page pref");
    c.type("Z 0");
    ASSERT_FALSE(c.s->question().empty());
    c.named("F9");  // POM: the axes move
    ASSERT_EQ(c.s->sim().state(), RunState::running);
    double before = c.s->sim().interp().frames().pref[Z];
    c.type("y");
    EXPECT_NE(c.message().find("wait until the axes stop"), std::string::npos) << c.message();
    EXPECT_EQ(c.s->sim().interp().frames().pref[Z], before);
}

// PREF.C is the origin of a rotary axis C, an angle, and no nose orientation
// (D3.C, a code from 0 to 8): it is set where the machine has a C axis and
// refused for the axis where it has none.
TEST(SettingProperty, PrefCIsTheOriginOfAxisCNotANoseOrientation) {
    Console five("mill5", {});
    five.type(":set PREF.C=180.5");
    EXPECT_NEAR(five.s->sim().interp().frames().pref[C], 180.5, 1e-9) << five.message();
    EXPECT_EQ(five.message().find("nose orientation"), std::string::npos) << five.message();
    Console three("mill", {});
    three.type(":set PREF.C=180.5");
    EXPECT_NE(three.message().find("axis C is not on"), std::string::npos) << three.message();
    EXPECT_EQ(three.s->sim().interp().frames().pref[C], 0);
    Console lathe;
    lathe.type(":set D1.C=9");
    EXPECT_NE(lathe.message().find("the nose orientation is a code from 0 to 8"), std::string::npos)
        << lathe.message();
}
