// Screen snapshots (pupitre(1), THE CONSOLE): a drawn screen compared with a text file
// under the source tree; PUPITRE_BLESS=1 rewrites the file instead, for an
// intended change to be reviewed in the diff.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace pupitre::test {

// `dir`: the snapshots' directory relative to the source tree.
inline void snapshot(const std::string& dir, const std::string& name, const std::string& screen) {
    std::string path = std::string(PUPITRE_SOURCE_DIR) + "/" + dir + "/" + name + ".txt";
    const char* bless = std::getenv("PUPITRE_BLESS");
    if (bless && *bless == '1') {
        std::ofstream(path) << screen;
        return;
    }
    std::ifstream in(path);
    ASSERT_TRUE(in) << "no snapshot " << path << " (run with PUPITRE_BLESS=1)\n" << screen;
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str(), screen) << "snapshot " << name << " differs; new screen:\n" << screen;
}

}  // namespace pupitre::test
