// Turning cycles as functions from arguments to elementary moves (STYLE.md): G64
// paraxial roughing, G65 groove roughing, G66 plunge roughing, G63 roughing with
// grooves, G33 threading, G38 chained threading (turning.md §6). Pure geometry in
// the lathe plane with abscissa Z and ordinate X as a radius (internal units); the
// interpreter extracts profiles and stock from the program and emits the moves.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/comp.hpp"

namespace pupitre::turning {

using V2 = comp::V2;  // (z, r)

// One elementary move of a cycle: rapid (0), feed (1) or arc (2, 3) to `to`.
struct Move {
    int g = 0;
    V2 to{0, 0};
    V2 c{0, 0};          // arc centre
    double sweep = 0;    // arc, radians, positive counter-clockwise in (z, r)
    double dwell = 0;    // seconds to wait after the move (0: none)
    int spindle = 0;     // threading: 0, or 3/4 to reverse the spindle after the move
};

// A finished profile as called (N<a> N<b> in the order written), resolved into
// lines and arcs (PGP and fillets already applied).
struct Profile {
    std::vector<comp::Elem> elems;
};

// Each cycle returns 0 or a NUM error number with `why` filled. The argument
// structures and functions are declared by the cycles' author below.

}  // namespace pupitre::turning
