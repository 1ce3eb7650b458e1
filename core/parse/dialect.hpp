// The controller dialects (pupitre-cazeneuve(5)): a machine profile names the one its
// programs are written in; the codes table keeps one set of rows per dialect.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>

namespace pupitre {

enum class Dialect : uint8_t {
    num,        // NUM 1020/1040/1060 (pupitre-iso(5))
    cazeneuve,  // the Cazeneuve HB CNC lathe of seed 003 (pupitre-cazeneuve(5))
};

}  // namespace pupitre
