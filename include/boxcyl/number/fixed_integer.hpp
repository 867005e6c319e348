// Signed integers of at most N limbs on the stack, with GMP's mpn functions doing the arithmetic: no
// allocation, no gcd. For the exact integer stage (exact/integer_inequalities.hpp), whose values are
// bounded by its inputs' exponent range: when a result would need more than N limbs, the operation
// raises a sticky per-thread flag (FixedOverflow) and returns 0; the caller discards that run and
// repeats it in mpz_class. Every result computed while the flag stays down is exact.
#pragma once

#include <gmp.h>    // mpn_add, mpn_sub, mpn_mul, mpn_cmp, mpn_lshift (Debian libgmp-dev)
#include <gmpxx.h>  // mpz_class, for to_mpz

#include <algorithm>  // std::copy_n, std::copy_backward, std::fill_n
#include <bit>        // std::bit_width, std::countl_zero
#include <cmath>      // std::fabs
#include <concepts>   // std::signed_integral
#include <cstddef>    // std::size_t
#include <cstdint>    // std::int64_t
#include <utility>    // std::swap

namespace boxcyl {

// The sticky overflow flag of this thread's FixedInt arithmetic.
struct FixedOverflow {
    static bool& flag() {
        thread_local bool f = false;
        return f;
    }
};

template <int N>
class FixedInt {
    static_assert(N >= 2, "FixedInt: at least two limbs");
    static_assert(GMP_NUMB_BITS == 64 && GMP_NAIL_BITS == 0, "FixedInt: 64-bit limbs without nails");

public:
    FixedInt() noexcept {}  // user-provided: value-initialisation (Vec3{}) must not zero the limbs
    template <std::signed_integral I>
        requires(sizeof(I) <= sizeof(std::int64_t))
    FixedInt(I v) {  // NOLINT(google-explicit-constructor): integers embed, as in mpz_class
        limb_[1] = 0;  // never read while size_ ≤ 1; stored so that GCC sees no uninitialised copy
        if (v == 0) return;
        const std::uint64_t mag = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
        limb_[0] = static_cast<mp_limb_t>(mag);
        size_ = v < 0 ? -1 : 1;
    }
    FixedInt(const FixedInt& o) : size_(o.size_) { copy_limbs(o); }
    FixedInt& operator=(const FixedInt& o) {
        if (this == &o) return *this;
        size_ = o.size_;
        copy_limbs(o);
        return *this;
    }

    friend int sgn(const FixedInt& x) { return (x.size_ > 0) - (x.size_ < 0); }
    friend int cmp(const FixedInt& x, const FixedInt& y) {
        if (x.size_ != y.size_) return x.size_ < y.size_ ? -1 : 1;
        const int c = compare_magnitude(x, y);
        return x.size_ < 0 ? -c : c;
    }
    friend bool operator<(const FixedInt& x, const FixedInt& y) { return cmp(x, y) < 0; }
    friend bool operator<=(const FixedInt& x, const FixedInt& y) { return cmp(x, y) <= 0; }
    friend bool operator==(const FixedInt& x, const FixedInt& y) { return cmp(x, y) == 0; }

    friend FixedInt operator-(const FixedInt& x) {
        FixedInt r(x);
        r.size_ = -r.size_;
        return r;
    }
    friend FixedInt operator+(const FixedInt& x, const FixedInt& y) {
        FixedInt r;
        add(r, x, y, false);
        return r;
    }
    friend FixedInt operator-(const FixedInt& x, const FixedInt& y) {
        FixedInt r;
        add(r, x, y, true);
        return r;
    }
    // In place: GMP's mpn_add and mpn_sub accept the result over their first operand, so no copy of
    // the limbs (the series arithmetic of the exact stage is mostly these).
    FixedInt& operator+=(const FixedInt& y) {
        add(*this, *this, y, false);
        return *this;
    }
    FixedInt& operator-=(const FixedInt& y) {
        add(*this, *this, y, true);
        return *this;
    }

    friend FixedInt operator*(const FixedInt& x, const FixedInt& y) {
        FixedInt r;
        multiply(r, x, y);
        return r;
    }
    // r = x·y written in place (r must not be x or y): the series arithmetic accumulates products
    // into its coefficients without a temporary.
    static void multiply(FixedInt& r, const FixedInt& x, const FixedInt& y) {
        int nx = x.abs_size(), ny = y.abs_size();
        if (nx == 0 || ny == 0) {
            r.size_ = 0;
            return;
        }
        const bool negative = (x.size_ < 0) != (y.size_ < 0);
        if (nx == 1 && ny == 1) {  // the common case, without a call
            const u128 prod = static_cast<u128>(x.limb_[0]) * y.limb_[0];
            r.limb_[0] = static_cast<mp_limb_t>(prod);
            r.limb_[1] = static_cast<mp_limb_t>(prod >> 64);
            const int n = r.limb_[1] != 0 ? 2 : 1;
            r.size_ = negative ? -n : n;
            return;
        }
        if (nx + ny > N) {
            r = overflowed();
            return;
        }
        const FixedInt* a = &x;
        const FixedInt* b = &y;
        if (nx < ny) std::swap(a, b), std::swap(nx, ny);
        mpn_mul(r.limb_, a->limb_, nx, b->limb_, ny);  // nx ≥ ny ≥ 1; r does not overlap
        int n = nx + ny;
        if (r.limb_[n - 1] == 0) --n;
        r.size_ = negative ? -n : n;
    }

    // Bits of |x| (0 for 0).
    int bit_length() const {
        const int n = abs_size();
        return n == 0 ? 0 : (n - 1) * GMP_NUMB_BITS + static_cast<int>(std::bit_width(limb_[n - 1]));
    }

    // Limbs in use.
    int limbs() const { return abs_size(); }

    // |x| ≈ m·2^e with m in [0.5, 1] and a relative error below 2^−51: the top 64 bits (truncation:
    // below 2^−63), converted to a double once (below 2^−52 in any rounding mode). false for 0.
    bool approximate(double& m, int& e) const {
        const int n = abs_size();
        if (n == 0) return false;
        const mp_limb_t hi = limb_[n - 1];
        const int lz = std::countl_zero(hi);
        std::uint64_t top = hi << lz;
        if (lz != 0 && n >= 2) top |= limb_[n - 2] >> (GMP_NUMB_BITS - lz);
        m = static_cast<double>(top) * 0x1p-64;
        e = n * GMP_NUMB_BITS - lz;
        return true;
    }

    // The value as an mpz_class (tests and messages).
    mpz_class to_mpz() const {
        mpz_class z;
        mpz_import(z.get_mpz_t(), static_cast<std::size_t>(abs_size()), -1, sizeof(mp_limb_t), 0, 0, limb_);
        if (size_ < 0) z = -z;
        return z;
    }

    // *this · 2^k.
    FixedInt& operator<<=(unsigned k) {
        const int n = abs_size();
        if (n == 0) return *this;
        const int whole = static_cast<int>(k / GMP_NUMB_BITS);
        const unsigned bits = k % GMP_NUMB_BITS;
        if (n + whole > N) return *this = overflowed();
        mp_limb_t carry = 0;
        if (bits != 0) carry = mpn_lshift(limb_, limb_, n, bits);
        int m = n;
        if (carry != 0) {
            if (n + whole + 1 > N) return *this = overflowed();
            limb_[m++] = carry;
        }
        if (whole != 0) {
            std::copy_backward(limb_, limb_ + m, limb_ + m + whole);
            std::fill_n(limb_, whole, mp_limb_t{0});
            m += whole;
        }
        size_ = size_ < 0 ? -m : m;
        return *this;
    }

private:
    __extension__ typedef unsigned __int128 u128;  // GCC/Clang: one 64×64 → 128-bit product

    int abs_size() const { return size_ < 0 ? -size_ : size_; }
    // Only the limbs in use; one or two without a call (most values are small).
    void copy_limbs(const FixedInt& o) {
        const int n = abs_size();
        if (n <= 2) {
            if (n >= 1) limb_[0] = o.limb_[0];
            if (n == 2) limb_[1] = o.limb_[1];
        } else {
            std::copy_n(o.limb_, n, limb_);
        }
    }
    static FixedInt overflowed() {
        FixedOverflow::flag() = true;
        return FixedInt();
    }
    static int compare_magnitude(const FixedInt& x, const FixedInt& y) {
        const int nx = x.abs_size(), ny = y.abs_size();
        if (nx != ny) return nx < ny ? -1 : 1;
        if (nx == 0) return 0;
        return mpn_cmp(x.limb_, y.limb_, nx);
    }
    // r = x + y, or x − y when negate_y. r may be x or y: GMP's mpn_add_n/mpn_sub_n, which mpn_add and
    // mpn_sub use, allow the result to coincide with an operand, and everything read from x and y is
    // read before r is written where they alias otherwise.
    static void add(FixedInt& r, const FixedInt& x, const FixedInt& y, bool negate_y) {
        const int sy = negate_y ? -y.size_ : y.size_;
        if (y.size_ == 0) {
            if (&r != &x) r = x;
            return;
        }
        if (x.size_ == 0) {
            if (&r != &y) r = y;
            r.size_ = sy;
            return;
        }
        const FixedInt* a = &x;
        const FixedInt* b = &y;
        int sa = x.size_, sb = sy;
        // A sum needs a with at least b's limbs; a difference |a| ≥ |b| (mpn_cmp only then).
        const bool swap = (sa < 0) == (sb < 0) ? x.abs_size() < y.abs_size() : compare_magnitude(x, y) < 0;
        if (swap) std::swap(a, b), std::swap(sa, sb);
        const int na = a->abs_size(), nb = b->abs_size();
        if (na == 1) {  // one limb each (for a difference |a| ≥ |b| > 0), without a call
            const mp_limb_t u = a->limb_[0], v = b->limb_[0];
            if ((sa < 0) == (sb < 0)) {
                r.limb_[0] = u + v;
                r.limb_[1] = 1;
                const int n = r.limb_[0] < u ? 2 : 1;
                r.size_ = sa < 0 ? -n : n;
            } else {
                r.limb_[0] = u - v;
                const int n = r.limb_[0] != 0 ? 1 : 0;
                r.size_ = sa < 0 ? -n : n;
            }
            return;
        }
        if ((sa < 0) == (sb < 0)) {
            // The carry limb is written after the sum; r may alias b, whose limbs the sum has read.
            const mp_limb_t carry = mpn_add(r.limb_, a->limb_, na, b->limb_, nb);
            int n = na;
            if (carry != 0) {
                if (n + 1 > N) {
                    r = overflowed();
                    return;
                }
                r.limb_[n++] = carry;
            }
            r.size_ = sa < 0 ? -n : n;
        } else {
            mpn_sub(r.limb_, a->limb_, na, b->limb_, nb);  // |a| ≥ |b|: no borrow
            int n = na;
            while (n > 0 && r.limb_[n - 1] == 0) --n;
            r.size_ = sa < 0 ? -n : n;
        }
    }

    int size_ = 0;  // ±(limbs in use), the sign of the number (as mpz)
    mp_limb_t limb_[N];
};

template <int N>
bool approximate(const FixedInt<N>& x, double& m, int& e) {
    return x.approximate(m, e);
}
// |x| ≈ m·2^e likewise for mpz_class (GMP truncates to 53 bits: below 2^−52).
inline bool approximate(const mpz_class& x, double& m, int& e) {
    if (sgn(x) == 0) return false;
    long exponent = 0;
    m = std::fabs(mpz_get_d_2exp(&exponent, x.get_mpz_t()));
    e = static_cast<int>(exponent);
    return true;
}

}  // namespace boxcyl
