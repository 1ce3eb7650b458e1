// Expression evaluation (000:7444-7457; pupitre-iso(5), PARAMETRIC
// PROGRAMMING): the accumulator starts with the first term; each `op term` is
// applied in turn, no precedence, no parentheses. Seed 004:1353: L1=2+3*5 gives
// 25.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parse/eval.hpp"

#include <cmath>
#include <numbers>

#include "core/i18n.hpp"
#include "core/numfmt.hpp"

namespace pupitre {

Error eval_operand(const Operand& o, const LVars& l, EAccess& e, double& out) {
    switch (o.kind) {
        case Operand::Number:
            out = o.num;
            break;
        case Operand::LVar:
            if (!LVars::valid(o.index))
                return {91, strf(tr("L%d does not exist (L0-L19, L100-L199, L900-L959)"), o.index)};
            out = l.v[size_t(o.index)];
            if (!l.written.test(size_t(o.index)))
                l.unset_read.set(size_t(o.index)), l.any_unset_read = true;
            break;
        case Operand::EParam: {
            int64_t raw;
            if (Error err = e.read_e(o.index, raw)) return err;
            out = double(raw);
            break;
        }
        case Operand::EIndirect: {
            if (!LVars::valid(o.index)) return {91, strf(tr("L%d does not exist"), o.index)};
            double n = l.v[size_t(o.index)];
            if (!l.written.test(size_t(o.index)))
                l.unset_read.set(size_t(o.index)), l.any_unset_read = true;
            if (n < 0 || n > 99999 || n != std::floor(n))
                return {91, strf(tr("E parameter number %s taken from L%d is not an E number"),
                                 std::to_string(n).c_str(), o.index)};
            int64_t raw;
            if (Error err = e.read_e(int(n), raw)) return err;
            out = double(raw);
            break;
        }
        case Operand::Blank:
        case Operand::SignOnly:
            out = 0;
            break;
    }
    if (o.neg) out = -out;
    return {};
}

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

Error apply_prefix(const Term& t, double& v) {
    for (int i = int(t.nprefix) - 1; i >= 0; --i) {
        switch (t.prefix[i]) {
            case '-':
                v = -v;
                break;
            case '+':
                break;
            case 'S':
                v = std::sin(v * kDeg);
                break;
            case 'C':
                v = std::cos(v * kDeg);
                break;
            case 'A':
                v = std::atan(v) / kDeg;
                break;
            case 'T':
                v = std::trunc(v);
                break;
            case 'R':
                if (v < 0)
                    return {94,
                            strf(tr("square root of a negative number (%s)"), fixed3(v).c_str())};
                v = std::sqrt(v);
                break;
        }
        // Keep values near exact where trigonometry leaves noise (sin 30 = 0.5).
        if (std::fabs(v) < 1e-15) v = 0;
    }
    return {};
}

int32_t as_int32(double v) {
    if (v > 2147483647.0) return INT32_MAX;
    if (v < -2147483648.0) return INT32_MIN;
    return int32_t(std::trunc(v));
}
}  // namespace

Error eval_expr(const Block& b, Expr x, const LVars& l, EAccess& e, double& out) {
    double acc = 0;
    for (uint16_t i = 0; i < x.count; ++i) {
        const Term& t = b.terms[size_t(x.first + i)];
        double v;
        if (Error err = eval_operand(t.v, l, e, v)) return err;
        if (Error err = apply_prefix(t, v)) return err;
        switch (t.op) {
            case '=':
                acc = v;
                break;
            case '+':
                acc += v;
                break;
            case '-':
                acc -= v;
                break;
            case '*':
                acc *= v;
                break;
            case '/':
                if (v == 0) return {94, tr("division by zero")};
                acc /= v;
                break;
            case '&':
                acc = double(as_int32(acc) & as_int32(v));
                break;
            case '!':
                acc = double(as_int32(acc) | as_int32(v));
                break;
        }
    }
    if (!std::isfinite(acc)) return {94, tr("result is not a finite number")};
    out = acc;
    return {};
}

bool compare(Cmp c, double a, double b) {
    double ra = std::round(a * 1e6), rb = std::round(b * 1e6);
    switch (c) {
        case Cmp::eq:
            return ra == rb;
        case Cmp::ne:
            return ra != rb;
        case Cmp::lt:
            return ra < rb;
        case Cmp::le:
            return ra <= rb;
        case Cmp::gt:
            return ra > rb;
        case Cmp::ge:
            return ra >= rb;
        case Cmp::none:
            return true;
    }
    return false;
}

}  // namespace pupitre
