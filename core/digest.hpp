// Digests, signatures and random bytes, through OpenSSL's libcrypto (a
// well-kept library, not code of ours): SHA-256 for the memory-protection PIN
// (the store keeps a salted hash, never the PIN), the exercises' seeds and
// `store copy`'s checksums; HMAC-SHA-256 for an attempt's signature; random
// bytes for keys, salts and an attempt's seed.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace pupitre {

// SHA-256 (FIPS 180-4) of `data`, 64 lowercase hex digits.
std::string sha256_hex(std::string_view data);
// HMAC-SHA-256 (RFC 2104) of `data` with `key`, in hex: the signature of an
// exercise's attempt. The same algorithm as before libcrypto did it, so a
// grade signed then still verifies.
std::string hmac_sha256_hex(std::string_view key, std::string_view data);
// `n` bytes from the system's strong random source, in hex (2n digits), or
// "" when it gave none.
std::string random_hex(size_t n);

}  // namespace pupitre
