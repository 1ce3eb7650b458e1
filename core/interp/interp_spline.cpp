// G48 (define a spline from point blocks), G06 (run it from the current point),
// G49 (delete it): 000:4854-4888; pupitre-iso(5), SPLINES.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/i18n.hpp"
#include "core/interp/plan.hpp"

namespace pupitre {

bool Interpreter::spline_define(const Plan& p) {
    if (modal_.radcomp != 40) return fail(140, tr("G48 must be programmed in G40"));
    if (p.spline.nc == 0) return fail(600, tr("G48: the curve number NC must not be 0"));
    if (p.spline.nc < 0 || p.spline.nn < 2)
        return fail(601, tr("G48 needs NC and the first and last blocks N.. N.."));
    const ProgramText* prog = stack_.back().prog;
    if (p.spline.h >= 0 && !(prog = mem_.find(p.spline.h)))
        return fail(25, strf(tr("G48 H%d: program not in memory"), p.spline.h));
    const Label* a = prog->find_label(p.spline.n[0]);
    const Label* b = prog->find_label(p.spline.n[1]);
    if (!a || !b)
        return fail(25, strf(tr("G48: block N%ld not found"), !a ? p.spline.n[0] : p.spline.n[1]));
    if (b->line < a->line) std::swap(a, b);
    // Decode each definition block like a move, without moving.
    std::string_view text = *prog->text;
    std::vector<std::pair<std::bitset<kAxes>, Axes>> blocks;
    size_t pos = a->offset;
    Loc saved = loc_;
    Block blk;
    for (int line = a->line; line <= b->line && pos < prog->end; ++line) {
        size_t eol = std::min(text.find('\n', pos), prog->end);
        loc_ = Loc{prog->number, line, line_label(text.substr(pos, eol - pos))};
        if (Error e = parse_block(text.substr(pos, eol - pos), blk)) return fail(e);
        Plan q;
        if (!decode(blk, q)) return false;
        if (line == a->line || line == b->line || q.to.axis.any())
            blocks.push_back({q.to.axis, q.to.val});
        pos = eol + 1;
    }
    loc_ = saved;
    spline::Curve c;
    const auto& first = blocks.front();
    for (int ax = 0; ax < kAxes; ++ax)
        if (first.first[size_t(ax)]) c.axes.push_back(ax);
    if (c.axes.empty()) return fail(602, tr("G48: the first block names no axis"));
    for (int ax : c.axes) c.t0.push_back(first.second[size_t(ax)]);
    std::vector<double> prev(c.axes.size(), 0);
    for (size_t i = 1; i + 1 < blocks.size(); ++i) {
        std::vector<double> pt(c.axes.size());
        for (size_t k = 0; k < c.axes.size(); ++k) {
            int ax = c.axes[k];
            pt[k] = blocks[i].first[size_t(ax)] ? blocks[i].second[size_t(ax)]
                                                : (i > 1 ? prev[k] : prog_[size_t(ax)]);
        }
        c.pts.push_back(pt);
        prev = pt;
    }
    const auto& last = blocks.back();
    if (blocks.size() > 1 && last.first.any())
        for (int ax : c.axes) c.t1.push_back(last.second[size_t(ax)]);
    if (Error e = spline::build(c)) return fail(e.code, "G48: " + e.detail);
    splines_[p.spline.nc] = std::move(c);
    return true;
}

bool Interpreter::spline_run(const Plan& p) {
    auto it = splines_.find(p.spline.nc);
    if (it == splines_.end())
        return fail(605, strf(tr("G06: curve NC%d is not defined"), p.spline.nc));
    if (p.tech.has_f || p.tech.has_s || p.tech.has_t)
        return fail(3, tr("no F, S or T in a G06 block (000:2055)"));
    const spline::Curve& c = it->second;
    for (const auto& pt : spline::sample(c, 0.002)) {
        Axes target = prog_;
        for (size_t k = 0; k < c.axes.size(); ++k) target[size_t(c.axes[k])] = pt[k];
        if (comp_.on) {
            comp::Elem line;
            line.a = comp::V2(prog_[size_t(comp_.a0)], prog_[size_t(comp_.a1)]);
            line.b = comp::V2(target[size_t(comp_.a0)], target[size_t(comp_.a1)]);
            if ((line.b - line.a).norm() < 1e-9) continue;
            if (!comp_element(line, 1, target, 0)) return false;
        } else if (!cycle_move(1, target)) {
            return false;
        }
    }
    return true;
}

}  // namespace pupitre
