// Binary COPY: a row cut into its fields, rows written (store/pg_copy.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/pg_copy.hpp"

#include <cstring>

namespace pupitre::store::pg_copy {

namespace {

uint32_t u32(const char* p) {
    return uint32_t(uint8_t(p[0])) << 24 | uint32_t(uint8_t(p[1])) << 16 |
           uint32_t(uint8_t(p[2])) << 8 | uint32_t(uint8_t(p[3]));
}

// The file format's header (PostgreSQL's COPY documentation, "Binary
// Format"): the signature with its NUL, the flags (bit 16: OIDs; the other
// high bits: what a reader must understand), the extension's length and bytes.
constexpr char kSignature[11] = {'P', 'G', 'C', 'O', 'P', 'Y', '\n', '\377', '\r', '\n', '\0'};
constexpr size_t kHeader = sizeof kSignature + 4 + 4;

void be(std::string& out, uint64_t v, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) out += char((v >> (8 * i)) & 0xff);
}

}  // namespace

Piece cut(const char* p, size_t n, bool& header, std::vector<Field>& fields) {
    const char* end = p + n;
    if (header) {
        if (n < kHeader || std::memcmp(p, kSignature, sizeof kSignature) != 0 ||
            (u32(p + 11) >> 16) != 0)
            return Piece::damaged;
        const uint32_t extension = u32(p + 15);
        if (extension > n - kHeader) return Piece::damaged;
        p += kHeader + extension;
        header = false;
    }
    if (end - p < 2) return Piece::damaged;
    const int count = int16_t(uint16_t(uint8_t(p[0]) << 8 | uint8_t(p[1])));
    p += 2;
    if (count == -1) return p == end ? Piece::end : Piece::damaged;
    if (count < 0) return Piece::damaged;
    fields.resize(size_t(count));
    for (Field& f : fields) {
        if (end - p < 4) return Piece::damaged;
        f.size = int32_t(u32(p));
        f.at = p += 4;
        if (f.size < -1 || f.size > end - p) return Piece::damaged;
        if (f.size > 0) p += f.size;
    }
    return p == end ? Piece::row : Piece::damaged;
}

void header(std::string& out) {
    out.append(kSignature, sizeof kSignature);
    be(out, 0, 4);  // flags: no OIDs
    be(out, 0, 4);  // no extension
}

void row(std::string& out, const db::Value* values, int width) {
    be(out, uint64_t(width), 2);
    for (const db::Value* v = values; v != values + width; ++v) {
        if (v->kind == db::Value::Kind::null) {
            be(out, 0xffffffffu, 4);
        } else if (v->kind == db::Value::Kind::integer) {
            be(out, 8, 4);
            be(out, uint64_t(v->integer), 8);
        } else {
            be(out, v->chars.size(), 4);
            out.append(v->chars.data(), v->chars.size());
        }
    }
}

void trailer(std::string& out) {
    be(out, 0xffff, 2);
}

}  // namespace pupitre::store::pg_copy
