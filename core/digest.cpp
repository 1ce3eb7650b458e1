// Digests, signatures and random bytes (see digest.hpp): libcrypto's EVP and
// HMAC one-shot functions, and RAND_bytes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/digest.hpp"

#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>

#include <vector>

namespace pupitre {

namespace {

std::string to_hex(const unsigned char* b, size_t n) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out(2 * n, '0');
    for (size_t i = 0; i < n; ++i) {
        out[2 * i] = kDigits[b[i] >> 4];
        out[2 * i + 1] = kDigits[b[i] & 15];
    }
    return out;
}

}  // namespace

std::string sha256_hex(std::string_view data) {
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    if (!EVP_Digest(data.data(), data.size(), md, &n, EVP_sha256(), nullptr)) return {};
    return to_hex(md, n);
}

std::string hmac_sha256_hex(std::string_view key, std::string_view data) {
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    if (!HMAC(EVP_sha256(), key.data(), int(key.size()),
              reinterpret_cast<const unsigned char*>(data.data()), data.size(), md, &n))
        return {};
    return to_hex(md, n);
}

std::string random_hex(size_t n) {
    std::vector<unsigned char> b(n);
    if (RAND_bytes(b.data(), int(n)) != 1) return {};
    return to_hex(b.data(), n);
}

}  // namespace pupitre
