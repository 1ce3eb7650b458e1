// The editing desk (console/edit.cpp, console/recover.cpp): EDIT and MODIF.
// It holds the editor and the program open in it, MODIF's interrupted
// program, the recovery journal that keeps typed work through a kill, the
// lease that tells another console on the same store who edits a program,
// and the HISTORY page's revisions.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "console/desk.hpp"
#include "console/editor.hpp"
#include "console/line_input.hpp"

namespace pupitre::console {

class EditDesk {
  public:
    explicit EditDesk(Bench& b) : b_(b) {}

    Editor& editor() { return editor_; }
    const Editor& editor() const { return editor_; }
    bool modif() const { return modif_; }  // the editor holds the interrupted program
    // Enter put the current block on the input line: the next line typed replaces it.
    bool modifying() const { return modify_pending_; }
    void stop_modifying() { modify_pending_ = false; }

    Effect open(int number);                // :edit N
    Effect text(const std::string& block);  // a line typed in EDIT
    Effect save(bool force);                // :save, :save!
    // A :save the server could not take, made again when it answers.
    bool save_waiting() const {
        return editor_.is_open() && editor_.number == save_waiting_ && editor_.dirty;
    }
    Effect close(bool force);      // :close asks before dropping unsaved changes
    Effect history();              // :history
    Effect restore(int revision);  // :restore REV
    Effect recover(bool discard);  // :recover, :discard
    Effect modif_start();          // :mode modif
    bool modif_apply();            // Cycle Start after MODIF: the changed text runs; false: refused
    void abandon_modif();          // RAZ: the interrupted program goes with the run

    // The EDIT page's MODIFY key: the block under the cursor to the input line.
    Effect modify_block(LineInput& input);

    // :quit with unsaved work asks first: true when asked (`quit` runs on
    // yes). leave() is the rest of quitting: the lease, the journal of a
    // forced quit.
    bool asks_before_quit(std::function<void()> quit);
    void leave(bool force);

    // Around each key: an earlier session's journal not yet recovered or
    // discarded holds the editor (a change is undone and refused); a change
    // made is journaled at once.
    bool held() const;
    void refuse_changes_since(const Editor& before);
    void sync_journal();

    // Two consoles on one store: the lease of the program open here, kept
    // fresh as time passes; released when the program closes.
    void keep_lease(double dt);
    void release_lease();

    std::string recovered_note() const;  // journals left by an earlier session
    std::string unsaved_note() const;    // where unsaved editor work is, "" if none

    // The EDIT and HISTORY pages' part of a frame.
    void view(pages::View& v) const;

  private:
    Effect header(const std::string& line);  // a % line typed in EDIT
    void take_lease(int number);
    std::string other_editor(int number) const;
    std::string journal_dir() const;
    std::string journal_path(int number) const;
    void drop_journal(int number);
    bool read_journal(int number, std::string& text, int& base) const;
    void offer_journal(int number, const std::string& loaded);

    Bench& b_;
    Editor editor_;
    bool modif_ = false;
    bool modify_pending_ = false;
    int save_waiting_ = -1;           // the program whose :save waits for the server
    uint64_t journaled_changes_ = 0;  // the editor's changes already in the journal
    int journal_held_ = -1;           // an earlier session's journal not yet recovered or discarded
    int leased_ = -1;                 // the program this console's lease names
    double lease_wait_ = 0;
    std::vector<pages::HistoryRow> history_;  // the HISTORY page (:history)
    int history_number_ = -1, history_current_ = 0;
};

}  // namespace pupitre::console
