// Real pictures in the terminal (issue 36): the kitty graphics protocol and
// sixel. The console asks the terminal which it understands (a kitty query
// and the primary device attributes, DA1, which every terminal answers), and
// sends a picture only to a terminal that said it takes it; tmux, which
// answers DA1 but not the kitty query, gets the cells. No ncurses here: the
// queries' answers are parsed and the pictures encoded in plain strings
// (term.cpp writes them, after ncurses has drawn the screen).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "core/render/image.hpp"

namespace pupitre::console {

enum class ImageProtocol : uint8_t { none, kitty, sixel };

// What the console sends to learn the terminal: a kitty graphics query
// (when `kitty`), the cell's size in pixels (XTWINOPS 16), then DA1, whose
// answer ends the wait.
std::string image_query(bool kitty);

// The terminal's answers, read so far.
struct ImageAnswer {
    bool done = false;   // DA1 answered: nothing more to wait for
    bool kitty = false;  // the kitty query was answered OK
    bool sixel = false;  // DA1 lists attribute 4 (sixel graphics)
    int cell_w = 0, cell_h = 0;
    ImageProtocol protocol() const {
        return kitty ? ImageProtocol::kitty : sixel ? ImageProtocol::sixel : ImageProtocol::none;
    }
};
// Reads the answers in `bytes`; what is not an answer (keys typed
// meanwhile) is appended to `rest`, for the key decoder.
ImageAnswer parse_answers(std::string_view bytes, std::string& rest);

// The picture as the terminal's own, drawn from the cursor over `cols` x
// `rows` cells: kitty (RGBA, placed with the id `id`, scaled by the
// terminal to the cells) or sixel (its pixels as they are, in 252 colours).
std::string image_sequence(const render::Image& img, ImageProtocol p, int cols, int rows,
                           uint32_t id);
// What takes the picture `id` away again (kitty); "" for sixel, which the
// screen's next full repaint covers.
std::string image_delete(ImageProtocol p, uint32_t id);

}  // namespace pupitre::console
