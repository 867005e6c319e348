// Compile-time forward error analysis for the semi-static filter (filtered/semi_static.hpp).
//
// A StaticBound stands for a quantity computed in plain double from inputs of known magnitude and
// error, in units of a per-query length scale L:
//
//     |x| ≤ mag·L^k                          (the exact value)
//     |x̃ − x| ≤ (eps·ε + g·γ_in)·L^k         (x̃ the double computed, x the exact value it stands for)
//
// k is the quantity's degree in lengths (the caller keeps track of it); ε = 2^-52 bounds one rounding
// relative to the result in every IEEE rounding mode (one ulp, not half); γ_in ≥ 0 is the caller's
// second error unit, for input errors that are not roundings (an oriented box's distance g from
// orthonormal; 0 otherwise). Both units are assumed ≤ θ = 2^-9. The same template expression that a
// filter evaluates in double, evaluated on StaticBounds in a constant expression, yields the two
// coefficients of its error bound, so no bound is derived by hand (docs/robustness/stage0.md).
//
// Per operation (a, b the operands; P = a bound of the computed result |x̃|/L^k, charged to ε as the
// rounding ε·|x̃|; second-order terms err_a·err_b ≤ θ·(the larger unit) charged to that unit):
//     a ± b:  mag = a.mag + b.mag;  eps = a.eps + b.eps + P;  g = a.g + b.g
//     a · b:  mag = a.mag·b.mag;    eps = a.mag·b.eps + b.mag·a.eps + a.eps·b.eps·θ + P;
//             g = a.mag·b.g + b.mag·a.g + (a.g·b.g + a.eps·b.g + a.g·b.eps)·θ
//     −a, |a|: exact, unchanged.
// with P = computed(a) ± computed(b) or computed(a)·computed(b), computed(x) = mag + (eps + g)·θ.
// A fused multiply-add (contraction) rounds once where this counts two roundings, so the bounds hold
// with or without FMA contraction.
// Not counted here, and covered by the callers' final slack: roundings in the subnormal range (at most
// 2^-1074 each, negligible when L ∈ [2^-200, 2^200]: see semi_static.hpp), and the rounding of this
// constant evaluation itself (relative 2^-53 per step; the callers inflate the result by 1%).
#pragma once

namespace boxcyl {

struct StaticBound {
    static constexpr double theta = 0x1p-9;  // both error units are ≤ θ: bounds the second-order terms

    double mag = 0;  // |exact value| ≤ mag·L^k
    double eps = 0;  // error coefficient of ε (roundings)
    double g = 0;    // error coefficient of the second unit (input errors that are not roundings)

    constexpr StaticBound() = default;
    constexpr StaticBound(double m, double e, double gi = 0) : mag(m), eps(e), g(gi) {}

    // The computed value's bound: |x̃| ≤ (mag + (eps + g)·θ)·L^k.
    [[nodiscard]] constexpr double computed() const { return mag + (eps + g) * theta; }

    friend constexpr StaticBound operator+(const StaticBound& a, const StaticBound& b) {
        return {a.mag + b.mag, a.eps + b.eps + (a.computed() + b.computed()), a.g + b.g};
    }
    friend constexpr StaticBound operator-(const StaticBound& a, const StaticBound& b) { return a + b; }
    friend constexpr StaticBound operator-(const StaticBound& a) { return a; }
    friend constexpr StaticBound operator*(const StaticBound& a, const StaticBound& b) {
        const double eps = a.mag * b.eps + b.mag * a.eps + a.eps * b.eps * theta + a.computed() * b.computed();
        const double g = a.mag * b.g + b.mag * a.g + (a.g * b.g + a.eps * b.g + a.g * b.eps) * theta;
        return {a.mag * b.mag, eps, g};
    }
    // |x|: exact, no rounding.
    friend constexpr StaticBound enclosure_abs(const StaticBound& a) { return a; }
};

}  // namespace boxcyl
