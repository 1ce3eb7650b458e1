// The HELP page: the modes with their English names, then every key binding
// and every command, generated from the bindings and commands tables so that
// it can never disagree with them.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/pages.hpp"

namespace pupitre::pages {

void page_help(const View& v, Canvas& c, const Rect& r) {
    c.rule(r.y, "HELP  keys and commands (PgUp/PgDn scroll)");
    std::vector<Line> lines;
    lines.push_back(Line{}.add(" Modes (F8 cycles through them, :mode NAME selects one)", Style::title));
    const Mode modes[] = {Mode::automatic, Mode::single, Mode::dry, Mode::test, Mode::rns,
                          Mode::imd,       Mode::jog,    Mode::inc, Mode::pom};
    for (Mode m : modes)
        lines.push_back(Line{}.add("   " + pad(std::string(mode_name(m)), 9), Style::value).add(std::string(mode_english(m))));
    std::string section;
    for (const HelpLine& h : v.help) {
        bool cmd = !h.key.empty() && h.key[0] == ':';
        std::string want = cmd ? "Commands (type them on the input line)" : "Keys";
        if (want != section) {
            section = want;
            lines.push_back(Line{});
            lines.push_back(Line{}.add(" " + section, Style::title));
        }
        Line l;
        l.add("   " + pad(h.key, cmd ? 22 : 12), Style::value).add(h.what);
        if (!h.when.empty()) l.add("  (" + h.when + ")", Style::dim);
        lines.push_back(std::move(l));
    }
    if (!v.store_path.empty()) {
        lines.push_back(Line{});
        lines.push_back(Line{}.add(" Store: ", Style::dim).add(v.store_path));
    }
    lines.push_back(Line{}.add(" Manual: man pupitre (the console), man pupitre-iso (the NUM dialect)", Style::dim));
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
