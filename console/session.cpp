// The console's session (see session.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/session.hpp"

#include <algorithm>
#include <charconv>
#include <utility>

#include "console/commands.hpp"
#include "console/exercise.hpp"
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
      store_key_(m.name),
      store_(std::move(store)),
      input_(input),
      sim_(std::make_unique<Sim>(m_, mem_)) {
    bindings.parse(default_bindings(), "bindings");
    sim_->set_path(&path_);
    graph.plane = m_.lathe ? PathPlane::zx : PathPlane::xy;
    input_.on_line = [this](const std::string& line) { submit(line); };
    input_.complete = [this](std::string_view w) { return complete(w); };
    input_.on_message = [this](const std::string& s) { say(s); };
}

Session::~Session() = default;

std::string Session::load_store() {
    if (!store_) {
        refresh_dir();
        return {};
    }
    std::string problem;
    if (auto r = store::load_programs(*store_, mem_); r.error) problem = r.error.message;
    if (auto r = store::seed_machine(*store_, sim_->interp(), store_key_); r.error)
        problem = r.error.message;
    sim_->interp().origins_changed();
    if (auto r = store_->imd_history(store_key_, 200); !r.error)
        for (auto it = r.value.rbegin(); it != r.value.rend(); ++it) input_.add_history(it->block);
    for (const auto& [name, v] : store::persistent_writes(sim_->interp())) persisted_[name] = v;
    if (auto r = store_->setting("protect.on"); !r.error && r.value) protect = *r.value == "1";
    load_witness();
    if (std::string w = load_workshop(); !w.empty() && problem.empty()) problem = w;
    refresh_dir();
    remember_store();
    if (problem.empty()) problem = recovered_note();
    return problem;
}

// The workshop this machine had when the console last stopped: the same
// setup and the part as the tools left it (pupitre-setup(5)).
std::string Session::load_workshop() {
    if (exercise_) return exercise_workshop();
    auto r = store_->workshop(store_key_);
    if (r.error) return r.error.message;
    if (!r.value) return {};
    workshop::Setup st;
    std::string why = workshop::parse_setup(r.value->setup, st);
    if (why.empty() && (st.kind == "lathe") != m_.lathe)
        why = st.kind == "lathe" ? tr("a lathe's, on a machining centre")
                                 : tr("a machining centre's, on a lathe");
    if (!why.empty())
        return strf(tr("the stored workshop is not a setup (%s): :setup %s loads one"), why.c_str(),
                    machine_setup());
    auto w = std::make_unique<workshop::Workshop>(m_, st, nullptr);
    const bool read = w->load_part(r.value->part);  // else fresh stock, as built
    workshop_saved_ = read ? w->generation() : 0;
    sim_->set_workshop(std::move(w));
    return read ? std::string()
                : std::string(tr(
                      "the stored part could not be read: the workshop starts with fresh stock"));
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
    if (!instrument_allowed(word)) return Effect::redraw;
    note_reading(word, r.value);
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

void Session::save_workshop() {
    const workshop::Workshop* w = sim_->shop();
    if (w) workshop_saved_ = w->generation();
    if (!store_) return;
    // An exercise's: its name, never the setup; the part scrambled.
    store::StoreError e = !w ? store_->put_workshop(store_key_, "", "")
                          : exercise_
                              ? store_->put_workshop(store_key_, "exercise " + exercise_->ex.name,
                                                     scramble(w->part_text(), exercise_->seed))
                              : store_->put_workshop(store_key_, w->setup().source, w->part_text());
    if (e) say(strf(tr("the workshop was not stored: %s"), e.message.c_str()), true);
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
    if (page != p && !pending_confirm.empty()) {
        // The question was about the page left: it is not answered blind.
        pending_confirm.clear();
        on_confirm = nullptr;
        say(tr("question cancelled: the page changed (nothing changed)"));
    }
    if (page != p) scroll = 0;
    // The store may have changed (a save, a conflict, another console).
    if (p == pages::PageId::dir && page != p) refresh_dir();
    page = p;
}

bool Session::select_program(int number) {
    if (std::string why = sim_->select(number); !why.empty()) {
        say(why, true);
        return false;
    }
    for (size_t i = 0; i < dir_.size(); ++i)
        if (dir_[i].number == number) dir_cursor = int(i);
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
    dir_cursor = std::min(dir_cursor, std::max(0, int(dir_.size()) - 1));
    // TRANSLATORS: the program's number, three times.
    say(strf(tr("%%%d deleted; its history stays (:history %d, then :restore %d REV)"), number,
             number, number));
    return true;
}

// ---- keys ----

Effect Session::on_key(const Key& k) {
    Effect e = journal_held() ? held_key(k) : dispatch_key(k);
    sync_journal();  // a change to the program in EDIT is journaled at once
    return e;
}

Effect Session::dispatch_key(const Key& k) {
    if (too_small()) return small_screen_key(k);
    if (std::exchange(swallow_enter_, false) && k.code == KeyCode::enter && input_.text().empty())
        return Effect::redraw;
    if (answer_key(k)) return Effect::redraw;
    std::string pg(pages::page_word(page)), md(mode_word(sim_->mode()));
    if (k.code != KeyCode::del) pending_delete = -1;
    for (const Binding* b : bindings.find(k, pg, md, m_.lathe ? "lathe" : "mill")) {
        const Action* a = find_action(b->action);
        if (!a || !a->can_run(*this, b->arg)) continue;
        return a->run(*this, b->arg);
    }
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
    bool had = !input_.text().empty() || modify_pending || !pending_confirm.empty();
    input_.clear();
    modify_pending = false;
    if (!pending_confirm.empty()) {
        pending_confirm.clear();
        on_confirm = nullptr;
        say(tr("cancelled: nothing changed"));
    } else if (had) {
        say(tr("input cancelled"));
    }
    return Effect::redraw;
}

// ---- the input line ----

Effect Session::submit(const std::string& raw) {
    std::string_view line = trim(raw);
    if (line.empty()) return Effect::none;
    input_.add_history(std::string(line));
    if (too_small() && !quits(line)) {
        say(tr("the terminal is too small: enlarge it, or :quit"), true);
        return Effect::redraw;
    }
    if (line.front() == ':') {
        // A command instead of an answer: the question is dropped, not answered yes.
        pending_confirm.clear();
        on_confirm = nullptr;
        return command(line.substr(1));
    }
    return plain_text(std::string(line));
}

Session::Target Session::target() const {
    switch (page) {
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
    if (!pending_confirm.empty()) return tr("y/n> ");
    switch (target()) {
        // TRANSLATORS: the prompt while a block is modified in EDIT (EDIT and
        // MODIF are NUM names and stay).
        case Target::edit:
            return modify_pending ? tr("MODIFY> ") : modif ? "MODIF> " : "EDIT> ";
        case Target::pref:
            return "PREF> ";
        case Target::corr:
            return "D" + std::to_string(corr_cursor) + "> ";
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
    for (const Binding& b : bindings.list()) {
        if (b.action != "jog") continue;
        auto f = bindings.find(b.key, "op", word, m_.lathe ? "lathe" : "mill");
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
    if (!pending_confirm.empty()) {
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
            return setting_text(t);
        case Target::edit:
            return edit_text(text);
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
        apply_setting(name, v, ":set");
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

// ---- time ----

void Session::tick(double dt) {
    if (sim_->mode() == Mode::test) {
        sim_->advance(dt, 50000);  // no motion to show: as fast as a frame allows
        check_run_end();
        return;
    }
    switch (speed) {
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
    watch_crashes();
    follow_store(dt);
}

bool Session::busy() const {
    return sim_->state() == RunState::running;
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

void Session::persist_run() {
    if (const workshop::Workshop* w = sim_->shop(); w && w->generation() != workshop_saved_)
        save_workshop();
    // The programs G76, G76+ and G76- changed: a revision each, or a deletion.
    std::vector<int> edited = mem_.take_changed();
    if (store_ && !edited.empty() && protect) {
        say(tr("memory protection is on: the programs G76 changed stay in memory, not in the "
               "store"),
            true);
    } else if (store_ && !edited.empty()) {
        std::string source = "G76 in %" + std::to_string(sim_->selected()) + " (console)";
        for (int n : edited) {
            const ProgramText* p = mem_.find(n);
            auto r = p ? store_->save(n, program_text(*p), store::kHead, source)
                       : store_->remove(n, store::kHead, source);
            if (r.error)
                say(strf(tr("%%%d changed by G76 was not stored: %s"), n, r.error.message.c_str()),
                    true);
        }
        refresh_dir();
    }
    if (!store_) return;
    std::vector<std::pair<std::string, int64_t>> fresh;
    for (const auto& [name, v] : store::persistent_writes(sim_->interp())) {
        auto it = persisted_.find(name);
        if (it != persisted_.end() && it->second == v) continue;
        fresh.emplace_back(name, v);
        persisted_[name] = v;
    }
    if (fresh.empty()) return;
    std::string source = "program %" + std::to_string(sim_->selected()) + " (console)";
    if (auto r = store_->set_values(store_key_, fresh, source); r.error)
        say(strf(tr("the program's corrector and origin writes were not stored: %s"),
                 r.error.message.c_str()),
            true);
}

// ---- view ----

// Whether a "page" binding's argument names the page on screen (F2 is OP and
// OM, F3 PROG and GRAPH, F5 the setting pages).
bool Session::shows_page(std::string_view arg, pages::PageId p) {
    using P = pages::PageId;
    if (arg == "pos") return p == P::op || p == P::om;
    if (arg == "prog") return p == P::prog || p == P::graph;
    if (arg == "set") return p == P::param || p == P::pref || p == P::corr;
    return arg == pages::page_word(p);
}

// The soft keys (what F1-F10 do here, from the bindings) and the HELP
// page's lines (every binding, every command).
void Session::view_keys(pages::View& v) const {
    std::string pg(pages::page_word(page)), md(mode_word(sim_->mode()));
    for (int i = 1; i <= 10; ++i) {
        Key k;
        k.code = KeyCode(int(KeyCode::f1) + i - 1);
        for (const Binding* b : bindings.find(k, pg, md, m_.lathe ? "lathe" : "mill")) {
            const Action* a = find_action(b->action);
            if (!a) continue;
            v.softkeys.push_back(pages::SoftKey{"F" + std::to_string(i), soft_label(*a, b->arg),
                                                a->name == "page" && shows_page(b->arg, page)});
            break;
        }
    }
    for (const Binding& b : bindings.list()) {
        const Action* a = find_action(b.action);
        if (a)
            v.help.push_back(
                pages::HelpLine{key_label(b.key_text), help_text(*a, b.arg), context_text(b.when)});
    }
    for (const Command& c : commands())
        if (!c.usage.empty())
            v.help.push_back(pages::HelpLine{std::string(c.usage), pages::tr_text(c.help), ""});
}

void Session::view_editor(pages::View& v) const {
    if (!editor.is_open()) return;
    v.edit_lines = &editor.lines();
    v.edit_number = editor.number;
    v.edit_revision = editor.revision;
    v.edit_cursor = editor.cursor;
    v.edit_mark = editor.mark;
    v.edit_locked = editor.locked;
    v.edit_error = editor.error_line;
    v.edit_dirty = editor.dirty;
    v.edit_modif = modif;
    v.edit_modify = modify_pending;
}

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
    v.page = page;
    v.scroll = scroll;
    v.message = message_;
    v.message_error = message_error_;
    Mode m = sim_->mode();
    v.prompt = prompt();
    v.mode_hint = mode_hint(m);
    v.history = history_;
    v.history_number = history_number_;
    v.history_current = history_current_;
    v.mode_setting = mode_setting(m);
    v.input = input_.text();
    v.input_cursor = input_.cursor();
    v.speed = speed == Speed::real ? "x1" : speed == Speed::x10 ? "x10" : "max";
    v.programs = dir_;
    v.dir_cursor = dir_cursor;
    view_keys(v);
    if (store_) v.store_path = store_->path();
    v.corr_cursor = corr_cursor;
    v.pending = pending_origins();
    v.protect = protect;
    v.undo_depth = undo_.size();
    v.last_setting = last_setting_;
    v.witness = witness_text();
    v.readings = &readings_;
    v.messages = &said_;
    exercise_view(v);
    view_editor(v);
    v.graph = graph;
    v.graph.path = &path_;
    if (sim_->ran_program()) v.graph.seconds = sim_->cycle_time();  // the M02 message's
    if (!graph_plane_chosen && !path_.empty()) v.graph.plane = path_.default_plane();
    tool_now_ = sim_->op();
    // The tool where it is over the part (a C turn, a B tilt), as the path.
    const Axes op_now = tool_now_;
    if (const workshop::Workshop* w = sim_->shop()) tool_now_ = w->on_part(sim_->om(), op_now);
    v.graph.tool = &tool_now_;
    v.graph.cache = &graph_cache_;
    // An exercise: the part drawn, but no coordinates read off it (the truth).
    v.graph.no_readout = exercise_ && !exercise_->grade;
    if (sim_->shop() && page == pages::PageId::graph) {  // only the GRAPH page draws the part
        view_part();
        v.graph.part = &part_now_, v.graph.chuck = &chuck_now_;
        if (const workshop::Workshop* w = sim_->shop(); w->is_mill()) {
            // The block where the program frame puts it, as for the lathe's part.
            const workshop::P3 tip = w->tip3(sim_->om(), false);
            v.graph.block = w->mill();
            v.graph.block_dx = op_now[X] - tip[0];
            v.graph.block_dy = op_now[Y] - tip[1];
        }
    }
    return v;
}

// The workshop's part where the program frame puts it: as the tool in use,
// with the gauge and origins entered, would read its points (so a wrong
// PREF shows as a path beside the part, as on the machine).
void Session::view_part() const {
    part_now_.clear();
    chuck_now_.clear();
    const workshop::Workshop* w = sim_->shop();
    if (!w || w->is_mill()) return;
    const workshop::Workshop::Frame f = w->part_frame(sim_->om(), tool_now_, sim_->corrector());
    const double dz = f.dz, dx = f.dx;
    auto place = [&](const workshop::CPaths& from,
                     std::vector<std::vector<std::array<double, 2>>>& to) {
        for (const workshop::CPath& q : from) {
            to.emplace_back();
            for (const auto& v : q) {
                workshop::Pt p = workshop::to_mm(v);
                to.back().push_back({p[0] + dz, p[1] + dx});
            }
        }
    };
    place(w->world().material(), part_now_);
    place(w->world().chuck(), chuck_now_);
    place(w->world().tailstock(), chuck_now_);
    place(w->world().gauge(), chuck_now_);
}

std::vector<std::string> Session::complete(std::string_view word) const {
    std::vector<std::string> out;
    if (word.empty()) return out;
    char first = char(std::toupper(static_cast<unsigned char>(word[0])));
    if (first == ':') {
        // The first name of each command: not its aliases (:q) nor its '!' forms.
        for (const Command& c : commands()) {
            std::string name = ":" + std::string(c.names.substr(0, c.names.find(' ')));
            if (c.run && name.rfind(word, 0) == 0) out.push_back(name);
        }
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
