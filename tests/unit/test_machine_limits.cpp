// The motion's limits in a machine profile (issue 35): per axis feed, rapid,
// acceleration and jerk; smoothing, in-position time, minimum block time and
// the spindle's acceleration, the interpolation period; the shipped profiles
// give them all.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/interp/machine.hpp"

namespace pupitre {
namespace {

TEST(MachineLimits, KeysAreRead) {
    MachineProfile m;
    ASSERT_EQ(parse_machine("name = m\naxes = X Y\nrapid.X = 12000\nfeed.max.X = 9000\n"
                            "accel.X = 1500\njerk.X = 20000\naccel.Y = 800\nsmoothing = 0.02\n"
                            "in_position = 0.03\nmin_block_time = 0.004\nspindle.accel = 2000\n"
                            "interpolation_period = 0.002\n",
                            m),
              "");
    EXPECT_EQ(m.axes[X].feed_max(), 9000);
    EXPECT_EQ(m.axes[Y].feed_max(), 10000);  // its rapid, the default
    EXPECT_EQ(m.axes[X].accel, 1500);
    EXPECT_EQ(m.axes[X].jerk, 20000);
    EXPECT_EQ(m.axes[Y].accel, 800);
    EXPECT_EQ(m.axes[Y].jerk, 0);
    EXPECT_EQ(m.smoothing, 0.02);
    EXPECT_EQ(m.in_position, 0.03);
    EXPECT_EQ(m.min_block_time, 0.004);
    EXPECT_EQ(m.spindle_accel, 2000);
    EXPECT_EQ(m.interpolation_period, 0.002);
    MachineProfile d;  // a profile that does not say: LinuxCNC's servo period
    ASSERT_EQ(parse_machine("name = d\naxes = X\n", d), "");
    EXPECT_EQ(d.interpolation_period, 0.001);
}

TEST(MachineLimits, BadValuesSayWhere) {
    MachineProfile m;
    EXPECT_EQ(parse_machine("name = m\naxes = X\naccel.X = -1\n", m), "line 3: accel must be >= 0");
    EXPECT_EQ(parse_machine("name = m\naxes = X\nfeed.max.X = 0\n", m),
              "line 3: feed.max of an axis must be positive");
    EXPECT_EQ(parse_machine("name = m\naxes = X\nsmoothing = x\n", m),
              "line 3: smoothing must be >= 0");
    EXPECT_NE(parse_machine("name = m\naxes = X\naccel.Q = 1\n", m), "");
    EXPECT_EQ(parse_machine("name = m\naxes = X\ninterpolation_period = -0.001\n", m),
              "line 3: interpolation_period must be >= 0");
    // from_chars reads "inf" and "nan"; a profile may not (found: a NaN
    // cycle time printed as -2562047788015215:-30:-8).
    EXPECT_EQ(parse_machine("name = m\naxes = X\ninterpolation_period = inf\n", m),
              "line 3: interpolation_period must be >= 0");
    EXPECT_EQ(parse_machine("name = m\naxes = X\nin_position = nan\n", m),
              "line 3: in_position must be >= 0");
}

TEST(MachineLimits, TheShippedProfilesGiveThem) {
    for (const char* name : {"lathe", "mill", "mill4", "mill5", "cazeneuve"}) {
        MachineProfile m;
        ASSERT_TRUE(builtin_machine(name, m)) << name;
        for (int a = 0; a < kAxes; ++a)
            if (m.has(a)) {
                EXPECT_GT(m.axes[size_t(a)].accel, 0) << name << ' ' << a;
            }
        EXPECT_GT(m.smoothing, 0) << name;
        EXPECT_GT(m.in_position, 0) << name;
        EXPECT_GT(m.min_block_time, 0) << name;
        // A move lasts at least one period (004:344): E32000's default is no shorter.
        EXPECT_GT(m.interpolation_period, 0) << name;
        EXPECT_GE(m.min_block_time, m.interpolation_period) << name;
        EXPECT_GT(m.spindle_accel, 0) << name;
    }
}

}  // namespace
}  // namespace pupitre
