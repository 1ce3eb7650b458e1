// The PARAM page: the L variables (L0-L19 local, L100-L199 global) and the E
// parameters the programs wrote. Values are entered on the input line as
// `L5=2` or `E80000=18000` (the same names as --set); the interpreter says
// which ones the manual lets an operator write.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>

#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

void l_block(std::vector<Line>& lines, const LVars& l, int from, int to, int cols) {
    for (int n = from; n <= to; n += cols) {
        Line line;
        line.add(" ");
        for (int k = 0; k < cols && n + k <= to; ++k) {
            int i = n + k;
            line.add(pad("L" + std::to_string(i), 6), Style::dim);
            line.add(pad(num(l.v[size_t(i)]), 12),
                     l.written[size_t(i)] ? Style::value : Style::normal);
        }
        lines.push_back(std::move(line));
    }
}

}  // namespace

void page_param(const View& v, Canvas& c, const Rect& r) {
    const Interpreter& in = v.sim->interp();
    // TRANSLATORS: the PARAM page's title: PARAM is the page's name.
    c.rule(r.y, tr("PARAM  L variables and E parameters"));
    std::vector<Line> lines;
    if (is_caz(v.sim->machine())) {
        for (const auto& part :
             wrap_text(tr("This controller has no L variables and no E parameters "
                          "(pupitre-cazeneuve(5)): nothing to set here."),
                       r.w - 2))
            lines.push_back(Line{}.add(" " + part, Style::dim));
        draw_lines(lines, 0, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
        return;
    }
    lines.push_back(Line{}.add(
        std::string(" ") + tr("Type L5=2 or E80000=18000 to set a value; PgUp/PgDn scroll."),
        Style::dim));
    int cols = r.w >= 100 ? 6 : 4;
    lines.push_back(Line{}.add(std::string(" ") + tr("Local variables L0-L19"), Style::title));
    l_block(lines, in.lvars(), 0, 19, cols);
    lines.push_back(Line{}.add(std::string(" ") + tr("Global variables L100-L199"), Style::title));
    l_block(lines, in.lvars(), 100, 199, cols);
    lines.push_back(
        Line{}.add(std::string(" ") + tr("E parameters written by the programs"), Style::title));
    if (in.e_written().empty())
        lines.push_back(Line{}.add(std::string("   ") + tr("none yet"), Style::dim));
    for (const auto& [n, val] : in.e_written())
        lines.push_back(Line{}
                            .add("   " + pad("E" + std::to_string(n), 9), Style::dim)
                            .add(std::to_string(val), Style::value));
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
