// JSON-lines trace and run summaries.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/trace.hpp"

#include <cmath>

#include "core/geometry/kinematics.hpp"
#include "core/i18n.hpp"

namespace pupitre {

void append_fixed4(std::string& s, double v) {
    if (std::fabs(v) < 0.00005) v = 0;
    char buf[64];
    int n = std::snprintf(buf, sizeof buf, "%.4f", v);
    s.append(buf, size_t(n));
}

void append_json_string(std::string& s, std::string_view v) {
    s += '"';
    for (char c : v) {
        switch (c) {
            case '"':
                s += "\\\"";
                break;
            case '\\':
                s += "\\\\";
                break;
            case '\n':
                s += "\\n";
                break;
            case '\t':
                s += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    s += buf;
                } else {
                    s += c;
                }
        }
    }
    s += '"';
}

void TraceWriter::head(const char* ev, const Loc& l) {
    buf_.clear();
    buf_ += "{\"ev\":\"";
    buf_ += ev;
    buf_ += "\",\"prog\":";
    buf_ += std::to_string(l.prog);
    buf_ += ",\"line\":";
    buf_ += std::to_string(l.line);
    buf_ += ",\"n\":";
    buf_ += l.n >= 0 ? std::to_string(l.n) : std::string("null");
}

void TraceWriter::axes(const char* key, const Axes& v, bool x_diam) {
    buf_ += ",\"";
    buf_ += key;
    buf_ += "\":{";
    bool first = true;
    for (int a = 0; a < kAxes; ++a) {
        if (!m_.has(a)) continue;
        if (!first) buf_ += ',';
        first = false;
        buf_ += '"';
        buf_ += kAxisNames[size_t(a)];
        buf_ += "\":";
        append_fixed4(buf_, (a == X && x_diam) ? 2 * v[size_t(a)] : v[size_t(a)]);
    }
    buf_ += '}';
}

void TraceWriter::move(const MoveEvent& e) {
    seconds += e.seconds;
    head("move", e.loc);
    buf_ += ",\"g\":";
    buf_ += std::to_string(e.g);
    if (e.g52) buf_ += ",\"g52\":true";
    axes("to", e.to_prog, x_diameter());
    if (e.g == 2 || e.g == 3) {
        buf_ += ",\"center\":{";
        int a0 = e.plane_a0, a1 = e.plane_a1;
        double c0 = e.c0, c1 = e.c1;
        if (a0 > a1) {
            std::swap(a0, a1);
            std::swap(c0, c1);
        }
        buf_ += '"';
        buf_ += kAxisNames[size_t(a0)];
        buf_ += "\":";
        append_fixed4(buf_, (a0 == X && x_diameter()) ? 2 * c0 : c0);
        buf_ += ",\"";
        buf_ += kAxisNames[size_t(a1)];
        buf_ += "\":";
        append_fixed4(buf_, (a1 == X && x_diameter()) ? 2 * c1 : c1);
        buf_ += "},\"sweep\":";
        append_fixed4(buf_, e.sweep);
    }
    axes("om", e.to_mach, x_diameter());
    buf_ += ",\"feed\":";
    append_fixed4(buf_, e.feed);
    buf_ += ",\"rpm\":";
    append_fixed4(buf_, e.rpm);
    buf_ += ",\"t\":";
    append_fixed4(buf_, e.seconds);
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::dwell(const Loc& l, double s) {
    seconds += s;
    head("dwell", l);
    buf_ += ",\"t\":";
    append_fixed4(buf_, s);
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

// "m6": an M06 changed the tool (true) or only the corrector D changed.
void TraceWriter::tool(const Loc& l, int t, int d, double s, bool m6) {
    seconds += s;
    head("tool", l);
    buf_ += ",\"t\":" + std::to_string(t) + ",\"d\":" + std::to_string(d);
    buf_ += m6 ? ",\"m6\":true}\n" : ",\"m6\":false}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::spindle(const SpindleEvent& e) {
    head("spindle", e.loc);
    buf_ += ",\"rpm\":";
    append_fixed4(buf_, e.rpm);
    buf_ += ",\"dir\":\"";
    buf_ += e.dir == 3 ? "cw" : e.dir == 4 ? "ccw" : e.dir == 19 ? "index" : "stop";
    buf_ += "\",\"css\":";
    if (e.css)
        append_fixed4(buf_, e.vc);
    else
        buf_ += "null";
    buf_ += ",\"range\":";
    buf_ += e.range >= 0 ? std::to_string(e.range) : std::string("null");
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::coolant(const Loc& l, bool m7, bool m8) {
    head("coolant", l);
    buf_ += std::string(",\"m7\":") + (m7 ? "true" : "false") +
            ",\"m8\":" + (m8 ? "true" : "false") + "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::stop(const Loc& l, int m) {
    head("stop", l);
    buf_ += ",\"m\":" + std::to_string(m) + "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::message(const Loc& l, int channel, std::string_view text) {
    head("message", l);
    buf_ += ",\"channel\":" + std::to_string(channel) + ",\"text\":";
    append_json_string(buf_, text);
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::end(const Loc& l, int m) {
    head("end", l);
    buf_ += ",\"m\":" + std::to_string(m) + ",\"t\":";
    append_fixed4(buf_, seconds);
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

namespace {
std::string fixed(double v, int decimals) {
    if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Shortest decimal form of an L value (up to 6 decimals, no trailing zeros).
std::string compact(double v) {
    std::string s = fixed(v, 6);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

std::string clock_text(double s) {
    long total = long(s);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60, total % 60);
    return buf;
}

void axes_json(std::string& o, const Interpreter& in, const Axes& v) {
    o += '{';
    bool first = true;
    for (int a = 0; a < kAxes; ++a) {
        if (!in.machine().has(a)) continue;
        if (!first) o += ',';
        first = false;
        o += '"';
        o += kAxisNames[size_t(a)];
        o += "\":";
        append_fixed4(o, in.to_display(a, v[size_t(a)]));
    }
    o += '}';
}

std::string axes_text(const Interpreter& in, const Axes& v) {
    std::string o;
    for (int a = 0; a < kAxes; ++a) {
        if (!in.machine().has(a)) continue;
        if (!o.empty()) o += ' ';
        o += kAxisNames[size_t(a)];
        o += fixed(in.to_display(a, v[size_t(a)]), 3);
    }
    return o;
}

void diag_json(std::string& o, const Diag& d) {
    o += "{\"code\":" + std::to_string(d.code) + ",\"file\":";
    append_json_string(o, d.file);
    o += ",\"line\":" + std::to_string(d.line) + ",\"n\":";
    o += d.n >= 0 ? std::to_string(d.n) : std::string("null");
    o += ",\"message\":";
    append_json_string(o, d.detail);
    o += '}';
}
}  // namespace

std::string summary_text(const Interpreter& in, const std::string& file) {
    std::string o;
    // TRANSLATORS: a count in the summary of a run; the English says "blocks" whatever the number.
    std::string blocks = strf(trn("%ld blocks", "%ld blocks", in.blocks()), in.blocks());
    // TRANSLATORS: a count in the summary of a run; the English says "moves" whatever the number.
    std::string moves = strf(trn("%ld moves", "%ld moves", in.moves()), in.moves());
    // TRANSLATORS: the first line of the summary of a run: program number, file, machine profile,
    // then the counts of blocks and moves, the path length, the cycle time h:mm:ss and in seconds.
    o += strf(tr("%%%d (%s) on %s: %s, %s, path %s mm, cycle time %s (%s s)\n"), in.main_program(),
              file.c_str(), in.machine().name.c_str(), blocks.c_str(), moves.c_str(),
              fixed(in.path_length(), 3).c_str(), clock_text(in.seconds()).c_str(),
              fixed(in.seconds(), 3).c_str());
    if (in.machine().dialect == Dialect::cazeneuve)
        // The programs are in micrometres; OP and OM are shown as the machine's pages show them.
        o += tr("units: mm, X a radius (the program's X15000 is X15.000; pupitre-cazeneuve(5))\n");
    o += strf(tr("final OP: %s\n"), axes_text(in, in.program_pos()).c_str());
    o += strf(tr("final OM: %s\n"), axes_text(in, in.machine_pos()).c_str());
    if (!in.tools_used().empty()) {
        o += tr("tools:");
        for (int t : in.tools_used()) o += " T" + std::to_string(t);
        o += '\n';
    }
    return o;
}

std::string summary_json(const Interpreter& in, const std::string& file,
                         const std::vector<Diag>& more, std::string_view fields) {
    std::string o = "{\"file\":";
    append_json_string(o, file);
    o += ",\"program\":" + std::to_string(in.main_program());
    o += ",\"machine\":";
    append_json_string(o, in.machine().name);
    o += ",\"blocks\":" + std::to_string(in.blocks());
    o += ",\"moves\":" + std::to_string(in.moves());
    o += ",\"path_length\":";
    append_fixed4(o, in.path_length());
    o += ",\"cycle_time\":";
    append_fixed4(o, in.seconds());
    o += ",\"op\":";
    axes_json(o, in, in.program_pos());
    o += ",\"om\":";
    axes_json(o, in, in.machine_pos());
    const MachineProfile& m = in.machine();
    if (!m.kinematics.empty()) {
        // The tool in the part frame by the kinematic model (004:1436-2018).
        const Axes& p = in.program_pos();
        Eigen::Isometry3d h =
            m.kinematics == "table"
                ? kin::forward4({p[X], p[Y], p[Z], p[B]}, m.kin_lx, m.kin_lz)
                : kin::forward5({p[X], p[Y], p[Z], p[B], p[C]}, m.kin_lx, m.kin_ly, m.kin_lz);
        Eigen::Vector3d t = h.translation(), k = h.linear().col(2);
        o += ",\"tool_in_part\":{\"X\":";
        append_fixed4(o, t.x());
        o += ",\"Y\":";
        append_fixed4(o, t.y());
        o += ",\"Z\":";
        append_fixed4(o, t.z());
        o += ",\"axis\":[";
        append_fixed4(o, k.x());
        o += ',';
        append_fixed4(o, k.y());
        o += ',';
        append_fixed4(o, k.z());
        o += "]}";
    }
    o += ",\"tools\":[";
    for (size_t i = 0; i < in.tools_used().size(); ++i) {
        if (i) o += ',';
        o += std::to_string(in.tools_used()[i]);
    }
    o += "],\"L\":{";
    bool first = true;
    for (size_t i = 0; i < in.lvars().v.size(); ++i) {
        if (!in.lvars().written.test(i)) continue;
        if (!first) o += ',';
        first = false;
        o += "\"L" + std::to_string(i) + "\":" + compact(in.lvars().v[i]);
    }
    o += "},\"E\":{";
    first = true;
    for (const auto& [n, v] : in.e_written()) {
        if (!first) o += ',';
        first = false;
        o += "\"E" + std::to_string(n) + "\":" + std::to_string(v);
    }
    o += "},\"errors\":[";
    first = true;
    for (const Diag& d : in.diags()) {
        if (!d.is_error()) continue;
        if (!first) o += ',';
        first = false;
        diag_json(o, d);
    }
    for (const Diag& d : more) {
        if (!first) o += ',';
        first = false;
        diag_json(o, d);
    }
    o += "],\"warnings\":[";
    first = true;
    for (const Diag& d : in.diags()) {
        if (d.is_error()) continue;
        if (!first) o += ',';
        first = false;
        diag_json(o, d);
    }
    o += ']';
    o += fields;
    o += "}\n";
    return o;
}

}  // namespace pupitre
