// pupitre: entry point and command line (DESIGN §2.1).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "console/cli.hpp"
#include "core/machine.hpp"

using namespace pupitre;

int main(int argc, char** argv) {
    CLI::App app{"pupitre - the operator panel of a NUM 1020/1040/1060 CNC, with the machine simulated"};
    app.set_version_flag("--version", std::string("pupitre ") + PUPITRE_VERSION);
    app.require_subcommand(0, 1);

    cli::RunArgs ra;
    auto add_common = [&](CLI::App* sub) {
        sub->add_option("--machine", ra.machine,
                        "machine profile: lathe, mill, mill4, mill5, or a .machine file (default mill)");
        sub->add_option("--set", ra.sets, "seed the machine before the run: PREF.X=-120.5, D1.R=4, L5=2, E80000=18000")
            ->type_name("NAME=VALUE")
            ->allow_extra_args(false);
        sub->add_flag("--block-skip", ra.block_skip, "skip the blocks that start with '/'");
        sub->add_option("--max-blocks", ra.max_blocks, "stop with error 1001 after this many blocks (default 20000000)");
        sub->add_option("files", ra.files, "program files; the first program of the first file is run")
            ->required()
            ->check(CLI::ExistingFile);
    };
    CLI::App* run = app.add_subcommand("run", "dry-run a program and print a summary, or a trace");
    add_common(run);
    run->add_flag("--trace", ra.trace, "one JSON line per machine event");
    run->add_flag("--json", ra.json, "the summary as JSON");
    run->add_flag("--optional-stop", ra.optional_stop, "M01 stops (the optional-stop switch is on)");
    CLI::App* check = app.add_subcommand("check", "report every problem a dry run would meet, without a trace");
    add_common(check);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // Missing files are "cannot open input", everything else is a usage error.
        app.exit(e);
        std::string what = e.what();
        if (what.find("does not exist") != std::string::npos) return cli::kNoInput;
        return cli::kUsage;
    }
    try {
        if (*run) return cli::run(ra);
        if (*check) return cli::check(ra);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pupitre: internal error: %s\n", e.what());
        return cli::kSoftware;
    }
    std::fputs(app.help().c_str(), stdout);
    std::fputs("\nThe console (pupitre with no command) is not part of this version yet: use run or check.\n",
               stdout);
    return cli::kUsage;
}
