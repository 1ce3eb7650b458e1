// The screen layout (pupitre(1), THE CONSOLE): status line, page, message line, input line,
// soft keys. The same on every terminal of at least 80x24; a bigger one gives
// the page more room.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/numfmt.hpp"
#include "pages/canvas.hpp"
#include "pages/page_graph.hpp"
#include "pages/pages.hpp"
#include "pages/view.hpp"

namespace pupitre::pages {

namespace {

// The run state as the status line shows it (core's state_name stays the
// English word of the traces).
const char* state_text(RunState st) {
    switch (st) {
        // TRANSLATORS: run states on the status line: at most 6 columns each.
        case RunState::idle:
            return tr("READY");
        // TRANSLATORS: run state (a program runs), at most 6 columns.
        case RunState::running:
            return tr("CYCLE");
        // TRANSLATORS: run state (feed hold), at most 6 columns.
        case RunState::hold:
            return tr("HOLD");
        // TRANSLATORS: run state (single block: waits for the next), at most 6 columns.
        case RunState::block:
            return tr("BLOCK");
        // TRANSLATORS: run state (M00/M01 stop), at most 6 columns.
        case RunState::stopped:
            return tr("STOP");
        // TRANSLATORS: run state (end of program), at most 6 columns.
        case RunState::ended:
            return tr("END");
        // TRANSLATORS: run state, at most 6 columns.
        case RunState::alarm:
            return tr("ALARM");
    }
    return "?";
}

constexpr std::string_view kPageWords[] = {"om",      "op",   "prog",     "info", "param", "dir",
                                           "alarm",   "help", "pref",     "corr", "edit",  "graph",
                                           "history", "shop", "exercise", "part"};

void status_line(const View& v, Canvas& c) {
    const Sim& s = *v.sim;
    c.fill(Rect{0, 0, c.width(), 1}, U' ', Style::status);
    std::string left = " " + std::string(mode_name(s.mode()));
    int x = c.text(0, 0, left, Style::status);
    x += 1;
    std::string prog = s.selected() >= 0 ? "%" + std::to_string(s.selected()) : "%-";
    x += c.text(x + 1, 0, prog, Style::status) + 1;
    const Loc& l = s.loc();
    std::string n = l.n >= 0     ? "N" + std::to_string(l.n)
                    : l.line > 0 ? strf(tr("line %d"), l.line)
                                 : "";
    if (!n.empty()) x += c.text(x + 1, 0, n, Style::status) + 1;
    RunState st = s.state();
    Style ss = st == RunState::alarm     ? Style::alarm
               : st == RunState::running ? Style::ok
               : (st == RunState::hold || st == RunState::stopped || st == RunState::block)
                   ? Style::warn
                   : Style::status;
    x += 1;
    // TRANSLATORS: status line, the alarm in force with its number.
    std::string state = s.alarm_active() ? strf(tr("ALARM %d"), s.alarms().back().diag.code)
                                         : std::string(state_text(st));
    x += c.text(x + 1, 0, " " + state + " ", ss) + 1;
    // The mode key's next mode (F8 cycles them; the HELP page lists them).
    c.text(x + 2, 0,
           std::string("F8") + (c.ascii() ? ">" : "→") +
               std::string(mode_name(next_mode(s.mode(), 1))),
           Style::status);
    // TRANSLATORS: status line, memory protection on: at most 5 columns.
    std::string lock = v.protect ? std::string(tr("LOCK")) + " " : "";
    char right[112];
    const std::string machine = machine_word(v.machine);
    std::snprintf(right, sizeof right, "%s%s F%d%% S%d%%%s%s %s ", lock.c_str(), machine.c_str(),
                  s.feed_override, s.spindle_override, s.interp().options().block_skip ? " /" : "",
                  s.interp().options().optional_stop ? " M01" : "", v.speed.c_str());
    c.text_right(0, 0, c.width(), right, Style::status);
}

void softkeys(const View& v, Canvas& c, int y) {
    int n = 10;
    int w = c.width() / n;
    for (int i = 0; i < n; ++i) {
        int x = i * w;
        std::string num = std::to_string(i + 1);
        c.text(x, y, num, Style::key);
        const SoftKey* k = nullptr;
        for (const auto& s : v.softkeys)
            if (s.key == "F" + num) k = &s;
        std::string label = k ? k->label : "";
        int lw = w - int(num.size());
        // The key of the page on screen stands out: the soft keys follow the page.
        Style st = k && k->current ? Style::softkey_on : Style::softkey;
        c.fill(Rect{x + int(num.size()), y, lw, 1}, U' ', st);
        c.text(x + int(num.size()), y, label, st, lw - 1);
    }
}

}  // namespace

// The machine's name as the panel says it: the built-in lathe and mill in
// the console's language (a profile's own name as it is).
std::string machine_word(const std::string& name) {
    if (name == "lathe") return tr("lathe");
    if (name == "mill") return tr("mill");
    return name;
}

std::string_view page_word(PageId p) {
    return kPageWords[int(p)];
}

bool parse_page(std::string_view word, PageId& out) {
    for (int i = 0; i < int(std::size(kPageWords)); ++i)
        if (kPageWords[i] == word) {
            out = PageId(i);
            return true;
        }
    return false;
}

std::string fmt_len(double v) {
    return fixed3_zeroed(v, 0.0005);
}

std::string fmt_axis(int axis, double v) {
    char buf[32];
    if (is_rotary(axis)) {
        if (std::abs(v) < 0.00005) v = 0;
        std::snprintf(buf, sizeof buf, "%.4f", v);
        return buf;
    }
    return fmt_len(v);
}

namespace {

// Below 80x24 the layout cannot hold: one clear screen says so, and what
// runs goes on (pupitre(1), THE CONSOLE).
void too_small(const View& v, Canvas& c) {
    const std::string lines[] = {
        tr("Terminal too small"),
        tr("pupitre needs at least 80x24;"),
        strf(tr("this terminal is %dx%d"), c.width(), c.height()),
        tr("Enlarge the window to go on."),
        std::string(mode_name(v.sim->mode())) + " " + std::string(state_text(v.sim->state())),
    };
    int n = int(std::size(lines));
    int y0 = std::max(0, (c.height() - n) / 2);
    for (int i = 0; i < n && y0 + i < c.height(); ++i) {
        int w = columns(lines[i]);
        c.text(std::max(0, (c.width() - w) / 2), y0 + i, lines[i],
               i == 0 ? Style::alarm : Style::normal, c.width());
    }
    // Below, the message and the input line: what :quit needs, seen as typed.
    const int h = c.height();
    if (h < y0 + n + 2) return;
    c.text(0, h - 2, v.message, v.message_error ? Style::alarm : Style::normal, c.width());
    c.fill(Rect{0, h - 1, c.width(), 1}, U' ', Style::input);
    const int px = c.text(0, h - 1, v.prompt, Style::input);
    c.text(px, h - 1, v.input, Style::input, std::max(0, c.width() - px));
}

}  // namespace

void render_screen(const View& v, Canvas& c) {
    c.clear();
    if (c.width() < 80 || c.height() < 24) return too_small(v, c);
    int h = c.height();
    status_line(v, c);
    render_page(v, c, Rect{0, 1, c.width(), h - 4});
    // Message line: the newest news, an error in the alarm style.
    c.text(1, h - 3, v.message, v.message_error ? Style::alarm : Style::normal, c.width() - 2);
    c.fill(Rect{0, h - 2, c.width(), 1}, U' ', Style::input);
    int px = c.text(0, h - 2, v.prompt, Style::input);
    // The input line scrolls so that the cursor stays visible.
    int room = c.width() - px - 1;
    int first = v.input_cursor > room ? v.input_cursor - room : 0;
    std::string shown;
    int col = 0;
    for (size_t i = 0; i < v.input.size(); ++col) {
        size_t start = i;
        ++i;
        while (i < v.input.size() && (static_cast<unsigned char>(v.input[i]) & 0xc0) == 0x80) ++i;
        if (col >= first) shown.append(v.input, start, i - start);
    }
    c.text(px, h - 2, shown, Style::input, room + 1);
    softkeys(v, c, h - 1);
}

void render_page(const View& v, Canvas& c, const Rect& r) {
    switch (v.page) {
        case PageId::om:
        case PageId::op:
            return page_position(v, c, r);
        case PageId::prog:
            return page_program(v, c, r);
        case PageId::info:
            return page_info(v, c, r);
        case PageId::param:
            return page_param(v, c, r);
        case PageId::dir:
            return page_dir(v, c, r);
        case PageId::alarm:
            return page_alarm(v, c, r);
        case PageId::help:
            return page_help(v, c, r);
        case PageId::pref:
            return page_pref(v, c, r);
        case PageId::corr:
            return page_corr(v, c, r);
        case PageId::edit:
            return page_edit(v, c, r);
        case PageId::graph:
            return page_graph(v.graph, v.sim->machine(), c, r);
        case PageId::history:
            return page_history(v, c, r);
        case PageId::shop:
            return page_shop(v, c, r);
        case PageId::exercise:
            return page_exercise(v, c, r);
        case PageId::part:
            return page_part(v, c, r);
    }
}

std::vector<std::string> wrap_text(const std::string& text, int width) {
    std::vector<std::string> out;
    std::string line;
    size_t i = 0;
    while (i < text.size()) {
        size_t sp = text.find(' ', i);
        std::string word = text.substr(i, sp == std::string::npos ? std::string::npos : sp - i);
        i = sp == std::string::npos ? text.size() : sp + 1;
        if (!line.empty() && columns(line) + 1 + columns(word) > width) {
            out.push_back(line);
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) out.push_back(line);
    return out;
}

void add_wrapped(std::vector<Line>& out, Line lead, const std::string& text, int width, Style st) {
    int indent = 0;
    for (const auto& part : lead.parts) indent += columns(part.first);
    const auto parts = wrap_text(text, std::max(20, width - indent));
    for (size_t i = 0; i < parts.size(); ++i) {
        if (i == 0) {
            out.push_back(std::move(lead));
            out.back().add(parts[i], st);
        } else {
            out.push_back(Line{}.add(std::string(size_t(indent), ' ') + parts[i], st));
        }
    }
    if (parts.empty()) out.push_back(std::move(lead));
}

// A long page is a list of lines; the view's scroll picks the ones shown.
void draw_lines(const std::vector<Line>& lines, int scroll, Canvas& c, const Rect& r) {
    int n = int(lines.size());
    if (scroll > n - r.h) scroll = n - r.h;
    if (scroll < 0) scroll = 0;
    for (int i = 0; i < r.h && scroll + i < n; ++i) {
        const Line& l = lines[size_t(scroll + i)];
        int x = r.x;
        for (const auto& [text, st] : l.parts) x += c.text(x, r.y + i, text, st, r.x + r.w - x);
        if (l.fill) c.style(Rect{r.x, r.y + i, r.w, 1}, l.fill_style);
    }
    if (n > r.h) {
        // Where we are in a long page: "12-31/140" at the right of the page's
        // rule above the lines, where it hides no text (over the last line
        // it hid the end of whatever was there).
        std::string where = std::to_string(scroll + 1) + "-" +
                            std::to_string(std::min(n, scroll + r.h)) + "/" + std::to_string(n);
        const int row = r.y > 0 ? r.y - 1 : r.y + r.h - 1;
        c.text_right(r.x, row, r.w - 1, " " + where + " ", Style::dim);
    }
}

}  // namespace pupitre::pages
