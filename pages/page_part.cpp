// The PART page (see page_part.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/page_part.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pages/pages.hpp"
#include "pages/view.hpp"

namespace pupitre::pages {

namespace {

constexpr int kBar = 24;  // the colour scale's cells

std::string number(double v, bool sign) {
    char buf[32];
    std::snprintf(buf, sizeof buf, sign ? "%+g" : "%g", v);
    return buf;
}

// The colour scale: its cells, then its ends' numbers and what it shows
// (shorter when the room is short).
void legend_line(const PartView& p, Canvas& c, int x, int y, int w) {
    const render::Legend& l = p.legend;
    const bool dev = l.paint == render::Paint::deviation;
    int at = x + 1;
    if (p.colours != Colours::none && !c.ascii()) {
        for (int k = 0; k < kBar; ++k)
            c.paint(at + k, y, U' ', kNoColour,
                    terminal_colour(render::legend_sample(l, k, kBar), p.colours));
        at += kBar + 1;
    }
    const std::string ends = dev ? number(-l.span_um, true) + " … " + number(l.span_um, true)
                                 : "0 … " + number(l.depth, false);
    std::string words;
    if (dev)
        // TRANSLATORS: the PART page's colour scale: deviations from the drawing in µm.
        words = p.numbers ? strf(tr("%s µm from the drawing: green in tolerance, red over, blue "
                                    "under, grey not dimensioned"),
                                 ends.c_str())
                          : std::string(tr("from the drawing: green in tolerance, red over, blue "
                                           "under"));
    else
        // TRANSLATORS: the PART page's colour scale: depth below the stock as loaded.
        words = p.numbers ? strf(tr("depth below the stock: %s mm; grey uncut"), ends.c_str())
                          : std::string(tr("depth below the stock; grey uncut"));
    if (columns(words) > x + w - at && p.numbers)
        // TRANSLATORS: the PART page's colour scale when the room is short.
        words = dev ? strf(tr("%s µm: green ok, red over, blue under"), ends.c_str())
                    : strf(tr("depth %s mm"), ends.c_str());
    c.text(at, y, words, Style::dim, x + w - at);
}

void info(const PartView& p, Canvas& c, const Rect& r) {
    const int y0 = r.y + r.h - p.info;
    legend_line(p, c, r.x, y0, r.w);
    const size_t room = size_t(std::max(1, p.info - 1));
    std::vector<PartLine> lines = p.lines;
    if (lines.size() > room) {
        const size_t more = lines.size() - (room - 1);
        lines.resize(room - 1);
        lines.push_back(
            {kNoColour, strf(tr("and %zu more: :part export FILE puts them on paper"), more)});
    }
    if (lines.size() < room) lines.push_back({kNoColour, p.keys});
    for (size_t i = 0; i < lines.size(); ++i) {
        const int y = y0 + 1 + int(i);
        int x = r.x + 1;
        if (lines[i].swatch != kNoColour) {
            if (p.colours != Colours::none && !c.ascii())
                c.paint(x, y, U'\u25a0', terminal_colour(lines[i].swatch, p.colours), kNoColour);
            else
                c.put(x, y, U'*');
            x += 2;
        }
        c.text(x, y, lines[i].text, lines[i].swatch == kNoColour ? Style::dim : Style::value,
               r.x + r.w - x);
    }
}

}  // namespace

int part_info(size_t lines) {
    return 1 + int(std::clamp<size_t>(lines + 1, 2, 5));
}

Rect part_area(const Rect& page, int info) {
    return Rect{page.x, page.y + 1, page.w, std::max(1, page.h - 1 - info)};
}

void page_part(const View& v, Canvas& c, const Rect& r) {
    const PartView& p = v.part;
    // TRANSLATORS: the PART page's title; PART is the page's name.
    c.rule(r.y, p.title.empty() ? std::string(tr("PART")) : strf(tr("PART  %s"), p.title.c_str()));
    const Rect a = part_area(r, p.info);
    if (!p.workshop) {
        std::vector<Line> lines;
        add_wrapped(lines, Line{}.add(" "),
                    v.sim->machine().lathe
                        ? tr("No workshop: :setup lathe puts a bar in the chuck; the part "
                             "cut shows here, in colour.")
                        : tr("No workshop: :setup mill puts a block in the vice; the part "
                             "cut shows here, in colour and in 3-D."),
                    r.w - 1, Style::dim);
        draw_lines(lines, 0, c, a);
        return;
    }
    if (p.cells) put_cells(*p.cells, c, a.x, a.y);
    if (!p.note.empty()) c.text(a.x + 1, a.y, p.note, Style::warn, a.w - 2);
    info(p, c, r);
}

uint32_t terminal_colour(render::Colour c, Colours colours) {
    const int r = int(render::red(c)), g = int(render::green(c)), b = int(render::blue(c));
    if (colours == Colours::direct) return rgb_colour(unsigned(r), unsigned(g), unsigned(b));
    if (colours == Colours::c256) {
        auto level = [](int v) { return v < 48 ? 0 : v < 115 ? 1 : (v - 35) / 40; };
        return palette_colour(unsigned(16 + 36 * level(r) + 6 * level(g) + level(b)));
    }
    // The ANSI colours: a bit for each of red, green and blue, bright when strong.
    const int bits = (r > 100 ? 1 : 0) | (g > 100 ? 2 : 0) | (b > 100 ? 4 : 0);
    const bool bright = std::max({r, g, b}) > 200 && colours == Colours::c16;
    return palette_colour(unsigned(bits + (bright ? 8 : 0)));
}

}  // namespace pupitre::pages
