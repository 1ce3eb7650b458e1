// pupitre: entry point and command line (pupitre(1), OPTIONS).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string_view>

#include "console/cli.hpp"
#include "console/cli_plot.hpp"
#include "core/i18n.hpp"
#include "core/interp/machine.hpp"

using namespace pupitre;

namespace {
// A program number as typed: 300 or %300.
bool parse_number(std::string s, int& n) {
    if (!s.empty() && s[0] == '%') s.erase(0, 1);
    auto r = std::from_chars(s.data(), s.data() + s.size(), n);
    return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size() && n >= 0;
}
// Where the catalogues are: $PUPITRE_LOCALEDIR, else locale/ beside the
// executable (the build tree, so that scripts/run needs no install), else the
// installed share/locale.
std::string locale_dir() {
    if (const char* d = std::getenv("PUPITRE_LOCALEDIR"); d && *d) return d;
    std::error_code ec;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        auto here = exe.parent_path() / "locale";
        if (std::filesystem::is_directory(here, ec)) return here.string();
    }
    return PUPITRE_LOCALEDIR;
}

// --lang is read before the command line is built, so that its help is
// already in the chosen language. Returns false (and says why) on an unknown
// language.
bool setup_language(int argc, char** argv) {
    std::string want;
    for (int i = 1; i < argc; ++i) {
        std::string_view a = argv[i];
        if (a == "--") break;
        if (a == "--lang" && i + 1 < argc)
            want = argv[i + 1];
        else if (a.starts_with("--lang="))
            want = std::string(a.substr(7));
    }
    std::string dir = locale_dir();
    const std::string env =
        i18n::wanted([](const char* n) -> const char* { return std::getenv(n); });
    std::string lang = i18n::choose(want, env, dir);
    if (lang.empty()) {
        // Said in the environment's language, the one the user reads.
        i18n::init(i18n::choose("", env, dir), dir);
        std::fprintf(stderr, tr("pupitre: no catalogue for the language '%s' (available: %s)\n"),
                     want.c_str(), i18n::available(dir).c_str());
        return false;
    }
    i18n::init(lang, dir);
    return true;
}

// A file given on the command line must exist: CLI::ExistingFile's check with
// its message in the chosen language; a missing file is "cannot open input"
// (exit 66), anything else a usage error.
bool g_missing_file = false;
CLI::Validator existing_file() {
    return CLI::Validator(
        [](std::string& f) -> std::string {
            std::error_code ec;
            auto st = std::filesystem::status(f, ec);
            if (!std::filesystem::exists(st)) {
                g_missing_file = true;
                return strf(tr("File does not exist: %s"), f.c_str());
            }
            if (std::filesystem::is_directory(st))
                return strf(tr("File is actually a directory: %s"), f.c_str());
            return "";
        },
        "FILE");
}

// CLI11's commonest errors in the chosen language: each English text is a
// prefix or a suffix around what was typed (CLI/Error.hpp); the others stay
// as CLI11 writes them.
std::string cli_error_text(std::string_view what) {
    static const struct {
        std::string_view prefix, suffix;
        const char* msgid;
    } kTexts[] = {
        {"The following argument was not expected: ", "",
         N_("The following argument was not expected: %s")},
        {"The following arguments were not expected: ", "",
         N_("The following arguments were not expected: %s")},
        {"Could not convert: ", "", N_("Could not convert: %s")},
        {"", " is required", N_("%s is required")},
    };
    for (const auto& t : kTexts)
        if (what.size() > t.prefix.size() + t.suffix.size() && what.starts_with(t.prefix) &&
            what.ends_with(t.suffix)) {
            std::string arg(
                what.substr(t.prefix.size(), what.size() - t.prefix.size() - t.suffix.size()));
            return strf(tr(t.msgid), arg.c_str());
        }
    return std::string(what);
}

// CLI11's own words, in the chosen language.
void translate_cli(CLI::App& app) {
    auto f = app.get_formatter();
    for (const char* w : {N_("Usage"), N_("OPTIONS"), N_("SUBCOMMAND"), N_("SUBCOMMANDS"),
                          N_("Positionals"), N_("REQUIRED"), N_("Needs"), N_("Excludes")})
        f->label(w, tr(w));
    app.option_defaults()->group(tr("Options"));
    app.set_help_flag("-h,--help", tr("Print this help message and exit"));
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return cli_error_text(e.what()) + "\n" + tr("Run with --help for more information.") + "\n";
    });
}

// What the command line fills in. CLI11 keeps pointers to these fields: the
// object stays where main() made it.
struct CommandLine {
    std::string lang;  // read by setup_language() already; here for --help and the parser
    std::string db;
    cli::ConsoleArgs ca;
    cli::RunArgs ra;
    cli::PlotArgs pa;
    cli::StoreArgs sa;
    cli::ExerciseArgs ea;
    std::vector<std::string> numbers;  // as typed, checked after parsing
    std::string number;
};

// The program's own options: --lang, --db, and the console's.
void add_program_options(CLI::App& app, CommandLine& c) {
    app.add_option("--lang", c.lang,
                   tr("the language of the texts people read: en or fr (default: LANGUAGE, LC_ALL, "
                      "LC_MESSAGES, LANG; else en)"))
        ->type_name("LANG");
    app.add_option("--db", c.db,
                   tr("the program store: a file, or a PostgreSQL server as postgresql://… or "
                      "key=value (default PUPITRE_DB, else $XDG_DATA_HOME/pupitre/pupitre.db, "
                      "created on first use); run and check use a store only when given"))
        ->type_name("STORE");

    cli::ConsoleArgs& ca = c.ca;
    app.add_option("--machine", ca.machine,
                   tr("the console's machine: lathe, mill, mill4, mill5, cazeneuve, a stored "
                      "profile or a .machine file "
                      "(default: the last one used, else lathe)"));
    app.add_option("--theme", ca.theme,
                   tr("the console's colours: colour, mono or phosphor (default colour; mono when "
                      "NO_COLOR is set)"));
    app.add_flag("--ascii", ca.ascii,
                 tr("draw the console with ASCII only, even on a UTF-8 terminal"));
}

// The options run and check share.
void add_run_options(CLI::App* sub, cli::RunArgs& ra) {
    sub->add_option("--machine", ra.machine,
                    tr("machine profile: lathe, mill, mill4, mill5, cazeneuve, or a .machine file "
                       "(default lathe)"));
    sub->add_option(
           "--set", ra.sets,
           tr("seed the machine before the run: PREF.X=-120.5, D1.R=4, L5=2, E80000=18000"))
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    sub->add_flag("--block-skip", ra.block_skip, tr("skip the blocks that start with '/'"));
    sub->add_option("--max-blocks", ra.max_blocks,
                    tr("stop with error 1001 after this many blocks, or twice as many moves "
                       "(default 20000000)"));
    sub->add_option("files", ra.files,
                    tr("program files; the first program of the first file is run"))
        ->required()
        ->check(existing_file());
}

CLI::App* add_run(CLI::App& app, cli::RunArgs& ra) {
    CLI::App* run =
        app.add_subcommand("run", tr("dry-run a program and print a summary, or a trace"));
    add_run_options(run, ra);
    run->add_flag("--trace", ra.trace, tr("one JSON line per machine event"));
    run->add_flag("--json", ra.json, tr("the summary as JSON"));
    run->add_flag("--optional-stop", ra.optional_stop,
                  tr("M01 stops (the optional-stop switch is on)"));
    run->add_option("--setup", ra.setup,
                    tr("run in the workshop: the true chuck or vice, stock and tools (lathe, mill, "
                       "mill5, cazeneuve, or a .setup file)"))
        ->type_name("SETUP");
    run->add_option("--measure", ra.measures,
                    tr("after the run, read an instrument: 'dia Z-20', 'bore Z-5', 'groove Z-30', "
                       "'length', 'tool T1 X'; a mill's: 'depth X10 Y40', 'width Y X10 Y40 Z-1'"))
        ->type_name("WHAT");
    run->add_flag("--no-plan", ra.no_plan,
                  tr("no planner: the cycle time at the feeds alone, as before the machine's "
                     "accelerations were modelled (faster)"));
    run->add_option("--edge-life", ra.edge_life,
                    tr("the life of a tool's edge in minutes of cutting, for every tool or for "
                       "one (T11=15): the summary says after how many parts to change it"))
        ->type_name("[TN=]MINUTES")
        ->allow_extra_args(false);
    run->add_option(
           "--part-out", ra.part_out,
           tr("write the cut part: a picture on a sheet if FILE ends in .pdf, or .png on a "
              "lathe; its half-section as SVG (.svg) or (Z, R) points; a mill's FILE.png is a "
              "16-bit height field and its JSON, unless --part-view names a view"))
        ->type_name("FILE");
    run->add_option("--part-view", ra.part_view,
                    tr("the picture of --part-out: section (lathe), top or 3d (machining centre)"))
        ->type_name("VIEW");
    return run;
}

CLI::App* add_plot(CLI::App& app, cli::PlotArgs& pa) {
    CLI::App* plot =
        app.add_subcommand("plot", tr("draw the toolpath of a dry run as SVG, PNG or PDF"));
    plot->add_option("--machine", pa.machine,
                     tr("machine profile: lathe, mill, mill4, mill5, cazeneuve, or a .machine file "
                        "(default lathe)"));
    plot->add_option("--plane", pa.plane,
                     tr("xy, xz, yz or zx (default: the program's; zx on the lathe)"));
    plot->add_option("--set", pa.sets,
                     tr("seed the machine before the run: PREF.X=-120.5, D1.R=4, L5=2"))
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    plot->add_flag("--block-skip", pa.block_skip, tr("skip the blocks that start with '/'"));
    plot->add_option("--max-blocks", pa.max_blocks,
                     tr("stop with error 1001 after this many blocks, or twice as many moves "
                        "(default 20000000)"));
    plot->add_option("--svg", pa.svg, tr("the SVG file to write ('-': the standard output)"))
        ->type_name("OUT");
    plot->add_option("--png", pa.png, tr("the picture as a PNG, 1600 pixels wide"))
        ->type_name("OUT");
    plot->add_option("--pdf", pa.pdf, tr("the picture as a one-page PDF, for printing"))
        ->type_name("OUT");
    plot->add_option("--edge-life", pa.edge_life,
                     tr("the life of a tool's edge in minutes of cutting, for every tool or for "
                        "one (T11=15): the PDF's table says after how many parts to change it"))
        ->type_name("[TN=]MINUTES")
        ->allow_extra_args(false);
    plot->add_option("--setup", pa.setup,
                     tr("draw the part the workshop cut under the path (lathe, mill, mill5, "
                        "cazeneuve, or a .setup file)"))
        ->type_name("SETUP");
    plot->add_option("files", pa.files,
                     tr("program files; the first program of the first file is run"))
        ->required()
        ->check(existing_file());
    return plot;
}

// A subcommand and what runs it.
struct Command {
    CLI::App* sub;
    int (*run)(const CommandLine& c);
};

// import, export, list, rm, history, restore: the program store.
void add_store(CLI::App& app, CommandLine& c, std::vector<Command>& commands) {
    cli::StoreArgs& sa = c.sa;
    CLI::App* imp =
        // xgettext:no-c-format
        app.add_subcommand("import", tr("store the % programs of files (one transaction for all)"));
    imp->add_option("files", sa.files,
                    // xgettext:no-c-format
                    tr("program files; each % program is stored under its number"))
        ->required();
    // xgettext:no-c-format
    imp->add_option("--number", sa.number, tr("the number for a file with no % line"))
        ->type_name("N");
    CLI::App* exp =
        app.add_subcommand("export", tr("write stored programs exactly as imported or saved"));
    exp->add_option("numbers", c.numbers, tr("program numbers, written one after the other"))
        ->required();
    exp->add_option("-o,--output", sa.output, tr("write to FILE instead of the standard output"))
        ->type_name("FILE");
    CLI::App* list = app.add_subcommand("list", tr("list the stored programs"));
    CLI::App* rm = app.add_subcommand("rm", tr("delete a stored program (its history stays)"));
    rm->add_option("number", c.number, tr("program number"))->required();
    CLI::App* hist = app.add_subcommand("history", tr("the revisions of a stored program"));
    hist->add_option("number", c.number, tr("program number"))->required();
    CLI::App* rest = app.add_subcommand("restore", tr("make an earlier revision current again"));
    rest->add_option("number", c.number, tr("program number"))->required();
    rest->add_option("revision", sa.revision, tr("revision (see history)"))->required();
    commands.push_back({imp, [](const CommandLine& k) { return cli::store_import(k.sa); }});
    commands.push_back({exp, [](const CommandLine& k) { return cli::store_export(k.sa); }});
    commands.push_back({list, [](const CommandLine& k) { return cli::store_list(k.sa); }});
    commands.push_back({rm, [](const CommandLine& k) { return cli::store_rm(k.sa); }});
    commands.push_back({hist, [](const CommandLine& k) { return cli::store_history(k.sa); }});
    commands.push_back({rest, [](const CommandLine& k) { return cli::store_restore(k.sa); }});
    CLI::App* st = app.add_subcommand("store", tr("the store itself: copy FROM TO"));
    st->require_subcommand(1);
    CLI::App* copy = st->add_subcommand(
        "copy", tr("copy a whole store (file or server) into a new one, and compare them"));
    copy->add_option("from", sa.from, tr("the store to copy: a file or a postgresql:// URI"))
        ->required();
    copy->add_option("to", sa.to, tr("the new store: a file or a server's empty database"))
        ->required();
    commands.push_back({st, [](const CommandLine& k) { return cli::store_copy(k.sa); }});
}

// The program numbers as typed (300 or %300), into sa.numbers; false (and
// says which) when one is not a number.
bool read_numbers(CommandLine& c) {
    if (!c.number.empty()) c.numbers.push_back(c.number);
    for (const auto& t : c.numbers) {
        int n = 0;
        if (!parse_number(t, n)) {
            std::fprintf(stderr, tr("pupitre: '%s' is not a program number\n"), t.c_str());
            return false;
        }
        c.sa.numbers.push_back(n);
    }
    return true;
}

// exercise and class: training (pupitre-exercise(5)).
void add_training(CLI::App& app, CommandLine& c, std::vector<Command>& commands) {
    cli::ExerciseArgs& ea = c.ea;
    CLI::App* ex = app.add_subcommand(
        "exercise", tr("an exercise: NAME opens the console on it; list, check FILE, add FILE, "
                       "truth NAME, save NAME"));
    ex->add_option("words", ea.words,
                   tr("NAME, or list, check FILE..., add FILE, truth NAME, save NAME"));
    ex->add_option("--student", ea.student, tr("who attempts it (default: the login name)"))
        ->type_name("NAME");
    ex->add_option(
        "--machine", ea.machine,
        tr("save: the machine whose workshop the exercise is made from (default lathe)"));
    ex->add_option("-o,--output", ea.output, tr("save: write to FILE"))->type_name("FILE");
    CLI::App* cl = app.add_subcommand(
        "class", tr("the teacher's side: class report [EXERCISE], replay ATTEMPT, and on a "
                    "server class init, add-student NAME…, students, grade, watch"));
    cl->add_option("words", ea.words,
                   tr("report [EXERCISE] | init | add-student NAME… | students | grade | watch | "
                      "replay ATTEMPT"))
        ->required();
    cl->add_option("--class", ea.group,
                   tr("init, add-student, students, watch: the class (default class)"))
        ->type_name("NAME")
        ->each([&ea](const std::string&) { ea.group_given = true; });
    cl->add_option("--from", ea.from, tr("add-student: the logins from the first column of a CSV"))
        ->type_name("FILE.csv");
    cl->add_flag("--csv", ea.csv, tr("the report as CSV"));
    cl->add_option("--html", ea.output, tr("the report as one printable HTML file"))
        ->type_name("FILE");
    cl->add_option("--pdf", ea.pdf, tr("the report's table as a PDF (A4 landscape)"))
        ->type_name("FILE");
    commands.push_back({ex, [](const CommandLine& k) {
                            cli::ExerciseArgs e = k.ea;
                            e.db = k.db;
                            e.console = k.ca;
                            return cli::exercise(e);
                        }});
    commands.push_back({cl, [](const CommandLine& k) {
                            cli::ExerciseArgs e = k.ea;
                            e.db = k.db;
                            e.console = k.ca;  // class replay: --theme, --ascii
                            return cli::class_command(e);
                        }});
}

// The subcommand given, else the console; an exception is an internal error.
int dispatch(CommandLine& c, const std::vector<Command>& commands) {
    try {
        for (const Command& k : commands)
            if (*k.sub) return k.run(c);
    } catch (const std::exception& e) {
        std::fprintf(stderr, tr("pupitre: internal error: %s\n"), e.what());
        return cli::kSoftware;
    }
    c.ca.db = c.db;
    try {
        return cli::console(c.ca);
    } catch (const std::exception& e) {
        std::fprintf(stderr, tr("pupitre: internal error: %s\n"), e.what());
        return cli::kSoftware;
    }
}
}  // namespace

int main(int argc, char** argv) {
    if (!setup_language(argc, argv)) return cli::kUsage;
    CLI::App app{
        tr("pupitre - the operator panel of a NUM 1020/1040/1060 CNC, with the machine simulated")};
    app.set_version_flag("--version", std::string("pupitre ") + PUPITRE_VERSION,
                         tr("Display program version information and exit"));
    app.require_subcommand(0, 1);
    // --db is the program's option; run and check pass it up when given after them.
    app.fallthrough();
    translate_cli(app);
    CommandLine c;
    add_program_options(app, c);
    std::vector<Command> commands;
    commands.push_back({add_run(app, c.ra), [](const CommandLine& k) { return cli::run(k.ra); }});
    CLI::App* check = app.add_subcommand(
        "check", tr("report every problem a dry run would meet, without a trace"));
    add_run_options(check, c.ra);
    commands.push_back({check, [](const CommandLine& k) { return cli::check(k.ra); }});
    commands.push_back({add_plot(app, c.pa), [](const CommandLine& k) { return cli::plot(k.pa); }});
    add_store(app, c, commands);
    add_training(app, c, commands);

    // TRANSLATORS: the heading of the list of commands in --help.
    for (CLI::App* sub : app.get_subcommands({})) sub->group(tr("Subcommands"));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return g_missing_file ? cli::kNoInput : cli::kUsage;
    }
    // PUPITRE_DB names the store as --db does (a class's server, say).
    if (const char* env = std::getenv("PUPITRE_DB"); c.db.empty() && env && *env) c.db = env;
    c.ra.db = c.db;
    c.sa.db = c.db;
    if (!read_numbers(c)) return cli::kUsage;
    return dispatch(c, commands);
}
