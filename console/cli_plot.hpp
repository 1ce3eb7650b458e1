// pupitre plot: the toolpath of a dry run drawn as SVG, PNG or PDF (issue 7,
// issue 12.11, pupitre(1), OPTIONS).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

namespace pupitre::cli {

struct PlotArgs {
    std::string machine;             // "": the lathe, as every batch command
    std::string plane;               // xy|xz|yz|zx; "" = the program's (the lathe's ZX)
    std::string svg;                 // output file; "-" for the standard output
    std::string png;                 // the picture as a PNG (Cairo), "" for none
    int png_width = 1600;            // pixels across
    std::string pdf;                 // the picture as a one-page PDF for printing, "" for none
    std::vector<std::string> files;  // the first program of the first file is run
    std::vector<std::string> sets;   // NAME=VALUE, as `run --set`
    bool block_skip = false;
    long max_blocks = 20'000'000;
    std::string setup;  // --setup: the workshop's part drawn under the path
    // --edge-life: the life of an edge for the PDF's table (core/plan/tools.hpp).
    std::vector<std::string> edge_life;
};

// Runs the program to its end (or its first error) and writes the drawing; the
// diagnostics go to stderr as `run` prints them. Exit codes as pupitre(1), EXIT STATUS:
// 0, 1 (the program has errors: what ran is drawn, the error marked), 64, 65,
// 66, 73 (an output cannot be created), 74 (it cannot be written).
int plot(const PlotArgs& a);

}  // namespace pupitre::cli
