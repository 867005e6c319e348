// The certified distance bounds of filtered/separation.hpp (lower ≤ dist(box, cylinder) ≤ upper),
// judged by the independent clearance oracle (tests/clearance/): the box comes within `upper` of the
// cylinder, and not within the double below `lower`. On random pairs of every generator profile, on a
// lattice of small integer shapes (distances often exactly rational), with and without a margin to
// decide at, and in every rounding mode. A violation prints the case as C++ to paste into a test.
#include <gtest/gtest.h>

#include <cfenv>    // rounding modes
#include <cmath>    // std::nextafter, std::isfinite
#include <cstdint>  // seeds
#include <cstdio>   // std::printf
#include <random>   // fixed-seed generators

#include "boxcyl/distance.hpp"  // the distance's search and goal
#include "boxcyl/filtered/separation.hpp"
#include "boxcyl/filtered/separation_refined.hpp"
#include "clearance/clearance_oracle.hpp"
#include "clearance/exact_case.hpp"
#include "clearance/lattice.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"  // RoundingMode

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

// GJK's bounds (intervals), or with `projected` the quick search's (running error bounds).
filtered::separation::Bounds bounds_of(const Case& c, double decide_at, bool projected = false) {
    return with_box(c, [&](const auto& box, const Cylinder<double>& cyl) {
        return projected ? filtered::separation::projected_bounds(box, cyl, decide_at)
                         : filtered::separation::bounds(box, cyl, decide_at);
    });
}

struct Tally {
    long checked = 0, converged = 0, tight = 0;
    int violations = 0;
};

// Both bounds judged; of the separated pairs (lower > 0) searched to convergence (no margin to decide
// at), "tight" counts those whose bounds are within 2^-20 of each other, relatively.
void judge(const Case& c, double decide_at, Tally& t, bool projected = false) {
    const filtered::separation::Bounds b = bounds_of(c, decide_at, projected);
    const Parallelepiped<Rational> box = exact_box(c);
    const Cylinder<Rational> cyl = to_exact(c.cylinder);
    ++t.checked;
    bool ok = true;
    if (std::isfinite(b.upper) && !clearance_oracle::within(box, cyl, to_rational(b.upper))) ok = false;
    if (b.lower > 0 && clearance_oracle::within(box, cyl, to_rational(std::nextafter(b.lower, 0.0)))) ok = false;
    if (!(b.lower >= 0) || !(b.lower <= b.upper || b.upper != b.upper)) ok = false;
    if (!ok && ++t.violations <= 5)
        ADD_FAILURE() << (projected ? "projected " : "") << "bounds [" << hex(b.lower) << ", " << hex(b.upper)
                      << "] (decide_at " << hex(decide_at) << ") do not hold for\n" << describe(c);
    if (decide_at < 0 && b.lower > 0) {
        ++t.converged;
        if (b.upper - b.lower <= 0x1p-20 * b.upper) ++t.tight;
    }
}

TEST(SeparationJudged, RandomPairsEveryProfile) {
    Tally t;
    for (Profile p : {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        const std::uint64_t seed = 0x5e9a0100 + static_cast<std::uint64_t>(p);
        CaseGenerator gen(seed, p);
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int i = 0; i < (p == Profile::magnitudes ? 20 : 150); ++i) {
            const Case c = gen.next();
            judge(c, -1, t);
            judge(c, unit(rng) * (c.cylinder.radius + c.cylinder.height), t);
        }
    }
    std::printf("random pairs: %ld bounds judged, %ld of %ld separated ones tight, %d violations\n", t.checked, t.tight,
                t.converged, t.violations);
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(t.tight, t.converged * 9 / 10);
}

// The quick search's bounds (projected_bounds: running error bounds): proved on both sides without a
// margin, and at margins around the distance (0.9, 0.999, 1.001 and 1.1 times GJK's estimate) where
// only a clear side is proved; random pairs of every profile, then in every rounding mode.
TEST(SeparationJudged, ProjectedBoundsRandomPairs) {
    Tally t;
    int decided = 0;
    for (Profile p : {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        CaseGenerator gen(0x5e9a0500 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < (p == Profile::magnitudes ? 10 : 50); ++i) {
            const Case c = gen.next();
            judge(c, -1, t, true);
            const double d = bounds_of(c, -1).upper;
            if (!std::isfinite(d)) continue;
            for (const double f : {0.9, 0.999, 1.001, 1.1}) {
                const filtered::separation::Bounds b = bounds_of(c, f * d, true);
                decided += b.lower > f * d || b.upper <= f * d;
                judge(c, f * d, t, true);
            }
        }
    }
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::degenerate}) {
        CaseGenerator gen(0x5e9a0600 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < 25; ++i) {
            const Case c = gen.next();
            for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
                filtered::separation::Bounds b{};
                {
                    const RoundingMode scope(mode);
                    b = bounds_of(c, -1, true);
                }
                ++t.checked;
                const Parallelepiped<Rational> box = exact_box(c);
                const Cylinder<Rational> cyl = to_exact(c.cylinder);
                const bool ok = (!std::isfinite(b.upper) || clearance_oracle::within(box, cyl, to_rational(b.upper))) &&
                                !(b.lower > 0 && clearance_oracle::within(box, cyl, to_rational(std::nextafter(b.lower, 0.0))));
                if (!ok && ++t.violations <= 5)
                    ADD_FAILURE() << "rounding mode " << mode_name(mode) << ": projected bounds [" << hex(b.lower) << ", "
                                  << hex(b.upper) << "] do not hold for\n" << describe(c);
            }
        }
    }
    std::printf("projected bounds: %ld judged, %d margins decided, %d violations\n", t.checked, decided, t.violations);
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(decided, 250);
}

TEST(SeparationJudged, IntegerLattice) {
    std::mt19937_64 rng(0x5e9a0300);
    const Integers integer{rng};
    Tally t;
    for (int i = 0; i < 400; ++i) {
        Case c;
        c.cylinder = {{integer(-3, 3), integer(-3, 3), integer(-3, 3)},
                      {integer(-2, 2), integer(-2, 2), integer(-2, 2)}, integer(0, 3), 2 * integer(0, 3)};
        if (c.cylinder.axis == Vec3<double>{0, 0, 0}) c.cylinder.axis = {0, 0, 1};
        lattice_box(c, i, integer);
        judge(c, -1, t);
        judge(c, integer(0, 12) / 2, t);
    }
    std::printf("lattice: %ld bounds judged, %ld of %ld separated ones tight, %d violations\n", t.checked, t.tight,
                t.converged, t.violations);
    EXPECT_EQ(t.violations, 0);
}

TEST(SeparationJudged, EveryRoundingMode) {
    Tally t;
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::degenerate}) {
        CaseGenerator gen(0x5e9a0400 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < 25; ++i) {
            const Case c = gen.next();
            for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
                const RoundingMode scope(mode);
                const filtered::separation::Bounds b = bounds_of(c, -1);
                const RoundingMode nearest(FE_TONEAREST);  // the judge in round to nearest
                const Parallelepiped<Rational> box = exact_box(c);
                const Cylinder<Rational> cyl = to_exact(c.cylinder);
                ++t.checked;
                const bool ok = (!std::isfinite(b.upper) || clearance_oracle::within(box, cyl, to_rational(b.upper))) &&
                                !(b.lower > 0 && clearance_oracle::within(box, cyl, to_rational(std::nextafter(b.lower, 0.0))));
                if (!ok && ++t.violations <= 5)
                    ADD_FAILURE() << "rounding mode " << mode_name(mode) << ": bounds [" << hex(b.lower) << ", "
                                  << hex(b.upper) << "] do not hold for\n" << describe(c);
            }
        }
    }
    std::printf("rounding modes: %ld bounds judged, %d violations\n", t.checked, t.violations);
    EXPECT_EQ(t.violations, 0);
}

// The refined bounds (double-double after Newton refinement): the enclosures' ends, taken exactly as
// rationals, bracket the oracle's squared distance; on most separated pairs they are tight to 2^-60
// (the enclosures' error grows with the coordinates' magnitude, so far from the origin less: 2^-70 or so
// relative to a distance 10^6 times smaller than the coordinates).
Rational end_of(const DoubleDouble& x, int side) {
    const Rational e = Rational(x.error()) * (Rational(1) + Rational(1, 1 << 30));
    return Rational(x.high()) + Rational(x.low()) + (side > 0 ? e : Rational(-e));
}

TEST(SeparationJudged, RefinedBoundsRandomPairs) {
    long checked = 0, separated = 0, tight = 0;
    int violations = 0;
    for (Profile p : {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        CaseGenerator gen(0x5e9a0500 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < (p == Profile::magnitudes ? 20 : 120); ++i) {
            const Case c = gen.next();
            const filtered::separation::RefinedBounds r = with_box(c, [](const auto& box, const Cylinder<double>& cyl) {
                filtered::separation::Approximate a;
                filtered::separation::bounds(box, cyl, -1, &a);
                return filtered::separation::refined_bounds(box, cyl, a);
            });
            if (!r.found || !std::isfinite(r.upper.high()) || !std::isfinite(r.upper.error())) continue;
            const Parallelepiped<Rational> box = exact_box(c);
            const Cylinder<Rational> cyl = to_exact(c.cylinder);
            ++checked;
            const Rational hi = end_of(r.upper, 1);
            bool ok = clearance_oracle::compare_squared_distance(box, cyl, hi * hi) <= 0;
            const bool lower_finite = std::isfinite(r.lower.high()) && std::isfinite(r.lower.error());
            if (lower_finite) {
                const Rational lo = end_of(r.lower, -1);
                if (lo > 0) {
                    ++separated;
                    ok = ok && clearance_oracle::compare_squared_distance(box, cyl, lo * lo) >= 0;
                    if (hi - lo <= Rational(hi) / Rational(mpz_class(1) << 60)) ++tight;
                }
            }
            if (!ok && ++violations <= 5)
                ADD_FAILURE() << "refined bounds [" << hex(r.lower.lo()) << ", " << hex(r.upper.hi()) << "] do not hold for\n"
                              << describe(c);
        }
    }
    std::printf("refined: %ld bounds judged, %ld of %ld separated ones tight to 2^-60, %d violations\n", checked, tight,
                separated, violations);
    EXPECT_EQ(violations, 0);
    EXPECT_GT(tight, separated * 8 / 10);
}

// Contacts the refinement once left loose (the exact decision then answered, in milliseconds): flat
// boxes whose plane lies within 1e-11 of parallel to a cap, touching at the foot of a rim point or at a
// kink of the distance along an edge. The refined bounds bracket the oracle's distance and agree to
// 2^-60, far closer than one ulp of it.
TEST(SeparationJudged, RefinedNearlyParallelContacts) {
    auto canonical = [](Vec3<double> e, Cylinder<double> cyl) {
        Case c;
        c.kind = BoxKind::canonical;
        c.canonical = {e};
        c.cylinder = cyl;
        return c;
    };
    Case aligned;
    aligned.kind = BoxKind::aligned;
    aligned.aligned = {{-0x1.1704daa1ad107p+15, -0x1.418eaeda172f2p+16, 0x1.6f62496595db8p+15},
                       {-0x1.9b9774e49ca6ep+14, -0x1.4954b56951c05p+15, 0x1.6f62496595db8p+15}};
    aligned.cylinder = {{-0x1.726a786904b2cp+15, -0x1.ee492dc378acp+15, 0x1.11fb6e63e681ep+15},
                        {-0x0.0000000000003p-1022, 0x1.19799812dea11p-40, 0x1.c62943ff99cep-5}, 0x1.ef63e01fe2adfp+13,
                        0x1.910556f5eb1bp+7};
    const Case cases[] = {
        canonical({0x1.35fef3ba705d1p+1, 0x1.6554e3e0e4f1fp+1, 0x0p+0},
                  {{-0x1.2939e8ceac7adp+1, 0x1.16742787057a4p+0, 0x1.0268cc7aeb7d4p+0},
                   {0x0p+0, -0x1.19799812dea11p-38, 0x1.a9e80f35c098p-5}, 0x1.23b9365b150fap-9, 0x1.ab4c18614473ap-2}),
        canonical({0x1.23658eeffafd6p+1, 0x1.b0e278e5b99e8p+3, 0x0p+0},
                  {{-0x1.3069661a09495p+3, 0x1.2587f2003ffa6p+2, -0x1.12e2b57a538fp+2},
                   {-0x1.637834a1d8b48p-2, -0x1.19799812dea11p-38, -0x1.86686337bacfp-3}, 0x1.39d3dccec7d51p+3,
                   0x1.795f81c447cbbp+2}),
        aligned,
    };
    for (const Case& c : cases) {
        const filtered::separation::RefinedBounds r = with_box(c, [](const auto& box, const Cylinder<double>& cyl) {
            filtered::separation::Approximate a;
            filtered::separation::bounds(box, cyl, -1, &a);
            return filtered::separation::refined_bounds(box, cyl, a);
        });
        ASSERT_TRUE(r.found);
        const Rational lo = end_of(r.lower, -1), hi = end_of(r.upper, 1);
        const Parallelepiped<Rational> box = exact_box(c);
        const Cylinder<Rational> cyl = to_exact(c.cylinder);
        EXPECT_LE(clearance_oracle::compare_squared_distance(box, cyl, hi * hi), 0) << describe(c);
        EXPECT_GE(clearance_oracle::compare_squared_distance(box, cyl, lo * lo), 0) << describe(c);
        EXPECT_LE(hi - lo, hi / Rational(mpz_class(1) << 60)) << "[" << hex(r.lower.lo()) << ", " << hex(r.upper.hi()) << "] for\n"
                                                              << describe(c);
    }
}

// Faces within about 2^-40 of parallel to the axis, from bench_distance's random set: the distance's
// valley along the face is so flat that Newton's method stops inside it, while the nearest point lies on
// an edge against the side. With the distance's own search (loose, as the distance runs it), the refined
// bounds once stayed 8,479 and 99,099 doubles apart, and the distance bisected them with the exact
// decision (a millisecond a pair); each edge's point nearest the axis now closes them to one double.
TEST(SeparationJudged, RefinedEdgesAlongNearlyParallelFaces) {
    Case a;
    a.kind = BoxKind::aligned;
    a.aligned = {{0x1.66f76359225fep+8, -0x1.f2874660777cfp+7, -0x1.3b8ff70991403p+9},
                 {0x1.36d658b00612dp+9, -0x1.9a52d97f3cd39p+7, -0x1.65dc74209f5fbp+7}};
    a.cylinder = {{0x1.30e4dc9e80b7fp+9, -0x1.801ac56c3d162p+8, -0x1.a745c8a8486afp+7},
                  {0x1.c25f235b7c41p+0, 0x1.19799812dea11p-39, 0x1.9c8e209f062f8p-1}, 0x1.5be8aa6523c7ap+6, 0x1.69b55fd16eddap+6};
    Case b;
    b.kind = BoxKind::aligned;
    b.aligned = {{-0x1.ff1a447c99317p-8, -0x1.35049f45af92p-14, -0x1.080ee46fc53f3p-7},
                 {-0x1.648c924aeea25p-8, 0x1.70f9f4afb66a8p-8, -0x1.d3f8ee0c766d6p-8}};
    b.cylinder = {{-0x1.0160456c22b14p-8, 0x1.3889a59f23755p-8, -0x1.a7d2c1581c386p-8},
                  {0x1.19799812dea11p-40, -0x1.7b7f2fb49075cp-3, -0x1.e4a18ffd67d57p-1}, 0x1.737742d1a335fp-11, 0x1.b19cf5e06c6cbp-9};
    for (const Case& c : {a, b}) {
        const filtered::separation::RefinedBounds r = with_box(c, [](const auto& box, const Cylinder<double>& cyl) {
            const filtered::separation::Approximate s =
                boxcyl::detail::clearance::search_in_double(box, cyl, -1, boxcyl::detail::distance::search_gap);
            return filtered::separation::refined_bounds(box, cyl, s, -1, boxcyl::detail::distance::newton_steps,
                                                        boxcyl::detail::distance::max_steps);
        });
        ASSERT_TRUE(r.found);
        const double lo = filtered::separation::refined::lower_double(r.lower);
        const double hi = filtered::separation::refined::upper_double(r.upper);
        EXPECT_LE(boxcyl::detail::distance::steps(lo, hi), 1u) << "[" << hex(lo) << ", " << hex(hi) << "] for\n" << describe(c);
        const Parallelepiped<Rational> box = exact_box(c);
        const Cylinder<Rational> cyl = to_exact(c.cylinder);
        EXPECT_LE(clearance_oracle::compare_squared_distance(box, cyl, Rational(hi) * Rational(hi)), 0) << describe(c);
        EXPECT_GE(clearance_oracle::compare_squared_distance(box, cyl, Rational(lo) * Rational(lo)), 0) << describe(c);
    }
}

// The distance's first start (the projections, then Newton's steps in double, without the steps in
// double-double or the last resorts) on random separated pairs: the bounds hold by the oracle's
// distance, and nearly all are within the distance's goal of 4 doubles: the lower bound's direction in
// the shapes' normal cones (in_normal_cones) leaves no first-order loss at a box edge or face, the
// side or a cap, so the steps in double-double are rarely needed.
TEST(SeparationJudged, FirstStartMeetsTheDistanceGoal) {
    long separated = 0, within = 0;
    int violations = 0;
    CaseGenerator gen(0xd157a001, Profile::mixed);
    while (separated < 400) {
        const Case c = gen.next();
        if (with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return intersects(box, cyl); })) continue;
        const filtered::separation::RefinedBounds r = with_box(c, [](const auto& box, const Cylinder<double>& cyl) {
            return filtered::separation::refined_bounds(box, cyl, boxcyl::detail::clearance::projected_search(box, cyl), -1,
                                                        boxcyl::detail::distance::newton_steps,
                                                        boxcyl::detail::distance::max_steps, false);
        });
        ASSERT_TRUE(r.found) << describe(c);
        ++separated;
        const double lo = filtered::separation::refined::lower_double(r.lower);
        const double hi = filtered::separation::refined::upper_double(r.upper);
        if (lo <= hi && boxcyl::detail::distance::steps(lo, hi) <= boxcyl::detail::distance::max_steps) ++within;
        const Parallelepiped<Rational> box = exact_box(c);
        const Cylinder<Rational> cyl = to_exact(c.cylinder);
        const bool ok = clearance_oracle::compare_squared_distance(box, cyl, Rational(hi) * Rational(hi)) <= 0 &&
                        clearance_oracle::compare_squared_distance(box, cyl, Rational(lo) * Rational(lo)) >= 0;
        if (!ok && ++violations <= 5) ADD_FAILURE() << "[" << hex(lo) << ", " << hex(hi) << "] do not hold for\n" << describe(c);
    }
    std::printf("first start: %ld of %ld separated pairs within 4 doubles\n", within, separated);
    EXPECT_EQ(violations, 0);
    EXPECT_GE(within, separated * 96 / 100);
}

// Cases that once failed: axes whose |D|² underflows (the enclosure of u was NaN, and a clamp turned
// NaN bounds into a "proved" zero distance).
TEST(SeparationJudged, Regressions) {
    Tally t;
    Case a;
    a.kind = BoxKind::aligned;
    a.aligned = {{0x1.1e4cea68ce309p-19, 0x1.22a5147a07a7cp-18, -0x1.ac9c9c74b5dd2p-19},
                 {0x1.8b39734232a27p-19, 0x1.371a807e2a844p-18, 0x1.5f7383d26023ap-19}};
    a.cylinder = {{0x1.5ea7ce3998c8cp-19, 0x1.1a9d41628c39p-20, -0x1.e1b7c560777fap-20},
                  {0x0p+0, 0x0p+0, -0x0.0000000000006p-1022}, 0x1.6b8592bba4ea6p-22, 0x1.7d5b2e9bfa81fp-17};
    Case b;
    b.kind = BoxKind::canonical;
    b.canonical = {{0x1.d711a85a819c6p-363, 0x1.109ced2aa36fp-366, 0x1.c1f5a69ce9492p-404}};
    b.cylinder = {{0x1.664f96a8bf3d8p-327, -0x1.b2cfb36de023cp-329, 0x1.264aa14f2d2b7p-327},
                  {0x0p+0, 0x0.0000000000018p-1022, 0x0p+0}, 0x1.1b1d609480bb1p-325, 0x1.7e429d39211bbp-404};
    for (const Case& c : {a, b}) {
        judge(c, -1, t);
        judge(c, c.cylinder.radius, t);
    }
    EXPECT_EQ(t.violations, 0);
}

// Hand constructions with a known distance: the bounds hold and are tight.
TEST(SeparationJudged, KnownDistances) {
    struct Known {
        AlignedBox<double> box;
        Cylinder<double> cyl;
        double distance;
    };
    const Known known[] = {
        {{{0, 0, 0}, {1, 1, 1}}, {{3, 0.5, 0.5}, {0, 0, 1}, 1, 1}, 1},     // face to side
        {{{0, 0, 0}, {1, 1, 1}}, {{0.5, 0.5, 4}, {0, 0, 2}, 5, 2}, 2},     // face to cap
        {{{0, 0, 0}, {1, 1, 1}}, {{4, 5, 0.5}, {0, 0, 1}, 0, 1}, 5},       // edge to segment: (3, 4)
        {{{0, 0, 0}, {1, 1, 1}}, {{0.5, 0.5, 0.5}, {1, 2, 3}, 0.25, 0.5}, 0},  // inside
    };
    for (const Known& k : known) {
        const filtered::separation::Bounds b = filtered::separation::bounds(k.box, k.cyl);
        EXPECT_LE(b.lower, k.distance);
        EXPECT_GE(b.upper, k.distance);
        EXPECT_LE(b.upper - b.lower, 0x1p-40 * (1 + k.distance)) << "[" << hex(b.lower) << ", " << hex(b.upper) << "]";
    }
}

}  // namespace
}  // namespace boxcyl
