// Setup files: "key = value" lines, '#' comments (pupitre-setup(5)).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/workshop/setup.hpp"

#include <charconv>
#include <cmath>
#include <functional>

#include "core/i18n.hpp"
#include "core/keyvalue.hpp"

namespace pupitre {
namespace data {
std::string_view setup_lathe();
std::string_view setup_mill();
std::string_view setup_mill5();
std::string_view setup_cazeneuve();
}  // namespace data

namespace workshop {

const ToolTruth* Setup::tool(int position) const {
    for (const ToolTruth& t : tools)
        if (t.position == position) return &t;
    return nullptr;
}

namespace {

using kv::trim;

using kv::workshop_number;

// Reads a number into `out` if it lies in [lo, hi]; else says why.
std::string in_range(std::string_view val, double lo, double hi, double& out) {
    double v = 0;
    if (!workshop_number(val, v)) return tr("expected a number");
    if (v < lo || v > hi) return strf(tr("must be from %g to %g"), lo, hi);
    out = v;
    return {};
}

constexpr double kBig = 5000;       // mm: no workshop is larger
constexpr double kMaxCells = 25e6;  // a mill's height field

// The setup's keys, by table: name, its smallest and largest value, the
// field of T it sets.
template <class T>
struct KeyOf {
    const char* name;
    double lo, hi;
    double T::*field;
};
constexpr KeyOf<LatheSetup> kLatheKeys[] = {
    {"axis.x", -kBig, kBig, &LatheSetup::axis_x},
    {"chuck.z", -kBig, kBig, &LatheSetup::chuck_z},
    {"chuck.diameter", 10, 2000, &LatheSetup::chuck_diameter},
    {"chuck.length", 1, 1000, &LatheSetup::chuck_length},
    {"jaw.length", 1, 500, &LatheSetup::jaw_length},
    {"jaw.height", 1, 500, &LatheSetup::jaw_height},
    {"jaw.reach", 1, 500, &LatheSetup::jaw_reach},
    {"stock.diameter", 0.1, 2000, &LatheSetup::stock_diameter},
    {"stock.length", 0.1, kBig, &LatheSetup::stock_length},
    {"stock.stickout", 0.1, kBig, &LatheSetup::stickout},
    {"stock.bore", 0, 2000, &LatheSetup::bore},
    {"tailstock.quill", 1, 500, &LatheSetup::quill_diameter},
};

constexpr KeyOf<MillSetup> kMillKeys[] = {
    {"table.z", -kBig, kBig, &MillSetup::table_z},
    {"stock.x", -kBig, kBig, &MillSetup::stock_x},
    {"stock.y", -kBig, kBig, &MillSetup::stock_y},
    {"stock.z", -kBig, kBig, &MillSetup::stock_z},
    {"stock.length", 0.5, 2000, &MillSetup::length},
    {"stock.width", 0.5, 2000, &MillSetup::width},
    {"stock.height", 0.5, 1000, &MillSetup::height},
    {"vice.jaw.height", 0.5, 500, &MillSetup::jaw_height},
    {"vice.jaw.width", 1, 1000, &MillSetup::jaw_width},
    {"vice.jaw.thickness", 1, 200, &MillSetup::jaw_thickness},
    {"plate.margin", 0, 500, &MillSetup::plate_margin},
    {"setter.x", -kBig, kBig, &MillSetup::setter_x},
    {"setter.y", -kBig, kBig, &MillSetup::setter_y},
    {"setter.diameter", 2, 100, &MillSetup::setter_diameter},
    {"zmap.cell", 0.02, 2, &MillSetup::cell},
    {"table.c.x", -kBig, kBig, &MillSetup::c_x},
    {"table.c.y", -kBig, kBig, &MillSetup::c_y},
    {"head.pivot", 0, 5000, &MillSetup::pivot},
    {"table.b.x", -kBig, kBig, &MillSetup::b_x},
    {"table.b.z", -kBig, kBig, &MillSetup::b_z},
};

constexpr KeyOf<Pin> kPinKeys[] = {
    {"x", -kBig, kBig, &Pin::x},
    {"y", -kBig, kBig, &Pin::y},
    {"diameter", 1, 100, &Pin::diameter},
    {"height", 0.5, 500, &Pin::height},
};

constexpr KeyOf<ToolTruth> kToolKeys[] = {
    {"x", -kBig, kBig, &ToolTruth::x},
    {"z", -kBig, kBig, &ToolTruth::z},
    {"radius", 0, 50, &ToolTruth::radius},
    {"angle", 20, 175, &ToolTruth::angle},
    {"edge", 0.5, 100, &ToolTruth::edge},
    {"wear", 0, 1000, &ToolTruth::wear},
    {"life", 0, 100000, &ToolTruth::life},
    // A milling cutter's (kind = mill).
    {"length", 0, 1000, &ToolTruth::length},
    {"corner", 0, 50, &ToolTruth::corner},
    {"flute", 0, 500, &ToolTruth::flute},
    {"reach", 0, 1000, &ToolTruth::reach},
    {"holder.diameter", 1, 300, &ToolTruth::holder_diameter},
};

// "z,x z,x ...": at least three points.
std::string points(std::string_view val, std::vector<Pt>& out) {
    out.clear();
    while (!(val = trim(val)).empty()) {
        size_t end = val.find_first_of(" \t");
        std::string_view p = val.substr(0, end);
        val = end == std::string_view::npos ? std::string_view{} : val.substr(end);
        size_t comma = p.find(',');
        Pt q{};
        if (comma == std::string_view::npos || !workshop_number(p.substr(0, comma), q[0]) ||
            !workshop_number(p.substr(comma + 1), q[1]))
            return tr("expected points as Z,X Z,X Z,X");
        out.push_back(q);
        if (out.size() > 64) return tr("at most 64 points");
    }
    if (out.size() < 3) return tr("expected points as Z,X Z,X Z,X");
    return {};
}

ToolTruth& tool_at(Setup& s, int position) {
    for (ToolTruth& t : s.tools)
        if (t.position == position) return t;
    s.tools.push_back(ToolTruth{});
    s.tools.back().position = position;
    if (s.kind == "mill") s.tools.back().spindle = 3;  // a right-hand cutter
    return s.tools.back();
}

std::string yes_no(std::string_view val, bool& out) {
    if (val != "yes" && val != "no") return tr("expected yes or no");
    out = val == "yes";
    return {};
}

// "N.FIELD" with N from 1 to `max`: N and FIELD; false when it is not one.
bool numbered(std::string_view key, int max, int& n, std::string_view& field) {
    auto r = std::from_chars(key.data(), key.data() + key.size(), n);
    if (r.ec != std::errc() || r.ptr == key.data() || n < 1 || n > max ||
        r.ptr == key.data() + key.size() || *r.ptr != '.')
        return false;
    field = key.substr(size_t(r.ptr - key.data()) + 1);
    return true;
}

// tool.N = none: no tool at position N (an exercise removes the tools of
// the built-in setup it does not use).
std::string no_tool(Setup& s, std::string_view key, std::string_view val) {
    int n = 0;
    auto r = std::from_chars(key.data(), key.data() + key.size(), n);
    if (r.ec != std::errc() || r.ptr != key.data() + key.size() || n < 1 || n > 99)
        return tr("expected tool.N.FIELD with N from 1 to 99");
    if (val != "none") return tr("expected tool.N = none, or tool.N.FIELD = value");
    std::erase_if(s.tools, [n](const ToolTruth& t) { return t.position == n; });
    return {};
}

// tool.N.FIELD = value
std::string tool_key(Setup& s, std::string_view key, std::string_view val) {
    if (key.find('.', 5) == std::string_view::npos) return no_tool(s, key.substr(5), val);
    int n = 0;
    std::string_view field;
    if (!numbered(key.substr(5), 99, n, field))  // after "tool."
        return tr("expected tool.N.FIELD with N from 1 to 99");
    ToolTruth& t = tool_at(s, n);
    for (const auto& k : kToolKeys)
        if (field == k.name) {
            // A lathe's nose radius is at most 10 mm; a milling cutter's 50.
            const double hi = field == "radius" && s.kind == "lathe" ? 10 : k.hi;
            return in_range(val, k.lo, hi, t.*k.field);
        }
    if (field == "orientation") {
        double c = 0;
        if (std::string e = in_range(val, 0, 8, c); !e.empty()) return e;
        if (c != std::floor(c)) return tr("must be a whole number from 0 to 8");
        t.orientation = int(c);
        return {};
    }
    if (field == "spindle") {
        if (val == "M3" || val == "M03")
            t.spindle = 3;
        else if (val == "M4" || val == "M04")
            t.spindle = 4;
        else if (val == "any")
            t.spindle = 0;
        else
            return tr("expected M3, M4 or any");
        return {};
    }
    if (field == "probe") return yes_no(val, t.probe);
    if (field == "finder") {
        // It finds a block's edges by the spindle's turning, beside X and Y.
        if (s.kind != "mill") return tr("an edge finder is a machining centre's (kind = mill)");
        return yes_no(val, t.finder);
    }
    if (field == "holder") return points(val, t.holder);
    return strf(tr("unknown tool field '%.*s'"), int(field.size()), field.data());
}

// pin.N.FIELD = value
std::string pin_key(Setup& s, std::string_view key, std::string_view val) {
    int n = 0;
    std::string_view field;
    if (!numbered(key.substr(4), 9, n, field))  // after "pin."
        return tr("expected pin.N.FIELD with N from 1 to 9");
    std::vector<Pin>& pins = s.mill.pins;
    if (pins.size() < size_t(n)) pins.resize(size_t(n));
    for (const auto& k : kPinKeys)
        if (field == k.name) return in_range(val, k.lo, k.hi, pins[size_t(n) - 1].*k.field);
    return strf(tr("unknown pin field '%.*s'"), int(field.size()), field.data());
}

// The machining centre's keys; "" when `key` is none of them (`known`
// false).
std::string mill_key(Setup& s, std::string_view key, std::string_view val, bool& known) {
    known = true;
    MillSetup& m = s.mill;
    if (key == "holding") {
        if (val != "vice" && val != "plate" && val != "none")
            return tr("expected vice, plate or none");
        m.holding = std::string(val);
        return {};
    }
    if (key == "setter.z") {
        m.setter = true;
        return in_range(val, -kBig, kBig, m.setter_z);
    }
    if (key.substr(0, 4) == "pin.") return pin_key(s, key, val);
    for (const auto& k : kMillKeys)
        if (key == k.name) return in_range(val, k.lo, k.hi, m.*k.field);
    known = false;
    return {};
}

std::string one_key(Setup& s, std::string_view key, std::string_view val) {
    if (key == "name") return s.name = std::string(val), std::string{};
    if (key == "description") return s.description = std::string(val), std::string{};
    if (key == "kind") {
        if (val != "lathe" && val != "mill") return tr("expected lathe or mill");
        if (!s.kind.empty() && s.kind != val) return tr("kind is given twice, differently");
        s.kind = std::string(val);
        return {};
    }
    // The kind decides what the other keys mean (stock.length is the bar's
    // on a lathe, the block's along X on a mill).
    if (s.kind.empty()) return tr("kind = lathe or kind = mill must come first");
    if (key.substr(0, 5) == "tool.") return tool_key(s, key, val);
    if (s.kind == "mill") {
        bool known = false;
        std::string why = mill_key(s, key, val, known);
        if (known) return why;
        return strf(tr("unknown key '%.*s' for a mill"), int(key.size()), key.data());
    }
    if (key == "stock.profile") return points(val, s.lathe.profile);
    if (key == "tailstock.z") {
        s.lathe.tailstock = true;
        return in_range(val, -kBig, kBig, s.lathe.tailstock_z);
    }
    for (const auto& k : kLatheKeys)
        if (key == k.name) return in_range(val, k.lo, k.hi, s.lathe.*k.field);
    return strf(tr("unknown key '%.*s'"), int(key.size()), key.data());
}

// The machining centre's: the stock on the table, the pins beside it, each
// cutter whole.
std::string consistent_mill(const Setup& s) {
    const MillSetup& m = s.mill;
    if (m.stock_z < m.table_z - 1e-9) return tr("stock.z must not be below table.z");
    if (m.setter && m.setter_z < m.table_z - 1e-9) return tr("setter.z must not be below table.z");
    // The height field's memory: 25,000,000 cells take about 150 MB.
    const double cells = std::ceil(m.length / m.cell) * std::ceil(m.width / m.cell);
    if (cells > kMaxCells)
        return strf(tr("the height field would have %.0f cells, at most %.0f: a larger zmap.cell"),
                    cells, kMaxCells);
    for (size_t i = 0; i < m.pins.size(); ++i) {
        const Pin& p = m.pins[i];
        // The pin's circle must not enter the stock's rectangle.
        double dx = std::max({m.stock_x - p.x, 0.0, p.x - (m.stock_x + m.length)});
        double dy = std::max({m.stock_y - p.y, 0.0, p.y - (m.stock_y + m.width)});
        if (std::hypot(dx, dy) < p.diameter / 2 - 1e-6)
            return strf(tr("pin.%d stands inside the stock"), int(i) + 1);
    }
    for (const ToolTruth& t : s.tools) {
        if (t.length <= 0) return strf(tr("tool.%d: length is missing"), t.position);
        if (t.corner > t.radius)
            return strf(tr("tool.%d: corner must not exceed radius"), t.position);
        if (t.probe && t.finder)
            return strf(tr("tool.%d: a probe or an edge finder, not both"), t.position);
    }
    return {};
}

// What no single line can say: the stock fits, the tools make sense.
std::string consistent(const Setup& s) {
    const LatheSetup& l = s.lathe;
    if (s.kind.empty()) return tr("kind = lathe or kind = mill is missing");
    if (s.kind == "mill") return consistent_mill(s);
    if (l.bore >= l.stock_diameter) return tr("stock.bore must be smaller than stock.diameter");
    if (l.stickout >= l.stock_length) return tr("stock.stickout must be shorter than stock.length");
    if (l.stock_diameter / 2 + l.jaw_height > l.chuck_diameter / 2 + 100)
        return tr("the jaws reach far beyond the chuck: check chuck.diameter and jaw.height");
    if (l.tailstock && l.tailstock_z <= l.chuck_z + l.stickout - 1e-9)
        return tr("tailstock.z must be to the right of the stock's face");
    for (const Pt& p : l.profile)
        if (p[0] > 1e-9 || p[0] < -l.stock_length - 1e-9 || p[1] < 0 ||
            p[1] > l.stock_diameter / 2 + 1e-9)
            return tr(
                "stock.profile must lie within the bar: Z from -stock.length to 0, R from 0 to the "
                "radius");
    for (const ToolTruth& t : s.tools)
        if (t.edge <= t.radius)
            return strf(tr("tool.%d: edge must be longer than radius"), t.position);
    return {};
}

}  // namespace

std::string parse_setup(std::string_view text, Setup& s) {
    s = Setup{};
    const std::string_view whole = text;
    Setup out;
    int lineno = 0;
    for (std::string_view line; kv::next_line(text, line, lineno);) {
        size_t eq = line.find('=');
        std::string why = eq == std::string_view::npos
                              ? std::string(tr("expected key = value"))
                              : one_key(out, trim(line.substr(0, eq)), trim(line.substr(eq + 1)));
        if (!why.empty()) {
            std::string_view key = trim(line.substr(0, eq));
            if (eq == std::string_view::npos) return strf(tr("line %d: %s"), lineno, why.c_str());
            return strf(tr("line %d: %.*s: %s"), lineno, int(key.size()), key.data(), why.c_str());
        }
        if (out.tools.size() > 99) return strf(tr("line %d: too many tools"), lineno);
    }
    if (std::string why = consistent(out); !why.empty()) return why;
    out.source = std::string(whole);
    s = std::move(out);
    return {};
}

bool builtin_setup(std::string_view name, Setup& s) {
    if (name == "lathe") return parse_setup(data::setup_lathe(), s).empty();
    if (name == "mill") return parse_setup(data::setup_mill(), s).empty();
    if (name == "mill5") return parse_setup(data::setup_mill5(), s).empty();
    if (name == "cazeneuve") return parse_setup(data::setup_cazeneuve(), s).empty();
    return false;
}

}  // namespace workshop
}  // namespace pupitre
