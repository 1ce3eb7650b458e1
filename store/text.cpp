// Program texts: cutting a file into % programs, reading a program's header.
// The header itself is read by ProgramMemory, so the store and the interpreter
// never disagree on a program's number.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/text.hpp"

#include <algorithm>
#include <cstring>
#include <map>

#include "core/i18n.hpp"
#include "core/parse/program.hpp"

namespace pupitre::store {

namespace {

int line_of(std::string_view text, size_t pos) {
    return 1 + int(std::count(text.begin(),
                              text.begin() + std::ptrdiff_t(std::min(pos, text.size())), '\n'));
}

StoreError bad(std::string msg) {
    return StoreError{Fault::bad_data, std::move(msg)};
}

struct HeaderLine {
    size_t offset;
    int line;
};

// The header lines of a text.
std::vector<HeaderLine> header_lines(std::string_view text) {
    std::vector<HeaderLine> out;
    size_t pos = 0;
    int line = 1;
    while (pos < text.size()) {
        size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos) eol = text.size();
        if (is_header_line(text.substr(pos, eol - pos))) out.push_back({pos, line});
        pos = eol + 1;
        ++line;
    }
    return out;
}

StoreError no_nul(std::string_view text, std::string_view name) {
    size_t nul = text.find('\0');
    if (nul == std::string_view::npos) return {};
    return bad(strf(tr("%s:%d: not a program text (NUL byte)"), std::string(name).c_str(),
                    line_of(text, nul)));
}

}  // namespace

bool is_header_line(std::string_view line) {
    size_t i = line.find_first_not_of(" \t");
    return i != std::string_view::npos && line[i] == '%';
}

int64_t count_lines(std::string_view text) {
    int64_t n = 0;
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end) {
        const void* nl = std::memchr(p, '\n', size_t(end - p));
        if (!nl) {
            ++n;  // a last line without its newline
            break;
        }
        ++n;
        p = static_cast<const char*>(nl) + 1;
    }
    return n;
}

namespace {
// Reads the header of one program's text; `first_line` is the line of the text
// in its file, for the messages.
StoreError parse_piece(std::string_view text, std::string_view name, int first_line, Header& h) {
    h = Header{};
    if (StoreError e = no_nul(text, name)) return e;
    std::vector<HeaderLine> headers = header_lines(text);
    if (headers.empty()) return {};  // a fragment: its number is given by the caller
    const std::string file(name);
    auto where = [&](int line) { return first_line - 1 + line; };
    if (headers.size() > 1)
        return bad(strf(
            tr("%s:%d: a second %% line; a stored program holds one program (import cuts a file "
               "into its programs)"),
            file.c_str(), where(headers[1].line)));
    ProgramMemory mem;
    if (std::optional<Diag> d = mem.load_text(std::string(name), std::string(text)))
        return bad(std::string(name) + ": " + d->detail);
    const auto& progs = mem.programs();
    if (progs.size() != 1)  // ProgramMemory made a program of the blocks before the % line
        return bad(
            strf(tr("%s:%d: blocks before the %% line; a stored program starts at its %% line "
                    "(only blank lines and comments may come before it)"),
                 file.c_str(), where(headers[0].line)));
    h.number = progs[0]->number;
    h.index = progs[0]->index;
    h.title = progs[0]->title;
    return {};
}
}  // namespace

StoreError parse_program(std::string_view text, std::string_view name, Header& h) {
    return parse_piece(text, name, 1, h);
}

Result<std::vector<Piece>> split_file(std::string_view text, std::string_view name,
                                      int number_if_headerless) {
    Result<std::vector<Piece>> r;
    if ((r.error = no_nul(text, name))) return r;
    std::vector<HeaderLine> starts = header_lines(text);
    const std::string source = "import " + std::string(name);
    if (starts.empty()) {
        ProgramMemory mem;
        if (std::optional<Diag> d = mem.load_text(std::string(name), std::string(text))) {
            r.error = bad(std::string(name) + ": " + d->detail);
            return r;
        }
        if (number_if_headerless < 0) {
            r.error =
                bad(strf(tr("%s: no %% line, so no program number; give it one with --number N"),
                         std::string(name).c_str()));
            return r;
        }
        r.value.push_back(Piece{number_if_headerless, std::string(text), source});
        return r;
    }
    if (number_if_headerless >= 0) {
        r.error = bad(strf(tr("%s: the file has %% lines; --number is for a file without one"),
                           std::string(name).c_str()));
        return r;
    }
    std::map<int, int> seen;  // number -> line of its % line
    for (size_t i = 0; i < starts.size(); ++i) {
        size_t begin = i == 0 ? 0 : starts[i].offset;
        size_t end = i + 1 < starts.size() ? starts[i + 1].offset : text.size();
        std::string_view piece = text.substr(begin, end - begin);
        Header h;
        if ((r.error = parse_piece(piece, name, i == 0 ? 1 : starts[i].line, h))) return r;
        auto [it, fresh] = seen.emplace(h.number, starts[i].line);
        if (!fresh) {
            r.error = bad(strf(tr("%s:%d: program %%%d again (first at line %d)"),
                               std::string(name).c_str(), starts[i].line, h.number, it->second));
            return r;
        }
        r.value.push_back(Piece{h.number, std::string(piece), source});
    }
    return r;
}

}  // namespace pupitre::store
