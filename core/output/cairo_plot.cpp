// The plot's scene through Cairo (see cairo_plot.hpp): the page is drawn in
// paper millimetres (one scale to pixels or points), the toolpath's layers
// clipped to the frame, then the marks.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/cairo_plot.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/geometry/geometry.hpp"

namespace pupitre {

namespace {

using ::pupitre::geometry::kPi;
// Segments stroked at once: Cairo's stroker slows down as one path gathers
// edges, and memory stays bounded for a million-move program.
constexpr int kBatch = 256;

void set_colour(cairo_t* cr, Rgb c, double alpha = 1) {
    cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

void set_layer_pen(cairo_t* cr, Layer l) {
    const LayerStyle& st = layer_style(l);
    set_colour(cr, st.colour, st.opacity);
    cairo_set_line_width(cr, st.width);
    int n = 0;
    while (n < int(st.dash.size()) && st.dash[size_t(n)] > 0) ++n;
    cairo_set_dash(cr, st.dash.data(), n, 0);
}

// Appends the moves of one layer to the path, mirrored (y -> -y) when `flip`.
class MovePen {
  public:
    MovePen(cairo_t* cr, const Scene& sc, bool flip)
        : cr_(cr), sc_(sc), p_(*sc.path), ys_(flip ? -1 : 1) {}
    void draw(Layer l);

  private:
    double x(const double* q) const { return sc_.px(q[sc_.h]); }
    double y(const double* q) const { return sc_.py(ys_ * q[sc_.v]); }
    void arc(size_t i);

    cairo_t* cr_;
    const Scene& sc_;
    const Toolpath& p_;
    double ys_;
};

void MovePen::draw(Layer l) {
    size_t last = 0;
    bool down = false;  // the pen is down at the end of move `last`
    int segs = 0;
    for (size_t i = 0; i < p_.size(); ++i) {
        const PathMove& mv = p_[i];
        if (move_layer(mv) != l) continue;
        const double* s = p_.from(i);
        bool flat =
            mv.arc == PathMove::kNoArc && s[sc_.h] == mv.p[sc_.h] && s[sc_.v] == mv.p[sc_.v];
        if (flat) {
            if (down && last + 1 == i) last = i;  // a plunge across the plane: the pen stays down
            continue;
        }
        if (!down || last + 1 != i || segs >= kBatch) {
            if (segs >= kBatch) {
                cairo_stroke(cr_);
                segs = 0;
            }
            cairo_move_to(cr_, x(s), y(s));
        }
        last = i;
        down = true;
        if (mv.arc != PathMove::kNoArc)
            arc(i);
        else
            cairo_line_to(cr_, x(mv.p), y(mv.p));
        ++segs;
    }
    cairo_stroke(cr_);
}

// An arc of the drawing's plane is a Cairo arc; a spiral or an arc seen
// edge-on, chords within 0.02 mm of paper.
void MovePen::arc(size_t i) {
    const PathMove& mv = p_[i];
    const PathArc& a = p_.arcs()[mv.arc];
    const double* s = p_.from(i);
    double r0, r1;
    arc_radii(p_, i, r0, r1);
    double sweep = double(a.sweep) * kPi / 180;
    const int h = sc_.h, v = sc_.v;
    bool in_plane = (a.a0 == h && a.a1 == v) || (a.a0 == v && a.a1 == h);
    if (in_plane && std::fabs(r0 - r1) <= 1e-4 + 1e-6 * r1) {
        bool swapped = a.a0 == v;
        double c[3] = {0, 0, 0};
        c[h] = swapped ? a.c1 : a.c0;
        c[v] = swapped ? a.c0 : a.c1;
        double cx = x(c), cy = y(c);
        double a0 = std::atan2(y(s) - cy, x(s) - cx);
        // Counter-clockwise seen with y up is clockwise on the page (y down).
        double page_sweep = -(swapped ? -sweep : sweep) * ys_;
        if (page_sweep > 0)
            cairo_arc(cr_, cx, cy, r1 * sc_.k, a0, a0 + page_sweep);
        else
            cairo_arc_negative(cr_, cx, cy, r1 * sc_.k, a0, a0 + page_sweep);
        return;
    }
    double r = std::max(r0, r1) * sc_.k, tol = 0.02;
    int n = r > tol ? int(std::ceil(std::fabs(sweep) / (2 * std::acos(1 - tol / r)))) : 1;
    n = std::clamp(n, 1, 4096);
    for (int k = 1; k <= n; ++k) {
        double q[3];
        arc_point(p_, i, double(k) / n, q);
        cairo_line_to(cr_, x(q), y(q));
    }
}

void stock_and_frames(cairo_t* cr, const Scene& sc) {
    const Toolpath& p = *sc.path;
    if (sc.present[size_t(Layer::part)]) {
        const LayerStyle& st = layer_style(Layer::part);
        cairo_save(cr);
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
        for (double ys : {1.0, -1.0}) {
            if (ys < 0 && !(sc.lathe && sc.opt.mirror)) continue;  // a mill's block: once
            for (const auto& poly : p.part()) {
                for (size_t k = 0; k < poly.size(); ++k)
                    (k ? cairo_line_to : cairo_move_to)(cr, sc.px(poly[k][0]),
                                                        sc.py(ys * poly[k][1]));
                cairo_close_path(cr);
            }
        }
        cairo_set_source_rgba(cr, st.colour.r / 255.0, st.colour.g / 255.0, st.colour.b / 255.0,
                              0.45);
        cairo_fill_preserve(cr);
        set_layer_pen(cr, Layer::part);
        cairo_stroke(cr);
        cairo_restore(cr);
    }
    if (sc.lathe) {
        set_layer_pen(cr, Layer::axis);
        cairo_move_to(cr, sc.px(sc.wx0), sc.py(0));
        cairo_line_to(cr, sc.px(sc.wx1), sc.py(0));
        cairo_stroke(cr);
    }
    if (sc.lathe && !p.stock().empty()) {
        set_layer_pen(cr, Layer::stock);
        for (const auto& poly : p.stock())
            for (double ys : {1.0, -1.0}) {
                if (ys < 0 && !sc.opt.mirror) continue;
                for (size_t k = 0; k < poly.size(); ++k)
                    (k ? cairo_line_to : cairo_move_to)(cr, sc.px(poly[k][0]),
                                                        sc.py(ys * poly[k][1]));
            }
        cairo_stroke(cr);
    }
    if (sc.present[size_t(Layer::extremes)]) {
        set_layer_pen(cr, Layer::extremes);
        double x0 = sc.px(p.extremes_lo()[size_t(sc.h)]), x1 = sc.px(p.extremes_hi()[size_t(sc.h)]);
        double y0 = sc.py(p.extremes_hi()[size_t(sc.v)]), y1 = sc.py(p.extremes_lo()[size_t(sc.v)]);
        cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
        cairo_stroke(cr);
    }
}

void profile(cairo_t* cr, const Scene& sc) {
    if (!sc.present[size_t(Layer::profile)]) return;
    set_layer_pen(cr, Layer::profile);
    for (const ProfileElem& e : sc.path->profile_elems()) {
        if (!profile_in_plane(e, sc.h, sc.v)) continue;
        double x, y;
        profile_point(e, 0, sc.h, x, y);
        double sx = sc.px(x), sy = sc.py(y);
        cairo_move_to(cr, sx, sy);
        if (!e.arc) {
            profile_point(e, 1, sc.h, x, y);
            cairo_line_to(cr, sc.px(x), sc.py(y));
            continue;
        }
        double c0 = e.a0 == sc.h ? e.c[0] : e.c[1], c1 = e.a0 == sc.h ? e.c[1] : e.c[0];
        double cx = sc.px(c0), cy = sc.py(c1), a0 = std::atan2(sy - cy, sx - cx);
        double page_sweep = -profile_view_sweep(e, sc.h) * kPi / 180;
        double r = std::hypot(sx - cx, sy - cy);
        if (page_sweep > 0)
            cairo_arc(cr, cx, cy, r, a0, a0 + page_sweep);
        else
            cairo_arc_negative(cr, cx, cy, r, a0, a0 + page_sweep);
    }
    cairo_stroke(cr);
}

// The toolpath's layers, clipped to the frame.
void layers(cairo_t* cr, const Scene& sc) {
    cairo_save(cr);
    cairo_rectangle(cr, sc.fx, sc.fy, sc.fw, sc.fh);
    cairo_clip(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    stock_and_frames(cr, sc);
    profile(cr, sc);
    static constexpr Layer kMoves[] = {Layer::rapid, Layer::feed, Layer::comp, Layer::travel,
                                       Layer::gouge};
    for (Layer l : kMoves) {
        if (!sc.present[size_t(l)]) continue;
        set_layer_pen(cr, l);
        MovePen(cr, sc, false).draw(l);
    }
    const Toolpath& p = *sc.path;
    set_layer_pen(cr, Layer::gouge);
    for (const PathError& e : p.errors()) {
        const double* at = e.moves == 0 ? p.start() : p[std::min(e.moves, p.size()) - 1].p;
        cairo_new_sub_path(cr);
        cairo_arc(cr, sc.px(at[sc.h]), sc.py(at[sc.v]), 1.2, 0, 2 * kPi);
        cairo_stroke(cr);
    }
    if (sc.mirror) {
        // The mirror image as one faded group, as the SVG's opacity does it.
        cairo_push_group(cr);
        for (Layer l : kMoves) {
            if (l == Layer::rapid || !sc.present[size_t(l)]) continue;
            set_layer_pen(cr, l);
            MovePen(cr, sc, true).draw(l);
        }
        cairo_pop_group_to_source(cr);
        cairo_paint_with_alpha(cr, layer_style(Layer::mirror).opacity);
    }
    cairo_restore(cr);
}

void mark(cairo_t* cr, const Mark& m) {
    const auto& q = m.pts;
    switch (m.kind) {
        case Mark::line:
            if (m.layer >= 0) {
                set_layer_pen(cr, Layer(m.layer));
            } else {
                set_colour(cr, m.stroke);
                cairo_set_line_width(cr, m.width);
                cairo_set_dash(cr, nullptr, 0, 0);
            }
            cairo_move_to(cr, q[0], q[1]);
            cairo_line_to(cr, q[2], q[3]);
            cairo_stroke(cr);
            return;
        case Mark::rect:
        case Mark::polygon:
            if (m.kind == Mark::rect)
                cairo_rectangle(cr, q[0], q[1], q[2], q[3]);
            else
                for (size_t k = 0; k + 1 < q.size(); k += 2) cairo_line_to(cr, q[k], q[k + 1]);
            cairo_close_path(cr);
            if (m.has_fill) {
                set_colour(cr, m.fill);
                cairo_fill_preserve(cr);
            }
            if (m.has_stroke) {
                set_colour(cr, m.stroke);
                cairo_set_line_width(cr, m.width);
                cairo_set_dash(cr, nullptr, 0, 0);
                cairo_stroke(cr);
            }
            cairo_new_path(cr);
            return;
        case Mark::text: {
            cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                                   m.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
            cairo_set_font_size(cr, m.size);
            double x = q[0];
            if (m.right) {
                cairo_text_extents_t te;
                cairo_text_extents(cr, m.words.c_str(), &te);
                x -= te.x_advance;
            }
            set_colour(cr, m.fill);
            cairo_move_to(cr, x, q[1]);
            cairo_show_text(cr, m.words.c_str());
            cairo_new_path(cr);
            return;
        }
    }
}

// The page: white paper, the layers, then the marks; `scale` device units per mm.
bool draw(cairo_surface_t* surface, const Scene& sc, double scale) {
    cairo_t* cr = cairo_create(surface);
    cairo_scale(cr, scale, scale);
    // Text laid out as the SVG's: no hinting of the glyphs' advances.
    cairo_font_options_t* fo = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    layers(cr, sc);
    for (const Mark& m : sc.marks) mark(cr, m);
    cairo_show_page(cr);
    bool ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    return ok;
}

cairo_status_t to_file(void* closure, const unsigned char* data, unsigned int length) {
    auto* f = static_cast<std::FILE*>(closure);
    return std::fwrite(data, 1, length, f) == length ? CAIRO_STATUS_SUCCESS
                                                     : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace

bool write_png(const Scene& sc, int width, std::FILE* out) {
    int w = std::clamp(width, 64, 8000);
    double scale = w / sc.page_w;
    int h = std::clamp(int(std::ceil(sc.page_h * scale)), 16, 32000);
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    bool ok = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS && draw(s, sc, scale);
    ok = ok && cairo_surface_write_to_png_stream(s, to_file, out) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(s);
    return ok && std::fflush(out) == 0;
}

bool write_pdf(const Scene& sc, std::FILE* out) {
    const double pt = 72 / 25.4;  // points per mm: the drawing prints at its ratio
    cairo_surface_t* s =
        cairo_pdf_surface_create_for_stream(to_file, out, sc.page_w * pt, sc.page_h * pt);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, sc.title.c_str());
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, sc.opt.generator.c_str());
    bool ok = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS && draw(s, sc, pt);
    cairo_surface_finish(s);
    ok = ok && cairo_surface_status(s) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(s);
    return ok && std::fflush(out) == 0;
}

namespace {

// One page of the text: the title and "page/pages" above, the lines below.
void text_page(cairo_t* cr, const std::string& title, const std::vector<std::string>& lines,
               size_t from, size_t to, int page, int pages) {
    const double w = 842, margin = 36, size = 8.5, lead = size * 1.4;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 11);
    cairo_move_to(cr, margin, margin + 11);
    cairo_show_text(cr, title.c_str());
    const std::string n = std::to_string(page) + "/" + std::to_string(pages);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, n.c_str(), &ext);
    cairo_move_to(cr, w - margin - ext.x_advance, margin + 11);
    cairo_show_text(cr, n.c_str());
    cairo_select_font_face(cr, "monospace", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    double y = margin + 11 + 2 * lead;
    for (size_t i = from; i < to; ++i, y += lead) {
        cairo_move_to(cr, margin, y);
        cairo_show_text(cr, lines[i].c_str());
    }
    cairo_show_page(cr);
}

}  // namespace

bool write_text_pdf(const std::string& title, const std::vector<std::string>& lines,
                    std::FILE* out) {
    const double w = 842, h = 595;  // A4 landscape, points
    cairo_surface_t* s = cairo_pdf_surface_create_for_stream(to_file, out, w, h);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, title.c_str());
    cairo_t* cr = cairo_create(s);
    const size_t per_page = 36;
    const int pages = std::max(1, int((lines.size() + per_page - 1) / per_page));
    for (int p = 0; p < pages; ++p)
        text_page(cr, title, lines, size_t(p) * per_page,
                  std::min(lines.size(), size_t(p + 1) * per_page), p + 1, pages);
    bool ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    cairo_surface_finish(s);
    ok = ok && cairo_surface_status(s) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(s);
    return ok && std::fflush(out) == 0;
}

}  // namespace pupitre
