// Inside the store: a statement in use (bind, step, read a column) over either
// backend, so the store's files read as SQL plus checks, and the one write
// transaction every change runs in. Not for use outside store/.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>

#include "store/backend.hpp"

namespace pupitre::store::sql {

// A cached statement in use: bound, stepped, and reset when it goes out of
// scope so the next user finds it clean (and no read stays open). `error` is
// set when the statement could not be prepared; nothing else may then be called.
class Use {
  public:
    Use(db::Stmt* s, StoreError e) : s_(s), error(std::move(e)) {}
    ~Use() {
        if (s_) s_->reset();
    }
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;

    Use& bind(int i, int64_t v) {
        s_->bind(i, v);
        return *this;
    }
    Use& bind(int i, int v) { return bind(i, int64_t(v)); }
    Use& bind(int i, double v) {
        s_->bind(i, v);
        return *this;
    }
    Use& bind(int i, std::string_view t) {
        s_->bind(i, t);
        return *this;
    }
    Use& bind(int i, const char* t) { return bind(i, std::string_view(t)); }
    Use& bind(int i, const std::string& t) { return bind(i, std::string_view(t)); }
    Use& blob(int i, std::string_view b) {
        s_->blob(i, b);
        return *this;
    }
    Use& null(int i) {
        s_->null(i);
        return *this;
    }

    int step() { return s_->step(); }

    bool is_null(int c) const { return s_->is_null(c); }
    int64_t i64(int c) const { return s_->i64(c); }
    int i32(int c) const { return int(s_->i64(c)); }
    double f64(int c) const { return s_->f64(c); }
    std::string str(int c) const { return std::string(s_->view(c)); }
    std::string_view view(int c) const { return s_->view(c); }

  private:
    db::Stmt* s_;

  public:
    StoreError error;
};

// One statement for many rows: `head`, then `row` (a row's part, written
// with the parameters ?1..?width) `rows` times separated by ", ", each
// copy's parameters numbered after the previous one's (the second row's ?1
// is ?width+1), then `tail`. Each text is made once per (head, rows, tail)
// and kept for the life of the process, as Backend::prepare wants (it keys
// statements by address); the stores of several threads share them.
inline const char* repeated(const char* head, const char* row, int width, int rows,
                            const char* tail = "") {
    static std::mutex m;
    static std::map<std::tuple<const char*, int, const char*>, std::string> made;
    std::lock_guard<std::mutex> lock(m);
    std::string& sql = made[{head, rows, tail}];
    if (!sql.empty()) return sql.c_str();
    sql = head;
    for (int r = 0; r < rows; ++r) {
        if (r) sql += ", ";
        for (const char* p = row; *p; ++p) {
            if (*p != '?') {
                sql += *p;
                continue;
            }
            int n = 0;
            while (p[1] >= '0' && p[1] <= '9') n = n * 10 + (*++p - '0');
            sql += '?' + std::to_string(r * width + n);
        }
    }
    sql += tail;
    return sql.c_str();
}

// How many rows the multi-row statements of a batch carry: as many as the
// largest holds, the rest in smaller ones (at most three of each), so that a
// batch makes few round trips and few statements are prepared. 256 rows of
// 11 parameters stay far below both engines' limits (SQLite 32766, PostgreSQL
// 65535).
inline constexpr int kBatchRows[] = {256, 64, 16, 4, 1};

// Calls f(first, count) over [0, n) in chunks of kBatchRows; stops at the
// first error.
template <class F>
StoreError in_batches(size_t n, F&& f) {
    size_t at = 0;
    for (int size : kBatchRows)
        while (n - at >= size_t(size)) {
            if (StoreError e = f(at, size_t(size))) return e;
            at += size_t(size);
        }
    return {};
}

inline StoreError& error_of(StoreError& e) {
    return e;
}
template <class T>
StoreError& error_of(Result<T>& r) {
    return r.error;
}

}  // namespace pupitre::store::sql

namespace pupitre::store {

// How many times a write transaction is run when the server reports a
// serialization failure or a deadlock (PostgreSQL under many writers); SQLite
// takes its write lock first and never meets one. Each round lets at least
// one writer through, so a class of 30 consoles saving the same program at
// the same moment all get through within this bound (12 was not enough on a
// loaded machine: the last ones were told "try again").
inline constexpr int kWriteAttempts = 40;

// Runs `body` (which returns a StoreError or a Result) in one write
// transaction: committed when it succeeds, rolled back when it fails, and run
// again from the start, up to kWriteAttempts times, when it failed on a
// serialization failure. `body` must leave nothing behind it between runs
// (it builds its answer afresh).
template <class F>
auto Store::in_write(F&& body) -> decltype(body()) {
    using R = decltype(body());
    for (int attempt = 1;; ++attempt) {
        R r{};
        if (StoreError e = begin_write()) {
            sql::error_of(r) = std::move(e);
        } else {
            r = body();
            if (sql::error_of(r))
                rollback();
            else if (StoreError c = commit())
                sql::error_of(r) = std::move(c);
        }
        if (!sql::error_of(r).retry || attempt == kWriteAttempts) return r;
        ++retried_;
        // Another writer won: let it finish, then read again, after a random
        // wait that grows, so that the losers do not meet again in step.
        thread_local std::minstd_rand jitter(std::random_device{}());
        const int most = 1 << std::min(attempt + 1, 7);
        std::this_thread::sleep_for(std::chrono::milliseconds(1 + int(jitter() % unsigned(most))));
    }
}

}  // namespace pupitre::store
