// Exercise files: "key = value" lines, '#' comments, then the program to
// machine from its '%' line to the end (pupitre-exercise(5)).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/training/exercise.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "core/keyvalue.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre {
namespace data {
std::string_view exercise_exam_2005();
std::string_view exercise_exam_2005_drawn();
std::string_view exercise_lathe_first();
std::string_view exercise_lathe_tools();
std::string_view exercise_mill_pocket();
std::string_view exercise_wear();
}  // namespace data

namespace training {

namespace {

using kv::trim;

struct Builtin {
    const char* name;
    std::string_view (*text)();
};
constexpr Builtin kBuiltins[] = {
    {"exam-2005", data::exercise_exam_2005},
    {"exam-2005-drawn", data::exercise_exam_2005_drawn},
    {"lathe-first", data::exercise_lathe_first},
    {"lathe-tools", data::exercise_lathe_tools},
    {"mill-pocket", data::exercise_mill_pocket},
    {"wear", data::exercise_wear},
};

using kv::workshop_number;

// The words of `text`, split at blanks.
std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    while (!(text = trim(text)).empty()) {
        size_t end = text.find_first_of(" \t");
        out.push_back(text.substr(0, end));
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end);
    }
    return out;
}

// "LO .. HI [step S]" or a number.
std::string draw_value(std::string_view val, Draw& d) {
    size_t dots = val.find("..");
    if (dots == std::string_view::npos) {
        if (!workshop_number(val, d.lo)) d.text = std::string(val);  // the setup checks it
        d.hi = d.lo;
        return {};
    }
    std::vector<std::string_view> w = words(val.substr(dots + 2));
    d.range = true;
    if (!workshop_number(val.substr(0, dots), d.lo) || w.empty() || !workshop_number(w[0], d.hi) ||
        (w.size() != 1 && (w.size() != 3 || w[1] != "step" || !workshop_number(w[2], d.step))))
        return tr("expected LO .. HI or LO .. HI step S");
    if (d.hi <= d.lo) return tr("HI must be above LO");
    if (d.step < 0.0001 || d.step > d.hi - d.lo) return tr("step must be from 0.0001 to HI - LO");
    return {};
}

// "truth", "truth + 0.015", "truth - 0.2" or a number.
std::string start_value_text(std::string_view val, Start& start) {
    if (val.substr(0, 5) != "truth") {
        if (!workshop_number(val, start.value)) return tr("expected a number or truth + N");
        return {};
    }
    start.from_truth = true;
    std::string_view rest = trim(val.substr(5));
    if (rest.empty()) return {};
    double v = 0;
    if ((rest[0] != '+' && rest[0] != '-') || !workshop_number(rest.substr(1), v))
        return tr("expected truth + N or truth - N");
    start.value = rest[0] == '-' ? -v : v;
    return {};
}

// "SPEC : NOMINAL TOL" or "SPEC : NOMINAL -LOWER +UPPER".
std::string dimension(std::string_view val, Dimension& d) {
    size_t colon = val.find(':');
    if (colon == std::string_view::npos) return tr("expected SPEC : NOMINAL TOLERANCE");
    d.spec = std::string(trim(val.substr(0, colon)));
    std::vector<std::string_view> w = words(val.substr(colon + 1));
    std::vector<std::string_view> spec = words(d.spec);
    if (spec.empty() || !workshop::is_instrument(spec[0]))
        return tr("expected an instrument's request before ':' (dia Z-20, length, depth X Y...)");
    double t = 0;
    if (w.size() == 2 && workshop_number(w[0], d.nominal) && workshop_number(w[1], t) && t > 0) {
        d.lower = -t, d.upper = t;
        return {};
    }
    if (w.size() == 3 && workshop_number(w[0], d.nominal) && workshop_number(w[1], d.lower) &&
        workshop_number(w[2], d.upper) && d.lower < d.upper)
        return {};
    return tr("expected NOMINAL TOLERANCE or NOMINAL LOWER UPPER after ':'");
}

std::string numbers(std::string_view val, std::vector<double>& out) {
    for (std::string_view w : words(val)) {
        double v = 0;
        if (!workshop_number(w, v) || v <= 0) return tr("expected positive numbers");
        out.push_back(v);
    }
    return {};
}

std::string find_key(std::string_view val, int line, Exercise& e) {
    std::vector<std::string_view> w = words(val);
    Target t;
    t.line = line;
    if (w.empty() || w.size() > 2 ||
        (w.size() == 2 &&
         (!workshop_number(w[1], t.tolerance) || t.tolerance <= 0 || t.tolerance > 10)))
        return tr("expected NAME [TOLERANCE], e.g. PREF.X 0.01");
    t.name = std::string(w[0]);
    if (!target_name(t.name, e.lathe()))
        return strf(tr("'%s' is not a value to find on this machine"), t.name.c_str());
    for (const Target& o : e.find)
        if (o.name == t.name) return tr("given twice");
    e.find.push_back(t);
    return {};
}

std::string plain_key(Exercise& e, std::string_view key, std::string_view val, int line) {
    if (key == "name") {
        if (val.empty() || val.size() > 40 ||
            val.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_") !=
                std::string_view::npos)
            return tr("expected a name of small letters, digits, '-' and '_'");
        e.name = std::string(val);
    } else if (key == "title") {
        e.title = std::string(val);
    } else if (key == "task") {
        e.task.emplace_back(val);
    } else if (key == "method") {
        e.method.emplace_back(val);
    } else if (key == "machine") {
        if (val != "lathe" && val != "mill") return tr("expected lathe or mill");
        e.machine = e.setup = std::string(val);
    } else if (key == "origin") {
        e.origin = std::string(val);
    } else if (key == "find") {
        return find_key(val, line, e);
    } else if (key == "instruments") {
        for (std::string_view w : words(val)) {
            if (!workshop::is_instrument(w))
                return strf(tr("'%.*s' is not an instrument's word"), int(w.size()), w.data());
            e.instruments.emplace_back(w);
        }
    } else if (key == "shims") {
        return numbers(val, e.shims);
    } else if (key == "diameters") {
        return numbers(val, e.diameters);
    } else if (key == "time") {
        if (!workshop_number(val, e.minutes) || e.minutes < 0 || e.minutes > 1440)
            return tr("expected minutes from 0 to 1440");
    } else {
        return strf(tr("unknown key '%.*s'"), int(key.size()), key.data());
    }
    return {};
}

// "title.fr", "task.fr": a two-letter language after the dot.
bool translated(Exercise& e, std::string_view key, std::string_view val) {
    const size_t dot = key.find('.');
    if (dot == std::string_view::npos || key.size() != dot + 3) return false;
    const std::string_view head = key.substr(0, dot), lang = key.substr(dot + 1);
    if ((head != "title" && head != "task" && head != "method") || lang[0] < 'a' || lang[0] > 'z' ||
        lang[1] < 'a' || lang[1] > 'z')
        return false;
    (head == "title" ? e.titles : head == "task" ? e.tasks : e.methods).emplace_back(lang, val);
    return true;
}

std::string one_key(Exercise& e, std::string_view key, std::string_view val, int line) {
    if (translated(e, key, val)) return {};
    if (key.substr(0, 6) == "truth.") {
        Draw d;
        d.key = std::string(key.substr(6));
        d.line = line;
        if (std::string why = draw_value(val, d); !why.empty()) return why;
        e.truth.push_back(d);
        return {};
    }
    if (key.substr(0, 6) == "start.") {
        Start s;
        s.name = std::string(key.substr(6));
        s.line = line;
        if (!target_name(s.name, e.lathe()))
            return strf(tr("'%s' is not a value of this machine"), s.name.c_str());
        if (std::string why = start_value_text(val, s); !why.empty()) return why;
        e.start.push_back(s);
        return {};
    }
    if (key == "dimension") {
        Dimension d;
        d.line = line;
        if (std::string why = dimension(val, d); !why.empty()) return why;
        e.dimensions.push_back(d);
        return {};
    }
    return plain_key(e, key, val, line);
}

// The program: from the first line that begins with '%' to the end.
size_t program_start(std::string_view text) {
    for (size_t at = 0; at < text.size();) {
        if (text[at] == '%') return at;
        size_t eol = text.find('\n', at);
        if (eol == std::string_view::npos) break;
        at = eol + 1;
    }
    return std::string_view::npos;
}

// splitmix64: a draw in [0, 1) for each key, whatever the order of the keys.
double unit(uint64_t seed, std::string_view key) {
    uint64_t x = seed;
    for (char c : key) x = (x ^ uint8_t(c)) * 0x100000001b3ULL;
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return double(x >> 11) / double(1ULL << 53);
}

std::string fixed3(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

// The setup's text with every truth key at `which`: 0 the low end, 1 the
// high end, 2 drawn with `seed`.
std::string setup_text(const Exercise& e, int which, uint64_t seed) {
    workshop::Setup base;
    workshop::builtin_setup(e.setup, base);
    std::string text = base.source;
    if (!text.empty() && text.back() != '\n') text += '\n';
    text += "# the exercise's truth\n";
    for (const Draw& d : e.truth) {
        double v = d.lo;
        if (d.range) {
            double u = which == 0 ? 0 : which == 1 ? 1 : unit(seed, d.key);
            double steps = std::floor((d.hi - d.lo) / d.step + 1e-9);
            v = d.lo + std::min(std::floor(u * (steps + 1)), steps) * d.step;
        }
        text += d.key + " = " + (d.text.empty() ? fixed3(v) : d.text) + "\n";
    }
    return text;
}

}  // namespace

std::string Exercise::title_here() const {
    for (const auto& [lang, text] : titles)
        if (lang == i18n::language()) return text;
    return title;
}

namespace {
// The lines of one language, else those written without one.
std::vector<std::string> here(const std::vector<std::pair<std::string, std::string>>& translated,
                              const std::vector<std::string>& plain) {
    std::vector<std::string> out;
    for (const auto& [lang, text] : translated)
        if (lang == i18n::language()) out.push_back(text);
    return out.empty() ? plain : out;
}
}  // namespace

std::vector<std::string> Exercise::task_here() const {
    return here(tasks, task);
}

std::vector<std::string> Exercise::method_here() const {
    return here(methods, method);
}

bool Exercise::drawn() const {
    return std::any_of(truth.begin(), truth.end(), [](const Draw& d) { return d.range; });
}

std::string parse_exercise(std::string_view text, Exercise& out) {
    Exercise e;
    e.source = std::string(text);
    size_t prog = program_start(text);
    std::string_view keys = text.substr(0, prog);
    int lineno = 0;
    for (std::string_view line; kv::next_line(keys, line, lineno);) {
        size_t eq = line.find('=');
        if (eq == std::string_view::npos) return strf(tr("line %d: expected key = value"), lineno);
        std::string_view key = trim(line.substr(0, eq));
        std::string why = one_key(e, key, trim(line.substr(eq + 1)), lineno);
        if (!why.empty())
            return strf(tr("line %d: %.*s: %s"), lineno, int(key.size()), key.data(), why.c_str());
    }
    if (prog != std::string_view::npos) {
        e.program = std::string(text.substr(prog));
        auto r = std::from_chars(e.program.data() + 1, e.program.data() + e.program.size(),
                                 e.program_number);
        if (r.ec != std::errc() || e.program_number < 0)
            return strf(tr("line %d: the program must begin with %%N"), lineno + 1);
    }
    if (e.name.empty()) return tr("name is missing");
    if (e.find.empty() && e.dimensions.empty())
        return tr("nothing to grade: give find or dimension lines");
    if (e.origin.empty()) e.origin = e.lathe() ? "face" : "corner";
    out = std::move(e);
    return {};
}

std::string check_exercise(const Exercise& e) {
    std::string out;
    auto say = [&out](int line, const std::string& what) {
        out += line > 0 ? strf(tr("line %d: %s"), line, what.c_str()) : what;
        out += '\n';
    };
    if (e.lathe() ? e.origin != "face" && e.origin != "jaws"
                  : e.origin != "corner" && e.origin != "centre")
        say(0, e.lathe() ? tr("origin must be face or jaws on a lathe")
                         : tr("origin must be corner or centre on a mill"));
    workshop::Setup s;
    for (int which = 0; which < 3; ++which) {
        std::string why = workshop::parse_setup(setup_text(e, which, 1), s);
        if (!why.empty()) {
            say(0, strf(which == 0   ? tr("with every range at its low end: %s")
                        : which == 1 ? tr("with every range at its high end: %s")
                                     : tr("the setup: %s"),
                        why.c_str()));
            return out;
        }
    }
    for (const Target& t : e.find)
        if (double v = 0; !expected(e, s, t.name, v))
            say(t.line, strf(tr("%s: the setup has no such tool"), t.name.c_str()));
    for (const Start& st : e.start)
        if (double v = 0; !expected(e, s, st.name, v))
            say(st.line, strf(tr("%s: the setup has no such tool"), st.name.c_str()));
    if (!out.empty()) return out;
    // Rehearsed at both ends of the ranges and in between: a student who
    // finds every value gets every dimension.
    static const char* const kWhich[] = {N_("at the ranges' low ends"),
                                         N_("at the ranges' high ends"), N_("drawn")};
    for (int which = 0; which < (e.drawn() ? 3 : 1); ++which) {
        workshop::Setup t;
        workshop::parse_setup(setup_text(e, which, 1), t);
        if (std::string why = rehearse(e, t); !why.empty()) {
            out +=
                strf(tr("done right %s, the exercise fails: %s"), tr(kWhich[which]), why.c_str());
            if (out.back() != '\n') out += '\n';
        }
    }
    return out;
}

std::vector<std::string> builtin_exercises() {
    std::vector<std::string> out;
    for (const Builtin& b : kBuiltins) out.emplace_back(b.name);
    return out;
}

bool builtin_exercise(std::string_view name, Exercise& e) {
    for (const Builtin& b : kBuiltins)
        if (name == b.name) return parse_exercise(b.text(), e).empty();
    return false;
}

uint64_t seed_of(const Exercise& e, std::string_view student, std::string_view secret) {
    std::string in = e.source;
    in += '\0';
    in += student;
    in += '\0';
    in += secret;
    const std::string h = sha256_hex(in);
    return std::stoull(h.substr(0, 16), nullptr, 16);
}

std::string draw_setup(const Exercise& e, uint64_t seed, workshop::Setup& setup) {
    return workshop::parse_setup(setup_text(e, 2, seed), setup);
}

std::string exercise_from_setup(const workshop::Setup& setup, std::string_view name) {
    std::string out = strf(
        "# pupitre exercise (pupitre-exercise(5)), from the setup %s: every value fixed.\n"
        "# Give ranges (LO .. HI) to the values each student must find.\n"
        "name = %.*s\ntitle = %s\nmachine = %s\n",
        setup.name.c_str(), int(name.size()), name.data(), setup.description.c_str(),
        setup.kind.c_str());
    out += setup.kind == "lathe" ? "find = PREF.X 0.01\nfind = PREF.Z 0.01\n"
                                 : "find = PREF.X 0.01\nfind = PREF.Y 0.01\nfind = PREF.Z 0.01\n";
    std::string_view text = setup.source;
    int lineno = 0;
    for (std::string_view line; kv::next_line(text, line, lineno);) {
        size_t eq = line.find('=');
        std::string_view key = trim(line.substr(0, eq));
        if (eq == std::string_view::npos || key == "name" || key == "description" || key == "kind")
            continue;
        out += "truth." + std::string(key) + " = " + std::string(trim(line.substr(eq + 1))) + "\n";
    }
    return out;
}

}  // namespace training
}  // namespace pupitre
