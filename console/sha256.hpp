// SHA-256 (FIPS 180-4), for the memory-protection PIN: the store keeps a
// salted hash, never the PIN.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace pupitre::console {

std::string sha256_hex(std::string_view data);

}  // namespace pupitre::console
