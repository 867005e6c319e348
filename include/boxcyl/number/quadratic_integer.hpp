// Numbers a + b·√d with integer a, b over an integer type Z (GMP's mpz_class, or the stack
// integers of number/fixed_integer.hpp), for one radicand d ≥ 0 held by a QuadraticRing. Only ring
// operations and the sign: no division, no fraction, no gcd — what the exact integer stage
// (exact/integer_inequalities.hpp) needs after it has scaled its problem to integers.
#pragma once

#include <cmath>  // std::ldexp

#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/fixed_integer.hpp"  // approximate() for FixedInt and mpz_class

namespace boxcyl {

template <class Z>
struct QuadInt {
    Z a, b;  // a + b·√d
};

template <class Z>
QuadInt<Z> operator+(const QuadInt<Z>& x, const QuadInt<Z>& y) {
    return {Z(x.a + y.a), Z(x.b + y.b)};
}
template <class Z>
QuadInt<Z> operator-(const QuadInt<Z>& x, const QuadInt<Z>& y) {
    return {Z(x.a - y.a), Z(x.b - y.b)};
}
template <class Z>
QuadInt<Z> operator-(const QuadInt<Z>& x) {
    return {Z(-x.a), Z(-x.b)};
}
template <class Z>
QuadInt<Z> operator*(const Z& s, const QuadInt<Z>& x) {
    return {Z(s * x.a), Z(s * x.b)};
}

// The ring Z[√d]: products and signs need d.
template <class Z>
class QuadraticRing {
public:
    explicit QuadraticRing(Z d) : d_(std::move(d)) {}
    const Z& d() const { return d_; }

    // Sums accumulate in place (+=): for the wide integer types a temporary costs a copy of its limbs.
    QuadInt<Z> square(const QuadInt<Z>& x) const {
        QuadInt<Z> r{Z(x.a * x.a), Z(Z(2) * x.a * x.b)};
        r.a += Z(x.b * x.b) * d_;
        return r;
    }
    // x·y = Σa_x·a_y + d·Σb_x·b_y + Σ(a_x·b_y + b_x·a_y)·√d: one product by d, not three.
    QuadInt<Z> dot(const Vec3<QuadInt<Z>>& x, const Vec3<QuadInt<Z>>& y) const {
        QuadInt<Z> r{Z(x[0].a * y[0].a), Z(x[0].a * y[0].b)};
        r.b += x[0].b * y[0].a;
        Z bb = x[0].b * y[0].b;
        for (int n = 1; n < 3; ++n) {
            r.a += x[n].a * y[n].a;
            r.b += x[n].a * y[n].b;
            r.b += x[n].b * y[n].a;
            bb += x[n].b * y[n].b;
        }
        r.a += bb * d_;
        return r;
    }
    // x·x likewise, with Σ2ab for the √d part.
    QuadInt<Z> norm2(const Vec3<QuadInt<Z>>& x) const {
        QuadInt<Z> r{Z(x[0].a * x[0].a), Z(x[0].a * x[0].b)};
        Z bb = x[0].b * x[0].b;
        for (int n = 1; n < 3; ++n) {
            r.a += x[n].a * x[n].a;
            r.b += x[n].a * x[n].b;
            bb += x[n].b * x[n].b;
        }
        r.a += bb * d_;
        r.b += r.b;
        return r;
    }

    // The exact sign of a + b√d: equal signs decide at once, otherwise a² is compared with b²·d —
    // first on approximations of |a|, |b| and d, exactly only when those cannot tell.
    int sign(const Z& a, const Z& b) const {
        const int sa = sgn(a), sb = sgn(b);
        if (sb == 0 || sgn(d_) == 0) return sa;  // √0 = 0
        if (sa == 0 || sa == sb) return sb;
        if (const int c = compare_squares_roughly(a, b); c != 0) return c > 0 ? sa : sb;
        const Z aa = a * a;
        const Z bbd = Z(b * b) * d_;
        const int c = cmp(aa, bbd);
        return c > 0 ? sa : c < 0 ? sb : 0;
    }
    int sign(const QuadInt<Z>& x) const { return sign(x.a, x.b); }

private:
    // The sign of a² − b²·d where approximations of |a|, |b|, d (m·2^e, m in [0.5, 1], each within a
    // relative 2^−50.9 of the value: approximate()) decide it, else 0. With Δ = 2e_a − 2e_b − e_d the
    // ratio a²/(b²d) is (m_a²/(m_b²·m_d))·2^Δ·(1 ± 2^−48), its mantissa part within [1/4, 8]: Δ ≥ 3
    // puts it above 1, Δ ≤ −4 below; in between the ratio is computed in five roundings of at most
    // 2^−52 each, and a distance of 2^−40 from 1 is far beyond all those errors together.
    int compare_squares_roughly(const Z& a, const Z& b) const {
        if constexpr (requires { a.limbs(); }) {  // FixedInt: exact squares of two limbs cost less
            if (a.limbs() < 3 && b.limbs() < 3) return 0;
        }
        if constexpr (requires(double& m, int& e) { approximate(a, m, e); }) {
            double ma = 0, mb = 0, md = 0;
            int ea = 0, eb = 0, ed = 0;
            if (!approximate(a, ma, ea) || !approximate(b, mb, eb) || !approximate(d_, md, ed)) return 0;
            const long delta = 2L * ea - 2L * eb - ed;
            if (delta >= 3) return 1;
            if (delta <= -4) return -1;
            const double r = ma * ma * std::ldexp(1.0, static_cast<int>(delta)) / (mb * mb * md);
            if (r > 1 + 0x1p-40) return 1;
            if (r < 1 - 0x1p-40) return -1;
        }
        return 0;
    }

    Z d_;
};

// Integer vector D times a vector of ring numbers: D × y and D·y need no d.
template <class Z>
Vec3<QuadInt<Z>> cross(const Vec3<Z>& D, const Vec3<QuadInt<Z>>& y) {
    return {D[1] * y[2] - D[2] * y[1], D[2] * y[0] - D[0] * y[2], D[0] * y[1] - D[1] * y[0]};
}
template <class Z>
QuadInt<Z> dot(const Vec3<Z>& D, const Vec3<QuadInt<Z>>& y) {
    return D[0] * y[0] + D[1] * y[1] + D[2] * y[2];
}

}  // namespace boxcyl
