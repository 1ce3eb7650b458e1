// EDIT and MODIF at the console: opening a program from the store, editing it
// through the input line and the EDIT page keys, saving with a syntax check
// (the cursor on the first block in error, with its NUM number), revisions,
// and MODIF: changing the blocks not yet prepared of an interrupted program,
// which the resumed run then executes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>
#include <ctime>

#include "console/session.hpp"
#include "store/store.hpp"

namespace pupitre::console {

Effect Session::edit_open(int number) {
    if (modif) {
        say("MODIF is open on %" + std::to_string(editor.number) + ": Cycle Start or RAZ first", true);
        return Effect::redraw;
    }
    if (editor.is_open() && editor.dirty && editor.number != number) {
        say("%" + std::to_string(editor.number) + " has changes: :save it (or :save! despite errors, :close to drop them)", true);
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
        text = "%" + std::to_string(number) + (p->title.empty() ? "" : " " + p->title) + "\n" + text;
    } else {
        fresh = true;
    }
    if (fresh) text = "%" + std::to_string(number) + "\n";
    editor.open(number, text, rev, fresh);
    journaled_changes_ = editor.changes;
    modify_pending = false;
    show_page(pages::PageId::edit);
    say(fresh ? "new program %" + std::to_string(number) + ": type its blocks, then :save"
              : "%" + std::to_string(number) + " r" + std::to_string(rev) +
                    ": type a block to insert it after >, Enter modifies the one under >");
    release_lease();
    if (std::string who = other_editor(number); !who.empty())
        say("%" + std::to_string(number) + " is open in another console (" + who +
                "): the second save will be kept as a conflict",
            true);
    if (store_) take_lease(number);
    offer_journal(number, text);
    return Effect::redraw;
}

Effect Session::edit_text(const std::string& block) {
    if (!editor.is_open()) {
        say("no program open: :edit N", true);
        return Effect::redraw;
    }
    std::string why = modify_pending ? editor.replace(block) : editor.insert_after(block);
    modify_pending = false;
    if (!why.empty()) say(why, true);
    else say(std::string("block ") + std::to_string(editor.cursor + 1) + (editor.dirty ? " (not saved)" : ""));
    return Effect::redraw;
}

Effect Session::edit_save(bool force) {
    if (!editor.is_open()) {
        say("no program open: :edit N", true);
        return Effect::redraw;
    }
    if (modif) {
        say("MODIF: Cycle Start runs and keeps the changes", true);
        return Effect::redraw;
    }
    if (!unprotected("programs")) return Effect::redraw;
    if (sim_->in_cycle() && sim_->selected() == editor.number) {
        say("%" + std::to_string(editor.number) + " is in cycle: RAZ first, or MODIF to change the blocks to come", true);
        return Effect::redraw;
    }
    Diag d;
    if (!editor.check(d) && !force) {
        say("line " + std::to_string(d.line) + (d.n >= 0 ? " N" + std::to_string(d.n) : "") + ": error " +
                std::to_string(d.code) + ": " + d.detail + " (not saved; :save! forces)",
            true);
        return Effect::redraw;
    }
    std::string text = editor.text();
    if (store_) {
        auto r = store_->save(editor.number, text, editor.revision > 0 ? editor.revision : store::kNew, "page EDIT");
        if (r.error) {
            say("not saved: " + r.error.message, true);
            return Effect::redraw;
        }
        drop_journal(editor.number);  // the text is in the store (a conflict keeps it too)
        if (r.value.status == store::SaveStatus::conflict) {
            editor.dirty = false;  // the text is safe in the store, as the CONFLICT revision
            say("conflict: r" + std::to_string(r.value.current) + " by " + r.value.current_by +
                    " came first; yours is kept as r" + std::to_string(r.value.revision) + " (:history " +
                    std::to_string(editor.number) + ")",
                true);
            return Effect::redraw;
        }
        editor.revision = r.value.revision;
    }
    Diag md;
    if (!mem_.replace(editor.number, "store:%" + std::to_string(editor.number), text, md)) {
        say("saved, but not loaded: " + md.detail, true);
        return Effect::redraw;
    }
    sim_->invalidate_text_cache();
    editor.dirty = false;
    drop_journal(editor.number);
    refresh_dir();
    say("%" + std::to_string(editor.number) + " saved" + (store_ ? " as revision " + std::to_string(editor.revision) : "") +
        (editor.error_line >= 0 ? " with a syntax error at line " + std::to_string(editor.error_line + 1) : ""));
    return Effect::redraw;
}

Effect Session::edit_history() {
    if (!editor.is_open() || !store_) {
        say("no stored program open: :edit N", true);
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
        history_.push_back(pages::HistoryRow{it->revision, std::string(store::kind_name(it->kind)), when, it->who,
                                             it->source, it->lines, it->conflict});
    }
    history_number_ = editor.number;
    history_current_ = editor.revision;
    if (auto info = store_->read(editor.number); !info.error) history_current_ = info.value.revision;
    show_page(pages::PageId::history);
    say(std::to_string(history_.size()) + " revision(s) of %" + std::to_string(editor.number) +
        ": :restore REV makes one current again");
    return Effect::redraw;
}

Effect Session::edit_restore(int rev) {
    if (!editor.is_open() || !store_) {
        say("no stored program open: :edit N", true);
        return Effect::redraw;
    }
    if (!unprotected("programs")) return Effect::redraw;
    int n = editor.number;
    auto r = store_->restore(n, rev, "page EDIT");
    if (r.error) {
        say(r.error.message, true);
        return Effect::redraw;
    }
    editor.close();
    edit_open(n);
    if (auto p = store_->read(n); !p.error) {
        Diag d;
        mem_.replace(n, "store:%" + std::to_string(n), p.value.text, d);
        sim_->invalidate_text_cache();
    }
    refresh_dir();
    say("%" + std::to_string(n) + ": revision " + std::to_string(rev) + " is current again (as revision " +
        std::to_string(r.value.revision) + ")");
    return Effect::redraw;
}

// MODIF (the manual's modification of an interrupted program): the blocks
// the interpreter has not read yet may change; M999 forbids it until M998.
Effect Session::modif_start() {
    RunState st = sim_->state();
    if (st != RunState::hold && st != RunState::block && st != RunState::stopped) {
        say("MODIF needs an interrupted program (feed hold, single block or M00)", true);
        return Effect::redraw;
    }
    if (sim_->interp().modal().modif_inhibited) {
        say("M999 is in force: MODIF and IMD are forbidden until M998", true);
        return Effect::redraw;
    }
    if (editor.is_open() && editor.dirty) {
        say("%" + std::to_string(editor.number) + " has unsaved changes: :save or :close them first", true);
        return Effect::redraw;
    }
    if (!unprotected("programs")) return Effect::redraw;
    int next_line = 0;
    sim_->interp().next_label(&next_line);
    const Loc& at = sim_->interp().location();
    const ProgramText* p = sim_->text_of(at.prog);
    if (!p || p->file == "IMD" || next_line <= 0) {
        say("MODIF: nothing left to change in this program", true);
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
    say("MODIF %" + std::to_string(p->number) + ": the blocks from line " + std::to_string(editor.locked + 1) +
        " on may change; Cycle Start runs them");
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
    Diag d;
    if (!editor.check(d)) {
        modif = true;
        say("MODIF: line " + std::to_string(d.line) + ": error " + std::to_string(d.code) + ": " + d.detail, true);
        return false;
    }
    if (!mem_.replace(editor.number, "store:%" + std::to_string(editor.number), text, d)) {
        modif = true;
        say("MODIF: " + d.detail, true);
        return false;
    }
    sim_->invalidate_text_cache();
    if (const ProgramText* p = mem_.find(editor.number)) sim_->interp().text_changed(p);
    if (store_) {
        if (auto r = store_->save(editor.number, text, store::kHead, "MODIF"); r.error)
            say("MODIF applied, but not stored: " + r.error.message, true);
    }
    editor.dirty = false;
    editor.close();
    refresh_dir();
    show_page(pages::PageId::prog);
    return true;
}

}  // namespace pupitre::console
