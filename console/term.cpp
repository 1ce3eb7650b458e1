// The ncurses backend (see term.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#define NCURSES_WIDECHAR 1
#include "console/term.hpp"

#include <curses.h>
#include <langinfo.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>

#include "core/i18n.hpp"
#include "pages/page_part.hpp"

namespace pupitre::console {

namespace {

volatile std::sig_atomic_t g_winch = 0;
volatile std::sig_atomic_t g_quit = 0;
struct termios g_saved;
bool g_have_saved = false;
bool g_open = false;

// What a crash writes: made by Terminal::open, in the chosen language, because
// the handler may not translate (gettext is not async-signal-safe).
char g_reset[256];
size_t g_reset_len = 0;

// A crash must not leave the user's terminal raw and on the alternate screen:
// only async-signal-safe calls here (write, tcsetattr), then the default action.
void crash_handler(int sig) {
    if (g_open) {
        ssize_t n = write(STDOUT_FILENO, g_reset, g_reset_len);
        (void)n;
        if (g_have_saved) tcsetattr(STDIN_FILENO, TCSANOW, &g_saved);
    }
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

void quit_handler(int sig) {
    g_quit = sig;
}
void winch_handler(int) {
    g_winch = 1;
}

void install(int sig, void (*h)(int)) {
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = h;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, nullptr);
}

void at_exit() {
    if (g_open) {
        endwin();
        g_open = false;
    }
}

short pair_of(pages::Style s) {
    return short(int(s) + 1);
}

// The pairs after the theme's are the pictures' (term.hpp, pair_for).
constexpr int kFirstPicturePair = 16;

}  // namespace

bool parse_theme(const std::string& name, Theme& out) {
    if (name == "colour" || name == "color")
        out = Theme::colour;
    else if (name == "mono")
        out = Theme::mono;
    else if (name == "phosphor")
        out = Theme::phosphor;
    else
        return false;
    return true;
}

bool Terminal::utf8_locale() {
    const char* cs = nl_langinfo(CODESET);
    return cs && (std::strcmp(cs, "UTF-8") == 0 || std::strcmp(cs, "utf8") == 0);
}

bool Terminal::interrupted() {
    return g_quit != 0;
}

int Terminal::signal_caught() {
    return int(g_quit);
}

std::string Terminal::open(Theme theme) {
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO))
        return tr("the console needs a terminal (try pupitre --help)");
    if (tcgetattr(STDIN_FILENO, &g_saved) == 0) g_have_saved = true;
    if (!initscr())
        return strf(tr("cannot initialise the terminal (TERM=%s)"),
                    getenv("TERM") ? getenv("TERM") : "");
    std::string reset = std::string("\033[0m\033[?25h\033[?1049l\r\n") +
                        tr("pupitre: crashed; the terminal is restored") + "\r\n";
    g_reset_len = std::min(reset.size(), sizeof g_reset);
    std::memcpy(g_reset, reset.data(), g_reset_len);
    g_open = open_ = true;
    std::atexit(at_exit);
    for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) install(s, crash_handler);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) install(s, quit_handler);
    install(SIGWINCH, winch_handler);
    raw();  // Ctrl-C and Ctrl-Z are keys: the bindings decide
    noecho();
    nonl();
    keypad(stdscr, FALSE);  // console/keys.cpp decodes the bytes
    intrflush(stdscr, FALSE);
    curs_set(1);
    if (has_colors() && theme != Theme::mono) {
        start_color();
        use_default_colors();
        theme_colours(theme);
        if (theme == Theme::colour)
            colours_ = COLORS >= 0x1000000 ? pages::Colours::direct
                       : COLORS >= 256     ? pages::Colours::c256
                       : COLORS >= 16      ? pages::Colours::c16
                                           : pages::Colours::c8;
        next_pair_ = kFirstPicturePair;
    } else {
        theme_colours(Theme::mono);
    }
    getmaxyx(stdscr, rows_, cols_);
    return {};
}

void Terminal::close() {
    if (!open_) return;
    endwin();
    open_ = g_open = false;
}

void Terminal::theme_colours(Theme t) {
    if (t == Theme::mono || !has_colors()) return;
    using S = pages::Style;
    short fg = t == Theme::phosphor ? COLOR_GREEN : -1;
    short bg = t == Theme::phosphor ? COLOR_BLACK : -1;
    struct P {
        S s;
        short f, b;
    };
    const P colour[] = {
        {S::normal, -1, -1},
        {S::dim, COLOR_CYAN, -1},
        {S::title, COLOR_YELLOW, -1},
        {S::value, -1, -1},
        {S::big, COLOR_GREEN, -1},
        {S::select, COLOR_BLACK, COLOR_CYAN},
        {S::alarm, COLOR_WHITE, COLOR_RED},
        {S::warn, COLOR_BLACK, COLOR_YELLOW},
        {S::ok, COLOR_BLACK, COLOR_GREEN},
        {S::status, COLOR_WHITE, COLOR_BLUE},
        {S::key, -1, -1},
        {S::softkey, COLOR_BLACK, COLOR_CYAN},
        {S::input, -1, -1},
        {S::softkey_on, COLOR_WHITE, COLOR_BLUE},
    };
    for (const P& p : colour) {
        if (t == Theme::phosphor) {
            bool inverse = p.b != -1 && p.s != S::softkey_on;  // bold green stands out
            init_pair(pair_of(p.s), inverse ? COLOR_BLACK : fg, inverse ? COLOR_GREEN : bg);
        } else {
            init_pair(pair_of(p.s), p.f, p.b);
        }
    }
    if (t == Theme::phosphor) bkgd(COLOR_PAIR(pair_of(S::normal)));
    theme_ = t;
}

void Terminal::ask_images(int ms) {
    const char* term = std::getenv("TERM");
    const std::string t = term ? term : "";
    if (t.empty() || t == "dumb" || t == "linux") return;
    struct winsize ws;
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 && ws.ws_row > 0)
        cell_w_ = ws.ws_xpixel / ws.ws_col, cell_h_ = ws.ws_ypixel / ws.ws_row;
    const std::string q = image_query(true);
    if (write(STDOUT_FILENO, q.data(), q.size()) != ssize_t(q.size())) return;
    std::string got;
    ImageAnswer a;
    for (int waited = 0; waited < ms && !a.done; waited += 10) {
        struct pollfd pfd = {STDIN_FILENO, POLLIN, 0};
        if (poll(&pfd, 1, 10) > 0) {
            char buf[512];
            const ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
            if (n > 0) got.append(buf, size_t(n));
        }
        input_.clear();
        a = parse_answers(got, input_);
    }
    if (a.cell_w > 0 && a.cell_h > 0) cell_w_ = a.cell_w, cell_h_ = a.cell_h;
    images_ = cell_w_ > 0 && cell_h_ > 0 ? a.protocol() : ImageProtocol::none;
}

void Terminal::picture(int x, int y, const std::string* seq, uint64_t serial) {
    if (images_ == ImageProtocol::none) return;
    if (!seq || seq->empty()) {
        if (shown_ == 0) return;
        const std::string del = image_delete(images_, 1);
        if (!del.empty() && write(STDOUT_FILENO, del.data(), del.size()) < 0) return;
        if (images_ == ImageProtocol::sixel) {  // its pixels stay until the screen is drawn again
            clearok(curscr, TRUE);
            refresh();
        }
        shown_ = 0;
        return;
    }
    if (serial == shown_ && !repainted_) return;
    // Where ncurses left the cursor, to put it back.
    int cy = 0, cx = 0;
    getyx(stdscr, cy, cx);
    std::string out = "\033[" + std::to_string(y + 1) + ";" + std::to_string(x + 1) + "H" + *seq +
                      "\033[" + std::to_string(cy + 1) + ";" + std::to_string(cx + 1) + "H";
    size_t at = 0;
    while (at < out.size()) {
        const ssize_t n = write(STDOUT_FILENO, out.data() + at, out.size() - at);
        if (n <= 0) break;
        at += size_t(n);
    }
    shown_ = serial;
    repainted_ = false;
}

bool Terminal::resized() {
    if (!g_winch) return false;
    g_winch = 0;
    struct winsize ws;
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_row > 0 && ws.ws_col > 0)
        resizeterm(ws.ws_row, ws.ws_col);
    getmaxyx(stdscr, rows_, cols_);
    clearok(stdscr, TRUE);
    repainted_ = true;  // a picture is drawn again over the new screen
    return true;
}

namespace {

// A style's attributes without colours (the mono theme).
attr_t mono_attr(pages::Style st) {
    using S = pages::Style;
    switch (st) {
        case S::title:
        case S::big:
        case S::softkey_on:  // the other soft keys are in reverse
            return A_BOLD;
        case S::dim:
            return A_DIM;
        case S::select:
        case S::status:
        case S::softkey:
        case S::ok:
            return A_REVERSE;
        case S::alarm:
        case S::warn:
            return A_REVERSE | A_BOLD;
        default:
            return A_NORMAL;
    }
}

}  // namespace

void Terminal::draw(const pages::Canvas& c, int cx, int cy) {
    using S = pages::Style;
    // The pictures' pairs begin again while half are free: a frame never
    // redefines a pair it drew with.
    if (next_pair_ > (COLOR_PAIRS + kFirstPicturePair) / 2) {
        pairs_.clear();
        next_pair_ = kFirstPicturePair;
    }
    for (int y = 0; y < c.height() && y < rows_; ++y) {
        for (int x = 0; x < c.width() && x < cols_; ++x) {
            const pages::Cell& cell = c.at(x, y);
            attr_t a = A_NORMAL;
            short pair = 0;
            if (theme_ == Theme::mono) {
                a = mono_attr(cell.st);
            } else {
                pair = pair_of(cell.st);
                if (cell.st == S::title || cell.st == S::big || cell.st == S::alarm ||
                    cell.st == S::softkey_on)
                    a |= A_BOLD;
            }
            wchar_t wc[2] = {wchar_t(cell.ch), 0};
            cchar_t cc;
            int own = 0;  // a picture's cell in its own colours
            if ((cell.fg != pages::kNoColour || cell.bg != pages::kNoColour) &&
                colours_ != pages::Colours::none)
                own = pair_for(cell.fg, cell.bg);
            // The colour pair is setcchar's own argument: a COLOR_PAIR in the
            // attributes would be overridden by it (an extended pair is given
            // through the last one).
            if (own > 0)
                setcchar(&cc, wc, A_NORMAL, 0, &own);
            else
                setcchar(&cc, wc, a, pair, nullptr);
            mvadd_wch(y, x, &cc);
        }
    }
    move(cy, cx);
    refresh();
}

int Terminal::colour_number(uint32_t c) const {
    if (c == pages::kNoColour) return -1;  // the terminal's own (use_default_colors)
    if (c & pages::kPaletteBit) return int(c & 0xff);
    if (colours_ == pages::Colours::direct) return int(c & 0xffffff);
    const uint32_t t =
        pages::terminal_colour(render::rgb((c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff), colours_);
    return int(t & 0xff);
}

int Terminal::pair_for(uint32_t fg, uint32_t bg) {
    const uint64_t k = uint64_t(fg) << 32 | bg;
    if (auto it = pairs_.find(k); it != pairs_.end()) return it->second;
    if (next_pair_ >= COLOR_PAIRS) {
        // Every pair taken: begin again (the whole frame is drawn anew).
        pairs_.clear();
        next_pair_ = kFirstPicturePair;
    }
    if (next_pair_ >= COLOR_PAIRS) return 0;
    const int p = next_pair_++;
    init_extended_pair(p, colour_number(fg), colour_number(bg));
    pairs_.emplace(k, p);
    return p;
}

}  // namespace pupitre::console
