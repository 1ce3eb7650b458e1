// libFuzzer target: terminal bytes -> KeyDecoder, read in chunks whose sizes the input chooses.
// Any crash or sanitizer report is a bug, and so is a broken invariant: the same keys whatever
// the chunking, no key without a code, every key's name parses back to the key, raw bytes taken
// from the input in order, and a bounded hold.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "console/keys.hpp"

using namespace pupitre::console;

namespace {

void check(bool ok) {
    if (!ok) std::abort();
}

void check_keys(const std::vector<Key>& keys, std::string_view input) {
    size_t at = 0;
    for (const Key& k : keys) {
        check(k.code != KeyCode::none && !k.raw.empty());
        Key back;
        check(parse_key_name(key_name(k), back) && back == k);
        at = input.find(k.raw, at);  // dropped sequences leave gaps, nothing is reordered
        check(at != std::string_view::npos);
        at += k.raw.size();
    }
}

}  // namespace

// Input: 4 bytes of chunk sizes (low 4 bits: size 0-15; high bit: flush after the chunk,
// as if the escape timeout had passed), then the terminal bytes.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 4 || size > 64 * 1024) return 0;
    const uint8_t* sizes = data;
    const std::string_view input(reinterpret_cast<const char*>(data + 4), size - 4);

    KeyDecoder whole;
    std::vector<Key> want;
    whole.feed(input, want);
    whole.flush(want);
    check(!whole.pending());
    check_keys(want, input);

    KeyDecoder chunked, timed;
    std::vector<Key> got, with_flushes;
    // all four sizes zero would never read anything: then read byte by byte
    const bool stuck = ((sizes[0] | sizes[1] | sizes[2] | sizes[3]) & 15) == 0;
    for (size_t pos = 0, i = 0; pos < input.size(); ++i) {
        const uint8_t s = sizes[i % 4];
        const std::string_view chunk = input.substr(pos, stuck ? 1 : s & 15);
        chunked.feed(chunk, got);
        timed.feed(chunk, with_flushes);
        if (s & 0x80) timed.flush(with_flushes);
        check(chunked.held_bytes() <= KeyDecoder::kMaxSequence + 1);
        pos += chunk.size();
    }
    chunked.flush(got);
    timed.flush(with_flushes);
    check(got == want);
    for (size_t i = 0; i < got.size(); ++i) check(got[i].raw == want[i].raw);
    check_keys(with_flushes, input);
    return 0;
}
