// The number texts shared by the summary, the drawings and the pages
// (core/numfmt.hpp): the cycle time as H:MM:SS.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/numfmt.hpp"

namespace pupitre {
namespace {

TEST(ClockText, HoursMinutesSecondsCut) {
    EXPECT_EQ(clock_text(0), "0:00:00");
    EXPECT_EQ(clock_text(14.263), "0:00:14");
    EXPECT_EQ(clock_text(3725.9), "1:02:05");
    EXPECT_EQ(clock_text(360000), "100:00:00");
}

// A profile with an acceleration of 1e-300 gave a cycle time of 1e62 s,
// printed as -2562047788015215:-30:-8: the hours overflowed a long.
TEST(ClockText, TimesNoIntegerHolds) {
    EXPECT_EQ(clock_text(1e20), "27777777777777776:46:40");
    const std::string huge = clock_text(1e300);
    EXPECT_EQ(huge.find('-'), std::string::npos);
    EXPECT_EQ(huge.substr(huge.size() - 6, 1), ":");
    EXPECT_EQ(clock_text(std::numeric_limits<double>::quiet_NaN()), "0:00:00");
    EXPECT_EQ(clock_text(-5), "0:00:00");
}

}  // namespace
}  // namespace pupitre
