// A program file's text, held or mapped (text.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parse/text.hpp"

#include <sys/mman.h>

namespace pupitre {

Text::~Text() {
    if (mapping_) munmap(mapping_, size_);
}

std::shared_ptr<Text> Text::map(int fd, size_t size) {
    if (size == 0) return nullptr;
    // MAP_POPULATE: the pages in one call rather than a fault each; read-only,
    // so that no page is copied.
    void* m = mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (m == MAP_FAILED) return nullptr;
    const char* c = static_cast<const char*>(m);
    if (c[size - 1] != '\n') {
        munmap(m, size);
        return nullptr;
    }
    auto t = std::make_shared<Text>();
    t->mapping_ = m;
    t->map_ = c;
    t->size_ = size;
    return t;
}

std::string& Text::str() {
    if (map_) {
        s_.assign(map_, size_);
        map_ = nullptr;
    }
    return s_;
}

}  // namespace pupitre
