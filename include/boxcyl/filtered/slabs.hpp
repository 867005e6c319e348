// Slab tests on the query as given (row `slabs`, before any other): a few separating directions tested
// in plain double before anything about the query is prepared, so that the pairs they part — most
// misses of random data, of shapes far from the origin and of sizes of very different magnitudes — cost
// a few nanoseconds instead of stage 0's preparation (an exact move near the origin, the unit axis, the
// frame). A box that holds the cylinder's centre is a hit (for an aligned or canonical box by exact
// comparisons).
//
// Directions: the coordinate axes (the solids' bounding slabs), an oriented box's face normals, and the
// cylinder's axis. Along a direction n the solids are apart when |n·(C − P)| exceeds the sum of their
// half-widths: the box's Σ e_k·|n·A_k| (P its centre, A_k its axes, e_k its extents) and the
// cylinder's r·|n × â| + (h/2)·|n·â| (â = a/|a|). The axis is scaled by the power of two 2^-k that
// brings its largest component's magnitude m into [1, 2): q = a·2^-k (exact, but for components below
// 2^-499, set to 0), |q| ≥ m, so |n·â| ≤ |n·q|/m up to 2^-498: the cylinder's half-width times m is at
// most m·r·|n| + (h/2)·|n·q|, with no division and no square root; along q itself it is (h/2)·|q| up to
// r·2^-498.
//
// Each test is decided only when the computed gap exceeds the computed widths by a margin T: 2^-40 of a
// bound on the magnitudes of all the terms involved, plus 2^-1000·(1 + h + Σe) — far beyond the
// rounding of the dozen operations behind each value (relative 2^-46 at most, in every rounding mode)
// and the underflow of the products (2^-1074 each, multiplied at most by one length). NaN or an
// overflow fails the comparisons, so every input is safe to ask; an axis whose largest component is
// subnormal or at least 2^1023 is not asked. docs/robustness/slabs.md gives the argument.
//
// An oriented box's face normals use its contract (geometry/validate.hpp): |A_i·A_j − δij| ≤ 10⁻⁴, so
// its half-width along A_k is at most e_k·(1 + g) + g·(e_i + e_j) with g = 2·10⁻⁴, and |A_k| ≤ 1 + 10⁻⁴
// (twice the tolerance: the contract is checked in long double). A parallelepiped has no such contract
// and gets the coordinate axes and the cylinder's axis only.
#pragma once

#include <algorithm>  // std::max
#include <array>      // the axes
#include <bit>        // std::bit_cast: the axis's power of two
#include <cmath>      // std::fabs
#include <cstdint>    // std::uint64_t
#include <optional>   // undecided

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"  // orthonormality_tolerance
#include "boxcyl/geometry/vec3.hpp"      // dot
#include "boxcyl/number/traits.hpp"       // BOXCYL_FORCE_INLINE

namespace boxcyl::filtered::slabs {

namespace detail {

inline double norm1(const Vec3<double>& v) { return std::fabs(v[0]) + std::fabs(v[1]) + std::fabs(v[2]); }

// The axis times the power of two 2^-k that brings its largest component's magnitude m into [1, 2),
// built on the bits (no product with a subnormal, which takes a slow path on some processors), with
// the components that would fall below 2^-499 set to 0: a direction within √3·2^-499 of a·2^-k, which
// the margin covers (docs/robustness/slabs.md). false for an axis whose largest component is subnormal,
// infinite or NaN.
inline bool scaled_axis(const Vec3<double>& a, Vec3<double>& q, double& m) {
    std::uint64_t bits[3], exponent[3];
    for (int j = 0; j < 3; ++j)
        bits[j] = std::bit_cast<std::uint64_t>(a[j]), exponent[j] = (bits[j] >> 52) & 0x7ff;
    const std::uint64_t top = std::max(std::max(exponent[0], exponent[1]), exponent[2]);
    const std::uint64_t k = (top - 1023) << 52;  // modulo 2^64: subtracting it lowers the exponent by top − 1023
    for (int j = 0; j < 3; ++j) q[j] = exponent[j] + 500 < top ? 0.0 : std::bit_cast<double>(bits[j] - k);
    m = std::max(std::max(std::fabs(q[0]), std::fabs(q[1])), std::fabs(q[2]));
    return top - 1 < 2046;  // top in [1, 2046]
}

// Along the axis q: |q·d| beyond the box's half-width `box`, the cylinder's (h/2)·|q| and the margin
// T, compared squared: x = |q·d| − box − T > 0 and x² > (h/2)²·|q|²·(1 + 2^-40) + 2^-1000 (x below 2^500,
// so that x² is finite; |q|² ≥ 1 never underflows).
inline bool apart_along_axis(const Vec3<double>& q, const Vec3<double>& d, double box, double h, double T) {
    const double x = std::fabs(dot(q, d)) - box - T;
    const double half = 0.5 * h;
    return x > 0 && x < 0x1p500 && x * x > (half * half) * dot(q, q) * (1 + 0x1p-40) + 0x1p-1000;
}

// The coordinate axes, the cylinder's axis and (an oriented box: `faces`) the face normals, for a box
// given by its centre, axes and extents. One margin T serves every test: 2^-40 of a bound on the
// magnitudes of all their terms (|q_j| < 2; an oriented box's |A_kj| ≤ 1 + 10⁻⁴; Σ_k e_k·|A_k|₁ = Σ_i B_i,
// B_i the box's half-width along coordinate axis i) plus the underflow term.
template <bool faces>
BOXCYL_FORCE_INLINE inline std::optional<bool> decide_framed(const Vec3<double>& p, const std::array<Vec3<double>, 3>& A,
                                                             const Vec3<double>& e, const Cylinder<double>& c) {
    Vec3<double> q;
    double m;
    if (!scaled_axis(c.axis, q, m)) return std::nullopt;
    const Vec3<double> d{c.center[0] - p[0], c.center[1] - p[1], c.center[2] - p[2]};
    const double r = c.radius, h = c.height, se = e[0] + e[1] + e[2];
    const auto width = [&](int i) { return e[0] * std::fabs(A[0][i]) + e[1] * std::fabs(A[1][i]) + e[2] * std::fabs(A[2][i]); };
    const Vec3<double> B{width(0), width(1), width(2)};
    const double T = 0x1p-40 * (4 * norm1(d) + 8 * (h + r + se) + 4 * (B[0] + B[1] + B[2])) + 0x1p-1000 * (1 + h + se);
    // Coordinate axis i, times m: the box's half-width m·B_i, the cylinder's m·r + (h/2)·|q_i|; the
    // margin 2T (m < 2). (The tests written out, here and below: as loops GCC kept them serial.)
    const auto world = [&](int i) {
        return static_cast<int>(m * std::fabs(d[i]) > m * (B[i] + r) + 0.5 * (h * std::fabs(q[i])) + 2 * T);
    };
    if (world(0) | world(1) | world(2)) return false;
    const Vec3<double> qa{dot(q, A[0]), dot(q, A[1]), dot(q, A[2])};
    if constexpr (faces) {
        // Face normal A_k, times m: the box's half-width Σ_j e_j·|A_k·A_j| ≤ e_k·(1 + g) + g·(e_i + e_j)
        // times m, the cylinder's m·r·|A_k| + (h/2)·|A_k·q|.
        constexpr double g = 2 * orthonormality_tolerance;
        const auto face = [&](int k, int i, int j) {
            const double box = e[k] * (1 + g) + g * (e[i] + e[j]);
            return static_cast<int>(m * std::fabs(dot(A[k], d)) >
                                    m * (box + (1 + orthonormality_tolerance) * r) + 0.5 * (h * std::fabs(qa[k])) + 2 * T);
        };
        if (face(0, 1, 2) | face(1, 2, 0) | face(2, 0, 1)) return false;
        // The cylinder's centre inside the box is a hit. Its coordinates s (C − P = Σ s_k·A_k) satisfy
        // |s_k| ≤ (|A_k·d| + 1.5·g·|d|₁)/(1 − g): Gershgorin bounds the Gram matrix's smallest eigenvalue
        // by 1 − 3g, so |s| ≤ 1.0003·|d|, and the off-diagonal entries are at most g.
        const double slack = 2 * g * norm1(d) + T;
        const auto inside = [&](int k) { return static_cast<int>(std::fabs(dot(A[k], d)) + slack <= e[k] * (1 - g)); };
        if (inside(0) & inside(1) & inside(2)) return true;
    }
    // The cylinder's axis q: the box's half-width Σ e_k·|q·A_k|.
    const double box = e[0] * std::fabs(qa[0]) + e[1] * std::fabs(qa[1]) + e[2] * std::fabs(qa[2]);
    if (apart_along_axis(q, d, box, h, T)) return false;
    return std::nullopt;
}

}  // namespace detail

// An aligned box: the cylinder's centre inside it is a hit; then the bounding slabs, whose gaps are one
// subtraction each (min_i − C_i or C_i − max_i: rounded within u of themselves), and the cylinder's
// axis, for which the box's centre and half-extents are rounded (within u of |P_j| and e_j: the
// magnitude counts Σ(|C_j| + |P_j|)).
inline std::optional<bool> decide(const AlignedBox<double>& b, const Cylinder<double>& c) {
    using namespace detail;
    const Vec3<double>& C = c.center;
    const auto within = [&](int i) { return static_cast<int>(b.min[i] <= C[i]) & static_cast<int>(C[i] <= b.max[i]); };
    if (within(0) & within(1) & within(2)) return true;
    Vec3<double> q;
    double m;
    if (!scaled_axis(c.axis, q, m)) return std::nullopt;
    const double r = c.radius, h = c.height;
    const Vec3<double> gap{std::max(b.min[0] - C[0], C[0] - b.max[0]), std::max(b.min[1] - C[1], C[1] - b.max[1]),
                           std::max(b.min[2] - C[2], C[2] - b.max[2])};
    const double T_slab = 0x1p-40 * (norm1(gap) + 4 * (h + r)) + 0x1p-1000 * (1 + h);
    const auto slab = [&](int i) {
        return static_cast<int>(m * gap[i] > m * r + 0.5 * (h * std::fabs(q[i])) + 2 * T_slab);
    };
    if (slab(0) | slab(1) | slab(2)) return false;
    const Vec3<double> p{0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1]), 0.5 * (b.min[2] + b.max[2])};
    const Vec3<double> d{C[0] - p[0], C[1] - p[1], C[2] - p[2]};
    const Vec3<double> e{0.5 * (b.max[0] - b.min[0]), 0.5 * (b.max[1] - b.min[1]), 0.5 * (b.max[2] - b.min[2])};
    const Vec3<double> abs_q{std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2])};
    const double box = dot(e, abs_q), se = e[0] + e[1] + e[2];
    const double T = 0x1p-40 * (4 * (norm1(C) + norm1(p)) + 8 * (h + r + se)) + 0x1p-1000 * (1 + h + se);
    if (apart_along_axis(q, d, box, h, T)) return false;
    return std::nullopt;
}

// A canonical box (the cylinder in its frame): the aligned box [−e, e].
inline std::optional<bool> decide(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    return decide(AlignedBox<double>{{-b.extents[0], -b.extents[1], -b.extents[2]}, b.extents}, c);
}

inline std::optional<bool> decide(const OrientedBox<double>& b, const Cylinder<double>& c) {
    return detail::decide_framed<true>(b.center, b.axes, b.extents, c);
}

inline std::optional<bool> decide(const Parallelepiped<double>& b, const Cylinder<double>& c) {
    return detail::decide_framed<false>(b.center, b.axes, b.extents, c);
}

}  // namespace boxcyl::filtered::slabs
