// The picture of `pupitre plot` as one description (docs/decisions.md, One
// scene, two back-ends): the frame fitted to the cutting moves, the layers of
// the toolpath with their styles, and the marks around them (title, axis
// arrows, scale bar, legend, notes) laid out on a page in paper millimetres.
// Two back-ends draw the same scene: the SVG writer (svg.cpp: arcs, layer ids
// and the trace's exact coordinates, which Cairo 1.16 cannot write) and Cairo
// (cairo_plot.cpp: PNG and PDF). No back-end decides a colour, a position or a
// word.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/output/toolpath.hpp"
#include "core/plan/tools.hpp"

namespace pupitre {

// The layers of the drawing, in drawing order (later ones on top).
enum class Layer : uint8_t {
    part,      // the workshop's part as cut, filled
    axis,      // the lathe's spindle axis
    stock,     // the G64 rough stock
    extremes,  // the EM- / EM+ frame
    profile,   // the programmed profile of G41/G42
    rapid,
    feed,
    comp,    // the radius-compensated path
    travel,  // moves ending beyond the machine's travel
    gouge,   // the moves of a block that raised an error, and where it stopped
    mirror,  // lathe: the cutting moves mirrored below the axis
    count_
};
inline constexpr size_t kLayerCount = size_t(Layer::count_);

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
};

struct LayerStyle {
    const char* id;      // the SVG group's id (pupitre(1) promises them)
    const char* legend;  // the legend's words
    Rgb colour;
    double width;                // paper mm
    std::array<double, 4> dash;  // paper mm, on/off pairs; all 0: solid
    double opacity;
};
const LayerStyle& layer_style(Layer l);
// The layer a move is drawn in (an error or the travel wins over its kind).
Layer move_layer(const PathMove& mv);

// What the options of `pupitre plot` say about the picture.
struct SceneOptions {
    PathPlane plane = PathPlane::xy;
    std::string machine;  // the profile's name as given (--machine)
    double seconds = -1;  // cycle time; < 0: the toolpath's own count
    // A table of each tool's time under the notes (issue 35: the PDF's): its
    // cutting and rapid time, passes, length cut, and the parts an edge
    // lasts when `life` gives it. Empty: no table.
    std::vector<plan::ToolRow> tools;
    plan::EdgeLife life;
    bool mirror = true;  // lathe: the half-profile's mirror image below the axis
    std::string generator = "pupitre";
};

// A mark around the drawing, on the page (paper mm, y down). A line with a
// layer takes the layer's style (the legend's samples).
struct Mark {
    enum Kind : uint8_t { line, rect, polygon, text } kind = line;
    enum Group : uint8_t { title, border, axes, scale, legend, notes, groups_ } group = title;
    std::vector<double> pts;  // line: x0 y0 x1 y1; rect: x y w h; polygon: x y pairs; text: x y
    Rgb stroke, fill;
    bool has_stroke = true, has_fill = false;
    double width = 0.25;
    int layer = -1;  // a Layer, for a legend sample
    // Text: the baseline's start (or end, `right`), size of the em in mm.
    std::string words;
    double size = 2.5;
    bool bold = false, right = false;
};
const char* mark_group_id(
    Mark::Group g);  // "title", "border", "axes", "scale-bar", "legend", "notes"

struct Scene {
    const Toolpath* path = nullptr;
    SceneOptions opt;
    int h = X, v = Y;     // the axes drawn across and up
    bool lathe = false;   // the lathe's ZX: true to shape, X as a radius up
    bool mirror = false;  // the mirror image is drawn
    PathFit fit;          // what the frame fits (before the margin)
    // The world window shown in the frame (mm, y up) and the drawing's scale
    // on paper: k paper mm per mm, 1, 2 or 5 times a power of ten.
    double wx0 = 0, wy0 = 0, wx1 = 1, wy1 = 1;
    double k = 1;
    std::string ratio;      // "1:2", "5:1"
    double bar_length = 1;  // the scale bar, mm of the part: 1, 2 or 5 times a power of ten
    double page_w = 210, page_h = 297;
    double fx = 0, fy = 0, fw = 1, fh = 1;  // the frame on the page
    std::array<bool, kLayerCount>
        present{};  // the legend's layers: those that leave ink in the frame
    std::vector<Mark> marks;
    std::string title;  // the document's title: "%555 EXEMPLE EN TOURNAGE"

    // World (mm, y up) to page (paper mm, y down).
    double px(double x) const { return fx + (x - wx0) * k; }
    double py(double y) const { return fy + (wy1 - y) * k; }
};

// A point of a programmed element at fraction t (0..1) of it, in the drawing's
// plane: x across (axis h), y up. The element must lie in that plane.
void profile_point(const ProfileElem& e, double t, int h, double& x, double& y);
// The sweep of an element seen with x across and y up (degrees, + counter-clockwise).
inline double profile_view_sweep(const ProfileElem& e, int h) {
    return e.a0 == h ? e.sweep : -e.sweep;
}
inline bool profile_in_plane(const ProfileElem& e, int h, int v) {
    return (e.a0 == h && e.a1 == v) || (e.a0 == v && e.a1 == h);
}

// The picture of a run: built once, drawn by every back-end.
Scene build_scene(const Toolpath& path, const SceneOptions& o);

// The width of text in DejaVu Sans (the back-ends' font), in ems: the layout
// is shared with the SVG writer, which cannot measure, so it is estimated a
// little wide from the font's advance widths.
double text_ems(const std::string& s, bool bold = false);

}  // namespace pupitre
