// The bindings table and the actions it names (see bindings.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/bindings.hpp"

#include <algorithm>
#include <charconv>

#include "console/session.hpp"

namespace pupitre::data {
std::string_view bindings_txt();
}

namespace pupitre::console {

std::string_view default_bindings() { return data::bindings_txt(); }

namespace {

bool always(const Session&, std::string_view) { return true; }
bool input_empty(const Session& s) { return s.input().text().empty(); }
bool on_dir(const Session& s, std::string_view) { return s.page == pages::PageId::dir && input_empty(s); }
bool jogging(const Session& s, std::string_view) {
    Mode m = s.sim().mode();
    return (m == Mode::jog || m == Mode::inc) && input_empty(s) && s.page != pages::PageId::edit;
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
        s.show_page(s.page == P::param ? P::pref : s.page == P::pref ? P::corr : P::param);
        return Effect::redraw;
    }
    if (arg == "pos") {
        s.show_page(s.page == pages::PageId::op ? pages::PageId::om : pages::PageId::op);
        return Effect::redraw;
    }
    if (arg == "prog") {  // the program text, again for its drawing
        s.show_page(s.page == pages::PageId::prog ? pages::PageId::graph : pages::PageId::prog);
        return Effect::redraw;
    }
    return s.command("page " + std::string(arg));
}

// F8 (S-F8 back): the next mode, and what to do in it.
Effect mode_step(Session& s, int dir) {
    Mode m = next_mode(s.sim().mode(), dir);
    std::string why;
    if (!s.sim().set_mode(m, why)) s.say(why, true);
    else s.say(s.mode_news(m));
    return Effect::redraw;
}

Effect scroll(Session& s, std::string_view arg) {
    int step = std::max(1, s.rows - 8);
    s.scroll = std::max(0, s.scroll + to_int(arg) * step);
    return Effect::redraw;
}

Effect dir_move(Session& s, std::string_view arg) {
    int n = int(s.programs().size());
    s.dir_cursor = std::clamp(s.dir_cursor + to_int(arg), 0, std::max(0, n - 1));
    return Effect::redraw;
}

bool on_corr(const Session& s, std::string_view) { return s.page == pages::PageId::corr && input_empty(s); }

Effect corr_move(Session& s, std::string_view arg) {
    s.corr_cursor = std::clamp(s.corr_cursor + to_int(arg), 1, s.machine().correctors);
    return Effect::redraw;
}

bool on_edit(const Session& s, std::string_view) {
    return s.page == pages::PageId::edit && s.editor.is_open() && input_empty(s);
}

Effect edit_move(Session& s, std::string_view arg) {
    if (arg == "home") s.editor.cursor = 0;
    else if (arg == "end") s.editor.cursor = int(s.editor.lines().size()) - 1;
    else s.editor.move(to_int(arg) * (std::abs(to_int(arg)) == 10 ? std::max(1, s.rows - 8) / 10 : 1));
    s.modify_pending = false;
    return Effect::redraw;
}

// Edit operations that answer "" or why they were refused.
Effect edit_op(Session& s, std::string (Editor::*op)(), const char* done) {
    std::string why = (s.editor.*op)();
    if (!why.empty()) s.say(why, true);
    else s.say(done);
    return Effect::redraw;
}

Effect edit_modify(Session& s, std::string_view) {
    std::string why;
    if (s.editor.cursor < s.editor.locked) {
        s.say("this block is already prepared", true);
        return Effect::redraw;
    }
    s.input().set_text(s.editor.lines()[size_t(s.editor.cursor)]);
    s.modify_pending = true;
    s.say("modify the block, Enter replaces it");
    return Effect::redraw;
}

bool on_graph(const Session& s, std::string_view) { return s.page == pages::PageId::graph && input_empty(s); }

Effect dir_load(Session& s, std::string_view) {
    if (s.programs().empty()) return Effect::none;
    s.select_program(s.programs()[size_t(s.dir_cursor)].number);
    return Effect::redraw;
}

Effect dir_delete(Session& s, std::string_view) {
    if (s.programs().empty()) return Effect::none;
    int n = s.programs()[size_t(s.dir_cursor)].number;
    if (s.pending_delete != n) {
        s.pending_delete = n;
        s.say("delete %" + std::to_string(n) + "? press Del again to confirm", true);
        return Effect::redraw;
    }
    s.pending_delete = -1;
    s.delete_program(n);
    return Effect::redraw;
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
    if (sim.mode() == Mode::jog && sim.queued_time() > 0.1) return Effect::none;
    // Lathe X is shown as a diameter: a step of the display is what the operator means.
    std::string why;
    if (!sim.jog(axis, sign * dist, why)) s.say("JOG: " + why, true);
    return Effect::redraw;
}

Effect override_step(Session& s, std::string_view arg, bool feed) {
    int& v = feed ? s.sim().feed_override : s.sim().spindle_override;
    v = std::clamp(v + to_int(arg), feed ? 0 : 50, 120);
    s.say(std::string(feed ? "feed" : "spindle") + " override " + std::to_string(v) + " %" +
          (s.sim().overrides_inhibited() ? " (inhibited by M49)" : ""));
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
    s.say("INC step " + pages::fmt_len(next) + " mm");
    return Effect::redraw;
}

const std::vector<Action> kActions = {
    {"page", "show the %s page", always, page, "%S"},
    {"mode-next", "next mode", always, [](Session& s, std::string_view) { return mode_step(s, 1); }, "MODE"},
    {"mode-prev", "previous mode", always, [](Session& s, std::string_view) { return mode_step(s, -1); }, "MODE-"},
    {"mode", "the %s mode", always,
     [](Session& s, std::string_view a) { return s.command("mode " + std::string(a)); }, "%S"},
    {"cycle-start", "Cycle Start", always, [](Session& s, std::string_view) { return s.command("cycle"); }, "START"},
    {"feed-hold", "feed hold", always, [](Session& s, std::string_view) { return s.command("stop"); }, "HOLD"},
    {"raz", "RAZ (reset)", always, [](Session& s, std::string_view) { return s.command("raz"); }, "RAZ"},
    {"quit", "leave the console", always, [](Session& s, std::string_view) { return s.command("quit"); }, "QUIT"},
    {"scroll", "scroll the page by %s screen", always, scroll, "SCROLL"},
    {"dir-move", "move the cursor by %s", on_dir, dir_move, "MOVE"},
    {"dir-load", "select the program under the cursor", on_dir, dir_load, "LOAD"},
    {"dir-delete", "delete the program under the cursor (twice to confirm)", on_dir, dir_delete, "DELETE"},
    {"jog", "jog %s", jogging, jog, "%S"},
    {"corr-move", "choose the corrector %s", on_corr, corr_move, "D"},
    {"graph-zoom", "zoom %s about the cursor", on_graph,
     [](Session& s, std::string_view a) { return s.graph_key("zoom", a); }, "ZOOM"},
    {"graph-pan", "pan the drawing (%s)", on_graph, [](Session& s, std::string_view a) { return s.graph_key("pan", a); },
     "PAN"},
    {"graph-cursor", "move the cursor (%s): its coordinates are shown", on_graph,
     [](Session& s, std::string_view a) { return s.graph_key("cursor", a); }, "CURSOR"},
    {"graph-fit", "fit the cutting moves", on_graph, [](Session& s, std::string_view) { return s.graph_key("fit", ""); },
     "FIT"},
    {"graph-plane", "next plane (XY, XZ, YZ; the lathe draws ZX)", on_graph,
     [](Session& s, std::string_view) { return s.graph_key("plane", ""); }, "PLANE"},
    {"edit-move", "move the editor's cursor (%s)", on_edit, edit_move, "MOVE"},
    {"edit-modify", "put the block under the cursor on the input line to modify it", on_edit, edit_modify, "MODIFY"},
    {"edit-delete", "delete the block under the cursor (or the marked blocks)", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::erase, "deleted"); }, "DELETE"},
    {"edit-mark", "mark: the blocks between the mark and the cursor form a range", on_edit,
     [](Session& s, std::string_view) {
         s.editor.toggle_mark();
         s.say(s.editor.mark >= 0 ? "mark set: move the cursor, then M-w copies, C-w cuts, Del deletes" : "mark cleared");
         return Effect::redraw;
     },
     "MARK"},
    {"edit-copy", "copy the block (or the marked range)", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::copy, "copied"); }, "COPY"},
    {"edit-cut", "cut the block (or the marked range), to paste elsewhere (move)", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::cut, "cut: C-y pastes it after the cursor"); },
     "CUT"},
    {"edit-paste", "paste the copied blocks after the cursor", on_edit,
     [](Session& s, std::string_view) { return edit_op(s, &Editor::paste, "pasted"); }, "PASTE"},
    {"undo", "undo the last change of an origin or corrector", always,
     [](Session& s, std::string_view) { return s.undo(); }, "UNDO"},
    {"protect", "memory-protect key (locks programs, origins, correctors)", always,
     [](Session& s, std::string_view) { return s.protect_command(""); }, "LOCK"},
    {"inc-step", "next INC step (0.001 0.01 0.1 1 10 mm)", always, inc_step, "STEP"},
    {"feed-override", "feed override %s %", always,
     [](Session& s, std::string_view a) { return override_step(s, a, true); }, "FEED"},
    {"spindle-override", "spindle override %s %", always,
     [](Session& s, std::string_view a) { return override_step(s, a, false); }, "SPINDLE"},
    {"speed-next", "animation speed x1, x10, max", always,
     [](Session& s, std::string_view) {
         s.speed = s.speed == Speed::real ? Speed::x10 : s.speed == Speed::x10 ? Speed::max : Speed::real;
         return Effect::redraw;
     },
     "SPEED"},
    {"toggle-skip", "block skip switch (/)", always, [](Session& s, std::string_view) { return s.command("skip"); },
     "SKIP"},
    {"toggle-m01", "optional stop switch (M01)", always,
     [](Session& s, std::string_view) { return s.command("m01"); }, "M01"},
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::string next_word(std::string_view& s) {
    s = trim(s);
    size_t e = 0;
    while (e < s.size() && s[e] != ' ' && s[e] != '\t') ++e;
    std::string w(s.substr(0, e));
    s.remove_prefix(e);
    return w;
}

bool matches(const std::string& want, std::string_view have) {
    if (want.empty()) return true;
    std::string_view w = want;
    while (!w.empty()) {
        size_t bar = w.find('|');
        if (w.substr(0, bar) == have) return true;
        if (bar == std::string_view::npos) break;
        w.remove_prefix(bar + 1);
    }
    return false;
}

}  // namespace

const std::vector<Action>& all_actions() { return kActions; }

const Action* find_action(std::string_view name) {
    for (const Action& a : kActions)
        if (a.name == name) return &a;
    return nullptr;
}

std::string help_text(const Action& a, std::string_view arg) {
    std::string h(a.help);
    if (a.name == "page" && arg == "pos") return "show the OP page, again for OM";
    if (a.name == "page" && arg == "set") return "show the PARAM, PREF and CORR pages in turn";
    if (a.name == "page" && arg == "prog") return "show the PROG page, again for the GRAPH page";
    if (size_t p = h.find("%s"); p != std::string::npos) h.replace(p, 2, arg);
    return h;
}

std::string soft_label(const Action& a, std::string_view arg) {
    std::string l(a.label);
    if (size_t p = l.find("%S"); p != std::string::npos) {
        std::string up(arg == "pos" ? "OP/OM" : arg == "set" ? "SET" : arg == "prog" ? "PROG/GR" : arg);
        for (char& c : up) c = char(std::toupper(static_cast<unsigned char>(c)));
        l.replace(p, 2, up);
    }
    return l;
}

std::string context_text(const Context& c) {
    std::string out;
    auto add = [&](const std::string& s) {
        if (s.empty()) return;
        if (!out.empty()) out += ", ";
        out += s;
    };
    if (!c.page.empty()) add("page " + c.page);
    if (!c.mode.empty()) add("mode " + c.mode);
    add(c.kind);
    return out;
}

std::string Bindings::parse(std::string_view text, std::string_view origin) {
    int lineno = 0;
    while (!text.empty()) {
        size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        ++lineno;
        if (size_t hash = line.find('#'); hash != std::string_view::npos && (hash == 0 || line[hash - 1] == ' '))
            line = line.substr(0, hash);
        line = trim(line);
        if (line.empty()) continue;
        auto bad = [&](const std::string& what) { return std::string(origin) + ":" + std::to_string(lineno) + ": " + what; };
        Binding b;
        b.line = lineno;
        b.key_text = next_word(line);
        if (!parse_key_name(b.key_text, b.key)) return bad("'" + b.key_text + "' is not a key name");
        b.action = next_word(line);
        if (!find_action(b.action)) return bad("'" + b.action + "' is not an action");
        std::string w = next_word(line);
        if (!w.empty() && w[0] != '@') {
            b.arg = w;
            w = next_word(line);
        }
        if (!w.empty()) {
            if (w[0] != '@') return bad("a context starts with @");
            std::string_view ctx = std::string_view(w).substr(1);
            while (!ctx.empty()) {
                size_t comma = ctx.find(',');
                std::string_view c = ctx.substr(0, comma);
                ctx = comma == std::string_view::npos ? std::string_view{} : ctx.substr(comma + 1);
                if (c.rfind("page=", 0) == 0) b.when.page = c.substr(5);
                else if (c.rfind("mode=", 0) == 0) b.when.mode = c.substr(5);
                else if (c == "lathe" || c == "mill") b.when.kind = c;
                else return bad("unknown context '" + std::string(c) + "'");
            }
        }
        if (!next_word(line).empty()) return bad("too many words");
        list_.push_back(std::move(b));
    }
    return {};
}

std::vector<const Binding*> Bindings::find(const Key& k, std::string_view page, std::string_view mode,
                                           std::string_view kind) const {
    std::vector<const Binding*> out;
    for (auto it = list_.rbegin(); it != list_.rend(); ++it) {  // a later line wins
        const Binding& b = *it;
        if (!(b.key == k)) continue;
        if (!b.when.page.empty() && !matches(b.when.page, page)) continue;
        if (!b.when.mode.empty() && !matches(b.when.mode, mode)) continue;
        if (!b.when.kind.empty() && b.when.kind != kind) continue;
        out.push_back(&b);
    }
    auto weight = [](const Binding* b) {
        return int(!b->when.page.empty()) + int(!b->when.mode.empty()) + int(!b->when.kind.empty());
    };
    std::stable_sort(out.begin(), out.end(), [&](auto* a, auto* b) { return weight(a) > weight(b); });
    return out;
}

}  // namespace pupitre::console
