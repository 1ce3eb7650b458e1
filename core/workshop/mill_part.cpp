// The machining centre's material (see mill_part.hpp): the cutters' shapes,
// the strokes and their geometry, the height field they cut, the store's text.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/workshop/mill_part.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "core/workshop/narrow.hpp"
#include "core/workshop/tilt.hpp"

namespace pupitre::workshop {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Farther than this (mm) is not a workshop: refused, and the text stays short.
constexpr double kFar = 1e7;

// The store keeps 0.1 µm; strokes are kept at that grain from the start so
// that a part read back from its text is the very part that was saved.
double grain(double v) {
    return std::round(v * 1e4) / 1e4;
}

// The interval of s where the line p = p0 (in the plane (s, p)) is within
// rho of the segment (sa, pa)-(sb, pb): the union of its two end discs and
// the band between them (the stadium is convex: one interval).
bool stadium_cut(double sa, double pa, double sb, double pb, double rho, double p0, double& lo,
                 double& hi) {
    if (!(rho > 0)) return false;
    lo = kInf, hi = -kInf;
    for (auto [s, p] : {std::pair{sa, pa}, std::pair{sb, pb}}) {
        double e = p0 - p;
        if (std::abs(e) > rho) continue;
        double w = std::sqrt((rho - e) * (rho + e));
        lo = std::min(lo, s - w), hi = std::max(hi, s + w);
    }
    const double ds = sb - sa, dp = pb - pa, len = std::hypot(ds, dp);
    if (len > 0) {
        // cross = ds (p0 - pa) - dp (s - sa) within ±rho len, and the
        // projection (s - sa) ds + (p0 - pa) dp within [0, len²].
        double t0 = -kInf, t1 = kInf;
        const double e = p0 - pa;
        if (narrow(ds * e + dp * sa, -dp, -rho * len, rho * len, t0, t1) &&
            narrow(e * dp - sa * ds, ds, 0, len * len, t0, t1) && std::isfinite(t0) &&
            std::isfinite(t1))
            lo = std::min(lo, t0), hi = std::max(hi, t1);
    }
    return lo < hi;
}

Cutter cutter_of(double radius, double corner) {
    Cutter k;
    k.radius = radius;
    k.corner = corner;
    return k;
}

// A ball end's lowest point at (x, y), its tip going from a to b: the lower
// surface of the capsule of radius r about the ball's centre line, exactly
// (the end spheres and the cylinder between them).
double lowest_ball(const P3& a, const P3& b, double r, double x, double y) {
    double best = kInf;
    for (const P3* e : {&a, &b}) {
        double dx = x - (*e)[0], dy = y - (*e)[1], q = r * r - dx * dx - dy * dy;
        if (q >= 0) best = std::min(best, (*e)[2] + r - std::sqrt(q));
    }
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double len = std::sqrt(ux * ux + uy * uy + uz * uz);
    const double nz = uz / len, k2 = 1 - nz * nz;
    if (k2 < 1e-12) return best;  // a plunge: the lower sphere is the bottom
    const double wx = x - a[0], wy = y - a[1], k = (wx * ux + wy * uy) / len;
    // |w|² - (w.u)² = r² with w = (wx, wy, s), s = z - (a.z + r).
    const double c0 = wx * wx + wy * wy - k * k - r * r, disc = k * k * nz * nz - k2 * c0;
    if (disc < 0) return best;
    for (double sign : {-1.0, 1.0}) {
        double s = (k * nz + sign * std::sqrt(disc)) / k2, along = k + s * nz;
        if (along >= 0 && along <= len) best = std::min(best, a[2] + r + s);
    }
    return best;
}

}  // namespace

double Cutter::bottom(double d) const {
    const double e = d - (radius - corner);
    if (e <= 0) return 0;
    if (e >= corner) return corner;
    return corner - std::sqrt((corner - e) * (corner + e));
}

double Cutter::slice(double u) const {
    if (u >= corner) return radius;
    u = std::max(u, 0.0);
    return radius - corner + std::sqrt(u * (2 * corner - u));
}

MillWorld::MillWorld(const Box3& stock, double cell)
    : stock_(stock), cell_(cell > 0 && std::isfinite(cell) ? cell : 0.1) {
    for (int k = 0; k < 3; ++k)
        if (stock_.hi[k] < stock_.lo[k]) std::swap(stock_.lo[k], stock_.hi[k]);
    // 300 / 0.1 is 2999.9999999999995 or 3000.0000000000005: not 3001 cells.
    auto count = [&](int k) {
        return std::max(1, int(std::ceil((stock_.hi[k] - stock_.lo[k]) / cell_ - 1e-9)));
    };
    nx_ = count(0), ny_ = count(1);
    for (int i = 0; i < nx_; ++i)
        xs_.push_back(std::min(stock_.lo[0] + (i + 0.5) * cell_, stock_.hi[0]));
    for (int j = 0; j < ny_; ++j)
        ys_.push_back(std::min(stock_.lo[1] + (j + 0.5) * cell_, stock_.hi[1]));
    tx_ = (nx_ + kTile - 1) / kTile, ty_ = (ny_ + kTile - 1) / kTile;
    const double wx = stock_.hi[0] - stock_.lo[0], wy = stock_.hi[1] - stock_.lo[1];
    bucket_ = std::max({5.0, wx / 256, wy / 256});
    bx_ = std::max(1, int(std::ceil(wx / bucket_))),
    by_ = std::max(1, int(std::ceil(wy / bucket_)));
    new_part();
}

void MillWorld::new_part() {
    const size_t n = size_t(nx_) * size_t(ny_);
    h_.assign(n, float(stock_.hi[2]));
    touched_.assign(n, 0);
    tile_max_.assign(size_t(tx_) * size_t(ty_), float(stock_.hi[2]));
    tile_stale_.assign(size_t(tx_) * size_t(ty_), 0);
    stale_ = false;
    strokes_.clear();
    under_.clear();
    buckets_.assign(size_t(bx_) * size_t(by_), {});
    ++generation_;
}

bool leans(const P3& u) {
    return std::abs(u[0]) > 1e-9 || std::abs(u[1]) > 1e-9 || !(u[2] > 0);
}

bool MillWorld::make_stroke(const P3& a, const P3& b, double radius, double corner, const P3& u,
                            Stroke& s) {
    for (double v : {a[0], a[1], a[2], b[0], b[1], b[2], radius, corner})
        if (!(std::abs(v) <= kFar)) return false;
    s = Stroke{};
    for (int k = 0; k < 3; ++k) s.a[k] = grain(a[k]), s.b[k] = grain(b[k]);
    s.radius = grain(radius);
    s.corner = std::clamp(grain(corner), 0.0, s.radius);
    const double len = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (!(len > 0.5 && len < 2)) return false;
    // The axis is kept to 1e-9, as the store keeps it: one read back (a unit
    // vector within 1e-8) is not made a unit again, so it stays the same.
    const double norm = std::abs(len - 1) < 1e-8 ? 1 : len;
    for (int k = 0; k < 3; ++k) s.u[k] = std::round(u[k] / norm * 1e9) / 1e9;
    s.tilt = leans(s.u);
    if (!s.tilt) s.u = kUp;
    return s.radius > 0;
}

// Where a stroke can take material: its tip's box grown by the radius; a
// tilted one's whole cylinder up to the stock's top, within the stock.
void MillWorld::bound(Stroke& s) const {
    const double r = s.radius;
    for (int k = 0; k < 3; ++k)
        s.reach.lo[k] = std::min(s.a[k], s.b[k]) - r, s.reach.hi[k] = std::max(s.a[k], s.b[k]) + r;
    if (!s.tilt) {
        s.reach.lo[2] = std::min(s.a[2], s.b[2]);
        return;
    }
    // Pointing up (B beyond 90°), the cutter's body goes down without end.
    if (s.u[2] < -1e-6) s.reach.lo[2] = std::min(s.reach.lo[2], stock_.lo[2] - r);
    const double rise = stock_.hi[2] - s.reach.lo[2];
    const double up = s.u[2] > 1e-6 ? std::min(rise / s.u[2], kFar) : kFar;
    for (int k = 0; k < 2; ++k) {
        s.reach.lo[k] = std::max(s.reach.lo[k] + std::min(0.0, up * s.u[k]), stock_.lo[k] - r);
        s.reach.hi[k] = std::min(s.reach.hi[k] + std::max(0.0, up * s.u[k]), stock_.hi[k] + r);
    }
}

bool MillWorld::meets_stock(const Stroke& s) const {
    const Box3& b = s.reach;
    return b.lo[0] <= stock_.hi[0] && b.hi[0] >= stock_.lo[0] && b.lo[1] <= stock_.hi[1] &&
           b.hi[1] >= stock_.lo[1] && b.lo[2] <= stock_.hi[2];
}

void MillWorld::record(const Stroke& s) {
    // A margin of 1 µm: a line exactly on a bucket's edge finds the strokes
    // that end there whichever way the division rounds.
    constexpr double m = 1e-3;
    auto bucket = [&](double v, int k, int n) {
        return std::clamp(int(std::floor((v - stock_.lo[k]) / bucket_)), 0, n - 1);
    };
    Stroke t = s;
    t.bi = bucket(s.reach.lo[0] - m, 0, bx_);
    t.bj = bucket(s.reach.lo[1] - m, 1, by_);
    const int bi1 = bucket(s.reach.hi[0] + m, 0, bx_);
    const int bj1 = bucket(s.reach.hi[1] + m, 1, by_);
    const auto k = uint32_t(strokes_.size());
    strokes_.push_back(t);
    for (int j = t.bj; j <= bj1; ++j)
        for (int i = t.bi; i <= bi1; ++i)
            buckets_[size_t(j) * size_t(bx_) + size_t(i)].push_back(k);
}

double MillWorld::cut(const Cutter& c, const P3& a, const P3& b, const P3& u) {
    Stroke s;
    if (!make_stroke(a, b, c.radius, c.corner, u, s)) return 0;
    bound(s);
    if (!meets_stock(s)) return 0;
    // Recorded even when the height field does not change: the stroke may
    // still take a sliver between the cells' centres, which the instruments see.
    record(s);
    ++generation_;
    return apply(s);
}

double MillWorld::lowest(const Stroke& s, double x, double y, double tol) {
    const double r = s.radius;
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1], dz = s.b[2] - s.a[2];
    const double px = x - s.a[0], py = y - s.a[1];
    const double A = dx * dx + dy * dy, B = px * dx + py * dy, C = px * px + py * py - r * r;
    const Cutter k = cutter_of(r, s.corner);
    if (A == 0 || dz == 0) {
        // Level, or a plunge: the distance to the segment decides.
        double t = A == 0 ? 0 : std::clamp(B / A, 0.0, 1.0);
        double d = std::hypot(px - t * dx, py - t * dy);
        return d <= r ? std::min(s.a[2], s.b[2]) + k.bottom(d) : kInf;
    }
    if (s.corner == r) {
        return lowest_ball(s.a, s.b, r, x, y);
    }
    // The tip positions whose disc of radius r covers (x, y).
    const double disc = B * B - A * C;
    if (disc < 0) return kInf;
    const double t0 = std::max(0.0, (B - std::sqrt(disc)) / A);
    const double t1 = std::min(1.0, (B + std::sqrt(disc)) / A);
    if (t0 > t1) return kInf;
    // A flat end: the lowest of those, at one end of the range.
    if (s.corner == 0) return s.a[2] + dz * (dz < 0 ? t1 : t0);
    auto f = [&](double t) {
        const double ex = px - t * dx, ey = py - t * dy;
        return s.a[2] + t * dz + k.bottom(std::min(r, std::sqrt(ex * ex + ey * ey)));
    };
    const double len = std::sqrt(A + dz * dz);
    return golden_min(f, t0, t1, tol / len).second;
}

double MillWorld::side(int axis, int k) const {
    // The last row and column may be partial cells.
    const int n = axis == 0 ? nx_ : ny_;
    return k == n - 1 ? stock_.hi[axis] - (stock_.lo[axis] + (n - 1) * cell_) : cell_;
}

double MillWorld::apply(const Stroke& s) {
    if (s.tilt) return apply_tilted(s);
    const double r = s.radius, lox = stock_.lo[0], loy = stock_.lo[1], top = stock_.hi[2];
    auto from = [&](double v, double lo, int n) {
        return std::clamp(int(std::floor((v - lo) / cell_ - 0.5)), 0, n - 1);
    };
    auto to = [&](double v, double lo, int n) {
        return std::clamp(int(std::ceil((v - lo) / cell_ - 0.5)), 0, n - 1);
    };
    const int i0 = from(std::min(s.a[0], s.b[0]) - r, lox, nx_);
    const int i1 = to(std::max(s.a[0], s.b[0]) + r, lox, nx_);
    const int j0 = from(std::min(s.a[1], s.b[1]) - r, loy, ny_);
    const int j1 = to(std::max(s.a[1], s.b[1]) + r, loy, ny_);
    const bool level = s.a[2] == s.b[2];
    const Cutter k = cutter_of(r, s.corner);
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1], A = dx * dx + dy * dy;
    const float floor_z = float(stock_.lo[2]);
    double removed = 0;
    for (int j = j0; j <= j1; ++j) {
        const double y = ys_[size_t(j)];
        double xa, xb, fa = kInf, fb = -kInf;
        if (!stadium_cut(s.a[0], s.a[1], s.b[0], s.b[1], r, y, xa, xb)) continue;
        // On a level stroke the flat of the end is the stroke's height.
        if (level && !stadium_cut(s.a[0], s.a[1], s.b[0], s.b[1], r - s.corner, y, fa, fb))
            fa = kInf, fb = -kInf;
        const int ia = std::max(i0, from(xa, lox, nx_)), ib = std::min(i1, to(xb, lox, nx_));
        float* h = &h_[size_t(j) * size_t(nx_)];
        uint8_t* reached = &touched_[size_t(j) * size_t(nx_)];
        double row = 0;
        for (int i = ia; i <= ib; ++i) {
            const double x = xs_[size_t(i)];
            if (x < xa || x > xb) continue;
            double low = s.a[2];
            if (!level) {
                low = lowest(s, x, y, 1e-6);
            } else if (x < fa || x > fb) {
                const double px = x - s.a[0], py = y - s.a[1];
                const double t = A == 0 ? 0 : std::clamp((px * dx + py * dy) / A, 0.0, 1.0);
                const double ex = px - t * dx, ey = py - t * dy, d = std::sqrt(ex * ex + ey * ey);
                low = d <= r ? s.a[2] + k.bottom(d) : kInf;
            }
            if (!(low <= top)) continue;
            reached[i] = 1;
            if (!under_.empty() && under_.count(size_t(j) * size_t(nx_) + size_t(i))) {
                row += carve(size_t(j) * size_t(nx_) + size_t(i), low, kInf) * side(0, i);
                continue;
            }
            const float z = std::max(float(low), floor_z);
            if (z < h[i]) {
                row += double(h[i] - z) * side(0, i);
                h[i] = z;
            }
        }
        removed += row * side(1, j);
    }
    if (removed > 0) mark_stale(i0, i1, j0, j1);
    return removed;
}

void MillWorld::mark_stale(int i0, int i1, int j0, int j1) {
    for (int tj = j0 / kTile; tj <= j1 / kTile; ++tj)
        for (int ti = i0 / kTile; ti <= i1 / kTile; ++ti)
            tile_stale_[size_t(tj) * size_t(tx_) + size_t(ti)] = 1;
    stale_ = true;
}

void MillWorld::refresh() const {
    if (!stale_) return;
    for (int tj = 0; tj < ty_; ++tj)
        for (int ti = 0; ti < tx_; ++ti) {
            const size_t t = size_t(tj) * size_t(tx_) + size_t(ti);
            if (!tile_stale_[t]) continue;
            float m = -std::numeric_limits<float>::infinity();
            for (int j = tj * kTile; j < std::min(ny_, (tj + 1) * kTile); ++j) {
                const float* h = &h_[size_t(j) * size_t(nx_)];
                for (int i = ti * kTile; i < std::min(nx_, (ti + 1) * kTile); ++i)
                    m = std::max(m, h[i]);
            }
            tile_max_[t] = m;
            tile_stale_[t] = 0;
        }
    stale_ = false;
}

bool MillWorld::removal(const Stroke& s, int axis, const P3& at, double& lo, double& hi) {
    if (s.tilt) {
        tilt::Line l;
        l.o = at;
        l.o[axis] = 0;
        l.e = {0, 0, 0};
        l.e[axis] = 1;
        const P3 d{s.b[0] - s.a[0], s.b[1] - s.a[1], s.b[2] - s.a[2]};
        const tilt::Span sp = tilt::swept_cutter(s.radius, s.corner, s.a, d, s.u, l);
        lo = sp.lo, hi = sp.hi;
        return !sp.empty();
    }
    if (axis == 2) {
        lo = lowest(s, at[0], at[1], 1e-10), hi = kInf;
        return lo < kInf;
    }
    const int q = 1 - axis;  // the line's other horizontal coordinate
    const double z0 = at[2], dz = s.b[2] - s.a[2];
    if (z0 < std::min(s.a[2], s.b[2])) return false;
    const Cutter k = cutter_of(s.radius, s.corner);
    if (dz == 0)
        return stadium_cut(s.a[axis], s.a[q], s.b[axis], s.b[q], k.slice(z0 - s.a[2]), at[q], lo,
                           hi);
    // The tip's positions at or below z0.
    double t0 = 0, t1 = 1;
    narrow(s.a[2], dz, -kInf, z0, t0, t1);
    auto c = [&](int ax, double t) { return s.a[ax] + t * (s.b[ax] - s.a[ax]); };
    if (s.corner == 0)
        return stadium_cut(c(axis, t0), c(q, t0), c(axis, t1), c(q, t1), s.radius, at[q], lo, hi);
    // Otherwise the union over t of the chords of the discs of radius
    // rad(t) about the axis: rad is concave in t, so the chord's half length
    // is (a Lorentz norm of (rad, offset)), and both ends are 1-D convex
    // searches over the t where the disc reaches the line at all.
    constexpr double tol = 1e-13;
    auto rad = [&](double t) { return k.slice(z0 - (s.a[2] + t * dz)); };
    auto reach = [&](double t) { return rad(t) - std::abs(at[q] - c(q, t)); };
    auto [tm, gm] = golden_min([&](double t) { return -reach(t); }, t0, t1, tol);
    if (gm >= 0) return false;
    const double f0 = reach(t0) >= 0 ? t0 : crossing(reach, tm, t0, tol);
    const double f1 = reach(t1) >= 0 ? t1 : crossing(reach, tm, t1, tol);
    auto half = [&](double t) {
        const double e = std::abs(at[q] - c(q, t)), r = rad(t);
        return r > e ? std::sqrt((r - e) * (r + e)) : 0.0;
    };
    hi = -golden_min([&](double t) { return -(c(axis, t) + half(t)); }, f0, f1, tol).second;
    lo = golden_min([&](double t) { return c(axis, t) - half(t); }, f0, f1, tol).second;
    return lo < hi;
}

std::string MillWorld::to_text() const {
    std::string o;
    char line[512];
    for (const Stroke& s : strokes_) {
        int n = s.tilt ? std::snprintf(line, sizeof line,
                                       "%.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.9f %.9f %.9f\n",
                                       s.a[0], s.a[1], s.a[2], s.b[0], s.b[1], s.b[2], s.radius,
                                       s.corner, s.u[0], s.u[1], s.u[2])
                       : std::snprintf(line, sizeof line,
                                       "%.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n", s.a[0], s.a[1],
                                       s.a[2], s.b[0], s.b[1], s.b[2], s.radius, s.corner);
        o.append(line, size_t(std::clamp(n, 0, int(sizeof line) - 1)));
    }
    return o;
}

// text -> { stroke "\n" } ; stroke -> ax ay az bx by bz radius corner [ux uy uz]
// (blank lines are allowed; anything else refuses the whole text).
bool MillWorld::from_text(std::string_view text) {
    size_t lines = size_t(std::count(text.begin(), text.end(), '\n'));
    if (!text.empty() && text.back() != '\n') ++lines;
    if (lines > 5'000'000) return false;
    std::vector<Stroke> parsed;
    while (!text.empty()) {
        const size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        const char* p = line.data();
        const char* end = p + line.size();
        auto blank = [&] {
            while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
        };
        blank();
        if (p == end) continue;
        double v[11] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
        int n = 0;
        for (; n < 11 && p < end; ++n) {
            auto r = std::from_chars(p, end, v[n]);
            if (r.ec != std::errc() || !std::isfinite(v[n])) return false;
            p = r.ptr;
            blank();
        }
        Stroke s;
        if (p != end || (n != 8 && n != 11) || !(v[6] > 0) || v[7] < 0 || v[7] > v[6] ||
            !make_stroke({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], v[7], {v[8], v[9], v[10]},
                         s))
            return false;
        bound(s);
        parsed.push_back(s);
    }
    new_part();
    for (const Stroke& s : parsed)
        if (meets_stock(s)) record(s), apply(s);
    return true;
}

}  // namespace pupitre::workshop
