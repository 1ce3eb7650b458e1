// The endless-loop guard (issue 14; docs/decisions.md, The endless-loop guard):
// at each backward G79 jump the interpreter takes a 128-bit digest of its
// whole state — where it reads (every frame of the call stack), the L and E
// variables written, the modal state, the position and the frames, the
// program memory's generation (G76 edits). A digest seen before means the
// program came back to a state it was in: it can never end, error 1001 at
// once, however many moves each pass makes (a G79 loop around a G64 roughing
// cycle used to run for hours). The block and move budgets stay as the
// backstop for loops whose state never repeats (a counter that grows).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstring>

#include "core/i18n.hpp"
#include "core/interp/interp.hpp"

namespace pupitre {

namespace {

// Two independent 64-bit mixes (splitmix64 finalisers with different seeds):
// a false repetition needs both to collide.
struct Digest {
    uint64_t a = 0x9e3779b97f4a7c15ULL, b = 0xd1b54a32d192ed03ULL;
    static uint64_t mix(uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    void add(uint64_t v) {
        a = mix(a ^ v) + 0x632be59bd9b4e019ULL;
        b = mix(b + v * 0xff51afd7ed558ccdULL) ^ 0xc4ceb9fe1a85ec53ULL;
    }
    void add(double d) {
        if (d == 0) d = 0;  // -0 and 0 are one state
        uint64_t u;
        std::memcpy(&u, &d, sizeof u);
        add(u);
    }
    void add(int v) { add(uint64_t(int64_t(v))); }
    void add(long v) { add(uint64_t(int64_t(v))); }
    void add(bool v) { add(uint64_t(v)); }
    void add(const Axes& v) {
        for (double d : v) add(d);
    }
};

}  // namespace

// The digest of everything a later block can read (see the file comment).
std::pair<uint64_t, uint64_t> Interpreter::state_digest() const {
    Digest h;
    h.add(uint64_t(stack_.size()));
    for (const Frame& f : stack_) {
        h.add(uint64_t(reinterpret_cast<uintptr_t>(f.prog)));
        h.add(uint64_t(f.pos)), h.add(f.call), h.add(f.whole), h.add(uint64_t(f.range_pos));
        h.add(f.end_line), h.add(f.emptied), h.add(f.repeats);
    }
    for (size_t i = l_.written._Find_first(); i < l_.written.size(); i = l_.written._Find_next(i))
        h.add(uint64_t(i)), h.add(l_.v[i]);
    for (const auto& [n, v] : e_written_) h.add(uint64_t(n)), h.add(uint64_t(v));
    const Modal& m = modal_;
    for (int v : {m.motion, m.plane, m.radcomp, m.feed_mode, m.spindle_mode, m.spindle_dir, m.range,
                  m.cycle, m.tool_axis, m.d, m.t, m.tool_in_spindle})
        h.add(v);
    for (double v : {m.feed, m.s, m.css_x0, m.css_pos0, m.smax, m.g92r, m.eg}) h.add(v);
    for (bool v : {m.incremental, m.feed_set, m.css_known, m.inch, m.tool_axis_neg, m.m7, m.m8,
                   m.overrides_off, m.clamped, m.modif_inhibited, m.radius_x})
        h.add(v);
    h.add(m.g75), h.add(m.coded_m);
    h.add(mach_);
    const Frames& f = frames_;
    h.add(f.pref), h.add(f.dec1), h.add(f.dec3), h.add(f.g59), h.add(f.gauge);
    h.add(f.g53), h.add(uint64_t(f.mirror.to_ulong())), h.add(f.scale_on), h.add(f.scale),
        h.add(f.ed);
    h.add(comp_.on), h.add(comp_.side), h.add(comp_.radius);
    h.add(uint64_t(mem_.generation()));
    return {h.a, h.b};
}

// Called before a backward G79 jump: false (error 1001 raised) when the
// state has been seen at an earlier backward jump.
bool Interpreter::note_backward_jump(long label) {
    // A window of digests keeps memory bounded on long legitimate loops; a
    // loop whose state repeats within it is still caught.
    constexpr size_t kWindow = size_t(1) << 18;
    if (seen_states_.size() >= kWindow) seen_states_.clear();
    auto d = state_digest();
    if (seen_states_.insert(DigestKey{d.first, d.second}).second) return true;
    return fail(err::kBlockBudget,
                strf(tr("endless loop: G79 N%ld comes back to a state the program was "
                        "already in (same block, "
                        "variables, modal state and position), so it can never end"),
                     label));
}

}  // namespace pupitre
