// Numbers of two far-apart scales: ε^v·(c_0 + c_1·ε + … + c_t·ε^t) + ρ with integer coefficients c_k,
// one power of two ε = 2^−E (E in the hundreds), the value's own lowest power v, and a remainder
// |ρ| ≤ 2^rem·ε^p (p > v + t) for the terms that operations dropped. For the exact integer stage
// (exact/integer_inequalities.hpp) on inputs that span a thousand binary orders only because a few
// values are tiny beside the others (an axis component of 1e-300 beside 1): written as plain integers,
// those inputs make every value thousands of bits long, almost all zeros; written in powers of ε, every
// coefficient stays the size of a narrow input's values, and the terms that can no longer matter are
// dropped with a bound.
//
// The run's order m counts from each value's own lowest power: t ≤ m. A product of values that are
// themselves small (a tiny axis component times another, a denominator made of them, squared) keeps
// m terms beyond its leading one, as a product of large values does; counted from ε^0 instead, such
// products would lose the very terms that decide them.
//
// Why the sign is exact. c_0 ≠ 0 (leading coefficients that cancel are removed, v growing). With b the
// bits of c_0, |c_0·ε^v| ≥ 2^(b−1)·ε^v, while the rest is at most ε^(v+1)·(Σ_{k≥1} |c_k| + 2^rem) ≤
// ε^(v+1)·2^tail; tail < E + b − 1 makes the rest smaller, so the value has c_0's sign. When that
// bound does not hold, or every coefficient cancelled and a remainder is left, the sign is unknown:
// the operation raises the sticky per-thread flag (SeriesContext::undecided) and the caller repeats the
// run at a higher order, or in plain integers. Every sign computed while the flag stays down is exact;
// the coefficient type's own overflow (the FixedOverflow flag of FixedInt) is the caller's to check
// likewise.
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
    EpsilonSeries(const EpsilonSeries& o) : v_(o.v_), top_(o.top_), rem_(o.rem_), p_(o.p_) {
        for (int k = 0; k <= top_; ++k) c_[idx(k)] = o.c_[idx(k)];
    }
    EpsilonSeries& operator=(const EpsilonSeries& o) {
        if (this == &o) return *this;
        v_ = o.v_;
        top_ = o.top_;
        rem_ = o.rem_;
        p_ = o.p_;
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
        r.c_[0] = c;
        r.top_ = 0;
        r.v_ = k;
        return r;
    }

    // c_0's sign when c_0·ε^v outweighs the rest, which is at most ε^(v+1)·2^tail (ε < 1, p ≥ v + 1).
    friend int sgn(const EpsilonSeries& x) {
        if (x.top_ < 0) {
            if (x.rem_ >= 0) SeriesContext::get().undecided = true;
            return 0;
        }
        const int s = sgn(x.c_[0]);
        if (x.top_ == 0 && x.rem_ < 0) return s;
        const int tail = x.tail_bits();
        if (tail >= 0 && tail >= SeriesContext::get().E + bit_length(x.c_[0]) - 1) SeriesContext::get().undecided = true;
        return s;
    }
    // |x| ≈ m·2^e as its leading term's approximation, when the rest is below 2^−60 of that term:
    // ε^(v+1)·2^tail against at least 2^(b−1)·ε^v. The relative error stays below 2^−50.9.
    friend bool approximate(const EpsilonSeries& x, double& m, int& e) {
        if (x.top_ < 0) return false;
        const int E = SeriesContext::get().E;
        const int tail = x.tail_bits();
        if (tail >= 0 && tail > E + bit_length(x.c_[0]) - 61) return false;
        if (!approximate(x.c_[0], m, e)) return false;
        e -= E * x.v_;
        return true;
    }
    friend int cmp(const EpsilonSeries& x, const EpsilonSeries& y) { return sgn(x - y); }
    friend bool operator<(const EpsilonSeries& x, const EpsilonSeries& y) { return cmp(x, y) < 0; }
    friend bool operator<=(const EpsilonSeries& x, const EpsilonSeries& y) { return cmp(x, y) <= 0; }
    friend bool operator==(const EpsilonSeries& x, const EpsilonSeries& y) { return cmp(x, y) == 0; }

    friend EpsilonSeries operator-(const EpsilonSeries& x) {
        EpsilonSeries r;
        r.v_ = x.v_;
        r.top_ = x.top_;
        r.rem_ = x.rem_;
        r.p_ = x.p_;
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

    // The terms of order v_x + v_y + m and below are kept. Everything dropped — products of order above
    // that, and the remainders' products, of order at least min(v_x + p_y, v_y + p_x) — is at most
    // ε^p·(|X|₁ + 2^rem_x)(|Y|₁ + 2^rem_y) for p the lowest order dropped, as |x| ≤ ε^v_x·(|X|₁ + 2^rem_x).
    friend EpsilonSeries operator*(const EpsilonSeries& x, const EpsilonSeries& y) {
        EpsilonSeries r;
        if (x.zero() || y.zero()) return r;
        if (x.monomial() || y.monomial()) {  // most products: an integer (times a power of ε) and a value
            const EpsilonSeries& s = x.monomial() ? y : x;
            const EpsilonSeries& f = x.monomial() ? x : y;
            for (int k = 0; k <= s.top_; ++k) multiply_into(r.c_[idx(k)], f.c_[0], s.c_[idx(k)]);
            r.top_ = s.top_;
            r.v_ = s.v_ + f.v_;
            if (s.rem_ >= 0) {  // |f·ρ| ≤ 2^(rem + bits of f)·ε^(p + v_f)
                r.rem_ = s.rem_ + bit_length(f.c_[0]);
                r.p_ = s.p_ + f.v_;
            }
            return r;
        }
        const int lx = x.low(), ly = y.low();
        r.v_ = lx + ly;
        int dropped = kNone;  // the lowest order dropped or left in a remainder
        if (x.rem_ >= 0) dropped = std::min(dropped, ly + x.p_);
        if (y.rem_ >= 0) dropped = std::min(dropped, lx + y.p_);
        const int last = std::min(SeriesContext::get().order, dropped - 1 - r.v_);  // highest index kept
        for (int i = 0; i <= x.top_; ++i) {
            if (sgn(x.c_[idx(i)]) == 0) continue;
            for (int j = 0; j <= y.top_; ++j) {
                if (sgn(y.c_[idx(j)]) == 0) continue;
                if (i + j > last) {
                    dropped = std::min(dropped, r.v_ + i + j);
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
        if (dropped != kNone) {
            r.rem_ = x.norm_bits() + y.norm_bits();
            r.p_ = dropped;
        }
        r.normalize();
        return r;
    }

    // *this · 2^k (the exact stage's scaling of inputs to integers).
    EpsilonSeries& operator<<=(unsigned k) {
        for (int i = 0; i <= top_; ++i) c_[idx(i)] <<= k;
        if (rem_ >= 0) rem_ += static_cast<int>(k);
        return *this;
    }

private:
    static constexpr int kNone = 1 << 30;  // no order dropped

    static std::size_t idx(int k) { return static_cast<std::size_t>(k); }
    bool zero() const { return top_ < 0 && rem_ < 0; }
    bool monomial() const { return top_ == 0 && rem_ < 0; }  // c_0·ε^v alone, exact
    // The lowest order of the value: v, or the remainder's when no coefficient is left.
    int low() const { return top_ >= 0 ? v_ : p_; }
    // An upper bound on log2(Σ_{k≥1}|c_k| + 2^rem), the terms after the leading one (−1: none).
    int tail_bits() const {
        int bits = rem_, terms = rem_ >= 0 ? 1 : 0;
        for (int k = 1; k <= top_; ++k)
            if (sgn(c_[idx(k)]) != 0) bits = std::max(bits, bit_length(c_[idx(k)])), ++terms;
        return terms == 0 ? -1 : bits + static_cast<int>(std::bit_width(static_cast<unsigned>(terms)));
    }
    // An upper bound on log2(Σ|c_k| + 2^rem).
    int norm_bits() const {
        int bits = rem_, terms = rem_ >= 0 ? 1 : 0;
        for (int k = 0; k <= top_; ++k)
            if (sgn(c_[idx(k)]) != 0) bits = std::max(bits, bit_length(c_[idx(k)])), ++terms;
        return bits + static_cast<int>(std::bit_width(static_cast<unsigned>(terms)));
    }
    // Leading coefficients that cancelled are removed (v grows), trailing zeros dropped; an exact zero
    // is the canonical one.
    void normalize() {
        while (top_ >= 0 && sgn(c_[idx(top_)]) == 0) --top_;
        int lead = 0;
        while (lead <= top_ && sgn(c_[idx(lead)]) == 0) ++lead;
        if (lead > 0 && lead <= top_) {
            for (int k = lead; k <= top_; ++k) c_[idx(k - lead)] = c_[idx(k)];
            top_ -= lead;
            v_ += lead;
        }
        if (top_ < 0) v_ = 0;
    }
    // *this ± y: the orders from the lower of the two lowest up to m beyond it (and below any
    // remainder) are kept; the rest goes into the remainder, whose bound is the sum of the magnitudes.
    void accumulate(const EpsilonSeries& y, bool negate_y) {
        if (y.zero()) return;
        if (zero()) {
            *this = negate_y ? EpsilonSeries(-y) : y;
            return;
        }
        if (monomial() && y.monomial() && v_ == y.v_) {  // most sums: two integers
            if (negate_y) c_[0] -= y.c_[0];
            else c_[0] += y.c_[0];
            if (sgn(c_[0]) == 0) top_ = -1, v_ = 0;
            return;
        }
        const int v = std::min(low(), y.low());
        int dropped = kNone;
        if (rem_ >= 0) dropped = p_;
        if (y.rem_ >= 0) dropped = std::min(dropped, y.p_);
        const int last = std::min(v + SeriesContext::get().order, dropped - 1);  // highest order kept
        int bits = -1, terms = 0;
        auto drop = [&](const C& c, int order) {
            bits = std::max(bits, bit_length(c)), ++terms;
            dropped = std::min(dropped, order);
        };
        if (rem_ >= 0) bits = rem_, ++terms;
        if (y.rem_ >= 0) bits = std::max(bits, y.rem_), ++terms;
        // This value's coefficients move to orders from v (up by v_ − v places), those beyond last drop.
        const int shift = top_ >= 0 ? v_ - v : 0;
        int keep = top_;
        while (keep >= 0 && v_ + keep > last) {
            if (sgn(c_[idx(keep)]) != 0) drop(c_[idx(keep)], v_ + keep);
            --keep;
        }
        if (shift > 0 && keep >= 0) {  // then v_ + keep ≤ last ≤ v + m: shift ≤ m
            for (int k = keep; k >= 0; --k) c_[idx(k + shift)] = c_[idx(k)];
            for (int k = 0; k < shift; ++k) c_[idx(k)] = C(0);
        }
        top_ = keep >= 0 ? keep + shift : -1;
        v_ = v;
        for (int k = 0; k <= y.top_; ++k) {
            const int order = y.v_ + k;
            if (sgn(y.c_[idx(k)]) == 0) continue;
            if (order > last) {
                drop(y.c_[idx(k)], order);
                continue;
            }
            const int at = order - v;
            while (top_ < at) c_[idx(++top_)] = C(0);
            if (negate_y) c_[idx(at)] -= y.c_[idx(k)];
            else c_[idx(at)] += y.c_[idx(k)];
        }
        if (terms != 0) {
            rem_ = bits + static_cast<int>(std::bit_width(static_cast<unsigned>(terms)));
            p_ = dropped;
        } else {
            rem_ = -1;
        }
        normalize();
    }

    std::array<C, M + 1> c_;  // c_[0..top_] in use; the others are not read
    int v_ = 0;               // the order of c_[0]
    int top_ = -1;            // highest index in use (−1: no coefficient)
    int rem_ = -1;            // remainder bound 2^rem_·ε^p_ (−1: none, the value is exact)
    int p_ = 0;               // the remainder's order (read only while rem_ ≥ 0)
};

}  // namespace boxcyl
