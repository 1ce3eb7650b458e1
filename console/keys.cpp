// Terminal key decoding: a small state machine over the held bytes, one key per step, so that
// the result never depends on how read() split the input, and key names for the bindings file.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/keys.hpp"

#include <cstdio>
#include <iterator>

namespace pupitre::console {

namespace {

constexpr char kEsc = '\x1b';
constexpr size_t kMax = KeyDecoder::kMaxSequence;

// What one decoding step did with the front of the held bytes.
struct Step {
    enum Kind : uint8_t { more, done, dropped, skipped } kind = more;  // skipped: eat the tail too
    size_t len = 0;
    Key key;
};

Step make(size_t len, KeyCode code, char32_t ch = 0, bool ctrl = false) {
    Step s{Step::done, len, {}};
    s.key.code = code;
    s.key.ch = ch;
    s.key.ctrl = ctrl;
    return s;
}

Step drop(size_t len, Step::Kind kind = Step::dropped) {
    return Step{kind, len, {}};
}

// Alt is sent as ESC before the key (xterm metaSendsEscape, rxvt, tmux, Linux console).
Step with_alt(Step s) {
    if (s.kind == Step::more) return s;
    s.key.alt = true;
    ++s.len;
    return s;
}

// ECMA-48: parameter and intermediate bytes, then one final byte.
bool is_param(unsigned char c) {
    return c >= 0x20 && c <= 0x3f;
}
bool is_final(unsigned char c) {
    return c >= 0x40 && c <= 0x7e;
}

// ---- UTF-8 ----------------------------------------------------------------------------------

// Length of the code point that `b` starts; 0 for a continuation byte, the overlong leads
// C0 and C1, and leads beyond U+10FFFF.
int utf8_length(unsigned char b) {
    if (b < 0x80) return 1;
    if (b >= 0xc2 && b <= 0xdf) return 2;
    if (b >= 0xe0 && b <= 0xef) return 3;
    if (b >= 0xf0 && b <= 0xf4) return 4;
    return 0;
}

// The second byte's range is what rules out overlong forms, surrogates and > U+10FFFF.
bool utf8_second_ok(unsigned char lead, unsigned char b) {
    unsigned char lo = 0x80, hi = 0xbf;
    if (lead == 0xe0) lo = 0xa0;
    if (lead == 0xed) hi = 0x9f;
    if (lead == 0xf0) lo = 0x90;
    if (lead == 0xf4) hi = 0x8f;
    return b >= lo && b <= hi;
}

// A bad byte becomes U+FFFD alone, so decoding resynchronises on the very next byte.
Step decode_utf8(std::string_view s, bool final) {
    const auto* u = reinterpret_cast<const unsigned char*>(s.data());
    const Step bad = make(1, KeyCode::character, 0xfffd);
    const int n = utf8_length(u[0]);
    if (n == 0) return bad;
    char32_t cp = u[0] & (0x7f >> n);
    for (int i = 1; i < n; ++i) {
        if (static_cast<size_t>(i) >= s.size()) return final ? bad : Step{};
        const bool ok = i == 1 ? utf8_second_ok(u[0], u[1]) : (u[i] & 0xc0) == 0x80;
        if (!ok) return bad;
        cp = (cp << 6) | (u[i] & 0x3f);
    }
    return make(n, KeyCode::character, cp);
}

void append_utf8(std::string& s, char32_t c) {
    if (c < 0x80) {
        s += static_cast<char>(c);
        return;
    }
    static constexpr unsigned char kLead[] = {0, 0, 0xc0, 0xe0, 0xf0};
    const int n = c < 0x800 ? 2 : c < 0x10000 ? 3 : 4;
    s += static_cast<char>(kLead[n] | (c >> (6 * (n - 1))));
    for (int i = n - 2; i >= 0; --i) s += static_cast<char>(0x80 | ((c >> (6 * i)) & 0x3f));
}

// ---- keys without ESC -----------------------------------------------------------------------

// Control bytes are what the tty sends for Ctrl with a key: 0x01-0x1a are C-a..C-z, except
// those that are Backspace, Tab and Enter on every terminal.
Step decode_plain(std::string_view s, bool final) {
    const unsigned char c = s[0];
    if (c == 0x0d || c == 0x0a) return make(1, KeyCode::enter);
    if (c == 0x09) return make(1, KeyCode::tab);
    if (c == 0x08 || c == 0x7f) return make(1, KeyCode::backspace);
    if (c == 0x1b) return make(1, KeyCode::escape);
    if (c == 0x00) return make(1, KeyCode::character, ' ', true);
    if (c < 0x1b) return make(1, KeyCode::character, U'a' + c - 1, true);
    if (c < 0x20)
        return make(1, KeyCode::character, static_cast<unsigned char>("\\]^_"[c - 0x1c]), true);
    if (c < 0x80) return make(1, KeyCode::character, c);
    return decode_utf8(s, final);
}

// ---- escape sequences -----------------------------------------------------------------------

struct Params {
    int n[2] = {-1, -1};  // -1: absent, take the default
    int count = 0;
};

// params -> ( number? ( ';' number? )? )   anything else (private '?', '<', ':') is not a key
bool parse_params(std::string_view p, Params& out) {
    if (p.empty()) return true;
    out.count = 1;
    for (const char c : p) {
        if (c == ';') {
            if (++out.count > 2) return false;
            continue;
        }
        if (c < '0' || c > '9') return false;
        int& v = out.n[out.count - 1];
        v = (v < 0 ? 0 : v) * 10 + (c - '0');
        if (v > 9999) return false;
    }
    return true;
}

// xterm sends 1 + (shift | alt << 1 | ctrl << 2 | meta << 3); meta is taken as Alt.
bool apply_modifier(int m, Key& k) {
    if (m < 0) return true;
    if (m < 1 || m > 16) return false;
    k.shift = (m - 1) & 1;
    k.alt = (m - 1) & 10;
    k.ctrl = (m - 1) & 4;
    return true;
}

// The final bytes that CSI and SS3 share.
KeyCode letter_key(char f) {
    using enum KeyCode;
    static constexpr std::string_view kFinals = "ABCDHFPQRS";
    static constexpr KeyCode kKeys[] = {up, down, right, left, home, end, f1, f2, f3, f4};
    const size_t i = kFinals.find(f);
    return i == std::string_view::npos ? none : kKeys[i];
}

// VT220 numbers (1 and 4 Find/Select are Home/End; 7 and 8 are rxvt's Home/End).
KeyCode tilde_key(int n) {
    using enum KeyCode;
    static constexpr KeyCode kTable[25] = {
        none, home, insert, del,  end, page_up, page_down, home, end, none, none, f1, f2,
        f3,   f4,   f5,     none, f6,  f7,      f8,        f9,   f10, none, f11,  f12};
    return n >= 0 && n < 25 ? kTable[n] : none;
}

// csi -> (1;m)? A-D|H|F|P-S  |  n(;m)? ~  |  n $|^|@ (rxvt shift, ctrl, both)  |  Z  |  a-d
bool csi_key(char f, const Params& p, Key& k) {
    const bool one = p.n[0] == -1 || p.n[0] == 1;
    if (f == '~' || f == '$' || f == '^' || f == '@') {
        k.code = tilde_key(p.n[0]);
        if (!apply_modifier(p.n[1], k)) return false;
        k.shift |= f == '$' || f == '@';
        k.ctrl |= f == '^' || f == '@';
    } else if (f == 'Z' && one) {
        k.code = KeyCode::backtab;
        if (!apply_modifier(p.n[1], k)) return false;
        k.shift = false;  // implied by the key: "S-Tab" names it
    } else if (f >= 'a' && f <= 'd' && p.count == 0) {
        k.code = letter_key(static_cast<char>(f - 'a' + 'A'));  // rxvt shifted arrows
        k.shift = true;
    } else if (one) {
        k.code = letter_key(f);
        if (!apply_modifier(p.n[1], k)) return false;
    }
    return k.code != KeyCode::none;
}

// ss3 -> (m | 1;m)? A-D|H|F|P-S|M  |  a-d (rxvt ctrl arrows)  |  j-y|X (application keypad)
bool ss3_key(char f, const Params& p, Key& k) {
    const int m = p.count < 2 ? p.n[0] : (p.n[0] == -1 || p.n[0] == 1) ? p.n[1] : 0;
    if (!apply_modifier(m, k)) return false;
    if (f >= 'a' && f <= 'd' && p.count == 0) {
        k.code = letter_key(static_cast<char>(f - 'a' + 'A'));
        k.ctrl = true;
    } else if (f == 'M') {
        k.code = KeyCode::enter;
    } else if (((f >= 'j' && f <= 'y') || f == 'X') && p.count == 0) {
        k.code = KeyCode::character;
        k.ch = f == 'X' ? U'=' : static_cast<unsigned char>("*+,-./0123456789"[f - 'j']);
    } else {
        k.code = letter_key(f);
    }
    return k.code != KeyCode::none;
}

// An unknown but well-formed sequence is eaten whole, never shown as junk text.
Step finish_sequence(std::string_view seq) {
    Params p;
    Step s = make(seq.size(), KeyCode::none);
    const char f = seq.back();
    const bool ok = parse_params(seq.substr(2, seq.size() - 3), p) &&
                    (seq[1] == '[' ? csi_key(f, p, s.key) : ss3_key(f, p, s.key));
    return ok ? s : drop(seq.size());
}

// Not a sequence after all: the user typed M-[ or M-O, and what follows is decoded anew.
Step alt_of_intro(std::string_view s) {
    Step st = make(2, KeyCode::character, static_cast<unsigned char>(s[1]));
    st.key.alt = true;
    return st;
}

// linux -> ESC [ [ A-E   (F1-F5 on the Linux console)
Step decode_linux_fkey(std::string_view s, bool final) {
    if (s.size() < 4) return final ? alt_of_intro(s) : Step{};
    if (s[3] >= 'A' && s[3] <= 'E')
        return make(4, static_cast<KeyCode>(static_cast<int>(KeyCode::f1) + s[3] - 'A'));
    return drop(is_final(static_cast<unsigned char>(s[3])) ? 4 : 3);
}

// rxvt ends shifted keys with '$', an intermediate byte for ECMA-48: ESC [ digits $ is whole.
bool rxvt_shift_final(std::string_view s, size_t i) {
    if (s[1] != '[' || s[i] != '$' || i == 2) return false;
    return s.substr(2, i - 2).find_first_not_of("0123456789") == std::string_view::npos;
}

// seq -> ESC ( '[' | 'O' ) param* final
Step decode_sequence(std::string_view s, bool final) {
    if (s[1] == '[' && s.size() > 2 && s[2] == '[') return decode_linux_fkey(s, final);
    size_t i = 2;
    for (; i < s.size() && i < kMax; ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (is_final(c) || rxvt_shift_final(s, i)) return finish_sequence(s.substr(0, i + 1));
        if (!is_param(c)) return alt_of_intro(s);
    }
    if (i == kMax) return drop(kMax, Step::skipped);
    return final ? alt_of_intro(s) : Step{};
}

// ESC ESC: Alt-Esc, or (rxvt, tmux without xterm-keys) Alt with a special key's sequence.
Step decode_alt_escape(std::string_view s, bool final) {
    Step alt_esc = make(2, KeyCode::escape);
    alt_esc.key.alt = true;
    if (s.size() == 2) return final ? alt_esc : Step{};
    if (s[2] != '[' && s[2] != 'O') return alt_esc;
    const Step inner = decode_sequence(s.substr(1), final);
    if (inner.kind == Step::done && inner.len == 2) return alt_esc;  // M-[ or M-O: not a sequence
    return with_alt(inner);
}

// A lone ESC waits: it is the Esc key only if nothing follows before the timeout.
Step decode_escape(std::string_view s, bool final) {
    if (s.size() == 1) return final ? make(1, KeyCode::escape) : Step{};
    if (s[1] == '[' || s[1] == 'O') return decode_sequence(s, final);
    if (s[1] == kEsc) return decode_alt_escape(s, final);
    return with_alt(decode_plain(s.substr(1), final));
}

// ---- names ----------------------------------------------------------------------------------

// Indexed by KeyCode.
constexpr std::string_view kNames[] = {
    "",      "",     "Enter", "Tab",  "S-Tab", "Backspace", "Esc", "Up",  "Down", "Left",
    "Right", "Home", "End",   "PgUp", "PgDn",  "Ins",       "Del", "F1",  "F2",   "F3",
    "F4",    "F5",   "F6",    "F7",   "F8",    "F9",        "F10", "F11", "F12"};
static_assert(std::size(kNames) == static_cast<size_t>(KeyCode::f12) + 1);

bool valid_code_point(char32_t c) {
    return c <= 0x10ffff && (c < 0xd800 || c > 0xdfff);
}

// Controls (C0, DEL, C1) and space would be invisible or break a bindings line.
bool shown_as_is(char32_t c) {
    return c > 0x20 && c != 0x7f && (c < 0x80 || c >= 0xa0) && valid_code_point(c);
}

std::string char_name(char32_t c) {
    if (c == ' ') return "Space";
    std::string s;
    if (shown_as_is(c)) {
        append_utf8(s, c);
        return s;
    }
    char b[16];
    std::snprintf(b, sizeof b, "U+%04X", static_cast<unsigned>(c));
    return b;
}

// U+ hex{1,6}
bool parse_code_point(std::string_view hex, char32_t& c) {
    if (hex.empty() || hex.size() > 6) return false;
    c = 0;
    for (const char h : hex) {
        const int d = h >= '0' && h <= '9'   ? h - '0'
                      : h >= 'A' && h <= 'F' ? h - 'A' + 10
                      : h >= 'a' && h <= 'f' ? h - 'a' + 10
                                             : -1;
        if (d < 0) return false;
        c = c * 16 + d;
    }
    return valid_code_point(c);
}

// base -> named key | "Space" | "U+" hex | one shown code point in UTF-8
bool parse_base(std::string_view name, Key& k) {
    for (size_t i = static_cast<size_t>(KeyCode::enter); i < std::size(kNames); ++i) {
        if (name == kNames[i]) {
            k.code = static_cast<KeyCode>(i);
            return true;
        }
    }
    k.code = KeyCode::character;
    if (name == "Space") {
        k.ch = ' ';
        return true;
    }
    if (name.size() > 2 && name.starts_with("U+")) return parse_code_point(name.substr(2), k.ch);
    if (name.empty()) return false;
    const Step s = decode_plain(name, true);
    k.ch = s.key.ch;
    const bool real_fffd = k.ch != 0xfffd || s.len == 3;  // not a lone invalid byte
    return s.key.code == KeyCode::character && !s.key.ctrl && s.len == name.size() &&
           shown_as_is(k.ch) && real_fffd;
}

// Folds Ctrl aliases onto what the terminal sends, and refuses what it cannot send.
bool normalize(Key& k) {
    if (k.code == KeyCode::tab && k.shift) {
        k.code = KeyCode::backtab;
        k.shift = false;
    }
    if (k.code != KeyCode::character) return true;
    if (k.shift) return false;  // the shift is in the character itself
    if (!k.ctrl) return true;
    if (k.ch >= 'A' && k.ch <= 'Z') k.ch += 'a' - 'A';
    static constexpr std::u32string_view kAliased = U"imjh[";
    static constexpr KeyCode kAliases[] = {KeyCode::tab, KeyCode::enter, KeyCode::enter,
                                           KeyCode::backspace, KeyCode::escape};
    if (const size_t a = kAliased.find(k.ch); a != std::u32string_view::npos) {
        k.code = kAliases[a];
        k.ch = 0;
        k.ctrl = false;
        return true;
    }
    return (k.ch >= 'a' && k.ch <= 'z') ||
           std::u32string_view(U" \\]^_").find(k.ch) != std::u32string_view::npos;
}

}  // namespace

bool Key::operator==(const Key& o) const {
    return code == o.code && ch == o.ch && ctrl == o.ctrl && alt == o.alt && shift == o.shift;
}

std::string key_name(const Key& k) {
    if (k.code == KeyCode::none) return {};
    std::string s;
    if (k.ctrl) s += "C-";
    if (k.alt) s += "M-";
    if (k.shift && k.code != KeyCode::backtab) s += "S-";
    if (k.code == KeyCode::character) return s + char_name(k.ch);
    const auto i = static_cast<size_t>(k.code);
    return i < std::size(kNames) ? s.append(kNames[i]) : std::string();
}

// name -> ( ( 'C' | 'M' | 'S' ) '-' )* base
bool parse_key_name(std::string_view name, Key& out) {
    Key k;
    while (name.size() > 2 && name[1] == '-') {
        bool* flag = name[0] == 'C'   ? &k.ctrl
                     : name[0] == 'M' ? &k.alt
                     : name[0] == 'S' ? &k.shift
                                      : nullptr;
        if (flag == nullptr) break;
        *flag = true;
        name.remove_prefix(2);
    }
    if (!parse_base(name, k) || !normalize(k)) return false;
    out = k;
    return true;
}

void KeyDecoder::feed(std::string_view bytes, std::vector<Key>& out) {
    held_.append(bytes);
    drain(false, out);
}

void KeyDecoder::flush(std::vector<Key>& out) {
    drain(true, out);
    skipping_ = false;
}

// Decodes as many keys as the held bytes allow; `final` says no more bytes are coming.
void KeyDecoder::drain(bool final, std::vector<Key>& out) {
    size_t pos = 0;
    while (pos < held_.size()) {
        const std::string_view rest = std::string_view(held_).substr(pos);
        const auto c = static_cast<unsigned char>(rest[0]);
        if (skipping_) {  // the tail of an over-long sequence, up to and with its final byte
            skipping_ = is_param(c);
            pos += is_param(c) || is_final(c);
            continue;
        }
        Step s = c == 0x1b ? decode_escape(rest, final) : decode_plain(rest, final);
        if (s.kind == Step::more) break;
        if (s.kind == Step::done) {
            s.key.raw.assign(rest.substr(0, s.len));
            out.push_back(std::move(s.key));
        }
        skipping_ = s.kind == Step::skipped;
        pos += s.len;
    }
    held_.erase(0, pos);
}

}  // namespace pupitre::console
