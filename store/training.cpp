// Training in the store (issue 16): the class's exercises and every attempt
// with its grade. One statement per call: SQLite makes each atomic.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "store/sql.hpp"
#include "store/store.hpp"

namespace pupitre::store {

namespace {

constexpr const char* kAttemptColumns =
    "id, exercise, exercise_sha, student, machine, started_ms, submitted_ms, seed, score, "
    "seconds, crashes, scrapped, mistakes, found, report, signature, record";

Attempt read_attempt(const sql::Use& u) {
    Attempt a;
    a.id = u.i64(0);
    a.exercise = u.str(1);
    a.exercise_sha = u.str(2);
    a.student = u.str(3);
    a.machine = u.str(4);
    a.started_ms = u.i64(5);
    a.submitted_ms = u.is_null(6) ? 0 : u.i64(6);
    a.seed = u.str(7);
    a.score = u.is_null(8) ? 0 : u.i32(8);
    a.seconds = u.is_null(9) ? 0 : u.f64(9);
    a.crashes = u.i32(10);
    a.scrapped = u.i32(11) != 0;
    a.mistakes = u.str(12);
    a.found = u.str(13);
    a.report = u.str(14);
    a.signature = u.str(15);
    a.record = u.str(16);
    return a;
}

}  // namespace

StoreError Store::put_exercise(std::string_view name, std::string_view text) {
    return in_write([&]() -> StoreError {
        // The text replaced, kept under its SHA-256 for the attempts made on it.
        std::string old;
        bool had = false;
        {
            sql::Use u = use("SELECT text FROM exercises WHERE name = ?1");
            if (u.error) return u.error;
            int rc = u.bind(1, name).step();
            if (rc == db::kRow)
                old = u.str(0), had = true;
            else if (rc != db::kDone)
                return fail(rc, tr("cannot read the exercises"));
        }
        if (had && old != text) {
            sql::Use u =
                use("INSERT INTO exercise_texts (sha, name, text, added_ms, who) "
                    "VALUES (?1, ?2, ?3, ?4, ?5) ON CONFLICT (sha) DO NOTHING");
            if (u.error) return u.error;
            u.bind(1, sha256_hex(old)).bind(2, name).bind(3, old).bind(4, now_ms()).bind(5, user_);
            if (int rc = u.step(); rc != db::kDone)
                return fail(rc, tr("cannot store the exercise"));
        }
        sql::Use u =
            use("INSERT INTO exercises (name, text, added_ms, who) VALUES (?1, ?2, ?3, ?4) "
                "ON CONFLICT (name) DO UPDATE SET text = ?2, added_ms = ?3, who = ?4");
        if (u.error) return u.error;
        if (int rc = u.bind(1, name).bind(2, text).bind(3, now_ms()).bind(4, user_).step();
            rc != db::kDone)
            return fail(rc, tr("cannot store the exercise"));
        return {};
    });
}

Result<std::optional<std::string>> Store::exercise(std::string_view name) {
    Result<std::optional<std::string>> r;
    StoreError e;
    sql::Use u = use("SELECT text FROM exercises WHERE name = ?1");
    e = u.error;
    if ((r.error = e)) return r;
    int rc = u.bind(1, name).step();
    if (rc == db::kRow)
        r.value = u.str(0);
    else if (rc != db::kDone)
        r.error = fail(rc, tr("cannot read the exercises"));
    return r;
}

Result<std::optional<std::string>> Store::exercise_text(std::string_view name,
                                                        std::string_view sha) {
    auto now = exercise(name);
    if (now.error || (now.value && sha256_hex(*now.value) == sha)) return now;
    Result<std::optional<std::string>> r;
    sql::Use u = use("SELECT text FROM exercise_texts WHERE sha = ?1 AND name = ?2");
    if ((r.error = u.error)) return r;
    int rc = u.bind(1, sha).bind(2, name).step();
    if (rc == db::kRow)
        r.value = u.str(0);
    else if (rc != db::kDone)
        r.error = fail(rc, tr("cannot read the exercises"));
    return r;
}

Result<std::vector<std::string>> Store::exercises() {
    Result<std::vector<std::string>> r;
    StoreError e;
    sql::Use u = use("SELECT name FROM exercises ORDER BY name");
    e = u.error;
    if ((r.error = e)) return r;
    int rc;
    while ((rc = u.step()) == db::kRow) r.value.push_back(u.str(0));
    if (rc != db::kDone) r.error = fail(rc, tr("cannot read the exercises"));
    return r;
}

Result<std::optional<Attempt>> Store::open_attempt(std::string_view exercise,
                                                   std::string_view student) {
    Result<std::optional<Attempt>> r;
    StoreError e;
    static const std::string sql = std::string("SELECT ") + kAttemptColumns +
                                   " FROM attempts WHERE exercise = ?1 AND student = ?2 AND "
                                   "submitted_ms IS NULL ORDER BY id DESC LIMIT 1";
    sql::Use u = use(sql.c_str());
    e = u.error;
    if ((r.error = e)) return r;
    int rc = u.bind(1, exercise).bind(2, student).step();
    if (rc == db::kRow)
        r.value = read_attempt(u);
    else if (rc != db::kDone)
        r.error = fail(rc, tr("cannot read the attempts"));
    return r;
}

StoreError Store::start_attempt(Attempt& a) {
    a.started_ms = now_ms();
    a.machine = machine_row(a.machine);
    return in_write([&]() -> StoreError {
        sql::Use u =
            use("INSERT INTO attempts (exercise, exercise_sha, student, machine, started_ms) "
                "VALUES (?1, ?2, ?3, ?4, ?5) RETURNING id");
        if (u.error) return u.error;
        int rc = u.bind(1, a.exercise)
                     .bind(2, a.exercise_sha)
                     .bind(3, a.student)
                     .bind(4, a.machine)
                     .bind(5, a.started_ms)
                     .step();
        if (rc != db::kRow) return fail(rc, tr("cannot store the attempt"));
        a.id = u.i64(0);
        if ((rc = u.step()) != db::kDone) return fail(rc, tr("cannot store the attempt"));
        return {};
    });
}

StoreError Store::add_crash(int64_t id) {
    // On a class's server a student writes no attempt: the server counts.
    auto on_class = class_server();
    if (on_class.error) return on_class.error;
    return in_write([&]() -> StoreError {
        sql::Use u =
            use(on_class.value ? "SELECT pupitre_add_crash(?1)"
                               : "UPDATE attempts SET crashes = crashes + 1 WHERE id = ?1");
        if (u.error) return u.error;
        int rc = u.bind(1, id).step();
        if (on_class.value && rc == db::kRow) rc = u.step();
        if (rc != db::kDone) return fail(rc, tr("cannot store the attempt"));
        return {};
    });
}

StoreError Store::keep_record(int64_t id, std::string_view record) {
    auto on_class = class_server();
    if (on_class.error) return on_class.error;
    return in_write([&]() -> StoreError {
        sql::Use u = use(on_class.value ? "SELECT pupitre_keep_record(?1, ?2)"
                                        : "UPDATE attempts SET record = ?2 WHERE id = ?1 AND "
                                          "submitted_ms IS NULL");
        if (u.error) return u.error;
        int rc = u.bind(1, id).bind(2, record).step();
        if (on_class.value && rc == db::kRow) rc = u.step();
        if (rc != db::kDone) return fail(rc, tr("cannot store the attempt"));
        return {};
    });
}

StoreError Store::submit_attempt(const Attempt& a) {
    return in_write([&]() -> StoreError {
        sql::Use u =
            use("UPDATE attempts SET submitted_ms = ?2, seed = ?3, score = ?4, seconds = ?5, "
                "crashes = ?6, scrapped = ?7, mistakes = ?8, found = ?9, report = ?10, signature = "
                "?11, record = ?12 WHERE id = ?1 AND submitted_ms IS NULL RETURNING id");
        if (u.error) return u.error;
        u.bind(1, a.id).bind(2, a.submitted_ms).bind(3, a.seed).bind(4, a.score);
        u.bind(5, a.seconds).bind(6, a.crashes).bind(7, a.scrapped ? 1 : 0);
        u.bind(8, a.mistakes).bind(9, a.found).bind(10, a.report).bind(11, a.signature);
        u.bind(12, a.record);
        return one_row(u, tr("the attempt was submitted already"), tr("cannot store the attempt"));
    });
}

Result<std::vector<Attempt>> Store::attempts(std::string_view exercise) {
    Result<std::vector<Attempt>> r;
    StoreError e;
    static const std::string sql =
        std::string("SELECT ") + kAttemptColumns + " FROM attempts WHERE exercise = ?1 ORDER BY id";
    // Every attempt (the class report): many rows, no parameter, so from a
    // server one binary COPY (Backend::prepare_many) rather than a result of
    // 50,000 fields that libpq builds one by one.
    static const std::string all =
        std::string("SELECT ") + kAttemptColumns + " FROM attempts ORDER BY id";
    sql::Use u = exercise.empty() ? use_many(all.c_str()) : use(sql.c_str());
    e = u.error;
    if ((r.error = e)) return r;
    if (!exercise.empty()) u.bind(1, exercise);
    int rc;
    while ((rc = u.step()) == db::kRow) r.value.push_back(read_attempt(u));
    if (rc != db::kDone) r.error = fail(rc, tr("cannot read the attempts"));
    return r;
}

}  // namespace pupitre::store
