// libFuzzer target: program text -> lexer, parser and interpreter, on the lathe
// and the mill. Any crash, sanitizer report, hang or runaway allocation is a bug:
// bad input must end in a diagnostic (DESIGN §2.2).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/interp/interp.hpp"

using namespace pupitre;

namespace {
struct Sink final : MachineSink {};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 64 * 1024) return 0;
    static MachineProfile lathe, mill;
    static bool init = builtin_machine("lathe", lathe) && builtin_machine("mill", mill);
    (void)init;
    std::string text(reinterpret_cast<const char*>(data), size);
    for (const MachineProfile* m : {&mill, &lathe}) {
        ProgramMemory mem;
        Diag d;
        if (!mem.load_text("fuzz.iso", text, d)) continue;
        Sink sink;
        RunOptions o;
        o.max_blocks = 20000;
        Interpreter in(*m, mem, sink, o);
        in.set("D1.R", 0);
        in.start(mem.first());
        in.run_to_end();
    }
    return 0;
}
