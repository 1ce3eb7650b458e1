// The SVG drawing of a toolpath (see svg.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/svg.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"

namespace pupitre {

namespace {

using ::pupitre::geometry::kPi;

// Commands per <path> element: long runs are split so that editors cope.
constexpr int kMaxCommands = 200;

struct PathLayer {
    std::string out;
    size_t last = SIZE_MAX;  // the last move appended, to know whether the pen is down
    int cmds = 0;
    bool open = false;
};

int chords(double r, double sweep_rad, double tol) {
    if (!(r > tol)) return std::max(1, int(std::ceil(std::fabs(sweep_rad) / (kPi / 2))));
    double n = std::ceil(std::fabs(sweep_rad) / (2 * std::acos(1 - tol / r)));
    return int(std::clamp(n, 1.0, 4096.0));
}

std::string hex(Rgb c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
    return buf;
}

// SVG arc flags for a sweep seen counter-clockwise positive with +y up (SVG's
// y runs down: a counter-clockwise arc on paper has sweep-flag 0).
const char* arc_flags(double view_sweep, int pieces) {
    bool large = pieces == 1 && std::fabs(view_sweep) > 180;
    if (view_sweep > 0) return large ? " 0 1 0 " : " 0 0 0 ";
    return large ? " 0 1 1 " : " 0 0 1 ";
}

class Writer {
  public:
    explicit Writer(const Scene& sc) : sc_(sc), p_(*sc.path), h_(sc.h), v_(sc.v) {}
    std::string document();

  private:
    void pt(std::string& s, const double* q) const {
        append_mm(s, q[h_]);
        s += ' ';
        append_mm(s, -q[v_]);
    }
    static void xy(std::string& s, double x, double y) {
        append_mm(s, x);
        s += ' ';
        append_mm(s, y);
    }
    // A length on paper (mm) in the drawing's units.
    double paper(double mm) const { return mm / sc_.k; }
    void begin(PathLayer& l, const double* start, const char* cls = nullptr);
    void close(PathLayer& l) {
        if (l.open) l.out += "\"/>\n";
        l.open = false;
    }
    void add_move(size_t i);
    void add_arc(PathLayer& l, size_t i);
    std::string group_open(Layer l) const;
    std::string frame_layers() const;
    std::string profile_layer() const;
    static std::string paint(const Mark& m);
    static std::string mark_line(const Mark& m);
    static std::string mark_rect(const Mark& m);
    static std::string mark_polygon(const Mark& m);
    static std::string mark_text(const Mark& m);
    std::string marks() const;
    std::string head() const;

    const Scene& sc_;
    const Toolpath& p_;
    int h_ = X, v_ = Y;
    PathLayer layers_[kLayerCount];
};

void Writer::begin(PathLayer& l, const double* start, const char* cls) {
    close(l);
    l.out += cls ? std::string("<path class=\"") + cls + "\" d=\"M" : std::string("<path d=\"M");
    pt(l.out, start);
    l.open = true;
    l.cmds = 0;
}

void Writer::add_move(size_t i) {
    const PathMove& mv = p_[i];
    PathLayer& l = layers_[size_t(move_layer(mv))];
    const double* s = p_.from(i);
    bool flat = mv.arc == PathMove::kNoArc && s[h_] == mv.p[h_] && s[v_] == mv.p[v_];
    if (flat && l.last + 1 == i) {
        l.last = i;  // a move across the plane (a plunge in XY): no ink, the pen stays down
        return;
    }
    if (flat) return;
    if (!l.open || l.last + 1 != i || l.cmds >= kMaxCommands) begin(l, s);
    l.last = i;
    if (mv.arc != PathMove::kNoArc) {
        add_arc(l, i);
        return;
    }
    l.out += " L";
    pt(l.out, mv.p);
    ++l.cmds;
}

// An arc in the drawing's plane is an SVG arc (split when it nears a full turn,
// where start and end would meet); a spiral or an arc seen edge-on is a polyline
// within a micrometre of the curve.
void Writer::add_arc(PathLayer& l, size_t i) {
    const PathMove& mv = p_[i];
    const PathArc& a = p_.arcs()[mv.arc];
    double r0, r1;
    arc_radii(p_, i, r0, r1);
    double sweep = double(a.sweep);
    bool in_plane = (a.a0 == h_ && a.a1 == v_) || (a.a0 == v_ && a.a1 == h_);
    if (in_plane && std::fabs(r0 - r1) <= 1e-4 + 1e-6 * r1) {
        double view_sweep = a.a0 == h_ ? sweep : -sweep;  // counter-clockwise seen with +v up
        int pieces = std::fabs(sweep) > 270 ? int(std::ceil(std::fabs(sweep) / 180)) : 1;
        // A split arc is a path of its own, class "arc": its half-way points are no block's end.
        if (pieces > 1) begin(l, p_.from(i), "arc");
        for (int k = 1; k <= pieces; ++k) {
            double q[3];
            arc_point(p_, i, double(k) / pieces, q);
            l.out += " A";
            xy(l.out, r1, r1);
            l.out += arc_flags(view_sweep, pieces);
            pt(l.out, q);
            ++l.cmds;
        }
        if (pieces > 1) l.cmds = kMaxCommands;  // the next move starts a new path
        return;
    }
    // A path of its own, class "arc": only its last point is a programmed one.
    begin(l, p_.from(i), "arc");
    int n = chords(std::max(r0, r1), sweep * kPi / 180, 0.001);
    for (int k = 1; k <= n; ++k) {
        double q[3];
        arc_point(p_, i, double(k) / n, q);
        l.out += " L";
        pt(l.out, q);
    }
    l.cmds = kMaxCommands;  // the next move starts a new path
}

// stroke, stroke-width, stroke-dasharray and opacity of a layer's style, its
// lengths in paper mm divided by `per_mm` (the scale, or 1 among the marks).
std::string pen_attrs(const LayerStyle& st, double per_mm) {
    std::string s = " stroke=\"" + hex(st.colour) + "\" stroke-width=\"";
    append_mm(s, st.width / per_mm);
    s += '"';
    if (st.dash[0] > 0) {
        s += " stroke-dasharray=\"";
        for (size_t k = 0; k < st.dash.size() && st.dash[k] > 0; ++k) {
            if (k) s += ' ';
            append_mm(s, st.dash[k] / per_mm);
        }
        s += '"';
    }
    if (st.opacity < 1) s += " opacity=\"" + std::to_string(st.opacity).substr(0, 4) + "\"";
    return s;
}

// <g id=... stroke=... stroke-width=...>: the layer's look from the scene's table.
std::string Writer::group_open(Layer l) const {
    const LayerStyle& st = layer_style(l);
    return std::string("<g id=\"") + st.id + "\"" + pen_attrs(st, sc_.k) + ">\n";
}

// The spindle axis and the stock (lathe: both groups always, as pupitre(1)
// promises them), the EM± frame.
std::string Writer::frame_layers() const {
    std::string s;
    if (sc_.present[size_t(Layer::part)]) {
        const LayerStyle& st = layer_style(Layer::part);
        char fill[64];
        std::snprintf(fill, sizeof fill,
                      " fill=\"#%02x%02x%02x\" fill-opacity=\"0.45\" fill-rule=\"evenodd\"",
                      st.colour.r, st.colour.g, st.colour.b);
        s += std::string("<g id=\"part\"") + fill + pen_attrs(st, sc_.k) + ">\n";
        for (double ys : {-1.0, 1.0}) {
            if (ys > 0 && !(sc_.lathe && sc_.opt.mirror)) continue;  // a mill's block: once
            s += "<path d=\"";
            for (const auto& poly : p_.part()) {
                for (size_t k = 0; k < poly.size(); ++k) {
                    s += k ? " L" : "M";
                    xy(s, poly[k][0], ys * poly[k][1]);
                }
                s += " Z ";
            }
            s += "\"/>\n";
        }
        s += "</g>\n";
    }
    if (sc_.lathe) {
        s += group_open(Layer::axis) + "<path d=\"M";
        xy(s, sc_.wx0, 0);
        s += " L";
        xy(s, sc_.wx1, 0);
        s += "\"/>\n</g>\n";
    }
    if (sc_.lathe) {
        s += group_open(Layer::stock);
        for (const auto& poly : p_.stock())
            for (double ys : {-1.0, 1.0}) {
                if (ys > 0 && !sc_.opt.mirror) continue;  // y = -X: ys -1 is the profile's side
                s += "<path d=\"M";
                for (size_t k = 0; k < poly.size(); ++k) {
                    if (k) s += " L";
                    xy(s, poly[k][0], ys * poly[k][1]);
                }
                s += "\"/>\n";
            }
        s += "</g>\n";
    }
    if (sc_.present[size_t(Layer::extremes)]) {
        s += group_open(Layer::extremes) + "<path d=\"M";
        double x0 = p_.extremes_lo()[size_t(h_)], x1 = p_.extremes_hi()[size_t(h_)];
        double y0 = -p_.extremes_hi()[size_t(v_)], y1 = -p_.extremes_lo()[size_t(v_)];
        xy(s, x0, y0);
        s += " H";
        append_mm(s, x1);
        s += " V";
        append_mm(s, y1);
        s += " H";
        append_mm(s, x0);
        s += " Z\"/>\n</g>\n";
    }
    return s;
}

// The programmed profile under G41/G42, its arcs as SVG arcs.
std::string Writer::profile_layer() const {
    if (!sc_.present[size_t(Layer::profile)]) return {};
    std::string s = group_open(Layer::profile);
    double lx = 0, ly = 0;
    bool open = false;
    for (const ProfileElem& e : p_.profile_elems()) {
        if (!profile_in_plane(e, h_, v_)) continue;
        double x, y;
        profile_point(e, 0, h_, x, y);
        if (!open || std::fabs(x - lx) > 1e-9 || std::fabs(y - ly) > 1e-9) {
            s += open ? "\"/>\n<path d=\"M" : "<path d=\"M";
            xy(s, x, -y);
            open = true;
        }
        double vs = profile_view_sweep(e, h_);
        int pieces = e.arc && std::fabs(vs) > 270 ? int(std::ceil(std::fabs(vs) / 180)) : 1;
        double r = std::hypot(e.from[0] - e.c[0], e.from[1] - e.c[1]);
        for (int k = 1; k <= pieces; ++k) {
            profile_point(e, double(k) / pieces, h_, x, y);
            if (e.arc) {
                s += " A";
                xy(s, r, r);
                s += arc_flags(vs, pieces);
            } else {
                s += " L";
            }
            xy(s, x, -y);
        }
        lx = x, ly = y;
    }
    if (open) s += "\"/>\n";
    return s + "</g>\n";
}

std::string Writer::paint(const Mark& m) {
    std::string s = std::string(" fill=\"") + (m.has_fill ? hex(m.fill) : "none") + "\"";
    if (m.has_stroke) {
        s += " stroke=\"" + hex(m.stroke) + "\" stroke-width=\"";
        append_mm(s, m.width);
        s += '"';
    }
    return s;
}

// A line of the marks; with a layer, the legend's sample of its style.
std::string Writer::mark_line(const Mark& m) {
    std::string s = "<path d=\"M";
    xy(s, m.pts[0], m.pts[1]);
    s += " L";
    xy(s, m.pts[2], m.pts[3]);
    s += '"';
    if (m.layer >= 0) return s + pen_attrs(layer_style(Layer(m.layer)), 1) + "/>\n";
    s += " stroke=\"" + hex(m.stroke) + "\" stroke-width=\"";
    append_mm(s, m.width);
    return s + "\"/>\n";
}

std::string Writer::mark_rect(const Mark& m) {
    std::string s = "<rect x=\"";
    append_mm(s, m.pts[0]);
    s += "\" y=\"";
    append_mm(s, m.pts[1]);
    s += "\" width=\"";
    append_mm(s, m.pts[2]);
    s += "\" height=\"";
    append_mm(s, m.pts[3]);
    return s + '"' + paint(m) + "/>\n";
}

std::string Writer::mark_polygon(const Mark& m) {
    std::string s = "<path d=\"M";
    for (size_t k = 0; k + 1 < m.pts.size(); k += 2) {
        if (k) s += " L";
        xy(s, m.pts[k], m.pts[k + 1]);
    }
    return s + " Z\"" + paint(m) + "/>\n";
}

std::string Writer::mark_text(const Mark& m) {
    std::string s = "<text x=\"";
    append_mm(s, m.pts[0]);
    s += "\" y=\"";
    append_mm(s, m.pts[1]);
    s += "\" font-size=\"";
    append_mm(s, m.size);
    s += "\" fill=\"" + hex(m.fill) + "\"";
    if (m.bold) s += " font-weight=\"bold\"";
    if (m.right) s += " text-anchor=\"end\"";
    return s + ">" + xml_escape(m.words) + "</text>\n";
}

// The marks around the drawing, in paper millimetres: one transform takes them
// to the drawing's units, so their numbers stay the layout's.
std::string Writer::marks() const {
    std::string s =
        "<g id=\"marks\" font-family=\"DejaVu Sans, sans-serif\" xml:space=\"preserve\" "
        "transform=\"translate(";
    xy(s, sc_.wx0 - sc_.fx / sc_.k, -sc_.wy1 - sc_.fy / sc_.k);
    s += ") scale(";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.10g", 1 / sc_.k);
    s += buf;
    s += ")\">\n";
    for (int g = 0; g < Mark::groups_; ++g) {
        s += std::string("<g id=\"") + mark_group_id(Mark::Group(g)) + "\">\n";
        // One writer per kind of mark, in the order of Mark::Kind.
        static constexpr std::string (*kWrite[])(const Mark&) = {mark_line, mark_rect, mark_polygon,
                                                                 mark_text};
        for (const Mark& m : sc_.marks)
            if (m.group == g) s += kWrite[m.kind](m);
        s += "</g>\n";
    }
    return s + "</g>\n";
}

std::string Writer::head() const {
    double ux = sc_.wx0 - sc_.fx / sc_.k, uy = -sc_.wy1 - sc_.fy / sc_.k;
    std::string s =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"";
    append_mm(s, sc_.page_w);
    s += "mm\" height=\"";
    append_mm(s, sc_.page_h);
    s += "mm\" viewBox=\"";
    xy(s, ux, uy);
    s += ' ';
    xy(s, paper(sc_.page_w), paper(sc_.page_h));
    s += "\">\n<title>" + xml_escape(sc_.title) + "</title>\n<desc>" +
         xml_escape(strf(
             sc_.lathe
                 ? tr("Toolpath in the program frame, plane %s; lengths in mm; the horizontal axis "
                      "to "
                      "the right and the vertical one up (lathe: Z across, X as a radius up, y = "
                      "-X/2 "
                      "of the diameters). Drawn at %s; the frame shows %s, and clips what reaches "
                      "beyond it.")
                 : tr("Toolpath in the program frame, plane %s; lengths in mm; the horizontal axis "
                      "to "
                      "the right and the vertical one up. Drawn at %s; the frame shows %s, and "
                      "clips "
                      "what reaches beyond it."),
             std::string(plane_name(sc_.opt.plane)).c_str(), sc_.ratio.c_str(),
             fit_words(p_, sc_.fit).c_str())) +
         "</desc>\n<defs>\n<clipPath id=\"window\"><rect x=\"";
    append_mm(s, sc_.wx0);
    s += "\" y=\"";
    append_mm(s, -sc_.wy1);
    s += "\" width=\"";
    append_mm(s, sc_.wx1 - sc_.wx0);
    s += "\" height=\"";
    append_mm(s, sc_.wy1 - sc_.wy0);
    s += "\"/></clipPath>\n</defs>\n<rect id=\"paper\" fill=\"#ffffff\" x=\"";
    append_mm(s, ux);
    s += "\" y=\"";
    append_mm(s, uy);
    s += "\" width=\"";
    append_mm(s, paper(sc_.page_w));
    s += "\" height=\"";
    append_mm(s, paper(sc_.page_h));
    return s + "\"/>\n";
}

std::string Writer::document() {
    for (size_t i = 0; i < p_.size(); ++i) add_move(i);
    for (PathLayer& l : layers_) close(l);
    std::string s = head();
    s += "<g clip-path=\"url(#window)\" fill=\"none\" stroke-linecap=\"round\" "
         "stroke-linejoin=\"round\">\n" +
         frame_layers() + profile_layer();
    for (Layer k : {Layer::rapid, Layer::feed, Layer::comp, Layer::travel, Layer::gouge}) {
        s += group_open(k) + layers_[size_t(k)].out;
        if (k == Layer::gouge)
            for (const PathError& e : p_.errors()) {
                const double* at =
                    e.moves == 0 ? p_.start() : p_[std::min(e.moves, p_.size()) - 1].p;
                s += "<circle cx=\"";
                append_mm(s, at[h_]);
                s += "\" cy=\"";
                append_mm(s, -at[v_]);
                s += "\" r=\"";
                append_mm(s, paper(1.2));
                s += "\"/>\n";
            }
        s += "</g>\n";
    }
    if (sc_.lathe && sc_.opt.mirror)  // pupitre(1): on the lathe, a mirror group always
        s += "<g id=\"mirror\" transform=\"scale(1,-1)\" opacity=\"0.35\">\n<use "
             "xlink:href=\"#feed\"/>\n"
             "<use xlink:href=\"#comp\"/>\n<use xlink:href=\"#travel\"/>\n<use "
             "xlink:href=\"#gouge\"/>\n</g>\n";
    return s + "</g>\n" + marks() + "</svg>\n";
}

}  // namespace

void append_mm(std::string& s, double v) {
    if (std::fabs(v) < 0.00005 || !std::isfinite(v)) v = 0;
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 4);
    s.append(buf, r.ptr);
}

std::string xml_escape(std::string_view in) {
    std::string out;
    out.reserve(in.size());
    for (size_t i = 0; i < in.size();) {
        unsigned char c = static_cast<unsigned char>(in[i]);
        if (c < 0x80) {
            ++i;
            switch (c) {
                case '&':
                    out += "&amp;";
                    break;
                case '<':
                    out += "&lt;";
                    break;
                case '>':
                    out += "&gt;";
                    break;
                case '"':
                    out += "&quot;";
                    break;
                case '\'':
                    out += "&apos;";
                    break;
                default:
                    if (c >= 0x20 && c != 0x7f)
                        out += char(c);
                    else if (c == '\t' || c == '\n')
                        out += ' ';
            }
            continue;
        }
        // A well-formed sequence of a character XML allows is kept; anything else is U+FFFD.
        int extra = c >= 0xf0 && c < 0xf5   ? 3
                    : c >= 0xe0 && c < 0xf0 ? 2
                    : c >= 0xc2 && c < 0xe0 ? 1
                                            : -1;
        bool ok = extra > 0 && i + size_t(extra) < in.size();
        for (int k = 1; ok && k <= extra; ++k)
            ok = (static_cast<unsigned char>(in[i + size_t(k)]) & 0xc0) == 0x80;
        if (ok) {
            unsigned char d = static_cast<unsigned char>(in[i + 1]);
            // No overlong forms, no surrogates, nothing above U+10FFFF, no U+FFFE/U+FFFF.
            ok = !(c == 0xe0 && d < 0xa0) && !(c == 0xed && d > 0x9f) && !(c == 0xf0 && d < 0x90) &&
                 !(c == 0xf4 && d > 0x8f) &&
                 !(c == 0xef && d == 0xbf && static_cast<unsigned char>(in[i + 2]) >= 0xbe);
        }
        if (ok) {
            out.append(in.substr(i, size_t(extra) + 1));
            i += size_t(extra) + 1;
        } else {
            out += "\xef\xbf\xbd";
            ++i;
        }
    }
    return out;
}

std::string svg_document(const Scene& scene) {
    return Writer(scene).document();
}

std::string svg_document(const Toolpath& path, const SvgOptions& o) {
    return svg_document(build_scene(path, o));
}

bool write_svg(const Scene& scene, std::FILE* out) {
    std::string s = svg_document(scene);
    return std::fwrite(s.data(), 1, s.size(), out) == s.size() && std::fflush(out) == 0;
}

}  // namespace pupitre
