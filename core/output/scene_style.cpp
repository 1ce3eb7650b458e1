// The layers' looks and the points of a programmed element (scene.hpp):
// apart from the rest of the scene, as the plot module (plot_module.hpp)
// holds its own copy.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/i18n.hpp"
#include "core/output/scene.hpp"

namespace pupitre {

namespace {

// One table for the layers' looks, read by both back-ends and the legend.
// Widths and dashes are paper millimetres; rapids are dashed, cuts solid.
// The legend's words are shown translated (tr(st.legend)).
constexpr LayerStyle kStyles[kLayerCount] = {
    {"part", N_("the part as cut (workshop)"), {120, 144, 176}, 0.15, {0, 0, 0, 0}, 1},
    {"axis", N_("spindle axis"), {127, 127, 127}, 0.18, {4, 1, 0.5, 1}, 1},
    {"stock", N_("stock (G64)"), {160, 82, 45}, 0.3, {1.2, 0.8, 0, 0}, 1},
    {"extremes", N_("EM- / EM+ extremes"), {51, 102, 204}, 0.2, {0.6, 0.6, 0, 0}, 1},
    {"profile", N_("programmed profile"), {142, 68, 173}, 0.2, {0, 0, 0, 0}, 1},
    {"rapid", N_("rapid G0"), {128, 128, 128}, 0.2, {1.6, 1.0, 0, 0}, 1},
    {"feed", N_("feed G1 G2 G3"), {31, 78, 156}, 0.35, {0, 0, 0, 0}, 1},
    {"comp", N_("compensated path G41 G42"), {11, 122, 75}, 0.35, {0, 0, 0, 0}, 1},
    {"travel", N_("beyond the travel"), {224, 128, 0}, 0.5, {0, 0, 0, 0}, 1},
    {"gouge", N_("block in error, where it stopped"), {212, 0, 0}, 0.5, {0, 0, 0, 0}, 1},
    {"mirror", N_("mirror image below the axis"), {31, 78, 156}, 0.35, {0, 0, 0, 0}, 0.35},
};

}  // namespace

const LayerStyle& layer_style(Layer l) {
    return kStyles[std::min(size_t(l), kLayerCount - 1)];
}

Layer move_layer(const PathMove& mv) {
    if (mv.flags & pathflag::error) return Layer::gouge;
    if (mv.flags & pathflag::travel) return Layer::travel;
    return mv.kind == PathKind::rapid  ? Layer::rapid
           : mv.kind == PathKind::comp ? Layer::comp
                                       : Layer::feed;
}

void profile_point(const ProfileElem& e, double t, int h, double& x, double& y) {
    double p0 = e.from[0] + (e.to[0] - e.from[0]) * t, p1 = e.from[1] + (e.to[1] - e.from[1]) * t;
    if (e.arc && t > 0 && t < 1) {
        double r = std::hypot(e.from[0] - e.c[0], e.from[1] - e.c[1]);
        double a = std::atan2(e.from[1] - e.c[1], e.from[0] - e.c[0]) +
                   e.sweep * t * 3.14159265358979323846 / 180;
        p0 = e.c[0] + r * std::cos(a);
        p1 = e.c[1] + r * std::sin(a);
    }
    x = e.a0 == h ? p0 : p1;
    y = e.a0 == h ? p1 : p0;
}

}  // namespace pupitre
