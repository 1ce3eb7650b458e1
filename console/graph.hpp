// The GRAPH page's window (console/graph.cpp): the toolpath of the last run or
// TEST, the window the page shows of it (zoom, pan, cursor, plane) and the
// workshop's part placed where the program frame puts it. The Session feeds
// it the GRAPH keys and asks it for the page's part of each frame.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/output/toolpath.hpp"
#include "core/sim/sim.hpp"
#include "pages/canvas.hpp"
#include "pages/view.hpp"

namespace pupitre::console {

class GraphWindow {
  public:
    // `m` outlives the window (the Session's own copy).
    explicit GraphWindow(const MachineProfile& m);

    // The toolpath the Sim records into.
    Toolpath& path() { return path_; }
    const Toolpath& path() const { return path_; }
    // The window as the keys left it (the page's is fill()'s).
    const pages::GraphView& window() const { return g_; }

    // A GRAPH key, "zoom in", "pan left", "cursor up", "fit", "plane", on
    // the window `shown` (fill()'s) in the page's `area`. Returns the news for
    // the message line, "" when none.
    std::string key(std::string_view what, std::string_view arg, pages::Rect area,
                    pages::GraphView shown);

    // The page's window of this frame, into v.graph: the path, the tool where
    // it is over the part, the part (on the GRAPH page only). `no_readout`: an
    // exercise, where no coordinates are read off the drawing (the truth).
    void fill(pages::View& v, const Sim& sim, bool graph_page, bool no_readout) const;

  private:
    void place_part(const Sim& sim) const;

    const MachineProfile& m_;
    Toolpath path_;
    pages::GraphView g_;
    bool plane_chosen_ = false;
    mutable pages::GraphCache cache_;
    mutable Axes tool_now_{};
    using Outlines = std::vector<std::vector<std::array<double, 2>>>;
    mutable Outlines part_now_;   // the workshop's part
    mutable Outlines chuck_now_;  // and its chuck and tailstock
};

}  // namespace pupitre::console
