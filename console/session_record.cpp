// The Session and an attempt's record (record.hpp): during an exercise, each
// key's action, line entered, answer and Escape is written with the Sim's
// clock, the notes the replay needs before it; on the teacher's side the
// replay (replay.hpp) feeds the same lines back through the same routing.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cctype>
#include <set>

#include "console/bindings.hpp"
#include "console/exercise_run.hpp"
#include "console/session.hpp"
#include "core/i18n.hpp"

namespace pupitre::console {

namespace {

// Keys that change only what is shown: not recorded.
constexpr std::string_view kViewActions[] = {
    "scroll", "graph-zoom", "graph-pan", "graph-cursor", "graph-fit", "graph-plane", "speed-next"};

bool view_only(std::string_view action) {
    for (std::string_view v : kViewActions)
        if (v == action) return true;
    return false;
}

// The command a line names (":cycle" -> "cycle"), "" for typed text.
std::string_view command_word(std::string_view line) {
    if (line.empty() || line.front() != ':') return {};
    line.remove_prefix(1);
    while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
    return line.substr(0, line.find(' '));
}

bool starts_cycle(const record::Action& a) {
    return (a.verb == record::Verb::key && a.text == "cycle-start") ||
           (a.verb == record::Verb::line && command_word(a.text) == "cycle");
}

// The programs a text may call: its H words (G77 H, G76 H, a spline's H),
// in a comment too. More than it calls costs a program's text, never a run.
void called(std::string_view text, std::vector<int>& out) {
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != 'H' && text[i] != 'h') continue;
        int n = 0;
        size_t j = i + 1;
        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && j < i + 6)
            n = n * 10 + (text[j++] - '0');
        if (j > i + 1) out.push_back(n);
    }
}

}  // namespace

// After the store's programs are in memory: the exercise's program is the
// one the replay starts with too (taken from the exercise at each start).
void Session::begin_record() {
    record::Recorder* r = exercise_ ? exercise_->recorder() : nullptr;
    if (!r) return;
    const int n = exercise_->definition().program_number;
    if (const ProgramText* p = n > 0 ? mem_.find(n) : nullptr) r->programs[n] = program_text(*p);
}

void Session::note_program(record::Recorder& r, int number) {
    const ProgramText* p = mem_.find(number);
    if (!p) return;
    std::string text = program_text(*p);
    if (auto it = r.programs.find(number); it != r.programs.end() && it->second == text) return;
    r.add({.clock = sim_->clock(), .verb = record::Verb::program, .text = text, .a = number});
    r.programs[number] = std::move(text);
}

// Before a Cycle Start: the text of each program it may run that the replay
// does not have as it is here (another console's, the class's library, one
// changed since).
void Session::note_programs_run(record::Recorder& r) {
    std::vector<int> todo;
    const Mode m = sim_->mode();
    if (m != Mode::imd && m != Mode::pom && m != Mode::jog && m != Mode::inc &&
        sim_->selected() >= 0)
        todo.push_back(sim_->selected());
    if (const ProgramText* imd = m == Mode::imd ? sim_->text_of(0) : nullptr)
        called(imd->body(), todo);
    std::set<int> seen;
    while (!todo.empty()) {
        const int n = todo.back();
        todo.pop_back();
        if (!seen.insert(n).second) continue;
        note_program(r, n);
        if (const ProgramText* p = mem_.find(n)) called(p->body(), todo);
    }
}

// A step, after the notes whose state changed since the last one: the
// protection (the store's and the PIN's answer), the program selected (the
// DIR page's cursor runs over this store's list, which the replay's is not).
void Session::note_step(record::Action a) {
    record::Recorder* r = exercise_ ? exercise_->recorder() : nullptr;
    if (!r) return;
    a.clock = sim_->clock();
    if (const int locked = setting_.locked(); r->protect != locked) {
        r->add({.clock = a.clock, .verb = record::Verb::protect, .a = locked});
        r->protect = locked;
    }
    if (const int sel = sim_->selected(); sel != r->selected) {
        if (sel >= 0) {
            note_program(*r, sel);
            r->add({.clock = a.clock, .verb = record::Verb::select, .a = sel});
        }
        r->selected = sel;
    }
    if (starts_cycle(a)) note_programs_run(*r);
    r->add(a);
    if (a.verb != record::Verb::key) exercise_->keep_record(true);
}

void Session::note_key(std::string_view action, std::string_view arg) {
    if (view_only(action)) return;
    note_step({.verb = record::Verb::key, .text = std::string(action), .arg = std::string(arg)});
}

void Session::note_line(std::string_view line) {
    if (command_word(line) == "speed") return;  // the animation only
    note_step({.verb = record::Verb::line, .text = std::string(line)});
}

void Session::resize(int cols, int rows) {
    cols_ = cols, rows_ = rows;
    record::Recorder* r = exercise_ ? exercise_->recorder() : nullptr;
    if (!r || (r->cols == cols && r->rows == rows)) return;
    // Below 80x24 the console takes nothing but :quit; PgUp in EDIT moves by a screen.
    r->add({.clock = sim_->clock(), .verb = record::Verb::size, .a = cols, .b = rows});
    r->cols = cols, r->rows = rows;
}

// ---- the replay ----

// A key's action by name, as on_key runs the binding the key found.
Effect Session::run_action(std::string_view name, std::string_view arg) {
    const Action* a = find_action(name);
    if (!a) {
        say(strf(tr("the record names no action %s"), std::string(name).c_str()), true);
        return Effect::redraw;
    }
    return keyed([&] {
        if (name != "dir-delete") pending_delete_ = -1;
        return a->run(*this, arg);
    });
}

Effect Session::replay(const record::Action& a) {
    using V = record::Verb;
    Effect e = Effect::redraw;
    switch (a.verb) {
        case V::session:
        case V::dia:
        case V::shim:
            return Effect::none;  // the replay's own, and the grade's notes
        case V::size:
            resize(a.a, a.b);
            return e;
        case V::protect:
            setting_.set_locked(a.a != 0);
            return e;
        case V::program:
            if (const ProgramText* p = mem_.find(a.a); !p || program_text(*p) != a.text) {
                mem_.replace(a.a, "record:%" + std::to_string(a.a), a.text);
                sim_->invalidate_text_cache();
            }
            return e;
        case V::select:
            if (sim_->selected() != a.a && mem_.find(a.a)) sim_->select(a.a);
            return e;
        case V::key:
            e = run_action(a.text, a.arg);
            break;
        case V::line:
            input_.clear();  // what Enter sends, the line leaves
            e = keyed([&] { return submit(a.text); });
            break;
        case V::answer:
            answer(a.a != 0);
            swallow_enter_ = true;
            break;
        case V::escape:
            e = cancel_input();
            break;
    }
    check_run_end();  // as the next frame would
    if (exercise_) exercise_->watch_crashes();
    return e;
}

void Session::run_to(double clock) {
    for (int guard = 0; guard < 200000 && busy(); ++guard) {
        const double before = sim_->clock();
        const long blocks = sim_->blocks_done();
        const RunState state = sim_->state();
        if (sim_->mode() == Mode::test)
            sim_->advance(0, 50000);  // TEST moves nothing: its clock stands
        else if (before < clock)
            sim_->advance(clock - before, 20000);
        else
            break;
        check_run_end();
        if (exercise_) exercise_->watch_crashes();
        if (sim_->clock() == before && sim_->blocks_done() == blocks && sim_->state() == state)
            break;  // the feed override at 0: the axes wait
    }
}

}  // namespace pupitre::console
