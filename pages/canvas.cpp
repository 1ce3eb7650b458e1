// The Canvas (see canvas.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/canvas.hpp"

#include <algorithm>

namespace pupitre::pages {

namespace {

// Decodes one code point; invalid bytes read as U+FFFD, one byte each.
char32_t next_cp(std::string_view s, size_t& i) {
    unsigned char c = static_cast<unsigned char>(s[i++]);
    if (c < 0x80) return c;
    int extra = c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : c >= 0xc0 ? 1 : -1;
    if (extra < 0 || i + size_t(extra) > s.size()) return U'\uFFFD';
    char32_t cp = c & (0x3f >> extra);
    for (int k = 0; k < extra; ++k) {
        unsigned char d = static_cast<unsigned char>(s[i]);
        if ((d & 0xc0) != 0x80) return U'\uFFFD';
        cp = (cp << 6) | (d & 0x3f);
        ++i;
    }
    return cp;
}

}  // namespace

int columns(std::string_view s) {
    int n = 0;
    for (size_t i = 0; i < s.size();) {
        next_cp(s, i);
        ++n;
    }
    return n;
}

std::string utf8(char32_t c) {
    std::string out;
    if (c < 0x80) {
        out += char(c);
    } else if (c < 0x800) {
        out += char(0xc0 | (c >> 6));
        out += char(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
        out += char(0xe0 | (c >> 12));
        out += char(0x80 | ((c >> 6) & 0x3f));
        out += char(0x80 | (c & 0x3f));
    } else {
        out += char(0xf0 | (c >> 18));
        out += char(0x80 | ((c >> 12) & 0x3f));
        out += char(0x80 | ((c >> 6) & 0x3f));
        out += char(0x80 | (c & 0x3f));
    }
    return out;
}

Canvas::Canvas(int width, int height, bool ascii) : w_(0), h_(0), ascii_(ascii) {
    resize(width, height);
}

void Canvas::resize(int width, int height) {
    w_ = std::max(width, 1);
    h_ = std::max(height, 1);
    cells_.assign(size_t(w_ * h_), Cell{});
    owner_.assign(cells_.size(), 0);
}

void Canvas::clear() {
    std::fill(cells_.begin(), cells_.end(), Cell{});
    std::fill(owner_.begin(), owner_.end(), 0);
    cut_ = overwrites_ = 0;
}

namespace {
// The ASCII face of a character: the letter of an accented Latin-1 one (the
// French console under --ascii), the plain form of typographic marks.
char32_t ascii_of(char32_t ch) {
    static constexpr std::string_view kLatin1 =  // U+00C0..U+00FF
        "AAAAAAACEEEEIIIIDNOOOOOxOUUUUYTs"
        "aaaaaaaceeeeiiiidnooooo/ouuuuyty";
    if (ch >= 0xC0 && ch <= 0xFF) return char32_t(kLatin1[ch - 0xC0]);
    switch (ch) {
        case U'\u00a0':
        case U'\u202f':
            return U' ';  // no-break spaces
        case U'\u00ab':
        case U'\u00bb':
        case U'\u201c':
        case U'\u201d':
            return U'"';
        case U'\u2018':
        case U'\u2019':
            return U'\'';
        case U'\u2013':
        case U'\u2014':
            return U'-';
        case U'\u0152':
            return U'O';  // Œ
        case U'\u0153':
            return U'o';  // œ
        case U'\u2192':
            return U'>';
        default:
            return U'?';
    }
}
}  // namespace

void Canvas::put(int x, int y, char32_t ch, Style st) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    if (ch < 0x20 || ch == 0x7f) ch = U'?';  // never a control character on screen
    if (ascii_ && ch >= 0x80) ch = ascii_of(ch);
    const size_t i = size_t(y * w_ + x);
    // A text drawn over another's letters cuts it with no mark (a test counts them).
    if (writer_ != 0 && owner_[i] != 0 && owner_[i] != writer_ && cells_[i].ch != U' ' &&
        cells_[i].ch != ch)
        ++overwrites_;
    cells_[i] = Cell{ch, st};
    owner_[i] = writer_;
}

void Canvas::paint(int x, int y, char32_t ch, uint32_t fg, uint32_t bg) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    if (ch < 0x20 || ch == 0x7f) ch = U' ';
    if (ascii_ && ch >= 0x80) ch = ascii_of(ch);
    const size_t i = size_t(y * w_ + x);
    cells_[i] = Cell{ch, Style::normal, fg, bg};
    owner_[i] = 0;
}

// A text cut by its room ends with a mark in its last cell, never with half a
// word that reads as whole (issue 38: nothing cut at 80 columns unseen).
int Canvas::text(int x, int y, std::string_view s, Style st, int max) {
    int limit = max < 0 ? w_ - x : std::min(max, w_ - x);
    int n = 0;
    size_t i = 0;
    writer_ = ++texts_;
    while (i < s.size() && n < limit) {
        put(x + n, y, next_cp(s, i), st);
        ++n;
    }
    if (n > 0 && i < s.size() && s.find_first_not_of(' ', i) != std::string_view::npos) {
        put(x + n - 1, y, ascii_ ? U'>' : U'\u2026', st);
        ++cut_;
    }
    writer_ = 0;
    return n;
}

void Canvas::text_right(int x, int y, int w, std::string_view s, Style st) {
    int n = columns(s);
    if (n > w) {
        text(x, y, s, st, w);
        return;
    }
    text(x + w - n, y, s, st, n);
}

void Canvas::fill(const Rect& r, char32_t ch, Style st) {
    for (int y = r.y; y < r.y + r.h; ++y)
        for (int x = r.x; x < r.x + r.w; ++x) put(x, y, ch, st);
}

void Canvas::style(const Rect& r, Style st) {
    for (int y = std::max(r.y, 0); y < std::min(r.y + r.h, h_); ++y)
        for (int x = std::max(r.x, 0); x < std::min(r.x + r.w, w_); ++x)
            cells_[size_t(y * w_ + x)].st = st;
}

void Canvas::hline(int x, int y, int w, Style st) {
    for (int i = 0; i < w; ++i) put(x + i, y, horiz(), st);
}

void Canvas::rule(int y, std::string_view title, Style st) {
    hline(0, y, w_, Style::dim);
    if (title.empty()) return;
    put(1, y, U' ', st);
    int n = text(2, y, title, st);
    put(2 + n, y, U' ', st);
}

std::string Canvas::to_text() const {
    std::string out;
    for (int y = 0; y < h_; ++y) {
        std::string line;
        for (int x = 0; x < w_; ++x) line += utf8(at(x, y).ch);
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out += line;
        out += '\n';
    }
    return out;
}

}  // namespace pupitre::pages
