// The Session's attempt at an exercise (issue 16, pupitre-exercise(5)): the
// hidden setup in the workshop, the machine state under the attempt's own
// name in the store, :submit, the report.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cmath>

#include "console/exercise.hpp"
#include "console/session.hpp"
#include "core/i18n.hpp"
#include "core/sha256.hpp"
#include "core/workshop/workshop.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

int64_t wall_ms() {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

// The values the exercise starts with, in the store's units, for a new
// attempt's machine.
std::vector<std::pair<std::string, int64_t>> start_values(const ExerciseRun& x) {
    std::vector<std::pair<std::string, int64_t>> out;
    for (const training::Start& st : x.ex.start) {
        double v = 0;
        if (training::start_value(x.ex, x.truth, st.name, v))
            out.emplace_back(st.name, store::internal_value(st.name, v));
    }
    return out;
}

}  // namespace

std::string Session::start_exercise(const training::Exercise& e, const std::string& student,
                                    const std::string& key) {
    if (!store_) return tr("an exercise needs the store");
    if (e.lathe() != m_.lathe)
        return strf(e.lathe() ? tr("exercise %s is on the lathe: pupitre exercise %s starts it")
                              : tr("exercise %s is on the machining centre: pupitre exercise %s "
                                   "starts it"),
                    e.name.c_str(), e.name.c_str());
    auto x = std::make_unique<ExerciseRun>();
    x->ex = e;
    x->student = student;
    x->key = key;
    x->seed = training::seed_of(e, student, key);
    if (std::string why = training::draw_setup(e, x->seed, x->truth); !why.empty())
        return strf(tr("exercise %s: its setup: %s"), e.name.c_str(), why.c_str());
    x->truth.name = e.name;
    x->truth.description = e.title_here();
    auto open = store_->open_attempt(e.name, student);
    if (open.error) return open.error.message;
    // An attempt begun on another text of the exercise (the teacher changed
    // it since) is left as it was: its truth was drawn from that text.
    if (open.value && open.value->exercise_sha == sha256_hex(e.source)) {
        x->attempt = *open.value;
    } else {
        x->attempt.exercise = e.name;
        x->attempt.exercise_sha = sha256_hex(e.source);
        x->attempt.student = student;
        x->attempt.machine = strf("%s#%s#%s#%lld", m_.name.c_str(), e.name.c_str(), student.c_str(),
                                  (long long)wall_ms());
        if (store::StoreError err = store_->start_attempt(x->attempt)) return err.message;
        auto values = start_values(*x);
        if (!values.empty())
            if (auto r = store_->set_values(x->attempt.machine, values, "exercise " + e.name);
                r.error)
                return r.error.message;
    }
    x->crashes_seen = 0;
    store_key_ = x->attempt.machine;
    if (!e.program.empty()) {
        // The exercise's program becomes the current text of its number; a
        // different text there stays in the program's history, and is named.
        auto r = store_->save(e.program_number, e.program, store::kHead, "exercise " + e.name);
        if (r.error) return r.error.message;
        if (r.value.status == store::SaveStatus::saved && r.value.revision > 1)
            x->program_note = strf(tr("%%%d is now the exercise's; the text it replaced is "
                                      "revision %d (:history %d)"),
                                   e.program_number, r.value.revision - 1, e.program_number);
    }
    exercise_ = std::move(x);
    return {};
}

// The workshop of the attempt: the truth drawn again, the part as the
// store keeps it (scrambled).
std::string Session::exercise_workshop() {
    auto w = std::make_unique<workshop::Workshop>(m_, exercise_->truth, nullptr);
    w->hide_places(true);
    auto r = store_->workshop(store_key_);
    bool fresh = true;
    const std::string part =
        !r.error && r.value ? unscramble(r.value->part, exercise_->seed) : std::string();
    if (!part.empty()) fresh = !w->load_part(part);  // else fresh stock, as built
    workshop_saved_ = fresh ? 0 : w->generation();
    sim_->set_workshop(std::move(w));
    if (fresh) save_workshop();
    return {};
}

bool Session::hidden(const char* what) {
    if (!exercise_ || exercise_->grade) return false;
    say(strf(tr("%s: not during an exercise (the setup is what you must find)"), what), true);
    return true;
}

void Session::note_shim(double mm) {
    if (exercise_) exercise_->ctx.shims.push_back(mm);
}

void Session::note_reading(const std::string& word, double value) {
    if (exercise_ && (word == "dia" || word == "bore")) exercise_->ctx.diameters.push_back(value);
}

bool Session::instrument_allowed(const std::string& word) {
    if (!exercise_ || exercise_->ex.instruments.empty()) return true;
    for (const std::string& i : exercise_->ex.instruments)
        if (i == word) return true;
    std::string list;
    for (const std::string& i : exercise_->ex.instruments) list += (list.empty() ? "" : ", ") + i;
    say(strf(tr("%s: not allowed in this exercise (allowed: %s)"), word.c_str(), list.c_str()),
        true);
    return false;
}

void Session::watch_crashes() {
    const workshop::Workshop* w = sim_->shop();
    if (!exercise_ || exercise_->grade || !w) return;
    const size_t n = w->crashes().size();
    for (size_t i = exercise_->crashes_seen; i < n; ++i) {
        ++exercise_->attempt.crashes;
        if (store_) store_->add_crash(exercise_->attempt.id);
    }
    exercise_->crashes_seen = n;
}

Effect Session::submit_exercise() {
    if (!exercise_) {
        say(tr("no exercise in progress: pupitre exercise NAME starts one"), true);
        return Effect::redraw;
    }
    if (exercise_->grade) {
        show_page(pages::PageId::exercise);
        say(tr("submitted already: the report is on the EXERCISE page"), true);
        return Effect::redraw;
    }
    if (sim_->in_cycle()) {
        say(tr("a program is in cycle"), true);
        return Effect::redraw;
    }
    watch_crashes();
    ExerciseRun& x = *exercise_;
    training::Values found;
    std::string found_text;
    for (const training::Target& t : x.ex.find) {
        double v = 0;
        sim_->interp().get(t.name, v);
        found[t.name] = v;
        found_text += strf("%s=%.4f\n", t.name.c_str(), v);
    }
    training::Context ctx = x.ctx;
    ctx.diameters.insert(ctx.diameters.end(), x.ex.diameters.begin(), x.ex.diameters.end());
    ctx.shims.insert(ctx.shims.end(), x.ex.shims.begin(), x.ex.shims.end());
    store::Attempt& a = x.attempt;
    a.submitted_ms = wall_ms();
    const double seconds = double(a.submitted_ms - a.started_ms) / 1000;
    x.grade = training::grade(x.ex, x.truth, found, ctx, sim_->shop(), a.crashes, seconds);
    if (workshop::Workshop* w = sim_->shop()) w->hide_places(false);  // the truth is out
    x.report = training::report_lines(x.ex, *x.grade);
    a.seed = strf("%016llx", (unsigned long long)x.seed);
    a.score = x.grade->score;
    a.seconds = seconds;
    a.scrapped = x.grade->scrapped;
    a.mistakes.clear();
    for (training::Mistake m : x.grade->mistakes())
        a.mistakes += (a.mistakes.empty() ? "" : " ") + std::string(training::mistake_id(m));
    a.found = found_text;
    a.report.clear();
    for (const std::string& l : x.report) a.report += l + "\n";
    a.signature = sign_attempt(a, x.key);
    if (store::StoreError e = store_->submit_attempt(a))
        say(strf(tr("the grade was not stored: %s"), e.message.c_str()), true);
    else
        say(strf(tr("submitted: %d%%; the report is on the EXERCISE page"), a.score));
    show_page(pages::PageId::exercise);
    return Effect::redraw;
}

// :exercise NAME: checked here (it exists, it is for this kind of machine,
// nothing unsaved), then the console starts again on it.
Effect Session::start_command(std::string_view name) {
    if (exercise_ && !exercise_->grade) {
        say(tr("an exercise is in progress: :submit ends it"), true);
        return Effect::redraw;
    }
    if (sim_->in_cycle()) {
        say(tr("a program is in cycle"), true);
        return Effect::redraw;
    }
    if (editor.is_open() && editor.dirty && !modif) {
        say(strf(tr("%%%d has unsaved changes: :save or :close! first"), editor.number), true);
        return Effect::redraw;
    }
    training::Exercise e;
    if (std::string why = find_exercise(store_.get(), std::string(name), e); !why.empty()) {
        say(why, true);
        return Effect::redraw;
    }
    if (!store_) {
        say(tr("an exercise needs the store"), true);
        return Effect::redraw;
    }
    release_lease();
    restart_exercise = std::string(name);
    quit = true;
    return Effect::quit;
}

Effect Session::exercise_command(std::string_view args) {
    while (!args.empty() && args.front() == ' ') args.remove_prefix(1);
    while (!args.empty() && args.back() == ' ') args.remove_suffix(1);
    if (!args.empty() && args != "show") return start_command(args);
    if (!exercise_) {
        say(tr("no exercise in progress: pupitre exercise NAME starts one"), true);
        return Effect::redraw;
    }
    show_page(pages::PageId::exercise);
    return Effect::redraw;
}

// The EXERCISE page: the task before :submit, the report after.
void Session::exercise_view(pages::View& v) const {
    if (!exercise_) return;
    const ExerciseRun& x = *exercise_;
    v.instruments = &x.ex.instruments;
    using K = pages::ExLine;
    if (x.grade) {
        // The report's lines: its title, the score, the tables' headings,
        // each value or dimension right or wrong, the notes under them.
        for (size_t i = 0; i < x.report.size(); ++i) {
            const std::string& l = x.report[i];
            const bool marked = l.size() > 2 && (l.ends_with(tr("ok")) || l.ends_with(tr("WRONG")));
            K k = i == 0                                    ? K::title
                  : i == 1                                  ? K::heading
                  : marked && l.ends_with(tr("ok"))         ? K::ok
                  : marked || l.rfind("    \u2192", 0) == 0 ? K::wrong
                  : l.rfind("    ", 0) == 0                 ? K::note
                                                            : K::text;
            v.exercise.emplace_back(k, l);
        }
        return;
    }
    v.exercise.emplace_back(K::title,
                            strf(tr("%s: %s"), x.ex.name.c_str(), x.ex.title_here().c_str()));
    const double minutes = double(wall_ms() - x.attempt.started_ms) / 60000;
    std::string clock =
        strf(tr("Student %s, %.0f min since the start"), x.student.c_str(), std::floor(minutes));
    if (x.ex.minutes > 0) clock += strf(tr(" (of %g)"), x.ex.minutes);
    if (x.attempt.crashes > 0) clock += strf(tr(", crashes %d"), x.attempt.crashes);
    v.exercise.emplace_back(K::note, clock);
    for (const std::string& t : x.ex.task_here()) {
        v.exercise.emplace_back(K::text, "");
        v.exercise.emplace_back(K::text, t);
    }
    v.exercise.emplace_back(K::text, "");
    std::string find;
    for (const training::Target& t : x.ex.find)
        find += strf(tr("%s (\u00b1%g)  "), t.name.c_str(), t.tolerance);
    if (!find.empty()) v.exercise.emplace_back(K::heading, tr("To find: ") + find);
    for (const training::Dimension& d : x.ex.dimensions)
        v.exercise.emplace_back(K::heading, strf(tr("Drawing: %s  %.3f (%+.3f %+.3f)"),
                                                 d.spec.c_str(), d.nominal, d.lower, d.upper));
    if (!x.ex.instruments.empty()) {
        std::string list;
        for (const std::string& i : x.ex.instruments) list += " " + i;
        v.exercise.emplace_back(K::note, tr("Instruments (:measure):") + list);
    }
    v.exercise.emplace_back(K::note, tr(":submit when every value is entered"));
}

}  // namespace pupitre::console
