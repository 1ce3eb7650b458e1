// The exercise run (console/exercise_run.cpp; issue 16, pupitre-exercise(5)):
// an attempt at an exercise in progress at the console, or graded. It holds
// the truth drawn from the seed, which it alone hands to the workshop, the
// attempt as the store keeps it, what the student placed and read, :submit
// and the report. The machine state lives under the attempt's own name in
// the store; the part is stored scrambled.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "console/desk.hpp"
#include "console/refusal.hpp"
#include "core/render/part_scene.hpp"
#include "core/training/grade.hpp"
#include "store/store.hpp"

namespace pupitre::console {

class ExerciseRun {
  public:
    // `student`'s attempt at `e` on the Session's store, begun or taken up
    // again; its machine state under its own name (machine_key()).
    static Answer<std::unique_ptr<ExerciseRun>> open(Bench& b, const training::Exercise& e,
                                                     const std::string& student,
                                                     const std::string& key);
    explicit ExerciseRun(Bench& b) : b_(b) {}
    const std::string& machine_key() const { return attempt_.machine; }
    // The exercise's program becomes the current text of its number; the
    // text it replaced is named (program_note()). "" or what went wrong.
    std::string take_program();
    const std::string& program_note() const { return program_note_; }
    bool graded() const { return grade_.has_value(); }
    // The exercise's drawing: its dimensions (the PART view, :part export).
    render::Drawing drawing() const { return render::drawing_of(ex_); }
    const training::Exercise& exercise() const { return ex_; }
    const std::string& student() const { return student_; }

    // The workshop of the attempt: the truth drawn again, its places hidden,
    // the part as the store keeps it; `fresh` when the stock is new.
    std::unique_ptr<workshop::Workshop> workshop(bool& fresh) const;
    // What the store keeps of the workshop: the exercise's name, never the
    // setup; the part scrambled.
    std::string stored_setup() const { return "exercise " + ex_.name; }
    std::string stored_part(const std::string& part) const;

    // True (and says why) when `what` would show the truth before :submit.
    bool hidden(const char* what);
    void note_shim(double mm);  // a shim or a gauge block placed
    void note_reading(const std::string& word, double value);
    bool instrument_allowed(const std::string& word);  // says why not
    void watch_crashes();
    Effect submit();  // :submit

    // The EXERCISE page: the task before :submit, the report after.
    void view(pages::View& v) const;

  private:
    static Answer<std::unique_ptr<ExerciseRun>> open_on_class(Bench& b,
                                                              const training::Exercise& e);
    Bench& b_;
    training::Exercise ex_;
    std::string student_, key_;
    uint64_t seed_ = 0;
    workshop::Setup truth_;
    store::Attempt attempt_;
    training::Context ctx_;  // the shims placed, the diameters read
    size_t crashes_seen_ = 0;
    bool on_class_ = false;     // on a class's server: the server opens, counts, the teacher signs
    std::string program_note_;  // the store's program the exercise's replaced, said at start
    std::optional<training::Grade> grade_;
    std::vector<std::string> report_;  // after :submit
};

}  // namespace pupitre::console
