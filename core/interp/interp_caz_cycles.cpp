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
    return g == 34 || g == 92;
}

bool Interpreter::CazState::cycle(Interpreter& in, const Plan& p) {
    struct Entry {
        int g;
        bool (*run)(Interpreter&, const Plan&);
    };
    static constexpr Entry kCycles[] = {{34, &CazState::g34}, {92, &CazState::g92}};
    for (const Entry& e : kCycles)
        if (p.g[size_t(e.g)]) {
            in.first_move_ = false;
            return e.run(in, p);
        }
    return true;
}

bool Interpreter::CazState::move(Interpreter& in, int g, double x, double z) {
    Plan q;
    q.to.axis.set(X).set(Z);
    q.to.val[X] = x;
    q.to.val[Z] = z;
    const int saved = in.modal_.motion;
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
    if (!p.to.axis[X] || !p.to.axis[Z] || !a.has_i || !a.has_d || !(a.has_f || a.has_s))
        return in.fail(caz::kFunction, tr("G34 needs X, Z, I, D and the pitch in F or S "
                                          "(003:1316-1330)"));
    if (a.i <= 0 || a.d <= 0)
        return in.fail(caz::kFunction, tr("G34: I and D must be positive (003:1324, 1328)"));
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
    const Modal saved = in.modal_;
    in.modal_.feed_mode = 95;
    in.modal_.feed = a.k * caz::kUm;
    in.modal_.feed_set = true;
    bool ok = true;
    {
        OwnFeed own(in);
        for (int k = 1; k <= passes && ok; ++k) {
            const double z = k == passes ? zf : z0 + dir * pass * k;
            ok = move(in, 0, x0, z) && move(in, 1, xf, z) && move(in, 0, xf, z0) &&
                 move(in, 0, x0, z0);
        }
    }
    in.modal_.feed_mode = saved.feed_mode;
    in.modal_.feed = saved.feed;
    in.modal_.feed_set = saved.feed_set;
    return ok;
}

}  // namespace pupitre
