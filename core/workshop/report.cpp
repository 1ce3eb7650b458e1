// The workshop's reports (see report.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/workshop/report.hpp"

#include <algorithm>
#include <cmath>

#include "core/i18n.hpp"
#include "core/numfmt.hpp"
#include "core/output/json.hpp"

namespace pupitre::workshop {

Diag crash_diag(const Crash& c) {
    Diag d;
    d.code = c.code;
    d.program = c.loc.prog;
    d.line = c.loc.line;
    d.n = c.loc.n;
    d.detail = c.what;
    return d;
}

std::string workshop_json(const Workshop& w, const std::vector<Asked>& asked) {
    std::string o = ",\"workshop\":{\"setup\":";
    append_json_string(o, w.setup().name);
    o += ",\"crashes\":[";
    for (size_t i = 0; i < w.crashes().size(); ++i) {
        const Crash& c = w.crashes()[i];
        if (i) o += ',';
        o += "{\"code\":" + std::to_string(c.code) + ",\"prog\":" + std::to_string(c.loc.prog) +
             ",\"line\":" + std::to_string(c.loc.line) +
             ",\"n\":" + (c.loc.n < 0 ? "null" : std::to_string(c.loc.n)) +
             ",\"tool\":" + std::to_string(c.tool) + ",\"om\":{\"X\":";
        append_fixed4(o, w.machine().x_diameter ? 2 * c.om[X] : c.om[X]);  // as the trace
        if (w.is_mill()) {
            o += ",\"Y\":";
            append_fixed4(o, c.om[Y]);
        }
        o += ",\"Z\":";
        append_fixed4(o, c.om[Z]);
        o += "},\"message\":";
        append_json_string(o, c.what);
        o += '}';
    }
    o += "],\"measurements\":[";
    for (size_t i = 0; i < asked.size(); ++i) {
        const Asked& a = asked[i];
        if (i) o += ',';
        o += "{\"spec\":";
        append_json_string(o, a.r.spec);
        if (!a.error.empty()) {
            o += ",\"error\":";
            append_json_string(o, a.error);
        } else {
            o += ",\"instrument\":";
            append_json_string(o, a.r.instrument);
            o += ",\"value\":";
            append_fixed4(o, a.r.value);
            o += ",\"resolution\":";
            append_fixed4(o, a.r.resolution);
            if (a.r.uncertainty > 0) {
                o += ",\"uncertainty\":";
                append_fixed4(o, a.r.uncertainty);
            }
        }
        o += '}';
    }
    o += "]}";
    return o;
}

std::string readings_text(const std::vector<Asked>& asked) {
    std::string o;
    for (const Asked& a : asked) {
        if (!a.error.empty()) {
            // TRANSLATORS: a measurement asked with --measure, and why there is no reading.
            o += strf(tr("%s: no reading: %s\n"), a.r.spec.c_str(), a.error.c_str());
            continue;
        }
        int decimals = a.r.resolution < 0.005 ? 3 : 2;
        if (a.r.uncertainty > 0)
            // TRANSLATORS: a presetter's reading: what was asked, the value and its uncertainty in
            // mm, the instrument.
            o += strf(tr("%s: %.*f mm \u00b1%.3f (%s)\n"), a.r.spec.c_str(), decimals, a.r.value,
                      a.r.uncertainty, a.r.instrument.c_str());
        else
            // TRANSLATORS: a reading: what was asked, the value in mm, the instrument.
            o += strf(tr("%s: %.*f mm (%s)\n"), a.r.spec.c_str(), decimals, a.r.value,
                      a.r.instrument.c_str());
    }
    return o;
}

std::string part_zr(const LatheWorld& w) {
    double face = 0;
    std::string o = "# pupitre part: half-section, Z from the right-hand face, R a radius (mm)\n";
    if (!w.right_face(face)) return o;
    bool first = true;
    for (const CPath& q : w.material()) {
        if (!first) o += '\n';
        first = false;
        for (const auto& v : q) {
            Pt p = to_mm(v);
            o += fixed3_zeroed(p[0] - face, 5e-5) + ' ' + fixed3_zeroed(p[1], 5e-5) + '\n';
        }
    }
    return o;
}

namespace {

void svg_path(std::string& o, const CPaths& ps, double face, const char* style) {
    o += "<path " + std::string(style) + " d=\"";
    for (const CPath& q : ps) {
        for (size_t i = 0; i < q.size(); ++i) {
            Pt p = to_mm(q[i]);
            o += (i ? " L" : "M") + fixed3(p[0] - face) + ',' + fixed3(-p[1]);
        }
        o += " Z ";
    }
    o += "\"/>\n";
}

}  // namespace

std::string part_svg(const LatheWorld& w, const std::string& title) {
    double face = 0;
    w.right_face(face);
    // Everything drawn, with a margin of 5 mm.
    double left = 1e300, right = -1e300, top = 0;
    for (const CPaths* ps : {&w.material(), &w.chuck(), &w.tailstock()})
        for (const CPath& q : *ps)
            for (const auto& v : q) {
                Pt p = to_mm(v);
                left = std::min(left, p[0] - face), right = std::max(right, p[0] - face),
                top = std::max(top, p[1]);
            }
    if (left > right) left = -10, right = 0;
    left -= 5, right += 5, top += 5;
    std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    o += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + fixed3(left) + ' ' +
         fixed3(-top) + ' ' + fixed3(right - left) + ' ' + fixed3(top + 5) + "\" width=\"" +
         fixed3((right - left) * 8) + "\" height=\"" + fixed3((top + 5) * 8) + "\">\n<title>";
    for (char c : title)
        o += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
    o += "</title>\n";
    // The spindle axis, the part filled, the jaws and the chuck outlined.
    o += "<line x1=\"" + fixed3(left) + "\" y1=\"0\" x2=\"" + fixed3(right) +
         "\" y2=\"0\" stroke=\"#888\" stroke-width=\"0.2\" stroke-dasharray=\"4 1 1 1\"/>\n";
    svg_path(o, w.material(), face,
             "fill=\"#9bb0c8\" stroke=\"#1d3557\" stroke-width=\"0.1\" fill-rule=\"nonzero\"");
    svg_path(o, w.chuck(), face, "fill=\"none\" stroke=\"#444\" stroke-width=\"0.3\"");
    if (!w.tailstock().empty())
        svg_path(o, w.tailstock(), face, "fill=\"none\" stroke=\"#444\" stroke-width=\"0.3\"");
    o += "</svg>\n";
    return o;
}

std::vector<std::vector<Pt>> block_from_above(const MillWorld& w) {
    const Box3& b = w.stock();
    std::vector<std::vector<Pt>> out{
        {{b.lo[0], b.lo[1]}, {b.hi[0], b.lo[1]}, {b.hi[0], b.hi[1]}, {b.lo[0], b.hi[1]}}};
    // Each row's runs of cut cells, merged by Clipper into outlines.
    ClipperLib::Clipper merge;
    const double c = w.cell(), top = b.hi[2] - 1e-3;
    for (int j = 0; j < w.ny(); ++j)
        for (int i = 0; i < w.nx();) {
            if (w.height(i, j) >= top) {
                ++i;
                continue;
            }
            int k = i;
            while (k < w.nx() && w.height(k, j) < top) ++k;
            const double x0 = b.lo[0] + i * c, x1 = std::min(b.hi[0], b.lo[0] + k * c);
            const double y0 = b.lo[1] + j * c, y1 = std::min(b.hi[1], y0 + c);
            merge.AddPath({to_int({x0, y0}), to_int({x1, y0}), to_int({x1, y1}), to_int({x0, y1})},
                          ClipperLib::ptSubject, true);
            i = k;
        }
    CPaths cut;
    merge.Execute(ClipperLib::ctUnion, cut, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    for (const CPath& q : cut) {
        out.emplace_back();
        for (const auto& v : q) out.back().push_back(to_mm(v));
    }
    return out;
}

std::vector<uint16_t> height_image(const MillWorld& w, double& mm_per_unit) {
    const Box3& b = w.stock();
    const double z0 = b.lo[2], span = b.hi[2] - b.lo[2];
    mm_per_unit = span / 65535;
    std::vector<uint16_t> v(size_t(w.nx()) * size_t(w.ny()));
    for (int j = 0; j < w.ny(); ++j)
        for (int i = 0; i < w.nx(); ++i) {
            const double u = std::round((double(w.height(i, j)) - z0) / mm_per_unit);
            v[size_t(w.ny() - 1 - j) * size_t(w.nx()) + size_t(i)] =
                uint16_t(std::clamp(u, 0.0, 65535.0));
        }
    return v;
}

std::string height_json(const MillWorld& w, const std::string& png, double mm_per_unit,
                        const std::string& title) {
    const Box3& b = w.stock();
    std::string o = "{\"format\":\"pupitre height field\",\"title\":";
    append_json_string(o, title);
    o += ",\"image\":";
    append_json_string(o, png);
    o += ",\"columns\":" + std::to_string(w.nx()) + ",\"rows\":" + std::to_string(w.ny()) +
         ",\"cell\":";
    append_fixed4(o, w.cell());
    o += ",\"origin\":{\"X\":";
    append_fixed4(o, b.lo[0]);
    o += ",\"Y\":";
    append_fixed4(o, b.lo[1]);
    o += ",\"Z\":";
    append_fixed4(o, b.lo[2]);
    o += "},\"stock\":{\"X\":";
    append_fixed4(o, b.hi[0] - b.lo[0]);
    o += ",\"Y\":";
    append_fixed4(o, b.hi[1] - b.lo[1]);
    o += ",\"Z\":";
    append_fixed4(o, b.hi[2] - b.lo[2]);
    o += "},\"z_per_unit\":" + strf("%.9g", mm_per_unit) +
         ",\"first_row\":\"+Y\",\"first_column\":\"-X\"}\n";
    return o;
}

}  // namespace pupitre::workshop
