// What a student and a newcomer found (issue 38): work that could still be
// lost in EDIT, the selected program after a kill, a console that guides
// (text typed on the wrong page, a question answered by one key, a screen too
// small to act on, an IMD block too long), and another console's news.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/console/fixture.hpp"

using namespace pupitre;
using pupitre::test::Console;

namespace {

// A store file of this test's own, removed with its journals at the end.
struct TempStore {
    std::string path;
    explicit TempStore(const std::string& name)
        : path(::testing::TempDir() + "/" + name + "_" + std::to_string(::getpid()) + ".db") {
        wipe();
    }
    ~TempStore() { wipe(); }
    void wipe() const {
        for (const char* ext : {"", "-wal", "-shm", "-journal"}) std::remove((path + ext).c_str());
        std::filesystem::remove_all(path + ".recover");
    }
    std::unique_ptr<store::Store> open() const {
        auto r = store::Store::open(path);
        EXPECT_FALSE(r.error) << r.error.message;
        return std::move(r.value);
    }
    std::string journal(int n) const {
        std::ifstream f(path + ".recover/" + std::to_string(n) + ".iso");
        std::stringstream ss;
        ss << f.rdbuf();
        return ss.str();
    }
};

bool has(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

std::string editor_text(const Console& c) {
    return c.s->editor.text();
}

}  // namespace

// Item 6: the program selected is kept when it is selected, not at exit.
TEST(Newcomer, TheSelectedProgramIsStoredWhenSelected) {
    TempStore st("selected");
    Console c("lathe", {}, st.open());
    c.type(":load 300");
    auto r = c.s->store()->setting("console.program.lathe");
    ASSERT_FALSE(r.error);
    ASSERT_TRUE(r.value.has_value());
    EXPECT_EQ(*r.value, "300");
}

// Item 7: what a signal leaves says where the work is.
TEST(Newcomer, UnsavedWorkAtASignalNamesItsJournal) {
    TempStore st("signal_note");
    Console c("lathe", {}, st.open());
    EXPECT_EQ(c.s->unsaved_note(), "");
    c.type(":edit 500");
    EXPECT_EQ(c.s->unsaved_note(), "");
    c.type("N50 M2");
    EXPECT_TRUE(has(c.s->unsaved_note(), st.path + ".recover/500.iso")) << c.s->unsaved_note();
    c.type(":save");
    EXPECT_EQ(c.s->unsaved_note(), "");
}

// Item 19: :mode's usage names every word it takes.
TEST(Newcomer, ModeUsageNamesEditAndModif) {
    Console c;
    c.type(":mode xyz");
    EXPECT_TRUE(has(c.message(), "|edit|modif")) << c.message();
}

// Item 20: after another program's import, this console's own settings are
// no news, even those that hold fractions of a µm (a touch-off's PREF).
TEST(Newcomer, AnImportElsewhereDoesNotListThisConsolesOwnSettings) {
    TempStore st("own_news");
    Console a("lathe", {}, st.open());
    a.type(":set PREF.Z=-250.0004");
    a.type(":set D1.X=10.00037");
    a.s->tick(1.0);  // the poll sees nothing new
    auto other = st.open();
    ASSERT_FALSE(other->save(777, "%777\nN10 M2\n", store::kNew, "import").error);
    a.s->tick(1.0);
    EXPECT_TRUE(has(a.message(), "%777")) << a.message();
    EXPECT_FALSE(has(a.message(), "PREF.Z")) << a.message();
    EXPECT_FALSE(has(a.message(), "D1.X")) << a.message();
}
