// Each tool's time in a part (issue 35): cutting and rapid time, passes and
// the length cut, and from the life of an edge, after how many parts the edge
// must be changed, as the Cazeneuve thesis tabulates it (003:2320-2420).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::plan {

struct ToolRow {
    int tool = 0;
    double cut_seconds = 0;    // feed moves (G1, G2, G3)
    double rapid_seconds = 0;  // rapid moves (G0)
    double cut_length = 0;     // mm (degrees for rotary axes alone) of the feed moves
    long passes = 0;           // runs of feed moves, each after a rapid or a tool change
};

class ToolTable {
  public:
    // A move made with `tool` (0: none loaded): cutting (a feed move) or not.
    // Inline: the planner adds every move (issue 35 item 7).
    void add(int tool, bool cut, double length, double seconds) {
        const bool begins = cut && !last_cut_;
        last_cut_ = cut;
        if (tool <= 0) return;
        ToolRow& r = last_ < rows_.size() && rows_[last_].tool == tool ? rows_[last_] : row(tool);
        if (cut) {
            r.cut_seconds += seconds;
            r.cut_length += length;
            r.passes += begins;
        } else {
            r.rapid_seconds += seconds;
        }
    }
    // A tool change: the next cut begins a pass.
    void change() { last_cut_ = false; }
    // In the order of first use; tool 0 (moves before any tool) is left out.
    const std::vector<ToolRow>& rows() const { return rows_; }

  private:
    ToolRow& row(int tool);  // the tool's row, made on its first move
    std::vector<ToolRow> rows_;
    size_t last_ = 0;  // the row of the last move's tool
    bool last_cut_ = false;
};

// The life of an edge in seconds of cutting, one for every tool unless a tool
// has its own (pupitre(1), --edge-life); 0: not given.
struct EdgeLife {
    double all = 0;
    std::map<int, double> tool;
    double of(int t) const {
        auto it = tool.find(t);
        return it != tool.end() ? it->second : all;
    }
    bool any() const { return all > 0 || !tool.empty(); }
};

// Reads one --edge-life: MINUTES for every tool, or TN=MINUTES for tool N.
// Empty on success, else what is wrong.
std::string read_edge_life(std::string_view text, EdgeLife& life);

// The parts an edge lasts: its life over a part's cutting time, rounded down
// (the edge is changed before it is worn out). 0 when either is not known.
long parts_per_edge(double cut_seconds, double life_seconds);

}  // namespace pupitre::plan
