// The program editor (see editor.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/editor.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "core/i18n.hpp"
#include "core/parse/block.hpp"
#include "core/parse/program.hpp"

namespace pupitre::console {

void Editor::open(int n, std::string_view text, int rev, bool is_new) {
    number = n;
    revision = is_new ? 0 : rev;
    dirty = is_new;
    cursor = 0;
    mark = -1;
    locked = 0;
    error_line = -1;
    lines_.clear();
    while (!text.empty()) {
        size_t eol = text.find('\n');
        std::string_view l = text.substr(0, eol);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        lines_.emplace_back(l);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
    }
    if (lines_.empty()) lines_.push_back("%" + std::to_string(n));
    open_ = true;
}

std::string Editor::text() const {
    std::string out;
    for (const auto& l : lines_) {
        out += l;
        out += '\n';
    }
    return out;
}

std::string Editor::refusal(int first) const {
    if (first < locked)
        return tr(
            "this block is already prepared: MODIF changes the blocks after the one in progress");
    if (first == 0 && !lines_.empty() && !lines_[0].empty() && lines_[0][0] == '%')
        // xgettext:no-c-format
        return tr("the % line names the program: keep it");
    return {};
}

void Editor::range(int& a, int& b) const {
    a = b = cursor;
    if (mark >= 0) {
        a = std::min(mark, cursor);
        b = std::max(mark, cursor);
    }
}

std::string Editor::insert_after(std::string block) {
    std::string why;
    if (cursor + 1 < locked)
        return tr("this place is already prepared: MODIF inserts after the block in progress");
    if (block.find('\n') != std::string::npos) return tr("one block at a time");
    lines_.insert(lines_.begin() + cursor + 1, std::move(block));
    ++cursor;
    dirty = true;
    ++changes;
    return {};
}

std::string Editor::replace(std::string block) {
    if (std::string why = refusal(cursor); !why.empty()) return why;
    lines_[size_t(cursor)] = std::move(block);
    dirty = true;
    ++changes;
    return {};
}

// A % line typed for the program open: it becomes the header (a second %
// line would start another program, which the store refuses).
std::string Editor::set_header(std::string line) {
    if (locked > 0) return refusal(0);
    if (lines_.empty() || lines_[0].empty() || lines_[0][0] != '%')
        lines_.insert(lines_.begin(), std::string());
    else if (lines_[0] == line)
        return {};
    lines_[0] = std::move(line);
    dirty = true;
    ++changes;
    return {};
}

std::string Editor::copy() {
    int a, b;
    range(a, b);
    clipboard_.assign(lines_.begin() + a, lines_.begin() + b + 1);
    mark = -1;
    return {};
}

std::string Editor::erase() {
    int a, b;
    range(a, b);
    if (std::string why = refusal(a); !why.empty()) return why;
    lines_.erase(lines_.begin() + a, lines_.begin() + b + 1);
    if (lines_.empty()) lines_.push_back("");
    cursor = std::min(a, int(lines_.size()) - 1);
    mark = -1;
    dirty = true;
    ++changes;
    return {};
}

std::string Editor::cut() {
    int a, b;
    range(a, b);
    if (std::string why = refusal(a); !why.empty()) return why;
    copy();
    mark = -1;
    cursor = a;
    mark = b == a ? -1 : b;
    return erase();
}

std::string Editor::paste() {
    if (clipboard_.empty()) return tr("nothing copied (M-w copies, C-w cuts)");
    if (cursor + 1 < locked) return tr("this place is already prepared");
    lines_.insert(lines_.begin() + cursor + 1, clipboard_.begin(), clipboard_.end());
    cursor += int(clipboard_.size());
    dirty = true;
    ++changes;
    return {};
}

void Editor::move(int delta) {
    cursor = std::clamp(cursor + delta, 0, int(lines_.size()) - 1);
}

bool Editor::goto_n(long n) {
    for (size_t i = 0; i < lines_.size(); ++i)
        if (line_label(lines_[i]) == n) {
            cursor = int(i);
            return true;
        }
    return false;
}

bool Editor::find(std::string_view t) {
    if (t.empty()) return false;
    auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    std::string want = lower(std::string(t));
    int n = int(lines_.size());
    for (int k = 1; k <= n; ++k) {
        int i = (cursor + k) % n;
        if (lower(lines_[size_t(i)]).find(want) != std::string::npos) {
            cursor = i;
            return true;
        }
    }
    return false;
}

namespace {

// The position and length of the N label of a block ("N120" after an optional
// '/' and blanks), or npos.
size_t label_at(const std::string& l, size_t& len) {
    size_t i = 0;
    while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
    if (i < l.size() && l[i] == '/') ++i;
    while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
    if (i >= l.size() || (l[i] != 'N' && l[i] != 'n')) return std::string::npos;
    size_t j = i + 1;
    while (j < l.size() && std::isdigit(static_cast<unsigned char>(l[j]))) ++j;
    if (j == i + 1) return std::string::npos;
    len = j - i;
    return i;
}

// Rewrites the N words of a block other than its label (outside comments):
// N is only ever a label or a reference to one (G77, G79, the profile of G64,
// G65, G66), so each must follow its label.
std::string relabel_refs(const std::string& l, const std::map<long, long>& map) {
    std::string out;
    size_t i = 0;
    size_t lab_len = 0;
    size_t lab = label_at(l, lab_len);
    int depth = 0;
    while (i < l.size()) {
        char c = l[i];
        if (c == '(') ++depth;
        if (c == ')' && depth > 0) --depth;
        bool is_ref = depth == 0 && (c == 'N' || c == 'n') && i != lab && i + 1 < l.size() &&
                      std::isdigit(static_cast<unsigned char>(l[i + 1]));
        if (!is_ref) {
            out += c;
            ++i;
            continue;
        }
        size_t j = i + 1;
        while (j < l.size() && std::isdigit(static_cast<unsigned char>(l[j]))) ++j;
        long n = std::stol(l.substr(i + 1, j - i - 1));
        auto it = map.find(n);
        out += c;
        out += it == map.end() ? l.substr(i + 1, j - i - 1) : std::to_string(it->second);
        i = j;
    }
    return out;
}

}  // namespace

int Editor::renumber(long start, long step) {
    std::map<long, long> map;
    long next = start;
    int count = 0;
    for (size_t i = size_t(std::max(locked, 1)); i < lines_.size(); ++i) {
        size_t len = 0;
        size_t at = label_at(lines_[i], len);
        if (at == std::string::npos) continue;
        long old = std::stol(lines_[i].substr(at + 1, len - 1));
        map.emplace(old, next);
        lines_[i].replace(at + 1, len - 1, std::to_string(next));
        next += step;
        ++count;
    }
    for (auto& l : lines_) l = relabel_refs(l, map);
    if (count) dirty = true, ++changes;
    return count;
}

std::optional<Diag> Editor::check() {
    Block b;
    for (size_t i = 0; i < lines_.size(); ++i) {
        const std::string& l = lines_[i];
        if (!l.empty() && l[0] == '%') continue;
        if (Error e = parse_block(l, b)) {
            Diag d = diag_of(e);
            d.line = int(i) + 1;
            d.n = line_label(l);
            error_line = int(i);
            cursor = int(i);
            return d;
        }
    }
    error_line = -1;
    return std::nullopt;
}

}  // namespace pupitre::console
