// The replay of an attempt (issue 34, pupitre-exercise(5), THE CLASS ON A
// SERVER): a console's Session of its own, on a scratch store, on the
// attempt's truth (its seed drawn again), fed the record's lines (record.hpp)
// at their simulated times. Its :submit gives the grade the teacher signs:
// the values are those the replay's machine holds and the part the one its
// tools cut, whatever the student's store says. `pupitre class grade` runs
// one to the end; `pupitre class replay` steps through one on the screen.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "console/line_input.hpp"
#include "console/record.hpp"
#include "console/refusal.hpp"
#include "core/interp/machine.hpp"
#include "core/training/exercise.hpp"
#include "store/store.hpp"

namespace pupitre::console {

class Session;
class ExerciseRun;

class Replay {
  public:
    // The attempt `a` (its seed, record, time and crashes) made on the
    // exercise `e`, at its first line. "" or why it cannot be replayed.
    static Answer<std::unique_ptr<Replay>> open(const training::Exercise& e,
                                                const store::Attempt& a);
    ~Replay();
    Replay(const Replay&) = delete;
    Replay& operator=(const Replay&) = delete;

    // A line of the record it could not read (the lines before it count).
    const std::string& problem() const { return problem_; }
    const std::vector<record::Action>& lines() const { return lines_; }
    size_t done() const { return done_; }  // lines applied
    size_t steps_done() const;             // of them, the operator's actions
    size_t steps() const;                  // in the whole record
    bool at_end() const { return done_ >= lines_.size(); }

    // The lines up to the next operator's action, that action included.
    void step();
    // Every line left; then :submit, when the record's did not grade (it
    // ended first, or the replay was in cycle when it came).
    void run_to_end();
    // From the start again, up to `lines` lines applied. "" or what went wrong.
    std::string rewind(size_t lines);

    Session& session() { return *s_; }
    const ExerciseRun& run() const;
    // The line after which a mistake named at the end first held for good
    // (a value entered wrong there, or 0: from the start), one per value
    // the grade explains. Known once run_to_end() has run.
    struct Named {
        std::string value;    // PREF.Z
        std::string mistake;  // dec1
        std::string title;    // DEC1 forgotten
        size_t line = 0;      // lines applied when it began
    };
    const std::vector<Named>& named() const { return named_; }

  private:
    Replay() = default;
    std::string begin_session();
    void apply(const record::Action& a);
    void follow_mistakes();

    training::Exercise e_;
    store::Attempt a_;
    MachineProfile m_;
    uint64_t seed_ = 0;
    std::vector<record::Action> lines_;
    std::string problem_;
    std::string dir_;  // the scratch store's directory
    int sessions_ = 0;
    size_t done_ = 0;
    std::unique_ptr<PlainLineInput> input_;
    std::unique_ptr<Session> s_;
    std::vector<Named> held_;  // the mistakes now, and since when
    std::vector<Named> named_;
};

}  // namespace pupitre::console
