// The clearance query decided from the box's centre P and a ball about it, in plain double with an
// a-priori error allowance (a few dozen flops):
//
//   yes  dist(P, cylinder) ≤ m: P is a box point;
//   no   dist(P, cylinder) > m + R, R ≥ the distance from P to every box point.
//
// Near the rim tori, where the probes' stage 0 leaves a box (and the batch's filter leaves its lanes),
// one of these decides most boxes that are small beside their distance to the rim.
//
// The distance is √(max(ρ − r, 0)² + max(|t| − h/2, 0)²) with Z = P − C, t = Z·u and ρ = |Z × u| for
// the exact unit axis u = D/|D|. Each computed quantity is bounded by hand (docs/clearance.md, "The
// centre ball", gives the derivation), with u = 2^-52 per operation in every rounding mode and the
// magnitudes held below 2^300, so that no square overflows and every underflow loss (at most 2^-1074 an
// operation) lies far below the absolute allowance τ = 2^-500:
//   |t̂ − t| ≤ 2^-47·W,  |q̂ − ρ²| ≤ 2^-44·W²   (q̂ = |Ẑ × û|², W = |Ẑ|₁ + |P̂|∞ where P̂ was rounded),
// which the code takes with a factor of 2 and 4 to spare, adding τ. Every later step rounds outward by
// a factor that covers its own roundings, so each test below is sound in every rounding mode.
#pragma once

#include <algorithm>  // std::max
#include <cmath>      // std::sqrt, std::abs
#include <optional>   // undecided

#include "boxcyl/filtered/rim.hpp"  // scaled_axis
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl::filtered::centre_ball {

inline constexpr double kBig = 0x1p300;   // the magnitudes allowed (squares stay below 2^601)
inline constexpr double kTau = 0x1p-500;  // absolute allowance: underflow losses, far below it
inline constexpr double kUp = 1 + 0x1p-50, kDown = 1 - 0x1p-50;  // cover up to two roundings each

// The centre as computed (p), the magnitude whose rounding it carries (rounded_magnitude: |P̂|∞ when
// P̂ = fl((min + max)/2), else 0) and r2_hi ≥ R², R the box's circumradius about the exact centre.
struct Ball {
    Vec3<double> p;
    double rounded_magnitude = 0;
    double r2_hi = 0;
};

// (Σ x_i²)·(1 + 2^-48) + τ ≥ the exact sum for x_i within a relative u (+ underflow) of exact values.
inline double sum_of_squares_up(double a, double b, double c) { return (a * a + b * b + c * c) * (1 + 0x1p-48) + kTau; }

inline Ball ball(const AlignedBox<double>& b) {
    Ball out;
    double h[3];
    for (int i = 0; i < 3; ++i) {
        out.p[i] = 0.5 * (b.min[i] + b.max[i]);  // within u|P_i| + 2^-1074 of the exact centre
        h[i] = 0.5 * (b.max[i] - b.min[i]);      // likewise of the exact half extent
        out.rounded_magnitude = std::max(out.rounded_magnitude, std::abs(out.p[i]));
    }
    out.r2_hi = sum_of_squares_up(h[0], h[1], h[2]);
    return out;
}
inline Ball ball(const CanonicalBox<double>& b) {
    return {{0, 0, 0}, 0, sum_of_squares_up(b.extents[0], b.extents[1], b.extents[2])};
}
// An oriented box's axes are orthonormal within 1e-4 (validate.hpp: every Gram entry within 1e-4 of
// δij), so |Σ ±e_i·A_i|² = Σ_ij ±e_i·e_j·G_ij ≤ (1 + 3·10⁻⁴)·Σ e_i².
inline Ball ball(const OrientedBox<double>& b) {
    return {b.center, 0, sum_of_squares_up(b.extents[0], b.extents[1], b.extents[2]) * 1.0004};
}
// Any axes: R ≤ Σ e_i·|A_i| ≤ Σ e_i·|A_i|₁.
inline Ball ball(const Parallelepiped<double>& b) {
    double R = 0;
    for (int i = 0; i < 3; ++i) R += b.extents[i] * (std::abs(b.axes[i][0]) + std::abs(b.axes[i][1]) + std::abs(b.axes[i][2]));
    R = R * (1 + 0x1p-48) + kTau;
    return {b.center, 0, R * R * kUp};
}

// x > 0 scaled up, else 0: an upper bound of max(exact, 0) for x = fl(exact·(1 + θ)), |θ| ≤ u.
inline double positive_up(double x) { return x > 0 ? x * kUp : 0.0; }
// x > 0 scaled down, else 0: a lower bound of max(exact, 0) likewise.
inline double positive_down(double x) { return x > 0 ? x * kDown : 0.0; }

// Whether dist(box, cylinder) ≤ m, where the centre ball proves it either way (valid inputs, m ≥ 0).
inline std::optional<bool> decide(const Ball& b, const Cylinder<double>& c, double m) {
    const Vec3<double> D = rim::scaled_axis(c.axis);  // largest component ≥ 1: |D|² neither under- nor overflows
    const double h = c.height;
    if (!(std::max({std::abs(D[0]), std::abs(D[1]), std::abs(D[2])}) <= kBig) || !(h == 0 || h >= 0x1p-1000))
        return std::nullopt;
    const double len = std::sqrt(dot(D, D));
    const Vec3<double> u{D[0] / len, D[1] / len, D[2] / len};  // |û_i − u_i| ≤ 4u + 2^-1074
    const Vec3<double> Z = b.p - c.center;
    const double W = std::abs(Z[0]) + std::abs(Z[1]) + std::abs(Z[2]) + b.rounded_magnitude;
    const double H = 0.5 * h;  // exact: h is 0 or normal
    if (!(W <= kBig && c.radius <= kBig && H <= kBig && m <= kBig && b.r2_hi <= kBig * kBig)) return std::nullopt;  // NaN too
    const double t = std::abs(dot(Z, u));
    const Vec3<double> n = cross(Z, u);
    const double q = dot(n, n);
    const double e_t = 0x1p-46 * W + kTau, e_q = 0x1p-42 * (W * W) + kTau;
    // ρ ∈ [rho_lo, rho_hi], |t| ∈ [a_lo, a_hi].
    const double rho_hi = std::sqrt(q + e_q) * kUp;
    const double rho_lo = std::sqrt(positive_down(q - e_q)) * kDown;
    const double a_hi = (t + e_t) * kUp, a_lo = positive_down(t - e_t);
    // The distance's parts, bounded: max(ρ − r, 0) and max(|t| − h/2, 0).
    const double dr_hi = positive_up(rho_hi - c.radius), da_hi = positive_up(a_hi - H);
    const double dr_lo = positive_down(rho_lo - c.radius), da_lo = positive_down(a_lo - H);
    // yes: d² ≤ m², the left side rounded up, m² down (m ≥ 2^-400: m² is normal).
    if (m >= 0x1p-400 && (dr_hi * dr_hi + da_hi * da_hi + kTau) * (1 + 0x1p-49) <= m * m * kDown) return true;
    // no: d² > (m + R)², the left side rounded down, the right up.
    const double mr = (m + std::sqrt(b.r2_hi) * kUp) * kUp;
    if ((dr_lo * dr_lo + da_lo * da_lo) * (1 - 0x1p-49) - kTau > mr * mr * kUp + kTau) return false;
    return std::nullopt;
}

template <class AnyBox>
std::optional<bool> decide(const AnyBox& box, const Cylinder<double>& c, double m) {
    return decide(ball(box), c, m);
}

}  // namespace boxcyl::filtered::centre_ball
