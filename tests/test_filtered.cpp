// The filtered exact query (include/boxcyl/filtered.hpp) and the interval arithmetic it
// rests on (include/boxcyl/number/interval.hpp).
//  * Interval: every +, −, ×, ÷, sqrt of random operands (zero, subnormal, tiny, huge, negative) and of
//    random intervals encloses the exact result (GMP rationals, Q(√d) for sqrt), in every IEEE rounding
//    mode; comparisons are certain only when they should be; exact zeros stay exact; ±∞ and NaN are
//    undecided, never wrong.
//  * filtered::query agrees with the oracle on 100% of the random, boundary (one-ulp pairs), degenerate
//    (2^±600), extreme (2^±1000, subnormal) and non-orthonormal-frame sets, and falls back rarely.
// The same file builds three executables (tests/CMakeLists.txt): test_filtered, test_filtered_checked
// (BOXCYL_CHECK_FILTER: every stage-1 answer is re-checked by stage 2 inside the library) and
// test_filtered_forced (BOXCYL_FORCE_EXACT: stage 2 only), the two variants with a quarter of the cases.
// Case counts scale with BOXCYL_TEST_SCALE (100 for the long run: 10,000,000 random cases).
#include <gtest/gtest.h>

#include <algorithm>  // std::max
#include <bit>        // std::bit_cast: random doubles
#include <cfenv>      // rounding modes
#include <cmath>      // std::ldexp, std::fabs
#include <cstdio>     // std::printf
#include <limits>     // special values
#include <optional>   // stage 1's answer
#include <random>     // operand generators
#include <string>     // labels
#include <vector>     // regression lists

#include "boxcyl/filtered.hpp"
#include "boxcyl/number/interval.hpp"
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"
#include "support/cases.hpp"
#include "support/enclosure.hpp"
#include "support/fp.hpp"
#include "support/numeric.hpp"
#include "support/runner.hpp"
#include "support/stages.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

#if defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT
constexpr bool forced = true;
#else
constexpr bool forced = false;
#endif
#if defined(BOXCYL_CHECK_FILTER) && BOXCYL_CHECK_FILTER
constexpr const char* variant = "checked";
#elif defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT
constexpr const char* variant = "forced";
#else
constexpr const char* variant = "plain";
#endif

// The debug variants repeat every set with a quarter of the cases: they exist to exercise the
// switches (every stage-1 answer re-checked / stage 2 alone), the plain build carries the counts.
long case_count(long n) {
    const long v = scaled(n);
    return std::string(variant) == "plain" ? v : (v + 3) / 4;
}

Rational q(double x) { return to_rational(x); }

// lo ≤ x ≤ hi for the exact rational x, with infinite bounds allowed.
bool encloses(const Interval& r, const Rational& x) {
    if (r.lo() != r.lo() || r.hi() != r.hi()) return false;
    const bool lo_ok = r.lo() == -inf || (r.lo() != inf && q(r.lo()) <= x);
    const bool hi_ok = r.hi() == inf || (r.hi() != -inf && x <= q(r.hi()));
    return lo_ok && hi_ok;
}

std::string show(const Interval& r) { return "[" + hex(r.lo()) + ", " + hex(r.hi()) + "]"; }

struct EnclosureCount {
    long checks = 0;
};

// Checks op on intervals a, b against the exact op on the exact points pa ∈ a, pb ∈ b.
template <class Op, class Exact>
void check_binary(EnclosureCount& n, const char* name, const Interval& a, const Interval& b, const Rational& pa,
                  const Rational& pb, Op op, Exact exact) {
    const Interval r = op(a, b);
    ++n.checks;
    EXPECT_TRUE(encloses(r, exact(pa, pb))) << name << " of " << show(a) << " and " << show(b) << " gave " << show(r);
}

void check_all_ops(EnclosureCount& n, const Interval& a, const Interval& b, const Rational& pa, const Rational& pb) {
    check_binary(n, "+", a, b, pa, pb, [](const Interval& x, const Interval& y) { return x + y; },
                 [](const Rational& x, const Rational& y) { return Rational(x + y); });
    check_binary(n, "-", a, b, pa, pb, [](const Interval& x, const Interval& y) { return x - y; },
                 [](const Rational& x, const Rational& y) { return Rational(x - y); });
    check_binary(n, "*", a, b, pa, pb, [](const Interval& x, const Interval& y) { return x * y; },
                 [](const Rational& x, const Rational& y) { return Rational(x * y); });
    if (b.lo() > 0 || b.hi() < 0) {
        check_binary(n, "/", a, b, pa, pb, [](const Interval& x, const Interval& y) { return x / y; },
                     [](const Rational& x, const Rational& y) { return Rational(x / y); });
    } else {
        const Interval r = a / b;  // divisor may be 0: the result must be NaN (undecided)
        EXPECT_TRUE(r.lo() != r.lo() && r.hi() != r.hi()) << show(a) << " / " << show(b) << " = " << show(r);
    }
}

// √x enclosed, checked in Q(√x): lo ≤ √x ≤ hi exactly.
void check_sqrt(EnclosureCount& n, const Interval& a, const Rational& pa) {
    const Interval r = sqrt(a);
    ++n.checks;
    if (!(a.lo() >= 0)) {
        EXPECT_TRUE(r.lo() != r.lo()) << "sqrt of " << show(a) << " must be undecided (NaN)";
        return;
    }
    ASSERT_TRUE(r.lo() >= 0) << show(r);
    EXPECT_TRUE(sqrt_enclosed(pa, r.lo(), r.hi())) << "sqrt of " << show(a) << " gave " << show(r);
}

class IntervalEnclosure : public ::testing::TestWithParam<int> {};

// 10,000 random operand pairs (×4 ops, points and intervals) per rounding mode.
TEST_P(IntervalEnclosure, RandomOperandsAreEnclosed) {
    ASSERT_TRUE(fp_environment_ok());
    const int mode = GetParam();
    const RoundingMode guard(mode);
    ASSERT_EQ(std::fegetround(), mode);
    std::mt19937_64 rng(9001 + static_cast<unsigned>(mode));
    EnclosureCount n;
    const long pairs = scaled(10000);
    for (long i = 0; i < pairs; ++i) {
        const double x = random_operand(rng), y = random_operand(rng);
        // Points: the exact result of the two doubles.
        check_all_ops(n, Interval(x), Interval(y), q(x), q(y));
        check_sqrt(n, Interval(std::fabs(x)), q(std::fabs(x)));
        // Intervals [min, max] of two operands each; exact points: the corners and the midpoints.
        const double z = random_operand(rng), w = random_operand(rng);
        const Interval a(std::min(x, z), std::max(x, z)), b(std::min(y, w), std::max(y, w));
        const Rational as[3] = {q(a.lo()), q(a.hi()), Rational((q(a.lo()) + q(a.hi())) / 2)};
        const Rational bs[3] = {q(b.lo()), q(b.hi()), Rational((q(b.lo()) + q(b.hi())) / 2)};
        for (const Rational& pa : as)
            for (const Rational& pb : bs) check_all_ops(n, a, b, pa, pb);
        const Interval abs_a(std::min(std::fabs(x), std::fabs(z)), std::max(std::fabs(x), std::fabs(z)));
        check_sqrt(n, abs_a, q(abs_a.lo()));
        check_sqrt(n, abs_a, q(abs_a.hi()));
        if (HasFailure()) {
            ADD_FAILURE() << "rounding mode " << mode_name(mode) << ", pair " << i << ": " << hex(x) << ", " << hex(y)
                          << ", " << hex(z) << ", " << hex(w);
            return;
        }
    }
    std::printf("interval enclosure, %-12s %ld checks\n", mode_name(mode), n.checks);
}

INSTANTIATE_TEST_SUITE_P(RoundingModes, IntervalEnclosure,
                         ::testing::Values(FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO),
                         [](const auto& info) { return std::string(mode_name(info.param)); });

// Sums of several rounded operations stay enclosed (the widening compounds correctly).
TEST(Interval, ChainedExpressionsAreEnclosed) {
    std::mt19937_64 rng(9100);
    std::uniform_real_distribution<double> u(-4, 4);
    for (int i = 0; i < 2000; ++i) {
        const double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
        const Interval r = Interval(a) * Interval(b) - Interval(c) * Interval(d) + Interval(a) / Interval(3.0);
        const Rational exact = q(a) * q(b) - q(c) * q(d) + q(a) / 3;
        ASSERT_TRUE(encloses(r, exact)) << hex(a) << " " << hex(b) << " " << hex(c) << " " << hex(d);
        // and stays tight: a few ulps of the terms' magnitudes
        EXPECT_LE(r.hi() - r.lo(), 0x1p-48 * (std::fabs(a * b) + std::fabs(c * d) + std::fabs(a) / 3 + 1e-300));
    }
}

// Exact sums are not widened (exactness is checked exactly, in every rounding mode); inexact ones are.
TEST(Interval, ExactSumsStayPoints) {
    for (int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        const RoundingMode guard(mode);
        auto point = [](const Interval& x, double v) { return x.lo() == v && x.hi() == v; };
        volatile double third = 1.0 / 3.0;  // not constant-folded
        const double t = third;
        EXPECT_TRUE(point(Interval(1) + Interval(2), 3)) << mode_name(mode);
        EXPECT_TRUE(point(Interval(t) - Interval(t), 0)) << mode_name(mode);
        EXPECT_TRUE(point(Interval(-t) + Interval(t), 0)) << mode_name(mode);
        EXPECT_TRUE(point(Interval(0.75) - Interval(0.5), 0.25)) << mode_name(mode);
        EXPECT_TRUE(point(Interval(dmax) - Interval(dmax / 2), dmax / 2)) << mode_name(mode);
        EXPECT_TRUE(point(Interval(denorm) + Interval(denorm), 2 * denorm)) << mode_name(mode);
        EXPECT_TRUE(point(Interval(1e300) - Interval(-1e300), 2e300)) << mode_name(mode);
        // Inexact: widened so that the exact sum is strictly inside.
        const Interval s = Interval(1) + Interval(0x1p-60);
        EXPECT_TRUE(encloses(s, q(1) + q(0x1p-60))) << mode_name(mode);
        EXPECT_LT(s.lo(), s.hi()) << mode_name(mode);
        EXPECT_TRUE(encloses(Interval(t) + Interval(0.1), q(t) + q(0.1))) << mode_name(mode);
        const Interval o = Interval(dmax) + Interval(dmax);  // overflow: inexact
        EXPECT_LE(o.lo(), dmax) << mode_name(mode);
        EXPECT_EQ(o.hi(), inf) << mode_name(mode);
    }
}

TEST(Interval, ComparisonsAreCertainOnlyWhenDecided) {
    const Interval a(1, 2), b(3, 4), c(1.5, 3.5);
    {
        UncertaintyScope s;
        EXPECT_TRUE(a < b);
        EXPECT_TRUE(a <= b);
        EXPECT_FALSE(a > b);
        EXPECT_FALSE(b <= a);
        EXPECT_TRUE(b > a);
        EXPECT_FALSE(a == b);
        EXPECT_TRUE(a != b);
        EXPECT_TRUE(Interval(2) == Interval(2));
        EXPECT_TRUE(Interval(2, 2) <= Interval(2, 3));  // touching end points decide ≤
        EXPECT_FALSE(Interval(2, 3) < Interval(1, 2));  // a.lo ≥ b.hi: certainly not <
        EXPECT_TRUE(s.certain());
    }
    for (int k = 0; k < 6; ++k) {
        UncertaintyScope s;
        switch (k) {
            case 0: (void)(a < c); break;
            case 1: (void)(c <= b); break;
            case 2: (void)(Interval(1, 2) < Interval(1.5, 1.5)); break;
            case 3: (void)(Interval(1, 2) == Interval(1, 2)); break;  // not a point: undecided
            case 4: (void)(Interval(2, 2) < Interval(2, 2)); break;   // equal points: < is certainly false
            case 5: (void)(Interval(1, 2) <= Interval(2, 2)); break;  // 1..2 ≤ 2: certain
        }
        EXPECT_EQ(s.certain(), k >= 4) << "comparison " << k;
    }
    // Scopes nest: an inner doubt reaches the outer scope, an outer doubt is not forgotten.
    UncertaintyScope outer;
    {
        UncertaintyScope inner;
        (void)(a < c);
        EXPECT_FALSE(inner.certain());
    }
    EXPECT_FALSE(outer.certain());
    {
        UncertaintyScope inner;
        EXPECT_TRUE(inner.certain());
    }
    EXPECT_FALSE(outer.certain());
}

TEST(Interval, ExactZerosStayExact) {
    const double xs[] = {3.0, -7.25, dmax, denorm, -dmin, 1e-300};
    for (double x : xs) {
        for (const Interval& r : {Interval(0) * Interval(x), Interval(x) * Interval(0), Interval(0) / Interval(x)}) {
            EXPECT_EQ(r.lo(), 0.0);
            EXPECT_EQ(r.hi(), 0.0);
        }
        const Interval s = Interval(x) + Interval(0), d = Interval(x) - Interval(0), e = Interval(0) - Interval(x);
        EXPECT_EQ(s.lo(), x);
        EXPECT_EQ(s.hi(), x);
        EXPECT_EQ(d.lo(), x);
        EXPECT_EQ(e.hi(), -x);
        UncertaintyScope scope;
        EXPECT_FALSE(Interval(0) * Interval(x) < Interval(0));
        EXPECT_TRUE(Interval(0) * Interval(x) <= Interval(0));
        EXPECT_EQ(sign_of(Interval(0) * Interval(x)), 0);
        EXPECT_TRUE(scope.certain());
    }
    // A non-zero result that underflows is not zero: its enclosure straddles 0 and signs are undecided.
    const Interval tiny = Interval(1e-200) * Interval(1e-200);
    EXPECT_LT(tiny.lo(), 0.0);
    EXPECT_GT(tiny.hi(), 0.0);
    UncertaintyScope scope;
    (void)sign_of(tiny);
    EXPECT_FALSE(scope.certain());
}

TEST(Interval, OverflowAndNanAreUndecidedNeverWrong) {
    // Overflow: the bound on the finite side is DBL_MAX, the other +∞; comparisons stay sound.
    const Interval big = Interval(dmax) * Interval(2.0);
    EXPECT_EQ(big.lo(), dmax);
    EXPECT_EQ(big.hi(), inf);
    {
        UncertaintyScope s;
        EXPECT_TRUE(Interval(1) < big);
        EXPECT_TRUE(s.certain());
    }
    {
        UncertaintyScope s;
        (void)(big < big);  // both unbounded above: undecided
        EXPECT_FALSE(s.certain());
    }
    const Interval neg = Interval(-dmax) - Interval(dmax);
    EXPECT_EQ(neg.lo(), -inf);
    EXPECT_EQ(neg.hi(), -dmax);
    // ∞ − ∞ and 0·∞ cannot produce a decided comparison.
    const Interval unbounded = big - big;
    EXPECT_EQ(unbounded.lo(), -inf);
    EXPECT_EQ(unbounded.hi(), inf);
    const Interval nan = Interval(0) * big;  // 0·∞ at a corner
    EXPECT_TRUE(nan.lo() != nan.lo());
    for (const Interval& x : {unbounded, nan, sqrt(Interval(-1.0, 1.0)), Interval(1) / Interval(-1.0, 1.0)}) {
        for (int k = 0; k < 4; ++k) {
            UncertaintyScope s;
            switch (k) {
                case 0: (void)(x < Interval(0)); break;
                case 1: (void)(Interval(0) <= x); break;
                case 2: (void)(x == x); break;
                case 3: (void)(x > Interval(-1)); break;
            }
            EXPECT_FALSE(s.certain()) << show(x) << " comparison " << k;
        }
    }
    // Division of a huge number by a tiny one overflows soundly.
    const Interval q = Interval(dmax) / Interval(denorm);
    EXPECT_EQ(q.lo(), dmax);
    EXPECT_EQ(q.hi(), inf);
}

TEST(Interval, EnvironmentIsTheAssumedOne) { EXPECT_TRUE(fp_environment_ok()); }

// ======================================================================================
// The filtered query against the oracle
// ======================================================================================

filtered::Result run(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return filtered::query(box, cyl); });
}

// What makes a case degenerate for stage 1 (docs/robustness/degenerate.md): a disk (h = 0), a flat
// box (an extent 0), a segment (r = 0), an axis component that is non-zero but below 2^-60 of the
// largest (its share of the unit axis is far below an ulp of the others). Otherwise "regular".
enum Shape { regular, disk, flat, segment, tiny_axis, shape_count };
const char* shape_name(int s) {
    const char* names[] = {"regular", "disk", "flat box", "segment", "tiny axis component"};
    return names[s];
}
int shape_of(const Case& c) {
    if (c.cylinder.height == 0) return disk;
    for (int i = 0; i < 3; ++i) {
        const double e = c.kind == BoxKind::aligned    ? c.aligned.max[i] - c.aligned.min[i]
                         : c.kind == BoxKind::oriented ? c.oriented.extents[i]
                                                       : c.canonical.extents[i];
        if (e == 0) return flat;
    }
    if (c.cylinder.radius == 0) return segment;
    const Vec3<double>& a = c.cylinder.axis;
    const double m = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])});
    for (int i = 0; i < 3; ++i)
        if (a[i] != 0 && std::fabs(a[i]) < std::ldexp(m, -60)) return tiny_axis;
    return regular;
}

// Counts answers and fallbacks (by shape); every answer is checked against the oracle with τ = 0.
struct FilterTally {
    Tally t;
    long exact_used = 0;
    long by_shape[shape_count] = {}, used_by_shape[shape_count] = {};

    void record(const Case& c, const filtered::Result& r) {
        exact_used += r.exact_used;
        ++by_shape[shape_of(c)];
        used_by_shape[shape_of(c)] += r.exact_used;
    }
    void check(const Case& c, bool want, const std::string& where) {
        check_case(t, c, want,
                   [&](const Case& k) {
                       const filtered::Result r = run(k);
                       record(k, r);
                       return r.intersect;
                   },
                   0.0, where);
    }
    double fallback() const { return t.cases ? double(exact_used) / double(t.cases) : 0.0; }
    double fallback(int shape) const {
        return by_shape[shape] ? double(used_by_shape[shape]) / double(by_shape[shape]) : 0.0;
    }
    void print(const std::string& label) const {
        print_tally((label + " [" + variant + "]").c_str(), t);
        std::printf("  exact fallback: %ld of %ld (%.3e);", exact_used, t.cases, fallback());
        for (int s = 0; s < shape_count; ++s)
            if (by_shape[s]) std::printf(" %s %ld/%ld", shape_name(s), used_by_shape[s], by_shape[s]);
        std::printf("\n");
    }
};

// Cases that once failed, or that pin a decision path: kept forever.
const std::vector<Case> regressions = {
    // Axis-aligned cylinder touching an aligned box's face: the filter must fall back, not guess.
    Case{BoxKind::aligned, AlignedBox<double>{{-1, -1, -1}, {1, 1, 1}}, {}, {},
         Cylinder<double>{{3, 0, 0}, {0, 0, 5}, 2, 1}},
    Case{BoxKind::aligned, AlignedBox<double>{{-1, -1, -1}, {1, 1, 1}}, {}, {},
         Cylinder<double>{{3, 0, 0}, {0, 0, 5}, 0x1.fffffffffffffp+0, 1}},
};

// Flat boxes hit away from the cross-sections stage 1's certificates try: they fell back to exact
// arithmetic until the witness search (docs/robustness/stage0.md) certified them; the last five needed
// its finest shrink (0.999) and up to 256 steps. The last one (a thick disk, r ≈ 728 ≫ H ≈ 27, whose
// rim crosses the flat box: the deepest box point is 3.6 inside) needs the cylinder shrunk by the same
// depth along and across the axis: shrunk by a factor, r lost more room than the whole overlap has.
// It cost 590 µs in exact arithmetic, one query of bench_batch's mixed aligned sets.
const std::vector<Case> flat_box_hits = {
    Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.d49fc13a2e63p+5, 0x1.788d1eedda2fp+5, 0x0p+0}},
         Cylinder<double>{{0x1.bdbe665c0a306p+5, -0x1.32f72ce6827ffp+3, -0x1.9c61bf44d62ccp+5},
                          {-0x1.fb2126540867ap-1, 0x1.1af9e198b654cp-1, 0x1.922d2421c2b2p-2}, 0x1.7c62787f4b53dp+5,
                          0x1.03a0dccda844ep+7}},
    Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.73c9c05d93bc1p-4, 0x0p+0, 0x1.7c803d6622de1p-2}},
         Cylinder<double>{{0x1.166c418f968ep-4, -0x1.0b0ed55aa44fep-3, -0x1.3d0724c29b7cbp-4},
                          {0x1.69ec1f0590e8p-1, -0x1.1f2ea2015bb6dp-1, -0x1.81c5ea1ca3e8cp-1}, 0x1.79c5792095f69p-4,
                          0x1.ce854ff0aa325p-3}},
    Case{BoxKind::aligned,
         AlignedBox<double>{{0x1.b7e15ed5090d6p+17, 0x1.2749d9f657ba5p+15, -0x1.efa1e5b95b9acp+18},
                            {0x1.bd07c9426dbcep+19, 0x1.78b18bf7c336ep+16, -0x1.efa1e5b95b9acp+18}},
         {}, {},
         Cylinder<double>{{0x1.aed8a0c6d4418p+19, -0x1.eadb2b8bfd2eap+18, -0x1.153b757460ccp+20},
                          {0x1.b705ba340507ep-3, -0x1.c32496b815e5fp-3, -0x1.3202f8b7946f4p-3}, 0x1.c331b35b5148dp+17,
                          0x1.d908d1f037aabp+20}},
    Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.9ba68c6483096p+13, 0x1.3a57e3fc1a98ap+14, 0x0p+0}},
         Cylinder<double>{{-0x1.72652f5b79dd3p+12, 0x1.3e112218e544ap+12, 0x1.78546ad45d2p+13},
                          {0x1.4040c3e2b80fp-3, 0x1.5c4c7e82ea416p+0, 0x1.247062802c14ap+0}, 0x1.a71c8d6b22657p+13,
                          0x1.659b796020402p+12}},
    Case{BoxKind::aligned,
         AlignedBox<double>{{-0x1.b4c01995d3342p-11, 0x1.5f668070a42bcp-12, 0x1.30f8554100a8p-16},
                            {0x1.01ec77f2fef5cp-12, 0x1.f3bc6bffe19f1p-10, 0x1.30f8554100a8p-16}},
         {}, {},
         Cylinder<double>{{-0x1.5f3dc0a67740ap-11, 0x1.a51d335c1b6d1p-10, -0x1.17122628693e9p-12},
                          {-0x1.fc388c724f784p-2, 0x1.03d238a5fa95cp-2, -0x1.2b0ea35715f2ep-1}, 0x1.2657175b34383p-12,
                          0x1.09e0de054ec17p-12}},
    Case{BoxKind::aligned,
         AlignedBox<double>{{-0x1.76ed60304da88p-5, -0x1.4a4dc4d080792p-1, -0x1.b3174a4636a3p-3},
                            {0x1.09f83b4e32ff1p-2, -0x1.4959534d5f247p-2, -0x1.b3174a4636a3p-3}},
         {}, {},
         Cylinder<double>{{0x1.849174c087a58p-5, -0x1.b3c7242d445f8p-2, -0x1.623d66d369482p-2},
                          {-0x1.07178afd702d8p-3, -0x1.a527d42cf6e9ap-3, -0x1.e93fbf6e1ef0ap-2}, 0x1.5724f14cc8b02p-4,
                          0x1.b7f9d2f997eaep-3}},
    Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.358eeab345e0fp+18, 0x0p+0, 0x1.5387e52b68db6p+18}},
         Cylinder<double>{{0x1.79584d358c91ep+16, -0x1.36cc349ecc713p+16, 0x1.ffdcfa9901a24p+16},
                          {0x1.3cb91dd4b2298p-3, -0x1.e14b3d45646f4p-1, 0x1.a722f7cde7e94p-1}, 0x1.eab81c3f5e16ap+13,
                          0x1.716feacc65995p+17}},
    Case{BoxKind::aligned,
         AlignedBox<double>{{-0x1.0e313e534735bp+11, -0x1.5adf34256e7dp+5, 0x1.8bc67e97a24eep+7},
                            {-0x1.7af255fee9853p+9, 0x1.43c149713c79cp+10, 0x1.8bc67e97a24eep+7}},
         {}, {},
         Cylinder<double>{{-0x1.932d7c5263efbp+8, 0x1.144856341cfecp+7, -0x1.18d8ec8e26fecp+8},
                          {0x1.476011725ae7p+0, -0x1.e4d7be2fb1e38p-2, 0x1.a835028ac67b4p+0}, 0x1.6bffc425fff06p+9,
                          0x1.b73fd92a77adfp+5}},
};

TEST(Filtered, WitnessSearchCertifiesFlatBoxHits) {
    for (std::size_t i = 0; i < flat_box_hits.size(); ++i) {
        const Case& c = flat_box_hits[i];
        ASSERT_TRUE(oracle_answer(c)) << i;
        const bool certified = c.kind == BoxKind::aligned ? thorough_hit(c.aligned, c.cylinder)
                                                          : thorough_hit(c.canonical, c.cylinder);
        EXPECT_TRUE(certified) << "flat box hit " << i << "\n  " << describe(c);
        const filtered::Result r = run(c);
        EXPECT_TRUE(r.intersect) << i;
        if (!forced) {
            EXPECT_FALSE(r.exact_used) << "flat box hit " << i << " fell back to exact arithmetic";
        }
    }
}

TEST(Filtered, Regressions) {
    FilterTally f;
    for (std::size_t i = 0; i < regressions.size(); ++i)
        f.check(regressions[i], oracle_answer(regressions[i]), "regression " + std::to_string(i));
    EXPECT_EQ(f.t.disagreements, 0);
}

// 4 shards × 25,000 = 100,000 random cases (×100 under BOXCYL_TEST_SCALE=100: 10,000,000).
class FilteredRandom : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(FilteredRandom, AgreesWithOracle) {
    ASSERT_TRUE(fp_environment_ok());
    const std::uint64_t seed = GetParam();
    CaseGenerator gen(seed);
    FilterTally f;
    const long n = case_count(25000);
    for (long i = 0; i < n; ++i) {
        const Case c = gen.next();
        f.check(c, oracle_answer(c), "seed " + std::to_string(seed) + " case " + std::to_string(i));
    }
    f.print("filtered random, seed " + std::to_string(seed));
    EXPECT_EQ(f.t.disagreements, 0);
    EXPECT_GT(f.t.hits, n / 5);
    EXPECT_LT(f.t.hits, n * 4 / 5);
    if (!forced) {
        // Measured 0–1 in 100,000 (without the witness search 0.03%, all flat boxes;
        // docs/robustness/degenerate.md); the bound leaves room for other seeds. The hit certificates keep disks and segments off
        // too.
        EXPECT_LT(f.fallback(), 2e-4);
        EXPECT_LT(f.fallback(regular), 0.0005);
        EXPECT_LT(f.fallback(disk), 0.002);
        EXPECT_LT(f.fallback(segment), 0.002);
    }
}

INSTANTIATE_TEST_SUITE_P(Shards, FilteredRandom, ::testing::Values(4401u, 4402u, 4403u, 4404u));

TEST(Filtered, BoundaryPairsAgreeWithOracle) {
    const std::uint64_t seed = 4501;
    CaseGenerator gen(seed);
    FilterTally f;
    for_each_boundary_pair(gen, seed, case_count(300), [&](const Case& a, bool wa, const Case& b, bool wb, const std::string& where) {
        f.check(a, wa, where);
        f.check(b, wb, where);
    });
    f.print("filtered boundary pairs");
    EXPECT_EQ(f.t.disagreements, 0);
}

TEST(Filtered, DegenerateProfileAgreesWithOracle) {
    const std::uint64_t seed = 4601;
    CaseGenerator gen(seed, Profile::degenerate);
    FilterTally f;
    const long n = case_count(3000);
    for (long i = 0; i < n; ++i) {
        const Case c = gen.next();
        f.check(c, oracle_answer(c), "degenerate seed 4601 case " + std::to_string(i));
    }
    f.print("filtered degenerate (2^±600)");
    EXPECT_EQ(f.t.disagreements, 0);
}

// Every length of the case multiplied by 2^k (the axis direction is kept): exact unless a value
// overflows (skipped) or becomes subnormal (then it is a different, still valid, case).
std::optional<Case> rescaled(Case c, int k) {
    auto s = [k](double& x) { x = std::ldexp(x, k); };
    auto sv = [&](Vec3<double>& v) {
        for (int i = 0; i < 3; ++i) s(v[i]);
    };
    sv(c.aligned.min), sv(c.aligned.max), sv(c.oriented.center), sv(c.oriented.extents), sv(c.canonical.extents);
    sv(c.cylinder.center), s(c.cylinder.radius), s(c.cylinder.height);
    const double scale = problem_scale(c);
    if (!(scale < inf)) return std::nullopt;
    for (int i = 0; i < 3; ++i)
        if (c.aligned.max[i] - c.aligned.min[i] == inf) return std::nullopt;  // fine for the exact semantics,
    return c;                                                                 // but keep the set readable
}

// Magnitudes at the ends of the double range: 2^±1000 (tiny sizes become subnormal or 0) — the filter
// must decide correctly or fall back, never answer wrongly.
TEST(Filtered, ExtremeMagnitudesAgreeWithOracle) {
    CaseGenerator gen(4701);
    FilterTally f;
    const long n = case_count(3000);
    const int exps[] = {-1060, -1040, -1000, -900, 900, 1000, 1010};
    long i = 0;
    while (f.t.cases < n) {
        const Case base = gen.next();
        const int k = exps[i % 7];
        ++i;
        const std::optional<Case> c = rescaled(base, k);
        if (!c || !validate(c->cylinder).ok()) continue;
        f.check(*c, oracle_answer(*c),
                "extreme seed 4701 case " + std::to_string(i) + " (2^" + std::to_string(k) + ")");
    }
    f.print("filtered extreme magnitudes (2^±1000)");
    EXPECT_EQ(f.t.disagreements, 0);
}

// The power-of-two scaling of queries out of stage 0's range: random doubles over the whole range
// (subnormals too) times 2^k, |k| ≤ 2044, in every rounding mode. Where std::ldexp is exact (its
// round trip gives x back), times_two_to gives the same double; where it is not, times_two_to's round
// trip does not give x back either — rescaled_exactly relies on exactly that.
TEST(Filtered, PowerOfTwoScalingIsExactOrRejected) {
    std::mt19937_64 rng(4702);
    const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    long exact = 0, rejected = 0;
    for (const int mode : modes) {
        ASSERT_EQ(std::fesetround(mode), 0);
        for (int i = 0; i < 20000; ++i) {
            const double x = std::bit_cast<double>(rng() & 0x7fffffffffffffffULL) * ((rng() & 1) != 0 ? 1 : -1);
            if (!std::isfinite(x)) continue;
            const int k = static_cast<int>(rng() % 4089) - 2044;
            const double reference = std::ldexp(x, k);
            const bool ldexp_exact = std::isfinite(reference) && std::ldexp(reference, -k) == x;
            const double y = filtered::times_two_to(x, k);
            const bool round_trip = filtered::times_two_to(y, -k) == x;
            if (ldexp_exact) {
                ++exact;
                EXPECT_EQ(y, reference) << std::hexfloat << x << " * 2^" << k << ", rounding mode " << mode;
                EXPECT_TRUE(round_trip) << std::hexfloat << x << " * 2^" << k << ", rounding mode " << mode;
            } else {
                ++rejected;
                EXPECT_FALSE(round_trip && std::isfinite(y)) << std::hexfloat << x << " * 2^" << k << ", rounding mode " << mode;
            }
        }
    }
    std::fesetround(FE_TONEAREST);
    EXPECT_GT(exact, 5000);
    EXPECT_GT(rejected, 5000);
}

// Hand-picked huge, tiny and subnormal inputs.
TEST(Filtered, HugeTinyAndSubnormalInputs) {
    FilterTally f;
    const double big = 1e300, small = 1e-300;
    const std::vector<Case> cases = {
        Case{BoxKind::aligned, AlignedBox<double>{{-big, -big, -big}, {big, big, big}}, {}, {},
             Cylinder<double>{{2 * big, 0, 0}, {1, 1, 0}, big, big}},
        Case{BoxKind::aligned, AlignedBox<double>{{-dmax, -dmax, -dmax}, {dmax, dmax, dmax}}, {}, {},
             Cylinder<double>{{dmax, dmax, dmax}, {1, 1, 1}, 0, 0}},
        Case{BoxKind::aligned, AlignedBox<double>{{-dmax, -dmax, -dmax}, {dmax, dmax, dmax}}, {}, {},
             Cylinder<double>{{dmax, dmax, dmax}, {1, 2, 3}, dmax, dmax}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{small, small, small}},
             Cylinder<double>{{3 * small, 0, 0}, {0, 1, 1}, small, small}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{denorm, denorm, 0}},
             Cylinder<double>{{3 * denorm, 0, 0}, {denorm, 1, 0}, 2 * denorm, 0}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{denorm, denorm, denorm}},
             Cylinder<double>{{2 * denorm, 2 * denorm, 0}, {1, 1, 0}, denorm, denorm}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{1, 1, 1}},
             Cylinder<double>{{0, 0, 0}, {denorm, denorm, denorm}, 0, 0}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{1, 1, 1}},
             Cylinder<double>{{0, 0, 1e300}, {denorm, 0, dmax}, 1e300, 1e-300}},
        Case{BoxKind::oriented, {}, OrientedBox<double>{{big, -big, small}, {Vec3<double>{0.6, 0.8, 0},
             Vec3<double>{-0.8, 0.6, 0}, Vec3<double>{0, 0, 1}}, {big, small, denorm}}, {},
             Cylinder<double>{{big, -big, 0}, {1e-300, 3 * denorm, -1}, small, big}},
        Case{BoxKind::oriented, {}, OrientedBox<double>{{0, 0, 0}, {Vec3<double>{0, 0, -1},
             Vec3<double>{1, 0, 0}, Vec3<double>{0, -1, 0}}, {denorm, 2 * denorm, 0}}, {},
             Cylinder<double>{{denorm, denorm, denorm}, {0, 0, 1}, denorm, 0}},
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        ASSERT_TRUE(validate(cases[i].cylinder).ok()) << i;
        f.check(cases[i], oracle_answer(cases[i]), "hand case " + std::to_string(i));
    }
    f.print("filtered hand-picked extremes");
    EXPECT_EQ(f.t.disagreements, 0);
}

// ---- Oriented boxes whose axes are valid but not orthonormal ----


// Stage 1 as the query runs it (Bounded, then Interval), optionally without the η widening.
// A test-only policy: the rounded frame taken as if it were orthonormal (no η), unsound.
struct NoWidening {
    static double eta(double) { return 0; }
};
std::optional<bool> stage1(const Case& c, bool apply_eta) {
    filtered::Prepared<OrientedBox<double>> q(c.oriented, c.cylinder);
    const auto& f = q.facts();
    const double scale = std::ldexp(f.scale, f.k);
    auto run = [&]<class N>(N) -> std::optional<bool> {
        if (apply_eta) return filtered::enclosed::inequalities<N>(q.box, q.cyl, f.k, scale, f.frame);
        return filtered::enclosed::inequalities<N, NoWidening>(q.box, q.cyl, f.k, scale, f.frame);
    };
    if (auto fast = run(Bounded(0.0))) return fast;
    return run(Interval(0.0));
}

TEST(FilteredNonOrthonormal, RandomCasesAgreeWithOracle) {
    CaseGenerator gen(4801);
    FilterTally f;
    const long n = case_count(5000);
    for (long i = 0; i < n; ++i) {
        const Case c = perturbed_frame(gen);
        f.check(c, oracle_answer(c), "perturbed frame seed 4801 case " + std::to_string(i));
    }
    f.print("filtered, perturbed frames (1e-6)");
    EXPECT_EQ(f.t.disagreements, 0);
    if (!forced) {
        EXPECT_LT(f.fallback(), 0.05);
    }
}

// Near the exact boundary, at distances from one ulp up to ~1e-4 of the problem's size, where the
// frame's 1e-6 non-orthogonality matters: the filter must still be exact there (it widens by η), and
// stage 1 WITHOUT η must be caught answering wrongly on some of them (the test has teeth).
TEST(FilteredNonOrthonormal, NearBoundaryNeedsEta) {
    CaseGenerator gen(4802);
    FilterTally f;
    long unsound_wrong = 0, probes = 0;
    const long bases = case_count(60);
    long made = 0;
    while (made < bases) {
        const Case c = perturbed_frame(gen);
        const Parameter which = static_cast<Parameter>(static_cast<int>(gen.uniform(0, 7)));
        const Vec3<double> axis0 = c.cylinder.axis;
        const double s = problem_scale(c);
        double lo = 0, hi = 0;
        switch (which) {
            case Parameter::radius: case Parameter::height: lo = 0; hi = 8 * s; break;
            case Parameter::center_x: case Parameter::center_y: case Parameter::center_z: {
                const int i = static_cast<int>(which) - static_cast<int>(Parameter::center_x);
                lo = c.cylinder.center[i] - 8 * s;
                hi = c.cylinder.center[i];
                break;
            }
            case Parameter::box_shift: lo = c.oriented.center[0] - 8 * s; hi = c.oriented.center[0] + 8 * s; break;
            case Parameter::rotation: lo = 0; hi = 3.14159; break;
        }
        auto answer = [&](double v) { return oracle_answer(with_parameter(c, which, v, axis0)); };
        if (answer(lo) == answer(hi)) continue;
        ++made;
        const auto [x, y] = bisect_ulp(lo, hi, answer);
        const double unit = which == Parameter::rotation ? 1.0 : s;
        for (int j = 14; j <= 54; j += 2) {
            for (double v : {x - std::ldexp(unit, -j), y + std::ldexp(unit, -j), j == 14 ? x : y}) {
                if (which == Parameter::radius || which == Parameter::height) v = std::max(v, 0.0);
                const Case k = with_parameter(c, which, v, axis0);
                const bool want = oracle_answer(k);
                f.check(k, want, "perturbed frame near boundary, seed 4802 base " + std::to_string(made) + " (" +
                                     name(which) + ")");
                ++probes;
                const std::optional<bool> unsound = stage1(k, false);
                unsound_wrong += unsound && *unsound != want;
            }
        }
    }
    f.print("filtered, perturbed frames near the boundary");
    std::printf("  stage 1 without the η widening: %ld wrong answers of %ld probes\n", unsound_wrong, probes);
    EXPECT_EQ(f.t.disagreements, 0);
    EXPECT_GT(unsound_wrong, 0) << "no probe distinguishes the η widening: the test lost its teeth";
}

// Under every rounding mode the filter stays exact (the cases are generated in round-to-nearest).
class FilteredRounding : public ::testing::TestWithParam<int> {};

TEST_P(FilteredRounding, AgreesWithOracle) {
    const int mode = GetParam();
    CaseGenerator gen(4901);
    std::vector<Case> cases;
    std::vector<bool> want;
    const long n = case_count(2000);
    for (long i = 0; i < n; ++i) {
        cases.push_back(i % 4 == 3 ? perturbed_frame(gen) : gen.next());
        want.push_back(oracle_answer(cases.back()));
    }
    FilterTally f;
    {
        const RoundingMode guard(mode);
        for (long i = 0; i < n; ++i) {
            const filtered::Result r = run(cases[i]);
            ++f.t.cases;
            f.t.hits += want[i];
            f.record(cases[i], r);
            if (r.intersect != want[i]) {
                ++f.t.disagreements;
                ADD_FAILURE() << "rounding mode " << mode_name(mode) << " case " << i << "\n  " << describe(cases[i]);
            }
        }
    }
    f.print(std::string("filtered, rounding mode ") + mode_name(mode));
    EXPECT_EQ(f.t.disagreements, 0);
}

INSTANTIATE_TEST_SUITE_P(RoundingModes, FilteredRounding,
                         ::testing::Values(FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO),
                         [](const auto& info) { return std::string(mode_name(info.param)); });

}  // namespace
}  // namespace boxcyl
