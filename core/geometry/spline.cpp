// Cubic splines by chord length: second derivatives from a tridiagonal system,
// clamped to the given tangents or natural at free ends.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/spline.hpp"

#include <algorithm>
#include <cmath>

#include "core/i18n.hpp"

namespace pupitre::spline {

namespace {
double norm(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

// Second derivatives of the spline through (s[i], y[i]); d0/d1 are the end slopes,
// NaN for a natural end.
std::vector<double> second_derivatives(const std::vector<double>& s, const std::vector<double>& y,
                                       double d0, double d1) {
    size_t n = s.size();
    std::vector<double> a(n, 0), b(n, 0), c(n, 0), r(n, 0);
    for (size_t i = 1; i + 1 < n; ++i) {
        double h0 = s[i] - s[i - 1], h1 = s[i + 1] - s[i];
        a[i] = h0 / 6;
        b[i] = (h0 + h1) / 3;
        c[i] = h1 / 6;
        r[i] = (y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0;
    }
    double h = s[1] - s[0];
    if (std::isnan(d0)) {
        b[0] = 1;
    } else {
        b[0] = h / 3;
        c[0] = h / 6;
        r[0] = (y[1] - y[0]) / h - d0;
    }
    h = s[n - 1] - s[n - 2];
    if (std::isnan(d1)) {
        b[n - 1] = 1;
    } else {
        a[n - 1] = h / 6;
        b[n - 1] = h / 3;
        r[n - 1] = d1 - (y[n - 1] - y[n - 2]) / h;
    }
    // Thomas algorithm.
    for (size_t i = 1; i < n; ++i) {
        double w = a[i] / b[i - 1];
        b[i] -= w * c[i - 1];
        r[i] -= w * r[i - 1];
    }
    std::vector<double> m(n);
    m[n - 1] = r[n - 1] / b[n - 1];
    for (size_t i = n - 1; i-- > 0;) m[i] = (r[i] - c[i] * m[i + 1]) / b[i];
    return m;
}
}  // namespace

Error build(Curve& c) {
    if (c.pts.size() < 3)
        return {604, strf(tr("a spline needs at least 3 points (%zu given)"), c.pts.size())};
    if (c.pts.size() > 255) return {604, tr("a spline has at most 255 points")};
    c.s.assign(c.pts.size(), 0);
    for (size_t i = 1; i < c.pts.size(); ++i) {
        std::vector<double> d(c.axes.size());
        for (size_t k = 0; k < d.size(); ++k) d[k] = c.pts[i][k] - c.pts[i - 1][k];
        double l = norm(d);
        if (l < 1e-6)
            return {603, strf(tr("two consecutive spline points are the same (point %zu)"),
                              size_t(i + 1))};
        c.s[i] = c.s[i - 1] + l;
    }
    std::vector<double> u0, u1;
    for (auto [t, u] : {std::pair{&c.t0, &u0}, std::pair{&c.t1, &u1}}) {
        if (t->empty()) continue;
        double l = norm(*t);
        if (l < 1e-12) return {603, tr("a spline end tangent is a zero vector")};
        for (double x : *t) u->push_back(x / l);  // unit speed along the chord-length parameter
    }
    c.m.assign(c.axes.size(), {});
    for (size_t k = 0; k < c.axes.size(); ++k) {
        std::vector<double> y(c.pts.size());
        for (size_t i = 0; i < y.size(); ++i) y[i] = c.pts[i][k];
        c.m[k] = second_derivatives(c.s, y, u0.empty() ? NAN : u0[k], u1.empty() ? NAN : u1[k]);
    }
    return {};
}

std::vector<double> at(const Curve& c, double u) {
    size_t i = size_t(std::upper_bound(c.s.begin(), c.s.end(), u) - c.s.begin());
    i = std::clamp<size_t>(i, 1, c.s.size() - 1);
    double h = c.s[i] - c.s[i - 1];
    double a = (c.s[i] - u) / h, b = (u - c.s[i - 1]) / h;
    std::vector<double> p(c.axes.size());
    for (size_t k = 0; k < p.size(); ++k) {
        double y0 = c.pts[i - 1][k], y1 = c.pts[i][k], m0 = c.m[k][i - 1], m1 = c.m[k][i];
        p[k] = a * y0 + b * y1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6;
    }
    return p;
}

std::vector<std::vector<double>> sample(const Curve& c, double tol) {
    std::vector<std::vector<double>> out;
    for (size_t i = 1; i < c.s.size(); ++i) {
        double h = c.s[i] - c.s[i - 1];
        // The chord error of a cubic over a step d is about max|y''| d^2 / 8.
        double curv = 1e-9;
        for (size_t k = 0; k < c.axes.size(); ++k)
            curv = std::max({curv, std::fabs(c.m[k][i - 1]), std::fabs(c.m[k][i])});
        int n = int(std::ceil(h / std::sqrt(8 * tol / curv)));
        n = std::clamp(n, 1, 400);
        for (int j = 1; j <= n; ++j) {
            if (j == n)
                out.push_back(c.pts[i]);
            else
                out.push_back(at(c, c.s[i - 1] + h * j / n));
        }
    }
    return out;
}

}  // namespace pupitre::spline
