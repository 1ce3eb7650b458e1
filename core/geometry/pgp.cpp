// Profile geometry programming (000:8358-8564, 000:13241-13279; pupitre-iso(5),
// PROFILE GEOMETRY PROGRAMMING (PGP)). Each block is classified by what it
// fixes of its element; an entity of 2 or 3 blocks is solved by enumerating
// every geometric candidate (intersections, tangent lines and circles), keeping
// those without a cusp at a tangency and with lines travelled forward, then
// choosing with the discriminants pupitre chose (pupitre-iso(5), DECISIONS,
// Discriminants of PGP). EB corners are cut afterwards, when both elements are
// known. The elements and the corners themselves are built in pgp_elements.cpp.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/pgp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/geometry/pgp_elements.hpp"
#include "core/i18n.hpp"

namespace pupitre::pgp {

using namespace detail;

namespace {
using ::pupitre::geometry::cross;
using ::pupitre::geometry::kPi;
using ::pupitre::geometry::perp;

// ---------------------------------------------------------------------------
// Entities.

// One geometric solution of an entity: the support of each element and the
// junctions between them.
struct Cand {
    Sup sup[3];
    V2 j[2];
    int branch = 0;  // which solution of the middle element (3 blocks)
};

// What joining the elements of an entity answers: its candidates are
// appended to the caller's; `need` when the next block determines the
// junction; `error` when these blocks cannot be joined.
struct Join {
    bool need = false;
    Error error{};
};

// Can the element be determined by the block after it (the middle of 3 blocks)?
bool middle(const Elt& e) {
    switch (e.form) {
        case Form::Angle:
        case Form::Axis:
        case Form::Centre:
            return true;
        case Form::Radius:
        case Form::Free:
            return !e.has_end;
        default:
            return false;
    }
}

std::vector<V2> dirs(const Elt& e) {
    if (e.form == Form::Axis) return {e.d, -e.d};
    return {e.d};
}

Join stop(int code, std::string detail) {
    return {false, Error{code, std::move(detail)}};
}

Join undetermined(const Elt& b) {
    if (middle(b)) return {.need = true};
    return stop(113, tr("the second element does not determine the junction"));
}

// Where two fully known elements touch (an over-determined tangency).
bool touching(const Sup& a, const Sup& b, V2& j) {
    if (a.arc && b.arc) {
        double dist = (b.p - a.p).norm();
        if (std::fabs(dist - (a.r + b.r)) > kOverTol &&
            std::fabs(dist - std::fabs(a.r - b.r)) > kOverTol)
            return false;
        j = contact(a, b.p, b.r);
        return true;
    }
    const Sup& l = a.arc ? b : a;
    const Sup& c = a.arc ? a : b;
    if (std::fabs(std::fabs(cross(l.d, c.p - l.p)) - c.r) > kOverTol) return false;
    j = contact(l, c.p, c.r);
    return true;
}

void add(std::vector<Cand>& out, const Sup& s1, const Sup& s2, const V2& j) {
    Cand c;
    c.sup[0] = s1;
    c.sup[1] = s2;
    c.j[0] = j;
    out.push_back(c);
}

// Junction of a first element whose support is known (a line through S at its
// angle, a circle through S) with the next element.
Join from_fixed(const V2& S, const Sup& A, const Elt& b, bool tan, std::vector<Cand>& out) {
    if (b.form == Form::Fixed) {
        if (!tan) {
            if (!A.arc && !b.sup.arc) {
                if (std::fabs(cross(A.d, b.sup.d)) < 1e-9)
                    return stop(112, tr("the two lines are parallel"));
                if (b.has_end && (b.end - S).norm() < kEq)
                    return stop(112, tr("the second line ends at the start of the first"));
            }
            for (const V2& j : meet(A, b.sup)) add(out, A, b.sup, j);
            return {};
        }
        if (!A.arc && !b.sup.arc)
            return stop(113, tr("two lines cannot be tangent (ES for their intersection)"));
        V2 j;
        if (!touching(A, b.sup, j))
            return stop(113, tr("the elements are not tangent (ES for their intersection)"));
        add(out, A, b.sup, j);
        return {};
    }
    if (!tan) return undetermined(b);
    switch (b.form) {
        case Form::Centre:  // its radius from the tangency
            for (double r : radii(A, b.c)) add(out, A, circle(b.c, r, b.s), contact(A, b.c, r));
            return {};
        case Form::Radius:  // through its end point, tangent to A
            if (!b.has_end) return {.need = true};
            for (const Sup& l : loci(A, b.r))
                for (const V2& q : meet(l, circle(b.end, b.r, 0)))
                    add(out, A, circle(q, b.r, b.s), contact(A, q, b.r));
            return {};
        case Form::Angle:  // tangent to the circle A at its angle
        case Form::Axis:
            if (!A.arc) return stop(113, tr("a line cannot be tangent to a line"));
            for (const V2& d : dirs(b))
                for (int sg : {1, -1}) {
                    V2 t = A.p + sg * A.r * perp(d);
                    add(out, A, line(t, d), t);
                }
            return {};
        case Form::Free:  // from the circle A to its end point
            if (!A.arc) return stop(113, tr("a line cannot be tangent to a line"));
            if (!b.has_end) return {.need = true};
            for (const V2& t : touch_from(A, b.end)) {
                V2 d = b.end - t;
                add(out, A, line(t, d.norm() < kEq ? tangent(A, t) : V2(d.normalized())), t);
            }
            return {};
        default:
            return stop(113, tr("the second element does not determine the junction"));
    }
}

// Junction of a first element (start S) with the next one.
Join solve2(const V2& S, const Elt& a, const Elt& b, char link, std::vector<Cand>& out) {
    bool tan = link != 'S';
    if (a.form == Form::Fixed) return from_fixed(S, a.sup, b, tan, out);
    if (b.form != Form::Fixed) return undetermined(b);
    if (a.form == Form::Free) {  // a line from S tangent to a circle
        if (!b.sup.arc)
            return stop(113, tr("a line of unknown direction must be tangent to a circle"));
        for (const V2& t : touch_from(b.sup, S)) {
            V2 d = t - S;
            add(out, line(S, d.norm() < kEq ? tangent(b.sup, t) : V2(d.normalized())), b.sup, t);
        }
        return {};
    }
    if (a.form == Form::Radius) {  // a circle through S tangent to b
        if (!tan) return stop(113, tr("a circle known by its radius only cannot be secant"));
        for (const Sup& l : loci(b.sup, a.r))
            for (const V2& q : meet(l, circle(S, a.r, 0)))
                add(out, circle(q, a.r, a.s), b.sup, contact(b.sup, q, a.r));
        return {};
    }
    return stop(113, tr("the first element does not determine the junction"));
}

// Three blocks, the middle element found from the third one: its radius about
// its centre, or its position at its angle, tangent to the third.
Join solve3_by_third(const V2& S, const Elt& a, const Elt& b, const Sup& C3, char link0,
                     std::vector<Cand>& out) {
    std::vector<std::pair<Sup, V2>> mids;
    if (b.form == Form::Centre) {
        for (double r : radii(C3, b.c)) mids.push_back({circle(b.c, r, b.s), contact(C3, b.c, r)});
    } else {
        if (!C3.arc) return stop(123, tr("a line cannot be tangent to a line"));
        for (const V2& d : dirs(b))
            for (int sg : {1, -1}) {
                V2 t = C3.p + sg * C3.r * perp(d);
                mids.push_back({line(t, d), t});
            }
    }
    int branch = 0;
    for (const auto& [sup, t23] : mids) {
        Elt m = b;
        m.form = Form::Fixed;
        m.sup = sup;
        m.has_end = true;
        m.end = t23;
        std::vector<Cand> part;
        Join j = solve2(S, a, m, link0, part);
        if (j.error.code == 112) return stop(122, tr("the first two blocks are parallel lines"));
        if (j.need || j.error) continue;
        for (Cand& cd : part) {
            cd.j[1] = t23;
            cd.sup[2] = C3;
            cd.branch = branch;
            out.push_back(cd);
        }
        ++branch;
    }
    return {};
}

// Three blocks: the middle element is found from the third one (its radius, its
// position) or together with both neighbours (a circle of given radius tangent
// to both, a common tangent line).
Join solve3(const V2& S, const Elt* e, const char link[2], std::vector<Cand>& out) {
    const Elt &a = e[0], &b = e[1], &c = e[2];
    if (c.form != Form::Fixed)
        return stop(123, tr("the third block must fix its element: EA X Y, or I J with R or X Y"));
    const Sup& C3 = c.sup;
    if (link[1] == 'S') return stop(123, tr("the middle element cannot be secant with the third"));
    if (b.form == Form::Angle || b.form == Form::Axis || b.form == Form::Centre)
        return solve3_by_third(S, a, b, C3, link[0], out);
    if (link[0] == 'S')
        return stop(123, tr("the first element cannot be secant with this middle element"));
    if (b.form == Form::Radius && !b.has_end) {
        if (a.form != Form::Fixed)
            return stop(123, tr("the first element must be fixed for this construction"));
        for (const Sup& l1 : loci(a.sup, b.r))
            for (const Sup& l3 : loci(C3, b.r))
                for (const V2& q : meet(l1, l3)) {
                    Cand cd;
                    cd.sup[0] = a.sup;
                    cd.sup[1] = circle(q, b.r, b.s);
                    cd.sup[2] = C3;
                    cd.j[0] = contact(a.sup, q, b.r);
                    cd.j[1] = contact(C3, q, b.r);
                    out.push_back(cd);
                }
        return {};
    }
    if (b.form == Form::Free && !b.has_end) {
        if (a.form != Form::Fixed || !a.sup.arc || !C3.arc)
            return stop(123, tr("a line tangent at both ends needs two circles"));
        for (const Tangent& t : common(a.sup, C3)) {
            Cand cd;
            cd.sup[0] = a.sup;
            cd.sup[1] = line(t.t1, t.d);
            cd.sup[2] = C3;
            cd.j[0] = t.t1;
            cd.j[1] = t.t2;
            out.push_back(cd);
        }
        return {};
    }
    return stop(123, tr("these three blocks do not determine the tangency points"));
}

// The entity being solved: its start, its blocks, their links and discriminants.
struct Entity {
    V2 S;
    Elt e[3];
    char link[2] = {0, 0};
    int disc[2] = {0, 0};
    int n = 2;

    // Start and end of element k in a candidate; false when the end is not known.
    bool ends(const Cand& c, int k, V2& a, V2& b) const {
        a = k == 0 ? S : c.j[k - 1];
        if (k < n - 1) {
            b = c.j[k];
            return true;
        }
        const Elt& x = e[k];
        if (x.has_end) {
            b = x.end;
            return true;
        }
        return !c.sup[k].arc && x.end_axis >= 0 && along(a, c.sup[k].d, x.end_axis, x.end_val, b);
    }

    // No cusp at a tangency (000:8405); lines are travelled forward.
    bool feasible(const Cand& c) const {
        for (int k = 0; k < n; ++k) {
            V2 a, b;
            if (!c.sup[k].arc && ends(c, k, a, b) && (b - a).dot(c.sup[k].d) < -kEq) return false;
        }
        for (int k = 0; k + 1 < n; ++k)
            if (link[k] != 'S' &&
                tangent(c.sup[k], c.j[k]).dot(tangent(c.sup[k + 1], c.j[k])) < 0.5)
                return false;
        return true;
    }

    // E± on arc k (pupitre-iso(5), DECISIONS): +1 when its centre is on the
    // left of its chord; its sweep.
    bool arc_side(const Cand& c, int k, int& side, double& sweep) const {
        V2 a, b;
        if (k < 0 || !c.sup[k].arc || !ends(c, k, a, b)) return false;
        side = cross(b - a, c.sup[k].p - a) > 0 ? 1 : -1;
        sweep = turn(a - c.sup[k].p, b - c.sup[k].p, c.sup[k].s);
        return true;
    }

    // The candidates whose arc k lies on side `want` (all of them for 0), the
    // smallest arc first (000:8388: by default the smaller arc).
    std::vector<Cand> by_arc(const std::vector<Cand>& cs, int k, int want) const {
        std::vector<std::pair<double, const Cand*>> keep;
        for (const Cand& c : cs) {
            int side = 0;
            double sw = 1e300;
            bool known = arc_side(c, k, side, sw);
            if (want == 0 || (known && side == want)) keep.push_back({sw, &c});
        }
        std::stable_sort(keep.begin(), keep.end(),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<Cand> out;
        for (const auto& kc : keep) out.push_back(*kc.second);
        return out;
    }

    // ES±: the order along the line (first met = -, pupitre-iso(5), DECISIONS,
    // Discriminants of PGP), or the side of the line of centres for two
    // circles.
    Error by_secant(const std::vector<Cand>& cs, Cand& pick) const {
        if (disc[0] == 0) return {114, tr("two intersections: choose one with ES+ or ES-")};
        auto key = [&](const Cand& c) {
            if (!c.sup[0].arc) return (c.j[0] - S).dot(c.sup[0].d);
            if (!c.sup[1].arc) return (c.j[0] - c.sup[1].p).dot(c.sup[1].d);
            return cross(c.sup[1].p - c.sup[0].p, c.j[0] - c.sup[0].p);
        };
        const Cand* best = &cs[0];
        for (const Cand& c : cs)
            if (disc[0] < 0 ? key(c) < key(*best) : key(c) > key(*best)) best = &c;
        pick = *best;
        return {};
    }

    // One candidate among the feasible ones; an ambiguity (114, 124) is about
    // the block (its item, 0 or 1) whose discriminant should have chosen.
    Error choose(const std::vector<Cand>& cs, Cand& pick) const {
        std::vector<int> branches;
        for (const Cand& c : cs)
            if (std::find(branches.begin(), branches.end(), c.branch) == branches.end())
                branches.push_back(c.branch);
        std::vector<Cand> per;  // one per solution of the middle element
        for (int b : branches) {
            std::vector<Cand> g;
            for (const Cand& c : cs)
                if (c.branch == b) g.push_back(c);
            Cand one = g[0];
            if (g.size() > 1) {
                if (link[0] == 'S') {
                    if (Error f = by_secant(g, one)) return about(0, std::move(f));
                } else {
                    std::vector<Cand> m = by_arc(g,
                                                 g[0].sup[0].arc   ? 0
                                                 : g[0].sup[1].arc ? 1
                                                                   : -1,
                                                 disc[0]);
                    if (m.empty())
                        return about(0, {114, strf(tr("ET%c designates none of the tangent "
                                                      "solutions"),
                                                   disc[0] > 0 ? '+' : '-')});
                    one = m[0];
                }
            }
            per.push_back(one);
        }
        pick = per[0];
        if (per.size() > 1) {
            // ET± of the middle block (pupitre-iso(5), DECISIONS, Discriminants
            // of PGP) must designate one solution.
            if (disc[1] == 0)
                return about(
                    1,
                    {124, tr("two tangencies between blocks 2 and 3: choose one with ET+ or ET-")});
            std::vector<Cand> m = by_arc(per, 1, disc[1]);
            if (m.size() != 1)
                return about(1, {124, strf(tr("ET%c does not designate one of the two tangencies "
                                              "between blocks 2 and 3"),
                                           disc[1] > 0 ? '+' : '-')});
            pick = m[0];
        }
        return {};
    }

    // The error `e` about block `block` of the entity (0 to 2).
    static Error about(int block, Error e) {
        e.item = block;
        return e;
    }
};

enum class Step { Complete, Wait, Solved };

// Solves the entity made of the waiting blocks (`count` of them, the first one
// starting at S, `over` its support if already known). Answers why they do
// not solve, its item the number of the block it is about; else `step` says
// what they gave: Complete: the first block is an element by itself; Wait:
// one more block is needed; Solved: `pick` is the chosen solution of en.n
// blocks.
Error entity(const V2& S, const Spec* const* specs, int count, const Sup* over, Entity& en,
             Cand& pick, Step& step) {
    step = Step::Wait;
    if (Error f = first_elt(*specs[0], S, over, en.e[0])) return Entity::about(0, std::move(f));
    if (en.e[0].form == Form::Complete) {
        step = Step::Complete;
        return {};
    }
    if (count < 2) return {};
    if (Error f = next_elt(*specs[1], 1, en.e[1])) return Entity::about(1, std::move(f));
    en.S = S;
    for (int k = 0; k < 2; ++k) {
        en.link[k] = specs[k]->link;
        en.disc[k] = specs[k]->disc;
    }
    std::vector<Cand> cs;
    Join j = solve2(S, en.e[0], en.e[1], en.link[0], cs);
    if (j.need) {
        if (count < 3) return {};
        if (Error f = next_elt(*specs[2], 2, en.e[2])) return Entity::about(2, std::move(f));
        en.n = 3;
        j = solve3(S, en.e, en.link, cs);
    }
    if (j.error) return Entity::about(en.n - 1, std::move(j.error));
    std::erase_if(cs, [&](const Cand& c) { return !en.feasible(c); });
    if (cs.empty())
        return Entity::about(en.n - 1,
                             {en.n == 2 ? 113 : 123,
                              en.n == 2 ? tr("no intersection or tangency between these two blocks")
                                        : tr("these three blocks give no tangency points")});
    if (Error f = en.choose(cs, pick)) return f;
    step = Step::Solved;
    return {};
}
}  // namespace

// ---------------------------------------------------------------------------

void Solver::start(const V2& p) {
    wait_.clear();
    held_ = false;
    idle_ = 0;
    pos_ = p;
}

bool Solver::pending() const {
    return !wait_.empty() || held_;
}

V2 Solver::position() const {
    return pos_;
}

Error Solver::fail(int code, int tag, std::string detail) {
    wait_.clear();
    held_ = false;
    idle_ = 0;
    return Error{.code = code, .detail = std::move(detail), .item = tag};
}

Error Solver::push(const Spec& s, std::vector<Elem>& out) {
    idle_ = 0;
    if (s.stop && s.has_eb) return fail(131, s.tag, tr("EB on a block with M0, M1 or M2"));
    // The block's own words, checked where it stands in its entity (110, 111, 121).
    Elt e;
    int pos = int(wait_.size());
    if (Error f = pos == 0 ? first_elt(s, pos_, nullptr, e) : next_elt(s, std::min(pos, 2), e))
        return fail(f.code, s.tag, f.detail);
    wait_.push_back(Item{s});
    return resolve(out);
}

Error Solver::idle() {
    if (!pending()) return {};
    if (++idle_ > 2)
        return fail(136, wait_.empty() ? held_elem_.tag : wait_[0].spec.tag,
                    tr("more than 2 blocks without motion between elements to be joined"));
    return {};
}

Error Solver::finish(std::vector<Elem>& out) {
    idle_ = 0;
    if (!wait_.empty())
        return fail(131, wait_[0].spec.tag,
                    tr("the profile ends before the end point of this element is known"));
    if (held_) out.push_back(held_elem_);
    held_ = false;
    return {};
}

Error Solver::resolve(std::vector<Elem>& out) {
    while (!wait_.empty()) {
        const Spec* specs[3] = {nullptr, nullptr, nullptr};
        int count = int(std::min<size_t>(wait_.size(), 3));
        for (int k = 0; k < count; ++k) specs[k] = &wait_[size_t(k)].spec;
        const Item& it = wait_[0];
        Sup over = it.arc ? circle(it.p, it.r, it.s) : line(it.p, it.d);
        Entity en;
        Cand pick;
        Step step = Step::Wait;
        if (Error f = entity(pos_, specs, count, it.fixed ? &over : nullptr, en, pick, step))
            return fail(f.code, wait_[size_t(f.item)].spec.tag, f.detail);
        switch (step) {
            case Step::Wait:
                return {};
            case Step::Complete: {
                Spec sp = it.spec;
                wait_.erase(wait_.begin());
                pos_ = en.e[0].geo.b;
                if (Error e = deliver(Elem{en.e[0].geo, sp.tag, false}, sp, out)) return e;
                continue;
            }
            case Step::Solved:
                break;
        }
        // The entity's last block starts the next entity, its support known.
        int last = en.n - 1;
        std::vector<Spec> done;
        for (int k = 0; k < last; ++k) done.push_back(wait_[size_t(k)].spec);
        const Sup& ls = pick.sup[last];
        Item next = wait_[size_t(last)];
        next.fixed = true;
        next.arc = ls.arc;
        next.p = ls.p;
        next.d = ls.d;
        next.r = ls.r;
        next.s = ls.s;
        wait_.erase(wait_.begin(), wait_.begin() + last);
        wait_[0] = next;
        V2 from = pos_;
        pos_ = pick.j[last - 1];
        for (int k = 0; k < last; ++k) {
            Elem el{piece(pick.sup[k], k == 0 ? from : pick.j[k - 1], pick.j[k]),
                    done[size_t(k)].tag, false};
            if (Error e = deliver(el, done[size_t(k)], out)) return e;
        }
    }
    return {};
}

Error Solver::deliver(Elem e, const Spec& s, std::vector<Elem>& out) {
    double len = length(e.geo);
    if (held_) {
        if (len < kEq) return fail(130, s.tag, tr("zero move in a block joined by EB"));
        Elem ins;
        ins.tag = held_elem_.tag;
        ins.inserted = true;
        if (Error c = corner(held_elem_.geo, held_eb_, e.geo, ins.geo))
            return fail(c.code, held_elem_.tag, c.detail);
        held_ = false;
        if ((held_elem_.geo.b - held_elem_.geo.a).norm() > 0 || held_elem_.geo.arc)
            out.push_back(held_elem_);
        out.push_back(ins);
    }
    if (s.has_eb && s.eb != 0) {
        if (len < kEq) return fail(130, s.tag, tr("zero move in a block joined by EB"));
        held_ = true;
        held_elem_ = e;
        held_eb_ = s.eb;
        return {};
    }
    if ((e.geo.b - e.geo.a).norm() > 0 || e.geo.arc) out.push_back(e);
    return {};
}

}  // namespace pupitre::pgp
