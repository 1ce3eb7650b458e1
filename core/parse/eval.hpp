// Parametric programming: L variables and strictly left-to-right expressions
// with S C A R T (000:7322-7545; pupitre-iso(5), PARAMETRIC PROGRAMMING). E
// parameters are reached through EAccess, which the interpreter implements,
// since most of them are live machine data.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <bitset>
#include <cstdint>
#include <string>

#include "core/diag.hpp"
#include "core/parse/block.hpp"

namespace pupitre {

struct LVars {
    std::array<double, 960> v{};
    std::bitset<960> written;  // set since power-on or --set: the run summary, warning 1111
    mutable std::bitset<960> unset_read;  // read while not written; the interpreter reports it
    mutable bool any_unset_read = false;
    static bool valid(int n) {
        return (n >= 0 && n <= 19) || (n >= 100 && n <= 199) || (n >= 900 && n <= 959);
    }
};

class EAccess {
  public:
    virtual ~EAccess() = default;
    // Both answer a NUM error (diag.hpp), empty on success.
    virtual Error read_e(int n, int64_t& out) = 0;
    virtual Error write_e(int n, int64_t value) = 0;
};

// Value of an operand in an expression: E parameters as raw integers (no unit
// scaling, 000:7651-7669; pupitre-iso(5), DECISIONS).
Error eval_operand(const Operand& o, const LVars& l, EAccess& e, double& out);
// Evaluates terms [first, first+count) of `b`.
Error eval_expr(const Block& b, Expr x, const LVars& l, EAccess& e, double& out);
// Comparison after rounding both sides to 1e-6 (pupitre-iso(5), DECISIONS, G79 comparisons).
bool compare(Cmp c, double a, double b);

}  // namespace pupitre
