// Internal to the interpreter: the decoding of one block, word by word
// (interp_words.cpp: the default meaning of each address; interp_args.cpp: the
// words a G function owns). Readers are picked by address from tables, as
// LinuxCNC's interp_read.cc picks them by letter.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <array>
#include <bitset>

#include "core/interp/plan.hpp"
#include "core/parse/codes.hpp"

namespace pupitre {

struct Interpreter::Decoder {
    // Reads one word into the plan; false once an error is reported.
    using Reader = bool (Decoder::*)(const Word&);

    Decoder(Interpreter& in, Plan& p, const Block& b);
    // word and plain_word run for every word of every block: inlined into
    // decode (interp_words.cpp), they keep the table dispatch as cheap as
    // the one function it replaced (callgrind, tests/perf).
    [[gnu::always_inline]] inline bool word(const Word& w);
    bool finish();

    Interpreter& in;
    Plan& p;
    const MachineProfile& m;
    const bool lathe, diam;
    double unit = 1.0;             // 25.4 when G70 is in force for the block
    bool inc;                      // G91, positionally
    const GCode* owner = nullptr;  // the G function owning the words that follow
    int owner_g = -1;
    bool owned = false;  // the word being read belongs to `owner`
    std::bitset<kAddrCount> seen;
    bool g52_seen = false, axis_seen = false;
    int pqr_sign_col = 0;  // a P± Q± R± met before any G16: error 3 (000:13178)
    int coded_modal = 0, coded_nonmodal = 0;

    bool bad(int code, std::string detail, int column = 0);
    // The value of a word (Interpreter::word_value), inlined into the readers
    // for a number written within its address's format (tests/perf).
    [[gnu::always_inline]] inline bool value(const Word& w, double& out, int* int_out = nullptr);
    static char letter(const Word& w) { return w.addr < 26 ? char('A' + w.addr) : 0; }
    static bool axis_addr(Addr a, int& axis);

    // G words (interp_words.cpp).
    bool g_word(const Word& w);
    bool g_known(int g, const GCode* gc, const Word& w);
    void g_group(int g, Group group);
    bool g_marks(int g, const Word& w);

    // Default meanings, by address (interp_words.cpp).
    [[gnu::always_inline]] inline bool plain_word(const Word& w);
    static const std::array<Reader, kAddrCount>& plain_readers();
    bool axis_word(const Word& w);
    bool ijk_word(const Word& w);
    bool r_word(const Word& w);
    bool feed_word(const Word& w);
    bool speed_word(const Word& w);
    bool tool_word(const Word& w);
    bool corrector_word(const Word& w);
    bool m_word(const Word& w);
    bool ed_word(const Word& w);
    bool eg_word(const Word& w);
    bool ec_word(const Word& w);
    bool em_word(const Word& w);
    bool cycle_or_sign(const Word& w);
    bool cycle_or_pgp(const Word& w);
    bool pgp_word(const Word& w);
    bool no_meaning(const Word& w);
    bool cyc_word(const Word& w);
    bool g29_normal(const Word& w);

    // Words owned by a G function, by G number (interp_args.cpp).
    struct ArgReader {
        int16_t g;
        bool axes_plain;  // its axis words keep their default meaning
        Reader read;      // null: every word keeps its default meaning
    };
    static const ArgReader* arg_reader(int g);
    bool unused_arg(const Word& w);
    bool g4_dwell(const Word& w);
    bool g16_arg(const Word& w);
    bool g51_arg(const Word& w);
    bool g59_arg(const Word& w);
    bool g92_arg(const Word& w);
    bool g96_arg(const Word& w);
    bool g97_arg(const Word& w);
    bool feed_mode_arg(const Word& w);
    bool g77_arg(const Word& w);
    bool label_arg(const Word& w);
    bool g76_arg(const Word& w);
    bool profile_cycle_arg(const Word& w);
    bool spline_arg(const Word& w);
    bool drill_arg(const Word& w);
    bool g46_arg(const Word& w);
    bool g78_arg(const Word& w);
};

}  // namespace pupitre
