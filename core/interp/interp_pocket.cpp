// G45 simple pockets: circular, oblong, rectangular with corner fillets
// (milling.md §7.1, 000:5943-6076): roughing by layers P and contours Q from the
// centre outwards, floor finishing by I, wall finishing by J.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <numbers>

#include "core/interp/plan.hpp"
#include "core/geometry/geometry.hpp"

namespace pupitre {

namespace {
using ::pupitre::geometry::kPi;
using ::pupitre::geometry::ceil_um;

// A closed tool-centre contour about the pocket centre (0, 0), as pieces.
struct Piece {
    bool arc = false;
    double x = 0, y = 0;     // end
    double cx = 0, cy = 0;   // arc centre
    double sweep = 0;        // radians
};

// Shape at one offset: rectangle (hx, hy, corner r), circle (r) or stadium
// (half-length l along X, radius r). Starts on the small-side axis, +direction.
std::vector<Piece> contour(int shape, double hx, double hy, double r, bool ccw, double& sx, double& sy) {
    std::vector<Piece> out;
    auto line = [&](double x, double y) { out.push_back({false, x, y, 0, 0, 0}); };
    auto arc = [&](double x, double y, double cx, double cy, double sw) { out.push_back({true, x, y, cx, cy, sw}); };
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
        std::vector<std::pair<double, double>> corners = {{hx, hy}, {-hx, hy}, {-hx, -hy}, {hx, -hy}};
        int first = along_x ? 0 : 1;  // the corner after the start point
        for (int k = 0; k < 4; ++k) {
            auto [cxs, cys] = corners[size_t((first + k) % 4)];
            double sgx = cxs > 0 ? 1 : -1, sgy = cys > 0 ? 1 : -1;
            // Entry and exit points of the corner going counter-clockwise.
            int idx = (first + k) % 4;
            double ex, ey, fx, fy;
            if (idx == 0) ex = hx, ey = hy - r, fx = hx - r, fy = hy;
            else if (idx == 1) ex = -hx + r, ey = hy, fx = -hx, fy = hy - r;
            else if (idx == 2) ex = -hx, ey = -hy + r, fx = -hx + r, fy = -hy;
            else ex = hx - r, ey = -hy, fx = hx, fy = -hy + r;
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

bool Interpreter::pocket(const Plan& p) {
    if (modal_.plane != 17) return fail(885, "G45 pockets are machined in the XY plane (G17)"), false;
    if (modal_.radcomp != 40) return fail(140, "G45 under radius compensation"), false;
    struct W {
        bool has = false;
        double v = 0;
    } ex, ey, eb, P, Q, I, J, er, eg;
    for (int i = 0; i < p.ncyc; ++i) {
        Addr a = p.cyc[i].a;
        double v = p.cyc[i].v;
        W* w = a == addrE('X') ? &ex : a == addrE('Y') ? &ey : a == addrE('B') ? &eb : a == addr1('P') ? &P
             : a == addr1('Q') ? &Q : a == addr1('I') ? &I : a == addr1('J') ? &J : a == addrE('R') ? &er
             : a == addrE('G') ? &eg : nullptr;
        if (w) *w = {true, v};
        if (a == addrE('P')) pocket_ep_ = v;
        if (a == addrE('Q')) pocket_eq_ = v;
        if (a == addrE('I')) pocket_ei_ = v;
        if (a == addrE('J')) pocket_ej_ = v;
        if ((a == addr1('P') || a == addr1('Q') || a == addr1('I') || a == addr1('J')) && v < 0)
            return fail(835, std::string(addr_name(a)) + " must be positive in G45"), false;
    }
    const Corrector& c = corr_[size_t(modal_.d)];
    const double R = c.r + c.dr;
    if (modal_.d == 0 || R <= 0) return fail(898, "G45 needs a tool corrector with a radius (D0 active)"), false;
    int shape;  // 1 circle, 2 oblong, 3 rectangle
    double hx, hy, rc, half_small;
    if (ey.has && !ex.has) return fail(889, "G45: EY without EX"), false;
    if (ex.has && ey.has) {
        shape = 3;
        if (eb.has && eb.v > 0 && eb.v < R)
            return fail(886, "G45: the corner radius EB is smaller than the tool radius"), false;
        half_small = std::min(ex.v, ey.v) / 2;
        hx = ex.v / 2 - R, hy = ey.v / 2 - R, rc = eb.has ? std::max(eb.v - R, 0.0) : 0;
    } else if (ex.has && eb.has) {
        shape = 2;
        if (ex.v < 2 * eb.v) return fail(897, "G45: the oblong is shorter than its width"), false;
        half_small = eb.v;
        hx = ex.v / 2 - eb.v, hy = 0, rc = eb.v - R;
    } else if (eb.has) {
        shape = 1;
        if (eb.v <= R) return fail(886, "G45: the pocket radius EB is not larger than the tool radius"), false;
        half_small = eb.v;
        hx = hy = 0, rc = eb.v - R;
    } else {
        return fail(889, "G45 needs EB, EX EY or EX EB"), false;
    }
    if (half_small <= R) return fail(896, "G45: the pocket is not wider than the tool"), false;
    if (Q.has && Q.v > 2 * R) return fail(887, "G45: the step-over Q is larger than the tool diameter"), false;
    const bool rough = P.has && Q.has, floor = Q.has && I.has, wall = P.has && J.has;
    if (!rough && !floor && !wall) return fail(889, "G45 needs P and Q, Q and I, or P and J"), false;
    if (rough && pocket_ep_ <= 0) return fail(892, "G45: no axial feed EP programmed"), false;
    if (rough && pocket_eq_ <= 0) return fail(893, "G45: no lateral feed EQ programmed"), false;
    double ei = pocket_ei_ > 0 ? pocket_ei_ : pocket_ep_, ej = pocket_ej_ > 0 ? pocket_ej_ : pocket_eq_;
    if (ei <= 0 || ej <= 0) return fail(892, "G45: no finishing feed (EI, EJ or EP, EQ)"), false;

    const int ax = Z;
    // The centre: X Y of the block, else the current point.
    double cx = p.axis[X] ? (p.inc[X] ? prog_[X] + p.val[X] : p.val[X]) : prog_[X];
    double cy = p.axis[Y] ? (p.inc[Y] ? prog_[Y] + p.val[Y] : p.val[Y]) : prog_[Y];
    if (!p.axis[Z]) return fail(882, "G45: the pocket bottom Z is not programmed"), false;
    double zb = p.inc[Z] ? prog_[Z] + p.val[Z] : p.val[Z];
    double top = er.has ? er.v : prog_[Z];
    if (er.has && std::fabs(er.v - zb) < 1e-9) return fail(891, "G45: ER is the pocket bottom"), false;
    const bool ccw = !(eg.has && std::lround(eg.v) == 2);
    const double d = half_small - R;  // lateral distance from the centre to the final contour

    Modal saved = modal_;
    modal_.feed_mode = 94;
    modal_.feed_set = true;
    auto go = [&](int g, double x, double y, double z, double feed) {
        Axes t = prog_;
        t[X] = cx + x, t[Y] = cy + y, t[size_t(ax)] = z;
        modal_.feed = feed;
        return cycle_move(g, t);
    };
    double z = prog_[size_t(ax)];
    auto run_contour = [&](double off, double feed) {
        double sx, sy;
        auto pcs = contour(shape, std::max(hx - off, 0.0), std::max(hy - off, 0.0), std::max(rc - off, 0.0), ccw, sx, sy);
        if (shape == 1) {
            pcs = contour(1, 0, 0, d - off, ccw, sx, sy);
        } else if (shape == 2) {
            pcs = contour(2, hx, 0, d - off, ccw, sx, sy);
        }
        if (!go(1, sx, sy, z, feed)) return false;
        modal_.feed = feed;
        for (const Piece& pc : pcs) {
            Axes t = prog_;
            t[X] = cx + pc.x, t[Y] = cy + pc.y;
            if (!pc.arc) {
                if (!cycle_move(1, t)) return false;
            } else if (!emit_arc(pc.sweep > 0 ? 3 : 2, t, X, Y, cx + pc.cx, cy + pc.cy, pc.sweep,
                                 std::hypot(prog_[X] - cx - pc.cx, prog_[Y] - cy - pc.cy),
                                 std::hypot(pc.x - pc.cx, pc.y - pc.cy), -1)) {
                return false;
            }
        }
        return true;
    };
    // Offsets (inward from the final contour) of the lateral passes out to `reach`.
    auto passes = [&](double reach) {
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
    };
    auto layers = [&](double from, double to) {
        std::vector<double> zs;
        double depth = from - to;
        if (depth <= 1e-9) return zs;
        int n = std::max(1, int(std::ceil(depth / P.v - 1e-9)));
        double q = ceil_um(depth / n);
        for (int k = 1; k < n; ++k) zs.push_back(from - k * q);
        zs.push_back(to);
        return zs;
    };

    // 1-2. To the centre, then to ER.
    if (!go(0, 0, 0, z, 0)) return false;
    if (er.has && !go(0, 0, 0, top, 0)) return false;
    z = top;
    const double rough_bottom = (floor ? zb + I.v : zb);
    const double rough_reach = d - (wall || J.has ? J.v : 0);
    if (rough) {
        for (double lz : layers(top, rough_bottom)) {
            if (!go(0, 0, 0, z, 0)) return false;  // back to the centre at the current level
            z = lz;
            if (!go(1, 0, 0, z, pocket_ep_)) return false;
            for (double off : passes(rough_reach))
                if (!run_contour(d - off, pocket_eq_)) return false;
            if (wall && I.has && !run_contour(0, ej)) return false;  // P Q I J: chained per layer
        }
    }
    if (wall && !(rough && I.has)) {
        // Wall finishing on the final contour, in axial steps P down to the bottom
        // (or I above it when the floor is not finished in this call).
        double wall_bottom = (I.has && !floor) ? zb + I.v : zb;
        if (!go(0, 0, 0, z, 0)) return false;
        for (double lz : layers(top, wall_bottom)) {
            z = lz;
            if (!go(1, 0, 0, z, ei)) return false;
            if (!run_contour(0, ej)) return false;
            if (!go(0, 0, 0, z, 0)) return false;
        }
    }
    if (floor) {
        if (!go(0, 0, 0, z, 0)) return false;
        z = zb;
        if (!go(1, 0, 0, z, ei)) return false;
        double reach = (J.has && !wall) ? d - J.v : d;
        for (double off : passes(reach))
            if (!run_contour(d - off, ej)) return false;
    }
    // 7. Lift 1 mm, back to the centre, up to ER.
    if (!go(0, prog_[X] - cx, prog_[Y] - cy, z + 1, 0)) return false;
    if (!go(0, 0, 0, z + 1, 0)) return false;
    if (!go(0, 0, 0, top, 0)) return false;
    modal_ = saved;
    return true;
}

}  // namespace pupitre
