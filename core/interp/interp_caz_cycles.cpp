// The Cazeneuve dialect's fixed cycles (seed 003, chapter VI §16-17;
// pupitre-cazeneuve(5)): each turns its words into the elementary moves of
// the shared machinery (a G0, a G1 at a feed per revolution, a G33 pass).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/caz.hpp"
#include "core/interp/plan.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

bool Interpreter::CazState::is_cycle(int g) {
    return g == 31 || g == 34 || g == 71 || g == 81 || g == 82 || g == 92;
}

int Interpreter::CazState::cycle_of(const Plan& p) {
    for (int g : {31, 34, 71, 81, 82, 92})
        if (p.g[size_t(g)]) return g;
    return -1;
}

// The fixed cycles (003:1306-1308): G71 and G81 are the turning cycle, as
// chapter VI's §16 writes it (003:1405) and as its list and the CNP's name it
// (003:1307, 1798); G92 and G82 the facing cycle likewise (003:1471, 1308,
// 1799). G31 is the threading cycle G71 "generates" (003:1418), the one
// G33 revokes beside G34 (003:1160), and ex13's taper threading cycle
// (003:1393): the thesis gives it no words of its own, so it runs as G34.
bool Interpreter::CazState::cycle(Interpreter& in, const Plan& p) {
    struct CycleEntry {
        int g;
        bool (*run)(Interpreter&, const Plan&);
    };
    static constexpr CycleEntry kCycles[] = {{31, &CazState::g34},     {34, &CazState::g34},
                                             {71, &CazState::turning}, {81, &CazState::turning},
                                             {82, &CazState::g92},     {92, &CazState::g92}};
    const int g = cycle_of(p);
    for (const CycleEntry& e : kCycles)
        if (e.g == g) {
            in.first_move_ = false;
            return e.run(in, p);
        }
    return true;
}

bool Interpreter::CazState::ends_comp(const Interpreter& in, const Plan& p) {
    if (p.tech.has_t || p.g[7] || p.g[33] || cycle_of(p) >= 0 || in.modal_.motion == 33)
        return true;
    for (int i = 0; i < p.tech.nm; ++i)
        if (p.tech.m[i] <= 2) return true;
    return in.caz_->m30;
}

bool Interpreter::CazState::end_comp(Interpreter& in) {
    if (in.comp_.on && !in.comp_exit(nullptr)) return false;
    in.modal_.radcomp = 40;
    return true;
}

// The turning and facing cycles' feed per revolution (F or K in µm/rev),
// theirs for their passes only: the program's feed mode and F come back after.
struct Interpreter::CazState::CycleFeed {
    Interpreter& in;
    const Modal saved;
    OwnFeed own;
    CycleFeed(Interpreter& i, double per_rev) : in(i), saved(i.modal_), own(i) {
        in.modal_.feed_mode = 95;
        in.modal_.feed = per_rev;
        in.modal_.feed_set = true;
    }
    ~CycleFeed() {
        in.modal_.feed_mode = saved.feed_mode;
        in.modal_.feed = saved.feed;
        in.modal_.feed_set = saved.feed_set;
    }
    CycleFeed(const CycleFeed&) = delete;
    CycleFeed& operator=(const CycleFeed&) = delete;
};

bool Interpreter::CazState::move(Interpreter& in, int g, double x, double z) {
    Plan q;
    q.to.axis.set(X).set(Z);
    q.to.val[X] = x;
    q.to.val[Z] = z;
    const int saved = in.modal_.motion;
    in.cycle_pass(g != 0);
    in.modal_.motion = g;
    const bool ok = in.caz_motion(q);
    in.modal_.motion = saved;
    return ok;
}

// G34 X Z I K D F|S, the threading cycle (003:1306-1336): from the point
// where the block finds the tool, each pass plunges in X at rapid, threads to
// Z at the pitch (K the radius gained by Z for a taper, 003:1326), retracts in
// X to the start and returns in Z: the four phases, repeated with a pass I
// deeper each time (003:1332-1342), from X + D (the crest) to the final X.
bool Interpreter::CazState::g34(Interpreter& in, const Plan& p) {
    const Args& a = in.caz_->args;
    const int g = cycle_of(p);  // G34, or G31 which runs as it
    if (!p.to.axis[X] || !p.to.axis[Z] || !a.has_i || !a.has_d || !(a.has_f || a.has_s))
        return in.fail(caz::kFunction, strf(tr("G%d needs X, Z, I, D and the pitch in F or S "
                                               "(003:1316-1330)"),
                                            g));
    if (a.i <= 0 || a.d <= 0)
        return in.fail(caz::kFunction,
                       strf(tr("G%d: I and D must be positive (003:1324, 1328)"), g));
    const double x0 = in.prog_[X], z0 = in.prog_[Z];
    const double xf = p.to.val[X], zf = p.to.val[Z];
    const double pass = a.i * caz::kUm, depth = a.d * caz::kUm, taper = a.k * caz::kUm;
    const double pitch = (a.has_s ? a.s : a.f) * caz::kUm;
    if (pitch > caz::kMaxPitch)
        return in.fail(caz::kPitch, strf(tr("pitch %s mm above the 60 mm maximum (003:1163)"),
                                         fixed3(pitch, 63).c_str()));
    // Outside the thread (X falls towards the final X) or inside it.
    const double dir = xf <= x0 ? -1.0 : 1.0;
    const double crest = xf - dir * depth;
    const int passes = int(std::ceil(depth / pass - 1e-9));
    const double saved_pitch = in.caz_->pitch;
    in.caz_->pitch = pitch;
    bool ok = true;
    for (int k = 1; k <= passes && ok; ++k) {
        const double x = k == passes ? xf : crest + dir * pass * k;
        ok = move(in, 0, x, z0) && move(in, 33, x + taper, zf) && move(in, 0, x0, zf) &&
             move(in, 0, x0, z0);
    }
    in.caz_->pitch = saved_pitch;
    return ok;
}

// G71 (or G81) X Z I K D F, the turning cycle (003:1399-1418): from the
// starting point (003:1401) each pass goes to its X at rapid, turns to Z at F
// µm per revolution (K the radius gained at Z for a taper, 003:1411-1414),
// retracts in X to the start and returns in Z, from X + D down by I to the
// final X, as G34's passes go.
bool Interpreter::CazState::turning(Interpreter& in, const Plan& p) {
    const Args& a = in.caz_->args;
    if (!p.to.axis[X] || !p.to.axis[Z] || !a.has_i || !a.has_d || !a.has_f)
        return in.fail(caz::kFunction, tr("the turning cycle needs X, Z, I, D and F "
                                          "(003:1405-1417)"));
    if (a.i <= 0 || a.d <= 0 || a.f <= 0)
        return in.fail(caz::kFunction,
                       tr("the turning cycle: I, D and F must be positive (003:1410-1417)"));
    const double x0 = in.prog_[X], z0 = in.prog_[Z];
    const double xf = p.to.val[X], zf = p.to.val[Z];
    const double pass = a.i * caz::kUm, depth = a.d * caz::kUm, taper = a.k * caz::kUm;
    const double dir = xf <= x0 ? -1.0 : 1.0;
    const double crest = xf - dir * depth;
    const int passes = int(std::ceil(depth / pass - 1e-9));
    const CycleFeed feed(in, a.f * caz::kUm);
    bool ok = true;
    for (int k = 1; k <= passes && ok; ++k) {
        const double x = k == passes ? xf : crest + dir * pass * k;
        ok = move(in, 0, x, z0) && move(in, 1, x + taper, zf) && move(in, 0, x0, zf) &&
             move(in, 0, x0, z0);
    }
    return ok;
}

// G92 X Z I K, the facing cycle (003:1467-1477), not the NUM's preset: the
// tool waits about 2 mm off the part in X and flush with its face in Z; each
// pass goes I deeper in Z at rapid, faces down to X at K µm per revolution,
// returns to the face's Z and to the start X, until the final Z.
bool Interpreter::CazState::g92(Interpreter& in, const Plan& p) {
    const Args& a = in.caz_->args;
    if (!p.to.axis[X] || !p.to.axis[Z] || !a.has_i || !a.has_k)
        return in.fail(caz::kFunction, tr("G92 needs X, Z, I and K (003:1471-1477)"));
    if (a.i <= 0 || a.k <= 0)
        return in.fail(caz::kFunction, tr("G92: I and K must be positive (003:1476-1477)"));
    const double x0 = in.prog_[X], z0 = in.prog_[Z];
    const double xf = p.to.val[X], zf = p.to.val[Z];
    const double pass = a.i * caz::kUm;
    const double dir = zf <= z0 ? -1.0 : 1.0;
    const int passes = int(std::ceil(std::fabs(zf - z0) / pass - 1e-9));
    const CycleFeed feed(in, a.k * caz::kUm);
    bool ok = true;
    for (int k = 1; k <= passes && ok; ++k) {
        const double z = k == passes ? zf : z0 + dir * pass * k;
        ok = move(in, 0, x0, z) && move(in, 1, xf, z) && move(in, 0, xf, z0) && move(in, 0, x0, z0);
    }
    return ok;
}

}  // namespace pupitre
