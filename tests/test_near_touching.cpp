// The filtered query's middle stage: DoubleDouble (include/boxcyl/number/double_double.hpp), the
// double-double numbers with a running error bound it runs §4 on, and the default query on the
// near-touching sets (tests/support/near_touching.hpp).
//  * DoubleDouble: every +, −, ×, ÷, sqrt of random operands across the double range (zero, subnormal,
//    tiny, huge; double-doubles with a low part; operands that already carry an error) keeps the exact
//    result within [lo(), hi()] (GMP rationals, Q(√d) for sqrt); long random chains too; exact sums and
//    products of doubles stay exact; overflow and NaN are undecided, never wrong; comparisons decide
//    differences far below double's ulp. TwoProd is exact by each of its routes (Dekker's product, the
//    FMA chosen at run time).
//  * DoubleDoubleValue (number/double_double_value.hpp): DoubleDouble's values without the bound.
//  * The default query equals the oracle on the exactly touching shapes and their one-ulp neighbours,
//    on the adversarial near-touching mix and on one-ulp boundary pairs (of the mixed and of the
//    uniform profile), in all four rounding modes
//    (the middle stage declines outside round-to-nearest; the answers must not change). Built a second
//    time with FMA contraction forced on (tests/CMakeLists.txt: test_near_touching_fma).
//  * The hint that orders the middle stage before stage 1's Bounded run near touching
//    (looks_near_touching: witness_search::near_touching, then answer_moves) on contacts, on boundary
//    pairs only the second shows, and on queries far from touching.
//  * The clipped-candidates test alone (filtered/clipped_candidates.hpp, the middle stage's method for
//    rotated frames): every answer it gives equals the oracle, on rotated boxes whose face, edge or vertex
//    a cylinder touches up to a few ulps (axis parallel to a box edge, to a face, or oblique; solid, flat
//    and segment boxes; disks), on random queries and on one-ulp boundary pairs; and it decides every
//    one whose gap is a few ulps.
#include <gtest/gtest.h>

#include <cfenv>   // rounding modes
#include <cmath>   // std::ldexp, std::fabs
#include <cstdio>  // std::printf
#include <optional>  // the clipped test's undecided
#include <random>  // operand generators
#include <string>  // messages
#include <vector>  // case lists

#include "boxcyl/filtered.hpp"
#include "boxcyl/number/double_double.hpp"
#include "boxcyl/number/double_double_value.hpp"
#include "support/cases.hpp"
#include "support/enclosure.hpp"
#include "support/fp.hpp"
#include "support/runner.hpp"
#include "support/near_touching.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;
using DD = DoubleDouble;

Rational q(double x) { return to_rational(x); }
Rational value(const DD& x) { return q(x.high()) + q(x.low()); }
std::string show(const DD& r) { return hex(r.high()) + " + " + hex(r.low()) + " ± " + hex(r.error()); }

bool finite(const DD& r) { return std::isfinite(r.high()) && std::isfinite(r.low()) && std::isfinite(r.error()); }
bool unusable_and_undecided(const DD& r) {
    UncertaintyScope scope;
    (void)(r < DD(0.0));
    (void)(DD(0.0) < r);
    (void)(r <= DD(1e300));
    return !scope.certain();
}
// lo() ≤ x ≤ hi() for the exact rational x, and the value within error() of x.
bool encloses(const DD& r, const Rational& x) {
    if (!finite(r)) return unusable_and_undecided(r);
    const double lo = r.lo(), hi = r.hi();
    if (lo != lo || hi != hi) return false;
    const bool lo_ok = lo == -inf || (lo != inf && q(lo) <= x);
    const bool hi_ok = hi == inf || (hi != -inf && x <= q(hi));
    const Rational d = value(r) - x;
    const bool bound_ok = (d < Rational(0) ? Rational(0) - d : d) <= q(r.error()) * Rational(1 + 0x1p-30);
    return lo_ok && hi_ok && bound_ok;
}

// A double-double operand: a double, or hi + lo with lo a fraction of ulp(hi) (normalised), with or
// without an error.
DD operand(std::mt19937_64& rng) {
    const double hi = random_operand(rng);
    double lo = 0;
    if (rng() % 2 && hi != 0 && std::fabs(hi) > 0x1p-960 && std::fabs(hi) < 0x1p1000)
        lo = hi * std::ldexp(double(rng() % 1000) / 1000 - 0.5, -53);
    double e = 0;
    switch (rng() % 4) {
        case 0: break;
        case 1: e = std::fabs(hi) * 0x1p-90; break;
        case 2: e = std::fabs(hi) * 0x1p-30 + denorm; break;
        default: e = std::ldexp(1.0, -1074 + static_cast<int>(rng() % 40)); break;
    }
    return {hi, lo, e};
}
// Exact points of an operand: its value and both ends of its error.
void points_of(const DD& b, Rational out[3]) {
    out[0] = value(b);
    out[1] = value(b) - q(b.error());
    out[2] = value(b) + q(b.error());
}

TEST(DoubleDouble, RandomOperationsEnclose) {
    ASSERT_TRUE(detail::round_to_nearest());
    std::mt19937_64 rng(7101);
    long checks = 0, undecided = 0;
    for (int n = 0; n < 20000; ++n) {
        const DD a = operand(rng), b = operand(rng);
        Rational pa[3], pb[3];
        points_of(a, pa);
        points_of(b, pb);
        const DD sum = a + b, diff = a - b, prod = a * b;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                ++checks;
                EXPECT_TRUE(encloses(sum, pa[i] + pb[j])) << show(a) << " + " << show(b) << " = " << show(sum);
                EXPECT_TRUE(encloses(diff, pa[i] - pb[j])) << show(a) << " - " << show(b) << " = " << show(diff);
                EXPECT_TRUE(encloses(prod, pa[i] * pb[j])) << show(a) << " * " << show(b) << " = " << show(prod);
            }
        {
            UncertaintyScope scope;
            const DD quot = a / b;
            if (!scope.certain()) {
                ++undecided;
            } else {
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) {
                        if (pb[j] == Rational(0)) continue;
                        EXPECT_TRUE(encloses(quot, pa[i] / pb[j])) << show(a) << " / " << show(b) << " = " << show(quot);
                    }
            }
        }
        {
            UncertaintyScope scope;
            const DD root = sqrt(a);
            if (scope.certain() && finite(root)) {
                for (int i = 0; i < 3; ++i) {
                    if (pa[i] < Rational(0)) continue;
                    EXPECT_TRUE(sqrt_enclosed(pa[i], root.lo(), root.hi())) << "sqrt " << show(a) << " = " << show(root);
                }
            }
        }
    }
    std::printf("  %ld enclosure checks, %ld undecided quotients\n", checks, undecided);
}

// Long chains: the bounds' own rounding stays covered.
TEST(DoubleDouble, ChainsEnclose) {
    std::mt19937_64 rng(7102);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int n = 0; n < 300; ++n) {
        DD x(u(rng));
        Rational exact = q(x.high());
        for (int k = 0; k < 200; ++k) {
            const double y = u(rng);
            switch (rng() % 3) {
                case 0: x = x + DD(y), exact = exact + q(y); break;
                case 1: x = x - DD(y) * DD(y), exact = exact - q(y) * q(y); break;
                default:
                    x = x * DD(0.5 + std::fabs(y) / 4), exact = exact * q(0.5 + std::fabs(y) / 4);
                    break;
            }
            ASSERT_TRUE(encloses(x, exact)) << "chain " << n << " step " << k << ": " << show(x);
        }
    }
}

TEST(DoubleDouble, ExactStaysExact) {
    const DD a(0.1), b(3.0);
    EXPECT_EQ((a + b).error(), 0.0);
    EXPECT_EQ((a * b).error(), 0.0);
    EXPECT_EQ(value(a * b), q(0.1) * q(3.0));
    EXPECT_EQ(value(a + b), q(0.1) + q(3.0));
    const DD z = a * b - b * a;
    EXPECT_TRUE(z.exact_zero()) << show(z);
    UncertaintyScope scope;
    EXPECT_FALSE(z < DD(0.0));
    EXPECT_TRUE(z <= DD(0.0));
    EXPECT_TRUE(scope.certain());
}

// TwoProd's error term by every route the build has: Dekker's product always, the processor's FMA where
// the build chooses it at run time (x86-64 without -mfma) or compile time. p + e = a·b exactly, on
// operands of random significands whose products neither overflow nor underflow.
TEST(DoubleDouble, TwoProdIsExactByEveryRoute) {
    std::mt19937_64 rng(7103);
    std::uniform_real_distribution<double> significand(1.0, 2.0);
    auto draw = [&] { return std::ldexp(significand(rng), static_cast<int>(rng() % 800) - 400) * (rng() % 2 ? 1 : -1); };
    for (int n = 0; n < 50000; ++n) {
        const double a = draw(), b = draw();
        const Rational exact = q(a) * q(b);
        double p, e;
        detail::dd::two_prod(a, b, p, e);
        ASSERT_EQ(q(p) + q(e), exact) << "two_prod(" << hex(a) << ", " << hex(b) << ")";
        ASSERT_EQ(q(p) + q(detail::dd::dekker_error(a, b, p)), exact) << "dekker_error(" << hex(a) << ", " << hex(b) << ")";
#if BOXCYL_DD_RUNTIME_FMA
        if (detail::dd::has_fma) {
            ASSERT_EQ(q(p) + q(detail::dd::fma_minus(a, b, p)), exact) << "fma_minus(" << hex(a) << ", " << hex(b) << ")";
        }
#endif
    }
}

// DoubleDoubleValue, the same arithmetic without the bound: +, − and × give DoubleDouble's values
// exactly; ÷ and √ values within 2^-100 of the exact result, relatively (one correction of the
// double's), wherever the result lies well inside the normal range.
TEST(DoubleDoubleValue, IsDoubleDoubleWithoutTheBound) {
    ASSERT_TRUE(detail::round_to_nearest());
    std::mt19937_64 rng(7104);
    using W = DoubleDoubleValue;
    auto same = [](const W& w, const DD& d) { return w.high() == d.high() && w.low() == d.low(); };
    auto rational = [](const W& w) -> Rational { return q(w.high()) + q(w.low()); };  // not an expression template
    auto within = [](const Rational& x, const Rational& exact, double rel) {
        const Rational magnitude = exact < Rational(0) ? Rational(Rational(0) - exact) : exact;
        const Rational d = x - exact, bound = q(rel) * magnitude;
        return d <= bound && Rational(0) - d <= bound;
    };
    auto normal = [](double x) { return std::fabs(x) >= 0x1p-900 && std::fabs(x) <= 0x1p900; };
    long quotients = 0, roots = 0;
    for (int n = 0; n < 20000; ++n) {
        const DD da = operand(rng), db = operand(rng);
        const DD a(da.high(), da.low(), 0.0), b(db.high(), db.low(), 0.0);
        const W wa(a), wb(b);
        const std::string ops = show(a) + ", " + show(b);
        if (finite(a + b)) {
            EXPECT_TRUE(same(wa + wb, a + b)) << "sum of " << ops;
        }
        if (finite(a - b)) {
            EXPECT_TRUE(same(wa - wb, a - b)) << "difference of " << ops;
        }
        if (finite(a * b)) {
            EXPECT_TRUE(same(wa * wb, a * b)) << "product of " << ops;
        }
        if (normal(a.high()) && normal(b.high()) && normal(a.high() / b.high())) {
            ++quotients;
            EXPECT_TRUE(within(rational(wa / wb), value(a) / value(b), 0x1p-100)) << "quotient of " << ops;
        }
        if (a.high() > 0 && normal(a.high())) {
            ++roots;
            const Rational s = rational(sqrt(wa));  // |s − √a| ≤ 2^-100·√a ⇐ |s² − a| ≤ 2^-99·a, about
            EXPECT_TRUE(within(s * s, value(a), 0x1p-98)) << "square root of " << show(a);
        }
    }
    EXPECT_GT(quotients, 1000);
    EXPECT_GT(roots, 1000);
}

TEST(DoubleDouble, DecidesFarBelowAnUlp) {
    // (1 + 2^-52)² − (1 + 2^-51) = 2^-104: far below double's resolution, decided here.
    const DD x = DD(1 + 0x1p-52) * DD(1 + 0x1p-52) - DD(1 + 0x1p-51);
    UncertaintyScope scope;
    EXPECT_TRUE(DD(0.0) < x) << show(x);
    EXPECT_TRUE(scope.certain());
    // √(1 + 2^-52)² is 1 + 2^-52, decided against its neighbours 2^-100 away.
    const DD s = sqrt(DD(1 + 0x1p-52) * DD(1 + 0x1p-52));
    EXPECT_TRUE(DD(1 + 0x1p-52) - DD(0x1p-90) < s && s < DD(1 + 0x1p-52) + DD(0x1p-90)) << show(s);
    EXPECT_TRUE(scope.certain());
}

TEST(DoubleDouble, OverflowIsUndecided) {
    const DD big(dmax);
    const DD p = big * big;
    EXPECT_TRUE(unusable_and_undecided(p)) << show(p);
    const DD s = big + big;
    EXPECT_TRUE(unusable_and_undecided(s)) << show(s);
    UncertaintyScope scope;
    (void)(DD(1.0) / DD(0.0));
    EXPECT_FALSE(scope.certain());
}

TEST(DoubleDouble, ProbeSeesTheRoundingMode) {
    EXPECT_TRUE(detail::round_to_nearest());
    for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        const RoundingMode guard(mode);
        EXPECT_FALSE(detail::round_to_nearest()) << mode_name(mode);
    }
}

// ---- The clipped-candidates test (rotated frames) ----

std::optional<bool> clipped_answer(const OrientedBox<double>& b, const Cylinder<double>& c) {
    return filtered::enclosed::clipped_candidates(b, c, filtered::scale_exponent(filtered::largest_length(b, c)));
}

// A rounded rotation, a box on it, and a cylinder placed against its face k (side parallel to the face
// when `parallel`, else an oblique axis touching with its rim), then moved by `ulps` ulps of its radius.
Case rotated_contact(std::mt19937_64& rng, int shape, int ulps_moved) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Case c;
    c.kind = BoxKind::oriented;
    c.oriented.axes = random_rotation(rng);
    c.oriented.center = {unit(rng) * 8 - 4, unit(rng) * 8 - 4, unit(rng) * 8 - 4};
    c.oriented.extents = {0.5 + unit(rng), 0.5 + unit(rng), 0.5 + unit(rng)};
    const int k = static_cast<int>(rng() % 3), a = (k + 1) % 3, b = (k + 2) % 3;
    if (shape == 3) c.oriented.extents[static_cast<std::size_t>(b)] = 0;  // flat: the face k is a segment's strip
    if (shape == 4) c.oriented.extents[static_cast<std::size_t>(b)] = c.oriented.extents[static_cast<std::size_t>(a)] = 0;
    c.cylinder.radius = 0.25 + unit(rng);
    c.cylinder.height = shape == 2 ? 0.0 : 0.5 + unit(rng);
    // shape 0: side parallel to the face (axis = a box axis); 1: axis along the face normal (a cap on the
    // face); 2: a disk parallel to the face; 3, 4: side parallel to a flat or segment box's face.
    const bool along_normal = shape == 1 || shape == 2;
    c.cylinder.axis = c.oriented.axes[static_cast<std::size_t>(along_normal ? k : a)];
    const double d = c.oriented.extents[static_cast<std::size_t>(k)] +
                     (along_normal ? 0.5 * c.cylinder.height : c.cylinder.radius);
    for (std::size_t i = 0; i < 3; ++i)
        c.cylinder.center[i] = c.oriented.center[i] + d * c.oriented.axes[static_cast<std::size_t>(k)][i];
    double& moved = along_normal ? c.cylinder.center[rng() % 3] : c.cylinder.radius;
    for (int i = 0; i < std::abs(ulps_moved); ++i)
        moved = std::nextafter(moved, ulps_moved > 0 ? INFINITY : -INFINITY);
    return c;
}

TEST(ClippedCandidates, RotatedContactsAgreeWithOracleAndAreDecided) {
    std::mt19937_64 rng(7301);
    long decided = 0, total = 0, moved = 0, moved_decided = 0;
    for (long i = 0; i < scaled(600); ++i) {
        const int shape = static_cast<int>(i % 5);
        const int ulps_moved = static_cast<int>(rng() % 9) - 4;
        const Case c = rotated_contact(rng, shape, ulps_moved);
        ASSERT_TRUE(validate(c.oriented).ok() && validate(c.cylinder).ok()) << describe(c);
        const std::optional<bool> r = clipped_answer(c.oriented, c.cylinder);
        ++total;
        if (ulps_moved != 0 && shape != 1 && shape != 2) ++moved;
        if (!r) continue;
        ++decided;
        if (ulps_moved != 0 && shape != 1 && shape != 2) ++moved_decided;
        EXPECT_EQ(*r, oracle_answer(c)) << "shape " << shape << ", " << ulps_moved << " ulps: " << describe(c);
    }
    std::printf("  rotated contacts: %ld of %ld decided; moved side contacts: %ld of %ld\n", decided, total,
                moved_decided, moved);
    // A side parallel to a face, moved by 1 to 4 ulps of its radius: a gap of about 2^-52 relative, which
    // the double-double enclosures resolve whatever the edge-parallel degeneracy.
    EXPECT_EQ(moved_decided, moved);
}

TEST(ClippedCandidates, RandomAndBoundaryQueriesAgreeWithOracle) {
    long decided = 0, total = 0;
    auto check = [&](const Case& c) {
        if (c.kind != BoxKind::oriented) return;
        const std::optional<bool> r = clipped_answer(c.oriented, c.cylinder);
        ++total;
        if (!r) return;
        ++decided;
        EXPECT_EQ(*r, oracle_answer(c)) << describe(c);
    };
    CaseGenerator gen(7302);
    for (long i = 0; i < scaled(3000); ++i) check(gen.next());
    CaseGenerator pairs(7303);
    for (long n = 0; n < scaled(150);) {
        Case x, y;
        Parameter p;
        if (!boundary_pair(pairs, x, y, p)) continue;
        check(x), check(y), ++n;
    }
    std::printf("  random and boundary oriented boxes: %ld of %ld decided\n", decided, total);
}

// ---- The order of the stages: the plain-double hint ----

bool hint(const AlignedBox<double>& b, const Cylinder<double>& c) {
    filtered::Prepared<AlignedBox<double>> q(b, c);
    EXPECT_TRUE(q.in_range);
    return q.looks_near();
}

TEST(NearTouchingHint, ContactsAreNearFarQueriesAreNot) {
    const AlignedBox<double> box{{-1, -1, -1}, {1, 1, 1}};
    // Near: the side on a face, a cap on a face, the side on an edge (Pythagorean offsets), the rim on a
    // vertex; each also one ulp away.
    const std::vector<Cylinder<double>> near = {
        {{3, 0, 0}, {0, 0, 1}, 2, 1},
        {{0, 0, 1.5}, {0, 0, 1}, 0.5, 1},
        {{1 + 0.6, 1 + 0.8, 0}, {0, 0, 1}, 1, 1},
        {{1 + 3, 1 + 4, 1.5}, {0, 0, 1}, 5, 1},
        {{3, 0, 0}, {0, 0, 1}, std::nextafter(2.0, 3.0), 1},
        {{0, 0, std::nextafter(1.5, 2.0)}, {0, 0, 1}, 0.5, 1},
    };
    for (const Cylinder<double>& c : near) EXPECT_TRUE(hint(box, c)) << filtered::detail::describe(c);
    // Far: a deep hit, a thin overlap of a fifth of the box, a miss by half the box.
    const std::vector<Cylinder<double>> far = {
        {{0, 0, 0}, {1, 2, 3}, 0.5, 1},
        {{2.8, 0, 0}, {0, 0, 1}, 2, 1},
        {{4, 0, 0}, {0, 1, 1}, 2, 1},
    };
    for (const Cylinder<double>& c : far) EXPECT_FALSE(hint(box, c)) << filtered::detail::describe(c);
    // Near, but shown by no separating axis and not by the axis segment's distance: one-ulp boundary
    // pairs (radius, then height bisected over adjacent doubles) of oblique cylinders against random
    // boxes. The rounded answer changes when the cylinder grows or shrinks by 2^-30 of the scale.
    struct Pair {
        AlignedBox<double> box;
        Cylinder<double> miss, hit;
    };
    const Pair pairs[] = {
        {{{-0x1.0ce9b6ef54438p-2, 0x1.63b1d3777b41ep-2, -0x1.49e3034b4b11ap+0},
          {0x1.c2ff61ffbdf28p-1, 0x1.83d5757564bf8p+0, 0x1.20b5f7cd0bb98p-4}},
         {{-0x1.a0357fdcbabe4p-1, -0x1.e27ef13498603p+0, 0x1.bdbe2bc749c3p-1},
          {-0x1.9f3c36fd30789p-1, 0x1.29a25dd304bd1p-1, 0x1.0dd2d075ada96p-4}, 0x1.539fb43d5534bp+1, 0x1.072d9f5b3023bp-1},
         {{-0x1.a0357fdcbabe4p-1, -0x1.e27ef13498603p+0, 0x1.bdbe2bc749c3p-1},
          {-0x1.9f3c36fd30789p-1, 0x1.29a25dd304bd1p-1, 0x1.0dd2d075ada96p-4}, 0x1.539fb43d5534cp+1, 0x1.072d9f5b3023bp-1}},
        {{{-0x1.c69e268b29d93p+0, -0x1.8d5e636a4470cp+0, -0x1.aa99449209723p-2},
          {-0x1.7fa9460cc1b6p-5, 0x1.18b57afdd1682p-2, 0x1.ed32093977f3ep-3}},
         {{-0x1.28083ba462dap-3, -0x1.774bf573d4142p+0, -0x1.5178875d5f264p-1},
          {0x1.9e60aac0a28dap-2, 0x1.5968981333d42p-2, 0x1.b3308cc86a12bp-1}, 0x1.c84d68a853c4bp-2, 0x1.e1592685d8e7p-5},
         {{-0x1.28083ba462dap-3, -0x1.774bf573d4142p+0, -0x1.5178875d5f264p-1},
          {0x1.9e60aac0a28dap-2, 0x1.5968981333d42p-2, 0x1.b3308cc86a12bp-1}, 0x1.c84d68a853c4bp-2, 0x1.e1592685d8e71p-5}},
    };
    for (const Pair& pair : pairs)
        for (const Cylinder<double>& c : {pair.miss, pair.hit}) {
            filtered::semi_static::Problem p;
            ASSERT_TRUE(filtered::semi_static::problem(pair.box, c, p));
            EXPECT_FALSE(filtered::witness_search::near_touching(p, filtered::semi_static::aligned_kappas)) << filtered::detail::describe(c);
            EXPECT_TRUE(filtered::answer_moves(pair.box, c, filtered::largest_length(pair.box, c))) << filtered::detail::describe(c);
            EXPECT_TRUE(hint(pair.box, c)) << filtered::detail::describe(c);
            Case k;
            k.kind = BoxKind::aligned;
            k.aligned = pair.box;
            k.cylinder = c;
            EXPECT_EQ(filtered::intersects(pair.box, c), oracle_answer(k)) << describe(k);
        }
    EXPECT_FALSE(filtered::intersects(pairs[0].box, pairs[0].miss));
    EXPECT_TRUE(filtered::intersects(pairs[0].box, pairs[0].hit));
}

// ---- The default query on the near-touching sets ----

filtered::Result run(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::query(b, cyl); });
}

struct Set {
    std::string name;
    std::vector<Case> cases;
    std::vector<bool> want;
};

const std::vector<Set>& sets() {
    static const std::vector<Set> s = [] {
        std::vector<Set> r;
        {
            Set t{"touching", {}, {}};
            std::mt19937_64 rng(7201);
            for (long i = 0; i < scaled(1500); ++i) t.cases.push_back(touching_case(rng));
            r.push_back(std::move(t));
        }
        {
            Set a{"adversarial", {}, {}};
            std::mt19937_64 rng(7202);
            for (long i = 0; i < scaled(1500); ++i) a.cases.push_back(adversarial_case(rng));
            r.push_back(std::move(a));
        }
        {
            CaseGenerator gen(7203);
            r.push_back(Set{"boundary", boundary_pairs(gen, static_cast<std::size_t>(scaled(100))), {}});
        }
        {
            CaseGenerator gen(7204, Profile::uniform);  // boundary pairs of plain data
            r.push_back(Set{"uniform-bnd", boundary_pairs(gen, static_cast<std::size_t>(scaled(100))), {}});
        }
        for (Set& set : r)
            for (const Case& c : set.cases) set.want.push_back(oracle_answer(c));
        return r;
    }();
    return s;
}

TEST(NearTouchingSets, CasesAreValid) {
    for (const Set& s : sets())
        for (const Case& c : s.cases) {
            const bool ok = with_box(c, [](const auto& b, const Cylinder<double>& cyl) {
                return validate(b).ok() && validate(cyl).ok();
            });
            EXPECT_TRUE(ok) << s.name << ": " << describe(c);
        }
}

// Failures found while building the middle stage, kept as regressions (none yet disagreed).
const std::vector<Case> regressions = {};

TEST(NearTouchingSets, Regressions) {
    for (const Case& c : regressions) EXPECT_EQ(run(c).intersect, oracle_answer(c)) << describe(c);
}

class NearTouchingRounding : public ::testing::TestWithParam<int> {};

TEST_P(NearTouchingRounding, AgreesWithOracle) {
    const int mode = GetParam();
    for (const Set& s : sets()) {
        long wrong = 0, exact = 0, hits = 0;
        {
            const RoundingMode guard(mode);
            for (std::size_t i = 0; i < s.cases.size(); ++i) {
                const filtered::Result r = run(s.cases[i]);
                exact += r.exact_used;
                hits += r.intersect;
                if (r.intersect != s.want[i]) {
                    ++wrong;
                    ADD_FAILURE() << s.name << " case " << i << " (rounding " << mode_name(mode) << "): answered "
                                  << r.intersect << "\n  " << describe(s.cases[i]);
                }
            }
        }
        std::printf("  %-12s %-12s cases %5zu  hits %5ld  exact fallbacks %5ld  wrong %ld\n", s.name.c_str(),
                    mode_name(mode), s.cases.size(), hits, exact, wrong);
        EXPECT_EQ(wrong, 0);
    }
}

INSTANTIATE_TEST_SUITE_P(RoundingModes, NearTouchingRounding,
                         ::testing::Values(FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO),
                         [](const auto& info) { return std::string(mode_name(info.param)); });

}  // namespace
}  // namespace boxcyl
