// pupitre class watch (issue 34): the teacher's live view of a class. Each
// student's last attempt and how it stands, read from the server in one
// query whenever the server announces a commit (LISTEN/NOTIFY, through
// Store::data_version: no round trip while nothing changes), and once every
// few seconds for what no commit announces (the clock, a student's session
// gone). Up and Down select a student, Enter shows their attempts, Esc goes
// back, q quits.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <map>

#include "console/cli.hpp"
#include "console/exercise.hpp"
#include "console/keys.hpp"
#include "console/term.hpp"
#include "console/wall_clock.hpp"
#include "core/i18n.hpp"
#include "pages/page_watch.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::cli {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kRefresh = std::chrono::seconds(5);  // what no commit announces

std::string hhmm(int64_t ms) {
    return local_time(ms, "%H:%M");
}

std::string ago(int64_t ms) {
    const int64_t s = std::max<int64_t>(0, ms / 1000);
    if (s < 60) return strf(tr("%llds ago"), (long long)s);
    return strf(tr("%lld min ago"), (long long)(s / 60));
}

class Watch {
  public:
    Watch(store::Store& st, std::string group) : st_(st), group_(std::move(group)) {}

    // The class read again; "" or why not.
    std::string refresh() {
        auto r = st_.class_status(group_);
        if (r.error) return r.error.message;
        rows_ = std::move(r.value);
        if (selected_ >= int(rows_.size())) selected_ = std::max(0, int(rows_.size()) - 1);
        return {};
    }

    pages::WatchView view() const {
        pages::WatchView v;
        v.title = group_.empty()
                      ? strf(tr("WATCH every class on %s"), st_.path().c_str())
                      : strf(tr("WATCH class %s on %s"), group_.c_str(), st_.path().c_str());
        v.clock = rows_.empty() ? "" : hhmm(rows_[0].now_ms);
        for (const store::StudentStatus& s : rows_) v.rows.push_back(row(s));
        v.selected = selected_;
        if (detail_) detail(v);
        v.message =
            message_.empty()
                ? std::string(tr("Up/Down a student, Enter their attempts, Esc back, q quit"))
                : message_;
        return v;
    }

    // False: quit.
    bool on_key(const console::Key& k) {
        using console::KeyCode;
        if (k.code == KeyCode::character && (k.ch == 'q' || (k.ctrl && k.ch == 'c'))) return false;
        if (k.code == KeyCode::up && selected_ > 0) --selected_;
        if (k.code == KeyCode::down && selected_ + 1 < int(rows_.size())) ++selected_;
        if (k.code == KeyCode::enter && !rows_.empty()) detail_ = true;
        if (k.code == KeyCode::escape || k.code == KeyCode::backspace) detail_ = false;
        return true;
    }
    void say(std::string m) { message_ = std::move(m); }

  private:
    double minutes_of(const std::string& exercise) const {
        auto it = minutes_.find(exercise);
        if (it != minutes_.end()) return it->second;
        training::Exercise e;
        double m = console::find_exercise(&st_, exercise, e).empty() ? e.minutes : 0;
        minutes_[exercise] = m;
        return m;
    }

    pages::WatchRow row(const store::StudentStatus& s) const {
        pages::WatchRow r;
        r.student = s.login, r.exercise = s.exercise;
        r.crashes = s.crashes, r.scrapped = s.scrapped;
        if (s.last_ms)
            r.last_action =
                (s.last_value ? s.last_name + " " + store::format_value(s.last_name, *s.last_value)
                              : s.last_name) +
                ", " + ago(s.now_ms - s.last_ms);
        if (!s.attempt) {
            r.status = tr("no attempt");
            return r;
        }
        const double allowed = minutes_of(s.exercise);
        const int64_t end = s.submitted_ms ? s.submitted_ms : s.now_ms;
        const double used = double(end - s.started_ms) / 60000;
        r.time = allowed > 0 ? strf("%.0f/%g min", std::floor(used), allowed)
                             : strf("%.0f min", std::floor(used));
        const bool late = allowed > 0 && used > allowed;
        using S = pages::WatchState;
        if (s.submitted_ms && s.graded)
            r.state = S::graded, r.status = strf(tr("graded %d%%"), s.score);
        else if (s.submitted_ms)
            r.state = S::submitted, r.status = tr("submitted");
        else if (!s.connected)
            r.state = S::disconnected, r.status = tr("disconnected");
        else if (late)
            r.state = S::late, r.status = tr("late");
        else
            r.state = S::working, r.status = tr("working");
        if (late && s.submitted_ms) r.status += tr(", late");
        return r;
    }

    void detail(pages::WatchView& v) const {
        const std::string& who = rows_[size_t(selected_)].login;
        v.detail_title = strf(tr("%s's attempts (Esc: the class)"), who.c_str());
        auto all = st_.attempts();
        if (all.error) {
            v.detail.push_back(all.error.message);
            return;
        }
        for (const store::Attempt& a : all.value) {
            if (a.student != who) continue;
            std::string state = !a.submitted_ms       ? tr("in progress")
                                : a.signature.empty() ? tr("submitted")
                                                      : strf(tr("graded %d%%"), a.score);
            v.detail.push_back(strf("%6lld  %-16s %s  %-14s %s %d  %s", (long long)a.id,
                                    a.exercise.c_str(), hhmm(a.started_ms).c_str(), state.c_str(),
                                    tr("crashes"), a.crashes, a.mistakes.c_str()));
        }
        if (v.detail.empty()) v.detail.push_back(tr("no attempt yet"));
    }

    store::Store& st_;
    std::string group_;
    std::vector<store::StudentStatus> rows_;
    mutable std::map<std::string, double> minutes_;
    int selected_ = 0;
    bool detail_ = false;
    std::string message_;
};

// Reads keys for at most `ms`; false when the terminal is gone or q pressed.
bool read_keys(console::KeyDecoder& dec, Watch& w, int ms, bool& dirty) {
    struct pollfd pfd = {STDIN_FILENO, POLLIN, 0};
    int r = poll(&pfd, 1, dec.pending() ? 25 : ms);
    std::vector<console::Key> keys;
    if (r > 0 && (pfd.revents & (POLLIN | POLLHUP | POLLERR))) {
        char buf[256];
        ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
        if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) return false;
        if (n > 0) dec.feed(std::string_view(buf, size_t(n)), keys);
    } else if (dec.pending()) {
        dec.flush(keys);
    }
    for (const console::Key& k : keys) {
        if (!w.on_key(k)) return false;
        dirty = true;
    }
    return true;
}

}  // namespace

int class_watch(const ExerciseArgs& a, store::Store& st) {
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
        std::fputs(tr("pupitre: class watch needs a terminal (pupitre class report for scripts)\n"),
                   stderr);
        return kNoInput;
    }
    Watch w(st, a.group_given ? a.group : "");
    if (std::string why = w.refresh(); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
        return kNoInput;
    }
    const char* no_color = std::getenv("NO_COLOR");
    console::Terminal term;
    if (std::string err =
            term.open(no_color && *no_color ? console::Theme::mono : console::Theme::colour);
        !err.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), err.c_str());
        return kNoInput;
    }
    console::KeyDecoder dec;
    pages::Canvas canvas(term.cols(), term.rows(), !console::Terminal::utf8_locale());
    auto version = st.data_version();
    Clock::time_point last = Clock::now();
    bool dirty = true;
    while (!console::Terminal::interrupted()) {
        if (term.resized()) canvas.resize(term.cols(), term.rows()), dirty = true;
        if (dirty) {
            pages::render_watch(w.view(), canvas);
            term.draw(canvas, 0, canvas.height() - 1);
            dirty = false;
        }
        if (!read_keys(dec, w, 100, dirty)) break;
        // A commit announced (a value set, an attempt opened or submitted),
        // or the clock's turn: the class read again.
        auto now = st.data_version();
        if ((!now.error && !version.error && now.value != version.value) ||
            Clock::now() - last >= kRefresh) {
            version = now;
            last = Clock::now();
            std::string why = w.refresh();
            w.say(why);
            dirty = true;
        }
    }
    term.close();
    return kOk;
}

}  // namespace pupitre::cli
