// The material region of a roughing cycle and its allowance zone (internal to
// core/turning_*.cpp), in a geom::Frame where passes run along x and the
// material lies above the part. G64, G65 and G63 cut what lies inside the
// material region M and outside the zone A = finished part + allowance.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/cycles/turning.hpp"
#include "core/cycles/turning_geom.hpp"

namespace pupitre::turning::zone {

using geom::Elem;
using geom::Frame;

// Kinds of the edges of M.
enum Kind { kStock = 0, kClosing = 1, kProfile = 2 };

// The elements of a loop by their extent along y (or x): the ones a level
// line can meet. A centred interval tree: a G64 on a stock of thousands of
// points asks hundreds of thousands of level lines, each meeting a few
// elements.
class ExtentIndex {
  public:
    void build(const std::vector<Elem>& es, double pad, int axis = 1);
    bool built_for(const std::vector<Elem>& es) const {
        return src_ == es.data() && n_ == es.size();
    }
    // Appends the elements whose extent, widened by the pad, holds y.
    void query(double y, std::vector<int>& out) const;
    // Appends the elements whose extent, widened by the pad, meets [lo, hi].
    void query(double lo, double hi, std::vector<int>& out) const { meeting(0, lo, hi, out); }

  private:
    struct Node {
        double c = 0;
        int left = -1, right = -1;
        std::vector<int> by_lo, by_hi;  // the elements holding c, by rising low / falling high end
    };
    int make(std::vector<int>& ids);
    void meeting(int k, double lo, double hi, std::vector<int>& out) const;
    std::vector<Node> nodes_;
    std::vector<double> lo_, hi_;
    const Elem* src_ = nullptr;
    size_t n_ = 0;
};

// What the passes ask of F or U at every level, built once per list: the
// crossings of a level line (by_y), the boxes of its elements widened by
// 1 µm (the segments that can meet them: by_x, by_y), the ends and extremes of its
// elements along x, where a vertical's meeting with them can change (sorted:
// ends_up along +x, ends_down along -x), and their tops (widened likewise),
// highest first: which can hide a point of a pass from above.
struct ElemIndex {
    void build(const std::vector<Elem>& es);
    bool built_for(const std::vector<Elem>& es) const { return by_y.built_for(es); }
    // Appends the elements whose boxes meet b.
    void near(const geom::Box& b, std::vector<int>& out) const;
    ExtentIndex by_x, by_y;
    std::vector<geom::Box> box;
    std::vector<double> ends_up, ends_down;
    std::vector<std::pair<double, int>> tops;  // (top, element)
};

struct Material {
    std::vector<Elem> M;    // closed boundary of the material region (may be empty)
    std::vector<int> kind;  // per edge of M
    std::vector<Elem> F;    // the finished profile as called
    std::vector<Elem> U;    // curves that hold the boundary of A
    V2 t{0, 0};             // paraxial allowance: A = part swept by t (G64, G65)
    double er = 0;          // normal allowance: A = points nearer F than er (G63)
    bool normal = false;

    // The allowance: call one of these once F is set.
    void translate(const V2& allowance);
    void offset(double allowance);

    bool in_A(const V2& q) const;  // strictly inside A, or on F
    // Without allowance A is F itself: a pass stops where it meets F.
    bool zero() const { return normal ? er < geom::kTol : t.norm() < geom::kTol; }
    bool in_M(const V2& q) const;  // inside M or on its boundary
    mutable ExtentIndex m_index;   // of M, built by m_intervals when M is new
    // Of F and of U, built when first asked after translate or offset.
    mutable ElemIndex f_index, u_index;
    const ElemIndex& f_idx() const;
    const ElemIndex& u_idx() const;
};

struct Interval {
    double a = 0, b = 0;   // a < b
    int front = kProfile;  // kind of the end the tool meets first (against d)
    int back = kProfile;   // kind of the other end
};

// The parts of the line y = Y inside M, in increasing x.
std::vector<Interval> m_intervals(const Material& m, double Y, int d);
// The runs of the line y = Y outside A between x0 and x1, travelled in direction
// d (x1 lies beyond x0 in direction d); each run is (start, end) along d.
std::vector<std::pair<double, double>> free_runs(const Material& m, double Y, double x0, double x1,
                                                 int d);
// Where a pass along y = Y from x0 towards x1 (direction d) must stop so that
// its retract, straight up, stays out of A: the first x whose vertical above
// the line meets A (the point is "hidden"), or x1. What the profile hides from
// the retract side is a groove, left to G65 (000:2434-2458; pupitre-iso(5), TURNING CYCLES).
double first_hidden(const Material& m, double Y, double x0, double x1, int d);
// The part, in a frame where it lies below the profile: the profile closed by
// two verticals down from its ends and a line far below (for winding numbers).
std::vector<Elem> part_loop(const std::vector<Elem>& F);
// The segment p-q never enters A; sliding along a wall's face that takes no
// allowance is touching it, not entering.
bool seg_clear(const Material& m, const V2& p, const V2& q);

// The part of a pass along y = Y from x0 towards x1 (direction d) whose
// retract by the clearance h, straight up, stays out of A: the first run of x
// where the vertical segment of height h above the line is clear, as (start,
// end) along d; start == end when there is none. Under an undercut wall (a
// dovetail groove) or a rounded corner of a normal allowance, a pass stops
// where less than the clearance is left above it, and starts, under an
// overhang on its own side, where it is left (issue 19 item 1: no retract or
// return rapid of G65 or G63 enters the part plus its allowance).
std::pair<double, double> clear_below(const Material& m, double Y, double h, double x0, double x1,
                                      int d);
// All the runs of x between x0 and x1 where that vertical segment is clear.
std::vector<std::pair<double, double>> clear_runs(const Material& m, double Y, double h, double x0,
                                                  double x1, int d);

// Error 871 when the profile is empty or not continuous.
Error check_profile(const Profile& f);
// Error 874 when a point of the elements lies beyond the spindle axis (r < 0),
// with tr(message), a text marked with N_(), as its detail.
Error check_axis(const std::vector<Elem>& es, const char* message);

// Length-weighted centroid of elements (the point itself for a lone point).
V2 centroid(const std::vector<Elem>& es);

// Collects moves in frame coordinates and writes them in (z, r).
struct Emit {
    Frame fr;
    std::vector<Move>& out;
    V2 cur;  // frame coordinates
    void go(int g, const V2& p, bool infeed = false, double dwell = 0);
    void arc(const Elem& e);  // at feed, from cur (e.a) along e
};

}  // namespace pupitre::turning::zone
