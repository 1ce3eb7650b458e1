// The console's refusal shape: what a console or batch command answers when it
// cannot do what was asked, returned as a value (ARCHITECTURE.md, Invariants).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

namespace pupitre {

// A value and, when refused, the message to show (no NUM number, no block):
// `why` is empty when done. Where the console refuses without a value it
// answers the message alone, a std::string, empty when done.
template <class T>
struct Answer {
    T value{};
    std::string why;
};

}  // namespace pupitre
