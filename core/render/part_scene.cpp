// The workshop copied for a picture (see part_scene.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/render/part_scene.hpp"

#include "core/training/exercise.hpp"

namespace pupitre::render {

Drawing drawing_of(const training::Exercise& e) {
    Drawing d;
    d.name = "exercise " + e.name;
    for (const training::Dimension& x : e.dimensions)
        d.dims.push_back({x.spec, x.nominal, x.lower, x.upper});
    return d;
}

Verdict DimReading::verdict() const {
    if (!read) return Verdict::unread;
    const double dev = deviation();
    if (dev > dim.upper + 1e-9) return Verdict::over;
    if (dev < dim.lower - 1e-9) return Verdict::under;
    return Verdict::inside;
}

namespace {

void lathe_scene(const workshop::Workshop& w, const Axes& om, LatheScene& s) {
    const workshop::LatheWorld& world = w.world();
    const workshop::LatheSetup& ls = w.setup().lathe;
    s.material = world.material();
    s.chuck = world.chuck();
    s.tailstock = world.tailstock();
    s.gauge = world.gauge();
    s.stock = workshop::LatheWorld(ls).material();  // the stock as loaded
    s.has_face = world.right_face(s.face_z);
    s.chuck_z = ls.chuck_z;
    s.jaw_top = ls.stock_diameter / 2 + ls.jaw_height;
    if (const workshop::ToolTruth* t = w.setup().tool(w.tool())) {
        s.has_tool = true;
        s.tool = workshop::tool_shape(*t);
        s.tip = w.tip(om);
    }
}

void mill_scene(const workshop::Workshop& w, const Axes& om, MillScene& s) {
    const workshop::MillWorld& m = *w.mill();
    s.stock = m.stock();
    s.nx = m.nx(), s.ny = m.ny(), s.cell = m.cell();
    s.height.resize(size_t(s.nx) * size_t(s.ny));
    for (int j = 0; j < s.ny; ++j)
        for (int i = 0; i < s.nx; ++i)
            s.height[size_t(j) * size_t(s.nx) + size_t(i)] = m.height(i, j);
    w.holding(s.boxes, s.pins);
    s.table_z = w.setup().mill.table_z;
    if (w.setup().tool(w.tool())) {
        s.has_cutter = true;
        s.cutter = w.cutter_now();
        s.tip = w.tip3(om);
        s.axis = w.axis3(om);
    }
}

}  // namespace

std::shared_ptr<const PartScene> snapshot(const workshop::Workshop& w, const Axes& om,
                                          const Drawing* drawing) {
    auto s = std::make_shared<PartScene>();
    s->mill = w.is_mill();
    s->generation = w.generation();
    if (s->mill)
        mill_scene(w, om, s->block);
    else
        lathe_scene(w, om, s->lathe);
    if (drawing && !drawing->dims.empty()) {
        s->drawing = drawing->name;
        for (const DrawnDim& d : drawing->dims) {
            DimReading r;
            r.dim = d;
            workshop::Reading x;
            r.why = w.measure(d.spec, x);
            r.read = r.why.empty();
            r.value = x.value;
            if (r.read) w.measure_place(d.spec, r.place);
            s->dims.push_back(std::move(r));
        }
    }
    return s;
}

}  // namespace pupitre::render
