// Two consoles on one store (issue 12.9): a classroom server, two terminals
// of one operator (docs/decisions.md, Two consoles, one operator). Every half
// second the console asks SQLite whether another connection committed
// (PRAGMA data_version); if so it takes the other console's origins,
// correctors and programs, and says what changed. A program open in EDIT
// holds a lease (the setting "editing.N") that tells another console opening
// it that someone edits it already.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "console/session.hpp"
#include "core/i18n.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

constexpr double kPollSeconds = 0.5;
constexpr double kLeaseRefresh = 10;  // a lease older than 3 refreshes is stale
constexpr int64_t kLeaseStaleMs = 30000;

int64_t now_ms() {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

std::string host() {
    char h[256] = {};
    if (gethostname(h, sizeof h - 1) != 0) return "?";
    return h;
}

std::string lease_key(int number) {
    return "editing." + std::to_string(number);
}

}  // namespace

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
    if (editor.is_open() && !modif && (lease_wait_ -= kPollSeconds) <= 0) take_lease(editor.number);
    auto v = store_->data_version();
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
        if (editor.is_open() && editor.number == e.number && editor.revision != e.revision)
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

// The lease of a program open in EDIT: "user host pid time".
void Session::take_lease(int number) {
    lease_wait_ = kLeaseRefresh;
    std::string mine = store_->user() + " " + host() + " " + std::to_string(getpid()) + " " +
                       std::to_string(now_ms());
    // This connection's own commits leave its data_version as it is: the
    // next poll still sees every other console's commit.
    store_->set_setting(lease_key(number), mine);
    leased_ = number;
}

void Session::release_lease() {
    if (!store_ || leased_ < 0) return;
    store_->set_setting(lease_key(leased_), "");
    leased_ = -1;
}

// Who else edits a program, if anyone: "" when nobody (or a stale lease).
std::string Session::other_editor(int number) const {
    if (!store_) return {};
    auto r = store_->setting(lease_key(number));
    if (r.error || !r.value || r.value->empty()) return {};
    char who[128] = {}, where[256] = {};
    long pid = 0;
    long long at = 0;
    if (std::sscanf(r.value->c_str(), "%127s %255s %ld %lld", who, where, &pid, &at) != 4)
        return {};
    if (where == host() && pid == getpid()) return {};
    if (now_ms() - at > kLeaseStaleMs) return {};
    if (where == host() && kill(pid_t(pid), 0) != 0) return {};  // that console has gone
    return std::string(who) + (where == host() ? "" : "@" + std::string(where));
}

}  // namespace pupitre::console
