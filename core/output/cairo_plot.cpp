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
#include "core/output/part_sheet.hpp"

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

// --- the part on paper (part_sheet.hpp) ---

namespace {

constexpr double kMargin = 12, kPicX = 12, kPicY = 30, kColumn = 208;

void sheet_text(cairo_t* cr, double x, double y, double size, const std::string& s,
                bool bold = false, double grey = 0) {
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_set_source_rgb(cr, grey, grey, grey);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr);
}

// "2:1", "1:2.5": paper millimetres to the part's.
std::string ratio_text(double r) {
    char buf[32];
    auto trim = [](double v) {
        char b[16];
        std::snprintf(b, sizeof b, "%.2f", v);
        std::string t = b;
        while (t.back() == '0') t.pop_back();
        if (t.back() == '.') t.pop_back();
        return t;
    };
    std::snprintf(buf, sizeof buf, "%s",
                  r >= 1 ? (trim(r) + ":1").c_str() : ("1:" + trim(1 / r)).c_str());
    return buf;
}

// The picture fitted into its box; `k` paper mm per pixel, the box's
// corner at (x0, y0).
void sheet_picture(cairo_t* cr, const PartSheet& s, double& k, double& x0, double& y0) {
    k = std::min(kSheetPictureW / s.w, kSheetPictureH / s.h);
    x0 = kPicX + (kSheetPictureW - s.w * k) / 2, y0 = kPicY + (kSheetPictureH - s.h * k) / 2;
    cairo_surface_t* img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, s.w, s.h);
    cairo_surface_flush(img);
    unsigned char* data = cairo_image_surface_get_data(img);
    const int stride = cairo_image_surface_get_stride(img);
    for (int y = 0; y < s.h; ++y) {
        auto* row = reinterpret_cast<uint32_t*>(data + size_t(y) * size_t(stride));
        for (int x = 0; x < s.w; ++x) {
            const uint32_t p = s.pixels[size_t(y) * size_t(s.w) + size_t(x)];
            row[x] = (p & 0xff) << 16 | (p & 0xff00) | ((p >> 16) & 0xff);
        }
    }
    cairo_surface_mark_dirty(img);
    cairo_save(cr);
    cairo_translate(cr, x0, y0);
    cairo_scale(cr, k, k);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_rectangle(cr, 0, 0, s.w, s.h);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 0.25);
    cairo_rectangle(cr, x0, y0, s.w * k, s.h * k);
    cairo_stroke(cr);
}

// Each label in the column at the right, a leader from the point read.
void sheet_labels(cairo_t* cr, const PartSheet& s, double k, double x0, double y0) {
    double y = kPicY + 4;
    for (const SheetLabel& l : s.labels) {
        const bool seen = std::isfinite(l.x) && std::isfinite(l.y) && l.x >= 0 && l.y >= 0 &&
                          l.x <= s.w && l.y <= s.h;
        if (seen) {
            cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
            cairo_set_line_width(cr, 0.25);
            cairo_arc(cr, x0 + l.x * k, y0 + l.y * k, 0.8, 0, 2 * kPi);
            cairo_fill(cr);
            cairo_move_to(cr, x0 + l.x * k, y0 + l.y * k);
            cairo_line_to(cr, kColumn - 1, y - 1.2);
            cairo_stroke(cr);
        }
        set_colour(cr, l.colour);
        cairo_rectangle(cr, kColumn, y - 2.8, 3, 3);
        cairo_fill(cr);
        // "SPEC: READING": the request on its line, the reading under it.
        const size_t colon = l.text.find(": ");
        sheet_text(cr, kColumn + 4.5, y, 3, l.text.substr(0, colon), true);
        if (colon != std::string::npos)
            sheet_text(cr, kColumn + 4.5, y + 4, 2.8, l.text.substr(colon + 2));
        y += 11;
    }
}

void sheet_marks(cairo_t* cr, const PartSheet& s, double k, double x0, double y0) {
    for (const SheetLabel& m : s.marks) {
        cairo_set_font_size(cr, 3);
        cairo_text_extents_t te;
        cairo_text_extents(cr, m.text.c_str(), &te);
        sheet_text(cr, x0 + m.x * k - te.x_advance / 2, y0 + m.y * k - 1.2, 3, m.text);
    }
}

// The colour scale and the picture's scale under it.
void sheet_scales(cairo_t* cr, const PartSheet& s, double k) {
    const double bx = kMargin, by = 176, bw = 130, bh = 5;
    sheet_text(cr, bx, by - 1.5, 3, s.scale_title);
    const size_t n = s.scale.size();
    for (size_t i = 0; i < n; ++i) {
        set_colour(cr, s.scale[i]);
        cairo_rectangle(cr, bx + bw * double(i) / n, by, bw / n + 0.05, bh);
        cairo_fill(cr);
    }
    for (const auto& [at, text] : s.ticks) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 0.2);
        cairo_move_to(cr, bx + bw * at, by + bh);
        cairo_line_to(cr, bx + bw * at, by + bh + 1.2);
        cairo_stroke(cr);
        cairo_text_extents_t te;
        cairo_set_font_size(cr, 2.6);
        cairo_text_extents(cr, text.c_str(), &te);
        sheet_text(cr, bx + bw * at - te.x_advance / 2, by + bh + 4.2, 2.6, text);
    }
    if (!(s.mm_per_px > 0)) return;
    const double ratio = k / s.mm_per_px;  // paper mm per part mm
    // A round length (1, 2 or 5 times a power of ten) about 40 mm on paper.
    const double target = 40 / ratio, p10 = std::pow(10.0, std::floor(std::log10(target)));
    const double len = target >= 5 * p10 ? 5 * p10 : target >= 2 * p10 ? 2 * p10 : p10;
    const double x = 160, y = by + bh;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, x, y - 1.5, len * ratio, 1.5);
    cairo_fill(cr);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g mm", len);
    sheet_text(cr, x, y + 4.2, 2.8, buf);
    sheet_text(cr, x + len * ratio + 3, y, 2.8, ratio_text(ratio));
}

bool draw_sheet(cairo_surface_t* surface, const PartSheet& s, double scale) {
    cairo_t* cr = cairo_create(surface);
    cairo_scale(cr, scale, scale);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    sheet_text(cr, kMargin, 18, 6, s.title, true);
    sheet_text(cr, kMargin, 25, 3.6, s.subtitle, false, 0.25);
    double k = 1, x0 = kPicX, y0 = kPicY;
    if (s.w > 0 && s.h > 0 && s.pixels.size() == size_t(s.w) * size_t(s.h)) {
        sheet_picture(cr, s, k, x0, y0);
        sheet_labels(cr, s, k, x0, y0);
        sheet_marks(cr, s, k, x0, y0);
        sheet_scales(cr, s, k);
    }
    double y = 195;
    for (const std::string& note : s.notes) {
        sheet_text(cr, kMargin, y, 3, note);
        y += 4.5;
    }
    sheet_text(cr, kSheetW - kMargin - 30, kSheetH - 4, 2.4, s.generator, false, 0.5);
    cairo_show_page(cr);
    const bool ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    return ok;
}

}  // namespace

bool write_part_png(const PartSheet& sheet, int width, std::FILE* out) {
    const int w = std::clamp(width, 200, 8000);
    const double scale = w / kSheetW;
    const int h = int(std::ceil(kSheetH * scale));
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    bool ok = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS && draw_sheet(s, sheet, scale);
    ok = ok && cairo_surface_write_to_png_stream(s, to_file, out) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(s);
    return ok && std::fflush(out) == 0;
}

bool write_part_pdf(const PartSheet& sheet, std::FILE* out) {
    const double pt = 72 / 25.4;
    cairo_surface_t* s =
        cairo_pdf_surface_create_for_stream(to_file, out, kSheetW * pt, kSheetH * pt);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, sheet.title.c_str());
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, sheet.generator.c_str());
    bool ok = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS && draw_sheet(s, sheet, pt);
    cairo_surface_finish(s);
    ok = ok && cairo_surface_status(s) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(s);
    return ok && std::fflush(out) == 0;
}

}  // namespace pupitre
