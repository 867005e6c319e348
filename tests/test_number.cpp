// The exact number types: rationals from doubles and the quadratic field a + b·√d.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"

namespace boxcyl {
namespace {

TEST(Rational, DoublesConvertExactly) {
    EXPECT_EQ(to_rational(0.5), Rational(1, 2));
    EXPECT_EQ(to_rational(0.1), Rational(mpz_class(3602879701896397), mpz_class(1) << 55));
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(to_rational(tiny), Rational(mpz_class(1), mpz_class(1) << 1074));
    EXPECT_EQ(to_rational(-0.0), Rational(0));
    EXPECT_THROW(to_rational(std::nan("")), std::domain_error);
    EXPECT_THROW(to_rational(INFINITY), std::domain_error);
}

TEST(QuadraticField, ArithmeticMatchesDefinition) {
    QuadraticField<Rational> f(Rational(2));
    const QFRational r2 = QFRational::root(f);  // √2
    EXPECT_EQ(r2 * r2, QFRational(2));
    const QFRational x(Rational(1), Rational(1), f);  // 1 + √2
    const QFRational y(Rational(3), Rational(-2), f);  // 3 − 2√2 = (1 + √2)⁻²
    EXPECT_EQ(x * x * y, QFRational(1));
    EXPECT_EQ(QFRational(1) / (x * x), y);
    EXPECT_EQ((x - r2).b(), Rational(0));
}

TEST(QuadraticField, SignIsExact) {
    QuadraticField<Rational> f(Rational(2));
    // 1.4142135623730951 (the double nearest √2) is above √2; its predecessor is below.
    const double s = std::sqrt(2.0);
    EXPECT_GT(QFRational(to_rational(s)), QFRational::root(f));
    EXPECT_LT(QFRational(to_rational(std::nextafter(s, 0.0))), QFRational::root(f));
    // a + b√d with opposite signs, equal magnitudes when d is a square.
    QuadraticField<Rational> sq(Rational(9, 4));  // √d = 3/2
    EXPECT_EQ(QFRational(Rational(3), Rational(-2), sq).sign(), 0);
    EXPECT_EQ(QFRational(Rational(-3), Rational(2), sq), QFRational(0));
    EXPECT_THROW(QFRational(1) / (QFRational(Rational(3), Rational(-2), sq)), std::domain_error);
    EXPECT_EQ(QFRational(Rational(6)) / QFRational(Rational(1), Rational(2), sq), QFRational(Rational(3, 2)));
}

TEST(QuadraticField, RandomSignsAgreeWithLongDouble) {
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> u(-1000, 1000);
    QuadraticField<Rational> f(Rational(7));
    const long double s7 = std::sqrt(7.0L);
    for (int i = 0; i < 2000; ++i) {
        const int a = u(rng), b = u(rng);
        const long double v = a + b * s7;  // never 0 unless a = b = 0 (√7 irrational)
        const int want = (v > 0) - (v < 0);
        EXPECT_EQ(QFRational(Rational(a), Rational(b), f).sign(), want) << a << " + " << b << "√7";
    }
}

TEST(QuadraticField, MixingFieldsIsALogicError) {
    QuadraticField<Rational> f(Rational(2)), g(Rational(3));
    EXPECT_THROW(QFRational::root(f) + QFRational::root(g), std::logic_error);
    EXPECT_NO_THROW(QFRational::root(f) + QFRational(Rational(5)));  // rationals mix with any field
    EXPECT_THROW(QuadraticField<Rational>(Rational(-1)), std::domain_error);
}

}  // namespace
}  // namespace boxcyl
