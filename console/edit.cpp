// The editing desk (see edit.hpp): opening a program from the store, editing it
// through the input line and the EDIT page keys, saving with a syntax check
// (the cursor on the first block in error, with its NUM number), revisions,
// and MODIF: changing the blocks not yet prepared of an interrupted program,
// which the resumed run then executes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/edit.hpp"

#include <unistd.h>

#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "console/wall_clock.hpp"
#include "core/i18n.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

constexpr double kLeaseRefresh = 10;  // a lease older than 3 refreshes is stale
constexpr int64_t kLeaseStaleMs = 30000;

std::string host() {
    char h[256] = {};
    if (gethostname(h, sizeof h - 1) != 0) return "?";
    return h;
}

std::string lease_key(int number) {
    return "editing." + std::to_string(number);
}

}  // namespace

Effect EditDesk::open(int number) {
    if (modif_) {
        b_.say(strf(tr("MODIF is open on %%%d: Cycle Start or RAZ first"), editor_.number), true);
        return Effect::redraw;
    }
    if (editor_.is_open() && editor_.dirty && editor_.number != number) {
        b_.say(
            strf(tr("%%%d has changes: :save it (or :save! despite errors, :close to drop them)"),
                 editor_.number),
            true);
        return Effect::redraw;
    }
    if (editor_.is_open() && editor_.dirty) {
        // The same program again: loading the stored text would drop the
        // changes (and the next key would write it over their journal).
        b_.show_page(pages::PageId::edit);
        b_.confirm(
            strf(tr("%%%d has unsaved changes: load the stored text and drop them?"), number),
            [this, number] {
                editor_.dirty = false;
                drop_journal(number);
                open(number);
            });
        return Effect::redraw;
    }
    std::string text;
    int rev = 0;
    bool fresh = false;
    if (b_.store()) {
        auto r = b_.store()->read(number);
        // A store that cannot be read is no reason to start the program
        // afresh: its stored text would be lost at the next save.
        if (r.error && r.error.fault != store::Fault::not_found) {
            b_.say(strf(tr("cannot open %%%d: %s"), number, r.error.message.c_str()), true);
            return Effect::redraw;
        }
        if (!r.error && !r.value.info.deleted) {
            text = r.value.text;
            rev = r.value.revision;
        } else {
            fresh = true;
        }
    } else if (const ProgramText* p = b_.memory().find(number)) {
        text = std::string(*p->text, p->begin, p->end - p->begin);
        text =
            "%" + std::to_string(number) + (p->title.empty() ? "" : " " + p->title) + "\n" + text;
    } else {
        fresh = true;
    }
    if (fresh) text = "%" + std::to_string(number) + "\n";
    editor_.open(number, text, rev, fresh);
    journaled_changes_ = editor_.changes;
    modify_pending_ = false;
    b_.show_page(pages::PageId::edit);
    b_.say(
        fresh
            ? strf(tr("new program %%%d: type its blocks, then :save"), number)
            : strf(
                  tr("%%%d r%d: type a block to insert it after >, Enter modifies the one under >"),
                  number, rev));
    release_lease();
    if (std::string who = other_editor(number); !who.empty())
        b_.say(strf(tr("%%%d is open in another console (%s): the second save will be kept as a "
                       "conflict"),
                    number, who.c_str()),
               true);
    if (b_.store()) take_lease(number);
    offer_journal(number, text);
    return Effect::redraw;
}

Effect EditDesk::text(const std::string& block) {
    if (!editor_.is_open()) {
        b_.say(tr("no program open: :edit N"), true);
        return Effect::redraw;
    }
    if (!block.empty() && block[0] == '%') return header(block);
    std::string why = modify_pending_ ? editor_.replace(block) : editor_.insert_after(block);
    modify_pending_ = false;
    if (!why.empty())
        b_.say(why, true);
    else
        b_.say(editor_.dirty ? strf(tr("block %d (not saved)"), editor_.cursor + 1)
                             : strf(tr("block %d"), editor_.cursor + 1));
    return Effect::redraw;
}

// "%500 (TEST)" typed in %500 is its header, as the first line of a file
// would be; another number is another program, opened by :edit.
Effect EditDesk::header(const std::string& line) {
    modify_pending_ = false;
    long n = std::strtol(line.c_str() + 1, nullptr, 10);
    if (n != editor_.number || line.size() < 2 ||
        !std::isdigit(static_cast<unsigned char>(line[1]))) {
        b_.say(strf(tr("this is %%%d: its header is %%%d (TITLE); :edit N opens another"),
                    editor_.number, editor_.number),
               true);
        return Effect::redraw;
    }
    if (std::string why = editor_.set_header(line); !why.empty()) {
        b_.say(why, true);
        return Effect::redraw;
    }
    b_.say(strf(tr("header %s (not saved)"), line.c_str()));
    return Effect::redraw;
}

Effect EditDesk::save(bool force) {
    if (!editor_.is_open()) {
        b_.say(tr("no program open: :edit N"), true);
        return Effect::redraw;
    }
    if (modif_) {
        b_.say(tr("MODIF: Cycle Start runs and keeps the changes"), true);
        return Effect::redraw;
    }
    if (!b_.unprotected("programs")) return Effect::redraw;
    if (b_.sim().in_cycle() && b_.sim().selected() == editor_.number) {
        b_.say(strf(tr("%%%d is in cycle: RAZ first, or MODIF to change the blocks to come"),
                    editor_.number),
               true);
        return Effect::redraw;
    }
    if (std::optional<Diag> d = editor_.check(); d && !force) {
        std::string at =
            strf(tr("line %d"), d->line) + (d->n >= 0 ? " N" + std::to_string(d->n) : "");
        // TRANSLATORS: "line 12 N40: error 107: the detail (not saved; ...)".
        b_.say(strf(tr("%s: error %d: %s (not saved; :save! forces)"), at.c_str(), d->code,
                    d->detail.c_str()),
               true);
        return Effect::redraw;
    }
    std::string text = editor_.text();
    if (b_.store()) {
        auto r =
            b_.store()->save(editor_.number, text,
                             editor_.revision > 0 ? editor_.revision : store::kNew, "page EDIT");
        if (r.error) {
            // A server out of reach: the text stays here (and in the journal)
            // and is saved when it answers, over the revision it was based on.
            const bool wait = r.error.gone;
            save_waiting_ = wait ? editor_.number : -1;
            b_.say(
                wait ? tr("not saved yet: the store does not answer; kept here, saved when it does")
                     : strf(tr("not saved: %s"), r.error.message.c_str()),
                true);
            return Effect::redraw;
        }
        save_waiting_ = -1;
        drop_journal(editor_.number);  // the text is in the store (a conflict keeps it too)
        if (r.value.status == store::SaveStatus::conflict) {
            editor_.dirty = false;  // the text is safe in the store, as the CONFLICT revision
            b_.say(strf(tr("conflict: r%d by %s came first; yours is kept as r%d (:history %d)"),
                        int(r.value.current), r.value.current_by.c_str(), int(r.value.revision),
                        editor_.number),
                   true);
            return Effect::redraw;
        }
        editor_.revision = r.value.revision;
    }
    if (std::optional<Diag> md =
            b_.memory().replace(editor_.number, "store:%" + std::to_string(editor_.number), text)) {
        b_.say(strf(tr("saved, but not loaded: %s"), md->detail.c_str()), true);
        return Effect::redraw;
    }
    b_.sim().invalidate_text_cache();
    editor_.dirty = false;
    drop_journal(editor_.number);
    b_.refresh_dir();
    std::string news = b_.store()
                           ? strf(tr("%%%d saved as revision %d"), editor_.number, editor_.revision)
                           : strf(tr("%%%d saved"), editor_.number);
    if (editor_.error_line >= 0)
        news += " " + strf(tr("with a syntax error at line %d"), editor_.error_line + 1);
    b_.say(news);
    return Effect::redraw;
}

Effect EditDesk::history() {
    if (!editor_.is_open() || !b_.store()) {
        b_.say(tr("no stored program open: :edit N"), true);
        return Effect::redraw;
    }
    auto r = b_.store()->history(editor_.number);
    if (r.error) {
        b_.say(r.error.message, true);
        return Effect::redraw;
    }
    // The HISTORY page lists them all, newest first (the message line could not).
    history_.clear();
    for (auto it = r.value.rbegin(); it != r.value.rend(); ++it) {
        history_.push_back(pages::HistoryRow{it->revision, std::string(store::kind_name(it->kind)),
                                             local_time(it->at_ms, "%Y-%m-%d %H:%M"), it->who,
                                             it->source, it->lines, it->conflict});
    }
    history_number_ = editor_.number;
    history_current_ = editor_.revision;
    if (auto info = b_.store()->read(editor_.number); !info.error)
        history_current_ = info.value.revision;
    b_.show_page(pages::PageId::history);
    b_.say(strf(tr("%zu revision(s) of %%%d: :restore REV makes one current again"),
                history_.size(), editor_.number));
    return Effect::redraw;
}

Effect EditDesk::restore(int rev) {
    if (!editor_.is_open() || !b_.store()) {
        b_.say(tr("no stored program open: :edit N"), true);
        return Effect::redraw;
    }
    if (!b_.unprotected("programs")) return Effect::redraw;
    if (editor_.dirty) {
        b_.confirm(strf(tr("%%%d has unsaved changes: restore revision %d and drop them?"),
                        editor_.number, rev),
                   [this, rev] {
                       editor_.dirty = false;
                       drop_journal(editor_.number);
                       restore(rev);
                   });
        return Effect::redraw;
    }
    int n = editor_.number;
    auto r = b_.store()->restore(n, rev, "page EDIT");
    if (r.error) {
        b_.say(r.error.message, true);
        return Effect::redraw;
    }
    editor_.close();
    open(n);
    if (auto p = b_.store()->read(n); !p.error) {
        b_.memory().replace(n, "store:%" + std::to_string(n), p.value.text);
        b_.sim().invalidate_text_cache();
    }
    b_.refresh_dir();
    b_.say(strf(tr("%%%d: revision %d is current again (as revision %d)"), n, rev,
                int(r.value.revision)));
    return Effect::redraw;
}

// MODIF (the manual's modification of an interrupted program): the blocks
// the interpreter has not read yet may change; M999 forbids it until M998.
Effect EditDesk::modif_start() {
    RunState st = b_.sim().state();
    if (st != RunState::hold && st != RunState::block && st != RunState::stopped) {
        b_.say(tr("MODIF needs an interrupted program (feed hold, single block or M00)"), true);
        return Effect::redraw;
    }
    if (b_.sim().interp().modal().modif_inhibited) {
        b_.say(tr("M999 is in force: MODIF and IMD are forbidden until M998"), true);
        return Effect::redraw;
    }
    if (editor_.is_open() && editor_.dirty) {
        b_.say(strf(tr("%%%d has unsaved changes: :save or :close them first"), editor_.number),
               true);
        return Effect::redraw;
    }
    if (!b_.unprotected("programs")) return Effect::redraw;
    int next_line = 0;
    b_.sim().interp().next_label(&next_line);
    const Loc& at = b_.sim().interp().location();
    const ProgramText* p = b_.sim().text_of(at.prog);
    if (!p || p->file == "IMD" || next_line <= 0) {
        b_.say(tr("MODIF: nothing left to change in this program"), true);
        return Effect::redraw;
    }
    // The program's own text with its header: lines keep their numbers.
    std::string text = program_text(*p);
    int first_file_line = p->first_line - 1;  // the % line
    editor_.open(p->number, text, 0, false);
    editor_.revision = 0;
    editor_.locked = next_line - first_file_line;
    editor_.cursor = std::min(int(editor_.lines().size()) - 1, editor_.locked);
    modif_ = true;
    b_.show_page(pages::PageId::edit);
    b_.say(strf(tr("MODIF %%%d: the blocks from line %d on may change; Cycle Start runs them"),
                p->number, editor_.locked + 1));
    return Effect::redraw;
}

bool EditDesk::modif_apply() {
    if (!modif_) return true;
    modif_ = false;
    if (!editor_.dirty) {
        editor_.close();
        return true;
    }
    std::string text = editor_.text();
    if (std::optional<Diag> bad = editor_.check()) {
        modif_ = true;
        b_.say(strf(tr("MODIF: line %d: error %d: %s"), bad->line, bad->code, bad->detail.c_str()),
               true);
        return false;
    }
    if (std::optional<Diag> d =
            b_.memory().replace(editor_.number, "store:%" + std::to_string(editor_.number), text)) {
        modif_ = true;
        b_.say("MODIF: " + d->detail, true);
        return false;
    }
    b_.sim().invalidate_text_cache();
    if (const ProgramText* p = b_.memory().find(editor_.number)) b_.sim().interp().text_changed(p);
    if (b_.store()) {
        if (auto r = b_.store()->save(editor_.number, text, store::kHead, "MODIF"); r.error)
            b_.say(strf(tr("MODIF applied, but not stored: %s"), r.error.message.c_str()), true);
    }
    editor_.dirty = false;
    editor_.close();
    b_.refresh_dir();
    b_.show_page(pages::PageId::prog);
    return true;
}

// :close asks before dropping unsaved changes, :close! does not.
Effect EditDesk::close(bool force) {
    auto usage = [this](const char* u) {
        b_.say(strf(tr("usage: %s"), u), true);
        return Effect::redraw;
    };
    if (modif_) return usage(tr(":close is for EDIT; MODIF ends with Cycle Start or RAZ"));
    if (!editor_.is_open()) return usage(tr(":edit N first"));
    int n = editor_.number;
    auto close = [this, n] {
        bool dirty = editor_.dirty;
        editor_.close();
        if (dirty) drop_journal(n);  // its own; an earlier session's stays for :recover
        release_lease();
        b_.say(dirty ? tr("editor closed (unsaved changes dropped)") : tr("editor closed"));
    };
    if (editor_.dirty && !force) {
        b_.confirm(strf(tr("%%%d has unsaved changes: close and drop them?"), n), close);
        return Effect::redraw;
    }
    close();
    return Effect::redraw;
}

void EditDesk::abandon_modif() {
    if (!modif_) return;
    modif_ = false;
    editor_.close();
    b_.show_page(pages::PageId::prog);
}

Effect EditDesk::modify_block(LineInput& input) {
    if (editor_.cursor < editor_.locked) {
        b_.say(tr("this block is already prepared"), true);
        return Effect::redraw;
    }
    input.set_text(editor_.lines()[size_t(editor_.cursor)]);
    modify_pending_ = true;
    b_.say(tr("modify the block, Enter replaces it"));
    return Effect::redraw;
}

void EditDesk::view(pages::View& v) const {
    v.history = history_;
    v.history_number = history_number_;
    v.history_current = history_current_;
    if (!editor_.is_open()) return;
    v.edit_lines = &editor_.lines();
    v.edit_number = editor_.number;
    v.edit_revision = editor_.revision;
    v.edit_cursor = editor_.cursor;
    v.edit_mark = editor_.mark;
    v.edit_locked = editor_.locked;
    v.edit_error = editor_.error_line;
    v.edit_dirty = editor_.dirty;
    v.edit_modif = modif_;
    v.edit_modify = modify_pending_;
}

// ---- two consoles on one store (console/session_store.cpp) ----

// A program open in EDIT holds a lease (the setting "editing.N") that tells
// another console opening it that someone edits it already; the Session's
// clock keeps it fresh.
void EditDesk::keep_lease(double dt) {
    if (editor_.is_open() && !modif_ && (lease_wait_ -= dt) <= 0) take_lease(editor_.number);
}

// The lease of a program open in EDIT: "user host pid time".
void EditDesk::take_lease(int number) {
    lease_wait_ = kLeaseRefresh;
    std::string mine = b_.store()->user() + " " + host() + " " + std::to_string(getpid()) + " " +
                       std::to_string(wall_ms());
    // This connection's own commits leave its data_version as it is: the
    // next poll still sees every other console's commit.
    b_.store()->set_setting(lease_key(number), mine);
    leased_ = number;
}

void EditDesk::release_lease() {
    if (!b_.store() || leased_ < 0) return;
    b_.store()->set_setting(lease_key(leased_), "");
    leased_ = -1;
}

// Who else edits a program, if anyone: "" when nobody (or a stale lease).
std::string EditDesk::other_editor(int number) const {
    if (!b_.store()) return {};
    auto r = b_.store()->setting(lease_key(number));
    if (r.error || !r.value || r.value->empty()) return {};
    char who[128] = {}, where[256] = {};
    long pid = 0;
    long long at = 0;
    if (std::sscanf(r.value->c_str(), "%127s %255s %ld %lld", who, where, &pid, &at) != 4)
        return {};
    if (where == host() && pid == getpid()) return {};
    if (wall_ms() - at > kLeaseStaleMs) return {};
    if (where == host() && kill(pid_t(pid), 0) != 0) return {};  // that console has gone
    return std::string(who) + (where == host() ? "" : "@" + std::string(where));
}

}  // namespace pupitre::console
