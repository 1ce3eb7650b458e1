// The plot's scene as an SVG drawing (issue 7, `pupitre plot --svg`): one layer
// per kind of move (ids rapid, feed, comp, travel, gouge, and profile, axis,
// stock, extremes, mirror), arcs as SVG arcs, +Y (on the lathe +X) up,
// coordinates in mm with 4 decimals so that tests compare them with the trace;
// the title, axis arrows, scale bar, legend and notes of the scene around it.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdio>
#include <string>
#include <string_view>

#include "core/output/scene.hpp"
#include "core/output/toolpath.hpp"

namespace pupitre {

using SvgOptions = SceneOptions;

// The whole document. On the lathe (plane ZX) the drawing is true to shape: Z
// across, X as a radius up (y = -X/2 of the trace's diameters).
std::string svg_document(const Scene& scene);
std::string svg_document(const Toolpath& path, const SvgOptions& o);
// Writes it; false when the stream fails (errno tells why).
bool write_svg(const Scene& scene, std::FILE* out);

// Text made safe for XML character data and attribute values: & < > " ' escaped,
// control characters dropped, invalid UTF-8 bytes replaced by U+FFFD.
std::string xml_escape(std::string_view s);
// Appends v with exactly 4 decimals ("-0.0000" is written "0.0000"), as the trace does.
void append_mm(std::string& s, double v);

}  // namespace pupitre
