// The Cazeneuve dialect's error numbers (pupitre-cazeneuve(5), ERRORS): what
// the shared machinery reports with a NUM number becomes the number of the
// thesis's category (003:798: syntax, function, capacity).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <utility>

#include "core/i18n.hpp"
#include "core/interp/caz.hpp"

namespace pupitre::caz {

namespace {
// NUM number -> dialect number, for what the shared steps can refuse.
constexpr std::pair<int, int> kFromNum[] = {
    {1, kNumber},     {2, kFunction},         {3, kFunction},  {20, kNoEnd},
    {28, kCss},       {29, kSpeed},           {101, kArc},     {106, kArc},
    {107, kArc},      {140, kCompensation},   {150, kTravelX}, {152, kTravelZ},
    {159, kFunction}, {831, kSpindleStopped},
};
}  // namespace

int error_of(int num_code) {
    if (num_code >= 1000) return num_code;  // pupitre's own: the run, the workshop
    for (const auto& [num, ours] : kFromNum)
        if (num == num_code) return ours;
    return kOther;
}

std::string detail_of(int num_code, std::string detail) {
    if (num_code == 20)  // these programs have no % line: the NUM's text says %0
        return tr("the text ends without M2 or M30 (003:962, 972)");
    return detail;
}

std::string_view category_of(int code) {
    if (code >= 2001 && code <= 2019) return "syntax";
    if (code >= 2020 && code <= 2049) return "function";
    if (code >= 2050 && code <= 2079) return "capacity";
    return "run";
}

}  // namespace pupitre::caz
