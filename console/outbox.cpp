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

}  // namespace

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
        if (s.set_values(u.key, {{u.name, u.value}}, u.source).error) break;
        sent.push_back(u.name);
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
