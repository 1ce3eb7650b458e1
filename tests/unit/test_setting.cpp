// The setter's arithmetic: PREF by touch-off and gauges by measurement, on the
// handbook's relation and on the course notes' exam (seed 004 L2050-2093).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/sim/setting.hpp"
#include "tests/unit/helpers.hpp"

using namespace pupitre;
using pupitre::test::Prog;

TEST(Setting, TheHandbooksG92Example) {
    // 000:1187-1211: PREF Z -300, DEC1 20, tool length 80, programmed Z40: OM -160.
    EXPECT_DOUBLE_EQ(setting::touch_pref(-160, 0, 20, 0, 80, 40), -300);
    EXPECT_DOUBLE_EQ(setting::measure_gauge(-160, 0, -300, 20, 0, 40), 80);
}

// The exam of the course notes: the presetter gives X/R 63.345 and Z 38.237
// for the tool; measurement 1 touches a 100 mm shim laid on the face (the tool
// point at Z+100) with OM Z -531.699; measurement 2 touches the turned
// diameter 59.978 with OM X -22.143. The OM page shows X as a diameter
// (pupitre-iso(5), DECISIONS, diameter and radius values on the lathe), so OM X
// is a radius of -11.0715 internally.
TEST(Setting, TheCourseNotesExam) {
    Prog p("%1\nM2\n", "lathe", {{"D1.X", 63.345}, {"D1.Z", 38.237}});
    Interpreter& in = *p.in;
    ASSERT_EQ(in.set("DEC1.Z", 0), "");
    ProgramText imd;  // T1 D1 M6 typed in IMD: D1 stays active (M02 would cancel it)
    imd.file = "IMD";
    imd.text = std::make_shared<Text>("T1 D1 M6\n");
    imd.end = imd.text->size();
    in.start_imd(&imd);
    in.run_to_end();
    ASSERT_EQ(in.modal().d, 1);
    Axes om = in.machine_pos();
    om[Z] = -531.699;
    om[X] = -22.143 / 2;
    in.place(om);
    setting::Touch tz, tx;
    ASSERT_EQ(setting::touch_off(in, Z, 100, tz), "");
    EXPECT_NEAR(tz.after, -531.699 - 38.237 - 100, 1e-9);  // PREF Z + DEC Z = -669.936
    ASSERT_EQ(setting::touch_off(in, X, 59.978, tx), "");
    EXPECT_NEAR(tx.after, -11.0715 - 29.989 - 63.345, 1e-9);  // PREF X + DEC X = -104.4055
    // The relation of the handbook then holds: the tool point reads the surface.
    in.set("PREF.Z", tz.after);
    in.set("PREF.X", tx.after);
    in.frames_mut().gauge[X] = in.active_gauge(X);
    in.frames_mut().gauge[Z] = in.active_gauge(Z);
    in.origins_changed();
    EXPECT_NEAR(in.program_pos()[Z], 100, 1e-9);
    EXPECT_NEAR(in.to_display(X, in.program_pos()[X]), 59.978, 1e-9);
}

TEST(Setting, MeasuringAGaugeByATouchedDiameterAndFace) {
    Prog p("%1\nM2\n", "lathe", {{"PREF.X", -100}, {"PREF.Z", -400}, {"DEC1.Z", 20}});
    Interpreter& in = *p.in;
    Axes om = in.machine_pos();
    om[X] = -100 + 25 + 60;  // touching Ø50 with a 60 mm X gauge
    om[Z] = -400 + 20 + 35;  // touching the face Z0 with a 35 mm Z gauge
    in.place(om);
    setting::Touch gx, gz;
    ASSERT_EQ(setting::measure(in, 3, X, 50, gx), "");
    EXPECT_NEAR(gx.after, 60, 1e-9);
    EXPECT_EQ(gx.name, "D3.X");
    ASSERT_EQ(setting::measure(in, 3, Z, 0, gz), "");
    EXPECT_NEAR(gz.after, 35, 1e-9);
    // A dynamic correction stays: the gauge is what is left of the length.
    in.set("D3.DZ", 0.5);
    ASSERT_EQ(setting::measure(in, 3, Z, 0, gz), "");
    EXPECT_NEAR(gz.after, 34.5, 1e-9);
}

TEST(Setting, MillToolLengthAlongTheToolAxis) {
    Prog p("%1\nM2\n", "mill", {{"PREF.Z", -500}});
    Interpreter& in = *p.in;
    Axes om = in.machine_pos();
    om[Z] = -500 + 10 + 120;  // a 120 mm tool touching a 10 mm gauge block on Z0
    in.place(om);
    setting::Touch t;
    ASSERT_EQ(setting::measure(in, 5, Z, 10, t), "");
    EXPECT_EQ(t.name, "D5.L");
    EXPECT_NEAR(t.after, 120, 1e-9);
    EXPECT_NE(setting::measure(in, 5, X, 0, t), "");  // not along the tool axis
}

TEST(Setting, RefusedUnderAMirror) {
    Prog p("%1\nG51 X-\nM0\nM2\n", "mill");
    p.in->start(1);
    p.in->step();
    setting::Touch t;
    EXPECT_NE(setting::touch_off(*p.in, X, 0, t).find("mirror"), std::string::npos);
}

TEST(Setting, AGaugeChangedOnTheActiveCorrectorWaitsForTheNextMove) {
    Prog p("%1\nG0 X0 Z0\nT1 D1 M6\nG0 X10 Z10\nM0\nG0 Z20\nG0 X20\nM2\n", "lathe");
    p.in->start(1);
    while (p.in->step() != StepResult::stopped) {
    }
    p.in->set("D1.Z", 5);
    EXPECT_TRUE(p.in->gauge_pending(Z));
    EXPECT_EQ(p.in->frames().gauge[Z], 0);
    p.in->step();  // G0 Z20: the Z gauge applies with this move
    EXPECT_EQ(p.in->frames().gauge[Z], 5);
    EXPECT_FALSE(p.in->gauge_pending(Z));
}
