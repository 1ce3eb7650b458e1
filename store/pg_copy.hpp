// Inside the PostgreSQL backend: COPY in PostgreSQL's binary format, both
// ways. A row of COPY … TO STDOUT cut into its fields: store/postgres.cpp
// reads the statements of Backend::prepare_many so, a row at a time as libpq
// gives them (PQgetCopyData). And the rows of Backend::insert_rows written
// for COPY … FROM STDIN. No SQL and no libpq here. Not for use outside store/.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <endian.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "store/backend.hpp"

namespace pupitre::store::pg_copy {

struct Field {
    const char* at = nullptr;
    int size = -1;  // bytes; -1: NULL
};

enum class Piece { row, end, damaged };

// Cuts one piece of a copy (`n` bytes at `p`) into `fields`, which point
// into it. The first piece (`header` true, then set false) begins with the
// format's header. A piece is a row, or the end of the copy; anything that
// does not add up exactly (lengths past the piece, bytes left over, another
// format, OIDs among the fields) is damaged, never read past.
Piece cut(const char* p, size_t n, bool& header, std::vector<Field>& fields);

// An integer field (smallint, integer, bigint: 2, 4 or 8 bytes in network
// order); 0 for a NULL or any other size. Inline: a list reads 50,000.
inline int64_t integer(const Field& f) {
    const auto* b = reinterpret_cast<const unsigned char*>(f.at);
    if (f.size == 8) {
        uint64_t x;
        std::memcpy(&x, b, 8);
        return int64_t(be64toh(x));
    }
    if (f.size == 4) {
        uint32_t x;
        std::memcpy(&x, b, 4);
        return int32_t(be32toh(x));
    }
    return f.size == 2 ? int16_t(uint16_t(b[0] << 8 | b[1])) : 0;
}

// A floating-point field (double precision: 8 bytes, IEEE 754 in network
// order; real: 4), its bits read as integer() reads them; 0 for a NULL or
// any other size.
inline double real(const Field& f) {
    if (f.size == 8) {
        const uint64_t bits = uint64_t(integer(f));
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
    }
    if (f.size == 4) {
        const uint32_t bits = uint32_t(integer(f));
        float v;
        std::memcpy(&v, &bits, 4);
        return v;
    }
    return 0;
}

// Writing (the documentation's "Binary Format" again): the header, then
// each row as its number of fields and each field as its length (-1: NULL)
// and its bytes (an integer as a bigint in network order; a text or a bytea
// as it is), then the trailer. Appended to `out`.
void header(std::string& out);
void row(std::string& out, const db::Value* values, int width);
void trailer(std::string& out);

}  // namespace pupitre::store::pg_copy
