// The ncurses backend: the only code that talks to the terminal. It shows a
// Canvas with a colour theme, and puts the terminal back as it found it on
// every way out (quit, Ctrl-C, a signal, a crash).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>

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

  private:
    void theme_colours(Theme t);
    // The colour pair of a cell's own colours, made on first use.
    int pair_for(uint32_t fg, uint32_t bg);
    int colour_number(uint32_t c) const;
    pages::Colours colours_ = pages::Colours::none;
    std::unordered_map<uint64_t, int> pairs_;
    int next_pair_ = 0;
    bool open_ = false;
    Theme theme_ = Theme::mono;
    int rows_ = 24, cols_ = 80;
};

}  // namespace pupitre::console
