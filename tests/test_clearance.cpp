// The clearance query, boxcyl::within_distance (include/boxcyl/clearance.hpp): exact answers on
// constructions whose distance is known by hand — one for each way the nearest points can lie (box
// face, edge, vertex against the cylinder's side, cap and rim), each exactly at the margin (within)
// and one ulp of the margin below (not within) — and its properties on random pairs: margin 0 is
// intersects(), the answer is monotone in the margin, and every box kind agrees with the parallelepiped
// it is.
#include <gtest/gtest.h>

#include <cfenv>      // rounding modes
#include <gmpxx.h>     // the shoulders' sizes, exactly
#include <cmath>      // std::nextafter, std::ldexp
#include <cstdint>    // seeds
#include <random>     // random margins
#include <stdexcept>  // std::invalid_argument
#include <string>     // error messages

#include "boxcyl/clearance.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

double below(double x) { return std::nextafter(x, 0.0); }

// dist == m exactly: within at m, not within one ulp below; far inside and outside too.
template <class Box>
void expect_distance(const Box& box, const Cylinder<double>& cyl, double dist) {
    EXPECT_TRUE(within_distance(box, cyl, dist));
    EXPECT_FALSE(within_distance(box, cyl, below(dist)));
    EXPECT_TRUE(within_distance(box, cyl, 2 * dist));
    EXPECT_FALSE(within_distance(box, cyl, dist / 2));
    EXPECT_FALSE(within_distance(box, cyl, 0.0));
}

const Cylinder<double> kUnit{{0, 0, 0}, {0, 0, 1}, 1, 2};  // r = 1, caps at z = ±1

TEST(Clearance, FaceAgainstSide) { expect_distance(AlignedBox<double>{{2, -1, -1}, {3, 1, 1}}, kUnit, 1.0); }

TEST(Clearance, FaceAgainstCap) { expect_distance(AlignedBox<double>{{-1, -1, 3}, {1, 1, 4}}, kUnit, 2.0); }

TEST(Clearance, AxisOfAnyLength) {
    Cylinder<double> c = kUnit;
    c.axis = {0, 0, 2};
    expect_distance(AlignedBox<double>{{-1, -1, 3}, {1, 1, 4}}, c, 2.0);
    c.axis = {0, 0, -0x1p-40};
    expect_distance(AlignedBox<double>{{2, -1, -1}, {3, 1, 1}}, c, 1.0);
}

// r = 3, h = 2: the top rim is the circle of radius 3 at z = 1.
const Cylinder<double> kRim{{0, 0, 0}, {0, 0, 1}, 3, 2};

TEST(Clearance, VertexAgainstRim) {
    // (6, 0, 5) is 5 from the rim point (3, 0, 1): (6 − 3)² + (5 − 1)² = 25.
    expect_distance(AlignedBox<double>{{6, 0, 5}, {7, 1, 6}}, kRim, 5.0);
    // The same below the bottom rim (z = −1).
    expect_distance(AlignedBox<double>{{6, 0, -6}, {7, 1, -5}}, kRim, 5.0);
}

TEST(Clearance, VertexAgainstRimAtAnAzimuth) {
    // r = 5; the vertex (6, 8, 13) has ρ = 10, height 12 over the rim plane z = 1: distance 13. The box
    // extends radially (3, 4, 0), tangentially (−4, 3, 0) and up, so that vertex is its nearest point.
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 5, 2};
    const Parallelepiped<double> box{{5.5, 11.5, 13.5}, {Vec3<double>{3, 4, 0}, {-4, 3, 0}, {0, 0, 1}}, {0.5, 0.5, 0.5}};
    expect_distance(box, c, 13.0);
}

TEST(Clearance, EdgeAgainstRim) {
    // The edge x = 6, z = 5 (y from −1 to 1) comes nearest the rim at its middle (6, 0, 5): distance 5.
    expect_distance(AlignedBox<double>{{6, -1, 5}, {7, 1, 6}}, kRim, 5.0);
}

TEST(Clearance, EdgeAgainstRimAtAnAzimuth) {
    // r = 5: the edge (6, 8, 13) + s·(−4, 3, 0), |s| ≤ 1/2, has ρ² = 100 + 25s² at height 12 over the rim
    // plane: nearest the rim at its middle, distance 13.
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 5, 2};
    const Parallelepiped<double> box{{7.5, 10, 13.5}, {Vec3<double>{3, 4, 0}, {-4, 3, 0}, {0, 0, 1}}, {0.5, 0.5, 0.5}};
    expect_distance(box, c, 13.0);
}

TEST(Clearance, FaceAgainstRim) {
    // The plane 3x + 4z = 38 is 5 from the rim point (3, 0, 1) (3·3 + 4·1 = 13, (38 − 13)/5 = 5), the
    // farthest point of the cylinder towards it; the foot (6, 0, 5) is the centre of the box's face.
    const Parallelepiped<double> box{{7.5, 0, 7}, {Vec3<double>{4, 0, -3}, {0, 1, 0}, {3, 0, 4}}, {0.5, 0.5, 0.5}};
    expect_distance(box, kRim, 5.0);
}

TEST(Clearance, SegmentAndDiskCylinders) {
    // r = 0: the segment from (0,0,−1) to (0,0,1); the vertex (3, 0, 5) is 5 from its end.
    const Cylinder<double> segment{{0, 0, 0}, {0, 0, 1}, 0, 2};
    expect_distance(AlignedBox<double>{{3, 0, 5}, {4, 1, 6}}, segment, 5.0);
    // h = 0: the disk of radius 3 at z = 0; the vertex (6, 0, 4) is 5 from its rim point (3, 0, 0).
    const Cylinder<double> disk{{0, 0, 0}, {0, 0, 1}, 3, 0};
    expect_distance(AlignedBox<double>{{6, 0, 4}, {7, 1, 5}}, disk, 5.0);
}

TEST(Clearance, FloatInputs) {
    const AlignedBox<float> box{{6, 0, 5}, {7, 1, 6}};
    const Cylinder<float> c{{0, 0, 0}, {0, 0, 1}, 3, 2};
    EXPECT_TRUE(within_distance(box, c, 5.0f));
    EXPECT_FALSE(within_distance(box, c, std::nextafter(5.0f, 0.0f)));
}

TEST(Clearance, RefusesABadMargin) {
    const AlignedBox<double> box{{2, -1, -1}, {3, 1, 1}};
    auto message = [&](double m) {
        try {
            (void)within_distance(box, kUnit, m);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(-1.0), "margin: is negative");
    EXPECT_EQ(message(std::nan("")), "margin: is NaN");
    EXPECT_EQ(message(INFINITY), "margin: is +Inf");
    EXPECT_EQ(message(-0.0), "no error");
    EXPECT_TRUE(within_distance(box, kUnit, 1e300));
    EXPECT_TRUE(within_distance(box, kUnit, 0x1.fffffffffffffp1023));
}

// Random pairs at random margins (0 to 2^±20 of the shapes, and subnormal): margin 0 is intersects(),
// and the answer never turns from within to not within as the margin grows.
TEST(Clearance, RandomPairsMarginZeroAndMonotone) {
    constexpr std::uint64_t seed = 0xc1ea0001;
    CaseGenerator gen(seed);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int within_count = 0;
    for (int i = 0; i < 300; ++i) {
        const Case c = gen.next();
        SCOPED_TRACE(describe(c));
        const bool touches = with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return intersects(box, cyl); });
        EXPECT_EQ(with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return within_distance(box, cyl, 0.0); }),
                  touches);
        bool previous = touches;
        for (double m : {0x1p-1074, std::ldexp(unit(rng), -20), unit(rng), std::ldexp(unit(rng), 20)}) {
            const double scaled = m * (c.cylinder.radius + c.cylinder.height + 1e-300);
            const bool w =
                with_box(c, [&](const auto& box, const Cylinder<double>& cyl) { return within_distance(box, cyl, scaled); });
            EXPECT_TRUE(!previous || w) << "margin " << hex(scaled);
            previous = w;
            within_count += w;
        }
    }
    EXPECT_GT(within_count, 100);
}

// Whether a cylinder of the same centre and axis lies in `cyl` rounded by m: max(r' − r, 0)² +
// max((h' − h)/2, 0)² ≤ m², exactly (rationals).
bool in_rounded(const Cylinder<double>& s, double r, double h, double m) {
    mpq_class dr = mpq_class(s.radius) - r, dh = (mpq_class(s.height) - h) / 2;
    dr = dr > 0 ? dr : mpq_class(0), dh = dh > 0 ? dh : mpq_class(0);
    return s.radius >= 0 && s.height >= 0 && dr * dr + dh * dh <= mpq_class(m) * m;
}

// Every shoulder lies inside the rounded cylinder, exactly, for margins and sizes from subnormal to
// huge, in every rounding mode: the three fixed ones, and those at the angles of the rim witnesses
// (shoulder_factors of distances beyond the side and a cap from 0 and subnormal to huge, and NaN).
TEST(Clearance, ShouldersLieInTheRoundedCylinder) {
    const double values[] = {0.0, 0x1p-1074, 0x1.8p-1060, 1e-300, 0.1, 0.7, 1.0, 3.0, 1e10, 0x1.fffffffffffffp1000, 1e308};
    int checked = 0;
    for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO})
        for (const double r : values)
            for (const double h : values)
                for (const double m : values) {
                    if (m == 0) continue;
                    const Cylinder<double> cyl{{0, 0, 0}, {0, 0, 1}, r, h};
                    detail::clearance::Grown g{};
                    std::array<Cylinder<double>, detail::clearance::kShoulders.size()> shoulders;
                    {
                        const RoundingMode rounding(mode);
                        g = detail::clearance::grown(cyl, m);
                        for (std::size_t k = 0; k < shoulders.size(); ++k) shoulders[k] = detail::clearance::shoulder(g, k);
                    }
                    for (std::size_t k = 0; k < shoulders.size(); ++k) {
                        EXPECT_TRUE(in_rounded(shoulders[k], r, h, m))
                            << "radius " << hex(r) << ", height " << hex(h) << ", margin " << hex(m) << ", shoulder " << k
                            << ", rounding " << mode_name(mode);
                        ++checked;
                    }
                    for (const double a : {0.0, 0x1p-1074, 1e-300, 0.3, 1.0, 1e300, -1.0, std::nan("")})
                        for (const double b : {0.0, 0x1p-1074, 1e-300, 0.3, 1.0, 1e300, -1.0, std::nan("")}) {
                            std::optional<Cylinder<double>> s;
                            {
                                const RoundingMode rounding(mode);
                                if (const auto f = detail::clearance::shoulder_factors(a, b))
                                    s = detail::clearance::shoulder(g, (*f)[0], (*f)[1]);
                            }
                            if (!s) continue;
                            EXPECT_TRUE(in_rounded(*s, r, h, m))
                                << "radius " << hex(r) << ", height " << hex(h) << ", margin " << hex(m) << ", factors of "
                                << hex(a) << ", " << hex(b) << ", rounding " << mode_name(mode);
                            ++checked;
                        }
                }
    EXPECT_GT(checked, 150000);
}

// A box corner in the rim region, within m of the rim but outside the fat and tall cylinders: a
// shoulder decides it (the shoulders' stage), and a margin below its distance is not within.
TEST(Clearance, ShoulderDecidesACornerInTheRimRegion) {
    // The corner (1.6, 0, 1.6) lies 0.6·√2 ≈ 0.8485 from the rim point (1, 0, 1).
    const AlignedBox<double> box{{1.6, -1, 1.6}, {3, 1, 3}};
    const detail::clearance::Grown g = detail::clearance::grown(kUnit, 1.0);
    const auto verdicts = detail::clearance::stage0_verdicts<false>(box, g).cylinders;
    EXPECT_EQ(verdicts[1], std::nullopt);  // outer: its misses alone, and none holds (a hit decides nothing)
    EXPECT_EQ(verdicts[3 + 1], true);  // the 45° shoulder: a hit
    detail::clearance::Pair<AlignedBox<double>> q(box, kUnit, 1.0);
    EXPECT_EQ(detail::clearance::shoulders(q), true);
    EXPECT_TRUE(within_distance(box, kUnit, 1.0));
    EXPECT_TRUE(within_distance(box, kUnit, 0.8486));
    EXPECT_FALSE(within_distance(box, kUnit, 0.8485));
}

// A corner at 15° from the rim's plane, 0.9897 from the rim point (1, 0, 1): outside fat, tall and the
// fixed shoulders (the 30° one reaches radius 1.866), so the rim witness (the box point nearest the rim
// point nearest the box centre: this corner) in the shoulder at its own angle decides it in stage 0.
TEST(Clearance, RimWitnessDecidesACornerBetweenTheShoulders) {
    const AlignedBox<double> box{{1.956, -1, 1.256}, {3, 1, 3}};
    const detail::clearance::Grown g = detail::clearance::grown(kUnit, 1.0);
    const detail::clearance::Stage0Verdicts verdicts = detail::clearance::stage0_verdicts<true>(box, g);
    EXPECT_EQ(verdicts.cylinders[0], false);  // fat
    EXPECT_EQ(verdicts.cylinders[2], false);  // tall
    for (std::size_t k = 0; k < detail::clearance::kShoulders.size(); ++k) EXPECT_EQ(verdicts.cylinders[3 + k], false);
    ASSERT_TRUE(verdicts.rim_shoulder);
    EXPECT_TRUE(intersects(box, *verdicts.rim_shoulder));
    EXPECT_TRUE(in_rounded(*verdicts.rim_shoulder, 1, 2, 1.0));
    // √(0.956² + 0.256²) = 0.98968...
    EXPECT_TRUE(within_distance(box, kUnit, 1.0));
    EXPECT_TRUE(within_distance(box, kUnit, 0.9897));
    EXPECT_FALSE(within_distance(box, kUnit, 0.9896));
}

// The grown box holds every point within m of the box: its sizes exceed the box's by at least m
// (an oriented box's by m·(1 + 2^-11), for axes orthonormal within 1e-4), exactly, in every rounding mode.
TEST(Clearance, GrownBoxHoldsTheBoxRoundedByTheMargin) {
    const double values[] = {0.0, 0x1p-1074, 1e-300, 0.1, 1.0, 3.0, 1e10, 1e300};
    const mpq_class oriented_factor = 1 + mpq_class(1, 2048);
    int checked = 0;
    for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO})
        for (const double x : values)
            for (const double m : values) {
                const AlignedBox<double> aligned{{-x, x / 3, -0.1}, {x, x, 0.1}};
                const OrientedBox<double> oriented{{x, -x, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {x, x / 3, 0.1}};
                const CanonicalBox<double> canonical{{x, x / 3, 0.1}};
                std::optional<AlignedBox<double>> ga;
                std::optional<OrientedBox<double>> go;
                std::optional<CanonicalBox<double>> gc;
                {
                    const RoundingMode rounding(mode);
                    ga = detail::clearance::grown_box(aligned, m);
                    go = detail::clearance::grown_box(oriented, m);
                    gc = detail::clearance::grown_box(canonical, m);
                }
                ASSERT_TRUE(ga && go && gc) << hex(x) << ", margin " << hex(m);  // no overflow here
                for (int i = 0; i < 3; ++i) {
                    EXPECT_GE(mpq_class(aligned.min[i]) - ga->min[i], mpq_class(m)) << hex(x) << ", margin " << hex(m) << ", " << mode_name(mode);
                    EXPECT_GE(mpq_class(ga->max[i]) - aligned.max[i], mpq_class(m)) << hex(x) << ", margin " << hex(m) << ", " << mode_name(mode);
                    EXPECT_GE(mpq_class(go->extents[i]) - oriented.extents[i], oriented_factor * m) << hex(x) << ", margin " << hex(m) << ", " << mode_name(mode);
                    EXPECT_EQ(go->center, oriented.center);
                    EXPECT_GE(mpq_class(gc->extents[i]) - canonical.extents[i], mpq_class(m)) << hex(x) << ", margin " << hex(m) << ", " << mode_name(mode);
                    ++checked;
                }
            }
    EXPECT_EQ(checked, 4 * 8 * 8 * 3);
    EXPECT_FALSE(detail::clearance::grown_box(AlignedBox<double>{{-1, 0, 0}, {1, 1, 0x1.fffffffffffffp1023}}, 1e300));
    EXPECT_FALSE(detail::clearance::grown_box(Parallelepiped<double>{}, 1.0));
}

// A box face facing the rim at 45°, 1.1 from it: the outer probe's corner (2, 0, 2) crosses the face's
// plane, the grown box misses the cylinder along the face's normal.
TEST(Clearance, GrownBoxDecidesAFaceNearTheRim) {
    const double s = 0x1.6a09e667f3bcdp-1;  // 1/√2, rounded
    const Vec3<double> n{s, 0, s};
    const double depth = 1.1 + 1;  // the face 1.1 from the rim point (1, 0, 1), the box 2 deep behind it
    const OrientedBox<double> box{{1 + depth * s, 0, 1 + depth * s}, {n, Vec3<double>{0, 1, 0}, Vec3<double>{-s, 0, s}}, {1, 1, 1}};
    detail::clearance::Pair<OrientedBox<double>> q(box, kUnit, 1.0);
    EXPECT_EQ(detail::clearance::stage0_verdicts<true>(box, q.g).cylinders[1], true);  // the outer probe: a hit
    EXPECT_EQ(detail::clearance::grown_box_misses(q), false);
    EXPECT_FALSE(within_distance(box, kUnit, 1.0));
    EXPECT_TRUE(within_distance(box, kUnit, 1.2));
}

// Random pairs (bench_clearance's set) that two steps of the quick search leave open and its Newton
// steps decide: a box along the rim, where alternating projections converge slowly. The quick bounds
// answer them, as the exact query does.
TEST(Clearance, QuickBoundsTakeNewtonStepsWhereTwoLeaveThePairOpen) {
    namespace sep = filtered::separation;
    struct Example {
        AlignedBox<double> box;
        Cylinder<double> cyl;
        double m;
        bool within;
    };
    const Example examples[] = {
        {{{0x1.29e93366d81afp+12, 0x1.d455bc8bb8582p+11, -0x1.19d7b58b21c5fp+13},
          {0x1.b10478c820235p+12, 0x1.606e76b6ded0ep+13, -0x1.4245b1708c8b8p+11}},
         {{0x1.0d2d06e4be0a8p+12, 0x1.1a1fd30870781p+13, -0x1.56708af4d2cc8p+11},
          {-0x1.5f5407e986be1p-2, -0x1.3a9d64ebc44p-2, 0x1.5969804779adcp-3},
          0x1.d2f1dae2979c8p+9,
          0},
         0x1.d30aca1be2edcp+5,
         true},
        {{{-0x1.f1685362ed99dp+12, -0x1.42f353dbffaf8p+11, -0x1.9e24866856d2p+12},
          {-0x1.acf278a856c97p+12, -0x1.42f353cbffaf8p+11, 0x1.3a494889b95a2p+10}},
         {{-0x1.4153d3362c21cp+12, -0x1.32e8511a8b377p+12, -0x1.28c25b0c33c5p+9},
          {-0x1.11ce6a04fb444p-1, 0x1.9b3e6d301d1ep-2, -0x1.180cf51b061e6p-2},
          0x1.16faaf68633f1p+11,
          0},
         0x1.da65aa7831f6cp+10,
         false},
    };
    for (const Example& e : examples) {
        sep::Approximate two;
        sep::projected_bounds(e.box, e.cyl, -1, &two);  // decide_at < 0: the two steps alone
        EXPECT_FALSE(sep::clear_of(two, e.m));
        const sep::Bounds b = sep::projected_bounds(e.box, e.cyl, e.m);
        EXPECT_EQ(b.upper <= e.m, e.within);
        EXPECT_EQ(b.lower > e.m, !e.within);
        EXPECT_EQ(within_distance(e.box, e.cyl, e.m), e.within);
    }
}

// The probes' stage 0 (one plain-double problem for the three probe cylinders, filtered/semi_static.hpp's
// error bounds) on pairs of every generator profile, at margins from subnormal to 2^20 of the shapes
// and at the approximate distance itself (probe cylinders within rounding of touching), in every
// rounding mode: every verdict it gives is the exact intersection query's on that probe cylinder.
TEST(Clearance, ProbesStageZeroAgreesWithTheExactProbes) {
    constexpr std::uint64_t seed = 0xc1ea0002;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int decided = 0, rim_hits = 0;
    for (const Profile profile :
         {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        CaseGenerator gen(seed, profile);
        for (int i = 0; i < 250; ++i) {
            const Case c = gen.next();
            with_box(c, [&](const auto& box, const Cylinder<double>& cyl) {
                const double size = cyl.radius + cyl.height + 1e-300;
                const double near = filtered::separation::bounds(box, cyl).upper;
                for (const double m : {0x1p-1074, std::ldexp(unit(rng), -40) * size, unit(rng) * size,
                                       std::ldexp(unit(rng), 20) * size, near}) {
                    if (!(m > 0) || !std::isfinite(m)) continue;
                    const detail::clearance::Grown g = detail::clearance::grown(cyl, m);
                    const auto probes = detail::clearance::probes(g);
                    for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
                        std::array<std::optional<bool>, detail::clearance::kStage0Cylinders> verdicts;
                        std::optional<Cylinder<double>> rim_shoulder;
                        {
                            const RoundingMode rounding(mode);
                            const detail::clearance::Stage0Verdicts v = detail::clearance::stage0_verdicts<true>(box, g);
                            verdicts = v.cylinders;
                            rim_shoulder = v.rim_shoulder;
                        }
                        if (rim_shoulder) {  // a hit in a shoulder inside the rounded cylinder
                            ++rim_hits;
                            EXPECT_TRUE(intersects(box, *rim_shoulder) && in_rounded(*rim_shoulder, cyl.radius, cyl.height, m))
                                << describe(c) << "\nmargin " << hex(m) << ", the rim witnesses' shoulder, rounding "
                                << mode_name(mode);
                        }
                        for (std::size_t k = 0; k < verdicts.size(); ++k) {
                            if (!verdicts[k]) continue;
                            ++decided;
                            const Cylinder<double> probe =
                                k < probes.size() ? *probes[k].cylinder : detail::clearance::shoulder(g, k - probes.size());
                            EXPECT_EQ(*verdicts[k], intersects(box, probe))
                                << describe(c) << "\nmargin " << hex(m) << ", stage 0 cylinder " << k << ", rounding "
                                << mode_name(mode);
                        }
                    }
                }
                return true;
            });
        }
    }
    EXPECT_GT(decided, 20000);
    EXPECT_GT(rim_hits, 20);

}

}  // namespace
}  // namespace boxcyl
