// Machine profiles (data/machines/*.machine): axes, travel, speeds, spindle
// ranges, tools and timings of a simulated NUM lathe or machining centre.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/axis.hpp"
#include "core/parse/dialect.hpp"

namespace pupitre {

struct AxisConfig {
    bool present = false;
    double min = -1e9, max = 1e9;  // travel of the reference relative to OM (lathe X: radius)
    double rapid = 10000;          // mm/min or deg/min
    // The motion's limits (core/plan): the highest speed of a feed move on
    // this axis (mm/min or deg/min, 0: its rapid), its acceleration (mm/s2 or
    // deg/s2, 0: none modelled) and jerk (mm/s3 or deg/s3, 0: none).
    double feed = 0;
    double accel = 0;
    double jerk = 0;
    double feed_max() const { return feed > 0 ? feed : rapid; }
};

struct SpindleRange {
    double min = 0, max = 0;
};

// The Cazeneuve lathes of seed 003, as MachineProfile::model (003:900-906).
inline constexpr int kHbCnc3 = 3, kHbCnc2 = 2;

struct MachineProfile {
    std::string name;
    std::string description;
    Dialect dialect = Dialect::num;  // the controller's language (pupitre-cazeneuve(5))
    bool lathe = false;
    int model = 1060;         // 1020, 1040 or 1060; kHbCnc3 or kHbCnc2 (the Cazeneuve)
    bool x_diameter = true;   // lathe: X programmed as a diameter
    bool rear_turret = true;  // lathe
    std::array<AxisConfig, kAxes> axes{};
    Axes home{};              // machine position of the reference at start (lathe X: radius)
    Axes pref{}, dec1{};      // default origins
    double max_feed = 5000;   // mm/min
    double max_feed_rev = 0;  // G95's own maximum (mm/min), 0: max_feed (the Cazeneuve's)
    double rev_feed_cap() const { return max_feed_rev > 0 ? max_feed_rev : max_feed; }
    double spindle_max = 4000;         // rev/min
    std::vector<SpindleRange> ranges;  // M40, M41, …
    bool auto_range = false;
    bool strict = false;  // the NUM's errors where pupitre is lenient on purpose (1114, 1115)
    int tools = 12;
    int correctors = 255;
    double tool_change_time = 2.0;
    // The planner's (core/plan; pupitre(1), MACHINE PROFILES): how far a
    // smoothed corner may leave the programmed point between chained blocks
    // (mm, 004:360), the time an exact stop waits for the axes to settle (s),
    // the shortest time of an interpolated block (s, E32000's default,
    // 004:1265), how fast the spindle changes speed (rev/min per second,
    // 0: at once), and the period at which the trajectory generator computes
    // a setpoint (s, 004:338: a motion comes to rest on one of its ticks; 0:
    // none, the textbook's times).
    double smoothing = 0.01;
    double in_position = 0;
    double min_block_time = 0;
    double spindle_accel = 0;
    double interpolation_period = 0.001;
    bool homing_required = false;  // console: programmed moves before POM give 159
    double jog_feed = 1000;        // mm/min of JOG and INC moves
    // Part-program memory in kilobytes: G76+ may not grow the programs in memory
    // beyond it (error 36). Files loaded larger than it still run.
    double program_memory_kb = 256;
    // 4/5 axes (004:1436-2018): "table" (B table, mill4) or "table-head" (C table and
    // B head, mill5), with the constants L_X, L_Y, L_Z of the course notes.
    std::string kinematics;
    double kin_lx = 0, kin_ly = 0, kin_lz = 0;

    bool has(int axis) const { return axis >= 0 && axis < kAxes && axes[size_t(axis)].present; }
};

// Parses a profile. Returns an empty string on success, else the error.
std::string parse_machine(std::string_view text, MachineProfile& out);
// The profiles shipped in data/machines (embedded): lathe, mill, mill4, mill5,
// cazeneuve.
bool builtin_machine(std::string_view name, MachineProfile& out);

}  // namespace pupitre
