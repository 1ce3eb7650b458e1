// The codes table (000:510-631, 000:3602-3629; groups from 000:1012-1819 and
// 000:510-587; pupitre-iso(5), FUNCTIONS; availability: starred functions are 1040/1060).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parse/codes.hpp"

#include <array>

#include "core/i18n.hpp"

namespace pupitre {

namespace {

using S = Support;
using G = Group;

// The texts are msgids (N_): show them with tr(std::string(text).c_str()).
constexpr GCode kG[] = {
    {0, G::motion, kBoth, 0, S::yes, "", N_("rapid linear interpolation")},
    {1, G::motion, kBoth, 0, S::yes, "", N_("linear interpolation at feed")},
    {2, G::motion, kBoth, 0, S::yes, "", N_("circular interpolation, clockwise")},
    {3, G::motion, kBoth, 0, S::yes, "", N_("circular interpolation, counter-clockwise")},
    {4, G::none, kBoth, 0, S::yes, "F", N_("dwell, seconds in F")},
    {5, G::none, kLathe, kBoth, S::option, "X Z",
     N_("move along an inclined axis (grinder option)")},
    {6, G::none, kBoth, kBoth, S::yes, "NC", N_("execute a spline curve")},
    {7, G::none, kLathe, kBoth, S::option, "X Z",
     N_("initial positioning for an inclined axis (grinder option)")},
    {9, G::none, kBoth, 0, S::yes, "", N_("exact stop at end of block")},
    {10, G::none, kBoth, 0, S::yes, "N EF", N_("interruptible block")},
    {12, G::none, kBoth, 0, S::ignored, "", N_("handwheel overspeed")},
    // Not a msgid: scripts/lib/extract-pot drops non-ASCII msgids (tr() returns it as written).
    {16, G::toolaxis, kBoth, 0, S::yes, "P Q R", "tool axis orientation P± Q± R±"},
    {17, G::plane, kMill, 0, S::yes, "", N_("XY plane")},
    {18, G::plane, kBoth, 0, S::yes, "", N_("ZX plane")},
    {19, G::plane, kMill, 0, S::yes, "", N_("YZ plane")},
    {20, G::coord, kLathe, 0, S::yes, "", N_("cartesian X Z programming")},
    {21, G::coord, kLathe, 0, S::option, "", N_("polar (face) transformation X/Y to X/C (option)")},
    {22, G::coord, kLathe, kBoth, S::option, "", N_("cylindrical transformation (option)")},
    {23, G::none, kBoth, kBoth, S::yes, "X Y Z I J K", N_("circle through three points")},
    {29, G::radcomp, kMill, 0, S::yes, "P Q R", N_("tool correction in space (3-D)")},
    {31, G::none, kMill, 0, S::yes, "X Y Z I J K P EC EF ER F", N_("single-point threading cycle")},
    {33, G::none, kLathe, 0, S::yes, "X Z K P Q R S EA EB ES F",
     N_("constant-pitch threading cycle")},
    {38, G::motion, kLathe, 0, S::yes, "X Z K", N_("chained threading")},
    {40, G::radcomp, kBoth, 0, S::yes, "", N_("cancel tool radius compensation")},
    {41, G::radcomp, kBoth, 0, S::yes, "", N_("tool radius compensation, tool left of profile")},
    {42, G::radcomp, kBoth, 0, S::yes, "", N_("tool radius compensation, tool right of profile")},
    {45, G::none, kMill, 0, S::yes, "X Y Z I J K P Q R EB EG EP EQ EI EJ EX EY ER",
     N_("simple pocket cycle")},
    {46, G::none, kMill, kBoth, S::yes, "NU NP NR ED Q J R LX LY X Y Z P ER EH EP EQ EI EJ EX EY",
     N_("pocket or facing with any contour")},
    {48, G::none, kBoth, kBoth, S::yes, "NC H N", N_("spline definition")},
    {49, G::none, kBoth, kBoth, S::yes, "NC", N_("spline deletion")},
    {51, G::none, kBoth, kBoth, S::yes, "X Y Z U V W A B C", N_("mirror: X- enables, X+ disables")},
    {52, G::none, kBoth, 0, S::yes, "", N_("absolute move relative to the measurement origin")},
    {53, G::prefdec, kBoth, 0, S::yes, "", N_("disable the PREF and DEC1 offsets")},
    {54, G::prefdec, kBoth, 0, S::yes, "", N_("enable the PREF and DEC1 offsets")},
    {59, G::none, kBoth, 0, S::yes, "X Y Z U V W A B C I J K ED", N_("programmed origin offset")},
    {63, G::none, kLathe, kBoth, S::yes, "N X Z I K P Q R EA EB EC EF EQ ER EU EW EX EZ EP",
     N_("roughing cycle with grooves")},
    {64, G::cycle, kLathe, 0, S::yes, "N X Z I K P R EP", N_("paraxial roughing cycle")},
    {65, G::none, kLathe, 0, S::yes, "N X Z I K P Q R EA EF EP", N_("groove roughing cycle")},
    {66, G::none, kLathe, 0, S::yes, "X Z P R D EA EF EP", N_("plunge roughing cycle")},
    {70, G::units, kBoth, 0, S::yes, "", N_("inch programming")},
    {71, G::units, kBoth, 0, S::yes, "", N_("metric programming")},
    {73, G::scale, kBoth, kBoth, S::yes, "", N_("scale factor off")},
    {74, G::scale, kBoth, kBoth, S::yes, "", N_("scale factor on (E69000)")},
    {75, G::none, kBoth, 0, S::yes, "N", N_("declare the emergency-retract block")},
    {76, G::none, kBoth, 0, S::yes, "H N",
     N_("write the current L/E values into a program; G76+/- edit (1040/1060)")},
    {77, G::none, kBoth, 0, S::yes, "H N P S", N_("call a subprogram or block range, with return")},
    {78, G::none, kBoth, kBoth, S::yes, "P",
     N_("axis-group synchronisation (one group here: a no-op)")},
    {79, G::none, kBoth, 0, S::yes, "N", N_("jump, conditional or not")},
    {80, G::cycle, kBoth, 0, S::yes, "", N_("cancel machining cycle")},
    {81, G::cycle, kBoth, kBoth, S::yes, "X Y Z ER EH", N_("drilling / centring cycle")},
    {82, G::cycle, kBoth, kBoth, S::yes, "X Y Z ER EH EF", N_("counterboring cycle with dwell")},
    {83, G::cycle, kBoth, 0, S::yes, "X Y Z P Q ER EH EF EP ES",
     N_("peck drilling with chip clearing")},
    {84, G::cycle, kBoth, kBoth, S::yes, "X Y Z K ER EH EF EK", N_("tapping cycle")},
    {85, G::cycle, kBoth, kBoth, S::yes, "X Y Z ER EH EF", N_("boring cycle")},
    {86, G::cycle, kMill, 0, S::yes, "X Y Z ER EH EC EP", N_("boring with indexed spindle stop")},
    {87, G::cycle, kBoth, 0, S::yes, "X Y Z P Q ER EH EF EP ES", N_("drilling with chip breaking")},
    {88, G::cycle, kMill, 0, S::yes, "X Y Z ER EH", N_("boring and facing")},
    {89, G::cycle, kBoth, kBoth, S::yes, "X Y Z ER EH EF", N_("boring with dwell")},
    {90, G::dist, kBoth, 0, S::yes, "", N_("absolute programming")},
    {91, G::dist, kBoth, 0, S::yes, "", N_("incremental programming")},
    {92, G::none, kBoth, 0, S::yes, "X Y Z U V W A B C S R",
     N_("origin preset (axes), spindle limit (S), tangential feed (R)")},
    {93, G::feed, kMill, 0, S::yes, "F", N_("inverse-time feed")},
    {94, G::feed, kBoth, 0, S::yes, "F", N_("feed per minute")},
    {95, G::feed, kBoth, kMill, S::yes, "F", N_("feed per revolution")},
    {96, G::spindle, kLathe, 0, S::yes, "X S", N_("constant surface speed, m/min")},
    {97, G::spindle, kBoth, 0, S::yes, "S", N_("spindle speed in rev/min")},
    {98, G::none, kLathe, 0, S::ignored, "X",
     N_("start X value for C-axis interpolation (stored only)")},
    {104, G::none, kMill, kBoth, S::option, "", N_("curve smoothing in space (an option)")},
    {110, G::none, kLathe, 0, S::ignored, "", N_("optimisation of handling moves")},
    {997, G::none, kBoth, kBoth, S::ignored, "", N_("execute the functions stored under G999")},
    {998, G::none, kBoth, kBoth, S::ignored, "",
     N_("validate blocks and functions stored under G999")},
    {999, G::none, kBoth, kBoth, S::ignored, "", N_("suspend execution, force concatenation")},
};

constexpr MCode kM[] = {
    {0, 0, MWhen::apres, false, true, N_("program stop")},
    {1, 1, MWhen::apres, false, true, N_("optional stop")},
    {2, 2, MWhen::apres, false, true, N_("end of program")},
    {3, 3, MWhen::avant, true, true, N_("spindle clockwise")},
    {4, 4, MWhen::avant, true, true, N_("spindle counter-clockwise")},
    {5, 5, MWhen::apres, true, true, N_("spindle stop")},
    {6, 6, MWhen::apres, false, true, N_("tool change")},
    {7, 7, MWhen::avant, true, true, N_("coolant 2 on")},
    {8, 8, MWhen::avant, true, true, N_("coolant 1 on")},
    {9, 9, MWhen::apres, true, true, N_("coolant off")},
    {10, 10, MWhen::apres, true, true, N_("axis clamp")},
    {11, 11, MWhen::avant, true, true, N_("axis unclamp")},
    {12, 12, MWhen::apres, false, false, N_("programmed machining stop")},
    {19, 19, MWhen::avant, true, true, N_("spindle indexing")},
    {40, 45, MWhen::avant, true, true, N_("spindle range")},
    {48, 48, MWhen::apres, true, true, N_("overrides enabled")},
    // xgettext:no-c-format
    {49, 49, MWhen::avant, true, true, N_("overrides inhibited (100 %)")},
    {61, 61, MWhen::avant, true, false, N_("release the current spindle")},
    {62, 65, MWhen::avant, true, true, N_("control of spindle 1-4")},
    {66, 69, MWhen::avant, true, true, N_("measurement of spindle 1-4")},
    {100, 199, MWhen::apres, false, true, N_("builder's coded M, non-modal")},
    {200, 899, MWhen::avant, true, true, N_("builder's coded M, modal")},
    {997, 997, MWhen::avant, false, false, N_("force block chaining")},
    {998, 998, MWhen::avant, true, false, N_("re-enable MODIF and IMD")},
    {999, 999, MWhen::avant, true, false, N_("inhibit MODIF and IMD")},
};

// The Cazeneuve HB CNC lathe of seed 003 (chapter VI): its own rows, with the
// seed line of each rule (pupitre-cazeneuve(5) lists them). Lengths in µm, X a
// radius. `later`: defined by the thesis, not run yet (error 2090); none today.
constexpr GCode kGCaz[] = {
    {0, G::motion, kLathe, 0, S::yes, "", N_("rapid move; G alone is G00 (003:993)")},
    {1, G::motion, kLathe, 0, S::yes, "", N_("linear move at feed (003:821)")},
    {2, G::motion, kLathe, 0, S::yes, "",
     N_("arc, trigonometric seen from the front turret; I K the centre (003:855, 874)")},
    {3, G::motion, kLathe, 0, S::yes, "",
     N_("arc, clockwise seen from the front turret; I K the centre (003:855, 874)")},
    {4, G::none, kLathe, 0, S::yes, "F", N_("dwell, F in tenths of a second (003:1018)")},
    {7, G::none, kLathe, 0, S::yes, "X Z",
     N_("G7XZ: back to the turret's indexing point, ends the CNP (003:1803)")},
    {25, G::none, kLathe, 0, S::yes, "S",
     N_("spindle limit under G96, S in rev/min (003:1124-1126, 1571)")},
    {31, G::none, kLathe, 0, S::yes, "X Z I K D F S",
     N_("threading cycle generated by G71, run as G34 (003:1160, 1393, 1418)")},
    {33, G::motion, kLathe, 0, S::yes, "F",
     N_("thread cutting, pitch F in micrometres (003:1158-1172)")},
    {34, G::none, kLathe, 0, S::yes, "X Z I K D F S", N_("threading cycle (003:1306-1336)")},
    {40, G::radcomp, kLathe, 0, S::yes, "", N_("cancel the nose-radius compensation (003:1793)")},
    {41, G::radcomp, kLathe, 0, S::yes, "",
     N_("nose-radius compensation, tool left of the profile (003:1791)")},
    {42, G::radcomp, kLathe, 0, S::yes, "",
     N_("nose-radius compensation, tool right of the profile (003:1792)")},
    {71, G::none, kLathe, 0, S::yes, "X Z I K D F", N_("turning cycle (003:1399-1418)")},
    {81, G::none, kLathe, 0, S::yes, "X Z I K D F", N_("turning cycle, as G71 (003:1307, 1798)")},
    {82, G::none, kLathe, 0, S::yes, "X Z I K", N_("facing cycle, as G92 (003:1308, 1799)")},
    {90, G::dist, kLathe, 0, S::yes, "", N_("absolute programming (003:831)")},
    {91, G::dist, kLathe, 0, S::yes, "", N_("incremental programming (003:833)")},
    {92, G::none, kLathe, 0, S::yes, "X Z I K", N_("facing cycle (003:1465-1477)")},
    {94, G::feed, kLathe, 0, S::yes, "F", N_("feed in mm/min (003:890)")},
    {95, G::feed, kLathe, 0, S::yes, "F", N_("feed in micrometres per revolution (003:891, 894)")},
    {96, G::spindle, kLathe, 0, S::yes, "S X",
     N_("constant surface speed, S in m/min, X the tool's radius in micrometres (003:1113-1115)")},
    {97, G::spindle, kLathe, 0, S::yes, "S", N_("spindle speed in rev/min (003:1123)")},
};

constexpr MCode kMCaz[] = {
    {0, 0, MWhen::apres, false, true, N_("program stop (003:958)")},
    {1, 1, MWhen::apres, false, true, N_("optional stop (003:960)")},
    {2, 2, MWhen::apres, false, true, N_("end of program (003:962)")},
    {3, 3, MWhen::avant, true, true, N_("spindle forward (003:910)")},
    {4, 4, MWhen::avant, true, true, N_("spindle reverse (003:912)")},
    {5, 5, MWhen::apres, true, true, N_("spindle stop (003:914)")},
    {8, 8, MWhen::avant, true, true, N_("coolant on (003:964)")},
    {9, 9, MWhen::apres, true, true, N_("coolant off (003:966)")},
    {30, 30, MWhen::apres, false, true, N_("end of program, back to its start (003:972)")},
    {50, 50, MWhen::avant, true, true, N_("handwheel and hydraulic tailstock enabled (003:968)")},
};

// The words each G function of a table owns.
template <size_t Size>
struct OwnTable {
    std::array<std::bitset<kAddrCount>, Size> own;
    explicit OwnTable(const GCode (&rows)[Size]) {
        for (size_t i = 0; i < own.size(); ++i) {
            std::string_view a = rows[i].args;
            while (!a.empty()) {
                size_t sp = a.find(' ');
                std::string_view w = a.substr(0, sp);
                a = sp == std::string_view::npos ? std::string_view{} : a.substr(sp + 1);
                if (w.size() == 1)
                    own[i].set(addr1(w[0]));
                else if (w[0] == 'E')
                    own[i].set(addrE(w[1]));
                else if (w[0] == 'N')
                    own[i].set(addrN(w[1]));
                else if (w[0] == 'L')
                    own[i].set(addrL(w[1]));
            }
        }
    }
};

}  // namespace

const GCode* find_g(int number, Dialect d) {
    for (const auto& g : all_g(d))
        if (g.number == number) return &g;
    return nullptr;
}

const MCode* find_m(int number, Dialect d) {
    for (const auto& m : all_m(d))
        if (number >= m.first && number <= m.last) return &m;
    return nullptr;
}

std::span<const BlockStep> block_steps() {
    static constexpr BlockStep kSteps[] = {
        {ExecStep::assign, "its L and E assignments, from left to right"},
        {ExecStep::modal, "the G functions and the modal values"},
        {ExecStep::m_before, "the M functions executed before the motion"},
        {ExecStep::spindle, "the spindle speed S, with G96 or G97"},
        {ExecStep::message, "the $ message"},
        {ExecStep::motion, "the motion"},
        {ExecStep::dwell, "the G04 dwell"},
        {ExecStep::m_after, "the M functions executed after the motion"},
        {ExecStep::flow, "the G79 jump, then the G77 call"},
    };
    return kSteps;
}

std::span<const GCode> all_g(Dialect d) {
    if (d == Dialect::cazeneuve) return kGCaz;
    return kG;
}
std::span<const MCode> all_m(Dialect d) {
    if (d == Dialect::cazeneuve) return kMCaz;
    return kM;
}

bool g_owns(const GCode& g, Addr a) {
    static const OwnTable t(kG);
    static const OwnTable caz(kGCaz);
    if (&g >= std::begin(kGCaz) && &g < std::end(kGCaz)) return caz.own[size_t(&g - kGCaz)].test(a);
    return t.own[size_t(&g - kG)].test(a);
}

}  // namespace pupitre
