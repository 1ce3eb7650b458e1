// The Session and its store: the machine's state loaded at the start, the
// workshop and a run's writes kept, and two consoles on one store (issue
// 12.9): a classroom server, two terminals of one operator (docs/decisions.md,
// Two consoles, one operator). Every half second the console asks the store
// whether another connection committed (SQLite's PRAGMA data_version, a
// server's NOTIFY); if so it takes the other console's origins, correctors
// and programs, and says what changed. On a server that does not answer,
// the same poll makes the connection again a step at a time, and the values
// set meanwhile wait in the outbox (outbox.hpp) until it answers. A program open in EDIT holds a
// lease that tells another console opening it that someone edits it already (the editing desk's,
// edit.cpp). SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstdlib>

#include "console/exercise_run.hpp"
#include "console/session.hpp"
#include "core/i18n.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

constexpr double kPollSeconds = 0.5;

}  // namespace

std::string Session::load_store() {
    if (!store_) {
        refresh_dir();
        return {};
    }
    std::string problem;
    if (auto r = store::load_programs(*store_, mem_); r.error) problem = r.error.message;
    if (auto r = store::seed_machine(*store_, sim_->interp(), store_key_); r.error)
        problem = r.error.message;
    open_outbox();
    sim_->interp().origins_changed();
    if (auto r = store_->imd_history(store_key_, 200); !r.error)
        for (auto it = r.value.rbegin(); it != r.value.rend(); ++it) input_.add_history(it->block);
    for (const auto& [name, v] : store::persistent_writes(sim_->interp())) persisted_[name] = v;
    setting_.load();  // the protection key, the witness cut
    if (std::string w = load_workshop(); !w.empty() && problem.empty()) problem = w;
    refresh_dir();
    remember_store();
    begin_record();
    if (problem.empty()) problem = editing_.recovered_note();
    return problem;
}

// The workshop this machine had when the console last stopped: the same
// setup and the part as the tools left it (pupitre-setup(5)).
std::string Session::load_workshop() {
    if (exercise_) {  // the truth drawn again, the part as the store keeps it
        bool fresh = true;
        auto w = exercise_->workshop(fresh);
        workshop_saved_ = fresh ? 0 : w->generation();
        sim_->set_workshop(std::move(w));
        if (fresh) save_workshop();
        return {};
    }
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

void Session::save_workshop() {
    const workshop::Workshop* w = sim_->shop();
    if (w) workshop_saved_ = w->generation();
    if (!store_) return;
    // An exercise's: its name, never the setup; the part scrambled.
    store::StoreError e = !w ? store_->put_workshop(store_key_, "", "")
                          : exercise_
                              ? store_->put_workshop(store_key_, exercise_->stored_setup(),
                                                     exercise_->stored_part(w->part_text()))
                              : store_->put_workshop(store_key_, w->setup().source, w->part_text());
    if (e) say(strf(tr("the workshop was not stored: %s"), e.message.c_str()), true);
}

void Session::persist_run() {
    if (const workshop::Workshop* w = sim_->shop(); w && w->generation() != workshop_saved_)
        save_workshop();
    // The programs G76, G76+ and G76- changed: a revision each, or a deletion.
    std::vector<int> edited = mem_.take_changed();
    if (store_ && !edited.empty() && setting_.locked()) {
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
    if (Stored st = store_values(fresh, source); st.kept)
        say(strf(tr("the program's corrector and origin writes: %s"), st.why.c_str()), true);
    else if (!st.why.empty())
        say(strf(tr("the program's corrector and origin writes were not stored: %s"),
                 st.why.c_str()),
            true);
}

Bench::Stored Session::store_values(const std::vector<std::pair<std::string, int64_t>>& values,
                                    std::string_view source) {
    if (!store_) return {};
    auto r = store_->set_values(store_key_, values, source);
    if (!r.error) return {};
    // A server out of reach: nothing of it was written; kept here in order and
    // sent when it answers again (the same values again are no new change).
    if (!r.error.gone) return {r.error.message, false};
    for (const auto& [name, value] : values) outbox_.add(store_key_, name, value, source);
    return {tr("the store does not answer: kept here, stored when it does"), true};
}

void Session::keep_submission(const store::Attempt& a, bool on_class) {
    outbox_.add_submission(a, on_class);
}

// From follow_store() once the server answers: what it could not take, in
// the order it was set.
void Session::send_outbox() {
    std::vector<std::string> sent = outbox_.send(*store_);
    std::string names;
    for (const std::string& n : sent) names += (names.empty() ? "" : ", ") + n;
    if (!sent.empty())
        say(strf(tr("the store answers again: %d values kept here are stored (%s)"),
                 int(sent.size()), names.c_str()));
}

// At start: what an earlier console on this PC set while the server did not
// answer is this machine's state, and is sent when the server answers.
void Session::open_outbox() {
    if (store_->engine() != "postgresql") return;
    outbox_.open(store_->local_path() + ".outbox");
    Interpreter& in = sim_->interp();
    for (const Outbox::Unsent& u : outbox_.unsent()) {
        if (u.key != store_key_) continue;
        in.set(u.name, std::strtod(store::format_value(u.name, u.value).c_str(), nullptr));
        persisted_[u.name] = u.value;
    }
    in.apply_gauges_now();
}

// ---- two consoles on one store ----

// What this console last saw of the store: values and program revisions.
void Session::remember_store() {
    if (!store_) return;
    if (auto v = store_->data_version(); !v.error) data_version_ = v.value;
    dir_seen_ = dir_;
}

// From tick(): polls the store's data version.
void Session::follow_store(double dt) {
    if (!store_) return;
    poll_wait_ -= dt;
    if (poll_wait_ > 0) return;
    poll_wait_ = kPollSeconds;
    editing_.keep_lease(kPollSeconds);
    auto v = store_->data_version();
    if (!v.error && !outbox_.empty()) send_outbox();
    if (!v.error && editing_.save_waiting()) editing_.save(false);
    if (v.error || (v.value == data_version_ && !store_pending_)) return;
    data_version_ = v.value;
    sync_from_store();
}

// Another console committed: its values and programs become this one's. While
// a program is in cycle the change waits for the end of the run.
void Session::sync_from_store() {
    if (sim_->in_cycle()) {
        store_pending_ = true;
        return;
    }
    store_pending_ = false;
    std::string news;
    if (auto r = store_->values(store_key_); !r.error) {
        Interpreter& in = sim_->interp();
        // A value differs from the machine's: the other console changed it
        // (this one's own writes are already in the machine).
        for (const auto& [name, value] : r.value) {
            std::string shown = store::format_value(name, value);
            double mm = std::strtod(shown.c_str(), nullptr), now = 0;
            // Compared as stored (µm, 0.0001°): a touch-off's PREF holds
            // fractions of a µm the store rounds, which are no other console's.
            if (in.get(name, now) && store::internal_value(name, now) == value) continue;
            if (in.set(name, mm).empty()) news += (news.empty() ? "" : ", ") + name + " " + shown;
        }
        in.apply_gauges_now();
        for (const auto& [name, val] : store::persistent_writes(in)) persisted_[name] = val;
    }
    // Programs whose revision moved since the last look (the DIR page may have
    // listed them already); a text this console has in memory is no news.
    std::vector<pages::DirEntry> before = dir_seen_;
    refresh_dir();
    dir_seen_ = dir_;
    for (const auto& e : dir_) {
        bool same = false;
        for (const auto& b : before)
            same = same || (b.number == e.number && b.revision == e.revision);
        if (same) continue;
        auto p = store_->read(e.number);
        if (p.error) continue;
        const ProgramText* mine = mem_.find(e.number);
        if (mine && program_text(*mine) == p.value.text) continue;
        if (mem_.replace(e.number, "store:%" + std::to_string(e.number), p.value.text)) continue;
        news += (news.empty() ? "%" : ", %") + std::to_string(e.number) + " r" +
                std::to_string(e.revision);
        if (const Editor& ed = editing_.editor();
            ed.is_open() && ed.number == e.number && ed.revision != e.revision)
            news += std::string(" ") + tr("(open here: :save keeps yours as a conflict)");
    }
    for (const auto& b : before) {
        bool still = false;
        for (const auto& e : dir_) still = still || e.number == b.number;
        if (!still && mem_.remove(b.number))
            news += (news.empty() ? "" : ", ") + strf(tr("%%%d deleted"), b.number);
    }
    sim_->invalidate_text_cache();
    if (!news.empty()) say(strf(tr("another console changed: %s"), news.c_str()));
}

}  // namespace pupitre::console
