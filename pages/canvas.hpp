// The Canvas: a grid of character cells with logical styles, which pages draw
// into (FTXUI's virtual screen). Only console/ turns it into ncurses calls; the
// tests print it as text (pupitre(1), THE CONSOLE).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::pages {

// Logical styles: the console's theme maps each to colours and attributes.
enum class Style : uint8_t {
    normal,
    dim,         // labels, units, frames
    title,       // page titles
    value,       // the numbers that matter
    big,         // the main coordinate column
    select,      // the selected line (cursor, current block)
    alarm,       // alarm numbers and texts
    warn,        // hold, stop, pending
    ok,          // running, end of program
    status,      // the status line
    key,         // the F-key number of a soft key
    softkey,     // a soft-key label
    input,       // the input line
    softkey_on,  // the soft key of the page on screen
    count_,
};

// A cell's own colours (the PART view's picture, issue 36): none (its
// style's), an RGB triple 0xRRGGBB, or an entry of the terminal's palette.
inline constexpr uint32_t kNoColour = 0xffffffffu;
inline constexpr uint32_t kPaletteBit = 0x01000000u;
constexpr uint32_t rgb_colour(unsigned r, unsigned g, unsigned b) {
    return (r & 0xff) << 16 | (g & 0xff) << 8 | (b & 0xff);
}
constexpr uint32_t palette_colour(unsigned index) {
    return kPaletteBit | (index & 0xff);
}

struct Cell {
    char32_t ch = U' ';
    Style st = Style::normal;
    uint32_t fg = kNoColour, bg = kNoColour;
    bool operator==(const Cell&) const = default;
};

struct Rect {
    int x = 0, y = 0, w = 0, h = 0;
};

class Canvas {
  public:
    Canvas(int width, int height, bool ascii = false);

    int width() const { return w_; }
    int height() const { return h_; }
    bool ascii() const { return ascii_; }
    // How many texts were cut by their room (each marked) since clear().
    int cuts() const { return cut_; }
    // How many letters a text drew over another text's since clear(): a
    // cut with no mark (the status line's right over its left, say).
    int overwrites() const { return overwrites_; }
    void resize(int width, int height);
    void clear();

    void put(int x, int y, char32_t ch, Style st = Style::normal);
    // A cell of a picture: its symbol in its own colours (kNoColour: the
    // style's).
    void paint(int x, int y, char32_t ch, uint32_t fg, uint32_t bg);
    // UTF-8 text from (x, y), clipped at `max` columns (-1: the right edge).
    // Returns the columns written.
    int text(int x, int y, std::string_view utf8, Style st = Style::normal, int max = -1);
    // Text right-aligned so that it ends at column x + w - 1.
    void text_right(int x, int y, int w, std::string_view utf8, Style st = Style::normal);
    void fill(const Rect& r, char32_t ch, Style st = Style::normal);
    void style(const Rect& r, Style st);  // restyles cells, keeping their characters
    void hline(int x, int y, int w, Style st = Style::dim);
    // A horizontal rule with a title in it: "── TITLE ─────".
    void rule(int y, std::string_view title, Style st = Style::title);

    const Cell& at(int x, int y) const { return cells_[size_t(y * w_ + x)]; }
    // The grid as text, one line per row, trailing blanks removed (snapshots).
    std::string to_text() const;

    // Glyphs with an ASCII fallback.
    char32_t horiz() const { return ascii_ ? U'-' : U'─'; }
    char32_t vert() const { return ascii_ ? U'|' : U'│'; }

  private:
    int w_, h_;
    bool ascii_;
    int cut_ = 0, overwrites_ = 0;
    int writer_ = 0, texts_ = 0;  // the text() drawing now (0: none), the last one's number
    std::vector<int> owner_;      // per cell: the text() that drew it, 0 when none
    std::vector<Cell> cells_;
};

// Columns of a UTF-8 string (one per code point: pupitre writes no wide characters).
int columns(std::string_view utf8);
std::string utf8(char32_t c);

}  // namespace pupitre::pages
