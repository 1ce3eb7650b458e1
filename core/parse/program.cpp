// Program memory: splitting files into % programs, label index.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parse/program.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>

#include "core/i18n.hpp"

namespace pupitre {

long line_label(std::string_view line) {
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i < line.size() && line[i] == '/') ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size() || line[i] != 'N') return -1;
    ++i;
    while (i < line.size() && line[i] == ' ') ++i;
    long n = 0;
    int digits = 0;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9' && digits < 9) {
        n = n * 10 + (line[i] - '0');
        ++i;
        ++digits;
    }
    // "NC", "NU"… are other addresses; a bare N is N0 (004:236, 000:2478;
    // pupitre-iso(5), DECISIONS).
    if (digits == 0 && i < line.size() && line[i] >= 'A' && line[i] <= 'Z') return -1;
    return n;
}

const Label* ProgramText::find_label(long n) const {
    if (!indexed_) {
        std::string_view all = *text;
        size_t pos = begin;
        int line = first_line;
        while (pos < end) {
            size_t eol = all.find('\n', pos);
            if (eol == std::string_view::npos || eol > end) eol = end;
            long lab = line_label(all.substr(pos, eol - pos));
            if (lab >= 0) labels_.push_back({lab, line, pos});
            pos = eol + 1;
            ++line;
        }
        std::stable_sort(labels_.begin(), labels_.end(),
                         [](const Label& a, const Label& b) { return a.n < b.n; });
        indexed_ = true;
    }
    auto it = std::lower_bound(labels_.begin(), labels_.end(), n,
                               [](const Label& a, long v) { return a.n < v; });
    return (it != labels_.end() && it->n == n) ? &*it : nullptr;
}

std::optional<Diag> ProgramMemory::load_file(const std::string& path) {
    auto cannot = [&](const char* why) {
        return Diag{Severity::error, err::kCannotRead, path, -1, 0, -1, 0, tr(why)};
    };
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return cannot(N_("cannot open the file"));
    struct stat st {};
    const bool regular = fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    // A large regular file is mapped (text.hpp).
    if (regular && size_t(st.st_size) >= kMapFrom)
        if (std::shared_ptr<Text> mapped = Text::map(fd, size_t(st.st_size))) {
            close(fd);
            return load_shared(path, std::move(mapped));
        }
    // A smaller one, a pipe or a terminal is read to its end (a program is
    // kept whole in memory anyway).
    std::string text;
    if (regular) text.reserve(size_t(st.st_size) + 1);  // + the '\n' load_text may add
    char buf[1 << 16];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) != 0) {
        if (n > 0)
            text.append(buf, size_t(n));
        else if (errno != EINTR)
            break;
    }
    close(fd);
    if (n < 0) return cannot(N_("read error"));
    return load_text(path, std::move(text));
}

namespace {
bool header_line(std::string_view line, int& number, int& index, std::string& title) {
    if (line.empty() || (line[0] != '%' && line[0] != ' ' && line[0] != '\t')) return false;
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size() || line[i] != '%') return false;
    ++i;
    number = 0;
    index = -1;
    while (i < line.size() && line[i] == ' ') ++i;
    int digits = 0;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9' && digits < 6) {
        number = number * 10 + (line[i++] - '0');
        ++digits;
    }
    if (i < line.size() && line[i] == '.') {
        ++i;
        index = 0;
        while (i < line.size() && line[i] >= '0' && line[i] <= '9' && index < 100000)
            index = index * 10 + (line[i++] - '0');
    }
    size_t open = line.find('(', i);
    if (open != std::string_view::npos) {
        size_t close = line.find(')', open);
        std::string_view t = line.substr(
            open + 1, close == std::string_view::npos ? std::string_view::npos : close - open - 1);
        while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
        while (!t.empty() && (t.back() == ' ' || t.back() == '\r')) t.remove_suffix(1);
        title = std::string(t);
    }
    return true;
}

bool blank_or_comment(std::string_view line) {
    bool in_comment = false;
    for (char c : line) {
        if (in_comment) {
            if (c == ')') in_comment = false;
        } else if (c == '(') {
            in_comment = true;
        } else if (c != ' ' && c != '\t' && c != '\r') {
            return false;
        }
    }
    return true;
}

// The programs of a file, one from each header line to the next. Text before
// the first header forms program 0 when it holds blocks (004_rectangle.iso is
// such a fragment). A header is a line whose first non-blank character is
// '%': the file is searched for '%' (rare) rather than read line by line, and
// the lines between headers are counted in one pass (issue 14: a 28 MB
// program was split at one memchr a line).
std::vector<std::unique_ptr<ProgramText>> split_programs(const std::string& name,
                                                         const std::shared_ptr<Text>& shared) {
    std::string_view all = *shared;
    std::vector<std::unique_ptr<ProgramText>> found;
    auto anon = std::make_unique<ProgramText>();
    anon->file = name;
    anon->text = shared;
    anon->begin = 0;
    anon->first_line = 1;
    ProgramText* cur = anon.get();
    size_t counted = 0;  // the lines before `counted` are in `line`
    int line = 1;
    for (size_t pct = all.find('%'); pct != std::string_view::npos; pct = all.find('%', pct + 1)) {
        const size_t nl = pct == 0 ? std::string_view::npos : all.rfind('\n', pct - 1);
        const size_t pos = nl == std::string_view::npos ? 0 : nl + 1;
        size_t eol = all.find('\n', pct);
        if (eol == std::string_view::npos) eol = all.size();
        int number, index;
        std::string title;
        if (!header_line(all.substr(pos, eol - pos), number, index, title)) continue;
        line += int(std::count(all.begin() + long(counted), all.begin() + long(pos), '\n'));
        counted = pos;
        cur->end = pos;
        auto p = std::make_unique<ProgramText>();
        p->number = number;
        p->index = index;
        p->title = std::move(title);
        p->file = name;
        p->text = shared;
        p->begin = std::min(eol + 1, all.size());
        p->first_line = line + 1;
        cur = p.get();
        found.push_back(std::move(p));
        pct = eol == all.size() ? eol - 1 : eol;
    }
    cur->end = all.size();
    // Program 0: the text before the first header, when a line of it is a block.
    bool anonymous_has_blocks = false;
    for (size_t pos = 0; pos < anon->end && !anonymous_has_blocks;) {
        size_t eol = all.find('\n', pos);
        if (eol == std::string_view::npos || eol > anon->end) eol = anon->end;
        anonymous_has_blocks = !blank_or_comment(all.substr(pos, eol - pos));
        pos = eol + 1;
    }
    if (anonymous_has_blocks) found.insert(found.begin(), std::move(anon));
    return found;
}
}  // namespace

std::optional<Diag> ProgramMemory::load_text(std::string name, std::string text) {
    // Every line ends with '\n', so G76+ can insert after the last one.
    if (!text.empty() && text.back() != '\n') text.push_back('\n');
    return load_shared(name, std::make_shared<Text>(std::move(text)));
}

std::optional<Diag> ProgramMemory::load_shared(const std::string& name,
                                               std::shared_ptr<Text> shared) {
    // A NUL byte is never part of a program: refuse binary input up front.
    if (shared->find('\0') != std::string_view::npos)
        return Diag{Severity::error,
                    err::kNotText,
                    name,
                    -1,
                    0,
                    -1,
                    0,
                    tr("not a text file (NUL byte found)")};
    std::vector<std::unique_ptr<ProgramText>> found = split_programs(name, shared);
    if (found.empty())
        return Diag{
            Severity::error, err::kNoProgram, name, -1, 0, -1, 0, tr("no program in the file")};
    for (auto& p : found) {
        if (const ProgramText* old = find(p->number)) {
            warnings_.push_back(
                Diag{Severity::warning, err::wDuplicateProgram, p->file, p->number,
                     p->first_line - 1, -1, 0,
                     strf(tr("program %%%d is already loaded from %s; this copy is ignored"),
                          p->number, old->file.c_str())});
            continue;
        }
        progs_.push_back(std::move(p));
    }
    return std::nullopt;
}

const ProgramText* ProgramMemory::find(int number) const {
    for (const auto& p : progs_)
        if (p->number == number) return p.get();
    return nullptr;
}

std::string program_text(const ProgramText& p) {
    std::string_view all = *p.text;
    size_t h = p.begin;
    if (h > 0) {
        size_t nl = h >= 2 ? all.rfind('\n', h - 2) : std::string_view::npos;
        h = nl == std::string_view::npos ? 0 : nl + 1;
    }
    return std::string(all.substr(h, p.end - h));
}

ProgramMemory ProgramMemory::clone() const {
    ProgramMemory out;
    std::vector<std::pair<const Text*, std::shared_ptr<Text>>> copies;
    for (const auto& p : progs_) {
        auto q = std::make_unique<ProgramText>(*p);
        auto it = std::find_if(copies.begin(), copies.end(),
                               [&](const auto& c) { return c.first == p->text.get(); });
        if (it == copies.end()) {
            copies.push_back({p->text.get(), std::make_shared<Text>(*p->text)});
            it = copies.end() - 1;
        }
        q->text = it->second;
        out.progs_.push_back(std::move(q));
    }
    return out;
}

const ProgramText* ProgramMemory::create(int number) {
    if (find(number)) return nullptr;
    auto p = std::make_unique<ProgramText>();
    p->number = number;
    p->file = "%" + std::to_string(number);
    p->text = std::make_shared<Text>("%" + std::to_string(number) + "\n");
    p->begin = p->end = p->text->size();
    p->first_line = 2;
    progs_.push_back(std::move(p));
    mark_changed(number);
    return progs_.back().get();
}

bool ProgramMemory::remove(int number) {
    for (auto it = progs_.begin(); it != progs_.end(); ++it)
        if ((*it)->number == number) {
            removed_.push_back(std::move(*it));
            progs_.erase(it);
            mark_changed(number);
            return true;
        }
    return false;
}

Splice ProgramMemory::splice(const ProgramText* p, size_t at, size_t del, std::string_view ins) {
    std::string& text = p->text->str();
    auto lines_in = [](std::string_view t) { return int(std::count(t.begin(), t.end(), '\n')); };
    const int line_at =
        p->first_line + lines_in(std::string_view(text).substr(p->begin, at - p->begin));
    const int del_lines = lines_in(std::string_view(text).substr(at, del));
    const Splice sp{at, del, ins.size(), line_at, del_lines, lines_in(ins)};
    const int dl = sp.ins_lines - sp.del_lines;
    const ptrdiff_t db = ptrdiff_t(ins.size()) - ptrdiff_t(del);
    text.replace(at, del, ins);
    for (auto& q : progs_) {
        if (q->text != p->text) continue;
        if (q.get() == p) {
            q->end = size_t(ptrdiff_t(q->end) + db);
        } else if (q->begin > at) {
            q->begin = size_t(ptrdiff_t(q->begin) + db);
            q->end = size_t(ptrdiff_t(q->end) + db);
            q->first_line += dl;
        }
        if (!q->indexed_) continue;
        auto& labels = q->labels_;
        std::erase_if(labels,
                      [&](const Label& l) { return l.offset >= at && l.offset < at + del; });
        for (Label& l : labels)
            if (l.offset >= at + del) {
                l.offset = size_t(ptrdiff_t(l.offset) + db);
                l.line += dl;
            }
        if (q.get() != p) continue;
        // The labels of the inserted lines, in (n, line) order like the index.
        size_t pos = 0;
        for (int line = line_at; pos < ins.size(); ++line) {
            size_t eol = std::min(ins.size(), ins.find('\n', pos));
            long n = line_label(ins.substr(pos, eol - pos));
            if (n >= 0) {
                Label l{n, line, at + pos};
                auto it = std::upper_bound(labels.begin(), labels.end(), l,
                                           [](const Label& a, const Label& b) {
                                               return a.n != b.n ? a.n < b.n : a.line < b.line;
                                           });
                labels.insert(it, l);
            }
            pos = eol + 1;
        }
    }
    mark_changed(p->number);
    return sp;
}

size_t ProgramMemory::size() const {
    size_t n = 0;
    for (const auto& p : progs_) n += p->end - p->begin;
    return n;
}

void ProgramMemory::mark_changed(int number) {
    ++generation_;
    if (std::find(changed_.begin(), changed_.end(), number) == changed_.end())
        changed_.push_back(number);
}

std::vector<int> ProgramMemory::take_changed() {
    std::vector<int> out;
    out.swap(changed_);
    return out;
}

std::optional<Diag> ProgramMemory::replace(int number, std::string name, std::string text) {
    ProgramMemory fresh;
    if (std::optional<Diag> d = fresh.load_text(name, std::move(text))) return d;
    auto& got = fresh.progs_;
    if (got.empty() || got.front()->number != number)
        return Diag{Severity::error,
                    err::kNoProgram,
                    name,
                    -1,
                    0,
                    -1,
                    0,
                    strf(tr("the text does not start with %%%d"), number)};
    for (auto& p : progs_)
        if (p->number == number) {
            *p = std::move(*got.front());  // same object: the interpreter's pointers stay good
            ++generation_;
            return std::nullopt;
        }
    progs_.push_back(std::move(got.front()));
    return std::nullopt;
}

}  // namespace pupitre
