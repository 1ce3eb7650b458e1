// Internal to the interpreter: a block's words resolved into values, in internal
// units (mm, lathe X as a radius), ready for the execution steps of turning.md
// §1.7.5: assignments, modal changes, avant M, motion, dwell, après M, flow.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <bitset>

#include "core/interp/interp.hpp"

namespace pupitre {

struct Interpreter::Plan {
    // G functions seen, by number (the modal ones keep the last of their group).
    std::bitset<1000> g;
    int motion = -1, dist = -1, plane = -1, radcomp = -1, prefdec = -1, feed_mode = -1;
    int spindle_mode = -1, units = -1, scale = -1, cycle = -1;

    // Axis words (default meaning): value and whether it is incremental.
    std::bitset<kAxes> axis;
    Axes val{};
    std::bitset<kAxes> inc;
    // Centre / intermediate point / pitch words I J K (index 0 1 2).
    std::bitset<3> ijk;
    double ijk_val[3] = {0, 0, 0};
    std::bitset<3> ijk_inc;
    bool has_r = false;      // arc radius
    double r = 0;
    int r_sign = 0;          // R+ / R- in G0/G1: +1 / -1
    bool has_f = false;
    double f = 0;
    bool has_s = false;
    double s = 0;
    bool has_t = false;
    int t = 0;
    bool has_d = false;
    int d = 0;
    int m[8];
    int nm = 0;
    bool has_ed = false;
    double ed = 0;
    bool has_eg = false;
    double eg = 0;
    bool has_ec = false;
    double ec = 0;
    bool em = false;  // EM+/EM-: the axis words are graphic extremes
    std::bitset<3> g29_has;       // G29: P Q R given
    double g29_n[3] = {0, 0, 0};  // the surface normal

    // Arguments of functions that own words.
    double dwell = -1;                    // G4 F
    std::bitset<kAxes> g92_axis;          // G92 X.. preset
    Axes g92_val{};
    bool g92_s = false, g92_r = false;
    double g92_s_val = 0, g92_r_val = 0;
    std::bitset<kAxes> g59_axis;
    Axes g59_val{};
    std::bitset<3> g59_ijk;
    double g59_ijk_val[3] = {0, 0, 0};
    bool g59_ed = false;
    double g59_ed_val = 0;
    std::bitset<kAxes> g51_on, g51_off;
    int g16_axis = -1;
    bool g16_neg = false;
    bool g96_x = false;
    double g96_x_val = 0;
    bool g96_s = false, g97_s = false;
    bool g94_f = false;                   // F given after G93/G94/G95
    int g77_h = -1;
    long g77_n[2] = {-1, -1};
    int g77_nn = 0;
    int g77_s = 1;
    int g77_level = 0;
    long g79_n = -1;
    char g79_sign = 0;                    // G79+ / G79-: preparation barrier, no effect here
    long g75_n = -2;                      // -2: absent
    long g10_n = -1;
    bool g78_p = false;
    char g76_sign = 0;                    // G76+ / G76-
    int g76_h = -1;
    long g76_n[2] = {-1, -1};
    int g76_nn = 0;
    // Words of a drilling cycle (G81-G89, G31): ER EH EF P Q ES EP EC EA K EK, and
    // F in G31 (number of starts).
    struct CycWord {
        Addr a;
        double v;
    };
    CycWord cyc[16];
    int ncyc = 0;
    bool cycle_words = false;             // the block is read with a cycle active
    int spl_nc = -1, spl_h = -1;          // G48 / G06 / G49: curve, program
    long spl_n[2] = {-1, -1};
    int spl_nn = 0;
    int unsupported = -1;                 // first G that pupitre does not run yet
    Addr unsupported_word = 0;            // or first word of a function not run yet
    bool has_unsupported_word = false;
    // Profile geometry programming words (pgp.md §2).
    bool pgp = false;                     // any of EA EB ES ET E± in the block
    bool has_ea = false;
    double ea = 0;
    char link = 0;                        // 'S' (ES) or 'T' (ET)
    int disc = 0;                         // +1 / -1 from E+ E- ES+ ET-
    bool has_eb = false, eb_unsigned = false;
    double eb = 0;
};

}  // namespace pupitre
