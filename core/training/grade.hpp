// Grading an attempt (issue 16): each value found against the truth, the cut
// part against the drawing, crashes and time; and the mistakes named, each
// detected from the value entered and the truth (pupitre-exercise(5),
// GRADING).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/training/exercise.hpp"

namespace pupitre::workshop {
class Workshop;
}

namespace pupitre::training {

// What the student did that a mistake can be traced to.
struct Context {
    std::vector<double> diameters;  // read with an instrument, or given by the task
    std::vector<double> shims;      // placed (:shim, :gauge), or given by the task
};

// The mistakes pupitre names (their words in the report and the store).
enum class Mistake { none, diameter, radius, sign, wear_sign, corrector, dec1, shim, unset };
const char* mistake_id(Mistake m);     // "diameter", "sign", …
std::string mistake_title(Mistake m);  // "X taken as a diameter instead of a radius"

struct ItemGrade {
    std::string name;  // PREF.X
    double found = 0, truth = 0, tolerance = 0;
    bool ok = false;
    std::string how;  // the truth's arithmetic
    Mistake mistake = Mistake::none;
    std::string why;  // the mistake explained with the numbers
};

struct DimGrade {
    Dimension dim;
    double measured = 0;
    bool read = false;  // false: the instrument could not read it (`why`)
    bool ok = false;
    std::string why;
};

struct Grade {
    std::vector<ItemGrade> items;
    std::vector<DimGrade> dims;
    int crashes = 0;
    bool scrapped = false;  // a crash, or a dimension out of tolerance
    double seconds = 0;
    bool late = false;  // over the exercise's time
    int score = 0;      // percent of the values and dimensions right
    std::vector<Mistake> mistakes() const;
};

// The values entered, as --set names them (X a radius on a lathe).
using Values = std::map<std::string, double>;

Grade grade(const Exercise& e, const workshop::Setup& truth, const Values& found,
            const Context& ctx, const workshop::Workshop* part, int crashes, double seconds);

// The report: what the REPORT page and `pupitre exercise` print, the
// truth and the arithmetic of each value, each mistake explained.
std::vector<std::string> report_lines(const Exercise& e, const Grade& g);

}  // namespace pupitre::training
