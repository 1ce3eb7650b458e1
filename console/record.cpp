// An attempt's record (see record.hpp): its lines written and read.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/record.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>

#include "core/i18n.hpp"

namespace pupitre::console::record {

namespace {

struct VerbName {
    Verb verb;
    std::string_view word;
};
constexpr VerbName kVerbs[] = {
    {Verb::session, "session"}, {Verb::size, "size"},     {Verb::key, "key"},
    {Verb::line, "line"},       {Verb::answer, "answer"}, {Verb::escape, "esc"},
    {Verb::program, "program"}, {Verb::select, "select"}, {Verb::protect, "protect"},
    {Verb::dia, "dia"},         {Verb::shim, "shim"},
};

std::string_view word_of(Verb v) {
    for (const VerbName& n : kVerbs)
        if (n.verb == v) return n.word;
    return "?";
}

bool verb_of(std::string_view w, Verb& v) {
    for (const VerbName& n : kVerbs)
        if (n.word == w) {
            v = n.verb;
            return true;
        }
    return false;
}

// A program's text on one line: \ n and \r escaped.
std::string escape(std::string_view s) {
    std::string out;
    for (char c : s) {
        if (c == '\\')
            out += "\\\\";
        else if (c == '\n')
            out += "\\n";
        else if (c == '\r')
            out += "\\r";
        else
            out += c;
    }
    return out;
}

std::string unescape(std::string_view s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '\\' || i + 1 == s.size()) {
            out += s[i];
            continue;
        }
        const char n = s[++i];
        out += n == 'n' ? '\n' : n == 'r' ? '\r' : n;
    }
    return out;
}

bool to_int(std::string_view s, int& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
}

bool to_double(std::string_view s, double& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
}

// "A B" -> A and B, at the first blank.
std::pair<std::string_view, std::string_view> split(std::string_view s) {
    const size_t sp = s.find(' ');
    if (sp == std::string_view::npos) return {s, {}};
    return {s.substr(0, sp), s.substr(sp + 1)};
}

// What follows the verb, read into `a`; false when it does not fit the verb.
bool read_rest(std::string_view rest, Action& a) {
    auto [first, more] = split(rest);
    switch (a.verb) {
        case Verb::session:
        case Verb::escape:
            return rest.empty();
        case Verb::size:
            return to_int(first, a.a) && to_int(more, a.b);
        case Verb::key:
            a.text = first, a.arg = more;
            return !first.empty();
        case Verb::line:
            a.text = rest;
            return true;
        case Verb::answer:
            a.a = rest == "y";
            return rest == "y" || rest == "n";
        case Verb::program:
            a.text = unescape(more);
            return to_int(first, a.a);
        case Verb::select:
        case Verb::protect:
            return to_int(rest, a.a);
        case Verb::dia:
        case Verb::shim:
            return to_double(rest, a.value);
    }
    return false;
}

// Before version 1: "dia 40.0120" and "shim 10.0000" lines alone.
std::string parse_old(std::string_view text, std::vector<Action>& out) {
    size_t n = 0;
    for (size_t at = 0; at < text.size();) {
        size_t eol = text.find('\n', at);
        if (eol == std::string_view::npos) eol = text.size();
        std::string_view l = text.substr(at, eol - at);
        at = eol + 1, ++n;
        if (l.empty()) continue;
        auto [w, rest] = split(l);
        Action a;
        if (!verb_of(w, a.verb) || (a.verb != Verb::dia && a.verb != Verb::shim) ||
            !read_rest(rest, a))
            return strf(tr("line %zu: not a record's line: %s"), n, std::string(l).c_str());
        out.push_back(std::move(a));
    }
    return {};
}

}  // namespace

std::string format(const Action& a) {
    std::string out = strf("%.6f %s", a.clock, std::string(word_of(a.verb)).c_str());
    switch (a.verb) {
        case Verb::session:
        case Verb::escape:
            break;
        case Verb::size:
            out += strf(" %d %d", a.a, a.b);
            break;
        case Verb::key:
            out += " " + a.text + (a.arg.empty() ? "" : " " + a.arg);
            break;
        case Verb::line:
            out += " " + a.text;
            break;
        case Verb::answer:
            out += a.a ? " y" : " n";
            break;
        case Verb::program:
            out += strf(" %d ", a.a) + escape(a.text);
            break;
        case Verb::select:
        case Verb::protect:
            out += strf(" %d", a.a);
            break;
        case Verb::dia:
        case Verb::shim:
            out += strf(" %.4f", a.value);
            break;
    }
    return out;
}

std::string parse(std::string_view text, std::vector<Action>& out) {
    out.clear();
    if (text.substr(0, text.find('\n')) != kHeader) return parse_old(text, out);
    size_t n = 1;
    for (size_t at = text.find('\n') + 1; at > 0 && at < text.size();) {
        size_t eol = text.find('\n', at);
        if (eol == std::string_view::npos) eol = text.size();
        std::string_view l = text.substr(at, eol - at);
        at = eol + 1, ++n;
        if (l.empty()) continue;
        auto [clock, rest] = split(l);
        auto [verb, args] = split(rest);
        Action a;
        if (!to_double(clock, a.clock) || !verb_of(verb, a.verb) || !read_rest(args, a))
            return strf(tr("line %zu: not a record's line: %s"), n,
                        std::string(l.substr(0, 60)).c_str());
        out.push_back(std::move(a));
    }
    return {};
}

std::string describe(const Action& a) {
    switch (a.verb) {
        case Verb::session:
            return tr("the console starts on the attempt");
        case Verb::size:
            return strf(tr("the terminal is %d x %d"), a.a, a.b);
        case Verb::key:
            // TRANSLATORS: a key's action as the record names it: "key page pref".
            return strf(tr("key %s%s%s"), a.text.c_str(), a.arg.empty() ? "" : " ", a.arg.c_str());
        case Verb::line:
            // TRANSLATORS: a line the student entered on the input line.
            return strf(tr("entered: %s"), a.text.c_str());
        case Verb::answer:
            return a.a ? tr("answered yes") : tr("answered no");
        case Verb::escape:
            return tr("Escape");
        case Verb::program:
            return strf(tr("%%%d as it was run"), a.a);
        case Verb::select:
            return strf(tr("%%%d selected"), a.a);
        case Verb::protect:
            return a.a ? tr("memory protection ON") : tr("memory protection off");
        case Verb::dia:
            return strf(tr("read \u00d8%.3f"), a.value);
        case Verb::shim:
            return strf(tr("a %.3f mm shim placed"), a.value);
    }
    return {};
}

void Recorder::begin(const std::string& earlier) {
    text_ = earlier.rfind(kHeader, 0) == 0 ? earlier : std::string(kHeader) + "\n";
    if (!text_.empty() && text_.back() != '\n') text_ += '\n';
    Action a;
    a.verb = Verb::session;
    add(a);
}

void Recorder::add(const Action& a) {
    text_ += format(a) + "\n";
    changed_ = true;
}

}  // namespace pupitre::console::record
