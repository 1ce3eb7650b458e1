// Profile geometry programming (PGP, 000:8358-8564; pupitre-iso(5), PROFILE
// GEOMETRY PROGRAMMING (PGP)): lines by angle, circles by centre or radius,
// tangency ET and secancy ES, the E+/E- discriminants, fillets EB+ and chamfers
// EB-. The solver takes one block's element description at a time and gives
// back resolved elements as soon as they are determined (look-ahead of at most
// two blocks). Pure plane geometry in (abscissa, ordinate) of the plane,
// internal units (lathe X as a radius), no interpreter state.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "core/diag.hpp"
#include "core/geometry/comp.hpp"

namespace pupitre::pgp {

using V2 = comp::V2;

// What one motion block says about its element, in plane coordinates.
struct Spec {
    int g = 1;                          // 1 line, 2 clockwise arc, 3 counter-clockwise arc
    bool has_x = false, has_y = false;  // end point, first / second plane axis
    double x = 0, y = 0;
    bool has_ea = false;  // line angle, degrees from the first axis
    double ea = 0;
    bool has_i = false, has_j = false;  // absolute centre, first / second axis
    double i = 0, j = 0;
    bool has_r = false;  // arc radius
    double r = 0;
    char link = 0;        // 0, 'S' (ES: secant with the next), 'T' (ET: tangent)
    int disc = 0;         // +1 (E+), -1 (E-), 0 none
    bool has_eb = false;  // EB: + fillet radius, - chamfer leg (sign kept)
    double eb = 0;
    bool eb_unsigned = false;  // EB written without a sign (taken as a fillet)
    int tag = 0;               // caller's id of the block (returned with its elements)
    bool stop = false;         // M0, M1 or M2 in the block (with EB: error 131)
};

// A resolved element. Fillets and chamfers are elements of their own, tagged
// with the block that asked for them.
struct Elem {
    comp::Elem geo;
    int tag = 0;
    bool inserted = false;  // a fillet or chamfer made by EB
};

class Solver {
  public:
    // The known start point of the next element (the current position).
    void start(const V2& p);
    // Adds a block's element. Resolved elements are appended to `out` (possibly
    // several, possibly none while the entity is incomplete). Answers a PGP
    // error (101-137) with the tag of the block it belongs to as its `item`.
    Error push(const Spec& s, std::vector<Elem>& out);
    // A block without motion in the plane between two elements (at most 2 while
    // an element is incomplete: error 136).
    Error idle();
    // The profile ends here (a non-PGP block, G40, end of program): anything still
    // incomplete is error 131; a pending fillet/chamfer element is flushed.
    Error finish(std::vector<Elem>& out);
    // True while an element waits for a following block.
    bool pending() const;
    // The end point of the last resolved element.
    V2 position() const;

  private:
    // A block waiting for the blocks that determine it; the first one starts at
    // pos_. `fixed` when solving the previous entity already found its support:
    // a line through p with unit travel direction d, or a circle about p of
    // radius r travelled in sense s (+1 counter-clockwise).
    struct Item {
        Spec spec;
        bool fixed = false;
        bool arc = false;
        V2 p{0, 0}, d{1, 0};
        double r = 0;
        int s = 0;
    };

    Error resolve(std::vector<Elem>& out);
    Error deliver(Elem e, const Spec& s, std::vector<Elem>& out);
    Error fail(int code, int tag, std::string detail);

    std::vector<Item> wait_;  // blocks of the entity being solved
    V2 pos_{0, 0};
    int idle_ = 0;
    bool held_ = false;  // an element with EB waits for the next element
    Elem held_elem_;
    double held_eb_ = 0;
};

}  // namespace pupitre::pgp
