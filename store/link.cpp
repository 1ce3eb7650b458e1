// The store as program memory and machine state of a run (see link.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/link.hpp"

#include <cmath>
#include <cstdio>

#include "core/interp/value_name.hpp"
#include "store/text.hpp"

namespace pupitre::store {

Result<int> load_programs(Store& s, ProgramMemory& mem) {
    Result<int> r;
    std::vector<Diag> problems;
    r.error = s.each_program([&](int number, std::string_view text) {
        if (mem.find(number)) return;
        std::string name = "store:%" + std::to_string(number);
        Header h;
        if (parse_program(text, name, h)) return;  // refused at save: cannot happen
        if (h.number >= 0) {
            if (!mem.load_text(name, std::string(text))) ++r.value;
            return;
        }
        // A fragment stored without a % line: its number is the store's. Its lines
        // keep their numbers in the diagnostics.
        std::string with_header = "%" + std::to_string(number) + "\n";
        with_header += text;
        if (!mem.load_text(name, std::move(with_header))) {
            mem.programs().back()->first_line = 1;
            ++r.value;
        }
    });
    return r;
}

Result<std::map<std::string, int64_t>> seed_machine(Store& s, Interpreter& in,
                                                    std::string_view key) {
    Result<std::map<std::string, int64_t>> r;
    const MachineProfile& m = in.machine();
    auto stored = s.values(key.empty() ? std::string_view(m.name) : key);
    if (stored.error) {
        r.error = stored.error;
        return r;
    }
    for (const auto& [name, v] : stored.value) {
        // A field of the other kind of machine, a corrector or an axis it has
        // not: skipped.
        ValueName n;
        if (!parse_value_name(name, m, n)) continue;
        if (n.kind == ValueName::Kind::corrector) {
            if (!n.field->stored) continue;
            Corrector& c = in.corrector(n.number);
            if (n.field->member)
                c.*n.field->member = double(v) / 1000.0;
            else
                c.c = int(v);
        } else if (n.kind == ValueName::Kind::origin) {
            double value = is_rotary(n.axis) ? double(v) / 1e4 : double(v) / 1000.0;
            if (!in.set(name, value).empty()) continue;
        } else {
            continue;  // no L or E parameter is a row
        }
        r.value[name] = v;
    }
    return r;
}

std::vector<std::pair<std::string, int64_t>> persistent_writes(const Interpreter& in) {
    std::vector<std::pair<std::string, int64_t>> out;
    const MachineProfile& m = in.machine();
    for (const auto& [n, v] : in.e_written()) {
        int k = n % 1000, fam = (n / 1000) % 10;
        if (n >= 50000 && n < 56000 && k >= 1 && k <= 255) {
            // Corrector fields by E family (E50xxx … E55xxx), as write_e maps them.
            out.emplace_back(
                format_value_name(ValueName::corrector(k, corr_field_of_e(fam, m.lathe))), v);
        } else if (n >= 60000 && n < 69000 && (k == 0 || k == 1 || k == 4)) {
            int axis = fam;  // E6x…: x is the axis
            if (!m.has(axis)) continue;
            // E6x000, 001, 004: PREF, DEC1, DEC3.
            out.emplace_back(format_value_name(ValueName::origin(k == 4 ? 2 : k, axis)), v);
        }
    }
    return out;
}

Result<std::vector<Change>> persist_run(Store& s, const Interpreter& in, std::string_view source,
                                        std::string_view profile_text) {
    auto writes = persistent_writes(in);
    if (writes.empty()) return {};
    return s.set_values(in.machine().name, writes, source, profile_text);
}

int64_t internal_value(std::string_view name, double v) {
    const ValueUnit u = value_unit(name);
    if (u == ValueUnit::whole) return int64_t(v);
    return int64_t(std::llround(v * (u == ValueUnit::angle ? 1e4 : 1e3)));
}

std::string format_value(std::string_view name, int64_t v) {
    const ValueUnit u = value_unit(name);
    if (u == ValueUnit::whole) return std::to_string(v);
    char buf[48];
    if (u == ValueUnit::angle)
        std::snprintf(buf, sizeof buf, "%.4f", double(v) / 1e4);
    else
        std::snprintf(buf, sizeof buf, "%.3f", double(v) / 1000.0);
    return buf;
}

}  // namespace pupitre::store
