// The G76 family: G76 writes the current L/E values into a program's text;
// G76+ and G76- are a program that creates and deletes programs, and inserts
// and deletes blocks, in the program memory (from the handbook
// 000:7018-7170, 7679-7735; pupitre-iso(5), PROGRAM FLOW). The changes live in
// memory: `pupitre run` never writes its files, the console stores them as
// revisions.
//
// Decisions where the handbook is silent (man/pupitre-iso.5, G76+ AND G76-):
// - The pointed block N.. is line 0 of the +k count; G76+ inserts after line k,
//   G76- deletes line k. Every line counts, comment lines included.
// - N0 that no line carries points before the first line of the program, so
//   "G76+ H300 N0 N10 G0 X0" writes the first block of an empty %300 (the
//   example of the handbook is a missing figure, 000:7043).
// - The inserted block keeps the words the handbook lists (000:7115): N,
//   G, X Y Z U V W A B C, I J K, P Q R and L0-L19. An L0-L19 in a word, and the
//   value assigned to L0-L19, are written as their value when G76+ runs (the
//   purpose is a program writing a program from its measurements). Other words
//   are error 1. The comments of the block are kept after its words.
// - A program already in memory: 1005; G76- of a program the run is executing:
//   1006; a missing program or block: 25; memory quota (profile
//   program_memory): 36.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

namespace {
// Shortest text of a value at `frac` decimals: 12.5, -3, 0.001.
std::string number_text(double v, int frac) {
    char buf[400];  // any double at 6 decimals (a too long block is refused after)
    std::snprintf(buf, sizeof buf, "%.*f", frac, v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") s = "0";
    return s;
}

bool listed_word(char c) {
    return std::string_view("NGXYZUVWABCIJKPQR").find(c) != std::string_view::npos;
}
}  // namespace

// G76 [H..] [N.. N..]: writes the current values of the L and E assignments that
// open the blocks of a program (or a range of it) into their reserved fields of
// at least 10 characters (000:7679-7735, pupitre-iso(5), PROGRAM FLOW). The text keeps its
// length, so labels and positions stay valid.
bool Interpreter::transfer(const Plan& p) {
    const ProgramText* target = stack_.back().prog;
    if (p.g76.h >= 0 && !(target = mem_.find(p.g76.h)))
        return fail(25, strf(tr("G76 H%d: program %%%d is not in memory"), p.g76.h, p.g76.h));
    size_t from = target->begin, to = target->end;
    if (p.g76.nn > 0) {
        const Label* a = target->find_label(p.g76.n[0]);
        const Label* b = target->find_label(p.g76.nn > 1 ? p.g76.n[1] : p.g76.n[0]);
        if (!a || !b)
            return fail(25, strf(tr("G76: block N%ld not found"), !a ? p.g76.n[0] : p.g76.n[1]));
        if (b->offset < a->offset) std::swap(a, b);
        from = a->offset;
        to = std::min(target->end, target->text->find('\n', b->offset));
    }
    for (size_t pos = from; pos < to;) {
        const size_t eol = std::min(to, target->text->find('\n', pos));
        if (!transfer_line(target, pos, eol)) return false;
        pos = eol + 1;
    }
    return true;
}

namespace {
bool digit(char c) {
    return c >= '0' && c <= '9';
}
bool upper(char c) {
    return c >= 'A' && c <= 'Z';
}
}  // namespace

// The L and E assignments that open one line [pos, eol), after its label.
bool Interpreter::transfer_line(const ProgramText* target, size_t pos, size_t eol) {
    const std::string_view text = *target->text;
    size_t i = pos;
    auto spaces = [&]() {
        while (i < eol && (text[i] == ' ' || text[i] == '\t')) ++i;
    };
    spaces();
    if (i < eol && text[i] == '/') ++i;
    spaces();
    if (i < eol && text[i] == 'N' && i + 1 < eol && (digit(text[i + 1]) || text[i + 1] == ' ')) {
        ++i;
        spaces();
        while (i < eol && digit(text[i])) ++i;
    }
    for (;;) {
        spaces();
        if (i + 1 >= eol || (text[i] != 'L' && text[i] != 'E') || !digit(text[i + 1])) return true;
        const bool is_l = text[i] == 'L';
        ++i;
        long n = 0;
        while (i < eol && digit(text[i])) n = n * 10 + (text[i++] - '0');
        spaces();
        if (i >= eol || text[i] != '=')
            return fail(97, strf(tr("G76: no '=' after %c%ld"), is_l ? 'L' : 'E', n));
        const size_t field = ++i;
        while (i < eol && !upper(text[i]) && text[i] != '(' && text[i] != '\r') ++i;
        // Keep the separating space before the next word.
        const bool word_follows = i < eol && upper(text[i]);
        if (!transfer_field(target, is_l, n, field, i - field, word_follows)) return false;
    }
}

// Writes the value of Ln or En into its field of `width` characters.
bool Interpreter::transfer_field(const ProgramText* target, bool is_l, long n, size_t field,
                                 size_t width, bool word_follows) {
    if (width < 10)
        return fail(97, strf(tr("G76: fewer than 10 characters reserved after %c%ld="),
                             is_l ? 'L' : 'E', n));
    std::string value;
    if (is_l) {
        if (!LVars::valid(int(n))) return fail(91, strf(tr("G76: L%ld does not exist"), n));
        value = number_text(l_.v[size_t(n)], 6);
    } else {
        int64_t raw;
        if (Error e = read_e(int(n), raw)) return fail(e.code, "G76: " + e.detail);
        value = std::to_string(raw);
    }
    const size_t room = word_follows ? width - 1 : width;
    if (value.size() > room)
        return fail(97, strf(tr("G76: the value %s does not fit the field after %c%ld"),
                             value.c_str(), is_l ? 'L' : 'E', n));
    value.resize(width, ' ');
    target->text->str().replace(field, width, value);
    if (mem_.find(target->number) == target)
        mem_.mark_changed(target->number);  // not an IMD fragment
    return true;
}

// The text of the block G76+ inserts, values of L0-L19 written in.
bool Interpreter::edit_block_text(const Block& b, std::string& out) {
    std::string_view raw = b.g76_block;
    Block ins;
    if (Error e = parse_block(raw, ins))
        return fail(e.code, "G76+: " + e.detail, b.g76_block_col - 1 + e.column);
    if (ins.msg_channel >= 0)
        return fail(1, tr("G76+: a $ message cannot be inserted"), b.g76_block_col);
    if (ins.test.cmp != Cmp::none)
        return fail(1, tr("G76+: a G79 condition cannot be inserted"),
                    b.g76_block_col - 1 + ins.test.col);
    if (ins.empty())
        return fail(2, tr("G76+ needs the block to insert after N.. (G76+ N100 G1 X10)"),
                    b.g76_block_col);
    // Words and assignments in the order they were written.
    std::vector<std::pair<uint16_t, std::string>> parts;
    if (!inserted_words(b, ins, parts) || !inserted_assigns(b, ins, parts)) return false;
    std::stable_sort(parts.begin(), parts.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    if (ins.skip) out += '/';
    for (size_t i = 0; i < parts.size(); ++i) {
        if (i) out += ' ';
        out += parts[i].second;
    }
    // The comments, as written (parse_block saw each one closed).
    for (size_t i = raw.find('('); i != std::string_view::npos; i = raw.find('(', i)) {
        size_t close = raw.find(')', i);
        if (close == std::string_view::npos) break;
        out += ' ';
        out += raw.substr(i, close - i + 1);
        i = close + 1;
    }
    if (!inserted_reads_back(b, out)) return false;
    out += '\n';
    return true;
}

// The words of the inserted block, their values computed now.
bool Interpreter::inserted_words(const Block& b, const Block& ins,
                                 std::vector<std::pair<uint16_t, std::string>>& parts) {
    auto col = [&](uint16_t c) { return b.g76_block_col - 1 + c; };
    for (const Word& w : ins.words) {
        char letter = w.addr < 26 ? char('A' + w.addr) : 0;
        if (!letter || !listed_word(letter))
            return fail(1,
                        strf(tr("G76+: %s cannot be inserted (N G X Y Z U V W A B C I J K P Q R "
                                "L0-L19 only)"),
                             std::string(addr_name(w.addr)).c_str()),
                        col(w.col));
        if ((w.v.kind == Operand::LVar && w.v.index > 19) || w.v.kind == Operand::EParam ||
            w.v.kind == Operand::EIndirect)
            return fail(1, tr("G76+: only L0-L19 can give a value in an inserted block"),
                        col(w.col));
        if (letter == 'G' && (w.gsign || w.glevel))
            return fail(1, tr("G76+: G76+/-, G79+/- and G77 -i cannot be inserted"), col(w.col));
        double v;
        int iv = 0;
        bool integer = letter == 'N' || letter == 'G';
        if (!word_value(w, v, integer ? &iv : nullptr)) {
            diags_.back().column = col(w.col);
            return false;
        }
        std::string t(1, letter);
        if (!(letter == 'N' && w.v.kind == Operand::Blank))  // a bare N is N0
            t += integer ? std::to_string(iv)
                         : number_text(v, letter >= 'A' && letter <= 'C' ? 4 : 3);
        parts.emplace_back(w.col, std::move(t));
    }
    return true;
}

// The assignments of the inserted block (L0-L19 only), their values computed now.
bool Interpreter::inserted_assigns(const Block& b, const Block& ins,
                                   std::vector<std::pair<uint16_t, std::string>>& parts) {
    auto col = [&](uint16_t c) { return b.g76_block_col - 1 + c; };
    // Expressions read L0-L19 only.
    for (const Term& t : ins.terms)
        if ((t.v.kind == Operand::LVar && t.v.index > 19) || t.v.kind == Operand::EParam ||
            t.v.kind == Operand::EIndirect)
            return fail(1, tr("G76+: only L0-L19 can give a value in an inserted block"),
                        b.g76_block_col);
    for (const Assign& a : ins.assigns) {
        if (a.target.kind != Operand::LVar || a.target.index > 19)
            return fail(1, tr("G76+: only L0-L19 can be assigned in an inserted block"),
                        col(a.col));
        double v;
        if (Error e = eval_expr(ins, a.expr, l_, *this, v))
            return fail(e.code, "G76+: " + e.detail, col(a.col));
        parts.emplace_back(a.col, "L" + std::to_string(a.target.index) + "=" + number_text(v, 6));
    }
    return true;
}

// What is written must read back: the block length, the digits of each
// address (an L value may be too large for X).
bool Interpreter::inserted_reads_back(const Block& b, const std::string& out) {
    Block back;
    if (Error e = parse_block(out, back))
        return fail(e.code,
                    strf(tr("G76+: the block to insert, %s: %s"), out.c_str(), e.detail.c_str()),
                    b.g76_block_col);
    for (const Word& w : back.words) {
        double v;
        if (!word_value(w, v)) {
            diags_.back().detail = strf(tr("G76+: the block to insert, %s: %s"), out.c_str(),
                                        diags_.back().detail.c_str());
            diags_.back().column = b.g76_block_col;
            return false;
        }
    }
    return true;
}

// G76+ / G76- (000:7037-7130): creates or deletes a program, or inserts or
// deletes one line of a program in memory.
bool Interpreter::edit_program(const Block& b, const Plan& p) {
    const char sign = p.g76.sign;
    if (m_.model == 1020)
        return fail(4, strf(tr("G76%c needs a NUM 1040 or 1060 (000:555)"), sign));
    if (!edit_block_alone(b, sign)) return false;
    // It moves nothing: under G41/G42 it counts among the blocks without motion.
    if (modal_.radcomp != 40 && ++nonmotion_in_comp_ > 2)
        return fail(140, tr("more than 2 blocks in a row without motion in the plane under radius "
                            "compensation"));
    if (p.g76.nn > 1)
        return fail(3, strf(tr("G76%c points at one block N.."), sign), b.words.back().col);
    if (p.g76.nn == 0) return edit_whole_program(b, p);
    return edit_line(b, p);
}

// The block holds nothing else: its label, G76±, one H and the pointed N.
bool Interpreter::edit_block_alone(const Block& b, char sign) {
    size_t g76_at = b.words.size();  // none yet
    int hs = 0;
    for (size_t i = 0; i < b.words.size(); ++i) {
        const Word& w = b.words[i];
        if (w.addr == addr1('G') && w.gsign) g76_at = i;
        bool label = i == 0 && w.addr == addr1('N') && b.n >= 0;
        bool arg = g76_at < i && (w.addr == addr1('H') || w.addr == addr1('N'));
        if (!label && i != g76_at && !arg)
            return fail(3,
                        strf(tr("G76%c takes only H.. and N.. [+k] (the block must hold nothing "
                                "else)"),
                             sign),
                        w.col);
        if (w.addr == addr1('H') && ++hs > 1)
            return fail(3, strf(tr("G76%c: H written twice"), sign), w.col);
    }
    if (!b.assigns.empty())
        return fail(3,
                    strf(tr("G76%c takes only H.. and N.. [+k]: no assignment in its block"), sign),
                    b.assigns[0].col);
    return true;
}

// Creating or deleting a whole program: H is the last word (000:7037, 7068).
bool Interpreter::edit_whole_program(const Block& b, const Plan& p) {
    const char sign = p.g76.sign;
    const size_t quota = size_t(m_.program_memory_kb * 1024);
    if (p.g76.h < 0)
        return fail(2, strf(tr("G76%c needs the program number H (G76%c H300)"), sign, sign));
    if (b.words.back().addr != addr1('H'))
        return fail(
            3, strf(tr("G76%c: the program number H must be the last word of the block"), sign),
            b.words.back().col);
    if (sign == '+') {
        if (mem_.find(p.g76.h))
            return fail(err::kProgramExists,
                        strf(tr("G76+ H%d: program %%%d is already in memory"), p.g76.h, p.g76.h));
        if (mem_.size() + 16 > std::max(quota, loaded_size_))
            return fail(36,
                        strf(tr("G76+: the part-program memory is full (%zu KB)"), quota / 1024));
        mem_.create(p.g76.h);
        return true;
    }
    const ProgramText* t = mem_.find(p.g76.h);
    if (!t) return fail(25, strf(tr("G76- H%d: no program %%%d"), p.g76.h, p.g76.h));
    bool running = t == main_ || std::any_of(stack_.begin(), stack_.end(),
                                             [&](const Frame& f) { return f.prog == t; });
    if (running)
        return fail(err::kProgramInUse,
                    strf(tr("G76- H%d: program %%%d is running"), p.g76.h, p.g76.h));
    mem_.remove(p.g76.h);
    return true;
}

// A line: the program H (or this one), the pointed line N.. and k lines on;
// G76+ inserts after it, G76- deletes it.
namespace {
// The index of the first character of `s` outside a comment and not a blank,
// or npos when there is none.
size_t outside_comments(std::string_view s) {
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '(') {
            size_t close = s.find(')', i);
            i = close == std::string_view::npos ? s.size() : close;
        } else if (s[i] != ' ' && s[i] != '\t') {
            return i;
        }
    }
    return std::string_view::npos;
}
}  // namespace

bool Interpreter::edit_line(const Block& b, const Plan& p) {
    const char sign = p.g76.sign;
    const ProgramText* t = stack_.back().prog;
    if (p.g76.h >= 0 && !(t = mem_.find(p.g76.h)))
        return fail(25, strf(tr("G76%c H%d: no program %%%d"), sign, p.g76.h, p.g76.h));
    if (mem_.find(t->number) != t)  // an IMD fragment is not a program of the memory
        return fail(25, strf(tr("G76%c without H edits the program that runs: in IMD, give the "
                                "program H"),
                             sign));
    if (size_t i = outside_comments(b.g76_block); sign == '-' && i != std::string_view::npos)
        return fail(3, tr("G76- takes nothing after N.. [+k]"), b.g76_block_col + int(i));
    const long n = p.g76.n[0];
    const int k = std::max(b.g76_k, 0);
    std::string_view all = *t->text;
    auto next_line = [&](size_t pos) {
        size_t eol = all.find('\n', pos);
        return eol == std::string_view::npos || eol >= t->end ? t->end : eol + 1;
    };
    // `start` is the first byte of the line k lines after the pointed one; with
    // a virtual N0 before the first line, line k is the k-th line.
    size_t start;
    int count = k;
    if (const Label* l = t->find_label(n)) {
        start = l->offset;
    } else if (n == 0) {
        start = t->begin;
        --count;
    } else {
        return fail(25, strf(tr("G76%c: no block N%ld in program %%%d"), sign, n, t->number));
    }
    for (; count > 0 && start < t->end; --count) start = next_line(start);
    const bool before_first = count < 0;  // N0 virtual, no +k: insert at the start
    if (!before_first && start >= t->end)
        return fail(
            25, strf(tr("G76%c: program %%%d has no line %d after N%ld"), sign, t->number, k, n));
    Splice s;
    if (sign == '+') {
        std::string text;
        if (!edit_block_text(b, text)) return false;
        const size_t quota = size_t(m_.program_memory_kb * 1024);
        if (mem_.size() + text.size() > std::max(quota, loaded_size_))
            return fail(36,
                        strf(tr("G76+: the part-program memory is full (%zu KB)"), quota / 1024));
        s = mem_.splice(t, before_first ? start : next_line(start), 0, text);
    } else {
        if (before_first)
            return fail(25, tr("G76- N0 points before the first line: give +k (the k-th line)"));
        s = mem_.splice(t, start, next_line(start) - start, {});
    }
    text_spliced(t, s);
    // The block budget (error 1001) counts an edit as one block per kilobyte
    // of text it moves: a loop of edits in a long program stops in seconds.
    blocks_ += long((t->text->size() - s.at) / 1024);
    return true;
}

// The frames reading the changed text keep their place in it: the next line
// to read, the first line of a range or of a repeated program, the last line
// of a range, and the line of the block being executed (after_block).
void Interpreter::text_spliced(const ProgramText* p, const Splice& s) {
    const ptrdiff_t db = ptrdiff_t(s.ins) - ptrdiff_t(s.del);
    const int dl = s.ins_lines - s.del_lines;
    const size_t del_end = s.at + s.del;
    // `keep_at`: a place equal to `at` stays there (the inserted line is read next).
    auto move = [&](size_t& pos, int& line, bool keep_at) {
        if (pos >= s.at && pos < del_end) {  // its line was deleted: the next one
            pos = s.at;
            line = s.line;
        } else if (pos >= del_end && !(keep_at && s.del == 0 && pos == s.at)) {
            pos = size_t(ptrdiff_t(pos) + db);
            line += dl;
        }
    };
    auto move_line = [&](int& line) {
        if (line >= s.line + s.del_lines)
            line += dl;
        else if (line >= s.line)
            line = s.line - 1;  // deleted: the line before
    };
    bool current = !stack_.empty() && stack_.back().prog->text == p->text;
    for (Frame& f : stack_) {
        if (f.prog->text != p->text) continue;
        move(f.pos, f.line, true);
        move(f.range_pos, f.range_line, f.whole);
        if (!f.whole) {
            move_line(f.end_line);
            if (f.range_line > f.end_line) f.emptied = true;
        }
    }
    if (current) move_line(cur_line_);
    cur_text_ = {};
}

}  // namespace pupitre
