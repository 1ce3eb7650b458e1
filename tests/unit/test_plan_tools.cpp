// Each tool's time, against the Cazeneuve thesis's table (issue 35 item 6):
// seed 003 tabulates, for the tail side of its part, each operation's length L,
// feed A and time T = L·60/A (003:2314), rapids taken at 3 m/min
// (003:2322), then each tool's cutting time and after how many parts its
// insert's edge must be changed, at 15 minutes of cutting an edge
// (003:2353-2368).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "core/output/summary.hpp"
#include "core/plan/tools.hpp"

namespace pupitre {
namespace {

struct Row {
    int tool;
    double length, feed;  // mm, mm/min
    const char* printed;  // T as printed, in seconds
    bool agrees;          // L·60/A gives the printed T to its last digit
};

// The table of 003:2328-2350, tail side. The thesis's "T091" is the tool its
// text calls 11 (003:2357); A = 3000 is a rapid (003:2322). Thirteen of the
// nineteen printed times are not L·60/A to their own precision: 83.144 mm at
// 71.1 mm/min is 70.16 s, printed 11.58; 9.778 mm at 4507 mm/min is 0.13 s,
// printed 6.549; 24.805 mm at 150 mm/min is 9.92 s, printed 5.8; 79.69 mm at
// 153.433 mm/min is 31.16 s, printed 7.7; and so on (the rows marked false).
// They are kept as printed, and the test says which agree.
constexpr Row kTail[] = {
    {11, 112.515, 3000, "2.121", false},   {11, 83.144, 71.1, "11.58", false},
    {11, 30.07, 3000, "0.938", false},     {11, 38.370, 156.6, "14.7", true},
    {11, 156.244, 403.1, "23.21", false},  {11, 9.778, 4507, "6.549", false},
    {11, 85.59, 332.52, "12.177", false},  {11, 11.965, 3000, "2.13", false},
    {11, 12.15, 3000, "0.243", true},      {11, 24.805, 150, "5.8", false},
    {11, 79.69, 153.433, "7.7", false},    {11, 16.8, 35.57, "28.33", true},
    {11, 12.564, 3000, "0.35", false},     {11, 19.624, 84.73, "13.98", false},
    {11, 389.63, 3000, "7.79", true},      {12, 333.99, 3000, "6.57", false},
    {12, 424.44, 184, "138.4", true},      {13, 335.89, 3000, "6.71", true},
    {13, 19.516, 106.20, "11.476", false},
};

double seconds(const Row& r) {
    return r.length * 60 / r.feed;
}
// One unit of the printed time's last digit.
double last_digit(const char* printed) {
    const std::string s = printed;
    const size_t dot = s.find('.');
    return dot == std::string::npos ? 1 : std::pow(10.0, -double(s.size() - dot - 1));
}

TEST(ToolTimes, TheThesisRowsAreLengthOverFeed) {
    for (const Row& r : kTail) {
        const double printed = std::strtod(r.printed, nullptr);
        const bool agrees = std::fabs(seconds(r) - printed) <= last_digit(r.printed);
        EXPECT_EQ(agrees, r.agrees) << r.length << " mm at " << r.feed << " mm/min: " << seconds(r)
                                    << " s, printed " << r.printed;
    }
}

TEST(ToolTimes, TheTablePerTool) {
    plan::ToolTable t;
    for (const Row& r : kTail) t.add(r.tool, r.feed != 3000, r.length, seconds(r));
    ASSERT_EQ(t.rows().size(), 3u);
    const plan::ToolRow& t12 = t.rows()[1];
    EXPECT_EQ(t12.tool, 12);
    // T12's finishing: 424.44 mm at 184 mm/min, 138.4 s (003:2346, 2365).
    EXPECT_NEAR(t12.cut_seconds, 138.4, 0.05);
    EXPECT_NEAR(t12.cut_length, 424.44, 1e-9);
    EXPECT_NEAR(t12.rapid_seconds, 6.68, 0.005);
    EXPECT_EQ(t12.passes, 1);
    const plan::ToolRow& t11 = t.rows()[0];
    EXPECT_EQ(t11.passes, 4);  // each run of cuts after a rapid
    // The thesis gives T11 141.78 s of cutting (003:2357); its own rows as
    // printed add up to 124.0 s, and from L and A to 207.0 s: no reading of
    // the table gives its total, which the test takes as the thesis states it.
    EXPECT_NEAR(t11.cut_seconds, 207.0, 0.05);
}

TEST(ToolTimes, PartsPerEdge) {
    const double edge = 15 * 60;  // 15 minutes of cutting an edge (003:2353)
    // T11, 141.78 s = 2.36 min a part: 15 / 2.36 is 6.35, so the edge is
    // changed every 6 parts. The thesis concludes "pour chaque 3 pièces"
    // (003:2361), which its numbers do not give.
    EXPECT_EQ(plan::parts_per_edge(141.78, edge), 6);
    // T12, 138.4 s: 6 parts too (the thesis: "comme le précédent", 003:2365).
    EXPECT_EQ(plan::parts_per_edge(138.4, edge), 6);
    // T13: the thesis takes 6.71 s, its rapid row, and concludes 144 parts
    // (003:2367-2368); 900 / 6.71 is 134, and the chamfer's cutting row,
    // 19.516 mm at 106.2 mm/min, is 11.03 s: 81 parts.
    EXPECT_EQ(plan::parts_per_edge(6.71, edge), 134);
    EXPECT_EQ(plan::parts_per_edge(19.516 * 60 / 106.20, edge), 81);
    EXPECT_EQ(plan::parts_per_edge(0, edge), 0);
    EXPECT_EQ(plan::parts_per_edge(100, 0), 0);
    // A cut of no time to speak of: as many parts as a long may say, not an
    // overflow (found: "change the edge every -9223372036854775808 parts").
    EXPECT_EQ(plan::parts_per_edge(1e-30, edge), 1000000000000000000L);
}

TEST(ToolTimes, TheSummaryLine) {
    plan::EdgeLife life;
    ASSERT_EQ(plan::read_edge_life("15", life), "");
    plan::ToolRow t11{.tool = 11,
                      .cut_seconds = 141.78,
                      .rapid_seconds = 13.5,
                      .cut_length = 424.44,
                      .passes = 3};
    EXPECT_EQ(tool_line(t11, life),
              "T11: 141.8 s of cutting a part (3 passes, 424.440 mm), 13.5 s of rapids, change "
              "the edge every 6 parts");
    EXPECT_EQ(tool_line(t11, {}),
              "T11: 141.8 s of cutting a part (3 passes, 424.440 mm), 13.5 s of rapids");
    // One pass is one "pass" (found running a program: "1 passes").
    t11.passes = 1;
    EXPECT_EQ(tool_line(t11, {}),
              "T11: 141.8 s of cutting a part (1 pass, 424.440 mm), 13.5 s of rapids");
}

TEST(ToolTimes, EdgeLifeOption) {
    plan::EdgeLife life;
    EXPECT_EQ(plan::read_edge_life("T12=20", life), "");
    EXPECT_EQ(plan::read_edge_life("15", life), "");
    EXPECT_DOUBLE_EQ(life.of(12), 1200);
    EXPECT_DOUBLE_EQ(life.of(11), 900);
    EXPECT_NE(plan::read_edge_life("0", life), "");
    EXPECT_NE(plan::read_edge_life("X1=3", life), "");
    EXPECT_NE(plan::read_edge_life("T1=", life), "");
    // from_chars reads these; no life is (found: --edge-life inf ran).
    EXPECT_NE(plan::read_edge_life("inf", life), "");
    EXPECT_NE(plan::read_edge_life("T2=nan", life), "");
    EXPECT_DOUBLE_EQ(life.of(2), 900);
}

}  // namespace
}  // namespace pupitre
