// The GRAPH page (see page_graph.hpp): the moves rasterised once per window
// and kept in a cache, the frame's own marks (spindle axis, stock, EM±, tool,
// cursor, errors) drawn over a copy, then the scale bar and the extents.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/page_graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/numfmt.hpp"
#include "pages/view.hpp"

namespace pupitre::pages {

// E31000 / E31001: the line type of G0 and of G1-G3 moves, 0 to 4 (004:1261,
// 1263). The seeds give no pattern for each value; pupitre's choice (man
// pupitre(1), GRAPH): 0 the default (rapids dashed, feeds solid), 1 solid,
// 2 dashed, 3 dotted, 4 dash-dot.
static uint16_t line_pattern(const PathMove& mv) {
    switch (mv.ltype) {
        case 1:
            return kSolid;
        case 2:
            return kDashed;
        case 3:
            return kDotted;
        case 4:
            return kDashDot;
        default:
            return mv.kind == PathKind::rapid ? kDashed : kSolid;
    }
}

namespace {

using ::pupitre::geometry::kPi;

const InkStyles kStyles = {
    Style::normal,  // none
    Style::dim,     // part
    Style::dim,     // axis
    Style::dim,     // mirror
    Style::dim,     // stock
    Style::dim,     // extremes
    Style::dim,     // rapid
    Style::normal,  // feed
    Style::value,   // comp
    Style::warn,    // travel
    Style::alarm,   // error
};

Ink ink_of(const PathMove& mv) {
    if (mv.flags & pathflag::error) return Ink::error;
    if (mv.flags & pathflag::travel) return Ink::travel;
    return mv.kind == PathKind::rapid  ? Ink::rapid
           : mv.kind == PathKind::comp ? Ink::comp
                                       : Ink::feed;
}

// An arc move, drawn in the view plane (h, v); `flip` draws its mirror image
// (y -> -y). An arc in another plane shows as the polyline of its projection.
void draw_path_arc(const Toolpath& p, size_t i, int h, int v, bool flip, const ViewXf& xf,
                   DotRaster& r, Ink ink, uint16_t dash) {
    const PathMove& mv = p[i];
    const PathArc& a = p.arcs()[mv.arc];
    const double* s = p.from(i);
    double r0, r1;
    arc_radii(p, i, r0, r1);
    double sweep = double(a.sweep) * kPi / 180;
    double ys = flip ? -1 : 1;
    if ((a.a0 == h && a.a1 == v) || (a.a0 == v && a.a1 == h)) {
        bool swapped = a.a0 == v;
        double cx = swapped ? a.c1 : a.c0, cy = (swapped ? a.c0 : a.c1) * ys;
        double ang0 = std::atan2(ys * s[v] - cy, s[h] - cx);
        double sw = (swapped ? -sweep : sweep) * ys;
        draw_arc(r, xf, cx, cy, r0, r1, ang0, sw, ink, dash);
        return;
    }
    int n = arc_chords(std::max(r0, r1) / xf.scale, sweep);
    double q0[3] = {s[0], s[1], s[2]}, q1[3];
    for (int k = 1; k <= n; ++k) {
        arc_point(p, i, double(k) / n, q1);
        draw_line(r, xf, q0[h], ys * q0[v], q1[h], ys * q1[v], ink, dash);
        std::copy(q1, q1 + 3, q0);
    }
}

// The lathe's rough stock (G64) as the run reported it, with its mirror image.
// With none reported nothing is drawn: a guessed bar would be wrong for a bore
// or a rim.
void draw_stock(const GraphView& g, const ViewXf& xf, DotRaster& r) {
    for (const auto& poly : g.path->stock())
        for (size_t k = 1; k < poly.size(); ++k)
            for (double ys : {1.0, -1.0})
                if (ys > 0 || g.mirror)
                    draw_line(r, xf, poly[k - 1][0], ys * poly[k - 1][1], poly[k][0],
                              ys * poly[k][1], Ink::stock);
}

// The workshop's part: its half-section filled row by row (even-odd), with
// its mirror image below the axis.
void fill_part(const GraphView& g, const ViewXf& xf, DotRaster& r) {
    if (!g.part) return;
    std::vector<double> xs;
    for (int j = 0; j < xf.h; ++j) {
        double y = xf.wy(j);
        if (y < 0 && !g.mirror) continue;
        double R = std::abs(y);
        xs.clear();
        for (const auto& poly : *g.part)
            for (size_t k = 0; k < poly.size(); ++k) {
                const auto &a = poly[k], &b = poly[(k + 1) % poly.size()];
                if ((a[1] <= R && R < b[1]) || (b[1] <= R && R < a[1]))
                    xs.push_back(a[0] + (b[0] - a[0]) * (R - a[1]) / (b[1] - a[1]));
            }
        std::sort(xs.begin(), xs.end());
        for (size_t k = 0; k + 1 < xs.size(); k += 2) {
            int i0 = std::max(0, int(std::ceil(xf.dx(xs[k]) - 0.5))),
                i1 = std::min(xf.w - 1, int(std::floor(xf.dx(xs[k + 1]) + 0.5)));
            for (int i = i0; i <= i1; ++i) r.dot(i, j, Ink::part);
        }
    }
}

// The marks of the frame that do not depend on the moves drawn so far.
void draw_frame_marks(const GraphView& g, const ViewXf& xf, bool lathe, DotRaster& r) {
    const Toolpath& p = *g.path;
    int h, v;
    plane_axes(g.plane, h, v);
    if (lathe && g.plane == PathPlane::zx) {
        r.phase = 0;
        fill_part(g, xf, r);
        if (g.chuck)  // the jaws and the chuck's body, outlined (and their mirror image)
            for (const auto& poly : *g.chuck)
                for (size_t k = 0; k < poly.size(); ++k)
                    for (double ys : {1.0, -1.0})
                        if (ys > 0 || g.mirror) {
                            const auto &a = poly[k], &b = poly[(k + 1) % poly.size()];
                            draw_line(r, xf, a[0], ys * a[1], b[0], ys * b[1], Ink::stock);
                        }
        draw_line(r, xf, xf.wx(-1), 0, xf.wx(xf.w), 0, Ink::axis, kDashDot);  // the spindle axis
        draw_stock(g, xf, r);
    }
    if (p.has_extremes()) {
        // EM-/EM+ frame: each side where the program gave both values.
        const Axes &lo = p.extremes_lo(), &hi = p.extremes_hi();
        uint16_t both = p.extremes_mask_lo() & p.extremes_mask_hi();
        if ((both >> h & 1) && (both >> v & 1)) {
            double x0 = lo[size_t(h)], x1 = hi[size_t(h)], y0 = lo[size_t(v)], y1 = hi[size_t(v)];
            draw_line(r, xf, x0, y0, x1, y0, Ink::extremes, kDotted);
            draw_line(r, xf, x1, y0, x1, y1, Ink::extremes, kDotted);
            draw_line(r, xf, x1, y1, x0, y1, Ink::extremes, kDotted);
            draw_line(r, xf, x0, y1, x0, y0, Ink::extremes, kDotted);
        }
    }
}

// 150-158: the move was refused at the travel limit of an axis (pupitre-iso(5), DECISIONS:
// the X travel error is 150); it is drawn as the travel highlight, not as an alarm.
bool travel_error(int code) {
    return code >= 150 && code <= 158;
}

size_t moves_shown(const GraphView& g) {
    return std::min(g.upto, g.path ? g.path->size() : size_t(0));
}

bool mirrored(const GraphView& g) {
    return g.mirror && g.path && g.path->machine().lathe && g.plane == PathPlane::zx;
}

// The moves' raster for this frame: from the cache when it still fits, drawing
// only what was added; else drawn whole (and cached).
const DotRaster& moves_raster(const GraphView& g, const ViewXf& xf, int cols, int rows,
                              DotRaster& local) {
    const Toolpath& p = *g.path;
    size_t n = moves_shown(g);
    bool mir = mirrored(g);
    GraphCache* c = g.cache;
    if (c && c->valid && c->path == &p && c->generation == p.generation() && c->xf == xf &&
        c->plane == g.plane && c->mirror == mir && c->errors == p.errors().size() &&
        c->drawn <= n && c->raster.cols() == cols && c->raster.rows() == rows) {
        draw_moves(p, g.plane, xf, mir, c->drawn, n, c->raster);
        c->drawn = n;
        return c->raster;
    }
    DotRaster& r = c ? c->raster : local;
    r.reset(cols, rows);
    draw_moves(p, g.plane, xf, mir, 0, n, r);
    if (c) {
        c->xf = xf;
        c->plane = g.plane;
        c->path = &p;
        c->generation = p.generation();
        c->drawn = n;
        c->errors = p.errors().size();
        c->mirror = mir;
        c->valid = true;
        c->full_draws++;
    }
    return r;
}

// Puts a marker in the cell of world point (x, y), if it is in the area.
void marker(Canvas& c, const Rect& area, const ViewXf& xf, double x, double y, char32_t ch,
            char ascii, Style st, bool keep_dots = false) {
    double dx = xf.dx(x), dy = xf.dy(y);
    if (!(dx > -0.5 && dy > -0.5 && dx < xf.w - 0.5 && dy < xf.h - 0.5)) return;
    int col = area.x + int(std::floor(dx + 0.5)) / 2, row = area.y + int(std::floor(dy + 0.5)) / 4;
    if (keep_dots && c.at(col, row).ch != U' ') {
        c.style(Rect{col, row, 1, 1}, st);
        return;
    }
    c.put(col, row, c.ascii() ? char32_t(ascii) : ch, st);
}

std::string fmt_mm(double v) {
    return fmt_len(v);
}

std::string axis_label(int axis, bool diam, bool ascii) {
    return std::string(1, kAxisNames[size_t(axis)]) + (diam && !ascii ? "ø" : "");
}

// World vertical value as the OP page shows it (lathe X as a diameter).
double shown(const Toolpath& p, int axis, double v) {
    return axis == X && p.machine().lathe && p.x_diameter() ? 2 * v : v;
}

// "├────┤ 10 mm": a bar of a round length about eight cells long.
std::string scale_bar(const ViewXf& xf, bool ascii) {
    double per_col = 2 * xf.scale;
    double len = nice_length(8 * per_col);
    int n = std::max(2, int(std::lround(len / per_col)));
    std::string s = ascii ? "|" : "├";
    for (int i = 0; i < n - 2; ++i) s += ascii ? "-" : "─";
    s += ascii ? "|" : "┤";
    char buf[32];
    std::snprintf(buf, sizeof buf, " %g mm", len);
    return s + buf;
}

void info_lines(const GraphView& g, const ViewXf& xf, Canvas& c, const Rect& r) {
    const Toolpath& p = *g.path;
    int h, v;
    plane_axes(g.plane, h, v);
    bool lathe = p.machine().lathe;
    int y1 = r.y + r.h - 2, y2 = r.y + r.h - 1;
    int x = r.x + 1;
    // Columns left on the line (Canvas::text reads a negative width as "to the edge").
    auto room = [&] { return std::max(0, r.x + r.w - x); };
    x += c.text(x, y1, scale_bar(xf, c.ascii()), Style::dim, room());
    double px = g.has_cursor ? g.cur_x : xf.cx, py = g.has_cursor ? g.cur_y : xf.cy;
    // TRANSLATORS: GRAPH page, before the coordinates of the cursor or of the
    // centre of the drawing.
    std::string cur = "   " + std::string(g.has_cursor ? tr("cursor") : tr("centre")) + " " +
                      axis_label(h, false, c.ascii()) + " " + fmt_mm(shown(p, h, px)) + "  " +
                      axis_label(v, lathe && v == X && p.x_diameter(), c.ascii()) + " " +
                      fmt_mm(shown(p, v, py));
    // TRANSLATORS: GRAPH page during an exercise, instead of the cursor's coordinates.
    if (g.no_readout) cur = "   " + std::string(tr("no coordinates during an exercise"));
    x += c.text(x, y1, cur, Style::normal, room());
    if (p.has_extremes()) {
        std::string em = "   EM";
        for (int a = X; a <= Z; ++a) {
            bool l = p.extremes_mask_lo() >> a & 1, hi = p.extremes_mask_hi() >> a & 1;
            if (!l && !hi) continue;
            em += std::string(" ") + kAxisNames[size_t(a)] +
                  (l ? fmt_mm(shown(p, a, p.extremes_lo()[size_t(a)])) : "") + "/" +
                  (hi ? fmt_mm(shown(p, a, p.extremes_hi()[size_t(a)])) : "");
        }
        c.text(x, y1, em, Style::dim, room());
    }
    // Extents of the program, then what needs the operator's eye.
    x = r.x + 1;
    const PathBox& b = p.bounds();
    for (int a = X; a <= Z && !b.empty(); ++a) {
        if (!p.machine().has(a)) continue;
        bool d = lathe && a == X && p.x_diameter();
        std::string e = axis_label(a, d, c.ascii()) + " " + fmt_mm(shown(p, a, b.lo[a])) + "/" +
                        fmt_mm(shown(p, a, b.hi[a])) + "  ";
        x += c.text(x, y2, e, Style::value, room());
    }
    if (p.travel_moves()) {
        std::string t = strf(tr("%zu beyond travel"), size_t(p.travel_moves())) + "  ";
        x += c.text(x, y2, t, Style::warn, room());
    }
    for (const PathError& e : p.errors()) {
        std::string t = strf(tr("error %d"), e.code) +
                        (e.loc.n >= 0 ? " N" + std::to_string(e.loc.n) : "") + " " +
                        strf(tr("line %d"), e.loc.line) + "  ";
        x += c.text(x, y2, t, travel_error(e.code) ? Style::warn : Style::alarm, room());
    }
}

// The first n columns of UTF-8 text (pupitre writes no wide characters).
std::string cut_columns(const std::string& s, int n) {
    size_t i = 0;
    for (int col = 0; i < s.size(); ++i) {
        bool lead = (static_cast<unsigned char>(s[i]) & 0xc0) != 0x80;
        if (lead && col++ == n) break;
    }
    return s.substr(0, i);
}

std::string title_of(const GraphView& g) {
    std::string t = "GRAPH  " + std::string(plane_name(g.plane));
    if (g.path && g.path->program >= 0) t += "  %" + std::to_string(g.path->program);
    if (g.path && !g.path->title.empty()) t += "  " + g.path->title;
    return t;
}

}  // namespace

void draw_moves(const Toolpath& p, PathPlane plane, const ViewXf& xf, bool mirror, size_t from,
                size_t to, DotRaster& r) {
    int h, v;
    plane_axes(plane, h, v);
    to = std::min(to, p.size());
    if (from >= to) return;
    // The hot loop of a frame: each end point is transformed once and carried
    // as the next move's start; a division-free transform.
    const double k = 1 / xf.scale, ox = (xf.w - 1) * 0.5 - xf.cx * k,
                 oy = (xf.h - 1) * 0.5 + xf.cy * k;
    const double* s = p.from(from);
    double sx = s[h] * k + ox, sy = oy - s[v] * k, my = oy + s[v] * k;
    for (size_t i = from; i < to; ++i) {
        const PathMove& mv = p[i];
        double ex = mv.p[h] * k + ox, ey = oy - mv.p[v] * k, mey = oy + mv.p[v] * k;
        Ink ink = ink_of(mv);
        uint16_t dash = line_pattern(mv);
        bool mir = mirror && mv.kind != PathKind::rapid;
        // An arc smaller than a dot is its chord: no trigonometry for the
        // thousands of fillets of a zoomed-out frame.
        bool arc = mv.arc != PathMove::kNoArc && (std::fabs(ex - sx) + std::fabs(ey - sy) > 1.0 ||
                                                  std::fabs(p.arcs()[mv.arc].sweep) > 180);
        if (arc) {
            draw_path_arc(p, i, h, v, false, xf, r, ink, dash);
            if (mir) draw_path_arc(p, i, h, v, true, xf, r, Ink::mirror, dash);
        } else {
            r.line(sx, sy, ex, ey, ink, dash);
            if (mir) r.line(sx, my, ex, mey, Ink::mirror, dash);
        }
        sx = ex;
        sy = ey;
        my = mey;
    }
}

Rect graph_area(const Rect& page) {
    return Rect{page.x, page.y + 1, page.w, std::max(1, page.h - 3)};
}

void graph_extent(const GraphView& g, double& x0, double& y0, double& x1, double& y1) {
    x0 = y0 = 0;
    x1 = y1 = 0;
    if (!g.path) return;
    // The part, not the trip from the tool-change position (the plot's rule).
    PathFit f = fit_box(*g.path, g.plane, mirrored(g), false);
    x0 = f.x0, y0 = f.y0, x1 = f.x1, y1 = f.y1;
    // The workshop's part, whole, with the path.
    if (shows_block(g)) {
        const workshop::Box3& b = g.block->stock();
        const bool none = g.path->empty();
        x0 = std::min(none ? 1e300 : x0, b.lo[0] + g.block_dx);
        y0 = std::min(none ? 1e300 : y0, b.lo[1] + g.block_dy);
        x1 = std::max(none ? -1e300 : x1, b.hi[0] + g.block_dx);
        y1 = std::max(none ? -1e300 : y1, b.hi[1] + g.block_dy);
        return;
    }
    if (!g.part || g.part->empty() || g.plane != PathPlane::zx || !g.path->machine().lathe) return;
    bool none = g.path->empty();
    for (const auto& poly : *g.part)
        for (const auto& p : poly) {
            if (none) x0 = x1 = p[0], y0 = y1 = p[1], none = false;
            x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
            y0 = std::min(y0, mirrored(g) ? -p[1] : p[1]), y1 = std::max(y1, p[1]);
        }
}

std::string graph_fit_words(const GraphView& g) {
    if (!g.path) return tr("no toolpath yet");
    PathFit f = fit_box(*g.path, g.plane, mirrored(g), false);
    count_outside(*g.path, g.plane, moves_shown(g), f);
    return fit_words(*g.path, f);
}

ViewXf graph_window(const GraphView& g, const Rect& page) {
    Rect a = graph_area(page);
    if (g.fit || !(g.scale > 0)) {
        double x0, y0, x1, y1;
        graph_extent(g, x0, y0, x1, y1);
        return fit_view(x0, y0, x1, y1, a.w * 2, a.h * 4, 3);
    }
    ViewXf v;
    v.cx = g.cx;
    v.cy = g.cy;
    v.scale = std::clamp(g.scale, kMinScale, kMaxScale);
    v.w = a.w * 2;
    v.h = a.h * 4;
    return v;
}

void page_graph(const GraphView& g, const MachineProfile& m, Canvas& c, const Rect& r) {
    bool part = (g.part && !g.part->empty() && m.lathe) || shows_block(g);
    if (!g.path || (g.path->empty() && g.path->errors().empty() && !part)) {
        c.rule(r.y, title_of(g));
        c.text(r.x + 2, r.y + 2,
               tr("No toolpath yet: run a program in AUTO, SEQ, DRY RUN or TEST."), Style::dim,
               r.w - 4);
        return;
    }
    const Toolpath& p = *g.path;
    char buf[96];
    double t = g.seconds >= 0 ? g.seconds : p.seconds();
    const size_t made = p.moves_made(moves_shown(g));
    // TRANSLATORS: the GRAPH page's title: the moves drawn, then the cycle time h:mm:ss.
    std::snprintf(buf, sizeof buf, trn(" %zu move  %s ", " %zu moves  %s ", made), made,
                  clock_text(t).c_str());
    // The title gives way to the count and the time on a narrow page.
    std::string title = title_of(g);
    int room = r.w - columns(buf) - 6;
    if (columns(title) > room) title = cut_columns(title, room);
    c.rule(r.y, title);
    c.text_right(r.x, r.y, r.w - 1, buf, Style::dim);
    Rect a = graph_area(r);
    ViewXf xf = graph_window(g, r);
    DotRaster local;
    const DotRaster& moves = moves_raster(g, xf, a.w, a.h, local);
    // The frame's own marks go on a copy, under the moves (weaker inks).
    DotRaster frame = moves;
    draw_frame_marks(g, xf, m.lathe, frame);
    if (shows_block(g)) {
        block_outline(g, xf, frame);
        shade_block(g, xf, c, a);  // under the dots: to_canvas leaves empty cells
    }
    Glyphs gl = c.ascii() ? Glyphs::ascii : g.glyphs;
    frame.to_canvas(c, a, gl, kStyles);
    int h, v;
    plane_axes(g.plane, h, v);
    for (const PathError& e : p.errors()) {
        const double* at = e.moves == 0 ? p.start() : p[std::min(e.moves, p.size()) - 1].p;
        marker(c, a, xf, at[h], at[v], U'✕', 'x',
               travel_error(e.code) ? Style::warn : Style::alarm);
    }
    if (g.tool)
        marker(c, a, xf, (*g.tool)[size_t(h)], (*g.tool)[size_t(v)], U'◆', '@', Style::select);
    if (g.has_cursor) marker(c, a, xf, g.cur_x, g.cur_y, U'+', '+', Style::select, true);
    info_lines(g, xf, c, r);
}

GraphView graph_zoom(const GraphView& g, const Rect& page, double factor) {
    ViewXf xf = graph_window(g, page);
    double px = g.has_cursor ? g.cur_x : xf.cx, py = g.has_cursor ? g.cur_y : xf.cy;
    ViewXf z = zoom_about(xf, px, py, factor);
    GraphView n = g;
    n.fit = false;
    n.cx = z.cx;
    n.cy = z.cy;
    n.scale = z.scale;
    return n;
}

GraphView graph_pan(const GraphView& g, const Rect& page, double fx, double fy) {
    ViewXf xf = graph_window(g, page);
    ViewXf p = pan_view(xf, fx, fy);
    GraphView n = g;
    n.fit = false;
    n.cx = p.cx;
    n.cy = p.cy;
    n.scale = p.scale;
    // The cursor keeps its place in the window.
    n.cur_x += p.cx - xf.cx;
    n.cur_y += p.cy - xf.cy;
    return n;
}

GraphView graph_fit(const GraphView& g) {
    GraphView n = g;
    n.fit = true;
    return n;
}

GraphView graph_next_plane(const GraphView& g, const MachineProfile& m) {
    GraphView n = g;
    if (m.lathe)
        n.plane = PathPlane::zx;
    else
        n.plane = g.plane == PathPlane::xy   ? PathPlane::xz
                  : g.plane == PathPlane::xz ? PathPlane::yz
                                             : PathPlane::xy;
    n.fit = true;
    n.has_cursor = false;
    return n;
}

GraphView graph_move_cursor(const GraphView& g, const Rect& page, int dcols, int drows) {
    ViewXf xf = graph_window(g, page);
    GraphView n = g;
    if (!n.has_cursor) {
        n.has_cursor = true;
        n.cur_x = xf.cx;
        n.cur_y = xf.cy;
    }
    n.cur_x += dcols * 2 * xf.scale;
    n.cur_y -= drows * 4 * xf.scale;
    // Off the window: the window follows by half its size.
    double dx = xf.dx(n.cur_x), dy = xf.dy(n.cur_y);
    double fx = dx < 0          ? -0.5
                : dx > xf.w - 1 ? 0.5
                                : 0,
           fy = dy < 0          ? 0.5
                : dy > xf.h - 1 ? -0.5
                                : 0;
    if (fx != 0 || fy != 0) {
        ViewXf p = pan_view(xf, fx, fy);
        n.fit = false;
        n.cx = p.cx;
        n.cy = p.cy;
        n.scale = p.scale;
    }
    return n;
}

}  // namespace pupitre::pages
