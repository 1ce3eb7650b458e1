// The console's session (see session.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/session.hpp"

#include <algorithm>
#include <charconv>
#include <utility>

#include "console/exercise_run.hpp"
#include "core/i18n.hpp"
#include "core/parse/codes.hpp"
#include "pages/pages.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool to_long(std::string_view s, long& out) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

Session::Session(const MachineProfile& m, std::unique_ptr<store::Store> store, LineInput& input)
    : m_(m),
      store_(std::move(store)),
      store_key_(m.name),
      input_(input),
      sim_(std::make_unique<Sim>(m_, mem_)) {
    add_bindings(default_bindings(), "bindings");
    sim_->set_path(&graph_.path());
    input_.on_line = [this](const std::string& line) { submit(line); };
    input_.complete = [this](std::string_view w) { return complete(w); };
    input_.on_message = [this](const std::string& s) { say(s); };
}

Session::~Session() {
    if (exercise_) exercise_->keep_record(true);  // the last actions, the :quit
}

// The built-in setup of this machine's kind: its own for the Cazeneuve.
const char* Session::machine_setup() const {
    if (m_.dialect == Dialect::cazeneuve) return "cazeneuve";
    return m_.lathe ? "lathe" : m_.has(C) ? "mill5" : "mill";
}

std::string Session::no_workshop() const {
    return m_.lathe ? strf(tr("no workshop: :setup %s puts a part in the chuck"), machine_setup())
                    : strf(tr("no workshop: :setup %s puts a block on the table"), machine_setup());
}

Effect Session::read_part(std::string_view spec) {
    const workshop::Workshop* w = sim_->shop();
    if (!w) {
        say(no_workshop(), true);
        return Effect::redraw;
    }
    while (!spec.empty() && spec.front() == ' ') spec.remove_prefix(1);
    const std::string asked(spec);
    workshop::Reading r;
    if (std::string why = w->measure(asked, r); !why.empty()) {
        say(strf(tr("%s: %s"), asked.c_str(), why.c_str()), true);
        return Effect::redraw;
    }
    // An exercise allows some instruments only; what is read may explain a
    // mistake (a diameter taken for a radius).
    const std::string word(workshop::instrument_word(asked.substr(0, asked.find(' '))));
    if (exercise_ && !exercise_->instrument_allowed(word)) return Effect::redraw;
    if (exercise_) exercise_->note_reading(word, r.value);
    int decimals = r.resolution < 0.005 ? 3 : 2;
    // TRANSLATORS: the instrument, what it measured, the reading in mm.
    std::string said =
        strf(tr("%s: %s = %.*f mm"), r.instrument.c_str(), asked.c_str(), decimals, r.value);
    // TRANSLATORS: after a presetter's reading: its uncertainty in mm.
    if (r.uncertainty > 0) said += strf(tr(" (\u00b1%.3f)"), r.uncertainty);
    say(said);
    readings_.insert(readings_.begin(), said);
    if (readings_.size() > 100) readings_.pop_back();
    return Effect::redraw;
}

void Session::refresh_dir() {
    dir_.clear();
    if (store_) {
        if (auto r = store_->list(); !r.error) {
            for (const auto& p : r.value) {
                if (p.deleted) continue;
                dir_.push_back(
                    pages::DirEntry{p.number, p.title, int(p.lines), p.revision, p.conflict});
            }
            return;
        }
    }
    for (const auto& p : mem_.programs()) {
        int lines = int(std::count(p->body().begin(), p->body().end(), '\n'));
        dir_.push_back(pages::DirEntry{p->number, p->title, lines, 0});
    }
}

void Session::say(std::string text, bool error) {
    // A server's store is named host/database, not by its whole URI, which
    // would take most of the line from what went wrong.
    if (store_ && store_->short_name() != store_->path())
        for (size_t at = 0; (at = text.find(store_->path(), at)) != std::string::npos;
             at += store_->short_name().size())
            text.replace(at, store_->path().size(), store_->short_name());
    // The ALARM page keeps them in full: the message line cuts a long one.
    if (!text.empty() && (said_.empty() || said_.front() != text)) {
        said_.insert(said_.begin(), text);
        if (said_.size() > 30) said_.pop_back();
    }
    message_ = std::move(text);
    message_error_ = error;
    if (error) ++refusals_;
}

void Session::show_page(pages::PageId p) {
    if (page_ != p && !pending_confirm_.empty()) {
        // The question was about the page left: it is not answered blind.
        pending_confirm_.clear();
        on_confirm_ = nullptr;
        say(tr("question cancelled: the page changed (nothing changed)"));
    }
    if (page_ != p) scroll_ = 0;
    // The store may have changed (a save, a conflict, another console).
    if (p == pages::PageId::dir && page_ != p) refresh_dir();
    page_ = p;
}

void Session::scroll_by(int screens) {
    int step = std::max(1, rows_ - 8);
    scroll_ = std::max(0, scroll_ + screens * step);
}

void Session::move_dir_cursor(int delta) {
    int n = int(dir_.size());
    dir_cursor_ = std::clamp(dir_cursor_ + delta, 0, std::max(0, n - 1));
}

bool Session::select_program(int number) {
    if (std::string why = sim_->select(number); !why.empty()) {
        say(why, true);
        return false;
    }
    for (size_t i = 0; i < dir_.size(); ++i)
        if (dir_[i].number == number) dir_cursor_ = int(i);
    // Kept at once, not at a clean exit: a killed console starts on it again.
    // An exercise selects its own program (app.cpp).
    if (store_ && !exercise_)
        store_->set_setting("console.program." + m_.name, std::to_string(number));
    Mode m = sim_->mode();
    bool runs = m == Mode::automatic || m == Mode::single || m == Mode::dry || m == Mode::test ||
                m == Mode::rns;
    say(runs ? strf(tr("%%%d selected: Cycle Start (F9) runs it in %s"), number,
                    std::string(mode_name(m)).c_str())
             : strf(tr("%%%d selected: F8 to AUTO (or SEQ, DRY RUN, TEST), then Cycle Start (F9)"),
                    number));
    return true;
}

bool Session::delete_program(int number) {
    if (!unprotected("programs")) return false;
    if (!store_) {
        say(tr("no store: programs cannot be deleted"), true);
        return false;
    }
    if (sim_->in_cycle() && sim_->selected() == number) {
        say(strf(tr("%%%d is in cycle: RAZ first"), number), true);
        return false;
    }
    auto r = store_->remove(number, store::kHead, "page DIR");
    if (r.error) {
        say(r.error.message, true);
        return false;
    }
    refresh_dir();
    dir_cursor_ = std::min(dir_cursor_, std::max(0, int(dir_.size()) - 1));
    // TRANSLATORS: the program's number, three times.
    say(strf(tr("%%%d deleted; its history stays (:history %d, then :restore %d REV)"), number,
             number, number));
    return true;
}

Effect Session::delete_under_cursor() {
    if (dir_.empty()) return Effect::none;
    int n = dir_[size_t(dir_cursor_)].number;
    if (pending_delete_ != n) {
        pending_delete_ = n;
        say(strf(tr("delete %%%d? press Del again to confirm"), n), true);
        return Effect::redraw;
    }
    pending_delete_ = -1;
    delete_program(n);
    return Effect::redraw;
}

// ---- keys ----

Effect Session::on_key(const Key& k) {
    return keyed([&] { return dispatch_key(k); });
}

Effect Session::keyed(const std::function<Effect()>& f) {
    Effect e;
    if (editing_.held()) {
        // An earlier session's journal waits: a change to the text is
        // undone and refused (only then is the editor copied, a rare moment).
        const Editor before = editing_.editor();
        e = f();
        editing_.refuse_changes_since(before);
    } else {
        e = f();
    }
    editing_.sync_journal();  // a change to the program in EDIT is journaled at once
    return e;
}

Effect Session::dispatch_key(const Key& k) {
    if (too_small()) return small_screen_key(k);
    if (std::exchange(swallow_enter_, false) && k.code == KeyCode::enter && input_.text().empty())
        return Effect::redraw;
    if (answer_key(k)) return Effect::redraw;
    if (k.code != KeyCode::del) pending_delete_ = -1;
    if (Effect e; run_binding(k, e)) return e;
    if (k.code == KeyCode::escape && !k.alt && !k.ctrl) return cancel_input();
    if (!for_line_editor(k)) {
        // F11, S-F1, C-F5, M-F9…: their bytes would leak into the line as text.
        say(strf(tr("%s does nothing here (F1 lists the keys)"), key_name(k).c_str()));
        return Effect::redraw;
    }
    input_.feed(k.raw);
    return Effect::redraw;
}

// The keys readline edits with; every other unbound key is refused.
bool Session::for_line_editor(const Key& k) {
    switch (k.code) {
        case KeyCode::character:
        case KeyCode::enter:
        case KeyCode::tab:
        case KeyCode::backspace:
            return true;
        case KeyCode::left:
        case KeyCode::right:
            return !k.shift && !k.alt;  // C-Left, C-Right: a word
        case KeyCode::up:
        case KeyCode::down:
        case KeyCode::home:
        case KeyCode::end:
        case KeyCode::del:
            return !k.shift && !k.alt && !k.ctrl;
        default:
            return false;
    }
}

// Escape: the input line is emptied, MODIFY is left, a question is answered no.
Effect Session::cancel_input() {
    note_step({.verb = record::Verb::escape});
    bool had = !input_.text().empty() || editing_.modifying() || !pending_confirm_.empty();
    input_.clear();
    editing_.stop_modifying();
    if (!pending_confirm_.empty()) {
        pending_confirm_.clear();
        on_confirm_ = nullptr;
        say(tr("cancelled: nothing changed"));
    } else if (had) {
        say(tr("input cancelled"));
    }
    return Effect::redraw;
}

// ---- the input line ----

// Asks "y/n" on the input line; `then` runs on "y".
void Session::confirm(std::string question, std::function<void()> then) {
    pending_confirm_ = question;
    on_confirm_ = std::move(then);
    // TRANSLATORS: a question on the message line; y, yes, o and oui answer yes.
    say(strf(tr("%s y/n?"), question.c_str()), true);
}

void Session::answer(bool yes) {
    auto run = std::move(on_confirm_);
    pending_confirm_.clear();
    on_confirm_ = nullptr;
    if (yes && run)
        run();
    else
        say(tr("cancelled: nothing changed"));
}

// One key answers a question (y or o yes, n no), as on the panel; a word
// typed after another first key still answers at Enter (plain_text).
bool Session::answer_key(const Key& k) {
    if (pending_confirm_.empty() || !input_.text().empty() || k.code != KeyCode::character ||
        k.alt || k.ctrl)
        return false;
    const char32_t c = k.ch | 0x20;  // lower case, for the ASCII letters asked
    if (c != U'y' && c != U'o' && c != U'n') return false;
    note_step({.verb = record::Verb::answer, .a = c != U'n'});
    answer(c != U'n');
    swallow_enter_ = true;  // "y" then Enter, by habit: the Enter is not a second action
    return true;
}

Effect Session::submit(const std::string& raw) {
    std::string_view line = trim(raw);
    if (line.empty()) return Effect::none;
    note_line(line);
    input_.add_history(std::string(line));
    if (too_small() && !quits(line)) {
        say(tr("the terminal is too small: enlarge it, or :quit"), true);
        return Effect::redraw;
    }
    if (line.front() == ':') {
        // A command instead of an answer: the question is dropped, not answered yes.
        pending_confirm_.clear();
        on_confirm_ = nullptr;
        return command(line.substr(1));
    }
    return plain_text(std::string(line));
}

Session::Target Session::target() const {
    switch (page_) {
        case pages::PageId::edit:
            return Target::edit;
        case pages::PageId::pref:
            return Target::pref;
        case pages::PageId::corr:
            return Target::corr;
        case pages::PageId::param:
            return Target::param;
        case pages::PageId::shop:
            return Target::shop;
        default:
            break;
    }
    switch (sim_->mode()) {
        case Mode::imd:
            return Target::imd;
        case Mode::rns:
            return Target::rns;
        case Mode::inc:
            return Target::inc;
        default:
            return Target::other;
    }
}

std::string Session::prompt() const {
    // TRANSLATORS: the prompt of a yes/no question: y, yes, o and oui answer yes.
    if (!pending_confirm_.empty()) return tr("y/n> ");
    switch (target()) {
        // TRANSLATORS: the prompt while a block is modified in EDIT (EDIT and
        // MODIF are NUM names and stay).
        case Target::edit:
            return editing_.modifying() ? tr("MODIFY> ") : editing_.modif() ? "MODIF> " : "EDIT> ";
        case Target::pref:
            return "PREF> ";
        case Target::corr:
            return "D" + std::to_string(setting_.corrector()) + "> ";
        case Target::param:
            return "L/E= ";
        // TRANSLATORS: the WORKSHOP page's prompt: what is typed is an instrument's request.
        case Target::shop:
            return tr("MEASURE> ");
        case Target::imd:
            return "IMD> ";
        case Target::rns:
            return "RNS N> ";
        case Target::inc:
            return "INC> ";
        case Target::other:
            break;
    }
    return "> ";
}

std::string Session::mode_hint(Mode m) const {
    bool homed = true;
    for (int a = 0; a < kAxes; ++a) homed = homed && (!m_.has(a) || sim_->interp().homed(a));
    bool runs = m == Mode::automatic || m == Mode::single || m == Mode::dry || m == Mode::rns;
    if (!homed && runs) return tr("home first: F8 to POM, then Cycle Start (F9)");
    switch (sim_->state()) {  // a program in cycle: what the panel's buttons do now
        case RunState::running:
            if (m != Mode::jog && m != Mode::inc && m != Mode::pom)
                return tr("F10 feed hold, F12 (RAZ) abandons the run");
            break;
        case RunState::hold:
            return tr("Cycle Start (F9) resumes, F12 (RAZ) abandons the run");
        case RunState::block:
            return tr("Cycle Start (F9) runs the next block, F12 (RAZ) abandons");
        case RunState::stopped:
            return tr("Cycle Start (F9) goes on, F12 (RAZ) abandons the run");
        case RunState::alarm:
            return tr("F12 (RAZ) acknowledges the alarm (F7: the ALARM page)");
        default:
            break;
    }
    if (m != Mode::jog && m != Mode::inc) return pages::tr_text(mode_how(m));
    // The jog keys as bound for this machine (data/bindings.txt or the user's).
    std::string keys;
    const char* word = m == Mode::jog ? "jog" : "inc";
    for (const Binding& b : bindings_.list()) {
        if (b.action != "jog") continue;
        auto f = bindings_.find(b.key, "op", word, m_.lathe ? "lathe" : "mill");
        if (!f.empty() && f.front() == &b)
            keys += (keys.empty() ? "" : ", ") + b.key_text + " " + b.arg;
    }
    return keys.empty() ? ":jog AXIS DIST" : keys;
}

std::string Session::mode_setting(Mode m) const {
    if (m == Mode::inc)
        return strf(tr("step %s mm (Alt-i: next step)"), pages::fmt_len(sim_->increment).c_str());
    if (m != Mode::jog) return {};
    return strf(tr("feed %.0f mm/min"), sim_->jog_feed > 0 ? sim_->jog_feed : m_.jog_feed);
}

std::string Session::mode_news(Mode m) const {
    // Short enough for 80 columns; the OP page keeps the keys, the status line
    // the next mode.
    return std::string(mode_name(m)) + ": " + pages::tr_text(mode_english(m)) + "; " +
           pages::tr_text(mode_how(m));
}

// Text that is not a command goes where the prompt says (target()): the page
// when it takes text, whatever the mode, else the mode. An entry that is
// refused drops the IMD block waiting for Cycle Start, so that Cycle Start
// never runs an older block than the one the operator believes typed.
Effect Session::plain_text(const std::string& text) {
    if (!pending_confirm_.empty()) {
        std::string a = text;
        for (char& c : a) c = char(std::tolower(static_cast<unsigned char>(c)));
        answer(a == "y" || a == "yes" || a == "o" || a == "oui");
        return Effect::redraw;
    }
    long before = refusals_;
    Effect e = route_text(text);
    if (refusals_ != before && sim_->mode() == Mode::imd && !sim_->in_cycle() && sim_->drop_imd())
        message_ = strf(tr("IMD block dropped: %s"), message_.c_str());
    return e;
}

Effect Session::route_text(const std::string& text) {
    std::string_view t = text;
    switch (target()) {
        case Target::pref:
        case Target::corr:
            return setting_.text(t);
        case Target::edit:
            return editing_.text(text);
        case Target::param:
            if (pages::is_caz(m_)) {
                say(tr("this controller has no L variables and no E parameters"), true);
                return Effect::redraw;
            }
            return set_value(t);
        case Target::shop:
            return read_part(t);
        default:
            break;
    }
    if (sim_->mode() == Mode::imd) {
        if (sim_->interp().modal().modif_inhibited) {
            say(tr("M999 is in force: IMD and MODIF are forbidden until M998"), true);
            return Effect::redraw;
        }
        if (std::string why = sim_->imd(t); !why.empty()) {
            say(why, true);
            return Effect::redraw;
        }
        if (store_) store_->add_imd(store_key_, t);
        say(strf(tr("IMD: Cycle Start (F9) executes: %s"), text.c_str()));
        return Effect::redraw;
    }
    if (t.find('=') != std::string_view::npos) return set_value(t);
    long n;
    if (sim_->mode() == Mode::rns) {
        std::string_view w = t;
        if (!w.empty() && (w.front() == 'N' || w.front() == 'n')) w.remove_prefix(1);
        std::string why;
        if (!to_long(w, n) || !(why = sim_->search(n)).empty())
            say(why.empty() ? std::string(tr("RNS: type a block number, e.g. N120")) : why, true);
        else
            say(sim_->message());
        return Effect::redraw;
    }
    if (sim_->mode() == Mode::inc) return command("inc " + text);  // one rule for the step
    std::string_view w = t;
    if (!w.empty() && w.front() == '%') w.remove_prefix(1);
    if (to_long(w, n) && n >= 0) {
        select_program(int(n));
        return Effect::redraw;
    }
    say(tr("blocks are typed in IMD mode (F8, or :mode imd); commands start with ':' (F1 for "
           "help)"),
        true);
    return Effect::redraw;
}

// NAME=VALUE, the names of --set: the PARAM page and :set.
Effect Session::set_value(std::string_view a) {
    size_t eq = a.find('=');
    std::string name(trim(a.substr(0, eq)));
    double v = 0;
    std::string val(eq == std::string_view::npos ? std::string_view{} : trim(a.substr(eq + 1)));
    if (size_t c = val.find(','); c != std::string::npos && val.find('.') == std::string::npos)
        val[c] = '.';  // L5=2,5: a French decimal comma, as on the setting pages
    auto [p, ec] = std::from_chars(val.data(), val.data() + val.size(), v);
    if (eq == std::string_view::npos || ec != std::errc() || p != val.data() + val.size()) {
        say(tr("set: NAME=VALUE, e.g. L5=2, E80000=18000, PREF.X=-120.5, D1.R=0.8"), true);
        return Effect::redraw;
    }
    for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
    if (name[0] == 'P' || name[0] == 'D') {
        setting_.apply(name, v, ":set");
        return Effect::redraw;
    }
    if (sim_->in_cycle()) {
        say(tr("a program is in cycle: values are set when it is stopped (RAZ)"), true);
        return Effect::redraw;
    }
    std::string why = sim_->interp().set(name, v);
    if (!why.empty()) {
        say(name + ": " + why, true);
        return Effect::redraw;
    }
    sim_->interp().origins_changed();
    say(name + " = " + std::string(val));
    return Effect::redraw;
}

// ---- the desks ----

std::string Session::start_exercise(const training::Exercise& e, const std::string& student,
                                    const std::string& key) {
    auto [x, why] = ExerciseRun::open(*this, e, student, key);
    if (!why.empty()) return why;
    store_key_ = x->machine_key();
    if (std::string w = x->take_program(); !w.empty()) return w;
    exercise_ = std::move(x);
    return {};
}

std::string Session::start_replay(const training::Exercise& e, uint64_t seed,
                                  const store::Attempt& a) {
    auto [x, why] = ExerciseRun::open_replay(*this, e, seed, a);
    if (!why.empty()) return why;
    store_key_ = x->machine_key();
    if (std::string w = x->take_program(); !w.empty()) return w;
    exercise_ = std::move(x);
    return {};
}

bool Session::hidden(const char* what) {
    return exercise_ && exercise_->hidden(what);
}

// Cycle Start, after MODIF's changed blocks are taken in.
Effect Session::cycle_command() {
    if (!editing_.modif_apply()) return Effect::redraw;
    if (std::string why = sim_->cycle_start(); !why.empty()) {
        say(why, true);
        return Effect::redraw;
    }
    // The run's end is news even when it comes within one frame ("max").
    last_state_ = sim_->state();
    Mode m = sim_->mode();
    bool runs_program =
        m == Mode::automatic || m == Mode::single || m == Mode::dry || m == Mode::test;
    if (!sim_->message().empty())
        say(sim_->message());
    else if (sim_->selected() >= 0 && runs_program)
        say(strf(tr("Cycle Start: %%%d in %s"), sim_->selected(),
                 std::string(mode_name(m)).c_str()));
    else
        say(strf(tr("Cycle Start (%s)"), std::string(mode_name(m)).c_str()));
    return Effect::redraw;
}

// :quit, Ctrl-C: unsaved changes in EDIT are dropped only when the operator
// says so (or :quit!).
Effect Session::quit_command(bool force) {
    if (!force && editing_.asks_before_quit([this] { quit_ = true; })) return Effect::redraw;
    editing_.leave(force);
    quit_ = true;
    return Effect::quit;
}

Effect Session::restart_on(std::string exercise) {
    restart_exercise_ = std::move(exercise);
    quit_ = true;
    return Effect::quit;
}

// ---- time ----

void Session::tick(double dt) {
    if (sim_->mode() == Mode::test) {
        sim_->advance(dt, 50000);  // no motion to show: as fast as a frame allows
        check_run_end();
        return;
    }
    switch (speed_) {
        case Speed::real:
            sim_->advance(dt, 2000);
            break;
        case Speed::x10:
            sim_->advance(dt * 10, 5000);
            break;
        case Speed::max:
            sim_->advance(1e9, 20000);
            break;
    }
    check_run_end();
    if (exercise_) {
        exercise_->watch_crashes();
        exercise_->keep_record(false);
    }
    follow_store(dt);
}

bool Session::busy() const {
    return sim_->state() == RunState::running;
}

bool Session::picture_pending() const {
    return page_ == pages::PageId::part && part_.busy();
}

// News of the run for the message line, and the program's writes to the store.
void Session::check_run_end() {
    RunState st = sim_->state();
    if (sim_->alarms().size() > alarms_seen_) {
        alarms_seen_ = sim_->alarms().size();
        const Diag& d = sim_->alarms().back().diag;
        // TRANSLATORS: the message line: ALARM 107 (%300 line 12 N20): the detail.
        say(strf(tr("ALARM %d (%s): %s"), d.code, pages::alarm_place(d).c_str(), d.detail.c_str()),
            true);
    } else if ((st != last_state_ || sim_->workshop_news() != news_seen_) &&
               !sim_->message().empty()) {
        say(sim_->message());
    }
    news_seen_ = sim_->workshop_news();
    if (st != last_state_ &&
        (st == RunState::ended || st == RunState::alarm || st == RunState::idle))
        persist_run();
    last_state_ = st;
}

// ---- view ----

// The word the bindings' contexts name a mode by ("auto", "jog"…).
std::string_view Session::mode_word(Mode m) {
    for (std::string_view w : {"auto", "seq", "dry", "test", "rns", "imd", "jog", "inc", "pom"}) {
        Mode x;
        if (parse_mode(w, x) && x == m) return w;
    }
    return {};
}

pages::View Session::view() const {
    pages::View v;
    v.sim = sim_.get();
    v.memory = &mem_;
    v.machine = m_.name;
    v.page = page_;
    v.scroll = scroll_;
    v.message = message_;
    v.message_error = message_error_;
    Mode m = sim_->mode();
    v.prompt = prompt();
    v.mode_hint = mode_hint(m);
    v.mode_setting = mode_setting(m);
    v.input = input_.text();
    v.input_cursor = input_.cursor();
    v.speed = speed_ == Speed::real ? "x1" : speed_ == Speed::x10 ? "x10" : "max";
    v.programs = dir_;
    v.dir_cursor = dir_cursor_;
    view_keys(v);
    if (store_) v.store_path = store_->path();
    v.readings = &readings_;
    v.messages = &said_;
    setting_.view(v);
    editing_.view(v);
    if (exercise_) exercise_->view(v);
    // An exercise: the part drawn, but no coordinates read off it (the truth).
    graph_.fill(v, *sim_, page_ == pages::PageId::graph, exercise_ && !exercise_->graded());
    if (page_ == pages::PageId::part) {
        // An exercise: the drawing, the scale's numbers and the stick-out after :submit only.
        render::Drawing d;
        const bool has = drawing(d);
        part_.fill(v, *sim_, has ? &d : nullptr, !exercise_ || exercise_->graded(),
                   pages::Rect{0, 1, cols_, rows_ - 4}, screen_);
    }
    return v;
}

bool Session::drawing(render::Drawing& d) const {
    if (!exercise_ || !exercise_->graded()) return false;
    d = exercise_->drawing();
    return !d.dims.empty();
}

PaperTitle Session::paper_title() const {
    PaperTitle t;
    if (const ProgramText* p = sim_->selected() >= 0 ? mem_.find(sim_->selected()) : nullptr)
        t.title = "%" + std::to_string(p->number) + (p->title.empty() ? "" : " " + p->title);
    else
        t.title = tr("the part");
    if (exercise_)
        t.where = strf(tr("exercise %s, %s"), exercise_->exercise().name.c_str(),
                       exercise_->student().c_str());
    else if (const workshop::Workshop* w = sim_->shop())
        t.where = strf(tr("setup %s, machine %s"), w->setup().name.c_str(),
                       pages::machine_word(m_.name).c_str());
    return t;
}

Effect Session::part_key(std::string_view what, std::string_view arg) {
    if (render::Drawing d; what == "paint" && !drawing(d)) {
        say(exercise_
                ? tr("painted by the depth of cut: the drawing's deviations after :submit")
                : tr("painted by the depth of cut: there is no drawing (an exercise has one)"));
        return Effect::redraw;
    }
    const std::string news = part_.key(what, arg, !m_.lathe);
    if (!news.empty()) say(news);
    return Effect::redraw;
}

// A GRAPH key, in the window the screen leaves the GRAPH page.
Effect Session::graph_key(std::string_view what, std::string_view arg) {
    pages::View v;
    graph_.fill(v, *sim_, page_ == pages::PageId::graph, exercise_ && !exercise_->graded());
    std::string news = graph_.key(what, arg, pages::Rect{0, 1, cols_, rows_ - 4}, v.graph);
    if (!news.empty()) say(news);
    return Effect::redraw;
}

std::vector<std::string> Session::complete(std::string_view word) const {
    std::vector<std::string> out;
    if (word.empty()) return out;
    char first = char(std::toupper(static_cast<unsigned char>(word[0])));
    if (first == ':') {
        complete_command(word, out);
        return out;
    }
    std::string up(word);
    for (char& c : up) c = char(std::toupper(static_cast<unsigned char>(c)));
    // The codes' texts are catalogue msgids (codes.cpp marks them N_).
    auto add = [&](std::string code, std::string_view text) {
        if (code.rfind(up, 0) == 0) out.push_back(code + "  " + tr(std::string(text).c_str()));
    };
    if (first == 'G')
        for (const GCode& g : all_g()) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "G%02d", g.number);
            add(buf, g.text);
        }
    if (first == 'M')
        for (const MCode& mc : all_m()) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "M%02d", mc.first);
            add(buf, mc.text);
        }
    return out;
}

}  // namespace pupitre::console
