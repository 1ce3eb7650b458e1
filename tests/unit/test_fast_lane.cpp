// The plain blocks' lane (core/interp/interp_fast.cpp) against the general
// path: every program of the repository and thousands of random ones, run
// both ways on the lathe and the mill, must report the same events, the same
// diagnostics and end in the same state, byte for byte.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "tests/unit/event_log.hpp"

using namespace pupitre;
namespace fs = std::filesystem;

namespace {

struct Machines {
    MachineProfile mill, lathe;
    Machines() {
        builtin_machine("mill", mill);
        builtin_machine("lathe", lathe);
    }
};
const Machines& machines() {
    static const Machines m;
    return m;
}

using Sets = std::vector<std::pair<std::string, double>>;

// Both ways; true when they agree. `plain` adds the blocks the lane took.
::testing::AssertionResult same_both_ways(const MachineProfile& m, const std::string& text,
                                          const Sets& sets, long* plain = nullptr) {
    long taken = 0;
    const std::string fast = test::run_log(m, text, sets, true, 20000, &taken);
    const std::string slow = test::run_log(m, text, sets, false);
    if (plain) *plain += taken;
    if (fast == slow) return ::testing::AssertionSuccess();
    size_t at = 0;
    while (at < fast.size() && at < slow.size() && fast[at] == slow[at]) ++at;
    size_t from = at > 200 ? at - 200 : 0;
    return ::testing::AssertionFailure()
           << "on " << m.name << ", the lane differs at byte " << at << "\nfast: ..."
           << fast.substr(from, 400) << "\nslow: ..." << slow.substr(from, 400) << "\nprogram:\n"
           << text;
}

std::string read(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// The programs of the repository: golden, bad, warning and demo programs.
std::vector<fs::path> repository_programs() {
    const fs::path root = PUPITRE_SOURCE_DIR;
    std::vector<fs::path> out;
    for (const char* dir : {"tests/golden/programs", "tests/bad", "tests/warn", "data/demo"}) {
        if (!fs::exists(root / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / dir))
            if (e.is_regular_file() && e.path().extension() == ".iso") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(FastLane, RepositoryProgramsRunTheSameBothWays) {
    const auto programs = repository_programs();
    ASSERT_GT(programs.size(), 200u);
    long plain = 0;
    for (const fs::path& p : programs) {
        const std::string text = read(p);
        for (const MachineProfile* m : {&machines().mill, &machines().lathe}) {
            EXPECT_TRUE(same_both_ways(*m, text, {}, &plain)) << p;
            EXPECT_TRUE(same_both_ways(*m, text, {{"D1.R", 4}, {"D1.L", 50}, {"D1.X", 20}})) << p;
        }
    }
    EXPECT_GT(plain, 300);  // the lane was exercised
}

namespace {

// Random programs near the lane's edge: plain moves, and everything that must
// leave it (other words, blanks, variables, too many digits, signs, twice the
// same word, incomplete circles, compensation, G91, G70, other planes, G96).
struct RandomProgram {
    std::mt19937 rng;
    bool lathe;
    explicit RandomProgram(unsigned seed, bool is_lathe) : rng(seed), lathe(is_lathe) {}

    int pick(int n) { return int(rng() % unsigned(n)); }
    bool chance(int percent) { return pick(100) < percent; }
    std::string number() {
        std::string s;
        if (chance(45))
            s += '-';
        else if (chance(3))
            s += '+';
        s += std::to_string(pick(chance(2) ? 2000000 : 200));
        if (chance(70)) {
            s += '.';
            int digits = chance(2) ? 4 : 1 + pick(3);
            for (int k = 0; k < digits; ++k) s += char('0' + pick(10));
        }
        return s;
    }
    std::string value() {
        if (chance(1)) return "";  // blank
        if (chance(1)) return chance(50) ? "+" : "-";
        if (chance(2)) return "L" + std::to_string(pick(3));
        return number();
    }
    std::string axis() {
        // Mostly the lane's words, now and then one it leaves to the
        // general path or one the machine has not.
        static const char* mill = "XXXXYYYYZZIJRF";
        static const char* turn = "XXXXZZZZIKRF";
        static const char* rare = "KUACSTDEPQ";
        const char* set = chance(4) ? rare : lathe ? turn : mill;
        return std::string(1, set[pick(int(std::strlen(set)))]);
    }
    std::string preamble() {
        static const char* mill[] = {
            "G91", "G70",     "G18",      "G19",     "G41 D1",    "G42 D1",  "G51 X-",       "ED30",
            "G74", "G95 F.1", "M3 S1000", "G59 X10", "G92 R5 F2", "G1 F0.5", "E60002=-1000", "G29"};
        static const char* turn[] = {"G91",       "G70",     "E11005=0",     "G41 D1",
                                     "G42 D1",    "G95 F.2", "M3 M40 S800",  "G96 S200 X40",
                                     "G92 S3000", "G1 F0.5", "E60002=-1000", "G94 F100"};
        std::string s;
        const int n = pick(3);
        for (int k = 0; k < n; ++k)
            s += std::string(lathe ? turn[pick(12)] : mill[pick(16)]) + "\n";
        return s;
    }
    // A move most of the time: a line on some axes, a circle with both
    // coordinates of the plane and R or its centre; then now and then a word
    // more, of any kind.
    std::string block(int n) {
        std::string s = "N" + std::to_string(n);
        const int g = chance(97) ? pick(4) : pick(100);
        if (chance(85)) s += " G" + std::to_string(g);
        if (chance(3)) s += " G" + std::to_string(pick(4));
        const char* a = lathe ? "ZX" : "XY";
        if (g == 2 || g == 3) {
            s += std::string(" ") + a[0] + number() + " " + a[1] + number();
            if (chance(60))
                s += " R" + std::to_string(300 + pick(200));
            else
                s += std::string(lathe ? " K" : " I") + number() + (lathe ? " I" : " J") + number();
        } else {
            for (char c : std::string(lathe ? "XZ" : "XYZ"))
                if (chance(60)) s += std::string(" ") + c + number();
        }
        if (chance(20)) s += " F" + std::to_string(1 + pick(3000));
        for (int k = chance(20) ? 1 + pick(2) : 0; k > 0; --k) s += " " + axis() + value();
        if (chance(2)) s += " M" + std::to_string(pick(10));
        if (chance(2)) s += " L1=" + number();
        if (chance(2)) s += " $1 hello";
        if (chance(2)) s += " (comment)";
        return s + "\n";
    }
    std::string program() {
        std::string s = "%1\n";
        s += lathe ? "G0 X50 Z20\n" : "G0 X0 Y0 Z20\nG1 Z-1 F500\n";
        s += preamble();
        const int blocks = 5 + pick(30);
        for (int k = 0; k < blocks; ++k) s += block(10 * (k + 1));
        if (chance(30)) s += "G40 G1 X10 Y10\n";
        if (chance(90)) s += "M2\n";
        return s;
    }
};

}  // namespace

TEST(FastLane, RandomProgramsRunTheSameBothWays) {
    long plain = 0;
    for (unsigned seed = 1; seed <= 4000; ++seed) {
        const bool lathe = seed % 3 == 0;
        RandomProgram g(seed, lathe);
        const std::string text = g.program();
        const MachineProfile& m = lathe ? machines().lathe : machines().mill;
        const Sets sets = {{"D1.R", double(seed % 4)}, {"L1", 2.5}};
        ASSERT_TRUE(same_both_ways(m, text, sets, &plain)) << "seed " << seed;
    }
    EXPECT_GT(plain, 5000);
}

// The benchmark's programs (scripts/gen-program), straight and in radius
// compensation: nearly every block takes the lane.
TEST(FastLane, GeneratedContoursTakeTheLane) {
    // A polygon of 24 sides gone round anticlockwise, a third of its sides
    // circles bulging out, every other block without its G.
    std::string text = "%1\nG0 X100 Y0 Z50\nG1 Z-5 F1000\nD1 G41 G1 X80 Y0 F800\n";
    char b[160];
    for (int k = 1; k <= 400; ++k) {
        const double t = k * 2 * 3.14159265358979 / 24;
        const char* g = k % 3 == 0 ? "G3 " : k % 3 == 1 ? "G1 " : "";
        std::snprintf(b, sizeof b, "N%d %sX%.3f Y%.3f%s\n", 10 * k, g, 80 * std::cos(t),
                      80 * std::sin(t), k % 3 == 0 ? " R120" : "");
        text += b;
    }
    text += "G40 G1 X0 Y0\nG0 Z50\nM2\n";
    long plain = 0;
    for (double r : {0.0, 0.5, 5.0}) {
        long before = plain;
        EXPECT_TRUE(same_both_ways(machines().mill, text, {{"D1.R", r}}, &plain));
        EXPECT_GT(plain - before, 300);
    }
}
