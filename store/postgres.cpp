// The PostgreSQL backend: a store that a class shares on a server. libpq's
// own environment and files apply (PGHOST, PGPORT, PGUSER, PGSSLMODE,
// ~/.pgpass, service files): pupitre never asks for a password and never
// writes one. Writes run SERIALIZABLE and are run again when the server
// refuses one for a concurrent writer (Store::in_write); the store's other
// consoles hear of a commit by NOTIFY. All of pupitre's PostgreSQL-only SQL
// is here and in store/schema_pg.hpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <arpa/inet.h>
#include <libpq-fe.h>
#include <poll.h>

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/i18n.hpp"
#include "store/backend.hpp"
#include "store/pg_connect.hpp"
#include "store/pg_copy.hpp"
#include "store/schema_pg.hpp"
#include "store/store.hpp"

namespace pupitre::store {

using pg::one_line;

static_assert(kServerSchemaVersion == schema_pg::kCount, "kServerSchemaVersion must match");

namespace {

// The codes this backend's calls return besides db::kOk/kRow/kDone: the
// server's answer (its SQLSTATE is kept), or a connection that is gone.
constexpr int kServerError = 1;
constexpr int kConnectionLost = 2;

constexpr Oid kByteaOid = 17;
constexpr Oid kInt8Oid = 20;
constexpr Oid kInt2Oid = 21;
constexpr Oid kInt4Oid = 23;
constexpr Oid kTextOid = 25;
constexpr Oid kVarcharOid = 1043;
// The channel a commit is announced on (Store::data_version), one per
// database; the payload names the store's schema, so that stores sharing a
// database (a schema each) do not hear each other.
constexpr const char* kNotify = "SELECT pg_notify('pupitre_store', coalesce(current_schema(), ''))";
constexpr const char* kListen = "LISTEN pupitre_store";

// ?N -> $N outside quoted strings: the statements both engines share are
// written with SQLite's numbered parameters. Also says which numbers appear.
std::string dollar_params(const char* sql, std::vector<bool>& used) {
    std::string out;
    char quote = 0;
    for (const char* p = sql; *p; ++p) {
        char c = *p;
        if (quote) {
            if (c == quote) quote = 0;
            out += c;
            continue;
        }
        if (c == '\'' || c == '"') quote = c;
        if (c == '?' && p[1] >= '0' && p[1] <= '9') {
            int n = 0;
            while (p[1] >= '0' && p[1] <= '9') n = n * 10 + (*++p - '0');
            if (int(used.size()) < n) used.resize(size_t(n), false);
            used[size_t(n - 1)] = true;
            out += '$' + std::to_string(n);
            continue;
        }
        out += c;
    }
    return out;
}

class PgBackend;

class PgStmt final : public db::Stmt {
  public:
    PgStmt(PgBackend& b, std::string name, const char* sql);
    ~PgStmt() override { reset(); }
    void bind(int i, int64_t v) override { set(i, std::to_string(v), 0); }
    void bind(int i, double v) override {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        set(i, buf, 0);
    }
    void bind(int i, std::string_view t) override { set(i, std::string(t), 0); }
    void blob(int i, std::string_view b) override { set(i, std::string(b), 1); }
    void null(int i) override {
        if (i >= 1 && size_t(i) <= values_.size()) values_[size_t(i - 1)].reset();
    }
    int step() override;
    void reset() override {
        if (res_) PQclear(res_);
        res_ = nullptr;
        row_ = -1;
        for (auto& v : values_) v.reset();
        for (int& f : formats_) f = 0;
    }
    bool is_null(int c) const override { return PQgetisnull(res_, row_, c) != 0; }
    int64_t i64(int c) const override;
    double f64(int c) const override {
        if (is_null(c)) return 0;
        if (binary_ && type(c) != kTextOid && type(c) != kVarcharOid) return double(i64(c));
        return std::strtod(PQgetvalue(res_, row_, c), nullptr);
    }
    std::string_view view(int c) const override;
    void forget() { prepared_ = false; }  // the connection was made again

  private:
    static bool binary_results(const PGresult* d);
    // A column's type, as the statement's description gave it (PQftype is
    // a call into libpq for each of a list's 100,000 values).
    Oid type(int c) const { return size_t(c) < cols_.size() ? cols_[size_t(c)] : PQftype(res_, c); }
    void set(int i, std::string v, int format) {
        if (i < 1 || size_t(i) > values_.size()) return;
        values_[size_t(i - 1)] = std::move(v);
        formats_[size_t(i - 1)] = format;
    }
    PgBackend& b_;
    std::string name_, sql_;
    std::vector<Oid> types_;
    std::vector<std::optional<std::string>> values_;
    std::vector<int> formats_;
    bool prepared_ = false;
    // Results in binary (binary_results): a program's text (bytea) comes as
    // its bytes rather than twice as many hex digits for the server to make
    // and us to decode, integers as their bytes rather than their digits.
    bool binary_ = false;
    std::vector<Oid> cols_;  // a SELECT's column types, from its description
    PGresult* res_ = nullptr;
    int row_ = -1;
    mutable std::vector<std::string> decoded_;  // bytea columns of the current row
    mutable int decoded_row_ = -1;
};

// A statement of Backend::prepare_many: its rows read by COPY (…) TO STDOUT
// in binary, one row per piece libpq gives and cut here (store/pg_copy.hpp),
// so that no result of 100,000 fields is built value by value. The copy runs
// at the first step; reset() reads what is left of it.
class PgCopyStmt final : public db::Stmt {
  public:
    PgCopyStmt(PgBackend& b, const char* sql)
        : b_(b), sql_(std::string("COPY (") + sql + ") TO STDOUT (FORMAT binary)") {}
    ~PgCopyStmt() override { reset(); }
    // prepare_many's statements have no parameters.
    void bind(int, int64_t) override {}
    void bind(int, double) override {}
    void bind(int, std::string_view) override {}
    void blob(int, std::string_view) override {}
    void null(int) override {}
    int step() override;
    void reset() override;
    bool is_null(int c) const override { return field(c).size < 0; }
    int64_t i64(int c) const override { return pg_copy::integer(field(c)); }
    // The caller knows the column's type, which a binary COPY does not say:
    // f64 reads a double precision (or real) column.
    double f64(int c) const override { return pg_copy::real(field(c)); }
    std::string_view view(int c) const override {
        const pg_copy::Field& f = field(c);
        return f.size < 0 ? std::string_view() : std::string_view(f.at, size_t(f.size));
    }

  private:
    const pg_copy::Field& field(int c) const {
        static const pg_copy::Field none;
        return size_t(c) < fields_.size() ? fields_[size_t(c)] : none;
    }
    int finish();
    int refuse();
    PgBackend& b_;
    std::string sql_;
    bool copying_ = false, header_ = false, done_ = false;
    char* piece_ = nullptr;  // the current row, libpq's
    std::vector<pg_copy::Field> fields_;
};

class PgBackend final : public db::Backend {
  public:
    explicit PgBackend(PGconn* c) : c_(c) {}
    ~PgBackend() override {
        stmts_.clear();
        copies_.clear();
        PQfinish(c_);
    }
    PGconn* conn() const { return c_; }

    // Keeps the server's answer when it is an error; returns the code.
    int check(PGresult* r, bool keep = false) {
        ExecStatusType st = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
        if (st == PGRES_COMMAND_OK || st == PGRES_TUPLES_OK) {
            if (!keep && r) PQclear(r);
            return db::kOk;
        }
        const char* state = r ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
        sqlstate_ = state ? state : "";
        message_ = one_line(r ? PQresultErrorMessage(r) : PQerrorMessage(c_));
        if (message_.empty()) message_ = one_line(PQerrorMessage(c_));
        if (r) PQclear(r);
        return PQstatus(c_) == CONNECTION_BAD || sqlstate_.rfind("08", 0) == 0 ||
                       sqlstate_.rfind("57P", 0) == 0
                   ? kConnectionLost
                   : kServerError;
    }
    int run(const char* sql) { return check(PQexec(c_, sql)); }

    db::Stmt* prepare(const char* sql, int& rc) override {
        if (int r = revive()) {
            rc = r;
            return nullptr;
        }
        auto it = stmts_.find(sql);
        if (it != stmts_.end()) return it->second.get();
        auto s = std::make_unique<PgStmt>(*this, "p" + std::to_string(stmts_.size()), sql);
        return stmts_.emplace(sql, std::move(s)).first->second.get();
    }
    db::Stmt* prepare_many(const char* sql, int& rc) override {
        if (std::strchr(sql, '?')) return prepare(sql, rc);  // parameters: not by COPY
        if (int r = revive()) {
            rc = r;
            return nullptr;
        }
        std::unique_ptr<PgCopyStmt>& s = copies_[sql];
        if (!s) s = std::make_unique<PgCopyStmt>(*this, sql);
        return s.get();
    }
    int exec(const char* sql) override { return run(sql); }
    int insert_rows(const char* table, const char* columns, int width,
                    const std::vector<db::Value>& values) override;
    int begin_write() override { return begin("BEGIN ISOLATION LEVEL SERIALIZABLE"); }
    // READ COMMITTED: after waiting for the lock, the next statement sees what
    // the process that held it committed.
    int begin_migration() override {
        int rc = begin("BEGIN");
        if (rc == db::kOk) rc = run("SELECT pg_advisory_xact_lock(1314212145)");  // "NUM1"
        return rc;
    }
    int begin_read() override { return begin("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY"); }
    // The other consoles hear of the change once it is committed; the
    // announcement and the commit in one round trip (a failure in either
    // is the answer, and nothing is committed).
    int commit() override {
        static const std::string sql = std::string(kNotify) + "; COMMIT";
        int rc = run(sql.c_str());
        in_tx_ = false;
        return rc;
    }
    void rollback() override {
        if (PQtransactionStatus(c_) != PQTRANS_IDLE && PQstatus(c_) == CONNECTION_OK)
            PQclear(PQexec(c_, "ROLLBACK"));
        in_tx_ = false;
    }
    // Two SERIALIZABLE writers inserting the same key (the next revision of
    // one program, a new program) may meet as a unique violation rather than
    // a serialization failure: run again, it reads what the other committed.
    bool retryable(int rc) const override {
        return rc == kServerError &&
               (sqlstate_ == "40001" || sqlstate_ == "40P01" || sqlstate_ == "23505");
    }
    StoreError explain(int rc, const std::string& head) const override;
    int read_meta(db::Meta& m) override;
    int schema_version() const override { return kServerSchemaVersion; }
    const char* migration(int v) const override { return schema_pg::kMigrations[v]; }
    const char* packed_list() const override {
        return packed_ ? "SELECT listing, title, modified_by FROM programs WHERE deleted = 0"
                       : nullptr;
    }
    // Schema 4 lacks only the packed list, which the list then does without.
    bool work_at(int64_t version) override {
        if (version != 4) return false;
        packed_ = false;
        return true;
    }
    int write_meta(int64_t version) override;
    int data_version(int64_t& out) override;
    int integrity(std::string& out) override;
    int after_copy() override;
    std::string_view engine() const override { return "postgresql"; }
    bool remote() const override { return true; }

    // Listens, and learns the schema whose announcements are this store's.
    int listen() {
        // One round trip: PQexec answers with the last statement's result.
        static const std::string sql =
            std::string(kListen) + "; SELECT coalesce(current_schema(), '')";
        PGresult* r = PQexec(c_, sql.c_str());
        if (int rc = check(r, true)) return rc;
        schema_ = PQntuples(r) == 1 ? PQgetvalue(r, 0, 0) : "";
        PQclear(r);
        return db::kOk;
    }
    // What each connection sets for itself (at open and when made again):
    // the server's notices kept for what matters; long values compressed
    // with lz4 (PostgreSQL 14 and later, when built with it) rather than the
    // default pglz, which takes 150 ms for a 3 MB program on a small server
    // (program texts are not compressed in a store made now: schema_pg.hpp);
    // prepared statements planned once for any values: the store's queries
    // are key lookups whose best plan does not depend on them, and a plan
    // made for the values copies each of them into it (a 3 MB program's text
    // on each of a connection's first five saves: a save took 20% longer).
    // All in one round trip; lz4 only where the server offers it.
    int session() {
        return run(
            "SET client_min_messages = warning; SET plan_cache_mode = force_generic_plan; "
            "SELECT set_config(name, 'lz4', false) FROM pg_settings WHERE name = "
            "'default_toast_compression' AND 'lz4' = ANY (enumvals)");
    }

  private:
    int begin(const char* sql) {
        if (int r = revive()) return r;
        int rc = run(sql);
        in_tx_ = rc == db::kOk;
        return rc;
    }
    // A connection the server dropped (restarted, stopped) is made again
    // before the next transaction; never inside one, whose work is lost. A
    // live store (the console) makes it a non-blocking step per call.
    int revive() {
        if (PQstatus(c_) == CONNECTION_OK && !resetting_) return db::kOk;
        if (in_tx_) return kConnectionLost;
        if (!resetting_) {
            if (!live_) {
                PQreset(c_);
                return made_again();
            }
            if (!PQresetStart(c_)) return lost();
            resetting_ = true;
        }
        // As many steps of the handshake as the server answers within a few
        // milliseconds each; the rest at the next call.
        for (int step = 0; step < 32; ++step) {
            PostgresPollingStatusType st = PQresetPoll(c_);
            if (st == PGRES_POLLING_OK) {
                resetting_ = false;
                return made_again();
            }
            if (st == PGRES_POLLING_FAILED) {
                resetting_ = false;
                return lost();
            }
            pollfd p{PQsocket(c_), short(st == PGRES_POLLING_READING ? POLLIN : POLLOUT), 0};
            if (p.fd < 0 || ::poll(&p, 1, 2) <= 0) break;
        }
        sqlstate_ = "08006";
        message_ = tr("connecting again");
        return kConnectionLost;
    }
    int made_again() {
        if (PQstatus(c_) != CONNECTION_OK) return lost();
        for (auto& [sql, s] : stmts_) s->forget();  // UTF-8 again: the connection's parameters
        if (int rc = session()) return rc;
        return listen();
    }
    int lost() {
        sqlstate_ = "08006";
        message_ = one_line(PQerrorMessage(c_));
        return kConnectionLost;
    }

  public:
    void set_live(bool live) { live_ = live; }

  private:
    PGconn* c_;
    bool in_tx_ = false;
    bool live_ = false, resetting_ = false;
    std::string sqlstate_, message_;
    int64_t version_ = 0;  // notifications heard from other connections
    std::string schema_;   // the store's, which its notifications name
    bool packed_ = true;   // programs.listing is there (schema 5)
    std::map<const char*, std::unique_ptr<PgStmt>> stmts_;
    std::map<const char*, std::unique_ptr<PgCopyStmt>> copies_;

    friend class PgStmt;
    friend class PgCopyStmt;
};

PgStmt::PgStmt(PgBackend& b, std::string name, const char* sql) : b_(b), name_(std::move(name)) {
    std::vector<bool> used;
    sql_ = dollar_params(sql, used);
    // A number the statement does not use (SQLite allows gaps) still needs a
    // type on the server: text, never bound.
    for (bool u : used) types_.push_back(u ? 0 : kTextOid);
    values_.resize(types_.size());
    formats_.assign(types_.size(), 0);
}

int PgStmt::step() {
    if (res_) {
        ++row_;
        return row_ < PQntuples(res_) ? db::kRow : db::kDone;
    }
    PGconn* c = b_.conn();
    if (!prepared_) {
        if (int rc = b_.check(PQprepare(c, name_.c_str(), sql_.c_str(), int(types_.size()),
                                        types_.empty() ? nullptr : types_.data())))
            return rc;
        if (sql_.rfind("SELECT", 0) == 0) {
            PGresult* d = PQdescribePrepared(c, name_.c_str());
            if (int rc = b_.check(d, true)) return rc;
            binary_ = binary_results(d);
            cols_.resize(size_t(PQnfields(d)));
            for (size_t i = 0; i < cols_.size(); ++i) cols_[i] = PQftype(d, int(i));
            PQclear(d);
        }
        prepared_ = true;
    }
    std::vector<const char*> vals(values_.size());
    std::vector<int> lens(values_.size());
    for (size_t i = 0; i < values_.size(); ++i) {
        vals[i] = values_[i] ? values_[i]->data() : nullptr;
        lens[i] = values_[i] ? int(values_[i]->size()) : 0;
    }
    PGresult* r = PQexecPrepared(c, name_.c_str(), int(vals.size()), vals.data(), lens.data(),
                                 formats_.data(), binary_ ? 1 : 0);
    if (int rc = b_.check(r, true)) return rc;
    res_ = r;
    row_ = 0;
    decoded_row_ = -1;
    return PQntuples(res_) > 0 ? db::kRow : db::kDone;
}

// Whether a statement's results can be asked in binary: each of its columns
// is bytea or of a type PgStmt reads in binary exactly as in text (integers,
// text). Binary spares the server the integers' digits and the client
// reading them back (a list of 10,000 programs has 60,000).
bool PgStmt::binary_results(const PGresult* d) {
    for (int i = 0; i < PQnfields(d); ++i) {
        const Oid t = PQftype(d, i);
        if (t != kByteaOid && t != kInt8Oid && t != kInt4Oid && t != kInt2Oid && t != kTextOid &&
            t != kVarcharOid)
            return false;
    }
    return true;
}

// Reading a column is what a list of 10,000 programs does 100,000 times: a
// NULL is told by its length 0 (it reads as 0, as an empty text would), the
// digits by from_chars, rather than by PQgetisnull and strtoll.
int64_t PgStmt::i64(int c) const {
    const char* v = PQgetvalue(res_, row_, c);
    const int n = PQgetlength(res_, row_, c);
    if (n == 0) return 0;
    if (binary_) {
        const Oid t = type(c);
        if (t == kInt8Oid) {
            uint32_t hi, lo;
            std::memcpy(&hi, v, 4);
            std::memcpy(&lo, v + 4, 4);
            return int64_t((uint64_t(ntohl(hi)) << 32) | ntohl(lo));
        }
        if (t == kInt4Oid) {
            uint32_t x;
            std::memcpy(&x, v, 4);
            return int32_t(ntohl(x));
        }
        if (t == kInt2Oid) {
            uint16_t x;
            std::memcpy(&x, v, 2);
            return int16_t(ntohs(x));
        }
    }
    int64_t x = 0;
    std::from_chars(v, v + n, x);
    return x;
}

// Text columns as the server sent them; bytea (program texts) as its bytes,
// in binary results, or decoded from the server's hex form, so the bytes are
// exactly those stored. Integers in binary results as they read in text.
std::string_view PgStmt::view(int c) const {
    const char* v = PQgetvalue(res_, row_, c);
    const size_t n = size_t(PQgetlength(res_, row_, c));
    if (n == 0) return PQgetisnull(res_, row_, c) ? std::string_view() : std::string_view(v, 0);
    const Oid t = type(c);
    if (binary_ && (t == kInt8Oid || t == kInt4Oid || t == kInt2Oid)) {
        if (decoded_row_ != row_) {
            decoded_.assign(size_t(PQnfields(res_)), std::string());
            decoded_row_ = row_;
        }
        return decoded_[size_t(c)] = std::to_string(i64(c));
    }
    if (binary_ || t != kByteaOid) return {v, n};
    if (decoded_row_ != row_) {
        decoded_.assign(size_t(PQnfields(res_)), std::string());
        decoded_row_ = row_;
    }
    std::string& d = decoded_[size_t(c)];
    if (d.empty()) {
        size_t len = 0;
        unsigned char* bytes = PQunescapeBytea(reinterpret_cast<const unsigned char*>(v), &len);
        if (bytes) d.assign(reinterpret_cast<const char*>(bytes), len);
        PQfreemem(bytes);
    }
    return d;
}

int PgCopyStmt::step() {
    PGconn* c = b_.conn();
    if (done_) return db::kDone;
    if (!copying_) {
        PGresult* r = PQexec(c, sql_.c_str());
        if (PQresultStatus(r) != PGRES_COPY_OUT) {
            const int rc = b_.check(r);
            return rc != db::kOk ? rc : refuse();  // an answer, but not a copy
        }
        PQclear(r);
        copying_ = header_ = true;
    }
    for (;;) {
        if (piece_) PQfreemem(piece_);
        piece_ = nullptr;
        const int n = PQgetCopyData(c, &piece_, 0);
        if (n < 0) return finish();  // -1: all sent; -2: failed (the result says why)
        const pg_copy::Piece p = pg_copy::cut(piece_, size_t(n), header_, fields_);
        if (p == pg_copy::Piece::row) return db::kRow;
        if (p == pg_copy::Piece::damaged) {
            reset();
            return refuse();
        }
    }
}

// An answer that is not what was asked for.
int PgCopyStmt::refuse() {
    done_ = true;
    b_.sqlstate_ = "XX001";
    b_.message_ = tr("the server's answer does not add up");
    return kServerError;
}

// The copy's end: the command's own result, OK or why it failed.
int PgCopyStmt::finish() {
    copying_ = false;
    done_ = true;
    fields_.clear();
    const int rc = b_.check(PQgetResult(b_.conn()));
    while (PGresult* more = PQgetResult(b_.conn())) PQclear(more);
    return rc == db::kOk ? db::kDone : rc;
}

void PgCopyStmt::reset() {
    if (piece_) PQfreemem(piece_);
    piece_ = nullptr;
    fields_.clear();
    if (copying_) {
        // The rest of a copy read to its end: the connection serves the next command.
        char* rest = nullptr;
        while (PQgetCopyData(b_.conn(), &rest, 0) > 0) PQfreemem(rest);
        finish();
    }
    done_ = false;
}

StoreError PgBackend::explain(int rc, const std::string& head) const {
    const std::string& m = message_;
    if (rc == db::kCorrupt)
        return {Fault::bad_data,
                head + strf(tr("the store is damaged (%s); nothing was changed: restore a backup"),
                            "revision missing")};
    if (rc == kConnectionLost) {
        StoreError e{Fault::io,
                     head + strf(tr("the server is gone (%s); nothing was changed"), m.c_str())};
        e.gone = true;
        return e;
    }
    const std::string& s = sqlstate_;
    if (s == "40001" || s == "40P01")
        return {Fault::io, head + tr("other consoles changed the same rows at the same time; "
                                     "nothing was changed, try again")};
    if (s == "53100")
        return {Fault::io, head + tr("the server's disk is full; nothing was changed")};
    if (s == "42501")
        return {Fault::cannot_create,
                head + strf(tr("permission denied (%s); nothing was changed"), m.c_str())};
    if (s.rfind("23", 0) == 0 || s.rfind("22", 0) == 0)
        return {Fault::bad_data,
                head + strf(tr("refused by the store (%s); nothing was changed"), m.c_str())};
    return {Fault::io, head + strf(tr("%s; nothing was changed"), m.c_str())};
}

int PgBackend::read_meta(db::Meta& m) {
    // pupitre_meta first: on a store the only question (counting the
    // schema's tables costs a new connection 2 ms of catalogue reads).
    PGresult* r = PQexec(c_, "SELECT to_regclass('pupitre_meta') IS NOT NULL, current_schema()");
    if (int rc = check(r, true)) return rc;
    const bool ours = PQgetvalue(r, 0, 0)[0] == 't';
    const std::string schema = PQgetvalue(r, 0, 1);
    PQclear(r);
    if (!ours) {
        r = PQexec(c_, "SELECT count(*) FROM pg_tables WHERE schemaname = current_schema()");
        if (int rc = check(r, true)) return rc;
        m.blank = std::strtoll(PQgetvalue(r, 0, 0), nullptr, 10) == 0;
        PQclear(r);
        m.foreign = !m.blank;
        if (m.foreign)
            m.foreign_why = strf(tr("a PostgreSQL database whose schema %s holds other tables"),
                                 schema.c_str());
        return db::kOk;
    }
    r = PQexec(c_,
               "SELECT (SELECT value FROM pupitre_meta WHERE key = 'application_id'), "
               "(SELECT value FROM pupitre_meta WHERE key = 'schema_version'), "
               "(SELECT pg_has_role(relowner, 'USAGE') FROM pg_class WHERE oid = "
               "to_regclass('programs'))");
    if (int rc = check(r, true)) return rc;
    int64_t app = std::strtoll(PQgetvalue(r, 0, 0), nullptr, 10);
    m.version = std::strtoll(PQgetvalue(r, 0, 1), nullptr, 10);
    m.may_change = PQgetisnull(r, 0, 2) || PQgetvalue(r, 0, 2)[0] == 't';
    PQclear(r);
    if (uint32_t(app) != kApplicationId) {
        m.foreign = true;
        m.foreign_why = strf(tr("a pupitre_meta table of another application"));
    }
    return db::kOk;
}

int PgBackend::write_meta(int64_t version) {
    std::string sql = "INSERT INTO pupitre_meta (key, value) VALUES ('application_id', " +
                      std::to_string(kApplicationId) + "), ('schema_version', " +
                      std::to_string(version) +
                      ") ON CONFLICT (key) DO UPDATE SET value = excluded.value";
    return run(sql.c_str());
}

// The number of commits other connections announced since this one was made.
int PgBackend::data_version(int64_t& out) {
    if (int r = revive()) return r;
    if (!PQconsumeInput(c_)) return lost();
    const int self = PQbackendPID(c_);
    while (PGnotify* n = PQnotifies(c_)) {
        // No schema named: a class set up by an older pupitre, heard by all.
        if (n->be_pid != self && (schema_ == n->extra || !*n->extra)) ++version_;
        PQfreemem(n);
    }
    out = version_;
    return db::kOk;
}

// The server keeps its own pages and keys sound; what the store checks is its
// own rule across tables: every program's current revision exists.
int PgBackend::integrity(std::string& out) {
    PGresult* r = PQexec(c_,
                         "SELECT p.number FROM programs p LEFT JOIN revisions r ON r.program = "
                         "p.number AND r.rev = p.head WHERE r.rev IS NULL ORDER BY p.number");
    if (int rc = check(r, true)) return rc;
    out.clear();
    for (int i = 0; i < PQntuples(r); ++i)
        out += std::string(out.empty() ? "" : "\n") + "program " + PQgetvalue(r, i, 0) +
               ": its current revision is missing";
    PQclear(r);
    if (out.empty()) out = "ok";
    return db::kOk;
}

// Rows copied in with their ids: identity columns go on after the largest.
int PgBackend::after_copy() {
    for (const char* t : {"audit", "imd_history", "attempts"}) {
        std::string sql = std::string("SELECT setval(pg_get_serial_sequence('") + t +
                          "', 'id'), (SELECT max(id) FROM " + t + "), true) WHERE EXISTS " +
                          "(SELECT 1 FROM " + t + ")";
        if (int rc = run(sql.c_str())) return rc;
    }
    return db::kOk;
}

// COPY in PostgreSQL's binary format (store/pg_copy.hpp), sent a megabyte at
// a time, so the server writes rows while the next are made.
int PgBackend::insert_rows(const char* table, const char* columns, int width,
                           const std::vector<db::Value>& values) {
    if (PQstatus(c_) != CONNECTION_OK) return lost();
    const std::string sql =
        std::string("COPY ") + table + " (" + columns + ") FROM STDIN (FORMAT binary)";
    PGresult* r = PQexec(c_, sql.c_str());
    if (PQresultStatus(r) != PGRES_COPY_IN) return check(r);
    PQclear(r);
    std::string buf;
    pg_copy::header(buf);
    bool sent = true;
    for (size_t at = 0; sent && at + size_t(width) <= values.size(); at += size_t(width)) {
        pg_copy::row(buf, &values[at], width);
        if (buf.size() >= (1u << 20)) {
            sent = PQputCopyData(c_, buf.data(), int(buf.size())) == 1;
            buf.clear();
        }
    }
    pg_copy::trailer(buf);
    sent = sent && PQputCopyData(c_, buf.data(), int(buf.size())) == 1;
    if (PQputCopyEnd(c_, sent ? nullptr : "not sent") != 1) return lost();
    int rc = check(PQgetResult(c_));
    while (PGresult* more = PQgetResult(c_)) PQclear(more);
    return rc;
}

}  // namespace

namespace db {

// postgresql://user:secret@host:5432/db?sslmode=require -> postgresql://user@host:5432/db
// host=h dbname=d user=u password=p -> postgresql://u@h/d
std::string display_name(const std::string& target) {
    if (!is_server(target)) return target;
    char* err = nullptr;
    PQconninfoOption* opts = PQconninfoParse(target.c_str(), &err);
    if (!opts) {
        PQfreemem(err);
        return "postgresql://?";
    }
    std::map<std::string, std::string> v;
    for (PQconninfoOption* o = opts; o->keyword; ++o)
        if (o->val && *o->val) v[o->keyword] = o->val;
    PQconninfoFree(opts);
    std::string out = "postgresql://";
    if (v.count("user")) out += v["user"] + "@";
    out += v.count("host") ? v["host"] : (v.count("hostaddr") ? v["hostaddr"] : "");
    if (v.count("port")) out += ":" + v["port"];
    out += "/";
    if (v.count("dbname")) out += v["dbname"];
    if (v.count("service")) out += "?service=" + v["service"];
    return out;
}

}  // namespace db

Result<std::unique_ptr<Store>> Store::open_postgres(const std::string& target, const Options& o) {
    Result<std::unique_ptr<Store>> r;
    const std::string name = db::display_name(target);
    // A server that does not answer is given up after 5 s unless the
    // connection string or PGCONNECT_TIMEOUT says otherwise.
    const char* timeout = std::getenv("PGCONNECT_TIMEOUT");
    // A server that vanishes without closing the connection (a cable, a
    // crash of its host) is noticed within seconds, not at TCP's pace.
    const char* keys[] = {
        "connect_timeout",           "keepalives_idle", "keepalives_interval", "tcp_user_timeout",
        "fallback_application_name", "dbname",          "client_encoding",     nullptr};
    const char* vals[] = {timeout && *timeout ? timeout : "5",
                          "5",
                          "2",
                          "10000",
                          "pupitre",
                          target.c_str(),
                          "UTF8",
                          nullptr};
    PGconn* c = PQconnectdbParams(keys, vals, 1);
    if (!c) {
        r.error = {Fault::io, strf(tr("%s: cannot connect: out of memory"), name.c_str())};
        return r;
    }
    if (PQstatus(c) != CONNECTION_OK) {
        r.error = pg::connect_error(name, PQerrorMessage(c), PQuser(c), PQdb(c));
        PQfinish(c);
        return r;
    }
    // The server's notices ("terminating connection…") would be printed on
    // stderr, over the console's screen: what matters comes back as errors.
    PQsetNoticeProcessor(
        c, [](void*, const char*) {}, nullptr);
    std::unique_ptr<Store> st(new Store);
    st->path_ = name;
    st->short_name_ = pg::short_name(PQhost(c), PQdb(c));
    st->opt_ = o;
    // On a server a person is their database login.
    st->user_ = o.user.empty() ? std::string(PQuser(c)) : o.user;
    auto backend = std::make_unique<PgBackend>(c);
    PgBackend& b = *backend;
    b.set_live(o.live);
    st->db_ = std::move(backend);
    if (int rc = b.session()) {
        r.error = st->fail(rc, tr("cannot open the store"));
        return r;
    }
    db::Meta m;
    if (int rc = b.read_meta(m)) {
        r.error = st->fail(rc, tr("cannot open the store"));
        return r;
    }
    if (m.blank && !o.create) {
        r.error = {Fault::not_found, strf(tr("%s: no such store"), name.c_str())};
        return r;
    }
    bool fresh = false;
    if ((r.error = st->validate_and_migrate(fresh, &m))) return r;
    if (int rc = b.listen()) {
        r.error = st->fail(rc, tr("cannot open the store"));
        return r;
    }
    st->created_ = fresh;
    r.value = std::move(st);
    return r;
}

}  // namespace pupitre::store
