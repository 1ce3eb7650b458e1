// pupitre exercise and pupitre class report (issue 16, pupitre-exercise(5)):
// the exercises checked, added, listed and drawn again for the teacher; the
// class's attempts as a table, CSV or a printable HTML report.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>

#include "console/class_report.hpp"
#include "console/cli.hpp"
#include "console/exercise.hpp"
#include "console/plot_loader.hpp"
#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "core/output/cairo_plot.hpp"
#include "store/store.hpp"

namespace pupitre::cli {

namespace {

bool read_text(const std::string& path, std::string& text) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::stringstream ss;
    ss << f.rdbuf();
    text = ss.str();
    return true;
}

// check FILE...: each file parsed and checked as a whole.
int exercise_check(const std::vector<std::string>& files) {
    if (files.empty()) {
        std::fputs(tr("pupitre: exercise check needs a FILE\n"), stderr);
        return kUsage;
    }
    int rc = kOk;
    for (const std::string& f : files) {
        std::string text;
        if (!read_text(f, text)) {
            std::fprintf(stderr, tr("pupitre: cannot read %s\n"), f.c_str());
            rc = kNoInput;
            continue;
        }
        training::Exercise e;
        std::string why = training::parse_exercise(text, e);
        if (why.empty()) why = training::check_exercise(e);
        if (!why.empty()) {
            std::istringstream lines(why);
            for (std::string l; std::getline(lines, l);)
                std::printf("%s: %s\n", f.c_str(), l.c_str());
            if (rc == kOk) rc = kDataErr;
            continue;
        }
        // TRANSLATORS: the file, the exercise's name, its machine (lathe or
        // mill, as the file says), counts, then one truth for all or one each.
        std::printf(tr("%s: exercise %s (machine %s): values to find %zu, dimensions %zu, %s\n"),
                    f.c_str(), e.name.c_str(), e.machine.c_str(), e.find.size(),
                    e.dimensions.size(),
                    e.drawn() ? tr("a truth drawn for each student") : tr("one truth for all"));
    }
    return rc;
}

int exercise_list(const ExerciseArgs& a) {
    std::unique_ptr<store::Store> st;
    if (int rc = open_store(a.db, st)) return rc;
    auto listed = [](const std::string& where, const std::string& name,
                     const training::Exercise& e) {
        std::printf("%-18s %-6s %-8s %s\n", name.c_str(), e.machine.c_str(), where.c_str(),
                    e.title_here().c_str());
    };
    for (const std::string& n : training::builtin_exercises()) {
        training::Exercise e;
        if (training::builtin_exercise(n, e)) listed(tr("shipped"), n, e);
    }
    auto r = st->exercises();
    if (r.error) return report(r.error);
    for (const std::string& n : r.value) {
        training::Exercise e;
        if (console::find_exercise(st.get(), n, e).empty()) listed(tr("class"), n, e);
    }
    return kOk;
}

// add FILE: the class's own exercise, kept in the store.
int exercise_add(const ExerciseArgs& a) {
    std::string text;
    if (a.words.size() != 2 || !read_text(a.words[1], text)) {
        std::fputs(tr("pupitre: exercise add needs a readable FILE\n"), stderr);
        return kUsage;
    }
    training::Exercise e;
    std::string why = training::parse_exercise(text, e);
    if (why.empty()) why = training::check_exercise(e);
    if (!why.empty()) {
        std::fprintf(stderr, "%s: %s", a.words[1].c_str(), why.c_str());
        if (why.back() != '\n') std::fputc('\n', stderr);
        return kDataErr;
    }
    std::unique_ptr<store::Store> st;
    if (int rc = open_store(a.db, st)) return rc;
    if (store::StoreError err = st->put_exercise(e.name, text)) return report(err);
    std::printf(tr("exercise %s stored: pupitre exercise %s starts it\n"), e.name.c_str(),
                e.name.c_str());
    return kOk;
}

// truth NAME --student S: what the student had to find, for the teacher
// (the class key is needed: without it the draw is not the student's).
int exercise_truth(const ExerciseArgs& a) {
    if (a.words.size() != 2) {
        std::fputs(tr("pupitre: exercise truth needs a NAME and --student\n"), stderr);
        return kUsage;
    }
    std::unique_ptr<store::Store> st;
    if (int rc = open_store(a.db, st)) return rc;
    if (auto on_class = st->class_server(); on_class.error || on_class.value) {
        if (on_class.error) return report(on_class.error);
        std::fputs(tr("pupitre: exercise truth: on a class's server the server draws each "
                      "attempt's truth; the graded report shows it (pupitre class grade)\n"),
                   stderr);
        return kUsage;
    }
    if (std::string why = console::teacher_allowed(*st); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
        return kNoPerm;
    }
    training::Exercise e;
    if (std::string why = console::find_exercise(st.get(), a.words[1], e); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
        return kNoInput;
    }
    std::string key;
    if (std::string why = console::store_class_key(*st, false, key); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
        return kNoInput;
    }
    const std::string student = console::student_name(a.student);
    if (std::string why = console::truth_allowed(*st, e, student, getuid()); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
        return kNoPerm;
    }
    const uint64_t seed = training::seed_of(e, student, key);
    workshop::Setup truth;
    if (std::string why = training::draw_setup(e, seed, truth); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
        return kDataErr;
    }
    std::printf(tr("# exercise %s, student %s, seed %016llx\n"), e.name.c_str(), student.c_str(),
                (unsigned long long)seed);
    for (const training::Target& t : e.find) {
        double v = 0;
        std::string how;
        training::expected(e, truth, t.name, v, &how);
        std::printf("%-8s %10.3f   # %s\n", t.name.c_str(), v, how.c_str());
    }
    std::printf(tr("# the setup drawn (pupitre-setup(5)):\n%s"), truth.source.c_str());
    return kOk;
}

// save NAME: an exercise from the machine's current setup, every value fixed.
int exercise_save(const ExerciseArgs& a) {
    if (a.words.size() != 2) {
        std::fputs(tr("pupitre: exercise save needs a NAME\n"), stderr);
        return kUsage;
    }
    std::unique_ptr<store::Store> st;
    if (int rc = open_store(a.db, st)) return rc;
    const std::string machine = a.machine.empty() ? kDefaultMachine : a.machine;
    auto r = st->workshop(machine);
    if (r.error) return report(r.error);
    workshop::Setup s;
    if (!r.value || !workshop::parse_setup(r.value->setup, s).empty()) {
        std::fprintf(stderr, tr("pupitre: machine %s has no workshop: :setup puts one on it\n"),
                     machine.c_str());
        return kNoInput;
    }
    const std::string text = training::exercise_from_setup(s, a.words[1]);
    if (a.output.empty() || a.output == "-") {
        std::fputs(text.c_str(), stdout);
        return kOk;
    }
    std::ofstream f(a.output, std::ios::binary);
    if (!(f << text) || !f.flush()) {
        std::fprintf(stderr, tr("pupitre: cannot write %s\n"), a.output.c_str());
        return kCantCreate;
    }
    return kOk;
}

// NAME: the console on the exercise's hidden setup.
int exercise_start(const ExerciseArgs& a) {
    ConsoleArgs c = a.console;
    c.db = a.db;
    c.exercise = a.words[0];
    c.student = a.student;  // as given: on a server, --student is refused
    return console(c);
}

}  // namespace

int exercise(const ExerciseArgs& a) {
    const std::string what = a.words.empty() ? "list" : a.words[0];
    if (what == "list") return exercise_list(a);
    if (what == "check")
        return exercise_check(std::vector<std::string>(a.words.begin() + 1, a.words.end()));
    if (what == "add") return exercise_add(a);
    if (what == "truth") return exercise_truth(a);
    if (what == "save") return exercise_save(a);
    if (a.words.size() != 1) {
        std::fputs(tr("pupitre: exercise NAME takes nothing after the name\n"), stderr);
        return kUsage;
    }
    return exercise_start(a);
}

namespace {

// The table as a PDF through Cairo, beside the HTML report (docs/decisions.md,
// Exercises hide the truth).
int report_pdf(const std::string& path, const console::ReportContext& c,
               const std::vector<store::Attempt>& attempts, std::FILE* said) {
    const std::string& title = c.title;
    std::istringstream text(console::class_report_text(attempts, console::ReportFormat::table, c));
    std::vector<std::string> lines;
    for (std::string l; std::getline(text, l);) lines.push_back(l);
    std::FILE* out = std::fopen(path.c_str(), "wb");
    if (!out) {
        std::fprintf(stderr, tr("pupitre: cannot write %s\n"), path.c_str());
        return kCantCreate;
    }
    const bool ok = write_text_pdf(title, lines, out);
    if (std::fclose(out) != 0 || !ok) {
        if (const std::string why = plot_module_error(); !why.empty())
            std::fprintf(stderr, tr("pupitre: cannot write %s: %s\n"), path.c_str(), why.c_str());
        else
            std::fprintf(stderr, tr("pupitre: cannot write %s\n"), path.c_str());
        return kCantCreate;
    }
    std::fprintf(said, tr("the report written to %s\n"), path.c_str());
    return kOk;
}

// The report as one HTML file ("-": on the standard output).
int report_html(const std::string& path, const console::ReportContext& c,
                const std::vector<store::Attempt>& attempts, std::FILE* said) {
    const std::string text = console::class_report_text(attempts, console::ReportFormat::html, c);
    if (path == "-") {
        std::fputs(text.c_str(), stdout);
        return kOk;
    }
    std::ofstream out(path, std::ios::binary);
    if (!(out << text) || !out.flush()) {
        std::fprintf(stderr, tr("pupitre: cannot write %s\n"), path.c_str());
        return kCantCreate;
    }
    std::fprintf(said, tr("the report written to %s\n"), path.c_str());
    return kOk;
}

}  // namespace

// class report [EXERCISE]: the table, or each of --csv, --html FILE, --pdf FILE.
// What the report checks and says: the key (on a class's server the
// server's, which a teacher's login reads; a student's report of their own
// attempts is not checked), and each exercise's current text.
store::Result<console::ReportContext> report_context(store::Store& st,
                                                     const std::vector<store::Attempt>& all,
                                                     const std::string& exercise) {
    store::Result<console::ReportContext> r;
    console::ReportContext& c = r.value;
    c.title = exercise.empty() ? std::string(tr("pupitre: the class's attempts"))
                               : strf(tr("pupitre: the class's attempts at %s"), exercise.c_str());
    auto on_class = st.class_server();
    if ((r.error = on_class.error)) return r;
    c.on_server = on_class.value;
    if (c.on_server) {
        if (auto k = st.class_signing_key(); !k.error) c.key = k.value;
    } else if (!console::class_key(false, c.key).empty()) {
        c.key.clear();
    }
    for (const store::Attempt& a : all) {
        if (c.current.count(a.exercise)) continue;
        training::Exercise e;
        if (console::find_exercise(&st, a.exercise, e).empty())
            c.current[a.exercise] = sha256_hex(e.source);
    }
    return r;
}

int class_report(const ExerciseArgs& a) {
    if (a.words.empty() || a.words[0] != "report" || a.words.size() > 2) {
        std::fputs(tr("pupitre: class report [EXERCISE] [--csv] [--html FILE] [--pdf FILE]\n"),
                   stderr);
        return kUsage;
    }
    const std::string exercise = a.words.size() == 2 ? a.words[1] : "";
    std::unique_ptr<store::Store> st;
    if (int rc = open_store(a.db, st)) return rc;
    auto r = st->attempts(exercise);
    if (r.error) return report(r.error);
    auto context = report_context(*st, r.value, exercise);
    if (context.error) return report(context.error);
    const console::ReportContext& c = context.value;
    // Every output asked for is written (--csv --html F --pdf G: the three),
    // none asked for, the table; what is written to a file is said on the
    // standard error when the standard output carries a report.
    if (a.csv && a.output == "-") {
        std::fputs(tr("pupitre: --csv and --html - would both write to the standard output\n"),
                   stderr);
        return kUsage;
    }
    std::FILE* said = a.csv || a.output == "-" ? stderr : stdout;
    int rc = kOk;
    if (a.csv)
        std::fputs(console::class_report_text(r.value, console::ReportFormat::csv, c).c_str(),
                   stdout);
    if (!a.output.empty()) rc = std::max(rc, report_html(a.output, c, r.value, said));
    if (!a.pdf.empty()) rc = std::max(rc, report_pdf(a.pdf, c, r.value, said));
    if (!a.csv && a.output.empty() && a.pdf.empty())
        std::fputs(console::class_report_text(r.value, console::ReportFormat::table, c).c_str(),
                   stdout);
    return rc;
}

}  // namespace pupitre::cli
