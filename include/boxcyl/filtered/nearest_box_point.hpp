// Newton's method for the box point nearest the cylinder: steps on the box coordinates μ (|μi| ≤ 1) of
// a point X = c + Σ μi·hi that lower g(μ) = dist(X, cylinder)², on the box feature where the point
// lies (coordinates at ±1 held there, released where g decreases into the box). It converges
// quadratically from a nearby start, where alternating projections between the solids converge only
// linearly (a box lying along the rim). No proof is needed: the point stays in the box by construction,
// and a poor point only loosens the bounds proved at it. In double (the quick bounds' search, the
// refined bounds' first steps) or in double-double values (the refined bounds' last steps).
#pragma once

#include <algorithm>  // std::max
#include <array>      // the box's half axes, μ
#include <cmath>      // std::abs, std::sqrt
#include <cstddef>    // std::size_t
#include <type_traits>  // std::is_same_v

#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/double_double_value.hpp"
#include "boxcyl/number/traits.hpp"  // abs_value

namespace boxcyl::filtered::separation::refined {

// Values without bounds (W), for the Newton steps: no proof is needed there.
using W = DoubleDoubleValue;
using WV = Vec3<DoubleDoubleValue>;

// The box and the cylinder in a number type N: double-double (the box exactly: sums and products of
// two doubles are exact in it) for the bounds and the last Newton steps, double for the first ones.
template <class N>
struct BoxOf {
    Vec3<N> center;
    std::array<Vec3<N>, 3> half;
};
template <class N>
struct CylOf {
    Vec3<N> C, u;
    N r, half_h;
};
// Values as values without bounds, and as doubles, for the steps in either number type.
inline const W& value(const W& x) { return x; }
inline const WV& value(const WV& v) { return v; }
inline double approx(const W& x) { return x.high() + x.low(); }
inline Vec3<double> approx(const WV& v) { return {approx(v[0]), approx(v[1]), approx(v[2])}; }
inline double value(double x) { return x; }
inline Vec3<double> value(const Vec3<double>& v) { return v; }
inline double approx(double x) { return x; }
inline const Vec3<double>& approx(const Vec3<double>& v) { return v; }
// The box point for μ (values of |μi| ≤ 1).
template <class N>
Vec3<N> point(const BoxOf<N>& box, const std::array<N, 3>& mu) {
    Vec3<N> X = box.center;
    for (std::size_t i = 0; i < 3; ++i) X = X + Vec3<N>{mu[i] * box.half[i][0], mu[i] * box.half[i][1], mu[i] * box.half[i][2]};
    return X;
}

// g(X) = dist(X, cylinder)², approximately (the search's measure of progress), from double-double
// values: ρ − r cancels where the distance is far below the coordinates (near touching), and in double
// it would be noise there.
inline double squared_distance(const CylOf<W>& k, const WV& X) {
    const WV Z = X - k.C;
    const W t = dot(Z, k.u);
    const WV Zxu = cross(Z, k.u);
    const W pp = dot(Zxu, Zxu);
    const W rho = approx(pp) > 0 ? sqrt(pp) : W(0.0);
    const double dr = std::max(0.0, approx(rho - k.r)), da = std::max(0.0, approx(abs_value(t) - k.half_h));
    return dr * dr + da * da;
}
// The same in double, for the first steps (noise where the distance is far below the coordinates: the
// double-double steps that follow take over there).
inline double squared_distance(const CylOf<double>& k, const Vec3<double>& X) {
    const Vec3<double> Z = X - k.C;
    const double t = dot(Z, k.u);
    const Vec3<double> Zxu = cross(Z, k.u);
    const double dr = std::max(0.0, std::sqrt(dot(Zxu, Zxu)) - k.r), da = std::max(0.0, std::abs(t) - k.half_h);
    return dr * dr + da * da;
}

// Newton steps on the free coordinates of μ (those strictly inside (−1, 1)) for g(μ) = dist(X(μ), cyl)²,
// on the values alone. g = (ρ − r)₊² + (|t| − h/2)₊² has, in X, the gradient 2(ρ − r)₊·∇ρ + 2(|t| − h/2)₊·sgn(t)·u
// and the Hessian 2[∇ρ∇ρᵀ + (ρ − r)₊·∇²ρ] (where ρ > r) + 2uuᵀ (where |t| > h/2), with ∇ρ = P/ρ (P the
// part of X − C across the axis) and ∇²ρ = (I − uuᵀ − ∇ρ∇ρᵀ)/ρ; the free coordinates see them through
// the half axes. A step that leaves [−1, 1] is clamped, and that coordinate fixed.
template <class N, class H = N>
void refine(const BoxOf<N>& box, const CylOf<N>& k, std::array<N, 3>& mu, std::array<bool, 3>& free, int steps) {
    using V = Vec3<N>;
    using std::sqrt;
    // μ's resolution in N (a step below it changes nothing), and a whole Newton step after which the
    // next, about its square, would be below it.
    constexpr bool in_double = std::is_same_v<N, double>;
    constexpr double resolution = in_double ? 0x1p-52 : 0x1p-104;
    constexpr double last_step = in_double ? 0x1p-26 : 0x1p-52;
    const V u = value(k.u);
    const N r = value(k.r), hh = value(k.half_h);
    std::array<bool, 3> movable{};  // a zero half axis leaves the point where it is
    for (std::size_t i = 0; i < 3; ++i) {
        movable[i] = approx(dot(box.half[i], box.half[i])) > 0;
        free[i] = free[i] && movable[i];
    }
    for (int step = 0; step < steps; ++step) {
        const V X = value(point(box, mu));
        const V Z = X - value(k.C);
        const N t = value(dot(Z, u));
        const V P = value(Z - V{t * u[0], t * u[1], t * u[2]});
        const double rho_d = std::sqrt(approx(dot(P, P)));
        const N rho = rho_d > 0 ? value(sqrt(dot(P, P))) : N(0.0);
        const bool side = approx(rho - r) > 0 && rho_d > 0, cap = std::abs(approx(t)) > approx(hh);
        // Gradient and Hessian in X, seen through the half axes: each dot product once per step.
        const V grad_rho = side ? V{P[0] / rho, P[1] / rho, P[2] / rho} : V{N(0.0), N(0.0), N(0.0)};
        const N over_r = side ? rho - r : N(0.0);
        const N over_h = cap ? abs_value(t) - hh : N(0.0);
        const N sgn = approx(t) < 0 ? N(-1.0) : N(1.0);
        std::array<N, 3> gr{}, uu{}, grad{};  // ∇ρ·Aᵢ, u·Aᵢ, ∂g/∂μᵢ
        for (std::size_t i = 0; i < 3; ++i) {
            if (!movable[i]) continue;
            gr[i] = side ? value(dot(grad_rho, box.half[i])) : N(0.0);
            uu[i] = value(dot(u, box.half[i]));
            grad[i] = value(N(2.0) * (over_r * gr[i] + over_h * sgn * uu[i]));
        }
        // The Hessian and the step's linear algebra in H: N, or double for N = double-double. From a
        // point within about an ulp of double of the minimum, a step with the gradient in N and the
        // Hessian to double's precision lands within about its square; only where the distance's
        // valley is nearly flat (a face within 2^-40 or so of parallel to the axis) does the Hessian
        // itself need double-double.
        auto in_h = [](const auto& x) {
            if constexpr (std::is_same_v<H, double>) return approx(x);
            else return value(x);
        };
        const H rho_h = in_h(rho), over_r_h = in_h(over_r);
        auto hessian = [&](std::size_t i, std::size_t j) {
            H h(0.0);
            const H gi = in_h(gr[i]), gj = in_h(gr[j]), ui = in_h(uu[i]), uj = in_h(uu[j]);
            if (side) h = gi * gj + over_r_h * (dot(in_h(box.half[i]), in_h(box.half[j])) - ui * uj - gi * gj) / rho_h;
            if (cap) h = h + ui * uj;
            return in_h(H(2.0) * h);
        };
        // A coordinate held at ±1 is released where g decreases into the box (the feature guessed
        // from the double search may be one too low: an edge where the nearest point is on a face).
        for (std::size_t i = 0; i < 3; ++i) {
            if (free[i] || !movable[i]) continue;
            const double gi = approx(grad[i]);
            if ((approx(mu[i]) >= 1 && gi > 0) || (approx(mu[i]) <= -1 && gi < 0)) free[i] = true;
        }
        std::array<std::size_t, 2> idx{};
        int nfree = 0;
        for (std::size_t i = 0; i < 3; ++i)
            if (free[i] && nfree < 2) idx[static_cast<std::size_t>(nfree++)] = i;
        if (nfree == 0) return;
        // The candidate steps, tried in turn until one lowers g:
        //  1. Newton's step for d = √g (where g > 0): d is smooth there and its minimum simple, while
        //     g = d² has a nearly double one where the distance is far below the shapes (a near-touching
        //     edge along the side: Newton on g would only halve d per step). ∇²d ∝ ∇²g − ∇g∇gᵀ/(2g), so
        //     the step is −(∇²g − ∇g∇gᵀ/(2g))⁻¹∇g.
        //  2. Newton's step for g (d is linear in the cap's region and along the axis: its form is
        //     singular there).
        //  3. The minimum of g along its gradient: where a face lies parallel, or nearly, to the cap or
        //     the side (every point of the contact region is nearest, and Newton's model has its minimum
        //     far away or points out of the box).
        const std::size_t i0 = idx[0], i1 = idx[nfree == 2 ? 1 : 0];
        const H g_value = in_h(over_r * over_r + over_h * over_h);
        const H g0 = in_h(grad[i0]), g1 = nfree == 2 ? in_h(grad[i1]) : H(0.0);
        const H hg00 = hessian(i0, i0), hg01 = nfree == 2 ? hessian(i0, i1) : H(0.0), hg11 = nfree == 2 ? hessian(i1, i1) : H(0.0);
        auto newton = [&](bool of_d, std::array<H, 2>& delta) {
            if (of_d && !(approx(g_value) > 0)) return false;
            const H two_g = H(2.0) * g_value;
            const H h00 = of_d ? in_h(hg00 - g0 * g0 / two_g) : hg00;
            if (nfree == 1) {
                if (!(approx(h00) > 0)) return false;
                delta = {in_h(-g0 / h00), H(0.0)};
                return approx(delta[0]) == approx(delta[0]);
            }
            const H h01 = of_d ? in_h(hg01 - g0 * g1 / two_g) : hg01, h11 = of_d ? in_h(hg11 - g1 * g1 / two_g) : hg11;
            const H det = h00 * h11 - h01 * h01;
            if (!(approx(det) > 0 && approx(h00) > 0)) return false;
            delta = {in_h((h01 * g1 - h11 * g0) / det), in_h((h01 * g0 - h00 * g1) / det)};
            return approx(delta[0]) == approx(delta[0]) && approx(delta[1]) == approx(delta[1]);  // NaN: a quotient undecided
        };
        auto gradient_line = [&](std::array<H, 2>& delta) {
            const H gHg = g0 * g0 * hg00 + H(2.0) * g0 * g1 * hg01 + g1 * g1 * hg11;
            if (!(approx(gHg) > 0)) return false;
            const H step = in_h(-(g0 * g0 + g1 * g1) / gHg);
            delta = {in_h(step * g0), in_h(step * g1)};
            return approx(delta[0]) == approx(delta[0]) && approx(delta[1]) == approx(delta[1]);
        };
        const double g_now = squared_distance(k, X);
        bool taken = false, last = false;
        for (int candidate = 0; candidate < 3 && !taken; ++candidate) {
            std::array<H, 2> delta{H(0.0), H(0.0)};
            if (!(candidate < 2 ? newton(candidate == 0, delta) : gradient_line(delta))) continue;
            // A step leaving the box is cut back to the first bound it crosses (clamping each coordinate
            // alone would leave the step's direction, and no halving of a far step would come back).
            // The coordinate that meets its bound is put on it exactly and fixed there, so that the
            // next step moves the others (a thin box's short axis would otherwise cut every step to
            // nothing).
            double alpha = 1;
            int hit = -1;
            for (int j = 0; j < nfree; ++j) {
                const double m = approx(mu[idx[static_cast<std::size_t>(j)]]), d = approx(delta[static_cast<std::size_t>(j)]);
                const double a = m + d > 1 ? (1 - m) / d : m + d < -1 ? (-1 - m) / d : 1.0;
                if (a < alpha) alpha = a, hit = j;
            }
            if (alpha < 1)
                for (H& d : delta) d = in_h(d * H(alpha));
            // Converged: a whole step below double-double's resolution of μ changes nothing.
            const bool tiny = std::abs(approx(delta[0])) <= resolution && std::abs(approx(delta[1])) <= resolution;
            if (tiny && hit < 0) return;
            if (tiny && approx(mu[idx[static_cast<std::size_t>(hit)]]) == (approx(delta[static_cast<std::size_t>(hit)]) > 0 ? 1.0 : -1.0))
                continue;  // already on that bound: the next candidate may move along it
            // A step that raises g is not taken (the model can overshoot far from the minimum or across
            // a region's edge) but halved, a few times. g's rounding cannot see the last steps' gains:
            // only a clear rise rejects a step.
            for (int halving = 0; halving < 4 && !taken; ++halving) {
                std::array<N, 3> next = mu;
                std::array<bool, 3> next_free = free;
                for (int j = 0; j < nfree; ++j) {
                    const std::size_t i = idx[static_cast<std::size_t>(j)];
                    N v = value(mu[i] + N(delta[static_cast<std::size_t>(j)]));
                    if (approx(v) != approx(v)) return;  // NaN (an underflowed quotient): keep the last point
                    if (j == hit && halving == 0) v = N(approx(delta[static_cast<std::size_t>(j)]) > 0 ? 1.0 : -1.0);
                    if (approx(v) >= 1) v = N(1.0), next_free[i] = false;
                    else if (approx(v) <= -1) v = N(-1.0), next_free[i] = false;
                    next[i] = v;
                }
                if (squared_distance(k, value(point(box, next))) <= g_now * (1 + 0x1p-40)) {
                    mu = next;
                    free = next_free;
                    taken = true;
                    // A whole Newton step this small: the next would move μ by about its square, below
                    // double-double's resolution (quadratic convergence).
                    last = candidate < 2 && alpha == 1 && halving == 0 &&
                           std::max(std::abs(approx(delta[0])), std::abs(approx(delta[1]))) <= last_step;
                } else {
                    for (H& d : delta) d = in_h(d * H(0.5));
                }
            }
        }
        if (!taken || last) return;
    }
}

// The steps' start from a search's coordinates: those within 2^-30 of ±1 held there (the point is on
// that face), the others free. False for a NaN coordinate.
inline bool held_start(const Vec3<double>& from, std::array<double, 3>& mu, std::array<bool, 3>& free) {
    for (std::size_t i = 0; i < 3; ++i) {
        const double m = from[i];
        if (!(std::abs(m) <= 1)) return false;
        free[i] = std::abs(m) < 1 - 0x1p-30;
        mu[i] = free[i] ? m : (m < 0 ? -1.0 : 1.0);
    }
    return true;
}

}  // namespace boxcyl::filtered::separation::refined
