// Machine profile parsing: "key = value" lines, '#' comments.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/interp/machine.hpp"
#include "core/i18n.hpp"
#include "core/keyvalue.hpp"

#include <charconv>
#include <cstdlib>

namespace pupitre {

namespace data {
std::string_view machine_lathe();
std::string_view machine_mill();
std::string_view machine_mill4();
std::string_view machine_mill5();
}  // namespace data

int axis_of(char letter) {
    // X Y Z U V W A B C -> 0..8, by table: this runs for every axis word.
    static constexpr signed char kIndex[26] = {6, 7, 8, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
                                               -1, -1, -1, -1, -1, -1, -1, 3, 4, 5, 0, 1, 2};
    return (letter >= 'A' && letter <= 'Z') ? kIndex[letter - 'A'] : -1;
}

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
    if (s == "yes" || s == "true" || s == "1") v = true;
    else if (s == "no" || s == "false" || s == "0") v = false;
    else return false;
    return true;
}
}  // namespace

std::string parse_machine(std::string_view text, MachineProfile& m) {
    m = MachineProfile{};
    int lineno = 0;
    for (std::string_view line; kv::next_line(text, line, lineno);) {
        size_t eq = line.find('=');
        auto bad = [&](std::string_view why) {
            return strf(tr("line %d: %.*s"), lineno, int(why.size()), why.data());
        };
        if (eq == std::string_view::npos) return bad(tr("expected key = value"));
        std::string_view key = trim(line.substr(0, eq)), val = trim(line.substr(eq + 1));
        double d1, d2;
        int axis = -1;
        std::string_view sub;
        if (size_t dot = key.find('.'); dot != std::string_view::npos && dot + 2 == key.size()) {
            axis = axis_of(key[dot + 1]);
            sub = key.substr(0, dot);
            if (axis < 0) return bad(strf(tr("unknown axis in '%.*s'"), int(key.size()), key.data()));
        }
        if (key == "name") m.name = val;
        else if (key == "description") m.description = val;
        else if (key == "kind") {
            if (val == "lathe") m.lathe = true;
            else if (val == "mill") m.lathe = false;
            else return bad(tr("kind must be lathe or mill"));
        } else if (key == "model") {
            if (!number(val, d1) || (d1 != 1020 && d1 != 1040 && d1 != 1060))
                return bad(tr("model must be 1020, 1040 or 1060"));
            m.model = int(d1);
        } else if (key == "axes") {
            for (char c : val) {
                if (c == ' ') continue;
                int a = axis_of(c);
                if (a < 0) return bad(tr("unknown axis letter in axes"));
                m.axes[size_t(a)].present = true;
            }
        } else if (key == "x_programming") {
            if (val == "diameter") m.x_diameter = true;
            else if (val == "radius") m.x_diameter = false;
            else return bad(tr("x_programming must be diameter or radius"));
        } else if (key == "turret") {
            if (val == "rear") m.rear_turret = true;
            else if (val == "front") m.rear_turret = false;
            else return bad(tr("turret must be rear or front"));
        } else if (sub == "travel") {
            if (!two_numbers(val, d1, d2, ' ') || d1 >= d2) return bad(tr("travel needs MIN MAX"));
            m.axes[size_t(axis)].min = d1;
            m.axes[size_t(axis)].max = d2;
        } else if (sub == "rapid") {
            if (!number(val, d1) || d1 <= 0) return bad(tr("rapid must be positive"));
            m.axes[size_t(axis)].rapid = d1;
        } else if (sub == "home") {
            if (!number(val, d1)) return bad(tr("home needs a number"));
            m.home[size_t(axis)] = d1;
        } else if (sub == "pref") {
            if (!number(val, d1)) return bad(tr("pref needs a number"));
            m.pref[size_t(axis)] = d1;
        } else if (sub == "dec1") {
            if (!number(val, d1)) return bad(tr("dec1 needs a number"));
            m.dec1[size_t(axis)] = d1;
        } else if (key == "feed.max") {
            if (!number(val, d1) || d1 <= 0) return bad(tr("feed.max must be positive"));
            m.max_feed = d1;
        } else if (key == "spindle.max") {
            if (!number(val, d1) || d1 <= 0) return bad(tr("spindle.max must be positive"));
            m.spindle_max = d1;
        } else if (key == "spindle.ranges") {
            m.ranges.clear();
            std::string_view v = val;
            while (!(v = trim(v)).empty()) {
                size_t sp = v.find(' ');
                std::string_view r = v.substr(0, sp);
                v = sp == std::string_view::npos ? std::string_view{} : v.substr(sp);
                if (!two_numbers(r, d1, d2, '-') || d1 > d2) return bad(strf(tr("ranges are MIN-MAX MIN-MAX%s"), "\u2026"));  // %s: an ellipsis
                m.ranges.push_back({d1, d2});
            }
            if (m.ranges.size() > 6) return bad(tr("at most 6 ranges (M40-M45)"));
        } else if (key == "spindle.auto_range") {
            if (!yes_no(val, m.auto_range)) return bad(tr("auto_range must be yes or no"));
        } else if (key == "strict") {
            if (!yes_no(val, m.strict)) return bad(tr("strict must be yes or no"));
        } else if (key == "tools") {
            if (!number(val, d1) || d1 < 1 || d1 > 999) return bad(tr("tools must be 1..999"));
            m.tools = int(d1);
        } else if (key == "correctors") {
            if (!number(val, d1) || d1 < 1 || d1 > 255) return bad(tr("correctors must be 1..255"));
            m.correctors = int(d1);
        } else if (key == "tool_change_time") {
            if (!number(val, d1) || d1 < 0) return bad(tr("tool_change_time must be >= 0"));
            m.tool_change_time = d1;
        } else if (key == "homing") {
            if (val != "required" && val != "none") return bad(tr("homing must be required or none"));
            m.homing_required = val == "required";
        } else if (key == "program_memory") {
            if (!number(val, d1) || d1 < 1) return bad(tr("program_memory must be at least 1 (kilobytes)"));
            m.program_memory_kb = d1;
        } else if (key == "jog.feed") {
            if (!number(val, d1) || d1 <= 0) return bad(tr("jog.feed must be positive"));
            m.jog_feed = d1;
        } else if (key == "kinematics") {
            if (val != "table" && val != "table-head") return bad(tr("kinematics must be table or table-head"));
            m.kinematics = val;
        } else if (key == "kinematics.lx" || key == "kinematics.ly" || key == "kinematics.lz") {
            if (!number(val, d1)) return bad(tr("kinematics constants are lengths"));
            (key.back() == 'x' ? m.kin_lx : key.back() == 'y' ? m.kin_ly : m.kin_lz) = d1;
        } else {
            return bad(strf(tr("unknown key '%.*s'"), int(key.size()), key.data()));
        }
    }
    if (m.name.empty()) return tr("the profile has no name");
    bool any = false;
    for (auto& a : m.axes) any = any || a.present;
    if (!any) return tr("the profile declares no axes");
    if (m.lathe && (!m.has(X) || !m.has(Z))) return tr("a lathe needs the X and Z axes");
    if (!m.lathe) m.x_diameter = false;
    if (m.kinematics == "table" && !m.has(B)) return tr("table kinematics need the B axis");
    if (m.kinematics == "table-head" && (!m.has(B) || !m.has(C))) return tr("table-head kinematics need B and C");
    return {};
}

std::vector<std::string> builtin_machines() { return {"lathe", "mill", "mill4", "mill5"}; }

bool builtin_machine(std::string_view name, MachineProfile& out) {
    std::string_view text;
    if (name == "lathe") text = data::machine_lathe();
    else if (name == "mill") text = data::machine_mill();
    else if (name == "mill4") text = data::machine_mill4();
    else if (name == "mill5") text = data::machine_mill5();
    else return false;
    return parse_machine(text, out).empty();
}

}  // namespace pupitre
