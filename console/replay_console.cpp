// pupitre class replay ATTEMPT (issue 34, pupitre(1) CLASS REPLAY): the
// console, read-only, on the replay of an attempt (replay.hpp). The teacher
// steps through the student's actions one at a time, back, to the end, or
// to the first action that produced a mistake the grade names; the pages,
// the workshop, the part and the GRAPH are the replay's Session's, as the
// student saw them. The pages can be looked at in turn without changing
// the replay: the page the student had is where the next action goes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "console/bindings.hpp"
#include "console/cli.hpp"
#include "console/exercise_run.hpp"
#include "console/keys.hpp"
#include "console/replay.hpp"
#include "console/session.hpp"
#include "console/term.hpp"
#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "pages/canvas.hpp"
#include "pages/pages.hpp"

namespace pupitre::cli {

namespace {

enum class Do { next, back, end, start, mistake, follow, quit };

struct ReplayKey {
    const char* key;
    Do what;
    const char* help;  // "" for another key of the row above
};

// The replay's own keys (pupitre(1), CLASS REPLAY); the HELP page lists them.
const ReplayKey kReplayKeys[] = {
    {"Right", Do::next, N_("the student's next action")},
    {"Space", Do::next, ""},
    {"F9", Do::next, ""},
    {"Left", Do::back, N_("back one action")},
    {"F8", Do::back, ""},
    {"End", Do::end, N_("to the end: the replay's :submit, its grade on the EXERCISE page")},
    {"F10", Do::end, ""},
    {"Home", Do::start, N_("back to the start")},
    {"m", Do::mistake,
     N_("the first action that produced a mistake the grade names (the next one)")},
    {"Tab", Do::follow, N_("the page the student had on screen again")},
    {"q", Do::quit, N_("leave the replay")},
    {"C-c", Do::quit, ""},
};

struct Viewer {
    console::Replay& r;
    size_t pos = 0;                          // the student's actions replayed
    std::optional<pages::PageId> page = {};  // the teacher's, else the student's
    size_t mistake = 0;                      // the next of r.named() for `m`
    std::string news = {};                   // what the last key did, else the action
    std::string store = {};                  // the attempt's store (not the replay's own)
    console::Session& s() { return r.session(); }
};

size_t steps_in(const console::Replay& r, size_t lines) {
    size_t n = 0;
    for (size_t i = 0; i < lines && i < r.lines().size(); ++i) n += r.lines()[i].step();
    return n;
}

// To the state after `p` of the student's actions.
void go_to(Viewer& v, size_t p) {
    if (p < v.pos) {
        if (std::string why = v.r.rewind(1); !why.empty()) v.news = why;
        v.pos = 0;
    }
    while (v.pos < p && !v.r.at_end()) {
        v.r.step();
        v.pos = steps_in(v.r, v.r.done());
    }
}

void jump_to_mistake(Viewer& v) {
    const auto& named = v.r.named();
    if (named.empty()) {
        v.news = tr("the grade names no mistake");
        return;
    }
    const console::Replay::Named& n = named[v.mistake++ % named.size()];
    go_to(v, steps_in(v.r, n.line));
    v.news = v.pos == 0 ? strf(tr("%s: %s, from the start"), n.value.c_str(), n.title.c_str())
                        : strf(tr("%s: %s, from this action"), n.value.c_str(), n.title.c_str());
}

bool replay_key(Viewer& v, Do what) {
    v.news.clear();
    if (what != Do::quit) v.page.reset();  // the page the student had, after the action
    switch (what) {
        case Do::next:
            if (v.r.at_end()) v.news = tr("the last action: End grades it");
            go_to(v, v.pos + 1);
            break;
        case Do::back:
            go_to(v, v.pos > 0 ? v.pos - 1 : 0);
            break;
        case Do::start:
            go_to(v, 0);
            break;
        case Do::end:
            v.r.run_to_end();
            v.pos = steps_in(v.r, v.r.done());
            v.page = pages::PageId::exercise;
            break;
        case Do::mistake:
            jump_to_mistake(v);
            break;
        case Do::follow:
            break;
        case Do::quit:
            return false;
    }
    return true;
}

pages::PageId page_after(std::string_view arg, pages::PageId now) {
    using P = pages::PageId;
    if (arg == "set") return now == P::param ? P::pref : now == P::pref ? P::corr : P::param;
    if (arg == "pos") return now == P::op ? P::om : P::op;
    if (arg == "prog") return now == P::prog ? P::graph : P::prog;
    P p;
    return pages::parse_page(arg, p) ? p : now;
}

pages::PageId shown(Viewer& v) {
    return v.page ? *v.page : v.s().page();
}

// A key: the replay's own, else a page, a scroll or a GRAPH key to look
// with; nothing else acts. False to leave.
bool on_key(Viewer& v, const console::Key& k) {
    const std::string name = console::key_name(k);
    for (const ReplayKey& rk : kReplayKeys)
        if (name == rk.key) return replay_key(v, rk.what);
    const console::Binding* b = v.s().binding_for(k, shown(v));
    const std::string action = b ? b->action : "";
    v.news.clear();
    if (action == "page")
        v.page = page_after(b->arg, shown(v));
    else if (action == "scroll")
        v.s().scroll_by(std::atoi(b->arg.c_str()));
    else if (action.rfind("graph-", 0) == 0 && shown(v) == pages::PageId::graph)
        v.s().graph_key(action.substr(6), b->arg);
    else if (action == "quit")
        return false;
    else
        v.news = strf(tr("%s: the replay changes nothing (F1 lists its keys)"), name.c_str());
    return true;
}

// The replay's keys on the HELP page, a row per action.
void help_lines(pages::View& pv) {
    pv.help.clear();
    for (size_t i = 0; i < std::size(kReplayKeys); ++i) {
        if (!*kReplayKeys[i].help) continue;
        std::string keys = console::key_label(kReplayKeys[i].key);
        for (size_t j = i + 1; j < std::size(kReplayKeys) && !*kReplayKeys[j].help; ++j)
            keys += ", " + console::key_label(kReplayKeys[j].key);
        pv.help.push_back({keys, tr(kReplayKeys[i].help), ""});
    }
    pv.help.push_back({"F1-F7 M-g M-p M-c M-w M-x",
                       tr("look at a page, as in the console; PgUp/PgDn scroll, the GRAPH's keys"),
                       ""});
}

pages::View frame(Viewer& v) {
    console::Session& s = v.s();
    pages::View pv = s.view();
    if (const pages::PageId p = shown(v); p != pv.page) {
        pv.page = p;
        const console::ExerciseRun* x = s.exercise();
        if (p == pages::PageId::graph) s.graph().fill(pv, s.sim(), true, x && !x->graded());
    }
    help_lines(pv);
    pv.replay = true;
    pv.store_path = v.store;
    for (pages::SoftKey& k : pv.softkeys) {
        // TRANSLATORS: soft-key labels of the replay: at most 6 columns (5 on F10).
        if (k.key == "F8") k.label = tr("BACK"), k.current = false;
        if (k.key == "F9") k.label = tr("NEXT"), k.current = false;
        if (k.key == "F10") k.label = tr("END"), k.current = false;
    }
    const size_t total = v.r.steps();
    const console::record::Action* last = nullptr;
    for (size_t i = 0; i < v.r.done(); ++i)
        if (v.r.lines()[i].step()) last = &v.r.lines()[i];
    // TRANSLATORS: the replay's prompt: the actions replayed of all, the student's clock.
    pv.prompt = strf(tr("REPLAY %zu/%zu %.1fs> "), v.pos, total, last ? last->clock : 0.0);
    pv.input = !v.news.empty() ? v.news
               : last          ? console::record::describe(*last)
                      : std::string(tr("the start: Right replays the first action, F1 the keys"));
    pv.input_cursor = 0;
    return pv;
}

int run_viewer(Viewer& v, console::Terminal& term, bool ascii) {
    console::KeyDecoder dec;
    pages::Canvas canvas(term.cols(), term.rows(), ascii);
    std::vector<console::Key> keys;
    bool dirty = true;
    for (;;) {
        if (term.resized()) dirty = true;
        if (dirty) {
            if (canvas.width() != term.cols() || canvas.height() != term.rows())
                canvas.resize(term.cols(), term.rows());
            pages::render_screen(frame(v), canvas);
            term.draw(canvas, 0, canvas.height() - 2);
            dirty = false;
        }
        struct pollfd pfd = {STDIN_FILENO, POLLIN, 0};
        int r = poll(&pfd, 1, dec.pending() ? 25 : 500);
        if (console::Terminal::interrupted()) return kOk;
        keys.clear();
        if (r > 0 && (pfd.revents & (POLLIN | POLLHUP | POLLERR))) {
            char buf[4096];
            ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
            if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) return kOk;
            if (n > 0) dec.feed(std::string_view(buf, size_t(n)), keys);
        } else if (dec.pending()) {
            dec.flush(keys);
        }
        for (const console::Key& k : keys) {
            if (!on_key(v, k)) return kOk;
            dirty = true;
        }
    }
}

// The attempt: its number (as class grade names it), or STUDENT EXERCISE
// (their last attempt at it); and the text of the exercise it was made on.
int find_attempt(store::Store& st, const std::vector<std::string>& words, store::Attempt& a,
                 training::Exercise& e) {
    auto all = st.attempts();
    if (all.error) return report(all.error);
    const std::string what = words.size() == 2 ? words[1] : words[1] + " " + words[2];
    for (const store::Attempt& x : all.value) {
        const bool match = words.size() == 2 ? std::to_string(x.id) == words[1]
                                             : x.student == words[1] && x.exercise == words[2];
        if (match) a = x;  // oldest first: the last one stays
    }
    if (a.id == 0) {
        std::fprintf(stderr,
                     tr("pupitre: no attempt %s (class grade names them by number; or STUDENT "
                        "EXERCISE)\n"),
                     what.c_str());
        return kNoInput;
    }
    auto text = st.exercise_text(a.exercise, a.exercise_sha);
    if (text.error) return report(text.error);
    // On a store file the shipped exercises are not in the store.
    training::Exercise shipped;
    if (!text.value && training::builtin_exercise(a.exercise, shipped) &&
        sha256_hex(shipped.source) == a.exercise_sha)
        text.value = shipped.source;
    std::string why = !text.value ? std::string(tr("the text it was made on is not in the store"))
                                  : training::parse_exercise(*text.value, e);
    if (!why.empty()) {
        std::fprintf(stderr, tr("pupitre: attempt %lld: %s\n"), (long long)a.id, why.c_str());
        return kDataErr;
    }
    return kOk;
}

}  // namespace

int class_replay(const ExerciseArgs& args, store::Store& st) {
    store::Attempt a;
    training::Exercise e;
    if (args.words.size() < 2 || args.words.size() > 3) {
        std::fputs(tr("pupitre: class replay ATTEMPT | STUDENT EXERCISE\n"), stderr);
        return kUsage;
    }
    if (int rc = find_attempt(st, args.words, a, e)) return rc;
    auto opened = console::Replay::open(e, a);
    if (!opened.why.empty()) {
        std::fprintf(stderr, tr("pupitre: attempt %lld: %s\n"), (long long)a.id,
                     opened.why.c_str());
        return kDataErr;
    }
    console::Replay& r = *opened.value;
    if (!r.problem().empty())
        std::fprintf(stderr, tr("pupitre: attempt %lld: its record: %s (replayed up to there)\n"),
                     (long long)a.id, r.problem().c_str());
    r.run_to_end();  // the mistakes the grade names, and from which action
    if (std::string why = r.rewind(1); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: attempt %lld: %s\n"), (long long)a.id, why.c_str());
        return kDataErr;
    }
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
        std::fputs(tr("pupitre: the replay needs a terminal (pupitre class grade replays in "
                      "batch)\n"),
                   stderr);
        return kNoInput;
    }
    console::Theme theme = console::Theme::colour;
    const char* no_color = std::getenv("NO_COLOR");
    const std::string tn = !args.console.theme.empty() ? args.console.theme
                           : no_color && *no_color     ? "mono"
                                                       : "colour";
    if (!console::parse_theme(tn, theme)) {
        std::fprintf(stderr, tr("pupitre: unknown theme '%s' (colour, mono, phosphor)\n"),
                     tn.c_str());
        return kUsage;
    }
    console::Terminal term;
    if (std::string err = term.open(theme); !err.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), err.c_str());
        return kNoInput;
    }
    Viewer v{r};
    v.store = st.path();
    v.news = strf(tr("attempt %lld: %s, %s: read-only; Right replays the first action, F1 the "
                     "keys"),
                  (long long)a.id, a.student.c_str(), a.exercise.c_str());
    int rc = run_viewer(v, term, args.console.ascii || !console::Terminal::utf8_locale());
    term.close();
    return rc;
}

}  // namespace pupitre::cli
