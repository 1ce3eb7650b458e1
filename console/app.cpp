// The console: pupitre with no command. Opens the store, the machine and the
// terminal, then runs the event loop: keys in, animation ticks, the screen
// drawn from the pages. Nothing in the loop waits for long: a running
// program advances a frame at a time (ARCHITECTURE.md).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <clocale>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "console/cli.hpp"
#include "console/exercise.hpp"
#include "console/exercise_run.hpp"
#include "console/keys.hpp"
#include "console/line_readline.hpp"
#include "console/session.hpp"
#include "console/term.hpp"
#include "core/i18n.hpp"
#include "pages/canvas.hpp"
#include "pages/pages.hpp"
#include "pages/view.hpp"
#include "store/store.hpp"

namespace pupitre::cli {

namespace {

using Clock = std::chrono::steady_clock;

std::string config_bindings_path() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x)
        return std::string(x) + "/pupitre/bindings";
    if (const char* h = std::getenv("HOME"); h && *h)
        return std::string(h) + "/.config/pupitre/bindings";
    return {};
}

// The machine: --machine, else the last one the console used, else the lathe.
bool console_machine(const ConsoleArgs& a, store::Store& s, MachineProfile& m) {
    std::string name = a.machine;
    if (name.empty()) {
        auto r = s.setting("console.machine");
        name = !r.error && r.value ? *r.value : "lathe";
    }
    if (!builtin_machine(name, m)) {
        auto p = s.machine_profile(name);
        if (!p.error && !p.value.empty()) {
            std::string err = parse_machine(p.value, m);
            if (!err.empty()) {
                std::fprintf(stderr, tr("pupitre: stored machine %s: %s\n"), name.c_str(),
                             err.c_str());
                return false;
            }
        } else if (!load_machine(name, m)) {
            return false;
        }
    }
    if (!a.machine.empty()) s.set_setting("console.machine", name);
    return true;
}

const char* signal_name(int sig) {
    switch (sig) {
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        case SIGINT:
            return "SIGINT";
        case SIGQUIT:
            return "SIGQUIT";
    }
    return "signal";
}

// Cursor position of the input line, as render_screen lays it out.
void input_cursor(const pages::View& v, const pages::Canvas& c, int& x, int& y) {
    int px = pages::columns(v.prompt);
    int room = c.width() - px - 1;
    x = px + (v.input_cursor > room ? room : v.input_cursor);
    y = c.height() - 2;
    if (c.width() < 80 || c.height() < 24) y = c.height() - 1;  // the "too small" screen's
}

// The PART page's picture as the terminal's own, over the page's
// rectangle, once ncurses has drawn the screen (term_image.hpp).
void draw_picture(const console::Session& s, const pages::View& v, console::Terminal& term) {
    if (term.images() == console::ImageProtocol::none) return;
    const std::string* seq =
        v.page == pages::PageId::part && v.part.image ? s.part().sequence() : nullptr;
    const pages::Rect a =
        pages::part_area(pages::Rect{0, 1, term.cols(), term.rows() - 4}, v.part.info);
    term.picture(a.x, a.y, seq, s.part().serial());
}

int event_loop(console::Session& s, console::Terminal& term, bool ascii) {
    console::KeyDecoder dec;
    pages::Canvas canvas(term.cols(), term.rows(), ascii);
    std::vector<console::Key> keys;
    // Keys typed while the terminal was asked about pictures.
    if (const std::string early = term.take_input(); !early.empty()) {
        dec.feed(early, keys);
        for (const console::Key& k : keys)
            if (s.on_key(k) == console::Effect::quit || s.quitting()) return kOk;
        keys.clear();
    }
    Clock::time_point last = Clock::now(), last_byte = last;
    bool dirty = true;
    for (;;) {
        if (term.resized()) dirty = true;
        s.resize(term.cols(), term.rows());
        if (dirty) {
            if (canvas.width() != term.cols() || canvas.height() != term.rows())
                canvas.resize(term.cols(), term.rows());
            pages::View v = s.view();
            pages::render_screen(v, canvas);
            int cx, cy;
            input_cursor(v, canvas, cx, cy);
            term.draw(canvas, cx, cy);
            draw_picture(s, v, term);
            dirty = false;
        }
        const bool picture = s.picture_pending();
        int timeout = s.busy() || picture ? 30 : dec.pending() ? 25 : 500;
        struct pollfd pfd = {STDIN_FILENO, POLLIN, 0};
        int r = poll(&pfd, 1, timeout);
        if (console::Terminal::interrupted()) return kOk;
        keys.clear();
        Clock::time_point now = Clock::now();
        if (r > 0 && (pfd.revents & (POLLIN | POLLHUP | POLLERR))) {
            char buf[4096];
            ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
            if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN))
                return kOk;  // the terminal is gone
            if (n > 0) dec.feed(std::string_view(buf, size_t(n)), keys);
            last_byte = now;
        } else if (dec.pending() && now - last_byte >= std::chrono::milliseconds(25)) {
            dec.flush(keys);
        }
        for (const console::Key& k : keys) {
            if (s.on_key(k) == console::Effect::quit || s.quitting()) return kOk;
            dirty = true;
        }
        double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        if (s.busy() || dt > 0.4) {
            s.tick(std::min(dt, 0.5));
            dirty = true;
        }
        if (picture) dirty = true;  // the worker's picture, when it is made
    }
}

// The store: --db, else the default one (its directories made). False with
// the exit code in `rc` when it cannot be opened.
bool open_console_store(const ConsoleArgs& a, std::unique_ptr<store::Store>& st, int& rc) {
    store::Options o;
    o.live = true;  // a server gone never holds the keys up
    std::string path = a.db;
    if (path.empty()) {
        path = store::default_path();
        o.create_parents = true;
        if (path.empty()) {
            std::fputs(tr("pupitre: no place for the default store: set HOME or XDG_DATA_HOME, or "
                          "give --db\n"),
                       stderr);
            rc = kCantCreate;
            return false;
        }
    }
    auto opened = store::Store::open(path, o);
    if (opened.error) {
        std::fprintf(stderr, tr("pupitre: %s\n"), opened.error.message.c_str());
        rc = store::exit_code(opened.error.fault);
        return false;
    }
    st = std::move(opened.value);
    return true;
}

bool console_theme(const ConsoleArgs& a, console::Theme& theme) {
    // NO_COLOR (no-color.org): set and not empty, the console is mono unless
    // --theme asks for colours.
    const char* no_color = std::getenv("NO_COLOR");
    std::string theme_name = !a.theme.empty() ? a.theme : no_color && *no_color ? "mono" : "colour";
    if (!console::parse_theme(theme_name, theme)) {
        std::fprintf(stderr, tr("pupitre: unknown theme '%s' (colour, mono, phosphor)\n"),
                     theme_name.c_str());
        return false;
    }
    return true;
}

// The first screen: the store's programs and state, the user's bindings, the
// program this machine had selected; the message line says what went wrong,
// else how to begin.
void first_screen(console::Session& s, const MachineProfile& m) {
    std::string news = s.load_store();
    std::string user = config_bindings_path();
    if (std::ifstream f(user); f) {
        std::stringstream ss;
        ss << f.rdbuf();
        std::string err = s.add_bindings(ss.str(), user);
        if (!err.empty()) news = err;
    }
    if (auto r = s.store()->setting("console.program." + m.name); !r.error && r.value) {
        int n = std::atoi(r.value->c_str());
        if (s.memory().find(n))
            if (std::string why = s.sim().select(n); !why.empty()) news = why;
    }
    if (news.empty())
        // TRANSLATORS: the console's first message line (80 columns): the
        // version, the machine profile's name, the keys to begin with.
        news = strf(tr("pupitre %s, %s: F1 help, F6 programs, F8 mode, F9 Cycle Start"),
                    PUPITRE_VERSION, pages::machine_word(m.name).c_str());
    s.say(news, false);
}

// pupitre exercise NAME: the exercise, the class key (made on first use),
// the exercise's machine. False (the message printed) when one is missing.
bool exercise_setup(const ConsoleArgs& a, store::Store& st, training::Exercise& e, std::string& key,
                    MachineProfile& m, int& rc) {
    rc = kNoInput;
    auto on_class = st.class_server();
    std::string why = on_class.error ? on_class.error.message : std::string();
    // On a server a person is their login: the server says who they are.
    if (why.empty() && st.engine() == "postgresql" && !a.student.empty())
        why = tr("--student: on a server store you are your login (the server says who you are)");
    if (why.empty() && on_class.value && console::exercise_is_file(a.exercise))
        why = strf(tr("%s: on a class's server the exercises are the server's (pupitre exercise "
                      "list)"),
                   a.exercise.c_str());
    if (why.empty()) why = console::find_exercise(&st, a.exercise, e);
    if (why.empty() && !on_class.value) why = console::store_class_key(st, true, key);
    if (why.empty() && !a.machine.empty() && a.machine != e.machine)
        why = strf(tr("exercise %s is on the %s, not on %s"), e.name.c_str(), e.machine.c_str(),
                   a.machine.c_str());
    if (why.empty() && !builtin_machine(e.machine, m))
        why = strf(tr("no machine %s"), e.machine.c_str());
    if (!why.empty()) std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
    return why.empty();
}

// :exercise NAME: this console ends and pupitre starts again on the
// exercise, on the same store, theme and student.
int restart_on(const ConsoleArgs& a, console::Session& s, const std::string& name) {
    std::vector<std::string> args = {"pupitre", "--db", s.store()->target()};
    if (!a.theme.empty()) args.insert(args.end(), {"--theme", a.theme});
    if (a.ascii) args.push_back("--ascii");
    args.insert(args.end(), {"exercise", name});
    if (!a.student.empty()) args.insert(args.end(), {"--student", a.student});
    std::vector<char*> argv;
    for (std::string& x : args) argv.push_back(x.data());
    argv.push_back(nullptr);
    execv("/proc/self/exe", argv.data());
    std::fprintf(stderr, tr("pupitre: cannot start again on exercise %s: %s\n"), name.c_str(),
                 std::strerror(errno));
    return kSoftware;
}

// The first screen of an attempt: its program selected, its task shown.
void exercise_screen(console::Session& s, const training::Exercise& e) {
    if (e.program_number > 0 && s.memory().find(e.program_number)) s.sim().select(e.program_number);
    s.show_page(pages::PageId::exercise);
    const std::string& note = s.exercise() ? s.exercise()->program_note() : std::string();
    s.say(note.empty()
              ? strf(tr("exercise %s: the task is on this page (Alt-x); :submit hands it in"),
                     e.name.c_str())
              : note);
}

}  // namespace

int console(const ConsoleArgs& a) {
    // The locale was set by main() (i18n::init): characters from the
    // environment, LC_NUMERIC "C".
    std::unique_ptr<store::Store> st;
    if (int rc = kOk; !open_console_store(a, st, rc)) return rc;
    MachineProfile m;
    training::Exercise ex;
    std::string key;
    if (int rc = kOk; !a.exercise.empty() && !exercise_setup(a, *st, ex, key, m, rc)) return rc;
    if (a.exercise.empty() && !console_machine(a, *st, m)) return kUsage;
    console::Theme theme;
    if (!console_theme(a, theme)) return kUsage;
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
        std::fputs(
            tr("pupitre: the console needs a terminal; for scripts use pupitre run, check, list "
               "(pupitre --help)\n"),
            stderr);
        return kNoInput;
    }
    // The student: on a server their login, on a file --student or the OS user.
    const std::string student =
        st->engine() == "postgresql" ? st->user() : console::student_name(a.student);
    console::ReadlineInput input;
    console::Session s(m, std::move(st), input);
    if (!a.exercise.empty()) {
        if (std::string why = s.start_exercise(ex, student, key); !why.empty()) {
            std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
            return kDataErr;
        }
    }
    first_screen(s, m);
    if (!a.exercise.empty()) exercise_screen(s, ex);
    console::Terminal term;
    if (std::string err = term.open(theme); !err.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), err.c_str());
        return kNoInput;
    }
    bool ascii = a.ascii || !console::Terminal::utf8_locale();
    console::Screen screen;
    screen.colours = term.colours();
    screen.ascii = ascii;
    // A real picture only where the terminal answers that it takes one.
    if (const char* im = std::getenv("PUPITRE_IMAGES"); !im || std::strcmp(im, "off") != 0) {
        term.ask_images(300);
        screen.protocol = term.images();
        screen.cell_w = term.cell_w(), screen.cell_h = term.cell_h();
    }
    s.set_screen(screen);
    int rc = event_loop(s, term, ascii);
    term.close();
    // A signal (a logout, a kill) ended the console with the editor's work
    // unsaved: the shell hears how it ended, the operator where the work is.
    if (int sig = console::Terminal::signal_caught(); sig != 0) {
        if (std::string note = s.unsaved_note(); !note.empty()) {
            std::fprintf(stderr, tr("pupitre: %s: %s\n"), signal_name(sig), note.c_str());
            return 128 + sig;
        }
    }
    if (!s.restart_exercise().empty()) return restart_on(a, s, s.restart_exercise());
    return rc;
}

}  // namespace pupitre::cli
