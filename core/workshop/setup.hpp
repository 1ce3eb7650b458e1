// The workshop's truth (ARCHITECTURE.md, the workshop): where the chuck and the stock really are
// and what each tool really measures, in the machine frame. The interpreter
// never sees it; the workshop turns the OM path into cuts, contacts and
// crashes with it. Text format: pupitre-setup(5).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::workshop {

using Pt = std::array<double, 2>;  // (Z, X) in mm, X a radius

// A tool as it really is. The tip is given the way a presetter reads it and a
// corrector holds it: the true gauge, OM - P for each axis, P being the
// theoretical tool point of the nose (000:706-731; pupitre-iso(5), TOOLS AND
// CORRECTORS). On a lathe X is a radius.
struct ToolTruth {
    int position = 0;     // turret position 1..n
    double x = 0, z = 0;  // true gauge (mm)
    double radius = 0;    // nose radius (mm)
    int orientation = 3;  // C1..C8 as in the corrector (000:706-731; pupitre-iso(5), TOOLS AND
                          // CORRECTORS); C0: a point
    double angle = 80;    // the insert's tip angle (degrees)
    double edge = 10;     // length of its cutting edges from the nose (mm)
    int spindle = 0;      // 3 or 4: the direction it cuts with; 0: either
    double wear = 0;      // µm per metre of cut
    double life = 0;      // minutes of cutting an edge lasts (003:2353); 0: not given
    // The holder's outline, points relative to P (Z, X); empty: the default
    // shank for the orientation (pupitre-setup(5)).
    std::vector<Pt> holder;
    bool probe = false;  // an electric touch probe: never cuts
    // A mechanical edge finder (a machining centre's): never cuts; its body
    // is `radius` wide, its lower part `flute` long.
    bool finder = false;
    // A milling cutter (kind = mill): x and z above are not used; the true
    // length from the gauge line to the tip, and its shape (mill_part.hpp).
    double length = 0;
    double corner = 0;            // corner radius: 0 flat, = radius a ball end
    double flute = 0;             // cutting length from the tip; 0: 4 radii, at least 10
    double reach = 0;             // from the tip to the holder's face; 0: flute + 10
    double holder_diameter = 40;  // the tool holder's (mm)
};

// The machining centre: a block of stock on the table, in a vice or on a
// plate, locating pins, a tool setter. The stock's corner is its lowest
// -X -Y corner.
struct Pin {
    double x = 0, y = 0, diameter = 10, height = 20;  // height above the stock's bottom
};
struct MillSetup {
    double table_z = -350;  // the table's top
    double stock_x = 0, stock_y = 0, stock_z = -330;
    double length = 120, width = 80, height = 40;  // along X, Y, Z
    std::string holding = "vice";                  // vice, plate or none
    double jaw_height = 30;                        // above the stock's bottom
    double jaw_width = 150, jaw_thickness = 25;    // along X, along Y
    double plate_margin = 20;                      // beyond the stock in X and Y
    std::vector<Pin> pins;
    bool setter = false;
    double setter_x = 0, setter_y = 0, setter_z = 0, setter_diameter = 20;
    double cell = 0.1;  // the height field's (mm)
    // A C rotary table (mill5): its axis's machine X and Y. The setup is
    // described at C0; the table carries the stock and the fixtures round.
    double c_x = 0, c_y = 0;
    // A B head (mill5): its axis's height above the spindle's gauge line.
    // A B table (mill4): its axis's machine X and Z; the setup is described
    // at B0 and the table tilts the stock and the fixtures with it.
    double pivot = 0;
    double b_x = 0, b_z = 0;
};

struct LatheSetup {
    // Chuck: the machine Z of the jaws' front face; the spindle axis's machine
    // X as a tool point would read it (so the true PREF X).
    double axis_x = 0;
    double chuck_z = 0;
    double chuck_diameter = 200, chuck_length = 80;  // the body behind the jaws
    double jaw_length = 25, jaw_height = 20;         // along Z, radially above the stock
    double jaw_reach = 25;                           // how far the bar goes into the jaws
    // Bar stock.
    double stock_diameter = 60, stock_length = 120, stickout = 95;  // stickout: from the jaws' face
    double bore = 0;                                                // diameter, 0: solid
    // A blank that is not a bar (a forging, a casting, a part turned
    // before): its half-section, Z from the stock's right-hand face (<= 0)
    // and R, replacing the bar's rectangle.
    std::vector<Pt> profile;
    // Tailstock centre: the machine Z of its point, if any.
    bool tailstock = false;
    double tailstock_z = 0, quill_diameter = 40;
};

struct Setup {
    std::string source;  // the text it was read from (the store keeps it)
    std::string name, description;
    std::string kind;  // "lathe" or "mill"
    LatheSetup lathe;
    MillSetup mill;
    std::vector<ToolTruth> tools;  // by position, in file order
    const ToolTruth* tool(int position) const;
};

// Parses a setup; returns "" or "line N: what is wrong". On error `s` is
// left default.
std::string parse_setup(std::string_view text, Setup& s);
// A setup shipped in data/setups (lathe, mill); false if there is none by
// that name.
bool builtin_setup(std::string_view name, Setup& s);

}  // namespace pupitre::workshop
