// Terminal key decoding, independent of ncurses: the bytes read from the tty become Key values
// (xterm, VT220, rxvt, Linux console and tmux sequences, UTF-8 text), and keys have the names
// used by the bindings file and the help page.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::console {

// Grouped by kind: one name per line would hide the groups.
// clang-format off
enum class KeyCode : uint8_t {
    none, character, enter, tab, backtab, backspace, escape,
    up, down, left, right, home, end, page_up, page_down, insert, del,
    f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12
};
// clang-format on

struct Key {
    KeyCode code = KeyCode::none;
    char32_t ch = 0;  // the code point, for KeyCode::character (lower-case letter for Ctrl-letter)
    bool ctrl = false, alt = false, shift = false;
    // The bytes that produced this key (given to readline when no binding takes it).
    std::string raw;
    bool operator==(const Key& o) const;  // compares code, ch and modifiers, not raw
};

// "F1", "S-F3", "C-c", "M-x", "C-Left", "PgUp", "PgDn", "Home", "End", "Ins", "Del", "Up", "Down",
// "Left", "Right", "Enter", "Tab", "S-Tab", "Backspace", "Esc", "a", "A", "é", "Space" (for ' ').
// Modifiers come in the order C- M- S-; a code point that cannot be shown is named "U+0085".
// Empty for KeyCode::none.
std::string key_name(const Key& k);

// The inverse, for the bindings file: false if the name is not a key. Names a terminal cannot
// send are refused ("S-a", "C-1"), and Ctrl aliases fold onto the key the terminal sends
// ("C-i" is Tab, "C-m" and "C-j" Enter, "C-h" Backspace, "C-[" Esc, "C-A" is "C-a").
bool parse_key_name(std::string_view name, Key& out);

class KeyDecoder {
  public:
    // Longest escape sequence kept whole; a longer one is dropped up to its final byte.
    static constexpr size_t kMaxSequence = 32;

    // Feeds bytes read from the terminal; complete keys are appended to `out`.
    void feed(std::string_view bytes, std::vector<Key>& out);
    // No byte came within the escape timeout (the caller owns the clock, ~25 ms):
    // a pending lone ESC, or an incomplete sequence, becomes keys now.
    void flush(std::vector<Key>& out);
    // Bytes held waiting for the rest of a sequence (at most kMaxSequence + 1 of them).
    // Also true in the tail of an over-long sequence, so that the caller's timeout ends it.
    bool pending() const { return !held_.empty() || skipping_; }
    size_t held_bytes() const { return held_.size(); }  // for tests: the hold stays bounded

  private:
    void drain(bool final, std::vector<Key>& out);

    std::string held_;       // the start of an incomplete key
    bool skipping_ = false;  // inside the tail of an over-long sequence
};

}  // namespace pupitre::console
