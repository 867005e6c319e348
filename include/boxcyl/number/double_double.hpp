// A double-double with a running error bound: the enclosure type of the exact default's middle stage
// (the double-double rows of filtered/schedule.hpp). A value is the unevaluated sum hi + lo of two doubles (|lo| ≤ ulp(hi)), about
// 106 significant bits, and a bound e with |exact − (hi + lo)| ≤ e for the real number the computation
// stands for. It has the interface of Bounded and Interval (the generic §4 code runs on it unchanged),
// at about 2^-100 relative error per operation instead of 2^-52: near-touching inputs whose gap is
// one ulp of the input (about 2^-52 relative) are decided far above the noise.
// docs/robustness/enclosures.md derives every bound; in short:
//
//  * Round-to-nearest only. The error-free transformations (TwoSum, Fast2Sum, TwoProd) and the
//    published error bounds of the double-word algorithms below assume it. The middle stage checks the
//    mode that the arithmetic actually uses (round_to_nearest(): a probe, not fegetround, which reads
//    the x87 control word on x86-64) and declines in any other mode: never a wrong answer, the exact
//    stage then answers.
//  * Addition is Joldes, Muller and Popescu's AccurateDWPlusDW (relative error ≤ 3u²/(1 − 4u)) and
//    multiplication their DWTimesDW with an FMA (≤ 5u²), u = 2^-53 ("Tight and rigorous error bounds for
//    basic building blocks of double-word arithmetic", ACM TOMS 44(2), 2017). Each result carries
//    rel·|hi| with rel = 2^-100 (≥ 10× those bounds, so |hi + lo| vs |hi| does not matter), plus the
//    propagated input errors. TwoProd uses a hardware FMA where the target has one (then the compiler
//    may contract, which the algorithms are written to survive: no plain product feeds a plain sum);
//    an x86-64 build for targets without one uses the processor's FMA where it has one, chosen at run
//    time (one instruction, in inline assembly: the compiler contracts nothing there), and Dekker's
//    exact product otherwise. Both give the same exact error term.
//  * Underflow: TwoSum and Fast2Sum stay exact (a subnormal sum is exact); a product or an FMA whose
//    result or error term underflows loses at most 2^-1075 per rounding: `tiny` = 2^-1066 covers the
//    (at most eight) roundings of one multiplication, and they are never divided afterwards.
//  * Division and square root are not given a priori bounds: their result q (s) is one Newton-like
//    correction of the double quotient (root), and the bound comes a posteriori from the residual
//    a − q·b (x − s·s) evaluated with the proved operations above:
//        |A/B − q| = |A − qB|/|B| ≤ (|r| + e_r)/(|b| − e_b),   r = a − q·b,
//        |√X − s| = |X − s²|/(√X + s) ≤ (|r| + e_r)/s,        r = x − s·s,
//    where e_r, the residual's running bound, already covers the input errors e_a, e_b, e_x.
//  * Exact results stay exact (e = 0): a sum or product of two doubles is a double-double exactly, and
//    a result 0 of exact operands is exactly 0, so the degenerate comparisons of exactly zero
//    differences stay decidable.
//  * The bounds are computed in double from non-negative terms by sums and products (and quotients by
//    a lower bound): each rounding lowers them by a factor ≥ (1 − 2^-52) at most, and comparisons
//    inflate the final bound by M = 1 + 2^-30, which covers chains of up to 2^21 roundings.
//  * Overflow gives ±∞ or NaN with e = ∞ or NaN: every comparison involving them is undecided.
//
// Comparisons behave as Bounded's and Interval's: when the bounds cannot separate the operands the
// comparison is undecided, returns false and records it in the current UncertaintyScope.
#pragma once

#include <algorithm>  // std::max, std::min
#include <cmath>      // std::sqrt, std::fabs, std::fma
#include <limits>     // infinity, NaN

#include "boxcyl/number/interval.hpp"  // UncertaintyScope, the uncertainty flag, next_up/next_down
#include "boxcyl/number/traits.hpp"


// A hardware FMA (then std::fma is one instruction), or an x86 target without one (then Dekker's
// product, and no contraction is possible either). Elsewhere std::fma is used as well.
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA) || !(defined(__x86_64__) || defined(__i386__))
#define BOXCYL_DD_USE_FMA 1
#else
#define BOXCYL_DD_USE_FMA 0
#endif
// An x86-64 build that may not assume FMA (the default: no -march) still runs on processors that have
// it, nearly all of them: TwoProd's error term is then one FMA instruction, chosen at run time, in
// place of Dekker's seventeen operations (a third of a double-double product's cost). BOXCYL_DD_DEKKER
// keeps Dekker's product everywhere (the tests build it so, for processors without FMA).
#if !BOXCYL_DD_USE_FMA && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(BOXCYL_DD_DEKKER)
#define BOXCYL_DD_RUNTIME_FMA 1
#else
#define BOXCYL_DD_RUNTIME_FMA 0
#endif

namespace boxcyl {

namespace detail::dd {

// s + t = a + b exactly (round to nearest, no overflow): Knuth's TwoSum.
BOXCYL_FORCE_INLINE inline void two_sum(double a, double b, double& s, double& t) {
    s = a + b;
    const double bb = s - a;
    t = (a - (s - bb)) + (b - bb);
}
// The same when |a| ≥ |b| or a = 0 (Dekker's Fast2Sum).
BOXCYL_FORCE_INLINE inline void fast_two_sum(double a, double b, double& s, double& t) {
    s = a + b;
    t = b - (s - a);
}
#if BOXCYL_DD_RUNTIME_FMA
// Whether the processor runs FMA3 instructions (GCC's and Clang's __builtin_cpu_supports count it only
// where the operating system saves the AVX state they need). Read before its initialisation (from
// another static initialiser) it is false: Dekker's product, which is exact as well.
inline bool detect_fma() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma") != 0;
}
inline const bool has_fma = detect_fma();
// a·b − p with one rounding (VFMSUB231SD: acc ← a·b − acc), for a build that may not emit it itself.
BOXCYL_FORCE_INLINE inline double fma_minus(double a, double b, double p) {
    double acc = p;
    asm("vfmsub231sd %2, %1, %0" : "+x"(acc) : "x"(a), "x"(b));
    return acc;
}
#endif

// a·b − p exactly for p = fl(a·b) (round to nearest, no overflow, no underflow of the result): Dekker's
// product, from each operand split into halves of 26 bits.
BOXCYL_FORCE_INLINE inline double dekker_error(double a, double b, double p) {
    constexpr double split = 134217729.0;  // 2^27 + 1
    const double ca = split * a, cb = split * b;
    const double ah = ca - (ca - a), al = a - ah;
    const double bh = cb - (cb - b), bl = b - bh;
    return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}
// p + e = a·b exactly (round to nearest, no overflow, no underflow of e).
BOXCYL_FORCE_INLINE inline void two_prod(double a, double b, double& p, double& e) {
    p = a * b;
#if BOXCYL_DD_USE_FMA
    e = std::fma(a, b, -p);
#elif BOXCYL_DD_RUNTIME_FMA
    e = has_fma ? fma_minus(a, b, p) : dekker_error(a, b, p);
#else
    e = dekker_error(a, b, p);
#endif
}
// x·y + z with one rounding where the target has an FMA, else two (the bound allows either).
BOXCYL_FORCE_INLINE inline double mul_add(double x, double y, double z) {
#if BOXCYL_DD_USE_FMA
    return std::fma(x, y, z);
#else
    return x * y + z;
#endif
}

}  // namespace detail::dd

class DoubleDouble {
public:
    static constexpr double rel = 0x1p-100;    // relative error allowance of one operation
    static constexpr double tiny = 0x1p-1066;  // underflow allowance of one multiplication
    static constexpr double margin = 1 + 0x1p-30;  // covers the rounding of the bounds themselves

    constexpr DoubleDouble() = default;
    constexpr DoubleDouble(double x) : hi_(x) {}  // NOLINT(google-explicit-constructor): exact embedding
    constexpr DoubleDouble(int x) : hi_(x) {}     // NOLINT(google-explicit-constructor)
    constexpr DoubleDouble(double hi, double lo, double error) : hi_(hi), lo_(lo), e_(error) {}

    // Every real in [lo, hi] (lo ≤ hi, finite) as a value with a bound that encloses it.
    static DoubleDouble range(double lo, double hi) {
        if (lo == hi) return DoubleDouble(lo);
        const double v = lo / 2 + hi / 2;
        return {v, 0.0, detail::next_up(std::max(hi - v, v - lo))};
    }

    double high() const { return hi_; }
    double low() const { return lo_; }
    double error() const { return e_; }
    bool exact_zero() const { return hi_ == 0 && lo_ == 0 && e_ == 0; }
    // Certain bounds of the exact value, as doubles (outward by a whole double: any rounding mode).
    double lo() const {
        if (lo_ == 0 && e_ == 0) return hi_;
        return detail::next_down(hi_ - detail::next_up(std::fabs(lo_) + e_ * margin));
    }
    double hi() const {
        if (lo_ == 0 && e_ == 0) return hi_;
        return detail::next_up(hi_ + detail::next_up(std::fabs(lo_) + e_ * margin));
    }

    BOXCYL_FORCE_INLINE inline friend DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
        if (b.exact_zero()) return a;
        if (a.exact_zero()) return b;
        double sh, sl, th, tl, vh, vl, zh, zl;
        detail::dd::two_sum(a.hi_, b.hi_, sh, sl);
        detail::dd::two_sum(a.lo_, b.lo_, th, tl);
        const double c = sl + th;
        detail::dd::fast_two_sum(sh, c, vh, vl);
        const double w = tl + vl;
        detail::dd::fast_two_sum(vh, w, zh, zl);
        // Two doubles: TwoSum alone (th = tl = 0, c = sl and both Fast2Sums meet their precondition),
        // exact. An exact zero result needs no term either (rel·|0| = 0).
        const bool exact = a.lo_ == 0 && b.lo_ == 0;
        return {zh, zl, a.e_ + b.e_ + (exact ? 0.0 : rel * std::fabs(zh))};
    }
    BOXCYL_FORCE_INLINE inline friend DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi_, -a.lo_, a.e_}; }
    BOXCYL_FORCE_INLINE inline friend DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) { return a + (-b); }
    // |AB − ab| ≤ |a|·e_b + |b|·e_a + e_a·e_b for |A − a| ≤ e_a, |B − b| ≤ e_b; |a| ≤ |a_hi| + |a_lo|.
    BOXCYL_FORCE_INLINE inline friend DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
        if (a.exact_zero() || b.exact_zero()) return DoubleDouble(0.0);
        double ch, cl1, zh, zl;
        detail::dd::two_prod(a.hi_, b.hi_, ch, cl1);
        const double tl = a.hi_ * b.lo_;
        const double cl2 = detail::dd::mul_add(a.lo_, b.hi_, tl);
        const double cl3 = cl1 + cl2;
        detail::dd::fast_two_sum(ch, cl3, zh, zl);
        // Two doubles: TwoProd alone, exact unless its error term underflows (|ab| ≥ 2^-960 rules that out).
        if (a.lo_ == 0 && b.lo_ == 0 && a.e_ == 0 && b.e_ == 0 && std::fabs(ch) >= 0x1p-960 &&
            std::fabs(ch) <= std::numeric_limits<double>::max())
            return {zh, zl, 0.0};
        const double ma = std::fabs(a.hi_) + std::fabs(a.lo_), mb = std::fabs(b.hi_) + std::fabs(b.lo_);
        const double e = ma * b.e_ + mb * a.e_ + a.e_ * b.e_ + rel * std::fabs(zh) + tiny;
        return {zh, zl, e};
    }
    // A lower bound of |B| for every B in the enclosure: |b| ≥ |b_hi|(1 − 2^-52); the factor 1 − 2^-50
    // and 2e_b leave room for the rounding of this very expression. ≤ 0 (or NaN) when |B| may be 0.
    double magnitude_lower() const { return std::fabs(hi_) * (1 - 0x1p-50) - 2 * e_; }

    // q = a/b corrected once, bounded from the residual (see the header comment).
    friend DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
        const double den = b.magnitude_lower();
        if (!(den > 0)) [[unlikely]]
            return undecided();
        if (a.exact_zero()) return DoubleDouble(0.0);
        const double q0 = a.hi_ / b.hi_;
        const DoubleDouble r0 = a - DoubleDouble(q0) * b;
        double qh, ql;
        detail::dd::fast_two_sum(q0, r0.hi_ / b.hi_, qh, ql);
        const DoubleDouble q(qh, ql, 0.0);
        const DoubleDouble r = a - q * b;  // a − q·b, with the bound of its own evaluation (e_a, e_b included)
        // r's running bound covers A − qB for every A, B in the enclosures: |A − qB| ≤ |r| + e_r.
        const double num = std::fabs(r.hi_) + std::fabs(r.lo_) + r.e_;
        return {qh, ql, num == 0 ? 0.0 : detail::next_up(num / den)};
    }
    DoubleDouble& operator+=(const DoubleDouble& b) { return *this = *this + b; }
    DoubleDouble& operator-=(const DoubleDouble& b) { return *this = *this - b; }
    DoubleDouble& operator*=(const DoubleDouble& b) { return *this = *this * b; }
    DoubleDouble& operator/=(const DoubleDouble& b) { return *this = *this / b; }

    // s = √x corrected once, bounded from the residual: |√X − s| = |X − s²|/(√X + s) ≤ (|x − s²| + e_x)/s.
    friend DoubleDouble sqrt(const DoubleDouble& x) {
        if (x.exact_zero()) return DoubleDouble(0.0);
        if (!(x.hi_ > 0) || !(x.hi_ <= std::numeric_limits<double>::max())) [[unlikely]]
            return undecided();
        const double s0 = std::sqrt(x.hi_);
        const DoubleDouble r0 = x - DoubleDouble(s0) * DoubleDouble(s0);
        double sh, sl;
        detail::dd::fast_two_sum(s0, r0.hi_ / (2 * s0), sh, sl);
        const DoubleDouble s(sh, sl, 0.0);
        const DoubleDouble r = x - s * s;
        const double den = s.magnitude_lower();
        if (!(den > 0)) [[unlikely]]
            return undecided();
        const double num = std::fabs(r.hi_) + std::fabs(r.lo_) + r.e_;
        return {sh, sl, num == 0 ? 0.0 : detail::next_up(num / den)};
    }

    // The sign of the exact value's difference: B − A lies within E of d = b − a (a double-double,
    // |d_lo| ≤ ulp(d_hi)), E = e_d·M. Decided when |d_hi| exceeds twice |d_lo| + E (a margin that
    // needs no care about the rounding of the test itself); an exact d decides by d_hi's sign.
    BOXCYL_FORCE_INLINE inline friend int compare(const DoubleDouble& a, const DoubleDouble& b) {  // sign of b − a, 2: undecided
        const DoubleDouble d = b - a;
        if (d.e_ == 0 && d.hi_ == d.hi_ && std::fabs(d.hi_) <= std::numeric_limits<double>::max())
            return (d.hi_ > 0) - (d.hi_ < 0);
        const double slack = (std::fabs(d.lo_) + d.e_ * margin) * 2;
        if (slack < d.hi_) return 1;
        if (slack < -d.hi_) return -1;
        return 2;
    }
    // An undecided comparison is recorded and answers by the order of the values (value_order), so
    // that the comparisons a sort makes always form a strict weak order (§3's hull sorts points).
    BOXCYL_FORCE_INLINE inline friend bool operator<(const DoubleDouble& a, const DoubleDouble& b) {
        int s = compare(a, b);
        if (s == 2) [[unlikely]]
            s = undecided_order(a, b);
        return s > 0;
    }
    BOXCYL_FORCE_INLINE inline friend bool operator<=(const DoubleDouble& a, const DoubleDouble& b) {
        int s = compare(a, b);
        if (s == 2) [[unlikely]]
            s = undecided_order(a, b);
        return s >= 0;
    }
    BOXCYL_FORCE_INLINE inline friend bool operator>(const DoubleDouble& a, const DoubleDouble& b) { return b < a; }
    BOXCYL_FORCE_INLINE inline friend bool operator>=(const DoubleDouble& a, const DoubleDouble& b) { return b <= a; }
    friend bool operator==(const DoubleDouble& a, const DoubleDouble& b) { return a <= b && b <= a; }
    friend bool operator!=(const DoubleDouble& a, const DoubleDouble& b) { return !(a == b); }

    // |x| without deciding the sign of x (|·| is 1-Lipschitz: the bound carries over). The sign of a
    // normalised hi + lo is the sign of hi.
    BOXCYL_FORCE_INLINE inline friend DoubleDouble enclosure_abs(const DoubleDouble& x) { return x.hi_ < 0 ? -x : x; }
    // x clamped to [−e, e] without a decision: where x is certainly outside, the bound ±e itself;
    // otherwise the clamp of the values, which is 1-Lipschitz in x and e (error max(e_x, e_e)), and for
    // an exact e within 2e of any point of [−e, e] (an exact 0 stays exact).
    friend DoubleDouble enclosure_clamp(const DoubleDouble& x, const DoubleDouble& e) {
        if (compare(e, x) == 1) return e;  // e < x certainly
        const DoubleDouble minus_e = -e;
        if (compare(x, minus_e) == 1) return minus_e;  // x < −e certainly
        // The sizes clamped to are ≥ 0 in reality, so a negative value of e is replaced by 0 (closer).
        const DoubleDouble ev = e.hi_ < 0 ? DoubleDouble(0.0) : DoubleDouble(e.hi_, e.lo_, 0.0);
        DoubleDouble v(x.hi_, x.lo_, 0.0);
        if (value_less(ev, v)) v = ev;
        else if (value_less(v, -ev)) v = -ev;
        double err = std::max(x.e_, e.e_);
        if (e.e_ == 0) err = std::min(err, detail::next_up(2 * (std::fabs(ev.hi_) + std::fabs(ev.lo_))));
        return {v.hi_, v.lo_, err};
    }

private:
    // The values' order, as doubles-doubles (no bound): normalised pairs compare by hi, then lo.
    static bool value_less(const DoubleDouble& a, const DoubleDouble& b) {
        return a.hi_ < b.hi_ || (a.hi_ == b.hi_ && a.lo_ < b.lo_);
    }
    static DoubleDouble undecided() {
        detail::uncertain_flag = true;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, std::numeric_limits<double>::infinity()};
    }
    // The sign of b − a for the values hi + lo (exactly: the double-double difference has the sign of
    // the difference of the values, its relative error being below 1), with every non-finite value
    // after every finite one and equal to the others. A total preorder; and every decided comparison
    // agrees with it (a decided sign is d_hi's sign, and so is the values'), so mixing decided and
    // undecided answers still gives a strict weak order.
    static int undecided_order(const DoubleDouble& a, const DoubleDouble& b) {
        detail::uncertain_flag = true;
        const bool sa = !a.finite(), sb = !b.finite();
        if (sa || sb) return sa == sb ? 0 : (sa ? -1 : 1);
        const DoubleDouble d = b - a;
        return (d.hi_ > 0) - (d.hi_ < 0);
    }
    bool finite() const {
        constexpr double big = std::numeric_limits<double>::max();
        return std::fabs(hi_) <= big && std::fabs(lo_) <= big;
    }

    double hi_ = 0, lo_ = 0, e_ = 0;
};

DoubleDouble sqrt(const DoubleDouble& x);

template <>
struct number_traits<DoubleDouble> {
    static constexpr bool is_exact = false;
    static constexpr bool has_sqrt = true;
    static DoubleDouble sqrt(const DoubleDouble& x) { return boxcyl::sqrt(x); }
};

namespace detail {
// Whether the arithmetic rounds to nearest now (the one mode the middle stage runs in): 1 + 3·2^-54
// rounds up to 1 + 2^-52 only to nearest or upward, and 1 + 2^-60 stays 1 only to nearest, downward or
// toward zero; the negated sums rule out the directed modes' mirror images. A probe of the arithmetic
// itself, so it sees SSE's MXCSR as well as any other control word.
inline bool round_to_nearest() {
    volatile double one = 1.0, a = 0x3p-54, b = 0x1p-60;
    const double up = one + a, stay = one + b, down = -one - a, stay_neg = -one - b;
    return up == 1 + 0x1p-52 && stay == 1 && down == -(1 + 0x1p-52) && stay_neg == -1;
}
}  // namespace detail

}  // namespace boxcyl
