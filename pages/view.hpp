// What the pages see of the console's session: the simulated machine (read
// only) and the few pieces of console state a page shows. Pages depend on
// core/ and on this struct only, never on ncurses or the store.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/sim/sim.hpp"
#include "pages/page_graph.hpp"
#include "pages/page_part.hpp"

namespace pupitre::pages {

enum class PageId {
    om,
    op,
    prog,
    info,
    param,
    dir,
    alarm,
    help,
    pref,
    corr,
    edit,
    graph,
    history,
    shop,
    exercise,
    part
};
std::string_view page_word(PageId p);  // om, op, prog, …
bool parse_page(std::string_view word, PageId& out);

struct SoftKey {
    std::string key;       // "F1"
    std::string label;     // "HELP"
    bool current = false;  // it shows the page on screen now (highlighted)
};

struct HelpLine {
    std::string key;   // "F9", or ":cycle" for a command
    std::string what;  // what it does
    std::string when;  // the context it applies in ("", "page dir", "mode jog")
};

struct DirEntry {
    int number = 0;
    std::string title;
    int lines = 0;
    int revision = 0;
    int conflict = 0;  // a revision kept aside by a conflicting save (the store), 0 if none
};

// A revision of a stored program, as the HISTORY page lists it.
struct HistoryRow {
    int revision = 0;
    std::string kind;  // save, import, restore, delete…
    std::string when;  // local time
    std::string who, source;
    int64_t lines = 0;
    bool conflict = false;
};

// How a line of the EXERCISE page shows.
enum class ExLine { title, heading, text, note, ok, wrong };

struct View {
    const Sim* sim = nullptr;
    const ProgramMemory* memory = nullptr;
    std::string machine;  // profile name
    PageId page = PageId::op;
    int scroll = 0;  // page scroll (lines) for long pages
    // Bottom of the screen.
    std::string message;
    bool message_error = false;
    std::string prompt;        // before the input line ("IMD> ", "> ")
    std::string mode_hint;     // what to do in this mode: Cycle Start, or the jog keys
    std::string mode_setting;  // the INC step or the JOG feed, "" in other modes
    std::string input;         // the input line text
    int input_cursor = 0;      // in columns
    std::vector<SoftKey> softkeys;
    // Speed of the animation as the status line shows it ("x1", "x10", "max").
    std::string speed;
    // DIR page.
    std::vector<DirEntry> programs;
    int dir_cursor = 0;
    // HELP page.
    std::vector<HelpLine> help;
    std::string store_path;
    // pupitre class replay: the keys of a replay are the page, no getting
    // started, no modes (nothing of the machine is the viewer's to drive).
    bool replay = false;
    // PREF and CORR pages.
    int corr_cursor = 1;
    std::vector<std::string> pending;  // origins changed in a run, not applied yet
    bool protect = false;
    size_t undo_depth = 0;
    std::string last_setting;  // the last touch-off or measurement, its arithmetic
    std::string witness;       // the witness cut the lathe's tools are set from, or ""
    // HISTORY (:history).
    int history_number = -1;          // the program shown
    int history_current = 0;          // its current revision
    std::vector<HistoryRow> history;  // newest first
    // EDIT and MODIF.
    const std::vector<std::string>* edit_lines = nullptr;  // null: no program open
    int edit_number = -1, edit_revision = 0;
    int edit_cursor = 0, edit_mark = -1, edit_locked = 0, edit_error = -1;
    bool edit_dirty = false, edit_modif = false, edit_modify = false;
    // GRAPH.
    GraphView graph;
    // WORKSHOP: the readings taken, newest first, as the message line said them.
    const std::vector<std::string>* readings = nullptr;
    // WORKSHOP: the instruments an exercise allows (their words: dia, tool);
    // null or empty: every one.
    const std::vector<std::string>* instruments = nullptr;
    const std::vector<std::string>* messages = nullptr;  // the message line's, newest first
    // EXERCISE: the task before :submit, the report after; empty: none.
    std::vector<std::pair<ExLine, std::string>> exercise;
    // PART: the part in colour (issue 36).
    PartView part;
};

// The whole screen: status line, page, message line, input line, soft keys.
void render_screen(const View& v, class Canvas& c);
// One page into a rectangle of the canvas.
void render_page(const View& v, Canvas& c, const struct Rect& r);

// Lengths as the pages print them: "-120.500", "12.0000" for degrees.
std::string fmt_len(double v);
std::string fmt_axis(int axis, double v);

}  // namespace pupitre::pages
