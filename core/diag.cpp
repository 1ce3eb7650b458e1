// Diagnostics formatting and the NUM error table (data/errors.tsv, embedded).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/diag.hpp"

#include <string>
#include <unordered_map>
#include <utility>

#include "core/i18n.hpp"

namespace pupitre {
namespace data {
std::string_view errors_tsv();
}

Diag diag_of(const Error& e, Severity s) {
    Diag d;
    d.severity = s;
    d.code = e.code;
    d.column = e.column;
    d.detail = e.detail;
    return d;
}

std::string format_diag(const Diag& d) {
    std::string s = d.file.empty() ? std::string("-") : d.file;
    s += ':';
    s += std::to_string(d.line);
    if (d.column > 0 && d.line > 0) {
        s += ':';
        s += std::to_string(d.column);
    }
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
// Columns: number, category, machine_error, message_fr, message_en. The
// English text is the catalogue's msgid (scripts/lib/extract-pot); po/fr.po
// carries message_fr as its translation (tests/i18n/catalogue.sh checks it).
std::unordered_map<int, std::string> load_errors() {
    std::unordered_map<int, std::string> m;
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
        if (num > 0) m.emplace(num, std::string(cols[4]));
    }
    return m;
}
}  // namespace

std::string_view num_error_text(int code) {
    static const auto table = load_errors();
    auto it = table.find(code);
    return it == table.end() ? std::string_view{} : tr(it->second.c_str());
}

// What the ALARM page says of our own numbers; pupitre(1), DIAGNOSTICS, says more.
std::string_view pupitre_diag_text(int code) {
    static const std::pair<int, const char*> kTexts[] = {
        {err::kBlockBudget, N_("Endless loop: the program comes back to a state it was in, or "
                               "exceeds the work budget")},
        {err::kNotText, N_("The file is not text")},
        {err::kNoProgram, N_("The file holds no program")},
        {err::kCannotRead, N_("The file cannot be opened or read")},
        {err::kProgramExists, N_("G76+ H of a program already in memory")},
        {err::kProgramInUse, N_("G76- H of a program that runs")},
        {err::wFeedClamped, N_("Warning: F above the machine maximum, limited to it")},
        {err::wSpeedClamped, N_("Warning: S above the machine maximum, limited to it")},
        {err::wUnknownM, N_("Warning: an M function with no meaning on the NUM, ignored")},
        {err::wSpindleStopped, N_("Warning: G96 while the spindle is not turning")},
        {err::wIncrementalFirst, N_("Warning: the first move is written in G91")},
        {err::wDuplicateProgram,
         N_("Warning: a program number loaded twice; this copy is ignored")},
        {err::wUnsignedEB, N_("Warning: EB without a sign, taken as a fillet")},
        {err::wTinyFeed,
         N_("Warning: a feed below 1 mm/min in G94 (a feed per revolution without G95?)")},
        {err::wFeedBeforeF, N_("Warning: a feed move before any F runs at the power-on feed")},
        {err::wLReadUnset, N_("Warning: an L variable read before anything set it reads 0")},
        {err::wIdleWord,
         N_("Warning: R, I, J or K in a G0/G1 block has no effect (a G2/G3 left out?)")},
        {err::wFractionalRpm, N_("Warning: a spindle speed in rev/min that is not a whole number")},
        {err::wProfileL, N_("Warning: L100-L199 or L900-L959 read in a roughing-cycle profile "
                            "(error 96 on the NUM)")},
        {err::wFeedModeNoF, N_("Warning: G94 or G95 without F in its block")},
        {err::wAllowanceInside,
         N_("Warning: a finishing allowance whose sign puts it inside the part")},
        {err::wNoToolWidth, N_("Warning: G66 correctors that give no tool width")},
        {err::wPlungeAway,
         N_("Warning: a G46 roughing plunges with the cutter away from the drilled hole")},
        // The workshop's crashes (core/workshop/workshop.hpp, kCrash*).
        {1200, N_("Crash: a rapid (G0) into the part")},
        {1201, N_("Crash: a feed into the part with the spindle stopped")},
        {1202, N_("Crash: the tool or its holder hit the work-holding (chuck, tailstock, vice, "
                  "plate, pin, table, tool setter)")},
        {1203, N_("Crash: the holder or a cutter's shank hit the part")},
        {1204, N_("Crash: cutting with the spindle turning the wrong way for the tool")},
        {1205, N_("Crash: a touch probe driven into something")},
    };
    for (const auto& [n, text] : kTexts)
        if (n == code) return tr(text);
    return {};
}

}  // namespace pupitre
