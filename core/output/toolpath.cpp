// The toolpath of a run (see toolpath.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/toolpath.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/geometry.hpp"
#include "core/i18n.hpp"
#include "core/parse/block.hpp"

namespace pupitre {

namespace {

using ::pupitre::geometry::kPi;

}  // namespace

std::string_view plane_name(PathPlane p) {
    static constexpr std::string_view kNames[] = {"XY", "XZ", "YZ", "ZX"};
    return kNames[int(p)];
}

bool parse_plane(std::string_view w, PathPlane& out) {
    std::string s(w);
    for (char& c : s) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    static constexpr std::string_view kWords[] = {"xy", "xz", "yz", "zx"};
    for (int i = 0; i < 4; ++i)
        if (s == kWords[i]) {
            out = PathPlane(i);
            return true;
        }
    return false;
}

void Toolpath::clear() {
    ++gen_;
    moves_.clear();
    arcs_.clear();
    locs_.clear();
    errors_.clear();
    stock_.clear();
    part_.clear();
    profile_.clear();
    has_start_ = false;
    all_ = cut_ = PathBox{};
    em_mask_lo_ = em_mask_hi_ = 0;
    counts_[0] = counts_[1] = counts_[2] = 0;
    pieces_.clear();
    beyond_ = false;
    travel_ = 0;
    plane_arcs_[0] = plane_arcs_[1] = plane_arcs_[2] = 0;
    ltype_rapid_ = ltype_feed_ = -1;
    seconds_ = length_ = 0;
    x_diam_ = m_.lathe && m_.x_diameter;
    end_ = Loc{};
}

void Toolpath::start_at(const Axes& prog) {
    for (int a = 0; a < 3; ++a) start_[a] = prog[size_t(a)];
    has_start_ = true;
    if (moves_.empty()) all_.add(start_);
}

void Toolpath::set_line_types(int rapid, int feed) {
    ltype_rapid_ = int8_t(rapid >= 0 && rapid <= 127 ? rapid : -1);
    ltype_feed_ = int8_t(feed >= 0 && feed <= 127 ? feed : -1);
}

bool Toolpath::beyond_travel(const Axes& mach) const {
    for (int a = 0; a < kAxes; ++a) {
        const AxisConfig& c = m_.axes[size_t(a)];
        if (!c.present) continue;
        double v = mach[size_t(a)];
        if (v < c.min - 1e-6 || v > c.max + 1e-6) return true;
    }
    return false;
}

void Toolpath::add(const MoveEvent& e) {
    if (moves_.empty() && !has_start_) {
        // No start given: the program frame moved as the machine did (true
        // unless a rotation or a mirror is active at the very first move).
        for (int a = 0; a < 3; ++a)
            start_[a] = e.to_prog[size_t(a)] - (e.to_mach[size_t(a)] - e.from_mach[size_t(a)]);
        has_start_ = true;
        all_.add(start_);
    }
    if (moves_.size() >= size_t(PathMove::kNoArc) - 1) return;  // 4 billion moves: keep the first
    PathMove mv;
    for (int a = 0; a < 3; ++a) mv.p[a] = e.to_prog[size_t(a)];
    mv.g = uint8_t(e.g);
    mv.kind = e.g == 0 ? PathKind::rapid : e.comp ? PathKind::comp : PathKind::feed;
    mv.ltype = e.g == 0 ? ltype_rapid_ : ltype_feed_;
    if (e.g52) mv.flags |= pathflag::g52;
    if (e.piece) mv.flags |= pathflag::piece;
    if (!e.piece) beyond_ = false;
    if (beyond_travel(e.to_mach)) {
        mv.flags |= pathflag::travel;
        if (!beyond_) ++travel_;  // a move drawn in pieces counts once
        beyond_ = true;
    }
    bool arc =
        (e.g == 2 || e.g == 3) && e.plane_a0 < 3 && e.plane_a1 < 3 && e.plane_a0 != e.plane_a1;
    if (arc) {
        PathArc a;
        a.c0 = e.c0;
        a.c1 = e.c1;
        a.sweep = float(e.sweep);
        a.a0 = uint8_t(e.plane_a0);
        a.a1 = uint8_t(e.plane_a1);
        mv.arc = uint32_t(arcs_.size());
        arcs_.push_back(a);
        int third = 3 - e.plane_a0 - e.plane_a1;  // Z for G17, Y for G18, X for G19
        plane_arcs_[third == Z ? 0 : third == Y ? 1 : 2]++;
    }
    uint32_t index = uint32_t(moves_.size());
    if (locs_.empty() || locs_.back().prog != e.loc.prog || locs_.back().line != e.loc.line ||
        locs_.back().n != int32_t(e.loc.n))
        locs_.push_back(LocRun{index, e.loc.prog, e.loc.line, int32_t(e.loc.n)});
    moves_.push_back(mv);
    PathBox one;
    one.add(mv.p);
    if (arc) add_arc_bounds(mv, arcs_.back(), one);
    all_.add(one);
    if (mv.kind != PathKind::rapid) {
        cut_.add(one);
        cut_.add(from(index));
    }
    if (e.piece)
        pieces_.push_back(index);
    else
        counts_[size_t(mv.kind)]++;
    seconds_ += e.seconds;
    length_ += e.length;
    x_diam_ = e.x_diameter;
}

size_t Toolpath::moves_made(size_t upto) const {
    upto = std::min(upto, moves_.size());
    return upto - size_t(std::lower_bound(pieces_.begin(), pieces_.end(), uint32_t(upto)) -
                         pieces_.begin());
}

// The arc's extreme points: where it crosses the directions 0°, 90°, 180°, 270°.
void Toolpath::add_arc_bounds(const PathMove& mv, const PathArc& a, PathBox& b) const {
    size_t i = moves_.size() - 1;
    const double* s = from(i);
    double r0 = std::hypot(s[a.a0] - a.c0, s[a.a1] - a.c1);
    double r1 = std::hypot(mv.p[a.a0] - a.c0, mv.p[a.a1] - a.c1);
    double ang0 = std::atan2(s[a.a1] - a.c1, s[a.a0] - a.c0);
    double sw = double(a.sweep) * kPi / 180;
    if (std::fabs(sw) < 1e-12) return;
    // Quarter directions crossed, as multiples k·90° between ang0 and ang0 + sw.
    double lo = std::min(ang0, ang0 + sw), hi = std::max(ang0, ang0 + sw);
    int k0 = int(std::ceil(lo / (kPi / 2))), k1 = int(std::floor(hi / (kPi / 2)));
    for (int k = k0; k <= k1 && k < k0 + 8; ++k) {
        double ang = k * kPi / 2;
        double t = (ang - ang0) / sw;
        double r = r0 + (r1 - r0) * t;
        double q[3] = {s[0] + (mv.p[0] - s[0]) * t, s[1] + (mv.p[1] - s[1]) * t,
                       s[2] + (mv.p[2] - s[2]) * t};
        q[a.a0] = a.c0 + r * std::cos(ang);
        q[a.a1] = a.c1 + r * std::sin(ang);
        b.add(q);
    }
}

void Toolpath::add_error(const Diag& d) {
    if (!d.is_error()) return;
    PathError pe;
    pe.loc = Loc{d.program, d.line, d.n};
    pe.code = d.code;
    pe.detail = d.detail;
    pe.moves = moves_.size();
    // The moves of the failing block are the last ones made: flag them.
    for (size_t k = locs_.size(); k-- > 0;) {
        const LocRun& r = locs_[k];
        if (r.prog != d.program || r.line != d.line) break;
        size_t last = k + 1 < locs_.size() ? locs_[k + 1].first : moves_.size();
        for (size_t i = r.first; i < last; ++i) moves_[i].flags |= pathflag::error;
    }
    errors_.push_back(std::move(pe));
}

void Toolpath::add_stock(const Loc&, const std::vector<std::array<double, 2>>& zr) {
    if (!zr.empty()) stock_.push_back(zr);
}

void Toolpath::set_extremes(const Axes& lo, const Axes& hi, uint16_t mask_lo, uint16_t mask_hi) {
    em_lo_ = lo;
    em_hi_ = hi;
    em_mask_lo_ = mask_lo;
    em_mask_hi_ = mask_hi;
}

Loc Toolpath::loc(size_t i) const {
    auto it = std::upper_bound(locs_.begin(), locs_.end(), uint32_t(i),
                               [](uint32_t v, const LocRun& r) { return v < r.first; });
    if (it == locs_.begin()) return Loc{};
    --it;
    return Loc{it->prog, it->line, it->n};
}

int Toolpath::arc_plane() const {
    int best = 0;
    for (int k = 1; k < 3; ++k)
        if (plane_arcs_[k] > plane_arcs_[best]) best = k;
    return plane_arcs_[best] == 0 ? 17 : 17 + best;
}

PathPlane Toolpath::default_plane() const {
    if (m_.lathe) return PathPlane::zx;
    int p = arc_plane();
    return p == 18 ? PathPlane::xz : p == 19 ? PathPlane::yz : PathPlane::xy;
}

size_t Toolpath::memory_bytes() const {
    size_t n = moves_.capacity() * sizeof(PathMove) + arcs_.capacity() * sizeof(PathArc) +
               locs_.capacity() * sizeof(LocRun) + errors_.capacity() * sizeof(PathError);
    for (const auto& s : stock_) n += s.capacity() * sizeof(s[0]);
    n += profile_.capacity() * sizeof(ProfileElem);
    return n + sizeof(*this);
}

double nice_length(double target) {
    if (!(target > 0) || !std::isfinite(target)) return 1;
    double p = std::pow(10.0, std::floor(std::log10(target)));
    double m = target / p;
    return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}

namespace {

// A programmed element seen in the plane (h, v), if it lies in it.
void add_profile_box(const ProfileElem& e, int h, int v, PathBox& b) {
    bool direct = e.a0 == h && e.a1 == v, swapped = e.a0 == v && e.a1 == h;
    if (!direct && !swapped) return;
    auto put = [&](double p0, double p1) {
        double q[3] = {0, 0, 0};
        q[e.a0] = p0;
        q[e.a1] = p1;
        b.add(q);
    };
    put(e.from[0], e.from[1]);
    put(e.to[0], e.to[1]);
    if (!e.arc) return;
    double r = std::hypot(e.from[0] - e.c[0], e.from[1] - e.c[1]);
    double a0 = std::atan2(e.from[1] - e.c[1], e.from[0] - e.c[0]), sw = e.sweep * kPi / 180;
    double lo = std::min(a0, a0 + sw), hi = std::max(a0, a0 + sw);
    for (int k = int(std::ceil(lo / (kPi / 2))); k <= int(std::floor(hi / (kPi / 2))); ++k)
        put(e.c[0] + r * std::cos(k * kPi / 2), e.c[1] + r * std::sin(k * kPi / 2));
}

}  // namespace

PathFit fit_box(const Toolpath& p, PathPlane plane, bool mirror, bool with_profile) {
    int h, v;
    plane_axes(plane, h, v);
    PathFit f;
    PathBox b = p.cut_bounds();
    f.what = b.empty() ? p.empty() ? PathFit::start : PathFit::moves : PathFit::cuts;
    if (b.empty()) b = p.bounds();
    if (b.empty()) b.add(p.start());
    for (const auto& poly : p.stock())
        for (const auto& q : poly) {
            double pt[3] = {0, 0, 0};
            pt[X] = q[1];
            pt[Z] = q[0];
            b.add(pt);
        }
    if (with_profile)
        for (const ProfileElem& e : p.profile_elems()) add_profile_box(e, h, v, b);
    f.x0 = b.lo[h], f.x1 = b.hi[h], f.y0 = b.lo[v], f.y1 = b.hi[v];
    // A machining centre's block (the workshop's), seen from above, whole.
    if (!p.machine().lathe && h == X && v == Y)
        for (const auto& poly : p.part())
            for (const auto& q : poly) {
                f.x0 = std::min(f.x0, q[0]), f.x1 = std::max(f.x1, q[0]);
                f.y0 = std::min(f.y0, q[1]), f.y1 = std::max(f.y1, q[1]);
            }
    // The mirror image (lathe) is of the cutting moves only.
    const PathBox& c = p.cut_bounds();
    if (mirror && !c.empty()) {
        if (c.lo[v] > c.hi[v] - c.lo[v])
            f.mirror_out = true;
        else
            f.y0 = std::min(f.y0, -c.hi[v]);
    }
    uint16_t both = p.extremes_mask_lo() & p.extremes_mask_hi();
    if ((both >> h & 1) && (both >> v & 1)) {
        f.x0 = std::min(f.x0, p.extremes_lo()[size_t(h)]);
        f.x1 = std::max(f.x1, p.extremes_hi()[size_t(h)]);
        f.y0 = std::min(f.y0, p.extremes_lo()[size_t(v)]);
        f.y1 = std::max(f.y1, p.extremes_hi()[size_t(v)]);
    }
    return f;
}

void count_outside(const Toolpath& p, PathPlane plane, size_t upto, PathFit& f) {
    int h, v;
    plane_axes(plane, h, v);
    const double tol = 1e-6 * (1 + std::max(f.x1 - f.x0, f.y1 - f.y0));
    f.outside = 0;
    bool counted = false;  // the move these pieces belong to is counted
    for (size_t i = 0; i < std::min(upto, p.size()); ++i) {
        if (!(p[i].flags & pathflag::piece)) counted = false;
        if (p[i].kind != PathKind::rapid || counted) continue;
        auto out = [&](const double* q) {
            return q[h] < f.x0 - tol || q[h] > f.x1 + tol || q[v] < f.y0 - tol || q[v] > f.y1 + tol;
        };
        if (out(p.from(i)) || out(p[i].p)) ++f.outside, counted = true;
    }
}

std::string fit_words(const Toolpath& p, const PathFit& f) {
    // What the plot's frame shows, a noun phrase ("frame fitted to %s").
    switch (f.what) {
        case PathFit::start:
            return tr("the start point (no move yet)");
        case PathFit::moves:
            return p.program >= 0 ? strf(tr("the whole path of %%%d (no cutting move)"), p.program)
                                  : std::string(tr("the whole path (no cutting move)"));
        case PathFit::cuts:
            break;
    }
    std::string s = p.program >= 0 ? strf(tr("the cutting moves of %%%d"), p.program)
                                   : std::string(tr("the cutting moves")),
                more;
    if (f.mirror_out) more = tr("the mirror image left out, far from the axis");
    if (f.outside)
        more +=
            (more.empty() ? "" : "; ") +
            strf(trn("%zu rapid reaches beyond", "%zu rapids reach beyond", f.outside), f.outside);
    return more.empty() ? s : s + " (" + more + ")";
}

// EM± then axis words, literal numbers only (a variable is not known before
// the run, and the extremes are only a frame for the drawing).
bool scan_extremes(const ProgramText& p, bool x_diameter, Axes& lo, Axes& hi, uint16_t& mask_lo,
                   uint16_t& mask_hi) {
    mask_lo = mask_hi = 0;
    std::string_view body = p.body();
    Block b;
    size_t pos = 0;
    while (pos < body.size()) {
        size_t eol = body.find('\n', pos);
        if (eol == std::string_view::npos) eol = body.size();
        std::string_view line = body.substr(pos, eol - pos);
        pos = eol + 1;
        if (line.find("EM") == std::string_view::npos) continue;
        if (Error e = parse_block(line, b)) continue;
        int sign = 0;  // -1 EM-, +1 EM+
        for (const Word& w : b.words) {
            if (w.addr == addrE('M')) {
                sign = w.v.neg ? -1 : w.v.has_sign ? 1 : 0;
                continue;
            }
            if (!sign || w.addr >= 26 || w.v.kind != Operand::Number) continue;
            int axis = axis_of(char('A' + w.addr));
            if (axis < X || axis > Z) continue;
            double v = w.v.neg ? -w.v.num : w.v.num;
            if (axis == X && x_diameter) v /= 2;
            (sign < 0 ? lo : hi)[size_t(axis)] = v;
            (sign < 0 ? mask_lo : mask_hi) |= uint16_t(1u << axis);
        }
    }
    return mask_lo || mask_hi;
}

}  // namespace pupitre
