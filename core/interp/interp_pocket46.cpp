// G46 pockets and facing with any contour (000:6078-6369; pupitre-iso(5), POCKETS):
// the geometric definition (NU0 header, NU1-NU6 contours, NU9) is read block by
// block without moving; the orders NU10 (drilling at the plunge points), NU15
// (roughing) and NU20 (finishing) turn it into elementary moves. The plane
// geometry (core/cycles/pocket46.cpp) is 2-D; this file maps it onto the plane of the
// definition, G17, G18 or G19 (see P46Axes below).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

namespace {
using ::pupitre::geometry::ceil_um;
std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

// Depth layers from `top` down to `bottom` by at most P, equal (as G45).
std::vector<double> layers(double top, double bottom, double P) {
    std::vector<double> zs;
    double depth = top - bottom;
    int n = std::max(1, int(std::ceil(depth / P - 1e-9)));
    double q = ceil_um(depth / n);
    for (int k = 1; k < n; ++k) zs.push_back(top - k * q);
    zs.push_back(bottom);
    return zs;
}

// A word's value as an int, clamped first: NP, NU, NR or R written through an
// L variable may be any double, and converting one beyond an int is undefined
// (issue 40). The checks that follow refuse what is not the value written.
int to_int(double v) {
    return int(std::clamp(v, -1e9, 1e9));
}

struct Words {
    bool has[128] = {};
    double v[128] = {};
    bool ok(Addr a) const { return has[a]; }
};

// The words of a G46 block, by address (C: the Plan's CycleWords, private to the interpreter).
template <class C>
Words words_of(const C& c) {
    Words w;
    for (int i = 0; i < c.n; ++i) w.has[c.word[i].a] = true, w.v[c.word[i].a] = c.word[i].v;
    return w;
}

std::string axis_name(int a) {
    return std::string(1, kAxisNames[size_t(a)]);
}
// The centre word of a plane axis (I for X, J for Y, K for Z).
std::string centre_name(int a) {
    return std::string(1, char('I' + a));
}
}  // namespace

// G46 in the three planes. The handbook describes G46 with G17 words only
// (000:6099-6109, 6281-6359), but errors 264 "cote en dehors du plan", 271 "tool
// direction not perpendicular to the contouring plane" and 273 "contouring plane
// changed between pocket definition and machining" (000:13340, 13347, 13349)
// show that it runs in any plane, and the drilling cycles NU10 uses are defined
// in G17 "pour les autres plans : permuter" (004:918-920, 950). pupitre permutes
// the axes as for circles and cycles (000:4650):
//   plane   first second normal   contour centres   bottom ER EH   G16
//   G17       X     Y      Z           I J              Z          R+
//   G18       Z     X      Y           K I              Y          Q+
//   G19       Y     Z      X           J K              X          P+
// so a pocket drawn in G18 is the same contour as in G17 turned onto the ZX
// plane (circles seen from +Y, 000:4312-4316; pupitre-iso(5), MOTION). LX LY
// (start and plunge point, finishing start) and EX EY (end of roughing) are
// fixed words: they are the first and second coordinates of the plane in its
// own order (in G18, LX is the Z and LY the X). The bottom of the orders NU10,
// NU15 and NU20 (the "Z.." of 000:6281-6359) is the word of the normal axis, as
// the hole bottom of G81-G89: Y in G18, X in G19; a plane coordinate there (Z
// in G18) is error 267 as X or Y is in G17. ER and EH are coordinates on the
// normal axis, "up" towards the spindle: the tool must point along the positive
// normal (G16 R+, Q+, P+), otherwise 271.
Interpreter::P46Axes Interpreter::p46_axes(int plane) {
    if (plane == 18) return {Z, X, Y};
    if (plane == 19) return {Y, Z, X};
    return {X, Y, Z};
}

// G46 NU.. blocks, and every block while a definition is open.
bool Interpreter::pocket46(const Plan& p) {
    if (!p.g[46]) return p46_contour(p);
    // A G46 block runs no modal function: a plane given there would be ignored.
    if (p.mode.plane >= 0 && p.mode.plane != modal_.plane)
        return fail(279, strf(tr("G%d in a G46 block: select the plane in a block before G46 NU0"),
                              p.mode.plane));
    const Words w = words_of(p.cycle_words);
    if (!w.has[addrN('U')])
        return fail(268, tr("G46 needs NU (NU0 header, NU1-NU6 contours, NU9, NU10/15/20 orders)"));
    const double nuv = w.v[addrN('U')];
    const int nu = to_int(nuv);
    const bool known = nuv == nu && (nu <= 6 || nu == 9 || nu == 10 || nu == 15 || nu == 20);
    if (!known)
        return fail(262, strf(tr("G46 NU%s: NU is 0-6, 9, 10, 15 or 20"), num(nuv).c_str()));
    if (p.tech.nm || p.tech.has_s || p.tech.has_t || p.tech.has_d)
        return fail(268, tr("M, S, T or D in a G46 block"));
    if (nu == 0) {
        // The same NU0 again: the run restarted inside its definition (a
        // block that did not parse stopped it).
        const bool again = p46_.at.prog == loc_.prog && p46_.at.line == loc_.line;
        if (p46_.defining && !again)
            return fail(274, tr("G46 NU0 inside a definition (NU9 missing)"));
        return p46_header(p, nu);
    }
    if (nu >= 10) {
        if (p46_.defining)
            return fail(270, tr("a machining order before the end of the definition (G46 NU9)"));
        return p46_order(p, nu);
    }
    return p46_section(p, nu);
}

// G46 NU1-NU6 opens a contour section (NU1, NU2 may give the drilling point LX
// LY); NU9 closes the definition and checks it.
bool Interpreter::p46_section(const Plan& p, int nu) {
    const Words w = words_of(p.cycle_words);
    if (!p46_.defining) return fail(270, strf(tr("G46 NU%d without a G46 NU0 header"), nu));
    // Contour sections accept LX LY (NU1, NU2) and nothing else.
    for (int i = 0; i < p.cycle_words.n; ++i) {
        Addr a = p.cycle_words.word[i].a;
        bool lxy = a == addrL('X') || a == addrL('Y');
        if (a != addrN('U') && !(lxy && (nu == 1 || nu == 2)))
            return fail(267, strf(tr("%s is not a word of G46 NU%d"),
                                  std::string(addr_name(a)).c_str(), nu));
    }
    if (p.to.axis.any() || p.to.ijk.any() || p.tech.has_f)
        return fail(267, strf(tr("G46 NU%d takes no coordinates"), nu));
    if (w.has[addrL('X')] != w.has[addrL('Y')]) return fail(277, tr("LX and LY go together"));
    if (!p46_close_section()) return false;
    if (nu == 9) {
        p46_.defining = false;
        if (Error e = p46::check(p46_.def)) return p46_fail(e, p46_.def);
        p46_.defs[p46_.def.np] = p46_.def;
        return true;
    }
    p46::Section s;
    s.nu = nu;
    s.line = loc_.line;
    s.n = loc_.n;
    if (w.has[addrL('X')]) s.has_l = true, s.l = p46::V2(w.v[addrL('X')], w.v[addrL('Y')]);
    p46_.def.sections.push_back(s);
    if (p46_.def.sections.size() > 255) return fail(285, tr("too many contours in one definition"));
    p46_.first = true;
    p46_.blocks = 0;
    return true;
}

// N.. G46 NU0 NP.. ED.. Q.. [J..] [NR±] [R03/R04] [LX.. LY..] [EX.. EY..]
bool Interpreter::p46_header(const Plan& p, int) {
    Words w;
    for (int i = 0; i < p.cycle_words.n; ++i) {
        Addr a = p.cycle_words.word[i].a;
        static const Addr ok[] = {addrN('U'), addrN('P'), addrN('R'), addrE('D'),
                                  addr1('Q'), addr1('J'), addr1('R'), addrL('X'),
                                  addrL('Y'), addrE('X'), addrE('Y')};
        if (std::find(std::begin(ok), std::end(ok), a) == std::end(ok))
            return fail(267,
                        strf(tr("%s is not a word of G46 NU0"), std::string(addr_name(a)).c_str()));
        w.has[a] = true, w.v[a] = p.cycle_words.word[i].v;
    }
    if (p.to.axis.any() || p.to.ijk.any() || p.tech.has_f)
        return fail(267, tr("G46 NU0 takes no coordinates"));
    if (!w.has[addrN('P')] || !w.has[addrE('D')] || !w.has[addr1('Q')])
        return fail(268, tr("G46 NU0 needs NP, ED and Q"));
    if (w.has[addrL('X')] != w.has[addrL('Y')]) return fail(277, tr("LX and LY go together"));
    if (w.has[addrE('X')] != w.has[addrE('Y')]) return fail(277, tr("EX and EY go together"));
    const Frames& f = frames_;
    bool g59 = std::fabs(f.ed) > 1e-12;
    for (int a = 0; a < kAxes; ++a) g59 = g59 || std::fabs(f.g59[size_t(a)]) > 1e-12;
    if (g59) return fail(275, tr("G46 NU0 with a G59 offset active"));
    p46::Def d;
    d.np = to_int(w.v[addrN('P')]);
    d.ed = w.v[addrE('D')];
    d.q = w.v[addr1('Q')];
    d.j = w.has[addr1('J')] ? w.v[addr1('J')] : 0;
    d.nr = w.has[addrN('R')] ? to_int(w.v[addrN('R')]) : 1;
    d.rot = w.has[addr1('R')] ? to_int(w.v[addr1('R')]) : 3;
    if (d.np <= 0 || d.np != w.v[addrN('P')] || d.ed <= 0 || d.q <= 0 || d.j < 0 ||
        (d.rot != 3 && d.rot != 4) || w.v[addr1('R')] != std::floor(w.v[addr1('R')]))
        return fail(282, tr("G46 NU0: NP a positive integer, ED and Q positive, J not negative, "
                            "R03 or R04"));
    if (w.has[addrL('X')]) d.has_l = true, d.l = p46::V2(w.v[addrL('X')], w.v[addrL('Y')]);
    if (w.has[addrE('X')]) d.has_e = true, d.e = p46::V2(w.v[addrE('X')], w.v[addrE('Y')]);
    d.plane = modal_.plane;
    p46_.def = d;
    p46_.at = loc_;
    p46_.defining = true;
    p46_.first = true;
    p46_.blocks = -1;  // no section yet
    p46_.motion = modal_.motion;
    return true;
}

// A contour block: G0/G1 positioning first, then lines and arcs (PGP allowed),
// in the plane of the definition.
bool Interpreter::p46_contour(const Plan& p) {
    const P46Axes ax = p46_axes(p46_.def.plane);
    const bool plane_words = p.to.axis.any() || p.to.ijk.any() || p.to.has_r || p.pgp.any;
    const bool tech_words = p.tech.nm || p.tech.has_f || p.tech.has_s || p.tech.has_t ||
                            p.tech.has_d || p.cycle_words.n;
    if (!plane_words && !p.g.any() && !tech_words) return true;  // a comment line
    if (!p46_contour_words(p, ax, tech_words)) return false;
    const size_t a0 = size_t(ax.a0), a1 = size_t(ax.a1);
    const int motion = p.mode.motion >= 0 ? p.mode.motion : p46_.motion;
    p46_.motion = motion;
    p46::V2 t = p46_.pos;
    if (p.to.axis[a0]) t.x() = p.to.inc[a0] ? p46_.pos.x() + p.to.val[a0] : p.to.val[a0];
    if (p.to.axis[a1]) t.y() = p.to.inc[a1] ? p46_.pos.y() + p.to.val[a1] : p.to.val[a1];
    if (p46_.first) return p46_contour_start(p, ax, motion, t);
    if (motion == 0)
        return fail(p46_.blocks == 1 ? 292 : 284,
                    p46_.blocks == 1 ? tr("two positionings at the start of a contour")
                                     : tr("G0 inside a contour"));
    return p46_contour_elem(p, ax, motion, t);
}

// The words a contour block may carry: G0-G3, the plane's coordinates and
// centres, R, EA, EB and the PGP links.
bool Interpreter::p46_contour_words(const Plan& p, const P46Axes& ax, bool tech_words) {
    const size_t a0 = size_t(ax.a0), a1 = size_t(ax.a1), an = size_t(ax.an);
    if (p46_.blocks < 0) return fail(269, tr("a contour block before G46 NU1-NU6"));
    for (size_t g = 0; g < p.g.size(); ++g)
        if (p.g[g] && g > 3) return fail(279, strf(tr("G%zu in a pocket contour block"), g));
    if (tech_words)
        return fail(268, strf(tr("only G0-G3, %s %s, %s %s, R and EB in a pocket contour block"),
                              axis_name(ax.a0).c_str(), axis_name(ax.a1).c_str(),
                              centre_name(ax.a0).c_str(), centre_name(ax.a1).c_str()));
    for (int a = 0; a < kAxes; ++a)
        if (p.to.axis[size_t(a)] && size_t(a) != a0 && size_t(a) != a1)
            return fail(264, strf(tr("%s is outside the contouring plane"), axis_name(a).c_str()));
    // The centre word of the normal axis (K in G17) is a coordinate outside the plane.
    if (p.to.ijk[an])
        return fail(264,
                    strf(tr("%s is outside the contouring plane"), centre_name(ax.an).c_str()));
    if (!p.to.axis[a0] && !p.to.axis[a1] && !p.pgp.has_ea)
        return fail(264, tr("no coordinate in the contouring plane"));
    return true;
}

// The first contour block: a G0 or G1 to the start point, both coordinates given.
bool Interpreter::p46_contour_start(const Plan& p, const P46Axes& ax, int motion, p46::V2 t) {
    if (motion != 0 && motion != 1)
        return fail(265, tr("a contour starts with a G0 or G1 positioning"));
    if (!p.to.axis[size_t(ax.a0)] || !p.to.axis[size_t(ax.a1)] || p.pgp.has_eb || p.pgp.any)
        return fail(280, tr("the first contour block gives both coordinates of the start point"));
    p46_.pos = t;
    p46_.solver = pgp::Solver();
    p46_.solver.start(t);
    p46_.first = false;
    p46_.blocks = 1;
    return true;
}

// One element of the contour, solved by the PGP solver (pupitre-iso(5), PROFILE
// GEOMETRY PROGRAMMING (PGP)), which may hold it until the next element fixes
// its end.
bool Interpreter::p46_contour_elem(const Plan& p, const P46Axes& ax, int motion, p46::V2 t) {
    const size_t a0 = size_t(ax.a0), a1 = size_t(ax.a1);
    ++p46_.blocks;
    pgp::Spec s;
    s.g = motion;
    s.has_x = p.to.axis[a0], s.x = t.x();
    s.has_y = p.to.axis[a1], s.y = t.y();
    s.has_ea = p.pgp.has_ea, s.ea = p.pgp.ea;
    s.has_i = p.to.ijk[a0], s.i = p.to.ijk_val[a0] + (p.to.ijk_inc[a0] ? p46_.pos.x() : 0);
    s.has_j = p.to.ijk[a1], s.j = p.to.ijk_val[a1] + (p.to.ijk_inc[a1] ? p46_.pos.y() : 0);
    s.has_r = p.to.has_r, s.r = p.to.r;
    s.link = p.pgp.link, s.disc = p.pgp.disc;
    s.has_eb = p.pgp.has_eb, s.eb = p.pgp.eb, s.eb_unsigned = p.pgp.eb_unsigned;
    s.tag = loc_.line;
    if (p.pgp.link == 'X') return fail(110, tr("ES and ET together in one block"));
    if (p.pgp.has_eb && p.pgp.eb_unsigned)
        warn(err::wUnsignedEB, tr("EB without a sign is taken as a fillet (EB+): write EB+ or EB- "
                                  "(pupitre-iso(5), PGP)"));
    if ((motion == 2 || motion == 3) && !s.has_i && !s.has_j && !s.has_r && !p.pgp.any)
        return fail(269, strf(tr("a circle without its centre (%s %s) or radius (R)"),
                              centre_name(ax.a0).c_str(), centre_name(ax.a1).c_str()));
    std::vector<pgp::Elem> out;
    if (Error e = p46_.solver.push(s, out)) return fail(e);
    for (const pgp::Elem& el : out) p46_.def.sections.back().elems.push_back(el.geo);
    p46_.pos = p46_.solver.pending() ? t : p46_.solver.position();
    return true;
}

bool Interpreter::p46_close_section() {
    if (p46_.blocks < 0 || p46_.def.sections.empty()) return true;
    std::vector<pgp::Elem> out;
    if (Error e = p46_.first ? Error{} : p46_.solver.finish(out)) return fail(e);
    for (const pgp::Elem& el : out) p46_.def.sections.back().elems.push_back(el.geo);
    if (p46_.def.sections.back().elems.empty())
        return fail(284, tr("a contour section with no element"));
    return true;
}

bool Interpreter::p46_fail(const Error& e, const p46::Def& d) {
    if (e.item >= 0 && size_t(e.item) < d.sections.size()) {
        const p46::Section& s = d.sections[size_t(e.item)];
        // TRANSLATORS: %s is the reason of a pocket error; the contour it is about follows.
        return fail(e.code, s.n >= 0
                                ? strf(tr("%s (contour N%ld)"), e.detail.c_str(), s.n)
                                : strf(tr("%s (contour at line %d)"), e.detail.c_str(), s.line));
    }
    return fail(e.code, e.detail);
}

// Runs at one depth: a plunge at each run not linked to the previous one.
// (x, y) are the plane's first and second coordinates, z the normal axis.
// Warning 1118: the passes of a roughing plunge with the cutter where no hole
// was drilled (NU10 drills one, at LX LY or the first plunge). The clean-up
// contours start in the cleared pocket and are not counted.
void Interpreter::warn_plunges(const p46::Def& d, const std::vector<p46::Run>& runs) {
    if (runs.empty()) return;
    const p46::V2 hole = d.has_l ? d.l : runs.front().start;
    std::vector<p46::V2> away;
    for (const p46::Run& r : runs)
        if (!r.linked && !r.cleanup && (r.start - hole).norm() > 1e-6) away.push_back(r.start);
    if (away.empty()) return;
    if (away.size() == 1)
        warn(err::wPlungeAway,
             strf(tr("the roughing plunges with the cutter at %s %s, away from the hole at %s %s "
                     "(NU10 drills only there; LX LY of NU0 chooses it)"),
                  num(away[0].x()).c_str(), num(away[0].y()).c_str(), num(hole.x()).c_str(),
                  num(hole.y()).c_str()));
    else
        // TRANSLATORS: %zu counts the other places where the cutter plunges (English keeps "more
        // places").
        warn(err::wPlungeAway,
             strf(trn("the roughing plunges with the cutter at %s %s and %zu more places, away "
                      "from the hole at %s %s (NU10 drills only there; LX LY of NU0 chooses it)",
                      "the roughing plunges with the cutter at %s %s and %zu more places, away "
                      "from the hole at %s %s (NU10 drills only there; LX LY of NU0 chooses it)",
                      away.size() - 1),
                  num(away[0].x()).c_str(), num(away[0].y()).c_str(), away.size() - 1,
                  num(hole.x()).c_str(), num(hole.y()).c_str()));
}

bool Interpreter::p46_emit(const P46Axes& ax, const std::vector<p46::Run>& runs, double z,
                           double approach, double clear, double f_ax, double f_lat) {
    const size_t a0 = size_t(ax.a0), a1 = size_t(ax.a1), an = size_t(ax.an);
    auto go = [&](int g, double x, double y, double zz, double feed) {
        Axes t = prog_;
        t[a0] = x, t[a1] = y, t[an] = zz;
        if (g) modal_.feed = feed;
        return cycle_move(g, t);
    };
    for (const p46::Run& r : runs) {
        if (!r.linked) {
            if (prog_[an] < clear - 1e-9 && !go(0, prog_[a0], prog_[a1], clear, 0)) return false;
            if (!go(0, r.start.x(), r.start.y(), prog_[an], 0)) return false;
            if (approach < prog_[an] - 1e-9 && !go(0, r.start.x(), r.start.y(), approach, 0))
                return false;
            if (!go(1, r.start.x(), r.start.y(), z, f_ax)) return false;
        } else if (!go(1, r.start.x(), r.start.y(), z, f_lat)) {
            return false;
        }
        for (const p46::Piece& pc : r.pieces) {
            if (!pc.arc) {
                if (!go(1, pc.to.x(), pc.to.y(), z, f_lat)) return false;
                continue;
            }
            modal_.feed = f_lat;
            Axes t = prog_;
            t[a0] = pc.to.x(), t[a1] = pc.to.y();
            double r0 = std::hypot(prog_[a0] - pc.c.x(), prog_[a1] - pc.c.y()),
                   r1 = (pc.to - pc.c).norm();
            if (std::fabs(pc.sweep) < 1e-12) continue;
            // Counter-clockwise from the first axis towards the second is G3 in
            // every plane (000:4312-4316; pupitre-iso(5), MOTION).
            if (!emit_arc(pc.sweep > 0 ? 3 : 2, t, ax.a0, ax.a1, pc.c.x(), pc.c.y(), pc.sweep, r0,
                          r1, -1))
                return false;
        }
    }
    return go(0, prog_[a0], prog_[a1], clear, 0);
}

// What a NU15 or NU20 order cuts, from its words: the bottom, the cutter's
// radius, the axial step P, J of NU20, the clearance (ER) and attack (EH)
// heights, and the axial and lateral feeds (EP EQ, EI EJ).
struct Interpreter::P46Cut {
    double zb = 0, R = 0, P = 0, jf = 0, clear = 0, top = 0, f_ax = 0, f_lat = 0;
};

// The checks every G46 order makes against the machine state and the block,
// before it plans anything: the pocket was defined for this plane and tool.
bool Interpreter::p46_order_allowed(const Plan& p, const p46::Def& d) {
    if (modal_.plane != d.plane)
        return fail(273, tr("the plane changed since the pocket was defined"));
    const P46Axes ax = p46_axes(d.plane);
    const size_t an = size_t(ax.an);
    const std::string bottom = axis_name(ax.an);
    if (modal_.tool_axis != ax.an || modal_.tool_axis_neg)
        return fail(271, strf(tr("the tool axis (G16) is not perpendicular to the contouring plane "
                                 "(G16 %c+ in G%d)"),
                              "PQR"[ax.an], d.plane));
    if (modal_.radcomp != 40) return fail(140, tr("G46 under radius compensation"));
    if (modal_.spindle_dir != d.rot)
        return fail(278, modal_.spindle_dir == 3 || modal_.spindle_dir == 4
                             ? strf(tr("the spindle turns M0%d, the pocket asks for R0%d"),
                                    modal_.spindle_dir, d.rot)
                             : strf(tr("the spindle turns not, the pocket asks for R0%d"), d.rot));
    // A plane coordinate first: in G18 the G17 habit of a Z bottom is refused
    // as a plane coordinate, not taken as a missing bottom.
    for (int a = 0; a < kAxes; ++a)
        if (p.to.axis[size_t(a)] && size_t(a) != an)
            return fail(267, strf(tr("a G46 order takes no plane coordinate (%s): its bottom is %s "
                                     "in G%d"),
                                  axis_name(a).c_str(), bottom.c_str(), d.plane));
    if (!p.to.axis[an])
        return fail(268, strf(tr("a G46 order needs the bottom %s"), bottom.c_str()));
    return true;
}

// NU10: the drilling cycle of the block, run once at the hole of the pocket,
// with the modal state of the program left as it was.
bool Interpreter::p46_drill(const Plan& p, const p46::Def& d) {
    const P46Axes ax = p46_axes(d.plane);
    const size_t a0 = size_t(ax.a0), a1 = size_t(ax.a1), an = size_t(ax.an);
    int code = p.g[81] ? 81 : p.g[83] ? 83 : p.g[87] ? 87 : 0;
    if (!code) return fail(268, tr("G46 NU10 needs G81, G83 or G87"));
    std::vector<p46::Run> runs;
    std::vector<double> ys;
    if (Error e = p46::roughing(d, d.ed / 2, runs, ys)) return p46_fail(e, d);
    Modal saved = modal_;
    CycleParams saved_cyc = cyc_;
    cyc_ = CycleParams{};
    modal_.motion = 0;
    modal_.cycle = code;
    modal_.feed_mode = 94;
    if (p.tech.has_f) modal_.feed = p.tech.f, feed_programmed_ = true;
    Plan q = p;
    q.to.axis.reset();
    q.to.axis.set(an);
    q.to.inc.reset();
    bool ok = cycle_words(q, code);  // the cycle axis is the normal axis (cycle_axis())
    q.to.axis.set(a0).set(a1);
    // Seed 000: LX LY of NU0 is "the start and/or drilling point for
    // roughing": one hole there, else where the roughing first plunges
    // (issue 19 item 4); the roughing warns where it plunges elsewhere.
    const p46::V2 hole = d.has_l ? d.l : runs.front().start;
    q.to.val[a0] = hole.x(), q.to.val[a1] = hole.y();
    if (ok) ok = cycle_run(q, code);
    cyc_ = saved_cyc;
    modal_ = saved;
    return ok;
}

// NU15 and NU20 take only their own words, and the roughing needs the cutter
// the pocket was defined for (ED).
bool Interpreter::p46_cutter(const Plan& p, int nu, const p46::Def& d, double& R) {
    const Corrector& c = corr_[size_t(modal_.d)];
    R = c.r + c.dr;
    if (modal_.d == 0 || R <= 0)
        return fail(272, tr("the pocket needs a cutter with a radius (D0 or R0 active)"));
    if (nu == 15 && std::fabs(2 * R - d.ed) > 1e-3)
        return fail(272,
                    strf(tr("the cutter (diameter %s) is not the roughing cutter ED of the pocket"),
                         num(2 * R).c_str()));
    static const Addr ok15[] = {addrN('U'), addrN('P'), addr1('P'), addrE('R'),
                                addrE('H'), addrE('P'), addrE('Q')};
    static const Addr ok20[] = {addrN('U'), addrN('P'), addr1('P'), addrE('R'),
                                addrE('H'), addrE('I'), addrE('J'), addr1('J')};
    for (int i = 0; i < p.cycle_words.n; ++i) {
        Addr a = p.cycle_words.word[i].a;
        bool ok = nu == 15 ? std::find(std::begin(ok15), std::end(ok15), a) != std::end(ok15)
                           : std::find(std::begin(ok20), std::end(ok20), a) != std::end(ok20);
        if (!ok)
            return fail(267, strf(tr("%s is not a word of G46 NU%d"),
                                  std::string(addr_name(a)).c_str(), nu));
    }
    if (p.tech.has_f || p.g.count() > 1)
        return fail(267, strf(tr("G46 NU%d takes no F and no other G"), nu));
    return true;
}

// The passes of NU15 (roughing) or NU20 (finishing), layer by layer down to the
// bottom, then the roughing's end point.
bool Interpreter::p46_cut(const p46::Def& d, int nu, const P46Cut& c) {
    const P46Axes ax = p46_axes(d.plane);
    std::vector<p46::Run> runs;
    if (nu == 15) {
        std::vector<double> ys;
        if (Error e = p46::roughing(d, c.R, runs, ys)) return p46_fail(e, d);
        warn_plunges(d, runs);
    } else {
        bool any = false;
        for (const auto& s : d.sections) any = any || s.nu == 1 || s.nu == 2 || s.nu == 6;
        if (!any) return true;  // NU20 is ignored for facing outlines and recesses (000:6369)
        if (Error e = p46::finishing(d, c.R, c.jf, runs)) return p46_fail(e, d);
    }
    Modal saved = modal_;
    modal_.feed_mode = 94;
    modal_.feed_set = true;
    modal_.motion = 1;
    OwnFeed own(*this);  // the order's EP and EQ
    bool ok = true;
    if (prog_[size_t(ax.an)] < c.clear - 1e-9) ok = cycle_axis_move(0, c.clear);
    double approach = c.top;
    for (double z : layers(c.top, c.zb, c.P)) {
        if (!ok) break;
        ok = p46_emit(ax, runs, z, approach, c.clear, c.f_ax, c.f_lat);
        approach = z;
    }
    // The roughing end point EX EY of the header (000:6109), at the clearance.
    if (ok && nu == 15 && d.has_e) {
        Axes t = prog_;
        t[size_t(ax.a0)] = d.e.x(), t[size_t(ax.a1)] = d.e.y();
        ok = cycle_move(0, t);
    }
    modal_ = saved;
    return ok;
}

// G46 NU10 NP.. G81/G83/G87 Z.. ... | NU15 NP.. Z.. P.. [ER] [EH] EP EQ |
// NU20 NP.. Z.. P.. [ER] [EH] EI EJ [J]   (Z: the normal axis, Y in G18, X in G19)
bool Interpreter::p46_order(const Plan& p, int nu) {
    Words w;
    for (int i = 0; i < p.cycle_words.n; ++i)
        w.has[p.cycle_words.word[i].a] = true,
        w.v[p.cycle_words.word[i].a] = p.cycle_words.word[i].v;
    if (!w.has[addrN('P')]) return fail(268, tr("a G46 order needs NP"));
    const double np = w.v[addrN('P')];
    auto it = np == to_int(np) ? p46_.defs.find(to_int(np)) : p46_.defs.end();
    if (it == p46_.defs.end())
        return fail(270, strf(tr("pocket NP%s is not defined"), num(np).c_str()));
    const p46::Def& d = it->second;
    if (!p46_order_allowed(p, d)) return false;
    const size_t an = size_t(p46_axes(d.plane).an);
    const std::string bottom = axis_name(int(an));
    P46Cut c;
    c.zb = p.to.inc[an] ? prog_[an] + p.to.val[an] : p.to.val[an];
    apply_corrector_gauges(std::bitset<kAxes>().set(an));
    first_move_ = false;
    if (nu == 10) return p46_drill(p, d);
    if (!p46_cutter(p, nu, d, c.R)) return false;
    if (!w.has[addr1('P')]) return fail(268, strf(tr("G46 NU%d needs the axial step P"), nu));
    const Addr fa = nu == 15 ? addrE('P') : addrE('I'), fl = nu == 15 ? addrE('Q') : addrE('J');
    if (!w.has[fa] || !w.has[fl])
        return fail(
            268,
            strf(nu == 15 ? tr("G46 NU%d needs EP and EQ") : tr("G46 NU%d needs EI and EJ"), nu));
    c.P = w.v[addr1('P')], c.jf = w.has[addr1('J')] ? w.v[addr1('J')] : 0;
    c.f_ax = w.v[fa], c.f_lat = w.v[fl];
    if (c.P <= 0 || c.f_ax <= 0 || c.f_lat <= 0 || c.jf < 0)
        return fail(282, tr("P, the feeds and J of a G46 order are positive"));
    c.clear = w.has[addrE('R')] ? w.v[addrE('R')] : prog_[an];
    c.top = w.has[addrE('H')] ? w.v[addrE('H')] : c.clear;
    if (c.top - c.zb < 1e-9)
        return fail(276,
                    strf(tr("the pocket bottom %s is not below the attack plane"), bottom.c_str()));
    if (c.clear < c.top - 1e-9)
        return fail(282, tr("the clearance plane ER is below the attack plane EH"));
    // A step P so small that the depth takes more layers than any pocket
    // needs is a bad P, as P0 is (issue 40): layers() would count past an int.
    constexpr double kMaxLayers = 1000;
    if (!((c.top - c.zb) / c.P <= kMaxLayers))
        return fail(282, strf(tr("P of a G46 order makes more than %d layers"), int(kMaxLayers)));
    return p46_cut(d, nu, c);
}

}  // namespace pupitre
