// The outbox of a console on a server store (outbox.hpp): a file of lines
// "KEY<TAB>NAME<TAB>VALUE<TAB>SOURCE", rewritten whole (a new file renamed
// over the old) at each change, removed when empty.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/outbox.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/i18n.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

// A field may not hold the separators.
std::string clean(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return out;
}

constexpr const char* kAttemptKey = "#attempt";
constexpr char kSep = '\x1f';  // between an attempt's fields, before the hex

std::string hex(std::string_view s) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out;
    for (unsigned char c : s) out += kDigits[c >> 4], out += kDigits[c & 15];
    return out;
}

std::string unhex(std::string_view h) {
    std::string out;
    for (size_t i = 0; i + 1 < h.size(); i += 2)
        out += char(std::stoi(std::string(h.substr(i, 2)), nullptr, 16));
    return out;
}

// The attempt's fields :submit sends, one string (hex in the file).
std::string pack(const store::Attempt& a) {
    std::string out;
    for (const std::string& f :
         {a.exercise, a.exercise_sha, a.student, a.machine, std::to_string(a.started_ms),
          std::to_string(a.submitted_ms), a.seed, std::to_string(a.score), strf("%.17g", a.seconds),
          std::to_string(a.crashes), std::string(a.scrapped ? "1" : "0"), a.mistakes, a.found,
          a.report, a.signature, a.record})
        out += f + kSep;
    return hex(out);
}

bool unpack(const std::string& h, int64_t id, store::Attempt& a) {
    std::vector<std::string> f;
    std::string all = unhex(h), cur;
    for (char c : all)
        if (c == kSep)
            f.push_back(cur), cur.clear();
        else
            cur += c;
    if (f.size() != 16) return false;
    a.id = id;
    a.exercise = f[0], a.exercise_sha = f[1], a.student = f[2], a.machine = f[3];
    a.started_ms = std::stoll(f[4]), a.submitted_ms = std::stoll(f[5]), a.seed = f[6];
    a.score = std::stoi(f[7]), a.seconds = std::strtod(f[8].c_str(), nullptr);
    a.crashes = std::stoi(f[9]), a.scrapped = f[10] == "1";
    a.mistakes = f[11], a.found = f[12], a.report = f[13], a.signature = f[14], a.record = f[15];
    return true;
}

// One line sent: a value, or an attempt's :submit. A submit the store says
// was done already (its answer was lost) is sent: never a second one.
bool send_one(store::Store& s, const Outbox::Unsent& u) {
    if (u.key != kAttemptKey) return !s.set_values(u.key, {{u.name, u.value}}, u.source).error;
    store::Attempt a;
    if (!unpack(u.source, u.value, a)) return true;  // unreadable: dropped, not retried forever
    store::StoreError e = u.name == "class" ? s.submit_class_attempt(a) : s.submit_attempt(a);
    return !e || e.fault == store::Fault::not_found;
}

}  // namespace

void Outbox::add_submission(const store::Attempt& a, bool on_class) {
    q_.push_back({kAttemptKey, on_class ? "class" : "signed", a.id, pack(a)});
    save();
}

void Outbox::open(std::string path) {
    path_ = std::move(path);
    q_.clear();
    if (path_.empty()) return;
    std::ifstream in(path_);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream f(line);
        Unsent u;
        std::string value;
        if (!std::getline(f, u.key, '\t') || !std::getline(f, u.name, '\t') ||
            !std::getline(f, value, '\t'))
            continue;
        std::getline(f, u.source);
        char* end = nullptr;
        u.value = std::strtoll(value.c_str(), &end, 10);
        if (end && *end == '\0' && !value.empty()) q_.push_back(std::move(u));
    }
}

void Outbox::add(std::string_view key, std::string_view name, int64_t value,
                 std::string_view source) {
    q_.push_back({clean(key), clean(name), value, clean(source)});
    save();
}

std::vector<std::string> Outbox::send(store::Store& s) {
    std::vector<std::string> sent;
    size_t n = 0;
    for (; n < q_.size(); ++n) {
        const Unsent& u = q_[n];
        if (!send_one(s, u)) break;
        sent.push_back(u.key == kAttemptKey ? std::string(tr("the attempt")) : u.name);
    }
    q_.erase(q_.begin(), q_.begin() + long(n));
    if (n) save();
    return sent;
}

void Outbox::save() const {
    if (path_.empty()) return;
    if (q_.empty()) {
        ::unlink(path_.c_str());
        return;
    }
    // Its directory is the journal's parent, made as the journal makes it.
    for (size_t slash = path_.find('/', 1); slash != std::string::npos;
         slash = path_.find('/', slash + 1))
        ::mkdir(path_.substr(0, slash).c_str(), 0700);
    std::string tmp = path_ + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) return;
    for (const Unsent& u : q_)
        std::fprintf(f, "%s\t%s\t%lld\t%s\n", u.key.c_str(), u.name.c_str(),
                     static_cast<long long>(u.value), u.source.c_str());
    bool ok = std::fflush(f) == 0 && ::fsync(fileno(f)) == 0;
    ok = std::fclose(f) == 0 && ok;
    if (!ok || std::rename(tmp.c_str(), path_.c_str()) != 0) ::unlink(tmp.c_str());
}

}  // namespace pupitre::console
