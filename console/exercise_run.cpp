// The exercise run (see exercise_run.hpp): the hidden setup in the workshop,
// the machine state under the attempt's own name in the store, :submit, the
// report.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/exercise_run.hpp"

#include <algorithm>
#include <cmath>

#include "console/exercise.hpp"
#include "console/wall_clock.hpp"
#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "core/workshop/workshop.hpp"
#include "store/link.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

// The values the exercise starts with, in the store's units, for a new
// attempt's machine.
std::vector<std::pair<std::string, int64_t>> start_values(const training::Exercise& ex,
                                                          const workshop::Setup& truth) {
    std::vector<std::pair<std::string, int64_t>> out;
    for (const training::Start& st : ex.start) {
        double v = 0;
        if (training::start_value(ex, truth, st.name, v))
            out.emplace_back(st.name, store::internal_value(st.name, v));
    }
    return out;
}

}  // namespace

// A new attempt's machine gets the values the exercise starts from: "", else
// why the store refused them.
std::string ExerciseRun::set_start_values() {
    auto values = start_values(ex_, truth_);
    if (values.empty()) return {};
    auto r = b_.store()->set_values(attempt_.machine, values, "exercise " + ex_.name);
    return r.error ? r.error.message : std::string();
}

Answer<std::unique_ptr<ExerciseRun>> ExerciseRun::open(Bench& b, const training::Exercise& e,
                                                       const std::string& student,
                                                       const std::string& key) {
    store::Store* st = b.store();
    const MachineProfile& m = b.machine();
    if (!st) return {nullptr, tr("an exercise needs the store")};
    if (e.lathe() != m.lathe)
        return {nullptr,
                strf(e.lathe() ? tr("exercise %s is on the lathe: pupitre exercise %s starts it")
                               : tr("exercise %s is on the machining centre: pupitre exercise %s "
                                    "starts it"),
                     e.name.c_str(), e.name.c_str())};
    auto on_class = st->class_server();
    if (on_class.error) return {nullptr, on_class.error.message};
    auto x = on_class.value ? open_on_class(b, e)
                            : open_local(b, e, student, training::seed_of(e, student, key));
    if (x.value) {
        x.value->key_ = key;
        x.value->rec_.begin(x.value->attempt_.record);
    }
    return x;
}

Answer<std::unique_ptr<ExerciseRun>> ExerciseRun::open_replay(Bench& b, const training::Exercise& e,
                                                              uint64_t seed,
                                                              const store::Attempt& a) {
    if (!b.store()) return {nullptr, tr("an exercise needs the store")};
    auto x = open_local(b, e, a.student, seed);
    if (x.value) {
        x.value->replay_ = true;
        x.value->replay_seconds_ = a.seconds;
        x.value->replay_crashes_ = a.crashes;
    }
    return x;
}

// On a store file: the attempt of `student` open at this text of the
// exercise, else a new one with the exercise's values at the start.
Answer<std::unique_ptr<ExerciseRun>> ExerciseRun::open_local(Bench& b, const training::Exercise& e,
                                                             const std::string& student,
                                                             uint64_t seed) {
    store::Store* st = b.store();
    auto x = std::make_unique<ExerciseRun>(b);
    x->ex_ = e;
    x->student_ = student;
    x->seed_ = seed;
    if (std::string why = training::draw_setup(e, x->seed_, x->truth_); !why.empty())
        return {nullptr, strf(tr("exercise %s: its setup: %s"), e.name.c_str(), why.c_str())};
    x->truth_.name = e.name;
    x->truth_.description = e.title_here();
    auto open = st->open_attempt(e.name, student);
    if (open.error) return {nullptr, open.error.message};
    // An attempt begun on another text of the exercise (the teacher changed
    // it since) is left as it was: its truth was drawn from that text.
    store::Attempt& a = x->attempt_;
    if (open.value && open.value->exercise_sha == sha256_hex(e.source)) {
        a = *open.value;
    } else {
        a.exercise = e.name;
        a.exercise_sha = sha256_hex(e.source);
        a.student = student;
        a.machine = strf("%s#%s#%s#%lld", b.machine().name.c_str(), e.name.c_str(), student.c_str(),
                         (long long)wall_ms());
        if (store::StoreError err = st->start_attempt(a)) return {nullptr, err.message};
        if (std::string why = x->set_start_values(); !why.empty()) return {nullptr, why};
    }
    x->crashes_seen_ = 0;
    return {std::move(x), {}};
}

// On a class's server: the server opens the attempt (this login's open one,
// else a new one) and draws its seed; the truth comes from that seed.
Answer<std::unique_ptr<ExerciseRun>> ExerciseRun::open_on_class(Bench& b,
                                                                const training::Exercise& e) {
    store::Store* st = b.store();
    auto x = std::make_unique<ExerciseRun>(b);
    x->ex_ = e;
    x->on_class_ = true;
    const std::string machine =
        strf("%s#%s#%lld", b.machine().name.c_str(), e.name.c_str(), (long long)wall_ms());
    auto open = st->open_class_attempt(e.name, machine);
    if (open.error) return {nullptr, open.error.message};
    store::Attempt& a = x->attempt_;
    a = open.value;
    x->student_ = a.student;
    if (a.exercise_sha != sha256_hex(e.source))
        return {nullptr, strf(tr("exercise %s changed on the server as it was opened: start again"),
                              e.name.c_str())};
    x->seed_ = std::stoull(a.seed, nullptr, 16);
    if (std::string why = training::draw_setup(e, x->seed_, x->truth_); !why.empty())
        return {nullptr, strf(tr("exercise %s: its setup: %s"), e.name.c_str(), why.c_str())};
    x->truth_.name = e.name;
    x->truth_.description = e.title_here();
    if (st->machine_shown(a.machine) == machine) {  // a new attempt: its starting values
        if (std::string why = x->set_start_values(); !why.empty()) return {nullptr, why};
    }
    x->crashes_seen_ = 0;
    return {std::move(x), {}};
}

std::string ExerciseRun::take_program() {
    if (ex_.program.empty()) return {};
    // The exercise's program becomes the current text of its number; a
    // different text there stays in the program's history, and is named.
    auto r =
        b_.store()->save(ex_.program_number, ex_.program, store::kHead, "exercise " + ex_.name);
    if (r.error) return r.error.message;
    if (r.value.status == store::SaveStatus::saved && r.value.revision > 1)
        program_note_ = strf(tr("%%%d is now the exercise's; the text it replaced is "
                                "revision %d (:history %d)"),
                             ex_.program_number, r.value.revision - 1, ex_.program_number);
    return {};
}

// The truth drawn again, the part as the store keeps it (scrambled).
std::unique_ptr<workshop::Workshop> ExerciseRun::workshop(bool& fresh) const {
    auto w = std::make_unique<workshop::Workshop>(b_.machine(), truth_, nullptr);
    w->hide_places(true);
    auto r = b_.store()->workshop(b_.store_key());
    fresh = true;
    const std::string part = !r.error && r.value ? unscramble(r.value->part, seed_) : std::string();
    if (!part.empty()) fresh = !w->load_part(part);  // else fresh stock, as built
    return w;
}

std::string ExerciseRun::stored_part(const std::string& part) const {
    return scramble(part, seed_);
}

bool ExerciseRun::hidden(const char* what) {
    if (grade_) return false;
    b_.say(strf(tr("%s: not during an exercise (the setup is what you must find)"), what), true);
    return true;
}

// Beside the action in the record: what the grade's mistakes read.
void ExerciseRun::note_shim(double mm) {
    ctx_.shims.push_back(mm);
    if (record::Recorder* r = recorder()) {
        record::Action a;
        a.clock = b_.sim().clock();
        a.verb = record::Verb::shim;
        a.value = mm;
        r->add(a);
    }
}

void ExerciseRun::note_reading(const std::string& word, double value) {
    if (word != "dia" && word != "bore") return;
    ctx_.diameters.push_back(value);
    if (record::Recorder* r = recorder()) {
        record::Action a;
        a.clock = b_.sim().clock();
        a.verb = record::Verb::dia;
        a.value = value;
        r->add(a);
    }
}

bool ExerciseRun::instrument_allowed(const std::string& word) {
    if (ex_.instruments.empty()) return true;
    for (const std::string& i : ex_.instruments)
        if (i == word) return true;
    std::string list;
    for (const std::string& i : ex_.instruments) list += (list.empty() ? "" : ", ") + i;
    b_.say(strf(tr("%s: not allowed in this exercise (allowed: %s)"), word.c_str(), list.c_str()),
           true);
    return false;
}

void ExerciseRun::watch_crashes() {
    const workshop::Workshop* w = b_.sim().shop();
    if (grade_ || !w) return;
    const size_t n = w->crashes().size();
    for (size_t i = crashes_seen_; i < n; ++i) {
        ++attempt_.crashes;
        if (b_.store()) b_.store()->add_crash(attempt_.id);
    }
    crashes_seen_ = n;
}

// The values to find as the machine holds them ("NAME=VALUE" lines in `text`).
training::Values ExerciseRun::found_values(std::string* text) const {
    training::Values found;
    for (const training::Target& t : ex_.find) {
        double v = 0;
        b_.sim().interp().get(t.name, v);
        found[t.name] = v;
        if (text) *text += strf("%s=%.4f\n", t.name.c_str(), v);
    }
    return found;
}

training::Context ExerciseRun::context() const {
    training::Context ctx = ctx_;
    ctx.diameters.insert(ctx.diameters.end(), ex_.diameters.begin(), ex_.diameters.end());
    ctx.shims.insert(ctx.shims.end(), ex_.shims.begin(), ex_.shims.end());
    return ctx;
}

training::Grade ExerciseRun::grade_values() const {
    return training::grade(ex_, truth_, found_values(nullptr), context(), nullptr, 0, 0);
}

// The grade of what the machine and the workshop hold now, in the attempt's
// fields; the truth is out.
void ExerciseRun::grade_now() {
    watch_crashes();
    std::string found_text;
    const training::Values found = found_values(&found_text);
    store::Attempt& a = attempt_;
    a.submitted_ms = wall_ms();
    const double seconds = replay_ ? replay_seconds_ : double(a.submitted_ms - a.started_ms) / 1000;
    // The server counted the crashes as they came: a record that lost some
    // (a console killed) does not lower them.
    if (replay_) a.crashes = std::max(a.crashes, replay_crashes_);
    grade_ = training::grade(ex_, truth_, found, context(), b_.sim().shop(), a.crashes, seconds);
    if (workshop::Workshop* w = b_.sim().shop()) w->hide_places(false);  // the truth is out
    report_ = training::report_lines(ex_, *grade_);
    a.seed = strf("%016llx", (unsigned long long)seed_);
    a.score = grade_->score;
    a.seconds = seconds;
    a.scrapped = grade_->scrapped;
    a.mistakes.clear();
    for (training::Mistake m : grade_->mistakes())
        a.mistakes += (a.mistakes.empty() ? "" : " ") + std::string(training::mistake_id(m));
    a.found = found_text;
    a.report.clear();
    for (const std::string& l : report_) a.report += l + "\n";
    if (!replay_) a.record = rec_.text();
}

Effect ExerciseRun::submit() {
    if (grade_) {
        b_.show_page(pages::PageId::exercise);
        b_.say(tr("submitted already: the report is on the EXERCISE page"), true);
        return Effect::redraw;
    }
    if (b_.sim().in_cycle()) {
        b_.say(tr("a program is in cycle"), true);
        return Effect::redraw;
    }
    grade_now();
    store::Attempt& a = attempt_;
    b_.show_page(pages::PageId::exercise);
    if (replay_) {
        b_.say(strf(tr("submitted: %d%% (the replay's grade)"), a.score));
        return Effect::redraw;
    }
    if (on_class_) {
        // The teacher's side grades it again by replaying the record, and
        // signs: this is provisional.
        if (store::StoreError e = b_.store()->submit_class_attempt(a); e.gone) {
            b_.keep_submission(a, true);
            b_.say(strf(tr("submitted: %d%%; the server does not answer: kept here until it does"),
                        a.score),
                   true);
        } else if (e) {
            b_.say(strf(tr("the grade was not stored: %s"), e.message.c_str()), true);
        } else {
            b_.say(strf(tr("submitted: %d%% (provisional: the teacher's grading signs it); the "
                           "report is on the EXERCISE page"),
                        a.score));
        }
        b_.show_page(pages::PageId::exercise);
        return Effect::redraw;
    }
    a.signature = sign_attempt(a, key_);
    if (store::StoreError e = b_.store()->submit_attempt(a); e.gone) {
        b_.keep_submission(a, false);
        b_.say(strf(tr("submitted: %d%%; the server does not answer: kept here until it does"),
                    a.score),
               true);
    } else if (e)
        b_.say(strf(tr("the grade was not stored: %s"), e.message.c_str()), true);
    else
        b_.say(strf(tr("submitted: %d%%; the report is on the EXERCISE page"), a.score));
    return Effect::redraw;
}

// The record so far, kept where the attempt is: a console stopped (or
// killed) and started again takes it up, and the teacher's view sees it
// grow. A server out of reach is tried again at the next call.
void ExerciseRun::keep_record(bool now) {
    if (replay_ || grade_ || !rec_.changed() || !b_.store()) return;
    const int64_t t = wall_ms();
    if (!now && t - record_kept_ms_ < 2000) return;
    record_kept_ms_ = t;
    if (store::StoreError e = b_.store()->keep_record(attempt_.id, rec_.text())) {
        if (!e.gone && !record_refused_)
            b_.say(strf(tr("the record was not stored (:submit sends it): %s"), e.message.c_str()),
                   true);
        record_refused_ = !e.gone;
        return;
    }
    rec_.kept();
}

// The EXERCISE page: the task before :submit, the report after.
void ExerciseRun::view(pages::View& v) const {
    v.instruments = &ex_.instruments;
    using K = pages::ExLine;
    if (grade_) {
        // The report's lines: its title, the score, the tables' headings,
        // each value or dimension right or wrong, the notes under them.
        for (size_t i = 0; i < report_.size(); ++i) {
            const std::string& l = report_[i];
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
                            strf(tr("%s: %s"), ex_.name.c_str(), ex_.title_here().c_str()));
    const double minutes = double(wall_ms() - attempt_.started_ms) / 60000;
    std::string clock = replay_ ? strf(tr("Student %s, the attempt replayed"), student_.c_str())
                                : strf(tr("Student %s, %.0f min since the start"), student_.c_str(),
                                       std::floor(minutes));
    if (ex_.minutes > 0 && !replay_) clock += strf(tr(" (of %g)"), ex_.minutes);
    if (attempt_.crashes > 0) clock += strf(tr(", crashes %d"), attempt_.crashes);
    v.exercise.emplace_back(K::note, clock);
    for (const std::string& t : ex_.task_here()) {
        v.exercise.emplace_back(K::text, "");
        v.exercise.emplace_back(K::text, t);
    }
    v.exercise.emplace_back(K::text, "");
    std::string find;
    for (const training::Target& t : ex_.find)
        find += strf(tr("%s (\u00b1%g)  "), t.name.c_str(), t.tolerance);
    if (!find.empty()) v.exercise.emplace_back(K::heading, tr("To find: ") + find);
    for (const training::Dimension& d : ex_.dimensions)
        v.exercise.emplace_back(K::heading, strf(tr("Drawing: %s  %.3f (%+.3f %+.3f)"),
                                                 d.spec.c_str(), d.nominal, d.lower, d.upper));
    if (!ex_.instruments.empty()) {
        std::string list;
        for (const std::string& i : ex_.instruments) list += " " + i;
        v.exercise.emplace_back(K::note, tr("Instruments (:measure):") + list);
    }
    v.exercise.emplace_back(K::note, tr(":submit when every value is entered"));
}

}  // namespace pupitre::console
