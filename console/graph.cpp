// The GRAPH page's keys: zoom about the cursor, pan, fit, plane, cursor (the
// pure functions of pages/page_graph.hpp applied to the session's window).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>
#include <string>

#include "console/session.hpp"
#include "core/i18n.hpp"

namespace pupitre::console {

Effect Session::graph_key(std::string_view what, std::string_view arg) {
    pages::Rect area{0, 1, cols, rows - 4};
    pages::GraphView g = view().graph;
    auto dir = [&](int& dx, int& dy) {
        dx = arg == "left" ? -1 : arg == "right" ? 1 : 0;
        dy = arg == "up" ? 1 : arg == "down" ? -1 : 0;
    };
    if (what == "zoom") {
        g = pages::graph_zoom(g, area, arg == "in" ? 2.0 : 0.5);
    } else if (what == "pan") {
        int dx, dy;
        dir(dx, dy);
        g = pages::graph_pan(g, area, 0.25 * dx, 0.25 * dy);
    } else if (what == "cursor") {
        int dx, dy;
        dir(dx, dy);
        g = pages::graph_move_cursor(g, area, dx, -dy);
    } else if (what == "fit") {
        g = pages::graph_fit(g);
        say(strf(tr("fit: %s"), pages::graph_fit_words(g).c_str()));
    } else if (what == "plane") {
        g = pages::graph_next_plane(g, m_);
        graph_plane_chosen = true;
        say(strf(tr("plane %s"), std::string(plane_name(g.plane)).c_str()));
    }
    g.path = nullptr;
    g.tool = nullptr;
    g.cache = nullptr;
    graph = g;
    return Effect::redraw;
}

}  // namespace pupitre::console
