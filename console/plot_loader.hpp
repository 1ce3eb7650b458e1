// The plot module as the executable opens it (plot_loader.cpp,
// core/output/plot_module.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

namespace pupitre {

// Why the module cannot be loaded, empty when it is (the writers of
// cairo_plot.hpp and height_png.hpp then fail): for the caller's message.
std::string plot_module_error();

}  // namespace pupitre
