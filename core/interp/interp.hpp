// The NUM interpreter: executes one block per step() and reports what the
// machine does to an injected MachineSink (ARCHITECTURE.md, Conventions:
// LinuxCNC's canonical functions). The simulated clock lives here; the console
// decides how fast to show it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <bitset>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "core/cycles/pocket46.hpp"
#include "core/cycles/turning.hpp"
#include "core/diag.hpp"
#include "core/geometry/comp.hpp"
#include "core/geometry/frames.hpp"
#include "core/geometry/pgp.hpp"
#include "core/geometry/spline.hpp"
#include "core/interp/machine.hpp"
#include "core/interp/sink.hpp"
#include "core/parse/block.hpp"
#include "core/parse/codes.hpp"
#include "core/parse/eval.hpp"
#include "core/parse/program.hpp"

namespace pupitre {

// One tool corrector (000:813-833, 000:3763-3791; pupitre-iso(5), TOOLS AND
// CORRECTORS). Lathe: X and Z gauges (X a radius), nose radius R, orientation
// C, dynamic DX (a diameter) and DZ. Mill: length L, radius R, end radius @,
// dynamic DL and DR.
struct Corrector {
    double x = 0, z = 0, r = 0, dx = 0, dz = 0;
    int c = 0;
    double l = 0, tip = 0, dl = 0, dr = 0;
};

struct Modal {
    int motion = 1;
    bool incremental = false;
    int plane = 17;
    int radcomp = 40;
    int feed_mode = 94;
    double feed = 1000;    // mm/min (G94), mm/rev (G95), 1/min (G93)
    bool feed_set = true;  // false after G94/G95/G93 changed the unit without F
    int spindle_mode = 97;
    double s = 0;            // rev/min (G97) or m/min (G96)
    bool css_known = false;  // a starting diameter is known for G96
    double css_x0 = 0;       // G96 starting X (radius) at registration
    double css_pos0 = 0;     // program X (radius) when registered
    double smax = 0;         // G92 S limit, 0 = none
    int spindle_dir = 5;     // 3, 4, 5 or 19
    int range = -1;          // 0..5 for M40..M45
    bool inch = false;
    int cycle = 80;
    int tool_axis = Z;  // G16: axis of the tool vector
    bool tool_axis_neg = false;
    int d = 0;  // active corrector
    int t = 0;  // selected tool
    int tool_in_spindle = 0;
    double g92r = 0;
    bool m7 = false, m8 = false;
    bool overrides_off = false;  // M49
    bool clamped = false;        // M10
    long g75 = -1;               // emergency-retract label
    double eg = 100;
    bool modif_inhibited = false;  // M999
    bool radius_x = false;         // E11005 = 0 on a diameter lathe
    long coded_m = -1;             // last modal coded M (M200-M899)
};

struct RunOptions {
    bool block_skip = false;       // operator switch: '/' blocks are skipped
    bool optional_stop = false;    // operator switch: M01 stops
    long max_blocks = 20'000'000;  // endless-loop guard (error 1001)
    // Plain G0-G3 blocks take their own lane (interp_fast.cpp); false sends
    // every block through the general decoding: the differential tests
    // compare the two (tests/unit/test_fast_lane.cpp, tests/fuzz).
    bool fast_lane = true;
    bool require_homing = false;  // the console's machines: moves before POM give 159
    // Tests: sees each G64 as run, its finished profile, stock, tool position,
    // arguments and moves (issue 19: every program's roughing checked against
    // its part, segment by segment).
    std::function<void(const turning::Profile&, const std::vector<comp::V2>&, comp::V2,
                       const turning::G64Args&, const std::vector<turning::Move>&)>
        on_g64;
    // Tests: the same for each G65, G63 and G66 as run (issue 19 item 1).
    std::function<void(const turning::Profile&, comp::V2, const turning::G65Args&,
                       const std::vector<turning::Move>&)>
        on_g65;
    std::function<void(const turning::Profile&, comp::V2, const turning::G63Args&,
                       const std::vector<turning::Move>&)>
        on_g63;
    std::function<void(comp::V2, const turning::G66Args&, const std::vector<turning::Move>&)>
        on_g66;
};

enum class StepResult {
    running,  // a block was executed; call step() again
    stopped,  // M00/M01/M12: waiting for cycle start (call step() to resume)
    ended,    // M02 (or end of a fragment with error 20 reported)
    error,    // an error stopped the run: see diags()
};

class GateSink;

class Interpreter final : private EAccess {
  public:
    Interpreter(const MachineProfile& m, ProgramMemory& mem, MachineSink& sink, RunOptions o = {});
    ~Interpreter();

    // Power-on state: modal defaults, machine at home, origins from the profile.
    void power_on();
    // Settings before a run (pupitre(1), OPTIONS, --set): PREF.X=-120.5,
    // D1.R=4, L5=2, E80000=18000. Returns an empty string or the reason it is
    // refused. `immediate` false (a setting changed while a program is in
    // cycle): an origin takes effect at the next move, not on the position
    // shown now.
    std::string set(std::string_view name, double value, bool immediate = true);
    // The value of a setting as set() names it (mm, X of origins and gauges as
    // radii, DX a diameter); false for an unknown name.
    bool get(std::string_view name, double& out) const;
    // The gauge of the active corrector on an axis, applied or not yet.
    double active_gauge(int axis) const { return gauge_for(modal_.d, axis); }
    bool gauge_pending(int axis) const { return gauge_pending_[size_t(axis)]; }
    // Outside a run, a setting applies at once: the active gauges now, and the
    // program position follows.
    void apply_gauges_now() {
        for (int a = 0; a < kAxes; ++a)
            if (gauge_pending_[size_t(a)]) frames_.gauge[size_t(a)] = gauge_for(modal_.d, a);
        gauge_pending_.reset();
        recompute_program_pos();
    }
    bool comp_active() const { return comp_.on; }
    double comp_radius() const { return comp_.radius; }

    bool start(int program);  // false: no such program (error 25 reported)
    bool start(const ProgramText* p);
    // IMD (manual data input): runs a fragment whose end is not error 20. The
    // modal state and the position carry over from whatever ran before.
    bool start_imd(const ProgramText* p);

    // The operator's controls (console). RAZ: stops any run, modal state as
    // after M02, alarms acknowledged; positions, origins and correctors stay.
    void raz();
    // JOG/INC: moves an axis of the machine by `delta` (internal units) outside
    // any program; answers the NUM error (150-158 travel), empty when done.
    Error jog(int axis, double delta);
    // POM: the axis reaches its home position and is marked homed.
    void home(int axis);
    bool homed(int axis) const { return homed_[size_t(axis)]; }
    bool running() const { return !ended_ && !stack_.empty(); }
    const Loc& location() const { return loc_; }
    std::string_view current_text() const { return cur_text_; }
    RunOptions& options() { return opt_; }
    const RunOptions& options() const { return opt_; }
    Frames& frames_mut() { return frames_; }
    void origins_changed() { recompute_program_pos(); }
    // RAZ in the middle of a move: the machine is where the axes stopped.
    void place(const Axes& mach) {
        mach_ = mach;
        recompute_program_pos();
    }
    // MODIF changed the text of `p` (same object): the frames reading it find
    // their lines again by number.
    void text_changed(const ProgramText* p);
    // The label of the next block to read (RNS), -1 when it has none or the run is over.
    long next_label(int* line = nullptr) const;
    StepResult step();
    // Runs to the end, an error, or a stop (stops are resumed: a dry run goes on).
    StepResult run_to_end();

    // Results.
    const std::vector<Diag>& diags() const { return diags_; }
    bool has_errors() const;
    const Modal& modal() const { return modal_; }
    const Frames& frames() const { return frames_; }
    const Axes& machine_pos() const { return mach_; }
    const Axes& program_pos() const { return prog_; }
    const MachineProfile& machine() const { return m_; }
    const LVars& lvars() const { return l_; }
    const std::map<int, int64_t>& e_written() const { return e_written_; }
    const std::vector<int>& tools_used() const { return tools_used_; }
    long blocks() const { return blocks_; }
    long moves() const { return moves_; }
    // Blocks the plain lane took (interp_fast.cpp): the differential tests
    // check that they exercise it.
    long plain_blocks() const { return plain_blocks_; }
    double path_length() const { return path_; }
    double seconds() const { return clock_; }
    int main_program() const { return main_ ? main_->number : -1; }
    double spindle_rpm() const { return rpm_; }
    Corrector& corrector(int d) { return corr_[size_t(d)]; }

    // Display conversion: lathe X as a diameter unless E11005 = 0.
    double to_display(int axis, double internal) const;

  private:
    struct Frame {
        const ProgramText* prog = nullptr;
        size_t pos = 0;        // next line to read
        int line = 0;          // its number
        bool call = false;     // pushed by G77
        bool whole = false;    // a whole program (else a block range)
        size_t range_pos = 0;  // first block of the range
        int range_line = 0;
        int end_line = 0;      // last block of the range (inclusive)
        bool emptied = false;  // G76- deleted every line of the range: no next pass
        int repeats = 1;       // executions left, this one included
        int saved_radcomp = 40;
        int saved_dir = 5, saved_range = -1;
        double saved_s = 0;
        bool saved_m7 = false, saved_m8 = false;
    };

    // Plan of a block: the words resolved into values (interp_words.cpp);
    // the words of a move, which a plain block reads alone (plan.hpp).
    struct Plan;
    struct AxisValues;
    struct Target;
    // The decoding of one block into its Plan (decode.hpp).
    struct Decoder;
    // One run of a drilling cycle (interp_cycles.cpp), one G45 pocket
    // (interp_pocket.cpp): their steps share the cycle's context.
    struct DrillRun;
    struct Pocket45;
    // While alive, moves run at feeds of the cycle's own (a thread's lead, rigid
    // tapping, a pocket's EP EQ): no warning 1110 for them.
    struct OwnFeed {
        Interpreter& in;
        const bool was;
        explicit OwnFeed(Interpreter& i) : in(i), was(i.feed_programmed_) {
            in.feed_programmed_ = true;
        }
        ~OwnFeed() { in.feed_programmed_ = was; }
        OwnFeed(const OwnFeed&) = delete;
        OwnFeed& operator=(const OwnFeed&) = delete;
    };

    // interp_caz*.cpp: the Cazeneuve HB CNC dialect (seed 003;
    // pupitre-cazeneuve(5)); its decoder reads a block into the same Plan.
    struct CazDecoder;
    struct CazState;
    std::unique_ptr<CazState> caz_;
    void caz_power_on();
    StepResult execute_caz(const Block& b);
    bool caz_motion(const Plan& p);
    bool caz_g7(const Plan& p);
    bool caz_tool(const Plan& p);
    bool caz_speed_limit(Plan& p);        // G25 S (interp_caz.cpp)
    void limit_spindle(int g, double s);  // G92 S or G25 S: modal_.smax
    bool caz_m(const Plan& p, StepResult& r);

    // interp.cpp
    bool fetch(std::string_view& line, int& lineno, bool& parsed);
    StepResult execute(const Block& b);
    // interp_fast.cpp: the lane of plain G0-G3 blocks (issue 14), which reads
    // their words straight into a Target; nothing when the block is not one
    // (it then has done nothing, and execute() reads it whole).
    struct PlainBlock;
    std::optional<StepResult> execute_plain(const Block& b);
    bool plain_state() const;
    bool plain_words(const Block& b, PlainBlock& w) const;
    // interp_exec.cpp: the steps of execute() and the modal groups of apply_modal().
    // The inline ones run for every block, where a call would cost more than
    // their tests; they are defined and called in interp_exec.cpp only.
    inline bool assign_all(const Block& b);
    bool assign_l(const Operand& t, double v, int col);
    bool assign_e(const Operand& t, double v, int col);
    std::optional<StepResult> run_apart(const Block& b, const Plan& p);
    bool block_allowed(const Plan& p);
    inline bool do_dwell(const Plan& p);
    bool do_g79(const Block& b, const Plan& p);
    bool do_flow(const Block& b, const Plan& p);
    inline bool modal_interpolation(const Plan& p);
    inline bool modal_cycle(const Plan& p);
    inline bool modal_frame_switches(const Plan& p);
    bool modal_feed(const Plan& p);
    bool modal_tool(const Plan& p);
    bool modal_g59(const Plan& p);
    inline bool modal_frame(const Plan& p);
    bool modal_g92(const Plan& p);
    void ed_axes(int& a0, int& a1) const;
    // Records error `code` at the current block (its program, line, N and the
    // column of the word, or `column` when given) and ends the run. Returns
    // false, so that a step answers with it: `return fail(2, tr("..."));`.
    bool fail(int code, std::string detail, int column = 0);
    // The same for what a pure layer answered (diag.hpp: Error).
    bool fail(const Error& e);
    void warn(int code, std::string detail);
    // The Diag both build (interp.cpp): `code` at the current block.
    Diag diag_here(Severity s, int code, std::string detail, int column) const;
    bool call(const Plan& p);
    bool jump(long label);
    bool transfer(const Plan& p);
    bool transfer_line(const ProgramText* target, size_t pos, size_t eol);
    bool transfer_field(const ProgramText* target, bool is_l, long n, size_t field, size_t width,
                        bool word_follows);
    // interp_g76.cpp: G76+ / G76- (000:7018-7170; pupitre-iso(5), PROGRAM FLOW)
    bool edit_program(const Block& b, const Plan& p);
    bool edit_block_alone(const Block& b, char sign);
    bool edit_whole_program(const Block& b, const Plan& p);
    bool edit_line(const Block& b, const Plan& p);
    bool inserted_words(const Block& b, const Block& ins,
                        std::vector<std::pair<uint16_t, std::string>>& parts);
    bool inserted_assigns(const Block& b, const Block& ins,
                          std::vector<std::pair<uint16_t, std::string>>& parts);
    bool inserted_reads_back(const Block& b, const std::string& out);
    bool edit_block_text(const Block& b, std::string& out);
    void text_spliced(const ProgramText* p, const Splice& s);
    bool end_of_frame();
    void after_block(int lineno);
    void reset_modal_m02();
    void recompute_program_pos();
    void apply_corrector_gauges(const std::bitset<kAxes>& programmed);
    double gauge_for(int d, int axis) const;
    Error read_e(int n, int64_t& out) override;
    Error write_e(int n, int64_t value) override;
    Error e_rights(int n, bool write) const;
    Error e_access() const;
    int64_t e_value(int n) const;
    int64_t e_axis(int n) const;
    int64_t e_raw(int n, int64_t none) const;
    std::string set_corrector(std::string_view name, double value);
    void note_tool(int t);

    // interp_words.cpp
    bool decode(const Block& b, Plan& p);
    bool word_value(const Word& w, double& out, int* int_out = nullptr);
    bool variable_value(const Word& w, double& out);
    bool apply_modal(const Plan& p);
    bool apply_spindle(const Plan& p);
    bool do_m_avant(const Plan& p);
    bool m_avant(int m, bool& coolant);
    bool do_m_apres(const Plan& p, StepResult& r);

    // motion.cpp
    bool do_motion(const Plan& p);
    // Inlined into do_motion, which every block runs (tests/perf).
    [[gnu::always_inline]] inline Axes target_of(const Target& to) const;
    [[gnu::always_inline]] inline bool motion_allowed(const Plan& p);
    [[gnu::always_inline]] inline std::optional<bool> motion_family(const Plan& p);
    inline bool pgp_motion(const Plan& p);
    inline bool g52_move(const Plan& p);
    inline bool comp_line(const Target& to, const Axes& target);
    [[gnu::always_inline]] inline bool straight(const Target& to, Axes target);
    // The move of a block whose family is known (do_motion, the plain lane).
    bool move_to(const Target& to, bool g23);
    // Error 140: more than 2 blocks without motion in the plane under G41/G42.
    bool count_plane_motion(const std::bitset<kAxes>& axis);
    bool linear(int g, const Axes& target_prog, bool g52, const std::bitset<kAxes>& axes);
    bool g29_move(const Plan& p);
    bool arc(const Target& to, const Axes& target_prog);
    // The axes of a circle's plane and their centre words (motion.cpp).
    struct ArcAxes {
        int a0, a1, an, i0, i1, in;
        bool helix;  // the normal axis moves too
    };
    [[gnu::always_inline]] inline bool arc_words(const Target& to, const ArcAxes& ax);
    [[gnu::always_inline]] inline bool arc_centre(const Target& to, const ArcAxes& ax,
                                                  const comp::V2& s, const comp::V2& e, comp::V2& c,
                                                  double& r0, double& r1);
    static inline double arc_sweep(const comp::V2& s, const comp::V2& e, const comp::V2& c,
                                   bool ccw);
    static int helix_turns(double dz, double k, double th0);
    bool arc3(const Target& to, const Axes& target_prog);
    bool emit_arc(int g, const Axes& target, int a0, int a1, double c0, double c1, double sweep_rad,
                  double r0, double r1, int helix_axis);
    // Every move asks: the common answer inline, travel_fault() for the rest.
    bool check_travel(const Axes& mach) {
        return (homed_.all() && inside_travel(mach)) || travel_fault(mach);
    }
    bool inside_travel(const Axes& mach) const;
    bool travel_fault(const Axes& mach);
    bool finish_move(MoveEvent& e, const Axes& mach, const Axes& prog, double seconds);
    double feed_rate(double& rpm_out);  // mm/min for the move start
    void check_tiny_feed();
    void report_unset_reads();
    void warn_idle_words(const Plan& p);
    void warn_spindle_words(const Plan& p);
    bool tiny_feed_warned_ = false;
    bool feed_programmed_ = false;  // an F was programmed (warning 1110)
    bool feed_before_f_warned_ = false;
    double s_raw_ = 0;                 // S read from a variable before rounding (1113)
    std::bitset<960> l_unset_warned_;  // warning 1111, once per variable
    double spindle_at(double x_radius) const;
    double feed_time(double length, double x0, double x1);
    void set_spindle_event();

    const MachineProfile& m_;
    ProgramMemory& mem_;
    MachineSink& sink_;                  // the real sink
    std::unique_ptr<PlainBlock> plain_;  // the lane's words (interp_fast.cpp)
    std::unique_ptr<GateSink> gate_;     // holds events while a compensated move waits
    MachineSink& out_;                   // where events go: the gate

    // Tool radius compensation with a non-zero radius (interp_comp.cpp).
    struct CompCtx {
        Loc loc;
        Modal modal;
        int g = 1;
        Axes target{};  // programmed target, all axes
        double rp = 0;  // programmed arc radius (tangential feed), 0 for a line
    };
    struct Comp {
        bool on = false;
        bool waiting_entry = false;  // engaged, no move yet
        bool has_pending = false;
        bool pending_is_entry = false;
        int side = 1;  // +1 left (G41), -1 right (G42), mirror included
        double radius = 0;
        int a0 = X, a1 = Y;
        comp::V2 shift{0, 0};  // lathe: nose centre to tool point, R·(sz, sx)
        comp::Elem pending;
        CompCtx ctx;
        comp::V2 tc{0, 0};  // tool centre where the next piece starts
    } comp_;
    // Drilling cycles G81-G89 and G31 (interp_cycles.cpp): modal parameters.
    struct CycleParams {
        bool has_z = false, has_er = false, has_eh = false, has_ef = false;
        bool has_p = false, has_q = false, has_es = false, has_ep = false, has_k = false,
             has_starts = false;
        double z = 0, er = 0, eh = 0, ef = 0, p = 0, q = 0, es = 0, ep = 0, ec = 0, ea = 0, k = 0,
               ek = 0;
        double starts = 1;
    } cyc_;
    int cycle_axis() const;
    bool cycle_move(int g, const Axes& target);
    bool cycle_axis_move(int g, double v);
    bool cycle_dwell(double s);
    bool cycle_words(const Plan& p, int code);
    bool cycle_run(const Plan& p, int code);
    bool cycle_block(const Plan& p);
    // Splines G48/G06/G49 (interp_spline.cpp).
    std::map<int, spline::Curve> splines_;
    bool spline_define(const Plan& p);
    bool spline_run(const Plan& p);
    // G45 pockets (interp_pocket.cpp); the feeds are kept from one G45 to the next.
    double pocket_ep_ = 0, pocket_eq_ = 0, pocket_ei_ = 0, pocket_ej_ = 0;
    bool pocket(const Plan& p);
    // G46 pockets and facing (interp_pocket46.cpp): the definition being read
    // between NU0 and NU9, and the definitions by NP.
    struct P46 {
        bool defining = false;
        p46::Def def;
        bool first = true;  // the next contour block is the section's positioning
        int blocks = 0;     // contour blocks read in the section
        int motion = 1;     // modal interpolation inside the definition
        p46::V2 pos{0, 0};
        long last_block = -1;  // blocks_ at the last definition block
        Loc at;                // where the open definition's NU0 is
        pgp::Solver solver;
        std::map<int, p46::Def> defs;
    } p46_;
    bool pocket46(const Plan& p);
    bool p46_contour(const Plan& p);
    bool p46_section(const Plan& p, int nu);
    bool p46_close_section();
    bool p46_header(const Plan& p, int nu);
    bool p46_order(const Plan& p, int nu);
    struct P46Cut;
    bool p46_order_allowed(const Plan& p, const p46::Def& d);
    bool p46_drill(const Plan& p, const p46::Def& d);
    bool p46_cutter(const Plan& p, int nu, const p46::Def& d, double& R);
    bool p46_cut(const p46::Def& d, int nu, const P46Cut& c);
    bool p46_fail(const Error& e, const p46::Def& d);
    // The axes of a G46 plane: first, second and normal (interp_pocket46.cpp).
    struct P46Axes {
        int a0, a1, an;
    };
    static P46Axes p46_axes(int plane);
    bool p46_contour_words(const Plan& p, const P46Axes& ax, bool tech_words);
    bool p46_contour_start(const Plan& p, const P46Axes& ax, int motion, p46::V2 t);
    bool p46_contour_elem(const Plan& p, const P46Axes& ax, int motion, p46::V2 t);
    void warn_plunges(const p46::Def& d, const std::vector<p46::Run>& runs);
    bool p46_emit(const P46Axes& ax, const std::vector<p46::Run>& runs, double z, double approach,
                  double clear, double f_ax, double f_lat);
    // Profile geometry programming (interp_pgp.cpp).
    pgp::Solver pgp_;
    int pgp_tag_ = 0;
    std::map<int, CompCtx> pgp_ctx_;  // the block context of each tag still held
    void plane_axes(int& a0, int& a1) const;
    bool pgp_wanted(const Plan& p) const;
    bool pgp_block(const Plan& p, const Axes& target);
    bool pgp_emit(const std::vector<pgp::Elem>& elems);
    bool pgp_fail(const Error& e);
    bool pgp_close();
    // Turning cycles (interp_turning.cpp): G64 waits for its stock until G80.
    turning::G64Args g64_;
    long g64_na_ = 0, g64_nb_ = 0;
    comp::V2 g64_tool_{0, 0};
    std::vector<comp::V2> g64_stock_;
    Loc g64_loc_;
    bool g64_pending_ = false;
    double g38_lead_ = 0;
    double profile_feed_ = 0;  // the first F of the last profile read
    bool coordinate_above(const ProgramText* prog, int line, int axis, double& v);
    static double cyc(const Plan& p, Addr a, double dflt, bool* has = nullptr);
    bool turning_profile(long na, long nb, turning::Profile& out, comp::V2& first);
    struct ProfileRead;
    bool profile_l_words(const Block& blk);
    bool profile_start(Plan& q, ProfileRead& r);
    pgp::Spec profile_spec(const Plan& q, const comp::V2& cur, int line) const;
    bool profile_block(Plan& q, int line, ProfileRead& r);
    static void profile_as_called(const std::vector<pgp::Elem>& elems, bool reversed,
                                  turning::Profile& out, comp::V2& first);
    void warn_allowance_inside(int g, double i, double k);
    bool turning_emit(const std::vector<turning::Move>& moves, double lead, double infeed);
    bool turning_block(const Plan& p);
    bool turning_g64(const Plan& p);
    bool turning_g65_g63(const Plan& p);
    bool turning_g66(const Plan& p);
    bool turning_g33(const Plan& p);
    bool turning_g38(const Plan& p);
    bool turning_emit_ef(const Plan& p, const std::vector<turning::Move>& moves);
    static turning::G65Args g65_args(const Plan& p);
    turning::G63Args g63_args(const Plan& p) const;
    bool turning_stock(const Plan& p);
    bool turning_g64_run();
    bool comp_engage(int g);
    bool comp_element(const comp::Elem& e, int g, const Axes& target, double rp);
    bool comp_other_axes(const Axes& target, const std::bitset<kAxes>& axes);
    bool comp_exit(const Axes* target);
    bool comp_emit(const std::vector<comp::Piece>& pieces, const CompCtx& ctx);
    // The pieces of the element being joined, kept so that a compensated block
    // allocates nothing (comp_element, comp_exit).
    std::vector<comp::Piece> comp_pieces_;
    RunOptions opt_;

    Modal modal_;
    Frames frames_;
    std::bitset<kAxes> gauge_pending_;
    std::array<Corrector, 256> corr_{};
    LVars l_;
    std::map<int, int64_t> e_raw_;    // E parameters with no machine meaning (E80000…)
    Axes travel_lo_{}, travel_hi_{};  // static travel narrowed by E6x002 / E6x003
    // The same with check_travel's 1e-6 of tolerance, worked out once
    // (update_travel) rather than at every move.
    Axes travel_lo_tol_{}, travel_hi_tol_{};
    // The axes with a bound (the others have none: an absent axis's is ±1e300).
    std::array<uint8_t, kAxes> bounded_{};
    int n_bounded_ = 0;
    void update_travel();
    std::map<int, int64_t> e_written_;  // every E written by the program
    Axes mach_{};                       // machine position of the reference
    Axes prog_{};                       // current program point
    Axes prog_next_{};                  // program point at the end of the linear move being made
    double rpm_ = 0;                    // actual spindle speed
    std::vector<Frame> stack_;
    const ProgramText* main_ = nullptr;
    Loc loc_;
    int col_ = 0;
    std::vector<Diag> diags_;
    std::vector<int> tools_used_;
    long blocks_ = 0, moves_ = 0, plain_blocks_ = 0;
    // The endless-loop guard (core/interp/interp_loop.cpp): digests of the state at
    // backward G79 jumps.
    struct DigestKey {
        uint64_t a, b;
        bool operator==(const DigestKey&) const = default;
    };
    struct DigestHash {
        size_t operator()(const DigestKey& k) const { return size_t(k.a ^ (k.b << 1)); }
    };
    std::unordered_set<DigestKey, DigestHash> seen_states_;
    std::pair<uint64_t, uint64_t> state_digest() const;
    bool note_backward_jump(long label);
    double path_ = 0, clock_ = 0;
    // E32000, the shortest time of an interpolated block (s; the profile's
    // min_block_time until a program writes it), carried on each move.
    double min_block_ = 0;
    // The kind of a canned cycle's last move in this block (0 rapid, 1 feed,
    // -1 none): where it changes, a pass ends or begins, and the NUM stops.
    signed char cycle_last_ = -1;
    void cycle_pass(bool feed) {
        if (cycle_last_ >= 0 && cycle_last_ != int(feed)) out_.exact_stop(loc_);
        cycle_last_ = feed;
    }
    bool ended_ = false;
    bool imd_ = false;            // the main program is an IMD fragment
    bool comp_emitting_ = false;  // moves now made are compensated pieces
    std::bitset<kAxes> homed_;
    bool first_move_ = true;
    int nonmotion_in_comp_ = 0;
    SpindleEvent last_sp_;  // last spindle state reported
    bool sp_emitted_ = false;
    bool x_known_ = false;  // an X was programmed (G96 start diameter)
    Block block_;           // reused parse buffer
    std::string_view cur_text_;
    int cur_line_ = 0;        // line of the block being executed (G76+/G76- move it)
    size_t loaded_size_ = 0;  // program memory at the start of the run (G76+ quota)
};

}  // namespace pupitre
