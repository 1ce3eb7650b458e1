// G45 simple pockets: circular, oblong, rectangular with corner fillets
// (000:5943-6076; pupitre-iso(5), POCKETS): roughing by layers P and contours Q from the
// centre outwards, floor finishing by I, wall finishing by J.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

namespace {
using ::pupitre::geometry::ceil_um;
using ::pupitre::geometry::kPi;

// A closed tool-centre contour about the pocket centre (0, 0), as pieces.
struct Piece {
    bool arc = false;
    double x = 0, y = 0;    // end
    double cx = 0, cy = 0;  // arc centre
    double sweep = 0;       // radians
};

// Shape at one offset: rectangle (hx, hy, corner r), circle (r) or stadium
// (half-length l along X, radius r). Starts on the small-side axis, +direction.
std::vector<Piece> contour(int shape, double hx, double hy, double r, bool ccw, double& sx,
                           double& sy) {
    std::vector<Piece> out;
    auto line = [&](double x, double y) { out.push_back({false, x, y, 0, 0, 0}); };
    auto arc = [&](double x, double y, double cx, double cy, double sw) {
        out.push_back({true, x, y, cx, cy, sw});
    };
    if (shape == 1) {  // circle
        sx = r, sy = 0;
        arc(r, 0, 0, 0, 2 * kPi);
    } else if (shape == 2) {  // stadium along X: small side Y
        double l = hx;
        sx = 0, sy = r;
        line(-l, r);
        arc(-l, -r, -l, 0, kPi);
        line(l, -r);
        arc(l, r, l, 0, kPi);
        line(0, r);
    } else {  // rectangle
        r = std::min(r, std::min(hx, hy));
        bool along_x = hx <= hy;  // the lateral step follows the small side
        sx = along_x ? hx : 0, sy = along_x ? 0 : hy;
        // Counter-clockwise from the start point; corners as quarter circles.
        std::vector<std::pair<double, double>> corners = {
            {hx, hy}, {-hx, hy}, {-hx, -hy}, {hx, -hy}};
        int first = along_x ? 0 : 1;  // the corner after the start point
        for (int k = 0; k < 4; ++k) {
            auto [cxs, cys] = corners[size_t((first + k) % 4)];
            double sgx = cxs > 0 ? 1 : -1, sgy = cys > 0 ? 1 : -1;
            // Entry and exit points of the corner going counter-clockwise.
            int idx = (first + k) % 4;
            double ex, ey, fx, fy;
            if (idx == 0)
                ex = hx, ey = hy - r, fx = hx - r, fy = hy;
            else if (idx == 1)
                ex = -hx + r, ey = hy, fx = -hx, fy = hy - r;
            else if (idx == 2)
                ex = -hx, ey = -hy + r, fx = -hx + r, fy = -hy;
            else
                ex = hx - r, ey = -hy, fx = hx, fy = -hy + r;
            line(ex, ey);
            if (r > 1e-9) arc(fx, fy, cxs - sgx * r, cys - sgy * r, kPi / 2);
        }
        line(sx, sy);
    }
    if (!ccw) {
        // Same contour clockwise: reverse the pieces.
        std::vector<Piece> rev;
        double px = sx, py = sy;
        std::vector<std::pair<double, double>> starts;
        for (const Piece& p : out) {
            starts.push_back({px, py});
            px = p.x, py = p.y;
        }
        for (size_t i = out.size(); i-- > 0;) {
            Piece p = out[i];
            p.x = starts[i].first, p.y = starts[i].second;
            p.sweep = -p.sweep;
            rev.push_back(p);
        }
        out = rev;
    }
    return out;
}
}  // namespace

// One G45 pocket: its words, its shape at the tool centre, and its passes.
struct Interpreter::Pocket45 {
    struct W {
        bool has = false;
        double v = 0;
    };

    explicit Pocket45(Interpreter& interp) : in(interp) {}

    Interpreter& in;
    W ex, ey, eb, P, Q, I, J, er, eg;
    double R = 0;   // tool radius
    int shape = 0;  // 1 circle, 2 oblong, 3 rectangle
    double hx = 0, hy = 0, rc = 0, half_small = 0;
    bool rough = false, floor = false, wall = false;
    double ei = 0, ej = 0;  // finishing feeds
    double cx = 0, cy = 0;  // the centre
    double zb = 0, top = 0, z = 0;
    bool ccw = true;
    double d = 0;  // lateral distance from the centre to the final contour

    bool words(const Plan& p);
    bool sizes();
    bool feeds();
    bool place(const Plan& p);
    bool steps() const;
    bool go(int g, double x, double y, double to_z, double feed);
    bool run_contour(double off, double feed);
    std::vector<double> passes(double reach) const;
    std::vector<double> layers(double from, double to) const;
    bool roughing();
    bool wall_finish();
    bool floor_finish();
};

bool Interpreter::pocket(const Plan& p) {
    if (modal_.plane != 17) return fail(885, tr("G45 pockets are machined in the XY plane (G17)"));
    if (modal_.radcomp != 40) return fail(140, tr("G45 under radius compensation"));
    Pocket45 k{*this};
    if (!k.words(p) || !k.sizes() || !k.feeds() || !k.place(p) || !k.steps()) return false;

    Modal saved = modal_;
    modal_.feed_mode = 94;
    modal_.feed_set = true;
    OwnFeed own(*this);  // EP EQ EI EJ
    k.z = prog_[Z];
    // 1-2. To the centre, then to ER.
    if (!k.go(0, 0, 0, k.z, 0)) return false;
    if (k.er.has && !k.go(0, 0, 0, k.top, 0)) return false;
    k.z = k.top;
    if (k.rough && !k.roughing()) return false;
    if (k.wall && !(k.rough && k.I.has) && !k.wall_finish()) return false;
    if (k.floor && !k.floor_finish()) return false;
    // 7. Lift 1 mm, back to the centre, up to ER.
    if (!k.go(0, prog_[X] - k.cx, prog_[Y] - k.cy, k.z + 1, 0)) return false;
    if (!k.go(0, 0, 0, k.z + 1, 0)) return false;
    if (!k.go(0, 0, 0, k.top, 0)) return false;
    modal_ = saved;
    return true;
}

// The words of the block; the feeds EP EQ EI EJ are kept for the next G45.
bool Interpreter::Pocket45::words(const Plan& p) {
    for (int i = 0; i < p.cycle_words.n; ++i) {
        Addr a = p.cycle_words.word[i].a;
        double v = p.cycle_words.word[i].v;
        W* w = a == addrE('X')   ? &ex
               : a == addrE('Y') ? &ey
               : a == addrE('B') ? &eb
               : a == addr1('P') ? &P
               : a == addr1('Q') ? &Q
               : a == addr1('I') ? &I
               : a == addr1('J') ? &J
               : a == addrE('R') ? &er
               : a == addrE('G') ? &eg
                                 : nullptr;
        if (w) *w = {true, v};
        if (a == addrE('P')) in.pocket_ep_ = v;
        if (a == addrE('Q')) in.pocket_eq_ = v;
        if (a == addrE('I')) in.pocket_ei_ = v;
        if (a == addrE('J')) in.pocket_ej_ = v;
        if ((a == addr1('P') || a == addr1('Q') || a == addr1('I') || a == addr1('J')) && v < 0)
            return in.fail(
                835, strf(tr("%s must be positive in G45"), std::string(addr_name(a)).c_str()));
    }
    return true;
}

// The shape from EX EY EB, reduced by the tool radius.
bool Interpreter::Pocket45::sizes() {
    const Corrector& c = in.corr_[size_t(in.modal_.d)];
    R = c.r + c.dr;
    if (in.modal_.d == 0 || R <= 0)
        return in.fail(898, tr("G45 needs a tool corrector with a radius (D0 active)"));
    if (ey.has && !ex.has) return in.fail(889, tr("G45: EY without EX"));
    if (ex.has && ey.has) {
        shape = 3;
        if (eb.has && eb.v > 0 && eb.v < R)
            return in.fail(886, tr("G45: the corner radius EB is smaller than the tool radius"));
        half_small = std::min(ex.v, ey.v) / 2;
        hx = ex.v / 2 - R, hy = ey.v / 2 - R, rc = eb.has ? std::max(eb.v - R, 0.0) : 0;
    } else if (ex.has && eb.has) {
        shape = 2;
        if (ex.v < 2 * eb.v) return in.fail(897, tr("G45: the oblong is shorter than its width"));
        half_small = eb.v;
        hx = ex.v / 2 - eb.v, hy = 0, rc = eb.v - R;
    } else if (eb.has) {
        shape = 1;
        if (eb.v <= R)
            return in.fail(886, tr("G45: the pocket radius EB is not larger than the tool radius"));
        half_small = eb.v;
        hx = hy = 0, rc = eb.v - R;
    } else {
        return in.fail(889, tr("G45 needs EB, EX EY or EX EB"));
    }
    if (half_small <= R) return in.fail(896, tr("G45: the pocket is not wider than the tool"));
    return true;
}

// Which operations P Q I J ask for, and their feeds.
bool Interpreter::Pocket45::feeds() {
    if (Q.has && Q.v > 2 * R)
        return in.fail(887, tr("G45: the step-over Q is larger than the tool diameter"));
    rough = P.has && Q.has, floor = Q.has && I.has, wall = P.has && J.has;
    if (!rough && !floor && !wall)
        return in.fail(889, tr("G45 needs P and Q, Q and I, or P and J"));
    if (rough && in.pocket_ep_ <= 0) return in.fail(892, tr("G45: no axial feed EP programmed"));
    if (rough && in.pocket_eq_ <= 0) return in.fail(893, tr("G45: no lateral feed EQ programmed"));
    ei = in.pocket_ei_ > 0 ? in.pocket_ei_ : in.pocket_ep_,
    ej = in.pocket_ej_ > 0 ? in.pocket_ej_ : in.pocket_eq_;
    if (ei <= 0 || ej <= 0) return in.fail(892, tr("G45: no finishing feed (EI, EJ or EP, EQ)"));
    return true;
}

// The centre (X Y of the block, else the current point), the bottom and the top.
bool Interpreter::Pocket45::place(const Plan& p) {
    const Axes& prog = in.prog_;
    cx = p.to.axis[X] ? (p.to.inc[X] ? prog[X] + p.to.val[X] : p.to.val[X]) : prog[X];
    cy = p.to.axis[Y] ? (p.to.inc[Y] ? prog[Y] + p.to.val[Y] : p.to.val[Y]) : prog[Y];
    if (!p.to.axis[Z]) return in.fail(882, tr("G45: the pocket bottom Z is not programmed"));
    zb = p.to.inc[Z] ? prog[Z] + p.to.val[Z] : p.to.val[Z];
    top = er.has ? er.v : prog[Z];
    if (er.has && std::fabs(er.v - zb) < 1e-9)
        return in.fail(891, tr("G45: ER is the pocket bottom"));
    ccw = !(eg.has && std::lround(eg.v) == 2);
    d = half_small - R;
    return true;
}

// The steps P and Q divide the depth and the width (passes(), layers()): a
// step of zero, or one so small that the pocket takes more contours than any
// pocket needs, is refused before a move. Error 881 "incompatible parameter
// value" (seed 000 l.13458), the number G83 gives a zero peck: the handbook
// has no number of its own for a zero step, 835 (seed 000 l.13445) is for a
// signed one.
bool Interpreter::Pocket45::steps() const {
    for (const auto& [w, name] : {std::pair{&P, "P"}, std::pair{&Q, "Q"}})
        if (w->has && !(w->v > 0))
            return in.fail(881, strf(tr("%s0 in G45: a step of zero never reaches the end"), name));
    // More contours than any pocket needs: an input mistake, not hours of moves.
    constexpr double kMaxContours = 10000;
    const double n_p = P.has ? std::ceil((top - zb) / P.v) : 1;
    const double n_q = Q.has ? std::ceil(d / Q.v) + 1 : 1;
    if (!(n_p <= kMaxContours))
        return in.fail(
            881, strf(tr("G45: the axial step P makes more than %d layers"), int(kMaxContours)));
    if (!(n_q <= kMaxContours))
        return in.fail(881, strf(tr("G45: the step-over Q makes more than %d contours a layer"),
                                 int(kMaxContours)));
    if (!(n_p * n_q <= kMaxContours))
        return in.fail(
            881, strf(tr("G45: the steps P and Q make more than %d contours"), int(kMaxContours)));
    return true;
}

bool Interpreter::Pocket45::go(int g, double x, double y, double to_z, double feed) {
    Axes t = in.prog_;
    t[X] = cx + x, t[Y] = cy + y, t[Z] = to_z;
    in.modal_.feed = feed;
    return in.cycle_move(g, t);
}

// One contour `off` inside the final one, from its start point.
bool Interpreter::Pocket45::run_contour(double off, double feed) {
    double sx, sy;
    auto pcs = contour(shape, std::max(hx - off, 0.0), std::max(hy - off, 0.0),
                       std::max(rc - off, 0.0), ccw, sx, sy);
    if (shape == 1) {
        pcs = contour(1, 0, 0, d - off, ccw, sx, sy);
    } else if (shape == 2) {
        pcs = contour(2, hx, 0, d - off, ccw, sx, sy);
    }
    if (!go(1, sx, sy, z, feed)) return false;
    in.modal_.feed = feed;
    const Axes& prog = in.prog_;
    for (const Piece& pc : pcs) {
        Axes t = prog;
        t[X] = cx + pc.x, t[Y] = cy + pc.y;
        if (!pc.arc) {
            if (!in.cycle_move(1, t)) return false;
        } else if (!in.emit_arc(pc.sweep > 0 ? 3 : 2, t, X, Y, cx + pc.cx, cy + pc.cy, pc.sweep,
                                std::hypot(prog[X] - cx - pc.cx, prog[Y] - cy - pc.cy),
                                std::hypot(pc.x - pc.cx, pc.y - pc.cy), -1)) {
            return false;
        }
    }
    return true;
}

// Offsets (inward from the final contour) of the lateral passes out to `reach`.
std::vector<double> Interpreter::Pocket45::passes(double reach) const {
    std::vector<double> at;  // distances from the centre
    if (reach <= 1e-9) return at;
    double start = 0;
    if (Q.v > R && shape != 1) {
        at.push_back(std::min(R / 2, reach));
        start = at.back();
    }
    double rest = reach - start;
    if (rest > 1e-9) {
        int n = std::max(1, int(std::ceil(rest / Q.v - 1e-9)));
        double q = ceil_um(rest / n);
        for (int k = 1; k < n; ++k) at.push_back(start + k * q);
        at.push_back(reach);
    }
    return at;
}

// The levels of the axial steps P from `from` down to `to`.
std::vector<double> Interpreter::Pocket45::layers(double from, double to) const {
    std::vector<double> zs;
    double depth = from - to;
    if (depth <= 1e-9) return zs;
    int n = std::max(1, int(std::ceil(depth / P.v - 1e-9)));
    double q = ceil_um(depth / n);
    for (int k = 1; k < n; ++k) zs.push_back(from - k * q);
    zs.push_back(to);
    return zs;
}

bool Interpreter::Pocket45::roughing() {
    const double rough_bottom = (floor ? zb + I.v : zb);
    const double rough_reach = d - (wall || J.has ? J.v : 0);
    for (double lz : layers(top, rough_bottom)) {
        if (!go(0, 0, 0, z, 0)) return false;  // back to the centre at the current level
        z = lz;
        if (!go(1, 0, 0, z, in.pocket_ep_)) return false;
        for (double off : passes(rough_reach))
            if (!run_contour(d - off, in.pocket_eq_)) return false;
        if (wall && I.has && !run_contour(0, ej)) return false;  // P Q I J: chained per layer
    }
    return true;
}

// Wall finishing on the final contour, in axial steps P down to the bottom (or
// I above it when the floor is not finished in this call).
bool Interpreter::Pocket45::wall_finish() {
    double wall_bottom = (I.has && !floor) ? zb + I.v : zb;
    if (!go(0, 0, 0, z, 0)) return false;
    for (double lz : layers(top, wall_bottom)) {
        z = lz;
        if (!go(1, 0, 0, z, ei)) return false;
        if (!run_contour(0, ej)) return false;
        if (!go(0, 0, 0, z, 0)) return false;
    }
    return true;
}

bool Interpreter::Pocket45::floor_finish() {
    if (!go(0, 0, 0, z, 0)) return false;
    z = zb;
    if (!go(1, 0, 0, z, ei)) return false;
    double reach = (J.has && !wall) ? d - J.v : d;
    for (double off : passes(reach))
        if (!run_contour(d - off, ej)) return false;
    return true;
}

}  // namespace pupitre
