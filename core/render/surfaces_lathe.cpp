// The lathe's surfaces painted (see surfaces.hpp): the half-section's
// outline edge by edge. A dimension's surface is found from where its
// instrument reads: the cylinder through the micrometer's point (dia), the
// bore's, the two walls of a groove, the right-hand face (length).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/render/surfaces.hpp"

namespace pupitre::render {

namespace {

constexpr double kFlat = 2e-3;  // mm: an edge this close to a level lies on it

workshop::Pt end_of(const Poly& p, size_t k) {
    return p[(k + 1) % p.size()];
}

// The distance from `q` to the stock's outline: how deep a surface is.
double depth_below(const std::vector<Poly>& stock, const workshop::Pt& q) {
    double best = 1e18;
    for (const Poly& p : stock)
        for (size_t k = 0; k < p.size(); ++k) {
            const workshop::Pt a = p[k], b = end_of(p, k);
            const double dz = b[0] - a[0], dr = b[1] - a[1];
            const double len2 = dz * dz + dr * dr;
            double t = len2 > 0 ? ((q[0] - a[0]) * dz + (q[1] - a[1]) * dr) / len2 : 0;
            t = std::clamp(t, 0.0, 1.0);
            best = std::min(best, std::hypot(q[0] - a[0] - t * dz, q[1] - a[1] - t * dr));
        }
    return best;
}

// Edges at level R = r (both ends within kFlat), grouped into the
// stretch that holds Z `z`: the marked edges and the stretch's Z extent.
bool level_stretch(const std::vector<Poly>& out, double r, double z,
                   std::vector<std::array<size_t, 2>>& marked, double& z0, double& z1) {
    struct E {
        double a, b;
        size_t p, k;
    };
    std::vector<E> es;
    for (size_t p = 0; p < out.size(); ++p)
        for (size_t k = 0; k < out[p].size(); ++k) {
            const workshop::Pt a = out[p][k], b = end_of(out[p], k);
            if (std::abs(a[1] - r) <= kFlat && std::abs(b[1] - r) <= kFlat && a[0] != b[0])
                es.push_back({std::min(a[0], b[0]), std::max(a[0], b[0]), p, k});
        }
    std::sort(es.begin(), es.end(), [](const E& x, const E& y) { return x.a < y.a; });
    for (size_t i = 0; i < es.size();) {
        size_t j = i;
        double hi = es[i].b;
        while (j + 1 < es.size() && es[j + 1].a <= hi + 1e-3) hi = std::max(hi, es[++j].b);
        if (es[i].a - kFlat <= z && z <= hi + kFlat) {
            z0 = es[i].a, z1 = hi;
            for (size_t m = i; m <= j; ++m) marked.push_back({es[m].p, es[m].k});
            return true;
        }
        i = j + 1;
    }
    return false;
}

// Edges along R (a face, a wall) at Z `z`, above R `above`.
void walls_at(const std::vector<Poly>& out, double z, double above,
              std::vector<std::array<size_t, 2>>& marked, double& r_top) {
    for (size_t p = 0; p < out.size(); ++p)
        for (size_t k = 0; k < out[p].size(); ++k) {
            const workshop::Pt a = out[p][k], b = end_of(out[p], k);
            if (std::abs(a[0] - z) > kFlat || std::abs(b[0] - z) > kFlat) continue;
            if (std::max(a[1], b[1]) <= above + kFlat) continue;
            marked.push_back({p, k});
            r_top = std::max({r_top, a[1], b[1]});
        }
}

// The walls of the groove whose bottom is at Z `z` (radius r0): the
// nearest rising edges on each side.
bool groove_walls(const std::vector<Poly>& out, double z, double r0, double& left, double& right) {
    left = -1e18, right = 1e18;
    for (const Poly& p : out)
        for (size_t k = 0; k < p.size(); ++k) {
            const workshop::Pt a = p[k], b = end_of(p, k);
            if (std::abs(a[0] - b[0]) > kFlat) continue;
            if (std::max(a[1], b[1]) <= r0 + kFlat || std::min(a[1], b[1]) > r0 + kFlat) continue;
            if (a[0] <= z) left = std::max(left, a[0]);
            if (a[0] >= z) right = std::min(right, a[0]);
        }
    return left > -1e18 && right < 1e18;
}

struct Found {
    std::vector<std::array<size_t, 2>> edges;
    std::array<double, 3> anchor{kNaN, kNaN, kNaN};
};

// The surface a lathe dimension reads, and its nominal lines.
Found lathe_surface(const PartScene& s, const Surfaces& sf, const DimReading& d,
                    std::vector<std::array<workshop::Pt, 2>>& nominal) {
    Found f;
    const std::string& w = d.place.word;
    const double z = d.place.at[2];
    std::vector<double> rs;
    crossings(sf.outline, z, rs);
    if (w == "dia" || w == "bore") {
        if (rs.empty()) return f;
        const double r = w == "dia" ? rs.back() : rs.front();
        double z0 = z, z1 = z;
        if (!level_stretch(sf.outline, r, z, f.edges, z0, z1)) return f;
        f.anchor = {z, r, 0};  // where the micrometer read
        nominal.push_back(
            {workshop::Pt{z0, d.dim.nominal / 2}, workshop::Pt{z1, d.dim.nominal / 2}});
    } else if (w == "groove") {
        if (rs.empty()) return f;
        double left = 0, right = 0, top = rs.back();
        if (!groove_walls(sf.outline, z, rs.back(), left, right)) return f;
        walls_at(sf.outline, left, rs.back(), f.edges, top);
        walls_at(sf.outline, right, rs.back(), f.edges, top);
        f.anchor = {z, rs.back(), 0};
        const double mid = (left + right) / 2, half = d.dim.nominal / 2;
        for (double zz : {mid - half, mid + half})
            nominal.push_back({workshop::Pt{zz, rs.back()}, workshop::Pt{zz, top}});
    } else if (w == "length" && s.lathe.has_face) {
        double top = 0;
        walls_at(sf.outline, s.lathe.face_z, -1, f.edges, top);
        f.anchor = {s.lathe.face_z, top / 2, 0};
        const double zn = s.lathe.chuck_z + d.dim.nominal;
        nominal.push_back({workshop::Pt{zn, 0}, workshop::Pt{zn, top}});
    }
    return f;
}

}  // namespace

void crossings(const std::vector<Poly>& outline, double z, std::vector<double>& rs) {
    rs.clear();
    for (const Poly& p : outline)
        for (size_t k = 0; k < p.size(); ++k) {
            const workshop::Pt a = p[k], b = end_of(p, k);
            if ((a[0] <= z && z < b[0]) || (b[0] <= z && z < a[0]))
                rs.push_back(a[1] + (b[1] - a[1]) * (z - a[0]) / (b[0] - a[0]));
        }
    std::sort(rs.begin(), rs.end());
}

void lathe_surfaces(const PartScene& s, Surfaces& out) {
    auto to_mm = [](const workshop::CPaths& from, std::vector<Poly>& to) {
        for (const workshop::CPath& q : from) {
            to.emplace_back();
            for (const auto& v : q) to.back().push_back(workshop::to_mm(v));
        }
    };
    to_mm(s.lathe.material, out.outline);
    to_mm(s.lathe.stock, out.stock);
    double deepest = 0;
    std::vector<std::vector<double>> depth(out.outline.size());
    for (size_t p = 0; p < out.outline.size(); ++p)
        for (size_t k = 0; k < out.outline[p].size(); ++k) {
            const workshop::Pt a = out.outline[p][k], b = end_of(out.outline[p], k);
            const double d = depth_below(out.stock, {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2});
            depth[p].push_back(d);
            deepest = std::max(deepest, d);
        }
    out.legend = legend_of(s, out.paint, round_up(deepest));
    out.edge.resize(out.outline.size());
    for (size_t p = 0; p < out.outline.size(); ++p)
        for (size_t k = 0; k < out.outline[p].size(); ++k) {
            const workshop::Pt a = out.outline[p][k], b = end_of(out.outline[p], k);
            const double d = depth[p][k];
            Colour c = out.paint == Paint::deviation ? kUnmarked
                       : d < 1e-3                    ? kUncut
                                                     : depth_colour(d / out.legend.depth);
            if (a[1] < kFlat && b[1] < kFlat) c = 0;  // on the axis: no surface
            out.edge[p].push_back(c);
        }
    out.anchor.assign(s.dims.size(), {kNaN, kNaN, kNaN});
    if (out.paint != Paint::deviation) return;
    for (size_t i = 0; i < s.dims.size(); ++i) {
        const DimReading& d = s.dims[i];
        if (!d.read) continue;
        Found f = lathe_surface(s, out, d, out.nominal);
        out.anchor[i] = f.anchor;
        const Colour c = reading_colour(d, out.legend.span_um);
        for (const auto& [p, k] : f.edges) out.edge[p][k] = c;
    }
}

std::shared_ptr<const Surfaces> prepare(const PartScene& s, Paint paint, bool paper) {
    auto out = std::make_shared<Surfaces>();
    out->paint = paint == Paint::deviation && !s.dims.empty() ? Paint::deviation : Paint::depth;
    if (s.mill)
        mill_surfaces(s, *out, paper);
    else
        lathe_surfaces(s, *out);
    return out;
}

}  // namespace pupitre::render
