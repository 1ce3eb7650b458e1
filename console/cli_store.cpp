// pupitre import / export / list / rm / history / restore, and the store of a
// `run` or `check` given --db (DESIGN §2.1, §4).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>

#include "console/cli.hpp"
#include "core/interp/interp.hpp"
#include "store/link.hpp"
#include "store/store.hpp"
#include "store/text.hpp"

namespace pupitre::cli {

using store::Fault;
using store::Store;

namespace {

int report(const store::Error& e) {
    std::fprintf(stderr, "pupitre: %s\n", e.message.c_str());
    return store::exit_code(e.fault);
}

// The store named by --db, or the default one (its directory made if needed).
int open_store(const std::string& db, std::unique_ptr<Store>& out) {
    store::Options o;
    std::string path = db;
    if (path.empty()) {
        path = store::default_path();
        o.create_parents = true;
    }
    auto r = Store::open(path, o);
    if (r.error) return report(r.error);
    out = std::move(r.value);
    return kOk;
}

std::string when(int64_t ms) {
    std::time_t t = std::time_t(ms / 1000);
    std::tm tm{};
    localtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", &tm);
    return buf;
}

std::string name_of(int number, int index = -1) {
    std::string s = "%" + std::to_string(number);
    if (index >= 0) s += "." + std::to_string(index);
    return s;
}

bool read_file(const std::string& path, std::string& text, std::string& why) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        why = std::strerror(errno);
        return false;
    }
    text.clear();
    char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
    bool ok = !std::ferror(f);
    int err = errno;  // a directory: EISDIR
    std::fclose(f);
    if (!ok) why = std::strerror(err);
    return ok;
}

void say_saved(const store::SaveResult& r, const std::string& from) {
    std::string what;
    switch (r.status) {
        case store::SaveStatus::created:
            what = "created as r" + std::to_string(r.revision);
            break;
        case store::SaveStatus::saved:
            what = "saved as r" + std::to_string(r.revision);
            break;
        case store::SaveStatus::unchanged:
            what = "unchanged (r" + std::to_string(r.revision) + ")";
            break;
        case store::SaveStatus::conflict:
            what = "CONFLICT: kept aside as r" + std::to_string(r.revision) + "; r" +
                   std::to_string(r.current) + " by " + r.current_by + " stays current";
            break;
    }
    std::printf("%s: %s%s%s\n", name_of(r.number).c_str(), what.c_str(),
                from.empty() ? "" : " from ", from.c_str());
}

}  // namespace

int store_import(const StoreArgs& a) {
    // Everything is read and checked before the store is opened: a bad file
    // changes nothing.
    std::vector<store::Piece> pieces;
    std::vector<std::string> from;
    if (a.number >= 0 && a.files.size() != 1) {
        std::fprintf(stderr, "pupitre: import --number takes one file\n");
        return kUsage;
    }
    for (const auto& f : a.files) {
        std::string text, why;
        if (!read_file(f, text, why)) {
            std::fprintf(stderr, "pupitre: %s: cannot read: %s\n", f.c_str(), why.c_str());
            return kNoInput;
        }
        auto r = store::split_file(text, f, a.number);
        if (r.error) return report(r.error);
        for (auto& p : r.value) {
            from.push_back(f);
            pieces.push_back(std::move(p));
        }
    }
    for (size_t i = 0; i < pieces.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (pieces[i].number == pieces[j].number) {
                std::fprintf(stderr,
                             "pupitre: %s: program %%%d is also in %s; import one of them\n",
                             from[i].c_str(), pieces[i].number, from[j].c_str());
                return kDataErr;
            }
    std::unique_ptr<Store> s;
    if (int rc = open_store(a.db, s)) return rc;
    auto r = s->save_all(pieces);
    if (r.error) return report(r.error);
    for (size_t i = 0; i < r.value.size(); ++i) say_saved(r.value[i], from[i]);
    return kOk;
}

int store_export(const StoreArgs& a) {
    std::unique_ptr<Store> s;
    if (int rc = open_store(a.db, s)) return rc;
    std::string out;
    for (int n : a.numbers) {
        auto r = s->read(n);
        if (r.error) return report(r.error);
        out += r.value.text;
    }
    if (a.output.empty() || a.output == "-") {
        if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size() ||
            std::fflush(stdout) != 0) {
            std::fprintf(stderr, "pupitre: cannot write the standard output: %s\n",
                         std::strerror(errno));
            return kIoErr;
        }
        return kOk;
    }
    std::FILE* f = std::fopen(a.output.c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, "pupitre: %s: cannot create: %s\n", a.output.c_str(),
                     std::strerror(errno));
        return kCantCreate;
    }
    bool ok = std::fwrite(out.data(), 1, out.size(), f) == out.size();
    ok = std::fflush(f) == 0 && ok;
    int err = errno;
    ok = std::fclose(f) == 0 && ok;
    if (!ok) {
        std::fprintf(stderr, "pupitre: %s: write error: %s\n", a.output.c_str(),
                     std::strerror(err));
        return kIoErr;
    }
    return kOk;
}

int store_list(const StoreArgs& a) {
    std::unique_ptr<Store> s;
    if (int rc = open_store(a.db, s)) return rc;
    auto r = s->list();
    if (r.error) return report(r.error);
    std::string out;
    char line[256];
    for (const auto& p : r.value) {
        std::snprintf(line, sizeof line, "%-10s r%-4d %7lld lines  %s  %-10s",
                      name_of(p.number, p.index).c_str(), p.revision,
                      static_cast<long long>(p.lines), when(p.modified_ms).c_str(),
                      p.modified_by.c_str());
        out += line;
        if (!p.title.empty()) out += "  (" + p.title + ")";
        if (p.conflict) out += "  CONFLICT: r" + std::to_string(p.conflict) + " kept aside";
        out += '\n';
    }
    std::fputs(out.c_str(), stdout);
    return kOk;
}

int store_rm(const StoreArgs& a) {
    std::unique_ptr<Store> s;
    if (int rc = open_store(a.db, s)) return rc;
    int n = a.numbers.front();
    auto r = s->remove(n, store::kHead, "rm");
    if (r.error) return report(r.error);
    std::printf("%s: deleted (r%d); its history stays: pupitre restore %d REV brings it back\n",
                name_of(n).c_str(), r.value.revision, n);
    return kOk;
}

int store_history(const StoreArgs& a) {
    std::unique_ptr<Store> s;
    if (int rc = open_store(a.db, s)) return rc;
    int n = a.numbers.front();
    auto info = s->read(n);
    int current = info.error ? 0 : info.value.revision;
    auto r = s->history(n);
    if (r.error) return report(r.error);
    if (info.error && info.error.fault == Fault::not_found) current = r.value.back().revision;
    std::string out;
    char line[256];
    for (const auto& h : r.value) {
        std::snprintf(line, sizeof line, "%c r%-4d %s  %-10s %-8s",
                      h.revision == current ? '*' : ' ', h.revision, when(h.at_ms).c_str(),
                      h.who.c_str(), std::string(kind_name(h.kind)).c_str());
        out += line;
        if (h.kind != store::RevisionKind::remove) {
            std::snprintf(line, sizeof line, " %7lld lines", static_cast<long long>(h.lines));
            out += line;
        } else {
            out += "              ";
        }
        if (!h.source.empty()) out += "  " + h.source;
        if (h.conflict)
            out += "  CONFLICT: based on r" + std::to_string(h.based_on) + ", kept aside";
        out += '\n';
    }
    std::fputs(out.c_str(), stdout);
    return kOk;
}

int store_restore(const StoreArgs& a) {
    std::unique_ptr<Store> s;
    if (int rc = open_store(a.db, s)) return rc;
    int n = a.numbers.front();
    auto r = s->restore(n, a.revision);
    if (r.error) return report(r.error);
    if (r.value.status == store::SaveStatus::unchanged)
        std::printf("%s: r%d is already the current text\n", name_of(n).c_str(), a.revision);
    else
        std::printf("%s: r%d restored as r%d\n", name_of(n).c_str(), a.revision, r.value.revision);
    return kOk;
}

// ---- run / check --db ----

RunStore::RunStore() = default;
RunStore::~RunStore() = default;

int RunStore::open(const std::string& db) {
    return open_store(db, s_);
}

int RunStore::load_programs(ProgramMemory& mem) {
    auto r = store::load_programs(*s_, mem);
    return r.error ? report(r.error) : kOk;
}

int RunStore::seed(Interpreter& in) {
    auto r = store::seed_machine(*s_, in);
    return r.error ? report(r.error) : kOk;
}

int RunStore::persist(const Interpreter& in, const std::string& file,
                      const std::string& machine_arg) {
    std::string profile;
    MachineProfile builtin;
    if (!builtin_machine(machine_arg, builtin)) {
        std::string why;
        read_file(machine_arg, profile, why);  // a .machine file: kept with the values
    }
    std::string source = "program %" + std::to_string(in.main_program()) + " (" + file + ")";
    auto r = store::persist_run(*s_, in, source, profile);
    if (r.error) {
        report(r.error);
        std::fprintf(stderr, "pupitre: the run's corrector and origin changes were not stored\n");
        return store::exit_code(r.error.fault);
    }
    for (const auto& c : r.value)
        std::fprintf(stderr, "pupitre: stored %s = %s (was %s) on %s\n", c.name.c_str(),
                     store::format_value(c.name, c.new_value).c_str(),
                     c.old_value ? store::format_value(c.name, *c.old_value).c_str() : "not set",
                     in.machine().name.c_str());
    return kOk;
}

}  // namespace pupitre::cli
