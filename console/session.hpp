// The console's session: the simulated machine, the store, the page shown, the
// input line and the key dispatch. No ncurses here, so the tests drive a
// Session exactly as the terminal does (ARCHITECTURE.md).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "console/bindings.hpp"
#include "console/editor.hpp"
#include "console/keys.hpp"
#include "console/line_input.hpp"
#include "core/sim/sim.hpp"
#include "pages/view.hpp"

namespace pupitre::store {
class Store;
}

namespace pupitre::training {
struct Exercise;
}

namespace pupitre::console {

struct ExerciseRun;

// How fast the animation shows the simulated clock.
enum class Speed { real, x10, max };

class Session {
  public:
    // `store` may be null (tests, or a store that cannot be opened): programs
    // then come from `memory` only and nothing is persisted.
    Session(const MachineProfile& m, std::unique_ptr<store::Store> store, LineInput& input);
    ~Session();

    // Loads the store's programs and the machine's correctors and origins.
    // Returns "" or a problem for the message line.
    std::string load_store();
    ProgramMemory& memory() { return mem_; }

    Effect on_key(const Key& k);
    Effect submit(const std::string& line);         // Enter on the input line
    Effect command(std::string_view text);          // a ':' command, without the ':'
    Effect set_value(std::string_view assignment);  // NAME=VALUE, as :set and --set
    // Lets `wall_seconds` of real time pass: the animation advances.
    void tick(double wall_seconds);
    // True while something moves: the event loop then wakes up often.
    bool busy() const;

    pages::View view() const;

    // State the actions and commands change.
    Sim& sim() { return *sim_; }
    // Keeps the workshop (setup and part) of this machine in the store.
    void save_workshop();
    const Sim& sim() const { return *sim_; }
    pages::PageId page = pages::PageId::op;
    int scroll = 0;
    int dir_cursor = 0;
    Speed speed = Speed::real;
    int rows = 24;  // the screen height, for page scrolling
    bool quit = false;
    void say(std::string text, bool error = false);
    void show_page(pages::PageId p);
    bool select_program(int number);
    void refresh_dir();
    bool delete_program(int number);
    Bindings bindings;
    const std::vector<pages::DirEntry>& programs() const { return dir_; }
    const MachineProfile& machine() const { return m_; }
    store::Store* store() { return store_.get(); }
    LineInput& input() { return input_; }
    const LineInput& input() const { return input_; }
    int pending_delete = -1;  // DIR: Del asks twice
    // Settings (console/setting.cpp): origins and correctors from the PREF and
    // CORR pages, touch-off, tool measurement, undo, memory protection.
    // Values in mm as --set names them (X of origins and gauges a radius).
    bool apply_setting(const std::string& name, double value, const std::string& source);
    Effect touch(int axis, double surface);  // asks first with no corrector (D0)
    Effect touch_now(int axis, double surface);
    std::string implausible_gauge(const std::string& name, double value) const;
    void confirm(std::string question, std::function<void()> then);
    void echo_comma(std::string_view typed, double v);
    Effect measure(int d, int axis, double surface);
    // The Cazeneuve's tool setting from a witness cut (console/witness.cpp):
    // :witness DIA [FACE] once, then :tangent X|Z with each tool.
    Effect witness(double dia, double face);  // dia <= 0: forget it; NaN: say it
    Effect tangent(int axis);                 // X or Z
    std::string witness_text() const;         // "" when none
    // Training (console/session_exercise.cpp): an attempt at an exercise on
    // its hidden setup. start_exercise() comes before load_store(): the
    // attempt's correctors and origins live under its own name in the store.
    // "" or what went wrong.
    std::string start_exercise(const training::Exercise& e, const std::string& student,
                               const std::string& key);
    Effect submit_exercise();                        // :submit
    Effect exercise_command(std::string_view args);  // :exercise
    // :exercise NAME: the console ends and starts again on that exercise
    // (app.cpp), as `pupitre exercise NAME` would.
    std::string restart_exercise;
    const ExerciseRun* exercise() const { return exercise_.get(); }
    // True (and says why) when `what` would show the truth of the exercise
    // in progress.
    bool hidden(const char* what);
    void note_shim(double mm);  // a shim or a gauge block placed
    // Reads an instrument on the workshop's part ("dia Z-20"): the reading
    // on the message line and at the head of the WORKSHOP page's list.
    Effect read_part(std::string_view spec);
    std::string no_workshop() const;  // what to type for one
    // The built-in setup to suggest: lathe, mill, mill5, cazeneuve.
    const char* machine_setup() const;
    Effect undo();
    Effect protect_command(std::string_view args);
    bool unprotected(std::string_view what);  // says why when protected
    bool protect = false;
    int corr_cursor = 1;  // the corrector the CORR page edits
    // Origins changed during a run that wait for the next move.
    std::vector<std::string> pending_origins() const;
    size_t undo_depth() const { return undo_.size(); }
    // EDIT and MODIF (console/edit.cpp).
    Editor editor;
    bool modif = false;           // the editor holds the interrupted program
    bool modify_pending = false;  // Enter put the current block on the input line
    Effect edit_open(int number);
    Effect recover_command(bool discard);  // :recover, :discard
    Effect quit_command(bool force);       // :quit asks before dropping unsaved changes
    Effect close_command(bool force);      // :close asks too
    Effect cycle_command();                // :cycle, Cycle Start
    std::string recovered_note() const;    // journals left by an earlier session
    std::string unsaved_note() const;      // where unsaved editor work is, "" if none
    // Two consoles on one store (console/shared.cpp).
    void remember_store();
    void follow_store(double dt);
    void sync_from_store();
    void take_lease(int number);
    void release_lease();
    std::string other_editor(int number) const;
    Effect edit_save(bool force);
    Effect edit_text(const std::string& block);
    Effect edit_header(const std::string& line);  // a % line typed in EDIT
    Effect edit_history();
    Effect edit_restore(int revision);
    Effect modif_start();
    bool modif_apply();  // Cycle Start after MODIF: the changed text runs; false: refused
    // GRAPH (console/graph.cpp): the toolpath of the last run or TEST, and the
    // window the page shows.
    Effect graph_key(std::string_view what, std::string_view arg);
    pages::GraphView graph;
    bool graph_plane_chosen = false;
    int cols = 80;  // the screen width, for the graph's window
    const Toolpath& toolpath() const { return path_; }
    // Completion of the word before the cursor: G/M codes and commands.
    std::vector<std::string> complete(std::string_view word) const;

    // Where text typed on the input line goes (pupitre(1), COMMANDS): the page when it
    // takes text (editor, PREF, CORR, PARAM), else the mode. The prompt names it.
    enum class Target { edit, pref, corr, param, shop, imd, rns, inc, other };
    Target target() const;
    // The message line on entering a mode, and the hint the OP page keeps:
    // what Cycle Start does, the jog keys from the bindings, the INC step.
    std::string mode_news(Mode m) const;
    std::string mode_hint(Mode m) const;
    std::string mode_setting(Mode m) const;  // the INC step, the JOG feed
    std::string prompt() const;
    // A plausible-but-doubtful setting waits for "y" on the input line.
    std::string pending_confirm;  // what is asked; empty: nothing
    std::function<void()> on_confirm;
    void answer(bool yes);  // runs on_confirm on yes; either way the question ends
    // Below 80x24 (pupitre(1), THE CONSOLE) only a resize, :quit and Ctrl-C act.
    bool too_small() const { return cols < 80 || rows < 24; }

  private:
    Effect plain_text(const std::string& line);
    Effect route_text(const std::string& line);
    static bool for_line_editor(const Key& k);
    static bool shows_page(std::string_view arg, pages::PageId p);
    static std::string_view mode_word(Mode m);
    void view_keys(pages::View& v) const;
    void view_editor(pages::View& v) const;
    Effect cancel_input();
    // The editor's recovery journal (console/recover.cpp).
    std::string journal_dir() const;
    std::string journal_path(int number) const;
    void sync_journal();
    void drop_journal(int number);
    bool read_journal(int number, std::string& text, int& base) const;
    void offer_journal(int number, const std::string& loaded);
    Effect dispatch_key(const Key& k);
    bool answer_key(const Key& k);
    bool swallow_enter_ = false;  // a key just answered a question
    Effect small_screen_key(const Key& k);
    static bool quits(std::string_view line);
    Effect held_key(const Key& k);
    bool journal_held() const;
    int journal_held_ = -1;  // an earlier session's journal not yet recovered or discarded
    void persist_run();
    void check_run_end();

    MachineProfile m_;
    Toolpath path_{m_};
    mutable pages::GraphCache graph_cache_;
    mutable Axes tool_now_{};
    uint64_t news_seen_ = 0;       // the Sim's workshop news already said
    uint64_t workshop_saved_ = 0;  // the part's generation the store holds
    std::string load_workshop();
    struct Witness {
        bool set = false;
        double dia = 0, face = 0;  // mm: the diameter read, the face's program Z
    } witness_;
    void load_witness();
    void save_witness();
    std::string store_key_;  // where the store keeps this console's machine state
    std::unique_ptr<ExerciseRun> exercise_;
    std::string exercise_workshop();
    void note_reading(const std::string& word, double value);
    bool instrument_allowed(const std::string& word);
    void watch_crashes();
    void exercise_view(pages::View& v) const;
    Effect start_command(std::string_view name);
    mutable std::vector<std::vector<std::array<double, 2>>>
        part_now_;  // GRAPH: the workshop's part
    mutable std::vector<std::vector<std::array<double, 2>>>
        chuck_now_;  // and its chuck and tailstock
    void view_part() const;
    std::unique_ptr<store::Store> store_;
    LineInput& input_;
    ProgramMemory mem_;
    std::unique_ptr<Sim> sim_;
    std::vector<pages::DirEntry> dir_;
    std::string message_;
    bool message_error_ = false;
    long refusals_ = 0;
    std::string last_setting_;           // the PREF and CORR pages show its arithmetic
    std::vector<std::string> readings_;  // the WORKSHOP page's, newest first
    std::vector<std::string> said_;      // the message line's, newest first (ALARM page)
    uint64_t journaled_changes_ = 0;
    int64_t data_version_ = -1;  // PRAGMA data_version last seen
    double poll_wait_ = 0, lease_wait_ = 0;
    bool store_pending_ = false;              // another console's change waits for the end of a run
    int leased_ = -1;                         // the program this console's lease names
    std::vector<pages::DirEntry> dir_seen_;   // the store's programs at the last look  // the
                                              // editor's changes already in the journal
    std::vector<pages::HistoryRow> history_;  // the HISTORY page (:history)
    int history_number_ = -1, history_current_ = 0;  // error messages said, to tell a refused entry
    RunState last_state_ = RunState::idle;
    size_t alarms_seen_ = 0;
    std::map<std::string, int64_t> persisted_;  // program writes already stored
    struct Undo {
        std::string name;
        double old = 0;
    };
    std::vector<Undo> undo_;
    std::map<std::string, long> pending_origin_;  // name -> interpreter moves when set
    Effect setting_text(std::string_view text);   // typed on the PREF or CORR page
};

}  // namespace pupitre::console
