// Seeding a new store with what data/ ships (embedded in the binary): the
// machine profiles and the demo programs.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <set>

#include "core/i18n.hpp"
#include "store/sql.hpp"
#include "store/store.hpp"
#include "store/text.hpp"

namespace pupitre::data {
std::string_view machine_lathe();
std::string_view machine_mill();
std::string_view machine_mill4();
std::string_view machine_mill5();
std::string_view demo_lathe_p300();
std::string_view demo_mill_p300_g19();
}  // namespace pupitre::data

namespace pupitre::store {

namespace {

struct Embedded {
    const char* name;
    std::string_view (*text)();
};

constexpr Embedded kMachines[] = {{"lathe", data::machine_lathe},
                                  {"mill", data::machine_mill},
                                  {"mill4", data::machine_mill4},
                                  {"mill5", data::machine_mill5}};
constexpr Embedded kDemos[] = {{"data/demo/lathe_p300.iso", data::demo_lathe_p300},
                               {"data/demo/mill_p300_g19.iso", data::demo_mill_p300_g19}};

// Gives a program text another number: the digits after '%' on its header line.
std::string renumber(std::string_view text, int number) {
    size_t pos = 0;
    while (pos < text.size()) {
        size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos) eol = text.size();
        if (is_header_line(text.substr(pos, eol - pos))) {
            size_t pc = text.find('%', pos) + 1;
            size_t end = pc;
            while (end < eol && text[end] == ' ') ++end;
            // The digits only: "%300 (TITLE)" keeps the space before its title.
            while (end < eol && text[end] >= '0' && text[end] <= '9') ++end;
            return std::string(text.substr(0, pc)) + std::to_string(number) +
                   std::string(text.substr(end));
        }
        pos = eol + 1;
    }
    return std::string(text);
}

}  // namespace

// Inside the creating transaction. The two demos are both %300 in the handbooks;
// one number holds one program, so the second is stored as the next free number
// (%301) with its % line changed accordingly.
StoreError Store::seed() {
    StoreError e;
    const int64_t now = now_ms();
    for (const Embedded& m : kMachines) {
        sql::Use u =
            use("INSERT INTO machines (name, profile, builtin, updated_ms) VALUES (?1, ?2, 1, ?3)");
        e = u.error;
        if (e) return e;
        if (int rc = u.bind(1, m.name).bind(2, m.text()).bind(3, now).step(); rc != db::kDone)
            return fail(rc, tr("cannot seed the machine profiles"));
    }
    std::set<int> used;
    for (const Embedded& d : kDemos) {
        Header h;
        if ((e = parse_program(d.text(), d.name, h))) return e;
        int number = h.number;
        std::string text(d.text());
        if (used.count(number)) {
            while (used.count(number)) ++number;
            text = renumber(text, number);
        }
        used.insert(number);
        Result<SaveResult> r =
            save_one(Piece{number, std::move(text), std::string("seed ") + d.name}, kNew,
                     RevisionKind::seed);
        if (r.error) return r.error;
    }
    return {};
}

}  // namespace pupitre::store
