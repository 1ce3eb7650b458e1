// pupitre class (issue 34, pupitre-exercise(5), THE CLASS ON A SERVER): a
// class set up on a PostgreSQL server, its students' logins, and the grading
// on the teacher's side: each submitted attempt graded again by replaying its
// record (replay.hpp) against the truth drawn from the seed the server drew,
// with the server's times and crashes, and signed with the key only a
// teacher's login reads. The report is in cli_exercise.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>
#include <fstream>
#include <sstream>

#include "console/cli.hpp"
#include "console/exercise.hpp"
#include "console/exercise_run.hpp"
#include "console/replay.hpp"
#include "core/i18n.hpp"
#include "core/training/grade.hpp"
#include "store/store.hpp"

namespace pupitre::cli {

namespace {

// init [--class NAME]: the class set up, the shipped exercises added.
int class_init(const ExerciseArgs& a, store::Store& st) {
    // On one PC: the teacher's key, apart from the class key, that
    // exercise truth needs from now on.
    if (st.engine() != "postgresql") {
        if (std::string why = console::init_teacher_key(st); !why.empty()) {
            std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
            return kCantCreate;
        }
        std::printf(tr("the teacher's key is %s: keep it where no student's account reads it; "
                       "exercise truth on %s needs it\n"),
                    console::teacher_key_path().c_str(), st.path().c_str());
        return kOk;
    }
    std::vector<store::NamedText> shipped;
    for (const std::string& n : training::builtin_exercises()) {
        training::Exercise e;
        if (training::builtin_exercise(n, e)) shipped.push_back({e.name, e.source});
    }
    if (store::StoreError e = st.class_init(a.group, shipped)) return report(e);
    std::printf(tr("class %s set up on %s: pupitre class add-student --class %s NAME… makes its "
                   "logins\n"),
                a.group.c_str(), st.path().c_str(), a.group.c_str());
    return kOk;
}

// NAME, or the first column of each line of a CSV file (a header line whose
// first field is "name", "login" or "student" is skipped).
bool names_from_csv(const std::string& path, std::vector<std::string>& names) {
    std::ifstream f(path);
    if (!f) return false;
    for (std::string line; std::getline(f, line);) {
        std::string first = line.substr(0, line.find_first_of(",;\t"));
        while (!first.empty() && (first.back() == '\r' || first.back() == ' ')) first.pop_back();
        while (!first.empty() && first.front() == ' ') first.erase(0, 1);
        if (first.size() >= 2 && first.front() == '"' && first.back() == '"')
            first = first.substr(1, first.size() - 2);
        if (first.empty() || first == "name" || first == "login" || first == "student") continue;
        names.push_back(first);
    }
    return true;
}

// add-student NAME… | --from FILE.csv: the logins, their passwords printed once.
int class_add(const ExerciseArgs& a, store::Store& st) {
    std::vector<std::string> names(a.words.begin() + 1, a.words.end());
    if (!a.from.empty() && !names_from_csv(a.from, names)) {
        std::fprintf(stderr, tr("pupitre: cannot read %s\n"), a.from.c_str());
        return kNoInput;
    }
    if (names.empty()) {
        std::fputs(tr("pupitre: class add-student needs NAME… or --from FILE.csv\n"), stderr);
        return kUsage;
    }
    auto r = st.add_students(a.group, names);
    if (r.error) return report(r.error);
    std::fputs(tr("# login password (shown once: hand each student theirs)\n"), stdout);
    for (const store::Login& l : r.value)
        std::printf("%s %s\n", l.name.c_str(), l.password.c_str());
    return kOk;
}

int class_students(const ExerciseArgs& a, store::Store& st) {
    auto r = st.students(a.group_given ? a.group : "");
    if (r.error) return report(r.error);
    for (const store::Login& l : r.value) std::printf("%s %s\n", l.group.c_str(), l.name.c_str());
    return kOk;
}

// One attempt graded again by replaying its record against its truth, and
// signed; "" or why it could not be. The values are those the replay's
// machine holds at its :submit and the part the one its tools cut: what the
// student's rows on the server say counts for nothing.
std::string grade_one(store::Store& st, store::Attempt a, const std::string& key) {
    auto text = st.exercise_text(a.exercise, a.exercise_sha);
    if (text.error) return text.error.message;
    if (!text.value) return tr("the text it was made on is not on the server");
    training::Exercise e;
    if (std::string why = training::parse_exercise(*text.value, e); !why.empty()) return why;
    auto replay = console::Replay::open(e, a);
    if (!replay.why.empty()) return replay.why;
    console::Replay& r = *replay.value;
    if (!r.problem().empty())
        std::fprintf(stderr, tr("pupitre: attempt %lld: its record: %s (replayed up to there)\n"),
                     (long long)a.id, r.problem().c_str());
    r.run_to_end();
    const store::Attempt& g = r.run().attempt();
    const int provisional = a.score;
    a.score = g.score;
    a.scrapped = g.scrapped;
    a.crashes = g.crashes;
    a.mistakes = g.mistakes;
    a.found = g.found;
    a.report = g.report;
    a.signature = console::sign_attempt(a, key);
    if (store::StoreError err = st.grade_attempt(a)) return err.message;
    const std::string named = a.mistakes.empty() ? "" : " (" + a.mistakes + ")";
    std::printf(tr("attempt %lld: %s, %s: %d%%%s\n"), (long long)a.id, a.student.c_str(),
                a.exercise.c_str(), a.score, named.c_str());
    // The console's own grade and the replay's differ: the record does not
    // say all the student did (or was written by hand).
    if (provisional != a.score)
        std::printf(tr("  the console said %d%% at :submit\n"), provisional);
    return {};
}

// grade: every attempt submitted and not yet signed.
int class_grade(store::Store& st) {
    auto on_class = st.class_server();
    if (on_class.error) return report(on_class.error);
    if (!on_class.value) {
        std::fputs(tr("pupitre: class grade: this store has no class (pupitre class init)\n"),
                   stderr);
        return kUsage;
    }
    auto key = st.class_signing_key();
    if (key.error) return report(key.error);
    auto all = st.attempts();
    if (all.error) return report(all.error);
    int rc = kOk, graded = 0;
    for (const store::Attempt& a : all.value) {
        if (a.submitted_ms == 0 || !a.signature.empty()) continue;
        if (std::string why = grade_one(st, a, key.value); !why.empty()) {
            std::fprintf(stderr, tr("pupitre: attempt %lld (%s, %s): %s\n"), (long long)a.id,
                         a.student.c_str(), a.exercise.c_str(), why.c_str());
            rc = kDataErr;
            continue;
        }
        ++graded;
    }
    std::printf(trn("%d attempt graded\n", "%d attempts graded\n", graded), graded);
    return rc;
}

}  // namespace

int class_command(const ExerciseArgs& a) {
    const std::string verb = a.words.empty() ? "" : a.words[0];
    if (verb == "report") return class_report(a);
    std::unique_ptr<store::Store> st;
    const bool known = verb == "init" || verb == "add-student" || verb == "students" ||
                       verb == "grade" || verb == "watch" || verb == "replay";
    if (!known) {
        std::fputs(tr("pupitre: class report|init|add-student|students|grade|watch|replay (pupitre "
                      "class --help)\n"),
                   stderr);
        return kUsage;
    }
    if (verb != "add-student" && verb != "replay" && a.words.size() > 1) {
        std::fprintf(stderr, tr("pupitre: class %s takes no NAME\n"), verb.c_str());
        return kUsage;
    }
    if (int rc = open_store(a.db, st)) return rc;
    if (verb == "init") return class_init(a, *st);
    if (verb == "add-student") return class_add(a, *st);
    if (verb == "students") return class_students(a, *st);
    if (verb == "watch") return class_watch(a, *st);
    if (verb == "replay") return class_replay(a, *st);
    return class_grade(*st);
}

}  // namespace pupitre::cli
