// Machine profile parsing: "key = value" lines, '#' comments.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/interp/machine.hpp"

#include <charconv>
#include <cstdlib>

#include "core/i18n.hpp"
#include "core/keyvalue.hpp"

namespace pupitre {

namespace data {
std::string_view machine_lathe();
std::string_view machine_mill();
std::string_view machine_mill4();
std::string_view machine_mill5();
std::string_view machine_cazeneuve();
}  // namespace data

namespace {
using kv::number;
using kv::trim;

bool two_numbers(std::string_view s, double& a, double& b, char sep) {
    s = trim(s);
    size_t p = s.find(sep, sep == '-' ? 1 : 0);
    if (p == std::string_view::npos) return false;
    return number(s.substr(0, p), a) && number(s.substr(p + 1), b);
}

bool yes_no(std::string_view s, bool& v) {
    s = trim(s);
    if (s == "yes" || s == "true" || s == "1")
        v = true;
    else if (s == "no" || s == "false" || s == "0")
        v = false;
    else
        return false;
    return true;
}

// One "key = value" line; `axis` is the X of a per-axis key such as travel.X.
struct Line {
    std::string_view key, val;
    size_t axis = 0;
};
// Reads the value of a line into the profile: empty, or what is wrong with it.
using Reader = std::string (*)(const Line& l, MachineProfile& m);
struct KeyReader {
    std::string_view key;
    Reader read;
};

// A value that is one of two words, into a flag (true for the first).
std::string one_of(std::string_view val, const char* yes, const char* no, bool& out,
                   const char* why) {
    if (val == yes)
        out = true;
    else if (val == no)
        out = false;
    else
        return why;
    return {};
}

// A number, unless it is out of range (`out_of_range`, as written so that a
// NaN passes where it always has); else `why`.
std::string number_unless(std::string_view val, bool (*out_of_range)(double), double& out,
                          const char* why) {
    double d;
    if (!number(val, d) || out_of_range(d)) return why;
    out = d;
    return {};
}
bool not_positive(double d) {
    return d <= 0;
}
bool never(double) {
    return false;
}

std::string read_name(const Line& l, MachineProfile& m) {
    m.name = l.val;
    return {};
}
std::string read_description(const Line& l, MachineProfile& m) {
    m.description = l.val;
    return {};
}
std::string read_kind(const Line& l, MachineProfile& m) {
    return one_of(l.val, "lathe", "mill", m.lathe, tr("kind must be lathe or mill"));
}
std::string read_dialect(const Line& l, MachineProfile& m) {
    if (l.val == "num")
        m.dialect = Dialect::num;
    else if (l.val == "cazeneuve")
        m.dialect = Dialect::cazeneuve;
    else
        return tr("dialect must be num or cazeneuve");
    return {};
}
// The NUM's 1020, 1040 or 1060; the Cazeneuve's HB CNC 3 or HB CNC 2, whose
// spindle ranges differ (seed 003:900-906): hbcnc3 and hbcnc2 set them and
// the maximum, which a later spindle.* line may still change.
std::string read_model(const Line& l, MachineProfile& m) {
    if (l.val == "hbcnc3" || l.val == "hbcnc2") {
        const bool two = l.val == "hbcnc2";
        m.model = two ? kHbCnc2 : kHbCnc3;
        m.ranges = two ? std::vector<SpindleRange>{{50, 375}, {400, 3000}}
                       : std::vector<SpindleRange>{{50, 325}, {400, 2100}};
        m.spindle_max = two ? 3000 : 2100;
        return {};
    }
    double d;
    if (!number(l.val, d) || (d != 1020 && d != 1040 && d != 1060))
        return tr("model must be 1020, 1040 or 1060 (hbcnc3 or hbcnc2 for the Cazeneuve)");
    m.model = int(d);
    return {};
}
std::string read_axes(const Line& l, MachineProfile& m) {
    for (char c : l.val) {
        if (c == ' ') continue;
        int a = axis_of(c);
        if (a < 0) return tr("unknown axis letter in axes");
        m.axes[size_t(a)].present = true;
    }
    return {};
}
std::string read_x_programming(const Line& l, MachineProfile& m) {
    return one_of(l.val, "diameter", "radius", m.x_diameter,
                  tr("x_programming must be diameter or radius"));
}
std::string read_turret(const Line& l, MachineProfile& m) {
    return one_of(l.val, "rear", "front", m.rear_turret, tr("turret must be rear or front"));
}
std::string read_travel(const Line& l, MachineProfile& m) {
    double d1, d2;
    if (!two_numbers(l.val, d1, d2, ' ') || d1 >= d2) return tr("travel needs MIN MAX");
    m.axes[l.axis].min = d1;
    m.axes[l.axis].max = d2;
    return {};
}
std::string read_rapid(const Line& l, MachineProfile& m) {
    return number_unless(l.val, not_positive, m.axes[l.axis].rapid, tr("rapid must be positive"));
}
bool negative(double d) {
    return d < 0;
}
std::string read_axis_feed(const Line& l, MachineProfile& m) {
    return number_unless(l.val, not_positive, m.axes[l.axis].feed,
                         tr("feed.max of an axis must be positive"));
}
std::string read_accel(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.axes[l.axis].accel, tr("accel must be >= 0"));
}
std::string read_jerk(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.axes[l.axis].jerk, tr("jerk must be >= 0"));
}
std::string read_smoothing(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.smoothing, tr("smoothing must be >= 0"));
}
std::string read_in_position(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.in_position, tr("in_position must be >= 0"));
}
std::string read_min_block_time(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.min_block_time, tr("min_block_time must be >= 0"));
}
std::string read_interpolation_period(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.interpolation_period,
                         tr("interpolation_period must be >= 0"));
}
std::string read_spindle_accel(const Line& l, MachineProfile& m) {
    return number_unless(l.val, negative, m.spindle_accel, tr("spindle.accel must be >= 0"));
}
std::string read_home(const Line& l, MachineProfile& m) {
    return number_unless(l.val, never, m.home[l.axis], tr("home needs a number"));
}
std::string read_pref(const Line& l, MachineProfile& m) {
    return number_unless(l.val, never, m.pref[l.axis], tr("pref needs a number"));
}
std::string read_dec1(const Line& l, MachineProfile& m) {
    return number_unless(l.val, never, m.dec1[l.axis], tr("dec1 needs a number"));
}
std::string read_feed_max(const Line& l, MachineProfile& m) {
    return number_unless(l.val, not_positive, m.max_feed, tr("feed.max must be positive"));
}
// A feed per revolution may have a maximum of its own: the Cazeneuve's G95
// goes to 9.2 m/min where G94 stops at 5.1 (seed 003:890-891).
std::string read_feed_max_rev(const Line& l, MachineProfile& m) {
    return number_unless(l.val, not_positive, m.max_feed_rev,
                         tr("feed.max_per_rev must be positive"));
}
std::string read_spindle_max(const Line& l, MachineProfile& m) {
    return number_unless(l.val, not_positive, m.spindle_max, tr("spindle.max must be positive"));
}
std::string read_spindle_ranges(const Line& l, MachineProfile& m) {
    m.ranges.clear();
    std::string_view v = l.val;
    double d1, d2;
    while (!(v = trim(v)).empty()) {
        size_t sp = v.find(' ');
        std::string_view r = v.substr(0, sp);
        v = sp == std::string_view::npos ? std::string_view{} : v.substr(sp);
        if (!two_numbers(r, d1, d2, '-') || d1 > d2)
            return strf(tr("ranges are MIN-MAX MIN-MAX%s"), "\u2026");  // %s: an ellipsis
        m.ranges.push_back({d1, d2});
    }
    if (m.ranges.size() > 6) return tr("at most 6 ranges (M40-M45)");
    return {};
}
std::string read_auto_range(const Line& l, MachineProfile& m) {
    if (!yes_no(l.val, m.auto_range)) return tr("auto_range must be yes or no");
    return {};
}
std::string read_strict(const Line& l, MachineProfile& m) {
    if (!yes_no(l.val, m.strict)) return tr("strict must be yes or no");
    return {};
}
std::string read_tools(const Line& l, MachineProfile& m) {
    double d;
    if (!number(l.val, d) || d < 1 || d > 999) return tr("tools must be 1..999");
    m.tools = int(d);
    return {};
}
std::string read_correctors(const Line& l, MachineProfile& m) {
    double d;
    if (!number(l.val, d) || d < 1 || d > 255) return tr("correctors must be 1..255");
    m.correctors = int(d);
    return {};
}
std::string read_tool_change_time(const Line& l, MachineProfile& m) {
    return number_unless(
        l.val, [](double d) { return d < 0; }, m.tool_change_time,
        tr("tool_change_time must be >= 0"));
}
std::string read_homing(const Line& l, MachineProfile& m) {
    return one_of(l.val, "required", "none", m.homing_required,
                  tr("homing must be required or none"));
}
std::string read_program_memory(const Line& l, MachineProfile& m) {
    return number_unless(
        l.val, [](double d) { return d < 1; }, m.program_memory_kb,
        tr("program_memory must be at least 1 (kilobytes)"));
}
std::string read_jog_feed(const Line& l, MachineProfile& m) {
    return number_unless(l.val, not_positive, m.jog_feed, tr("jog.feed must be positive"));
}
std::string read_kinematics(const Line& l, MachineProfile& m) {
    if (l.val != "table" && l.val != "table-head")
        return tr("kinematics must be table or table-head");
    m.kinematics = l.val;
    return {};
}
std::string read_kinematics_l(const Line& l, MachineProfile& m) {
    double& out = l.key.back() == 'x' ? m.kin_lx : l.key.back() == 'y' ? m.kin_ly : m.kin_lz;
    return number_unless(l.val, never, out, tr("kinematics constants are lengths"));
}

// The keys of a profile (pupitre-machine(5)).
constexpr KeyReader kKeys[] = {
    {"name", read_name},
    {"description", read_description},
    {"kind", read_kind},
    {"dialect", read_dialect},
    {"model", read_model},
    {"axes", read_axes},
    {"x_programming", read_x_programming},
    {"turret", read_turret},
    {"feed.max", read_feed_max},
    {"feed.max_per_rev", read_feed_max_rev},
    {"spindle.max", read_spindle_max},
    {"spindle.ranges", read_spindle_ranges},
    {"spindle.auto_range", read_auto_range},
    {"strict", read_strict},
    {"tools", read_tools},
    {"correctors", read_correctors},
    {"tool_change_time", read_tool_change_time},
    {"smoothing", read_smoothing},
    {"in_position", read_in_position},
    {"min_block_time", read_min_block_time},
    {"interpolation_period", read_interpolation_period},
    {"spindle.accel", read_spindle_accel},
    {"homing", read_homing},
    {"program_memory", read_program_memory},
    {"jog.feed", read_jog_feed},
    {"kinematics", read_kinematics},
    {"kinematics.lx", read_kinematics_l},
    {"kinematics.ly", read_kinematics_l},
    {"kinematics.lz", read_kinematics_l},
};
// The per-axis keys, written NAME.X (X any axis letter).
constexpr KeyReader kAxisKeys[] = {
    {"travel", read_travel}, {"rapid", read_rapid}, {"home", read_home},
    {"pref", read_pref},     {"dec1", read_dec1},   {"feed.max", read_axis_feed},
    {"accel", read_accel},   {"jerk", read_jerk},
};

Reader reader_of(std::string_view key, const KeyReader* begin, const KeyReader* end) {
    for (const KeyReader* k = begin; k != end; ++k)
        if (k->key == key) return k->read;
    return nullptr;
}

// The profile as a whole, once every line is read.
std::string check_whole(MachineProfile& m) {
    if (m.name.empty()) return tr("the profile has no name");
    bool any = false;
    for (auto& a : m.axes) any = any || a.present;
    if (!any) return tr("the profile declares no axes");
    if (m.lathe && (!m.has(X) || !m.has(Z))) return tr("a lathe needs the X and Z axes");
    if (!m.lathe) m.x_diameter = false;
    if (m.dialect == Dialect::cazeneuve && (!m.lathe || m.x_diameter))
        return tr("the cazeneuve dialect is a lathe's, with X programmed as a radius");
    if ((m.model == kHbCnc2 || m.model == kHbCnc3) && m.dialect != Dialect::cazeneuve)
        return tr("models hbcnc3 and hbcnc2 are the cazeneuve dialect's");
    if (m.kinematics == "table" && !m.has(B)) return tr("table kinematics need the B axis");
    if (m.kinematics == "table-head" && (!m.has(B) || !m.has(C)))
        return tr("table-head kinematics need B and C");
    return {};
}
}  // namespace

// profile -> { line } ; line -> key '=' value [ '#' comment ] ;
// key -> NAME | NAME '.' AXIS   (travel.X, rapid.Z, feed.max.X, ...)
std::string parse_machine(std::string_view text, MachineProfile& m) {
    m = MachineProfile{};
    int lineno = 0;
    for (std::string_view line; kv::next_line(text, line, lineno);) {
        size_t eq = line.find('=');
        auto bad = [&](std::string_view why) {
            return strf(tr("line %d: %.*s"), lineno, int(why.size()), why.data());
        };
        if (eq == std::string_view::npos) return bad(tr("expected key = value"));
        Line l{trim(line.substr(0, eq)), trim(line.substr(eq + 1))};
        std::string_view key = l.key, sub;
        if (size_t dot = key.rfind('.'); dot != std::string_view::npos && dot + 2 == key.size()) {
            int axis = axis_of(key[dot + 1]);
            sub = key.substr(0, dot);
            if (axis < 0)
                return bad(strf(tr("unknown axis in '%.*s'"), int(key.size()), key.data()));
            l.axis = size_t(axis);
        }
        Reader read = reader_of(key, std::begin(kKeys), std::end(kKeys));
        if (!read) read = reader_of(sub, std::begin(kAxisKeys), std::end(kAxisKeys));
        if (!read) return bad(strf(tr("unknown key '%.*s'"), int(key.size()), key.data()));
        if (std::string why = read(l, m); !why.empty()) return bad(why);
    }
    return check_whole(m);
}

bool builtin_machine(std::string_view name, MachineProfile& out) {
    std::string_view text;
    if (name == "lathe")
        text = data::machine_lathe();
    else if (name == "mill")
        text = data::machine_mill();
    else if (name == "mill4")
        text = data::machine_mill4();
    else if (name == "mill5")
        text = data::machine_mill5();
    else if (name == "cazeneuve")
        text = data::machine_cazeneuve();
    else
        return false;
    return parse_machine(text, out).empty();
}

}  // namespace pupitre
