// A double with a running error bound (Wilkinson's running error analysis), the fast stage of the
// certified filter: value v and bound e with |exact − v| ≤ e for the real number the
// computation stands for. Every operation is a handful of branch-free flops and inlines, several
// times cheaper than outward-rounded intervals (interval.hpp, the second stage), at the price of
// slightly wider bounds. docs/robustness/enclosures.md derives every bound below; in short:
//
//  * u = 2^-52 bounds the relative rounding error of one operation in every IEEE rounding mode (one
//    ulp, not half), so the bounds do not depend on the rounding mode. For a normal result r, the
//    computed u·|r| is ≥ ulp(r) even when it is subnormal (it rounds monotonically from a power of two).
//  * A product, quotient or square root whose result or error terms underflow loses at most 2^-1074
//    per rounded term; `tiny` = 2^-1071 covers the (at most four) such terms of one operation, provided
//    no term is divided or multiplied again after it was rounded within the same operation (the
//    quotient's bound is arranged so; a test caught the first version, which divided an underflowed
//    product). Sums need no such term: a sum that is subnormal is exact.
//  * The bounds themselves are computed in floating point from non-negative terms by sums, products
//    and quotients by a positive lower bound, so each rounding lowers them by a factor ≥ (1 − u) at
//    most. Comparisons inflate the final bound by M = 1 + 2^-30, which covers chains of up to 2^21
//    roundings — the linear-inequalities computation has a few hundred.
//  * An operand that is an exact zero (v = 0, e = 0) gives an exact zero product and quotient, and
//    exact operands that sum to 0 give an exact 0: the exact zeros of degenerate inputs (flat boxes,
//    axis-aligned directions, zero-length clipped edges) stay exactly zero and decidable.
//  * Overflow: in round to nearest it gives v = ±∞, but rounding toward zero, up or down can turn it
//    into ±DBL_MAX, a finite value that no bound relates to the exact one, and the bound itself can
//    stop at DBL_MAX the same way. So every result whose |v| + e reaches DBL_MAX gets e = ∞ (a
//    result that large is useless anyway): every comparison that involves it is undecided.
//  * FMA contraction can only remove roundings, and every bound holds for the contracted evaluation
//    too (docs/robustness/enclosures.md).
//
// Comparisons behave as Interval's: when the bounds cannot separate the operands the comparison is
// undecided, returns false and records it in the current UncertaintyScope (interval.hpp).
#pragma once

#include <algorithm>  // std::max, std::min
#include <cmath>      // std::sqrt, std::fabs
#include <limits>     // DBL_MAX, infinity

#include "boxcyl/number/interval.hpp"  // UncertaintyScope, the uncertainty flag, the fp checks
#include "boxcyl/number/traits.hpp"

// The operations are a few flops each; inlining them is what makes this stage cheap (GCC at -O2 would
// otherwise call many of them out of line): BOXCYL_FORCE_INLINE.

namespace boxcyl {

class Bounded {
public:
    static constexpr double u = 0x1p-52;       // relative rounding bound of one operation, any mode
    static constexpr double tiny = 0x1p-1071;  // underflow allowance of one product/quotient/sqrt
    static constexpr double margin = 1 + 0x1p-30;  // covers the rounding of the bounds themselves

    constexpr Bounded() = default;
    constexpr Bounded(double x) : v_(x) {}  // NOLINT(google-explicit-constructor): exact embedding
    constexpr Bounded(int x) : v_(x) {}     // NOLINT(google-explicit-constructor)
    constexpr Bounded(double value, double error) : v_(value), e_(error) {}

    // Every real in [lo, hi] (lo ≤ hi, finite) as a value with a bound that encloses it.
    static Bounded range(double lo, double hi) {
        if (lo == hi) return Bounded(lo);
        const double v = lo / 2 + hi / 2;
        return {v, detail::next_up(std::max(hi - v, v - lo))};
    }

    double value() const { return v_; }
    double error() const { return e_; }
    // Certain bounds of the exact value (one whole double outward: sound in every rounding mode).
    double lo() const { return e_ == 0 ? v_ : detail::next_down(v_ - e_ * margin); }
    double hi() const { return e_ == 0 ? v_ : detail::next_up(v_ + e_ * margin); }
    bool exact_zero() const { return v_ == 0 && e_ == 0; }

    BOXCYL_FORCE_INLINE inline friend Bounded operator+(const Bounded& a, const Bounded& b) {
        const double v = a.v_ + b.v_;
        return checked(v, a.e_ + b.e_ + u * std::fabs(v));
    }
    BOXCYL_FORCE_INLINE inline friend Bounded operator-(const Bounded& a, const Bounded& b) {
        const double v = a.v_ - b.v_;
        return checked(v, a.e_ + b.e_ + u * std::fabs(v));
    }
    BOXCYL_FORCE_INLINE inline friend Bounded operator-(const Bounded& a) { return {-a.v_, a.e_}; }
    // |AB − ab| ≤ |a|·e_b + |b|·e_a + e_a·e_b for |A − a| ≤ e_a, |B − b| ≤ e_b.
    BOXCYL_FORCE_INLINE inline friend Bounded operator*(const Bounded& a, const Bounded& b) {
        const double v = a.v_ * b.v_;
        const double e = std::fabs(a.v_) * b.e_ + std::fabs(b.v_) * a.e_ + a.e_ * b.e_ + u * std::fabs(v) + tiny;
        return checked(v, (a.exact_zero() || b.exact_zero()) ? 0.0 : e);
    }
    // |A/B − a/b| ≤ (e_a + |a/b|·e_b)/(|b| − e_b); the divisor is taken as |b| − 2e_b (a lower bound
    // of |b| − e_b whatever the rounding of e_b) and must be positive, else the result is undecided.
    BOXCYL_FORCE_INLINE inline friend Bounded operator/(const Bounded& a, const Bounded& b) {
        const double v = a.v_ / b.v_;
        const double den = std::fabs(b.v_) - 2 * b.e_;
        if (!(den > 0)) [[unlikely]]
            return undecided();
        // Written so that no rounded term is divided afterwards (an underflowed numerator term divided
        // by a tiny divisor would be amplified): e_a/den and |v|·(e_b/den), each rounded last. If
        // e_b/den underflows, |v| amplifies that loss to at most 2^-1074·|v|, which the second u·|v|
        // covers (the first covers the rounding of v itself).
        const double av = std::fabs(v);
        const double e = a.e_ / den + av * (b.e_ / den) + 2 * u * av + tiny;
        return checked(v, a.exact_zero() ? 0.0 : e);
    }
    Bounded& operator+=(const Bounded& b) { return *this = *this + b; }
    Bounded& operator-=(const Bounded& b) { return *this = *this - b; }
    Bounded& operator*=(const Bounded& b) { return *this = *this * b; }
    Bounded& operator/=(const Bounded& b) { return *this = *this / b; }

    // |√A − √a| = |A − a|/(√A + √a) ≤ e_a/√a.
    BOXCYL_FORCE_INLINE inline friend Bounded sqrt(const Bounded& a) {
        if (a.exact_zero()) return Bounded(0.0);
        if (!(a.v_ > 0)) [[unlikely]]
            return undecided();
        const double s = std::sqrt(a.v_);
        return checked(s, a.e_ / s + u * s + tiny);
    }

    // B − A lies in [d − b, d + b] for d = b.v − a.v rounded and b = (e_a + e_b + u|d|)·M.
    BOXCYL_FORCE_INLINE inline friend bool operator<(const Bounded& a, const Bounded& b) {
        const double d = b.v_ - a.v_;
        const double bound = (a.e_ + b.e_ + u * std::fabs(d)) * margin;
        if (d - bound > 0) return true;
        if (d + bound <= 0) return false;
        return uncertain();
    }
    BOXCYL_FORCE_INLINE inline friend bool operator<=(const Bounded& a, const Bounded& b) {
        const double d = b.v_ - a.v_;
        const double bound = (a.e_ + b.e_ + u * std::fabs(d)) * margin;
        if (d - bound >= 0) return true;
        if (d + bound < 0) return false;
        return uncertain();
    }
    BOXCYL_FORCE_INLINE inline friend bool operator>(const Bounded& a, const Bounded& b) { return b < a; }
    BOXCYL_FORCE_INLINE inline friend bool operator>=(const Bounded& a, const Bounded& b) { return b <= a; }
    friend bool operator==(const Bounded& a, const Bounded& b) { return a <= b && b <= a; }
    friend bool operator!=(const Bounded& a, const Bounded& b) { return !(a == b); }

    // |x| without deciding the sign of x: |·| is 1-Lipschitz, so the bound carries over.
    BOXCYL_FORCE_INLINE inline friend Bounded enclosure_abs(const Bounded& x) { return {std::fabs(x.v_), x.e_}; }
    // x clamped to [−e, e], also without a decision. Where x is certainly outside, the result is the
    // bound ±e itself; otherwise the clamp is 1-Lipschitz in x and in e, so max(e_x, e_e) bounds the
    // error, and an exact e bounds it by 2e as well (an exact 0 stays exact).
    BOXCYL_FORCE_INLINE inline friend Bounded enclosure_clamp(const Bounded& x, const Bounded& e) {
        if (certainly_less(e, x)) return e;
        const Bounded minus_e = -e;
        if (certainly_less(x, minus_e)) return minus_e;
        const double ev = std::max(e.v_, 0.0);
        const double v = std::min(std::max(x.v_, -ev), ev);
        const double err = std::max(x.e_, e.e_);
        return {v, e.e_ == 0 ? std::min(err, 2 * ev) : err};
    }

private:
    // A result that may have overflowed (see the header comment): |v| + e rounds to at least DBL_MAX
    // in every rounding mode when |v| or e is at DBL_MAX, and is ∞ or NaN when either is.
    BOXCYL_FORCE_INLINE inline static Bounded checked(double v, double e) {
        return {v, std::fabs(v) + e < std::numeric_limits<double>::max() ? e : std::numeric_limits<double>::infinity()};
    }
    BOXCYL_FORCE_INLINE inline static bool certainly_less(const Bounded& a, const Bounded& b) {  // a < b decided true; no flag
        const double d = b.v_ - a.v_;
        return d - (a.e_ + b.e_ + u * std::fabs(d)) * margin > 0;
    }
    static Bounded undecided() {
        detail::uncertain_flag = true;
        const double inf = std::numeric_limits<double>::infinity();
        return {std::numeric_limits<double>::quiet_NaN(), inf};
    }
    static bool uncertain() {  // overlap, NaN or ∞
        detail::uncertain_flag = true;
        return false;
    }

    double v_ = 0, e_ = 0;
};

Bounded sqrt(const Bounded& a);

template <>
struct number_traits<Bounded> {
    static constexpr bool is_exact = false;
    static constexpr bool has_sqrt = true;
    static Bounded sqrt(const Bounded& x) { return boxcyl::sqrt(x); }
};

}  // namespace boxcyl
