// Numbers a + b·√d with integer a, b over an integer type Z (GMP's mpz_class, or the stack
// integers of number/fixed_integer.hpp), for one radicand d ≥ 0 held by a QuadraticRing. Only ring
// operations and the sign: no division, no fraction, no gcd — what the exact integer stage
// (exact/integer_inequalities.hpp) needs after it has scaled its problem to integers.
#pragma once

#include "boxcyl/geometry/vec3.hpp"

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

    // The exact sign of a + b√d: equal signs decide at once, otherwise a² is compared with b²·d.
    int sign(const Z& a, const Z& b) const {
        const int sa = sgn(a), sb = sgn(b);
        if (sb == 0 || sgn(d_) == 0) return sa;  // √0 = 0
        if (sa == 0 || sa == sb) return sb;
        const Z aa = a * a;
        const Z bbd = Z(b * b) * d_;
        const int c = cmp(aa, bbd);
        return c > 0 ? sa : c < 0 ? sb : 0;
    }
    int sign(const QuadInt<Z>& x) const { return sign(x.a, x.b); }

private:
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
