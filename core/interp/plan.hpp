// Internal to the interpreter: a block's words resolved into values, in
// internal units (mm, lathe X as a radius), ready for the execution steps of
// pupitre-iso(5), MODAL STATE AND THE ORDER INSIDE A BLOCK: assignments, modal
// changes, avant M, motion, dwell, après M, flow. One struct per family of
// words: the modal groups, the target (axes, centre, radius), the technology
// words (F S T D M), then the arguments each G function owns, read by the
// readers of interp_args.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <bitset>
#include <utility>

#include "core/interp/interp.hpp"

namespace pupitre {

// Axis words: which, and their values.
struct Interpreter::AxisValues {
    std::bitset<kAxes> axis;
    Axes val{};
};
// Axis words in their default meaning, the centre / intermediate point /
// pitch words I J K (index 0 1 2) and the arc radius: all a move reads of its
// block, so that the plain blocks' lane (interp_fast.cpp) needs no Plan.
struct Interpreter::Target : AxisValues {
    std::bitset<kAxes> inc;  // the value is incremental
    std::bitset<3> ijk;
    double ijk_val[3] = {0, 0, 0};
    std::bitset<3> ijk_inc;
    bool has_r = false;
    double r = 0;
    int r_sign = 0;   // R+ / R- in G0/G1: +1 / -1
    bool em = false;  // EM+/EM-: the axis words are graphic extremes
};

// The words of a plain block (interp_fast.cpp), kept from one block to the
// next: clearing its flags is a few stores where a fresh one was 168 bytes
// zeroed a block (issue 14). A value is read only where its flag is set.
struct Interpreter::PlainBlock {
    Target to;
    int g = -1;  // the G written, -1: none
    bool has_f = false;
    double f = 0;
    void clear() {
        to.axis.reset();
        to.inc.reset();
        to.ijk.reset();
        to.ijk_inc.reset();
        to.has_r = false;
        g = -1;
        has_f = false;
    }
};

struct Interpreter::Plan {
    // The modal groups the block sets; -1: not coded (the last G of a group wins).
    struct Modes {
        int motion = -1, dist = -1, plane = -1, radcomp = -1, prefdec = -1, feed = -1;
        int spindle = -1, units = -1, scale = -1, cycle = -1;
        // G `number` of modal group `group` (both dialects' decoders); a
        // group that keeps no mode is ignored.
        void set(Group group, int number) {
            static constexpr std::pair<Group, int Modes::*> kFields[] = {
                {Group::motion, &Modes::motion},   {Group::dist, &Modes::dist},
                {Group::plane, &Modes::plane},     {Group::radcomp, &Modes::radcomp},
                {Group::prefdec, &Modes::prefdec}, {Group::feed, &Modes::feed},
                {Group::spindle, &Modes::spindle}, {Group::units, &Modes::units},
                {Group::scale, &Modes::scale},     {Group::cycle, &Modes::cycle}};
            for (const auto& [grp, field] : kFields)
                if (grp == group) this->*field = number;
        }
    };
    // Technology words: feed, speed, tool, corrector, M functions, ED EG EC.
    struct Tech {
        bool has_f = false;
        double f = 0;
        bool f_with_mode = false;  // F given in a block with G93/G94/G95
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
    };
    // G29: the surface normal P Q R.
    struct G29Args {
        std::bitset<3> has;
        double n[3] = {0, 0, 0};
    };
    // G92: axis presets, S speed limit, R.
    struct G92Args : AxisValues {
        bool has_s = false, has_r = false;
        double s = 0, r = 0;
    };
    // G59: origin offset on axes, I J K, ED.
    struct G59Args : AxisValues {
        std::bitset<3> ijk;
        double ijk_val[3] = {0, 0, 0};
        bool has_ed = false;
        double ed = 0;
    };
    struct G51Args {
        std::bitset<kAxes> on, off;  // mirrored axes
    };
    struct G16Args {
        int axis = -1;
        bool neg = false;
    };
    // G96 X (the diameter for the speed), S with G96 or G97.
    struct SpindleArgs {
        bool has_x = false;
        double x = 0;
        bool g96_s = false, g97_s = false;
    };
    // A range of blocks of a program: Hprogram, N first, N last.
    struct BlockRange {
        int h = -1;
        long n[2] = {-1, -1};
        int nn = 0;  // N words read
    };
    struct G77Args : BlockRange {
        int s = 1;  // repetitions
        int level = 0;
    };
    struct G76Args : BlockRange {
        char sign = 0;  // G76+ / G76-
    };
    struct SplineArgs : BlockRange {
        int nc = -1;  // G48 / G06 / G49: the curve
    };
    // Jumps and labels.
    struct FlowArgs {
        long g79_n = -1;
        char g79_sign = 0;  // G79+ / G79-: preparation barrier, no effect here
        long g75_n = -2;    // -2: absent
        long g10_n = -1;
        bool g78_p = false;
    };
    // Words of a cycle (G81-G89, G31): ER EH EF P Q ES EP EC EA K EK, and F in
    // G31 (number of starts).
    struct CycleWords {
        struct Word {
            Addr a;
            double v;
        };
        Word word[16];
        int n = 0;
        bool active = false;  // the block is read with a cycle active
    };
    // The first function pupitre does not run yet.
    struct Unsupported {
        int g = -1;     // first G that pupitre does not run yet
        Addr word = 0;  // or first word of a function not run yet
        bool has_word = false;
    };
    // Profile geometry programming words (000:8378-8388; pupitre-iso(5),
    // PROFILE GEOMETRY PROGRAMMING (PGP)).
    struct PgpArgs {
        bool any = false;  // any of EA EB ES ET E± in the block
        bool has_ea = false;
        double ea = 0;
        char link = 0;  // 'S' (ES) or 'T' (ET)
        int disc = 0;   // +1 / -1 from E+ E- ES+ ET-
        bool has_eb = false, eb_unsigned = false;
        double eb = 0;
    };

    std::bitset<1000> g;  // G functions seen, by number
    Modes mode;
    Target to;
    Tech tech;
    double dwell = -1;  // G4 F
    G29Args g29;
    G92Args g92;
    G59Args g59;
    G51Args g51;
    G16Args g16;
    SpindleArgs spindle;
    G77Args g77;
    G76Args g76;
    SplineArgs spline;
    FlowArgs flow;
    CycleWords cycle_words;
    Unsupported unsupported;
    PgpArgs pgp;
};

}  // namespace pupitre
