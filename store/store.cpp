// Opening a store on either backend, checking that it is a pupitre store of a
// schema we know before touching it, migrations, and the transactions every
// operation runs in. The engines' own parts: store/sqlite.cpp, store/postgres.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/store.hpp"

#include <pwd.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdlib>

#include "core/i18n.hpp"
#include "store/sql.hpp"

namespace pupitre::store {

int exit_code(Fault f) {
    switch (f) {
        case Fault::none:
            return 0;
        case Fault::cannot_create:
            return 73;
        case Fault::io:
            return 74;
        case Fault::bad_data:
            return 65;
        case Fault::not_found:
            return 66;
    }
    return 70;
}

std::string os_user() {
    if (const char* u = std::getenv("USER"); u && *u) return u;
    if (struct passwd* pw = getpwuid(getuid()); pw && pw->pw_name) return pw->pw_name;
    return "uid " + std::to_string(getuid());
}

std::string Store::machine_row(std::string_view name) const {
    if (class_state_ != 1 || name.find('/') != std::string_view::npos) return std::string(name);
    return user_ + "/" + std::string(name);
}

std::string Store::machine_shown(std::string_view row) const {
    if (class_state_ != 1 || !row.starts_with(user_ + "/")) return std::string(row);
    return std::string(row.substr(user_.size() + 1));
}

std::string default_path() {
    if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x == '/')
        return std::string(x) + "/pupitre/pupitre.db";
    std::string home;
    if (const char* h = std::getenv("HOME"); h && *h)
        home = h;
    else if (struct passwd* pw = getpwuid(getuid()); pw && pw->pw_dir)
        home = pw->pw_dir;
    if (home.empty()) return {};
    return home + "/.local/share/pupitre/pupitre.db";
}

namespace db {

bool is_server(std::string_view target) {
    if (target.rfind("postgresql://", 0) == 0 || target.rfind("postgres://", 0) == 0) return true;
    // A conninfo string: "host=… dbname=…". A file path has no '=' before its
    // first '/' in any store name pupitre makes; a name such as "a=b.db" is
    // written ./a=b.db.
    size_t eq = target.find('=');
    return eq != std::string_view::npos && eq > 0 && target.find('/') > eq;
}

}  // namespace db

Store::Store() = default;
Store::~Store() = default;

std::string_view Store::engine() const {
    return db_->engine();
}

Result<std::unique_ptr<Store>> Store::open(const std::string& target, const Options& o) {
    auto r = db::is_server(target) ? open_postgres(target, o) : open_sqlite(target, o);
    if (r.value) r.value->target_ = target;
    // Whether a class is set up there decides where machines are kept
    // (machine_row); a server that cannot say now is asked again later.
    if (r.value && r.value->engine() == "postgresql") r.value->class_server();
    return r;
}

std::string Store::local_path() const {
    if (engine() == "sqlite") return path_;
    std::string base = default_path();
    if (base.empty()) return {};
    std::string name;
    for (char c : path_.substr(path_.find("//") + 2))
        name += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
    return base.substr(0, base.rfind('/')) + "/servers/" + name;
}

StoreError Store::fail(int rc, std::string_view what) {
    // TRANSLATORS: the beginning of a store error: the store's file, what
    // could not be done ("cannot read the store"), then why follows.
    std::string head = strf(tr("%s: %s: "), path_.c_str(), std::string(what).c_str());
    StoreError e = db_->explain(rc, head);
    e.retry = db_->retryable(rc);
    return e;
}

StoreError Store::one_row(sql::Use& u, const char* gone, const char* what) {
    int rc = u.step();
    if (rc == db::kDone || (rc == db::kRow && u.is_null(0))) return {Fault::not_found, gone};
    if (rc != db::kRow) return fail(rc, what);
    if ((rc = u.step()) != db::kDone) return fail(rc, what);
    return {};
}

StoreError Store::exec(const char* sql) {
    int rc = db_->exec(sql);
    return rc == db::kOk ? StoreError{} : fail(rc, "SQL");
}

sql::Use Store::use(const char* sql) {
    int rc = db::kOk;
    db::Stmt* s = db_->prepare(sql, rc);
    if (!s) return sql::Use(nullptr, fail(rc, tr("cannot read the store")));
    return sql::Use(s, {});
}

sql::Use Store::use_many(const char* sql) {
    int rc = db::kOk;
    db::Stmt* s = db_->prepare_many(sql, rc);
    if (!s) return sql::Use(nullptr, fail(rc, tr("cannot read the store")));
    return sql::Use(s, {});
}

StoreError Store::begin_write() {
    int rc = db_->begin_write();
    return rc == db::kOk ? StoreError{} : fail(rc, tr("cannot start a change"));
}

StoreError Store::begin_read() {
    int rc = db_->begin_read();
    return rc == db::kOk ? StoreError{} : fail(rc, tr("cannot read the store"));
}

StoreError Store::commit() {
    int rc = db_->commit();
    if (rc == db::kOk) return {};
    StoreError e = fail(rc, tr("cannot save the change"));
    rollback();
    return e;
}

void Store::rollback() {
    db_->rollback();
}

int64_t Store::now_ms() const {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

// Refuses what is not ours or newer than us before any write; creates the schema
// of an empty store; applies the migrations a store written by an older
// pupitre needs, all in one transaction. The check is repeated inside that
// transaction: another process may have done the work meanwhile.
StoreError Store::validate_and_migrate(bool& fresh, const db::Meta* known) {
    fresh = false;
    for (int attempt = 0; attempt < 2; ++attempt) {
        db::Meta m;
        if (attempt == 0 && known) {
            m = *known;
        } else if (int rc = db_->read_meta(m)) {
            if (attempt) rollback();
            return fail(rc, tr("cannot read the store"));
        }
        if (m.foreign) {
            if (attempt) rollback();
            return {Fault::bad_data, strf(tr("%s: not a pupitre store (%s); left untouched"),
                                          path_.c_str(), m.foreign_why.c_str())};
        }
        const int current = db_->schema_version();
        if (m.version > current) {
            if (attempt) rollback();
            return {Fault::bad_data,
                    strf(tr("%s: written by a newer pupitre (schema %lld, this pupitre knows "
                            "up to %d); left untouched: use a newer pupitre"),
                         path_.c_str(), static_cast<long long>(m.version), current)};
        }
        if (m.version == current || (!m.may_change && db_->work_at(m.version))) {
            if (attempt) rollback();
            return {};
        }
        if (attempt == 0) {
            if (int rc = db_->begin_migration()) return fail(rc, tr("cannot start a change"));
            continue;  // check again under the lock
        }
        // Under the lock and still behind: migrate (or create) now.
        for (int v = int(m.version); v < current; ++v) {
            if (StoreError e = exec(db_->migration(v))) {
                rollback();
                return e;
            }
        }
        if (int rc = db_->write_meta(current)) {
            StoreError e = fail(rc, tr("cannot save the change"));
            rollback();
            return e;
        }
        if (m.blank && opt_.seed) {
            if (StoreError e = seed()) {
                rollback();
                return e;
            }
        }
        if (StoreError e = commit()) return e;
        fresh = m.blank;
        return {};
    }
    return {};
}

Result<std::string> Store::integrity_check() {
    Result<std::string> r;
    if (int rc = db_->integrity(r.value)) r.error = fail(rc, tr("cannot check the store"));
    return r;
}

}  // namespace pupitre::store
