// The ASCII console in French: accented letters keep their letter (issue 20).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "pages/canvas.hpp"

using pupitre::pages::Canvas;

TEST(Canvas, AsciiKeepsTheLettersOfFrenchText) {
    Canvas c(40, 1, true);
    c.text(0, 0, "Départ cycle « RAZ » à l’outil ø20 → Ç");
    EXPECT_EQ(c.to_text(), "Depart cycle \" RAZ \" a l'outil o20 > C\n");
}

TEST(Canvas, Utf8KeepsFrenchText) {
    Canvas c(40, 1, false);
    EXPECT_EQ(c.text(0, 0, "Départ cycle"), 12);
    EXPECT_EQ(c.to_text(), "Départ cycle\n");
}
