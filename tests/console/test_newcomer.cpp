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
    return c.s->editing().editor().text();
}

}  // namespace

// Item 5: :edit N on the program open with changes asks first; "n" keeps
// the changes and the journal goes on holding them.
TEST(Newcomer, EditingTheOpenProgramAgainAsksBeforeDroppingItsChanges) {
    TempStore st("edit_again");
    Console c("lathe", {}, st.open());
    c.type(":edit 500");
    c.type("N50 M2 (IMPORTANT WORK)");
    ASSERT_TRUE(has(st.journal(500), "IMPORTANT WORK"));
    c.type(":edit 500");
    ASSERT_FALSE(c.s->question().empty()) << c.message();
    EXPECT_TRUE(has(c.message(), "unsaved changes")) << c.message();
    c.key("n");  // one key answers
    EXPECT_TRUE(c.s->question().empty());
    c.type("N60 M5");
    EXPECT_TRUE(has(editor_text(c), "IMPORTANT WORK")) << editor_text(c);
    EXPECT_TRUE(has(st.journal(500), "IMPORTANT WORK")) << st.journal(500);
    EXPECT_TRUE(has(st.journal(500), "N60 M5")) << st.journal(500);
    // "y" drops them, as asked, with their journal.
    c.type(":edit 500");
    c.key("y");
    EXPECT_FALSE(has(editor_text(c), "IMPORTANT WORK")) << editor_text(c);
    EXPECT_EQ(st.journal(500), "");
}

// Item 5, the audit: :restore over unsaved changes asks too.
TEST(Newcomer, RestoringARevisionOverUnsavedChangesAsks) {
    TempStore st("restore_dirty");
    Console c("lathe", {}, st.open());
    c.type(":edit 300");
    c.type("N1 (SAVED ONE)");
    c.type(":save");
    c.type("N2 (NOT SAVED)");
    c.type(":restore 1");
    ASSERT_FALSE(c.s->question().empty()) << c.message();
    c.key("n");
    EXPECT_TRUE(has(editor_text(c), "NOT SAVED"));
    EXPECT_TRUE(has(st.journal(300), "NOT SAVED"));
}

// Item 5, the audit: an earlier session's journal offered by :edit is not
// written over by the next key, nor dropped by :close, before :recover or
// :discard.
TEST(Newcomer, AnEarlierSessionsJournalWaitsForRecoverOrDiscard) {
    TempStore st("held_journal");
    {
        Console a("lathe", {}, st.open());
        a.type(":edit 500");
        a.type("N50 M2 (IMPORTANT WORK)");
    }  // killed: the journal stays
    ASSERT_TRUE(has(st.journal(500), "IMPORTANT WORK"));
    Console b("lathe", {}, st.open());
    b.type(":edit 500");
    EXPECT_TRUE(has(b.message(), "earlier session")) << b.message();
    b.type("N60 M5");
    EXPECT_TRUE(has(b.message(), ":recover or :discard")) << b.message();
    EXPECT_FALSE(has(editor_text(b), "N60 M5"));
    EXPECT_TRUE(has(st.journal(500), "IMPORTANT WORK")) << st.journal(500);
    b.type(":close");
    EXPECT_TRUE(has(st.journal(500), "IMPORTANT WORK")) << st.journal(500);
    b.type(":edit 500");
    b.type(":recover");
    b.type("N60 M5");
    EXPECT_TRUE(has(editor_text(b), "IMPORTANT WORK"));
    EXPECT_TRUE(has(st.journal(500), "N60 M5")) << st.journal(500);
}

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

// Item 12: an ISO block typed on CORR or PREF is refused there, and the
// message says where blocks go.
TEST(Newcomer, AnImdBlockTypedOnASettingPageIsRefusedThere) {
    Console c;
    c.type(":mode imd");
    c.type(":page corr");
    double x = 0, after = 0;
    ASSERT_TRUE(c.s->sim().interp().get("D1.X", x));
    c.type("T1 D1 M6 S500 M3");
    EXPECT_TRUE(has(c.message(), "in IMD on the OP page (F2)")) << c.message();
    EXPECT_TRUE(c.s->view().message_error);
    ASSERT_TRUE(c.s->sim().interp().get("D1.X", after));
    EXPECT_EQ(after, x);
    c.type(":page pref");
    c.type("G0 X40 Z25");
    EXPECT_TRUE(has(c.message(), "in IMD on the OP page (F2)")) << c.message();
    c.type("X40 Z25");
    EXPECT_TRUE(has(c.message(), "in IMD on the OP page (F2)")) << c.message();
    c.type("Z 0");  // still a touch-off (D0: it asks)
    EXPECT_FALSE(c.s->question().empty()) << c.message();
}

// Item 13: one key answers; a page change cancels the question and says so.
TEST(Newcomer, OneKeyAnswersAndAPageChangeCancels) {
    Console c;
    c.type(":page pref");
    c.type("Z 0");  // D0: asks
    ASSERT_FALSE(c.s->question().empty());
    c.named("F2");
    EXPECT_TRUE(c.s->question().empty());
    EXPECT_TRUE(has(c.message(), "question cancelled")) << c.message();
    c.type(":page pref");
    c.type("Z 0");
    ASSERT_FALSE(c.s->question().empty());
    const double before = c.s->sim().interp().frames().pref[Z];
    c.key("y");  // no Enter
    EXPECT_TRUE(c.s->question().empty());
    EXPECT_NE(c.s->sim().interp().frames().pref[Z], before);
    EXPECT_EQ(c.s->input().text(), "");
    // The Enter typed after it by habit is not a second action (in EDIT,
    // Enter on an empty line would take the block under the cursor).
    c.type(":edit 300");
    c.type("N1 (CHANGED)");
    c.type(":close");
    c.key("n");
    c.key("\r");
    EXPECT_FALSE(c.s->editing().modifying());
    EXPECT_TRUE(has(c.message(), "cancelled")) << c.message();
}

// Item 14: on the "Terminal too small" screen no key acts blind; :quit and
// Ctrl-C do.
TEST(Newcomer, KeysDoNothingBlindOnATooSmallScreen) {
    Console c;
    c.type(":mode pom");
    c.named("F9");
    c.run_until_settled();
    c.type(":load 300");
    c.type(":mode auto");
    c.s->resize(60, 20);
    c.named("F9");
    EXPECT_EQ(c.s->sim().state(), RunState::idle);
    c.named("F2");
    EXPECT_NE(c.s->page(), pages::PageId::om);
    c.type(":cycle");
    EXPECT_EQ(c.s->sim().state(), RunState::idle);
    EXPECT_TRUE(has(c.message(), "too small")) << c.message();
    const std::string small = c.screen(60, 20);
    EXPECT_TRUE(has(small, "too small")) << small;
    c.type(":quit");
    EXPECT_TRUE(c.s->quitting());
}

TEST(Newcomer, CtrlCQuitsOnATooSmallScreen) {
    Console c;
    c.s->resize(60, 20);
    c.named("C-c");
    EXPECT_TRUE(c.s->quitting());
}

// Item 15: an IMD block longer than a block may be is refused at Enter.
TEST(Newcomer, AnOverlongImdBlockIsRefusedAtEnter) {
    Console c;
    c.type(":mode imd");
    c.type("G0 X10 (" + std::string(5490, 'A') + ")");
    EXPECT_TRUE(has(c.message(), "error 1: block longer than 117 characters")) << c.message();
    EXPECT_TRUE(c.s->view().message_error);
    c.named("F9");
    EXPECT_FALSE(c.s->sim().alarm_active());
}

// Item 18: a typed % line of the program open is its header.
TEST(Newcomer, ATypedHeaderIsTheNewProgramsHeader) {
    TempStore st("header");
    Console c("lathe", {}, st.open());
    c.type(":edit 500");
    c.type("%500 (TEST)");
    c.type("N10 G0 X10");
    c.type("N20 M2");
    ASSERT_EQ(c.s->editing().editor().lines().size(), 3u) << editor_text(c);
    EXPECT_EQ(c.s->editing().editor().lines()[0], "%500 (TEST)");
    c.type(":save");
    EXPECT_TRUE(has(c.message(), "saved as revision")) << c.message();
    auto r = c.s->store()->read(500);
    ASSERT_FALSE(r.error);
    EXPECT_EQ(r.value.text, "%500 (TEST)\nN10 G0 X10\nN20 M2\n");
    c.type("%501 (OTHER)");
    EXPECT_TRUE(has(c.message(), ":edit N opens another")) << c.message();
    EXPECT_EQ(c.s->editing().editor().lines().size(), 3u);
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

// Item 9: the decimal comma the README promises, in commands and on PARAM
// as on the setting pages.
TEST(Newcomer, ADecimalCommaIsReadInCommandsAndOnParam) {
    Console c;
    c.type(":inc 0,5");
    EXPECT_EQ(c.s->sim().increment, 0.5) << c.message();
    c.type(":set L6=1,25");
    EXPECT_EQ(c.message(), "L6 = 1.25");
    c.type(":page param");
    c.type("L5=2,5");
    EXPECT_EQ(c.message(), "L5 = 2.5");
}
