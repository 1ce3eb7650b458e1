// pupitre import / export / list / rm / history / restore, and the store of a
// `run` or `check` given --db (pupitre(1), OPTIONS and PROGRAM STORE).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "console/cli.hpp"
#include "console/refusal.hpp"
#include "console/wall_clock.hpp"
#include "core/i18n.hpp"
#include "core/interp/interp.hpp"
#include "store/link.hpp"
#include "store/store.hpp"
#include "store/text.hpp"

namespace pupitre::cli {

using store::Fault;
using store::Store;

int report(const store::StoreError& e) {
    // TRANSLATORS: any message, after the program's name.
    std::fprintf(stderr, tr("pupitre: %s\n"), e.message.c_str());
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

namespace {

std::string when(int64_t ms) {
    return local_time(ms, "%Y-%m-%d %H:%M:%S");
}

std::string name_of(int number, int index = -1) {
    std::string s = "%" + std::to_string(number);
    if (index >= 0) s += "." + std::to_string(index);
    return s;
}

// Display columns of UTF-8 text (code points): the French words carry accents,
// and printf's %-10s counts bytes.
size_t columns(std::string_view s) {
    size_t n = 0;
    for (unsigned char c : s) n += (c & 0xc0) != 0x80;
    return n;
}

// `s` padded with spaces to `width` display columns.
std::string pad(std::string s, size_t width) {
    size_t n = columns(s);
    if (n < width) s.append(width - n, ' ');
    return s;
}

// "     12 lines", as wide in every row (the widest form of the language).
std::string lines_cell(long long n) {
    // TRANSLATORS: a column of `pupitre list` and `pupitre history`; keep the
    // number's width (%7lld), the rows are aligned on it.
    std::string cell = strf(trn("%7lld lines", "%7lld lines", static_cast<unsigned long>(n)), n);
    return pad(std::move(cell), columns(strf(trn("%7lld lines", "%7lld lines", 2), 0LL)));
}

// What made a revision, as `pupitre history` shows it (the store keeps the
// English word: kind_name).
const char* kind_label(store::RevisionKind k) {
    switch (k) {
        case store::RevisionKind::import:
            // TRANSLATORS: revision kind, 8 characters at most: `pupitre import`.
            return tr("import");
        case store::RevisionKind::save:
            // TRANSLATORS: revision kind, 8 characters at most: saved in the editor.
            return tr("save");
        case store::RevisionKind::restore:
            // TRANSLATORS: revision kind, 8 characters at most: `pupitre restore`.
            return tr("restore");
        case store::RevisionKind::remove:
            // TRANSLATORS: revision kind, 8 characters at most: `pupitre rm`.
            return tr("delete");
        case store::RevisionKind::seed:
            // TRANSLATORS: revision kind, 8 characters at most: a demo program
            // stored when the store was created.
            return tr("seed");
    }
    return tr("save");
}

// The file's bytes, or why they could not be read (then what was read before the error).
Answer<std::string> read_file(const std::string& path) {
    Answer<std::string> r;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        r.why = std::strerror(errno);
        return r;
    }
    char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) r.value.append(buf, n);
    bool ok = !std::ferror(f);
    int err = errno;  // a directory: EISDIR
    std::fclose(f);
    if (!ok) r.why = std::strerror(err);
    return r;
}

void say_saved(const store::SaveResult& r, const std::string& from) {
    const std::string n = name_of(r.number);
    const char* f = from.c_str();
    std::string s;
    switch (r.status) {
        case store::SaveStatus::created:
            s = from.empty() ? strf(tr("%s: created as r%d"), n.c_str(), r.revision)
                             : strf(tr("%s: created as r%d from %s"), n.c_str(), r.revision, f);
            break;
        case store::SaveStatus::saved:
            s = from.empty() ? strf(tr("%s: saved as r%d"), n.c_str(), r.revision)
                             : strf(tr("%s: saved as r%d from %s"), n.c_str(), r.revision, f);
            break;
        case store::SaveStatus::unchanged:
            s = from.empty() ? strf(tr("%s: unchanged (r%d)"), n.c_str(), r.revision)
                             : strf(tr("%s: unchanged (r%d) from %s"), n.c_str(), r.revision, f);
            break;
        case store::SaveStatus::conflict:
            s = from.empty()
                    // TRANSLATORS: the program (%12), the revision kept aside,
                    // the current revision, who wrote it.
                    ? strf(tr("%s: CONFLICT: kept aside as r%d; r%d by %s stays current"),
                           n.c_str(), r.revision, r.current, r.current_by.c_str())
                    // TRANSLATORS: as above, then the file imported.
                    : strf(tr("%s: CONFLICT: kept aside as r%d; r%d by %s stays current from %s"),
                           n.c_str(), r.revision, r.current, r.current_by.c_str(), f);
            break;
    }
    s += '\n';
    std::fputs(s.c_str(), stdout);
}

}  // namespace

int store_import(const StoreArgs& a) {
    // Everything is read and checked before the store is opened: a bad file
    // changes nothing.
    std::vector<store::Piece> pieces;
    std::vector<std::string> from;
    if (a.number >= 0 && a.files.size() != 1) {
        std::fputs(tr("pupitre: import --number takes one file\n"), stderr);
        return kUsage;
    }
    for (const auto& f : a.files) {
        auto [text, why] = read_file(f);
        if (!why.empty()) {
            std::fprintf(stderr, tr("pupitre: %s: cannot read: %s\n"), f.c_str(), why.c_str());
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
                             tr("pupitre: %s: program %%%d is also in %s; import one of them\n"),
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
            std::fprintf(stderr, tr("pupitre: cannot write the standard output: %s\n"),
                         std::strerror(errno));
            return kIoErr;
        }
        return kOk;
    }
    std::FILE* f = std::fopen(a.output.c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, tr("pupitre: %s: cannot create: %s\n"), a.output.c_str(),
                     std::strerror(errno));
        return kCantCreate;
    }
    bool ok = std::fwrite(out.data(), 1, out.size(), f) == out.size();
    ok = std::fflush(f) == 0 && ok;
    int err = errno;
    ok = std::fclose(f) == 0 && ok;
    if (!ok) {
        std::fprintf(stderr, tr("pupitre: %s: write error: %s\n"), a.output.c_str(),
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
        std::snprintf(line, sizeof line, "%-10s r%-4d %s  %s  %-10s",
                      name_of(p.number, p.index).c_str(), p.revision,
                      lines_cell(static_cast<long long>(p.lines)).c_str(),
                      when(p.modified_ms).c_str(), p.modified_by.c_str());
        out += line;
        if (!p.title.empty()) out += "  (" + p.title + ")";
        if (p.conflict) out += "  " + strf(tr("CONFLICT: r%d kept aside"), int(p.conflict));
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
    std::printf(tr("%s: deleted (r%d); its history stays: pupitre restore %d REV brings it back\n"),
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
        std::snprintf(line, sizeof line, "%c r%-4d %s  %-10s %s", h.revision == current ? '*' : ' ',
                      h.revision, when(h.at_ms).c_str(), h.who.c_str(),
                      pad(kind_label(h.kind), 8).c_str());
        out += line;
        out += ' ';
        if (h.kind != store::RevisionKind::remove)
            out += lines_cell(static_cast<long long>(h.lines));
        else
            out += std::string(columns(lines_cell(0)), ' ');
        if (!h.source.empty()) out += "  " + h.source;  // as stored: not translated
        if (h.conflict) out += "  " + strf(tr("CONFLICT: based on r%d, kept aside"), h.based_on);
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
        std::printf(tr("%s: r%d is already the current text\n"), name_of(n).c_str(), a.revision);
    else
        std::printf(tr("%s: r%d restored as r%d\n"), name_of(n).c_str(), a.revision,
                    r.value.revision);
    return kOk;
}

// store copy FROM TO: FROM must exist; TO is made (unseeded) when it does not.
int store_copy(const StoreArgs& a) {
    store::Options src;
    src.create = false;
    auto from = Store::open(a.from, src);
    if (from.error) return report(from.error);
    store::Options dst;
    dst.seed = false;
    auto to = Store::open(a.to, dst);
    if (to.error) return report(to.error);
    const bool made = to.value->created() && to.value->engine() == "sqlite";
    auto r = from.value->copy_to(*to.value);
    if (r.error) {
        // A file this command made holds nothing worth keeping.
        if (made) {
            std::string path = to.value->path();
            to.value.reset();
            std::remove(path.c_str());
        }
        return report(r.error);
    }
    long long rows = 0;
    for (const auto& t : r.value.tables) {
        std::printf("%-12s %8lld  %s\n", t.name.c_str(), static_cast<long long>(t.rows),
                    t.checksum.c_str());
        rows += t.rows;
    }
    std::printf(tr("%s -> %s: %lld rows in %d tables copied; counts and checksums agree\n"),
                from.value->path().c_str(), to.value->path().c_str(), rows,
                int(r.value.tables.size()));
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
        profile = read_file(machine_arg).value;  // a .machine file: kept with the values
    }
    std::string source = "program %" + std::to_string(in.main_program()) + " (" + file + ")";
    auto r = store::persist_run(*s_, in, source, profile);
    if (r.error) {
        report(r.error);
        std::fputs(tr("pupitre: the run's corrector and origin changes were not stored\n"), stderr);
        return store::exit_code(r.error.fault);
    }
    for (const auto& c : r.value)
        std::fprintf(
            stderr, tr("pupitre: stored %s = %s (was %s) on %s\n"), c.name.c_str(),
            store::format_value(c.name, c.new_value).c_str(),
            c.old_value ? store::format_value(c.name, *c.old_value).c_str() : tr("not set"),
            in.machine().name.c_str());
    return kOk;
}

}  // namespace pupitre::cli
