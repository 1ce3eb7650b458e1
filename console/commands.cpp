// The ':' commands of the input line (DESIGN §2.5): every page and mode is
// reachable by them, which is also how the end-to-end tests drive the console.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <charconv>
#include <cmath>

#include "console/session.hpp"
#include "core/store/store.hpp"

namespace pupitre::console {

namespace {

std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
        size_t j = i;
        while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
        if (j > i) out.push_back(s.substr(i, j - i));
        i = j;
    }
    return out;
}

bool number(std::string_view s, double& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && p == s.data() + s.size() && std::isfinite(out);
}

bool integer(std::string_view s, long& out) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && p == s.data() + s.size();
}

bool on_off(std::string_view s, bool current, bool& out) {
    if (s.empty()) out = !current;
    else if (s == "on") out = true;
    else if (s == "off") out = false;
    else return false;
    return true;
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& command_help() {
    static const std::vector<std::pair<std::string, std::string>> k = {
        {":page om|op|prog|graph|info|param|pref|corr|dir|alarm|help|edit|history", "show a page"},
        {":mode auto|seq|dry|test|rns|imd|jog|inc|pom|edit|modif", "select a mode (refused while a program is in cycle)"},
        {":load N", "select program %N for AUTO, SEQ, DRY RUN, TEST and RNS"},
        {":cycle", "Cycle Start"},
        {":stop", "feed hold (Cycle Start resumes)"},
        {":raz", "RAZ: reset; the run is abandoned, alarms acknowledged"},
        {":jog AXIS DIST", "move an axis by DIST mm (X as a diameter on the lathe), at the jog feed"},
        {":set NAME=VALUE", "PREF.X=-120.5, DEC1.Z=3, D1.R=0.8, L5=2, E80000=18000 (names as --set)"},
        {":search N", "RNS: the block to search for (same as typing N in RNS mode)"},
        {":feed PCT", "feed override, 0 to 120 % (ignored under M49)"},
        {":spindle PCT", "spindle override, 50 to 120 % (ignored under M49)"},
        {":speed x1|x10|max", "animation speed: real time, ten times, as fast as possible"},
        {":skip on|off", "block skip switch: blocks starting with / are skipped"},
        {":m01 on|off", "optional stop switch: M01 stops"},
        {":inc STEP", "INC step in mm (0.001 to 100)"},
        {":rm N", "delete program %N from the store (its history stays)"},
        {":touch AXIS VALUE", "touch-off: PREF so that the tool point reads VALUE (X a diameter on the lathe)"},
        {":measure Dn AXIS VALUE", "tool measurement: the gauge of Dn from a touched face or diameter"},
        {":undo", "undo the last change of an origin or a corrector"},
        {":protect on|off [PIN]", "the memory-protect key: locks programs, origins and correctors"},
        {":protect pin [NEWPIN]", "set (or remove) the PIN that unlocks the protection"},
        {":edit N", "EDIT: open program %N (new if absent; without N the one selected)"},
        {":save", "save the program edited, after a syntax check (:save! saves despite an error)"},
        {":goto Nnnn", "EDIT: the cursor to block Nnnn"},
        {":find TEXT", "EDIT: the next block containing TEXT"},
        {":renum [START [STEP]]", "EDIT: renumber the N labels (default 10 10) and their references"},
        {":history / :restore REV", "EDIT: the revisions of the program, and making one current again"},
        {":close", "EDIT: close the program (asks before dropping unsaved changes; :close! does not)"},
        {":recover / :discard", "EDIT: load the changes an earlier session left unsaved, or drop them"},
        {":mode modif", "MODIF: change the blocks to come of an interrupted program"},
        {":quit", "leave the console, also Ctrl-C (asks before dropping unsaved changes; :quit! does not)"},
    };
    return k;
}

Effect Session::command(std::string_view text) {
    auto w = words(text);
    if (w.empty()) return Effect::none;
    std::string_view cmd = w[0];
    std::string_view a1 = w.size() > 1 ? w[1] : std::string_view{};
    std::string why;
    auto usage = [&](std::string_view u) {
        say(std::string("usage: ") + std::string(u), true);
        return Effect::redraw;
    };
    if (cmd == "quit" || cmd == "q" || cmd == "quit!" || cmd == "q!") return quit_command(cmd.back() == '!');
    if (cmd == "recover" || cmd == "discard") return recover_command(cmd == "discard");
    if (cmd == "page") {
        pages::PageId p;
        if (!pages::parse_page(a1, p)) {
            return usage(":page om|op|prog|graph|info|param|pref|corr|dir|alarm|help|edit|history");
        }
        show_page(p);
        return Effect::redraw;
    }
    if (cmd == "mode") {
        Mode m;
        if (!parse_mode(a1, m)) {
            if (a1 == "modif") return modif_start();
            if (a1 == "edit") return command("edit");
            return usage(":mode auto|seq|dry|test|rns|imd|jog|inc|pom");
        }
        if (!sim().set_mode(m, why)) say(why, true);
        else say(mode_news(m));
        return Effect::redraw;
    }
    if (cmd == "load") {
        long n;
        std::string_view s = a1;
        if (!s.empty() && s.front() == '%') s.remove_prefix(1);
        if (!integer(s, n) || n < 0) return usage(":load N");
        select_program(int(n));
        return Effect::redraw;
    }
    if (cmd == "cycle") {
        if (!modif_apply()) return Effect::redraw;
        if (!sim().cycle_start(why)) {
            say(why, true);
            return Effect::redraw;
        }
        // The run's end is news even when it comes within one frame ("max").
        last_state_ = sim().state();
        if (!sim().message().empty()) say(sim().message());
        else if (sim().selected() >= 0 && (sim().mode() == Mode::automatic || sim().mode() == Mode::single ||
                                           sim().mode() == Mode::dry || sim().mode() == Mode::test))
            say("Cycle Start: %" + std::to_string(sim().selected()) + " in " + std::string(mode_name(sim().mode())));
        else
            say("Cycle Start (" + std::string(mode_name(sim().mode())) + ")");
        return Effect::redraw;
    }
    if (cmd == "stop") {
        sim().feed_hold();
        say("feed hold: Cycle Start resumes, RAZ abandons the run");
        return Effect::redraw;
    }
    if (cmd == "raz") {
        if (modif) {
            modif = false;
            editor.close();
            show_page(pages::PageId::prog);
        }
        sim().raz();
        say("RAZ");
        return Effect::redraw;
    }
    if (cmd == "jog") {
        double d;
        if (w.size() != 3 || a1.size() != 1 || axis_of(char(std::toupper(a1[0]))) < 0 || !number(w[2], d))
            return usage(":jog AXIS DIST, e.g. :jog X -10");
        if (!sim().jog(axis_of(char(std::toupper(a1[0]))), d, why)) say("JOG: " + why, true);
        return Effect::redraw;
    }
    if (cmd == "set") {
        std::string rest(text.substr(text.find("set") + 3));
        return set_value(rest);
    }
    if (cmd == "search") {
        long n;
        std::string_view s = a1;
        if (!s.empty() && (s.front() == 'N' || s.front() == 'n')) s.remove_prefix(1);
        if (!integer(s, n) || !sim().search(n, why)) return usage(":search N (in RNS mode)");
        say(sim().message());
        return Effect::redraw;
    }
    if (cmd == "feed" || cmd == "spindle") {
        long n;
        bool feed = cmd == "feed";
        if (!integer(a1, n) || n < (feed ? 0 : 50) || n > 120) return usage(feed ? ":feed 0..120" : ":spindle 50..120");
        (feed ? sim().feed_override : sim().spindle_override) = int(n);
        say(std::string(feed ? "feed" : "spindle") + " override " + std::to_string(n) + " %" +
            (sim().overrides_inhibited() ? " (inhibited by M49)" : ""));
        return Effect::redraw;
    }
    if (cmd == "speed") {
        if (a1 == "x1") speed = Speed::real;
        else if (a1 == "x10") speed = Speed::x10;
        else if (a1 == "max") speed = Speed::max;
        else return usage(":speed x1|x10|max");
        return Effect::redraw;
    }
    if (cmd == "skip" || cmd == "m01") {
        bool& sw = cmd == "skip" ? sim().block_skip() : sim().optional_stop();
        bool v;
        if (!on_off(a1, sw, v)) return usage(cmd == "skip" ? ":skip on|off" : ":m01 on|off");
        sw = v;
        say(std::string(cmd == "skip" ? "block skip " : "optional stop M01 ") + (v ? "ON" : "off"));
        return Effect::redraw;
    }
    if (cmd == "inc") {
        double d;
        if (!number(a1, d) || d < 0.001 || d > 100) return usage(":inc STEP (0.001 to 100 mm)");
        sim().increment = d;
        say("INC step " + pages::fmt_len(d) + " mm");
        return Effect::redraw;
    }
    if (cmd == "rm") {
        long n;
        if (!integer(a1, n)) return usage(":rm N");
        delete_program(int(n));
        return Effect::redraw;
    }
    if (cmd == "touch") {
        double v;
        int axis = a1.size() == 1 ? axis_of(char(std::toupper(a1[0]))) : -1;
        if (w.size() != 3 || axis < 0 || !number(w[2], v)) return usage(":touch AXIS VALUE, e.g. :touch Z 0");
        return touch(axis, v);
    }
    if (cmd == "measure") {
        double v;
        long d = 0;
        int axis = w.size() > 2 && w[2].size() == 1 ? axis_of(char(std::toupper(w[2][0]))) : -1;
        bool ok = w.size() == 4 && a1.size() > 1 && (a1[0] == 'D' || a1[0] == 'd') && integer(a1.substr(1), d) &&
                  axis >= 0 && number(w[3], v);
        if (!ok) return usage(":measure Dn AXIS VALUE, e.g. :measure D2 X 59.978");
        corr_cursor = int(d);
        return measure(int(d), axis, v);
    }
    if (cmd == "undo") return undo();
    if (cmd == "protect") return protect_command(text.substr(std::min(text.size(), text.find("protect") + 7)));
    if (cmd == "edit") {
        long n;
        std::string_view s = a1;
        if (!s.empty() && s.front() == '%') s.remove_prefix(1);
        if (s.empty()) {
            if (editor.is_open()) {
                show_page(pages::PageId::edit);
                return Effect::redraw;
            }
            if (page == pages::PageId::dir && !programs().empty()) return edit_open(programs()[size_t(dir_cursor)].number);
            if (sim().selected() >= 0) return edit_open(sim().selected());
            return usage(":edit N");
        }
        if (!integer(s, n) || n < 0 || n > 99999) return usage(":edit N");
        return edit_open(int(n));
    }
    if (cmd == "save" || cmd == "save!") return edit_save(cmd == "save!");
    if (cmd == "close" || cmd == "close!") {
        if (modif) return usage(":close is for EDIT; MODIF ends with Cycle Start or RAZ");
        if (!editor.is_open()) return usage(":edit N first");
        int n = editor.number;
        auto close = [this, n] {
            bool dirty = editor.dirty;
            editor.close();
            drop_journal(n);
            release_lease();
            say(dirty ? "editor closed (unsaved changes dropped)" : "editor closed");
        };
        if (editor.dirty && cmd == "close") {
            confirm("%" + std::to_string(n) + " has unsaved changes: close and drop them?", close);
            return Effect::redraw;
        }
        close();
        return Effect::redraw;
    }
    if (cmd == "goto" || cmd == "find") {
        if (!editor.is_open()) return usage(":edit N first");
        long n;
        std::string_view s = a1;
        if (!s.empty() && (s.front() == 'N' || s.front() == 'n')) s.remove_prefix(1);
        bool ok = cmd == "goto" ? integer(s, n) && editor.goto_n(n)
                                : editor.find(text.substr(std::min(text.size(), text.find("find") + 5)));
        show_page(pages::PageId::edit);
        if (!ok) say(cmd == "goto" ? "no block N" + std::string(s) : "not found", true);
        return Effect::redraw;
    }
    if (cmd == "renum") {
        if (!editor.is_open()) return usage(":edit N first");
        long start = 10, step = 10;
        if (w.size() > 1 && !integer(w[1], start)) return usage(":renum [START [STEP]]");
        if (w.size() > 2 && !integer(w[2], step)) return usage(":renum [START [STEP]]");
        if (start < 0 || step < 1) return usage(":renum [START [STEP]]");
        int k = editor.renumber(start, step);
        say(std::to_string(k) + " blocks renumbered from N" + std::to_string(start) + " by " + std::to_string(step) +
            "; G77/G79/cycle references follow");
        return Effect::redraw;
    }
    if (cmd == "history") return edit_history();
    if (cmd == "restore") {
        long r;
        if (!integer(a1, r)) return usage(":restore REV (see :history)");
        return edit_restore(int(r));
    }
    if (cmd == "help") {
        show_page(pages::PageId::help);
        return Effect::redraw;
    }
    say("unknown command :" + std::string(cmd) + " (F1 lists the commands)", true);
    return Effect::redraw;
}

}  // namespace pupitre::console
