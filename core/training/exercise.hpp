// Exercises (issue 16, ARCHITECTURE.md, the workshop): a machine, a setup whose values are drawn
// from ranges, the task, what the student must find, a program to machine
// and the drawing's dimensions. A student's truth is drawn with a seed made
// of the exercise, the student and the class's secret, so neighbours get
// different values and the teacher can draw any attempt again. Text format:
// pupitre-exercise(5).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/workshop/setup.hpp"

namespace pupitre::training {

// A setup key the exercise fixes ("truth.chuck.z = -60") or draws from a
// range ("truth.chuck.z = -80 .. -40"), to `step` mm.
struct Draw {
    std::string key;  // the setup's key: chuck.z
    double lo = 0, hi = 0, step = 0.001;
    bool range = false;
    std::string text;  // a value that is not a number (yes, M4, plate)
    int line = 0;
};

// A value the student must find, as --set names it (PREF.X, DEC1.Z, D1.X,
// D2.DX, D3.L; X a radius on a lathe), and how close is right (mm).
struct Target {
    std::string name;
    double tolerance = 0.01;
    int line = 0;
};

// A value the machine has when the exercise starts: a number, or the truth
// plus an offset ("truth + 0.015": a corrector that is off, a worn tool).
struct Start {
    std::string name;
    double value = 0;
    bool from_truth = false;
    int line = 0;
};

// A dimension of the drawing, read on the cut part by an instrument
// (pupitre-setup(5), MEASUREMENTS): "dia Z-20 : 40 0.02".
struct Dimension {
    std::string spec;                          // the instrument's request
    double nominal = 0, lower = 0, upper = 0;  // within [nominal + lower, nominal + upper]
    int line = 0;
};

struct Exercise {
    std::string source;  // the file's text
    std::string name, title;
    std::string machine = "lathe";    // the profile: lathe or mill
    std::string setup = "lathe";      // the built-in setup it starts from
    std::string origin;               // lathe: face or jaws; mill: corner or centre
    std::vector<std::string> task;    // paragraphs
    std::vector<std::string> method;  // how the values are worked out, shown after :submit
    // The title, task and method in other languages ("title.fr", "task.fr",
    // "method.fr"), by code.
    std::vector<std::pair<std::string, std::string>> titles, tasks, methods;
    std::vector<Draw> truth;
    std::vector<Target> find;
    std::vector<Start> start;
    std::vector<Dimension> dimensions;
    std::vector<std::string> instruments;  // empty: every one
    std::vector<double> shims;             // thicknesses the task hands out (mm)
    std::vector<double> diameters;         // diameters the task gives (mm)
    double minutes = 0;                    // the time allowed, 0: none
    int program_number = 0;                // the program below, as %N
    std::string program;                   // its text, "" when none
    bool drawn() const;                    // some value comes from a range
    // The title and the task in the language of the texts (i18n), else as
    // written without a language.
    std::string title_here() const;
    std::vector<std::string> task_here() const;
    std::vector<std::string> method_here() const;
    bool lathe() const { return machine == "lathe"; }
};

// Parses an exercise: "" or "line N: what is wrong". Checks each key alone;
// check_exercise() checks the whole.
std::string parse_exercise(std::string_view text, Exercise& e);
// What no single line can say: the setup holds at the ranges' ends, each
// target names a tool the setup has, the origin suits the machine. Returns
// the problems, one per line ("" when none).
std::string check_exercise(const Exercise& e);
// The shipped exercises (data/exercises): their names, and one by name.
std::vector<std::string> builtin_exercises();
bool builtin_exercise(std::string_view name, Exercise& e);

// The seed of a student's truth: SHA-256 of the exercise's text, the
// student and the class's secret.
uint64_t seed_of(const Exercise& e, std::string_view student, std::string_view secret);
// The setup drawn with `seed` (its text: the built-in setup, then one line
// per truth key). "" or what is wrong.
std::string draw_setup(const Exercise& e, uint64_t seed, workshop::Setup& setup);
// The value the machine has at the start for `name` given the truth, if the
// exercise says one.
bool start_value(const Exercise& e, const workshop::Setup& truth, const std::string& name,
                 double& v);

// The right value of a target for this truth, and its arithmetic ("PREF Z =
// the jaws' face + the stick-out = -60.000 + 95.000 = 35.000"). False when
// the name is not one an exercise can ask for on this machine.
bool expected(const Exercise& e, const workshop::Setup& truth, const std::string& name, double& v,
              std::string* how = nullptr);
// Whether `name` is a value an exercise can ask for on a lathe (or a mill).
bool target_name(std::string_view name, bool lathe);

// The exercise done right on `truth`: every corrector at the true tool,
// the start values, every target at its right value; the program cut in
// the workshop and each dimension read. "" when that student would get full
// marks; else what goes wrong (a crash, an error, a dimension out).
std::string rehearse(const Exercise& e, const workshop::Setup& truth);

// An exercise file from a machine's setup, every value fixed: a start for
// the teacher's own (`pupitre exercise save`).
std::string exercise_from_setup(const workshop::Setup& setup, std::string_view name);

}  // namespace pupitre::training
