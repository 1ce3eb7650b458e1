// Cutting the rows of a binary COPY (store/pg_copy.hpp), as the PostgreSQL
// backend reads a list: a good piece gives its fields, anything that does not
// add up is refused without reading past the piece (issue 33).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "store/pg_copy.hpp"

using namespace pupitre::store::pg_copy;

namespace {

const std::string kHead("PGCOPY\n\377\r\n\0\0\0\0\0\0\0\0\0", 19);

std::string be(uint64_t v, int bytes) {
    std::string s;
    for (int i = bytes - 1; i >= 0; --i) s += char((v >> (8 * i)) & 0xff);
    return s;
}

// A row of a bigint, a NULL, a text and an integer -7.
std::string row() {
    return be(4, 2) + be(8, 4) + be(1234, 8) + be(0xffffffff, 4) + be(5, 4) + "PIECE" + be(4, 4) +
           be(uint32_t(-7), 4);
}

Piece cut_all(const std::string& s, bool& header, std::vector<Field>& f) {
    return cut(s.data(), s.size(), header, f);
}

}  // namespace

TEST(StorePgCopy, HeaderThenRowsThenTheEnd) {
    bool header = true;
    std::vector<Field> f;
    ASSERT_EQ(cut_all(kHead + row(), header, f), Piece::row);
    EXPECT_FALSE(header);
    ASSERT_EQ(f.size(), 4u);
    EXPECT_EQ(integer(f[0]), 1234);
    EXPECT_EQ(f[1].size, -1);
    EXPECT_EQ(integer(f[1]), 0);
    EXPECT_EQ(std::string(f[2].at, size_t(f[2].size)), "PIECE");
    EXPECT_EQ(integer(f[3]), -7);
    const std::string second = row();  // the fields point into it
    ASSERT_EQ(cut_all(second, header, f), Piece::row);
    EXPECT_EQ(integer(f[0]), 1234);
    EXPECT_EQ(cut_all(be(0xffff, 2), header, f), Piece::end);
}

TEST(StorePgCopy, IntegersOfEachWidth) {
    const std::string b[] = {be(uint16_t(-2), 2), be(uint32_t(-300000), 4),
                             be(uint64_t(-5000000000LL), 8), "abc"};
    EXPECT_EQ(integer({b[0].data(), 2}), -2);
    EXPECT_EQ(integer({b[1].data(), 4}), -300000);
    EXPECT_EQ(integer({b[2].data(), 8}), -5000000000LL);
    EXPECT_EQ(integer({b[3].data(), 3}), 0);
}

TEST(StorePgCopy, RealsOfEachWidth) {
    const std::string d = be(0xC04EA00000000000ULL, 8);  // -61.25
    const std::string f = be(0x3FC00000U, 4);            // 1.5
    EXPECT_EQ(real({d.data(), 8}), -61.25);
    EXPECT_EQ(real({f.data(), 4}), 1.5);
    EXPECT_EQ(real({d.data(), 3}), 0);
    EXPECT_EQ(real({nullptr, -1}), 0);
}

TEST(StorePgCopy, HeaderWithAnExtension) {
    std::string head = kHead.substr(0, 15) + be(3, 4) + "xyz";
    bool header = true;
    std::vector<Field> f;
    EXPECT_EQ(cut_all(head + row(), header, f), Piece::row);
}

TEST(StorePgCopy, WhatDoesNotAddUpIsRefused) {
    const std::string r = row();
    std::string oids = kHead;
    oids[12] = 1;  // the flags' bit 16 (big-endian, from byte 11): an OID before each row
    std::string bad_sig = kHead;
    bad_sig[0] = 'X';
    const std::string cases[] = {
        kHead.substr(0, 12),                     // a header cut short
        bad_sig + r,                             // not binary COPY
        oids + r,                                // OIDs
        kHead.substr(0, 15) + be(99, 4) + r,     // an extension past the piece
        kHead + r.substr(0, r.size() - 1),       // a field cut short
        kHead + r + "x",                         // bytes left over
        kHead + be(2, 2) + be(50, 4) + "abc",    // a length past the piece
        kHead + be(1, 2) + be(uint32_t(-2), 4),  // a length below -1
        kHead + be(uint16_t(-3), 2),             // a negative count
        kHead + be(0xffff, 2) + "x",             // an end with bytes after it
        kHead + "\x01",                          // no count
    };
    for (const std::string& c : cases) {
        bool header = true;
        std::vector<Field> f;
        EXPECT_EQ(cut_all(c, header, f), Piece::damaged) << testing::PrintToString(c);
    }
}

// The rows Backend::insert_rows sends (COPY … FROM STDIN): what the writer
// makes, the reader cuts back into the same fields, byte for byte.
TEST(StorePgCopy, WrittenRowsReadBack) {
    using pupitre::store::db::Value;
    const std::string text("%1\nG1 X1\n\0\377", 12);
    const Value values[] = {{Value::Kind::integer, -5000000000LL, {}},
                            {},
                            {Value::Kind::text, 0, "PIECE"},
                            {Value::Kind::bytes, 0, text},
                            {Value::Kind::text, 0, ""}};
    std::string s;
    header(s);
    EXPECT_EQ(s, kHead);
    row(s, values, 5);
    EXPECT_EQ(s.size(), 19u + 2 + (4 + 8) + 4 + (4 + 5) + (4 + text.size()) + 4);
    bool first = true;
    std::vector<Field> f;
    ASSERT_EQ(cut_all(s, first, f), Piece::row);
    ASSERT_EQ(f.size(), 5u);
    EXPECT_EQ(integer(f[0]), -5000000000LL);
    EXPECT_EQ(f[1].size, -1);
    EXPECT_EQ(std::string(f[2].at, size_t(f[2].size)), "PIECE");
    EXPECT_EQ(std::string(f[3].at, size_t(f[3].size)), text);
    EXPECT_EQ(f[4].size, 0);
    std::string end;
    trailer(end);
    EXPECT_EQ(cut_all(end, first, f), Piece::end);
}
