// The workshop as the PART view draws it (issue 36): a copy of the part, the
// work-holding and the tool where it stands, and the drawing's dimensions
// read on the part, taken at one moment. A copy, so that a picture can be
// made away from the console's loop while the machine goes on cutting.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/axis.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::training {
struct Exercise;
}

namespace pupitre::render {

// A dimension of the drawing (pupitre-exercise(5), The drawing): an
// instrument's request, right within [nominal + lower, nominal + upper].
struct DrawnDim {
    std::string spec;
    double nominal = 0, lower = 0, upper = 0;
};

// What the part is held against; no dimension: no drawing.
struct Drawing {
    std::string name;  // "exercise lathe-first"
    std::vector<DrawnDim> dims;
};
Drawing drawing_of(const training::Exercise& e);

enum class Verdict : uint8_t { unread, inside, over, under };

// A dimension read on the part, and where: the surface it reads.
struct DimReading {
    DrawnDim dim;
    bool read = false;
    double value = 0;  // mm, as the instrument gave it
    std::string why;   // why there is no reading
    workshop::Workshop::Place place;
    double deviation() const { return value - dim.nominal; }
    Verdict verdict() const;
};

struct LatheScene {
    workshop::CPaths material, stock, chuck, tailstock, gauge;
    bool has_face = false;
    double face_z = 0;   // the part's right-hand face (machine Z)
    double chuck_z = 0;  // the jaws' face
    double jaw_top = 0;  // the jaws' top (R)
    bool has_tool = false;
    workshop::ToolShape tool;  // about the tool point
    workshop::Pt tip{};        // the tool point (Z, R)
};

struct MillScene {
    workshop::Box3 stock;
    int nx = 0, ny = 0;
    double cell = 0.1;
    std::vector<float> height;  // nx * ny, row j from -Y
    std::vector<workshop::Box3> boxes;
    std::vector<workshop::Cylinder> pins;
    double table_z = 0;
    bool has_cutter = false;
    workshop::Cutter cutter;
    workshop::P3 tip{}, axis{0, 0, 1};
    float h(int i, int j) const { return height[size_t(j) * size_t(nx) + size_t(i)]; }
};

struct PartScene {
    bool mill = false;
    LatheScene lathe;
    MillScene block;
    std::string drawing;  // its name; "" when there is none
    std::vector<DimReading> dims;
    uint64_t generation = 0;
};

// The workshop now, its tool at machine position `om`, its part read
// against `drawing` (null or no dimension: none).
std::shared_ptr<const PartScene> snapshot(const workshop::Workshop& w, const Axes& om,
                                          const Drawing* drawing);

}  // namespace pupitre::render
