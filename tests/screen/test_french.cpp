// No English left in the French console (issue 38 item 9): the machine's
// name on the status line, HELP's pages, modes and directions, the setup's
// description, and the instruments typed with their French words.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/i18n.hpp"
#include "pages/canvas.hpp"
#include "tests/console/fixture.hpp"

using namespace pupitre;
using pupitre::test::Console;

namespace {

struct French : ::testing::Test {
    void SetUp() override { i18n::init("fr", PUPITRE_LOCALE_BUILD_DIR); }
    void TearDown() override { i18n::init("en", PUPITRE_LOCALE_BUILD_DIR); }
};

bool has(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

// Every line of the HELP page.
std::string help_text(Console& c) {
    c.type(":page help");
    pages::Canvas tall(80, 400);
    pages::render_screen(c.s->view(), tall);
    return tall.to_text();
}

}  // namespace

TEST_F(French, TheStatusLineNamesTheLatheTour) {
    Console c;
    const std::string first = c.screen().substr(0, c.screen().find('\n'));
    EXPECT_TRUE(has(first, " tour ")) << first;
    EXPECT_FALSE(has(first, "lathe")) << first;
}

TEST_F(French, HelpSaysPagesModesAndDirectionsInFrench) {
    Console c;
    const std::string h = help_text(c);
    for (const char* english :
         {"la page help", "la page alarm", "la page shop", "le mode edit", "zoom in", "zoom out",
          "(left)", "(up)", "(home)", "page edit)", "page graph)"})
        EXPECT_FALSE(has(h, english)) << english << "\n" << h;
    EXPECT_TRUE(has(h, "la page AIDE")) << h;
    EXPECT_TRUE(has(h, "zoom avant")) << h;
    EXPECT_TRUE(has(h, "(gauche)")) << h;
    // The keys as a French keyboard labels them, in the key column and the text.
    EXPECT_TRUE(has(h, "   Entrée ")) << h;
    EXPECT_TRUE(has(h, "   Suppr ")) << h;
    EXPECT_FALSE(has(h, "Escape la vide")) << h;
}

TEST_F(French, TheSetupAndTheInstrumentsSpeakFrench) {
    Console c;
    c.type(":setup lathe");
    c.type(":page shop");
    const std::string shop = c.screen();
    EXPECT_TRUE(has(shop, "mandrin trois mors")) << shop;
    EXPECT_TRUE(has(shop, "longueur")) << shop;
    c.type("longueur");
    EXPECT_TRUE(has(c.message(), "= 95.00 mm")) << c.message();
    c.type(":measure diam Z-20");
    EXPECT_TRUE(has(c.message(), "= 60.000 mm")) << c.message();
    c.type(":measure outil T1 X");
    EXPECT_FALSE(c.s->view().message_error) << c.message();
}
