// Internal to the interpreter: the Cazeneuve HB CNC dialect (seed 003,
// chapter VI; pupitre-cazeneuve(5)). Its state beside the NUM modal state,
// the units of its words, and its numbered errors.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

#include "core/interp/interp.hpp"

namespace pupitre {

namespace caz {
// The thesis's error categories (003:798: "la nature [syntaxe, fonction,
// capacité] des erreurs"), numbered 2000-2099, and warnings 2100-2199.
inline constexpr int kSyntax = 2001;          // a character or address this controller lacks
inline constexpr int kNumber = 2002;          // a value written outside its format
inline constexpr int kTwice = 2003;           // an address written twice in a block
inline constexpr int kUnknownG = 2004;        // a G function the thesis does not define
inline constexpr int kUnknownM = 2005;        // an M function the thesis does not define
inline constexpr int kFunction = 2020;        // a function's word missing or misplaced
inline constexpr int kArc = 2021;             // an arc whose centre or end does not fit
inline constexpr int kSpindleStopped = 2022;  // a feed per revolution or a thread, spindle stopped
inline constexpr int kTool = 2023;            // T: no such turret position
inline constexpr int kCss = 2024;             // G96 without S or without a starting X
inline constexpr int kNoEnd = 2025;           // the text ends without M2 or M30
inline constexpr int kCompensation = 2026;    // what the CNP forbids
inline constexpr int kTravelX = 2050;         // capacity: X beyond the travel
inline constexpr int kTravelZ = 2052;         // capacity: Z beyond the travel
inline constexpr int kSpeed = 2053;           // capacity: S in no spindle range
inline constexpr int kPitch = 2054;           // capacity: thread pitch or thread speed too high
inline constexpr int kCorrector = 2055;       // capacity: corrector number
inline constexpr int kLater = 2090;           // defined by the thesis, not run by pupitre yet
inline constexpr int kOther = 2099;           // any other refusal of the shared machinery

// The dialect's number for what the shared (NUM) machinery reports; pupitre's
// own numbers (1000 and up) stay as they are.
int error_of(int num_code);
// The message of a shared step's refusal in this dialect's words, where the
// NUM's would mislead (its M02 and %number); else `detail` as it is.
std::string detail_of(int num_code, std::string detail);
// The category of a dialect error: "syntax", "function", "capacity" or "run".
std::string_view category_of(int code);

// Units of the words (003:1115, 1161, 1330; 003:894; 003:1018).
inline constexpr double kUm = 0.001;            // mm per micrometre
inline constexpr double kDwellUnit = 0.1;       // seconds per unit of G4 F ("F4,1", Fmax 60000)
inline constexpr double kMaxPitch = 60;         // mm (003:1163)
inline constexpr double kMaxThreadFeed = 3800;  // mm/min (003:1162)
}  // namespace caz

// What the dialect keeps beside the NUM modal state, and its fixed cycles
// (interp_caz_cycles.cpp), which reach the interpreter's moves from here.
struct Interpreter::CazState {
    double pitch = 0;  // G33: the last pitch, mm
    int turret = 0;    // the position T last indexed, 0 none
    bool m30 = false;  // the block being run has M30
    // The words of a fixed cycle as written, in their own units (µm, µm/rev).
    struct Args {
        bool has_i = false, has_k = false, has_d = false, has_f = false, has_s = false;
        double i = 0, k = 0, d = 0, f = 0, s = 0;
    } args;

    // Whether G`g` is a fixed cycle this dialect runs (its words are its own).
    static bool is_cycle(int g);
    // The fixed cycle the block calls, -1 for none.
    static int cycle_of(const Plan& p);
    // Runs the fixed cycle of the block; false once an error is reported.
    static bool cycle(Interpreter& in, const Plan& p);
    static bool g34(Interpreter& in, const Plan& p);
    static bool turning(Interpreter& in, const Plan& p);
    static bool g92(Interpreter& in, const Plan& p);
    // Whether the block ends the nose-radius compensation before it runs: G33,
    // the fixed cycles, M0, M1, M2, M30, T and G7XZ (003:1795-1803).
    static bool ends_comp(const Interpreter& in, const Plan& p);
    // Ends it: the compensated profile stops at its last point, G40.
    static bool end_comp(Interpreter& in);
    // One elementary move of a cycle: G0, G1 at the feed in force, or G33 at
    // the pitch in force, to program X Z (mm, X a radius).
    static bool move(Interpreter& in, int g, double x, double z);
    struct CycleFeed;  // a cycle's own feed per revolution, for its passes
};

}  // namespace pupitre
