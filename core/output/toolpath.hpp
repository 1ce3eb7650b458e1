// The toolpath of a run, kept for drawing (issue 7): every move in the program
// frame, compactly, arcs kept as arcs, with the block it came from, its kind
// (rapid, feed, compensated), moves beyond the machine's travel, and the errors
// of the run where they happened. A MachineSink, so the interpreter can feed it
// directly, or another sink can pass it each move with add().
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"
#include "core/interp/sink.hpp"
#include "core/parse/program.hpp"

namespace pupitre {

// The drawing planes: horizontal axis first. XY is G17 seen from +Z, XZ the
// front view of G18 on a mill, YZ the side view of G19; ZX is the lathe: Z
// horizontal, X (a radius) up.
enum class PathPlane : uint8_t { xy, xz, yz, zx };
std::string_view plane_name(PathPlane p);                 // "XY", "XZ", "YZ", "ZX"
bool parse_plane(std::string_view word, PathPlane& out);  // xy|xz|yz|zx, any case
// The axis drawn across (h) and up (v).
inline void plane_axes(PathPlane p, int& h, int& v) {
    static constexpr int kH[] = {X, X, Y, Z}, kV[] = {Y, Z, Z, X};
    h = kH[int(p)];
    v = kV[int(p)];
}

enum class PathKind : uint8_t { rapid, feed, comp };

namespace pathflag {
inline constexpr uint8_t travel = 1;  // ends beyond the machine's travel (profile limits)
inline constexpr uint8_t error = 2;   // made by a block that raised an error (149 gouge, …)
inline constexpr uint8_t g52 = 4;     // programmed in machine coordinates
inline constexpr uint8_t piece = 8;   // a piece after the first of one move (MoveEvent::piece)
}  // namespace pathflag

// One move. Its start is the end of the previous move (or Toolpath::start()).
// Coordinates are the program frame in internal units: mm, lathe X a radius.
struct PathMove {
    double p[3] = {0, 0, 0};  // end point X Y Z
    uint32_t arc = kNoArc;    // index into Toolpath::arcs(), or kNoArc for a line
    PathKind kind = PathKind::feed;
    uint8_t flags = 0;
    int8_t ltype = -1;  // E31000 (rapid) or E31001 (feed) when the program set it, else -1
    uint8_t g = 1;      // 0, 1, 2, 3
    static constexpr uint32_t kNoArc = std::numeric_limits<uint32_t>::max();
};

// The circle part of a G2/G3 move: centre in its plane and signed sweep (several
// turns for a helix). The radius may change from start to end (the interpreter's
// spiral arcs): it varies linearly with the angle.
struct PathArc {
    double c0 = 0, c1 = 0;   // centre on axes a0, a1 (program frame, internal units)
    float sweep = 0;         // degrees, negative for G2
    uint8_t a0 = X, a1 = Y;  // the plane's axes, positive sweep from a0 towards a1
};

// An error of the run, where it stopped the tool.
struct PathError {
    Loc loc;
    int code = 0;
    std::string detail;
    size_t moves = 0;  // moves made before it: the tool stands at the end of move moves-1
};

// Per-axis extents of X Y Z (program frame, internal units).
struct PathBox {
    double lo[3] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
    bool empty() const { return lo[0] > hi[0]; }
    void add(const double p[3]) {
        for (int a = 0; a < 3; ++a) {
            if (p[a] < lo[a]) lo[a] = p[a];
            if (p[a] > hi[a]) hi[a] = p[a];
        }
    }
    void add(const PathBox& b) {
        if (!b.empty()) {
            add(b.lo);
            add(b.hi);
        }
    }
};

class Toolpath final : public MachineSink {
  public:
    explicit Toolpath(const MachineProfile& m) : m_(m), x_diam_(m.lathe && m.x_diameter) {}

    // Forgets every move (a new run); the machine stays.
    void clear();
    // The program point before the first move (Interpreter::program_pos()).
    // Without it, the first move's start is worked out from its machine delta.
    void start_at(const Axes& prog);
    void add(const MoveEvent& e);
    // The program's line types (E31000 for G0, E31001 for G1/G2/G3), -1 while
    // not set; they apply to the moves added after the call.
    void set_line_types(int rapid, int feed);
    // An error of the run: the moves of its block are flagged, and the point
    // where the tool stopped is kept. Warnings are ignored.
    void add_error(const Diag& d);
    // The rough stock of a lathe cycle (G64), as (Z, X radius) points.
    void add_stock(const Loc& l, const std::vector<std::array<double, 2>>& zr);
    // EM- / EM+: the part's extremes as the program declares them (docs/decisions.md, EM- and EM+).
    void set_extremes(const Axes& lo, const Axes& hi, uint16_t mask_lo, uint16_t mask_hi);

    // MachineSink: moves are recorded; dwells and tool changes count in the time.
    void move(const MoveEvent& e) override { add(e); }
    void dwell(const Loc&, double s) override { seconds_ += s; }
    void tool(const Loc&, int, int, double s, bool) override { seconds_ += s; }
    void end(const Loc& l, int) override { end_ = l; }
    void stock(const Loc& l, const std::vector<std::array<double, 2>>& zr) override {
        add_stock(l, zr);
    }
    void profile(const Loc&, const ProfileElem& e) override { profile_.push_back(e); }

    // --- reading ---
    const MachineProfile& machine() const { return m_; }
    // Changes with every clear(): a drawing cached for one run is not reused for the next.
    uint32_t generation() const { return gen_; }
    size_t size() const { return moves_.size(); }
    // The moves the program made among the first `upto` drawn (a move drawn
    // on the part in pieces counts once).
    size_t moves_made(size_t upto) const;
    size_t moves_made() const { return moves_made(moves_.size()); }
    bool empty() const { return moves_.empty(); }
    const PathMove& operator[](size_t i) const { return moves_[i]; }
    const std::vector<PathMove>& moves() const { return moves_; }
    const std::vector<PathArc>& arcs() const { return arcs_; }
    const double* start() const { return start_; }
    // The start point of move i (the end of move i-1).
    const double* from(size_t i) const { return i == 0 ? start_ : moves_[i - 1].p; }
    // The block of move i.
    Loc loc(size_t i) const;
    const std::vector<PathError>& errors() const { return errors_; }
    const std::vector<std::vector<std::array<double, 2>>>& stock() const { return stock_; }
    // The workshop's part as cut (pupitre-setup(5)): its half-section, (Z, X
    // as a radius) in the program frame; drawn filled under the path.
    void set_part(std::vector<std::vector<std::array<double, 2>>> p) { part_ = std::move(p); }
    const std::vector<std::vector<std::array<double, 2>>>& part() const { return part_; }
    // The programmed profile of the compensated moves (G41/G42), element by element.
    const std::vector<ProfileElem>& profile_elems() const { return profile_; }
    // Extents of every move, and of the cutting moves only (feed and compensated).
    const PathBox& bounds() const { return all_; }
    const PathBox& cut_bounds() const { return cut_; }
    bool has_extremes() const { return em_mask_lo_ || em_mask_hi_; }
    const Axes& extremes_lo() const { return em_lo_; }
    const Axes& extremes_hi() const { return em_hi_; }
    uint16_t extremes_mask_lo() const { return em_mask_lo_; }
    uint16_t extremes_mask_hi() const { return em_mask_hi_; }
    size_t count(PathKind k) const { return counts_[size_t(k)]; }
    size_t travel_moves() const { return travel_; }
    double seconds() const { return seconds_; }
    double length() const { return length_; }
    // Lathe X is shown as a diameter (the last move said so, else the profile).
    bool x_diameter() const { return x_diam_; }
    // The plane the program's arcs use most (G17/G18/G19 as 17/18/19), 17 with no arc.
    int arc_plane() const;
    // The plane to draw when none is chosen: ZX on a lathe, else the arcs' plane.
    PathPlane default_plane() const;
    // Bytes held (the budget: a 1,000,000-move program well under 100 MB).
    size_t memory_bytes() const;

    // The program drawn (title block, title rule): the main program's number and title.
    int program = -1;
    std::string title;

  private:
    struct LocRun {
        uint32_t first;  // first move of the block
        int32_t prog, line, n;
    };
    bool beyond_travel(const Axes& mach) const;
    void add_arc_bounds(const PathMove& mv, const PathArc& a, PathBox& b) const;

    const MachineProfile& m_;
    std::vector<PathMove> moves_;
    std::vector<PathArc> arcs_;
    std::vector<LocRun> locs_;
    std::vector<PathError> errors_;
    std::vector<std::vector<std::array<double, 2>>> stock_;
    std::vector<std::vector<std::array<double, 2>>> part_;
    std::vector<ProfileElem> profile_;
    double start_[3] = {0, 0, 0};
    bool has_start_ = false;
    PathBox all_, cut_;
    Axes em_lo_{}, em_hi_{};
    uint16_t em_mask_lo_ = 0, em_mask_hi_ = 0;
    size_t counts_[3] = {0, 0, 0};
    std::vector<uint32_t> pieces_;  // the indices of the pieces (pathflag::piece), in order
    size_t travel_ = 0;
    bool beyond_ = false;  // the move being drawn is counted beyond travel
    int plane_arcs_[3] = {0, 0, 0};
    int8_t ltype_rapid_ = -1, ltype_feed_ = -1;
    double seconds_ = 0, length_ = 0;
    bool x_diam_;
    uint32_t gen_ = 0;
    Loc end_;
};

// EM- and EM+ of a program's text (EM- or EM+ then axis values with literal
// numbers; docs/decisions.md, EM- and EM+). Returns false when the program has none.
// Lathe X is read as a diameter when `x_diameter`.
bool scan_extremes(const ProgramText& p, bool x_diameter, Axes& lo, Axes& hi, uint16_t& mask_lo,
                   uint16_t& mask_hi);

// What a drawing's frame fits, one rule for the GRAPH page's `f` and for the
// plot: the cutting moves (feed and compensated) with the lathe's stock, the
// EM± frame, the mirror image (of the cutting moves) and, when drawn, the
// programmed profile. Rapids are left out, so that the trip from the home or
// tool-change position does not shrink the part to a dot; with no cutting
// move, every move is fitted. The mirror image is left out too when the cuts
// are further from the axis than they are high (a rim, a flange): it would
// leave the part a sliver between two empty bands. Box in the plane: h
// across, v up (world mm).
struct PathFit {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    enum What : uint8_t {
        start,
        moves,
        cuts
    } what = start;           // the start point alone, every move, the cuts
    bool mirror_out = false;  // the mirror image was asked for but is not in the box
    size_t outside = 0;       // rapids that leave the box (counted by count_outside)
};
PathFit fit_box(const Toolpath& path, PathPlane plane, bool mirror, bool with_profile);
// Rapids among the first `upto` moves that start or end outside the box: f.outside.
void count_outside(const Toolpath& path, PathPlane plane, size_t upto, PathFit& f);
// What the box holds, in words: "the cutting moves of %555 (3 rapids reach beyond)".
std::string fit_words(const Toolpath& path, const PathFit& f);

// Drawing helpers shared by the raster, the plot's scene and the SVG writer.
// A "nice" length for a scale bar about `target` long: 1, 2 or 5 times a power of ten.
double nice_length(double target);
// The point of arc move i at fraction t (0..1) of its sweep, program frame.
void arc_point(const Toolpath& path, size_t i, double t, double out[3]);
// Start and end radii of arc move i.
void arc_radii(const Toolpath& path, size_t i, double& r0, double& r1);

}  // namespace pupitre
