// Key decoder: every sequence family, the same keys whatever the read() split, lone ESC only on
// the timeout, UTF-8 and its errors, unknown sequences swallowed, key names round-trip.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "console/keys.hpp"

using namespace pupitre::console;

namespace {

using namespace std::string_literals;

std::string names(const std::vector<Key>& keys) {
    std::string s;
    for (const Key& k : keys) s += (s.empty() ? "" : " ") + key_name(k);
    return s;
}

std::string raws(const std::vector<Key>& keys) {
    std::string s;
    for (const Key& k : keys) s += k.raw;
    return s;
}

std::vector<Key> decode(std::string_view in, bool flush = true) {
    KeyDecoder d;
    std::vector<Key> out;
    d.feed(in, out);
    if (flush) d.flush(out);
    return out;
}

std::vector<Key> decode_bytewise(std::string_view in) {
    KeyDecoder d;
    std::vector<Key> out;
    for (const char c : in) d.feed(std::string_view(&c, 1), out);
    d.flush(out);
    return out;
}

std::string names_of(std::string_view in) {
    return names(decode(in));
}

struct Case {
    std::string bytes, name;
};

// One complete key each: decoded at once without waiting for the timeout, and byte by byte.
void expect_keys(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
        const std::vector<Key> keys = decode(c.bytes, false);
        ASSERT_EQ(keys.size(), 1u) << c.name;
        EXPECT_EQ(key_name(keys[0]), c.name);
        EXPECT_EQ(keys[0].raw, c.bytes) << c.name;
        EXPECT_EQ(names(decode_bytewise(c.bytes)), c.name);
    }
}

}  // namespace

TEST(Keys, CsiAndSs3Arrows) {
    expect_keys({{"\x1b[A", "Up"},
                 {"\x1b[B", "Down"},
                 {"\x1b[C", "Right"},
                 {"\x1b[D", "Left"},
                 {"\x1bOA", "Up"},
                 {"\x1bOB", "Down"},
                 {"\x1bOC", "Right"},
                 {"\x1bOD", "Left"}});
}

TEST(Keys, HomeEndAndEditingKeys) {
    expect_keys({{"\x1b[H", "Home"},
                 {"\x1b[F", "End"},
                 {"\x1bOH", "Home"},
                 {"\x1bOF", "End"},
                 {"\x1b[1~", "Home"},
                 {"\x1b[4~", "End"},
                 {"\x1b[7~", "Home"},
                 {"\x1b[8~", "End"},
                 {"\x1b[2~", "Ins"},
                 {"\x1b[3~", "Del"},
                 {"\x1b[5~", "PgUp"},
                 {"\x1b[6~", "PgDn"}});
}

TEST(Keys, FunctionKeys) {
    expect_keys({{"\x1bOP", "F1"},   {"\x1bOQ", "F2"},   {"\x1bOR", "F3"},    {"\x1bOS", "F4"},
                 {"\x1b[11~", "F1"}, {"\x1b[12~", "F2"}, {"\x1b[13~", "F3"},  {"\x1b[14~", "F4"},
                 {"\x1b[[A", "F1"},  {"\x1b[[B", "F2"},  {"\x1b[[C", "F3"},   {"\x1b[[D", "F4"},
                 {"\x1b[[E", "F5"},  {"\x1b[15~", "F5"}, {"\x1b[17~", "F6"},  {"\x1b[18~", "F7"},
                 {"\x1b[19~", "F8"}, {"\x1b[20~", "F9"}, {"\x1b[21~", "F10"}, {"\x1b[23~", "F11"},
                 {"\x1b[24~", "F12"}});
}

TEST(Keys, XtermModifiers) {
    expect_keys({{"\x1b[1;2A", "S-Up"},
                 {"\x1b[1;5D", "C-Left"},
                 {"\x1b[1;3C", "M-Right"},
                 {"\x1b[1;6B", "C-S-Down"},
                 {"\x1b[1;8H", "C-M-S-Home"},
                 {"\x1b[1;2R", "S-F3"},
                 {"\x1b[1;5P", "C-F1"},
                 {"\x1b[5;5~", "C-PgUp"},
                 {"\x1b[3;3~", "M-Del"},
                 {"\x1b[15;2~", "S-F5"},
                 {"\x1b[24;7~", "C-M-F12"},
                 {"\x1b[1;9A", "M-Up"},
                 {"\x1b[;5A", "C-Up"},
                 {"\x1b[2;1~", "Ins"},
                 {"\x1bO2P", "S-F1"},
                 {"\x1bO5A", "C-Up"},
                 {"\x1bO1;3Q", "M-F2"}});
}

TEST(Keys, BacktabRxvtAndKeypad) {
    expect_keys({{"\x1b[Z", "S-Tab"},
                 {"\x1b[1;5Z", "C-S-Tab"},
                 {"\x1b[a", "S-Up"},
                 {"\x1b[d", "S-Left"},
                 {"\x1bOa", "C-Up"},
                 {"\x1bOd", "C-Left"},
                 {"\x1b[2$", "S-Ins"},
                 {"\x1b[5^", "C-PgUp"},
                 {"\x1b[3@", "C-S-Del"},
                 {"\x1b[23$", "S-F11"},
                 {"\x1bOM", "Enter"},
                 {"\x1bOp", "0"},
                 {"\x1bOy", "9"},
                 {"\x1bOj", "*"},
                 {"\x1bOX", "="}});
}

TEST(Keys, ControlBytes) {
    expect_keys({{"\r", "Enter"},
                 {"\n", "Enter"},
                 {"\t", "Tab"},
                 {"\x7f", "Backspace"},
                 {"\x08", "Backspace"},
                 {"\0"s, "C-Space"},
                 {"\x01", "C-a"},
                 {"\x03", "C-c"},
                 {"\x07", "C-g"},
                 {"\x0b", "C-k"},
                 {"\x1a", "C-z"},
                 {"\x1c", "C-\\"},
                 {"\x1d", "C-]"},
                 {"\x1e", "C-^"},
                 {"\x1f", "C-_"},
                 {" ", "Space"},
                 {"a", "a"},
                 {"A", "A"},
                 {"~", "~"},
                 {"-", "-"}});
    const std::vector<Key> k = decode("\x03");
    EXPECT_EQ(k[0].code, KeyCode::character);
    EXPECT_EQ(k[0].ch, U'c');
    EXPECT_TRUE(k[0].ctrl);
}

TEST(Keys, AltIsEscapePrefix) {
    expect_keys({{"\x1bx", "M-x"},
                 {"\x1bX", "M-X"},
                 {"\x1b\x03", "C-M-c"},
                 {"\x1b\r", "M-Enter"},
                 {"\x1b\x7f", "M-Backspace"},
                 {"\x1b ", "M-Space"},
                 {"\x1b-", "M--"},
                 {"\x1b\xc3\xa9", "M-\xc3\xa9"},
                 {"\x1b\x1b[A", "M-Up"},
                 {"\x1b\x1bOP", "M-F1"},
                 {"\x1b\x1b[1;5D", "C-M-Left"},
                 {"\x1b\t", "M-Tab"}});
    EXPECT_EQ(names_of("\x1b\x1b"), "M-Esc");  // waits: it could start M-Up
    EXPECT_EQ(names_of("\x1b\x1bx"), "M-Esc x");
    EXPECT_EQ(names_of("\x1b\x1b\x1b"), "M-Esc Esc");
    EXPECT_EQ(names_of("\x1b\x1b[?5h"), "");  // an unknown sequence stays swallowed
}

TEST(Keys, LoneEscapeOnlyAfterFlush) {
    KeyDecoder d;
    std::vector<Key> out;
    d.feed("\x1b", out);
    EXPECT_TRUE(out.empty());
    EXPECT_TRUE(d.pending());
    d.flush(out);
    EXPECT_EQ(names(out), "Esc");
    EXPECT_EQ(out[0].raw, "\x1b");
    EXPECT_FALSE(d.pending());
    // Esc then Up, with the timeout between them
    d.feed("\x1b", out);
    d.flush(out);
    d.feed("\x1b[A", out);
    EXPECT_EQ(names(out), "Esc Esc Up");
    // without a timeout, ESC and the next key are one Alt key
    out.clear();
    d.feed("\x1b", out);
    d.feed("x", out);
    EXPECT_EQ(names(out), "M-x");
    EXPECT_FALSE(d.pending());
    out.clear();
    d.flush(out);  // nothing held: nothing comes
    EXPECT_TRUE(out.empty());
}

TEST(Keys, IncompleteSequenceBecomesKeysOnFlush) {
    EXPECT_EQ(names_of("\x1b["), "M-[");
    EXPECT_EQ(names_of("\x1bO"), "M-O");
    EXPECT_EQ(names_of("\x1b[1;5"), "M-[ 1 ; 5");
    EXPECT_EQ(names_of("\x1b[["), "M-[ [");
    EXPECT_EQ(raws(decode("\x1b[1;5")), "\x1b[1;5");
    KeyDecoder d;
    std::vector<Key> out;
    d.feed("\x1b[1;", out);
    EXPECT_TRUE(out.empty());
    EXPECT_TRUE(d.pending());
}

TEST(Keys, MalformedSequenceIsKeysNotLost) {
    EXPECT_EQ(names_of("\x1b[1\x03"), "M-[ 1 C-c");
    EXPECT_EQ(names_of("\x1b[\x1b[A"), "M-[ Up");  // Alt-[ then Up typed quickly
    EXPECT_EQ(names_of("\x1bO\r"), "M-O Enter");
}

TEST(Keys, Utf8SplitAcrossFeeds) {
    for (const auto& [bytes, cp] : std::vector<std::pair<std::string, char32_t>>{
             {"\xc3\xa9", U'é'}, {"\xe2\x82\xac", U'€'}, {"\xf0\x9f\x98\x80", U'😀'}}) {
        KeyDecoder d;
        std::vector<Key> out;
        for (size_t i = 0; i + 1 < bytes.size(); ++i) {
            d.feed(bytes.substr(i, 1), out);
            EXPECT_TRUE(out.empty());
            EXPECT_TRUE(d.pending());
        }
        d.feed(bytes.substr(bytes.size() - 1), out);
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(out[0].code, KeyCode::character);
        EXPECT_EQ(out[0].ch, cp);
        EXPECT_EQ(out[0].raw, bytes);
        EXPECT_EQ(key_name(out[0]), bytes);
    }
    EXPECT_EQ(names(decode_bytewise("a\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80z")),
              "a \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80 z");
}

TEST(Keys, InvalidUtf8IsReplacementPerByte) {
    struct Bad {
        std::string bytes;
        std::string tail;  // the keys after the U+FFFD ones
        size_t fffd;
    };
    for (const Bad& b : std::vector<Bad>{{"\xff", "", 1},
                                         {"\x80", "", 1},
                                         {"\xc0\x80", "", 2},          // overlong NUL
                                         {"\xe0\x80\x80", "", 3},      // overlong
                                         {"\xed\xa0\x80", "", 3},      // surrogate
                                         {"\xf4\x90\x80\x80", "", 4},  // above U+10FFFF
                                         {"\xe2\x82"
                                          "A",
                                          "A", 2},  // truncated, resyncs
                                         {"\xc3\x1b[A", "Up", 1},
                                         {"\xe2\x82", "", 2}}) {  // truncated at the timeout
        for (const std::vector<Key>& keys : {decode(b.bytes), decode_bytewise(b.bytes)}) {
            ASSERT_GE(keys.size(), b.fffd);
            for (size_t i = 0; i < b.fffd; ++i) {
                EXPECT_EQ(keys[i].ch, 0xfffdu);
                EXPECT_EQ(keys[i].raw, b.bytes.substr(i, 1));
            }
            EXPECT_EQ(names(std::vector<Key>(keys.begin() + b.fffd, keys.end())), b.tail);
            EXPECT_EQ(raws(keys), b.bytes);
        }
    }
}

TEST(Keys, UnknownSequencesAreSwallowed) {
    EXPECT_EQ(names_of("a\x1b[?1;2cb"), "a b");       // device attributes reply
    EXPECT_EQ(names_of("\x1b[200~x\x1b[201~"), "x");  // bracketed paste marks
    EXPECT_EQ(names_of("\x1b[I\x1b[O"), "");          // focus in and out
    EXPECT_EQ(names_of("\x1b[<0;10;20M"), "");        // SGR mouse
    EXPECT_EQ(names_of("\x1b[99~\x1b[1;99A\x1b[1;2;3A"), "");
    EXPECT_EQ(names_of("\x1bOz\x1b[[Z\x1b[16~"), "");
    EXPECT_EQ(names_of("\x1b[5x\x1b[ q"), "");
    EXPECT_EQ(names(decode_bytewise("a\x1b[?1;2cb")), "a b");
}

TEST(Keys, OverlongSequenceDroppedAndBounded) {
    // 32 bytes is still a sequence; 33 is dropped, up to and with its final byte
    const std::string in32 = "\x1b[" + std::string(28, '0') + "5~";
    ASSERT_EQ(in32.size(), 32u);
    EXPECT_EQ(names_of(in32), "PgUp");
    const std::string in33 = "\x1b[" + std::string(29, '0') + "5~";
    EXPECT_EQ(names_of(in33 + "ab"), "a b");
    EXPECT_EQ(names(decode_bytewise(in33 + "ab")), "a b");

    KeyDecoder d;
    std::vector<Key> out;
    d.feed("\x1b[", out);
    for (int i = 0; i < 10000; ++i) {
        d.feed(";1", out);
        ASSERT_LE(d.held_bytes(), KeyDecoder::kMaxSequence + 1);
    }
    d.feed("~x\x1b[A", out);
    EXPECT_EQ(names(out), "x Up");
    // the timeout ends the tail: later digits are typed text again
    out.clear();
    d.feed("\x1b[" + std::string(40, '1'), out);
    d.flush(out);
    d.feed("12", out);
    EXPECT_EQ(names(out), "1 2");
}

TEST(Keys, RawBytesAreKept) {
    const std::string in = "a\x1b[A\xc3\xa9\r\x1b\x1b[1;5C\x1bx\x03\x1bOP \t";
    const std::vector<Key> keys = decode(in);
    EXPECT_EQ(names(keys), "a Up \xc3\xa9 Enter C-M-Right M-x C-c F1 Space Tab");
    EXPECT_EQ(raws(keys), in);
}

TEST(KeyNames, RoundTripForAllNamedKeys) {
    for (int c = static_cast<int>(KeyCode::enter); c <= static_cast<int>(KeyCode::f12); ++c) {
        for (int m = 0; m < 8; ++m) {
            Key k;
            k.code = static_cast<KeyCode>(c);
            k.ctrl = m & 4, k.alt = m & 2, k.shift = (m & 1) && k.code != KeyCode::backtab;
            if (k.code == KeyCode::tab && k.shift) continue;  // that is S-Tab, the backtab
            Key back;
            ASSERT_TRUE(parse_key_name(key_name(k), back)) << key_name(k);
            EXPECT_EQ(back, k) << key_name(k);
        }
    }
    for (const char32_t ch :
         {U'a', U'A', U'~', U' ', U'é', U'€', U'😀', U'\x85', U'\xa0', U'\xfffd'}) {
        for (int alt = 0; alt < 2; ++alt) {
            Key k;
            k.code = KeyCode::character, k.ch = ch, k.alt = alt;
            Key back;
            ASSERT_TRUE(parse_key_name(key_name(k), back)) << key_name(k);
            EXPECT_EQ(back, k) << key_name(k);
        }
    }
    for (const char32_t ch : U"abcxyz \\]^_") {
        if (ch == 0) continue;
        Key k;
        k.code = KeyCode::character, k.ch = ch, k.ctrl = true;
        Key back;
        ASSERT_TRUE(parse_key_name(key_name(k), back)) << key_name(k);
        EXPECT_EQ(back, k);
    }
}

TEST(KeyNames, Spellings) {
    Key k;
    k.code = KeyCode::f3, k.shift = true;
    EXPECT_EQ(key_name(k), "S-F3");
    k = Key{};
    k.code = KeyCode::character, k.ch = U'\x85';
    EXPECT_EQ(key_name(k), "U+0085");
    EXPECT_EQ(key_name(Key{}), "");
    ASSERT_TRUE(parse_key_name("C-Left", k));
    EXPECT_EQ(k.code, KeyCode::left);
    EXPECT_TRUE(k.ctrl);
    ASSERT_TRUE(parse_key_name("é", k));
    EXPECT_EQ(k.ch, U'é');
    ASSERT_TRUE(parse_key_name("U+20ac", k));
    EXPECT_EQ(key_name(k), "€");
}

TEST(KeyNames, AliasesFoldOntoWhatTheTerminalSends) {
    const std::vector<std::pair<std::string, std::string>> aliases = {
        {"C-i", "Tab"},         {"C-m", "Enter"},  {"C-j", "Enter"},   {"C-h", "Backspace"},
        {"C-[", "Esc"},         {"C-A", "C-a"},    {"C-M-i", "M-Tab"}, {"S-Tab", "S-Tab"},
        {"C-S-Tab", "C-S-Tab"}, {"M-C-x", "C-M-x"}};
    for (const auto& [in, want] : aliases) {
        Key k;
        ASSERT_TRUE(parse_key_name(in, k)) << in;
        EXPECT_EQ(key_name(k), want);
    }
    Key k;
    ASSERT_TRUE(parse_key_name("S-Tab", k));
    EXPECT_EQ(k.code, KeyCode::backtab);
    EXPECT_EQ(decode("\x1b[Z")[0], k);
}

TEST(KeyNames, RefusesWhatIsNotAKey) {
    for (const std::string bad :
         {"",       "Foo",      "S-a",  "C-1",        "C-\xc3\xa9", "ab",    "X-a",
          "U+D800", "U+110000", "U+",   "U+12345678", "\xff",       "\xc3",  "C-",
          "F13",    "\x01",     "\x7f", "\xc2\x85",   "up",         "Space "}) {
        Key k;
        EXPECT_FALSE(parse_key_name(bad, k)) << bad;
    }
}

// Keys from valid encodings, joined and read in random chunks, come back the same, with their
// bytes; a lone ESC or ESC ESC is left out since what follows changes what they mean.
TEST(KeysProperty, ValidKeysInRandomChunks) {
    const std::vector<std::string> pool = {
        "\x1b[A",       "\x1bOB", "\x1b[1;5C", "\x1b[3~",  "\x1b[24;2~",   "\x1b[[E",
        "\x1bOP",       "\x1b[Z", "\x1b[2$",   "\x1bOd",   "\x1b\x1b[A",   "\x1bx",
        "\x1b\x03",     "\r",     "\t",        "\x7f",     "\0"s,          "\x01",
        "\x1f",         "a",      " ",         "\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80",
        "\x1b\xc3\xa9", "\x1bOM"};
    std::mt19937 rng(7);
    for (int round = 0; round < 500; ++round) {
        std::string in;
        std::vector<Key> want;
        const int n = std::uniform_int_distribution<int>(1, 40)(rng);
        for (int i = 0; i < n; ++i) {
            std::string piece = pool[rng() % pool.size()];
            if (rng() % 4 == 0) {  // any code point that is not a control
                char32_t cp = std::uniform_int_distribution<char32_t>(0xa0, 0x10ffff)(rng);
                if (cp >= 0xd800 && cp <= 0xdfff) cp = U'Z';
                Key k;
                k.code = KeyCode::character, k.ch = cp;
                ASSERT_TRUE(parse_key_name(key_name(k), k));
                piece = key_name(k);
            }
            const std::vector<Key> one = decode(piece);
            ASSERT_EQ(one.size(), 1u) << piece;
            want.push_back(one[0]);
            in += piece;
        }
        KeyDecoder d;
        std::vector<Key> got;
        for (size_t pos = 0; pos < in.size();) {
            const size_t len = std::uniform_int_distribution<size_t>(0, 9)(rng);
            d.feed(std::string_view(in).substr(pos, len), got);
            pos += len;
        }
        EXPECT_FALSE(d.pending());
        ASSERT_EQ(got, want) << names(got) << " / " << names(want);
        EXPECT_EQ(raws(got), in);
    }
}

// Whatever the bytes: no crash, bounded hold, the same keys for any chunking, keys that name
// themselves, and raw bytes that are the input with only whole sequences cut out.
TEST(KeysProperty, RandomBytesInRandomChunks) {
    const std::string alphabet =
        "\x1b\x1b\x1b[[[OOO;;0123456789~$^@ABCDHFPQRSZ?<Mabjz\r\t\x7f\x01"
        "\x80\xbf\xc3\xe2\xf0\xff\xed\xa9";
    std::mt19937 rng(11);
    for (int round = 0; round < 3000; ++round) {
        std::string in(std::uniform_int_distribution<size_t>(0, 80)(rng), '\0');
        for (char& c : in) c = rng() % 8 ? alphabet[rng() % alphabet.size()] : char(rng());
        const std::vector<Key> whole = decode(in);
        KeyDecoder d;
        std::vector<Key> got;
        for (size_t pos = 0; pos < in.size();) {
            const size_t len = std::uniform_int_distribution<size_t>(1, 12)(rng);
            d.feed(std::string_view(in).substr(pos, len), got);
            ASSERT_LE(d.held_bytes(), KeyDecoder::kMaxSequence + 1);
            pos += len;
        }
        d.flush(got);
        EXPECT_FALSE(d.pending());
        ASSERT_EQ(got, whole);
        size_t at = 0;  // each raw is found, in order, in what is left of the input
        for (size_t i = 0; i < got.size(); ++i) {
            const Key& k = got[i];
            ASSERT_NE(k.code, KeyCode::none);
            ASSERT_EQ(k.raw, whole[i].raw);
            ASSERT_FALSE(k.raw.empty());
            at = in.find(k.raw, at);
            ASSERT_NE(at, std::string::npos);
            at += k.raw.size();
            Key back;
            ASSERT_TRUE(parse_key_name(key_name(k), back)) << key_name(k);
            ASSERT_EQ(back, k) << key_name(k);
        }
    }
}
