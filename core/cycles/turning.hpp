// Turning cycles as functions from arguments to elementary moves
// (ARCHITECTURE.md, Conventions): G64 paraxial roughing, G65 groove roughing,
// G66 plunge roughing, G63 roughing with grooves, G33 threading, G38 chained
// threading (pupitre-iso(5), TURNING CYCLES). Pure geometry in the lathe plane
// with abscissa Z and ordinate X as a radius (internal units); the interpreter
// extracts profiles and stock from the program and emits the moves.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/diag.hpp"
#include "core/geometry/comp.hpp"

namespace pupitre::turning {

using V2 = comp::V2;  // (z, r)

// One elementary move of a cycle: rapid (0), feed (1) or arc (2, 3) to `to`.
// g 33 is a spindle-synchronised threading move (G33, G38): its lead is the
// cycle's K along the threading axis, overrides are inactive.
struct Move {
    int g = 0;
    V2 to{0, 0};
    V2 c{0, 0};           // arc centre
    double sweep = 0;     // arc, radians, positive counter-clockwise in (z, r)
    double dwell = 0;     // seconds to wait after the move (0: none)
    int spindle = 0;      // threading: 0, or 3/4 to reverse the spindle after the move
    bool infeed = false;  // g 1 at the infeed feed EF (G65, G63) instead of F
};

// A finished profile as called (N<a> N<b> in the order written), resolved into
// lines and arcs (PGP and fillets already applied).
struct Profile {
    std::vector<comp::Elem> elems;
};

// Each cycle answers an Error (diag.hpp), empty on success. `out` receives
// the moves in order from the tool position `tool` (the last programmed point
// before the cycle, in the active corrector's terms); the cycles never see a
// diameter: X words reach them as radii. Errors the caller raises itself: 140
// (G64/G65/G63/G66 in G41/G42), 830 (no known position), 96 (L100-L199 or
// L900-L959 in the profile), 4 (EP), 2 (G63 on a 1020), 76/895 (G21/G22), 8
// (D above 255). After every roughing cycle the motion state is G00.

// G64 N<a> N<b> [I..] [K..] P.. | R.. [F..], then the stock blocks until G80
// (000:2434-2458; pupitre-iso(5), TURNING CYCLES). `stock` lists the stock
// points in the order written.
struct G64Args {
    double i = 0, k = 0;  // allowances along X (radius) and Z, signed
    bool has_p = false, has_r = false;
    double p = 0, r = 0;     // depth of cut: P along X (passes along Z), R along Z
    double clearance = 1.0;  // configuration item cycle_clearance, mm
    // Out: the allowance points into the part (a positive I on a bore); the
    // passes cut it as written, into the part (docs/decisions.md, Roughing allowances
    // are signed; warning 1116).
    mutable bool allowance_inside = false;
};
Error g64(const Profile& finished, const std::vector<V2>& stock, V2 tool, const G64Args& a,
          std::vector<Move>& out);

// G65 N<a> N<b> X.. | Z.. [I..] [K..] EA.. P.. | R.. [Q..] [EF..] [F..] (000:2587-2612).
struct G65Args {
    bool has_x = false, has_z = false;
    double x = 0, z = 0;  // end of the passes: Z with P (axial), X with R (frontal)
    double i = 0, k = 0;
    bool has_ea = false;
    double ea = 0;  // infeed angle, degrees from +Z
    bool has_p = false, has_r = false;
    double p = 0, r = 0;
    double q = 0;  // clearance; <= 0: the configured one
    double clearance = 1.0;
    // Out: the allowance points into the groove's bottom; the passes cut it as
    // written (warning 1116).
    mutable bool allowance_inside = false;
};
Error g65(const Profile& finished, V2 tool, const G65Args& a, std::vector<Move>& out);

// G63 N<a> N<b> X.. Z.. EX.. | EZ.. P.. | R.. [EA.. | EU.. EW..] [EB..] [EC..] [ER..]
// [Q..] [EQ..] [EF..] (000:2634-2707, 1040/1060).
struct G63Args {
    bool has_x = false, has_z = false;
    double x = 0, z = 0;  // start point D (radius, Z)
    bool has_ex = false, has_ez = false;
    double ex = 0, ez = 0;  // end of the passes: EZ with P, EX with R
    bool has_p = false, has_r = false;
    double p = 0, r = 0;
    bool has_ea = false, has_eu = false, has_ew = false;
    double ea = 0, eu = 0, ew = 0;  // start line angle; limit point of the last pass (EU radius)
    bool has_eb = false, has_ec = false;
    double eb = 90, ec = 0;  // groove entry limit angle; end-of-pass angle (degrees)
    double er = 0;           // finishing allowance, normal to the profile
    double q = 0;            // clearance; <= 0: the configured one
    double eq = 0;           // minimum chip
    double clearance = 1.0;
};
Error g63(const Profile& finished, V2 tool, const G63Args& a, std::vector<Move>& out);

// G66 D.. X.. Z.. [EA..] P.. | R.. [EP..] [EF..] [F..] (000:2791-2840). The moves are in the
// terms of the first corrector (the one active at the call); after the cycle the
// second corrector `d` is active and the tool stands at (Z of B, X of A) in its
// terms.
struct G66Args {
    int d_first = 0;            // the active corrector (0: none, error 898)
    int d = 0;                  // the second corrector (0: not programmed, error 898)
    V2 gauge_delta{0, 0};       // gauge of D(d) minus gauge of D(d_first), (Z, X radius)
    bool milling_tool = false;  // error 864
    bool has_x = false, has_z = false;
    double x = 0, z = 0;  // end point B, in the second corrector's terms
    double ea = 0;        // slope of the groove bottom, degrees
    bool has_p = false, has_r = false;
    double p = 0, r = 0;  // distance between plunges: P frontal, R radial groove
    double ep = 0;        // 45° move at the end of each plunge, mm
    double ef = 0;        // dwell at the bottom of each plunge, s
};
Error g66(V2 tool, const G66Args& a, std::vector<Move>& out);

// G33 X.. Z.. K.. [EA..] [EB..] P.. [Q..] [R..] [F..] [S.. | ES..] (000:3194-3222). The S of
// the block is a number of passes here, not a spindle speed.
struct G33Args {
    bool has_x = false, has_z = false;
    double x = 0, z = 0;  // end of the thread (radius, Z)
    bool has_k = false;
    double k = 0;   // lead along the threading axis
    double ea = 0;  // half apex angle; ±90: face thread
    double eb = 0;  // infeed angle
    bool has_p = false;
    double p = 0;  // total depth, Q included
    bool has_q = false;
    double q = 0;  // last pass; programmed Q0: a spring pass
    double r = 0;  // exit slope length along the threading axis
    bool has_f = false;
    double f = 1;  // number of starts
    bool has_s = false, has_es = false;
    double s = 1, es = 1;         // passes: degressive (S) or constant (ES)
    bool spindle_turning = true;  // error 831 when false
    bool plane_ok = true;         // G18/G20 active; error 836 when false
    bool radius_comp = false;     // G41/G42 active; error 27
};
Error g33(V2 tool, const G33Args& a, std::vector<Move>& out);

// G38 X.. Z.. [K..] (000:3270-3294): one synchronised move per block, chained. `prev_k` is
// the lead of the previous G38 block (0 when this block starts a chain); the lead
// used is k when given, else prev_k.
struct G38Args {
    V2 to{0, 0};  // end of this segment (radius, Z)
    bool has_k = false;
    double k = 0;
    double prev_k = 0;
    bool spindle_turning = true;
    bool radius_comp = false;
};
Error g38(V2 tool, const G38Args& a, std::vector<Move>& out);

// The threading axis of a synchronised move from `from` to `to` (G38: the one with
// the larger displacement): 0 for Z, 1 for X. The feed is the lead times the
// spindle speed along that axis.
int thread_axis(V2 from, V2 to);

}  // namespace pupitre::turning
