// Machine values in the store: profiles, tool correctors and origins with an
// audit row per change, settings, and the IMD history.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>

#include "core/i18n.hpp"
#include "core/interp/value_name.hpp"
#include "store/sql.hpp"
#include "store/store.hpp"

namespace pupitre::store {

// "D12.DX" -> corrector 12, field DX; "PREF.Z" -> origin PREF, axis Z: the
// columns of a row of correctors or origins.
struct StoredName {
    bool corrector = false;
    int d = 0;
    std::string field;  // corrector field, or origin kind
    std::string axis;
};

namespace {

bool parse_name(std::string_view s, StoredName& n) {
    ValueName v;
    if (!parse_value_name(s, v)) return false;
    n.corrector = v.kind == ValueName::Kind::corrector;
    if (n.corrector) {
        n.d = v.number;
        n.field = std::string(v.field->text);
    } else if (v.kind == ValueName::Kind::origin) {
        n.field = std::string(kOriginNames[v.number]);
        n.axis = std::string(1, kAxisNames[size_t(v.axis)]);
    } else {
        return false;  // L and E parameters are no rows
    }
    return true;
}

// A row's columns -> its name: corrector d's field (d > 0), or the origin
// `field` names on an axis. False for none (the schema's CHECKs keep them out).
bool row_name(int64_t d, std::string_view field, std::string_view axis, ValueName& n) {
    if (d > 0) {
        const CorrField* f = any_corr_field(field);
        if (f) n = ValueName::corrector(int(d), f);
        return f;
    }
    for (int k = 0; k < 3; ++k)
        if (field == kOriginNames[k] && axis.size() == 1 && axis_of(axis[0]) >= 0) {
            n = ValueName::origin(k, axis_of(axis[0]));
            return true;
        }
    return false;
}

// LIMIT for "all": both engines read a limit this large as none (PostgreSQL
// refuses SQLite's -1).
constexpr int64_t kNoLimit = INT64_MAX;

constexpr const char* kMachineExists = "SELECT 1 FROM machines WHERE name = ?1";
constexpr const char* kInsertMachine =
    "INSERT INTO machines (name, profile, builtin, updated_ms) VALUES (?1, ?2, ?3, ?4)";

}  // namespace

StoreError Store::put_machine(std::string_view name, std::string_view profile) {
    const std::string row = machine_row(name);
    return in_write([&]() -> StoreError {
        StoreError e;
        {
            sql::Use u = use(
                "INSERT INTO machines (name, profile, builtin, updated_ms) VALUES (?1, ?2, 0, ?3) "
                "ON CONFLICT (name) DO UPDATE SET profile = ?2, updated_ms = ?3");
            e = u.error;
            if (!e) {
                u.bind(1, row).bind(2, profile).bind(3, now_ms());
                if (int rc = u.step(); rc != db::kDone)
                    e = fail(rc, tr("cannot store the machine profile"));
            }
        }
        return e;
    });
}

Result<std::vector<std::string>> Store::machines() {
    Result<std::vector<std::string>> r;
    StoreError e;
    sql::Use u = use("SELECT name FROM machines ORDER BY name");
    e = u.error;
    if ((r.error = e)) return r;
    int rc;
    while ((rc = u.step()) == db::kRow) r.value.push_back(machine_shown(u.str(0)));
    if (rc != db::kDone) r.error = fail(rc, tr("cannot list the machines"));
    return r;
}

Result<std::string> Store::machine_profile(std::string_view name) {
    Result<std::string> r;
    StoreError e;
    sql::Use u = use("SELECT profile FROM machines WHERE name = ?1");
    e = u.error;
    if ((r.error = e)) return r;
    int rc = u.bind(1, machine_row(name)).step();
    if (rc == db::kRow)
        r.value = u.str(0);
    else if (rc == db::kDone)
        r.error = {Fault::not_found,
                   strf(tr("%s: no machine %s"), path_.c_str(), std::string(name).c_str())};
    else
        r.error = fail(rc, tr("cannot read the machine profile"));
    return r;
}

Result<std::map<std::string, int64_t>> Store::values(std::string_view machine) {
    Result<std::map<std::string, int64_t>> r;
    StoreError e;
    // The columns, spelt into names by the vocabulary (not by the SQL).
    sql::Use u =
        use("SELECT d, field, '', value FROM correctors WHERE machine = ?1 "
            "UNION ALL SELECT 0, kind, axis, value FROM origins WHERE machine = ?1");
    e = u.error;
    if ((r.error = e)) return r;
    u.bind(1, machine_row(machine));
    int rc;
    while ((rc = u.step()) == db::kRow)
        if (ValueName n; row_name(u.i64(0), u.str(1), u.str(2), n))
            r.value[format_value_name(n)] = u.i64(3);
    if (rc != db::kDone) {
        r.value.clear();
        r.error = fail(rc, tr("cannot read the correctors and origins"));
    }
    return r;
}

Result<std::vector<Change>> Store::set_values(std::string_view machine,
                                              const std::vector<std::pair<std::string, int64_t>>& v,
                                              std::string_view source, std::string_view profile) {
    Result<std::vector<Change>> r;
    std::vector<StoredName> names(v.size());
    for (size_t i = 0; i < v.size(); ++i)
        if (!parse_name(v[i].first, names[i])) {
            r.error = {Fault::bad_data,
                       strf(tr("unknown corrector or origin '%s' (%s)"), v[i].first.c_str(),
                            "D1.X … D255.DR, PREF.X, DEC1.Z, DEC3.B…")};
            return r;
        }
    const std::string what =
        strf(tr("cannot store the correctors and origins of %s"), std::string(machine).c_str());
    const std::string row = machine_row(machine);
    return in_write([&] { return write_values(row, v, names, source, profile, what); });
}

// Inside set_values' transaction.
Result<std::vector<Change>> Store::write_values(
    std::string_view machine, const std::vector<std::pair<std::string, int64_t>>& v,
    const std::vector<StoredName>& names, std::string_view source, std::string_view profile,
    const std::string& what) {
    Result<std::vector<Change>> r;
    auto abort = [&](StoreError e) {
        r.value.clear();
        r.error = std::move(e);
        return r;
    };
    StoreError e;
    bool known = false;
    {
        sql::Use u = use(kMachineExists);
        e = u.error;
        if (e) return abort(e);
        int rc = u.bind(1, machine).step();
        if (rc == db::kRow)
            known = true;
        else if (rc != db::kDone)
            return abort(fail(rc, what));
    }
    const int64_t now = now_ms();
    if (!known) {
        sql::Use u = use(kInsertMachine);
        e = u.error;
        if (e) return abort(e);
        u.bind(1, machine).bind(2, profile).bind(3, 0).bind(4, now);
        if (int rc = u.step(); rc != db::kDone) return abort(fail(rc, what));
    }
    for (size_t i = 0; i < v.size(); ++i) {
        const StoredName& n = names[i];
        Change c{v[i].first, std::nullopt, v[i].second};
        {
            sql::Use u = use(
                n.corrector
                    ? "SELECT value FROM correctors WHERE machine = ?1 AND d = ?2 AND field = ?3"
                    : "SELECT value FROM origins WHERE machine = ?1 AND kind = ?3 AND axis = ?4");
            e = u.error;
            if (e) return abort(e);
            u.bind(1, machine).bind(3, n.field);
            if (n.corrector)
                u.bind(2, n.d);
            else
                u.bind(4, n.axis);
            int rc = u.step();
            if (rc == db::kRow)
                c.old_value = u.i64(0);
            else if (rc != db::kDone)
                return abort(fail(rc, what));
        }
        if (c.old_value && *c.old_value == c.new_value) continue;
        {
            sql::Use u = use(
                n.corrector
                    ? "INSERT INTO correctors (machine, d, field, value) VALUES (?1, ?2, ?3, ?5) "
                      "ON CONFLICT (machine, d, field) DO UPDATE SET value = ?5"
                    : "INSERT INTO origins (machine, kind, axis, value) VALUES (?1, ?3, ?4, ?5) "
                      "ON CONFLICT (machine, kind, axis) DO UPDATE SET value = ?5");
            e = u.error;
            if (e) return abort(e);
            u.bind(1, machine).bind(3, n.field).bind(5, c.new_value);
            if (n.corrector)
                u.bind(2, n.d);
            else
                u.bind(4, n.axis);
            if (int rc = u.step(); rc != db::kDone) return abort(fail(rc, what));
        }
        {
            sql::Use u =
                use("INSERT INTO audit (at_ms, who, machine, name, old, new, source) "
                    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
            e = u.error;
            if (e) return abort(e);
            u.bind(1, now).bind(2, user_).bind(3, machine).bind(4, c.name);
            if (c.old_value)
                u.bind(5, *c.old_value);
            else
                u.null(5);
            u.bind(6, c.new_value).bind(7, source);
            if (int rc = u.step(); rc != db::kDone) return abort(fail(rc, what));
        }
        r.value.push_back(std::move(c));
    }
    return r;
}

Result<std::vector<AuditRow>> Store::audit(std::string_view machine, int limit) {
    Result<std::vector<AuditRow>> r;
    StoreError e;
    sql::Use u =
        use("SELECT id, at_ms, who, machine, name, old, new, source FROM audit "
            "WHERE ?1 = '' OR machine = ?1 ORDER BY id DESC LIMIT ?2");
    e = u.error;
    if ((r.error = e)) return r;
    u.bind(1, machine.empty() ? std::string() : machine_row(machine))
        .bind(2, limit > 0 ? int64_t(limit) : kNoLimit);
    int rc;
    while ((rc = u.step()) == db::kRow) {
        AuditRow a;
        a.id = u.i64(0);
        a.at_ms = u.i64(1);
        a.who = u.str(2);
        a.machine = machine_shown(u.str(3));
        a.name = u.str(4);
        if (!u.is_null(5)) a.old_value = u.i64(5);
        if (!u.is_null(6)) a.new_value = u.i64(6);
        a.source = u.str(7);
        r.value.push_back(std::move(a));
    }
    if (rc != db::kDone) {
        r.value.clear();
        r.error = fail(rc, tr("cannot read the audit"));
    }
    std::reverse(r.value.begin(), r.value.end());
    return r;
}

Result<std::optional<std::string>> Store::setting(std::string_view key) {
    Result<std::optional<std::string>> r;
    StoreError e;
    sql::Use u = use("SELECT value FROM settings WHERE key = ?1");
    e = u.error;
    if ((r.error = e)) return r;
    int rc = u.bind(1, key).step();
    if (rc == db::kRow)
        r.value = u.str(0);
    else if (rc != db::kDone)
        r.error = fail(rc, tr("cannot read the settings"));
    return r;
}

Result<std::optional<Store::Workshop>> Store::workshop(std::string_view machine) {
    Result<std::optional<Workshop>> r;
    StoreError e;
    sql::Use u = use("SELECT setup, part FROM workshops WHERE machine = ?1");
    e = u.error;
    if ((r.error = e)) return r;
    int rc = u.bind(1, machine_row(machine)).step();
    if (rc == db::kRow)
        r.value = Workshop{u.str(0), u.str(1)};
    else if (rc != db::kDone)
        r.error = fail(rc, tr("cannot read the workshop"));
    return r;
}

StoreError Store::put_workshop(std::string_view name, std::string_view setup,
                               std::string_view part) {
    const std::string row = machine_row(name);
    const std::string_view machine = row;
    return in_write([&]() -> StoreError {
        StoreError e;
        {
            if (!setup.empty()) {
                sql::Use m = use(kMachineExists);
                e = m.error;
                if (!e && m.bind(1, machine).step() == db::kDone) {
                    sql::Use add = use(kInsertMachine);
                    e = add.error;
                    if (!e) {
                        add.bind(1, machine).bind(2, "").bind(3, 0).bind(4, now_ms());
                        if (int rc = add.step(); rc != db::kDone)
                            e = fail(rc, tr("cannot store the workshop"));
                    }
                }
            }
            const char* sql = setup.empty()
                                  ? "DELETE FROM workshops WHERE machine = ?1"
                                  : "INSERT INTO workshops (machine, setup, part, updated_ms, who) "
                                    "VALUES (?1, ?2, ?3, ?4, ?5) ON CONFLICT (machine) DO UPDATE "
                                    "SET setup = ?2, part = ?3, updated_ms = ?4, who = ?5";
            if (e) return e;
            sql::Use u = use(sql);
            e = u.error;
            if (!e) {
                u.bind(1, machine);
                if (!setup.empty()) u.bind(2, setup).bind(3, part).bind(4, now_ms()).bind(5, user_);
                if (int rc = u.step(); rc != db::kDone)
                    e = fail(rc, tr("cannot store the workshop"));
            }
        }
        return e;
    });
}

Result<int64_t> Store::data_version() {
    Result<int64_t> r;
    if (int rc = db_->data_version(r.value)) r.error = fail(rc, tr("cannot read the data version"));
    return r;
}

StoreError Store::set_setting(std::string_view key, std::string_view value) {
    return in_write([&]() -> StoreError {
        StoreError e;
        {
            sql::Use u =
                use("INSERT INTO settings (key, value) VALUES (?1, ?2) "
                    "ON CONFLICT (key) DO UPDATE SET value = ?2");
            e = u.error;
            if (!e) {
                if (int rc = u.bind(1, key).bind(2, value).step(); rc != db::kDone)
                    e = fail(rc, tr("cannot store the setting"));
            }
        }
        return e;
    });
}

StoreError Store::add_imd(std::string_view name, std::string_view block) {
    const std::string row = machine_row(name);
    const std::string_view machine = row;
    return in_write([&]() -> StoreError {
        StoreError e;
        const int64_t now = now_ms();
        {
            sql::Use u = use(kMachineExists);
            e = u.error;
            if (!e) {
                int rc = u.bind(1, machine).step();
                if (rc == db::kDone) {
                    sql::Use m = use(kInsertMachine);
                    e = m.error;
                    if (!e) {
                        m.bind(1, machine).bind(2, "").bind(3, 0).bind(4, now);
                        if (int rc2 = m.step(); rc2 != db::kDone)
                            e = fail(rc2, tr("cannot store the IMD block"));
                    }
                } else if (rc != db::kRow) {
                    e = fail(rc, tr("cannot store the IMD block"));
                }
            }
        }
        if (!e) {
            sql::Use u =
                use("INSERT INTO imd_history (at_ms, who, machine, block) VALUES (?1, ?2, ?3, ?4)");
            e = u.error;
            if (!e) {
                if (int rc = u.bind(1, now).bind(2, user_).bind(3, machine).bind(4, block).step();
                    rc != db::kDone)
                    e = fail(rc, tr("cannot store the IMD block"));
            }
        }
        return e;
    });
}

Result<std::vector<ImdEntry>> Store::imd_history(std::string_view name, int limit) {
    const std::string row = machine_row(name);
    const std::string_view machine = row;
    Result<std::vector<ImdEntry>> r;
    StoreError e;
    sql::Use u =
        use("SELECT id, at_ms, who, machine, block FROM imd_history WHERE machine = ?1 "
            "ORDER BY id DESC LIMIT ?2");
    e = u.error;
    if ((r.error = e)) return r;
    u.bind(1, machine).bind(2, limit > 0 ? int64_t(limit) : kNoLimit);
    int rc;
    while ((rc = u.step()) == db::kRow)
        r.value.push_back(
            ImdEntry{u.i64(0), u.i64(1), u.str(2), machine_shown(u.str(3)), u.str(4)});
    if (rc != db::kDone) {
        r.value.clear();
        r.error = fail(rc, tr("cannot read the IMD history"));
    }
    std::reverse(r.value.begin(), r.value.end());
    return r;
}

}  // namespace pupitre::store
