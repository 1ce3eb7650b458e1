// The setting desk (see setting.hpp): the PREF and CORR pages, touch-off, tool
// measurement, changes made during a run, undo, and the memory-protect key.
// Every change is stored with an audit row (the store's set_values).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/setting.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "core/interp/value_name.hpp"
#include "core/sim/setting.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

std::string mm(double v) {
    return pages::fmt_len(v);
}

bool is_origin(std::string_view name) {
    ValueName n;
    return parse_value_name(name, n) && n.kind == ValueName::Kind::origin;
}

// A number typed on a setting page. A French decimal comma (Z 1,5) is read
// as a point (docs/decisions.md, A decimal comma on the setting pages); `comma`
// says so, to echo it.
bool parse_num(std::string_view s, double& v, bool* comma = nullptr) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    std::string text(s);
    size_t c = text.find(',');
    if (c != std::string::npos && text.find(',', c + 1) == std::string::npos &&
        text.find('.') == std::string::npos) {
        text[c] = '.';
        if (comma) *comma = true;
    }
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    return ec == std::errc() && p == text.data() + text.size() && std::isfinite(v);
}

// An ISO block typed on a setting page ("T1 D1 M6", "G0 X40 Z25"): a word
// of the program's letters first, or two address words. What these pages
// read is one word and a number ("X 59.978", "D5", "PREF.Z=-300").
bool looks_like_block(std::string_view t) {
    auto address = [](std::string_view w) {
        return w.size() > 1 && std::isalpha(static_cast<unsigned char>(w[0])) &&
               (std::isdigit(static_cast<unsigned char>(w[1])) || w[1] == '-' || w[1] == '.');
    };
    size_t sp = t.find(' ');
    std::string_view first = t.substr(0, sp);
    if (!first.empty() && first[0] == '%') return true;
    if (address(first) && std::string_view("GMTSFN").find(first[0]) != std::string_view::npos)
        return true;
    if (sp == std::string_view::npos || !address(first)) return false;
    std::string_view rest = t.substr(sp + 1);
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    return address(rest.substr(0, rest.find(' ')));
}

// The field of a corrector a setting names ("D3.X" -> X), of either machine,
// or nullptr. A field of the other machine is Interpreter::set's to refuse,
// with its message.
const CorrField* corrector_field(std::string_view name) {
    ValueName n;
    return parse_value_name(name, n) && n.kind == ValueName::Kind::corrector ? n.field : nullptr;
}

}  // namespace

void SettingDesk::load() {
    if (store::Store* st = b_.store())
        if (auto r = st->setting("protect.on"); !r.error && r.value) protect_ = *r.value == "1";
    load_witness();
}

void SettingDesk::move_corrector(int delta) {
    corr_cursor_ = std::clamp(corr_cursor_ + delta, 1, b_.machine().correctors);
}

void SettingDesk::view(pages::View& v) const {
    v.corr_cursor = corr_cursor_;
    v.pending = pending_origins();
    v.protect = protect_;
    v.undo_depth = undo_.size();
    v.last_setting = last_setting_;
    v.witness = witness_text();
}

bool SettingDesk::unprotected(std::string_view what) {
    if (!protect_) return true;
    b_.say(
        what == "programs"
            ? tr("memory protection is on: programs cannot be changed (:protect off)")
        : what == "origins and correctors"
            ? tr("memory protection is on: origins and correctors cannot be changed (:protect off)")
        : what == "the PIN"
            ? tr("memory protection is on: the PIN cannot be changed (:protect off)")
            : strf(tr("memory protection is on: %s cannot be changed (:protect off)"),
                   std::string(what).c_str()),
        true);
    return false;
}

bool SettingDesk::apply(const std::string& name, double value, const std::string& source) {
    if (!unprotected("origins and correctors")) return false;
    if (std::abs(value) > 100000) {
        b_.say(strf(tr("%s: %s is beyond any machine"), name.c_str(), mm(value).c_str()), true);
        return false;
    }
    // A lathe's nose orientation D3.C is a code; PREF.C, the origin of a
    // rotary axis C, is an angle: the vocabulary tells them apart.
    bool code = value_unit(name) == ValueUnit::whole;
    if (code && (value != std::floor(value) || value < 0 || value > 8)) {
        b_.say(strf(tr("%s: the nose orientation is a code from 0 to 8"), name.c_str()), true);
        return false;
    }
    const CorrField* field = corrector_field(name);
    if (field && field->text == "R" && value < 0) {
        b_.say(strf(tr("%s: a tool or nose radius is never negative (its wear goes in %s)"),
                    name.c_str(), b_.machine().lathe ? "DX/DZ" : "DR"),
               true);
        return false;
    }
    Interpreter& in = b_.sim().interp();
    double old = 0;
    bool had = in.get(name, old);
    bool running = b_.sim().in_cycle();
    std::string why = in.set(name, value, !running);
    if (!why.empty()) {
        b_.say(name + ": " + why, true);
        return false;
    }
    if (!had) in.get(name, old);
    if (running && is_origin(name)) pending_origin_[name] = in.moves();
    // No program in cycle: the tool the setter holds is the one shown, at once.
    if (!running) in.apply_gauges_now();
    undo_.push_back({name, old});
    std::string news = name + " " + (code ? std::to_string(int(old)) : mm(old)) + " -> " +
                       (code ? std::to_string(int(value)) : mm(value));
    if (running)
        news += std::string(" ") + (is_origin(name)
                                        ? tr("(applies at the next move)")
                                        : tr("(applies as the manual says: gauge at the next move "
                                             "of its axis, radius at the next G41/G42)"));
    Bench::Stored st = b_.store_values({{name, store::internal_value(name, value)}}, source);
    if (st.kept) {
        b_.say(strf(tr("%s; %s"), news.c_str(), st.why.c_str()), true);
        return true;
    }
    if (!st.why.empty()) {
        b_.say(strf(tr("%s; NOT stored: %s"), news.c_str(), st.why.c_str()), true);
        return true;
    }
    b_.say(news);
    return true;
}

std::vector<std::string> SettingDesk::pending_origins() const {
    std::vector<std::string> out;
    if (!b_.sim().in_cycle()) return out;
    for (const auto& [name, moves] : pending_origin_)
        if (b_.sim().interp().moves() == moves) out.push_back(name);
    return out;
}

// Touch-off and measurement use the interpreter's position: it must be the
// position shown, so the axes must be at rest and no program in cycle.
static std::string at_rest(const Sim& s) {
    if (s.state() == RunState::running) return tr("wait until the axes stop");
    if (s.in_cycle()) return tr("a program is interrupted: RAZ first");
    if (s.alarm_active()) return tr("an alarm is active: RAZ first");
    return {};
}

// A gauge longer than the axis travel cannot be a tool's: the question to ask
// first, or "".
std::string SettingDesk::implausible_gauge(const std::string& name, double value) const {
    const CorrField* field = corrector_field(name);
    const GaugeAxis gauge = field ? field->gauge : GaugeAxis::none;
    int axis = gauge == GaugeAxis::x           ? X
               : gauge == GaugeAxis::z         ? Z
               : gauge == GaugeAxis::tool_axis ? b_.sim().interp().modal().tool_axis
                                               : -1;
    if (axis < 0 || !b_.machine().has(axis)) return {};
    const AxisConfig& ax = b_.machine().axes[size_t(axis)];
    double travel = ax.max - ax.min;
    if (!(travel > 0 && travel < 1e8) || std::abs(value) <= travel) return {};
    return strf(tr("%s = %s is longer than the %c travel (%s). Keep it?"), name.c_str(),
                mm(value).c_str(), kAxisNames[size_t(axis)], mm(travel).c_str());
}

Effect SettingDesk::touch(int axis, double surface) {
    if (std::string w = at_rest(b_.sim()); !w.empty()) {
        b_.say(strf(tr("touch-off: %s"), w.c_str()), true);
        return Effect::redraw;
    }
    if (b_.sim().corrector() == 0) {
        // D0: the gauge is zero, so PREF would place the turret reference (or the
        // spindle nose), not a tool point, on the surface. Rare, never silent.
        b_.confirm(strf(tr("D0, no tool gauge (T%d): the turret reference would read %c %s."),
                        b_.sim().tool(), kAxisNames[size_t(axis)], mm(surface).c_str()),
                   [this, axis, surface] { touch_now(axis, surface); });
        return Effect::redraw;
    }
    return touch_now(axis, surface);
}

Effect SettingDesk::touch_now(int axis, double surface) {
    if (std::string w = at_rest(b_.sim()); !w.empty()) {  // again: a "y" may come late
        b_.say(strf(tr("touch-off: %s"), w.c_str()), true);
        return Effect::redraw;
    }
    // The gauge of the active corrector is the one the touch-off assumes: it
    // applies now (not at the next move), so OP reads what was typed.
    b_.sim().interp().apply_gauges_now();
    setting::Touch t;
    if (std::string why = setting::touch_off(b_.sim().interp(), axis, surface, t); !why.empty()) {
        b_.say(strf(tr("touch-off: %s"), why.c_str()), true);
        return Effect::redraw;
    }
    if (apply(t.name, t.after,
              "touch-off " + std::string(1, kAxisNames[size_t(axis)]) + " " + mm(surface))) {
        last_setting_ = t.formula + " " + strf(tr("(was %s)"), mm(t.before).c_str());
        // On CORR a student who means the tool's gauge types :touch (found
        // touching a tool off by keys): say what changed and what was meant.
        // The hint first: the message line is cut at the screen's width.
        b_.say(b_.page() == pages::PageId::corr
                   ? strf(tr(":touch set PREF, not D%d (here type %c %s; :undo): %s"),
                          b_.sim().corrector(), kAxisNames[size_t(axis)], mm(surface).c_str(),
                          last_setting_.c_str())
                   : last_setting_);
    }
    return Effect::redraw;
}

Effect SettingDesk::measure(int d, int axis, double surface) {
    if (std::string w = at_rest(b_.sim()); !w.empty()) {
        b_.say(strf(tr("measure: %s"), w.c_str()), true);
        return Effect::redraw;
    }
    setting::Touch t;
    if (std::string why = setting::measure(b_.sim().interp(), d, axis, surface, t); !why.empty()) {
        b_.say(strf(tr("measure: %s"), why.c_str()), true);
        return Effect::redraw;
    }
    if (apply(t.name, t.after,
              "measure " + std::string(1, kAxisNames[size_t(axis)]) + " " + mm(surface))) {
        last_setting_ = t.formula + " " + strf(tr("(was %s)"), mm(t.before).c_str());
        b_.say(last_setting_);
    }
    return Effect::redraw;
}

Effect SettingDesk::undo() {
    if (undo_.empty()) {
        b_.say(tr("nothing to undo"), true);
        return Effect::redraw;
    }
    Undo u = undo_.back();
    undo_.pop_back();
    if (apply(u.name, u.old, "undo")) {
        undo_.pop_back();  // the undo itself is not undone by the next :undo
        b_.say(strf(tr("undone: %s = %s"), u.name.c_str(), mm(u.old).c_str()));
    }
    return Effect::redraw;
}

// The memory-protect key of the panel, with an optional PIN kept hashed.
Effect SettingDesk::protect_command(std::string_view args) {
    std::string a(args);
    while (!a.empty() && a.front() == ' ') a.erase(0, 1);
    std::string word = a.substr(0, a.find(' '));
    std::string rest = a.find(' ') == std::string::npos ? "" : a.substr(a.find(' ') + 1);
    auto stored_pin = [&]() -> std::string {
        if (!b_.store()) return {};
        auto r = b_.store()->setting("protect.pin");
        return !r.error && r.value ? *r.value : std::string();
    };
    auto save_state = [&]() {
        if (b_.store()) b_.store()->set_setting("protect.on", protect_ ? "1" : "0");
    };
    if (word == "on" || (word.empty() && !protect_)) {
        protect_ = true;
        save_state();
        b_.say(tr("memory protection ON: programs, origins and correctors are locked"));
    } else if (word == "off" || word.empty()) {
        std::string pin = stored_pin();
        if (!pin.empty()) {
            std::string salt = pin.substr(0, pin.find(':'));
            if (rest.empty() || salt + ":" + sha256_hex(salt + rest) != pin) {
                b_.say(tr("memory protection: wrong PIN (:protect off PIN)"), true);
                return Effect::redraw;
            }
        }
        protect_ = false;
        save_state();
        b_.say(tr("memory protection off"));
    } else if (word == "pin") {
        if (!unprotected("the PIN")) return Effect::redraw;
        if (!b_.store()) {
            b_.say(tr("no store: the PIN cannot be kept"), true);
        } else if (rest.empty()) {
            b_.store()->set_setting("protect.pin", "");
            b_.say(tr("PIN removed: the protection key needs none"));
        } else {
            const std::string salt = random_hex(8);
            b_.store()->set_setting("protect.pin", salt + ":" + sha256_hex(salt + rest));
            b_.say(tr("PIN set: :protect off PIN is needed to unlock"));
        }
    } else {
        b_.say(strf(tr("usage: %s"), ":protect [on|off [PIN]|pin [NEWPIN]]"), true);
    }
    return Effect::redraw;
}

// The message line says how a decimal comma was read.
void SettingDesk::echo_comma(std::string_view typed, double v) {
    b_.message() = strf(tr("read %s as %s: %s"), std::string(typed).c_str(), mm(v).c_str(),
                        b_.message().c_str());
}

// Text typed on the PREF page: NAME=VALUE, or AXIS VALUE for a touch-off.
// On the CORR page: FIELD=VALUE for the corrector under the cursor, Dn to
// choose one, AXIS VALUE to measure it by touching a surface.
Effect SettingDesk::text(std::string_view text) {
    std::string t(text);
    for (char& c : t) c = char(std::toupper(static_cast<unsigned char>(c)));
    size_t eq = t.find('=');
    bool corr = b_.page() == pages::PageId::corr;
    if (eq == std::string::npos && looks_like_block(t)) {
        // TRANSLATORS: on the PREF or CORR page, an ISO block typed there.
        b_.say(tr("ISO blocks are typed in IMD on the OP page (F2), not here"), true);
        return Effect::redraw;
    }
    if (eq != std::string::npos) {
        std::string name = t.substr(0, eq);
        while (!name.empty() && name.back() == ' ') name.pop_back();
        double v;
        bool comma = false;
        if (!parse_num(std::string_view(t).substr(eq + 1), v, &comma)) {
            b_.say(strf(tr("%s: not a number (use a decimal point: 1.5)"), name.c_str()), true);
            return Effect::redraw;
        }
        if (corr && name.find('.') == std::string::npos) name = corrector_name(corr_cursor_, name);
        std::string source = corr ? "page CORR" : "page PREF";
        if (std::string question = implausible_gauge(name, v); !question.empty()) {
            b_.confirm(question, [this, name, v, source] { apply(name, v, source); });
            return Effect::redraw;
        }
        if (apply(name, v, source) && comma) echo_comma(text, v);
        return Effect::redraw;
    }
    if (corr && t.size() > 1 && t[0] == 'D' && std::isdigit(static_cast<unsigned char>(t[1]))) {
        int d = std::atoi(t.c_str() + 1);
        if (d < 1 || d > b_.machine().correctors)
            b_.say(strf(tr("correctors are D1 to D%d"), b_.machine().correctors), true);
        else
            corr_cursor_ = d;
        return Effect::redraw;
    }
    int axis = t.empty() ? -1 : axis_of(t[0]);
    double v;
    bool comma = false;
    if (axis >= 0 && parse_num(std::string_view(t).substr(1), v, &comma)) {
        if (!corr)
            touch(axis, v);
        else if (corr_cursor_ != b_.sim().corrector() && at_rest(b_.sim()).empty()) {
            // The tool touching is the one of the active corrector: measuring
            // another asks first (docs/decisions.md, :measure never asks).
            int d = corr_cursor_;
            // TRANSLATORS: the corrector under the cursor, the active one, the first again.
            b_.confirm(
                strf(tr("D%d is not the active corrector (D%d): measure D%d with this tool?"), d,
                     b_.sim().corrector(), d),
                [this, d, axis, v] { measure(d, axis, v); });
        } else {
            measure(corr_cursor_, axis, v);
        }
        if (comma && !b_.message_is_error()) echo_comma(text, v);
        return Effect::redraw;
    }
    b_.say(corr ? strf(tr("CORR: X=63.345 sets a field of D%d, D5 chooses a corrector, X 59.978 "
                          "measures by a touched diameter"),
                       corr_cursor_)
                : std::string(tr(
                      "PREF: PREF.Z=-300 or DEC1.X=2 sets a value, Z 0 or X 59.978 touches off")),
           true);
    return Effect::redraw;
}

}  // namespace pupitre::console
