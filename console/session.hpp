// The console's session: the simulated machine, the store, the page shown, the
// input line and the routing of keys, typed lines and commands to the desks.
// No ncurses here, so the tests drive a Session exactly as the terminal does
// (ARCHITECTURE.md).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "console/desk.hpp"
#include "console/edit.hpp"
#include "console/graph.hpp"
#include "console/keymap.hpp"
#include "console/keys.hpp"
#include "console/line_input.hpp"
#include "console/outbox.hpp"
#include "console/part_paper.hpp"
#include "console/part_window.hpp"
#include "console/record.hpp"
#include "console/setting.hpp"
#include "core/sim/sim.hpp"
#include "pages/view.hpp"

namespace pupitre::training {
struct Exercise;
}
namespace pupitre::store {
struct Attempt;
}

namespace pupitre::console {

class ExerciseRun;

// How fast the animation shows the simulated clock.
enum class Speed { real, x10, max };

// The Session routes: the keys (through the bindings, bindings.cpp), the
// input line's target, the ':' commands (commands.cpp) to the desk that owns
// them, the view of each frame, the clock and the message line. The desks
// keep their own state behind their faces: setting (setting.hpp), editing
// (edit.hpp), the exercise run (exercise_run.hpp), the graph window
// (graph.hpp); they reach the Session only as a Bench (desk.hpp).
class Session final : public Bench {
  public:
    // `store` may be null (tests, or a store that cannot be opened): programs
    // then come from `memory` only and nothing is persisted.
    Session(const MachineProfile& m, std::unique_ptr<store::Store> store, LineInput& input);
    ~Session();

    // Loads the store's programs and the machine's correctors and origins.
    // Returns "" or a problem for the message line.
    std::string load_store();
    // Training: an attempt at an exercise on its hidden setup.
    // start_exercise() comes before load_store(): the attempt's correctors
    // and origins live under its own name in the store. "" or what went wrong.
    std::string start_exercise(const training::Exercise& e, const std::string& student,
                               const std::string& key);
    // The teacher's replay of the attempt `a` (replay.hpp): the exercise on
    // the truth drawn from `seed`, graded with the attempt's time and at
    // least its crashes. "" or what went wrong.
    std::string start_replay(const training::Exercise& e, uint64_t seed, const store::Attempt& a);
    // The user's bindings over the shipped ones: "" or "NAME:LINE: problem".
    std::string add_bindings(std::string_view text, std::string_view origin);

    // ---- routing ----
    Effect on_key(const Key& k);
    Effect submit(const std::string& line);         // Enter on the input line
    Effect command(std::string_view text);          // a ':' command, without the ':'
    Effect set_value(std::string_view assignment);  // NAME=VALUE, as :set and --set
    // Where text typed on the input line goes (pupitre(1), COMMANDS): the page when it
    // takes text (editor, PREF, CORR, PARAM), else the mode. The prompt names it.
    enum class Target { edit, pref, corr, param, shop, imd, rns, inc, other };
    Target target() const;
    std::string prompt() const;
    // Completion of the word before the cursor: G/M codes and commands.
    std::vector<std::string> complete(std::string_view word) const;
    // A plausible-but-doubtful setting (or a drop of unsaved work) waits
    // for "y" on the input line: what is asked, "" when nothing.
    const std::string& question() const { return pending_confirm_; }
    void answer(bool yes);  // runs the question's action on yes; either way it ends

    // ---- the desks ----
    SettingDesk& setting() { return setting_; }
    const SettingDesk& setting() const { return setting_; }
    EditDesk& editing() { return editing_; }
    const EditDesk& editing() const { return editing_; }
    const GraphWindow& graph() const { return graph_; }
    ExerciseRun* exercise() { return exercise_.get(); }  // null: no exercise
    const ExerciseRun* exercise() const { return exercise_.get(); }
    // True (and says why) when `what` would show the truth of the exercise
    // in progress.
    bool hidden(const char* what);

    // ---- the clock ----
    // Lets `wall_seconds` of real time pass: the animation advances.
    void tick(double wall_seconds);
    // True while something moves: the event loop then wakes up often.
    bool busy() const;
    // The PART page's picture is being made, or made and not shown yet: the
    // event loop comes back for it soon, and draws the screen again.
    bool picture_pending() const;
    Speed speed() const { return speed_; }
    void set_speed(Speed s) { speed_ = s; }
    Effect cycle_command();  // :cycle, Cycle Start

    // ---- the attempt's record (record.hpp, session_record.cpp) ----
    // One line of a record run as the key, the line or the answer did, or
    // its note taken (a program's text, the selection, the protection).
    Effect replay(const record::Action& a);
    // Lets the simulated clock run up to `clock`, as the frames between two
    // actions did.
    void run_to(double clock);

    // ---- the view ----
    pages::View view() const;
    void resize(int cols, int rows);
    int rows() const { return rows_; }
    // Below 80x24 (pupitre(1), THE CONSOLE) only a resize, :quit and Ctrl-C act.
    bool too_small() const { return cols_ < 80 || rows_ < 24; }
    void scroll_by(int screens);  // the page, by a screen less 8 lines
    // The message line on entering a mode, and the hint the OP page keeps:
    // what Cycle Start does, the jog keys from the bindings, the INC step.
    std::string mode_news(Mode m) const;
    std::string mode_hint(Mode m) const;
    std::string mode_setting(Mode m) const;  // the INC step, the JOG feed
    // The binding a key runs when `page` is shown, null when none: the
    // replay's viewer looks at other pages than the student's this way.
    const Binding* binding_for(const Key& k, pages::PageId page) const;
    // A GRAPH key (graph.hpp) in the window the screen leaves the page.
    Effect graph_key(std::string_view what, std::string_view arg);
    // The PART page (part_window.hpp): a key, the window, what the
    // terminal shows (app.cpp tells it once the terminal is open).
    Effect part_key(std::string_view what, std::string_view arg);
    PartWindow& part() { return part_; }
    const PartWindow& part() const { return part_; }
    void set_screen(const Screen& s) { screen_ = s; }
    const Screen& screen() const { return screen_; }
    // What the part is held against: the exercise's drawing once it is
    // submitted; false when there is none (or not yet).
    bool drawing(render::Drawing& d) const;
    // The title of the part on paper: the program selected, the exercise
    // and the student or the setup.
    PaperTitle paper_title() const;

    // ---- the Bench the desks sit at ----
    Sim& sim() override { return *sim_; }
    const Sim& sim() const override { return *sim_; }
    const MachineProfile& machine() const override { return m_; }
    ProgramMemory& memory() override { return mem_; }
    store::Store* store() const override { return store_.get(); }
    const std::string& store_key() const override { return store_key_; }
    void say(std::string text, bool error = false) override;
    std::string& message() override { return message_; }
    bool message_is_error() const override { return message_error_; }
    pages::PageId page() const override { return page_; }
    void show_page(pages::PageId p) override;
    void confirm(std::string question, std::function<void()> then) override;
    void refresh_dir() override;
    bool unprotected(std::string_view what) override { return setting_.unprotected(what); }
    Stored store_values(const std::vector<std::pair<std::string, int64_t>>& values,
                        std::string_view source) override;
    void keep_submission(const store::Attempt& a, bool on_class) override;

    LineInput& input() { return input_; }
    const LineInput& input() const { return input_; }

    // ---- programs (DIR) ----
    const std::vector<pages::DirEntry>& programs() const { return dir_; }
    int dir_cursor() const { return dir_cursor_; }
    void move_dir_cursor(int delta);
    bool select_program(int number);
    bool delete_program(int number);
    Effect delete_under_cursor();  // DIR's Del asks twice

    // ---- the workshop ----
    // Keeps the workshop (setup and part) of this machine in the store.
    void save_workshop();
    // Reads an instrument on the workshop's part ("dia Z-20"): the reading
    // on the message line and at the head of the WORKSHOP page's list.
    Effect read_part(std::string_view spec);
    std::string no_workshop() const;  // what to type for one
    // The built-in setup to suggest: lathe, mill, mill5, cazeneuve.
    const char* machine_setup() const;

    // ---- leaving ----
    Effect quit_command(bool force);  // :quit asks before dropping unsaved changes
    // :exercise NAME: the console ends and starts again on that exercise
    // (app.cpp), as `pupitre exercise NAME` would.
    Effect restart_on(std::string exercise);
    bool quitting() const { return quit_; }
    const std::string& restart_exercise() const { return restart_exercise_; }
    std::string unsaved_note() const { return editing_.unsaved_note(); }

  private:
    // The key routing through the bindings (bindings.cpp) and the command
    // table (commands.cpp).
    Effect dispatch_key(const Key& k);
    Effect keyed(const std::function<Effect()>& f);  // on_key's guard of the editor
    // The record of an exercise's attempt: a step with the notes before it
    // that changed (session_record.cpp).
    void note_step(record::Action a);
    void note_key(std::string_view action, std::string_view arg);
    void note_line(std::string_view line);
    void note_programs_run(record::Recorder& r);
    void note_program(record::Recorder& r, int number);
    void begin_record();
    Effect run_action(std::string_view name, std::string_view arg);
    bool run_binding(const Key& k, Effect& e);
    Effect small_screen_key(const Key& k);
    void view_keys(pages::View& v) const;
    static bool quits(std::string_view line);
    void complete_command(std::string_view word, std::vector<std::string>& out) const;
    static bool for_line_editor(const Key& k);
    static std::string_view mode_word(Mode m);
    bool answer_key(const Key& k);
    Effect cancel_input();
    Effect plain_text(const std::string& line);
    Effect route_text(const std::string& line);
    void check_run_end();  // the run's news for the message line; its writes stored
    // The store: the machine's state, its workshop, the run's writes, and
    // another console's changes (session_store.cpp).
    std::string load_workshop();
    void persist_run();
    void remember_store();
    void follow_store(double dt);
    void send_outbox();
    void open_outbox();
    void sync_from_store();

    MachineProfile m_;
    std::unique_ptr<store::Store> store_;
    std::string store_key_;  // where the store keeps this console's machine state
    LineInput& input_;
    ProgramMemory mem_;
    GraphWindow graph_{m_};  // its toolpath outlives the Sim that records into it
    PartWindow part_;
    Screen screen_;
    std::unique_ptr<Sim> sim_;
    Keymap bindings_;

    // The desks.
    SettingDesk setting_{*this};
    EditDesk editing_{*this};
    std::unique_ptr<ExerciseRun> exercise_;

    // The screen: the page, its scroll, the DIR cursor.
    pages::PageId page_ = pages::PageId::op;
    int scroll_ = 0;
    int dir_cursor_ = 0;
    int pending_delete_ = -1;  // DIR: Del asks twice
    int rows_ = 24, cols_ = 80;
    Speed speed_ = Speed::real;
    bool quit_ = false;
    std::string restart_exercise_;
    std::vector<pages::DirEntry> dir_;

    // The input line's question.
    std::string pending_confirm_;
    std::function<void()> on_confirm_;
    bool swallow_enter_ = false;  // a key just answered a question

    // The message line.
    std::string message_;
    bool message_error_ = false;
    long refusals_ = 0;                  // error messages said, to tell a refused entry
    std::vector<std::string> said_;      // the message line's, newest first (ALARM page)
    std::vector<std::string> readings_;  // the WORKSHOP page's, newest first

    // The run and the store.
    uint64_t news_seen_ = 0;       // the Sim's workshop news already said
    uint64_t workshop_saved_ = 0;  // the part's generation the store holds
    RunState last_state_ = RunState::idle;
    size_t alarms_seen_ = 0;
    std::map<std::string, int64_t> persisted_;  // program writes already stored
    int64_t data_version_ = -1;                 // PRAGMA data_version last seen
    double poll_wait_ = 0;
    bool store_pending_ = false;             // another console's change waits for the end of a run
    std::vector<pages::DirEntry> dir_seen_;  // the store's programs at the last look
    // Values a server out of reach could not take, in order, until it answers.
    Outbox outbox_;
};

}  // namespace pupitre::console
