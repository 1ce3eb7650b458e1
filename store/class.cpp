// The class on a PostgreSQL server (store.hpp, "The class"): its roles,
// grants and policies set up once (class_pg.hpp), its students' logins, and
// an attempt opened, crashed and submitted through the server's functions.
// The server decides who may do what; this file asks it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cctype>

#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "store/class_pg.hpp"
#include "store/sql.hpp"
#include "store/store.hpp"

namespace pupitre::store {

namespace {

constexpr const char* kAttemptColumns =
    "id, exercise, exercise_sha, student, machine, started_ms, submitted_ms, seed, score, "
    "seconds, crashes, scrapped, mistakes, found, report, signature, record";

std::string replace_all(std::string s, std::string_view what, std::string_view with) {
    for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size()))
        s.replace(at, what.size(), with);
    return s;
}

StoreError not_a_server(const std::string& path) {
    return {Fault::bad_data,
            strf(tr("%s: a class lives on a PostgreSQL server (--db postgresql://…), "
                    "not in a file"),
                 path.c_str())};
}

}  // namespace

bool login_name_ok(std::string_view name) {
    if (name.empty() || name.size() > 63 || !(std::islower((unsigned char)name[0]))) return false;
    for (char c : name)
        if (!std::islower((unsigned char)c) && !std::isdigit((unsigned char)c) && c != '_' &&
            c != '.' && c != '-')
            return false;
    return !name.starts_with("pg_") && !name.starts_with("pupitre_");
}

Result<bool> Store::class_server() {
    Result<bool> r;
    r.value = false;
    if (engine() != "postgresql") return r;
    if (class_state_ >= 0) {
        r.value = class_state_ == 1;
        return r;
    }
    sql::Use u =
        use("SELECT (to_regprocedure('pupitre_open_attempt(text,text)') IS NOT NULL)::int");
    if ((r.error = u.error)) return r;
    if (int rc = u.step(); rc != db::kRow) {
        r.error = fail(rc, tr("cannot read the store"));
        return r;
    }
    r.value = u.i64(0) != 0;
    class_state_ = r.value ? 1 : 0;
    return r;
}

StoreError Store::class_init(std::string_view group, const std::vector<NamedText>& exercises) {
    if (engine() != "postgresql") return not_a_server(path_);
    if (!login_name_ok(group))
        return {Fault::bad_data, strf(tr("%s: not a class name (lowercase letters, digits, _ . -; "
                                         "beginning with a letter)"),
                                      std::string(group).c_str())};
    auto had = class_server();
    if (had.error) return had.error;
    StoreError done = in_write([&]() -> StoreError {
        std::string schema;
        {
            sql::Use u = use("SELECT quote_ident(current_schema())");
            if (u.error) return u.error;
            if (int rc = u.step(); rc != db::kRow) return fail(rc, tr("cannot set up the class"));
            schema = u.str(0);
        }
        if (StoreError e = exec(class_pg::kRoles)) return e;
        if (!had.value)
            if (StoreError e = exec(replace_all(class_pg::kGrants, "@SCHEMA@", schema).c_str()))
                return e;
        const std::string make = strf(
            "DO $$ BEGIN CREATE ROLE \"%s\" NOLOGIN IN ROLE pupitre_students; "
            "EXCEPTION WHEN duplicate_object OR unique_violation THEN NULL; END $$",
            std::string(group).c_str());
        if (StoreError e = exec(make.c_str())) return e;
        for (const NamedText& p : exercises) {
            sql::Use u =
                use("INSERT INTO exercises (name, text, added_ms, who) VALUES (?1, ?2, ?3, ?4) "
                    "ON CONFLICT (name) DO NOTHING");
            if (u.error) return u.error;
            u.bind(1, p.name).bind(2, p.text).bind(3, now_ms()).bind(4, user_);
            if (int rc = u.step(); rc != db::kDone)
                return fail(rc, tr("cannot store the exercise"));
        }
        return {};
    });
    if (!done) class_state_ = 1;
    return done;
}

Result<std::vector<Login>> Store::add_students(std::string_view group,
                                               const std::vector<std::string>& names) {
    Result<std::vector<Login>> r;
    if (engine() != "postgresql") {
        r.error = not_a_server(path_);
        return r;
    }
    for (const std::string& n : names)
        if (!login_name_ok(n)) {
            r.error = {Fault::bad_data,
                       strf(tr("%s: not a login name (lowercase letters, digits, _ . -; beginning "
                               "with a letter)"),
                            n.c_str())};
            return r;
        }
    r.error = in_write([&]() -> StoreError {
        r.value.clear();
        sql::Use g = use(
            "SELECT 1 FROM pg_auth_members m JOIN pg_roles c ON c.oid = m.roleid JOIN pg_roles g "
            "ON g.oid = m.member WHERE c.rolname = 'pupitre_students' AND g.rolname = ?1");
        if (g.error) return g.error;
        if (int rc = g.bind(1, group).step(); rc == db::kDone)
            return {Fault::not_found, strf(tr("no class %s here: pupitre class init --class %s"),
                                           std::string(group).c_str(), std::string(group).c_str())};
        else if (rc != db::kRow)
            return fail(rc, tr("cannot read the class"));
        for (const std::string& n : names) {
            const std::string password = random_hex(9);
            if (password.empty()) return {Fault::io, tr("the system gave no random bytes")};
            const std::string sql = strf("CREATE ROLE \"%s\" LOGIN PASSWORD '%s' IN ROLE \"%s\"",
                                         n.c_str(), password.c_str(), std::string(group).c_str());
            if (StoreError e = exec(sql.c_str())) return e;
            r.value.push_back({n, std::string(group), password});
        }
        return {};
    });
    if (r.error) r.value.clear();
    return r;
}

Result<std::vector<Login>> Store::students(std::string_view group) {
    Result<std::vector<Login>> r;
    if (engine() != "postgresql") {
        r.error = not_a_server(path_);
        return r;
    }
    sql::Use u = use(
        "SELECT s.rolname, g.rolname FROM pg_auth_members c JOIN pg_roles p ON p.oid = c.roleid "
        "JOIN pg_roles g ON g.oid = c.member JOIN pg_auth_members m ON m.roleid = g.oid "
        "JOIN pg_roles s ON s.oid = m.member WHERE p.rolname = 'pupitre_students' "
        "AND (?1 = '' OR g.rolname = ?1) ORDER BY g.rolname, s.rolname");
    if ((r.error = u.error)) return r;
    u.bind(1, group);
    int rc;
    while ((rc = u.step()) == db::kRow) r.value.push_back({u.str(0), u.str(1), ""});
    if (rc != db::kDone) r.error = fail(rc, tr("cannot read the class"));
    return r;
}

Result<std::vector<StudentStatus>> Store::class_status(std::string_view group) {
    Result<std::vector<StudentStatus>> r;
    if (engine() != "postgresql") {
        r.error = not_a_server(path_);
        return r;
    }
    sql::Use u =
        use("WITH s AS (SELECT st.rolname AS login, g.rolname AS grp FROM pg_auth_members c "
            "  JOIN pg_roles p ON p.oid = c.roleid JOIN pg_roles g ON g.oid = c.member "
            "  JOIN pg_auth_members m ON m.roleid = g.oid JOIN pg_roles st ON st.oid = m.member "
            "  WHERE p.rolname = 'pupitre_students' AND (?1 = '' OR g.rolname = ?1)), "
            "a AS (SELECT DISTINCT ON (student) * FROM attempts ORDER BY student, id DESC), "
            "n AS (SELECT student, count(*) FILTER (WHERE submitted_ms IS NOT NULL) AS done, "
            "  sum(crashes)::bigint AS crashes, sum(scrapped)::bigint AS scrapped FROM attempts "
            "  GROUP BY student), "
            "l AS (SELECT DISTINCT ON (split_part(machine, '/', 1)) split_part(machine, '/', 1) AS "
            "  login, at_ms, name, new FROM audit WHERE machine LIKE '%/%' "
            "  ORDER BY split_part(machine, '/', 1), id DESC), "
            "c AS (SELECT DISTINCT usename FROM pg_stat_activity WHERE usename IS NOT NULL) "
            "SELECT s.login, s.grp, coalesce(a.id, 0), coalesce(a.exercise, ''), "
            "  coalesce(a.started_ms, 0), coalesce(a.submitted_ms, 0), "
            "  (coalesce(a.signature, '') <> '')::int, coalesce(a.score, -1), coalesce(n.done, 0), "
            "  coalesce(n.crashes, 0), coalesce(n.scrapped, 0), coalesce(l.at_ms, 0), "
            "  coalesce(l.name, ''), l.new, (c.usename IS NOT NULL)::int, "
            "  (extract(epoch FROM clock_timestamp()) * 1000)::bigint "
            "FROM s LEFT JOIN a ON a.student = s.login LEFT JOIN n ON n.student = s.login "
            "LEFT JOIN l ON l.login = s.login LEFT JOIN c ON c.usename = s.login "
            "ORDER BY s.grp, s.login");
    if ((r.error = u.error)) return r;
    u.bind(1, group);
    int rc;
    while ((rc = u.step()) == db::kRow) {
        StudentStatus t;
        t.login = u.str(0), t.group = u.str(1);
        t.attempt = u.i64(2), t.exercise = u.str(3);
        t.started_ms = u.i64(4), t.submitted_ms = u.i64(5);
        t.graded = u.i64(6) != 0, t.score = u.i32(7);
        t.attempts = u.i32(8), t.crashes = u.i32(9), t.scrapped = u.i32(10);
        t.last_ms = u.i64(11), t.last_name = u.str(12);
        if (!u.is_null(13)) t.last_value = u.i64(13);
        t.connected = u.i64(14) != 0;
        t.now_ms = u.i64(15);
        r.value.push_back(std::move(t));
    }
    if (rc != db::kDone) {
        r.value.clear();
        r.error = fail(rc, tr("cannot read the class"));
    }
    return r;
}

Result<std::string> Store::class_signing_key() {
    Result<std::string> r;
    sql::Use u = use("SELECT key FROM pupitre_class_key WHERE id = 1");
    if ((r.error = u.error)) return r;
    if (int rc = u.step(); rc == db::kRow)
        r.value = u.str(0);
    else
        r.error = fail(rc, tr("cannot read the class's key (a teacher's login reads it)"));
    return r;
}

Result<Attempt> Store::open_class_attempt(std::string_view exercise, std::string_view machine) {
    Result<Attempt> r;
    r.error = in_write([&]() -> StoreError {
        static const std::string sql =
            std::string("SELECT ") + kAttemptColumns + " FROM pupitre_open_attempt(?1, ?2)";
        sql::Use u = use(sql.c_str());
        if (u.error) return u.error;
        int rc = u.bind(1, exercise).bind(2, machine_row(machine)).step();
        if (rc != db::kRow) return fail(rc, tr("cannot open the attempt"));
        Attempt& a = r.value;
        a.id = u.i64(0);
        a.exercise = u.str(1);
        a.exercise_sha = u.str(2);
        a.student = u.str(3);
        a.machine = u.str(4);
        a.started_ms = u.i64(5);
        a.seed = u.str(7);
        a.crashes = u.i32(10);
        a.record = u.str(16);  // an attempt taken up again: its record so far
        if ((rc = u.step()) != db::kDone) return fail(rc, tr("cannot open the attempt"));
        return {};
    });
    return r;
}

StoreError Store::submit_class_attempt(const Attempt& a) {
    return in_write([&]() -> StoreError {
        sql::Use u = use("SELECT pupitre_submit(?1, ?2, ?3, ?4, ?5, ?6, ?7)");
        if (u.error) return u.error;
        u.bind(1, a.id).bind(2, a.score).bind(3, a.scrapped ? 1 : 0).bind(4, a.mistakes);
        u.bind(5, a.found).bind(6, a.report).bind(7, a.record);
        return one_row(u, tr("the attempt was submitted already"), tr("cannot store the attempt"));
    });
}

StoreError Store::grade_attempt(const Attempt& a) {
    return in_write([&]() -> StoreError {
        sql::Use u =
            use("UPDATE attempts SET score = ?2, scrapped = ?3, mistakes = ?4, found = ?5, report "
                "= ?6, signature = ?7, crashes = ?8 WHERE id = ?1 AND submitted_ms IS NOT NULL "
                "AND signature = '' RETURNING id");
        if (u.error) return u.error;
        u.bind(1, a.id).bind(2, a.score).bind(3, a.scrapped ? 1 : 0).bind(4, a.mistakes);
        u.bind(5, a.found).bind(6, a.report).bind(7, a.signature).bind(8, a.crashes);
        return one_row(u, tr("the attempt was graded already"), tr("cannot store the grade"));
    });
}

}  // namespace pupitre::store
