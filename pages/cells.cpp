// A picture as character cells through libchafa (see cells.hpp): the
// canvas of chafa is asked for each cell's symbol (chafa_canvas_get_char_at)
// and colours (chafa_canvas_get_colors_at, or the palette's index with
// chafa_canvas_get_raw_colors_at), never for its printed form.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/cells.hpp"

#include <chafa.h>

#include <mutex>

namespace pupitre::pages {

namespace {

// The symbols for `--ascii`: marks that draw a shape, no letters.
constexpr const char kAscii[] = " .,:;'`-_=+*#%@|/\\<>^()[]";

ChafaCanvasMode mode_of(Colours c) {
    switch (c) {
        case Colours::direct:
            return CHAFA_CANVAS_MODE_TRUECOLOR;
        case Colours::c256:
            // Not the first 16, which a terminal's theme may have changed.
            return CHAFA_CANVAS_MODE_INDEXED_240;
        case Colours::c16:
            return CHAFA_CANVAS_MODE_INDEXED_16;
        case Colours::c8:
            return CHAFA_CANVAS_MODE_INDEXED_8;
        case Colours::none:
            break;
    }
    return CHAFA_CANVAS_MODE_FGBG;
}

ChafaSymbolMap* symbols(Colours colours, bool ascii) {
    ChafaSymbolMap* map = chafa_symbol_map_new();
    if (ascii) {
        for (const char* p = kAscii; *p; ++p)
            chafa_symbol_map_add_by_range(map, gunichar(*p), gunichar(*p));
    } else if (colours == Colours::none) {
        // One colour: the shape is all there is, braille draws it finest.
        chafa_symbol_map_add_by_tags(
            map, ChafaSymbolTags(CHAFA_SYMBOL_TAG_SPACE | CHAFA_SYMBOL_TAG_BLOCK |
                                 CHAFA_SYMBOL_TAG_BRAILLE));
    } else {
        chafa_symbol_map_add_by_tags(
            map, ChafaSymbolTags(CHAFA_SYMBOL_TAG_SPACE | CHAFA_SYMBOL_TAG_BLOCK |
                                 CHAFA_SYMBOL_TAG_HALF));
    }
    return map;
}

uint32_t colour_of(int v, bool raw) {
    if (v < 0) return kNoColour;
    if (raw) return palette_colour(unsigned(v));
    return uint32_t(v) & 0xffffffu;
}

}  // namespace

CellImage to_cells(const render::Image& img, int cols, int rows, Colours colours, bool ascii) {
    // One thread: the console's worker is the only one that waits on it,
    // and the machine is shared.
    static std::once_flag once;
    std::call_once(once, [] { chafa_set_n_threads(1); });
    CellImage out;
    if (cols <= 0 || rows <= 0 || img.empty()) return out;
    out.cols = cols, out.rows = rows;
    out.cells.assign(size_t(cols) * size_t(rows), Cell{});
    ChafaSymbolMap* map = symbols(colours, ascii);
    ChafaCanvasConfig* cfg = chafa_canvas_config_new();
    chafa_canvas_config_set_geometry(cfg, cols, rows);
    chafa_canvas_config_set_canvas_mode(cfg, mode_of(colours));
    chafa_canvas_config_set_symbol_map(cfg, map);
    chafa_canvas_config_set_work_factor(cfg, 0.3f);
    if (colours == Colours::none)
        chafa_canvas_config_set_fg_color(cfg, 0xffffff), chafa_canvas_config_set_bg_color(cfg, 0);
    ChafaCanvas* canvas = chafa_canvas_new(cfg);
    chafa_canvas_draw_all_pixels(canvas, CHAFA_PIXEL_RGBA8_UNASSOCIATED,
                                 reinterpret_cast<const guint8*>(img.pixels().data()), img.w(),
                                 img.h(), img.w() * 4);
    const bool raw = colours != Colours::direct && colours != Colours::none;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < cols; ++x) {
            Cell& c = out.cells[size_t(y) * size_t(cols) + size_t(x)];
            c.ch = chafa_canvas_get_char_at(canvas, x, y);
            if (colours == Colours::none) continue;
            gint fg = -1, bg = -1;
            if (raw)
                chafa_canvas_get_raw_colors_at(canvas, x, y, &fg, &bg);
            else
                chafa_canvas_get_colors_at(canvas, x, y, &fg, &bg);
            c.fg = colour_of(fg, raw), c.bg = colour_of(bg, raw);
        }
    chafa_canvas_unref(canvas);
    chafa_canvas_config_unref(cfg);
    chafa_symbol_map_unref(map);
    return out;
}

void put_cells(const CellImage& ci, Canvas& c, int x, int y) {
    for (int r = 0; r < ci.rows; ++r)
        for (int k = 0; k < ci.cols; ++k) {
            const Cell& cell = ci.at(k, r);
            c.paint(x + k, y + r, cell.ch, cell.fg, cell.bg);
        }
}

}  // namespace pupitre::pages
