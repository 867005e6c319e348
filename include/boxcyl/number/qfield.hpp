// Numbers a + b·√d over an exact ordered field R (GMP rationals), for one radicand d ≥ 0 shared by a
// whole computation. They make the cylinder axis u = D/|D| exact for any rational direction D:
// |D| = √(D·D), so u = (D/d)·√d with d = D·D (the published note's "rational quadratic fields").
//
// The radicand is held by pointer to a `QuadraticField<R>` that must outlive the numbers made from
// it. Pure rationals (b == 0) carry no radicand and mix with any field. Mixing two different fields
// is a logic error, checked in every build (it is one pointer comparison).
#pragma once

#include <cassert>    // assert: documentation of internal invariants
#include <stdexcept>  // std::logic_error, std::domain_error
#include <string>     // to_string

#include "boxcyl/number/rational.hpp"
#include "boxcyl/number/traits.hpp"

namespace boxcyl {

template <class R>
class QuadraticField {
public:
    explicit QuadraticField(R d) : d_(std::move(d)) {
        if (sgn(d_) < 0) throw std::domain_error("boxcyl::QuadraticField: negative radicand");
    }
    QuadraticField(const QuadraticField&) = delete;  // numbers point at this object
    QuadraticField& operator=(const QuadraticField&) = delete;
    const R& d() const { return d_; }

private:
    R d_;
};

template <class R>
class QFNumber {
public:
    QFNumber() : a_(0), b_(0) {}
    QFNumber(const R& a) : a_(a), b_(0) {}  // NOLINT(google-explicit-constructor): rationals embed
    QFNumber(int a) : a_(a), b_(0) {}       // NOLINT(google-explicit-constructor)
    QFNumber(R a, R b, const QuadraticField<R>& f) : a_(std::move(a)), b_(std::move(b)), f_(&f) {}

    // √d itself.
    static QFNumber root(const QuadraticField<R>& f) { return QFNumber(R(0), R(1), f); }

    const R& a() const { return a_; }
    const R& b() const { return b_; }
    const QuadraticField<R>* field() const { return f_; }
    bool is_rational() const { return sgn(b_) == 0; }

    friend QFNumber operator+(const QFNumber& x, const QFNumber& y) {
        return QFNumber(R(x.a_ + y.a_), R(x.b_ + y.b_), common(x, y));
    }
    friend QFNumber operator-(const QFNumber& x, const QFNumber& y) {
        return QFNumber(R(x.a_ - y.a_), R(x.b_ - y.b_), common(x, y));
    }
    friend QFNumber operator-(const QFNumber& x) { return QFNumber(R(-x.a_), R(-x.b_), x.f_); }

    friend QFNumber operator*(const QFNumber& x, const QFNumber& y) {
        const QuadraticField<R>* f = common(x, y);
        if (sgn(y.b_) == 0) return QFNumber(R(x.a_ * y.a_), R(x.b_ * y.a_), f);
        if (sgn(x.b_) == 0) return QFNumber(R(x.a_ * y.a_), R(x.a_ * y.b_), f);
        // (a + b√d)(c + e√d) = (ac + be·d) + (ae + bc)√d
        return QFNumber(R(x.a_ * y.a_ + x.b_ * y.b_ * f->d()), R(x.a_ * y.b_ + x.b_ * y.a_), f);
    }
    friend QFNumber operator/(const QFNumber& x, const QFNumber& y) {
        const QuadraticField<R>* f = common(x, y);
        if (sgn(y.b_) == 0) {
            if (sgn(y.a_) == 0) throw std::domain_error("boxcyl::QFNumber: division by zero");
            return QFNumber(R(x.a_ / y.a_), R(x.b_ / y.a_), f);
        }
        // x / (c + e√d) = x (c − e√d) / (c² − e²d); the norm is 0 only for y == 0 when d is not a
        // square, and for y != 0 with c² == e²d when it is (then y = c ± c = 0 or 2c: handled).
        const R norm = y.a_ * y.a_ - y.b_ * y.b_ * f->d();
        if (sgn(norm) == 0) {
            // d is a rational square q² and y = c + e·q is a plain rational.
            const R yv = y.a_ + y.b_ * exact_root(f->d());
            if (sgn(yv) == 0) throw std::domain_error("boxcyl::QFNumber: division by zero");
            return QFNumber(R(x.a_ / yv), R(x.b_ / yv), f);
        }
        const QFNumber conj(y.a_, R(-y.b_), *f);
        QFNumber p = x * conj;
        return QFNumber(R(p.a_ / norm), R(p.b_ / norm), f);
    }
    QFNumber& operator+=(const QFNumber& y) { return *this = *this + y; }
    QFNumber& operator-=(const QFNumber& y) { return *this = *this - y; }
    QFNumber& operator*=(const QFNumber& y) { return *this = *this * y; }
    QFNumber& operator/=(const QFNumber& y) { return *this = *this / y; }

    // Exact sign of a + b√d: equal signs decide at once, otherwise compare a² with b²·d.
    int sign() const {
        const int sa = sgn(a_), sb = sgn(b_);
        if (sb == 0) return sa;
        assert(f_ != nullptr);  // b != 0 only ever comes from a field
        if (sgn(f_->d()) == 0) return sa;  // √0 == 0
        if (sa == 0 || sa == sb) return sb;
        const int c = cmp(R(a_ * a_), R(b_ * b_ * f_->d()));
        return c > 0 ? sa : c < 0 ? sb : 0;
    }

    friend bool operator==(const QFNumber& x, const QFNumber& y) { return (x - y).sign() == 0; }
    friend auto operator<=>(const QFNumber& x, const QFNumber& y) { return (x - y).sign() <=> 0; }

    std::string to_string() const {
        if (f_ == nullptr || sgn(b_) == 0) return a_.get_str();
        return a_.get_str() + " + " + b_.get_str() + "*sqrt(" + f_->d().get_str() + ")";
    }

private:
    QFNumber(R a, R b, const QuadraticField<R>* f) : a_(std::move(a)), b_(std::move(b)), f_(f) {}

    static const QuadraticField<R>* common(const QFNumber& x, const QFNumber& y) {
        if (x.f_ == nullptr) return y.f_;
        if (y.f_ != nullptr && y.f_ != x.f_)
            throw std::logic_error("boxcyl::QFNumber: operands from different quadratic fields");
        return x.f_;
    }
    // √q for a rational square q (only reached when the norm vanished, which proves q is a square).
    static R exact_root(const R& q) {
        const mpz_class& n = q.get_num();
        const mpz_class& m = q.get_den();
        mpz_class rn = sqrt(n), rm = sqrt(m);
        assert(rn * rn == n && rm * rm == m);
        return R(rn, rm);
    }

    R a_, b_;
    const QuadraticField<R>* f_ = nullptr;
};

template <class R>
struct number_traits<QFNumber<R>> {
    static constexpr bool is_exact = true;
    static constexpr bool has_sqrt = false;
};

template <class R>
int sign_of(const QFNumber<R>& x) {
    return x.sign();
}

using QFRational = QFNumber<Rational>;

}  // namespace boxcyl
