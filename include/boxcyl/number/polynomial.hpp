// Polynomials over the rationals and the number of their real roots in (0, 1), on FLINT
// (fmpq_poly / fmpz_poly: exact arithmetic and Sturm sequences; Debian libflint-dev). The clearance
// query decides whether a box edge meets a rim torus by counting such roots (exact/clearance.hpp).
#pragma once

#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>

#include <initializer_list>  // RationalPolynomial{c0, c1, ...}

#include "boxcyl/number/rational.hpp"

namespace boxcyl {

// A polynomial with rational coefficients, owning its FLINT object.
class RationalPolynomial {
public:
    RationalPolynomial() { fmpq_poly_init(p_); }
    // c0 + c1·x + c2·x² + …
    RationalPolynomial(std::initializer_list<Rational> coefficients) : RationalPolynomial() {
        slong i = 0;
        for (const Rational& c : coefficients) fmpq_poly_set_coeff_mpq(p_, i++, c.get_mpq_t());
    }
    RationalPolynomial(const RationalPolynomial& o) : RationalPolynomial() { fmpq_poly_set(p_, o.p_); }
    RationalPolynomial& operator=(const RationalPolynomial& o) {
        if (this != &o) fmpq_poly_set(p_, o.p_);
        return *this;
    }
    ~RationalPolynomial() { fmpq_poly_clear(p_); }

    friend RationalPolynomial operator+(const RationalPolynomial& a, const RationalPolynomial& b) {
        RationalPolynomial r;
        fmpq_poly_add(r.p_, a.p_, b.p_);
        return r;
    }
    friend RationalPolynomial operator-(const RationalPolynomial& a, const RationalPolynomial& b) {
        RationalPolynomial r;
        fmpq_poly_sub(r.p_, a.p_, b.p_);
        return r;
    }
    friend RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b) {
        RationalPolynomial r;
        fmpq_poly_mul(r.p_, a.p_, b.p_);
        return r;
    }
    friend RationalPolynomial operator*(const Rational& c, const RationalPolynomial& a) {
        RationalPolynomial r;
        fmpq_poly_scalar_mul_mpq(r.p_, a.p_, c.get_mpq_t());
        return r;
    }

    slong degree() const { return fmpq_poly_degree(p_); }
    const fmpq_poly_struct* get() const { return p_; }

private:
    fmpq_poly_t p_;
};

namespace detail {

// fmpz_poly with automatic clearing.
struct IntegerPolynomial {
    IntegerPolynomial() { fmpz_poly_init(p); }
    IntegerPolynomial(const IntegerPolynomial&) = delete;
    IntegerPolynomial& operator=(const IntegerPolynomial&) = delete;
    ~IntegerPolynomial() { fmpz_poly_clear(p); }
    fmpz_poly_t p;
};

// Distinct positive roots of a squarefree integer polynomial with p(0) ≠ 0.
inline slong positive_roots(const fmpz_poly_t p) {
    const slong n = fmpz_poly_degree(p);
    if (n < 1) return 0;
    if (n == 1) {  // c0 + c1·x: the root −c0/c1 is positive when the signs differ
        return fmpz_sgn(fmpz_poly_get_coeff_ptr(p, 0)) != fmpz_sgn(fmpz_poly_get_coeff_ptr(p, 1)) ? 1 : 0;
    }
    // FLINT's Sturm count wants a squarefree polynomial of degree > 1 with a nonzero constant term.
    slong negative = 0;
    slong positive = 0;
    _fmpz_poly_num_real_roots_sturm(&negative, &positive, p->coeffs, p->length);
    return positive;
}

}  // namespace detail

// The number of distinct real roots of p in the open interval (0, 1). Precondition: p(0) ≠ 0 and
// p(1) ≠ 0 (so p is not the zero polynomial).
inline long roots_in_unit_interval(const RationalPolynomial& p) {
    detail::IntegerPolynomial q;  // p times a positive integer: the same roots
    fmpq_poly_get_numerator(q.p, p.get());
    // Squarefree part q / gcd(q, q'): the same distinct roots.
    {
        detail::IntegerPolynomial dq;
        detail::IntegerPolynomial g;
        fmpz_poly_derivative(dq.p, q.p);
        fmpz_poly_gcd(g.p, q.p, dq.p);
        if (fmpz_poly_degree(g.p) > 0) fmpz_poly_div(q.p, q.p, g.p);
    }
    // Roots in (0, 1) = roots in (0, ∞) minus roots in (1, ∞), the latter the positive roots of
    // q(x + 1) (whose constant term is q(1) ≠ 0).
    detail::IntegerPolynomial shifted;
    fmpz_t one;
    fmpz_init_set_ui(one, 1);
    fmpz_poly_taylor_shift(shifted.p, q.p, one);
    fmpz_clear(one);
    return detail::positive_roots(q.p) - detail::positive_roots(shifted.p);
}

}  // namespace boxcyl
