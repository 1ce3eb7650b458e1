// Diagnostics formatting and the NUM error table (data/errors.tsv, embedded).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/diag.hpp"

#include <unordered_map>

namespace pupitre {
namespace data {
std::string_view errors_tsv();
}

std::string format_diag(const Diag& d) {
    std::string s = d.file.empty() ? std::string("-") : d.file;
    s += ':';
    s += std::to_string(d.line);
    s += ": ";
    if (d.n >= 0) {
        s += 'N';
        s += std::to_string(d.n);
        s += ": ";
    }
    s += d.is_error() ? "error " : "warning ";
    s += std::to_string(d.code);
    s += ": ";
    s += d.detail;
    return s;
}

namespace {
// Columns: number, category, machine_error, message_fr, message_en.
std::unordered_map<int, std::string_view> load_errors() {
    std::unordered_map<int, std::string_view> m;
    std::string_view all = data::errors_tsv();
    bool header = true;
    while (!all.empty()) {
        size_t eol = all.find('\n');
        std::string_view line = all.substr(0, eol);
        all = eol == std::string_view::npos ? std::string_view{} : all.substr(eol + 1);
        if (header) {
            header = false;
            continue;
        }
        std::string_view cols[5];
        for (int i = 0; i < 5; ++i) {
            size_t tab = line.find('\t');
            cols[i] = line.substr(0, tab);
            line = tab == std::string_view::npos ? std::string_view{} : line.substr(tab + 1);
        }
        int num = 0;
        for (char c : cols[0]) {
            if (c < '0' || c > '9') break;
            num = num * 10 + (c - '0');
        }
        if (num > 0) m.emplace(num, cols[4]);
    }
    return m;
}
}  // namespace

std::string_view num_error_text(int code) {
    static const auto table = load_errors();
    auto it = table.find(code);
    return it == table.end() ? std::string_view{} : it->second;
}

}  // namespace pupitre
