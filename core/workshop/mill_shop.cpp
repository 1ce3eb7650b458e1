// The workshop on a machining centre (issue 15): the moves of the spindle's
// gauge line become the true cutter's, which cuts the block, stops a jog at
// a contact and crashes into the vice, the plate, a pin, the table or the
// tool setter (see workshop.hpp, mill_part.hpp, pupitre-setup(5)).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/numfmt.hpp"
#include "core/workshop/tilt.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::workshop {

namespace {

constexpr double kFar = 1e5;  // mm: beyond any workshop

P3 lerp(const P3& a, const P3& b, double f) {
    return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

// A cutter grown by `g` (cutter(g)) has its tip `g` further down its axis.
P3 below(const P3& p, double g, const P3& u = kUp) {
    return {p[0] - g * u[0], p[1] - g * u[1], p[2] - g * u[2]};
}

double dist(const P3& a, const P3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

P3 plus(const P3& a, const P3& d) {
    return {a[0] + d[0], a[1] + d[1], a[2] + d[2]};
}

// `g` mm from a towards b; nothing when they are one point.
P3 along(const P3& a, const P3& b, double g) {
    const double l = dist(a, b);
    if (!(l > 0)) return {0, 0, 0};
    return {g * (b[0] - a[0]) / l, g * (b[1] - a[1]) / l, g * (b[2] - a[2]) / l};
}

bool overlap(const Box3& p, const Box3& q) {
    for (int k = 0; k < 3; ++k)
        if (p.hi[k] < q.lo[k] || p.lo[k] > q.hi[k]) return false;
    return true;
}

// Whether `part` swept from a to b can come near the box at all.
bool may_meet(const Cutter& c, Part part, const P3& a, const P3& b, const Box3& box,
              const P3& u = kUp) {
    if (leans(u)) {
        const double top = followed(c, part);
        Box3 s = tilt::part_box(c, part, a, u, top);
        const Box3 t = tilt::part_box(c, part, b, u, top);
        for (int k = 0; k < 3; ++k)
            s.lo[k] = std::min(s.lo[k], t.lo[k]) - 1e-3,
            s.hi[k] = std::max(s.hi[k], t.hi[k]) + 1e-3;
        return overlap(s, box);
    }
    const PartSpan s = span_of(c, part);
    const double r = s.radius + 1e-3;
    return std::min(a[0], b[0]) - r <= box.hi[0] && std::max(a[0], b[0]) + r >= box.lo[0] &&
           std::min(a[1], b[1]) - r <= box.hi[1] && std::max(a[1], b[1]) + r >= box.lo[1] &&
           std::min(a[2], b[2]) + s.base <= box.hi[2] && std::max(a[2], b[2]) + s.top >= box.lo[2];
}

// The first fraction of a->b where `depth_at` exceeds `depth`: marched in
// steps of 0.25 mm (nothing a workshop holds is thinner), then bisected to
// 0.1 µm of travel; 2 when never.
template <class F>
double marched(const P3& a, const P3& b, double depth, bool before, F depth_at) {
    const double len = dist(a, b);
    if (depth_at(a) > depth) return 0;
    const int steps = std::max(1, int(std::ceil(len / 0.25)));
    double prev = 0;
    for (int k = 1; k <= steps; ++k) {
        const double f = double(k) / steps;
        if (depth_at(lerp(a, b, f)) <= depth) {
            prev = f;
            continue;
        }
        double lo = prev, hi = f;
        for (int i = 0; i < 60 && (hi - lo) * len > 1e-4; ++i) {
            const double mid = (lo + hi) / 2;
            (depth_at(lerp(a, b, mid)) > depth ? hi : lo) = mid;
        }
        return before ? lo : hi;
    }
    return 2;
}

constexpr Part kParts[] = {Part::flute, Part::shank, Part::holder};

}  // namespace

// A point of the tool seen from the workshop: the tip of the cutter grown by
// `g` for a contact.
P3 Workshop::grown_tip(const Axes& om, double g) const {
    const Pose p = pose3(om, true);
    return below(p.tip, g, p.u);
}

// The fixtures of the setup, built once by the constructor.
void Workshop::mill_fixtures() {
    const MillSetup& m = setup_.mill;
    const double cx = m.stock_x + m.length / 2, jw = m.jaw_width / 2, th = m.jaw_thickness;
    const double y0 = m.stock_y, y1 = m.stock_y + m.width;
    auto box = [&](Met what, const Box3& b) { fixtures_.push_back({what, b, std::nullopt}); };
    auto pin = [&](Met what, const Cylinder& k) {
        fixtures_.push_back(
            {what,
             {{k.x - k.radius, k.y - k.radius, k.z0}, {k.x + k.radius, k.y + k.radius, k.z1}},
             k});
    };
    box(Met::table, {{-kFar, -kFar, m.table_z - 100}, {kFar, kFar, m.table_z}});
    if (m.holding == "vice") {
        const double top = m.stock_z + m.jaw_height;
        box(Met::vice, {{cx - jw, y1, m.table_z}, {cx + jw, y1 + th, top}});  // fixed, at +Y
        box(Met::vice, {{cx - jw, y0 - th, m.table_z}, {cx + jw, y0, top}});  // moving
        if (m.stock_z > m.table_z + 1e-9)  // the body and parallels under the block
            box(Met::vice, {{cx - jw, y0, m.table_z}, {cx + jw, y1, m.stock_z}});
    } else if (m.holding == "plate" && m.stock_z > m.table_z + 1e-9) {
        const double g = m.plate_margin;
        box(Met::plate,
            {{m.stock_x - g, y0 - g, m.table_z}, {m.stock_x + m.length + g, y1 + g, m.stock_z}});
    }
    for (const Pin& p : m.pins)
        pin(Met::pin, {p.x, p.y, p.diameter / 2, m.table_z, m.stock_z + p.height});
    if (m.setter)
        pin(Met::setter, {m.setter_x, m.setter_y, m.setter_diameter / 2, m.table_z, m.setter_z});
    mill_ = std::make_unique<MillWorld>(
        Box3{{m.stock_x, m.stock_y, m.stock_z},
             {m.stock_x + m.length, m.stock_y + m.width, m.stock_z + m.height}},
        m.cell);
}

Cutter Workshop::cutter(double grow) const {
    Cutter c;
    const Tool* t = current();
    if (!t) return c;
    const ToolTruth& tt = *t->truth;
    // Wear takes the cutter's side and end back alike (pupitre-setup(5)).
    const double w = tt.wear > 0 ? tt.wear * 1e-3 * (t->cut / 1000) : 0;
    c.radius = std::max(0.0, tt.radius - w) + grow;
    c.corner = std::min(c.radius, tt.corner + grow);
    c.flute = tt.flute > 0 ? tt.flute : std::max(10.0, 4 * tt.radius);
    c.reach = std::max(c.flute, tt.reach > 0 ? tt.reach : c.flute + 10);
    c.holder = std::max(c.radius, tt.holder_diameter / 2 + grow);
    return c;
}

// The tool in the table's frame (the tool frame in the part's of course
// notes 004 §5, core/geometry/kinematics.cpp):
//  - a B head (mill5, forward5: Rot_Y(B) about the head's axis, `pivot`
//    above the gauge line) swings the tool about that axis;
//  - a B table (mill4, forward4: Rot_Y(B) about the table's axis) tilts the
//    part, so the tool is the machine's, turned by B about that axis;
//  - a C table (mill5: Rot_Z(C) about the table's axis) carries the part
//    round, so the tool is turned by C about that axis.
Workshop::Pose Workshop::pose3(const Axes& om, bool turned) const {
    const Tool* t = current();
    double length = 0;
    if (t) {
        const ToolTruth& tt = *t->truth;
        length = tt.length - (tt.wear > 0 ? tt.wear * 1e-3 * (t->cut / 1000) : 0);
    }
    Pose p{{om[X], om[Y], om[Z] - length}, kUp};
    if (!turned) return p;
    const MillSetup& ms = setup_.mill;
    if (m_.has(B) && om[B] != 0) {
        const double a = om[B] * geometry::kDeg, cb = std::cos(a), sb = std::sin(a);
        p.u = {sb, 0, cb};
        if (m_.kinematics == "table") {
            const double dx = p.tip[0] - ms.b_x, dz = p.tip[2] - ms.b_z;
            p.tip[0] = ms.b_x + cb * dx + sb * dz;
            p.tip[2] = ms.b_z - sb * dx + cb * dz;
        } else {
            const double down = ms.pivot + length;
            p.tip[0] = om[X] - sb * down;
            p.tip[2] = om[Z] + ms.pivot - cb * down;
        }
    }
    if (m_.has(C) && om[C] != 0) {
        const double a = om[C] * geometry::kDeg, cc = std::cos(a), sc = std::sin(a);
        const double dx = p.tip[0] - ms.c_x, dy = p.tip[1] - ms.c_y;
        p.tip[0] = ms.c_x + dx * cc - dy * sc;
        p.tip[1] = ms.c_y + dx * sc + dy * cc;
        p.u = {p.u[0] * cc - p.u[1] * sc, p.u[0] * sc + p.u[1] * cc, p.u[2]};
    }
    return p;
}

P3 Workshop::tip3(const Axes& om, bool turned) const {
    return pose3(om, turned).tip;
}

P3 Workshop::axis3(const Axes& om) const {
    return pose3(om, true).u;
}

namespace {

bool turned(const MachineProfile& m, const Axes& a) {
    return (m.has(B) && a[B] != 0) || (m.has(C) && a[C] != 0);
}

}  // namespace

Axes Workshop::on_part(const Axes& om, const Axes& op) const {
    if (!mill_ || !turned(m_, om)) return op;
    const P3 at = tip3(om), flat = tip3(om, false);
    Axes p = op;
    for (int k = 0; k < 3; ++k) p[size_t(k)] += at[size_t(k)] - flat[size_t(k)];
    return p;
}

bool Workshop::on_part(const MoveEvent& e, std::vector<MoveEvent>& out) const {
    out.clear();
    if (!mill_ || (!turned(m_, e.from_mach) && !turned(m_, e.to_mach))) return false;
    std::vector<Axes> oms;
    path_of(e, oms);
    const double n = double(oms.size() - 1);
    for (size_t i = 0; i + 1 < oms.size(); ++i) {
        MoveEvent p = e;
        p.g = e.g == 0 ? 0 : 1;
        p.sweep = 0;
        p.from_mach = oms[i];
        p.to_mach = oms[i + 1];
        // The program point of that machine position (the offsets of the
        // move's end), then moved onto the part.
        Axes op = oms[i + 1];
        for (size_t k = 0; k < op.size(); ++k) op[k] -= e.to_mach[k] - e.to_prog[k];
        p.to_prog = on_part(oms[i + 1], op);
        p.length = e.length / n;
        p.seconds = e.seconds / n;
        p.piece = i > 0;
        out.push_back(p);
    }
    return true;
}

P3 Workshop::piece_axis(const Axes& from, const Axes& to) const {
    Axes mid = from;
    for (size_t i = 0; i < mid.size(); ++i) mid[i] += 0.5 * (to[i] - from[i]);
    return axis3(mid);
}

// A jog of C or B: the part turns under the tool or the tool swings, made as
// the jogs of the chords of its path, up to the first that stops.
Outcome Workshop::mill_jog_turn(const MoveEvent& e, bool continuous) {
    std::vector<Axes> oms;
    path_of(e, oms);
    const int axis = m_.has(C) && e.to_mach[C] != e.from_mach[C] ? C : B;
    const double span = e.to_mach[axis] - e.from_mach[axis];
    for (size_t i = 0; i + 1 < oms.size(); ++i) {
        MoveEvent piece = e;
        piece.g = 1;
        piece.from_mach = oms[i];
        piece.to_mach = oms[i + 1];
        Outcome o = mill_jog_line(piece, continuous);
        if (!o.crashed && !o.touched) continue;
        o.fraction = span != 0 ? (o.stop[axis] - e.from_mach[axis]) / span : 1;
        if (o.crashed) crashes_.back().fraction = o.fraction;
        return o;
    }
    return {};
}

// How deep the cutter is into anything at `tip`, and what.
double Workshop::mill_depth(const Cutter& c, const P3& tip, const P3& u, Met& what) const {
    double deepest = 0;
    what = Met::none;
    auto keep = [&](double d, Met h) {
        if (d > deepest) deepest = d, what = h;
    };
    const bool lean = leans(u);
    for (Part p : kParts) {
        keep(mill_->depth_into(c, tip, p, u), Met::material);
        if (!lean) {
            for (const Fixture& f : fixtures_) keep(f.depth(c, tip, p), f.what);
            continue;
        }
        const std::vector<P3>& points = mill_->surface_of(c, p, u);
        for (const Fixture& f : fixtures_)
            if (may_meet(c, p, tip, tip, f.box, u)) keep(f.depth(points, tip), f.what);
    }
    return deepest;
}

// The first contact along a->b deeper than `depth`: with the material
// (`with_material`: the flute too; else only the shank and the holder, the
// flute cutting) and every fixture.
Workshop::Contact Workshop::mill_first(const Cutter& c, const P3& a, const P3& b, const P3& u,
                                       double depth, bool with_material, bool before,
                                       double flute_depth) const {
    Contact k;
    auto keep = [&](double f, Met h, Part p) {
        if (f < k.f) k = Contact{f, h, p};
    };
    // A part whose lowest point stays above the block's top as loaded never
    // meets the material (most moves: the shank and holder while cutting,
    // the flute on a rapid over the part).
    const bool lean = leans(u);
    const double top = mill_->stock().hi[2] + depth;
    for (Part p : kParts) {
        const double d = p == Part::flute && flute_depth >= 0 ? flute_depth : depth;
        const double reach = followed(c, p);
        const double low = lean ? std::min(tilt::part_box(c, p, a, u, reach).lo[2],
                                           tilt::part_box(c, p, b, u, reach).lo[2])
                                : std::min(a[2], b[2]) + span_of(c, p).base;
        if ((with_material || p != Part::flute) && low < top + (d - depth))
            keep(mill_->first_contact(c, a, b, p, d, before, u), Met::material, p);
        const std::vector<P3>* points = nullptr;
        for (const Fixture& f : fixtures_) {
            if (!may_meet(c, p, a, b, f.box, u)) continue;
            if (!lean) {
                keep(marched(a, b, d, before, [&](const P3& q) { return f.depth(c, q, p); }),
                     f.what, p);
                continue;
            }
            if (!points) points = &mill_->surface_of(c, p, u);
            keep(marched(a, b, d, before, [&](const P3& q) { return f.depth(*points, q); }), f.what,
                 p);
        }
    }
    return k;
}

// Where something happened, in the part's own terms (from the block's
// corner as loaded, which does not depend on PREF).
std::string Workshop::mill_where(const P3& p) const {
    if (hide_places_) return {};
    const MillSetup& m = setup_.mill;
    // TRANSLATORS: where a crash or a contact happened on a milling machine's block.
    return strf(tr("at X%s Y%s Z%s from the block's corner"),
                fixed3_zeroed(p[0] - m.stock_x, 5e-4).c_str(),
                fixed3_zeroed(p[1] - m.stock_y, 5e-4).c_str(),
                fixed3_zeroed(p[2] - (m.stock_z + m.height), 5e-4).c_str());
}

namespace {

// A thing the cutter met, for the messages (N_-marked: translated where shown).
const char* hit_name(int h) {
    static const char* const names[] = {"",
                                        N_("the part"),
                                        N_("the vice"),
                                        N_("the plate"),
                                        N_("a locating pin"),
                                        N_("the table"),
                                        N_("the tool setter"),
                                        N_("the shim")};
    return names[h];
}

}  // namespace

std::string Workshop::mill_crash_text(int code, const Contact& c, const std::string& place) const {
    const char* p = place.c_str();
    if (code == kCrashProbe && finder())
        return strf(tr("crash: the edge finder T%d was bent against the part %s"), tool_, p);
    if (std::string s = part_crash_text(code, current()->truth->spindle, p); !s.empty()) return s;
    const char* what = tr(hit_name(int(c.what)));
    if (c.part == Part::holder)
        return strf(tr("crash: the holder of T%d hit %s %s"), tool_, what, p);
    if (c.part == Part::shank) return strf(tr("crash: the shank of T%d hit %s %s"), tool_, what, p);
    return strf(tr("crash: T%d hit %s %s"), tool_, what, p);
}

std::string Workshop::mill_touch_text(const Contact& c, const std::string& place) const {
    if (c.what == Met::shim)
        return strf(tr("T%d touched the %s mm shim on the part %s"), tool_, fixed3(shim_).c_str(),
                    place.c_str());
    const char* what = tr(hit_name(int(c.what)));
    if (c.part == Part::holder)
        return strf(tr("the holder of T%d touched %s %s"), tool_, what, place.c_str());
    if (c.part == Part::shank)
        return strf(tr("the shank of T%d touched %s %s"), tool_, what, place.c_str());
    return strf(tr("T%d touched %s %s"), tool_, what, place.c_str());
}

// One straight piece of a move, tip from a to b (the machine from oma to
// omb): cut while cutting, checked against everything; false on a crash,
// recorded with the fraction of this piece done.
bool Workshop::mill_stroke(const MoveEvent& e, const P3& a, const P3& b, const P3& u,
                           const Axes& oma, const Axes& omb) {
    Tool* t = current();
    if (!t) return true;
    const ToolTruth& tt = *t->truth;
    const bool feed = e.g != 0, stopped = dir_ != 3 && dir_ != 4;
    // An edge finder never cuts: fed into the part it is bent (1205, as a
    // probe); a rapid is any tool's 1200.
    const bool cutting =
        feed && !stopped && !tt.probe && !tt.finder && (tt.spindle == 0 || tt.spindle == dir_);
    const int flute_code = tt.probe    ? kCrashProbe
                           : !feed     ? kCrashRapid
                           : tt.finder ? kCrashProbe
                           : stopped   ? kCrashStopped
                                       : kCrashDirection;
    // Cutting deeper than the flute, the piece goes in steps of at most 1 mm
    // (half the flute for a short one). The shank and the holder are checked against the
    // material before each step is cut: plunging, they follow the flute down
    // the hole the steps before made; on a side pass deeper than the flute
    // they meet what is ahead (the material is a height field: a cut takes
    // all above the flute's bottom, so after it nothing would be left).
    const double len = dist(a, b);
    const Cutter c0 = cutter();
    const double step = std::min(1.0, c0.flute / 2);
    const double shank = leans(u) ? std::min(tilt::part_box(c0, Part::shank, a, u, c0.reach).lo[2],
                                             tilt::part_box(c0, Part::shank, b, u, c0.reach).lo[2])
                                  : std::min(a[2], b[2]) + c0.flute;
    const bool deep = shank < mill_->stock().hi[2] + kCrashDepth;
    const int steps = cutting && deep ? std::max(1, int(std::ceil(len / step))) : 1;
    for (int k = 0; k < steps; ++k) {
        const double f0 = double(k) / steps, f1 = double(k + 1) / steps;
        const P3 p = lerp(a, b, f0), q = lerp(a, b, f1);
        const Cutter c = cutter();
        const Contact hit = mill_first(c, p, q, u, kCrashDepth, !cutting, false);
        const P3 end = hit.f > 1 ? q : lerp(p, q, hit.f);
        if (cutting && mill_->cut(c, p, end, u) > 0) t->cut += dist(p, end);
        if (hit.f > 1) continue;
        mill_crash(e, flute_code, hit, a, b, oma, omb, f0 + hit.f * (f1 - f0));
        return false;
    }
    return true;
}

void Workshop::mill_crash(const MoveEvent& e, int flute_code, const Contact& hit, const P3& a,
                          const P3& b, const Axes& oma, const Axes& omb, double f) {
    Crash cr;
    cr.code = hit.what == Met::material ? (hit.part == Part::flute ? flute_code : kCrashHolder)
                                        : kCrashChuck;
    cr.loc = e.loc;
    cr.tool = tool_;
    cr.fraction = f;
    for (size_t i = 0; i < cr.om.size(); ++i) cr.om[i] = oma[i] + f * (omb[i] - oma[i]);
    cr.what = told(mill_crash_text(cr.code, hit, mill_where(lerp(a, b, f))));
    crashes_.push_back(std::move(cr));
}

Outcome Workshop::mill_apply(const MoveEvent& e) {
    Outcome o;
    if (crashed()) return o;
    std::vector<Axes> oms;
    path_of(e, oms);
    std::vector<double> at(oms.size(), 0);  // the path's length at each point
    for (size_t i = 1; i < oms.size(); ++i)
        at[i] = at[i - 1] + dist(tip3(oms[i - 1]), tip3(oms[i]));
    for (size_t i = 0; i + 1 < oms.size(); ++i) {
        if (mill_stroke(e, tip3(oms[i]), tip3(oms[i + 1]), piece_axis(oms[i], oms[i + 1]), oms[i],
                        oms[i + 1]))
            continue;
        Crash& c = crashes_.back();
        const double total = at.back();
        c.fraction = total > 0 ? (at[i] + c.fraction * (at[i + 1] - at[i])) / total : 1;
        o.crashed = true;
        o.stop = c.om;
        o.fraction = c.fraction;
        o.what = c.what;
        return o;
    }
    return o;
}

// JOG and INC (see jog()): the first contact of the cutter, its shank or
// holder with the block, a fixture or the shim stops the move.
Outcome Workshop::mill_jog(const MoveEvent& e, bool continuous) {
    Outcome o;
    if (crashed() || !current()) return o;
    if ((m_.has(C) && e.to_mach[C] != e.from_mach[C]) ||
        (m_.has(B) && e.to_mach[B] != e.from_mach[B]))
        return mill_jog_turn(e, continuous);
    return mill_jog_line(e, continuous);
}

// A jog along a straight line of the table's frame.
Outcome Workshop::mill_jog_line(const MoveEvent& e, bool continuous) {
    Outcome o;
    const P3 a = tip3(e.from_mach), b = tip3(e.to_mach), u = piece_axis(e.from_mach, e.to_mach);
    Met what = Met::none;
    const bool touching = mill_depth(cutter(kNear), below(a, kNear, u), u, what) > kTouchDepth;
    // A shim on the part (the paper test) or a gauge block: a body of its own
    // between the cutter and the surface along the approach, as a setter
    // holds it. The cutter meets the part a shim's thickness early along
    // the move, wherever it stands, and cannot cut through it.
    const P3 by = along(a, b, shim_);
    const bool on_shim = shim_ > 0 && mill_->depth_into(cutter(kNear), below(plus(a, by), kNear, u),
                                                        Part::flute, u) > kTouchDepth;
    if (on_shim && !continuous) return on_the_shim(e.from_mach, tool_);
    if (touching && !continuous) return finder() ? finder_push(e) : mill_apply(e);
    // A held key slides along or away, and stops again before going deeper.
    const double limit =
        touching ? std::max(kTouchDepth, mill_depth(cutter(), a, u, what)) : kTouchDepth;
    Contact k = mill_first(cutter(), a, b, u, limit, true, true);
    if (shim_ > 0) {
        const Cutter over = cutter();
        const P3 oa = plus(a, by), ob = plus(b, by);
        const double deep = on_shim ? mill_->depth_into(over, oa, Part::flute, u) : 0;
        const double f =
            mill_->first_contact(over, oa, ob, Part::flute, std::max(kTouchDepth, deep), true, u);
        if (f < k.f) k = Contact{f, Met::shim, Part::flute};
    }
    // A finder pushed aside (finder_push) moves off the face without crashing.
    if (k.f > 1) return finder() ? o : mill_apply(e);
    o.touched = true;
    o.fraction = k.f;
    for (size_t i = 0; i < o.stop.size(); ++i)
        o.stop[i] = e.from_mach[i] + k.f * (e.to_mach[i] - e.from_mach[i]);
    const std::string place = mill_where(lerp(a, b, k.f));
    o.what = told(finder() && k.what != Met::shim && !leans(u) ? finder_text(k, a, b, place)
                                                               : mill_touch_text(k, place));
    return o;
}

bool Workshop::finder() const {
    const Tool* t = current();
    return t && t->truth->finder;
}

// From the kick an increment pushes the finder's lower part aside on its
// spring, the spindle's axis going on towards the face: up to kFinderTravel,
// then it is bent (1205; the shank and the holder are rigid, 1203 and 1202).
Outcome Workshop::finder_push(const MoveEvent& e) {
    Outcome o;
    const P3 a = tip3(e.from_mach), b = tip3(e.to_mach), u = piece_axis(e.from_mach, e.to_mach);
    const Cutter c = cutter();
    const Contact hit = mill_first(c, a, b, u, kCrashDepth, true, false, kFinderTravel);
    if (hit.f <= 1) {
        mill_crash(e, kCrashProbe, hit, a, b, e.from_mach, e.to_mach, hit.f);
        o.crashed = true;
        o.stop = crashes_.back().om;
        o.fraction = hit.f;
        o.what = crashes_.back().what;
        return o;
    }
    Met what = Met::none;
    const double aside = mill_depth(c, b, u, what);
    if (aside <= kTouchDepth) return o;  // off the face: it runs true again
    o.touched = true;
    o.stop = e.to_mach;
    o.what = strf(tr("the edge finder T%d is pushed %s mm aside; past %s mm it bends"), tool_,
                  fixed3(aside).c_str(), fixed3(kFinderTravel).c_str());
    return o;
}

// The kick: the finder's lower part, running true, leaves the axis as its
// side meets a face square to a horizontal jog along X or Y, the spindle's
// axis one radius from the face. Anything else is a plain contact.
std::string Workshop::finder_text(const Contact& k, const P3& a, const P3& b,
                                  const std::string& place) const {
    const char* p = place.c_str();
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const bool side = k.part == Part::flute && a[2] == b[2] && (dx == 0) != (dy == 0);
    if (!side) return mill_touch_text(k, place);
    // Still, it wobbles off the axis as it was left: its side touches, no
    // kick tells where.
    if (dir_ != 3 && dir_ != 4)
        return strf(tr("%s, but the spindle is not turning: an edge finder centres and kicks only "
                       "turning (about 800 rev/min)"),
                    mill_touch_text(k, place).c_str());
    if (k.what != Met::material)
        return strf(tr("the edge finder T%d kicks on %s %s"), tool_, tr(hit_name(int(k.what))), p);
    const int axis = dx != 0 ? 0 : 1;
    const bool plus = dx + dy > 0;
    static const char* const faces[2][2] = {{"+X", "-X"}, {"+Y", "-Y"}};
    const char* face = faces[axis][plus];
    // The contact's side of the finder, against the block's own face as
    // loaded or a wall the tools have cut.
    const double at = a[axis] + k.f * (b[axis] - a[axis]) + (plus ? 1 : -1) * cutter().radius;
    const Box3& st = mill_->stock();
    if (std::abs(at - (plus ? st.lo[axis] : st.hi[axis])) < kNear)
        return strf(tr("the edge finder T%d kicks on the block's %s face %s"), tool_, face, p);
    return strf(tr("the edge finder T%d kicks on a wall facing %s %s"), tool_, face, p);
}

// --- instruments on the machining centre ---

namespace {

// "X60 Y30 Z-5" and a bare axis letter: what a request gives.
struct Request {
    int axis = -1;                        // X or Y given alone: the direction
    bool has[3] = {false, false, false};  // X, Y, Z given with a value
    double v[3] = {0, 0, 0};
};

bool read_request(std::string_view rest, Request& q) {
    while (!rest.empty()) {
        const size_t sp = rest.find(' ');
        std::string_view w = rest.substr(0, sp);
        rest = sp == std::string_view::npos ? "" : rest.substr(sp + 1);
        if (w.empty()) continue;
        const char c = char(w[0] & ~0x20);
        const int a = c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : -1;
        if (a < 0) return false;
        if (w.size() == 1) {
            if (q.axis >= 0 || a == 2) return false;
            q.axis = a;
            continue;
        }
        double v = 0;
        auto r = std::from_chars(w.data() + 1, w.data() + w.size(), v);
        if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(v) || q.has[a])
            return false;
        q.has[a] = true;
        q.v[a] = v;
    }
    return true;
}

struct MillInstrument {
    const char* word;
    const char* name;  // N_()-marked
    double resolution;
    bool axis;        // takes a direction, X or Y
    bool needs[3];    // which of X, Y, Z it needs besides
    const char* how;  // N_()-marked: the form, for the message
};
constexpr MillInstrument kMillInstruments[] = {
    {"length", N_("caliper"), 0.01, true, {true, true, true}, N_("length X Y30 Z-5")},
    {"width", N_("caliper"), 0.01, true, {true, true, true}, N_("width X X60 Y30 Z-5")},
    {"depth", N_("depth gauge"), 0.01, false, {true, true, false}, N_("depth X60 Y30")},
    {"height", N_("micrometer"), 0.001, false, {true, true, false}, N_("height X60 Y30")},
};

}  // namespace

bool is_mill_instrument(std::string_view word) {
    for (const MillInstrument& i : kMillInstruments)
        if (word == i.word) return true;
    return false;
}

// Reads the block with an instrument (pupitre-setup(5), MEASUREMENTS): the
// place from the block's corner as loaded, Z from its top face as loaded.
std::string Workshop::mill_measure(std::string_view word, std::string_view rest, Reading& r) const {
    const MillInstrument* in = nullptr;
    for (const MillInstrument& i : kMillInstruments)
        if (word == i.word) in = &i;
    if (!in)
        return tr(
            "expected length X|Y, width X|Y, depth, height (with X Y Z from the block's "
            "corner) or tool Tn L|R");
    Request q;
    bool ok = read_request(rest, q) && (q.axis >= 0) == in->axis;
    for (int a = 0; a < 3 && ok; ++a) {
        // length takes every coordinate but its direction's.
        const bool want = in->word == std::string_view("length") ? a != q.axis : in->needs[a];
        ok = want == q.has[a];
    }
    if (!ok) return strf(tr("expected %s (from the block's corner)"), tr(in->how));
    if (q.v[2] > 0) return tr("Z is measured from the block's top face: 0 or negative (Z-5)");
    const Box3& b = mill_->stock();
    const P3 at{b.lo[0] + q.v[0], b.lo[1] + q.v[1], b.hi[2] + q.v[2]};
    const int axis = in->axis ? q.axis : 2;
    const auto span = mill_->along(axis, at);
    r.instrument = tr(in->name);
    r.resolution = in->resolution;
    double v = 0;
    if (in->word == std::string_view("length")) {
        if (span.empty()) return tr("no material there");
        v = span.back()[1] - span.front()[0];
    } else if (in->word == std::string_view("width")) {
        double lo = -kFar, hi = kFar;
        for (const auto& s : span) {
            if (s[0] < at[axis] && s[1] > at[axis])
                return tr("that point is in the material: width measures the gap around it");
            if (s[1] <= at[axis]) lo = std::max(lo, s[1]);
            if (s[0] >= at[axis]) hi = std::min(hi, s[0]);
        }
        if (lo == -kFar || hi == kFar) return tr("no walls there: the gap opens out of the part");
        v = hi - lo;
    } else {
        if (span.empty()) return tr("no material there");
        v = in->word == std::string_view("depth") ? b.hi[2] - span.back()[1]
                                                  : span.back()[1] - span.front()[0];
    }
    r.value = std::round(v / in->resolution) * in->resolution;
    return {};
}

bool Workshop::mill_place(std::string_view rest, Place& p) const {
    Request q;
    if (!read_request(rest, q)) return false;
    const Box3& b = mill_->stock();
    p.at = {b.lo[0] + q.v[0], b.lo[1] + q.v[1], b.hi[2] + q.v[2]};
    p.axis = q.axis >= 0 ? q.axis : 2;
    return true;
}

void Workshop::holding(std::vector<Box3>& boxes, std::vector<Cylinder>& pins) const {
    for (const Fixture& f : fixtures_) {
        if (f.what == Met::table || f.what == Met::setter) continue;
        if (f.pin)
            pins.push_back(*f.pin);
        else
            boxes.push_back(f.box);
    }
}

}  // namespace pupitre::workshop
