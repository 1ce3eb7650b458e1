// Motion: G0/G1 lines, G2/G3 arcs (R or absolute centre, 20 µm rule, helix with
// the K pitch choosing the turns), G23, G52, R±, travel limits, and the time model
// (rapid per axis, G94/G95/G93, G96 integrated along the path).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/interp/plan.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

namespace {
using ::pupitre::geometry::kPi;
constexpr double kArcTolerance = 0.020;  // mm: start and end radii (004:626, 000:13249)

// The shared formatter, cut where the 64-byte buffer it replaces cut.
std::string f3(double v) {
    return fixed3(v, 63);
}

int ijk_index(int axis) {
    return axis == X ? 0 : axis == Y ? 1 : 2;
}

double linear_length(const Axes& a, const Axes& b) {
    double s = 0;
    for (int i = X; i <= W; ++i) s += (b[size_t(i)] - a[size_t(i)]) * (b[size_t(i)] - a[size_t(i)]);
    return std::sqrt(s);
}
double rotary_length(const Axes& a, const Axes& b) {
    double s = 0;
    for (int i = A; i <= C; ++i) s += (b[size_t(i)] - a[size_t(i)]) * (b[size_t(i)] - a[size_t(i)]);
    return std::sqrt(s);
}
}  // namespace

// The comparisons of travel_fault()'s loop, which finds the axis at fault,
// with the bounds' tolerance added once (update_travel), on the axes that have
// bounds: bitwise on ints, not && on bools, so no branch per axis.
bool Interpreter::inside_travel(const Axes& mach) const {
    int inside = 1;
    for (int i = 0; i < n_bounded_; ++i) {
        const size_t a = bounded_[size_t(i)];
        inside &= int(mach[a] >= travel_lo_tol_[a]) & int(mach[a] <= travel_hi_tol_[a]);
    }
    return inside;
}

bool Interpreter::travel_fault(const Axes& mach) {
    for (int a = 0; a < kAxes; ++a) {
        double v = mach[size_t(a)], lo = travel_lo_[size_t(a)], hi = travel_hi_[size_t(a)];
        if (!homed_[size_t(a)] && std::abs(v - mach_[size_t(a)]) > 1e-9) {
            // 000:13307: a programmed move of an axis whose POM is not done.
            return fail(159,
                        strf(tr("axis %c is not homed: do the POM first"), kAxisNames[size_t(a)]));
        }
        if (v >= lo - 1e-6 && v <= hi + 1e-6) continue;
        const char axis = kAxisNames[size_t(a)];
        if (a == X && m_.lathe)
            return fail(150 + a, strf(tr("%c travel limit: the move goes to %c%s on the OM scale "
                                         "(radius), beyond %s"),
                                      axis, axis, f3(v).c_str(), f3(v < lo ? lo : hi).c_str()));
        return fail(150 + a,
                    strf(tr("%c travel limit: the move goes to %c%s on the OM scale, beyond %s"),
                         axis, axis, f3(v).c_str(), f3(v < lo ? lo : hi).c_str()));
    }
    return true;
}

// Seconds to travel `len` at feed from program X (radius) xa to xb, linearly.
// Returns a negative number when the spindle is stopped under G95.
double Interpreter::feed_time(double len, double xa, double xb) {
    double unit = modal_.inch ? 25.4 : 1.0;
    if (modal_.feed_mode == 93) return 60.0 / modal_.feed;
    if (modal_.feed_mode == 94) {
        double f = std::min(modal_.feed * unit, m_.max_feed);
        return len / f * 60.0;
    }
    // G95: feed per revolution; under G96 the speed follows X (000:1538-1551;
    // pupitre-iso(5), FEEDS AND SPINDLE).
    double per_rev = modal_.feed * unit;
    if (modal_.spindle_mode != 96) {
        double n = spindle_at(xa);
        if (n <= 0) return -1;
        return len / std::min(per_rev * n, m_.rev_feed_cap()) * 60.0;
    }
    constexpr int kSteps = 16;
    double t = 0;
    for (int i = 0; i < kSteps; ++i) {
        double x = xa + (xb - xa) * (i + 0.5) / kSteps;
        double n = spindle_at(x);
        if (n <= 0) return -1;
        t += (len / kSteps) / std::min(per_rev * n, m_.rev_feed_cap()) * 60.0;
    }
    return t;
}

// A feed per minute below 1 mm/min is almost always a feed per revolution written
// without G95 (the handbook's palier %2000 and %2001): said once per run.
// Warnings 1110 (a feed move before any F: it runs at the power-on feed) and
// 1109, each once a run.
void Interpreter::check_tiny_feed() {
    if (!feed_programmed_ && !feed_before_f_warned_) {
        feed_before_f_warned_ = true;
        warn(
            err::wFeedBeforeF,
            strf(modal_.feed_mode == 95 ? tr("feed move before any F: it runs at F%s mm/rev, the "
                                             "power-on feed; program F in this block or before it")
                                        : tr("feed move before any F: it runs at F%s mm/min, the "
                                             "power-on feed; program F in this block or before it"),
                 f3(modal_.feed).c_str()));
    }
    if (modal_.feed_mode == 94 && modal_.feed < 1.0 && !tiny_feed_warned_) {
        tiny_feed_warned_ = true;
        warn(err::wTinyFeed, strf(tr("F%s in G94 is %s mm/min: a feed per revolution needs G95"),
                                  f3(modal_.feed).c_str(), f3(modal_.feed).c_str()));
    }
}

double Interpreter::feed_rate(double& rpm_out) {
    double unit = modal_.inch ? 25.4 : 1.0;
    rpm_out = spindle_at(prog_[X]);
    if (modal_.feed_mode == 95) return std::min(modal_.feed * unit * rpm_out, m_.rev_feed_cap());
    return std::min(modal_.feed * unit, m_.max_feed);
}

// Warning 1112: R, I, J or K left in a G0/G1 block that is no PGP element and
// no cycle moves nothing (usually a G2/G3 left out).
void Interpreter::warn_idle_words(const Plan& p) {
    std::string w;
    if (p.to.has_r) w += " R";
    for (int k = 0; k < 3; ++k)
        if (p.to.ijk[size_t(k)]) w += std::string(" ") + char('I' + k);
    if (w.empty() || p.g[23]) return;
    warn(err::wIdleWord, strf(trn("word%s has no effect in a G%d block: the move is a straight "
                                  "line (a circle needs G2 or G3)",
                                  "words%s has no effect in a G%d block: the move is a straight "
                                  "line (a circle needs G2 or G3)",
                                  w.size() / 2),
                              w.c_str(), modal_.motion));
}

// The target of a block in program coordinates: its axis words over the
// current position.
inline Axes Interpreter::target_of(const Target& to) const {
    Axes target = prog_;
    for (size_t a = 0; a < size_t(kAxes); ++a)
        if (to.axis[a]) target[a] = to.inc[a] ? prog_[a] + to.val[a] : to.val[a];
    return target;
}

// The motion of a block (pupitre-iso(5), MODAL STATE AND THE ORDER INSIDE A
// BLOCK, the motion): a cycle, a profile element or a move.
bool Interpreter::do_motion(const Plan& p) {
    if (!motion_allowed(p)) return false;
    if (std::optional<bool> done = motion_family(p)) return *done;
    if (p.to.axis.none()) {
        bool arcwords = p.to.ijk.any() || p.to.has_r;
        if (p.g[23] || ((p.mode.motion == 2 || p.mode.motion == 3) && arcwords))
            return fail(101, tr("circle without its end point"));
        return true;
    }
    const bool g52 = p.g[52];
    if ((p.to.has_r || p.to.ijk.any()) && (modal_.motion == 0 || modal_.motion == 1))
        warn_idle_words(p);
    if (first_move_ && p.to.inc.any())
        warn(err::wIncrementalFirst,
             tr("first move written in G91: relative to the position after homing"));
    first_move_ = false;
    if (p.to.axis[X] && !g52) modal_.css_known = true;
    if (g52) return g52_move(p);
    return move_to(p.to, p.g[23]);
}

// The move itself: the target over the current position, then the line, the
// circle or the compensated element.
bool Interpreter::move_to(const Target& to, bool g23) {
    apply_corrector_gauges(to.axis);
    Axes target = target_of(to);
    if (comp_.on && modal_.radcomp == 40) return comp_exit(&target);
    if (g23) return arc3(to, target);
    if (modal_.motion == 2 || modal_.motion == 3) return arc(to, target);
    if (comp_.on) return comp_line(to, target);
    return straight(to, target);
}

// Under compensation (the callers ask), a third block in a row without
// motion in the plane is refused.
bool Interpreter::count_plane_motion(const std::bitset<kAxes>& axis) {
    int a0 = m_.lathe ? Z : modal_.plane == 17 ? X : modal_.plane == 18 ? Z : Y;
    int a1 = m_.lathe ? X : modal_.plane == 17 ? Y : modal_.plane == 18 ? X : Z;
    if (axis[size_t(a0)] || axis[size_t(a1)]) {
        nonmotion_in_comp_ = 0;
    } else if (++nonmotion_in_comp_ > 2) {
        return fail(140, tr("more than 2 blocks in a row without motion in the plane under "
                            "radius compensation"));
    }
    return true;
}

// What a block may not do before it moves: a third block without motion in
// the plane under compensation, a G52 move that cannot be made.
inline bool Interpreter::motion_allowed(const Plan& p) {
    const bool comp = modal_.radcomp != 40;
    if (comp && !count_plane_motion(p.to.axis)) return false;
    if (p.g[52]) {
        if (comp) return fail(27, tr("G52 move under radius compensation (program G40 first)"));
        if (modal_.incremental) return fail(3, tr("G52 needs absolute programming (G90)"));
        if (modal_.motion == 2 || modal_.motion == 3)
            return fail(3, tr("G52 moves are linear (G0 or G1)"));
    }
    return true;
}

// The blocks that a family of functions runs: G29, the end of a compensated
// profile, splines, turning cycles, pockets, drilling cycles and PGP.  No
// value: the block is a plain move.
inline std::optional<bool> Interpreter::motion_family(const Plan& p) {
    const bool g52 = p.g[52];
    if (modal_.radcomp == 29 && !g52) return g29_move(p);
    // The end of a compensated profile: held PGP elements are resolved first.
    if (comp_.on && modal_.radcomp == 40 && pgp_.pending() && !pgp_close()) return false;
    if (comp_.on && modal_.radcomp == 40 && p.to.axis.none()) return comp_exit(nullptr);
    if (p.g[6]) return spline_run(p);
    if (p.g[33] || p.g[63] || p.g[64] || p.g[65] || p.g[66] ||
        (modal_.motion == 38 && p.to.axis.any())) {
        first_move_ = false;
        return turning_block(p);
    }
    if (p.g[45]) {
        if (p.to.axis.any()) apply_corrector_gauges(p.to.axis);
        first_move_ = false;
        return pocket(p);
    }
    if (p.g[31] || (modal_.cycle >= 81 && modal_.cycle <= 89)) {
        if (g52) return fail(3, tr("G52 in a drilling cycle block"));
        if (p.to.axis.any()) apply_corrector_gauges(p.to.axis);
        first_move_ = false;
        return cycle_block(p);
    }
    if (!g52 && !(comp_.on && modal_.radcomp == 40) && pgp_wanted(p)) return pgp_motion(p);
    return std::nullopt;
}

// A block while PGP may hold elements: an element in the plane, or a move out
// of it made when the held elements are out.
inline bool Interpreter::pgp_motion(const Plan& p) {
    int a0, a1;
    plane_axes(a0, a1);
    if (p.pgp.any || p.to.axis[size_t(a0)] || p.to.axis[size_t(a1)] || p.to.ijk.any() ||
        p.to.has_r) {
        const Axes target = target_of(p.to);
        if (p.to.axis.any()) apply_corrector_gauges(p.to.axis);
        first_move_ = false;
        return pgp_block(p, target);
    }
    if (Error e = pgp_.idle()) return fail(e);  // at the block that overflows
    if (p.to.axis.any()) return comp_other_axes(target_of(p.to), p.to.axis);
    return true;
}

// G52: a move in machine coordinates.  With G40 in the same block (the book's
// own form, %222 N170) the compensated profile ends at its last point first.
inline bool Interpreter::g52_move(const Plan& p) {
    if (comp_.on && !comp_exit(nullptr)) return false;
    Axes mach = mach_;
    for (size_t a = 0; a < size_t(kAxes); ++a)
        if (p.to.axis[a]) mach[a] = p.to.val[a];
    if (!check_travel(mach)) return false;
    if (!linear(modal_.motion, mach, true, p.to.axis)) return false;
    // G96 starts again from the recomputed program X (000:1538-1551;
    // pupitre-iso(5), FEEDS AND SPINDLE).
    modal_.css_x0 = modal_.css_pos0 = prog_[X];
    return true;
}

// A straight move under radius compensation: an element of the profile, or
// a move of the other axes only.
inline bool Interpreter::comp_line(const Target& to, const Axes& target) {
    comp::V2 s(prog_[size_t(comp_.a0)], prog_[size_t(comp_.a1)]);
    comp::V2 e(target[size_t(comp_.a0)], target[size_t(comp_.a1)]);
    if ((e - s).norm() > 1e-9 ||
        (comp_.waiting_entry && (to.axis[size_t(comp_.a0)] || to.axis[size_t(comp_.a1)]))) {
        comp::Elem line;
        line.a = s;
        line.b = e;
        return comp_element(line, modal_.motion, target, 0);
    }
    return comp_other_axes(target, to.axis);
}

// A straight G0/G1 move without compensation; R- stops one tool radius short
// of the point, R+ beyond it (000:4542-4592; pupitre-iso(5), MOTION).
inline bool Interpreter::straight(const Target& to, Axes target) {
    if (to.r_sign != 0 && modal_.d > 0) {
        const Corrector& c = corr_[size_t(modal_.d)];
        double r = c.r + (m_.lathe ? 0 : c.dr);
        double len = linear_length(prog_, target);
        if (len > 1e-9)
            for (int a = X; a <= W; ++a)
                target[size_t(a)] += to.r_sign * r * (target[size_t(a)] - prog_[size_t(a)]) / len;
    }
    Axes mach = frames_.to_machine(target);
    if (frames_.ed == 0)
        for (int a = 0; a < kAxes; ++a)
            if (!to.axis[size_t(a)] && !frames_.mirror[size_t(a)])
                mach[size_t(a)] = mach_[size_t(a)];
    if (!check_travel(mach)) return false;
    prog_next_ = target;
    return linear(modal_.motion, mach, false, to.axis);
}

// G29, tool correction in space (000:3545, 004:697-699; pupitre-iso(5), G29):
// each block gives a contact point X Y Z on the surface and the unit normal P Q
// R pointing from the material to the tool; the tool tip goes where a torus
// cutter of radius R and end radius @ touches that point:
//   Ct = Pc + @ N;  w = unit(N - (N.u) u);  Oc = Ct + (R - @) w;  tip = Oc - @ u.
bool Interpreter::g29_move(const Plan& p) {
    if (p.to.axis.none() && p.g29.has.none()) return true;
    if (!(p.to.axis[X] && p.to.axis[Y] && p.to.axis[Z]) || p.g29.has.count() != 3)
        return fail(146, tr("a G29 block needs all of X Y Z and P Q R (000:13291)"));
    if (modal_.motion != 0 && modal_.motion != 1)
        return fail(146, tr("G29 blocks are linear moves (G0 or G1)"));
    Eigen::Vector3d n(p.g29.n[0], p.g29.n[1], p.g29.n[2]);
    if (std::fabs(n.squaredNorm() - 1) > 1e-3)
        return fail(145, strf(tr("P Q R is not a unit vector: P2+Q2+R2 = %s (000:13290)"),
                              f3(n.squaredNorm()).c_str()));
    n.normalize();
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    u[modal_.tool_axis == X ? 0 : modal_.tool_axis == Y ? 1 : 2] = modal_.tool_axis_neg ? -1 : 1;
    const Corrector& c = corr_[size_t(std::max(modal_.d, 0))];
    double r = c.r + c.dr, tip_r = c.tip;
    if (tip_r > r) return fail(146, tr("the end radius @ is larger than the tool radius R"));
    Eigen::Vector3d pc;
    for (int a = 0; a < 3; ++a)
        pc[a] = p.to.inc[size_t(a)] ? prog_[size_t(a)] + p.to.val[size_t(a)] : p.to.val[size_t(a)];
    Eigen::Vector3d w = n - n.dot(u) * u;
    w = w.norm() > 1e-12 ? Eigen::Vector3d(w.normalized()) : Eigen::Vector3d::Zero();
    Eigen::Vector3d tip = pc + tip_r * n + (r - tip_r) * w - tip_r * u;
    first_move_ = false;
    apply_corrector_gauges(p.to.axis);
    Axes target = prog_;
    for (int a = 0; a < kAxes; ++a)
        if (p.to.axis[size_t(a)])
            target[size_t(a)] = a < 3
                                    ? tip[a]
                                    : (p.to.inc[size_t(a)] ? prog_[size_t(a)] + p.to.val[size_t(a)]
                                                           : p.to.val[size_t(a)]);
    Axes mach = frames_.to_machine(target);
    if (!check_travel(mach)) return false;
    prog_next_ = target;
    return linear(modal_.motion, mach, false, p.to.axis);
}

bool Interpreter::linear(int g, const Axes& mach, bool g52, const std::bitset<kAxes>&) {
    MoveEvent e;
    e.loc = loc_;
    e.g = g == 0 ? 0 : 1;
    e.g52 = g52;
    e.x_diameter = m_.lathe && m_.x_diameter && !modal_.radius_x;
    e.from_mach = mach_;
    e.to_mach = mach;
    e.eg = modal_.eg;
    e.min_block = min_block_;
    double len = linear_length(mach_, mach);
    double rot = rotary_length(mach_, mach);
    e.length = len > 1e-12 ? len : rot;
    Axes start_prog = prog_;
    Axes end_prog = g52 ? frames_.to_program(mach) : prog_next_;
    double t;
    if (e.g == 0) {
        t = 0;
        for (int a = 0; a < kAxes; ++a)
            if (m_.has(a))
                t = std::max(
                    t, std::fabs(mach[size_t(a)] - mach_[size_t(a)]) / m_.axes[size_t(a)].rapid);
        t *= 60.0;
        e.feed = t > 0 ? e.length / t * 60.0 : 0;
        e.rpm = spindle_at(prog_[X]);
    } else {
        if (!modal_.feed_set)
            return fail(
                2, strf(tr("no feed F programmed since G%d changed the unit"), modal_.feed_mode));
        if (modal_.feed <= 0) return fail(1, tr("feed F0 in a feed move"));
        if (modal_.feed_mode == 94 && modal_.feed * (modal_.inch ? 25.4 : 1) > m_.max_feed)
            warn(err::wFeedClamped,
                 strf(tr("F%s above the machine maximum %s mm/min: limited to it"),
                      f3(modal_.feed).c_str(), f3(m_.max_feed).c_str()));
        check_tiny_feed();
        e.feed = feed_rate(e.rpm);
        t = feed_time(e.length, start_prog[X], end_prog[X]);
        if (t < 0) return fail(831, tr("feed per revolution (G95) with the spindle stopped"));
        if (modal_.feed_mode == 93) e.feed = t > 0 ? e.length / t * 60.0 : 0;
    }
    return finish_move(e, mach, end_prog, t);
}

// Books a move: the machine is there, the clock and the path advance, the sink hears.
bool Interpreter::finish_move(MoveEvent& e, const Axes& mach, const Axes& prog, double seconds) {
    // The move budget holds within a block too: one cycle block whose
    // arguments ask for millions of passes stops here, not after them.
    if (moves_ >= 2 * opt_.max_blocks)
        return fail(err::kBlockBudget, strf(tr("more than %ld moves made: endless loop? (G79/G77)"),
                                            2 * opt_.max_blocks));
    e.seconds = seconds;
    e.to_prog = prog;
    e.comp = comp_emitting_;
    mach_ = mach;
    prog_ = prog;
    path_ += e.length;
    clock_ += seconds;
    ++moves_;
    out_.move(e);
    if (modal_.spindle_mode == 96) set_spindle_event();  // the speed followed X
    return true;
}

bool Interpreter::arc(const Target& to, const Axes& target) {
    const bool lathe = m_.lathe;
    ArcAxes ax;
    ax.a0 = lathe ? Z : modal_.plane == 17 ? X : modal_.plane == 18 ? Z : Y;
    ax.a1 = lathe ? X : modal_.plane == 17 ? Y : modal_.plane == 18 ? X : Z;
    ax.an = lathe ? Y : modal_.plane == 17 ? Z : modal_.plane == 18 ? Y : X;
    ax.i0 = ijk_index(ax.a0), ax.i1 = ijk_index(ax.a1), ax.in = ijk_index(ax.an);
    ax.helix = !lathe && to.axis[size_t(ax.an)];
    if (!arc_words(to, ax)) return false;
    const Eigen::Vector2d s(prog_[size_t(ax.a0)], prog_[size_t(ax.a1)]);
    const Eigen::Vector2d e(target[size_t(ax.a0)], target[size_t(ax.a1)]);
    const bool ccw = modal_.motion == 3;
    Eigen::Vector2d c;
    double r0 = 0, r1 = 0;
    if (!arc_centre(to, ax, s, e, c, r0, r1)) return false;
    double sw = arc_sweep(s, e, c, ccw);
    if (ax.helix && to.ijk[size_t(ax.in)])
        sw += (ccw ? 1 : -1) * 2 * kPi *
              helix_turns(std::fabs(target[size_t(ax.an)] - prog_[size_t(ax.an)]),
                          std::fabs(to.ijk_val[ax.in]), std::fabs(sw) * 180 / kPi);
    if (comp_.on)
        return comp_element(comp::Elem{.arc = true, .a = s, .b = e, .c = c, .sweep = sw},
                            modal_.motion, target, r0);
    return emit_arc(modal_.motion, target, ax.a0, ax.a1, c.x(), c.y(), sw, r0, r1,
                    ax.helix ? ax.an : -1);
}

// The words a G2/G3 block needs: both coordinates of the plane, and either
// the centre or R; only the normal axis may move (a helix).
inline bool Interpreter::arc_words(const Target& to, const ArcAxes& ax) {
    const int a0 = ax.a0, a1 = ax.a1, an = ax.an, i0 = ax.i0, i1 = ax.i1, in = ax.in;
    bool centre = to.ijk[size_t(i0)] && to.ijk[size_t(i1)];
    if (!to.axis[size_t(a0)] || !to.axis[size_t(a1)] || centre == to.has_r) {
        return fail(
            101, strf(tr("G%d needs %c%c and either %c%c or R, even if unchanged"), modal_.motion,
                      kAxisNames[size_t(a0)], kAxisNames[size_t(a1)], 'I' + i0, 'I' + i1));
    }
    for (int a = 0; a < kAxes; ++a)
        if (to.axis[size_t(a)] && a != a0 && a != a1 && (m_.lathe || a != an))
            return fail(106, strf(tr("axis %c in a circle: only the axis normal to the plane may "
                                     "move (helix)"),
                                  kAxisNames[size_t(a)]));
    if (to.ijk[size_t(in)] && !ax.helix)
        return fail(107, strf(tr("helix pitch %c without the %c end point"), 'I' + in,
                              kAxisNames[size_t(an)]));
    return true;
}

// The centre and the radii at both ends, from R (the shorter arc) or from
// the centre words.
inline bool Interpreter::arc_centre(const Target& to, const ArcAxes& ax, const comp::V2& s,
                                    const comp::V2& e, comp::V2& c, double& r0, double& r1) {
    if (to.has_r) {
        double d = (e - s).norm();
        double r = to.r;
        if (r <= 0) return fail(107, tr("circle radius R must be positive"));
        if (d < 1e-9) return fail(107, tr("circle with R: the end point equals the start point"));
        if (d > 2 * r + 0.001)
            return fail(107, strf(tr("circle end point too far: chord %s > 2R %s"), f3(d).c_str(),
                                  f3(2 * r).c_str()));
        // The shorter arc (004:622): the centre on the left of the chord for G3.
        double h = std::sqrt(std::max(0.0, r * r - d * d / 4));
        Eigen::Vector2d left(-(e - s).y() / d, (e - s).x() / d);
        c = (s + e) / 2 + (modal_.motion == 3 ? h : -h) * left;
        r0 = r1 = r;
        return true;
    }
    c = Eigen::Vector2d(to.ijk_val[ax.i0], to.ijk_val[ax.i1]);
    if (to.ijk_inc[size_t(ax.i0)]) c.x() += s.x();
    if (to.ijk_inc[size_t(ax.i1)]) c.y() += s.y();
    r0 = (s - c).norm();
    r1 = (e - c).norm();
    if (r0 < 1e-9) return fail(107, tr("circle centre on the start point"));
    if (std::fabs(r0 - r1) > kArcTolerance + 1e-9)
        return fail(107, strf(tr("circle end point inconsistent: start radius %s, end radius %s "
                                 "(more than 0.020 apart)"),
                              f3(r0).c_str(), f3(r1).c_str()));
    return true;
}

// The signed sweep from s to e about c: a full turn when they meet.
inline double Interpreter::arc_sweep(const comp::V2& s, const comp::V2& e, const comp::V2& c,
                                     bool ccw) {
    // One atan2 of the angle between the radii, not two (issue 14: the
    // arcs' atan2 were a tenth of a run).
    const comp::V2 u = s - c, v = e - c;
    double sw = std::atan2(u.x() * v.y() - u.y() * v.x(), u.x() * v.x() + u.y() * v.y());
    bool full = (e - s).norm() < 1e-7;
    if (ccw) {
        while (sw <= 1e-12) sw += 2 * kPi;
        if (full) sw = 2 * kPi;
    } else {
        while (sw >= -1e-12) sw -= 2 * kPi;
        if (full) sw = -2 * kPi;
    }
    return sw;
}

// The extra turns of a helix: the number whose pitch is nearest the
// programmed one (000:4745, 004:628).  dz: the rise, k: the pitch, th0: the
// sweep in degrees.
int Interpreter::helix_turns(double dz, double k, double th0) {
    if (dz <= 1e-9 || k <= 1e-9) return 0;
    int best = 0;
    double err = 1e300;
    for (int n = 0; n < 100000; ++n) {
        double pitch = dz * 360.0 / (th0 + 360.0 * n);
        double d = std::fabs(pitch - k);
        if (d >= err) break;  // |pitch - k| decreases then increases
        err = d;
        best = n;
    }
    return best;
}

bool Interpreter::arc3(const Target& to, const Axes& target) {
    const bool lathe = m_.lathe;
    int a0 = lathe ? Z : modal_.plane == 17 ? X : modal_.plane == 18 ? Z : Y;
    int a1 = lathe ? X : modal_.plane == 17 ? Y : modal_.plane == 18 ? X : Z;
    int i0 = ijk_index(a0), i1 = ijk_index(a1);
    if (!to.axis[size_t(a0)] || !to.axis[size_t(a1)] || !to.ijk[size_t(i0)] || !to.ijk[size_t(i1)])
        return fail(101, tr("G23 needs the end point and the intermediate point"));
    Eigen::Vector2d s(prog_[size_t(a0)], prog_[size_t(a1)]),
        e(target[size_t(a0)], target[size_t(a1)]);
    Eigen::Vector2d m(to.ijk_val[i0], to.ijk_val[i1]);
    if (to.ijk_inc[size_t(i0)]) m.x() += s.x();
    if (to.ijk_inc[size_t(i1)]) m.y() += s.y();
    Eigen::Vector2d u = m - s, v = e - s;
    double cross = u.x() * v.y() - u.y() * v.x();
    if (std::fabs(cross) < 1e-9) return fail(101, tr("G23: the three points are on one line"));
    // Circumcentre of s, m, e.
    double uu = u.squaredNorm(), vv = v.squaredNorm();
    Eigen::Vector2d c =
        s + Eigen::Vector2d(v.y() * uu - u.y() * vv, u.x() * vv - v.x() * uu) / (2 * cross);
    double r = (s - c).norm();
    // Through m from s to e: counter-clockwise when m is left of s->e.
    bool ccw = cross > 0;
    double as = std::atan2(s.y() - c.y(), s.x() - c.x());
    double ae = std::atan2(e.y() - c.y(), e.x() - c.x());
    double sw = ae - as;
    if (ccw) {
        while (sw <= 0) sw += 2 * kPi;
    } else {
        while (sw >= 0) sw -= 2 * kPi;
    }
    if (comp_.on)
        return comp_element(comp::Elem{.arc = true, .a = s, .b = e, .c = c, .sweep = sw},
                            ccw ? 3 : 2, target, r);
    return emit_arc(ccw ? 3 : 2, target, a0, a1, c.x(), c.y(), sw, r, r, -1);
}

bool Interpreter::emit_arc(int g, const Axes& target, int a0, int a1, double c0, double c1,
                           double sw, double r0, double r1, int helix_axis) {
    Axes mach = frames_.to_machine(target);
    if (frames_.ed == 0)
        for (int a = 0; a < kAxes; ++a)
            if (a != a0 && a != a1 && a != helix_axis && !frames_.mirror[size_t(a)])
                mach[size_t(a)] = mach_[size_t(a)];
    if (!check_travel(mach)) return false;
    // The circle's extremes must be inside the travel too.
    Axes cm = prog_;
    bool flip = false;
    {
        cm[size_t(a0)] = c0;
        cm[size_t(a1)] = c1;
        if (frames_.translation_only()) {  // the two axes used, as to_machine would
            cm[size_t(a0)] += frames_.shift(a0);
            cm[size_t(a1)] += frames_.shift(a1);
        } else {
            cm = frames_.to_machine(cm);
        }
        double mx = mach_[size_t(a0)] - cm[size_t(a0)], my = mach_[size_t(a1)] - cm[size_t(a1)];
        const double dist = std::sqrt(mx * mx + my * my);  // a margin: hypot's care is not needed
        double rm = dist + std::fabs(r1 - r0);
        bool inside = cm[size_t(a0)] - rm >= travel_lo_[size_t(a0)] &&
                      cm[size_t(a0)] + rm <= travel_hi_[size_t(a0)] &&
                      cm[size_t(a1)] - rm >= travel_lo_[size_t(a1)] &&
                      cm[size_t(a1)] + rm <= travel_hi_[size_t(a1)];
        rm = dist;
        double am = inside ? 0 : std::atan2(my, mx);
        flip = frames_.mirror[size_t(a0)] != frames_.mirror[size_t(a1)];
        double swm = flip ? -sw : sw;
        Axes probe = mach;
        // Quadrant points (0°, 90°, 180°, 270°) crossed by the swept angle.
        double span = std::fabs(swm);
        for (int q = 0; q < (inside ? 0 : 4); ++q) {
            double rel = q * kPi / 2 - am;
            if (swm < 0) rel = -rel;
            rel -= 2 * kPi * std::floor(rel / (2 * kPi));
            if (rel > span) continue;
            static constexpr double kCos[] = {1, 0, -1, 0}, kSin[] = {0, 1, 0, -1};
            probe[size_t(a0)] = cm[size_t(a0)] + rm * kCos[q];
            probe[size_t(a1)] = cm[size_t(a1)] + rm * kSin[q];
            if (probe[size_t(a0)] < travel_lo_[size_t(a0)] - 1e-6 ||
                probe[size_t(a0)] > travel_hi_[size_t(a0)] + 1e-6 ||
                probe[size_t(a1)] < travel_lo_[size_t(a1)] - 1e-6 ||
                probe[size_t(a1)] > travel_hi_[size_t(a1)] + 1e-6)
                if (!check_travel(probe)) return false;
        }
    }
    MoveEvent e;
    e.loc = loc_;
    e.g = g;
    e.from_mach = mach_;
    e.to_mach = mach;
    e.plane_a0 = a0;
    e.plane_a1 = a1;
    e.c0 = c0;
    e.c1 = c1;
    e.sweep = sw * 180 / kPi;
    e.mc0 = cm[size_t(a0)];
    e.mc1 = cm[size_t(a1)];
    e.msweep = flip ? -e.sweep : e.sweep;
    e.eg = modal_.eg;
    e.min_block = min_block_;
    e.x_diameter = m_.lathe && m_.x_diameter && !modal_.radius_x;
    double scale = frames_.scale_on ? frames_.scale : 1.0;
    double arclen = std::fabs(sw) * (r0 + r1) / 2 * scale;
    double dh =
        helix_axis >= 0 ? std::fabs(mach[size_t(helix_axis)] - mach_[size_t(helix_axis)]) : 0;
    e.length = dh == 0 ? arclen : std::hypot(arclen, dh);
    if (!modal_.feed_set)
        return fail(2,
                    strf(tr("no feed F programmed since G%d changed the unit"), modal_.feed_mode));
    if (modal_.feed <= 0) return fail(1, tr("feed F0 in a feed move"));
    if (modal_.feed_mode == 93)
        return fail(4, tr("G02/G03 are not allowed in inverse-time feed (G93)"));
    check_tiny_feed();
    e.feed = feed_rate(e.rpm);
    double t = 0;
    if (modal_.feed_mode == 95 && modal_.spindle_mode == 96) {
        // X changes along the arc: integrate piece by piece.
        constexpr int kPieces = 16;
        double as = std::atan2(prog_[size_t(a1)] - c1, prog_[size_t(a0)] - c0);
        for (int i = 0; i < kPieces; ++i) {
            auto x_at = [&](double f) {
                double ang = as + sw * f, r = r0 + (r1 - r0) * f;
                if (a0 == X) return c0 + r * std::cos(ang);
                if (a1 == X) return c1 + r * std::sin(ang);
                return prog_[X];
            };
            double piece = feed_time(e.length / kPieces, x_at(double(i) / kPieces),
                                     x_at(double(i + 1) / kPieces));
            if (piece < 0)
                return fail(831, tr("feed per revolution (G95) with the spindle stopped"));
            t += piece;
        }
    } else {
        t = feed_time(e.length, prog_[X], target[X]);
        if (t < 0) return fail(831, tr("feed per revolution (G95) with the spindle stopped"));
    }
    if (modal_.feed_mode == 94 && modal_.feed * (modal_.inch ? 25.4 : 1) > m_.max_feed)
        warn(err::wFeedClamped, strf(tr("F%s above the machine maximum %s mm/min: limited to it"),
                                     f3(modal_.feed).c_str(), f3(m_.max_feed).c_str()));
    return finish_move(e, mach, target, t);
}

}  // namespace pupitre
