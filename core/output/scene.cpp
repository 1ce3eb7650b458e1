// The plot's scene (see scene.hpp): the frame fitted to the cutting moves at a
// round scale on paper, and the marks around it laid out once for every back-end.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/i18n.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

namespace {

// The page (paper mm): margins, the narrowest block of text, the widest page,
// the drawing's room in landscape and in portrait (about A4 with the marks).
constexpr double kMargin = 10, kMinContent = 170, kMaxContent = 400;
constexpr double kLandW = 257, kLandH = 165, kPortW = 180, kPortH = 215;
constexpr double kTitle = 4.2, kSub = 2.8, kBody = 2.5, kSmall = 2.2;
constexpr Rgb kInk{0, 0, 0}, kGrey{90, 90, 90}, kLight{200, 200, 200}, kRed{212, 0, 0},
    kWhite{255, 255, 255};

Mark text_mark(Mark::Group g, double x, double y, std::string words, double size, Rgb colour,
               bool bold = false) {
    Mark m;
    m.kind = Mark::text;
    m.group = g;
    m.pts = {x, y};
    m.words = std::move(words);
    m.size = size;
    m.fill = colour;
    m.has_fill = true;
    m.has_stroke = false;
    m.bold = bold;
    return m;
}

Mark line_mark(Mark::Group g, double x0, double y0, double x1, double y1, Rgb colour, double w) {
    Mark m;
    m.kind = Mark::line;
    m.group = g;
    m.pts = {x0, y0, x1, y1};
    m.stroke = colour;
    m.width = w;
    return m;
}

Mark rect_mark(Mark::Group g, double x, double y, double w, double h, Rgb stroke, double width,
               const Rgb* fill) {
    Mark m;
    m.kind = Mark::rect;
    m.group = g;
    m.pts = {x, y, w, h};
    m.stroke = stroke;
    m.width = width;
    m.has_fill = fill != nullptr;
    if (fill) m.fill = *fill;
    return m;
}

std::string hms(double t) {
    return clock_text(t) + " (" + fixed3(t, 399) + " s)";  // as `run` prints it
}

// The ratio on paper: 2 -> "2:1", 0.05 -> "1:20".
std::string ratio_words(double k) {
    char buf[48];
    if (k >= 1)
        std::snprintf(buf, sizeof buf, "%.0f:1", k);
    else
        std::snprintf(buf, sizeof buf, "1:%.0f", 1 / k);
    return buf;
}

// The largest scale of the 1-2-5 series at which the window fits the page.
double paper_scale(double w, double h) {
    double mw = w >= h ? kLandW : kPortW, mh = w >= h ? kLandH : kPortH;
    for (int n = 4; n >= -6; --n)
        for (double m : {5.0, 2.0, 1.0}) {
            double k = m * std::pow(10.0, n);
            if (w * k <= mw && h * k <= mh) return k;
        }
    return 1e-6;
}

void find_layers(Scene& s) {
    const Toolpath& p = *s.path;
    // A layer is in the legend when it leaves ink: not for plunges across the plane.
    for (size_t i = 0; i < p.size(); ++i) {
        const PathMove& mv = p[i];
        const double* a = p.from(i);
        if (mv.arc != PathMove::kNoArc || a[s.h] != mv.p[s.h] || a[s.v] != mv.p[s.v])
            s.present[size_t(move_layer(mv))] = true;
    }
    if (!p.errors().empty()) s.present[size_t(Layer::gouge)] = true;
    // The axis and the mirror are drawn on the lathe, in the legend when in the frame.
    s.present[size_t(Layer::axis)] = s.lathe && s.wy0 <= 0 && s.wy1 >= 0;
    s.present[size_t(Layer::stock)] = s.lathe && !p.stock().empty();
    // The workshop's part: the lathe's half-section, the mill's block from above.
    s.present[size_t(Layer::part)] = (s.lathe || (s.h == X && s.v == Y)) && !p.part().empty();
    uint16_t both = p.extremes_mask_lo() & p.extremes_mask_hi();
    s.present[size_t(Layer::extremes)] = (both >> s.h & 1) && (both >> s.v & 1);
    for (const ProfileElem& e : p.profile_elems())
        if (profile_in_plane(e, s.h, s.v)) s.present[size_t(Layer::profile)] = true;
    s.present[size_t(Layer::mirror)] = s.mirror && !s.fit.mirror_out;
}

// The title's two lines: the program, then the machine and the plane.
std::vector<std::string> title_lines(const Scene& s) {
    const Toolpath& p = *s.path;
    const MachineProfile& m = p.machine();
    std::string prog =
        p.program >= 0 ? "%" + std::to_string(p.program) : std::string(tr("(no program)"));
    if (!p.title.empty()) prog += "  " + p.title;
    // TRANSLATORS: the plot's title: the machine profile's name.
    std::string mach =
        strf(tr("machine %s"), (s.opt.machine.empty() ? m.name : s.opt.machine).c_str());
    // A shipped profile's description is in the catalogue (scripts/lib/extract-pot).
    if (!m.description.empty()) mach += std::string(" (") + tr(m.description.c_str()) + ")";
    // TRANSLATORS: the plot's title: XY, ZX...
    mach += " \u00b7 " + strf(tr("plane %s"), std::string(plane_name(s.opt.plane)).c_str());
    // TRANSLATORS: the end of the plot's title on a lathe.
    if (s.lathe) mach += tr(", X up as a radius (true to shape)");
    return {prog, mach};
}

// The notes under the legend, with their colours: the fit, the numbers, the errors.
std::vector<std::pair<std::string, Rgb>> note_lines(const Scene& s) {
    const Toolpath& p = *s.path;
    const MachineProfile& m = p.machine();
    std::vector<std::pair<std::string, Rgb>> out;
    // TRANSLATORS: a note of the plot; %s is a noun phrase such as "the cutting moves of %300".
    std::string fit = strf(tr("frame fitted to %s"), fit_words(p, s.fit).c_str());
    if (s.fit.outside) fit += tr(", clipped at the frame");
    out.push_back({fit, kGrey});
    // TRANSLATORS: the English says "moves" whatever the number.
    out.push_back(
        {strf(tr("cycle time %s"), hms(s.opt.seconds >= 0 ? s.opt.seconds : p.seconds()).c_str()) +
             " \u00b7 " + strf(trn("%zu moves", "%zu moves", p.moves_made()), p.moves_made()) +
             " \u00b7 " + strf(tr("path %.3f mm"), p.length()),
         kInk});
    // TRANSLATORS: a note of the plot, followed by the extents of each axis (X -10/20  Z 0/50).
    std::string ext = tr("extents");
    const PathBox& b = p.bounds();
    for (int a = X; a <= Z && !b.empty(); ++a) {
        if (!m.has(a)) continue;
        double f = a == X && m.lathe && p.x_diameter() ? 2 : 1;
        ext += std::string("  ") + kAxisNames[size_t(a)] + (f == 2 ? "\u00f8 " : " ") +
               fixed3_zeroed(f * b.lo[a], 0.0005, 47) + "/" +
               fixed3_zeroed(f * b.hi[a], 0.0005, 47);
    }
    // TRANSLATORS: the English says "moves" whatever the number.
    if (p.travel_moves())
        ext += " \u00b7 " +
               strf(trn("%zu moves beyond travel", "%zu moves beyond travel", p.travel_moves()),
                    p.travel_moves());
    out.push_back({ext, kInk});
    for (const PathError& e : p.errors()) {
        if (e.loc.n >= 0)
            out.push_back({strf(tr("error %d line %d N%ld: %s"), e.code, e.loc.line, e.loc.n,
                                e.detail.c_str()),
                           kRed});
        else
            out.push_back(
                {strf(tr("error %d line %d: %s"), e.code, e.loc.line, e.detail.c_str()), kRed});
    }
    return out;
}

// Text cut to `room` mm at `size`, with an ellipsis.
std::string fit_text(const std::string& s, double size, double room, bool bold = false) {
    if (text_ems(s, bold) * size <= room) return s;
    std::string t = s;
    while (!t.empty() && text_ems(t + "\u2026", bold) * size > room) {
        // One character off the end: its continuation bytes, then its first byte.
        while (!t.empty() && (static_cast<unsigned char>(t.back()) & 0xc0) == 0x80) t.pop_back();
        if (!t.empty()) t.pop_back();
    }
    return t + "\u2026";
}

// An arrow from (x0, y0) to (x1, y1) with its head, and the axis name beyond it.
void arrow(Scene& s, double x0, double y0, double x1, double y1, const std::string& name, double lx,
           double ly) {
    double dx = x1 - x0, dy = y1 - y0, n = std::hypot(dx, dy);
    dx /= n, dy /= n;
    const double len = 2.2, half = 0.8;
    s.marks.push_back(
        line_mark(Mark::axes, x0, y0, x1 - dx * len * 0.8, y1 - dy * len * 0.8, kInk, 0.3));
    Mark head;
    head.kind = Mark::polygon;
    head.group = Mark::axes;
    head.pts = {x1,
                y1,
                x1 - dx * len - dy * half,
                y1 - dy * len + dx * half,
                x1 - dx * len + dy * half,
                y1 - dy * len - dx * half};
    head.has_stroke = false;
    head.has_fill = true;
    head.fill = kInk;
    s.marks.push_back(head);
    s.marks.push_back(text_mark(Mark::axes, lx, ly, name, kSub, kInk, true));
}

// Below the frame, left to right: the axis arrows, then the scale bar. Returns
// the height used.
double axes_and_scale(Scene& s, double x, double y) {
    std::string hn(1, kAxisNames[size_t(s.h)]), vn(1, kAxisNames[size_t(s.v)]);
    double ox = x + 1, oy = y + 11;
    arrow(s, ox, oy, ox + 11, oy, hn, ox + 12.2, oy + 1);
    arrow(s, ox, oy, ox, oy - 11, vn, ox + 1.6, oy - 9);
    // The bar: about 30 mm of paper, a round length of the part, halves dark and light.
    s.bar_length = nice_length(30 / s.k);
    double bx = x + 24, by = y + 6, bw = s.bar_length * s.k, bh = 1.4;
    s.marks.push_back(rect_mark(Mark::scale, bx, by, bw / 2, bh, kInk, 0.2, &kInk));
    s.marks.push_back(rect_mark(Mark::scale, bx + bw / 2, by, bw / 2, bh, kInk, 0.2, &kWhite));
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g mm", s.bar_length);
    s.marks.push_back(text_mark(Mark::scale, bx, by - 1.2, "0", kSmall, kInk));
    Mark end = text_mark(Mark::scale, bx + bw, by - 1.2, buf, kSmall, kInk);
    end.right = true;
    s.marks.push_back(end);
    // TRANSLATORS: %s is the scale of the plot, 1:2 or 5:1.
    s.marks.push_back(text_mark(Mark::scale, bx + bw + 3, by + bh,
                                strf(tr("drawn at %s on paper (PDF, SVG)"), s.ratio.c_str()),
                                kSmall, kGrey));
    return 14;
}

// The legend: a sample of each layer drawn, flowing in rows. Returns the height used.
double legend(Scene& s, double x, double y, double room) {
    double cx = x, row = y + kBody;
    // TRANSLATORS: the title of the plot's legend.
    const char* title = tr("legend");
    s.marks.push_back(text_mark(Mark::legend, cx, row, title, kBody, kInk, true));
    cx += text_ems(title, true) * kBody + 4;
    for (size_t l = 0; l < kLayerCount; ++l) {
        if (!s.present[l]) continue;
        const LayerStyle& st = layer_style(Layer(l));
        const char* words = tr(st.legend);
        double w = 9.5 + text_ems(words) * kBody + 5;
        if (cx + w > x + room && cx > x) {
            cx = x + text_ems(title, true) * kBody + 4;
            row += kBody * 1.7;
        }
        Mark sample =
            line_mark(Mark::legend, cx, row - 0.8, cx + 8, row - 0.8, st.colour, st.width);
        sample.layer = int(l);
        s.marks.push_back(sample);
        s.marks.push_back(text_mark(Mark::legend, cx + 9.5, row, words, kBody, kInk));
        cx += w;
    }
    return row - y + 2;
}

// The table of each tool's time (SceneOptions::tools): a bold header, one row
// per tool, the numbers right-aligned. Returns the height used.
double tool_table(Scene& s, double x, double y) {
    // The right edge of each column from x (mm of paper); the tool's is its left.
    static constexpr double kRight[] = {0, 36, 54, 78, 100, 130};
    static constexpr const char* kHead[] = {
        // TRANSLATORS: the headers of the plot's table of each tool's time.
        N_("tool"),   N_("cutting s"), N_("passes"),
        N_("cut mm"), N_("rapids s"),  N_("parts per edge")};
    const double top = y;
    auto cell = [&](size_t c, const std::string& words, bool bold) {
        Mark m = text_mark(Mark::notes, x + kRight[c], y, words, kBody, kInk, bold);
        m.right = c > 0;
        s.marks.push_back(m);
    };
    y += kBody * 2.2;
    for (size_t c = 0; c < std::size(kHead); ++c) cell(c, tr(kHead[c]), true);
    for (const plan::ToolRow& r : s.opt.tools) {
        y += kBody * 1.6;
        char b[5][32];
        std::snprintf(b[0], sizeof b[0], "%.1f", r.cut_seconds);
        std::snprintf(b[1], sizeof b[1], "%ld", r.passes);
        std::snprintf(b[2], sizeof b[2], "%.3f", r.cut_length);
        std::snprintf(b[3], sizeof b[3], "%.1f", r.rapid_seconds);
        const long n = plan::parts_per_edge(r.cut_seconds, s.opt.life.of(r.tool));
        if (n > 0)
            std::snprintf(b[4], sizeof b[4], "%ld", n);
        else
            std::snprintf(b[4], sizeof b[4], "%s", "\u2014");  // not given
        cell(0, "T" + std::to_string(r.tool), true);
        for (size_t c = 0; c < 5; ++c) cell(c + 1, b[c], false);
    }
    return y - top;
}

// The window: the fitted box with a margin, at the largest round scale that fits the page.
void frame_window(Scene& s) {
    double w = s.fit.x1 - s.fit.x0, h = s.fit.y1 - s.fit.y0;
    double m = std::max(0.06 * std::max(w, h), 1.0);
    s.wx0 = s.fit.x0 - m, s.wx1 = s.fit.x1 + m;
    s.wy0 = s.fit.y0 - m, s.wy1 = s.fit.y1 + m;
    s.k = paper_scale(s.wx1 - s.wx0, s.wy1 - s.wy0);
    s.ratio = ratio_words(s.k);
    s.fw = (s.wx1 - s.wx0) * s.k;
    s.fh = (s.wy1 - s.wy0) * s.k;
}

void lay_out(Scene& s) {
    std::vector<std::string> title = title_lines(s);
    std::vector<std::pair<std::string, Rgb>> notes = note_lines(s);
    double widest = text_ems(title[0], true) * kTitle;
    widest = std::max(widest, text_ems(title[1]) * kSub);
    for (const auto& n : notes) widest = std::max(widest, text_ems(n.first) * kBody);
    double content = std::clamp(std::max(widest, s.fw), kMinContent, std::max(kMaxContent, s.fw));
    double x = kMargin, y = kMargin + kTitle;
    s.marks.push_back(text_mark(Mark::title, x, y, fit_text(title[0], kTitle, content, true),
                                kTitle, kInk, true));
    y += kSub * 1.8;
    s.marks.push_back(text_mark(Mark::title, x, y, fit_text(title[1], kSub, content), kSub, kGrey));
    s.fx = x + (content - s.fw) / 2;
    s.fy = y + 4;
    s.marks.push_back(rect_mark(Mark::border, s.fx, s.fy, s.fw, s.fh, kLight, 0.25, nullptr));
    y = s.fy + s.fh + 4;
    y += axes_and_scale(s, x, y);
    y += legend(s, x, y, content) + 2;
    for (const auto& [words, colour] : notes) {
        y += kBody * 1.6;
        s.marks.push_back(
            text_mark(Mark::notes, x, y, fit_text(words, kBody, content), kBody, colour));
    }
    if (!s.opt.tools.empty()) y += tool_table(s, x, y);
    y += kSmall * 1.8;
    // TRANSLATORS: %s is the program that drew the plot: pupitre 1.2.
    s.marks.push_back(text_mark(Mark::notes, x, y, strf(tr("drawn by %s"), s.opt.generator.c_str()),
                                kSmall, kGrey));
    s.page_w = content + 2 * kMargin;
    s.page_h = y + kMargin;
}

}  // namespace

const char* mark_group_id(Mark::Group g) {
    static constexpr const char* kIds[Mark::groups_] = {"title",     "border", "axes",
                                                        "scale-bar", "legend", "notes"};
    return kIds[g];
}

double text_ems(const std::string& s, bool bold) {
    // DejaVu Sans advance widths (ems), rounded up: narrow, digits, wide, capitals, the rest.
    double w = 0;
    for (unsigned char c : s) {
        if ((c & 0xc0) == 0x80) continue;  // a UTF-8 continuation byte
        if (c >= 0x80)
            w += 0.7;
        else if (c == ' ' || c == '.' || c == ',' || c == ':' || c == ';' || c == '\'' ||
                 c == '|' || c == 'i' || c == 'j' || c == 'l' || c == 'I' || c == '!')
            w += 0.34;
        else if (c == '(' || c == ')' || c == '/' || c == '-' || c == 'f' || c == 't' || c == 'r')
            w += 0.42;
        else if (c >= '0' && c <= '9')
            w += 0.64;
        else if (c == 'm' || c == 'w' || c == 'M' || c == 'W' || c == '%')
            w += 0.99;
        else if (c >= 'A' && c <= 'Z')
            w += 0.75;
        else
            w += 0.62;
    }
    return w * (bold ? 1.1 : 1.0);
}

Scene build_scene(const Toolpath& path, const SceneOptions& o) {
    Scene s;
    s.path = &path;
    s.opt = o;
    plane_axes(o.plane, s.h, s.v);
    s.lathe = path.machine().lathe && o.plane == PathPlane::zx;
    s.mirror = s.lathe && o.mirror && !path.cut_bounds().empty();
    s.fit = fit_box(path, o.plane, s.mirror, true);
    count_outside(path, o.plane, path.size(), s.fit);
    s.title = path.program >= 0 ? "%" + std::to_string(path.program) : std::string();
    if (!path.title.empty()) s.title += (s.title.empty() ? "" : " ") + path.title;
    frame_window(s);
    find_layers(s);
    lay_out(s);
    return s;
}

}  // namespace pupitre
