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

}  // namespace pupitre::test
