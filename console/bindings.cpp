// The actions the bindings name (see bindings.hpp), and the Session's
// routing of a key through them: the binding that applies in the page and
// the mode, the soft keys and the HELP page drawn from the same rows.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/bindings.hpp"

#include <algorithm>
#include <charconv>

#include "console/commands.hpp"
#include "console/session.hpp"
#include "core/i18n.hpp"
#include "pages/pages.hpp"

namespace pupitre::console {

namespace {

bool always(const Session&, std::string_view) {
    return true;
}
bool input_empty(const Session& s) {
    return s.input().text().empty();
}
bool on_dir(const Session& s, std::string_view) {
    return s.page() == pages::PageId::dir && input_empty(s);
}
// JOG: the axis is about to move for a tenth of a second or more; a
// press (an auto-repeat) does nothing then, and is not recorded.
bool jog_waits(const Session& s) {
    return s.sim().mode() == Mode::jog && s.sim().queued_time() > 0.1;
}

bool jogging(const Session& s, std::string_view) {
    Mode m = s.sim().mode();
    return (m == Mode::jog || m == Mode::inc) && input_empty(s) && s.page() != pages::PageId::edit;
}

int to_int(std::string_view a) {
    int v = 0;
    if (!a.empty() && a.front() == '+') a.remove_prefix(1);
    std::from_chars(a.data(), a.data() + a.size(), v);
    return v;
}

Effect page(Session& s, std::string_view arg) {
    if (arg == "set") {  // the setting pages in turn: PARAM, PREF, CORR
        using P = pages::PageId;
        // The Cazeneuve's controller has no variables (003 chapter VI): no PARAM.
        const P after_corr = pages::is_caz(s.sim().machine()) ? P::pref : P::param;
        s.show_page(s.page() == P::param ? P::pref : s.page() == P::pref ? P::corr : after_corr);
        return Effect::redraw;
    }
    if (arg == "pos") {
        s.show_page(s.page() == pages::PageId::op ? pages::PageId::om : pages::PageId::op);
        return Effect::redraw;
    }
    if (arg == "prog") {  // the program text, again for its drawing
        s.show_page(s.page() == pages::PageId::prog ? pages::PageId::graph : pages::PageId::prog);
        return Effect::redraw;
    }
    return s.command("page " + std::string(arg));
}

// F8 (S-F8 back): the next mode, and what to do in it.
Effect mode_step(Session& s, int dir) {
    Mode m = next_mode(s.sim().mode(), dir);
    if (std::string why = s.sim().set_mode(m); !why.empty())
        s.say(why, true);
    else
        s.say(s.mode_news(m));
    return Effect::redraw;
}

Effect scroll(Session& s, std::string_view arg) {
    s.scroll_by(to_int(arg));
    return Effect::redraw;
}

Effect dir_move(Session& s, std::string_view arg) {
    s.move_dir_cursor(to_int(arg));
    return Effect::redraw;
}

bool on_corr(const Session& s, std::string_view) {
    return s.page() == pages::PageId::corr && input_empty(s);
}

Effect corr_move(Session& s, std::string_view arg) {
    s.setting().move_corrector(to_int(arg));
    return Effect::redraw;
}

bool on_edit(const Session& s, std::string_view) {
    return s.page() == pages::PageId::edit && s.editing().editor().is_open() && input_empty(s);
}

Effect edit_move(Session& s, std::string_view arg) {
    Editor& ed = s.editing().editor();
    if (arg == "home")
        ed.cursor = 0;
    else if (arg == "end")
        ed.cursor = int(ed.lines().size()) - 1;
    else
        ed.move(to_int(arg) * (std::abs(to_int(arg)) == 10 ? std::max(1, s.rows() - 8) / 10 : 1));
    s.editing().stop_modifying();
    return Effect::redraw;
}

// Edit operations that answer "" or why they were refused.
Effect edit_op(Session& s, std::string (Editor::*op)(), const char* done) {
    std::string why = (s.editing().editor().*op)();
    if (!why.empty())
        s.say(why, true);
    else
        s.say(done);
    return Effect::redraw;
}

Effect edit_modify(Session& s, std::string_view) {
    return s.editing().modify_block(s.input());
}

bool on_graph(const Session& s, std::string_view) {
    return s.page() == pages::PageId::graph && input_empty(s);
}

bool on_part(const Session& s, std::string_view) {
    return s.page() == pages::PageId::part && input_empty(s);
}

Effect dir_load(Session& s, std::string_view) {
    if (s.programs().empty()) return Effect::none;
    s.select_program(s.programs()[size_t(s.dir_cursor())].number);
    return Effect::redraw;
}

Effect dir_delete(Session& s, std::string_view) {
    return s.delete_under_cursor();
}

// JOG: each press adds a short stretch while less than 0.1 s of motion is
// queued, so a held key (the terminal's auto-repeat) moves the axis steadily
// and it stops within a tenth of a second of the release. INC: one step a press.
Effect jog(Session& s, std::string_view arg) {
    int axis = axis_of(arg.empty() ? '?' : arg[0]);
    double sign = arg.size() > 1 && arg[1] == '-' ? -1 : 1;
    Sim& sim = s.sim();
    double feed = sim.jog_feed > 0 ? sim.jog_feed : s.machine().jog_feed;
    double dist = sim.mode() == Mode::inc ? sim.increment : feed / 60.0 * 0.05;
    if (jog_waits(s)) return Effect::none;
    // Lathe X is shown as a diameter: a step of the display is what the operator means.
    if (std::string why = sim.jog(axis, sign * dist); !why.empty())
        s.say(strf(tr("JOG: %s"), why.c_str()), true);
    return Effect::redraw;
}

Effect override_step(Session& s, std::string_view arg, bool feed) {
    int& v = feed ? s.sim().feed_override : s.sim().spindle_override;
    v = std::clamp(v + to_int(arg), feed ? 0 : 50, 120);
    std::string news = strf(feed ? tr("feed override %d %%") : tr("spindle override %d %%"), v);
    if (s.sim().overrides_inhibited()) news += std::string(" ") + tr("(inhibited by M49)");
    s.say(news);
    return Effect::redraw;
}

Effect inc_step(Session& s, std::string_view) {
    const double steps[] = {0.001, 0.01, 0.1, 1, 10};
    double cur = s.sim().increment;
    double next = steps[0];
    for (double st : steps)
        if (st > cur + 1e-9) {
            next = st;
            break;
        }
    s.sim().increment = next;
    s.say(strf(tr("INC step %s mm"), pages::fmt_len(next).c_str()));
    return Effect::redraw;
}

// The help texts stay plain literals in the rows (tests/console/man_sync.py
// reads the action names from there); kActionHelp below marks them for the
// catalogue. Soft-key labels: F1-F9 show 6 columns, F10 5.
const std::vector<Action> kActions = {
    {"page", "show the %s page", always, page, "%S"},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"mode-next", "next mode", always, [](Session& s, std::string_view) { return mode_step(s, 1); },
     N_("MODE")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"mode-prev", "previous mode", always,
     [](Session& s, std::string_view) { return mode_step(s, -1); }, N_("MODE-")},
    {"mode", "the %s mode", always,
     [](Session& s, std::string_view a) { return s.command("mode " + std::string(a)); }, "%S"},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"cycle-start", "Cycle Start", always,
     [](Session& s, std::string_view) { return s.command("cycle"); }, N_("START")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"feed-hold", "feed hold", always,
     [](Session& s, std::string_view) { return s.command("stop"); }, N_("HOLD")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"raz", "RAZ (reset)", always, [](Session& s, std::string_view) { return s.command("raz"); },
     N_("RAZ")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"quit", "leave the console", always,
     [](Session& s, std::string_view) { return s.command("quit"); }, N_("QUIT")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"scroll", "scroll the page by %s screen", always, scroll, N_("SCROLL")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"dir-move", "move the cursor by %s", on_dir, dir_move, N_("MOVE")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"dir-load", "select the program under the cursor", on_dir, dir_load, N_("LOAD")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"dir-delete", "delete the program under the cursor (twice to confirm)", on_dir, dir_delete,
     N_("DELETE")},
    {"jog", "jog %s", jogging, jog, "%S"},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"corr-move", "choose the corrector %s", on_corr, corr_move, N_("D")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"graph-zoom", "zoom %s about the cursor", on_graph,
     [](Session& s, std::string_view a) { return s.graph_key("zoom", a); }, N_("ZOOM")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"graph-pan", "pan the drawing (%s)", on_graph,
     [](Session& s, std::string_view a) { return s.graph_key("pan", a); }, N_("PAN")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"graph-cursor", "move the cursor (%s): its coordinates are shown", on_graph,
     [](Session& s, std::string_view a) { return s.graph_key("cursor", a); }, N_("CURSOR")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"graph-fit", "fit the cutting moves", on_graph,
     [](Session& s, std::string_view) { return s.graph_key("fit", ""); }, N_("FIT")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"graph-plane", "next plane (XY, XZ, YZ; the lathe draws ZX)", on_graph,
     [](Session& s, std::string_view) { return s.graph_key("plane", ""); }, N_("PLANE")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-turn", "turn the 3-D view of the part (%s)", on_part,
     [](Session& s, std::string_view a) { return s.part_key("turn", a); }, N_("TURN")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-tilt", "tilt the 3-D view of the part (%s)", on_part,
     [](Session& s, std::string_view a) { return s.part_key("tilt", a); }, N_("TILT")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-zoom", "zoom %s on the part", on_part,
     [](Session& s, std::string_view a) { return s.part_key("zoom", a); }, N_("ZOOM")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-pan", "pan the part's picture (%s)", on_part,
     [](Session& s, std::string_view a) { return s.part_key("pan", a); }, N_("PAN")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-view", "the part's next view (section; top, 3-D)", on_part,
     [](Session& s, std::string_view) { return s.part_key("view", ""); }, N_("VIEW")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-fit", "the whole part, as first seen", on_part,
     [](Session& s, std::string_view) { return s.part_key("fit", ""); }, N_("FIT")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"part-paint", "paint the part by its deviation from the drawing, or by depth", on_part,
     [](Session& s, std::string_view) { return s.part_key("paint", ""); }, N_("PAINT")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"edit-move", "move the editor's cursor (%s)", on_edit, edit_move, N_("MOVE")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"edit-modify", "put the block under the cursor on the input line to modify it", on_edit,
     edit_modify, N_("MODIFY")},
    {"edit-delete", "delete the block under the cursor (or the marked blocks)", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::erase, tr("deleted")); },
     N_("DELETE")},
    {"edit-mark", "mark: the blocks between the mark and the cursor form a range", on_edit,
     [](Session& s, std::string_view) {
         Editor& ed = s.editing().editor();
         ed.toggle_mark();
         s.say(ed.mark >= 0
                   ? tr("mark set: move the cursor, then M-w copies, C-w cuts, Del deletes")
                   : tr("mark cleared"));
         return Effect::redraw;
     },
     N_("MARK")},
    {"edit-copy", "copy the block (or the marked range)", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::copy, tr("copied")); },
     N_("COPY")},
    {"edit-cut", "cut the block (or the marked range), to paste elsewhere (move)", on_edit,
     [](Session& s, std::string_view) {
         return edit_op(s, &Editor::cut, tr("cut: C-y pastes it after the cursor"));
     },
     N_("CUT")},
    {"edit-paste", "paste the copied blocks after the cursor", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::paste, tr("pasted")); },
     N_("PASTE")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"undo", "undo the last change of an origin or corrector", always,
     [](Session& s, std::string_view) { return s.setting().undo(); }, N_("UNDO")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"protect", "memory-protect key (locks programs, origins, correctors)", always,
     [](Session& s, std::string_view) { return s.setting().protect_command(""); }, N_("LOCK")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"inc-step", "next INC step (0.001 0.01 0.1 1 10 mm)", always, inc_step, N_("STEP")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"feed-override", "feed override %s %", always,
     [](Session& s, std::string_view a) { return override_step(s, a, true); }, N_("FEED")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"spindle-override", "spindle override %s %", always,
     [](Session& s, std::string_view a) { return override_step(s, a, false); }, N_("SPINDLE")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"speed-next", "animation speed x1, x10, max", always,
     [](Session& s, std::string_view) {
         s.set_speed(s.speed() == Speed::real  ? Speed::x10
                     : s.speed() == Speed::x10 ? Speed::max
                                               : Speed::real);
         return Effect::redraw;
     },
     N_("SPEED")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"toggle-skip", "block skip switch (/)", always,
     [](Session& s, std::string_view) { return s.command("skip"); }, N_("SKIP")},
    // TRANSLATORS: a soft-key label: at most 6 columns (5 on F10).
    {"toggle-m01", "optional stop switch (M01)", always,
     [](Session& s, std::string_view) { return s.command("m01"); }, N_("M01")},
};

// The help texts of kActions, for the catalogue (help_text translates them).
[[maybe_unused]] const char* const kActionHelp[] = {
    N_("show the %s page"),
    N_("next mode"),
    N_("previous mode"),
    N_("the %s mode"),
    N_("Cycle Start"),
    N_("feed hold"),
    N_("RAZ (reset)"),
    N_("leave the console"),
    N_("scroll the page by %s screen"),
    N_("move the cursor by %s"),
    N_("select the program under the cursor"),
    N_("delete the program under the cursor (twice to confirm)"),
    N_("jog %s"),
    N_("choose the corrector %s"),
    N_("zoom %s about the cursor"),
    N_("pan the drawing (%s)"),
    N_("move the cursor (%s): its coordinates are shown"),
    N_("fit the cutting moves"),
    N_("next plane (XY, XZ, YZ; the lathe draws ZX)"),
    N_("turn the 3-D view of the part (%s)"),
    N_("tilt the 3-D view of the part (%s)"),
    N_("zoom %s on the part"),
    N_("pan the part's picture (%s)"),
    N_("the part's next view (section; top, 3-D)"),
    N_("the whole part, as first seen"),
    N_("paint the part by its deviation from the drawing, or by depth"),
    N_("move the editor's cursor (%s)"),
    N_("put the block under the cursor on the input line to modify it"),
    N_("delete the block under the cursor (or the marked blocks)"),
    N_("mark: the blocks between the mark and the cursor form a range"),
    N_("copy the block (or the marked range)"),
    N_("cut the block (or the marked range), to paste elsewhere (move)"),
    N_("paste the copied blocks after the cursor"),
    N_("undo the last change of an origin or corrector"),
    N_("memory-protect key (locks programs, origins, correctors)"),
    N_("next INC step (0.001 0.01 0.1 1 10 mm)"),
    // xgettext:no-c-format
    N_("feed override %s %"),
    // xgettext:no-c-format
    N_("spindle override %s %"),
    N_("animation speed x1, x10, max"),
    N_("block skip switch (/)"),
    N_("optional stop switch (M01)"),
};

}  // namespace

const Action* find_action(std::string_view name) {
    for (const Action& a : kActions)
        if (a.name == name) return &a;
    return nullptr;
}

bool is_action(std::string_view name) {
    return find_action(name) != nullptr;
}

// The soft-key labels of the pages (F1-F7 and the like), for the catalogue.
// TRANSLATORS: a page's soft-key label: at most 6 columns (5 on F10).
[[maybe_unused]] const char* const kPageLabels[] = {
    N_("HELP"),  N_("OP/OM"), N_("PRG/GR"),  N_("INFO"), N_("SET"),
    N_("DIR"),   N_("ALARM"), N_("PREF"),    N_("CORR"), N_("PARAM"),
    N_("GRAPH"), N_("EDIT"),  N_("HISTORY"), N_("SHOP"), N_("PART")};

// The words of the bindings' arguments, for the catalogue: the HELP page
// says them in the console's language (arg_text).
[[maybe_unused]] const char* const kArgWords[] = {N_("in"), N_("out"),  N_("left"), N_("right"),
                                                  N_("up"), N_("down"), N_("home"), N_("end")};

// An action's argument as HELP says it: a page by its name on the panel
// (AIDE, ALARME), a mode by its NUM name, a direction in the console's
// language; a number or an axis as it is.
std::string arg_text(std::string_view action, std::string_view arg) {
    std::string up(arg);
    for (char& c : up) c = char(std::toupper(static_cast<unsigned char>(c)));
    if (action == "page") return up == "SHOP" ? std::string(tr("WORKSHOP")) : pages::tr_text(up);
    if (action == "mode") {
        // "jog|inc" (a context): each of them.
        if (size_t bar = arg.find('|'); bar != std::string_view::npos)
            return arg_text(action, arg.substr(0, bar)) + "|" +
                   arg_text(action, arg.substr(bar + 1));
        Mode m;
        return parse_mode(arg, m) ? std::string(mode_name(m)) : up;
    }
    for (const char* w : kArgWords)
        if (arg == w) return pages::tr_text(w);
    return std::string(arg);
}

std::string help_text(const Action& a, std::string_view arg) {
    std::string h = pages::tr_text(a.help);
    if (a.name == "page" && arg == "pos") return tr("show the OP page, again for OM");
    if (a.name == "page" && arg == "set") return tr("show the PARAM, PREF and CORR pages in turn");
    if (a.name == "page" && arg == "prog")
        return tr("show the PROG page, again for the GRAPH page");
    if (size_t p = h.find("%s"); p != std::string::npos) h.replace(p, 2, arg_text(a.name, arg));
    return h;
}

std::string soft_label(const Action& a, std::string_view arg) {
    std::string l = a.label == "%S" ? std::string(a.label) : pages::tr_text(a.label);
    if (size_t p = l.find("%S"); p != std::string::npos) {
        std::string up(arg == "pos"    ? "OP/OM"
                       : arg == "set"  ? "SET"
                       : arg == "prog" ? "PRG/GR"
                                       : arg);
        for (char& c : up) c = char(std::toupper(static_cast<unsigned char>(c)));
        // A page's soft key in the language of the panel (the modes keep their NUM names).
        if (a.name == "page") up = pages::tr_text(up);
        l.replace(p, 2, up);
    }
    return l;
}

// TRANSLATORS: the label of these keys on a keyboard of your language.
[[maybe_unused]] const char* const kKeyLabels[] = {N_("Enter"), N_("Del"), N_("Esc")};

std::string key_label(const std::string& key_text) {
    for (const char* k : kKeyLabels)
        if (key_text == k) return tr(k);
    return key_text;
}

std::string context_text(const Context& c) {
    std::string out;
    auto add = [&](const std::string& s) {
        if (s.empty()) return;
        if (!out.empty()) out += ", ";
        out += s;
    };
    if (!c.page.empty()) add(strf(tr("page %s"), arg_text("page", c.page).c_str()));
    if (!c.mode.empty()) add(strf(tr("mode %s"), arg_text("mode", c.mode).c_str()));
    add(c.kind == "lathe" ? tr("lathe") : c.kind == "mill" ? tr("mill") : c.kind);
    return out;
}

// ---- the Session's key routing ----

std::string Session::add_bindings(std::string_view text, std::string_view origin) {
    return bindings_.parse(text, origin, is_action);
}

// The first binding of the key that applies here and can run, run.
bool Session::run_binding(const Key& k, Effect& e) {
    std::string pg(pages::page_word(page_)), md(mode_word(sim_->mode()));
    for (const Binding* b : bindings_.find(k, pg, md, m_.lathe ? "lathe" : "mill")) {
        const Action* a = find_action(b->action);
        if (!a || !a->can_run(*this, b->arg)) continue;
        if (a->name != "jog" || !jog_waits(*this)) note_key(a->name, b->arg);
        e = a->run(*this, b->arg);
        return true;
    }
    return false;
}

const Binding* Session::binding_for(const Key& k, pages::PageId page) const {
    for (const Binding* b : bindings_.find(k, pages::page_word(page), mode_word(sim_->mode()),
                                           m_.lathe ? "lathe" : "mill"))
        if (find_action(b->action)) return b;
    return nullptr;
}

// A key on the "Terminal too small" screen, where the operator sees nothing
// of the page: only what quits, and the input line's keys to type :quit
// (not the page's bindings of those keys: Enter on DIR would load blind).
Effect Session::small_screen_key(const Key& k) {
    for (const Binding* b : bindings_.find(k, pages::page_word(page_), mode_word(sim_->mode()),
                                           m_.lathe ? "lathe" : "mill"))
        if (const Action* a = find_action(b->action); a && b->action == "quit")
            return a->run(*this, b->arg);
    if (k.code == KeyCode::escape && !k.alt && !k.ctrl) return cancel_input();
    if (for_line_editor(k))
        input_.feed(k.raw);
    else
        say(tr("the terminal is too small: enlarge it, or :quit"), true);
    return Effect::redraw;
}

namespace {

// Whether a "page" binding's argument names the page on screen (F2 is OP and
// OM, F3 PROG and GRAPH, F5 the setting pages).
bool shows_page(std::string_view arg, pages::PageId p) {
    using P = pages::PageId;
    if (arg == "pos") return p == P::op || p == P::om;
    if (arg == "prog") return p == P::prog || p == P::graph;
    if (arg == "set") return p == P::param || p == P::pref || p == P::corr;
    return arg == pages::page_word(p);
}

}  // namespace

// The soft keys (what F1-F10 do here, from the bindings) and the HELP
// page's lines (every binding, every command).
void Session::view_keys(pages::View& v) const {
    std::string pg(pages::page_word(page_)), md(mode_word(sim_->mode()));
    for (int i = 1; i <= 10; ++i) {
        Key k;
        k.code = KeyCode(int(KeyCode::f1) + i - 1);
        for (const Binding* b : bindings_.find(k, pg, md, m_.lathe ? "lathe" : "mill")) {
            const Action* a = find_action(b->action);
            if (!a) continue;
            v.softkeys.push_back(pages::SoftKey{"F" + std::to_string(i), soft_label(*a, b->arg),
                                                a->name == "page" && shows_page(b->arg, page_)});
            break;
        }
    }
    for (const Binding& b : bindings_.list()) {
        const Action* a = find_action(b.action);
        if (a)
            v.help.push_back(
                pages::HelpLine{key_label(b.key_text), help_text(*a, b.arg), context_text(b.when)});
    }
    for (const Command& c : commands())
        if (!c.usage.empty())
            v.help.push_back(pages::HelpLine{std::string(c.usage), pages::tr_text(c.help), ""});
}

}  // namespace pupitre::console
