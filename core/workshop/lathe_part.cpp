// The lathe's half-section (see lathe_part.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/workshop/lathe_part.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "core/geometry/geometry.hpp"

namespace pupitre::workshop {

using ClipperLib::IntPoint;
using geometry::kPi;

IntPoint to_int(Pt p) {
    return IntPoint(ClipperLib::cInt(std::llround(p[0] / kUnit)),
                    ClipperLib::cInt(std::llround(p[1] / kUnit)));
}
Pt to_mm(const IntPoint& p) {
    return {double(p.X) * kUnit, double(p.Y) * kUnit};
}

namespace {

// Segments for an arc of radius r and `angle` radians with chords within
// kChord of it.
int segments(double r, double angle) {
    if (r <= kChord) return 1;
    double step = 2 * std::acos(std::max(-1.0, 1 - kChord / r));
    return std::clamp(int(std::ceil(std::abs(angle) / step)), 1, 100000);
}

CPath rect(double z0, double r0, double z1, double r1) {
    return {to_int({z0, r0}), to_int({z1, r0}), to_int({z1, r1}), to_int({z0, r1})};
}

// Andrew's monotone chain: the convex hull, counter-clockwise.
CPath hull(CPath p) {
    std::sort(p.begin(), p.end(), [](const IntPoint& a, const IntPoint& b) {
        return a.X < b.X || (a.X == b.X && a.Y < b.Y);
    });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    auto turn = [](const IntPoint& o, const IntPoint& a, const IntPoint& b) {
        return double(a.X - o.X) * double(b.Y - o.Y) - double(a.Y - o.Y) * double(b.X - o.X);
    };
    CPath h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, lo = k + 1; i-- > 0;) {
        while (k >= lo && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

// True when every turn of the outline goes the same way.
bool convex(const CPath& p) {
    if (p.size() < 3) return true;
    int sign = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const IntPoint &a = p[i], &b = p[(i + 1) % p.size()], &c = p[(i + 2) % p.size()];
        double t = double(b.X - a.X) * double(c.Y - b.Y) - double(b.Y - a.Y) * double(c.X - b.X);
        int s = t > 0 ? 1 : t < 0 ? -1 : 0;
        if (s && sign && s != sign) return false;
        if (s) sign = s;
    }
    return true;
}

CPaths clip(const CPaths& a, const CPaths& b, ClipperLib::ClipType op) {
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    c.AddPaths(b, ClipperLib::ptClip, true);
    CPaths out;
    c.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

double area_mm2(const CPaths& p) {
    double a = 0;
    for (const CPath& q : p) a += ClipperLib::Area(q);
    return a * kUnit * kUnit;
}

// The default holder, relative to P (Z, R) (pupitre-setup(5)): a boring bar
// along +Z below a tip that points outwards; otherwise a 16 mm shank rising
// from the insert, set 1 mm behind the tip in the direction it cuts.
CPath default_holder(int sx, int sz, double edge) {
    if (sx > 0) return rect(2, -12, 200, -2);
    double z0 = sz < 0 ? 1 : sz > 0 ? -17 : -8;
    return rect(z0, sx == 0 ? -8 : edge / 2, z0 + 16, 60);
}

}  // namespace

// A sweep that reaches below the axis, with its mirror image: a tool past
// the centre cuts what it meets on the other side.
static CPaths mirrored(CPaths out) {
    bool below = false;
    for (const CPath& q : out)
        for (const IntPoint& v : q) below = below || v.Y < 0;
    if (!below) return out;
    CPaths mirror = out;
    for (CPath& q : mirror) {
        for (IntPoint& v : q) v.Y = -v.Y;
        ClipperLib::ReversePath(q);
    }
    return clip(out, mirror, ClipperLib::ctUnion);
}

void nose_direction(int c, int& sx, int& sz) {
    // C0 (P at the nose centre) takes C3's insert: an outside tool.
    const int k = c >= 1 && c <= 8 ? c : 3;
    sx = geometry::kNose[k][0];
    sz = geometry::kNose[k][1];
}

CPath circle(Pt c, double r) {
    // Inscribed, with a vertex on each axis: the points that turn a diameter
    // or a face are exact; elsewhere the polygon is within kChord inside.
    CPath p;
    if (r <= kChord) return {to_int(c)};
    int n = (std::max(8, segments(r, 2 * kPi)) + 3) / 4 * 4;
    for (int i = 0; i < n; ++i) {
        double a = 2 * kPi * i / n;
        p.push_back(to_int({c[0] + r * std::cos(a), c[1] + r * std::sin(a)}));
    }
    return p;
}

void arc_points(Pt a, Pt c, double sweep, std::vector<Pt>& out) {
    double r = std::hypot(a[0] - c[0], a[1] - c[1]);
    double a0 = std::atan2(a[1] - c[1], a[0] - c[0]);
    int n = segments(r, sweep);
    for (int i = 1; i <= n; ++i) {
        double t = a0 + sweep * i / n;
        out.push_back({c[0] + r * std::cos(t), c[1] + r * std::sin(t)});
    }
}

ToolShape tool_shape(const ToolTruth& t) {
    if (t.probe) {
        // An electric touch probe: a ball of the tool's radius centred on P
        // (its corrector's R, C0), on a stem 1.2 radii wide rising along +X.
        ToolShape probe;
        const double r = std::max(t.radius, 0.05);
        probe.insert = circle({0, 0}, r);
        probe.holder = t.holder.empty() ? rect(-0.6 * r, 0.5 * r, 0.6 * r, 80) : CPath{};
        for (const Pt& q : t.holder) probe.holder.push_back(to_int(q));
        if (ClipperLib::Area(probe.holder) < 0) ClipperLib::ReversePath(probe.holder);
        return probe;
    }
    const int c = std::clamp(t.orientation, 0, 8);
    int sx = 0, sz = 0;
    nose_direction(c, sx, sz);
    const double r = t.radius;
    Pt centre{-r * sz, -r * sx};
    if (c == 0) centre = {0, 0};
    // The insert's two cutting edges, as directions from the nose
    // (pupitre-setup(5)): C1-C4 (and C0) hold one edge along X, away from
    // the point, the other `angle` from it (a 90° lead: the tool turns to a
    // shoulder and leaves it square); C5-C8 are symmetric about their point.
    const double a = t.angle * kPi / 180;
    Pt d1, d2;
    if (sx != 0 && sz != 0) {
        d1 = {0.0, double(-sx)};
        d2 = {-sz * std::sin(a), -sx * std::cos(a)};
    } else {
        double uz = -sz, ux = -sx, h = a / 2;
        d1 = {uz * std::cos(h) - ux * std::sin(h), uz * std::sin(h) + ux * std::cos(h)};
        d2 = {uz * std::cos(h) + ux * std::sin(h), -uz * std::sin(h) + ux * std::cos(h)};
    }
    const Pt body{d1[0] + d2[0], d1[1] + d2[1]};
    CPath pts = circle(centre, r);
    for (const Pt& d : {d1, d2}) {
        // The edge leaves the nose where it is tangent: its outward normal
        // is a quarter turn from it, away from the insert's body.
        Pt n{-d[1], d[0]};
        if (n[0] * body[0] + n[1] * body[1] > 0) n = {d[1], -d[0]};
        pts.push_back(
            to_int({centre[0] + r * n[0] + t.edge * d[0], centre[1] + r * n[1] + t.edge * d[1]}));
        pts.push_back(to_int({centre[0] + r * n[0], centre[1] + r * n[1]}));
    }
    ToolShape shape;
    shape.insert = hull(std::move(pts));
    if (t.holder.empty()) {
        shape.holder = default_holder(sx, sz, t.edge);
    } else {
        for (const Pt& q : t.holder) shape.holder.push_back(to_int(q));
        if (ClipperLib::Area(shape.holder) < 0) ClipperLib::ReversePath(shape.holder);
    }
    return shape;
}

LatheWorld::LatheWorld(const LatheSetup& s) : s_(s) {
    const double face = s.chuck_z, rs = s.stock_diameter / 2;
    // The jaws grip the bar over jaw.reach; the body lies behind them.
    double jaw0 = face - s.jaw_length;
    chuck_.push_back(rect(jaw0, rs, face, rs + s.jaw_height));
    chuck_.push_back(rect(jaw0 - s.chuck_length, 0, jaw0, s.chuck_diameter / 2));
    chuck_ = clip(chuck_, {}, ClipperLib::ctUnion);
    if (s.tailstock) {
        // A 60° centre, then the quill.
        double tz = s.tailstock_z, rq = s.quill_diameter / 2, cone = 8 / std::tan(30 * kPi / 180);
        CPath tip{to_int({tz, 0}), to_int({tz + cone, 0}), to_int({tz + cone, 8})};
        tail_ = clip({tip, rect(tz + cone, 0, tz + cone + 120, rq)}, {}, ClipperLib::ctUnion);
    }
    chuck_box_ = box(chuck_);
    tail_box_ = box(tail_);
    new_part();
}

void LatheWorld::new_part() {
    double right = s_.chuck_z + s_.stickout, left = right - s_.stock_length;
    ++generation_;
    part_ = {rect(left, s_.bore / 2, right, s_.stock_diameter / 2)};
    if (!s_.profile.empty()) {
        CPath p;
        for (const Pt& q : s_.profile) p.push_back(to_int({right + q[0], q[1]}));
        part_ = clip({p}, {}, ClipperLib::ctUnion);
    }
}

CPaths LatheWorld::sweep(const CPath& shape, const std::vector<Pt>& path) {
    // Clipper's sum sweeps the shape's edges; the shape itself at both ends
    // fills what the edges leave.
    CPaths out;
    CPath p;
    for (const Pt& q : path) p.push_back(to_int(q));
    if (convex(shape)) {
        // A convex shape along a straight move sweeps the hull of its two
        // places: exact, and much cheaper than the sum. Along a polyline (an
        // arc's chords) it sweeps the union of those hulls, a Boolean of a
        // few dozen small polygons where the sum makes one quadrilateral per
        // edge of the shape and of the path.
        for (size_t i = 0; i + 1 < std::max<size_t>(p.size(), 2); ++i) {
            CPath both;
            for (const IntPoint& d : {p[i], p[std::min(i + 1, p.size() - 1)]})
                for (const IntPoint& q : shape) both.emplace_back(q.X + d.X, q.Y + d.Y);
            out.push_back(hull(std::move(both)));
        }
        if (out.size() > 1) out = clip(out, {}, ClipperLib::ctUnion);
        return mirrored(std::move(out));
    }
    if (p.size() > 1) ClipperLib::MinkowskiSum(shape, p, out, false);
    // What the edges never cross was under the shape where the path starts
    // or where it ends.
    for (const IntPoint& d : {p.front(), p.back()}) {
        CPath moved = shape;
        for (IntPoint& q : moved) q.X += d.X, q.Y += d.Y;
        out.push_back(std::move(moved));
    }
    out = clip(out, {}, ClipperLib::ctUnion);
    return mirrored(std::move(out));
}

LatheWorld::Box LatheWorld::box(const CPaths& p) {
    Box b;
    bool any = false;
    for (const CPath& q : p)
        for (const IntPoint& v : q) {
            if (!any) b.x0 = b.x1 = v.X, b.y0 = b.y1 = v.Y, any = true;
            b.x0 = std::min(b.x0, v.X), b.x1 = std::max(b.x1, v.X);
            b.y0 = std::min(b.y0, v.Y), b.y1 = std::max(b.y1, v.Y);
        }
    return b;
}

void LatheWorld::set_gauge_block(double length) {
    gauge_length_ = length > 0 ? length : 0;
    gauge_.clear();
    if (gauge_length_ > 0) {
        const double r0 = s_.stock_diameter / 2 + 2;
        gauge_.push_back(rect(s_.chuck_z, r0, s_.chuck_z + gauge_length_, r0 + 9));
    }
    gauge_box_ = box(gauge_);
}

const CPaths& LatheWorld::obstacle(Obstacle what) const {
    return what == Obstacle::material    ? part_
           : what == Obstacle::chuck     ? chuck_
           : what == Obstacle::tailstock ? tail_
                                         : gauge_;
}

const LatheWorld::Box& LatheWorld::box_of(Obstacle what) const {
    if (what == Obstacle::chuck) return chuck_box_;
    if (what == Obstacle::tailstock) return tail_box_;
    if (what == Obstacle::gauge) return gauge_box_;
    if (part_box_gen_ != generation_) part_box_ = box(part_), part_box_gen_ = generation_;
    return part_box_;
}

bool LatheWorld::near(Obstacle what, double z0, double r0, double z1, double r1) const {
    const CPaths& o = obstacle(what);
    if (o.empty()) return false;
    Box b;
    b.x0 = to_int({z0, r0}).X, b.y0 = to_int({z0, r0}).Y;
    b.x1 = to_int({z1, r1}).X, b.y1 = to_int({z1, r1}).Y;
    return b.meets(box_of(what));
}

double LatheWorld::depth_into(const CPaths& swept, Obstacle what) const {
    const CPaths& o = obstacle(what);
    if (o.empty() || swept.empty()) return 0;
    if (!box(swept).meets(box_of(what))) return 0;  // far apart: no Boolean needed
    double deepest = 0;
    for (const CPath& q : clip(swept, o, ClipperLib::ctIntersection)) {
        double a = std::abs(ClipperLib::Area(q)) * kUnit * kUnit, per = 0;
        for (size_t i = 0; i < q.size(); ++i) {
            Pt p0 = to_mm(q[i]), p1 = to_mm(q[(i + 1) % q.size()]);
            per += std::hypot(p1[0] - p0[0], p1[1] - p0[1]);
        }
        if (per > 0) deepest = std::max(deepest, 2 * a / per);
    }
    return deepest;
}

double LatheWorld::cut(const CPaths& swept) {
    double before = area_mm2(part_);
    CPaths after = clip(part_, swept, ClipperLib::ctDifference);
    double removed = before - area_mm2(after);
    if (removed > 0) {
        part_ = std::move(after);
        ++generation_;
    }
    return removed;
}

std::string LatheWorld::to_text() const {
    std::string o;
    for (const CPath& q : part_) {
        for (size_t i = 0; i < q.size(); ++i)
            o += (i ? " " : "") + std::to_string(q[i].X) + ' ' + std::to_string(q[i].Y);
        o += '\n';
    }
    return o;
}

bool LatheWorld::from_text(std::string_view text) {
    CPaths out;
    while (!text.empty()) {
        size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        CPath q;
        const char* p = line.data();
        const char* end = line.data() + line.size();
        while (p < end) {
            long long v[2];
            for (long long& x : v) {
                while (p < end && *p == ' ') ++p;
                auto r = std::from_chars(p, end, x);
                if (r.ec != std::errc() || std::llabs(x) > 100000000000LL) return false;  // 10 km
                p = r.ptr;
            }
            q.emplace_back(ClipperLib::cInt(v[0]), ClipperLib::cInt(v[1]));
            while (p < end && *p == ' ') ++p;
        }
        if (q.size() >= 3)
            out.push_back(std::move(q));
        else if (!q.empty())
            return false;
    }
    part_ = std::move(out);
    ++generation_;
    return true;
}

bool LatheWorld::right_face(double& z) const {
    bool any = false;
    for (const CPath& q : part_)
        for (const IntPoint& v : q) {
            double vz = double(v.X) * kUnit;
            if (!any || vz > z) z = vz;
            any = true;
        }
    return any;
}

void LatheWorld::crossings(double z, std::vector<double>& rs) const {
    rs.clear();
    for (const CPath& q : part_)
        for (size_t i = 0; i < q.size(); ++i) {
            Pt a = to_mm(q[i]), b = to_mm(q[(i + 1) % q.size()]);
            if ((a[0] <= z && z < b[0]) || (b[0] <= z && z < a[0]))
                rs.push_back(a[1] + (b[1] - a[1]) * (z - a[0]) / (b[0] - a[0]));
        }
    std::sort(rs.begin(), rs.end());
}

bool LatheWorld::outer_radius(double z, double& r) const {
    std::vector<double> rs;
    crossings(z, rs);
    if (rs.empty()) return false;
    r = rs.back();
    return true;
}

bool LatheWorld::inner_radius(double z, double& r) const {
    std::vector<double> rs;
    crossings(z, rs);
    if (rs.empty() || rs.front() < 1e-3) return false;
    r = rs.front();
    return true;
}

bool LatheWorld::groove(double z, double& left, double& right) const {
    double r0 = 0;
    if (!outer_radius(z, r0)) return false;
    std::vector<double> zs;
    for (const CPath& q : part_)
        for (const IntPoint& v : q) zs.push_back(double(v.X) * kUnit);
    std::sort(zs.begin(), zs.end());
    zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
    // A wall: just past the vertex the profile stands above the bottom.
    constexpr double eps = 2e-4, tol = 1e-3;
    auto wall = [&](double zv, double side) {
        double r = 0;
        return !outer_radius(zv + side * eps, r) ? -1 : r > r0 + tol ? 1 : 0;
    };
    left = right = z;
    bool found_left = false, found_right = false;
    for (auto it = std::upper_bound(zs.begin(), zs.end(), z); it != zs.begin();) {
        int w = wall(*--it, -1);
        if (w < 0) return false;  // the part ends: a step, not a groove
        if (w > 0) {
            left = *it;
            found_left = true;
            break;
        }
    }
    for (auto it = std::upper_bound(zs.begin(), zs.end(), z); it != zs.end(); ++it) {
        int w = wall(*it, +1);
        if (w < 0) return false;
        if (w > 0) {
            right = *it;
            found_right = true;
            break;
        }
    }
    return found_left && found_right;
}

}  // namespace pupitre::workshop
