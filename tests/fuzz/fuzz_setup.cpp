// libFuzzer target: setup text -> parse_setup, then the lathe's world built
// from it (stock, chuck, tailstock), every tool's true shape, a Workshop and
// the instruments' readings. Any crash, sanitizer report, hang or runaway
// allocation is a bug: a bad setup must end in "line N: ..." (pupitre-setup(5)).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/interp/interp.hpp"
#include "core/workshop/lathe_part.hpp"
#include "core/workshop/setup.hpp"
#include "core/workshop/workshop.hpp"

using namespace pupitre;
using namespace pupitre::workshop;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16 * 1024) return 0;
    static MachineProfile lathe;
    static bool init = builtin_machine("lathe", lathe);
    (void)init;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    Setup s;
    if (!parse_setup(text, s).empty()) return 0;
    for (const ToolTruth& t : s.tools) {
        ToolShape shape = tool_shape(t);
        (void)shape;
    }
    LatheWorld world(s.lathe);
    world.new_part();
    Workshop w(lathe, s, nullptr);
    static constexpr std::string_view kSpecs[] = {
        "dia Z-10", "dia Z0", "bore Z-5", "groove Z-5", "length", "dia Z-1e300", "bore Z-0.0001"};
    for (std::string_view spec : kSpecs) {
        Reading r;
        (void)w.measure(spec, r);
    }
    return 0;
}
