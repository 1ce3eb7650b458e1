// The ALARM page: the alarm in force with its NUM number, the manual's text
// (data/errors.tsv) and where it was raised; the last messages in full; then
// the earlier alarms, newest first.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cstdio>

#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

std::string explain(int code) {
    std::string_view t = code >= 1000 ? pupitre_diag_text(code) : num_error_text(code);
    if (!t.empty()) return std::string(t) + (code >= 1000 ? tr(" (pupitre(1), DIAGNOSTICS)") : "");
    return code >= 1000 ? tr("pupitre diagnostic (see pupitre(1), DIAGNOSTICS)") : "";
}

}  // namespace

// Where an alarm was raised: "%300 line 12 N20", "IMD line 3", or the
// manual mode (JOG, INC) of a crash that comes from no block.
std::string alarm_place(const Diag& d) {
    if (d.file == "JOG" || d.file == "INC") return d.file;  // a manual move's crash
    std::string s =
        d.file == "IMD" || d.program < 0 ? std::string("IMD") : "%" + std::to_string(d.program);
    if (d.line > 0) s += " " + strf(tr("line %d"), d.line);
    if (d.n >= 0) s += " N" + std::to_string(d.n);
    return s;
}

void page_alarm(const View& v, Canvas& c, const Rect& r) {
    const Sim& s = *v.sim;
    const auto& all = s.alarms();
    // TRANSLATORS: the ALARM page's title: ALARM is the page's name.
    c.rule(r.y, strf(tr("ALARM  %zu since power-on"), all.size()));
    std::vector<Line> lines;
    if (s.alarm_active()) {
        const Diag& d = all.back().diag;
        lines.push_back(Line{}
                            .add(" " + strf(tr("ALARM %d"), d.code), Style::alarm)
                            .add("   " + alarm_place(d), Style::value));
        for (const std::string& l : wrap_text(explain(d.code), std::max(20, r.w - 4)))
            lines.push_back(Line{}.add("   " + l, Style::normal));
        for (const std::string& l : wrap_text(d.detail, std::max(20, r.w - 4)))
            lines.push_back(Line{}.add("   " + l, Style::value));
        lines.push_back(
            Line{}.add(std::string("   ") + tr("RAZ (F12 or :raz) acknowledges it."), Style::dim));
    } else {
        lines.push_back(Line{}.add(std::string(" ") + tr("No alarm in force."), Style::dim));
    }
    lines.push_back(Line{});
    // The message line in full (it cuts a long one with a mark).
    if (v.messages && !v.messages->empty()) {
        lines.push_back(Line{}.add(std::string(" ") + tr("Messages (newest first)"), Style::title));
        for (size_t i = 0; i < std::min<size_t>(v.messages->size(), 10); ++i)
            add_wrapped(lines, Line{}.add("   "), (*v.messages)[i], r.w - 1);
        lines.push_back(Line{});
    }
    // The warnings of the last run: what ran instead of what was written.
    if (s.run_warning_count() > 0) {
        lines.push_back(Line{}.add(
            " " + strf(tr("Warnings of the last run (%zu)"), size_t(s.run_warning_count())),
            Style::title));
        for (const Diag& w : s.run_warnings()) {
            add_wrapped(lines,
                        Line{}
                            .add("   " + lpad(std::to_string(w.code), 4), Style::value)
                            .add("  " + pad(alarm_place(w), 22), Style::value),
                        explain(w.code), r.w - 1);
            for (const std::string& l : wrap_text(w.detail, std::max(20, r.w - 10)))
                lines.push_back(Line{}.add("         " + l, Style::dim));
        }
        if (s.run_warning_count() > s.run_warnings().size())
            lines.push_back(
                Line{}.add("   " + strf(tr("and %zu more (pupitre check lists them all)"),
                                        size_t(s.run_warning_count() - s.run_warnings().size())),
                           Style::dim));
        lines.push_back(Line{});
    }
    if (!all.empty())
        lines.push_back(Line{}.add(std::string(" ") + tr("History (newest first)"), Style::title));
    for (size_t i = all.size(); i-- > 0;) {
        const Alarm& a = all[i];
        char t[32];
        std::snprintf(t, sizeof t, "%9.1f s", a.clock);
        add_wrapped(lines,
                    Line{}
                        .add(" " + std::string(t) + "  ", Style::dim)
                        .add(lpad(std::to_string(a.diag.code), 4), Style::alarm)
                        .add("  " + pad(alarm_place(a.diag), 22), Style::value),
                    explain(a.diag.code), r.w - 1);
        add_wrapped(lines, Line{}.add(std::string(19, ' ')), a.diag.detail, r.w - 1, Style::dim);
    }
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
