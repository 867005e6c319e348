// Bounded (include/boxcyl/number/bounded.hpp), the running-error-bound numbers of the filter's
// fast stage. Every +, −, ×, ÷, sqrt of random operands across the whole double range (zero,
// subnormal, tiny, huge) and of operands that already carry an error keeps the exact result within
// [lo(), hi()] (checked in GMP rationals, Q(√d) for sqrt), in every IEEE rounding mode; so do long
// random chains (the bounds' own rounding, covered by the margin); comparisons are certain only when
// they should be; exact zeros stay exact; overflow and NaN are undecided, never wrong; abs and clamp
// enclose without deciding a sign.
#include <gtest/gtest.h>

#include <algorithm>  // std::min, std::max
#include <cfenv>      // rounding modes
#include <cmath>      // std::fabs, std::ldexp
#include <cstdio>     // std::printf
#include <random>     // operand generators
#include <string>     // messages

#include "boxcyl/number/bounded.hpp"
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"
#include "support/cases.hpp"  // hex()
#include "support/enclosure.hpp"
#include "support/fp.hpp"
#include "support/runner.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

Rational q(double x) { return to_rational(x); }

// A result that is not finite (overflow: v = ±∞, or e = ∞/NaN) encloses nothing, but then it must make
// every comparison undecided (never a wrong decided answer).
bool unusable_and_undecided(const Bounded& r) {
    UncertaintyScope scope;
    (void)(r < Bounded(0.0));
    (void)(Bounded(0.0) < r);
    (void)(r <= Bounded(1e300));
    return !scope.certain();
}

// lo() ≤ x ≤ hi() for the exact rational x; infinite bounds allowed, NaN never encloses.
bool encloses(const Bounded& r, const Rational& x) {
    if (!std::isfinite(r.value()) || !std::isfinite(r.error())) return unusable_and_undecided(r);
    const double lo = r.lo(), hi = r.hi();
    if (lo != lo || hi != hi) return false;
    const bool lo_ok = lo == -inf || (lo != inf && q(lo) <= x);
    const bool hi_ok = hi == inf || (hi != -inf && x <= q(hi));
    return lo_ok && hi_ok;
}
// An undecided result: NaN value (a division by a divisor that may be 0, sqrt of a possibly negative).
bool undecided(const Bounded& r) { return r.value() != r.value() && unusable_and_undecided(r); }

std::string show(const Bounded& r) { return hex(r.value()) + " ± " + hex(r.error()); }

// A value with an error: v ± e where e is a random fraction of |v| (or an absolute tiny amount).
Bounded with_error(std::mt19937_64& rng, double v) {
    switch (rng() % 4) {
        case 0: return Bounded(v);
        case 1: return {v, std::fabs(v) * 0x1p-40};
        case 2: return {v, std::fabs(v) * 0x1p-10 + denorm};
        default: return {v, std::ldexp(1.0, -1074 + static_cast<int>(rng() % 40))};
    }
}
// Exact points of v ± e: both ends and the value itself.
void points_of(const Bounded& b, Rational out[3]) {
    out[0] = q(b.value());
    out[1] = q(b.value()) - q(b.error());
    out[2] = q(b.value()) + q(b.error());
}

struct Count {
    long checks = 0, undecided = 0;
};

void check_ops(Count& n, const Bounded& a, const Bounded& b) {
    Rational pa[3], pb[3];
    points_of(a, pa);
    points_of(b, pb);
    const Bounded sum = a + b, diff = a - b, prod = a * b, quot = a / b;
    const bool divisor_may_be_zero = !(std::fabs(b.value()) > 2 * b.error());
    for (const Rational& x : pa)
        for (const Rational& y : pb) {
            n.checks += 4;
            EXPECT_TRUE(encloses(sum, x + y)) << show(a) << " + " << show(b) << " = " << show(sum);
            EXPECT_TRUE(encloses(diff, x - y)) << show(a) << " - " << show(b) << " = " << show(diff);
            EXPECT_TRUE(encloses(prod, x * y)) << show(a) << " * " << show(b) << " = " << show(prod);
            if (divisor_may_be_zero) {
                EXPECT_TRUE(undecided(quot)) << show(a) << " / " << show(b) << " = " << show(quot);
            } else if (!undecided(quot)) {
                EXPECT_TRUE(encloses(quot, x / y)) << show(a) << " / " << show(b) << " = " << show(quot);
            }
        }
    n.undecided += undecided(quot);
}

// √x within [lo, hi], checked exactly in Q(√x).
void check_sqrt(Count& n, const Bounded& a) {
    const Bounded r = sqrt(a);
    ++n.checks;
    if (a.exact_zero()) {
        EXPECT_TRUE(r.exact_zero());
        return;
    }
    if (!(a.value() > 0)) {
        EXPECT_TRUE(undecided(r)) << "sqrt of " << show(a);
        return;
    }
    Rational pa[3];
    points_of(a, pa);
    for (const Rational& x : pa) {
        if (x < 0) continue;  // √ of the negative points is not asked for
        EXPECT_TRUE(sqrt_enclosed(x, std::max(0.0, r.lo()), r.hi())) << "sqrt of " << show(a) << " = " << show(r);
    }
}

class BoundedEnclosure : public ::testing::TestWithParam<int> {};

TEST_P(BoundedEnclosure, RandomOperandsAreEnclosed) {
    ASSERT_TRUE(fp_environment_ok());
    const int mode = GetParam();
    const RoundingMode guard(mode);
    ASSERT_EQ(std::fegetround(), mode);
    std::mt19937_64 rng(9301 + static_cast<unsigned>(mode));
    Count n;
    const long pairs = scaled(10000);
    for (long i = 0; i < pairs; ++i) {
        const double x = random_operand(rng), y = random_operand(rng);
        check_ops(n, Bounded(x), Bounded(y));
        check_ops(n, with_error(rng, x), with_error(rng, y));
        check_sqrt(n, Bounded(std::fabs(x)));
        check_sqrt(n, with_error(rng, std::fabs(x)));
        if (HasFailure()) {
            ADD_FAILURE() << "rounding mode " << mode_name(mode) << ", pair " << i << ": " << hex(x) << ", " << hex(y);
            return;
        }
    }
    std::printf("bounded enclosure, %-12s %ld checks (%ld undecided quotients)\n", mode_name(mode), n.checks,
                n.undecided);
}

// Long random chains of operations on values of mixed magnitudes stay enclosed: the bounds' own
// rounding compounds, and the comparison margin must cover it.
TEST_P(BoundedEnclosure, LongChainsAreEnclosed) {
    const int mode = GetParam();
    const RoundingMode guard(mode);
    std::mt19937_64 rng(9401 + static_cast<unsigned>(mode));
    std::uniform_real_distribution<double> u(-4, 4);
    const long chains = scaled(300);
    for (long c = 0; c < chains; ++c) {
        Bounded b(u(rng));
        Rational x = q(b.value());
        for (int step = 0; step < 60; ++step) {
            const double y = u(rng) * std::ldexp(1.0, static_cast<int>(rng() % 20) - 10);
            switch (rng() % 4) {
                case 0: b = b + Bounded(y), x = x + q(y); break;
                case 1: b = b - Bounded(y), x = x - q(y); break;
                case 2: b = b * Bounded(y), x = x * q(y); break;
                default:
                    if (y == 0) break;
                    b = b / Bounded(y), x = x / q(y);
                    break;
            }
            if (undecided(b) || !(std::fabs(b.value()) < 1e200)) break;
            ASSERT_TRUE(encloses(b, x)) << mode_name(mode) << " chain " << c << " step " << step << ": " << show(b);
        }
    }
}

// An overflow is not always ±∞: rounding toward zero, up or down turns it into ±DBL_MAX on one side.
// Such a result, scaled back into range by a tiny factor, must still enclose the exact value or be
// undecided (a parallelepiped's separating direction with components of 1e±150 once certified a wrong
// miss this way under FE_DOWNWARD).
TEST_P(BoundedEnclosure, OverflowScaledBackIsEnclosedOrUndecided) {
    const int mode = GetParam();
    const RoundingMode guard(mode);
    const double bigs[] = {dmax, 1e300, 1e200, 1.5e154, -1e300, -dmax};
    const double tinies[] = {1e-300, 1e-200, 4e-320, -1e-250};
    for (double x : bigs)
        for (double y : bigs)
            for (double t : tinies) {
                const Bounded a(x), b(y), s(t);
                const Bounded sums[] = {(a + b) * s, (a - b) * s, (a * b) * s, (a / Bounded(t)) * s,
                                        (a * b + a) * s * s, sqrt(Bounded(std::fabs(x)) * Bounded(std::fabs(y))) * s};
                const Rational exact[] = {(q(x) + q(y)) * q(t), (q(x) - q(y)) * q(t), q(x) * q(y) * q(t),
                                          q(x) / q(t) * q(t), (q(x) * q(y) + q(x)) * q(t) * q(t)};
                for (int k = 0; k < 5; ++k)
                    EXPECT_TRUE(encloses(sums[k], exact[k]))
                        << mode_name(mode) << " op " << k << " of " << hex(x) << ", " << hex(y) << ", " << hex(t) << ": "
                        << show(sums[k]);
                // The root of an overflowed product: enclosed means its square's bounds hold x·y·t².
                const Bounded& r = sums[5];
                if (std::isfinite(r.value()) && std::isfinite(r.error()) && r.lo() > 0) {
                    const Rational square = q(std::fabs(x)) * q(std::fabs(y)) * q(t) * q(t);
                    EXPECT_TRUE(q(r.lo()) * q(r.lo()) <= square && square <= q(r.hi()) * q(r.hi()))
                        << mode_name(mode) << " sqrt of " << hex(x) << " * " << hex(y) << ": " << show(r);
                }
            }
}

INSTANTIATE_TEST_SUITE_P(RoundingModes, BoundedEnclosure,
                         ::testing::Values(FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO),
                         [](const auto& info) { return std::string(mode_name(info.param)); });

TEST(Bounded, ComparisonsAreCertainOnlyWhenDecided) {
    const Bounded a(1.5, 0.5), b(3.5, 0.5), c(2.5, 1.0);  // [1, 2], [3, 4], [1.5, 3.5]
    {
        UncertaintyScope s;
        EXPECT_TRUE(a < b);
        EXPECT_TRUE(a <= b);
        EXPECT_FALSE(a > b);
        EXPECT_FALSE(b <= a);
        EXPECT_TRUE(b > a);
        EXPECT_FALSE(a == b);
        EXPECT_TRUE(Bounded(2) == Bounded(2));
        EXPECT_FALSE(Bounded(2) < Bounded(2));  // equal exact values: < is certainly false
        EXPECT_TRUE(Bounded(0.1) < Bounded(0.1 + 0x1p-56));  // exact values one ulp apart
        EXPECT_TRUE(s.certain());
    }
    for (int k = 0; k < 4; ++k) {
        UncertaintyScope s;
        switch (k) {
            case 0: (void)(a < c); break;
            case 1: (void)(c <= b); break;
            case 2: (void)(Bounded(1.0, 0x1p-60) < Bounded(1.0)); break;  // equal within the error
            case 3: (void)(Bounded(1.0, 0x1p-60) == Bounded(1.0, 0x1p-60)); break;
        }
        EXPECT_FALSE(s.certain()) << "comparison " << k;
    }
}

TEST(Bounded, ExactZerosStayExact) {
    for (double x : {3.0, -7.25, dmax, denorm, -dmin, 1e-300}) {
        for (const Bounded& y : {Bounded(x), Bounded(x, std::fabs(x) * 0x1p-20)}) {
            for (const Bounded& r : {Bounded(0) * y, y * Bounded(0), Bounded(0) / y}) {
                EXPECT_TRUE(r.exact_zero()) << show(y) << " gave " << show(r);
            }
        }
        EXPECT_TRUE((Bounded(x) - Bounded(x)).exact_zero());
        EXPECT_TRUE((Bounded(-x) + Bounded(x)).exact_zero());
        UncertaintyScope scope;
        EXPECT_FALSE(Bounded(0) * Bounded(x) < Bounded(0));
        EXPECT_TRUE(Bounded(0) * Bounded(x) <= Bounded(0));
        EXPECT_TRUE(scope.certain());
    }
    EXPECT_TRUE(sqrt(Bounded(0)).exact_zero());
    // A product that underflows is not known to be zero: its sign is undecided.
    const Bounded tiny = Bounded(1e-200) * Bounded(1e-200);
    UncertaintyScope scope;
    (void)(Bounded(0) < tiny);
    EXPECT_FALSE(scope.certain());
}

TEST(Bounded, OverflowAndNanAreUndecidedNeverWrong) {
    const Bounded big = Bounded(dmax) * Bounded(2.0);
    const Bounded unbounded = big - big;
    const Bounded nan = Bounded(1.0) / Bounded(1.0, 1.0);  // divisor may be 0
    for (const Bounded& x : {big, unbounded, nan, sqrt(Bounded(-1.0, 0.5)), Bounded(0) * big + big}) {
        for (int k = 0; k < 4; ++k) {
            UncertaintyScope s;
            switch (k) {
                case 0: (void)(x < Bounded(0)); break;
                case 1: (void)(Bounded(0) <= x); break;
                case 2: (void)(x == x); break;
                case 3: (void)(x > Bounded(-1)); break;
            }
            EXPECT_FALSE(s.certain()) << show(x) << " comparison " << k;
        }
    }
}

// abs and clamp enclose without deciding a sign; a certainly-outside clamp returns the bound itself.
TEST(Bounded, AbsAndClampEnclose) {
    UncertaintyScope scope;
    const Bounded near_zero(0x1p-60, 0x1p-50);  // sign unknown
    const Bounded a = abs_value(near_zero);
    EXPECT_TRUE(encloses(a, q(0x1p-50)));
    EXPECT_TRUE(encloses(a, q(0)));
    const Bounded e(2.0);
    EXPECT_EQ(clamp_symmetric(Bounded(1e30, 1e20), e).value(), 2.0);     // far outside: exactly e
    EXPECT_EQ(clamp_symmetric(Bounded(1e30, 1e20), e).error(), 0.0);
    EXPECT_EQ(clamp_symmetric(Bounded(-1e30, 1e20), e).value(), -2.0);
    const Bounded inside = clamp_symmetric(Bounded(1.0, 0x1p-40), e);
    EXPECT_TRUE(encloses(inside, q(1.0) + q(0x1p-40)));
    const Bounded edge = clamp_symmetric(Bounded(2.0, 0x1p-40), e);  // at the bound: either side
    EXPECT_TRUE(encloses(edge, q(2.0)));
    EXPECT_TRUE(encloses(edge, q(2.0) - q(0x1p-40)));
    EXPECT_TRUE(clamp_symmetric(Bounded(0.5, 0.25), Bounded(0)).exact_zero());  // an exact 0 extent
    EXPECT_TRUE(scope.certain());
}

}  // namespace
}  // namespace boxcyl
