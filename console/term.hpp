// The ncurses backend: the only code that talks to the terminal. It shows a
// Canvas with a colour theme, and puts the terminal back as it found it on
// every way out (quit, Ctrl-C, a signal, a crash).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>

#include "console/term_image.hpp"
#include "pages/canvas.hpp"
#include "pages/cells.hpp"

namespace pupitre::console {

enum class Theme { colour, mono, phosphor };
bool parse_theme(const std::string& name, Theme& out);

class Terminal {
  public:
    // Takes the terminal: raw mode, no echo, alternate screen. "" or why not.
    std::string open(Theme theme);
    void close();  // idempotent
    ~Terminal() { close(); }

    int rows() const { return rows_; }
    int cols() const { return cols_; }
    // True once after the window changed size (SIGWINCH); rows and cols are new.
    bool resized();
    void draw(const pages::Canvas& c, int cursor_x, int cursor_y);
    // Set by SIGINT, SIGTERM, SIGHUP: the event loop leaves cleanly.
    static bool interrupted();
    static int signal_caught();  // SIGTERM, SIGHUP…: the one that ended the loop, or 0
    // Whether the terminal's locale can show UTF-8 (else the ASCII fallback).
    static bool utf8_locale();
    // The colours a picture's cells may take: the terminal's own (24-bit
    // when its terminfo says so), none in the mono and phosphor themes.
    pages::Colours colours() const { return colours_; }

    // Asks the terminal which pictures it takes (term_image.hpp), waiting
    // at most `ms` for its answers; keys typed meanwhile are kept
    // (take_input). Not on the Linux console nor a dumb terminal.
    void ask_images(int ms);
    ImageProtocol images() const { return images_; }
    int cell_w() const { return cell_w_; }
    int cell_h() const { return cell_h_; }
    std::string take_input() { return std::exchange(input_, {}); }
    // After draw(): the picture's sequence at cell (x, y), sent again only
    // when `serial` is new or the screen was repainted whole; null takes
    // the picture shown away.
    void picture(int x, int y, const std::string* seq, uint64_t serial);

  private:
    void theme_colours(Theme t);
    // The colour pair of a cell's own colours, made on first use.
    int pair_for(uint32_t fg, uint32_t bg);
    int colour_number(uint32_t c) const;
    pages::Colours colours_ = pages::Colours::none;
    ImageProtocol images_ = ImageProtocol::none;
    int cell_w_ = 0, cell_h_ = 0;
    std::string input_;
    uint64_t shown_ = 0;     // the picture on screen (its serial), 0: none
    bool repainted_ = true;  // the screen was drawn whole since
    std::unordered_map<uint64_t, int> pairs_;
    int next_pair_ = 0;
    bool open_ = false;
    Theme theme_ = Theme::mono;
    int rows_ = 24, cols_ = 80;
};

}  // namespace pupitre::console
