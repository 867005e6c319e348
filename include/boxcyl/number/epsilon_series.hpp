// Numbers of two far-apart scales: c_0 + c_1·ε + … + c_m·ε^m + ρ with integer coefficients c_k, one
// power of two ε = 2^−E (E in the hundreds), and a remainder |ρ| ≤ 2^rem·ε^(m+1) for the terms beyond
// the order m that products drop. For the exact integer stage (exact/integer_inequalities.hpp) on
// inputs that span a thousand binary orders only because a few values are tiny beside the others (an
// axis component of 1e-300 beside 1): written as plain integers, those inputs make every value
// thousands of bits long, almost all zeros; written in powers of ε, every coefficient stays the size
// of a narrow input's values, and the terms that can no longer matter are dropped with a bound.
//
// Why the sign is exact. With c_k0 the first non-zero coefficient, of b bits, |c_k0·ε^k0| ≥
// 2^(b−1)·ε^k0, while the rest is at most ε^(k0+1)·(Σ_{k>k0} |c_k| + 2^rem) ≤ ε^(k0+1)·2^tail;
// tail < E + b − 1 makes the rest smaller, so the value has c_k0's sign. When that bound does not hold, or every kept coefficient is zero but a
// remainder is not, the sign is unknown: the operation raises the sticky per-thread flag
// (SeriesContext::undecided) and the caller repeats the run at a higher order, or in plain integers.
// Every sign computed while the flag stays down is exact; the coefficient type's own overflow (the
// FixedOverflow flag of FixedInt) is the caller's to check likewise.
#pragma once

#include <gmpxx.h>  // mpz_class coefficients

#include <algorithm>  // std::max, std::min
#include <array>      // the coefficients
#include <bit>        // std::bit_width
#include <concepts>   // std::signed_integral
#include <cstdint>    // std::int64_t

#include "boxcyl/number/fixed_integer.hpp"

namespace boxcyl {

// The run's ε = 2^−E and order m (every EpsilonSeries of one run shares them), and the sticky flag
// that a sign could not be decided at that order. Per thread, like FixedOverflow.
struct SeriesContext {
    int E = 0;
    int order = 1;
    bool undecided = false;
    static SeriesContext& get() {
        thread_local SeriesContext c;
        return c;
    }
};

// Bits of |x| (0 for 0), an upper bound on log2|x| + 1.
template <int N>
int bit_length(const FixedInt<N>& x) {
    return x.bit_length();
}
inline int bit_length(const mpz_class& x) {
    return sgn(x) == 0 ? 0 : static_cast<int>(mpz_sizeinbase(x.get_mpz_t(), 2));
}

// r = x·y into an existing coefficient (r is neither operand): no temporary to copy.
template <int N>
void multiply_into(FixedInt<N>& r, const FixedInt<N>& x, const FixedInt<N>& y) {
    FixedInt<N>::multiply(r, x, y);
}
inline void multiply_into(mpz_class& r, const mpz_class& x, const mpz_class& y) {
    mpz_mul(r.get_mpz_t(), x.get_mpz_t(), y.get_mpz_t());
}

// C: the coefficients' integer type (FixedInt<N> or mpz_class). M: the highest order a run may ask.
template <class C, int M>
class EpsilonSeries {
    static_assert(M >= 1, "EpsilonSeries: order at least 1");

public:
    using Coefficient = C;

    EpsilonSeries() = default;
    // Copies only the coefficients in use: a FixedInt coefficient is hundreds of bytes.
    EpsilonSeries(const EpsilonSeries& o) : top_(o.top_), rem_(o.rem_) {
        for (int k = 0; k <= top_; ++k) c_[idx(k)] = o.c_[idx(k)];
    }
    EpsilonSeries& operator=(const EpsilonSeries& o) {
        if (this == &o) return *this;
        top_ = o.top_;
        rem_ = o.rem_;
        for (int k = 0; k <= top_; ++k) c_[idx(k)] = o.c_[idx(k)];
        return *this;
    }
    template <std::signed_integral I>
        requires(sizeof(I) <= sizeof(std::int64_t))
    EpsilonSeries(I v) : top_(v != 0 ? 0 : -1) {  // NOLINT(google-explicit-constructor): integers embed
        if (v != 0) c_[0] = C(v);
    }
    // c·ε^k.
    static EpsilonSeries term(const C& c, int k) {
        EpsilonSeries r;
        if (sgn(c) == 0) return r;
        r.c_[static_cast<std::size_t>(k)] = c;
        r.top_ = k;
        return r;
    }

    friend int sgn(const EpsilonSeries& x) {
        if (x.plain()) return x.top_ < 0 ? 0 : sgn(x.c_[0]);
        int k0 = 0;
        while (k0 <= x.top_ && sgn(x.c_[idx(k0)]) == 0) ++k0;
        if (k0 > x.top_) {
            if (x.rem_ >= 0) SeriesContext::get().undecided = true;
            return 0;
        }
        const int s = sgn(x.c_[idx(k0)]);
        int bits = x.rem_, terms = x.rem_ >= 0 ? 1 : 0;
        for (int k = k0 + 1; k <= x.top_; ++k)
            if (sgn(x.c_[idx(k)]) != 0) bits = std::max(bits, bit_length(x.c_[idx(k)])), ++terms;
        const int tail = bits + static_cast<int>(std::bit_width(static_cast<unsigned>(terms)));
        if (terms != 0 && tail >= SeriesContext::get().E + bit_length(x.c_[idx(k0)]) - 1)
            SeriesContext::get().undecided = true;
        return s;
    }
    friend int cmp(const EpsilonSeries& x, const EpsilonSeries& y) { return sgn(x - y); }
    friend bool operator<(const EpsilonSeries& x, const EpsilonSeries& y) { return cmp(x, y) < 0; }
    friend bool operator<=(const EpsilonSeries& x, const EpsilonSeries& y) { return cmp(x, y) <= 0; }
    friend bool operator==(const EpsilonSeries& x, const EpsilonSeries& y) { return cmp(x, y) == 0; }

    friend EpsilonSeries operator-(const EpsilonSeries& x) {
        EpsilonSeries r;
        r.top_ = x.top_;
        r.rem_ = x.rem_;
        for (int k = 0; k <= r.top_; ++k) r.c_[idx(k)] = -x.c_[idx(k)];
        return r;
    }
    friend EpsilonSeries operator+(const EpsilonSeries& x, const EpsilonSeries& y) {
        EpsilonSeries r(x);
        r.accumulate(y, false);
        return r;
    }
    friend EpsilonSeries operator-(const EpsilonSeries& x, const EpsilonSeries& y) {
        EpsilonSeries r(x);
        r.accumulate(y, true);
        return r;
    }
    EpsilonSeries& operator+=(const EpsilonSeries& y) {
        accumulate(y, false);
        return *this;
    }
    EpsilonSeries& operator-=(const EpsilonSeries& y) {
        accumulate(y, true);
        return *this;
    }

    // Terms of order above m are dropped into the remainder: Σ_{i+j>m} |a_i b_j| ε^(i+j) plus the
    // remainders' products are at most ε^(m+1)·(|A|₁ + 2^rem_a)(|B|₁ + 2^rem_b) (ε < 1).
    friend EpsilonSeries operator*(const EpsilonSeries& x, const EpsilonSeries& y) {
        EpsilonSeries r;
        if (x.zero() || y.zero()) return r;
        if (x.plain() && y.plain()) {  // most values: order 0 and exact
            r.c_[0] = x.c_[0] * y.c_[0];
            r.top_ = 0;
            return r;
        }
        const int m = SeriesContext::get().order;
        if ((x.plain() || y.plain()) && std::max(x.top_, y.top_) <= m) {  // an integer times a series
            const EpsilonSeries& s = x.plain() ? y : x;
            const C& f = x.plain() ? x.c_[0] : y.c_[0];
            for (int k = 0; k <= s.top_; ++k) multiply_into(r.c_[idx(k)], f, s.c_[idx(k)]);
            r.top_ = s.top_;
            if (s.rem_ >= 0) r.rem_ = s.rem_ + bit_length(f);  // |f·ρ| ≤ 2^(rem + bits of f)·ε^(m+1)
            return r;
        }
        bool dropped = x.rem_ >= 0 || y.rem_ >= 0;
        for (int i = 0; i <= x.top_; ++i) {
            if (sgn(x.c_[idx(i)]) == 0) continue;
            for (int j = 0; j <= y.top_; ++j) {
                if (sgn(y.c_[idx(j)]) == 0) continue;
                if (i + j > m) {
                    dropped = true;
                    break;
                }
                if (i + j > r.top_) {
                    for (int k = r.top_ + 1; k < i + j; ++k) r.c_[idx(k)] = C(0);
                    multiply_into(r.c_[idx(i + j)], x.c_[idx(i)], y.c_[idx(j)]);
                    r.top_ = i + j;
                } else {
                    C product;
                    multiply_into(product, x.c_[idx(i)], y.c_[idx(j)]);
                    r.c_[idx(i + j)] += product;
                }
            }
        }
        if (dropped) r.rem_ = x.norm_bits() + y.norm_bits();
        return r;
    }

    // *this · 2^k (the exact stage's scaling of inputs to integers).
    EpsilonSeries& operator<<=(unsigned k) {
        for (int i = 0; i <= top_; ++i) c_[idx(i)] <<= k;
        if (rem_ >= 0) rem_ += static_cast<int>(k);
        return *this;
    }

private:
    static std::size_t idx(int k) { return static_cast<std::size_t>(k); }
    bool zero() const { return top_ < 0 && rem_ < 0; }
    bool plain() const { return top_ <= 0 && rem_ < 0; }  // c_0 alone (or 0), exact
    // An upper bound on log2(Σ|c_k| + 2^rem).
    int norm_bits() const {
        int bits = rem_, terms = rem_ >= 0 ? 1 : 0;
        for (int k = 0; k <= top_; ++k)
            if (sgn(c_[idx(k)]) != 0) bits = std::max(bits, bit_length(c_[idx(k)])), ++terms;
        return bits + static_cast<int>(std::bit_width(static_cast<unsigned>(terms)));
    }
    // *this ± y, coefficient by coefficient in place.
    void accumulate(const EpsilonSeries& y, bool negate_y) {
        if (plain() && y.plain()) {
            if (y.top_ < 0) return;
            if (top_ < 0) {
                c_[0] = negate_y ? C(-y.c_[0]) : y.c_[0];
                top_ = 0;
                return;
            }
            if (negate_y) c_[0] -= y.c_[0];
            else c_[0] += y.c_[0];
            if (sgn(c_[0]) == 0) top_ = -1;
            return;
        }
        for (int k = 0; k <= y.top_; ++k) {
            if (k <= top_) {
                if (negate_y) c_[idx(k)] -= y.c_[idx(k)];
                else c_[idx(k)] += y.c_[idx(k)];
            } else {
                c_[idx(k)] = negate_y ? C(-y.c_[idx(k)]) : y.c_[idx(k)];
            }
        }
        top_ = std::max(top_, y.top_);
        while (top_ >= 0 && sgn(c_[idx(top_)]) == 0) --top_;
        if (rem_ >= 0 || y.rem_ >= 0) rem_ = std::max(rem_, y.rem_) + 1;
    }

    std::array<C, M + 1> c_;  // c_[0..top_] in use; the others are not read
    int top_ = -1;            // highest order in use (−1: no coefficient)
    int rem_ = -1;            // remainder bound 2^rem_·ε^(m+1) (−1: none, the value is exact)
};

}  // namespace boxcyl
