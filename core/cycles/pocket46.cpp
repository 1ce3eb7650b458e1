// G46 pockets and facing (pupitre-iso(5), DECISIONS, G46: what the seeds do not
// say): region of the tool centre on a line (exact for lines and arcs), zig-zag
// roughing, clean-up and finishing contours by the radius-compensation offsets
// of core/comp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cycles/pocket46.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"

namespace pupitre::p46 {

namespace {
using ::pupitre::geometry::ceil_um;
using ::pupitre::geometry::cross;
using ::pupitre::geometry::kPi;

// Points along an element (its start excluded), chords within 0.1 µm of arcs.
void tessellate(const Elem& e, std::vector<V2>& out) {
    if (!e.arc) {
        out.push_back(e.b);
        return;
    }
    double r = e.r();
    double step = 2 * std::acos(std::max(-1.0, 1 - 1e-4 / std::max(r, 1e-6)));
    int n = std::max(2, int(std::ceil(std::fabs(e.sweep) / std::max(step, 1e-4))));
    n = std::min(n, 20000);
    double a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x());
    for (int k = 1; k < n; ++k) {
        double a = a0 + e.sweep * k / n;
        out.push_back(e.c + r * V2(std::cos(a), std::sin(a)));
    }
    out.push_back(e.b);
}

std::vector<V2> loop_of(const std::vector<Elem>& el) {
    std::vector<V2> pts;
    if (el.empty()) return pts;
    pts.push_back(el.front().a);
    for (const Elem& e : el) tessellate(e, pts);
    return pts;
}

// Interval of x where a + (x, y) maps into [lo, hi] by the linear form k*x + m.
bool linear_range(double k, double m, double lo, double hi, double& x0, double& x1) {
    if (std::fabs(k) < 1e-14) {
        if (m < lo || m > hi) return false;
        x0 = -1e300, x1 = 1e300;
        return true;
    }
    double u = (lo - m) / k, v = (hi - m) / k;
    x0 = std::min(u, v), x1 = std::max(u, v);
    return true;
}

void disc(const V2& c, double d, double y, Spans& out) {
    double dy = y - c.y();
    if (std::fabs(dy) >= d) return;
    double h = std::sqrt(d * d - dy * dy);
    out.push_back({c.x() - h, c.x() + h});
}

// The x where the line at y lies closer than d to the element.
void forbidden(const Elem& e, double d, double y, Spans& out) {
    if (d <= 0) return;
    disc(e.a, d, y, out);
    disc(e.b, d, y, out);
    if (!e.arc) {
        V2 ab = e.b - e.a;
        double len = ab.norm();
        if (len < 1e-12) return;
        V2 u = ab / len, n(-u.y(), u.x());
        double t0, t1, s0, s1;
        // t = (x - ax) ux + (y - ay) uy; s = (x - ax) nx + (y - ay) ny
        if (!linear_range(u.x(), -e.a.x() * u.x() + (y - e.a.y()) * u.y(), 0, len, t0, t1)) return;
        if (!linear_range(n.x(), -e.a.x() * n.x() + (y - e.a.y()) * n.y(), -d, d, s0, s1)) return;
        double x0 = std::max(t0, s0), x1 = std::min(t1, s1);
        if (x0 < x1) out.push_back({x0, x1});
        return;
    }
    // Arc: the annulus r ± d inside the wedge of each sub-arc of at most 90°.
    double r = e.r();
    int parts = std::max(1, int(std::ceil(std::fabs(e.sweep) / (kPi / 2) - 1e-9)));
    double a0 = std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x());
    Spans ring;
    {
        double dy = y - e.c.y();
        if (std::fabs(dy) >= r + d) return;
        double ho = std::sqrt((r + d) * (r + d) - dy * dy);
        if (r - d > 0 && std::fabs(dy) < r - d) {
            double hi = std::sqrt((r - d) * (r - d) - dy * dy);
            ring.push_back({e.c.x() - ho, e.c.x() - hi});
            ring.push_back({e.c.x() + hi, e.c.x() + ho});
        } else {
            ring.push_back({e.c.x() - ho, e.c.x() + ho});
        }
    }
    for (int k = 0; k < parts; ++k) {
        double t0 = a0 + e.sweep * k / parts, t1 = a0 + e.sweep * (k + 1) / parts;
        if (t1 < t0) std::swap(t0, t1);  // counter-clockwise from t0 to t1
        V2 u0(std::cos(t0), std::sin(t0)), u1(std::cos(t1), std::sin(t1));
        // cross(u0, p - c) >= 0 and cross(p - c, u1) >= 0, p = (x, y).
        double w0, w1, v0, v1;
        double py = y - e.c.y();
        if (!linear_range(-u0.y(), -u0.y() * -e.c.x() + u0.x() * py, 0, 1e300, w0, w1)) continue;
        if (!linear_range(u1.y(), u1.y() * -e.c.x() - u1.x() * py, 0, 1e300, v0, v1)) continue;
        double x0 = std::max(w0, v0), x1 = std::min(w1, v1);
        for (auto [r0, r1] : ring) {
            double lo = std::max(x0, r0), hi = std::min(x1, r1);
            if (lo < hi) out.push_back({lo, hi});
        }
    }
}

Spans subtract(const Spans& a, Spans b) {
    std::sort(b.begin(), b.end());
    Spans out;
    for (auto [x0, x1] : a) {
        double cur = x0;
        for (auto [f0, f1] : b) {
            if (f1 <= cur || f0 >= x1) continue;
            if (f0 > cur) out.push_back({cur, f0});
            cur = std::max(cur, f1);
            if (cur >= x1) break;
        }
        if (cur < x1) out.push_back({cur, x1});
    }
    return out;
}

bool proper_cross(const V2& a, const V2& b, const V2& c, const V2& d) {
    double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c),
           d4 = cross(d - c, b - c);
    return ((d1 > 1e-12 && d2 < -1e-12) || (d1 < -1e-12 && d2 > 1e-12)) &&
           ((d3 > 1e-12 && d4 < -1e-12) || (d3 < -1e-12 && d4 > 1e-12));
}

// A straight move from a to b stays where the tool centre may go: it crosses
// no boundary and keeps its clearance from every wall (sampled every 0.05 mm).
// Inside, or on a limit (the pass ends of a facing lie on its outline).
bool reachable(const Region& r, const V2& p) {
    if (inside(r, p, 1e-6)) return true;
    if (margin(r, p) < -1e-6) return false;
    for (const auto& l : r.loops)
        for (size_t i = 0; i < l.size(); ++i) {
            Elem e;
            e.a = l[i], e.b = l[(i + 1) % l.size()];
            if (distance(e, p) < 1e-7) return true;
        }
    return false;
}

bool link_ok(const Region& r, const V2& a, const V2& b) {
    if (!reachable(r, a) || !reachable(r, b)) return false;
    for (const auto& l : r.loops)
        for (size_t i = 0; i < l.size(); ++i)
            if (proper_cross(a, b, l[i], l[(i + 1) % l.size()])) return false;
    double len = (b - a).norm();
    int n = std::max(1, int(std::ceil(len / 0.05)));
    for (int k = 1; k < n; ++k)
        if (margin(r, a + (b - a) * (double(k) / n)) < -1e-6) return false;
    return true;
}

// Every point of the path keeps its clearance from the walls.
bool path_clear(const Region& r, V2 from, const std::vector<Piece>& pcs, double tol) {
    for (const Piece& p : pcs) {
        int n;
        if (!p.arc) {
            n = std::max(1, int(std::ceil((p.to - from).norm() / 0.05)));
            for (int k = 0; k <= n; ++k)
                if (margin(r, from + (p.to - from) * (double(k) / n)) < -tol) return false;
        } else {
            double rr = (from - p.c).norm();
            n = std::max(2, int(std::ceil(std::fabs(p.sweep) * rr / 0.05)));
            double a0 = std::atan2(from.y() - p.c.y(), from.x() - p.c.x());
            for (int k = 0; k <= n; ++k) {
                double a = a0 + p.sweep * k / n;
                if (margin(r, p.c + rr * V2(std::cos(a), std::sin(a))) < -tol) return false;
            }
        }
        from = p.to;
    }
    return true;
}

// A point of a piece at parameter u in [0, 1], and the piece from u0 to u1.
V2 at(const V2& from, const Piece& p, double u) {
    if (!p.arc) return from + (p.to - from) * u;
    double a0 = std::atan2(from.y() - p.c.y(), from.x() - p.c.x()), rr = (from - p.c).norm();
    return p.c + rr * V2(std::cos(a0 + p.sweep * u), std::sin(a0 + p.sweep * u));
}
Piece part(const V2& from, const Piece& p, double u0, double u1) {
    Piece q = p;
    q.to = at(from, p, u1);
    q.sweep = p.sweep * (u1 - u0);
    return q;
}

// The stretches of a path that keep their clearance, as separate runs.
std::vector<Run> clip(const Region& r, V2 from, const std::vector<Piece>& pcs) {
    std::vector<Run> out;
    bool open = false;
    auto ok = [&](const V2& f, const Piece& p, double u) {
        return margin(r, at(f, p, u)) >= -1e-6;
    };
    for (const Piece& p : pcs) {
        double len = p.arc ? std::fabs(p.sweep) * (from - p.c).norm() : (p.to - from).norm();
        int n = std::max(1, int(std::ceil(len / 0.05)));
        double u_in = 0;
        bool in = ok(from, p, 0);
        if (!in) open = false;
        for (int k = 1; k <= n; ++k) {
            double u = double(k) / n;
            bool now = ok(from, p, u);
            if (now == in) continue;
            double lo = double(k - 1) / n, hi = u;
            for (int it = 0; it < 30; ++it)
                ((ok(from, p, (lo + hi) / 2) == in) ? lo : hi) = (lo + hi) / 2;
            double edge = in ? lo : hi;
            if (in) {  // leaving the clear zone: the stretch ends here
                if (!open) out.push_back({at(from, p, u_in), {}, false});
                if (edge > u_in + 1e-9) out.back().pieces.push_back(part(from, p, u_in, edge));
                open = false;
            } else {
                u_in = edge;
            }
            in = now;
        }
        if (in) {
            if (!open) out.push_back({at(from, p, u_in), {}, false});
            if (1 > u_in + 1e-9) out.back().pieces.push_back(part(from, p, u_in, 1));
            open = true;
        }
        from = p.to;
    }
    std::vector<Run> kept;
    for (Run& run : out)
        if (!run.pieces.empty()) kept.push_back(run);
    return kept;
}

V2 end_of(const Run& r) {
    return r.pieces.empty() ? r.start : r.pieces.back().to;
}

// A NU6 wall as written, or travelled the other way (keep false).
std::vector<Elem> wall_as(const Section& s, bool keep) {
    if (keep) return s.elems;
    std::vector<Elem> w;
    for (size_t i = s.elems.size(); i-- > 0;) w.push_back(reversed(s.elems[i]));
    return w;
}

// The sections that make the facing's closed boundary (NU5/NU6 in order).
std::vector<Elem> chain56(const Def& d) {
    std::vector<Elem> all;
    for (const Section& s : d.sections)
        if (s.nu == 5 || s.nu == 6) all.insert(all.end(), s.elems.begin(), s.elems.end());
    return all;
}

// Orients a closed contour so that the region lies on side `side` of travel.
std::vector<Elem> oriented(const std::vector<Elem>& el, bool region_inside, int side) {
    double a = area(el);
    bool region_left = (a > 0) == region_inside;
    if (region_left == (side > 0)) return el;
    std::vector<Elem> rev;
    for (size_t i = el.size(); i-- > 0;) rev.push_back(reversed(el[i]));
    return rev;
}
}  // namespace

bool Def::facing() const {
    for (const Section& s : sections)
        if (s.nu == 3 || s.nu == 5 || s.nu == 6) return true;
    return false;
}

double distance(const Elem& e, const V2& p) {
    if (!e.arc) {
        V2 ab = e.b - e.a;
        double l2 = ab.squaredNorm();
        double t = l2 < 1e-24 ? 0 : std::clamp((p - e.a).dot(ab) / l2, 0.0, 1.0);
        return (e.a + t * ab - p).norm();
    }
    V2 u = e.a - e.c, v = p - e.c;
    double phi = std::atan2(cross(u, v), u.dot(v));  // from the start, counter-clockwise
    if (e.sweep < 0) phi = -phi;
    if (phi < 0) phi += 2 * kPi;
    if (phi <= std::fabs(e.sweep) + 1e-12) return std::fabs(v.norm() - e.r());
    return std::min((p - e.a).norm(), (p - e.b).norm());
}

Region region(const Def& d, double clear) {
    Region r;
    for (const Section& s : d.sections) {
        if (s.nu == 1 || s.nu == 2 || s.nu == 3) r.loops.push_back(loop_of(s.elems));
        if (s.nu == 1 || s.nu == 2 || s.nu == 6)
            for (const Elem& e : s.elems) r.bounds.push_back({e, clear});
    }
    std::vector<Elem> c = chain56(d);
    if (!c.empty()) r.loops.push_back(loop_of(c));
    bool first = true;
    for (const auto& l : r.loops)
        for (const V2& p : l) {
            if (first) r.xlo = r.xhi = p.x(), r.ylo = r.yhi = p.y(), first = false;
            r.xlo = std::min(r.xlo, p.x()), r.xhi = std::max(r.xhi, p.x());
            r.ylo = std::min(r.ylo, p.y()), r.yhi = std::max(r.yhi, p.y());
        }
    return r;
}

double margin(const Region& r, const V2& p) {
    double m = 1e300;
    for (const Bound& b : r.bounds) m = std::min(m, distance(b.e, p) - b.clear);
    return m;
}

bool inside(const Region& r, const V2& p, double tol) {
    bool in = false;
    for (const auto& l : r.loops)
        for (size_t i = 0; i < l.size(); ++i) {
            const V2& a = l[i];
            const V2& b = l[(i + 1) % l.size()];
            if ((a.y() > p.y()) != (b.y() > p.y())) {
                double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
                if (x > p.x()) in = !in;
            }
        }
    return in && margin(r, p) >= -tol;
}

Spans spans(const Region& r, double y) {
    std::vector<double> xs;
    for (const auto& l : r.loops)
        for (size_t i = 0; i < l.size(); ++i) {
            const V2& a = l[i];
            const V2& b = l[(i + 1) % l.size()];
            if ((a.y() > y) != (b.y() > y))
                xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        }
    std::sort(xs.begin(), xs.end());
    Spans in;
    for (size_t i = 0; i + 1 < xs.size(); i += 2) in.push_back({xs[i], xs[i + 1]});
    Spans no;
    for (const Bound& b : r.bounds) forbidden(b.e, b.clear, y, no);
    Spans out;
    for (auto s : subtract(in, no))
        if (s.second - s.first > 1e-3) out.push_back(s);
    return out;
}

bool offset_chain(const std::vector<Elem>& el, bool closed, double r, int side, V2& start,
                  std::vector<Piece>& out) {
    out.clear();
    if (el.empty()) return false;
    Elem o;
    if (!comp::offset(el[0], r, side, o)) return false;
    V2 from = o.a;
    const size_t n = el.size();
    if (closed) {
        // First turn: where the joint at the start point trims the first element.
        std::vector<Piece> tmp;
        for (size_t i = 0; i < n; ++i) {
            V2 next;
            if (comp::join(el[i], from, el[(i + 1) % n], r, side, tmp, next)) return false;
            from = next;
        }
    }
    start = from;
    for (size_t i = 0; i + 1 < n || (closed && i < n); ++i) {
        V2 next;
        if (comp::join(el[i], from, el[(i + 1) % n], r, side, out, next)) return false;
        from = next;
    }
    if (!closed && comp::finish(el[n - 1], from, r, side, out)) return false;
    return true;
}

namespace {
// Error `code`, about section `sec` (-1: the whole definition).
Error refuse(int code, std::string why, int sec = -1) {
    return Error{.code = code, .detail = std::move(why), .item = sec};
}

// How many outer profiles and islands the sections declare, and whether the
// facing's limits (NU5) and walls (NU6) are there.
struct Roles {
    int outer = 0, islands = 0;
    bool has5 = false, has6 = false;
};

// Each section has elements; an NU1..NU4 contour closes and encloses an area.
Error check_sections(const Def& d, Roles& n) {
    for (size_t i = 0; i < d.sections.size(); ++i) {
        const Section& s = d.sections[i];
        if (s.elems.empty()) return refuse(284, tr("a contour with no element"), int(i));
        if (s.nu == 1 || s.nu == 3) ++n.outer;
        if (s.nu == 2 || s.nu == 4) ++n.islands;
        if (s.nu == 5) n.has5 = true;
        if (s.nu == 6) n.has6 = true;
        if (s.nu <= 4 && (s.elems.back().b - s.elems.front().a).norm() > 1e-3)
            return refuse(281, tr("the contour does not end where it starts"), int(i));
        if (s.nu <= 4 && std::fabs(area(s.elems)) < 1e-6)
            return refuse(284, tr("a contour that encloses no area"), int(i));
    }
    return {};
}

// The NU5/NU6 sections follow one another and close.
Error check_chain56(const Def& d) {
    const Section* prev = nullptr;
    const Section* first = nullptr;
    for (size_t i = 0; i < d.sections.size(); ++i) {
        const Section& s = d.sections[i];
        if (s.nu != 5 && s.nu != 6) continue;
        if (!first) first = &s;
        if (prev && (prev->elems.back().b - s.elems.front().a).norm() > 1e-3)
            return refuse(281, tr("a limit or wall does not start where the previous one ends"),
                          int(i));
        prev = &s;
    }
    if ((prev->elems.back().b - first->elems.front().a).norm() > 1e-3)
        return refuse(281, tr("the limits and walls do not close"), -1);
    return {};
}

// Islands lie inside the outer profile, apart from each other.
Error check_islands(const Def& d, bool has56) {
    Region outer_only;
    for (const Section& s : d.sections)
        if (s.nu == 1 || s.nu == 3) outer_only.loops.push_back(loop_of(s.elems));
    if (has56) outer_only.loops.push_back(loop_of(chain56(d)));
    for (size_t i = 0; i < d.sections.size(); ++i) {
        const Section& s = d.sections[i];
        if (s.nu != 2 && s.nu != 4) continue;
        for (const Elem& e : s.elems)
            if (!inside(outer_only, e.a) && !(s.nu == 4 && d.facing()))
                return refuse(284, tr("an island is not inside the outer profile"), int(i));
    }
    return {};
}
}  // namespace

Error check(const Def& d) {
    Roles n;
    if (Error e = check_sections(d, n)) return e;
    bool has56 = n.has5 || n.has6;
    if (has56) {
        if (!n.has5 || !n.has6)
            return refuse(283, tr("facing limits (NU5) and walls (NU6) go together"));
        ++n.outer;
        if (Error e = check_chain56(d)) return e;
    }
    if (n.outer != 1)
        return refuse(283, n.outer == 0 ? tr("no outer profile (NU1, NU3 or NU5/NU6)")
                                        : tr("more than one outer profile"));
    if (n.islands > 127) return refuse(285, tr("more than 127 islands and recesses"));
    if (d.facing() && d.has_e) return refuse(293, tr("a roughing end point (EX EY) in a facing"));
    if (d.q > d.ed) return refuse(286, tr("the step-over Q is larger than the cutter diameter ED"));
    Region r = region(d, 0);
    if (r.xhi - r.xlo > 40 * d.q || r.yhi - r.ylo > 40 * d.q)
        return refuse(287, tr("the pocket is larger than 40 times the step-over Q"));
    return check_islands(d, has56);
}

namespace {
// The lowest (y0) and highest (y1) lines that cut: scan, then bisect; false
// when no line cuts.
bool cutting_range(const Region& reg, double q, double& y0, double& y1) {
    const double h = std::max({1e-3, std::min(0.05, q / 4), (reg.yhi - reg.ylo) / 20000});
    auto any = [&](double y) { return !spans(reg, y).empty(); };
    bool found = false;
    for (double y = reg.ylo; y <= reg.yhi; y += h)
        if (any(y)) {
            double lo = y - h, hi = y;
            for (int k = 0; k < 40; ++k) ((any((lo + hi) / 2)) ? hi : lo) = (lo + hi) / 2;
            y0 = hi, found = true;
            break;
        }
    if (!found) return false;
    for (double y = reg.yhi; y >= reg.ylo; y -= h)
        if (any(y)) {
            double lo = y, hi = y + h;
            for (int k = 0; k < 40; ++k) ((any((lo + hi) / 2)) ? lo : hi) = (lo + hi) / 2;
            y1 = lo;
            break;
        }
    return true;
}

// The ordinates of the passes from y0 to y1 at an even step Q' <= Q (rounded
// up to the micron); one line midway when the range is narrower than Q.
void pass_lines(double y0, double y1, double q, std::vector<double>& line_y) {
    int n = std::max(0, int(std::ceil((y1 - y0) / q - 1e-9)));
    if (n == 0) {
        line_y.push_back((y0 + y1) / 2);
    } else {
        double step = ceil_um((y1 - y0) / n);
        for (int k = 0; k < n; ++k) line_y.push_back(y0 + k * step);
        line_y.push_back(y1);
    }
}

struct Seg {
    V2 a, b;
    bool done = false;
};

// The nearest end of a segment not yet cut that a move at feed reaches, else
// the nearest end: its segment, and whether it is cut from b to a.
std::pair<size_t, bool> next_segment(const Region& reg, const std::vector<Seg>& segs, V2 cur,
                                     double q, bool first) {
    struct Cand {
        double d;
        size_t i;
        bool rev;
    };
    std::vector<Cand> cands;
    for (size_t i = 0; i < segs.size(); ++i) {
        if (segs[i].done) continue;
        cands.push_back({(segs[i].a - cur).norm(), i, false});
        cands.push_back({(segs[i].b - cur).norm(), i, true});
    }
    std::sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) {
        return x.d < y.d - 1e-9 ||
               (x.d < y.d + 1e-9 && (x.i < y.i || (x.i == y.i && x.rev < y.rev)));
    });
    size_t best = cands[0].i;
    bool rev = cands[0].rev;
    if (!first)
        for (size_t k = 0; k < std::min<size_t>(cands.size(), 8); ++k) {
            const Cand& cd = cands[k];
            if (cd.d > 3 * q) break;
            if (link_ok(reg, cur, cd.rev ? segs[cd.i].b : segs[cd.i].a)) {
                best = cd.i, rev = cd.rev;
                break;
            }
        }
    return {best, rev};
}

// The zig-zag passes: each segment once, the next one the nearest reached at
// feed; the first from LX LY when given. Returns where the last one ends.
V2 zigzag(const Def& d, const Region& reg, std::vector<Seg>& segs, V2 cur, std::vector<Run>& runs) {
    bool first = true;
    for (size_t left = segs.size(); left > 0; --left) {
        auto [best, rev] = next_segment(reg, segs, cur, d.q, first);
        Seg& s = segs[best];
        s.done = true;
        V2 a = rev ? s.b : s.a, b = rev ? s.a : s.b;
        Run run;
        if (first && d.has_l) {
            run.start = d.l;
            run.pieces.push_back({false, a, {0, 0}, 0, false});
            if (!link_ok(reg, d.l, a)) run.pieces.clear(), run.start = a;
        } else {
            run.start = a;
            run.linked = !first && link_ok(reg, cur, a);
        }
        run.pieces.push_back({false, b, {0, 0}, 0, false});
        runs.push_back(run);
        cur = b;
        first = false;
    }
    return cur;
}

// One clean-up contour at offset r. Where it comes closer to another wall than
// its clearance (a gap narrower than the cutter), only its stretches that keep
// clear run; a vanished offset leaves nothing to clean.
void cleanup(const Region& reg, const std::vector<Elem>& el, bool closed, double r,
             bool region_inside, int side, V2& cur, std::vector<Run>& runs) {
    std::vector<Elem> o = closed ? oriented(el, region_inside, side) : el;
    V2 start;
    std::vector<Piece> pcs;
    if (!offset_chain(o, closed, r, side, start, pcs)) return;
    for (Run& run : clip(reg, start, pcs)) {
        run.linked = link_ok(reg, cur, run.start);
        run.cleanup = true;
        cur = end_of(run);
        runs.push_back(run);
    }
}

// The clean-up contours: walls at R + J, facing outlines on the outline.
void cleanups(const Def& d, const Region& reg, double c, V2 cur, std::vector<Run>& runs) {
    const int side = d.sense();
    for (const Section& s : d.sections) {
        if (s.nu == 1) cleanup(reg, s.elems, true, c, true, side, cur, runs);
        if (s.nu == 3) cleanup(reg, s.elems, true, 0, true, side, cur, runs);
        if (s.nu == 2) cleanup(reg, s.elems, true, c, false, side, cur, runs);
    }
    std::vector<Elem> ch = chain56(d);
    if (!ch.empty()) {
        bool keep = (area(ch) > 0) == (side > 0);
        for (const Section& s : d.sections)
            if (s.nu == 6) cleanup(reg, wall_as(s, keep), false, c, true, side, cur, runs);
    }
}
}  // namespace

Error roughing(const Def& d, double R, std::vector<Run>& runs, std::vector<double>& line_y) {
    runs.clear();
    line_y.clear();
    const double c = R + d.j;
    Region reg = region(d, c);
    double y0 = 0, y1 = 0;
    if (!cutting_range(reg, d.q, y0, y1))
        return refuse(289, tr("the cutter does not fit in the pocket"));
    pass_lines(y0, y1, d.q, line_y);
    std::vector<Seg> segs;
    for (double y : line_y)
        for (auto [x0, x1] : spans(reg, y)) segs.push_back({V2(x0, y), V2(x1, y)});
    if (segs.empty()) return refuse(289, tr("the cutter does not fit in the pocket"));
    V2 cur = segs[0].a;
    if (d.has_l) {
        if (!inside(reg, d.l, 1e-6))
            return refuse(282,
                          tr("the roughing start point LX LY is not where the cutter can plunge"));
        cur = d.l;
    }
    cur = zigzag(d, reg, segs, cur, runs);
    cleanups(d, reg, c, cur, runs);
    return {};
}

namespace {
// What the finishing of each contour and wall shares.
struct Finish {
    double R = 0;  // the finishing tool's radius
    int side = 1;
    double r = 0;      // R + J: the offset of its centre
    Region walls;      // the finishing tool's clearances
    Region rough;      // what roughing has cleared
    double reach = 0;  // how far from the contour the tool engages
};

// The contour from LX LY round to LX LY: rotated when the point is a vertex,
// else its element split there.
std::vector<Elem> rotated_to(const std::vector<Elem>& el, size_t best, const V2& l) {
    Elem e = el[best];
    std::vector<Elem> rot;
    if ((l - e.a).norm() < 1e-6) {
        rot.insert(rot.end(), el.begin() + long(best), el.end());
        rot.insert(rot.end(), el.begin(), el.begin() + long(best));
    } else if ((l - e.b).norm() < 1e-6) {
        rot.insert(rot.end(), el.begin() + long(best) + 1, el.end());
        rot.insert(rot.end(), el.begin(), el.begin() + long(best) + 1);
    } else {
        Elem e1 = e, e2 = e;
        V2 p = l;
        if (e.arc) p = e.c + (l - e.c).normalized() * e.r();
        e1.b = p, e2.a = p;
        if (e.arc) {
            double a1 = std::atan2(cross(e.a - e.c, p - e.c), (e.a - e.c).dot(p - e.c));
            if (e.sweep > 0 && a1 < 0) a1 += 2 * kPi;
            if (e.sweep < 0 && a1 > 0) a1 -= 2 * kPi;
            e1.sweep = a1, e2.sweep = e.sweep - a1;
        }
        rot.push_back(e2);
        rot.insert(rot.end(), el.begin() + long(best) + 1, el.end());
        rot.insert(rot.end(), el.begin(), el.begin() + long(best));
        rot.push_back(e1);
    }
    return rot;
}

// Start at LX LY, which must lie on the contour (error 291).
Error start_at_l(const Section& s, int si, std::vector<Elem>& el) {
    size_t best = 0;
    double bd = 1e300;
    for (size_t i = 0; i < el.size(); ++i) {
        double dd = distance(el[i], s.l);
        if (dd < bd) bd = dd, best = i;
    }
    if (bd > 1e-3)
        return refuse(291, tr("the finishing start point LX LY is not on the contour"), si);
    el = rotated_to(el, best, s.l);
    return {};
}

// One NU1/NU2 contour: from its start (LX LY or its first point), engaged
// along the normal from the zone the roughing cleared, round and back out.
Error contour_run(const Finish& f, const Section& s, int si, std::vector<Run>& runs) {
    std::vector<Elem> el = oriented(s.elems, s.nu == 1, f.side);
    if (s.has_l)
        if (Error e = start_at_l(s, si, el)) return e;
    // A re-entrant corner at the start point cannot be engaged.
    V2 t_in = comp::end_tangent(el.back()), t_out = comp::start_tangent(el.front());
    if (double(f.side) * cross(t_in, t_out) > 1e-9 && t_in.dot(t_out) < 1 - 1e-9)
        return refuse(288, tr("the finishing starts in a re-entrant corner"), si);
    Run run;
    V2 start;
    std::vector<Piece> pcs;
    if (!offset_chain(el, true, f.r, f.side, start, pcs) ||
        !path_clear(f.walls, start, pcs, 1e-6)) {
        return refuse(289, tr("the finishing cutter is too large for the contour"), si);
    }
    V2 nrm = comp::normal(t_out, f.side);
    run.start = el.front().a + f.reach * nrm;
    if (!inside(f.rough, run.start, 1e-6))
        return refuse(288, tr("the finishing engages in a zone the roughing did not clear"), si);
    if ((run.start - start).norm() > 1e-9) run.pieces.push_back({false, start, {0, 0}, 0, false});
    run.pieces.insert(run.pieces.end(), pcs.begin(), pcs.end());
    if ((run.start - start).norm() > 1e-9)
        run.pieces.push_back({false, run.start, {0, 0}, 0, false});
    runs.push_back(run);
    return {};
}

// One NU6 wall, travelled as the facing's outline goes (keep) or the other way:
// in from beyond the open end and out past the other, along the tangents.
Error wall_run(const Finish& f, const Section& s, bool keep, int si, std::vector<Run>& runs) {
    std::vector<Elem> w = wall_as(s, keep);
    Run run;
    V2 start;
    std::vector<Piece> pcs;
    if (!offset_chain(w, false, f.r, f.side, start, pcs) ||
        !path_clear(f.walls, start, pcs, 1e-6)) {
        return refuse(289, tr("the finishing cutter is too large for the wall"), si);
    }
    V2 t0 = comp::start_tangent(w.front()), t1 = comp::end_tangent(w.back());
    V2 end = pcs.empty() ? start : pcs.back().to;
    run.start = start - (f.R + 1) * t0;
    run.pieces.push_back({false, start, {0, 0}, 0, false});
    run.pieces.insert(run.pieces.end(), pcs.begin(), pcs.end());
    run.pieces.push_back({false, V2(end + (f.R + 1) * t1), {0, 0}, 0, false});
    runs.push_back(run);
    return {};
}
}  // namespace

Error finishing(const Def& d, double R, double J, std::vector<Run>& runs) {
    runs.clear();
    Finish f;
    f.R = R;
    f.side = d.sense();
    f.r = R + J;
    f.walls = region(d, f.r);
    f.rough = region(d, d.ed / 2 + d.j);
    f.reach = std::max(f.r, d.ed / 2 + d.j);
    for (size_t si = 0; si < d.sections.size(); ++si) {
        const Section& s = d.sections[si];
        if (s.nu != 1 && s.nu != 2) continue;
        if (Error e = contour_run(f, s, int(si), runs)) return e;
    }
    std::vector<Elem> ch = chain56(d);
    if (!ch.empty()) {
        bool keep = (area(ch) > 0) == (f.side > 0);
        for (size_t si = 0; si < d.sections.size(); ++si) {
            const Section& s = d.sections[si];
            if (s.nu != 6) continue;
            if (Error e = wall_run(f, s, keep, int(si), runs)) return e;
        }
    }
    return {};
}

}  // namespace pupitre::p46
