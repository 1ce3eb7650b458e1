// The witness cut (seed 003:802-808): :witness and :tangent set the active
// tool's corrector from a turned diameter and face, on a NUM lathe and on the
// Cazeneuve, whose pages and store keep it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>

#include "tests/console/fixture.hpp"

using namespace pupitre;
using pupitre::test::Console;

// On a NUM lathe the witness's diameter is typed as the micrometer reads it,
// and :tangent X measures the active corrector from it as a diameter.
TEST(Witness, TangentSetsTheActiveCorrectorFromTheWitness) {
    Console c;
    setter_lathe(c);  // T1 D1 at OM X 150 (radius) Z 200, PREF 0
    c.type(":tangent X");
    EXPECT_NE(c.message().find("no witness cut yet"), std::string::npos) << c.message();
    c.type(":witness 100 5");
    EXPECT_NE(c.message().find("face at Z 5.000"), std::string::npos) << c.message();
    c.type(":tangent X");
    double x = 0, z = 0;
    ASSERT_TRUE(c.s->sim().interp().get("D1.X", x));
    EXPECT_NEAR(x, 100, 1e-9);  // OM 150 less the witness's radius 50
    c.type(":tangent Z");
    ASSERT_TRUE(c.s->sim().interp().get("D1.Z", z));
    EXPECT_NEAR(z, 195, 1e-9);  // OM 200 less the face's Z 5
    c.type(":undo");
    c.s->sim().interp().get("D1.Z", z);
    EXPECT_NEAR(z, 38.237, 1e-9);
    c.type(":tangent Q");
    EXPECT_NE(c.message().find(":tangent X|Z"), std::string::npos);
    c.type(":witness -3");
    EXPECT_NE(c.message().find("usage"), std::string::npos);
    c.type(":witness off");
    c.type(":witness");
    EXPECT_NE(c.message().find("no witness cut"), std::string::npos);
}

// :touch on the CORR page sets PREF, as everywhere; the message says so
// first, with what the page takes for the corrector (found by keys: a
// student touching a tool off typed :touch there and broke PREF).
TEST(Witness, TouchOnTheCorrPageSaysItSetPref) {
    Console c;
    setter_lathe(c);
    c.type(":page corr");
    c.type(":touch X 60");
    EXPECT_EQ(c.message().rfind(":touch set PREF, not D1 (here type X 60.000; :undo): PREF.X", 0),
              0u)
        << c.message();
    c.type(":undo");
    c.type(":page pref");
    c.type(":touch X 60");
    EXPECT_EQ(c.message().rfind("PREF.X (radius) = ", 0), 0u) << c.message();
}

// On the Cazeneuve, X is a radius and the corrector is T's last two digits;
// the witness stays in the store with the machine's correctors.
TEST(Witness, CazeneuveTangentKeptInTheStore) {
    std::string path = ::testing::TempDir() + "/witness_test_" + std::to_string(::getpid()) + ".db";
    std::remove(path.c_str());
    // A file of an earlier process with this pid leaves no WAL behind.
    std::remove((path + "-wal").c_str()), std::remove((path + "-shm").c_str());
    {
        auto opened = store::Store::open(path);
        ASSERT_FALSE(opened.error) << opened.error.message;
        Console c("cazeneuve", {}, std::move(opened.value));
        c.type(":mode pom");
        c.named("F9");
        c.run_until_settled();
        c.type(":mode imd");
        c.type("T204");
        c.named("F9");
        c.run_until_settled();
        ASSERT_EQ(c.s->sim().corrector(), 4);
        c.type(":witness 58");
        c.type(":tangent X");  // OM X 200 (radius), the witness's radius 29
        double x = 0;
        ASSERT_TRUE(c.s->sim().interp().get("D4.X", x));
        EXPECT_NEAR(x, 171, 1e-9);
        // The rear turret (positions 11-14) touches it behind the axis, X < 0.
        c.type("T1111");
        c.named("F9");
        c.run_until_settled();
        c.type(":tangent X");
        double x11 = 0;
        ASSERT_TRUE(c.s->sim().interp().get("D11.X", x11));
        EXPECT_NEAR(x11, 229, 1e-9);  // OM X 200 less the surface at -29
        c.type(":page corr");
        EXPECT_NE(c.s->view().witness.find("58.000"), std::string::npos);
        // No PARAM page on this controller: F5 goes PREF, CORR, PREF.
        c.named("F5");
        EXPECT_EQ(c.s->page(), pages::PageId::pref);
        c.named("F5");
        EXPECT_EQ(c.s->page(), pages::PageId::corr);
    }
    auto again = store::Store::open(path);
    ASSERT_FALSE(again.error);
    Console c("cazeneuve", {}, std::move(again.value));
    c.type(":witness");
    EXPECT_NE(c.message().find("witness cut: \u00f858.000, face at Z 0.000"), std::string::npos)
        << c.message();
    double x = 0;
    c.s->sim().interp().get("D4.X", x);
    EXPECT_NEAR(x, 171, 1e-9);
    std::remove(path.c_str());
}

// The Cazeneuve's controller has no L or E variables: what is typed on the
// PARAM page (reached by :page param) is refused, not set.
TEST(Witness, CazeneuveHasNoVariablesToSet) {
    Console c("cazeneuve", {});
    c.type(":page param");
    c.type("L5=2");
    EXPECT_NE(c.message().find("no L variables"), std::string::npos) << c.message();
    EXPECT_EQ(c.s->sim().interp().lvars().v[5], 0);
}
