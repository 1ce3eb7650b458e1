// The exercise run (console/exercise_run.cpp; issue 16, pupitre-exercise(5)):
// an attempt at an exercise in progress at the console, or graded. It holds
// the truth drawn from the seed, which it alone hands to the workshop, the
// attempt as the store keeps it, what the student placed and read, the
// record of what they did (record.hpp), :submit and the report. The machine
// state lives under the attempt's own name in the store; the part is stored
// scrambled. The teacher's side runs one too, in a replay (replay.hpp): the
// same truth, the record's actions fed to its Session, its :submit grading.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "console/desk.hpp"
#include "console/record.hpp"
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
    // The replay of the attempt `a` (replay.hpp): the truth drawn from
    // `seed`, on the replay's own store; :submit grades with the attempt's
    // seconds (the server's time) and at least its crashes (the server's
    // count), and keeps nothing.
    static Answer<std::unique_ptr<ExerciseRun>> open_replay(Bench& b, const training::Exercise& e,
                                                            uint64_t seed, const store::Attempt& a);
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

    // The record: null once graded, and in a replay (which records nothing).
    record::Recorder* recorder() { return grade_ || replay_ ? nullptr : &rec_; }
    // The record so far to the store: `now`, else at most every 2 s.
    void keep_record(bool now);

    // The replay's side: the grade of what the machine holds now, without
    // the part (the mistakes named at each action); the grade as :submit
    // would give it, even in cycle (a record that ends without a :submit
    // the replay took); the attempt as graded.
    training::Grade grade_values() const;
    void grade_now();
    const std::optional<training::Grade>& grade() const { return grade_; }
    const store::Attempt& attempt() const { return attempt_; }
    const training::Exercise& definition() const { return ex_; }

    // The EXERCISE page: the task before :submit, the report after.
    void view(pages::View& v) const;

  private:
    static Answer<std::unique_ptr<ExerciseRun>> open_on_class(Bench& b,
                                                              const training::Exercise& e);
    static Answer<std::unique_ptr<ExerciseRun>> open_local(Bench& b, const training::Exercise& e,
                                                           const std::string& student,
                                                           uint64_t seed);
    std::string set_start_values();  // a new attempt's machine; "" or why not
    training::Values found_values(std::string* text) const;
    training::Context context() const;  // the task's and what the student did
    Bench& b_;
    training::Exercise ex_;
    std::string student_, key_;
    uint64_t seed_ = 0;
    workshop::Setup truth_;
    store::Attempt attempt_;
    training::Context ctx_;  // the shims placed, the diameters read
    size_t crashes_seen_ = 0;
    bool on_class_ = false;  // on a class's server: the server opens, counts, the teacher signs
    bool replay_ = false;    // the teacher's replay: nothing kept, the time given
    double replay_seconds_ = 0;
    int replay_crashes_ = 0;
    record::Recorder rec_;
    int64_t record_kept_ms_ = 0;
    bool record_refused_ = false;  // said once
    std::string program_note_;     // the store's program the exercise's replaced, said at start
    std::optional<training::Grade> grade_;
    std::vector<std::string> report_;  // after :submit
};

}  // namespace pupitre::console
