// Inside the store: a thin layer over sqlite3 statements (bind, step, read a
// column) so the store's files read as SQL plus checks. Not for use outside store/.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <sqlite3.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace pupitre::store::sql {

// A cached statement in use: bound, stepped, and reset when it goes out of scope
// so the next user finds it clean (and no read transaction stays open).
class Use {
  public:
    explicit Use(sqlite3_stmt* s) : s_(s) {}
    ~Use() {
        if (s_) {
            sqlite3_reset(s_);
            sqlite3_clear_bindings(s_);
        }
    }
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;

    Use& bind(int i, int64_t v) {
        sqlite3_bind_int64(s_, i, v);
        return *this;
    }
    Use& bind(int i, int v) { return bind(i, int64_t(v)); }
    Use& bind(int i, double v) {
        sqlite3_bind_double(s_, i, v);
        return *this;
    }
    Use& bind(int i, std::string_view t) {
        sqlite3_bind_text(s_, i, t.data(), int(t.size()), SQLITE_TRANSIENT);
        return *this;
    }
    Use& bind(int i, const char* t) { return bind(i, std::string_view(t)); }
    Use& bind(int i, const std::string& t) { return bind(i, std::string_view(t)); }
    // Program texts are blobs: stored and given back byte for byte, whatever their encoding.
    Use& blob(int i, std::string_view b) {
        sqlite3_bind_blob64(s_, i, b.empty() ? "" : b.data(), b.size(), SQLITE_STATIC);
        return *this;
    }
    Use& null(int i) {
        sqlite3_bind_null(s_, i);
        return *this;
    }

    int step() { return sqlite3_step(s_); }

    bool is_null(int c) const { return sqlite3_column_type(s_, c) == SQLITE_NULL; }
    int64_t i64(int c) const { return sqlite3_column_int64(s_, c); }
    int i32(int c) const { return sqlite3_column_int(s_, c); }
    double f64(int c) const { return sqlite3_column_double(s_, c); }
    std::string str(int c) const {
        const void* p = sqlite3_column_blob(s_, c);  // text or blob: the bytes as stored
        int n = sqlite3_column_bytes(s_, c);
        return p ? std::string(static_cast<const char*>(p), size_t(n)) : std::string();
    }
    std::string_view view(int c) const {
        const void* p = sqlite3_column_blob(s_, c);
        int n = sqlite3_column_bytes(s_, c);
        return p ? std::string_view(static_cast<const char*>(p), size_t(n)) : std::string_view();
    }

  private:
    sqlite3_stmt* s_;
};

}  // namespace pupitre::store::sql
