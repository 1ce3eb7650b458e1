// Material region, allowance zone and the runs of a pass line through them.
// Passes are cut where a level line lies inside the material and outside the
// allowance zone; both are decided exactly (winding numbers with arcs, exact
// crossings), then sub-intervals are classified at their midpoints.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cycles/turning_zone.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"

namespace pupitre::turning::zone {

using namespace geom;

namespace {
using ::pupitre::geometry::kPi;

using ::pupitre::geometry::perp;

Elem arc(const V2& c, const V2& a, double sweep) {
    Elem e;
    e.arc = true;
    e.c = c;
    e.a = a;
    V2 u = a - c;
    double cs = std::cos(sweep), sn = std::sin(sweep);
    e.b = c + V2(cs * u.x() - sn * u.y(), sn * u.x() + cs * u.y());
    e.sweep = sweep;
    return e;
}

void full_circle(const V2& c, double r, std::vector<Elem>& out) {
    out.push_back(arc(c, c + V2(r, 0), kPi));
    out.push_back(arc(c, c - V2(r, 0), kPi));
}
}  // namespace

void Material::translate(const V2& allowance) {
    f_index = {}, u_index = {};
    normal = false;
    t = allowance;
    U = F;
    if (t.norm() < kTol) return;
    V2 n = perp(t).normalized();
    for (const Elem& e : F) {
        U.push_back(translated(e, t));
        U.push_back(line(e.a, e.a + t));
        U.push_back(line(e.b, e.b + t));
        if (!e.arc) continue;
        // Where the arc's tangent is parallel to t, the swept zone's boundary
        // is the segment swept by that point.
        for (double sg : {-1.0, 1.0}) {
            V2 p = e.c + sg * e.r() * n;
            if (on_arc(e, p)) U.push_back(line(p, p + t));
        }
    }
}

void Material::offset(double allowance) {
    f_index = {}, u_index = {};
    normal = true;
    er = std::max(0.0, allowance);
    U = F;
    if (er < kTol) return;
    for (const Elem& e : F) {
        if (e.arc) {
            double r = e.r();
            for (double rr : {r - er, r + er}) {
                if (rr < kTol) continue;
                Elem o = e;
                o.a = e.c + (e.a - e.c) * (rr / r);
                o.b = e.c + (e.b - e.c) * (rr / r);
                U.push_back(o);
            }
        } else {
            V2 d = e.b - e.a;
            if (d.norm() < kTol) continue;
            V2 n = perp(d).normalized() * er;
            U.push_back(line(e.a + n, e.b + n));
            U.push_back(line(e.a - n, e.b - n));
        }
        full_circle(e.a, er, U);
        full_circle(e.b, er, U);
    }
}

bool Material::in_A(const V2& q) const {
    if (normal) {
        double lim = std::max(er - kTol, kTol);
        for (const Elem& e : F)
            if (dist(e, q) < lim) return true;
        return false;
    }
    double tn = t.norm();
    if (tn < kTol) {
        for (const Elem& e : F)
            if (dist(e, q) <= kTol) return true;
        return false;
    }
    // q is in A when moving it back by (a fraction of) t meets the finished
    // profile; stopping 0.1 µm short of the full t (well above the tolerance of
    // the intersections) leaves the translated profile itself outside.
    double eps = std::min(0.5, 100 * kTol / tn);
    Elem s = line(q - (1 - eps) * t, q);
    std::vector<int> near;
    f_idx().near(box(s, 0), near);  // the others cannot meet s
    std::vector<V2> pts;
    for (int i : near) {
        intersect(F[size_t(i)], s, pts);
        if (!pts.empty()) return true;
    }
    return false;
}

void ExtentIndex::build(const std::vector<Elem>& es, double pad, int axis) {
    src_ = es.data();
    n_ = es.size();
    nodes_.clear();
    lo_.resize(n_);
    hi_.resize(n_);
    for (size_t i = 0; i < n_; ++i) {
        const Elem& e = es[i];
        const double a = e.a[axis], b = e.b[axis], c = e.c[axis];
        double lo = std::min(a, b), hi = std::max(a, b);
        if (e.arc) lo = std::min(lo, c - e.r()), hi = std::max(hi, c + e.r());
        lo_[i] = lo - pad;
        hi_[i] = hi + pad;
    }
    std::vector<int> ids(n_);
    for (size_t i = 0; i < n_; ++i) ids[i] = int(i);
    make(ids);
}

// A node holds the elements across the median of the end points; each side
// gets at most half of them, so the depth is logarithmic.
int ExtentIndex::make(std::vector<int>& ids) {
    if (ids.empty()) return -1;
    std::vector<double> ends;
    ends.reserve(2 * ids.size());
    for (int i : ids) ends.push_back(lo_[size_t(i)]), ends.push_back(hi_[size_t(i)]);
    auto mid = ends.begin() + ptrdiff_t(ends.size() / 2);
    std::nth_element(ends.begin(), mid, ends.end());
    const double c = *mid;
    std::vector<int> below, above, here;
    for (int i : ids) {
        if (hi_[size_t(i)] < c)
            below.push_back(i);
        else if (lo_[size_t(i)] > c)
            above.push_back(i);
        else
            here.push_back(i);
    }
    int k = int(nodes_.size());
    nodes_.emplace_back();
    nodes_[size_t(k)].c = c;
    nodes_[size_t(k)].by_lo = here;
    std::sort(nodes_[size_t(k)].by_lo.begin(), nodes_[size_t(k)].by_lo.end(),
              [this](int a, int b) { return lo_[size_t(a)] < lo_[size_t(b)]; });
    nodes_[size_t(k)].by_hi = std::move(here);
    std::sort(nodes_[size_t(k)].by_hi.begin(), nodes_[size_t(k)].by_hi.end(),
              [this](int a, int b) { return hi_[size_t(a)] > hi_[size_t(b)]; });
    ids.clear();
    int l = make(below);
    nodes_[size_t(k)].left = l;  // nodes_ may have moved: index again
    int r = make(above);
    nodes_[size_t(k)].right = r;
    return k;
}

void ExtentIndex::query(double y, std::vector<int>& out) const {
    for (int k = nodes_.empty() ? -1 : 0; k >= 0;) {
        const Node& n = nodes_[size_t(k)];
        if (y < n.c) {
            for (int i : n.by_lo) {
                if (lo_[size_t(i)] > y) break;
                out.push_back(i);
            }
            k = n.left;
        } else {
            for (int i : n.by_hi) {
                if (hi_[size_t(i)] < y) break;
                out.push_back(i);
            }
            k = n.right;
        }
    }
}

// The elements of a node all hold its centre: below [lo, hi] the ones that
// reach up to lo, above it the ones that reach down to hi, else all of them.
void ExtentIndex::meeting(int k, double lo, double hi, std::vector<int>& out) const {
    if (k < 0 || nodes_.empty()) return;
    const Node& n = nodes_[size_t(k)];
    if (hi < n.c) {
        for (int i : n.by_lo) {
            if (lo_[size_t(i)] > hi) break;
            out.push_back(i);
        }
        return meeting(n.left, lo, hi, out);
    }
    if (lo > n.c) {
        for (int i : n.by_hi) {
            if (hi_[size_t(i)] < lo) break;
            out.push_back(i);
        }
        return meeting(n.right, lo, hi, out);
    }
    out.insert(out.end(), n.by_lo.begin(), n.by_lo.end());
    meeting(n.left, lo, hi, out);
    meeting(n.right, lo, hi, out);
}

namespace {
// The x where a vertical's meeting with the element can change whatever the
// level: its ends and, on an arc, its extremes along x.
void static_xs(const Elem& e, std::vector<double>& xs) {
    xs.push_back(e.a.x());
    xs.push_back(e.b.x());
    if (e.arc)
        for (double sg : {-1.0, 1.0})
            if (on_arc(e, e.c + V2(sg * e.r(), 0))) xs.push_back(e.c.x() + sg * e.r());
}
}  // namespace

void ElemIndex::build(const std::vector<Elem>& es) {
    // Widened as the boxes: the elements they find hold every box that meets.
    by_x.build(es, kUm, 0);
    by_y.build(es, kUm, 1);
    box.clear();
    ends_up.clear();
    tops.clear();
    for (size_t i = 0; i < es.size(); ++i) {
        box.push_back(geom::box(es[i], kUm));
        static_xs(es[i], ends_up);
        tops.push_back({box.back().y1, int(i)});
    }
    std::sort(ends_up.begin(), ends_up.end());
    ends_down.assign(ends_up.rbegin(), ends_up.rend());
    std::sort(tops.begin(), tops.end(), std::greater<>());
}

void ElemIndex::near(const Box& b, std::vector<int>& out) const {
    const size_t from = out.size();
    if (b.x1 - b.x0 < b.y1 - b.y0)
        by_x.query(b.x0, b.x1, out);
    else
        by_y.query(b.y0, b.y1, out);
    out.erase(std::remove_if(out.begin() + ptrdiff_t(from), out.end(),
                             [&](int i) { return !box[size_t(i)].meets(b); }),
              out.end());
}

const ElemIndex& Material::f_idx() const {
    if (!f_index.built_for(F)) f_index.build(F);
    return f_index;
}

const ElemIndex& Material::u_idx() const {
    if (!u_index.built_for(U)) u_index.build(U);
    return u_index;
}

namespace {
// Where the element crosses the line y = Y going up (+1) or down (-1), by the
// half-open rule (an end exactly on the line counts for the element it is the
// lower end of), so that summing the crossings right of a point not on the
// loop gives its winding number. Arcs are cut where y is extreme, into pieces
// along which y only rises or only falls, each on one side of the centre.
void ray_crossings(const Elem& e, double Y, std::vector<std::pair<double, int>>& out) {
    auto piece = [&](const V2& p, const V2& q, double side) {
        if ((p.y() <= Y) == (q.y() <= Y)) return;
        double x;
        if (!e.arc) {
            x = p.x() + (q.x() - p.x()) * (Y - p.y()) / (q.y() - p.y());
        } else {
            double r = e.r(), dy = Y - e.c.y();
            x = e.c.x() + side * std::sqrt(std::max(0.0, r * r - dy * dy));
        }
        out.push_back({x, q.y() > p.y() ? 1 : -1});
    };
    if (!e.arc) return piece(e.a, e.b, 0);
    const double r = e.r(), t0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x()),
                 t1 = t0 + e.sweep;
    const double lo = std::min(t0, t1), hi = std::max(t0, t1), eps = 1e-12;
    std::vector<double> ts{t0};
    // The angles pi/2 + k pi strictly inside the sweep, in the sense of travel.
    for (double t = kPi / 2 + std::ceil((lo + eps - kPi / 2) / kPi) * kPi; t < hi - eps; t += kPi)
        ts.push_back(t);
    if (e.sweep < 0) std::reverse(ts.begin() + 1, ts.end());
    ts.push_back(t1);
    V2 p = e.a;
    for (size_t i = 1; i < ts.size(); ++i) {
        bool last = i + 1 == ts.size();
        V2 q = last ? e.b : V2(e.c.x(), e.c.y() + r * std::sin(ts[i]));
        piece(p, q, std::cos((ts[i - 1] + ts[i]) / 2) >= 0 ? 1 : -1);
        p = q;
    }
}

}  // namespace

// On M's boundary, or a winding number other than 0, which the crossings of
// the ray from q along +x give, as m_intervals finds them: only the elements
// of M whose extent along y holds q can be within kTol of it or cross the ray
// (m_index). (The winding number's angle about q from every element of M,
// asked at every sample of G64's last pass, was a sixth of the cycle's work.)
bool Material::in_M(const V2& q) const {
    if (M.empty()) return false;
    if (!m_index.built_for(M)) m_index.build(M, 10 * kTol);
    std::vector<int> near;
    m_index.query(q.y(), near);
    std::vector<std::pair<double, int>> ray;
    for (int i : near) {
        if (dist(M[size_t(i)], q) <= kTol) return true;
        ray_crossings(M[size_t(i)], q.y(), ray);
    }
    int w = 0;
    for (const auto& [x, s] : ray)
        if (x > q.x()) w += s;
    return w != 0;
}

namespace {
// A point where the line meets M, with the kinds of the edges met there.
struct Cut {
    double x;
    int mask;
};

// The kind an interval's end takes from the edges met there: the stock before
// the closing edges before the profile.
int kind_of(int mask) {
    if (mask & (1 << kStock)) return int(kStock);
    if (mask & (1 << kClosing)) return int(kClosing);
    return int(kProfile);
}

// The crossings of the line with the elements `near`, merged where they lie
// within kTol of each other, in rising x; and the crossings of the ray, for
// the winding numbers.
std::vector<Cut> line_cuts(const Material& m, double Y, const std::vector<int>& near,
                           std::vector<std::pair<double, int>>& ray) {
    std::vector<Cut> xs;
    std::vector<double> tmp;
    for (int i : near) {
        tmp.clear();
        cross_h(m.M[size_t(i)], Y, tmp);
        for (double x : tmp) xs.push_back({x, 1 << m.kind[size_t(i)]});
        ray_crossings(m.M[size_t(i)], Y, ray);
    }
    std::sort(xs.begin(), xs.end(), [](const Cut& a, const Cut& b) { return a.x < b.x; });
    std::vector<Cut> pts;
    for (const Cut& x : xs) {
        if (!pts.empty() && x.x - pts.back().x <= kTol)
            pts.back().mask |= x.mask;
        else
            pts.push_back(x);
    }
    return pts;
}

// Whether a point of the line is in M, asked at rising x: on the boundary, the
// elements whose extent along x holds the point, kept in a sweep so that each
// is tested only while it can hold one; else the winding number right of x,
// the sum of the crossings beyond it.
class InsideSweep {
  public:
    InsideSweep(const Material& m, double Y, const std::vector<int>& near,
                std::vector<std::pair<double, int>>& ray)
        : m_(m), Y_(Y), ray_(ray) {
        std::sort(ray.begin(), ray.end());
        beyond_.assign(ray_.size() + 1, 0);
        for (size_t i = ray_.size(); i-- > 0;) beyond_[i] = beyond_[i + 1] + ray_[i].second;
        for (int i : near) by_lo_.push_back({x_lo(i), i});
        std::sort(by_lo_.begin(), by_lo_.end());
    }

    bool operator()(double x) {
        while (next_ < by_lo_.size() && by_lo_[next_].first <= x)
            active_.push_back(by_lo_[next_++].second);
        V2 q(x, Y_);
        for (size_t k = 0; k < active_.size();) {
            int i = active_[k];
            if (x_hi(i) < x) {  // behind the sweep for good
                active_[k] = active_.back();
                active_.pop_back();
                continue;
            }
            if (dist(m_.M[size_t(i)], q) <= kTol) return true;
            ++k;
        }
        auto it = std::upper_bound(ray_.begin(), ray_.end(), std::pair<double, int>(x, 2));
        return beyond_[size_t(it - ray_.begin())] != 0;
    }

  private:
    double x_lo(int i) const {
        const Elem& e = m_.M[size_t(i)];
        return (e.arc ? e.c.x() - e.r() : std::min(e.a.x(), e.b.x())) - 10 * kTol;
    }
    double x_hi(int i) const {
        const Elem& e = m_.M[size_t(i)];
        return (e.arc ? e.c.x() + e.r() : std::max(e.a.x(), e.b.x())) + 10 * kTol;
    }

    const Material& m_;
    double Y_;
    const std::vector<std::pair<double, int>>& ray_;
    std::vector<int> beyond_;
    std::vector<std::pair<double, int>> by_lo_;
    std::vector<int> active_;
    size_t next_ = 0;
};
}  // namespace

std::vector<Interval> m_intervals(const Material& m, double Y, int d) {
    // Only the elements of M near the line matter (ExtentIndex): the crossings, the
    // boundary within kTol, and the winding numbers by the crossings of a ray.
    if (!m.m_index.built_for(m.M)) m.m_index.build(m.M, 10 * kTol);
    std::vector<int> near;
    m.m_index.query(Y, near);
    std::sort(near.begin(), near.end());
    std::vector<std::pair<double, int>> ray;
    const std::vector<Cut> pts = line_cuts(m, Y, near, ray);
    InsideSweep inside(m, Y, near, ray);
    // Runs of inside sub-intervals, as index ranges into pts.
    std::vector<std::pair<size_t, size_t>> runs;
    bool open = false;
    for (size_t j = 0; j + 1 < pts.size(); ++j) {
        bool in = inside((pts[j].x + pts[j + 1].x) / 2);
        if (in && open)
            runs.back().second = j + 1;
        else if (in)
            runs.push_back({j, j + 1});
        open = in;
    }
    std::vector<Interval> out;
    for (auto [i, j] : runs)
        out.push_back({pts[i].x, pts[j].x, kind_of(d > 0 ? pts[i].mask : pts[j].mask),
                       kind_of(d > 0 ? pts[j].mask : pts[i].mask)});
    return out;
}

std::vector<std::pair<double, double>> free_runs(const Material& m, double Y, double x0, double x1,
                                                 int d) {
    std::vector<std::pair<double, double>> runs;
    if ((x1 - x0) * d <= 0) return runs;
    std::vector<double> xs;
    // Only the elements whose extent along y holds the line cross it (ExtentIndex).
    std::vector<int> near;
    m.f_idx().by_y.query(Y, near);
    // Outside the part, meeting the profile means entering the part: the runs
    // end there whatever A says (A is only decided outside the part).
    for (int i : near) cross_h(m.F[size_t(i)], Y, xs);
    for (double x : xs)
        if ((x - x0) * d > kTol && (x1 - x) * d > 0) x1 = x;
    xs.clear();
    near.clear();
    m.u_idx().by_y.query(Y, near);
    for (int i : near) cross_h(m.U[size_t(i)], Y, xs);
    std::vector<double> cuts{x0};
    for (double x : xs)
        if ((x - x0) * d > kTol && (x1 - x) * d > kTol) cuts.push_back(x);
    cuts.push_back(x1);
    std::sort(cuts.begin(), cuts.end(), [d](double a, double b) { return a * d < b * d; });
    if (m.zero()) {  // the run ends where the line meets the profile
        if (!m.in_A(V2(x0, Y)) || std::fabs(cuts[1] - x0) > kTol) runs.push_back({x0, cuts[1]});
        return runs;
    }
    bool open = false;
    for (size_t j = 0; j + 1 < cuts.size(); ++j) {
        double a = cuts[j], b = cuts[j + 1];
        if (std::fabs(b - a) <= kTol) continue;
        bool free = !m.in_A(V2((a + b) / 2, Y));
        if (free && open)
            runs.back().second = b;
        else if (free)
            runs.push_back({a, b});
        open = free;
    }
    return runs;
}

namespace {
// Whether a vertical from (x, y0) up to y1 meets A changes only at the ends
// of A's boundary curves, at their extremes along x and where they cross y0
// or y1: those x strictly between x0 and x1, with x0 and x1, sorted along d.
std::vector<double> critical_xs(const Material& m, double y0, double y1, double x0, double x1,
                                int d) {
    auto between = [&](double x) { return (x - x0) * d > kTol && (x1 - x) * d > kTol; };
    std::vector<double> cuts{x0, x1}, xs;
    for (const Elem& e : m.U) {
        xs.clear();
        static_xs(e, xs);
        cross_h(e, y0, xs);
        if (y1 != y0) cross_h(e, y1, xs);
        for (double x : xs)
            if (between(x)) cuts.push_back(x);
    }
    std::sort(cuts.begin(), cuts.end(), [d](double a, double b) { return a * d < b * d; });
    return cuts;
}

// The elements of U that can hide a point of a pass between x0 and x1 from
// above `lift`: those reaching above it whose extent along x meets the pass.
// No other element has a point above lift at an x of the pass.
std::vector<int> hiding(const ElemIndex& ix, double lift, double x0, double x1) {
    const double lo = std::min(x0, x1), hi = std::max(x0, x1);
    std::vector<int> ids;
    for (const auto& [top, i] : ix.tops) {
        if (top <= lift) break;
        if (ix.box[size_t(i)].x1 >= lo && ix.box[size_t(i)].x0 <= hi) ids.push_back(i);
    }
    return ids;
}

// The cuts of critical_xs(m, lift, lift, x0, x1, d), walked along d from the
// last one at or before u = x·d = `from`: the index's sorted ends merged with
// the crossings of the level line, so that a pass sorts no more than these.
class CutWalk {
  public:
    CutWalk(const Material& m, double lift, double x0, double x1, int d, double from)
        : ends_(d > 0 ? m.u_index.ends_up : m.u_index.ends_down), x0_(x0), x1_(x1), d_(d) {
        std::vector<int> near;
        m.u_index.by_y.query(lift, near);
        std::vector<double> xs;
        for (int i : near) cross_h(m.U[size_t(i)], lift, xs);
        for (double x : xs)
            if (between(x)) cross_.push_back(x);
        std::sort(cross_.begin(), cross_.end(), [d](double a, double b) { return a * d < b * d; });
        start_ = x0;
        auto after = [d](double u, double x) { return u < x * d; };
        auto e = std::upper_bound(ends_.begin(), ends_.end(), from, after);
        for (; e != ends_.begin() && (*(e - 1) - x0) * d > kTol; --e)
            if (between(*(e - 1))) {
                start_ = *(e - 1);
                break;
            }
        for (double x : cross_)
            if (x * d <= from && x * d > start_ * d) start_ = x;
        i_ =
            size_t(std::upper_bound(ends_.begin(), ends_.end(), start_ * d, after) - ends_.begin());
        j_ = size_t(std::upper_bound(cross_.begin(), cross_.end(), start_ * d, after) -
                    cross_.begin());
    }
    double start() const { return start_; }
    // The next cut along d, x1 last; false after x1.
    bool next(double& x) {
        if (done_) return false;
        while (i_ < ends_.size() && (ends_[i_] - x0_) * d_ <= kTol) ++i_;
        const bool end = i_ < ends_.size() && between(ends_[i_]), cross = j_ < cross_.size();
        if (cross && (!end || cross_[j_] * d_ < ends_[i_] * d_))
            x = cross_[j_++];
        else if (end)
            x = ends_[i_++];
        else
            x = x1_, done_ = true;
        return true;
    }

  private:
    bool between(double x) const { return (x - x0_) * d_ > kTol && (x1_ - x) * d_ > kTol; }
    const std::vector<double>& ends_;
    std::vector<double> cross_;
    double x0_, x1_, start_ = 0;
    int d_;
    size_t i_ = 0, j_ = 0;
    bool done_ = false;
};
}  // namespace

// The vertical above a cut-free stretch of the line meets A when one of U's
// elements has a point above the line there. Only the elements reaching
// above it can (hiding), and not before the first of them along d: the walk
// over the cuts starts at the last cut before it, and a pass above all of U
// (half of a long G64's levels) walks none (issue 35 item 7: the walk over
// every cut and every element was 76% of the g64_roughing benchmark).
double first_hidden(const Material& m, double Y, double x0, double x1, int d) {
    if ((x1 - x0) * d <= kTol) return x1;
    const double lift = Y + kUm;  // a pass may run along A's upper edge itself
    const ElemIndex& ix = m.u_idx();
    const std::vector<int> h = hiding(ix, lift, x0, x1);
    if (h.empty()) return x1;
    double from = kInf;  // along d, no point of h lies before it
    for (int i : h) from = std::min(from, d > 0 ? ix.box[size_t(i)].x0 : -ix.box[size_t(i)].x1);
    CutWalk cuts(m, lift, x0, x1, d, from);
    double a = cuts.start(), b = 0;
    for (; cuts.next(b); a = b) {
        if (std::fabs(b - a) <= kTol) continue;
        const double mid = (a + b) / 2;
        for (int i : h)
            if (max_y_in(m.U[size_t(i)], mid, mid) > lift) return a;
    }
    return x1;
}

// The part, in a frame where it lies below the profile: the profile closed by
// two verticals down from its ends and a line far below (a loop of elements
// for winding numbers).
std::vector<Elem> part_loop(const std::vector<Elem>& F) {
    double lo = kInf, span = 0;
    for (const Elem& e : F) lo = std::min(lo, min_y(e)), span = std::max(span, length(e));
    lo -= 100 + 10 * span * double(F.size());
    V2 a = F.front().a, b = F.back().b;
    std::vector<Elem> loop = F;
    loop.push_back(line(b, V2(b.x(), lo)));
    loop.push_back(line(V2(b.x(), lo), V2(a.x(), lo)));
    loop.push_back(line(V2(a.x(), lo), a));
    return loop;
}

namespace {
// The straight elements of F among `near` that the segment p-q runs along: a
// tool sliding down a square wall's face touches the part there without
// entering it, and meets the wall's ends on the way (issue 19: G65 grooves
// whose start lies beyond a wall that takes no allowance).
std::vector<const Elem*> walls_along(const Material& m, const std::vector<int>& near, const V2& p,
                                     const V2& q) {
    auto on_line = [](const Elem& e, const V2& x) {
        const V2 d = e.b - e.a;
        return std::fabs(geometry::cross(d, x - e.a)) <= kTol * d.norm();
    };
    std::vector<const Elem*> along;
    for (int i : near) {
        const Elem& e = m.F[size_t(i)];
        if (!e.arc && (e.b - e.a).norm() > kTol && on_line(e, p) && on_line(e, q))
            along.push_back(&e);
    }
    return along;
}
}  // namespace

bool seg_clear(const Material& m, const V2& p, const V2& q) {
    double len = (q - p).norm();
    if (len < kTol) return !m.in_A(p);
    Elem s = line(p, q);
    // Only the elements whose boxes meet the segment's can meet it, or hold
    // one of its points within kTol (issue 35 item 7: G64's last pass asks
    // thousands of segments).
    const Box sb = box(s, 0);
    std::vector<int> fs, us;
    m.f_idx().near(sb, fs);
    m.u_idx().near(sb, us);
    const std::vector<const Elem*> along = walls_along(m, fs, p, q);
    auto on_wall = [&](const V2& x) {
        for (const Elem* e : along)
            if (dist(*e, x) <= kTol) return true;
        return false;
    };
    // On such a wall, a face that takes no allowance (the allowance points
    // into the part there) bounds A: a point on it touches A without being in
    // it.  The face's free side is the one out of the part.
    std::vector<Elem> part;
    auto face_bare = [&](const V2& x) {
        if (part.empty()) part = part_loop(m.F);
        const V2 n = perp(q - p).normalized() * (10 * kUm);
        const V2 free = winding(part, V2(x + n)) == 0 ? V2(x + n) : V2(x - n);
        return !m.in_A(free);
    };
    std::vector<double> ts{0, 1};
    std::vector<V2> pts;
    for (int i : fs) {
        pts.clear();
        intersect(m.F[size_t(i)], s, pts);
        for (const V2& x : pts) {
            double t = (x - p).dot(q - p) / (len * len);
            if (t * len > kTol && (1 - t) * len > kTol && !on_wall(x))
                return false;  // into the part
        }
    }
    for (int i : us) {
        pts.clear();
        intersect(m.U[size_t(i)], s, pts);
        for (const V2& x : pts)
            if (!m.zero() || !on_wall(x)) ts.push_back((x - p).dot(q - p) / (len * len));
    }
    std::sort(ts.begin(), ts.end());
    for (size_t j = 0; j + 1 < ts.size(); ++j) {
        if ((ts[j + 1] - ts[j]) * len <= kTol) continue;
        if (m.zero() && ts[j] * len > kTol) return false;  // meets the profile on the way
        const V2 mid = p + (ts[j] + ts[j + 1]) / 2 * (q - p);
        if (m.in_A(mid) && !(on_wall(mid) && (m.zero() || face_bare(mid)))) return false;
    }
    return true;
}

// The stretches of [x0, x1] where the vertical from Y up by h stays out of A.
std::vector<std::pair<double, double>> clear_runs(const Material& m, double Y, double h, double x0,
                                                  double x1, int d) {
    if ((x1 - x0) * d <= kTol || h <= kTol) return {{x0, x1}};
    const std::vector<double> cuts = critical_xs(m, Y + kUm, Y + h, x0, x1, d);
    std::vector<std::pair<double, double>> runs;
    bool open = false;
    for (size_t j = 0; j + 1 < cuts.size(); ++j) {
        if (std::fabs(cuts[j + 1] - cuts[j]) <= kTol) continue;
        double mid = (cuts[j] + cuts[j + 1]) / 2;
        bool clear = seg_clear(m, V2(mid, Y + kUm), V2(mid, Y + h));
        if (clear && open)
            runs.back().second = cuts[j + 1];
        else if (clear)
            runs.push_back({cuts[j], cuts[j + 1]});
        open = clear;
    }
    return runs;
}

std::pair<double, double> clear_below(const Material& m, double Y, double h, double x0, double x1,
                                      int d) {
    auto runs = clear_runs(m, Y, h, x0, x1, d);
    return runs.empty() ? std::pair<double, double>{x0, x0} : runs.front();
}

Error check_profile(const Profile& f) {
    if (f.elems.empty()) return {871, tr("the finished profile has no element")};
    for (size_t i = 0; i + 1 < f.elems.size(); ++i)
        if ((f.elems[i].b - f.elems[i + 1].a).norm() > kUm)
            return {871, tr("the finished profile is not continuous")};
    return {};
}

Error check_axis(const std::vector<Elem>& es, const char* message) {
    for (const Elem& e : es)
        if (min_y(e) < -kUm) return {874, tr(message)};
    return {};
}

V2 centroid(const std::vector<Elem>& es) {
    V2 sum(0, 0);
    double w = 0;
    for (const Elem& e : es) {
        double l = length(e);
        sum += l * midpoint(e);
        w += l;
    }
    if (w > kTol) return sum / w;
    return es.empty() ? V2(0, 0) : es.front().a;
}

void Emit::go(int g, const V2& p, bool infeed, double dwell) {
    if ((p - cur).norm() <= kTol && dwell == 0) return;
    Move mv;
    mv.g = g;
    mv.to = fr.back(p);
    mv.infeed = infeed;
    mv.dwell = dwell;
    out.push_back(mv);
    cur = p;
}

void Emit::arc(const Elem& e) {
    Move mv;
    mv.sweep = e.sweep * fr.det();
    mv.g = mv.sweep > 0 ? 3 : 2;
    mv.to = fr.back(e.b);
    mv.c = fr.back(e.c);
    out.push_back(mv);
    cur = e.b;
}

}  // namespace pupitre::turning::zone
