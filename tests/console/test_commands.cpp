// The ':' commands as a transcript: every command, with good and bad words,
// and what each leaves on the message line and in the session, compared with
// tests/console/expected/commands.txt (PUPITRE_BLESS=1 rewrites it). A change
// to how the commands are written must leave it byte for byte as it was.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "tests/console/fixture.hpp"
#include "tests/screen/snapshot.hpp"

using namespace pupitre;
using pupitre::test::Console;

namespace {

// One line per command: '~' lets the run settle, "~S" lets S seconds pass,
// '#' is a comment; any other line is typed on the input line, then Enter.
const char* const kScript = R"(# pages and modes
:
:frobnicate now
:page
:page nowhere
:page dir
:help
:page op
:mode
:mode nowhere
:mode jog
:mode pom
:cycle
~
# the program, the knobs and the switches
:load
:load x
:load -1
:load %300
:mode auto
:speed
:speed x2
:speed max
:speed x10
:speed x1
:feed
:feed 121
:feed 80
:spindle 49
:spindle 110
:skip maybe
:skip on
:skip
:m01 off
:m01
:inc
:inc 0
:inc 200
:inc 0.5
:inc +1
:jog
:jog X
:jog Q 1
:jog X 1 2
:mode jog
:jog x -1
~
:jog Z +2.5
~
:stop
:raz
:mode rns
:search
:search x
:search N40
:search n9999
:mode auto
:cycle
~0.5
:stop
:mode modif
:close
:raz
:cycle
~
:raz
# settings
:set
:set L5=2
:set  PREF.Z = 3
:touch
:touch Z
:touch q 0
:touch Z 0
n
:touch Z 0
y
:measure
:measure D2 X
:measure X2 X 1
:measure D2 X 59.978
:measure d1 z 0
:undo
:undo
:undo
:measure dia Z-10
:setup
:setup nowhere.setup
:part
:part new
:setup lathe
:setup
:measure dia Z-10
:measure groove Z-10
:measure tool T1 X
:measure dia
:shim
:shim 0.05
:shim off
:part export
:part export /nonexistent-dir/part.svg
:part new
:setup off
:protect
:protect
:protect pin 1234
:protect on
:protect off 99
:protect off 1234
:protect pin
# the store and the editor
:rm
:rm x
:rm 999
:goto 10
:find G0
:renum
:close
:close!
:recover
:discard
:history
:restore 1
:mode edit
:edit x
:edit 123456
:edit %700
G0 X10
N20 G1 Z-5 F100
N30 G77 N20 N20
M2
:goto N20
:goto x
:goto 99
:find
:find   Z-5
:find Z-5
:find nothing-like-this
:renum x
:renum 10 0
:renum -1
:renum 100 5
:recover
:discard
:close
n
:quit
n
:q
n
:save!
:history
:restore
:restore x
:restore 1
:save
:close
:page dir
:edit
:close
:mode edit
:close!
:edit 700
:find G1
:page op
:edit
G4 F-1
:save
:close
y
:rm 700
:rm 700
:history
:quit!
:q!
:q
:quit
)";

std::string state(Console& c) {
    console::Session& s = *c.s;
    const Sim& sim = s.sim();
    pages::View v = s.view();
    std::ostringstream o;
    o << "  " << v.message << (v.message_error ? "  [error]" : "") << "\n  page "
      << pages::page_word(s.page()) << ", " << mode_name(sim.mode()) << ", run " << int(sim.state())
      << ", %" << sim.selected() << ", speed " << int(s.speed()) << ", F" << sim.feed_override
      << "% S" << sim.spindle_override << "%, skip " << s.sim().block_skip() << " m01 "
      << s.sim().optional_stop() << ", inc " << sim.increment << ", D" << s.setting().corrector()
      << ", protect " << s.setting().locked() << ", undo " << s.setting().undo_depth();
    if (s.editing().editor().is_open())
        o << ", edit %" << s.editing().editor().number << (s.editing().editor().dirty ? "*" : "")
          << " line " << s.editing().editor().cursor << "/" << s.editing().editor().lines().size()
          << (s.editing().modif() ? " MODIF" : "");
    if (!s.question().empty()) o << ", asks: " << s.question();
    if (s.quitting()) o << ", quit";
    return o.str() + "\n";
}

}  // namespace

TEST(Commands, TranscriptOfEveryCommand) {
    std::string path = ::testing::TempDir() + "/commands_" + std::to_string(::getpid()) + ".db";
    auto wipe = [&] {
        for (const char* ext : {"", "-wal", "-shm", "-journal"}) std::remove((path + ext).c_str());
        std::filesystem::remove_all(path + ".recover");
    };
    wipe();
    auto opened = store::Store::open(path);
    ASSERT_FALSE(opened.error) << opened.error.message;
    Console c("lathe", {"data/demo/lathe_p300.iso"}, std::move(opened.value));
    std::ostringstream out;
    std::istringstream script(kScript);
    const char* effects[] = {"none", "redraw", "quit"};
    for (std::string line; std::getline(script, line);) {
        if (line.empty() || line[0] == '#') continue;
        if (line[0] == '~') {
            if (line.size() == 1)
                c.run_until_settled();
            else
                for (double t = 0; t < std::stod(line.substr(1)); t += 1.0 / 30)
                    c.s->tick(1.0 / 30);
            out << "~ " << line.substr(1) << "\n" << state(c);
            continue;
        }
        c.s->say("");  // each line shows what this command says, or nothing
        console::Effect e = c.s->submit(line);
        out << "> " << line << "  (" << effects[int(e)] << ")\n" << state(c);
    }
    // What the HELP page lists of the commands, and what Tab completes.
    out << "\nHELP\n";
    for (const auto& h : c.s->view().help)
        if (h.key.rfind(":", 0) == 0) out << "  " << h.key << "  |  " << h.what << "\n";
    out << "\nTab\n";
    for (const char* w : {":", ":re", ":q", ":mo", ":h", ":s", ":x"}) {
        out << "  " << w << " ->";
        for (const auto& s : c.s->complete(w)) out << " " << s;
        out << "\n";
    }
    c.s.reset();
    wipe();
    std::string text = out.str();
    for (size_t at; (at = text.find(path)) != std::string::npos;)
        text.replace(at, path.size(), "STORE");
    test::snapshot("tests/console/expected", "commands", text);
}
