// The ':' commands of the input line (pupitre(1), COMMANDS): every page and mode is
// reachable by them, which is also how the end-to-end tests drive the console.
// One small function per command, and at the end the table that names them.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/commands.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "console/exercise.hpp"
#include "console/exercise_run.hpp"
#include "console/part_paper.hpp"
#include "console/session.hpp"
#include "console/workshop_io.hpp"
#include "core/i18n.hpp"
#include "core/workshop/report.hpp"
#include "pages/pages.hpp"

namespace pupitre::console {

struct CommandCall {
    std::string_view text;                // the line, without the ':'
    std::vector<std::string_view> words;  // words[0]: the name as typed
    std::string_view name() const { return words[0]; }
    std::string_view arg(size_t i) const {
        return i < words.size() ? words[i] : std::string_view{};
    }
    // What follows the name, blanks included: :set and :protect parse it.
    std::string_view rest() const { return text.substr(text.find(name()) + name().size()); }
};

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

// A number typed in a command; a French decimal comma (:jog X -1,5) is read
// as a point, as on the setting pages (README). Programs keep error 1.
bool number(std::string_view s, double& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    std::string t(s);
    if (size_t c = t.find(','); c != std::string::npos && t.find(',', c + 1) == std::string::npos &&
                                t.find('.') == std::string::npos)
        t[c] = '.';
    auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
    return ec == std::errc() && p == t.data() + t.size() && std::isfinite(out);
}

bool integer(std::string_view s, long& out) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && p == s.data() + s.size();
}

bool on_off(std::string_view s, bool current, bool& out) {
    if (s.empty())
        out = !current;
    else if (s == "on")
        out = true;
    else if (s == "off")
        out = false;
    else
        return false;
    return true;
}

// "%300" -> "300", "N40" -> "40": the letter the operator may type first.
std::string_view drop_prefix(std::string_view s, std::string_view letters) {
    if (!s.empty() && letters.find(s.front()) != std::string_view::npos) s.remove_prefix(1);
    return s;
}

// The axis a one-letter word names, or -1.
int axis_word(std::string_view s) {
    return s.size() == 1 ? axis_of(char(std::toupper(static_cast<unsigned char>(s[0])))) : -1;
}

// "AXIS VALUE" as the last two words, from word `at` (:jog, :touch, :measure).
bool axis_value(const CommandCall& c, size_t at, int& axis, double& v) {
    axis = axis_word(c.arg(at));
    return c.words.size() == at + 2 && axis >= 0 && number(c.words[at + 1], v);
}

const Command* find_command(std::string_view name);

Effect usage(Session& s, std::string_view u) {
    s.say(strf(tr("usage: %s"), std::string(u).c_str()), true);
    return Effect::redraw;
}

// ---- pages, modes and the run ----

Effect page(Session& s, const CommandCall& c) {
    pages::PageId p;
    if (!pages::parse_page(c.arg(1), p))
        return usage(
            s,
            ":page "
            "om|op|prog|graph|info|param|pref|corr|dir|alarm|help|edit|history|shop|exercise|part");
    s.show_page(p);
    return Effect::redraw;
}

// MODIF and EDIT are the editor's, not the machine's: the Sim has no such mode.
Effect mode(Session& s, const CommandCall& c) {
    std::string_view name = c.arg(1);
    Mode m;
    if (!parse_mode(name, m)) {
        if (name == "modif") return s.editing().modif_start();
        if (name == "edit") return s.command("edit");
        return usage(s, find_command("mode")->usage);  // the table's: every word it takes
    }
    if (std::string why = s.sim().set_mode(m); !why.empty())
        s.say(why, true);
    else
        s.say(s.mode_news(m));
    return Effect::redraw;
}

Effect load(Session& s, const CommandCall& c) {
    long n;
    if (!integer(drop_prefix(c.arg(1), "%"), n) || n < 0) return usage(s, ":load N");
    s.select_program(int(n));
    return Effect::redraw;
}

Effect feed_hold(Session& s, const CommandCall&) {
    s.sim().feed_hold();
    s.say(tr("feed hold: Cycle Start resumes, RAZ abandons the run"));
    return Effect::redraw;
}

// RAZ also ends MODIF: the interrupted program is abandoned with the run.
Effect raz(Session& s, const CommandCall&) {
    s.editing().abandon_modif();
    s.sim().raz();
    s.say("RAZ");
    return Effect::redraw;
}

Effect jog(Session& s, const CommandCall& c) {
    double d;
    int axis;
    if (!axis_value(c, 1, axis, d)) return usage(s, tr(":jog AXIS DIST, e.g. :jog X -10"));
    if (std::string why = s.sim().jog(axis, d); !why.empty())
        s.say(strf(tr("JOG: %s"), why.c_str()), true);
    return Effect::redraw;
}

Effect search(Session& s, const CommandCall& c) {
    long n;
    if (!integer(drop_prefix(c.arg(1), "Nn"), n) || !s.sim().search(n).empty())
        return usage(s, tr(":search N (in RNS mode)"));
    s.say(s.sim().message());
    return Effect::redraw;
}

// :feed and :spindle, the override knobs of the panel.
Effect override_knob(Session& s, const CommandCall& c, bool feed) {
    long n;
    if (!integer(c.arg(1), n) || n < (feed ? 0 : 50) || n > 120)
        return usage(s, feed ? ":feed 0..120" : ":spindle 50..120");
    (feed ? s.sim().feed_override : s.sim().spindle_override) = int(n);
    std::string news = strf(feed ? tr("feed override %ld %%") : tr("spindle override %ld %%"), n);
    if (s.sim().overrides_inhibited()) news += std::string(" ") + tr("(inhibited by M49)");
    s.say(news);
    return Effect::redraw;
}

Effect speed(Session& s, const CommandCall& c) {
    std::string_view a = c.arg(1);
    if (a == "x1")
        s.set_speed(Speed::real);
    else if (a == "x10")
        s.set_speed(Speed::x10);
    else if (a == "max")
        s.set_speed(Speed::max);
    else
        return usage(s, ":speed x1|x10|max");
    return Effect::redraw;
}

// :skip and :m01, the two switches of the panel; without a word, they toggle.
Effect panel_switch(Session& s, const CommandCall& c, bool skip) {
    bool& sw = skip ? s.sim().block_skip() : s.sim().optional_stop();
    bool v;
    if (!on_off(c.arg(1), sw, v)) return usage(s, skip ? ":skip on|off" : ":m01 on|off");
    sw = v;
    s.say(skip ? (v ? tr("block skip ON") : tr("block skip off"))
               : (v ? tr("optional stop M01 ON") : tr("optional stop M01 off")));
    return Effect::redraw;
}

Effect inc(Session& s, const CommandCall& c) {
    double d;
    if (!number(c.arg(1), d) || d < 0.001 || d > 100)
        return usage(s, tr(":inc STEP (0.001 to 100 mm)"));
    s.sim().increment = d;
    s.say(strf(tr("INC step %s mm"), pages::fmt_len(d).c_str()));
    return Effect::redraw;
}

// ---- settings ----

Effect touch(Session& s, const CommandCall& c) {
    double v;
    int axis;
    if (!axis_value(c, 1, axis, v)) return usage(s, tr(":touch AXIS VALUE, e.g. :touch Z 0"));
    return s.setting().touch(axis, v);
}

// ---- the workshop (pupitre-setup(5)) ----

// An instrument's reading of the part: ":measure dia Z-20".
Effect read_instrument(Session& s, const CommandCall& c) {
    return s.read_part(c.rest());
}

Effect setup(Session& s, const CommandCall& c) {
    std::string_view what = c.arg(1);
    workshop::Workshop* now = s.sim().shop();
    if (s.hidden(":setup")) return Effect::redraw;
    if (what.empty()) {
        s.say(now ? strf(tr("workshop: setup %s, %s"), now->setup().name.c_str(),
                         pages::tr_text(now->setup().description).c_str())
                  : strf(tr("no workshop: the machine moves a point (:setup %s)"),
                         s.machine_setup()));
        return Effect::redraw;
    }
    if (s.sim().in_cycle()) {
        s.say(tr("a program is in cycle"), true);
        return Effect::redraw;
    }
    if (what == "off") {
        s.sim().set_workshop(nullptr);
        s.say(tr("workshop off: the machine moves a point"));
        s.save_workshop();
        return Effect::redraw;
    }
    workshop::Setup st;
    if (std::string why = read_setup(std::string(what), s.machine(), st); !why.empty()) {
        s.say(why, true);
        return Effect::redraw;
    }
    s.sim().set_workshop(std::make_unique<workshop::Workshop>(s.machine(), st, nullptr));
    s.say(strf(st.kind == "mill" ? tr("workshop: setup %s, %s; a fresh block in the vice")
                                 : tr("workshop: setup %s, %s; fresh stock in the chuck"),
               st.name.c_str(), pages::tr_text(st.description).c_str()));
    s.save_workshop();
    return Effect::redraw;
}

// The paper test: a shim of known thickness between the tool and the part.
Effect shim(Session& s, const CommandCall& c) {
    workshop::Workshop* w = s.sim().shop();
    if (!w) {
        s.say(s.no_workshop(), true);
        return Effect::redraw;
    }
    double mm = 0;
    if (c.arg(1) == "off") {
        w->set_shim(0);
        s.say(tr("no shim on the part"));
        return Effect::redraw;
    }
    if (!number(c.arg(1), mm) || mm < 0.005 || mm > 50 || !c.arg(2).empty())
        return usage(s, tr(":shim MM (0.005 to 50) or :shim off"));
    w->set_shim(mm);
    if (ExerciseRun* x = s.exercise()) x->note_shim(mm);
    s.say(strf(tr("a %s mm shim on the part: a jog stops when the tool pinches it; subtract it "
                  "when you touch off"),
               pages::fmt_len(mm).c_str()));
    return Effect::redraw;
}

// A gauge block held against the jaws' face (seed 004's exam: "une cale
// étalon de 100 mm sur la face du porte-pièce"): a jog stops on its end, so
// the touch-off gives the jaws' face plus its length.
Effect gauge(Session& s, const CommandCall& c) {
    workshop::Workshop* w = s.sim().shop();
    if (!w) {
        s.say(s.no_workshop(), true);
        return Effect::redraw;
    }
    if (w->is_mill()) {
        s.say(tr("on the machining centre a gauge block on the part is :shim MM"), true);
        return Effect::redraw;
    }
    double mm = 0;
    if (c.arg(1) == "off" && c.arg(2).empty()) {
        w->set_gauge_block(0);
        s.say(tr("no gauge block against the jaws"));
        return Effect::redraw;
    }
    if (!number(c.arg(1), mm) || mm < 1 || mm > 500 || !c.arg(2).empty())
        return usage(s, tr(":gauge MM (1 to 500) or :gauge off"));
    w->set_gauge_block(mm);
    if (ExerciseRun* x = s.exercise()) x->note_shim(mm);
    s.say(strf(tr("a %s mm gauge block against the jaws' face, 2 mm above the bar: a jog stops "
                  "on its end"),
               pages::fmt_len(mm).c_str()));
    return Effect::redraw;
}

// A view of the PART page the machine has, or says which it has.
bool parse_part_view(Session& s, std::string_view word, bool mill, render::PartMode& m) {
    if (render::parse_mode(word, m) && render::mode_fits(m, mill)) return true;
    s.say(mill ? tr("the machining centre's views: top, 3d") : tr("the lathe's view: section"),
          true);
    return false;
}

// ":part export FILE [VIEW]": the picture on a sheet (part_paper.hpp) for
// FILE.pdf, a lathe's FILE.png or any with a VIEW; else the part as
// write_part writes it (workshop_io.hpp).
Effect export_part(Session& s, const workshop::Workshop& w, const std::string& path,
                   std::string_view view) {
    render::Look look = s.part().look(w.is_mill());
    if (!view.empty() && !parse_part_view(s, view, w.is_mill(), look.mode)) return Effect::redraw;
    Answer<int> done;
    const bool heights = w.is_mill() && view.empty() && path.ends_with(".png");
    if (wants_picture(path, w.is_mill(), !view.empty())) {
        render::Drawing d;
        const bool has = s.drawing(d);
        done = write_part_picture(path, w, s.sim().om(), has ? &d : nullptr, look, s.paper_title());
    } else if (!view.empty()) {
        done = {64, tr("a view is drawn as a picture: FILE.png or FILE.pdf")};
    } else {
        done = write_part(path, w, w.setup().name);
    }
    if (done.value != 0)
        s.say(done.why, true);
    else if (heights)  // data for scripts, not a picture: say how to get one
        s.say(strf(tr("the part's height field (16-bit data) written to %s; its picture: "
                      ":part export %s %s"),
                   path.c_str(), path.c_str(), render::mode_word(look.mode).data()));
    else
        s.say(strf(tr("the part written to %s"), path.c_str()));
    return Effect::redraw;
}

Effect part(Session& s, const CommandCall& c) {
    workshop::Workshop* w = s.sim().shop();
    const std::string_view what = c.arg(1);
    const bool exporting = what == "export" && !c.arg(2).empty() && c.arg(4).empty();
    const bool viewing = what == "view" && !c.arg(2).empty() && c.arg(3).empty();
    if (what.empty() || viewing) {
        s.show_page(pages::PageId::part);
        render::PartMode m;
        if (viewing && parse_part_view(s, c.arg(2), !s.machine().lathe, m))
            s.part().set_mode(m, !s.machine().lathe);
        return Effect::redraw;
    }
    if (what != "new" && !exporting)
        return usage(s, ":part [view VIEW] | :part new | :part export FILE [VIEW]");
    if (!w) {
        s.say(s.no_workshop(), true);
        return Effect::redraw;
    }
    if (exporting)
        return s.hidden(":part export") ? Effect::redraw
                                        : export_part(s, *w, std::string(c.arg(2)), c.arg(3));
    if (s.sim().in_cycle()) {
        s.say(tr("a program is in cycle"), true);
        return Effect::redraw;
    }
    w->new_part();
    s.say(w->is_mill() ? tr("a fresh block in the vice") : tr("fresh stock in the chuck"));
    s.save_workshop();
    return Effect::redraw;
}

// :witness, :witness off, :witness DIA [FACE] (console/witness.cpp).
Effect witness(Session& s, const CommandCall& c) {
    double dia = std::nan(""), face = 0;
    if (c.words.size() == 2 && c.arg(1) == "off") return s.setting().witness(0, 0);
    if (c.words.size() > 3 || (c.words.size() > 1 && (!number(c.arg(1), dia) || dia <= 0)) ||
        (c.words.size() == 3 && !number(c.arg(2), face)))
        return usage(s, ":witness DIA [FACE] | :witness off");
    return s.setting().witness(dia, face);
}

Effect tangent(Session& s, const CommandCall& c) {
    const int axis = axis_word(c.arg(1));
    if (c.words.size() != 2 || (axis != X && axis != Z)) return usage(s, ":tangent X|Z");
    return s.setting().tangent(axis);
}

Effect measure(Session& s, const CommandCall& c) {
    if (workshop::is_instrument(c.arg(1))) return read_instrument(s, c);
    double v;
    long d = 0;
    int axis;
    std::string_view dn = c.arg(1);
    bool ok = dn.size() > 1 && (dn[0] == 'D' || dn[0] == 'd') && integer(dn.substr(1), d) &&
              axis_value(c, 2, axis, v);
    if (!ok) return usage(s, tr(":measure Dn AXIS VALUE, e.g. :measure D2 X 59.978"));
    s.setting().choose_corrector(int(d));
    return s.setting().measure(int(d), axis, v);
}

// ---- the program store and the editor ----

Effect remove_program(Session& s, const CommandCall& c) {
    long n;
    if (!integer(c.arg(1), n)) return usage(s, ":rm N");
    s.delete_program(int(n));
    return Effect::redraw;
}

// Without N: back to the editor if open, else the program under the DIR
// cursor, else the one selected.
Effect edit(Session& s, const CommandCall& c) {
    long n;
    std::string_view number = drop_prefix(c.arg(1), "%");
    if (number.empty()) {
        if (s.editing().editor().is_open()) {
            s.show_page(pages::PageId::edit);
            return Effect::redraw;
        }
        if (s.page() == pages::PageId::dir && !s.programs().empty())
            return s.editing().open(s.programs()[size_t(s.dir_cursor())].number);
        if (s.sim().selected() >= 0) return s.editing().open(s.sim().selected());
        return usage(s, ":edit N");
    }
    if (!integer(number, n) || n < 0 || n > 99999) return usage(s, ":edit N");
    return s.editing().open(int(n));
}

Effect goto_block(Session& s, const CommandCall& c) {
    Editor& ed = s.editing().editor();
    if (!ed.is_open()) return usage(s, tr(":edit N first"));
    long n;
    std::string_view label = drop_prefix(c.arg(1), "Nn");
    bool ok = integer(label, n) && ed.goto_n(n);
    s.show_page(pages::PageId::edit);
    if (!ok) s.say(strf(tr("no block N%s"), std::string(label).c_str()), true);
    return Effect::redraw;
}

// The text searched is the rest of the line after one blank: it may hold blanks.
Effect find_text(Session& s, const CommandCall& c) {
    Editor& ed = s.editing().editor();
    if (!ed.is_open()) return usage(s, tr(":edit N first"));
    std::string_view text = c.rest();
    bool ok = ed.find(text.empty() ? text : text.substr(1));
    s.show_page(pages::PageId::edit);
    if (!ok) s.say(tr("not found"), true);
    return Effect::redraw;
}

Effect renum(Session& s, const CommandCall& c) {
    Editor& ed = s.editing().editor();
    if (!ed.is_open()) return usage(s, tr(":edit N first"));
    long start = 10, step = 10;
    if (c.words.size() > 1 && !integer(c.words[1], start)) return usage(s, ":renum [START [STEP]]");
    if (c.words.size() > 2 && !integer(c.words[2], step)) return usage(s, ":renum [START [STEP]]");
    if (start < 0 || step < 1) return usage(s, ":renum [START [STEP]]");
    int k = ed.renumber(start, step);
    s.say(strf(tr("%d blocks renumbered from N%ld by %ld; G77/G79/cycle references follow"), k,
               start, step));
    return Effect::redraw;
}

Effect restore(Session& s, const CommandCall& c) {
    long r;
    if (!integer(c.arg(1), r)) return usage(s, tr(":restore REV (see :history)"));
    return s.editing().restore(int(r));
}

// :exercise NAME: checked here (it exists, it is for this kind of machine,
// nothing unsaved), then the console starts again on it.
Effect start_exercise(Session& s, std::string_view name) {
    if (s.exercise() && !s.exercise()->graded()) {
        s.say(tr("an exercise is in progress: :submit ends it"), true);
        return Effect::redraw;
    }
    if (s.sim().in_cycle()) {
        s.say(tr("a program is in cycle"), true);
        return Effect::redraw;
    }
    if (const Editor& ed = s.editing().editor(); ed.is_open() && ed.dirty && !s.editing().modif()) {
        s.say(strf(tr("%%%d has unsaved changes: :save or :close! first"), ed.number), true);
        return Effect::redraw;
    }
    training::Exercise e;
    if (std::string why = find_exercise(s.store(), std::string(name), e); !why.empty()) {
        s.say(why, true);
        return Effect::redraw;
    }
    if (!s.store()) {
        s.say(tr("an exercise needs the store"), true);
        return Effect::redraw;
    }
    s.editing().release_lease();
    return s.restart_on(std::string(name));
}

Effect exercise(Session& s, const CommandCall& c) {
    std::string_view args = c.rest();
    while (!args.empty() && args.front() == ' ') args.remove_prefix(1);
    while (!args.empty() && args.back() == ' ') args.remove_suffix(1);
    if (!args.empty() && args != "show") return start_exercise(s, args);
    if (!s.exercise()) {
        s.say(tr("no exercise in progress: pupitre exercise NAME starts one"), true);
        return Effect::redraw;
    }
    s.show_page(pages::PageId::exercise);
    return Effect::redraw;
}

// :submit: the exercise run grades the attempt.
Effect submit(Session& s, const CommandCall&) {
    if (!s.exercise()) {
        s.say(tr("no exercise in progress: pupitre exercise NAME starts one"), true);
        return Effect::redraw;
    }
    return s.exercise()->submit();
}

Effect help_page(Session& s, const CommandCall&) {
    s.show_page(pages::PageId::help);
    return Effect::redraw;
}

bool forced(const CommandCall& c) {
    return c.name().back() == '!';
}

// The HELP page lists the rows with a usage, in this order; the usage is the
// syntax as typed (English, as in pupitre(1)), the help is translated there. Each row starts a
// line with {" (tests/console/man_sync.py reads the names from there).
constexpr Command kCommands[] = {
    {"page",
     ":page om|op|prog|graph|info|param|pref|corr|dir|alarm|help|edit|history|shop|exercise|part",
     N_("show a page"), page},
    {"mode", ":mode auto|seq|dry|test|rns|imd|jog|inc|pom|edit|modif",
     N_("select a mode (refused while a program is in cycle)"), mode},
    {"load", ":load N",
     // xgettext:no-c-format
     N_("select program %N for AUTO, SEQ, DRY RUN, TEST and RNS"), load},
    {"cycle", ":cycle", N_("Cycle Start"),
     [](Session& s, const CommandCall&) { return s.cycle_command(); }},
    {"stop", ":stop", N_("feed hold (Cycle Start resumes)"), feed_hold},
    {"raz", ":raz", N_("RAZ: reset; the run is abandoned, alarms acknowledged"), raz},
    {"jog", ":jog AXIS DIST",
     N_("move an axis by DIST mm (X as a diameter on the lathe), at the jog feed"), jog},
    {"set", ":set NAME=VALUE",
     N_("PREF.X=-120.5, DEC1.Z=3, D1.R=0.8, L5=2, E80000=18000 (names as --set)"),
     [](Session& s, const CommandCall& c) { return s.set_value(c.rest()); }},
    {"search", ":search N", N_("RNS: the block to search for (same as typing N in RNS mode)"),
     search},
    {"feed", ":feed PCT",
     // xgettext:no-c-format
     N_("feed override, 0 to 120 % (ignored under M49)"),
     [](Session& s, const CommandCall& c) { return override_knob(s, c, true); }},
    {"spindle", ":spindle PCT",
     // xgettext:no-c-format
     N_("spindle override, 50 to 120 % (ignored under M49)"),
     [](Session& s, const CommandCall& c) { return override_knob(s, c, false); }},
    {"speed", ":speed x1|x10|max", N_("animation speed: real time, ten times, as fast as possible"),
     speed},
    {"skip", ":skip on|off", N_("block skip switch: blocks starting with / are skipped"),
     [](Session& s, const CommandCall& c) { return panel_switch(s, c, true); }},
    {"m01", ":m01 on|off", N_("optional stop switch: M01 stops"),
     [](Session& s, const CommandCall& c) { return panel_switch(s, c, false); }},
    {"inc", ":inc STEP", N_("INC step in mm (0.001 to 100)"), inc},
    {"rm", ":rm N",
     // xgettext:no-c-format
     N_("delete program %N from the store (its history stays)"), remove_program},
    {"touch", ":touch AXIS VALUE",
     N_("touch-off: PREF so that the tool point reads VALUE (X a diameter on the lathe)"), touch},
    {"measure", ":measure Dn AXIS VALUE",
     N_("tool measurement: the gauge of Dn from a touched face or diameter"), measure},
    {"", ":measure dia Z-n|bore Z-n|groove Z-n|length|tool Tn X|Z|R",
     N_("read an instrument on the workshop's part, from its right-hand face, or the presetter"),
     nullptr},
    {"witness", ":witness DIA [FACE]|off",
     N_("the witness cut: its diameter read with the micrometer, its face's Z (default 0)"),
     witness},
    {"tangent", ":tangent X|Z",
     N_("the active tool touches the witness: its corrector is set from it (Cazeneuve)"), tangent},
    {"setup", ":setup [lathe|mill|cazeneuve|FILE|off]",
     N_("the workshop: a true part, chuck and tools the moves cut and touch"), setup},
    {"part", ":part [view VIEW]",
     N_("the PART page: the part in colour; VIEW section on the lathe, top or 3d on the "
        "machining centre"),
     part},
    {"", ":part new", N_("the workshop: fresh stock in the chuck"), nullptr},
    {"", ":part export FILE [VIEW]",
     N_("the part on paper: FILE.pdf, FILE.png (a mill's FILE.png without VIEW: its height "
        "field); FILE.svg or its Z R outline on the lathe"),
     nullptr},
    {"shim", ":shim MM|off",
     N_("the paper test: a shim of MM on the part stops a jog when the tool pinches it"), shim},
    {"gauge", ":gauge MM|off",
     N_("a gauge block of MM against the lathe's jaws: a jog stops on its end"), gauge},
    {"exercise", ":exercise [NAME]",
     N_("the EXERCISE page: the task, the report once submitted; NAME: start that exercise"),
     exercise},
    {"submit", ":submit",
     N_("hand in the exercise: the values entered and the part are graded, the truth shown"),
     submit},
    {"undo", ":undo", N_("undo the last change of an origin or a corrector"),
     [](Session& s, const CommandCall&) { return s.setting().undo(); }},
    {"protect", ":protect on|off [PIN]",
     N_("the memory-protect key: locks programs, origins and correctors"),
     [](Session& s, const CommandCall& c) { return s.setting().protect_command(c.rest()); }},
    {"", ":protect pin [NEWPIN]", N_("set (or remove) the PIN that unlocks the protection"),
     nullptr},
    {"edit", ":edit N",
     // xgettext:no-c-format
     N_("EDIT: open program %N (new if absent; without N the one selected)"), edit},
    {"save save!", ":save",
     N_("save the program edited, after a syntax check (:save! saves despite an error)"),
     [](Session& s, const CommandCall& c) { return s.editing().save(forced(c)); }},
    {"goto", ":goto Nnnn", N_("EDIT: the cursor to block Nnnn"), goto_block},
    {"find", ":find TEXT", N_("EDIT: the next block containing TEXT"), find_text},
    {"renum", ":renum [START [STEP]]",
     N_("EDIT: renumber the N labels (default 10 10) and their references"), renum},
    {"history", ":history / :restore REV",
     N_("EDIT: the revisions of the program, and making one current again"),
     [](Session& s, const CommandCall&) { return s.editing().history(); }},
    {"restore", "", "", restore},
    {"close close!", ":close",
     N_("EDIT: close the program (asks before dropping unsaved changes; :close! does not)"),
     [](Session& s, const CommandCall& c) { return s.editing().close(forced(c)); }},
    {"recover", ":recover / :discard",
     N_("EDIT: load the changes an earlier session left unsaved, or drop them"),
     [](Session& s, const CommandCall&) { return s.editing().recover(false); }},
    {"discard", "", "", [](Session& s, const CommandCall&) { return s.editing().recover(true); }},
    {"", ":mode modif", N_("MODIF: change the blocks to come of an interrupted program"), nullptr},
    {"quit q quit! q!", ":quit",
     N_("leave the console, also Ctrl-C (asks before dropping unsaved changes; :quit! does not)"),
     [](Session& s, const CommandCall& c) { return s.quit_command(forced(c)); }},
    {"help", "", "", help_page},
};

bool answers_to(const Command& c, std::string_view name) {
    for (std::string_view n : words(c.names))
        if (n == name) return true;
    return false;
}

const Command* find_command(std::string_view name) {
    for (const Command& c : kCommands)
        if (c.run && answers_to(c, name)) return &c;
    return nullptr;
}

}  // namespace

std::span<const Command> commands() {
    return kCommands;
}

Effect Session::command(std::string_view text) {
    CommandCall call{text, words(text)};
    if (call.words.empty()) return Effect::none;
    if (const Command* c = find_command(call.name())) return c->run(*this, call);
    say(strf(tr("unknown command :%s (F1 lists the commands)"), std::string(call.name()).c_str()),
        true);
    return Effect::redraw;
}

// Whether a line typed is :quit (or :q, :quit!): all a too small screen takes.
bool Session::quits(std::string_view line) {
    if (line.empty() || line.front() != ':') return false;
    std::vector<std::string_view> w = words(line.substr(1));
    const Command* c = w.empty() ? nullptr : find_command(w[0]);
    return c && c->names.substr(0, c->names.find(' ')) == "quit";
}

// The first name of each command: not its aliases (:q) nor its '!' forms.
void Session::complete_command(std::string_view word, std::vector<std::string>& out) const {
    for (const Command& c : commands()) {
        std::string name = ":" + std::string(c.names.substr(0, c.names.find(' ')));
        if (c.run && name.rfind(word, 0) == 0) out.push_back(name);
    }
}

}  // namespace pupitre::console
