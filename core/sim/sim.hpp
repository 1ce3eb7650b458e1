// The simulated machine behind the console: it runs the interpreter block by
// block and animates the moves on a simulated clock (ARCHITECTURE.md, data flow). The
// console decides how many simulated seconds pass per frame; nothing here
// knows the wall clock or the terminal.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/interp/interp.hpp"
#include "core/output/toolpath.hpp"
#include "core/plan/plan_sink.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre {

// The NUM operating modes (the console's mode key). MODIF and EDIT belong to
// the editor.
enum class Mode { automatic, single, dry, test, rns, imd, jog, inc, pom };
std::string_view mode_name(Mode m);                 // "AUTO", "SEQ", "DRY RUN", …
std::string_view mode_english(Mode m);              // "continuous", "single block", …
std::string_view mode_how(Mode m);                  // what the operator does in it
Mode next_mode(Mode m, int dir);                    // the mode key's order (F8: +1, S-F8: -1)
bool parse_mode(std::string_view word, Mode& out);  // auto|seq|dry|test|rns|imd|jog|inc|pom

enum class RunState {
    idle,     // nothing in cycle
    running,  // cycle start given: blocks are executed and animated
    hold,     // feed hold: motion frozen mid-move, cycle start resumes
    block,    // SEQ: a block is done, cycle start runs the next one
    stopped,  // M00 / M01 / G88 wait: cycle start resumes
    ended,    // M02, end of an IMD block, end of a POM or a jog
    alarm,    // an error stopped the run: RAZ acknowledges it
};
std::string_view state_name(RunState state);

struct Alarm {
    Diag diag;
    double clock = 0;  // simulated seconds since power-on
};

// The state of a block as the interpreter left it, carried with its events:
// in a planned run the interpreter works up to the look-ahead beyond the block
// shown, and the pages show the state of the block shown (Sim::modal).
struct ShownState {
    Modal modal;
    Frames frames;
    long blocks = 0;  // the run's blocks done, this one included
};

// A move's planned speed along its path (core/plan: entry, peak, exit and
// duration), as a trapezoid: the speed rises from the entry to the peak,
// holds, and falls to the exit, at the one acceleration that makes its length
// in its time. Speeds in mm/s (degrees/s), times in s.
struct SpeedProfile {
    double v0 = 0, vp = 0, v1 = 0;
    double t1 = 0, t2 = 0, T = 0;  // the ends of the rise and of the cruise; the duration
    double length = 0;
    bool planned = false;
    static SpeedProfile of(const MoveEvent& m);
    double speed(double t) const;     // at t seconds into the move
    double distance(double t) const;  // travelled by t
    double time_at(double d) const;   // when `d` is travelled
};

class Sim final : private MachineSink {
  public:
    Sim(const MachineProfile& m, ProgramMemory& mem);
    ~Sim();

    // The graphic page's toolpath: a program's moves are added as they are
    // shown (AUTO, SEQ, DRY RUN), or as TEST checks them (the graphic test).
    void set_path(Toolpath* p) { path_ = p; }
    Interpreter& interp() { return *in_; }
    const Interpreter& interp() const { return *in_; }
    const MachineProfile& machine() const { return m_; }

    // The workshop (pupitre-setup(5)): with one, the moves the machine makes
    // cut its part, and a contact stops a jog or raises a crash alarm. Null:
    // the machine moves a point, as before.
    void set_workshop(std::unique_ptr<workshop::Workshop> w);
    workshop::Workshop* shop() { return shop_.get(); }
    const workshop::Workshop* shop() const { return shop_.get(); }

    // --- controls ---
    // Each control answers what the operator is refused, as the message to
    // show, or an empty string when it is done (ARCHITECTURE.md, Invariants).
    Mode mode() const { return mode_; }
    // Changing mode is refused while a program is in cycle (as on the panel).
    std::string set_mode(Mode m);
    std::string select(int program);  // the program AUTO/SEQ/DRY/TEST/RNS run
    int selected() const { return selected_; }
    std::string cycle_start();
    void feed_hold();
    void raz();
    // IMD: the block(s) Cycle Start will execute.
    std::string imd(std::string_view blocks);
    // Forgets the IMD block waiting for Cycle Start; false if there was none.
    bool drop_imd() {
        if (!imd_ || in_cycle()) return false;
        imd_.reset();
        invalidate_text_cache();
        return true;
    }
    // RNS: the block searched for; Cycle Start rebuilds the state up to it.
    std::string search(long n);
    long search_target() const { return search_n_; }
    // JOG / INC / :jog: moves one axis by `delta` (mm or degrees; lathe X as
    // the OP page shows it). `continuous` marks a held JOG key.
    std::string jog(int axis, double delta);
    double jog_feed = 0;   // mm/min; 0: the profile's
    double increment = 1;  // INC step, mm

    // --- operator switches ---
    int feed_override = 100;     // %, 0..120, ignored under M49
    int spindle_override = 100;  // %, 50..120, ignored under M49
    bool& block_skip() { return in_->options().block_skip; }
    bool& optional_stop() { return in_->options().optional_stop; }

    // Lets `dt` simulated seconds pass, executing at most `max_blocks`
    // blocks (so a long program in "instant" speed runs over several frames).
    void advance(double dt, long max_blocks = 5000);

    // --- what the pages show ---
    RunState state() const { return state_; }
    bool in_cycle() const {
        return state_ == RunState::running || state_ == RunState::hold ||
               state_ == RunState::block || state_ == RunState::stopped;
    }
    const Axes& om() const { return om_; }   // machine position now (internal units)
    Axes op() const;                         // program position now (internal units)
    Axes to_go() const;                      // remaining of the current move (program units)
    const Loc& loc() const { return loc_; }  // the block being shown
    bool moving() const { return cur_ != nullptr; }
    int motion() const { return cur_ ? cur_->m.g : -1; }
    double feed() const;  // mm/min now, overrides applied (a planned move's speed now)
    double rpm() const;   // spindle rev/min now, override applied
    int spindle_dir() const { return sp_.dir; }
    int spindle_range() const { return sp_.range; }
    bool m7() const { return m7_; }
    bool m8() const { return m8_; }
    int tool() const { return tool_; }
    // The corrector the machine applies: the animated one while a program's
    // moves are shown, else the interpreter's (IMD D3, M02 and RAZ: D0).
    int corrector() const { return in_cycle() && !manual_ ? corr_ : in_->modal().d; }
    double clock() const { return clock_; }
    // Seconds of motion still queued (JOG keeps about 0.1 s ahead).
    double queued_time() const;
    // The cycle time, one for every page and message (the M02 and TEST
    // messages, OP's run line, the GRAPH title): the seconds of the last
    // program run (or IMD block), its moves, dwells and tool changes as the
    // machine took them (as planned, `run`'s time), jogs and POM not
    // counted; TEST: its own planner's.
    double cycle_time() const {
        return mode_ == Mode::test && test_ ? test_plan_->report().seconds : run_seconds_;
    }
    // The last program's time with each move at its feed alone (`run`'s
    // second time), once its M02 is shown; -1 before, or when not planned.
    double feed_time() const { return feed_seconds_; }
    // Each tool's share of the last program (cutting and rapid time, passes,
    // length cut: `run`'s tool lines), once its M02 is shown; empty before.
    const std::vector<plan::ToolRow>& tool_times() const { return tool_times_; }
    // The last Cycle Start ran a program (AUTO, SEQ, DRY RUN, TEST, RNS),
    // whose drawing the GRAPH page shows, not an IMD block.
    bool ran_program() const { return ran_program_; }
    long blocks_done() const {
        return mode_ == Mode::test && test_ ? test_blocks_ : shown() ? shown()->blocks : blocks_;
    }
    const std::vector<Alarm>& alarms() const { return alarms_; }  // history, newest last
    // The warnings of the last run (the first kMaxRunWarnings), and how many.
    const std::vector<Diag>& run_warnings() const { return run_warnings_; }
    size_t run_warning_count() const { return run_warning_count_; }
    static constexpr size_t kMaxRunWarnings = 100;
    bool alarm_active() const { return state_ == RunState::alarm; }
    const std::string& message() const { return message_; }  // $0 text or cycle news
    // Counts the workshop's news (a contact that stopped a jog): the console
    // says them even when the state did not change between two frames.
    uint64_t workshop_news() const { return workshop_news_; }
    long test_blocks() const { return test_blocks_; }
    bool overrides_inhibited() const { return modal().overrides_off; }
    // The functions in force and the frames of the block shown: the
    // interpreter's own, except in a planned run, where it may be up to the
    // look-ahead further on.
    const Modal& modal() const { return shown() ? shown()->modal : in_->modal(); }
    const Frames& frames() const { return shown() ? shown()->frames : in_->frames(); }
    // The planned time of a block of the run (seconds at 100 %), shown or
    // queued to be shown; -1 when not known (not run yet, or long ago).
    double block_time(int prog, int line) const;
    double to_display(int axis, double v) const { return in_->to_display(axis, v); }
    // The program a location is in (the IMD fragment for program 0 of IMD).
    const ProgramText* text_of(int prog) const;
    // The text of line `line` (1-based, file numbering) of a program; "" if
    // there is none. Cached, so following a running program costs little.
    std::string_view line_of(const ProgramText* p, int line) const;
    void invalidate_text_cache() { lc_ = LineCache{}; }  // a program's text changed

  private:
    struct Ev {
        // wait: the axes at rest (the planner's exact stops and spindle);
        // note: a diagnostic of the interpreter's, raised when shown.
        enum Kind { move, dwell, tool, spindle, coolant, stop, message, end, home, wait, note };
        Kind kind = move;
        MoveEvent m;
        SpindleEvent sp;
        Loc loc;
        double seconds = 0;
        int a = 0, b = 0;  // tool t, d / coolant m7, m8 / stop m / end m / home axis
        bool overrides_off = false;
        bool feed_move = false;  // G1/G2/G3 (a feed override applies)
        std::string text;
        std::shared_ptr<const ShownState> shown;  // its block's state (a planned run)
    };
    // Between the interpreter and the planner (sim_plan.cpp): keeps each
    // event's block state, and in a run that is not planned hands the events
    // straight to the queue.
    class Front;
    friend class Front;

    // MachineSink: the interpreter's events join the queue.
    void move(const MoveEvent&) override;
    void dwell(const Loc&, double seconds) override;
    void tool(const Loc&, int t, int d, double seconds, bool m6) override;
    void spindle(const SpindleEvent&) override;
    void coolant(const Loc&, bool m7, bool m8) override;
    void stop(const Loc&, int m) override;
    void message(const Loc&, int channel, std::string_view) override;
    void end(const Loc&, int m) override;
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) override {
        take_tag();
        if (path_ && !searching_) path_->add_stock(l, zr);
    }
    void profile(const Loc&, const ProfileElem&) override { take_tag(); }
    void exact_stop(const Loc&) override { take_tag(); }
    void wait(const Loc& l, double seconds) override;

    // The planned run (sim_plan.cpp). The state of the block shown, when the
    // interpreter may be ahead of it.
    const ShownState* shown() const {
        return shown_ && in_cycle() && !manual_ && mode_ != Mode::test ? shown_.get() : nullptr;
    }
    // The block state the planner's next event out was sent with.
    std::shared_ptr<const ShownState> take_tag();
    bool planner_holds() const { return !tags_.empty(); }
    void plan_reset(bool on);  // a new planner, empty; `on`: the run is planned
    void plan_flush();         // the moves held are planned and queued
    void note_diags();         // the interpreter's new diagnostics, in their place
    void raise(const Diag& d);
    // A message that is a diagnostic's place (note_diags) becomes its note.
    static bool note_of(int channel, std::string_view text, Ev& e);
    void keep_block_time(const Ev& e, double seconds);

    static Ev event(Ev::Kind k, const Loc& l) {
        Ev e;
        e.kind = k;
        e.loc = l;
        return e;
    }
    void push(Ev e, bool tagged = true);  // tagged: the event left the Front
    void new_path(const Axes& start);
    std::string need_program() const;
    std::string start_from_rest();  // cycle_start in idle or ended
    void start_test();
    void start_pom();
    void rns_found(int next_line);
    double fraction() const;  // of the current move's length, travelled at t_
    bool begin_next();        // takes the next event; false if none
    void finish_current();    // the current event is done
    // Parts of begin_next: a move or a homing; M02 or an IMD block's end.
    void begin_move(Ev& e);
    void begin_end(const Ev& e);
    double duration(const Ev& e) const;
    double rate(const Ev& e) const;  // simulated progress per second (overrides)
    void interpolate();              // om_ from the current move and t_
    bool step_interp(long& budget);  // false: nothing more to run now
    void test_advance(long budget);
    void queue_move_to(const Axes& mach, int g, Loc loc, double feed, bool home_axis, int axis);
    void through_workshop(Ev& e);  // a move about to be made meets the part
    Diag workshop_diag(const workshop::Crash& c) const;

    const MachineProfile& m_;
    ProgramMemory& mem_;
    // Before the interpreter, which sends them its events: a Front, its sink,
    // and the planner after it.
    std::unique_ptr<MachineSink> front_;
    std::unique_ptr<MachineSink> make_front();
    std::unique_ptr<plan::PlanSink> plan_;
    std::unique_ptr<Interpreter> in_;
    std::unique_ptr<ProgramMemory> test_mem_;    // TEST's copy of the programs (before test_)
    std::unique_ptr<plan::PlanSink> test_plan_;  // TEST's planner: its cycle time (before test_)
    std::unique_ptr<Interpreter> test_;          // TEST mode: a second interpreter, no motion
    std::unique_ptr<MachineSink> null_;
    bool planning_ = false;  // the program's events go through plan_
    // The block state of each event in the planner, oldest first; the state
    // of the block shown; the block state being built by the interpreter.
    std::deque<std::shared_ptr<const ShownState>> tags_;
    std::shared_ptr<const ShownState> shown_;
    SpeedProfile prof_;      // the current move's (planned), its length shown
    double prof_scale_ = 1;  // the shown length over the profile's (a contact cuts it short)
    Loc alarm_loc_;          // the block an error stopped at
    long step_before_ = 0;   // the interpreter's blocks before the step under way
    // Each block's time as shown (the last kBlockTimes), the current one's so far.
    struct BlockTime {
        Loc loc;
        double seconds = 0;
    };
    static constexpr size_t kBlockTimes = 512;
    std::deque<BlockTime> block_times_;
    Toolpath* path_ = nullptr;
    std::unique_ptr<workshop::Workshop> shop_;
    uint64_t workshop_news_ = 0;

    Mode mode_ = Mode::automatic;
    RunState state_ = RunState::idle;
    int selected_ = -1;
    long search_n_ = -1;
    bool searching_ = false;
    bool interp_done_ = true;     // the interpreter has nothing more to run
    bool pending_alarm_ = false;  // raised once the failing block's moves are shown
    bool manual_ = false;         // the queue holds POM or JOG moves, not a program
    bool seq_stop_ = false;       // SEQ: stop once this block's events are shown
    size_t diag_seen_ = 0;
    std::vector<Diag> run_warnings_;
    size_t run_warning_count_ = 0;
    Axes planned_{};  // machine position at the end of the queue
    std::unique_ptr<ProgramText> imd_;
    std::deque<Ev> q_;
    std::unique_ptr<Ev> cur_;
    double t_ = 0;                // simulated seconds into the current event
    double dur_ = 0;              // its duration at 100 %
    Axes om_{};                   // shown machine position
    Axes op_off0_{}, op_off1_{};  // OM - OP at the start and end of the current move
    Axes op_{};                   // shown program position (after the last finished move)
    Axes op_from_{};              // program position at the start of the current move
    Loc loc_;
    SpindleEvent sp_;
    bool m7_ = false, m8_ = false;
    int tool_ = 0, corr_ = 0;
    double clock_ = 0;
    double run_seconds_ = 0;
    double feed_seconds_ = -1;
    std::vector<plan::ToolRow> tool_times_;  // tool_times()
    bool ran_program_ = false;
    long blocks_ = 0;
    long test_blocks_ = 0;
    std::vector<Alarm> alarms_;
    std::string message_;
    struct LineCache {
        const ProgramText* p = nullptr;
        int line = 0;
        size_t offset = 0;
        uint64_t generation = 0;  // of the program memory (G76+/G76- move lines)
    };
    mutable LineCache lc_;
};

}  // namespace pupitre
