// Closed intervals of doubles with outward rounding, for the certified filter.
//
// Each operation is evaluated once in the current rounding mode and its bounds are then moved one
// double outward. That is sound with no change of rounding mode: any IEEE rounding mode returns a
// neighbour of the true value (error below one spacing), and the next double outward is a whole
// spacing away (also across a binade boundary and in the subnormal range). Results with a zero operand,
// and sums that are exact (checked exactly, see exact_sum), are not widened. It holds with or without
// FMA contraction: a rounded product reaches later arithmetic only through a bit-level step (nothing
// to fuse) or as an exact zero (fusing it changes nothing). Assumed (checked by fp_environment_ok()
// and the tests): IEEE doubles with gradual underflow (no flush-to-zero / denormals-are-zero).
//
// Comparisons return bool, as the generic algorithms expect. When the two intervals overlap the
// comparison is undecided: it returns an arbitrary value and records the fact in the current
// UncertaintyScope; the filtered query then discards the whole run and asks the exact path. NaN
// (from ∞ − ∞ or 0·∞ after overflow) is undecided too, and ±∞ bounds stay sound.
#pragma once

#include <algorithm>  // std::min, std::max
#include <bit>        // std::bit_cast
#include <cfloat>     // FLT_EVAL_METHOD
#include <cmath>      // std::sqrt, std::isnan
#include <cstdint>    // std::int64_t
#include <limits>     // infinity

#include "boxcyl/number/traits.hpp"

// The filter relies on IEEE 754 double semantics (no reassociation, NaN and subnormals honoured).
#if defined(__FAST_MATH__)
#error "boxcyl: the certified filter is unsound under -ffast-math; compile boxcyl code without it"
#endif
// exact_sum() tests a sum where it was stored; with excess precision (x87: FLT_EVAL_METHOD 2) the test
// would see the unrounded value.
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "boxcyl: the certified filter needs double arithmetic evaluated in double (FLT_EVAL_METHOD == 0, e.g. SSE2)"
#endif

namespace boxcyl {

namespace detail {
// The next double toward −∞ / +∞ of a finite or infinite x (NaN stays NaN). Exact bit steps.
inline double next_down(double x) {
    if (x == 0) return -std::numeric_limits<double>::denorm_min();
    if (x != x || x == -std::numeric_limits<double>::infinity()) return x;
    const auto b = std::bit_cast<std::int64_t>(x);
    return std::bit_cast<double>(x > 0 ? b - 1 : b + 1);
}
inline double next_up(double x) { return -next_down(-x); }

// A product or quotient with a zero operand, and a sum with a zero operand, is exact: no widening, so
// that exact zeros (axis-aligned directions, zero extents) stay exactly zero and decidable.
inline double down_mul(double x, double y, double p) { return (x == 0 || y == 0) ? p : next_down(p); }
inline double up_mul(double x, double y, double p) { return (x == 0 || y == 0) ? p : next_up(p); }
// A rounded sum s = x + y is exact iff s − x == y when |x| ≥ |y|, in every rounding mode: s − x is then
// itself exact (Sterbenz: either s lies in [|x|/2, 2|x|] with the sign of x, or x + y cancels so far
// that it is exact already), so it equals y only if s = x + y. Overflow (s = ±∞) and NaN read as
// inexact. Exact sums are not widened: x − x stays exactly 0 and point intervals stay points whenever
// the arithmetic allows it (flat boxes and edge directions depend on that).
inline bool exact_sum(double x, double y, double s) {
    return (x < 0 ? -x : x) >= (y < 0 ? -y : y) ? s - x == y : s - y == x;
}
inline double down_add(double x, double y) {
    const double s = x + y;
    return (x == 0 || y == 0 || exact_sum(x, y, s)) ? s : next_down(s);
}
inline double up_add(double x, double y) {
    const double s = x + y;
    return (x == 0 || y == 0 || exact_sum(x, y, s)) ? s : next_up(s);
}

inline thread_local bool uncertain_flag = false;
}  // namespace detail

// Marks a region whose interval comparisons are watched: `certain()` is false if any was undecided.
class UncertaintyScope {
public:
    UncertaintyScope() : saved_(detail::uncertain_flag) { detail::uncertain_flag = false; }
    ~UncertaintyScope() { detail::uncertain_flag = saved_ || detail::uncertain_flag; }
    UncertaintyScope(const UncertaintyScope&) = delete;
    UncertaintyScope& operator=(const UncertaintyScope&) = delete;
    bool certain() const { return !detail::uncertain_flag; }

private:
    bool saved_;
};

class Interval {
public:
    constexpr Interval() = default;
    constexpr Interval(double x) : lo_(x), hi_(x) {}  // NOLINT(google-explicit-constructor): exact embedding
    constexpr Interval(int x) : lo_(x), hi_(x) {}     // NOLINT(google-explicit-constructor)
    constexpr Interval(double lo, double hi) : lo_(lo), hi_(hi) {}

    // The interval [lo, hi] (the same factory as Bounded::range, for code generic over both).
    static Interval range(double lo, double hi) { return {lo, hi}; }

    double lo() const { return lo_; }
    double hi() const { return hi_; }

    friend Interval operator+(const Interval& a, const Interval& b) {
        return {detail::down_add(a.lo_, b.lo_), detail::up_add(a.hi_, b.hi_)};
    }
    friend Interval operator-(const Interval& a, const Interval& b) {
        return {detail::down_add(a.lo_, -b.hi_), detail::up_add(a.hi_, -b.lo_)};
    }
    friend Interval operator-(const Interval& a) { return {-a.hi_, -a.lo_}; }
    // The extremes of x·y over a × b lie at corners known from the signs of the bounds (the classic
    // nine cases), so two products suffice unless both intervals straddle 0. A NaN bound (or 0·∞ at a
    // corner) gives the NaN interval: undecided.
    friend Interval operator*(const Interval& a, const Interval& b) {
        double x0, y0, x1, y1;  // lo = x0·y0, hi = x1·y1
        if (a.lo_ >= 0) {
            if (b.lo_ >= 0) x0 = a.lo_, y0 = b.lo_, x1 = a.hi_, y1 = b.hi_;
            else if (b.hi_ <= 0) x0 = a.hi_, y0 = b.lo_, x1 = a.lo_, y1 = b.hi_;
            else x0 = a.hi_, y0 = b.lo_, x1 = a.hi_, y1 = b.hi_;
        } else if (a.hi_ <= 0) {
            if (b.lo_ >= 0) x0 = a.lo_, y0 = b.hi_, x1 = a.hi_, y1 = b.lo_;
            else if (b.hi_ <= 0) x0 = a.hi_, y0 = b.hi_, x1 = a.lo_, y1 = b.lo_;
            else x0 = a.lo_, y0 = b.hi_, x1 = a.lo_, y1 = b.lo_;
        } else if (b.lo_ >= 0) {
            x0 = a.lo_, y0 = b.hi_, x1 = a.hi_, y1 = b.hi_;
        } else if (b.hi_ <= 0) {
            x0 = a.hi_, y0 = b.lo_, x1 = a.lo_, y1 = b.lo_;
        } else {  // both straddle 0 (or a bound is NaN): all four corners
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (double x : {a.lo_, a.hi_})
                for (double y : {b.lo_, b.hi_}) {
                    const double p = x * y;
                    if (p != p) return nan_interval();
                    lo = std::min(lo, detail::down_mul(x, y, p));
                    hi = std::max(hi, detail::up_mul(x, y, p));
                }
            return {lo, hi};
        }
        const double p0 = x0 * y0, p1 = x1 * y1;
        if (p0 != p0 || p1 != p1) return nan_interval();  // 0·∞
        return {detail::down_mul(x0, y0, p0), detail::up_mul(x1, y1, p1)};
    }
    friend Interval operator/(const Interval& a, const Interval& b) {
        if (!(b.lo_ > 0 || b.hi_ < 0)) return nan_interval();  // divisor may be 0: undecided
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (double x : {a.lo_, a.hi_})
            for (double y : {b.lo_, b.hi_}) {
                const double q = x / y;
                if (q != q) return nan_interval();  // ∞/∞
                lo = std::min(lo, detail::down_mul(x, 1.0, q));
                hi = std::max(hi, detail::up_mul(x, 1.0, q));
            }
        return {lo, hi};
    }
    Interval& operator+=(const Interval& b) { return *this = *this + b; }
    Interval& operator-=(const Interval& b) { return *this = *this - b; }
    Interval& operator*=(const Interval& b) { return *this = *this * b; }
    Interval& operator/=(const Interval& b) { return *this = *this / b; }

    // a < b is certainly true when a.hi < b.lo, certainly false when a.lo ≥ b.hi; otherwise undecided.
    friend bool operator<(const Interval& a, const Interval& b) { return decide(a.hi_ < b.lo_, a.lo_ >= b.hi_); }
    friend bool operator<=(const Interval& a, const Interval& b) { return decide(a.hi_ <= b.lo_, a.lo_ > b.hi_); }
    friend bool operator>(const Interval& a, const Interval& b) { return b < a; }
    friend bool operator>=(const Interval& a, const Interval& b) { return b <= a; }
    friend bool operator==(const Interval& a, const Interval& b) {
        return decide(a.lo_ == a.hi_ && b.lo_ == b.hi_ && a.lo_ == b.lo_, a.hi_ < b.lo_ || b.hi_ < a.lo_);
    }
    friend bool operator!=(const Interval& a, const Interval& b) { return !(a == b); }

    // Outward-rounded square root of the non-negative part (sqrt is correctly rounded in IEEE 754).
    friend Interval sqrt(const Interval& a) {
        if (!(a.lo_ >= 0)) return nan_interval();
        return {std::max(0.0, detail::next_down(std::sqrt(a.lo_))), detail::next_up(std::sqrt(a.hi_))};
    }

    // |x| and the clamp of x to [−e, e] (e ≥ 0) as enclosures, without deciding a sign (traits.hpp).
    // Both are monotone in each bound, so the extremes are at the corners; nothing rounds.
    friend Interval enclosure_abs(const Interval& x) {
        if (x.lo_ >= 0) return x;
        if (x.hi_ <= 0) return -x;
        return {0.0, std::max(-x.lo_, x.hi_)};  // NaN bounds give NaN (undecided later)
    }
    friend Interval enclosure_clamp(const Interval& x, const Interval& e) {
        const double lo = x.lo_ >= 0 ? std::min(x.lo_, e.lo_) : std::max(x.lo_, -e.hi_);
        const double hi = x.hi_ <= 0 ? std::max(x.hi_, -e.lo_) : std::min(x.hi_, e.hi_);
        return {lo, hi};
    }

private:
    static Interval nan_interval() {
        const double n = std::numeric_limits<double>::quiet_NaN();
        return {n, n};
    }
    static bool decide(bool certainly_true, bool certainly_false) {
        if (certainly_true) return true;
        if (!certainly_false) detail::uncertain_flag = true;  // overlap or NaN
        return false;
    }

    double lo_ = 0, hi_ = 0;
};

// The friend above is visible only to argument-dependent lookup; this declaration makes the qualified
// call boxcyl::sqrt below (and in callers) find it.
Interval sqrt(const Interval& a);

template <>
struct number_traits<Interval> {
    static constexpr bool is_exact = false;
    static constexpr bool has_sqrt = true;
    static Interval sqrt(const Interval& x) { return boxcyl::sqrt(x); }
};

inline int sign_of(const Interval& x) { return (Interval(0) < x) - (x < Interval(0)); }

// The self-test of the floating-point environment the filter assumes (cf. CGAL's rounding tester):
// subnormals are produced and read (no FTZ/DAZ), NaN compares unordered. Cheap; call it at start-up.
inline bool fp_environment_ok() {
    volatile double tiny = std::numeric_limits<double>::min();  // smallest normal
    volatile double half = tiny / 2;                             // subnormal unless flushed
    volatile double dmin = std::numeric_limits<double>::denorm_min();
    volatile double sum = dmin + 0.0;                            // 0 if denormals are treated as zero
    volatile double nan = std::numeric_limits<double>::quiet_NaN();
    return half != 0 && sum != 0 && !(nan == nan) && std::numeric_limits<double>::is_iec559;
}

}  // namespace boxcyl
