// Store test helpers: a private temporary directory, files as bytes, and a store
// opened in it. Tests may use sqlite3 directly to set up what a user's file
// could be (another application's database, a newer schema, a lock held).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "store/store.hpp"

namespace pupitre::test {

struct TempDir {
    std::string path;
    TempDir() {
        std::string tmpl =
            (std::filesystem::temp_directory_path() / "pupitre-store-XXXXXX").string();
        char* p = mkdtemp(tmpl.data());
        if (p) path = p;
    }
    ~TempDir() {
        if (path.empty()) return;
        std::error_code ec;
        // Make everything removable again (tests make directories read-only).
        for (auto& e : std::filesystem::recursive_directory_iterator(path, ec))
            if (e.is_directory(ec)) ::chmod(e.path().c_str(), 0755);
        ::chmod(path.c_str(), 0755);
        std::filesystem::remove_all(path, ec);
    }
    std::string operator/(const std::string& name) const { return path + "/" + name; }
};

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline void spit(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

inline bool exists(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

inline std::unique_ptr<store::Store> open_store(const std::string& path, store::Options o = {}) {
    if (o.user.empty()) o.user = "tester";
    auto r = store::Store::open(path, o);
    EXPECT_FALSE(r.error) << r.error.message;
    return std::move(r.value);
}

// The shared reference programs beside the repository, or "" when absent.
inline std::string shared_programs() {
    std::string dir = std::string(PUPITRE_SOURCE_DIR) + "/../shared/programs";
    return exists(dir) ? dir : std::string();
}

// Where a test's stores live, on either engine: `place / "p.db"` is a file
// in a private directory for SQLite; for PostgreSQL, a schema of its own on
// the test server (PUPITRE_TEST_PG, started by scripts/test), made on first
// use and dropped at the end, named by a connection string whose
// search_path is that schema.
class Place {
  public:
    explicit Place(std::string engine) : engine_(std::move(engine)) {}
    ~Place();
    Place(const Place&) = delete;
    Place& operator=(const Place&) = delete;
    std::string operator/(const std::string& name);
    const std::string& engine() const { return engine_; }
    const TempDir& dir() const { return dir_; }

  private:
    std::string engine_;
    TempDir dir_;
    std::vector<std::pair<std::string, std::string>> made_;  // name, target
    std::vector<std::string> schemas_;
};

// Runs one SQL text on the test server as its administrator; "" when done,
// else the server's message.
std::string pg_admin(const std::string& sql);

// The same cases on both engines. The PostgreSQL half is skipped (one line)
// when no test server was started, and fails under CI, where one always is.
class OnBothEngines : public ::testing::TestWithParam<std::string> {
  protected:
    void SetUp() override;
};

std::string engine_name(const ::testing::TestParamInfo<std::string>& p);

}  // namespace pupitre::test

#define PUPITRE_ON_BOTH_ENGINES(Suite)                                                  \
    INSTANTIATE_TEST_SUITE_P(Engines, Suite, ::testing::Values("sqlite", "postgresql"), \
                             ::pupitre::test::engine_name)
