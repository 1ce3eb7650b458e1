// What the pages show differently for a machine of the Cazeneuve dialect
// (seed 003, pupitre-cazeneuve(5)): its T word. The thesis's controller has no
// L or E variables, no DEC1, DEC3 or G59, no mirror or scale: the pages show
// none of them (its INFO page: caz_info_lines in page_info.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/pages.hpp"

namespace pupitre::pages {

bool is_caz(const MachineProfile& m) {
    return m.dialect == Dialect::cazeneuve;
}

// NUM: "T2  D4"; Cazeneuve: T204, the turret position then the two digits of
// its corrector (003:1036-1039).
std::string tool_word(const MachineProfile& m, int tool, int corrector) {
    if (is_caz(m)) return strf("T%d%02d", tool, corrector);
    return "T" + std::to_string(tool) + "  D" + std::to_string(corrector);
}

}  // namespace pupitre::pages
