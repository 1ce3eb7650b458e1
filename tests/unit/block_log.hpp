// A parsed line as text, every field of the Block (or the error), for the
// differential checks of the parser's lane of plain blocks against the
// general parser (tests/unit/test_parse_lane.cpp, tests/fuzz/fuzz_interp.cpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <sstream>
#include <string>
#include <string_view>

#include "core/parse/block.hpp"

namespace pupitre::test {

inline std::string operand_text(const Operand& v) {
    std::ostringstream o;
    o << int(v.kind) << ',' << v.neg << ',' << v.has_sign << ',' << int(v.int_digits) << ','
      << int(v.frac_digits) << ',' << v.index << ',' << std::hexfloat << v.num;
    return o.str();
}

// Everything a Block holds, as text.
inline std::string block_text(const Block& b) {
    std::ostringstream o;
    o << "n=" << b.n << " skip=" << b.skip << " msg=" << b.msg_channel << ':' << b.msg
      << " test=" << int(b.test.cmp) << ',' << b.test.lhs.first << ',' << b.test.lhs.count << ','
      << b.test.rhs.first << ',' << b.test.rhs.count << ',' << b.test.col << " g76=" << b.g76_k
      << ':' << b.g76_block << ':' << b.g76_block_col << '\n';
    for (const Word& w : b.words)
        o << "w " << int(w.addr) << ' ' << w.col << ' ' << int(w.gsign) << ' ' << w.glevel << ' '
          << operand_text(w.v) << '\n';
    for (const Assign& a : b.assigns)
        o << "a " << operand_text(a.target) << ' ' << a.expr.first << ' ' << a.expr.count << ' '
          << a.col << '\n';
    for (const Term& t : b.terms)
        o << "t " << t.op << ' ' << std::string(t.prefix, t.nprefix) << ' ' << operand_text(t.v)
          << '\n';
    return o.str();
}

// Both parsers' answer for one line: the Block, or the error.
inline std::string parse_answer(std::string_view line, bool lane) {
    Block b;
    const Error e = lane ? parse_block(line, b) : parse_block_general(line, b);
    if (e)
        return "error " + std::to_string(e.code) + " col " + std::to_string(e.column) + ": " +
               e.detail;
    return block_text(b);
}

}  // namespace pupitre::test
