// SHA-256 (FIPS 180-4), for the memory-protection PIN (the store keeps a
// salted hash, never the PIN), the exercises' seeds and signatures.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace pupitre {

std::string sha256_hex(std::string_view data);
// HMAC-SHA-256 (RFC 2104), in hex: the signature of an exercise's attempt.
std::string hmac_sha256_hex(std::string_view key, std::string_view data);

}  // namespace pupitre
