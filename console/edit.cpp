// EDIT and MODIF at the console: opening a program from the store, editing it
// through the input line and the EDIT page keys, saving with a syntax check
// (the cursor on the first block in error, with its NUM number), revisions,
// and MODIF: changing the blocks not yet prepared of an interrupted program,
// which the resumed run then executes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "console/session.hpp"
#include "core/i18n.hpp"
#include "store/store.hpp"

namespace pupitre::console {

Effect Session::edit_open(int number) {
    if (modif) {
        say(strf(tr("MODIF is open on %%%d: Cycle Start or RAZ first"), editor.number), true);
        return Effect::redraw;
    }
    if (editor.is_open() && editor.dirty && editor.number != number) {
        say(strf(tr("%%%d has changes: :save it (or :save! despite errors, :close to drop them)"),
                 editor.number),
            true);
        return Effect::redraw;
    }
    if (editor.is_open() && editor.dirty) {
        // The same program again: loading the stored text would drop the
        // changes (and the next key would write it over their journal).
        show_page(pages::PageId::edit);
        confirm(strf(tr("%%%d has unsaved changes: load the stored text and drop them?"), number),
                [this, number] {
                    editor.dirty = false;
                    drop_journal(number);
                    edit_open(number);
                });
        return Effect::redraw;
    }
    std::string text;
    int rev = 0;
    bool fresh = false;
    if (store_) {
        auto r = store_->read(number);
        if (!r.error && !r.value.info.deleted) {
            text = r.value.text;
            rev = r.value.revision;
        } else {
            fresh = true;
        }
    } else if (const ProgramText* p = mem_.find(number)) {
        text = std::string(*p->text, p->begin, p->end - p->begin);
        text =
            "%" + std::to_string(number) + (p->title.empty() ? "" : " " + p->title) + "\n" + text;
    } else {
        fresh = true;
    }
    if (fresh) text = "%" + std::to_string(number) + "\n";
    editor.open(number, text, rev, fresh);
    journaled_changes_ = editor.changes;
    modify_pending = false;
    show_page(pages::PageId::edit);
    say(fresh
            ? strf(tr("new program %%%d: type its blocks, then :save"), number)
            : strf(
                  tr("%%%d r%d: type a block to insert it after >, Enter modifies the one under >"),
                  number, rev));
    release_lease();
    if (std::string who = other_editor(number); !who.empty())
        say(strf(tr("%%%d is open in another console (%s): the second save will be kept as a "
                    "conflict"),
                 number, who.c_str()),
            true);
    if (store_) take_lease(number);
    offer_journal(number, text);
    return Effect::redraw;
}

Effect Session::edit_text(const std::string& block) {
    if (!editor.is_open()) {
        say(tr("no program open: :edit N"), true);
        return Effect::redraw;
    }
    if (!block.empty() && block[0] == '%') return edit_header(block);
    std::string why = modify_pending ? editor.replace(block) : editor.insert_after(block);
    modify_pending = false;
    if (!why.empty())
        say(why, true);
    else
        say(editor.dirty ? strf(tr("block %d (not saved)"), editor.cursor + 1)
                         : strf(tr("block %d"), editor.cursor + 1));
    return Effect::redraw;
}

// "%500 (TEST)" typed in %500 is its header, as the first line of a file
// would be; another number is another program, opened by :edit.
Effect Session::edit_header(const std::string& line) {
    modify_pending = false;
    long n = std::strtol(line.c_str() + 1, nullptr, 10);
    if (n != editor.number || line.size() < 2 ||
        !std::isdigit(static_cast<unsigned char>(line[1]))) {
        say(strf(tr("this is %%%d: its header is %%%d (TITLE); :edit N opens another"),
                 editor.number, editor.number),
            true);
        return Effect::redraw;
    }
    if (std::string why = editor.set_header(line); !why.empty()) {
        say(why, true);
        return Effect::redraw;
    }
    say(strf(tr("header %s (not saved)"), line.c_str()));
    return Effect::redraw;
}

Effect Session::edit_save(bool force) {
    if (!editor.is_open()) {
        say(tr("no program open: :edit N"), true);
        return Effect::redraw;
    }
    if (modif) {
        say(tr("MODIF: Cycle Start runs and keeps the changes"), true);
        return Effect::redraw;
    }
    if (!unprotected("programs")) return Effect::redraw;
    if (sim_->in_cycle() && sim_->selected() == editor.number) {
        say(strf(tr("%%%d is in cycle: RAZ first, or MODIF to change the blocks to come"),
                 editor.number),
            true);
        return Effect::redraw;
    }
    if (std::optional<Diag> d = editor.check(); d && !force) {
        std::string at =
            strf(tr("line %d"), d->line) + (d->n >= 0 ? " N" + std::to_string(d->n) : "");
        // TRANSLATORS: "line 12 N40: error 107: the detail (not saved; ...)".
        say(strf(tr("%s: error %d: %s (not saved; :save! forces)"), at.c_str(), d->code,
                 d->detail.c_str()),
            true);
        return Effect::redraw;
    }
    std::string text = editor.text();
    if (store_) {
        auto r = store_->save(editor.number, text,
                              editor.revision > 0 ? editor.revision : store::kNew, "page EDIT");
        if (r.error) {
            say(strf(tr("not saved: %s"), r.error.message.c_str()), true);
            return Effect::redraw;
        }
        drop_journal(editor.number);  // the text is in the store (a conflict keeps it too)
        if (r.value.status == store::SaveStatus::conflict) {
            editor.dirty = false;  // the text is safe in the store, as the CONFLICT revision
            say(strf(tr("conflict: r%d by %s came first; yours is kept as r%d (:history %d)"),
                     int(r.value.current), r.value.current_by.c_str(), int(r.value.revision),
                     editor.number),
                true);
            return Effect::redraw;
        }
        editor.revision = r.value.revision;
    }
    if (std::optional<Diag> md =
            mem_.replace(editor.number, "store:%" + std::to_string(editor.number), text)) {
        say(strf(tr("saved, but not loaded: %s"), md->detail.c_str()), true);
        return Effect::redraw;
    }
    sim_->invalidate_text_cache();
    editor.dirty = false;
    drop_journal(editor.number);
    refresh_dir();
    std::string news = store_
                           ? strf(tr("%%%d saved as revision %d"), editor.number, editor.revision)
                           : strf(tr("%%%d saved"), editor.number);
    if (editor.error_line >= 0)
        news += " " + strf(tr("with a syntax error at line %d"), editor.error_line + 1);
    say(news);
    return Effect::redraw;
}

Effect Session::edit_history() {
    if (!editor.is_open() || !store_) {
        say(tr("no stored program open: :edit N"), true);
        return Effect::redraw;
    }
    auto r = store_->history(editor.number);
    if (r.error) {
        say(r.error.message, true);
        return Effect::redraw;
    }
    // The HISTORY page lists them all, newest first (the message line could not).
    history_.clear();
    for (auto it = r.value.rbegin(); it != r.value.rend(); ++it) {
        std::time_t t = std::time_t(it->at_ms / 1000);
        char when[32];
        std::strftime(when, sizeof when, "%Y-%m-%d %H:%M", std::localtime(&t));
        history_.push_back(pages::HistoryRow{it->revision, std::string(store::kind_name(it->kind)),
                                             when, it->who, it->source, it->lines, it->conflict});
    }
    history_number_ = editor.number;
    history_current_ = editor.revision;
    if (auto info = store_->read(editor.number); !info.error)
        history_current_ = info.value.revision;
    show_page(pages::PageId::history);
    say(strf(tr("%zu revision(s) of %%%d: :restore REV makes one current again"), history_.size(),
             editor.number));
    return Effect::redraw;
}

Effect Session::edit_restore(int rev) {
    if (!editor.is_open() || !store_) {
        say(tr("no stored program open: :edit N"), true);
        return Effect::redraw;
    }
    if (!unprotected("programs")) return Effect::redraw;
    if (editor.dirty) {
        confirm(strf(tr("%%%d has unsaved changes: restore revision %d and drop them?"),
                     editor.number, rev),
                [this, rev] {
                    editor.dirty = false;
                    drop_journal(editor.number);
                    edit_restore(rev);
                });
        return Effect::redraw;
    }
    int n = editor.number;
    auto r = store_->restore(n, rev, "page EDIT");
    if (r.error) {
        say(r.error.message, true);
        return Effect::redraw;
    }
    editor.close();
    edit_open(n);
    if (auto p = store_->read(n); !p.error) {
        mem_.replace(n, "store:%" + std::to_string(n), p.value.text);
        sim_->invalidate_text_cache();
    }
    refresh_dir();
    say(strf(tr("%%%d: revision %d is current again (as revision %d)"), n, rev,
             int(r.value.revision)));
    return Effect::redraw;
}

// MODIF (the manual's modification of an interrupted program): the blocks
// the interpreter has not read yet may change; M999 forbids it until M998.
Effect Session::modif_start() {
    RunState st = sim_->state();
    if (st != RunState::hold && st != RunState::block && st != RunState::stopped) {
        say(tr("MODIF needs an interrupted program (feed hold, single block or M00)"), true);
        return Effect::redraw;
    }
    if (sim_->interp().modal().modif_inhibited) {
        say(tr("M999 is in force: MODIF and IMD are forbidden until M998"), true);
        return Effect::redraw;
    }
    if (editor.is_open() && editor.dirty) {
        say(strf(tr("%%%d has unsaved changes: :save or :close them first"), editor.number), true);
        return Effect::redraw;
    }
    if (!unprotected("programs")) return Effect::redraw;
    int next_line = 0;
    sim_->interp().next_label(&next_line);
    const Loc& at = sim_->interp().location();
    const ProgramText* p = sim_->text_of(at.prog);
    if (!p || p->file == "IMD" || next_line <= 0) {
        say(tr("MODIF: nothing left to change in this program"), true);
        return Effect::redraw;
    }
    // The program's own text with its header: lines keep their numbers.
    std::string text = program_text(*p);
    int first_file_line = p->first_line - 1;  // the % line
    editor.open(p->number, text, 0, false);
    editor.revision = 0;
    editor.locked = next_line - first_file_line;
    editor.cursor = std::min(int(editor.lines().size()) - 1, editor.locked);
    modif = true;
    show_page(pages::PageId::edit);
    say(strf(tr("MODIF %%%d: the blocks from line %d on may change; Cycle Start runs them"),
             p->number, editor.locked + 1));
    return Effect::redraw;
}

bool Session::modif_apply() {
    if (!modif) return true;
    modif = false;
    if (!editor.dirty) {
        editor.close();
        return true;
    }
    std::string text = editor.text();
    if (std::optional<Diag> bad = editor.check()) {
        modif = true;
        say(strf(tr("MODIF: line %d: error %d: %s"), bad->line, bad->code, bad->detail.c_str()),
            true);
        return false;
    }
    if (std::optional<Diag> d =
            mem_.replace(editor.number, "store:%" + std::to_string(editor.number), text)) {
        modif = true;
        say("MODIF: " + d->detail, true);
        return false;
    }
    sim_->invalidate_text_cache();
    if (const ProgramText* p = mem_.find(editor.number)) sim_->interp().text_changed(p);
    if (store_) {
        if (auto r = store_->save(editor.number, text, store::kHead, "MODIF"); r.error)
            say(strf(tr("MODIF applied, but not stored: %s"), r.error.message.c_str()), true);
    }
    editor.dirty = false;
    editor.close();
    refresh_dir();
    show_page(pages::PageId::prog);
    return true;
}

}  // namespace pupitre::console
