// The block parser: NUM character set, words, blank values, comments, L/E
// assignments with left-to-right expressions, G79 tests, $ messages.
// Grammar (000:362-470, 000:7444-7457; pupitre-iso(5), BLOCKS and PARAMETRIC PROGRAMMING):
//   block      -> ['/'] { word | comment | assign | message }
//   word       -> address [sign] [number | 'L'digits | 'E'digits | 'EL'digits | symbol]
//   assign     -> ('L'digits | 'E'digits | 'EL'digits | symbol) '=' expr
//   expr       -> term { binop term }           (strictly left to right)
//   term       -> { sign | S | C | A | R | T } operand
//   test       -> expr cmp expr                 (only after G79)
//   message    -> '$' digit text-up-to-'('-or-end
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parse/block.hpp"

#include <charconv>
#include <cstring>
#include <string>

#include "core/i18n.hpp"

namespace pupitre {

namespace {
// The text of each address (block.hpp: A-Z, EA-EZ, NA-NZ, E+, LA-LZ), built
// at compile time: a table filled at the first call behind a flag would be a
// data race between two interpreters on two threads (ARCHITECTURE.md, Conventions).
struct AddrNames {
    char text[kAddrCount][3] = {};
    constexpr AddrNames() {
        for (int i = 0; i < 26; ++i) {
            set(addr1(char('A' + i)), 'A' + i, 0);
            set(addrE(char('A' + i)), 'E', 'A' + i);
            set(addrN(char('A' + i)), 'N', 'A' + i);
            set(addrL(char('A' + i)), 'L', 'A' + i);
        }
        set(kAddrEsign, 'E', '+');
    }
    constexpr void set(Addr a, int c0, int c1) {
        text[a][0] = char(c0);
        text[a][1] = char(c1);
    }
};
constexpr AddrNames kAddrNames;
}  // namespace

std::string_view addr_name(Addr a) {
    if (a >= kAddrCount) return "?";
    const char* t = kAddrNames.text[a];
    return std::string_view(t, t[1] ? 2 : 1);
}

namespace {

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}
bool is_upper(char c) {
    return c >= 'A' && c <= 'Z';
}
bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// The digits of a number at `i`: digits [ '.' digits ] | '.' digits, as a
// mantissa (which wraps past 19 digits, where from_chars takes over) and
// the counts on each side of the point; `end` is one past the last.
struct Digits {
    uint64_t m = 0;
    size_t int_digits = 0, frac_digits = 0, end = 0;
};
// A digit's value, or more than 9: one comparison a character (issue 14).
inline unsigned digit_at(const char* p, size_t i) {
    return unsigned(uint8_t(p[i])) - unsigned('0');
}
// The digits at `i` (before `n`) appended to `m`; returns one past the last.
// (Eight at a time, with 64-bit arithmetic, measured 6% more instructions a
// block on g17_mix, whose numbers have 3 or 4 digits a side: issue 14.)
inline size_t digit_run(const char* p, size_t i, size_t n, uint64_t& m) {
    for (unsigned v; i < n && (v = digit_at(p, i)) <= 9; ++i) m = m * 10 + v;
    return i;
}

inline Digits scan_digits(const char* p, size_t i, size_t n) {
    Digits d;
    const size_t start = i;
    uint64_t m = 0;
    i = digit_run(p, i, n, m);
    d.int_digits = i - start;
    if (i < n && p[i] == '.') {
        const size_t f = ++i;
        i = digit_run(p, i, n, m);
        d.frac_digits = i - f;
    }
    d.m = m;
    d.end = i;
    return d;
}

// Up to 15 digits, mantissa and power of ten are exact doubles, so the one
// division rounds correctly: the value from_chars would give, faster.
constexpr size_t kExactDigits = 15;
inline double exact_value(const Digits& d) {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    return double(d.m) / kPow10[d.frac_digits];
}

// The fast lane (issue 14). Most blocks are a label and words of a letter and
// a number written against it: "N60 G2 X12.963 Y-127.942 I6.264 J-137.481".
// This reads such a block in one pass and makes the Block the Parser would;
// at anything else (a blank or variable value, a space inside a word, E, L
// and O words, NC-like addresses, G76 G77 G79, a $ message, a number of more
// than 15 digits, an error) it gives up, and the Parser reads the line from
// its start.
//
// kToNewline: the line is read from `p` up to its '\n' (`n`, the bytes that
// follow `p`, bounds the reads of digits), and its
// length left in `len`: the caller need not find the line's end first
// (issue 14: that was one memchr a block). A '\0' (std::string's terminator,
// past the text's end) is a character the lane does not take.
template <bool kToNewline>
bool plain_lane(const char* p, size_t n, Block& b, size_t& len) {
    auto at_end = [&](size_t i) {
        if constexpr (kToNewline)
            return p[i] == '\n';
        else
            return i == n;
    };
    size_t i = 0;
    while (!at_end(i) && is_blank(p[i])) ++i;
    if (!at_end(i) && p[i] == '/') {
        b.skip = true;
        ++i;
    }
    for (;;) {
        while (!at_end(i) && is_blank(p[i])) ++i;
        if (at_end(i)) {
            len = i;
            return true;
        }
        const char c = p[i];
        if (c == '(') {
            size_t close = i + 1;
            while (!at_end(close) && p[close] != ')' && p[close] != '\0') ++close;
            if (at_end(close) || p[close] != ')') return false;
            i = close + 1;
            continue;
        }
        if (!is_upper(c) || c == 'E' || c == 'L' || c == 'O') return false;
        Word& w = b.words.emplace_back();
        w.addr = addr1(c);
        w.col = uint16_t(i + 1);
        size_t k = i + 1;
        if (!at_end(k) && (p[k] == '+' || p[k] == '-')) {
            w.v.has_sign = true;
            w.v.neg = p[k] == '-';
            ++k;
        }
        const Digits d = scan_digits(p, k, n);
        const size_t digits = d.int_digits + d.frac_digits;
        if (digits == 0 || digits > kExactDigits) return false;
        w.v.kind = Operand::Number;
        w.v.int_digits = uint8_t(d.int_digits);
        w.v.frac_digits = uint8_t(d.frac_digits);
        w.v.num = exact_value(d);
        i = d.end;
        if (c == 'G') {
            const int g = w.v.num < 1e6 ? int(w.v.num) : -1;
            if (g == 76 || g == 77 || g == 79) return false;
        } else if (c == 'N' && b.words.size() == 1) {
            if (d.frac_digits || d.int_digits > 5) return false;
            b.n = long(w.v.num);
        }
    }
}

bool parse_plain(std::string_view line, Block& b) {
    size_t len;
    return plain_lane<false>(line.data(), line.size(), b, len);
}

struct Parser {
    std::string_view line;
    size_t pos = 0;
    Block& b;
    Error err{};  // what run() answers when it is false

    bool fail(int code, size_t at, std::string msg) {
        err.code = code;
        err.column = int(at) + 1;
        err.detail = std::move(msg);
        return false;
    }
    char peek(size_t k = 0) const { return pos + k < line.size() ? line[pos + k] : '\0'; }
    void skip_spaces() {
        while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t' || line[pos] == '\r'))
            ++pos;
    }
    size_t after_spaces(size_t p) const {
        while (p < line.size() && (line[p] == ' ' || line[p] == '\t')) ++p;
        return p;
    }

    /* number -> digits ['.' digits] | '.' digits */
    bool number(Operand& v) {
        const size_t start = pos;
        const Digits d = scan_digits(line.data(), start, line.size());
        pos = d.end;
        v.int_digits = uint8_t(std::min<size_t>(d.int_digits, 255));
        v.frac_digits = uint8_t(std::min<size_t>(d.frac_digits, 255));
        if (d.int_digits == 0 && d.frac_digits == 0) return fail(1, start, tr("number expected"));
        if (d.int_digits + d.frac_digits <= kExactDigits) {
            v.num = exact_value(d);
        } else {
            std::string_view span = line.substr(start, pos - start);
            char buf[64];
            if (span.size() >= sizeof buf - 1) return fail(1, start, tr("too many digits"));
            size_t k = 0;
            if (span.front() == '.') buf[k++] = '0';
            std::memcpy(buf + k, span.data(), span.size());
            k += span.size();
            if (buf[k - 1] == '.') buf[k++] = '0';
            auto r = std::from_chars(buf, buf + k, v.num);
            if (r.ec != std::errc()) return fail(1, start, tr("number out of range"));
        }
        v.kind = Operand::Number;
        return true;
    }

    bool digits_index(int32_t& out, int max_digits) {
        size_t start = pos;
        long long n = 0;
        while (is_digit(peek())) {
            n = n * 10 + (line[pos] - '0');
            ++pos;
            if (int(pos - start) > max_digits)
                return fail(91, start, tr("parameter number too long"));
        }
        if (pos == start) return fail(93, start, tr("parameter number expected"));
        out = int32_t(n);
        return true;
    }

    // 'A'..'Z' -> L900..L925, 'EA'..'EZ' -> L926..L951 (000:7334-7340).
    bool symbol(int32_t& l) {
        size_t start = pos;
        ++pos;  // opening quote
        int base = 900;
        if (peek() == 'E' && is_upper(peek(1)) && peek(2) == '\'') {
            base = 926;
            ++pos;
        }
        if (!is_upper(peek()) || peek(1) != '\'')
            return fail(93, start, tr("bad symbol, expected 'A'..'Z' or 'EA'..'EZ'"));
        l = base + (line[pos] - 'A');
        pos += 2;
        return true;
    }

    // Variable-like operand at pos: Lnn, Enn, ELnn, 'X'. Returns false with no error
    // if there is none (v.kind untouched).
    bool variable(Operand& v, bool& found) {
        found = false;
        char c = peek();
        if (c == 'L' && is_digit(peek(1))) {
            ++pos;
            found = true;
            v.kind = Operand::LVar;
            return digits_index(v.index, 4);
        }
        if (c == 'E' && is_digit(peek(1))) {
            ++pos;
            found = true;
            v.kind = Operand::EParam;
            return digits_index(v.index, 6);
        }
        if (c == 'E' && peek(1) == 'L' && is_digit(peek(2))) {
            pos += 2;
            found = true;
            v.kind = Operand::EIndirect;
            return digits_index(v.index, 4);
        }
        if (c == '\'') {
            found = true;
            v.kind = Operand::LVar;
            return symbol(v.index);
        }
        return true;
    }

    // After pos (a variable's end), does an assignment '=' follow? ("<=" ">=" are tests.)
    bool assignment_follows(size_t p) const {
        p = after_spaces(p);
        return p < line.size() && line[p] == '=';
    }

    // The value of an address word.
    bool operand(Operand& v) {
        skip_spaces();
        if (peek() == '+' || peek() == '-') {
            v.has_sign = true;
            v.neg = peek() == '-';
            ++pos;
            skip_spaces();
        }
        char c = peek();
        if (is_digit(c) || c == '.') return number(v);
        size_t save = pos;
        Operand tmp = v;
        bool found;
        if (!variable(tmp, found)) return false;
        if (found) {
            // "X L1=5": X is blank and L1=5 an assignment of its own.
            if (assignment_follows(pos) && !in_test_) {
                pos = save;
            } else {
                v = tmp;
                return true;
            }
        }
        v.kind = v.has_sign ? Operand::SignOnly : Operand::Blank;
        return true;
    }

    /* term -> {'+' | '-' | S | C | A | R | T} (number | variable) */
    bool term(Term& t) {
        for (;;) {
            skip_spaces();
            char c = peek();
            if (c == '+' || c == '-' || c == 'S' || c == 'C' || c == 'A' || c == 'R' || c == 'T') {
                if (t.nprefix >= sizeof t.prefix)
                    return fail(93, pos, tr("too many functions in a term"));
                t.prefix[t.nprefix++] = c;
                ++pos;
                continue;
            }
            break;
        }
        char c = peek();
        if (is_digit(c) || c == '.') return number(t.v);
        bool found;
        if (!variable(t.v, found)) return false;
        if (!found) {
            if (pos >= line.size()) return fail(93, pos, tr("expression ends without a value"));
            return fail(93, pos, strf(tr("'%c' cannot appear in an expression"), c));
        }
        return true;
    }

    /* expr -> term {binop term} ; stops before a comparator or the next word */
    bool expr(Expr& e) {
        e.first = uint16_t(b.terms.size());
        Term t;
        t.op = '=';
        if (!term(t)) return false;
        b.terms.push_back(t);
        for (;;) {
            size_t p = after_spaces(pos);
            char c = p < line.size() ? line[p] : '\0';
            if (c == '+' || c == '-' || c == '*' || c == '/' || c == '&' || c == '!') {
                pos = p + 1;
                Term u;
                u.op = c;
                if (!term(u)) return false;
                b.terms.push_back(u);
                continue;
            }
            break;
        }
        e.count = uint16_t(b.terms.size() - e.first);
        return true;
    }

    bool assign(const Operand& target, size_t col) {
        skip_spaces();
        if (peek() != '=') return fail(93, pos, tr("'=' expected after the parameter"));
        ++pos;
        Assign a;
        a.target = target;
        a.col = uint16_t(col + 1);
        if (!expr(a.expr)) return false;
        b.assigns.push_back(a);
        return true;
    }

    bool cmp(Cmp& c) {
        skip_spaces();
        char a = peek(), n = peek(1);
        if (a == '<' && n == '=') {
            c = Cmp::le;
            pos += 2;
        } else if (a == '>' && n == '=') {
            c = Cmp::ge;
            pos += 2;
        } else if (a == '<' && n == '>') {
            c = Cmp::ne;
            pos += 2;
        } else if (a == '<') {
            c = Cmp::lt;
            ++pos;
        } else if (a == '>') {
            c = Cmp::gt;
            ++pos;
        } else if (a == '=') {
            c = Cmp::eq;
            ++pos;
        } else
            return fail(93, pos, tr("comparison operator expected (= <> < <= > >=)"));
        return true;
    }

    /* test -> expr cmp expr */
    bool test() {
        b.test.col = uint16_t(pos + 1);
        in_test_ = true;
        if (!expr(b.test.lhs)) return false;
        if (!cmp(b.test.cmp)) return false;
        if (!expr(b.test.rhs)) return false;
        in_test_ = false;
        return true;
    }

    static bool keyword_at(std::string_view rest, std::string_view kw) {
        if (rest.substr(0, kw.size()) != kw) return false;
        return rest.size() == kw.size() || rest[kw.size()] == ' ' || rest[kw.size()] == '\t' ||
               rest[kw.size()] == '(';
    }

    bool structured_keyword() {
        // Keywords are two or more letters; an ordinary word is a letter and a value.
        if (!is_upper(peek()) || !is_upper(peek(1))) return false;
        static constexpr std::string_view kws[] = {"WHILE", "ENDW", "FOR",    "ENDF", "ENDIF",
                                                   "ENDI",  "ELSE", "THEN",   "PUSH", "PULL",
                                                   "VAR",   "DO",   "REPEAT", "UNTIL"};
        std::string_view rest = line.substr(pos);
        for (auto kw : kws)
            if (keyword_at(rest, kw)) return true;
        // IF alone reads as I0 F0 (004:236) unless it opens an IF…THEN construct.
        return keyword_at(rest, "IF") && line.find("THEN") != std::string_view::npos;
    }

    /* word -> 'E' ('+' | '-') | address operand [g_suffix] [test]
       address -> letter | 'E' letter | 'N' ('C' | 'U' | 'P' | 'R') ; test after a G79 */
    bool word(char c) {
        size_t col = pos;
        Word w;
        w.col = uint16_t(col + 1);
        if (c == 'E') {
            char n = peek(1);
            if ((n == '+' || n == '-') &&
                !(is_digit(peek(2)) || peek(2) == '.' || peek(2) == 'L')) {
                w.addr = kAddrEsign;
                w.v.kind = Operand::SignOnly;
                w.v.has_sign = true;
                w.v.neg = n == '-';
                pos += 2;
                b.words.push_back(w);
                return true;
            }
            if (!is_upper(n) || n == 'O' || n == 'L')
                return fail(1, col,
                            strf(tr("address E must be followed by a letter (EA, EB%s) or a "
                                    "parameter number"),
                                 "\u2026"));
            w.addr = addrE(n);
            pos += 2;
        } else if (c == 'N' &&
                   (peek(1) == 'C' || peek(1) == 'U' || peek(1) == 'P' || peek(1) == 'R')) {
            w.addr = addrN(peek(1));
            pos += 2;
        } else {
            w.addr = addr1(c);
            ++pos;
        }
        if (!operand(w.v)) return false;
        if (c == 'G' && w.addr == addr1('G') && w.v.kind == Operand::Number) g_suffix(w);
        b.words.push_back(w);
        if (c == 'G' && w.v.kind == Operand::Number && w.v.num == 79 && w.gsign == 0) {
            // A condition follows unless the next word is the target N.
            size_t p = after_spaces(pos);
            if (p < line.size()) {
                char k = line[p];
                if (k == 'L' || k == '\'' || k == '+' || k == '-' || is_digit(k) || k == '.' ||
                    (k == 'E' && p + 1 < line.size() &&
                     (is_digit(line[p + 1]) || line[p + 1] == 'L'))) {
                    pos = p;
                    return test();
                }
            }
        }
        return true;
    }

    /* g_suffix -> ('+' | '-') after G76 or G79 | '-' level after G77 */
    void g_suffix(Word& w) {
        // A G number out of int's range is no G76/G77/G79 (decode says error 2).
        int g = w.v.num >= 0 && w.v.num < 1e6 ? int(w.v.num) : -1;
        if ((g == 76 || g == 79) && (peek() == '+' || peek() == '-')) {
            w.gsign = peek();
            ++pos;
            if (g == 76) g76_edit_ = b.words.size() + 1;
        } else if (g == 77) {
            size_t p = after_spaces(pos);
            if (p + 1 < line.size() && line[p] == '-' && is_digit(line[p + 1])) {
                pos = p + 1;
                int lvl = 0;
                while (is_digit(peek()) && lvl < 1000) lvl = lvl * 10 + (line[pos++] - '0');
                w.glevel = int16_t(lvl);
            }
        }
    }

    /* block -> ['/'] {comment | message | element} */
    bool run() {
        skip_spaces();
        if (peek() == '/') {
            b.skip = true;
            ++pos;
        }
        bool first_word = true;
        for (skip_spaces(); pos < line.size(); skip_spaces()) {
            const char c = line[pos];
            if (c == '(') {
                if (!comment()) return false;
                continue;
            }
            if (c == '$') {
                if (!message()) return false;
                continue;
            }
            if (first_word || (b.words.size() == 1 && b.words[0].addr == addr1('N'))) {
                if (structured_keyword())
                    return fail(4, pos,
                                strf(tr("structured programming (IF, WHILE, FOR%s) is an option "
                                        "this machine does not have"),
                                     "\u2026"));
            }
            first_word = false;
            if (!element(c)) return false;
        }
        return true;
    }

    /* comment -> '(' {character} ')' */
    bool comment() {
        size_t close = line.find(')', pos);
        if (close == std::string_view::npos)
            return fail(17, pos, tr("end of block inside a comment"));
        pos = close + 1;
        return true;
    }

    /* message -> '$' channel {character}, up to the next '(' or the block's end */
    bool message() {
        if (!is_digit(peek(1)))
            return fail(1, pos, tr("'$' must be followed by a channel digit 0-6"));
        int channel = peek(1) - '0';
        if (channel > 6) return fail(1, pos, tr("message channel must be $0 to $6"));
        pos += 2;
        size_t end = line.find('(', pos);
        if (end == std::string_view::npos) end = line.size();
        std::string_view text = line.substr(pos, end - pos);
        while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
            text.remove_prefix(1);
        while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
            text.remove_suffix(1);
        b.msg_channel = channel;
        b.msg = text;
        pos = end;
        return true;
    }

    /* element -> l_word | assignment | address_word */
    bool element(char c) {
        if (c == 'L' && is_upper(peek(1)) && peek(1) != 'O') return l_word();
        if (c == 'L' || c == '\'' ||
            (c == 'E' && (is_digit(peek(1)) || (peek(1) == 'L' && is_digit(peek(2))))))
            return assignment();
        if (is_upper(c)) return address_word(c);
        if (c >= 'a' && c <= 'z')
            return fail(1, pos, strf(tr("lower-case letter '%c' outside a comment"), c));
        if (is_digit(c) || c == '.' || c == '+' || c == '-')
            return fail(1, pos, tr("value without an address letter"));
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126)
            return fail(1, pos, tr("character outside the ISO set"));
        return fail(1, pos, strf(tr("unknown character '%c'"), c));
    }

    /* l_word -> 'L' letter operand ; the letter is no O */
    bool l_word() {
        Word w;
        w.col = uint16_t(pos + 1);
        w.addr = addrL(peek(1));
        pos += 2;
        if (!operand(w.v)) return false;
        b.words.push_back(w);
        return true;
    }

    /* assignment -> variable '=' expr */
    bool assignment() {
        size_t col = pos;
        Operand target;
        bool found;
        if (!variable(target, found)) return false;
        if (!found) return fail(93, col, tr("bad parameter"));
        if (!assignment_follows(pos)) {
            if (target.kind == Operand::LVar)
                return fail(93, col, tr("L variable not followed by '='"));
            return fail(93, col, tr("E parameter not followed by '='"));
        }
        return assign(target, col);
    }

    /* address_word -> word [block_number] [g76_tail] ; the letter is no O */
    bool address_word(char c) {
        if (c == 'O')
            return fail(1, pos, tr("the letter O is not an ISO address (did you mean 0?)"));
        if (!word(c)) return false;
        if (g76_edit_ && b.words.size() > g76_edit_ && b.words.back().addr == addr1('N'))
            return g76_tail();  // the rest of the line is the block to insert
        if (b.words.size() == 1 && c == 'N' && b.words[0].addr == addr1('N'))
            return block_number(b.words[0]);
        return true;
    }

    /* block_number -> 'N' [digit {digit}] ; 1 to 5 digits, blank for N0 */
    bool block_number(const Word& n) {
        const Operand& v = n.v;
        if (v.kind == Operand::Number) {
            if (v.frac_digits || v.int_digits > 5)
                return fail(1, n.col - 1, tr("block number must have 1 to 5 digits"));
            b.n = long(v.num);
        } else if (v.kind == Operand::Blank) {
            b.n = 0;
        } else {
            return fail(1, n.col - 1, tr("block number must be a number"));
        }
        return true;
    }

    /* g76_tail -> ['+' digits] {character} */
    // After the pointed block of G76+/G76-: an optional "+k" line offset, then the
    // block to insert, kept as text (000:7098-7147).
    bool g76_tail() {
        size_t p = after_spaces(pos);
        if (p + 1 < line.size() && line[p] == '+' && is_digit(line[p + 1])) {
            int k = 0, digits = 0;
            size_t at = p++;
            while (p < line.size() && is_digit(line[p])) {
                if (++digits > 5)
                    return fail(1, at, tr("the line offset +k has more than 5 digits"));
                k = k * 10 + (line[p++] - '0');
            }
            b.g76_k = k;
            p = after_spaces(p);
        }
        std::string_view rest = line.substr(p);
        while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
        b.g76_block = rest;
        b.g76_block_col = uint16_t(p + 1);
        pos = line.size();
        return true;
    }

    bool in_test_ = false;
    size_t g76_edit_ = 0;  // 1 + index of a G76+/G76- word, 0 if none
};

}  // namespace

// `lane`: the lane of plain blocks first (parse_plain), else the general
// parser alone.
static Error parse_line(std::string_view line, Block& out, bool lane) {
    out.clear();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.size() > kMaxBlockChars)
        return Error{
            1,
            strf(tr("block longer than %zu characters (%zu)"), size_t(kMaxBlockChars), line.size()),
            int(kMaxBlockChars) + 1};
    if (lane && parse_plain(line, out)) return {};
    out.clear();
    Parser p{line, 0, out};
    if (p.run()) return {};
    return std::move(p.err);
}

Error parse_block(std::string_view line, Block& out) {
    return parse_line(line, out, true);
}

Error parse_lines(std::string_view text) {
    Block b;
    for (size_t at = 0; at <= text.size();) {
        const size_t eol = std::min(text.find('\n', at), text.size());
        if (Error e = parse_block(text.substr(at, eol - at), b)) return e;
        at = eol + 1;
    }
    return {};
}

Error parse_block_general(std::string_view line, Block& out) {
    return parse_line(line, out, false);
}

bool parse_plain_line(const char* text, size_t avail, Block& out, size_t& len) {
    out.clear();
    return plain_lane<true>(text, avail, out, len) && len <= kMaxBlockChars;
}

}  // namespace pupitre
