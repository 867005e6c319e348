// An independent numeric reference: the distance between the box and the cylinder, minimised by
// accelerated projected gradient (FISTA) in long double. f(ξ) = ½·dist²(K + Aξ, cylinder) is convex with
// 1-Lipschitz gradient X − proj(X) (A orthonormal up to rounding), the box constraint is a clamp, and
// the projection onto a finite cylinder is exact in local coordinates (clamp the axial part to ±h/2,
// shrink the radial part to ≤ r). Used only to cross-check the oracle away from touching.
#pragma once

#include <algorithm>  // std::clamp, std::max
#include <cmath>      // std::sqrt

#include "support/cases.hpp"

namespace boxcyl::testing {

using LD = long double;

struct NumericBox {
    LD k[3];
    LD a[3][3];  // a[i] = axis i
    LD e[3];
};

inline NumericBox numeric_box(const Case& c) {
    NumericBox b{};
    switch (c.kind) {
        case BoxKind::aligned:
            for (int i = 0; i < 3; ++i) {
                b.k[i] = (LD(c.aligned.min[i]) + LD(c.aligned.max[i])) / 2;
                b.e[i] = (LD(c.aligned.max[i]) - LD(c.aligned.min[i])) / 2;
                for (int j = 0; j < 3; ++j) b.a[i][j] = (i == j);
            }
            break;
        case BoxKind::oriented:
            for (int i = 0; i < 3; ++i) {
                b.k[i] = c.oriented.center[i];
                b.e[i] = c.oriented.extents[i];
                for (int j = 0; j < 3; ++j) b.a[i][j] = c.oriented.axes[i][j];
            }
            break;
        case BoxKind::canonical:
            for (int i = 0; i < 3; ++i) {
                b.k[i] = 0;
                b.e[i] = c.canonical.extents[i];
                for (int j = 0; j < 3; ++j) b.a[i][j] = (i == j);
            }
            break;
    }
    return b;
}

// Distance from the box to the cylinder with radius r and height h (other fields from the case).
inline LD numeric_distance(const Case& c, LD r, LD h, int iterations = 4000) {
    const NumericBox b = numeric_box(c);
    LD u[3], C[3];
    LD n = 0;
    for (int i = 0; i < 3; ++i) n += LD(c.cylinder.axis[i]) * LD(c.cylinder.axis[i]);
    // Scale first: the axis may have subnormal components whose squares underflow.
    LD m = 0;
    for (int i = 0; i < 3; ++i) m = std::max(m, std::fabs(LD(c.cylinder.axis[i])));
    n = 0;
    for (int i = 0; i < 3; ++i) n += (LD(c.cylinder.axis[i]) / m) * (LD(c.cylinder.axis[i]) / m);
    n = std::sqrt(n);
    for (int i = 0; i < 3; ++i) u[i] = LD(c.cylinder.axis[i]) / m / n, C[i] = c.cylinder.center[i];

    auto point = [&](const LD xi[3], LD X[3]) {
        for (int j = 0; j < 3; ++j) X[j] = b.k[j] + xi[0] * b.a[0][j] + xi[1] * b.a[1][j] + xi[2] * b.a[2][j];
    };
    auto grad = [&](const LD xi[3], LD g[3], LD& dist2) {
        LD X[3], Y[3], P[3];
        point(xi, X);
        for (int j = 0; j < 3; ++j) Y[j] = X[j] - C[j];
        const LD t = Y[0] * u[0] + Y[1] * u[1] + Y[2] * u[2];
        LD rad[3], rl = 0;
        for (int j = 0; j < 3; ++j) rad[j] = Y[j] - t * u[j], rl += rad[j] * rad[j];
        rl = std::sqrt(rl);
        const LD tc = std::clamp(t, -h / 2, h / 2);
        const LD s = rl > r ? r / rl : LD(1);
        dist2 = 0;
        for (int j = 0; j < 3; ++j) {
            P[j] = C[j] + tc * u[j] + s * rad[j];
            const LD d = X[j] - P[j];
            dist2 += d * d;
            P[j] = d;  // gradient in world coordinates
        }
        for (int i = 0; i < 3; ++i) g[i] = b.a[i][0] * P[0] + b.a[i][1] * P[1] + b.a[i][2] * P[2];
    };
    LD xi[3] = {0, 0, 0}, yk[3] = {0, 0, 0}, best = -1;
    // Start at the box point nearest the cylinder centre.
    for (int i = 0; i < 3; ++i) {
        LD proj = 0;
        for (int j = 0; j < 3; ++j) proj += (C[j] - b.k[j]) * b.a[i][j];
        xi[i] = yk[i] = std::clamp(proj, -b.e[i], b.e[i]);
    }
    LD tk = 1;
    for (int it = 0; it < iterations; ++it) {
        LD g[3], d2;
        grad(yk, g, d2);
        if (best < 0 || d2 < best) best = d2;
        LD nx[3];
        for (int i = 0; i < 3; ++i) nx[i] = std::clamp(yk[i] - g[i], -b.e[i], b.e[i]);
        const LD tn = (1 + std::sqrt(1 + 4 * tk * tk)) / 2;
        for (int i = 0; i < 3; ++i) {
            yk[i] = nx[i] + (tk - 1) / tn * (nx[i] - xi[i]);
            yk[i] = std::clamp(yk[i], -b.e[i], b.e[i]);
            xi[i] = nx[i];
        }
        tk = tn;
    }
    LD g[3], d2;
    grad(xi, g, d2);
    if (d2 < best) best = d2;
    return std::sqrt(best);
}

// The size of the problem: the largest magnitude among all inputs (for relative tolerances).
inline double problem_scale(const Case& c) {
    double s = std::max(std::abs(c.cylinder.radius), std::abs(c.cylinder.height));
    for (int i = 0; i < 3; ++i) s = std::max(s, std::abs(c.cylinder.center[i]));
    for (int i = 0; i < 3; ++i) switch (c.kind) {
            case BoxKind::aligned: s = std::max({s, std::abs(c.aligned.min[i]), std::abs(c.aligned.max[i])}); break;
            case BoxKind::oriented: s = std::max({s, std::abs(c.oriented.center[i]), c.oriented.extents[i]}); break;
            case BoxKind::canonical: s = std::max(s, c.canonical.extents[i]); break;
        }
    return s;
}

}  // namespace boxcyl::testing
