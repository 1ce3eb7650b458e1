// The JSON-lines trace of a run (pupitre(1), OUTPUT, Trace).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/trace.hpp"

#include "core/output/json.hpp"

namespace pupitre {

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
    const bool planned = e.plan_seconds >= 0;
    seconds += planned ? e.plan_seconds : e.seconds;
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
    if (planned) {
        // As the planner made it (core/plan): when it starts, how long it
        // takes, and its highest speed.
        append_fixed4(buf_, e.plan_seconds);
        buf_ += ",\"start\":";
        append_fixed4(buf_, e.plan_start);
        buf_ += ",\"peak\":";
        append_fixed4(buf_, e.plan_peak);
    } else {
        append_fixed4(buf_, e.seconds);
    }
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

void TraceWriter::dwell(const Loc& l, double duration) {
    seconds += duration;
    head("dwell", l);
    buf_ += ",\"t\":";
    append_fixed4(buf_, duration);
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

// "m6": an M06 changed the tool (true) or only the corrector D changed.
void TraceWriter::tool(const Loc& l, int t, int d, double duration, bool m6) {
    seconds += duration;
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
    append_fixed4(buf_, clock_ ? *clock_ : seconds);
    buf_ += "}\n";
    std::fwrite(buf_.data(), 1, buf_.size(), out_);
}

}  // namespace pupitre
