// The GRAPH page's window (see graph.hpp): its keys are the pure functions of
// pages/page_graph.hpp applied to the window kept here.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/graph.hpp"

#include <cstdio>
#include <string>

#include "core/i18n.hpp"

namespace pupitre::console {

GraphWindow::GraphWindow(const MachineProfile& m) : m_(m), path_(m) {
    g_.plane = m_.lathe ? PathPlane::zx : PathPlane::xy;
}

std::string GraphWindow::key(std::string_view what, std::string_view arg, pages::Rect area,
                             pages::GraphView g) {
    std::string news;
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
        news = strf(tr("fit: %s"), pages::graph_fit_words(g).c_str());
    } else if (what == "plane") {
        g = pages::graph_next_plane(g, m_);
        plane_chosen_ = true;
        news = strf(tr("plane %s"), std::string(plane_name(g.plane)).c_str());
    }
    g.path = nullptr;
    g.tool = nullptr;
    g.cache = nullptr;
    g_ = g;
    return news;
}

void GraphWindow::fill(pages::View& v, const Sim& sim, bool graph_page, bool no_readout) const {
    v.graph = g_;
    v.graph.path = &path_;
    if (sim.ran_program()) v.graph.seconds = sim.cycle_time();  // the M02 message's
    if (!plane_chosen_ && !path_.empty()) v.graph.plane = path_.default_plane();
    tool_now_ = sim.op();
    // The tool where it is over the part (a C turn, a B tilt), as the path.
    const Axes op_now = tool_now_;
    if (const workshop::Workshop* w = sim.shop()) tool_now_ = w->on_part(sim.om(), op_now);
    v.graph.tool = &tool_now_;
    v.graph.cache = &cache_;
    v.graph.no_readout = no_readout;
    if (sim.shop() && graph_page) {  // only the GRAPH page draws the part
        place_part(sim);
        v.graph.part = &part_now_, v.graph.chuck = &chuck_now_;
        if (const workshop::Workshop* w = sim.shop(); w->is_mill()) {
            // The block where the program frame puts it, as for the lathe's part.
            const workshop::P3 tip = w->tip3(sim.om(), false);
            v.graph.block = w->mill();
            v.graph.block_dx = op_now[X] - tip[0];
            v.graph.block_dy = op_now[Y] - tip[1];
        }
    }
}

// The workshop's part where the program frame puts it: as the tool in use,
// with the gauge and origins entered, would read its points (so a wrong
// PREF shows as a path beside the part, as on the machine).
void GraphWindow::place_part(const Sim& sim) const {
    part_now_.clear();
    chuck_now_.clear();
    const workshop::Workshop* w = sim.shop();
    if (!w || w->is_mill()) return;
    const workshop::Workshop::Frame f = w->part_frame(sim.om(), tool_now_, sim.corrector());
    const double dz = f.dz, dx = f.dx;
    auto place = [&](const workshop::CPaths& from, Outlines& to) {
        for (const workshop::CPath& q : from) {
            to.emplace_back();
            for (const auto& v : q) {
                workshop::Pt p = workshop::to_mm(v);
                to.back().push_back({p[0] + dz, p[1] + dx});
            }
        }
    };
    place(w->world().material(), part_now_);
    place(w->world().chuck(), chuck_now_);
    place(w->world().tailstock(), chuck_now_);
    place(w->world().gauge(), chuck_now_);
}

}  // namespace pupitre::console
