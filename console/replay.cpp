// The replay of an attempt (see replay.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/replay.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "console/exercise_run.hpp"
#include "console/session.hpp"
#include "core/i18n.hpp"

namespace pupitre::console {

namespace {

// A directory of its own for the scratch store, under $TMPDIR.
std::string scratch_dir() {
    const char* t = std::getenv("TMPDIR");
    std::string tmpl = std::string(t && *t ? t : "/tmp") + "/pupitre-replay-XXXXXX";
    return mkdtemp(tmpl.data()) ? tmpl : std::string();
}

// Past a line's time by a microsecond: its clock is written to the
// microsecond, and the replay's frames fall elsewhere than the console's,
// so a run that ended at that time has ended here too.
constexpr double kPast = 1e-6;

}  // namespace

Answer<std::unique_ptr<Replay>> Replay::open(const training::Exercise& e, const store::Attempt& a) {
    std::unique_ptr<Replay> r(new Replay);
    r->e_ = e;
    r->a_ = a;
    if (!builtin_machine(e.machine, r->m_))
        return {nullptr, strf(tr("no machine %s"), e.machine.c_str())};
    char* end = nullptr;
    r->seed_ = std::strtoull(a.seed.c_str(), &end, 16);
    if (a.seed.empty() || *end) return {nullptr, tr("the attempt has no seed")};
    r->problem_ = record::parse(a.record, r->lines_);
    // A record before version 1 (or none): nothing the operator did is known.
    if (r->lines_.empty() || r->lines_.front().verb != record::Verb::session) {
        std::erase_if(r->lines_, [](const record::Action& x) { return x.step(); });
        r->lines_.insert(r->lines_.begin(), record::Action{.verb = record::Verb::session});
    }
    if (std::string why = r->rewind(1); !why.empty()) return {nullptr, why};
    return {std::move(r), {}};
}

Replay::~Replay() {
    s_.reset();
    input_.reset();
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
}

size_t Replay::steps_done() const {
    size_t n = 0;
    for (size_t i = 0; i < done_; ++i) n += lines_[i].step();
    return n;
}

size_t Replay::steps() const {
    size_t n = 0;
    for (const record::Action& a : lines_) n += a.step();
    return n;
}

const ExerciseRun& Replay::run() const {
    return *s_->exercise();
}

// A console starts on the attempt, as app.cpp starts one: the exercise on
// the store (its program, the values it starts with, or those the last
// console left), the store read, the exercise's program selected.
std::string Replay::begin_session() {
    s_.reset();
    input_ = std::make_unique<PlainLineInput>();
    store::Options o;
    o.seed = false;
    o.user = "replay";
    auto st = store::Store::open(dir_ + "/replay.db", o);
    if (st.error) return st.error.message;
    s_ = std::make_unique<Session>(m_, std::move(st.value), *input_);
    if (std::string why = s_->start_replay(e_, seed_, a_); !why.empty()) {
        s_.reset();
        return why;
    }
    s_->load_store();
    if (e_.program_number > 0 && s_->memory().find(e_.program_number))
        s_->sim().select(e_.program_number);
    s_->show_page(pages::PageId::exercise);
    ++sessions_;
    return {};
}

void Replay::apply(const record::Action& a) {
    if (a.verb == record::Verb::session) {
        if (std::string why = begin_session(); !why.empty()) {
            problem_ = why;
            done_ = lines_.size();  // nothing more can run
        }
    } else {
        s_->run_to(a.clock + kPast);
        s_->replay(a);
    }
    follow_mistakes();
}

// After each line: the mistake each value would be graded with now, and
// since which line it has held.
void Replay::follow_mistakes() {
    const ExerciseRun* x = s_ ? s_->exercise() : nullptr;
    if (!x || x->grade()) return;
    for (const training::ItemGrade& it : x->grade_values().items) {
        const std::string id = training::mistake_id(it.mistake);
        auto h = std::find_if(held_.begin(), held_.end(),
                              [&](const Named& n) { return n.value == it.name; });
        if (h == held_.end())
            held_.push_back({it.name, id, "", done_});
        else if (h->mistake != id)
            *h = {it.name, id, "", done_};
    }
}

void Replay::step() {
    while (!at_end()) {
        const record::Action& a = lines_[done_++];
        apply(a);
        if (a.step()) break;
    }
}

void Replay::run_to_end() {
    while (!at_end()) step();
    if (!s_ || !s_->exercise()) return;
    ExerciseRun& x = *s_->exercise();
    if (!x.grade()) x.grade_now();
    named_.clear();
    for (const training::ItemGrade& it : x.grade()->items) {
        if (it.mistake == training::Mistake::none) continue;
        const std::string id = training::mistake_id(it.mistake);
        size_t line = done_;
        for (const Named& h : held_)
            if (h.value == it.name && h.mistake == id) line = h.line;
        named_.push_back({it.name, id, training::mistake_title(it.mistake), line});
    }
}

std::string Replay::rewind(size_t lines) {
    s_.reset();
    input_.reset();
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
    dir_ = scratch_dir();
    if (dir_.empty()) return tr("no directory for the replay's store (TMPDIR)");
    done_ = 0;
    sessions_ = 0;
    held_.clear();
    while (done_ < lines && !at_end()) apply(lines_[done_++]);
    if (!s_) return problem_.empty() ? tr("the replay did not start") : problem_;
    return {};
}

}  // namespace pupitre::console
