// pupitre class (issue 34, pupitre-exercise(5), THE CLASS ON A SERVER): a
// class set up on a PostgreSQL server, its students' logins, and the grading
// on the teacher's side: each submitted attempt graded again from what the
// server holds (the machine's values the student entered, the part they cut,
// their record, the crashes the server counted, the server's times) against
// the truth drawn from the seed the server drew, and signed with the key
// only a teacher's login reads. The report is in cli_exercise.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>
#include <fstream>
#include <sstream>

#include "console/cli.hpp"
#include "console/exercise.hpp"
#include "core/i18n.hpp"
#include "core/interp/interp.hpp"
#include "core/interp/machine.hpp"
#include "core/training/grade.hpp"
#include "core/workshop/workshop.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::cli {

namespace {

struct Quiet final : MachineSink {};

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

// The values the student entered, as the server keeps their attempt's machine.
training::Values found_values(store::Store& st, const MachineProfile& m,
                              const training::Exercise& e, const std::string& machine,
                              std::string& why) {
    ProgramMemory mem;
    Quiet quiet;
    Interpreter in(m, mem, quiet);
    training::Values found;
    if (auto r = store::seed_machine(st, in, machine); r.error) {
        why = r.error.message;
        return found;
    }
    for (const training::Target& t : e.find) {
        double v = 0;
        in.get(t.name, v);
        found[t.name] = v;
    }
    return found;
}

// One attempt graded again and signed; "" or why it could not be.
std::string grade_one(store::Store& st, store::Attempt a, const std::string& key) {
    auto text = st.exercise_text(a.exercise, a.exercise_sha);
    if (text.error) return text.error.message;
    if (!text.value) return tr("the text it was made on is not on the server");
    training::Exercise e;
    if (std::string why = training::parse_exercise(*text.value, e); !why.empty()) return why;
    MachineProfile m;
    if (!builtin_machine(e.machine, m)) return strf(tr("no machine %s"), e.machine.c_str());
    const uint64_t seed = std::stoull(a.seed, nullptr, 16);
    workshop::Setup truth;
    if (std::string why = training::draw_setup(e, seed, truth); !why.empty()) return why;
    std::string why;
    training::Values found = found_values(st, m, e, a.machine, why);
    if (!why.empty()) return why;
    training::Context ctx = console::record_context(a.record);
    ctx.diameters.insert(ctx.diameters.end(), e.diameters.begin(), e.diameters.end());
    ctx.shims.insert(ctx.shims.end(), e.shims.begin(), e.shims.end());
    workshop::Workshop shop(m, truth, nullptr);
    auto w = st.workshop(a.machine);
    if (w.error) return w.error.message;
    if (w.value) shop.load_part(console::unscramble(w.value->part, seed));
    training::Grade g = training::grade(e, truth, found, ctx, &shop, a.crashes, a.seconds);
    a.score = g.score;
    a.scrapped = g.scrapped;
    a.mistakes.clear();
    for (training::Mistake k : g.mistakes())
        a.mistakes += (a.mistakes.empty() ? "" : " ") + std::string(training::mistake_id(k));
    a.found.clear();
    for (const training::Target& t : e.find)
        a.found += strf("%s=%.4f\n", t.name.c_str(), found[t.name]);
    a.report.clear();
    for (const std::string& l : training::report_lines(e, g)) a.report += l + "\n";
    a.signature = console::sign_attempt(a, key);
    if (store::StoreError err = st.grade_attempt(a)) return err.message;
    const std::string named = a.mistakes.empty() ? "" : " (" + a.mistakes + ")";
    std::printf(tr("attempt %lld: %s, %s: %d%%%s\n"), (long long)a.id, a.student.c_str(),
                a.exercise.c_str(), a.score, named.c_str());
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
                       verb == "grade" || verb == "watch";
    if (!known) {
        std::fputs(tr("pupitre: class report|init|add-student|students|grade|watch (pupitre "
                      "class --help)\n"),
                   stderr);
        return kUsage;
    }
    if (verb != "add-student" && a.words.size() > 1) {
        std::fprintf(stderr, tr("pupitre: class %s takes no NAME\n"), verb.c_str());
        return kUsage;
    }
    if (int rc = open_store(a.db, st)) return rc;
    if (verb == "init") return class_init(a, *st);
    if (verb == "add-student") return class_add(a, *st);
    if (verb == "students") return class_students(a, *st);
    if (verb == "watch") return class_watch(a, *st);
    return class_grade(*st);
}

}  // namespace pupitre::cli
