// Training (issue 16): exercise files, a truth per student drawn from a seed,
// the values expected with their arithmetic, grading and the mistakes named.
// The numbers are worked out by hand in the comments.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/digest.hpp"
#include "core/training/exercise.hpp"
#include "core/training/grade.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::training {
namespace {

Exercise builtin(const char* name) {
    Exercise e;
    EXPECT_TRUE(builtin_exercise(name, e)) << name;
    return e;
}

workshop::Setup truth_of(const Exercise& e, uint64_t seed = 1) {
    workshop::Setup s;
    EXPECT_EQ(draw_setup(e, seed, s), "");
    return s;
}

double expect(const Exercise& e, const workshop::Setup& s, const char* name) {
    double v = 0;
    EXPECT_TRUE(expected(e, s, name, v)) << name;
    return v;
}

TEST(Exercise, EveryShippedOneParsesChecksAndRehearses) {
    for (const std::string& n : builtin_exercises()) {
        Exercise e = builtin(n.c_str());
        EXPECT_EQ(e.name, n);
        EXPECT_EQ(check_exercise(e), "") << n;
    }
}

TEST(Exercise, BadLinesAreNamed) {
    Exercise e;
    EXPECT_EQ(parse_exercise("name = x\nfind = PREF.Q\n", e),
              "line 2: find: 'PREF.Q' is not a value to find on this machine");
    EXPECT_EQ(parse_exercise("name = x\nfind = PREF.X\ntruth.chuck.z = -40 .. -80\n", e),
              "line 3: truth.chuck.z: HI must be above LO");
    EXPECT_EQ(parse_exercise("name = x\nfind = PREF.X\ndimension = dia Z-10 : 40\n", e),
              "line 3: dimension: expected NOMINAL TOLERANCE or NOMINAL LOWER UPPER after ':'");
    EXPECT_EQ(parse_exercise("name = x\nfind = PREF.X\nstart.D1.X = truth * 2\n", e),
              "line 3: start.D1.X: expected truth + N or truth - N");
    EXPECT_EQ(parse_exercise("name = Big Name\n", e),
              "line 1: name: expected a name of small letters, digits, '-' and '_'");
    EXPECT_EQ(parse_exercise("name = x\n", e), "nothing to grade: give find or dimension lines");
    EXPECT_EQ(parse_exercise("name = x\nmachine = mill\nfind = PREF.Z\nfind = D1.X\n", e),
              "line 4: find: 'D1.X' is not a value to find on this machine");
}

TEST(Exercise, CheckFindsWhatNoLineCanSay) {
    Exercise e;
    // The stick-out's range reaches past the bar's length at its high end.
    ASSERT_EQ(parse_exercise("name = x\nfind = PREF.Z\ntruth.stock.stickout = 90 .. 130\n", e), "");
    EXPECT_EQ(check_exercise(e),
              "with every range at its high end: stock.stickout must be shorter than "
              "stock.length\n");
    // A tool the setup does not have.
    ASSERT_EQ(parse_exercise("name = x\nfind = D9.X\n", e), "");
    EXPECT_EQ(check_exercise(e), "line 2: D9.X: the setup has no such tool\n");
    // Done right, the part is Ø40: a drawing that asks Ø39 cannot be passed.
    Exercise w = builtin("wear");
    std::string text = w.source;
    text.replace(text.find("dia Z-10 : 40 0.01"), 18, "dia Z-10 : 39 0.01");
    ASSERT_EQ(parse_exercise(text, e), "");
    const std::string why = check_exercise(e);
    EXPECT_NE(why.find("dimension dia Z-10: the part reads 40.000, outside 39.000"),
              std::string::npos)
        << why;
}

TEST(Exercise, ATruthReproducesFromItsSeedAndDiffersBetweenStudents) {
    Exercise e = builtin("exam-2005-drawn");
    const uint64_t a = seed_of(e, "alice", "class-secret-0123");
    EXPECT_EQ(a, seed_of(e, "alice", "class-secret-0123"));
    EXPECT_NE(a, seed_of(e, "bob", "class-secret-0123"));
    EXPECT_NE(a, seed_of(e, "alice", "another-secret-456"));
    workshop::Setup s1 = truth_of(e, a), s2 = truth_of(e, a), s3 = truth_of(e, a + 1);
    EXPECT_EQ(s1.source, s2.source);
    EXPECT_NE(s1.source, s3.source);
    // Within the ranges, on their steps.
    EXPECT_GE(s1.lathe.axis_x, -40);
    EXPECT_LE(s1.lathe.axis_x, -20);
    EXPECT_GE(s1.lathe.stickout, 80);
    EXPECT_LE(s1.lathe.stickout, 100);
    EXPECT_DOUBLE_EQ(s1.lathe.stickout * 2, std::round(s1.lathe.stickout * 2));
    EXPECT_DOUBLE_EQ(s1.lathe.stock_diameter, std::round(s1.lathe.stock_diameter));
    EXPECT_NEAR(s1.lathe.axis_x * 1000, std::round(s1.lathe.axis_x * 1000), 1e-6);
}

TEST(Exercise, TheBookExamsAnswer) {
    // seed 004:2050-2100. PREF Z = -531.699 - 38.237 - 100 = -669.936;
    // PREF X = -22.143 - 63.345 - (59.978 / 2 + 20) = -135.477; the face at
    // -334.432 - 38.237 - 40 = -412.669, so DEC1 Z = 257.267.
    Exercise e = builtin("exam-2005");
    workshop::Setup s = truth_of(e);
    EXPECT_NEAR(expect(e, s, "PREF.X"), -135.477, 1e-9);
    EXPECT_NEAR(expect(e, s, "PREF.Z"), -669.936, 1e-9);
    EXPECT_NEAR(expect(e, s, "DEC1.X"), 0, 1e-9);
    EXPECT_NEAR(expect(e, s, "DEC1.Z"), 257.267, 1e-9);
    EXPECT_NEAR(expect(e, s, "D1.X"), 63.345, 1e-9);
    EXPECT_NEAR(expect(e, s, "D1.Z"), 38.237, 1e-9);
    std::string how;
    double v = 0;
    expected(e, s, "DEC1.Z", v, &how);
    EXPECT_EQ(how, "DEC1 Z = the part's face - the jaws' face = the stick-out = 257.267");
}

TEST(Exercise, OriginsOnTheFaceAndOnTheBlock) {
    Exercise e = builtin("lathe-first");  // origin = face
    workshop::Setup s = truth_of(e, 7);
    EXPECT_NEAR(expect(e, s, "PREF.Z"), s.lathe.chuck_z + s.lathe.stickout, 1e-9);
    EXPECT_NEAR(expect(e, s, "DEC1.Z"), 0, 1e-9);
    Exercise m = builtin("mill-pocket");  // origin = corner, Z on the top
    workshop::Setup t = truth_of(m, 7);
    EXPECT_NEAR(expect(m, t, "PREF.X"), t.mill.stock_x, 1e-9);
    EXPECT_NEAR(expect(m, t, "PREF.Y"), t.mill.stock_y, 1e-9);
    EXPECT_NEAR(expect(m, t, "PREF.Z"), t.mill.stock_z + t.mill.height, 1e-9);
    EXPECT_NEAR(expect(m, t, "D6.R"), 5, 1e-9);
}

TEST(Exercise, AWearCorrectionIsADiameterOnTheLathe) {
    // D1 X is given 0.015 too large (a radius): the part comes out 0.030 over
    // size; the NUM's DX holds a diameter, so DX = 2 x -0.015 = -0.030.
    Exercise e = builtin("wear");
    workshop::Setup s = truth_of(e, 3);
    double given = 0;
    ASSERT_TRUE(start_value(e, s, "D1.X", given));
    EXPECT_NEAR(given - s.tool(1)->x, 0.015, 1e-9);
    EXPECT_NEAR(expect(e, s, "D1.DX"), -0.030, 1e-9);
}

// The exam's values, right, then with one mistake each.
Values exam_right() {
    return {{"PREF.X", -135.477}, {"PREF.Z", -669.936}, {"DEC1.X", 0},
            {"DEC1.Z", 257.267},  {"D1.X", 63.345},     {"D1.Z", 38.237}};
}

Grade exam_grade(const Values& v) {
    Exercise e = builtin("exam-2005");
    Context ctx;
    ctx.diameters = e.diameters;
    ctx.shims = e.shims;
    return grade(e, truth_of(e), v, ctx, nullptr, 0, 600);
}

const ItemGrade& item(const Grade& g, const char* name) {
    for (const ItemGrade& i : g.items)
        if (i.name == name) return i;
    ADD_FAILURE() << name;
    return g.items.front();
}

TEST(Grade, TheRightAnswerGetsFullMarks) {
    Grade g = exam_grade(exam_right());
    EXPECT_EQ(g.score, 100);
    EXPECT_TRUE(g.mistakes().empty());
    EXPECT_FALSE(g.scrapped);
    EXPECT_FALSE(g.late);
}

TEST(Grade, XTakenAsADiameterIsNamed) {
    // PREF X = OM X - L X - (59.978 + 20) = -165.466: the diameter used
    // where its half belongs, 29.989 too low.
    Values v = exam_right();
    v["PREF.X"] = -165.466;
    Grade g = exam_grade(v);
    EXPECT_EQ(g.score, 83);  // 5 of 6
    const ItemGrade& i = item(g, "PREF.X");
    EXPECT_FALSE(i.ok);
    EXPECT_EQ(i.mistake, Mistake::diameter);
    EXPECT_NEAR(i.found - i.truth, -29.989, 1e-9);
    EXPECT_NE(i.why.find("half the \u00d859.978"), std::string::npos) << i.why;
}

TEST(Grade, EachMistakeIsTracedToItsCause) {
    struct Case {
        const char* name;
        double value;
        Mistake m;
    } cases[] = {
        {"D1.X", -63.345, Mistake::sign},               // OM - P taken as P - OM
        {"D1.X", 126.69, Mistake::diameter},            // the presetter's X/R read as a diameter
        {"DEC1.Z", 0, Mistake::dec1},                   // DEC1 never entered
        {"PREF.Z", -669.936 + 257.267, Mistake::dec1},  // the offset put into PREF
        {"PREF.Z", -669.936 + 38.237, Mistake::corrector},  // touched off with D0
        {"PREF.Z", -669.936 + 100, Mistake::shim},          // the gauge block not subtracted
        {"PREF.Z", -669.936 - 40, Mistake::shim},           // the 40 mm block added, not subtracted
        {"D1.Z", 0, Mistake::unset},                        // left as the exercise began
    };
    for (const Case& c : cases) {
        Values v = exam_right();
        v[c.name] = c.value;
        const ItemGrade& i = item(exam_grade(v), c.name);
        EXPECT_FALSE(i.ok) << c.name << " " << c.value;
        EXPECT_EQ(i.mistake, c.m) << c.name << " " << c.value << ": " << i.why;
    }
}

TEST(Grade, AWearCorrectionWithTheWrongSign) {
    Exercise e = builtin("wear");
    workshop::Setup s = truth_of(e, 3);
    Grade g = grade(e, s, {{"D1.DX", 0.030}}, {}, nullptr, 0, 60);
    EXPECT_EQ(g.items[0].mistake, Mistake::wear_sign);
    // Half of it: the diameter's correction halved as if DX were a radius
    // (named as that, not as the reverse).
    g = grade(e, s, {{"D1.DX", -0.015}}, {}, nullptr, 0, 60);
    EXPECT_EQ(g.items[0].mistake, Mistake::radius);
    EXPECT_EQ(mistake_title(Mistake::radius), "X taken as a radius instead of a diameter");
    EXPECT_NE(g.items[0].why.find("a radius where a diameter was expected"), std::string::npos)
        << g.items[0].why;
    // No part: its dimensions cannot be read, and count as wrong.
    EXPECT_FALSE(g.dims[0].read);
    EXPECT_TRUE(g.scrapped);
}

TEST(Grade, ACorrectorHoldingAnotherToolsGaugeIsTheWrongCorrector) {
    // lathe-tools: D2 touched off with T1 in the turret holds T1's gauges.
    Exercise e = builtin("lathe-tools");
    workshop::Setup s = truth_of(e, 3);
    const workshop::ToolTruth* t1 = s.tool(1);
    ASSERT_NE(t1, nullptr);
    Grade g = grade(e, s, {{"D2.X", t1->x}, {"D2.Z", t1->z}}, {}, nullptr, 0, 60);
    for (const char* name : {"D2.X", "D2.Z"}) {
        const ItemGrade& i = item(g, name);
        EXPECT_FALSE(i.ok) << name;
        EXPECT_EQ(i.mistake, Mistake::corrector) << name << ": " << i.why;
        EXPECT_NE(i.why.find("T1's gauge, not T2's"), std::string::npos) << i.why;
    }
    // Its own gauge is right, whatever the others hold.
    EXPECT_TRUE(item(grade(e, s, {{"D1.X", t1->x}}, {}, nullptr, 0, 60), "D1.X").ok);
}

TEST(Grade, TheCutPartAgainstTheDrawingAndACrash) {
    Exercise e = builtin("wear");
    workshop::Setup s = truth_of(e, 3);
    MachineProfile m;
    ASSERT_TRUE(builtin_machine("lathe", m));
    workshop::Workshop fresh(m, s, nullptr);  // uncut: Ø60 where Ø40 is drawn
    Grade g = grade(e, s, {{"D1.DX", -0.030}}, {}, &fresh, 0, 60);
    EXPECT_TRUE(g.items[0].ok);
    ASSERT_EQ(g.dims.size(), 2u);
    EXPECT_TRUE(g.dims[0].read);
    EXPECT_NEAR(g.dims[0].measured, 60, 1e-9);
    EXPECT_FALSE(g.dims[0].ok);
    EXPECT_TRUE(g.scrapped);
    EXPECT_EQ(g.score, 33);  // 1 of 3
    g = grade(e, s, {{"D1.DX", -0.030}}, {}, &fresh, 1, 60 * 31);
    EXPECT_TRUE(g.late);  // 31 min of 30
    EXPECT_EQ(g.crashes, 1);
    const std::vector<std::string> lines = report_lines(e, g);
    EXPECT_NE(lines[1].find("crashes 1"), std::string::npos) << lines[1];
    EXPECT_NE(lines[1].find("late"), std::string::npos) << lines[1];
}

TEST(Exercise, SavedFromASetupItReadsBack) {
    workshop::Setup s;
    ASSERT_TRUE(workshop::builtin_setup("lathe", s));
    Exercise e;
    ASSERT_EQ(parse_exercise(exercise_from_setup(s, "mine"), e), "");
    EXPECT_EQ(check_exercise(e), "");
    workshop::Setup t = truth_of(e);
    EXPECT_NEAR(expect(e, t, "PREF.Z"), 35, 1e-9);  // the shipped setup: face at Z 35
    EXPECT_NEAR(expect(e, t, "PREF.X"), -20, 1e-9);
}

TEST(Exercise, TheTaskInTheLanguageOfTheTexts) {
    Exercise e;
    ASSERT_EQ(parse_exercise("name = x\nfind = PREF.Z\ntitle = Face\ntitle.fr = La face\n"
                             "task = Touch it.\ntask.fr = La tangenter.\ntask.fr = Puis :submit.\n",
                             e),
              "");
    EXPECT_EQ(e.title_here(), "Face");  // the tests run in English
    EXPECT_EQ(e.task_here(), std::vector<std::string>{"Touch it."});
    ASSERT_EQ(e.tasks.size(), 2u);
    EXPECT_EQ(e.tasks[1].first, "fr");
    EXPECT_EQ(e.tasks[1].second, "Puis :submit.");
    EXPECT_EQ(parse_exercise("name = x\nfind = PREF.Z\ntask.french = non\n", e),
              "line 3: task.french: unknown key 'task.french'");
    for (const std::string& n : builtin_exercises())  // each shipped one has its French
        EXPECT_FALSE(builtin(n.c_str()).tasks.empty()) << n;
}

TEST(Sha256, HmacMatchesRfc4231) {
    // RFC 4231, test case 2.
    EXPECT_EQ(hmac_sha256_hex("Jefe", "what do ya want for nothing?"),
              "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
}

// The student's report, as the EXERCISE page and the store show it after
// :submit: golden files (PUPITRE_BLESS=1 rewrites them).
void golden_report(const char* name, const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    const std::string path = std::string(PUPITRE_SOURCE_DIR) + "/tests/unit/expected/" + name;
    if (const char* b = std::getenv("PUPITRE_BLESS"); b && *b == '1') {
        std::ofstream(path, std::ios::binary) << text;
        return;
    }
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str(), text) << "golden " << path << " differs (PUPITRE_BLESS=1 rewrites)";
}

TEST(Grade, TheStudentsReportIsGolden) {
    // The book exam with three mistakes, 20 min 34 s into its hour.
    Values v = exam_right();
    v["PREF.X"] = -165.466;  // the diameter where its half belongs
    v["D1.X"] = -63.345;     // a gauge with the wrong sign
    v["DEC1.Z"] = 0;         // DEC1 forgotten
    Exercise e = builtin("exam-2005");
    Context ctx;
    ctx.diameters = e.diameters;
    ctx.shims = e.shims;
    golden_report("report_exam.txt",
                  report_lines(e, grade(e, truth_of(e), v, ctx, nullptr, 0, 1234)));
    // The wear exercise on an uncut bar after a crash, late: the part is read and scrapped.
    Exercise w = builtin("wear");
    workshop::Setup s = truth_of(w, 3);
    MachineProfile m;
    ASSERT_TRUE(builtin_machine("lathe", m));
    workshop::Workshop fresh(m, s, nullptr);
    golden_report("report_wear.txt",
                  report_lines(w, grade(w, s, {{"D1.DX", -0.015}}, {}, &fresh, 1, 2400)));
}

}  // namespace
}  // namespace pupitre::training
