// The axes of a NUM machine (X Y Z U V W A B C) and a position on each: what
// the geometry, the interpreter and every sink of its moves count in.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <string_view>

namespace pupitre {

// Axis index, as in the E parameters (E6x000…) and travel errors 150-158.
enum Axis : int { X = 0, Y, Z, U, V, W, A, B, C, kAxes };
using Axes = std::array<double, kAxes>;
constexpr std::string_view kAxisNames = "XYZUVWABC";
inline bool is_rotary(int a) {
    return a >= A;
}
// X Y Z U V W A B C -> 0..8, -1 if not an axis letter.
inline int axis_of(char letter) {
    // By table: this runs for every axis word.
    static constexpr signed char kIndex[26] = {6,  7,  8,  -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
                                               -1, -1, -1, -1, -1, -1, -1, 3,  4,  5,  0,  1,  2};
    return (letter >= 'A' && letter <= 'Z') ? kIndex[letter - 'A'] : -1;
}

}  // namespace pupitre
