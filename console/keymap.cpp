// The bindings table (see keymap.hpp): its lines read, and a key's bindings
// found in a context.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/keymap.hpp"

#include <algorithm>

#include "core/i18n.hpp"

namespace pupitre::data {
std::string_view bindings_txt();
}

namespace pupitre::console {

std::string_view default_bindings() {
    return data::bindings_txt();
}

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

std::string next_word(std::string_view& s) {
    s = trim(s);
    size_t e = 0;
    while (e < s.size() && s[e] != ' ' && s[e] != '\t') ++e;
    std::string w(s.substr(0, e));
    s.remove_prefix(e);
    return w;
}

bool matches(const std::string& want, std::string_view have) {
    if (want.empty()) return true;
    std::string_view w = want;
    while (!w.empty()) {
        size_t bar = w.find('|');
        if (w.substr(0, bar) == have) return true;
        if (bar == std::string_view::npos) break;
        w.remove_prefix(bar + 1);
    }
    return false;
}

}  // namespace

std::string Keymap::parse(std::string_view text, std::string_view origin,
                          bool (*is_action)(std::string_view name)) {
    int lineno = 0;
    while (!text.empty()) {
        size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        ++lineno;
        if (size_t hash = line.find('#');
            hash != std::string_view::npos && (hash == 0 || line[hash - 1] == ' '))
            line = line.substr(0, hash);
        line = trim(line);
        if (line.empty()) continue;
        auto bad = [&](const std::string& what) {
            return std::string(origin) + ":" + std::to_string(lineno) + ": " + what;
        };
        Binding b;
        b.line = lineno;
        b.key_text = next_word(line);
        if (!parse_key_name(b.key_text, b.key))
            return bad(strf(tr("'%s' is not a key name"), b.key_text.c_str()));
        b.action = next_word(line);
        if (!is_action(b.action)) return bad(strf(tr("'%s' is not an action"), b.action.c_str()));
        std::string w = next_word(line);
        if (!w.empty() && w[0] != '@') {
            b.arg = w;
            w = next_word(line);
        }
        if (!w.empty()) {
            if (w[0] != '@') return bad(tr("a context starts with @"));
            std::string_view ctx = std::string_view(w).substr(1);
            while (!ctx.empty()) {
                size_t comma = ctx.find(',');
                std::string_view c = ctx.substr(0, comma);
                ctx = comma == std::string_view::npos ? std::string_view{} : ctx.substr(comma + 1);
                if (c.rfind("page=", 0) == 0)
                    b.when.page = c.substr(5);
                else if (c.rfind("mode=", 0) == 0)
                    b.when.mode = c.substr(5);
                else if (c == "lathe" || c == "mill")
                    b.when.kind = c;
                else
                    return bad(strf(tr("unknown context '%s'"), std::string(c).c_str()));
            }
        }
        if (!next_word(line).empty()) return bad(tr("too many words"));
        list_.push_back(std::move(b));
    }
    return {};
}

std::vector<const Binding*> Keymap::find(const Key& k, std::string_view page, std::string_view mode,
                                         std::string_view kind) const {
    std::vector<const Binding*> out;
    for (auto it = list_.rbegin(); it != list_.rend(); ++it) {  // a later line wins
        const Binding& b = *it;
        if (!(b.key == k)) continue;
        if (!b.when.page.empty() && !matches(b.when.page, page)) continue;
        if (!b.when.mode.empty() && !matches(b.when.mode, mode)) continue;
        if (!b.when.kind.empty() && b.when.kind != kind) continue;
        out.push_back(&b);
    }
    auto weight = [](const Binding* b) {
        return int(!b->when.page.empty()) + int(!b->when.mode.empty()) + int(!b->when.kind.empty());
    };
    std::stable_sort(out.begin(), out.end(),
                     [&](auto* a, auto* b) { return weight(a) > weight(b); });
    return out;
}

}  // namespace pupitre::console
