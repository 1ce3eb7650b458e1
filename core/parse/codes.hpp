// The codes table: every G and M function of the NUM 1020/1040/1060 with its
// modal group, where in a block it acts, the words it owns, which machines and
// models have it, and a one-line text. Validation, modal conflicts, the help page
// and the man page all read this one table (ARCHITECTURE.md, Conventions: CAMotics' Codes.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <bitset>
#include <cstdint>
#include <span>
#include <string_view>

#include "core/parse/block.hpp"
#include "core/parse/dialect.hpp"

namespace pupitre {

enum class Group : uint8_t {
    none,      // non-modal
    motion,    // G00 G01 G02 G03 (G38)
    dist,      // G90 G91
    plane,     // G17 G18 G19
    radcomp,   // G40 G41 G42 (G29)
    prefdec,   // G53 G54
    feed,      // G93 G94 G95
    spindle,   // G96 G97
    units,     // G70 G71
    scale,     // G73 G74
    cycle,     // G80 G81-G89 G64
    toolaxis,  // G16
    coord,     // G20 G21 G22
};

enum MachineKinds : uint8_t { kLathe = 1, kMill = 2, kBoth = 3 };

enum class Support : uint8_t {
    yes,      // pupitre runs it
    later,    // planned (geometry issue): refused with error 1010 for now
    ignored,  // accepted, no effect on a simulated machine (timing or PLC only)
    option,   // an option the simulated machines do not have: error 4
};

struct GCode {
    int16_t number;
    Group group;
    uint8_t machines;  // MachineKinds
    uint8_t starred;   // MachineKinds on which it is NUM 1040/1060 only (starred)
    Support support;
    std::string_view args;  // addresses the function owns, space separated ("X Z S R")
    std::string_view text;  // English, a msgid: shown with tr(std::string(text).c_str())
};

enum class MWhen : uint8_t { avant, apres };

struct MCode {
    int16_t first, last;  // a range of numbers sharing one entry (M40-M45, M100-M199…)
    MWhen when;
    bool modal;
    bool all_models;
    std::string_view text;  // English, a msgid: shown with tr(std::string(text).c_str())
};

// The parts of a block in the order they take effect (000:497-498;
// pupitre-iso(5), MODAL STATE AND THE ORDER INSIDE A BLOCK):
// Interpreter::execute (interp_exec.cpp) runs its steps in this order, a test
// checks it on the trace, and pupitre-iso(5) lists them from this table
// (tests/man/codes_table.py).
enum class ExecStep : uint8_t {
    assign,
    modal,
    m_before,
    spindle,
    message,
    motion,
    dwell,
    m_after,
    flow
};
struct BlockStep {
    ExecStep step;
    std::string_view text;  // as pupitre-iso(5) words it
};
std::span<const BlockStep> block_steps();

// Each dialect has its own rows: the same number can mean something else
// (G92 presets an origin on the NUM, faces on the Cazeneuve lathe).
const GCode* find_g(int number, Dialect d = Dialect::num);
const MCode* find_m(int number, Dialect d = Dialect::num);
std::span<const GCode> all_g(Dialect d = Dialect::num);
std::span<const MCode> all_m(Dialect d = Dialect::num);

// Whether address `a` is one of the words G function `g` owns.
bool g_owns(const GCode& g, Addr a);

}  // namespace pupitre
