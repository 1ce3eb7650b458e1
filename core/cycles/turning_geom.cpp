// Plane geometry shared by the turning cycles: exact intersections of lines and
// arcs (no polygonal approximation, so a pass ends exactly on an arc of the
// profile), winding numbers with arcs, distances.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cycles/turning_geom.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"

namespace pupitre::turning::geom {

namespace {
using ::pupitre::geometry::kPi;

using ::pupitre::geometry::cross;
using ::pupitre::geometry::perp;

V2 rotate(const V2& v, double ang) {
    double c = std::cos(ang), s = std::sin(ang);
    return V2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

// Parameter of p projected on segment e, in units of the segment length.
double seg_param(const Elem& e, const V2& p) {
    V2 d = e.b - e.a;
    double l2 = d.squaredNorm();
    return l2 > 0 ? (p - e.a).dot(d) / l2 : 0;
}

bool on_seg(const Elem& e, const V2& p, double tol) {
    double len = (e.b - e.a).norm();
    if (len < kTol) return (p - e.a).norm() <= tol;
    double t = seg_param(e, p);
    return t >= -tol / len && t <= 1 + tol / len;
}

// Points of the circle of arc `c` on the infinite line through segment `l`.
int line_circle(const Elem& l, const V2& c, double r, V2 out[2]) {
    V2 d = l.b - l.a;
    double len = d.norm();
    if (len < kTol) return 0;
    d /= len;
    V2 w = l.a - c;
    double b = w.dot(d), cc = w.squaredNorm() - r * r;
    double disc = b * b - cc;
    if (disc < -2 * r * kTol) return 0;
    double h = std::sqrt(std::max(0.0, disc));
    out[0] = l.a + (-b - h) * d;
    out[1] = l.a + (-b + h) * d;
    return h < kTol ? 1 : 2;
}

void push_unique(std::vector<V2>& pts, const V2& p) {
    for (const V2& q : pts)
        if ((q - p).norm() < kTol) return;
    pts.push_back(p);
}
}  // namespace

Elem line(const V2& a, const V2& b) {
    Elem e;
    e.a = a;
    e.b = b;
    return e;
}

Elem translated(const Elem& e, const V2& t) {
    Elem r = e;
    r.a += t;
    r.b += t;
    r.c += t;
    return r;
}

double arc_offset(const Elem& e, const V2& p) {
    double s = e.sweep < 0 ? -1 : 1;
    V2 u = e.a - e.c, v = p - e.c;
    double d = s * (std::atan2(v.y(), v.x()) - std::atan2(u.y(), u.x()));
    d = std::fmod(d, 2 * kPi);
    if (d < 0) d += 2 * kPi;
    return d;
}

bool on_arc(const Elem& e, const V2& p, double tol) {
    double r = e.r();
    if (r < kTol) return (p - e.a).norm() <= tol;
    double off = arc_offset(e, p), span = std::fabs(e.sweep), slack = tol / r;
    return off <= span + slack || off >= 2 * kPi - slack;
}

void intersect(const Elem& e, const Elem& f, std::vector<V2>& pts) {
    if (!e.arc && !f.arc) {
        V2 d1 = e.b - e.a, d2 = f.b - f.a;
        double l1 = d1.norm(), l2 = d2.norm();
        if (l1 < kTol || l2 < kTol) {
            const Elem& pt = l1 < kTol ? e : f;
            const Elem& other = l1 < kTol ? f : e;
            if (dist(other, pt.a) <= kTol) push_unique(pts, pt.a);
            return;
        }
        double den = cross(d1, d2);
        if (std::fabs(den) <= 1e-12 * l1 * l2) {
            if (std::fabs(cross(f.a - e.a, d1)) / l1 > kTol) return;  // parallel
            double t0 = seg_param(e, f.a), t1 = seg_param(e, f.b);
            double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
            if (hi < lo - kTol / l1) return;
            push_unique(pts, e.a + std::clamp(lo, 0.0, 1.0) * d1);
            push_unique(pts, e.a + std::clamp(hi, 0.0, 1.0) * d1);
            return;
        }
        double t = cross(f.a - e.a, d2) / den, u = cross(f.a - e.a, d1) / den;
        if (t < -kTol / l1 || t > 1 + kTol / l1 || u < -kTol / l2 || u > 1 + kTol / l2) return;
        push_unique(pts, e.a + std::clamp(t, 0.0, 1.0) * d1);
        return;
    }
    if (e.arc != f.arc) {
        const Elem& l = e.arc ? f : e;
        const Elem& c = e.arc ? e : f;
        if ((l.b - l.a).norm() < kTol) {
            if (dist(c, l.a) <= kTol) push_unique(pts, l.a);
            return;
        }
        V2 p[2];
        int n = line_circle(l, c.c, c.r(), p);
        for (int i = 0; i < n; ++i)
            if (on_seg(l, p[i], kTol) && on_arc(c, p[i])) push_unique(pts, p[i]);
        return;
    }
    double r1 = e.r(), r2 = f.r();
    V2 d = f.c - e.c;
    double dd = d.norm();
    if (dd < kTol) {
        if (std::fabs(r1 - r2) > kTol) return;
        for (const V2& p : {f.a, f.b})
            if (on_arc(e, p)) push_unique(pts, p);
        for (const V2& p : {e.a, e.b})
            if (on_arc(f, p)) push_unique(pts, p);
        return;
    }
    double a = (r1 * r1 - r2 * r2 + dd * dd) / (2 * dd);
    double h2 = r1 * r1 - a * a;
    if (h2 < -2 * r1 * kTol) return;
    double h = std::sqrt(std::max(0.0, h2));
    V2 m = e.c + a * d / dd;
    for (V2 p : {V2(m + h * perp(d) / dd), V2(m - h * perp(d) / dd)})
        if (on_arc(e, p) && on_arc(f, p)) push_unique(pts, p);
}

void cross_h(const Elem& e, double Y, std::vector<double>& xs) {
    bool ea = std::fabs(e.a.y() - Y) <= kTol, eb = std::fabs(e.b.y() - Y) <= kTol;
    if (ea) xs.push_back(e.a.x());
    if (eb) xs.push_back(e.b.x());
    if (!e.arc) {
        if (ea || eb) return;
        double da = e.a.y() - Y, db = e.b.y() - Y;
        if ((da < 0) == (db < 0)) return;
        xs.push_back(e.a.x() + (e.b.x() - e.a.x()) * da / (da - db));
        return;
    }
    double r = e.r(), dy = Y - e.c.y();
    if (std::fabs(dy) > r + kTol) return;
    double h = std::sqrt(std::max(0.0, r * r - dy * dy));
    for (double x : {e.c.x() - h, e.c.x() + h}) {
        V2 p(x, Y);
        if ((ea && (p - e.a).norm() < 1e-7) || (eb && (p - e.b).norm() < 1e-7)) continue;
        if (on_arc(e, p)) xs.push_back(x);
        if (h < kTol) break;
    }
}

double ray_hit(const Elem& e, const V2& p, const V2& u) {
    double un = u.norm();
    if (un < kTol) return kInf;
    V2 v = u / un;
    double best = kInf;
    if (!e.arc) {
        V2 d = e.b - e.a;
        double len = d.norm();
        if (len < kTol) {
            double s = (e.a - p).dot(v);
            if (s >= -kTol && std::fabs(cross(v, e.a - p)) <= kTol) best = std::max(0.0, s);
            return best / un;
        }
        double den = cross(v, d);
        if (std::fabs(den) <= 1e-12 * len) {
            if (std::fabs(cross(v, e.a - p)) > kTol) return kInf;
            double sa = (e.a - p).dot(v), sb = (e.b - p).dot(v);
            if (std::max(sa, sb) < -kTol) return kInf;
            best = std::min(sa, sb) <= 0 ? 0 : std::min(sa, sb);
            return best / un;
        }
        double s = cross(e.a - p, d) / den, t = cross(e.a - p, v) / den;
        if (s >= -kTol && t >= -kTol / len && t <= 1 + kTol / len) best = std::max(0.0, s);
        return best / un;
    }
    V2 w = p - e.c;
    double r = e.r(), b = w.dot(v), cc = w.squaredNorm() - r * r, disc = b * b - cc;
    if (disc < -2 * r * kTol) return kInf;
    double h = std::sqrt(std::max(0.0, disc));
    for (double s : {-b - h, -b + h})
        if (s >= -kTol && on_arc(e, p + s * v)) {
            best = std::max(0.0, s);
            break;
        }
    return best / un;
}

V2 closest(const Elem& e, const V2& p, V2* tangent) {
    if (!e.arc) {
        V2 d = e.b - e.a;
        double len = d.norm();
        if (tangent) *tangent = len > 0 ? V2(d / len) : V2(1, 0);
        return e.a + std::clamp(seg_param(e, p), 0.0, 1.0) * d;
    }
    V2 w = p - e.c;
    double r = e.r(), n = w.norm();
    V2 q = n > kTol ? V2(e.c + r * w / n) : e.a;
    if (!on_arc(e, q)) q = (p - e.a).norm() <= (p - e.b).norm() ? e.a : e.b;
    if (tangent) *tangent = perp(q - e.c).normalized() * (e.sweep < 0 ? -1.0 : 1.0);
    return q;
}

double dist(const Elem& e, const V2& p) {
    return (closest(e, p) - p).norm();
}

namespace {
bool arc_has_dir(const Elem& e, const V2& dir) {
    return on_arc(e, V2(e.c + e.r() * dir));
}
}  // namespace

double min_y(const Elem& e) {
    double m = std::min(e.a.y(), e.b.y());
    if (e.arc && arc_has_dir(e, V2(0, -1))) m = std::min(m, e.c.y() - e.r());
    return m;
}

double max_y(const Elem& e) {
    double m = std::max(e.a.y(), e.b.y());
    if (e.arc && arc_has_dir(e, V2(0, 1))) m = std::max(m, e.c.y() + e.r());
    return m;
}

namespace {
// Candidate points of e with x in [x0, x1] where y can be extreme.
std::vector<V2> extreme_candidates(const Elem& e, double x0, double x1) {
    std::vector<V2> c;
    auto in = [&](const V2& p) { return p.x() >= x0 - kTol && p.x() <= x1 + kTol; };
    for (const V2& p : {e.a, e.b})
        if (in(p)) c.push_back(p);
    if (!e.arc) {
        V2 d = e.b - e.a;
        if (std::fabs(d.x()) > kTol)
            for (double x : {x0, x1}) {
                double t = (x - e.a.x()) / d.x();
                if (t > 0 && t < 1) c.push_back(e.a + t * d);
            }
        return c;
    }
    double r = e.r();
    for (const V2& dir : {V2(0, -1), V2(0, 1)}) {
        V2 p = e.c + r * dir;
        if (in(p) && on_arc(e, p)) c.push_back(p);
    }
    for (double x : {x0, x1}) {
        double dx = x - e.c.x();
        if (std::fabs(dx) > r) continue;
        double h = std::sqrt(r * r - dx * dx);
        for (double y : {e.c.y() - h, e.c.y() + h})
            if (on_arc(e, V2(x, y))) c.push_back(V2(x, y));
    }
    return c;
}
}  // namespace

double min_y_in(const Elem& e, double x0, double x1) {
    double m = kInf;
    for (const V2& p : extreme_candidates(e, x0, x1)) m = std::min(m, p.y());
    return m;
}

double max_y_in(const Elem& e, double x0, double x1) {
    double m = -kInf;
    for (const V2& p : extreme_candidates(e, x0, x1)) m = std::max(m, p.y());
    return m;
}

Box box(const Elem& e, double pad) {
    if (e.arc) {
        const double r = e.r();
        return {e.c.x() - r - pad, e.c.x() + r + pad, e.c.y() - r - pad, e.c.y() + r + pad};
    }
    return {std::min(e.a.x(), e.b.x()) - pad, std::max(e.a.x(), e.b.x()) + pad,
            std::min(e.a.y(), e.b.y()) - pad, std::max(e.a.y(), e.b.y()) + pad};
}

double length(const Elem& e) {
    return e.arc ? e.r() * std::fabs(e.sweep) : (e.b - e.a).norm();
}

V2 midpoint(const Elem& e) {
    return point_at(e, 0.5);
}

V2 point_at(const Elem& e, double t) {
    if (!e.arc) return e.a + t * (e.b - e.a);
    return e.c + rotate(e.a - e.c, t * e.sweep);
}

int winding(const std::vector<Elem>& loop, const V2& q) {
    double sum = 0;
    for (const Elem& e : loop) {
        V2 u = e.a - q, v = e.b - q;
        double d = std::atan2(cross(u, v), u.dot(v));
        if (e.arc && (q - e.c).norm() < e.r()) {
            if (e.sweep > 0 && d <= 0) d += 2 * kPi;
            if (e.sweep < 0 && d >= 0) d -= 2 * kPi;
        }
        sum += d;
    }
    return int(std::lround(sum / (2 * kPi)));
}

bool on_loop(const std::vector<Elem>& loop, const V2& q, double tol) {
    for (const Elem& e : loop)
        if (dist(e, q) <= tol) return true;
    return false;
}

namespace {
bool near_end(const Elem& e, const V2& p) {
    return (p - e.a).norm() < 1e-7 || (p - e.b).norm() < 1e-7;
}

// Adjacent elements meeting at `joint` fold back onto each other.
bool folds(const Elem& e, const Elem& f, const V2& joint) {
    std::vector<V2> pts;
    intersect(e, f, pts);
    for (const V2& p : pts)
        if ((p - joint).norm() > 1e-7) return true;
    return false;
}
}  // namespace

bool self_intersects(const std::vector<Elem>& loop) {
    const size_t n = loop.size();
    // Only elements whose boxes meet can meet: a sweep along x over the boxes
    // (a rough stock may have thousands of points).
    std::vector<Box> boxes(n);
    for (size_t i = 0; i < n; ++i) boxes[i] = box(loop[i], kUm);
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return boxes[a].x0 < boxes[b].x0; });
    std::vector<V2> pts;
    for (size_t oi = 0; oi < n; ++oi) {
        for (size_t oj = oi + 1; oj < n && boxes[order[oj]].x0 <= boxes[order[oi]].x1; ++oj) {
            size_t i = std::min(order[oi], order[oj]), j = std::max(order[oi], order[oj]);
            if (boxes[i].y0 > boxes[j].y1 || boxes[j].y0 > boxes[i].y1) continue;
            bool next = j == i + 1, wrap = i == 0 && j == n - 1;
            if (next || wrap) {
                if (n > 2 && folds(loop[i], loop[j], next ? loop[i].b : loop[i].a)) return true;
                continue;
            }
            pts.clear();
            intersect(loop[i], loop[j], pts);
            // An overlap of collinear or concentric elements, or two crossings.
            if (pts.size() >= 2 && (pts[0] - pts[1]).norm() > 1e-7) return true;
            for (const V2& p : pts)
                if (!near_end(loop[i], p) && !near_end(loop[j], p)) return true;
        }
    }
    return false;
}

Elem Frame::to(const Elem& e) const {
    Elem r = e;
    r.a = to(e.a);
    r.b = to(e.b);
    r.c = to(e.c);
    r.sweep = e.sweep * det();
    return r;
}

std::vector<Elem> Frame::to(const std::vector<Elem>& es) const {
    std::vector<Elem> out;
    out.reserve(es.size());
    for (const Elem& e : es) out.push_back(to(e));
    return out;
}

}  // namespace pupitre::turning::geom
