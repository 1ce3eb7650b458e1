// The batch commands of the pupitre executable (DESIGN §2.1).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

namespace pupitre::cli {

// sysexits(3)
inline constexpr int kOk = 0, kProgramErrors = 1, kUsage = 64, kDataErr = 65, kNoInput = 66,
                     kSoftware = 70;

struct RunArgs {
    std::string machine = "mill";
    std::vector<std::string> sets;   // NAME=VALUE
    std::vector<std::string> files;
    bool trace = false;
    bool json = false;
    bool block_skip = false;
    bool optional_stop = false;
    long max_blocks = 20'000'000;
};

int run(const RunArgs& a);
int check(const RunArgs& a);

}  // namespace pupitre::cli
