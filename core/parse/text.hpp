// A program file's text, shared by the programs split from it: either held
// in a string, or mapped read-only from a large file (issue 14: reading a
// 28 MB program into a string cost the kernel's zeroing and copying of every
// page, about a tenth of its run; a mapping of the page cache costs neither).
// A mapped text becomes a string at its first change (G76 writes a field,
// G76+ and G76- insert and delete lines); the mapping stays until the Text
// goes, so a view taken before the change still reads (the old text).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace pupitre {

class Text {
  public:
    Text() = default;
    explicit Text(std::string s) : s_(std::move(s)) {}
    Text(const Text& o) : s_(o.view()) {}  // a copy is a string
    Text& operator=(const Text&) = delete;
    ~Text();

    // Maps the regular file open on `fd`, `size` bytes, when it ends with a
    // '\n' (the lane of plain blocks reads a line up to its '\n' and never
    // past it); nullptr when it cannot: the caller reads the file instead.
    static std::shared_ptr<Text> map(int fd, size_t size);

    std::string_view view() const { return map_ ? std::string_view(map_, size_) : s_; }
    operator std::string_view() const { return view(); }
    const char* data() const { return map_ ? map_ : s_.data(); }
    size_t size() const { return map_ ? size_ : s_.size(); }
    size_t find(char c, size_t pos = 0) const { return view().find(c, pos); }
    bool mapped() const { return map_ != nullptr; }

    // The text to change, as a string (a mapped text is copied first).
    std::string& str();

  private:
    std::string s_;
    const char* map_ = nullptr;  // the text, while it is the mapping's
    void* mapping_ = nullptr;    // kept until the destructor
    size_t size_ = 0;
};

}  // namespace pupitre
