// pupitre run / pupitre check: load the programs, seed the machine, dry-run.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <charconv>
#include <cstdio>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

#include "console/cli.hpp"
#include "console/part_paper.hpp"
#include "console/workshop_io.hpp"
#include "core/i18n.hpp"
#include "core/interp/interp.hpp"
#include "core/output/summary.hpp"
#include "core/output/trace.hpp"
#include "core/plan/plan_thread.hpp"
#include "core/workshop/report.hpp"

namespace pupitre::cli {

void print_diag(const Diag& d) {
    std::string s = format_diag(d);
    s += '\n';
    std::fputs(s.c_str(), stderr);
}

bool load_machine(const std::string& name, MachineProfile& m) {
    if (builtin_machine(name, m)) return true;
    std::ifstream in(name);
    if (!in) {
        std::fprintf(stderr,
                     tr("pupitre: unknown machine '%s' (lathe, mill, mill4, mill5, cazeneuve, or a "
                        ".machine file)\n"),
                     name.c_str());
        return false;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    std::string err = parse_machine(ss.str(), m);
    if (!err.empty()) {
        // TRANSLATORS: the machine file, then what is wrong in it.
        std::fprintf(stderr, tr("pupitre: %s: %s\n"), name.c_str(), err.c_str());
        return false;
    }
    return true;
}

// Loads every file; returns an exit code (0 on success).
int load_all(const std::vector<std::string>& files, ProgramMemory& mem) {
    for (const auto& f : files) {
        if (std::optional<Diag> d = mem.load_file(f)) {
            print_diag(*d);
            return d->code == err::kCannotRead ? kNoInput : kDataErr;
        }
    }
    for (const Diag& w : mem.warnings()) print_diag(w);
    return kOk;
}

int apply_sets(const std::vector<std::string>& sets, Interpreter& in) {
    for (const auto& s : sets) {
        size_t eq = s.find('=');
        double v = 0;
        bool ok = eq != std::string::npos && eq > 0;
        if (ok) {
            std::string_view val(s.c_str() + eq + 1);
            auto r = std::from_chars(val.data(), val.data() + val.size(), v);
            ok = r.ec == std::errc() && r.ptr == val.data() + val.size();
        }
        if (!ok) {
            std::fprintf(stderr, tr("pupitre: --set %s: expected NAME=VALUE with a number\n"),
                         s.c_str());
            return kUsage;
        }
        std::string why = in.set(std::string_view(s).substr(0, eq), v);
        if (!why.empty()) {
            std::fprintf(stderr, "pupitre: --set %s: %s\n", s.c_str(), why.c_str());
            return kUsage;
        }
    }
    return kOk;
}

namespace {

class NullSink final : public MachineSink {};

}  // namespace

// --setup: a shipped setup's name or a setup file; prints the problem.
bool load_setup(const std::string& name, const MachineProfile& m, workshop::Setup& s) {
    std::string why = read_setup(name, m, s);
    if (!why.empty()) std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
    return why.empty();
}

namespace {

// The file a program came from, for a diagnostic found outside the interpreter.
void place(Diag& d, const ProgramMemory& mem) {
    d.file = "-";
    for (const auto& p : mem.programs())
        if (p->number == d.program) {
            d.file = p->file;
            break;
        }
}

// Runs to the end, an error or a stop; with a workshop, also to its crash,
// where the machine stops (pupitre-setup(5)).
void run_in(Interpreter& in, const workshop::Workshop* shop) {
    if (!shop) {
        in.run_to_end();
        return;
    }
    for (StepResult r = StepResult::running;
         !shop->crashed() && (r == StepResult::running || r == StepResult::stopped);)
        r = in.step();
}

// The crashes as diagnostics (printed), and the readings asked for.
void workshop_results(const workshop::Workshop& shop, const ProgramMemory& mem,
                      const std::vector<std::string>& measures, std::vector<Diag>& crashes,
                      std::vector<workshop::Asked>& asked) {
    for (const workshop::Crash& c : shop.crashes()) {
        crashes.push_back(workshop::crash_diag(c));
        place(crashes.back(), mem);
        print_diag(crashes.back());
    }
    for (const std::string& spec : measures) {
        asked.emplace_back();
        asked.back().error = shop.measure(spec, asked.back().r);
    }
}

// The program run and check run: the first one of the file; null if the file
// has none.
const ProgramText* first_program(const ProgramMemory& mem, const std::string& file) {
    for (const auto& p : mem.programs())
        if (p->file == file) return p.get();
    return nullptr;
}

// The summary on stdout: JSON, else the text one unless the trace took its
// place; the workshop's crashes and readings with it.
void print_summary(const RunArgs& a, const Interpreter& in, const workshop::Workshop* shop,
                   const std::vector<Diag>& crashes, const std::vector<workshop::Asked>& asked,
                   const PlanSummary& plan) {
    if (a.json) {
        std::string s = summary_json(in, a.files.front(), crashes,
                                     shop ? workshop::workshop_json(*shop, asked) : "", plan);
        std::fputs(s.c_str(), stdout);
    } else if (!a.trace) {
        std::string s = summary_text(in, a.files.front(), plan) + workshop::readings_text(asked);
        std::fputs(s.c_str(), stdout);
    }
}

// check's dry run of the first file's first program: its diagnostics
// printed, their lines in `reported`. An exit code.
int dry_run_first(const RunArgs& a, const MachineProfile& m, ProgramMemory& mem, RunStore& store,
                  std::set<std::pair<std::string, int>>& reported, bool& errors) {
    const ProgramText* main = first_program(mem, a.files.front());
    if (!main) return kOk;
    NullSink quiet;
    RunOptions o;
    o.block_skip = a.block_skip;
    o.max_blocks = a.max_blocks;
    Interpreter in(m, mem, quiet, o);
    if (!a.db.empty())
        if (int rc = store.seed(in)) return rc;
    if (int rc = apply_sets(a.sets, in)) return rc;
    in.start(main);
    in.run_to_end();
    for (const Diag& d : in.diags()) {
        print_diag(d);
        reported.insert({d.file, d.line});
        errors = errors || d.is_error();
    }
    return kOk;
}

// check parses every line of the files given: a block that does not parse
// and had no diagnostic from the dry run gets a warning.
void warn_unreached(const RunArgs& a, const ProgramMemory& mem,
                    const std::set<std::pair<std::string, int>>& reported) {
    // Stored programs are program memory, not what is being checked.
    std::set<std::string> files(a.files.begin(), a.files.end());
    Block b;
    for (const auto& p : mem.programs()) {
        if (!files.count(p->file)) continue;
        std::string_view body = p->body();
        int line = p->first_line;
        size_t pos = 0;
        while (pos < body.size()) {
            size_t eol = body.find('\n', pos);
            if (eol == std::string_view::npos) eol = body.size();
            Error e = parse_block(body.substr(pos, eol - pos), b);
            if (e && !reported.count({p->file, line})) {
                Diag d = diag_of(e, Severity::warning);
                d.file = p->file;
                d.program = p->number;
                d.line = line;
                d.n = line_label(body.substr(pos, eol - pos));
                d.detail = strf(tr("%s (in a block the dry run did not reach)"), d.detail.c_str());
                print_diag(d);
            }
            pos = eol + 1;
            ++line;
        }
    }
}

// --part-out: the picture on a sheet (part_paper.hpp), or the part as
// write_part writes it.
Answer<int> part_out(const RunArgs& a, const workshop::Workshop& w, const Interpreter& in,
                     const ProgramMemory& mem) {
    const bool mill = w.is_mill();
    if (!wants_picture(a.part_out, mill, !a.part_view.empty()))
        return write_part(a.part_out, w, a.files.front());
    render::Look look;
    look.mode = render::first_mode(mill);
    if (!a.part_view.empty()) render::parse_mode(a.part_view, look.mode);
    PaperTitle t;
    t.title = a.files.front();
    if (const ProgramText* p = first_program(mem, a.files.front()))
        t.title = "%" + std::to_string(p->number) + (p->title.empty() ? "" : " " + p->title);
    t.where = strf(tr("setup %s, machine %s"), w.setup().name.c_str(), w.machine().name.c_str());
    return write_part_picture(a.part_out, w, in.machine_pos(), nullptr, look, t);
}

}  // namespace

void default_machine_note(const std::string& asked, bool errors) {
    if (asked.empty() && errors)
        std::fprintf(stderr,
                     tr("pupitre: ran on the %s, the default machine (--machine mill for a "
                        "machining centre)\n"),
                     kDefaultMachine);
}

int run(const RunArgs& a) {
    // The JSON summary holds the diagnostics' messages: machine-readable output
    // does not change with the language, so a --json run speaks English
    // throughout, its diagnostics on stderr included (pupitre(1), --lang).
    if (a.json) i18n::use_english();
    MachineProfile m;
    const std::string machine = batch_machine(a.machine);
    if (!load_machine(machine, m)) return kUsage;
    workshop::Setup setup;
    if (a.setup.empty() && (!a.measures.empty() || !a.part_out.empty())) {
        std::fprintf(stderr, tr("pupitre: --measure and --part-out need a --setup\n"));
        return kUsage;
    }
    if (!a.setup.empty() && !load_setup(a.setup, m, setup)) return kUsage;
    if (std::string why = part_name_problem(a.part_out, a.part_view, setup); !why.empty()) {
        std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());  // before the run, not after it
        return kUsage;
    }
    PlanSummary plan;
    for (const std::string& life : a.edge_life)
        if (std::string why = plan::read_edge_life(life, plan.life); !why.empty()) {
            std::fprintf(stderr, tr("pupitre: --edge-life %s: %s\n"), life.c_str(), why.c_str());
            return kUsage;
        }
    plan.life = edge_life(setup, plan.life);
    ProgramMemory mem;
    if (int rc = load_all(a.files, mem)) return rc;
    RunStore store;
    if (!a.db.empty()) {
        if (int rc = store.open(a.db)) return rc;
        if (int rc = store.load_programs(mem)) return rc;
    }
    static char outbuf[1 << 16];
    std::setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);
    TraceWriter trace(stdout, m);
    NullSink quiet;
    // The planner hears what the machine does (after the workshop, which
    // stops it at a crash) and hands the trace each move with its times.
    plan::PlanSink planner(m, a.trace ? &trace : nullptr);
    // Without a trace nothing reads the plan's times before the summary: the
    // planner then runs on a thread of its own, beside the interpreter.
    std::unique_ptr<plan::PlanThread> apart;
    if (!a.no_plan && !a.trace) apart = std::make_unique<plan::PlanThread>(m);
    if (!a.no_plan && a.trace) trace.follow(&planner.clock());
    MachineSink& out = a.no_plan ? (a.trace ? static_cast<MachineSink&>(trace) : quiet)
                       : apart   ? static_cast<MachineSink&>(*apart)
                                 : planner;
    std::unique_ptr<workshop::Workshop> shop;
    if (!a.setup.empty()) shop = std::make_unique<workshop::Workshop>(m, setup, &out);
    RunOptions o;
    o.block_skip = a.block_skip;
    o.optional_stop = a.optional_stop;
    o.max_blocks = a.max_blocks;
    Interpreter in(m, mem, shop ? static_cast<MachineSink&>(*shop) : out, o);
    if (!a.db.empty())
        if (int rc = store.seed(in)) return rc;
    if (int rc = apply_sets(a.sets, in)) return rc;
    in.start(first_program(mem, a.files.front()));
    run_in(in, shop.get());
    planner.finish();
    if (apart) apart->finish();
    if (!a.no_plan) plan.report = apart ? &apart->report() : &planner.report();
    std::fflush(stdout);
    for (const Diag& d : in.diags()) print_diag(d);
    std::vector<Diag> crashes;
    std::vector<workshop::Asked> asked;
    if (shop) workshop_results(*shop, mem, a.measures, crashes, asked);
    const bool errors = in.has_errors() || !crashes.empty();
    default_machine_note(a.machine, errors);
    print_summary(a, in, shop.get(), crashes, asked, plan);
    std::fflush(stdout);
    if (shop && !a.part_out.empty())
        if (auto [rc, why] = part_out(a, *shop, in, mem); rc != 0) {
            std::fprintf(stderr, tr("pupitre: %s\n"), why.c_str());
            return rc;
        }
    // What the program wrote into correctors and origins stays, as on the NUM.
    if (!a.db.empty())
        if (int rc = store.persist(in, a.files.front(), machine)) return rc;
    return errors ? kProgramErrors : kOk;
}

int check(const RunArgs& a) {
    MachineProfile m;
    if (!load_machine(batch_machine(a.machine), m)) return kUsage;
    ProgramMemory mem;
    if (int rc = load_all(a.files, mem)) return rc;
    RunStore store;  // check stores nothing back: no persist
    if (!a.db.empty()) {
        if (int rc = store.open(a.db)) return rc;
        if (int rc = store.load_programs(mem)) return rc;
    }
    bool errors = false;
    std::set<std::pair<std::string, int>> reported;
    // 1. A dry run of the first file's first program, as `run` does; the other
    // files are program memory (subprograms need no M02 of their own).
    if (int rc = dry_run_first(a, m, mem, store, reported, errors)) return rc;
    // 2. Every other block must parse too. A block the dry run did not reach gets a
    // warning: the controller would only meet it on another path.
    warn_unreached(a, mem, reported);
    default_machine_note(a.machine, errors);
    return errors ? kProgramErrors : kOk;
}

}  // namespace pupitre::cli
