// The workshop: events in, cuts and crashes out (see workshop.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/workshop/workshop.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/numfmt.hpp"

namespace pupitre::workshop {

namespace {

// The tool-point path cut at `f` (0..1) of its length.
std::vector<Pt> prefix(const std::vector<Pt>& p, double f, double* at_index = nullptr) {
    double total = 0;
    for (size_t i = 1; i < p.size(); ++i)
        total += std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]);
    std::vector<Pt> out{p.front()};
    double left = f * total;
    for (size_t i = 1; i < p.size(); ++i) {
        double l = std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]);
        if (l >= left) {
            double t = l > 0 ? left / l : 0;
            out.push_back({p[i - 1][0] + t * (p[i][0] - p[i - 1][0]),
                           p[i - 1][1] + t * (p[i][1] - p[i - 1][1])});
            if (at_index) *at_index = double(i - 1) + t;
            return out;
        }
        left -= l;
        out.push_back(p[i]);
    }
    if (at_index) *at_index = double(p.size() - 1);
    return out;
}

// The outline grown by `by` mm (round corners).
CPath grown(const CPath& shape, double by) {
    ClipperLib::ClipperOffset grow;
    grow.AddPath(shape, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    grow.ArcTolerance = kChord / kUnit;
    CPaths out;
    grow.Execute(out, by / kUnit);
    return out.empty() ? shape : out.front();
}

// A thin body from `from` to `len` mm further along the unit vector d
// (20 µm wide): a shim seen edge-on.
CPath bar(Pt from, Pt d, double len) {
    constexpr double kHalf = 0.01;
    const Pt n{-d[1] * kHalf, d[0] * kHalf}, to{from[0] + len * d[0], from[1] + len * d[1]};
    CPath out;
    for (const Pt& q : {Pt{from[0] + n[0], from[1] + n[1]}, Pt{to[0] + n[0], to[1] + n[1]},
                        Pt{to[0] - n[0], to[1] - n[1]}, Pt{from[0] - n[0], from[1] - n[1]}})
        out.push_back(to_int(q));
    if (ClipperLib::Area(out) < 0) std::reverse(out.begin(), out.end());
    return out;
}

// The outline's point farthest along d (among those within 1 µm of it, the
// nearest the tool's point, the origin).
Pt farthest(const CPath& shape, Pt d) {
    double best = -1e300;
    for (const ClipperLib::IntPoint& v : shape)
        best = std::max(best, to_mm(v)[0] * d[0] + to_mm(v)[1] * d[1]);
    Pt out{0, 0};
    double near = 1e300;
    for (const ClipperLib::IntPoint& v : shape) {
        const Pt q = to_mm(v);
        if (q[0] * d[0] + q[1] * d[1] < best - 1e-3) continue;
        if (double r = std::hypot(q[0], q[1]); r < near) near = r, out = q;
    }
    return out;
}

// The unit vector from a to b; none when they are one point.
Pt towards(const Pt& a, const Pt& b) {
    const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
    return l > 0 ? Pt{(b[0] - a[0]) / l, (b[1] - a[1]) / l} : Pt{0, 0};
}

double length_of(const std::vector<Pt>& p) {
    double total = 0;
    for (size_t i = 1; i < p.size(); ++i)
        total += std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]);
    return total;
}

// The machine position at `at`, an index into the path's positions with its
// fraction (as prefix gives it).
Axes om_at(const std::vector<Axes>& oms, double at) {
    size_t i = std::min(size_t(at), oms.size() - 1), j = std::min(i + 1, oms.size() - 1);
    Axes om{};
    for (size_t a = 0; a < om.size(); ++a)
        om[a] = oms[i][a] + (at - double(i)) * (oms[j][a] - oms[i][a]);
    return om;
}

}  // namespace

// Nor from a contact with the gauge block: it is steel, held by hand.
Outcome Workshop::on_the_gauge(const Axes& om, int tool) {
    Outcome o = on_the_shim(om, tool);
    o.what =
        strf(tr("the gauge block is between T%d and the chuck: :gauge off before going on"), tool);
    return o;
}

// An increment from a contact with the shim goes nowhere: the insert cannot
// cut through the shim (the paper test).
Outcome Workshop::on_the_shim(const Axes& om, int tool) {
    Outcome o;
    o.touched = true;
    o.fraction = 0;
    o.stop = om;
    o.what = strf(tr("the shim is between T%d and the part: :shim off before cutting"), tool);
    return o;
}

Workshop::Workshop(const MachineProfile& m, const Setup& s, MachineSink* next)
    : m_(m), setup_(s), world_(s.kind == "mill" ? LatheWorld() : LatheWorld(s.lathe)), next_(next) {
    if (setup_.kind == "mill") mill_fixtures();
    int top = 0;
    for (const ToolTruth& t : setup_.tools) top = std::max(top, t.position);
    tools_.resize(size_t(top) + 1);
    for (const ToolTruth& t : setup_.tools) {
        Tool& slot = tools_[size_t(t.position)];
        slot.truth = setup_.tool(t.position);
        if (mill_) continue;  // a cutter's shape is made as it is used (cutter())
        slot.shape = tool_shape(t);
        slot.near.insert = grown(slot.shape.insert, kNear);
        slot.near.holder = grown(slot.shape.holder, kNear);
    }
}

Workshop::Tool* Workshop::current() {
    return tool_ > 0 && size_t(tool_) < tools_.size() && tools_[size_t(tool_)].truth
               ? &tools_[size_t(tool_)]
               : nullptr;
}
const Workshop::Tool* Workshop::current() const {
    return const_cast<Workshop*>(this)->current();
}

bool Workshop::probe_in_use() const {
    const Tool* t = current();
    return t && t->truth->probe;
}

bool Workshop::probe_contact(const Axes& om) const {
    const Tool* t = current();
    if (!t || !t->truth->probe) return false;
    if (mill_) {
        Met what = Met::none;
        return mill_depth(cutter(kNear), grown_tip(om, kNear), axis3(om), what) > kTouchDepth;
    }
    const CPaths ball = LatheWorld::sweep(t->near.insert, {tip(om)});
    for (Obstacle w : {Obstacle::material, Obstacle::chuck, Obstacle::tailstock, Obstacle::gauge})
        if (world_.depth_into(ball, w) > kTouchDepth) return true;
    return false;
}

double Workshop::cut_length(int tool) const {
    return tool > 0 && size_t(tool) < tools_.size() ? tools_[size_t(tool)].cut : 0;
}

Pt Workshop::tip(const Axes& om) const {
    const Tool* t = current();
    if (!t) return {om[Z], om[X] - setup_.lathe.axis_x};
    const ToolTruth& tt = *t->truth;
    Pt p{om[Z] - tt.z, om[X] - tt.x - setup_.lathe.axis_x};
    if (tt.wear > 0 && t->cut > 0) {
        // Wear takes the nose back into the insert, along its bisector
        // (pupitre-setup(5)): µm per metre of cut.
        int sx = 0, sz = 0;
        nose_direction(tt.orientation, sx, sz);
        double ux = -sx, uz = -sz, n = std::hypot(ux, uz);
        double w = tt.wear * 1e-3 * (t->cut / 1000);
        p[0] += w * uz / n;
        p[1] += w * ux / n;
    }
    return p;
}

void Workshop::path_of(const MoveEvent& e, std::vector<Axes>& out) const {
    out.clear();
    out.push_back(e.from_mach);
    if (e.g == 2 || e.g == 3) {
        const int a0 = e.plane_a0, a1 = e.plane_a1;
        Pt c{e.c0 + e.to_mach[size_t(a0)] - e.to_prog[size_t(a0)],
             e.c1 + e.to_mach[size_t(a1)] - e.to_prog[size_t(a1)]};
        std::vector<Pt> pts;
        arc_points({e.from_mach[size_t(a0)], e.from_mach[size_t(a1)]}, c, e.sweep * geometry::kDeg,
                   pts);
        for (size_t i = 0; i + 1 < pts.size(); ++i) {
            double f = double(i + 1) / double(pts.size());
            Axes p = e.from_mach;
            for (size_t a = 0; a < p.size(); ++a) p[a] += f * (e.to_mach[a] - e.from_mach[a]);
            p[size_t(a0)] = pts[i][0];
            p[size_t(a1)] = pts[i][1];
            out.push_back(p);
        }
    }
    out.push_back(e.to_mach);
    turn_pieces(out);
}

// A C table turning or B tilting along the path: pieces short enough that
// the tool's tip, seen from the part, is within 0.5 µm of their chords (at
// its largest distance from the axis), and that the tool's axis turns by at
// most kAxisStep in one (a piece is cut with its middle's axis: within
// 9 µm at the side of a Ø10 cutter; 3+2 work, B and C still while cutting,
// is exact).
void Workshop::turn_pieces(std::vector<Axes>& out) const {
    if (!mill_) return;
    const bool c_turns = m_.has(C) && out.front()[C] != out.back()[C];
    const bool b_turns = m_.has(B) && out.front()[B] != out.back()[B];
    if (!c_turns && !b_turns) return;
    const MillSetup& ms = setup_.mill;
    double rc = 0, rb = 0;
    for (const Axes& p : out) {
        const P3 tip = tip3(p);
        rc = std::max(rc, std::hypot(tip[0] - ms.c_x, tip[1] - ms.c_y));
        rb = std::max(rb, m_.kinematics == "table" ? std::hypot(tip[0] - ms.b_x, tip[2] - ms.b_z)
                                                   : ms.pivot + p[Z] - tip3(p, false)[2]);
    }
    auto chord = [](double r) {
        return r > 1e-3 ? 2 * std::acos(1 - 5e-4 / r) / geometry::kDeg : 360;
    };
    // Turning C with the tool tilted by B turns its axis by dC sin B.
    double lean = 0;
    if (m_.has(B))
        for (const Axes& p : out) lean = std::max(lean, std::fabs(std::sin(p[B] * geometry::kDeg)));
    const double step_c = std::min(chord(rc), lean > 1e-9 ? kAxisStep / lean : 360);
    const double step_b = std::min(kAxisStep, chord(rb));
    std::vector<Axes> fine{out.front()};
    for (size_t i = 0; i + 1 < out.size(); ++i) {
        double turns = 1;
        if (c_turns) turns = std::max(turns, std::fabs(out[i + 1][C] - out[i][C]) / step_c);
        if (b_turns) turns = std::max(turns, std::fabs(out[i + 1][B] - out[i][B]) / step_b);
        const int n = int(std::ceil(turns));
        for (int k = 1; k <= n; ++k) {
            Axes p = out[i];
            for (size_t a = 0; a < p.size(); ++a) p[a] += (out[i + 1][a] - out[i][a]) * k / n;
            fine.push_back(k == n ? out[i + 1] : p);
        }
    }
    out.swap(fine);
}

bool Workshop::near(const CPath& shape, const std::vector<Pt>& tips) const {
    double z0 = 1e300, z1 = -1e300, r0 = 1e300, r1 = 0;
    bool crosses = false;
    for (const Pt& p : tips) {
        z0 = std::min(z0, p[0]), z1 = std::max(z1, p[0]);
        r0 = std::min(r0, std::abs(p[1])), r1 = std::max(r1, std::abs(p[1]));
        crosses = crosses || p[1] * tips.front()[1] < 0;
    }
    // The shape's extent about its point, and the mirror image (sweep()).
    double sz0 = 0, sz1 = 0, sr = 0;
    for (const auto& v : shape) {
        const Pt q = to_mm(v);
        sz0 = std::min(sz0, q[0]), sz1 = std::max(sz1, q[0]), sr = std::max(sr, std::abs(q[1]));
    }
    const double lo = crosses ? 0 : std::max(0.0, r0 - sr), hi = r1 + sr;
    for (Obstacle w : {Obstacle::material, Obstacle::chuck, Obstacle::tailstock, Obstacle::gauge})
        if (world_.near(w, z0 + sz0 - kNear, lo - kNear, z1 + sz1 + kNear, hi + kNear)) return true;
    return false;
}

std::string Workshop::told(std::string what) const {
    if (!hide_places_) return what;
    for (size_t at; (at = what.find(" ,")) != std::string::npos;) what.erase(at, 1);
    while (!what.empty() && (what.back() == ' ' || what.back() == ',')) what.pop_back();
    return what;
}

std::string Workshop::where(const Pt& p) const {
    if (hide_places_) return {};
    // The contact in the part's terms, which do not depend on PREF: the
    // diameter and the distance from the stock's face as it was loaded.
    double face = setup_.lathe.chuck_z + setup_.lathe.stickout;
    // TRANSLATORS: where a crash happened: a diameter, then the distance from the stock's face.
    return strf(tr("at \u00f8%s, %s mm from the stock's face"),
                fixed3_zeroed(2 * std::abs(p[1]), 5e-4).c_str(),
                fixed3_zeroed(p[0] - face, 5e-4).c_str());
}

double Workshop::first_contact(const CPath& shape, const std::vector<Pt>& tips, Obstacle what,
                               double depth, bool before, const CPaths* whole) const {
    if (world_.depth_into(whole ? *whole : LatheWorld::sweep(shape, tips), what) <= depth) return 2;
    // Bisection along the move, to 0.1 µm.
    double lo = 0, hi = 1, total = length_of(tips);
    for (int i = 0; i < 60 && (hi - lo) * total > 1e-4; ++i) {
        double mid = (lo + hi) / 2;
        if (world_.depth_into(LatheWorld::sweep(shape, prefix(tips, mid)), what) > depth)
            hi = mid;
        else
            lo = mid;
    }
    return before ? lo : hi;
}

// The crashes of the tool's cutting part into the part, on both machines;
// "" for the others.
std::string Workshop::part_crash_text(int code, int spindle, const char* p) const {
    switch (code) {
        case kCrashRapid:
            return strf(tr("crash: T%d rapid (G0) into the part %s"), tool_, p);
        case kCrashStopped:
            return strf(tr("crash: T%d fed into the part with the spindle stopped %s"), tool_, p);
        case kCrashDirection:
            return strf(tr("crash: T%d cuts with M%d, the spindle turns M%d, %s"), tool_, spindle,
                        dir_, p);
        case kCrashProbe:
            return strf(tr("crash: the probe T%d was driven into the part %s"), tool_, p);
        default:
            return {};
    }
}

// What hit what, where: the crash's message.
std::string Workshop::crash_text(int code, bool holder, Obstacle what, const ToolTruth& tt,
                                 const std::string& place) const {
    const char* p = place.c_str();
    if (std::string s = part_crash_text(code, tt.spindle, p); !s.empty()) return s;
    if (code == kCrashHolder) return strf(tr("crash: the holder of T%d hit the part %s"), tool_, p);
    if (what == Obstacle::gauge)
        return strf(holder ? tr("crash: the holder of T%d hit the gauge block on the jaws' face %s")
                           : tr("crash: T%d hit the gauge block on the jaws' face %s"),
                    tool_, p);
    if (what == Obstacle::chuck)
        return strf(holder ? tr("crash: the holder of T%d hit the chuck %s")
                           : tr("crash: T%d hit the chuck %s"),
                    tool_, p);
    return strf(holder ? tr("crash: the holder of T%d hit the tailstock %s")
                       : tr("crash: T%d hit the tailstock %s"),
                tool_, p);
}

bool Workshop::check(const MoveEvent& e, const std::vector<Pt>& tips,
                     const std::vector<Axes>& oms) {
    Tool* t = current();
    if (!t) return true;
    const ToolTruth& tt = *t->truth;
    struct Hit {
        int code;
        const CPath* shape;
        Obstacle what;
    };
    bool feed = e.g != 0, stopped = dir_ != 3 && dir_ != 4;
    bool cutting = feed && !stopped && !tt.probe && (tt.spindle == 0 || tt.spindle == dir_);
    int insert_code = tt.probe  ? kCrashProbe
                      : !feed   ? kCrashRapid
                      : stopped ? kCrashStopped
                                : kCrashDirection;
    Hit hits[] = {{kCrashChuck, &t->shape.insert, Obstacle::chuck},
                  {kCrashChuck, &t->shape.holder, Obstacle::chuck},
                  {kCrashChuck, &t->shape.insert, Obstacle::tailstock},
                  {kCrashChuck, &t->shape.holder, Obstacle::tailstock},
                  {kCrashChuck, &t->shape.insert, Obstacle::gauge},
                  {kCrashChuck, &t->shape.holder, Obstacle::gauge},
                  {kCrashHolder, &t->shape.holder, Obstacle::material},
                  {insert_code, &t->shape.insert, Obstacle::material}};
    // Each shape's sweep along the whole move, once; the holder's only when
    // its box comes near something (it seldom does: the sweeps are most of
    // a run's time).
    const CPaths swept_insert = LatheWorld::sweep(t->shape.insert, tips);
    const bool holder_near = near(t->shape.holder, tips);
    const CPaths swept_holder = holder_near ? LatheWorld::sweep(t->shape.holder, tips) : CPaths{};
    double first = 2;
    const Hit* worst = nullptr;
    for (const Hit& h : hits) {
        if (h.code == insert_code && h.what == Obstacle::material && cutting) continue;
        if (h.shape == &t->shape.holder && !holder_near) continue;
        const CPaths* whole = h.shape == &t->shape.insert ? &swept_insert : &swept_holder;
        double f = first_contact(*h.shape, tips, h.what, kCrashDepth, false, whole);
        if (f < first) first = f, worst = &h;
    }
    double f = worst ? first : 1;
    std::vector<Pt> done = worst ? prefix(tips, f) : tips;
    if (cutting) {
        double removed =
            world_.cut(worst ? LatheWorld::sweep(t->shape.insert, done) : swept_insert);
        if (removed > 1e-9) t->cut += length_of(done);
    }
    if (!worst) return true;
    double at = 0;
    prefix(tips, f, &at);
    size_t i = std::min(size_t(at), oms.size() - 1), j = std::min(i + 1, oms.size() - 1);
    Crash c;
    c.code = worst->code;
    c.loc = e.loc;
    c.tool = tool_;
    c.fraction = f;
    for (size_t a = 0; a < c.om.size(); ++a)
        c.om[a] = oms[i][a] + (at - double(i)) * (oms[j][a] - oms[i][a]);
    c.what = told(
        crash_text(c.code, worst->shape == &t->shape.holder, worst->what, tt, where(done.back())));
    crashes_.push_back(std::move(c));
    return false;
}

Workshop::Frame Workshop::part_frame(const Axes& om, const Axes& op, int corrector) const {
    if (corrector == 0 && frame_.known) return frame_;
    const Pt t = tip(om);
    return Frame{corrector != 0, op[Z] - t[0], op[X] - t[1]};
}

void Workshop::note_frame(const MoveEvent& e) {
    if (corr_ != 0) frame_ = part_frame(e.to_mach, e.to_prog, corr_);
}

Outcome Workshop::apply(const MoveEvent& e) {
    if (mill_) return mill_apply(e);
    Outcome o;
    if (crashed()) return o;
    note_frame(e);
    std::vector<Axes> oms;
    path_of(e, oms);
    std::vector<Pt> tips;
    tips.reserve(oms.size());
    for (const Axes& om : oms) tips.push_back(tip(om));
    // A long arc is met piece by piece, so that each Boolean stays small (a
    // half circle of R 300 is 860 chords) and the first piece that crashes
    // ends it.
    constexpr size_t kPiece = 32;  // chords
    const double total = length_of(tips);
    double before = 0;
    for (size_t i = 0; i + 1 < tips.size(); i += kPiece) {
        const size_t j = std::min(i + kPiece, tips.size() - 1);
        const std::vector<Pt> piece(tips.begin() + long(i), tips.begin() + long(j) + 1);
        const std::vector<Axes> at(oms.begin() + long(i), oms.begin() + long(j) + 1);
        const double len = length_of(piece);
        if (!check(e, piece, at)) {
            Crash& c = crashes_.back();
            c.fraction = total > 0 ? (before + c.fraction * len) / total : 1;
            o.crashed = true;
            o.stop = c.om;
            o.fraction = c.fraction;
            o.what = c.what;
            return o;
        }
        before += len;
    }
    return o;
}

Outcome Workshop::jog(const MoveEvent& e, bool continuous) {
    if (mill_) return mill_jog(e, continuous);
    Outcome o;
    const Tool* t = current();
    if (!t || crashed()) return o;
    note_frame(e);
    std::vector<Axes> oms;
    path_of(e, oms);
    std::vector<Pt> tips;
    for (const Axes& om : oms) tips.push_back(tip(om));
    const std::vector<Pt> here{tips.front()};
    // A shim, a pin or a gauge block (:shim) is a body of its own between the
    // tool and the surface, along the jog, as a setter holds it: under the
    // insert's point farthest along the jog, or, where the part is not under
    // that point (the nose beyond the face), under the tool's point P, slid
    // along its line of contact onto the part. Its far end meets the part:
    // the reading is the surface's plus the thickness wherever the tool
    // stands over it, whatever shoulder is beside it. The insert cannot cut
    // through it.
    const CPath shim = shim_body(t->shape.insert, towards(tips.front(), tips.back()), tips.front());
    const CPath shim_near = shim.empty() ? CPath{} : grown(shim, kNear);
    const CPath* shapes[] = {&shim, &t->shape.insert, &t->shape.holder};
    const CPath* near[] = {&shim_near, &t->near.insert, &t->near.holder};
    const Obstacle things[] = {Obstacle::material, Obstacle::chuck, Obstacle::tailstock,
                               Obstacle::gauge};
    double first = 2;
    Obstacle hit = Obstacle::none;
    bool holder = false, on_shim = false;
    for (int k = shim.empty() ? 1 : 0; k < 3; ++k) {
        const CPaths near_here = LatheWorld::sweep(*near[k], here),
                     at_here = LatheWorld::sweep(*shapes[k], here);
        const CPaths whole = LatheWorld::sweep(*shapes[k], tips);
        for (Obstacle w : things) {
            if (k == 0 && w != Obstacle::material) continue;  // the shim lies on the part
            // At a contact, an increment goes on as a feed; a held JOG key
            // slides along or away, and stops again before going deeper.
            const bool touching = world_.depth_into(near_here, w) > kTouchDepth;
            if (touching && !continuous && k == 0) return on_the_shim(oms.front(), tool_);
            if (touching && !continuous && w == Obstacle::gauge)
                return on_the_gauge(oms.front(), tool_);
            if (touching && !continuous) return apply(e);
            const double limit =
                touching ? std::max(kTouchDepth, world_.depth_into(at_here, w)) : kTouchDepth;
            if (double f = first_contact(*shapes[k], tips, w, limit, true, &whole); f < first)
                first = f, hit = w, holder = k == 2, on_shim = k == 0;
        }
    }
    if (hit == Obstacle::none) return apply(e);
    double at = 0;
    std::vector<Pt> done = prefix(tips, first, &at);
    o.stop = om_at(oms, at);
    o.touched = true;
    o.fraction = first;
    o.what = told(touch_text(hit, holder, on_shim, where(done.back())));
    return o;
}

// The shim seen edge-on for a jog along d from `at` (the tool point): from
// the insert's point farthest along d, or from P when the part is not
// along d from that point; none without a shim or a direction.
CPath Workshop::shim_body(const CPath& insert, Pt d, const Pt& at) const {
    if (shim_ <= 0 || (d[0] == 0 && d[1] == 0)) return {};
    constexpr double kFar = 1e4;  // mm: beyond any part
    const Pt far = farthest(insert, d);
    const bool under =
        world_.depth_into(LatheWorld::sweep(bar(far, d, kFar), {at}), Obstacle::material) > 0;
    return bar(under ? far : Pt{0, 0}, d, shim_);
}

// What a jog touched, where.
std::string Workshop::touch_text(Obstacle hit, bool holder, bool on_shim,
                                 const std::string& place) const {
    if (on_shim)
        return strf(tr("T%d touched the %s mm shim on the part %s"), tool_, fixed3(shim_).c_str(),
                    place.c_str());
    if (hit == Obstacle::gauge)
        return strf(holder
                        ? tr("the holder of T%d touched the %s mm gauge block on the jaws' face %s")
                        : tr("T%d touched the %s mm gauge block on the jaws' face %s"),
                    tool_, fixed3(world_.gauge_block()).c_str(), place.c_str());
    const char* what =
        hit == Obstacle::material
            ? (holder ? tr("the holder of T%d touched the part %s") : tr("T%d touched the part %s"))
        : hit == Obstacle::chuck ? (holder ? tr("the holder of T%d touched the chuck %s")
                                           : tr("T%d touched the chuck %s"))
                                 : (holder ? tr("the holder of T%d touched the tailstock %s")
                                           : tr("T%d touched the tailstock %s"));
    return strf(what, tool_, place.c_str());
}

MoveEvent Workshop::truncated(const MoveEvent& e, const Axes& stop, double fraction) {
    MoveEvent cut = e;
    const double f = std::clamp(fraction, 0.0, 1.0);
    for (size_t a = 0; a < stop.size(); ++a) cut.to_prog[a] += stop[a] - e.to_mach[a];
    cut.to_mach = stop;
    cut.sweep *= f;
    cut.length *= f;
    cut.seconds *= f;
    return cut;
}

void Workshop::move(const MoveEvent& e) {
    if (crashed()) return;  // the machine stopped at the contact
    Outcome o = apply(e);
    if (!next_) return;
    const MoveEvent made = o.crashed ? truncated(e, o.stop, o.fraction) : e;
    std::vector<MoveEvent> pieces;
    if (!draw_on_part_ || !on_part(made, pieces)) return next_->move(made);
    for (const MoveEvent& p : pieces) next_->move(p);
}

uint64_t Workshop::generation() const {
    return mill_ ? mill_->generation() : world_.generation();
}

std::string Workshop::part_text() const {
    return mill_ ? mill_->to_text() : world_.to_text();
}

bool Workshop::load_part(std::string_view text) {
    return mill_ ? mill_->from_text(text) : world_.from_text(text);
}

void Workshop::new_part() {
    if (mill_)
        mill_->new_part();
    else
        world_.new_part();
}

void Workshop::tool(const Loc& l, int t, int d, double s, bool m6) {
    tool_ = t;  // the lathe's turret indexes on T
    corr_ = d;
    if (next_) next_->tool(l, t, d, s, m6);
}

void Workshop::spindle(const SpindleEvent& e) {
    dir_ = e.dir;
    if (next_) next_->spindle(e);
}

// --- instruments ---

namespace {

struct Instrument {
    const char* word;  // the request's first word
    const char* name;  // N_()-marked: what reads it
    double resolution;
    bool needs_z;
};
constexpr Instrument kInstruments[] = {
    {"dia", N_("micrometer"), 0.001, true},
    {"bore", N_("bore gauge"), 0.001, true},
    {"groove", N_("caliper"), 0.01, true},
    {"length", N_("depth gauge"), 0.01, false},
};

}  // namespace

std::string_view instrument_word(std::string_view word) {
    static constexpr std::pair<std::string_view, std::string_view> kFrench[] = {
        {"diam", "dia"},       {"diamètre", "dia"},     {"alésage", "bore"},
        {"alesage", "bore"},   {"gorge", "groove"},     {"longueur", "length"},
        {"outil", "tool"},     {"largeur", "width"},    {"profondeur", "depth"},
        {"hauteur", "height"}, {"épaisseur", "height"}, {"epaisseur", "height"}};
    for (const auto& [fr, en] : kFrench)
        if (word == fr) return en;
    return word;
}

bool is_instrument(std::string_view word) {
    word = instrument_word(word);
    for (const Instrument& i : kInstruments)
        if (word == i.word) return true;
    return word == "tool" || is_mill_instrument(word);
}

namespace {

double rounded(double v, double res) {
    return std::round(v / res) * res;
}

}  // namespace

// The tool presetter (seed 004:570-572, "la longueur d'outil est fournie par
// le banc de pré-réglage avec son incertitude de mesure"): the true gauge or
// nose radius to 0.001 mm, off by a fixed amount within ±kPresetter that
// depends on the setup, the tool and the field ([DECISION]: a presetter is
// not the truth; the part measured after a cut refines it, 004 §2.9.4).
inline constexpr double kPresetter = 0.002;

std::string Workshop::presetter(std::string_view rest, Reading& r) const {
    int t = 0;
    char field = 0;
    if (rest.size() >= 4 && (rest[0] == 'T' || rest[0] == 't')) {
        size_t sp = rest.find(' ');
        auto res = std::from_chars(
            rest.data() + 1, rest.data() + (sp == std::string_view::npos ? rest.size() : sp), t);
        if (res.ec == std::errc() && sp != std::string_view::npos && sp + 2 == rest.size())
            field = rest[sp + 1];
    }
    const ToolTruth* tt = setup_.tool(t);
    if (mill_ && field != 'L' && field != 'R')
        return tr("tool needs a tool and a field: tool T1 L or tool T1 R");
    if (!mill_ && field != 'X' && field != 'Z' && field != 'R')
        return tr("tool needs a tool and a field: tool T1 X, tool T1 Z or tool T1 R");
    if (!tt)
        return strf(
            mill_ ? tr("there is no T%d in the magazine") : tr("there is no T%d on the turret"), t);
    double v = field == 'X' ? tt->x : field == 'Z' ? tt->z : field == 'L' ? tt->length : tt->radius;
    // A fixed error per setup, tool and field, from a small hash.
    uint32_t h = 2166136261u;
    for (char c : setup_.name + char('0' + t % 10) + char('0' + t / 10) + field)
        h = (h ^ uint8_t(c)) * 16777619u;
    double off = (double(h % 5) - 2) * kPresetter / 2;
    r.instrument = tr("presetter");
    r.resolution = 0.001;
    r.uncertainty = kPresetter;
    const double read = std::round((v + off) * 1000) / 1000;
    r.value = field == 'R' ? std::max(0.0, read) : read;  // a radius is never negative
    return {};
}

// The request split as measure() splits it: its word in English, the rest.
static void split_request(std::string_view s, std::string_view& word, std::string_view& rest) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    const size_t sp = s.find(' ');
    word = instrument_word(s.substr(0, sp));
    rest = sp == std::string_view::npos ? "" : s.substr(sp + 1);
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    while (!rest.empty() && rest.back() == ' ') rest.remove_suffix(1);
}

bool Workshop::measure_place(std::string_view spec, Place& p) const {
    Reading r;
    if (!measure(spec, r).empty()) return false;
    std::string_view word, rest;
    split_request(spec, word, rest);
    if (word == "tool") return false;
    p = Place{};
    p.word = std::string(word);
    if (mill_) return mill_place(rest, p);
    double face = 0, dz = 0;
    world_.right_face(face);
    if (rest.size() > 1) std::from_chars(rest.data() + 1, rest.data() + rest.size(), dz);
    p.at = {0, 0, face + dz};
    return true;
}

std::string Workshop::measure(std::string_view spec, Reading& r) const {
    r = Reading{};
    r.spec = std::string(spec);
    std::string_view word, rest;
    split_request(spec, word, rest);
    if (word == "tool") return presetter(rest, r);
    if (mill_) return mill_measure(word, rest, r);
    const Instrument* in = nullptr;
    for (const Instrument& i : kInstruments)
        if (word == i.word) in = &i;
    if (!in) return tr("expected dia Z-n, bore Z-n, groove Z-n, length or tool Tn X|Z|R");
    double face = 0;
    if (!world_.right_face(face)) return tr("there is no part");
    double dz = 0;
    if (in->needs_z) {
        if (rest.size() < 2 || (rest[0] != 'Z' && rest[0] != 'z'))
            return strf(tr("%s needs a Z: how far from the part's right-hand face (Z-20)"),
                        in->word);
        auto res = std::from_chars(rest.data() + 1, rest.data() + rest.size(), dz);
        if (res.ec != std::errc() || res.ptr != rest.data() + rest.size() || !std::isfinite(dz))
            return strf(tr("%s needs a Z: how far from the part's right-hand face (Z-20)"),
                        in->word);
        if (dz > 0)
            return tr("Z is measured from the part's right-hand face: a negative distance (Z-20)");
    } else if (!rest.empty()) {
        return strf(tr("%s takes no Z"), in->word);
    }
    const double z = face + dz;
    r.instrument = tr(in->name);
    r.resolution = in->resolution;
    double v = 0, a = 0, b = 0;
    if (in->word == std::string_view("dia")) {
        if (!world_.outer_radius(z, v)) return tr("no material there");
        v *= 2;
    } else if (in->word == std::string_view("bore")) {
        if (!world_.outer_radius(z, a)) return tr("no material there");
        if (!world_.inner_radius(z, v)) return tr("the part is solid there");
        v *= 2;
    } else if (in->word == std::string_view("groove")) {
        if (!world_.groove(z, a, b)) return tr("no groove there: Z must be on a groove's bottom");
        v = b - a;
    } else {
        v = face - setup_.lathe.chuck_z;  // from the jaws' face
    }
    r.value = rounded(v, in->resolution);
    return {};
}

}  // namespace pupitre::workshop
