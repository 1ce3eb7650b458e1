// A height field as a 16-bit greyscale PNG (the machining centre's part,
// pupitre-setup(5), THE CUT PART), through libpng. Built into the
// pupitre_plot library beside Cairo's back-end, not the core.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <cstdio>
#include <vector>

namespace pupitre {

// `values` holds `height` rows of `width` samples, the first row the image's
// top. False when libpng or the stream fails.
bool write_gray16_png(const std::vector<uint16_t>& values, int width, int height, std::FILE* out);

}  // namespace pupitre
