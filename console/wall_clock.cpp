// The wall clock (wall_clock.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/wall_clock.hpp"

#include <chrono>
#include <ctime>

namespace pupitre {

int64_t wall_ms() {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

std::string local_time(int64_t ms, const char* format) {
    const std::time_t t = std::time_t(ms / 1000);
    std::tm tm{};
    localtime_r(&t, &tm);
    char buf[64];
    return std::strftime(buf, sizeof buf, format, &tm) ? buf : "";
}

}  // namespace pupitre
