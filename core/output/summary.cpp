// The summary of a run, plain or JSON (pupitre(1)).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/summary.hpp"

#include <cmath>
#include <cstdio>

#include "core/geometry/kinematics.hpp"
#include "core/i18n.hpp"
#include "core/numfmt.hpp"
#include "core/output/json.hpp"

namespace pupitre {

namespace {
std::string fixed(double v, int decimals) {
    if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Shortest decimal form of an L value (up to 6 decimals, no trailing zeros).
std::string compact(double v) {
    std::string text = fixed(v, 6);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? "0" : text;
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

std::string tool_line(const plan::ToolRow& r, const plan::EdgeLife& life) {
    // TRANSLATORS: a tool's share of the cycle: T, its cutting time in seconds, its passes
    // (one "pass", more "passes"), the length cut in mm, its rapid time.
    std::string o =
        strf(trn("T%d: %s s of cutting a part (%ld pass, %s mm), %s s of rapids",
                 "T%d: %s s of cutting a part (%ld passes, %s mm), %s s of rapids", r.passes),
             r.tool, fixed(r.cut_seconds, 1).c_str(), r.passes, fixed(r.cut_length, 3).c_str(),
             fixed(r.rapid_seconds, 1).c_str());
    if (long n = plan::parts_per_edge(r.cut_seconds, life.of(r.tool)))
        // TRANSLATORS: follows a tool's line of the summary, when the life of an edge is known.
        o += strf(trn(", change the edge every %ld part", ", change the edge every %ld parts", n),
                  n);
    return o;
}

std::string summary_text(const Interpreter& in, const std::string& file, const PlanSummary& plan) {
    std::string o;
    // TRANSLATORS: a count in the summary of a run; the English says "blocks" whatever the number.
    std::string blocks = strf(trn("%ld blocks", "%ld blocks", in.blocks()), in.blocks());
    // TRANSLATORS: a count in the summary of a run; the English says "moves" whatever the number.
    std::string moves = strf(trn("%ld moves", "%ld moves", in.moves()), in.moves());
    // TRANSLATORS: the first line of the summary of a run: program number, file, machine profile,
    // then the counts of blocks and moves, the path length, the cycle time h:mm:ss and in seconds.
    if (plan.report) {
        const double t = plan.report->seconds;
        // TRANSLATORS: the first line of the summary of a run: program number, file, machine
        // profile, the counts of blocks and moves, the path length, the cycle time with the
        // machine's accelerations h:mm:ss and in seconds, then the time at the feeds alone.
        o += strf(tr("%%%d (%s) on %s: %s, %s, path %s mm, cycle time %s (%s s; %s s at the "
                     "feeds alone)\n"),
                  in.main_program(), file.c_str(), in.machine().name.c_str(), blocks.c_str(),
                  moves.c_str(), fixed(in.path_length(), 3).c_str(), clock_text(t).c_str(),
                  fixed(t, 3).c_str(), fixed(plan.report->feed_seconds, 3).c_str());
    } else {
        o += strf(tr("%%%d (%s) on %s: %s, %s, path %s mm, cycle time %s (%s s)\n"),
                  in.main_program(), file.c_str(), in.machine().name.c_str(), blocks.c_str(),
                  moves.c_str(), fixed(in.path_length(), 3).c_str(),
                  clock_text(in.seconds()).c_str(), fixed(in.seconds(), 3).c_str());
    }
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
    if (plan.report)
        for (const plan::ToolRow& r : plan.report->tools.rows())
            o += tool_line(r, plan.life) + '\n';
    return o;
}

namespace {
// "tool_times":[{"t":11,"cut":141.78,"rapid":6.6,"passes":3,"cut_length":424.44,
// "parts_per_edge":6}]: parts_per_edge null when the edge's life is not given.
void tool_times_json(std::string& o, const PlanSummary& plan) {
    o += ",\"tool_times\":[";
    bool first = true;
    for (const plan::ToolRow& r : plan.report->tools.rows()) {
        if (!first) o += ',';
        first = false;
        o += "{\"t\":" + std::to_string(r.tool) + ",\"cut\":";
        append_fixed4(o, r.cut_seconds);
        o += ",\"rapid\":";
        append_fixed4(o, r.rapid_seconds);
        o += ",\"passes\":" + std::to_string(r.passes) + ",\"cut_length\":";
        append_fixed4(o, r.cut_length);
        const long n = plan::parts_per_edge(r.cut_seconds, plan.life.of(r.tool));
        o += ",\"parts_per_edge\":" + (n > 0 ? std::to_string(n) : std::string("null")) + '}';
    }
    o += ']';
}
}  // namespace

std::string summary_json(const Interpreter& in, const std::string& file,
                         const std::vector<Diag>& more, std::string_view fields,
                         const PlanSummary& plan) {
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
    append_fixed4(o, plan.report ? plan.report->seconds : in.seconds());
    if (plan.report) {
        o += ",\"feed_time\":";
        append_fixed4(o, plan.report->feed_seconds);
    }
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
    o += ']';
    if (plan.report) tool_times_json(o, plan);
    o += ",\"L\":{";
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
