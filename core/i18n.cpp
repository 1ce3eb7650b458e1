// The language people read: the choice of language and GNU gettext.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/i18n.hpp"

#include <libintl.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <clocale>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

namespace pupitre {
namespace {

constexpr const char* kDomain = "pupitre";
bool g_active = false;  // a catalogue other than English is bound
std::string g_lang = "en";

bool is_c_locale(const char* loc) {
    return !loc || !std::strcmp(loc, "C") || !std::strcmp(loc, "POSIX");
}

bool has_catalogue(const std::string& localedir, const std::string& lang) {
    std::error_code ec;
    return std::filesystem::is_regular_file(
        localedir + "/" + lang + "/LC_MESSAGES/" + kDomain + ".mo", ec);
}

// "fr_FR.UTF-8@euro" -> "fr_FR", "fr".
void add_candidates(std::string_view name, std::vector<std::string>& out) {
    name = name.substr(0, name.find_first_of(".@"));
    if (name.empty()) return;
    out.emplace_back(name);
    if (size_t u = name.find('_'); u != std::string_view::npos) out.emplace_back(name.substr(0, u));
}

bool says_utf8(const char* loc) {
    if (!loc) return false;
    std::string s(loc);
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s.find("utf-8") != std::string::npos || s.find("utf8") != std::string::npos;
}

const char* env_or_null(const char* name) {
    const char* v = std::getenv(name);
    return v && *v ? v : nullptr;
}

}  // namespace

const char* tr(const char* msgid) {
    return g_active ? dgettext(kDomain, msgid) : msgid;
}

const char* trn(const char* one, const char* many, unsigned long n) {
    return g_active ? dngettext(kDomain, one, many, n) : (n == 1 ? one : many);
}

std::string strf(const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    va_list again;
    va_copy(again, ap);
    int n = std::vsnprintf(nullptr, 0, fmt, ap);
    va_end(ap);
    std::string s;
    if (n > 0) {
        s.resize(size_t(n) + 1);
        std::vsnprintf(s.data(), s.size(), fmt, again);
        s.resize(size_t(n));
    }
    va_end(again);
    return s;
}

namespace i18n {

std::string wanted(Getenv get) {
    auto var = [&](const char* name) -> const char* {
        const char* v = get(name);
        return v && *v ? v : nullptr;
    };
    const char* loc = var("LC_ALL");
    if (!loc) loc = var("LC_MESSAGES");
    if (!loc) loc = var("LANG");
    std::vector<std::string> c;
    if (const char* list = var("LANGUAGE"); list && !is_c_locale(loc)) {
        std::string_view l(list);
        while (!l.empty()) {
            size_t colon = l.find(':');
            add_candidates(l.substr(0, colon), c);
            l = colon == std::string_view::npos ? std::string_view{} : l.substr(colon + 1);
        }
    }
    if (!is_c_locale(loc)) add_candidates(loc, c);
    std::string out;
    for (const auto& s : c) out += (out.empty() ? "" : ":") + s;
    return out;
}

std::string choose(std::string_view override, const std::string& wanted_list,
                   const std::string& localedir) {
    auto usable = [&](const std::string& l) { return l == "en" || has_catalogue(localedir, l); };
    if (!override.empty()) {
        std::vector<std::string> c;
        add_candidates(override, c);
        for (const auto& l : c)
            if (usable(l)) return l;
        return "";
    }
    std::string_view l(wanted_list);
    while (!l.empty()) {
        size_t colon = l.find(':');
        std::string one(l.substr(0, colon));
        l = colon == std::string_view::npos ? std::string_view{} : l.substr(colon + 1);
        if (usable(one)) return one;
    }
    return "en";
}

void init(const std::string& lang, const std::string& localedir) {
    if (!std::setlocale(LC_ALL, "")) {
        // The named locale is not generated (a fresh Debian has only C.UTF-8):
        // keep what can be kept, and UTF-8 characters when the name asks for them.
        const char* ctype = env_or_null("LC_ALL");
        if (!ctype) ctype = env_or_null("LC_CTYPE");
        if (!ctype) ctype = env_or_null("LANG");
        if (!std::setlocale(LC_CTYPE, "") && says_utf8(ctype)) std::setlocale(LC_CTYPE, "C.UTF-8");
        std::setlocale(LC_MESSAGES, "");
    }
    // Programs, profiles, the store and every output use the decimal point.
    std::setlocale(LC_NUMERIC, "C");
    g_lang = lang.empty() ? "en" : lang;
    g_active = false;
    if (g_lang == "en") return;
    // glibc reads LANGUAGE only when LC_MESSAGES is not "C".
    if (is_c_locale(std::setlocale(LC_MESSAGES, nullptr))) std::setlocale(LC_MESSAGES, "C.UTF-8");
    setenv("LANGUAGE", g_lang.c_str(), 1);
    bindtextdomain(kDomain, localedir.c_str());
    bind_textdomain_codeset(kDomain, "UTF-8");
    g_active = true;
}

void use_english() {
    g_active = false;
    g_lang = "en";
}

std::string_view language() {
    return g_lang;
}

std::string available(const std::string& localedir) {
    std::vector<std::string> langs{"en"};
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(localedir, ec)) {
        std::string l = e.path().filename().string();
        if (l != "en" && has_catalogue(localedir, l)) langs.push_back(l);
    }
    std::sort(langs.begin(), langs.end());
    std::string out;
    for (const auto& l : langs) out += (out.empty() ? "" : ", ") + l;
    return out;
}

}  // namespace i18n
}  // namespace pupitre
