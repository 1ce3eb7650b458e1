// The SVG drawing of a toolpath (see svg.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/svg.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace pupitre {

namespace {

constexpr double kPi = 3.14159265358979323846;

enum LayerId { kRapid, kFeed, kComp, kTravel, kGouge, kLayers };
constexpr const char* kLayerIds[kLayers] = {"rapid", "feed", "comp", "travel", "gouge"};
constexpr const char* kLayerStroke[kLayers] = {"#8c8c8c", "#1a1a1a", "#0b7a4b", "#d98200",
                                               "#d40000"};
// Commands per <path> element: long runs are split so that editors cope.
constexpr int kMaxCommands = 200;

struct Layer {
    std::string out;
    size_t last = SIZE_MAX;  // the last move appended, to know whether the pen is down
    int cmds = 0;
    bool open = false;
};

LayerId layer_of(const PathMove& mv) {
    if (mv.flags & pathflag::error) return kGouge;
    if (mv.flags & pathflag::travel) return kTravel;
    return mv.kind == PathKind::rapid ? kRapid : mv.kind == PathKind::comp ? kComp : kFeed;
}

int chords(double r, double sweep_rad, double tol) {
    if (!(r > tol)) return std::max(1, int(std::ceil(std::fabs(sweep_rad) / (kPi / 2))));
    double n = std::ceil(std::fabs(sweep_rad) / (2 * std::acos(1 - tol / r)));
    return int(std::clamp(n, 1.0, 4096.0));
}

// The drawing's box in SVG coordinates (y down): moves, stock, EM±, mirror.
struct Box {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

class Writer {
  public:
    Writer(const Toolpath& p, const SvgOptions& o) : p_(p), o_(o) {
        plane_axes(o.plane, h_, v_);
        lathe_ = p.machine().lathe && o.plane == PathPlane::zx;
    }
    std::string document();

  private:
    void pt(std::string& s, const double* q) const {
        append_mm(s, q[h_]);
        s += ' ';
        append_mm(s, -q[v_]);
    }
    void xy(std::string& s, double x, double y) const {
        append_mm(s, x);
        s += ' ';
        append_mm(s, y);
    }
    void begin(Layer& l, const double* start, const char* cls = nullptr);
    void close(Layer& l) {
        if (l.open) l.out += "\"/>\n";
        l.open = false;
    }
    void add_move(size_t i);
    void add_arc(Layer& l, size_t i);
    Box box() const;
    std::string frame_layers(const Box& b) const;
    std::string title_block(const Box& b, double fs) const;

    const Toolpath& p_;
    const SvgOptions& o_;
    int h_ = X, v_ = Y;
    bool lathe_ = false;
    Layer layers_[kLayers];
};

void Writer::begin(Layer& l, const double* start, const char* cls) {
    close(l);
    l.out += cls ? std::string("<path class=\"") + cls + "\" d=\"M" : std::string("<path d=\"M");
    pt(l.out, start);
    l.open = true;
    l.cmds = 0;
}

void Writer::add_move(size_t i) {
    const PathMove& mv = p_[i];
    Layer& l = layers_[layer_of(mv)];
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
void Writer::add_arc(Layer& l, size_t i) {
    const PathMove& mv = p_[i];
    const PathArc& a = p_.arcs()[mv.arc];
    double r0, r1;
    arc_radii(p_, i, r0, r1);
    double sweep = double(a.sweep);
    bool in_plane = (a.a0 == h_ && a.a1 == v_) || (a.a0 == v_ && a.a1 == h_);
    if (in_plane && std::fabs(r0 - r1) <= 1e-4 + 1e-6 * r1) {
        double view_sweep = a.a0 == h_ ? sweep : -sweep;  // counter-clockwise seen with +v up
        int pieces = std::fabs(sweep) > 270 ? int(std::ceil(std::fabs(sweep) / 180)) : 1;
        const char* large = pieces == 1 && std::fabs(sweep) > 180 ? " 1 " : " 0 ";
        // SVG's y runs down: a counter-clockwise arc on paper has sweep-flag 0.
        const char* flag = view_sweep > 0 ? "0 " : "1 ";
        // A split arc is a path of its own, class "arc": its half-way points are no block's end.
        if (pieces > 1) begin(l, p_.from(i), "arc");
        for (int k = 1; k <= pieces; ++k) {
            double q[3];
            arc_point(p_, i, double(k) / pieces, q);
            l.out += " A";
            append_mm(l.out, r1);
            l.out += ' ';
            append_mm(l.out, r1);
            l.out += " 0";
            l.out += large;
            l.out += flag;
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

Box Writer::box() const {
    PathBox b = p_.bounds();
    if (b.empty()) b.add(p_.start());
    double x0 = b.lo[h_], x1 = b.hi[h_], y0 = b.lo[v_], y1 = b.hi[v_];
    for (const auto& poly : p_.stock())
        for (const auto& q : poly) {
            x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]);
            y0 = std::min(y0, -q[1]), y1 = std::max(y1, q[1]);
        }
    // The mirror image is of the cutting moves only.
    if (lathe_ && o_.mirror && !p_.cut_bounds().empty()) y0 = std::min(y0, -p_.cut_bounds().hi[v_]);
    uint16_t both = p_.extremes_mask_lo() & p_.extremes_mask_hi();
    if ((both >> h_ & 1) && (both >> v_ & 1)) {
        x0 = std::min(x0, p_.extremes_lo()[size_t(h_)]),
        x1 = std::max(x1, p_.extremes_hi()[size_t(h_)]);
        y0 = std::min(y0, p_.extremes_lo()[size_t(v_)]),
        y1 = std::max(y1, p_.extremes_hi()[size_t(v_)]);
    }
    return Box{x0, -y1, x1, -y0};  // SVG: y down
}

// The spindle axis and the stock (lathe), the EM± frame, the mirror image.
std::string Writer::frame_layers(const Box& b) const {
    std::string s;
    if (lathe_) {
        s += "<g id=\"axis\" stroke=\"#9a9a9a\" stroke-dasharray=\"6 1.5 1 1.5\">\n<path d=\"M";
        xy(s, b.x0, 0);
        s += " L";
        xy(s, b.x1, 0);
        s += "\"/>\n</g>\n";
        s += "<g id=\"stock\" stroke=\"#9a9a9a\" stroke-dasharray=\"1 1\">\n";
        for (const auto& poly : p_.stock())
            for (double ys : {-1.0, 1.0}) {
                if (ys > 0 && !o_.mirror) continue;  // y = -X: ys -1 is the profile's side
                s += "<path d=\"M";
                for (size_t k = 0; k < poly.size(); ++k) {
                    if (k) s += " L";
                    xy(s, poly[k][0], ys * poly[k][1]);
                }
                s += "\"/>\n";
            }
        s += "</g>\n";
    }
    uint16_t both = p_.extremes_mask_lo() & p_.extremes_mask_hi();
    if ((both >> h_ & 1) && (both >> v_ & 1)) {
        s += "<g id=\"extremes\" stroke=\"#3366cc\" stroke-dasharray=\"1 1\">\n<path d=\"M";
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

std::string hms(double t) {
    char buf[64];
    long s = long(std::floor(t));  // as `run` prints it
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld (%.3f s)", s / 3600, s / 60 % 60, s % 60, t);
    return buf;
}

std::string Writer::title_block(const Box& b, double fs) const {
    const MachineProfile& m = p_.machine();
    std::vector<std::pair<std::string, const char*>> lines;
    std::string prog =
        p_.program >= 0 ? "%" + std::to_string(p_.program) : std::string("(no program)");
    if (!p_.title.empty()) prog += "  " + p_.title;
    lines.push_back({prog, "#000"});
    std::string mach = "machine " + (o_.machine.empty() ? m.name : o_.machine);
    if (!m.description.empty()) mach += " (" + m.description + ")";
    mach += "   plane " + std::string(plane_name(o_.plane));
    lines.push_back({mach, "#000"});
    char buf[160];
    std::snprintf(buf, sizeof buf, "   %zu moves   path %.3f mm", p_.size(), p_.length());
    lines.push_back(
        {"cycle time " + hms(o_.seconds >= 0 ? o_.seconds : p_.seconds()) + buf, "#000"});
    std::string ext = "extents";
    const PathBox& pb = p_.bounds();
    for (int a = X; a <= Z && !pb.empty(); ++a) {
        if (!m.has(a)) continue;
        double k = a == X && m.lathe && p_.x_diameter() ? 2 : 1;
        std::snprintf(buf, sizeof buf, "  %c%s %.3f/%.3f", kAxisNames[size_t(a)], k == 2 ? "ø" : "",
                      k * pb.lo[a], k * pb.hi[a]);
        ext += buf;
    }
    if (p_.travel_moves())
        ext += "   " + std::to_string(p_.travel_moves()) + " moves beyond travel";
    lines.push_back({ext, "#000"});
    for (const PathError& e : p_.errors()) {
        std::string t = "error " + std::to_string(e.code) + " line " + std::to_string(e.loc.line);
        if (e.loc.n >= 0) t += " N" + std::to_string(e.loc.n);
        lines.push_back({t + ": " + e.detail, "#d40000"});
    }
    lines.push_back({"drawn by " + o_.generator, "#666"});
    std::string s = "<g id=\"title\" font-family=\"sans-serif\" font-size=\"";
    append_mm(s, fs);
    s += "\">\n<rect fill=\"none\" stroke=\"#000\" stroke-width=\"";
    append_mm(s, fs / 12);
    s += "\" x=\"";
    append_mm(s, b.x0);
    s += "\" y=\"";
    append_mm(s, b.y1 + fs);
    s += "\" width=\"";
    append_mm(s, b.x1 - b.x0);
    s += "\" height=\"";
    append_mm(s, fs * (1.4 * double(lines.size()) + 0.8));
    s += "\"/>\n";
    for (size_t k = 0; k < lines.size(); ++k) {
        s += "<text x=\"";
        append_mm(s, b.x0 + fs * 0.5);
        s += "\" y=\"";
        append_mm(s, b.y1 + fs * (2.2 + 1.4 * double(k)));
        s += std::string("\" fill=\"") + lines[k].second +
             (k == 0 ? "\" font-weight=\"bold\">" : "\">");
        s += xml_escape(lines[k].first);
        s += "</text>\n";
    }
    return s + "</g>\n";
}

std::string Writer::document() {
    for (size_t i = 0; i < p_.size(); ++i) add_move(i);
    for (Layer& l : layers_) close(l);
    Box b = box();
    double w = std::max(b.x1 - b.x0, 1.0), hgt = std::max(b.y1 - b.y0, 1.0);
    double margin = std::max(0.05 * std::max(w, hgt), 2.0);
    Box f{b.x0 - margin, b.y0 - margin, b.x0 - margin + w + 2 * margin,
          b.y0 - margin + hgt + 2 * margin};
    double fs = std::clamp((f.x1 - f.x0) / 45, 1.5, 50.0);
    double lines = 6.0 + double(p_.errors().size());
    double total_h = (f.y1 - f.y0) + fs * (1.4 * lines + 2.4);
    double sw = std::clamp(std::hypot(w, hgt) / 700, 0.05, 5.0);
    std::string s =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"";
    append_mm(s, f.x1 - f.x0);
    s += "mm\" height=\"";
    append_mm(s, total_h);
    s += "mm\" viewBox=\"";
    xy(s, f.x0, f.y0);
    s += ' ';
    xy(s, f.x1 - f.x0, total_h);
    std::string title = p_.program >= 0 ? "%" + std::to_string(p_.program) : std::string();
    if (!p_.title.empty()) title += (title.empty() ? "" : " ") + p_.title;
    s += "\">\n<title>" + xml_escape(title) + "</title>\n<desc>" +
         xml_escape(
             "Toolpath in the program frame, plane " + std::string(plane_name(o_.plane)) +
             "; lengths in mm; the horizontal axis to the right and the vertical one up" +
             (lathe_ ? " (lathe: Z across, X as a radius up, y = -X/2 of the diameters)." : ".")) +
         "</desc>\n";
    s += "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\" stroke-width=\"";
    append_mm(s, sw);
    s += "\">\n" + frame_layers(b);
    for (int k = 0; k < kLayers; ++k) {
        s += std::string("<g id=\"") + kLayerIds[k] + "\" stroke=\"" + kLayerStroke[k] + "\"";
        if (k == kRapid) {
            s += " stroke-dasharray=\"";
            xy(s, 4 * sw, 3 * sw);
            s += "\"";
        }
        s += ">\n" + layers_[k].out;
        if (k == kGouge)
            for (const PathError& e : p_.errors()) {
                const double* at =
                    e.moves == 0 ? p_.start() : p_[std::min(e.moves, p_.size()) - 1].p;
                s += "<circle cx=\"";
                append_mm(s, at[h_]);
                s += "\" cy=\"";
                append_mm(s, -at[v_]);
                s += "\" r=\"";
                append_mm(s, 6 * sw);
                s += "\"/>\n";
            }
        s += "</g>\n";
    }
    if (lathe_ && o_.mirror)
        s += "<g id=\"mirror\" transform=\"scale(1,-1)\" opacity=\"0.35\">\n<use "
             "xlink:href=\"#feed\"/>\n"
             "<use xlink:href=\"#comp\"/>\n<use xlink:href=\"#travel\"/>\n<use "
             "xlink:href=\"#gouge\"/>\n</g>\n";
    s += "</g>\n" + title_block(f, fs) + "</svg>\n";
    return s;
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

std::string svg_document(const Toolpath& path, const SvgOptions& o) {
    return Writer(path, o).document();
}

bool write_svg(const Toolpath& path, const SvgOptions& o, std::FILE* out) {
    std::string s = svg_document(path, o);
    return std::fwrite(s.data(), 1, s.size(), out) == s.size() && std::fflush(out) == 0;
}

}  // namespace pupitre
