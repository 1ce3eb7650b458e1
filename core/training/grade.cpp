// Grading: the values against the truth, the part against the drawing, the
// mistakes named from the value entered and the truth.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/training/grade.hpp"

#include <algorithm>
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/value_name.hpp"
#include "core/workshop/workshop.hpp"

namespace pupitre::training {

namespace {

std::string mm(double v) {
    return strf("%.3f", std::abs(v) < 5e-7 ? 0.0 : v);
}

bool near(double a, double b, double tol) {
    return std::abs(a - b) <= tol + 1e-9;
}

// What a mistake's finder sees.
struct Probe {
    const Exercise& e;
    const workshop::Setup& s;
    const Context& ctx;
    const ItemGrade& it;
    ValueName n;        // the target, PREF.X or D2.DX (target_name's)
    std::string field;  // its axis or field: X, DX
    double tol;
    bool origin() const { return n.kind == ValueName::Kind::origin; }
    bool corrector() const { return !origin(); }
    bool pref() const { return origin() && n.number == 0; }
    bool dec1() const { return origin() && n.number == 1; }
    bool wear() const { return corrector() && n.field->wear; }  // DX DZ DL DR
};

using Finder = std::string (*)(const Probe&);

// A corrector's X (or DX) twice its truth: a diameter entered where the CORR
// page wants a radius; an origin off by half or a quarter of a diameter read.
std::string diameter(const Probe& p) {
    const double t = p.it.truth, f = p.it.found;
    if (p.field != "X" && p.field != "DX") return {};
    if (p.corrector()) {
        if (std::abs(t) > p.tol && near(f, 2 * t, p.tol))
            return strf(tr("%s is twice the truth %s: a diameter where a radius was expected"),
                        mm(f).c_str(), mm(t).c_str());
        return {};
    }
    for (double d : p.ctx.diameters)
        for (double k : {0.5, -0.5, 0.25, -0.25})
            if (near(f, t + k * d, p.tol))
                return strf(tr("off by %s mm, %s the \u00d8%s: a diameter taken for a radius, or "
                               "the reverse"),
                            mm(f - t).c_str(), std::abs(k) == 0.5 ? tr("half") : tr("a quarter of"),
                            mm(d).c_str());
    return {};
}

// The reverse: a corrector's X or DX half its truth (a lathe's DX is a
// diameter, a wear correction halved as if it were a radius).
std::string radius(const Probe& p) {
    const double t = p.it.truth, f = p.it.found;
    if ((p.field != "X" && p.field != "DX") || !p.corrector()) return {};
    if (std::abs(t) > p.tol && near(f, t / 2, p.tol))
        return strf(tr("%s is half the truth %s: a radius where a diameter was expected"),
                    mm(f).c_str(), mm(t).c_str());
    return {};
}

std::string sign(const Probe& p) {
    if (!p.corrector() || p.wear() || std::abs(p.it.truth) <= p.tol) return {};
    if (!near(p.it.found, -p.it.truth, p.tol)) return {};
    return strf(tr("%s instead of %s: a gauge is OM - P, the turret or spindle reference minus the "
                   "tool point"),
                mm(p.it.found).c_str(), mm(p.it.truth).c_str());
}

std::string wear_sign(const Probe& p) {
    if (!p.wear() || std::abs(p.it.truth) <= p.tol) return {};
    if (!near(p.it.found, -p.it.truth, p.tol)) return {};
    return strf(tr("%s instead of %s: a part too large needs a smaller gauge, a negative "
                   "correction"),
                mm(p.it.found).c_str(), mm(p.it.truth).c_str());
}

// A tool's gauge along an origin's axis (0 when it has none there).
double gauge_along(const workshop::ToolTruth& t, const std::string& axis, bool lathe) {
    if (lathe) return axis == "X" ? t.x : axis == "Z" ? t.z : 0;
    return axis == "Z" ? t.length : 0;
}

// A corrector that holds another tool's gauge: the touch-off was made with
// that tool in the turret (or spindle) while this corrector was active.
std::string other_tool(const Probe& p) {
    const bool lathe = p.s.kind == "lathe";
    // The gauges: X and Z on a lathe, L (along Z) on a mill.
    if (lathe ? p.field != "X" && p.field != "Z" : p.field != "L") return {};
    const int d = p.n.number;
    for (const workshop::ToolTruth& b : p.s.tools) {
        const double g = gauge_along(b, lathe ? p.field : "Z", lathe);
        if (b.position != d && std::abs(g - p.it.truth) > p.tol && near(p.it.found, g, p.tol))
            return strf(tr("%s is T%d's gauge, not T%d's: touched off with T%d in the turret and "
                           "D%d active"),
                        mm(p.it.found).c_str(), b.position, d, b.position, d);
    }
    return {};
}

// An origin off by a tool's gauge (touched off under D0), or by the
// difference of two tools' gauges (the wrong corrector active); a corrector
// holding another tool's gauge.
std::string corrector(const Probe& p) {
    if (p.corrector()) return other_tool(p);  // X Z or L only: not a DX
    if (!p.pref()) return {};
    const bool lathe = p.s.kind == "lathe";
    const double err = p.it.found - p.it.truth;
    for (const workshop::ToolTruth& a : p.s.tools) {
        const double ga = gauge_along(a, p.field, lathe);
        if (std::abs(ga) > p.tol && (near(err, ga, p.tol) || near(err, -ga, p.tol)))
            return strf(tr("off by %s mm, T%d's gauge: touched off with no corrector (D0) "
                           "active"),
                        mm(err).c_str(), a.position);
        for (const workshop::ToolTruth& b : p.s.tools) {
            const double d = ga - gauge_along(b, p.field, lathe);
            if (&a != &b && std::abs(d) > p.tol && near(err, d, p.tol))
                return strf(tr("off by %s mm, T%d's gauge minus T%d's: touched off with T%d in "
                               "the turret and D%d active"),
                            mm(err).c_str(), a.position, b.position, a.position, b.position);
        }
    }
    return {};
}

std::string dec1(const Probe& p) {
    if (p.dec1()) {
        if (std::abs(p.it.truth) > p.tol && near(p.it.found, 0, p.tol))
            return strf(tr("DEC1 %s left at 0: the program's origin is %s mm from PREF"),
                        p.field.c_str(), mm(p.it.truth).c_str());
        return {};
    }
    double dec = 0;
    if (!p.pref() || !expected(p.e, p.s, format_value_name(ValueName::origin(1, p.n.axis)), dec) ||
        std::abs(dec) <= p.tol || !near(p.it.found, p.it.truth + dec, p.tol))
        return {};
    return strf(tr("PREF %s holds PREF + DEC1 (%s + %s): the offset went into PREF, DEC1 was "
                   "forgotten"),
                p.field.c_str(), mm(p.it.truth).c_str(), mm(dec).c_str());
}

std::string shim(const Probe& p) {
    if (p.wear() || p.field == "R" || p.dec1()) return {};
    const double err = p.it.found - p.it.truth;
    for (double s : p.ctx.shims)
        if (near(err, s, p.tol) || near(err, -s, p.tol))
            return strf(tr("off by %s mm: the %s mm shim or gauge block was not subtracted"),
                        mm(err).c_str(), mm(s).c_str());
    return {};
}

std::string unset(const Probe& p) {
    double start = 0;
    start_value(p.e, p.s, p.it.name, start);
    if (!near(p.it.found, start, 1e-6)) return {};
    return strf(tr("left at %s, its value when the exercise began"), mm(start).c_str());
}

struct Row {
    Mistake m;
    const char* id;
    const char* title;
    Finder find;
};
// In the order they are tried: the first that explains the value names it.
constexpr Row kMistakes[] = {
    {Mistake::dec1, "dec1", N_("DEC1 forgotten"), dec1},
    {Mistake::diameter, "diameter", N_("X taken as a diameter instead of a radius"), diameter},
    {Mistake::radius, "radius", N_("X taken as a radius instead of a diameter"), radius},
    {Mistake::sign, "sign", N_("a gauge with the wrong sign"), sign},
    {Mistake::wear_sign, "wear-sign", N_("a wear correction with the wrong sign"), wear_sign},
    {Mistake::corrector, "corrector", N_("a touch-off with the wrong corrector active"), corrector},
    {Mistake::shim, "shim", N_("a shim's thickness not subtracted"), shim},
    {Mistake::unset, "unset", N_("not entered"), unset},
};

void name_mistake(const Exercise& e, const workshop::Setup& truth, const Context& ctx,
                  ItemGrade& it) {
    ValueName n;
    if (!parse_value_name(it.name, n) || n.kind == ValueName::Kind::l_param ||
        n.kind == ValueName::Kind::e_param)
        return;  // no target (target_name): nothing to explain
    const std::string field = n.kind == ValueName::Kind::corrector
                                  ? std::string(n.field->text)
                                  : std::string(1, kAxisNames[size_t(n.axis)]);
    Probe p{e, truth, ctx, it, n, field, it.tolerance};
    for (const Row& r : kMistakes) {
        std::string why = r.find(p);
        if (why.empty()) continue;
        it.mistake = r.m;
        it.why = why;
        return;
    }
}

DimGrade dimension(const Dimension& d, const workshop::Workshop* part) {
    DimGrade g;
    g.dim = d;
    workshop::Reading r;
    if (!part) {
        g.why = tr("no part");
        return g;
    }
    if (std::string why = part->measure(d.spec, r); !why.empty()) {
        g.why = why;
        return g;
    }
    g.read = true;
    g.measured = r.value;
    g.ok = r.value >= d.nominal + d.lower - 1e-9 && r.value <= d.nominal + d.upper + 1e-9;
    return g;
}

}  // namespace

const char* mistake_id(Mistake m) {
    for (const Row& r : kMistakes)
        if (r.m == m) return r.id;
    return "";
}

std::string mistake_title(Mistake m) {
    for (const Row& r : kMistakes)
        if (r.m == m) return tr(r.title);
    return {};
}

std::vector<Mistake> Grade::mistakes() const {
    std::vector<Mistake> out;
    for (const ItemGrade& i : items)
        if (i.mistake != Mistake::none) out.push_back(i.mistake);
    return out;
}

Grade grade(const Exercise& e, const workshop::Setup& truth, const Values& found,
            const Context& ctx, const workshop::Workshop* part, int crashes, double seconds) {
    Grade g;
    int right = 0;
    for (const Target& t : e.find) {
        ItemGrade it;
        it.name = t.name;
        it.tolerance = t.tolerance;
        expected(e, truth, t.name, it.truth, &it.how);
        auto f = found.find(t.name);
        it.found = f == found.end() ? 0 : f->second;
        it.ok = near(it.found, it.truth, t.tolerance);
        if (!it.ok) name_mistake(e, truth, ctx, it);
        right += it.ok;
        g.items.push_back(std::move(it));
    }
    g.crashes = crashes;
    g.scrapped = crashes > 0;
    for (const Dimension& d : e.dimensions) {
        g.dims.push_back(dimension(d, part));
        if (!g.dims.back().ok) g.scrapped = true;
    }
    // A crash scraps the part: its dimensions count as wrong.
    if (crashes == 0)
        for (const DimGrade& d : g.dims) right += d.ok;
    g.seconds = seconds;
    g.late = e.minutes > 0 && seconds > e.minutes * 60;
    const size_t total = g.items.size() + g.dims.size();
    g.score = total ? int(std::lround(100.0 * right / double(total))) : 0;
    return g;
}

namespace {
std::string duration(double seconds) {
    const long s = std::lround(seconds);
    return s >= 60 ? strf(tr("%ld min %02ld s"), s / 60, s % 60) : strf(tr("%ld s"), s);
}
}  // namespace

std::vector<std::string> report_lines(const Exercise& e, const Grade& g) {
    std::vector<std::string> out;
    out.push_back(strf(tr("%s: %s"), e.name.c_str(), e.title_here().c_str()));
    std::string head = strf(tr("Score %d%%  time %s"), g.score, duration(g.seconds).c_str());
    if (e.minutes > 0) head += strf(tr(" (of %g min%s)"), e.minutes, g.late ? tr(", late") : "");
    head += strf(tr("  crashes %d"), g.crashes);
    if (g.scrapped) head += tr("  the part is scrapped");
    out.push_back(head);
    if (!g.items.empty()) {
        out.emplace_back();
        out.push_back(tr("VALUE       FOUND        TRUTH     ERROR \u00b5m  TOL \u00b5m"));
    }
    for (const ItemGrade& i : g.items) {
        out.push_back(strf("%-9s %10s  %11s  %10.0f  %7.0f  %s", i.name.c_str(),
                           mm(i.found).c_str(), mm(i.truth).c_str(),
                           std::round((i.found - i.truth) * 1000) + 0.0, i.tolerance * 1000,
                           i.ok ? tr("ok") : tr("WRONG")));
        out.push_back("    " + i.how);
        if (i.mistake != Mistake::none)
            out.push_back("    \u2192 " +
                          strf(tr("%s: %s"), mistake_title(i.mistake).c_str(), i.why.c_str()));
    }
    if (const std::vector<std::string> how = e.method_here(); !how.empty()) {
        out.emplace_back();
        out.push_back(tr("HOW THE VALUES ARE WORKED OUT"));
        for (const std::string& l : how) out.push_back("    " + l);
    }
    if (!g.dims.empty()) {
        out.emplace_back();
        out.push_back(tr("DIMENSION            NOMINAL    MEASURED   LIMITS"));
    }
    for (const DimGrade& d : g.dims) {
        const Dimension& m = d.dim;
        std::string limits = mm(m.nominal + m.lower) + " .. " + mm(m.nominal + m.upper);
        out.push_back(strf("%-18s %10s  %10s   %-20s %s", m.spec.c_str(), mm(m.nominal).c_str(),
                           d.read ? mm(d.measured).c_str() : "-", limits.c_str(),
                           d.ok ? tr("ok") : tr("WRONG")));
        if (!d.read) out.push_back("    " + d.why);
    }
    if (g.crashes > 0) out.push_back(tr("A crash scraps the part: its dimensions count as wrong."));
    return out;
}

}  // namespace pupitre::training
