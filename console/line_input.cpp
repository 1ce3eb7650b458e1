// The plain input line (see line_input.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/line_input.hpp"

namespace pupitre::console {

void PlainLineInput::feed(std::string_view bytes) {
    if (!bytes.empty() && bytes.front() == '\x1b') return;  // cursor keys: not for this editor
    for (char c : bytes) {
        unsigned char u = static_cast<unsigned char>(c);
        if (c == '\r' || c == '\n') {
            std::string line = std::move(text_);
            text_.clear();
            if (on_line) on_line(line);
        } else if (u == 0x7f || u == 0x08) {
            // Backspace removes a whole UTF-8 code point.
            while (!text_.empty() && (static_cast<unsigned char>(text_.back()) & 0xc0) == 0x80)
                text_.pop_back();
            if (!text_.empty()) text_.pop_back();
        } else if (u == 0x15) {
            text_.clear();  // Ctrl-U
        } else if (u >= 0x20 || u >= 0x80) {
            text_ += c;
        }
        // Other control bytes and escape sequences are ignored.
    }
}

int PlainLineInput::cursor() const {
    int n = 0;
    for (char c : text_) n += (static_cast<unsigned char>(c) & 0xc0) != 0x80;
    return n;
}

}  // namespace pupitre::console
