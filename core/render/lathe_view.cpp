// The lathe's picture (see part_view.hpp): above the spindle axis the
// half-section as cut (the stock as loaded, what the tools removed, the
// material hatched, its surfaces painted along the outline, the drawing's
// lines dashed over it), below the axis the part seen from outside, each
// column shaded as the cylinder it is; the jaws, the tailstock, the tool
// and its holder where they stand, the stick-out.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/render/part_view.hpp"

namespace pupitre::render {

namespace {

// Machine (Z, R) to pixels.
struct Xf {
    double cz = 0, cr = 0, s = 1;  // the picture's centre, mm per pixel
    int w = 1, h = 1;
    V2 px(const workshop::Pt& p) const {
        return {(p[0] - cz) / s + w / 2.0, h / 2.0 - (p[1] - cr) / s};
    }
    double z_of(double x) const { return cz + (x - w / 2.0) * s; }
};

using Polys = std::vector<std::vector<V2>>;

Polys placed(const workshop::CPaths& from, const Xf& xf, double sign = 1,
             workshop::Pt at = {0, 0}) {
    Polys out;
    for (const workshop::CPath& q : from) {
        out.emplace_back();
        for (const auto& v : q) {
            const workshop::Pt p = workshop::to_mm(v);
            out.back().push_back(xf.px({at[0] + p[0], sign * (at[1] + p[1])}));
        }
    }
    return out;
}

Polys placed(const std::vector<Poly>& from, const Xf& xf, double sign = 1) {
    Polys out;
    for (const Poly& q : from) {
        out.emplace_back();
        for (const workshop::Pt& p : q) out.back().push_back(xf.px({p[0], sign * p[1]}));
    }
    return out;
}

// The view that holds the stock, the jaws and the mirror image below the
// axis, zoomed and panned.
Xf fit(const PartScene& s, const Surfaces& sf, const Look& look, int w, int h) {
    double z0 = 1e18, z1 = -1e18, r1 = s.lathe.jaw_top;
    for (const Poly& p : sf.stock)
        for (const workshop::Pt& q : p)
            z0 = std::min(z0, q[0]), z1 = std::max(z1, q[0]), r1 = std::max(r1, q[1]);
    if (z0 > z1) z0 = s.lathe.chuck_z, z1 = z0 + 100;
    z0 = std::min(z0, s.lathe.chuck_z - 30);
    r1 += 4;
    Xf xf;
    xf.w = w, xf.h = h;
    xf.s = std::max((z1 - z0) / w, 2 * r1 / h) * 1.08 / look.cam.zoom;
    xf.cz = (z0 + z1) / 2 - look.cam.pan_x * w * xf.s;
    xf.cr = look.cam.pan_y * h * xf.s;
    return xf;
}

// Below the axis: each column's outer radius, shaded across as a cylinder
// lit from above and in front, in the colour of the surface there.
void silhouette(const Surfaces& sf, const Xf& xf, Image& img) {
    std::vector<double> rmax(size_t(img.w()), 0);
    std::vector<Colour> col(size_t(img.w()), 0);
    for (size_t p = 0; p < sf.outline.size(); ++p) {
        const Poly& q = sf.outline[p];
        for (size_t k = 0; k < q.size(); ++k) {
            const workshop::Pt a = q[k], b = q[(k + 1) % q.size()];
            if (sf.edge[p][k] == 0 || a[0] == b[0]) continue;
            const double xa = xf.px(a)[0], xb = xf.px(b)[0];
            const int c0 = std::max(0, int(std::ceil(std::min(xa, xb) - 0.5)));
            const int c1 = std::min(img.w(), int(std::ceil(std::max(xa, xb) - 0.5)));
            for (int c = c0; c < c1; ++c) {
                const double z = xf.z_of(c + 0.5);
                const double r = a[1] + (b[1] - a[1]) * (z - a[0]) / (b[0] - a[0]);
                if (r > rmax[size_t(c)]) rmax[size_t(c)] = r, col[size_t(c)] = sf.edge[p][k];
            }
        }
    }
    const double axis_y = xf.px({0, 0})[1];
    for (int c = 0; c < img.w(); ++c) {
        const double r = rmax[size_t(c)];
        if (r <= 0) continue;
        const int y0 = std::max(0, int(std::ceil(axis_y - 0.5)));
        const int y1 = std::min(img.h(), int(std::ceil(axis_y + r / xf.s - 0.5)));
        for (int y = y0; y < y1; ++y) {
            const double t = std::min(1.0, (y + 0.5 - axis_y) * xf.s / r);
            const double nz = std::sqrt(1 - t * t);
            const double lit = std::max(0.0, -0.5 * t + 0.866 * nz);
            const double spec = std::pow(std::max(0.0, -0.26 * t + 0.966 * nz), 24);
            img.set(c, y, shade(col[size_t(c)], 0.3 + 0.75 * lit + 0.35 * spec));
        }
    }
}

// The outline's edges in their surfaces' colours, `width` pixels wide.
void surface_edges(const Surfaces& sf, const Xf& xf, double width, Image& img) {
    for (size_t p = 0; p < sf.outline.size(); ++p) {
        const Poly& q = sf.outline[p];
        for (size_t k = 0; k < q.size(); ++k)
            if (sf.edge[p][k] != 0)
                img.line(xf.px(q[k]), xf.px(q[(k + 1) % q.size()]), sf.edge[p][k], width);
    }
}

void tool(const PartScene& s, const Xf& xf, const Palette& pal, Image& img) {
    if (!s.lathe.has_tool) return;
    const Polys holder = placed(workshop::CPaths{s.lathe.tool.holder}, xf, 1, s.lathe.tip);
    const Polys insert = placed(workshop::CPaths{s.lathe.tool.insert}, xf, 1, s.lathe.tip);
    img.fill(holder, pal.holder);
    img.fill(insert, pal.insert);
    for (const Polys* ps : {&holder, &insert})
        for (const auto& q : *ps)
            for (size_t k = 0; k < q.size(); ++k)
                img.line(q[k], q[(k + 1) % q.size()], pal.chuck_edge);
}

// From the jaws' face to the part's face, above the jaws: a line with its
// two ends ticked.
void stickout(const PartScene& s, const Xf& xf, const Palette& pal, Picture& p) {
    if (!s.lathe.has_face) return;
    const double r = s.lathe.jaw_top + 2;
    p.has_stickout = true;
    p.stickout = s.lathe.face_z - s.lathe.chuck_z;
    p.stick = {xf.px({s.lathe.chuck_z, r}), xf.px({s.lathe.face_z, r})};
    p.image.line(p.stick[0], p.stick[1], pal.drawing);
    for (const V2& e : p.stick) p.image.line({e[0], e[1] - 4}, {e[0], e[1] + 4}, pal.drawing);
}

}  // namespace

void lathe_section(const PartScene& s, const Surfaces& sf, const Look& look, Picture& p) {
    const Palette& pal = palette(look.paper);
    Image& img = p.image;
    const Xf xf = fit(s, sf, look, img.w(), img.h());
    p.mm_per_px = xf.s;
    const double unit = std::max(1.0, img.h() / 240.0);  // line widths grow with the picture
    img.fill(placed(sf.stock, xf), pal.removed);
    const Polys material = placed(sf.outline, xf);
    img.fill(material, pal.section);
    img.hatch(material, pal.hatch, int(std::lround(6 * unit)));
    silhouette(sf, xf, img);
    for (double sign : {1.0, -1.0})
        for (const workshop::CPaths* c : {&s.lathe.chuck, &s.lathe.tailstock, &s.lathe.gauge}) {
            const Polys q = placed(*c, xf, sign);
            img.fill(q, pal.chuck);
            for (const auto& poly : q)
                for (size_t k = 0; k < poly.size(); ++k)
                    img.line(poly[k], poly[(k + 1) % poly.size()], pal.chuck_edge);
        }
    surface_edges(sf, xf, 3 * unit, img);
    for (const auto& seg : sf.nominal)
        img.line(xf.px(seg[0]), xf.px(seg[1]), pal.drawing, unit, int(std::lround(4 * unit)));
    const double axis_y = xf.px({0, 0})[1];
    img.line({0, axis_y}, {double(img.w()), axis_y}, pal.axis, unit, int(std::lround(8 * unit)));
    tool(s, xf, pal, img);
    stickout(s, xf, pal, p);
    for (size_t i = 0; i < sf.anchor.size() && i < p.anchor.size(); ++i)
        if (!std::isnan(sf.anchor[i][0])) p.anchor[i] = xf.px({sf.anchor[i][0], sf.anchor[i][1]});
}

}  // namespace pupitre::render
