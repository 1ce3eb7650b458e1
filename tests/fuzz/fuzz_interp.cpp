// libFuzzer target: program text -> lexer, parser and interpreter, on the lathe
// and the mill. Any crash, sanitizer report, hang or runaway allocation is a bug:
// bad input must end in a diagnostic (pupitre(1), DIAGNOSTICS). Each line is parsed with
// and without the parser's lane of plain blocks (the same Block or the same
// error), and each input runs with the interpreter's plain lane on and off
// (core/interp/interp_fast.cpp): the two runs must report the same events and
// diagnostics and end in the same state.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/interp/interp.hpp"
#include "tests/unit/block_log.hpp"
#include "tests/unit/event_log.hpp"

using namespace pupitre;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 64 * 1024) return 0;
    static MachineProfile lathe, mill;
    static bool init = builtin_machine("lathe", lathe) && builtin_machine("mill", mill);
    (void)init;
    std::string text(reinterpret_cast<const char*>(data), size);
    // The parser's lane of plain blocks against the general parser, line by line.
    for (size_t at = 0; at <= text.size();) {
        size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        const std::string_view line(text.data() + at, end - at);
        if (test::parse_answer(line, true) != test::parse_answer(line, false)) {
            std::fprintf(stderr, "the parser's plain lane differs on a line\n");
            std::abort();
        }
        at = end + 1;
    }
    for (const MachineProfile* m : {&mill, &lathe}) {
        // The mill's D1 has a radius: G41/G42 then hold moves (GateSink).
        const std::vector<std::pair<std::string, double>> sets = {{"D1.R", m == &mill ? 2 : 0}};
        const std::string fast = test::run_log(*m, text, sets, true);
        const std::string slow = test::run_log(*m, text, sets, false);
        if (fast != slow) {
            std::fprintf(stderr, "the plain lane differs from the general path on %s\n",
                         m->name.c_str());
            std::abort();
        }
    }
    return 0;
}
