// The cycle sweep (issue 40): every canned cycle and every roughing and
// pocket cycle of the lathe and the machining centre, from a template that
// runs clean, with each of its numeric arguments set in turn to 0, a negative
// value, 1e-9, 0.001, 1e6 and 1e12 (1e-9 rounds to nothing in most words,
// 0.001 is the smallest step they take, 1e12 is beyond any int). Each run
// must end at M02 or with a NUM error, within the interpreter's move budget
// and a time budget; built with ASan and UBSan (scripts/test), no sanitizer
// report either. Fuzzing found G45 with Q0
// dividing by zero; a sweep finds the same family everywhere, not by luck.
//   cycle_sweep [-v]     -v: each run and its answer
// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "core/interp/interp.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#include <sanitizer/common_interface_defs.h>
#define PUPITRE_SWEEP_SANITIZED 1
#endif
#endif

using namespace pupitre;

namespace {

// A template: the machine, its settings and a program whose swept words are
// written in braces, {P4}: the address, then its value in the template.
struct Template {
    const char* name;
    const char* machine;
    std::vector<std::pair<std::string, double>> sets;
    const char* text;
};

// The values each argument takes in turn; the text is what the program
// assigns to L1 (a word's own digits could not write 1e-9 or 1e6).
struct Value {
    const char* label;
    const char* expr;
};
const Value kValues[] = {{"0", "0"},
                         {"-1", "-1"},
                         {"1e-9", "1/1000/1000/1000"},
                         {"0.001", ".001"},  // the smallest step a word writes
                         {"1e6", "1000*1000"},
                         {"1e12", "1000*1000*1000*1000"}};  // beyond any int

const std::vector<std::pair<std::string, double>> kMillTools = {
    {"D1.R", 4}, {"D2.R", 4}, {"D3.R", 4}};

// The mill's cycles. The preamble: tool, spindle, above the part.
#define MILL_START "%1\nN10 T1 D1 M6\nN20 M3 S2000\nN30 G0 X50 Y50 Z10\n"
#define MILL_END "N90 G80 G0 Z10\nN99 M2\n"
const Template kMillCycles[] = {
    // The issue's program (G45 rectangle with fillets) and the other shapes.
    {"G45 rectangle", "mill", kMillTools,
     MILL_START "N40 G45 {X50} {Y50} {Z-10} {ER3} {EX80} {EY30} {EB5} {P4} {Q3} {EP100} "
                "{EQ300}\n" MILL_END},
    {"G45 circle, I J", "mill", kMillTools,
     MILL_START "N40 G45 X50 Y50 {Z-10} {ER2} {EB20} {P4} {Q3} {I.5} {J.5} {EP100} {EQ300} "
                "{EI80} {EJ200}\n" MILL_END},
    {"G45 oblong EG2", "mill", kMillTools,
     MILL_START
     "N40 G45 X50 Y50 {Z-8} ER2 {EX60} {EB10} {P4} {Q5} {J.5} {EG2} EP100 EQ300\n" MILL_END},
    {"G45 floor Q I", "mill", kMillTools,
     MILL_START "N40 G45 X50 Y50 Z-8 ER2 EX40 EY40 {Q5} {I1} EP100 EQ300\n" MILL_END},
    {"G45 walls P J", "mill", kMillTools,
     MILL_START "N40 G45 X50 Y50 Z-8 ER2 EX40 EY40 {P3} {J1} EP100 EQ300\n" MILL_END},
    // G46: the handbook's pocket with an island (seed 000 l.6538), its
    // header and its three orders.
    {"G46 pocket, island", "mill", kMillTools,
     "%100\nN10 G46 NU0 {NP1} {ED8} {Q5} {J.5} NR+ {LX25} {LY0}\nN100 G46 NU1\nN110 G1 X35 Y0\n"
     "N120 Y-15 EB5\nN130 X25\nN140 Y-20 EB5\nN150 X-15\nN160 G2 X-15 Y20 I-15 J0\n"
     "N170 G1 X25 EB5\nN180 Y15\nN190 X35 EB5\nN200 Y0\nN300 G46 NU2 LX15 LY0\nN310 G1 X15 Y5\n"
     "N320 Y-5\nN330 X-15\nN340 G2 X-15 Y5 I-15 J0\nN350 G1 X15\nN400 G46 NU9\n"
     "N510 T1 D1 M6\nN520 M3 M40 S1200\n"
     "N530 G46 NU10 NP1 G83 {Z-9.5} {P4} {Q1} {ER2} {EF.5} {F300}\n"
     "N600 T2 D2 M6\nN610 M3 M41 S1800\n"
     "N620 G46 NU15 {NP1} {Z-10} {P3} {ER1} {EH0} {EP250} {EQ350}\n"
     "N700 T3 D3 M6\nN710 M3 M41 S2000\n"
     "N720 G46 NU20 NP1 {Z-10} {P10} {EH0} {ER2} {EI200} {EJ300} {J.2}\nN800 G Z150\nN810 M2\n"},
    // The drilling, boring and tapping cycles, and G31.
    {"G81", "mill", kMillTools,
     MILL_START "N40 G81 {X20} {Y20} {ER2} {EH1} {Z-10} {F100}\nN50 {X30}\n" MILL_END},
    {"G82", "mill", kMillTools, MILL_START "N40 G82 X20 Y20 {ER2} {Z-10} {EF1} {F100}\n" MILL_END},
    {"G83 P Q", "mill", kMillTools,
     MILL_START "N40 G83 X20 Y20 {ER2} {Z-30} {P10} {Q2} {EP1} {EF.5} {F100}\n" MILL_END},
    {"G83 ES", "mill", kMillTools,
     MILL_START "N40 G83 X20 Y20 ER2 {Z-30} {ES4} {P8} {Q3} F100\n" MILL_END},
    {"G84 floating", "mill", kMillTools,
     MILL_START "N35 S200\nN40 G84 X20 Y20 {ER5} {Z-20} {EF1} {F150}\n" MILL_END},
    {"G84 rigid", "mill", kMillTools,
     MILL_START "N35 S200\nN40 G84 X20 Y20 {ER10} {Z-20} {K1.5} {EK2}\n" MILL_END},
    {"G85", "mill", kMillTools, MILL_START "N40 G85 X20 Y20 {ER2} {Z-20} {EF50} {F100}\n" MILL_END},
    {"G86", "mill", kMillTools,
     MILL_START "N40 G86 X20 Y20 {ER2} {Z-20} {EP2} {EC30} {EA10} {F100}\n" MILL_END},
    {"G87", "mill", kMillTools,
     MILL_START "N40 G87 X20 Y20 {ER2} {Z-30} {P6} {Q2} {EP.5} {F100}\n" MILL_END},
    {"G88", "mill", kMillTools, MILL_START "N40 G88 X20 Y20 {ER2} {Z-20} {F100}\n" MILL_END},
    {"G89", "mill", kMillTools, MILL_START "N40 G89 X20 Y20 {ER2} {Z-20} {EF1} {F100}\n" MILL_END},
    {"G31", "mill", kMillTools,
     MILL_START "N35 S200\nN40 G31 X30 Y30 {ER5} {Z-20} {K3} {P4} {F2} {EF1} {EC0}\n" MILL_END},
};

// The lathe's cycles (G86 and G88 are not the lathe's: error 2): the
// handbook's %555 profile for G64 and G65 (seed 000 l.2511), %100 for G63, %2
// for G66, the M20 thread for G33.
#define P555_PROFILE                                                                          \
    "%555\nN10 T1 D1 M6\nN20 G92 S2000\nN30 G X200 Z150\nN40 G96 S100 M3 M40\nN50 G79 N200\n" \
    "N100 X140 Z0\nN110 G2 X120 Z10 R10\nN120 G1 X60\nN130 Z20\nN140 X40 Z30\nN150 Z40\n"     \
    "N160 X60 Z50\nN170 Z60\nN180 X25 Z90\nN190 X0\n"
#define LATHE_START "%1\nN10 T1 D1 M6\nN20 G97 S800 M3 M40\nN30 G0 X60 Z5\n"
#define LATHE_END "N90 G80 G0 X100 Z50\nN99 M2\n"
const Template kLatheCycles[] = {
    {"G64 P",
     "lathe",
     {},
     P555_PROFILE "N200 G64 N100 N190 {I.5} {K.2} {P2} {F200}\nN210 X144 Z0\nN220 Z10\n"
                  "N230 X40 Z94\nN240 X0\nN250 G80 X200 Z150\nN260 M2\n"},
    {"G64 R",
     "lathe",
     {},
     P555_PROFILE "N200 G64 N190 N100 {I.5} {K.2} {R3} {F200}\nN210 X144 Z0\nN220 Z10\n"
                  "N230 X40 Z94\nN240 X0\nN250 G80 X200 Z150\nN260 M2\n"},
    {"G65",
     "lathe",
     {},
     P555_PROFILE
     "N200 G79 N300\nN300 G97 S800\nN310 T3 D3 M6\nN320 G X70 Z50\nN330 G96 S80 F150\nN340 X62\n"
     "N350 G65 N120 N170 {EA-135} {P2} {Z20} {I.5} {K.2} {Q1} {EF100}\n"
     "N360 G G80 X200 Z150\nN370 M2\n"},
    {"G63",
     "lathe",
     {},
     "%100\nN10 G G52 X150 Z200\nN20 T5 D5 M6\nN30 S900 M40 M3\nN40 X10 Z10\nN50 G92 S3000\n"
     "N60 G96 S70\nN70 G95 F.1\n"
     "N80 G63 N120 N220 {X16} {Z5} {EU50} {EZ-92} {P2} {EB110} {EC70} {ER.2} {Q1} {EQ.5} {EF.1}\n"
     "N90 G Z5\nN100 G G52 X150 Z200\nN110 G79 N250\n"
     "N120 G41 X50 Z5\nN140 G1 X30 Z-5\nN150 Z-20\nN160 X40 Z-25\nN170 Z-45 EB2\n"
     "N180 G2 X40 Z-55 I40 K-50 EB2\nN190 G1 Z-75\nN200 X30 Z-80\nN210 Z-85\nN220 X16 Z-92\n"
     "N250 M2\n"},
    {"G66",
     "lathe",
     {},
     "%2\nN10 T5 D5 M6\nN20 G X200 Z100\nN30 G96 S150 M3 M40\nN40 G92 S2000\nN50 G95 F.1\n"
     "N530 G D10 X27 Z-32.3\nN540 G66 {D11} {X23} {Z-27.8} {EA5} {R4} {EP.5} {EF1} {F.05}\n"
     "N550 G80 G Z5\nN560 M2\n"},
    {"G66 P",
     "lathe",
     {},
     "%2\nN10 T5 D5 M6\nN20 G X200 Z100\nN30 G96 S150 M3 M40\nN40 G92 S2000\nN50 G95 F.1\n"
     "N530 G D10 X60 Z2\nN540 G66 D11 {X40} {Z-3} {P4} {EF1}\nN550 G80 G Z5\nN560 M2\n"},
    {"G33 degressive",
     "lathe",
     {},
     "%1\nN10 T1 D1 M6\nN20 G97 S500 M3 M40\nN30 G0 X24 Z64\n"
     "N40 G33 {X20} {Z10} {K2.5} {P2.165} {Q.05} {R3} {EA0} {EB30} {F2} {S6}\n"
     "N50 G0 X100 Z100\nN60 M2\n"},
    {"G33 constant",
     "lathe",
     {},
     "%1\nN10 T1 D1 M6\nN20 G97 S500 M3 M40\nN30 G0 X24 Z64\n"
     "N40 G33 X20 Z10 {K2.5} {P2.165} {Q0} {ES5}\nN50 G0 X100 Z100\nN60 M2\n"},
    {"G38",
     "lathe",
     {},
     "%1\nN10 T1 D1 M6\nN20 G97 S500 M3 M40\nN30 G0 X19 Z5\n"
     "N40 G38 {X19} {Z-20} {K1.5}\nN50 {X25} {Z-30} {K2}\nN60 G0 X100 Z100\nN70 M2\n"},
    {"lathe G81", "lathe", {}, LATHE_START "N40 G0 X0\nN50 G81 {Z-20} {ER2} {F.1}\n" LATHE_END},
    {"lathe G82", "lathe", {}, LATHE_START "N40 G0 X0\nN50 G82 {Z-20} {EF1} F.1\n" LATHE_END},
    {"lathe G83",
     "lathe",
     {},
     LATHE_START "N40 G0 X0\nN50 G83 {Z-30} {P12} {Q3} {EP1} {ER3} F.1\n" LATHE_END},
    {"lathe G84", "lathe", {}, LATHE_START "N40 G0 X0\nN50 G84 {Z-20} {K1.5} {EK1}\n" LATHE_END},
    {"lathe G85", "lathe", {}, LATHE_START "N40 G0 X0\nN50 G85 {Z-20} {EF.2} F.1\n" LATHE_END},
    {"lathe G87",
     "lathe",
     {},
     LATHE_START "N40 G0 X0\nN50 G87 {Z-30} {ES3} {EP.5} F.1\n" LATHE_END},
    {"lathe G89", "lathe", {}, LATHE_START "N40 G0 X0\nN50 G89 {Z-20} {EF1} F.1\n" LATHE_END},
};

// A swept word of a template: where it is and its address.
struct Swept {
    size_t at, len;  // the braces included
    std::string addr;
};

std::vector<Swept> words_of(const std::string& t) {
    std::vector<Swept> out;
    for (size_t at = t.find('{'); at != std::string::npos; at = t.find('{', at + 1)) {
        size_t end = t.find('}', at);
        size_t k = at + 1;
        while (k < end && t[k] >= 'A' && t[k] <= 'Z') ++k;
        out.push_back({at, end + 1 - at, t.substr(at + 1, k - at - 1)});
    }
    return out;
}

// The template's program with word `swept` (-1: none) reading L1 = `expr`.
std::string program(const std::string& t, const std::vector<Swept>& ws, int swept,
                    const char* expr) {
    std::string out;
    size_t from = 0;
    for (size_t i = 0; i < ws.size(); ++i) {
        out += t.substr(from, ws[i].at - from);
        if (int(i) == swept)
            out += ws[i].addr + "L1";
        else
            out += t.substr(ws[i].at + 1, ws[i].len - 2);
        from = ws[i].at + ws[i].len;
    }
    out += t.substr(from);
    if (swept >= 0) {  // L1 set in a block of its own after the % line
        size_t nl = out.find('\n');
        out.insert(nl + 1, std::string("N1 L1=") + expr + "\n");
    }
    return out;
}

struct Ends final : MachineSink {
    int m02 = 0;
    void end(const Loc&, int m) override { m02 += m == 2; }
};

std::string current;  // the run under way, for a sanitizer's report

struct Outcome {
    bool ok = false;
    bool at_m02 = false;
    int code = 0;
    std::string what;
    double seconds = 0;
};

// Runs one program: it ends at M02, or with an error of the NUM list (or one
// of pupitre's own numbers other than the loop guard's 1001).
Outcome run(const MachineProfile& m, const Template& t, const std::string& text) {
    Outcome o;
    auto t0 = std::chrono::steady_clock::now();
    ProgramMemory mem;
    if (std::optional<Diag> d = mem.load_text("sweep.iso", text)) {
        o.what = "the program does not load: error " + std::to_string(d->code);
        return o;
    }
    Ends ends;
    RunOptions opt;
    opt.max_blocks = 100000;  // and twice as many moves, counted within a block too
    Interpreter in(m, mem, ends, opt);
    for (const auto& [k, v] : t.sets) in.set(k, v);
    in.start(mem.first());
    StepResult r = in.run_to_end();
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Diag* err = nullptr;
    for (const Diag& x : in.diags())
        if (x.is_error() && !err) err = &x;
    if (r == StepResult::ended && !err && ends.m02 == 1) {
        o.ok = o.at_m02 = true;
        return o;
    }
    if (r != StepResult::error || !err) {
        o.what = "the run ended without M02 and without an error";
        return o;
    }
    o.code = err->code;
    o.what =
        "error " + std::to_string(err->code) + " N" + std::to_string(err->n) + ": " + err->detail;
    const bool known = !num_error_text(err->code).empty() ||
                       (err->code >= 1000 && !pupitre_diag_text(err->code).empty());
    if (err->code == err::kBlockBudget)
        o.what += " (the move budget: a runaway cycle)";
    else if (!known)
        o.what += " (not a NUM error number)";
    else
        o.ok = true;
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const bool verbose = argc > 1 && std::strcmp(argv[1], "-v") == 0;
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // what ran before a crash is printed
#ifdef PUPITRE_SWEEP_SANITIZED
    __sanitizer_set_death_callback([] {
        std::fprintf(stderr, "cycle sweep: the report above is from %s\n", current.c_str());
    });
#endif
    MachineProfile mill, lathe;
    if (!builtin_machine("mill", mill) || !builtin_machine("lathe", lathe)) {
        std::fprintf(stderr, "cycle sweep: no built-in mill or lathe\n");
        return 2;
    }
    constexpr double kRunSeconds = 10;  // under ASan on a loaded machine
    int runs = 0, at_m02 = 0, with_error = 0, failures = 0, templates = 0, args = 0;
    double slowest = 0;
    std::string slowest_name;
    std::map<int, int> codes;
    auto sweep = [&](const MachineProfile& m, const Template& t) {
        ++templates;
        const std::string text = t.text;
        const std::vector<Swept> ws = words_of(text);
        args += int(ws.size());
        for (int w = -1; w < int(ws.size()); ++w) {
            for (const Value& v : kValues) {
                current = std::string(t.name) + (w < 0 ? std::string(" as written")
                                                       : " " + ws[size_t(w)].addr + "=" + v.label);
                const Outcome o = run(m, t, program(text, ws, w, v.expr));
                ++runs;
                at_m02 += o.at_m02;
                with_error += o.ok && !o.at_m02;
                if (o.code) ++codes[o.code];
                if (o.seconds > slowest) slowest = o.seconds, slowest_name = current;
                bool bad = !o.ok || (w < 0 && !o.at_m02) || o.seconds > kRunSeconds;
                if (verbose || bad)
                    std::fprintf(bad ? stderr : stdout, "%s%s: %s (%.3f s)\n", bad ? "FAIL " : "",
                                 current.c_str(), o.at_m02 ? "M02" : o.what.c_str(), o.seconds);
                failures += bad;
                if (w < 0) break;  // the template as written runs once
            }
        }
    };
    for (const Template& t : kMillCycles) sweep(mill, t);
    for (const Template& t : kLatheCycles) sweep(lathe, t);
    std::string hist;
    for (const auto& [c, n] : codes) hist += " " + std::to_string(c) + "x" + std::to_string(n);
    std::printf(
        "cycle sweep: %d templates, %d arguments, %d runs, %d ended at M02, %d with a NUM "
        "error, %d failed; slowest %.3f s (%s)\n",
        templates, args, runs, at_m02, with_error, failures, slowest, slowest_name.c_str());
    if (verbose) std::printf("errors:%s\n", hist.c_str());
    return failures ? 1 : 0;
}
