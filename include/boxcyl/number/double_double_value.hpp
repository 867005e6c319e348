// A double-double value without an error bound: DoubleDouble's arithmetic (number/double_double.hpp,
// the same error-free transformations and double-word algorithms, about 2^-100 relative per
// operation) for computations whose results need no proof — the Newton steps that place the box point
// where the refined distance bounds are then evaluated, with DoubleDouble, and proved. Without the
// running bound and its exact-operand cases, an operation costs about two thirds as much.
//
// Round to nearest, as DoubleDouble; in another mode the values are merely less accurate, which a
// search tolerates (its callers decline other modes anyway). Division and square root take one
// correction of the double result. Comparisons compare the values (hi, then lo).
#pragma once

#include <cmath>  // std::sqrt

#include "boxcyl/number/double_double.hpp"  // detail::dd: the error-free transformations
#include "boxcyl/number/traits.hpp"

namespace boxcyl {

class DoubleDoubleValue {
public:
    constexpr DoubleDoubleValue() = default;
    constexpr DoubleDoubleValue(double x) : hi_(x) {}  // NOLINT(google-explicit-constructor): exact embedding
    constexpr DoubleDoubleValue(int x) : hi_(x) {}     // NOLINT(google-explicit-constructor)
    constexpr DoubleDoubleValue(double hi, double lo) : hi_(hi), lo_(lo) {}
    // A DoubleDouble's value, its bound dropped.
    explicit DoubleDoubleValue(const DoubleDouble& x) : hi_(x.high()), lo_(x.low()) {}

    double high() const { return hi_; }
    double low() const { return lo_; }
    // The value as a DoubleDouble known exactly (error 0): what a proof then starts from.
    DoubleDouble exact() const { return {hi_, lo_, 0.0}; }

    BOXCYL_FORCE_INLINE inline friend DoubleDoubleValue operator+(const DoubleDoubleValue& a, const DoubleDoubleValue& b) {
        double sh, sl, th, tl, vh, vl, zh, zl;
        detail::dd::two_sum(a.hi_, b.hi_, sh, sl);
        detail::dd::two_sum(a.lo_, b.lo_, th, tl);
        detail::dd::fast_two_sum(sh, sl + th, vh, vl);
        detail::dd::fast_two_sum(vh, tl + vl, zh, zl);
        return {zh, zl};
    }
    BOXCYL_FORCE_INLINE inline friend DoubleDoubleValue operator-(const DoubleDoubleValue& a) { return {-a.hi_, -a.lo_}; }
    BOXCYL_FORCE_INLINE inline friend DoubleDoubleValue operator-(const DoubleDoubleValue& a, const DoubleDoubleValue& b) {
        return a + (-b);
    }
    BOXCYL_FORCE_INLINE inline friend DoubleDoubleValue operator*(const DoubleDoubleValue& a, const DoubleDoubleValue& b) {
        // A zero factor gives 0, as in DoubleDouble (Dekker's split of a huge other factor would overflow).
        if (a.hi_ == 0 || b.hi_ == 0) return {0.0, 0.0};
        double ch, cl1, zh, zl;
        detail::dd::two_prod(a.hi_, b.hi_, ch, cl1);
        const double cl2 = detail::dd::mul_add(a.lo_, b.hi_, a.hi_ * b.lo_);
        detail::dd::fast_two_sum(ch, cl1 + cl2, zh, zl);
        return {zh, zl};
    }
    friend DoubleDoubleValue operator/(const DoubleDoubleValue& a, const DoubleDoubleValue& b) {
        const double q0 = a.hi_ / b.hi_;
        const DoubleDoubleValue r = a - DoubleDoubleValue(q0) * b;
        double qh, ql;
        detail::dd::fast_two_sum(q0, r.hi_ / b.hi_, qh, ql);
        return {qh, ql};
    }
    friend DoubleDoubleValue sqrt(const DoubleDoubleValue& x) {
        if (!(x.hi_ > 0)) return {x.hi_ == 0 ? 0.0 : std::sqrt(x.hi_), 0.0};  // 0, or NaN below 0
        const double s0 = std::sqrt(x.hi_);
        const DoubleDoubleValue r = x - DoubleDoubleValue(s0) * DoubleDoubleValue(s0);
        double sh, sl;
        detail::dd::fast_two_sum(s0, r.hi_ / (2 * s0), sh, sl);
        return {sh, sl};
    }
    DoubleDoubleValue& operator+=(const DoubleDoubleValue& b) { return *this = *this + b; }
    DoubleDoubleValue& operator-=(const DoubleDoubleValue& b) { return *this = *this - b; }
    DoubleDoubleValue& operator*=(const DoubleDoubleValue& b) { return *this = *this * b; }
    DoubleDoubleValue& operator/=(const DoubleDoubleValue& b) { return *this = *this / b; }

    // Normalised pairs compare by hi, then lo.
    friend bool operator<(const DoubleDoubleValue& a, const DoubleDoubleValue& b) {
        return a.hi_ < b.hi_ || (a.hi_ == b.hi_ && a.lo_ < b.lo_);
    }
    friend bool operator>(const DoubleDoubleValue& a, const DoubleDoubleValue& b) { return b < a; }
    friend bool operator<=(const DoubleDoubleValue& a, const DoubleDoubleValue& b) { return !(b < a); }
    friend bool operator>=(const DoubleDoubleValue& a, const DoubleDoubleValue& b) { return !(a < b); }

private:
    double hi_ = 0, lo_ = 0;
};

DoubleDoubleValue sqrt(const DoubleDoubleValue& x);

template <>
struct number_traits<DoubleDoubleValue> {
    static constexpr bool is_exact = false;
    static constexpr bool has_sqrt = true;
    static DoubleDoubleValue sqrt(const DoubleDoubleValue& x) { return boxcyl::sqrt(x); }
};

}  // namespace boxcyl
