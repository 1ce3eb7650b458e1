// The HELP page: "Getting started" (home, jog, tool, touch-off, run), the
// modes in the order of the mode key, then every key binding and every
// command, generated from the bindings and commands tables so that it can
// never disagree with them. Long texts wrap under their column at any width.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cctype>

#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

// The first steps of a student at the lathe or the mill (README "Quick start").
const char* const kGettingStarted[] = {
    N_("1. Home: F8 until the status line shows POM, then Cycle Start (F9)."),
    N_("2. Jog: F8 to JOG, hold an arrow key (the OP page lists the keys); INC moves one step."),
    N_("3. Tool: F2 for the OP page, F8 to IMD, type T1 D1 M6, Enter, then F9 (Cycle Start); "
       "the PREF and CORR pages take settings, not blocks."),
    N_("4. Touch off: jog the tool onto the part, Alt-p for the PREF page, type Z\u00a00 for the "
       "face or X\u00a059.978 for a diameter; the OP page then reads what you typed."),
    N_("5. Run: F6 lists the programs (Enter selects), F8 to AUTO, F9 runs; F10 holds, F12 (RAZ) "
       "abandons."),
    N_("6. A real part: :setup lathe puts a bar in the chuck; a jog stops when the tool touches "
       "it, "
       ":measure dia Z-20 reads the part (pupitre-setup(5))."),
    N_("   On the machining centre :setup mill puts a block in the vice; :measure depth X10 Y40 "
       "reads it from its corner."),
    N_("7. See the part: Alt-v (or :part) shows it in colour as cut, in 3-D on the machining "
       "centre (the arrows turn it); :part export FILE.pdf puts it on paper."),
    N_("The prompt says where typed text goes (IMD>, PREF>, D5>, EDIT>); Escape empties it. "
       "Commands start with ':' (Tab completes). RAZ is F12 (or Alt-r), off the F1-F10 row."),
};

// The modes' descriptions (core's mode_english and mode_how, English there:
// the status line and traces name the modes), for the catalogue; the HELP
// page and the message line show them through tr().
[[maybe_unused]] const char* const kModeTexts[] = {
    N_("continuous run"),
    N_("Cycle Start (F9) runs the selected program"),
    N_("single block"),
    N_("Cycle Start (F9) runs one block"),
    N_("dry run: feeds at the machine maximum"),
    N_("Cycle Start (F9) runs it"),
    N_("program check, no motion"),
    N_("Cycle Start (F9) checks the program"),
    N_("block search and resume"),
    N_("type the N to find, then Cycle Start (F9)"),
    N_("manual data input"),
    N_("type a block, Enter, then Cycle Start (F9)"),
    N_("continuous jog"),
    N_("hold an arrow key to move an axis (keys on OP)"),
    N_("incremental jog"),
    N_("an arrow key moves one step (keys on OP)"),
    N_("homing"),
    N_("Cycle Start (F9) homes the axes"),
};

// A step of "Getting started": "6. text" wraps under its text; a paragraph
// that starts with blanks belongs to the step above and stands under its
// text, every line; one without is a note at the margin.
void step(std::vector<Line>& lines, std::string_view text, int width) {
    size_t blanks = text.find_first_not_of(' ');
    if (blanks == std::string_view::npos) return;
    text.remove_prefix(blanks);
    const bool numbered = std::isdigit(static_cast<unsigned char>(text[0])) != 0;
    const std::string first(blanks > 0 ? 6 : 3, ' '), next(blanks > 0 || numbered ? 6 : 3, ' ');
    const auto parts = wrap_text(std::string(text), width - int(next.size()));
    for (size_t i = 0; i < parts.size(); ++i)
        lines.push_back(Line{}.add((i ? next : first) + parts[i]));
}

// A two-column entry: the key (or command) in its column, the text beside it
// wrapped under itself; a key too wide for its column takes a line of its own.
void entry(std::vector<Line>& lines, const std::string& key, int col, const std::string& what,
           const std::string& when, int width) {
    const int indent = 3 + col + 1;
    std::string text = what + (when.empty() ? "" : "  (" + when + ")");
    bool own_line = columns(key) > col;
    if (own_line) {
        // A usage wider than the page breaks after a '|' (":page om|op|…").
        std::string row;
        for (size_t i = 0; i < key.size();) {
            size_t bar = key.find('|', i);
            std::string piece = key.substr(i, bar == std::string::npos ? bar : bar + 1 - i);
            i = bar == std::string::npos ? key.size() : bar + 1;
            if (!row.empty() && 5 + columns(row + piece) > width) {
                lines.push_back(Line{}.add("   " + row, Style::value));
                row = "  ";
            }
            row += piece;
        }
        lines.push_back(Line{}.add("   " + row, Style::value));
    }
    auto parts = wrap_text(text, std::max(20, width - indent - 1));
    for (size_t i = 0; i < parts.size(); ++i) {
        Line l;
        if (i == 0 && !own_line)
            l.add("   " + pad(key, size_t(col + 1)), Style::value);
        else
            l.add(std::string(size_t(indent), ' '));
        l.add(parts[i]);
        lines.push_back(std::move(l));
    }
}

void modes(const View& v, std::vector<Line>& lines, int width) {
    lines.push_back(Line{}.add(
        std::string(" ") + tr("Modes: F8 goes to the next one (S-F8 back), :mode NAME selects one"),
        Style::title));
    Mode now = v.sim->mode();
    Mode m = Mode::automatic;
    do {
        std::string when = m == now                 ? tr("now")
                           : m == next_mode(now, 1) ? tr("F8 goes here next")
                                                    : "";
        entry(lines, std::string(mode_name(m)), 8,
              tr_text(mode_english(m)) + "; " + tr_text(mode_how(m)), when, width);
        m = next_mode(m, 1);
    } while (m != Mode::automatic);
    entry(lines, "EDIT", 8, tr("the program editor: :edit N or Alt-e (the selected program)"), "",
          width);
    entry(lines, "MODIF", 8,
          tr("change the blocks to come of an interrupted program: Alt-m or :mode modif"), "",
          width);
}

}  // namespace

void page_help(const View& v, Canvas& c, const Rect& r) {
    // TRANSLATORS: the HELP page's title: HELP is the page's name.
    c.rule(r.y, tr("HELP  keys and commands (PgUp/PgDn scroll)"));
    std::vector<Line> lines;
    // The whole width but a margin (the scroll position is on the rule).
    const int width = r.w - 1;
    if (v.replay) {
        // TRANSLATORS: the HELP page of pupitre class replay.
        step(lines,
             tr("A replay of the student's actions: what the console showed them, read-only."),
             width);
    } else {
        lines.push_back(Line{}.add(std::string(" ") + tr("Getting started"), Style::title));
        for (const char* s : kGettingStarted) step(lines, tr(s), width);
        lines.push_back(Line{});
        modes(v, lines, width);
    }
    std::string section;
    for (const HelpLine& h : v.help) {
        bool cmd = !h.key.empty() && h.key[0] == ':';
        std::string want = cmd ? tr("Commands (type them on the input line)") : tr("Keys");
        if (want != section) {
            section = want;
            lines.push_back(Line{});
            lines.push_back(Line{}.add(" " + section, Style::title));
        }
        entry(lines, h.key, cmd ? 22 : 12, h.what, h.when, width);
    }
    if (!v.store_path.empty()) {
        lines.push_back(Line{});
        lines.push_back(
            Line{}.add(std::string(" ") + tr("Store:") + " ", Style::dim).add(v.store_path));
    }
    lines.push_back(
        Line{}.add(std::string(" ") +
                       tr("Manual: man pupitre (the console), man pupitre-iso (the NUM dialect)"),
                   Style::dim));
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
