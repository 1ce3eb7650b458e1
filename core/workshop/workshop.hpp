// The workshop (ARCHITECTURE.md, the workshop): the interpreter's events, OM positions computed
// from what the operator entered, become what really happens to the setup's
// true part and tools: cuts, contacts, crashes. A MachineSink that passes
// every event on to the next sink (the trace, the console's queue).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/interp/sink.hpp"
#include "core/workshop/lathe_part.hpp"
#include "core/workshop/mill_part.hpp"
#include "core/workshop/setup.hpp"

namespace pupitre::workshop {

// Workshop alarms, 1200-1299 (pupitre(1), DIAGNOSTICS).
inline constexpr int kCrashRapid = 1200;      // a rapid into the material
inline constexpr int kCrashStopped = 1201;    // a feed into the material, spindle stopped
inline constexpr int kCrashChuck = 1202;      // the tool or holder hits the work-holding
inline constexpr int kCrashHolder = 1203;     // the holder or shank hits the material
inline constexpr int kCrashDirection = 1204;  // cutting with the spindle turning the wrong way
inline constexpr int kCrashProbe = 1205;      // a touch probe driven into the material

// What a move came to.
struct Outcome {
    bool crashed = false;  // crashes().back() says how
    bool touched = false;  // a jog stopped at a contact: `what` says where
    Axes stop{};           // where the motion ended (the contact), when either
    double fraction = 1;   // of the move's length
    std::string what;
};

// A jog stops when the tool comes this close into something (mm); it is at
// a contact when grown by kNear it overlaps it (a face it has just cut).
inline constexpr double kTouchDepth = 1e-4;
inline constexpr double kNear = 1e-3;

// A move that turns B, or C with the tool tilted, goes in pieces in which the
// tool's axis turns by at most this (degrees).
inline constexpr double kAxisStep = 0.2;

// A contact deeper than this is a crash; a tool that only touches (a finishing
// pass along a cut face) is not (mm, about twice the chord error).
inline constexpr double kCrashDepth = 2e-3;

// An edge finder's lower part, kicked off the axis at the contact, slides on
// its spring this far aside (mm); driven further it is bent: crash 1205.
inline constexpr double kFinderTravel = 1.0;

struct Crash {
    int code = 0;
    Loc loc;
    int tool = 0;
    Axes om{};            // where the motion stopped: the contact
    double fraction = 1;  // of the move's length done
    std::string what;     // the message: what hit what, where
};

// One instrument's reading (pupitre-setup(5), MEASUREMENTS).
struct Reading {
    std::string spec;        // as asked: "dia Z-20"
    std::string instrument;  // "micrometer", "caliper", …
    double value = 0;        // mm, rounded to the instrument's resolution
    double resolution = 0;   // mm
    double uncertainty = 0;  // mm, ± (the presetter's); 0: within the resolution
};

// Whether `word` begins an instrument's request on either machine ("dia",
// "depth", "tool", …): what :measure reads on the part rather than a gauge.
bool is_instrument(std::string_view word);
// An instrument's word as the workshop knows it: the French word a French
// console shows (longueur, alésage, outil…) is the English one (length,
// bore, tool…); any other word as it is.
std::string_view instrument_word(std::string_view word);
bool is_mill_instrument(std::string_view word);  // mill_shop.cpp

class Workshop final : public MachineSink {
  public:
    // `next` receives every event after the workshop (may be null).
    Workshop(const MachineProfile& m, const Setup& s, MachineSink* next);

    const Setup& setup() const { return setup_; }
    const MachineProfile& machine() const { return m_; }
    // The lathe's half-section; on a machining centre (is_mill()) the
    // material is mill() and world() holds nothing.
    LatheWorld& world() { return world_; }
    const LatheWorld& world() const { return world_; }
    bool is_mill() const { return mill_ != nullptr; }
    const MillWorld* mill() const { return mill_.get(); }
    // The part, whichever the machine: its changes, the text the store
    // keeps (and back: false, fresh stock kept, when it does not read),
    // fresh stock.
    uint64_t generation() const;
    std::string part_text() const;
    bool load_part(std::string_view text);
    void new_part();
    bool crashed() const { return !crashes_.empty(); }
    const std::vector<Crash>& crashes() const { return crashes_; }
    void clear_crash() { crashes_.clear(); }  // RAZ: the alarm is acknowledged
    int tool() const { return tool_; }
    double cut_length(int tool) const;  // mm of feed in material so far
    // A shim (or a cigarette paper) of this thickness on the part: a jog
    // stops when the tool pinches it (the paper test); 0: none.
    void set_shim(double mm) { shim_ = mm; }
    double shim() const { return shim_; }
    // A gauge block against the lathe's jaws (LatheWorld::set_gauge_block);
    // 0: none. A jog stops on its end; no move goes through it.
    void set_gauge_block(double mm) { world_.set_gauge_block(mm); }
    // An exercise (pupitre-exercise(5)): contacts and crashes say what was
    // touched, not where on the part (that would read the truth off it).
    void hide_places(bool hide) { hide_places_ = hide; }
    double gauge_block() const { return world_.gauge_block(); }

    // An electric touch probe in use, and its lamp: lit when the ball touches
    // the part, the chuck or the tailstock at machine position `om`.
    bool probe_in_use() const;
    bool probe_contact(const Axes& om) const;
    // The true tool point of the tool in use for a machine position (Z, R).
    Pt tip(const Axes& om) const;
    // Where the program frame puts the lathe's part: the shift (Z, R) from
    // the part's coordinates to the program's, so that a point of the part
    // is drawn where the tool in use reads it. Under D0 (after M02 or RAZ)
    // the turret reference has no gauge and would put the part a gauge away:
    // the shift read at the last move made with a corrector stands. The
    // NUM's PREF and the Cazeneuve's correctors (which carry its origin)
    // come out the same.
    struct Frame {
        bool known = false;  // read at a move with a corrector
        double dz = 0, dx = 0;
    };
    // `corrector`: the one in use now (the interpreter's D).
    Frame part_frame(const Axes& om, const Axes& op, int corrector) const;
    // A machining centre's: the true tip of the cutter in the spindle (X, Y,
    // Z: the centre of its end); the gauge line itself when none. In the
    // table's frame (a C table turned, mill5; a B head or table tilted), or,
    // not `turned`, as if B and C were 0: how GRAPH and plot place the block
    // under the path, which they draw as the machine moved.
    P3 tip3(const Axes& om, bool turned = true) const;
    // The cutter's axis in the table's frame, from its tip up (kUp at B0).
    P3 axis3(const Axes& om) const;
    // Where the path is drawn on the part (GRAPH, plot): the program point
    // `op` of machine position `om`, moved by what the rotary axes turn the
    // tool in the table's frame (the tip there, in the frame the program
    // reads at B0 C0). `op` itself at B0 C0.
    Axes on_part(const Axes& om, const Axes& op) const;
    // A move as on_part() draws it: pieces within the chord error when a
    // rotary axis is away from 0 along it (false, nothing added, when none is).
    bool on_part(const MoveEvent& e, std::vector<MoveEvent>& out) const;
    // Passes the moves on to the next sink as on_part() draws them (plot).
    void draw_on_part(bool on) { draw_on_part_ = on; }
    // Reads an instrument; "" or what is wrong with the request.
    std::string measure(std::string_view spec, Reading& r) const;
    // Where a request that reads (measure() answers "") reads the part, for
    // the PART view to mark the surface: the instrument's word in English
    // and, on the lathe, the machine Z (at[2]) of a dia, bore or groove (the
    // part's face for length); on the machining centre the machine point
    // and the axis it reads along (0 X, 1 Y, 2 Z). False when it reads
    // nothing (or is the presetter's).
    struct Place {
        std::string word;
        P3 at{};
        int axis = 2;
    };
    bool measure_place(std::string_view spec, Place& p) const;
    // The cutter in the spindle as it is now (worn); a default one when none.
    Cutter cutter_now() const { return cutter(); }
    // The machining centre's work-holding as the PART view draws it: the
    // vice or the plate (boxes) and the locating pins (not the table, nor
    // the tool setter far from the block).
    void holding(std::vector<Box3>& boxes, std::vector<Cylinder>& pins) const;

    // A program's move as the machine makes it (the console calls this as it
    // animates the move; move() does it for a batch run).
    Outcome apply(const MoveEvent& e);
    // JOG and INC: the move stops at the first contact of the tool or its
    // holder with the part, the chuck or the tailstock. From a contact an
    // increment goes on as a feed (a cut with the spindle turning, else a
    // crash); a `continuous` jog (a held key) stops again before going deeper.
    Outcome jog(const MoveEvent& e, bool continuous);
    // An increment from a contact with the shim goes nowhere.
    static Outcome on_the_shim(const Axes& om, int tool);
    static Outcome on_the_gauge(const Axes& om, int tool);
    // The move cut short where it stopped: `stop`, `fraction` of its length.
    static MoveEvent truncated(const MoveEvent& e, const Axes& stop, double fraction);

    // MachineSink
    void move(const MoveEvent& e) override;
    void dwell(const Loc& l, double s) override {
        if (next_) next_->dwell(l, s);
    }
    void tool(const Loc& l, int t, int d, double s, bool m6) override;
    void spindle(const SpindleEvent& e) override;
    void coolant(const Loc& l, bool a, bool b) override {
        if (next_) next_->coolant(l, a, b);
    }
    void stop(const Loc& l, int m) override {
        if (next_) next_->stop(l, m);
    }
    void message(const Loc& l, int c, std::string_view t) override {
        if (next_) next_->message(l, c, t);
    }
    void end(const Loc& l, int m) override {
        if (next_) next_->end(l, m);
    }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) override {
        if (next_) next_->stock(l, zr);
    }
    void profile(const Loc& l, const ProfileElem& p) override {
        if (next_) next_->profile(l, p);
    }
    void exact_stop(const Loc& l) override {
        if (next_) next_->exact_stop(l);
    }

  private:
    // --- the machining centre (mill_shop.cpp) ---
    enum class Met { none, material, vice, plate, pin, table, setter, shim };
    struct Contact {
        double f = 2;  // fraction of the move, 2: none
        Met what = Met::none;
        Part part = Part::flute;
    };
    void mill_fixtures();
    P3 grown_tip(const Axes& om, double g) const;
    struct Pose {
        P3 tip, u;
    };
    Pose pose3(const Axes& om, bool turned) const;
    // The axis a piece of a path is cut with: the tool's half way along it.
    P3 piece_axis(const Axes& from, const Axes& to) const;
    Cutter cutter(double grow = 0) const;  // the one in the spindle, worn, grown by `grow`
    // `flute_depth`: the flute's own limit, when not `depth` (>= 0).
    Contact mill_first(const Cutter& c, const P3& a, const P3& b, const P3& u, double depth,
                       bool with_material, bool before, double flute_depth = -1) const;
    double mill_depth(const Cutter& c, const P3& tip, const P3& u, Met& what) const;
    Outcome mill_apply(const MoveEvent& e);
    Outcome mill_jog(const MoveEvent& e, bool continuous);
    // A C table (mill5) turns the part under the tool and B tilts the tool:
    // a jog of C or B is made chord by chord, each a jog along a line.
    Outcome mill_jog_turn(const MoveEvent& e, bool continuous);
    Outcome mill_jog_line(const MoveEvent& e, bool continuous);
    bool mill_stroke(const MoveEvent& e, const P3& a, const P3& b, const P3& u, const Axes& oma,
                     const Axes& omb);
    // Records a crash of `hit` at `f` of the piece a->b (oma->omb).
    void mill_crash(const MoveEvent& e, int flute_code, const Contact& hit, const P3& a,
                    const P3& b, const Axes& oma, const Axes& omb, double f);
    // The edge finder in the spindle: its kick (a jog's contact) and an
    // increment from it.
    bool finder() const;
    Outcome finder_push(const MoveEvent& e);
    std::string finder_text(const Contact& k, const P3& a, const P3& b,
                            const std::string& place) const;
    std::string mill_where(const P3& p) const;
    std::string mill_measure(std::string_view word, std::string_view rest, Reading& r) const;
    bool mill_place(std::string_view rest, Place& p) const;
    std::string mill_crash_text(int code, const Contact& c, const std::string& place) const;
    std::string mill_touch_text(const Contact& c, const std::string& place) const;
    // The vice's jaws and body, the plate, the table (boxes); the pins and
    // the setter's plunger (cylinders, `box` their bounds).
    struct Fixture {
        Met what;
        Box3 box;
        std::optional<Cylinder> pin;
        double depth(const Cutter& c, const P3& tip, Part p) const {
            return pin ? depth_into(c, tip, p, *pin) : depth_into(c, tip, p, box);
        }
        // A tilted part, as points of its surface.
        double depth(const std::vector<P3>& points, const P3& tip) const {
            return pin ? depth_into(points, tip, *pin) : depth_into(points, tip, box);
        }
    };
    std::vector<Fixture> fixtures_;
    std::unique_ptr<MillWorld> mill_;

    struct Tool {
        const ToolTruth* truth = nullptr;
        ToolShape shape;
        ToolShape near;  // grown by kNear: touching what it is next to
        double cut = 0;  // mm of feed in material
    };
    Tool* current();
    const Tool* current() const;
    // The machine positions along a move, arcs and the turn of a C table
    // within the chord error (B: the tool's axis within 2 µm at its side).
    void path_of(const MoveEvent& e, std::vector<Axes>& out) const;
    void turn_pieces(std::vector<Axes>& out) const;
    // Checks a path of the tool; on a crash records it and returns false,
    // `stop` being the index fraction where the motion ends.
    bool check(const MoveEvent& e, const std::vector<Pt>& tips, const std::vector<Axes>& oms);
    std::string where(const Pt& p) const;
    std::string told(std::string what) const;  // without the place when hidden
    // Whether `shape` swept along `tips` can come near the part, the chuck
    // or the tailstock (a box test, no Boolean).
    bool near(const CPath& shape, const std::vector<Pt>& tips) const;
    std::string presetter(std::string_view rest, Reading& r) const;
    std::string part_crash_text(int code, int spindle, const char* place) const;
    std::string crash_text(int code, bool holder, Obstacle what, const ToolTruth& tt,
                           const std::string& place) const;
    std::string touch_text(Obstacle hit, bool holder, bool on_shim, const std::string& place) const;
    // The shim (:shim) as a thin body for a jog along the unit vector d from
    // the tool point `at`; empty without one (see jog()).
    CPath shim_body(const CPath& insert, Pt d, const Pt& at) const;
    // The first fraction of the path where `shape` comes deeper than `depth`
    // into `what` (`before`: the last one where it does not yet, within
    // 0.1 µm); 2 when it never does.
    // `whole`: the shape's sweep along the whole path, when already made.
    double first_contact(const CPath& shape, const std::vector<Pt>& tips, Obstacle what,
                         double depth, bool before = false, const CPaths* whole = nullptr) const;

    const MachineProfile& m_;
    Setup setup_;
    LatheWorld world_;
    MachineSink* next_;
    std::vector<Tool> tools_;  // by turret position (0: none)
    int tool_ = 0;
    int corr_ = 0;  // the corrector in use (0: D0)
    Frame frame_;   // part_frame() read at the last move with a corrector
    void note_frame(const MoveEvent& e);
    double shim_ = 0;
    bool hide_places_ = false;
    bool draw_on_part_ = false;
    int dir_ = 5;
    std::vector<Crash> crashes_;
};

}  // namespace pupitre::workshop
