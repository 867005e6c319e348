// The default query's exact stage in integers (include/boxcyl/exact/integer_inequalities.hpp): §4 in
// Z[√d] after scaling the doubles by a power of two. Judged by the oracle on
//  * exactly touching queries (support/touching.hpp: faces, edges, vertices, tangent sides, caps and
//    disks flush with faces, segments ending on faces, integer coordinates, rational and irrational
//    oblique axes), directly and through filtered::query;
//  * the random, degenerate (2^±600) and extreme (2^±1000, subnormal) sets of the other tests;
//  * hand-made touching cases with their exact answers, and one ulp off them;
//  * inputs of two scales (tiny axis components and lengths) through the EpsilonSeries run;
//  * its parts: the dyadic decomposition of doubles, the sign of a + b√d, FixedInt and EpsilonSeries
//    against exact references.
// Failing cases print as pasteable C++ (support/cases.hpp's describe()).
#include <gtest/gtest.h>

#include <pthread.h>  // a thread with a painted stack

#include <cmath>     // std::ldexp, std::nextafter
#include <cstdlib>   // posix_memalign, std::free
#include <cstring>   // std::memset
#include <cstddef>   // std::size_t
#include <cstdint>   // seeds
#include <limits>    // extreme doubles
#include <optional>  // the stage's "no exact frame"
#include <random>    // operands
#include <string>    // labels
#include <tuple>     // hand-made cases
#include <type_traits>  // per box kind
#include <utility>   // std::pair
#include <vector>    // series programs

#include "boxcyl/exact/integer_inequalities.hpp"
#include "boxcyl/exact/answer.hpp"
#include "boxcyl/exact/integer_parallelepiped.hpp"
#include "boxcyl/exact/point.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"
#include "support/near_touching.hpp"
#include "support/runner.hpp"
#include "support/touching.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

Parallelepiped<double> as_parallelepiped(const OrientedBox<double>& b) { return {b.center, b.axes, b.extents}; }

// The integer stage's answer, or nullopt for an oriented box without an exact canonical frame.
std::optional<bool> integer_answer(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) -> std::optional<bool> {
        return exact::integer::answer(b, cyl);
    });
}

struct StageTally {
    long cases = 0, judged = 0, judged_parallelepiped = 0, hits = 0, point_hits = 0, axis_decided = 0, exact_stage = 0,
         wrong = 0;
    void check(const Case& c, const std::string& where) {
        ++cases;
        const bool want = oracle_answer(c);
        hits += want;
        if (const std::optional<bool> got = integer_answer(c)) {
            ++judged;
            if (*got != want && ++wrong <= 10)
                ADD_FAILURE() << where << ": integer stage answered " << *got << ", oracle " << want << "\n  "
                              << describe(c);
        }
        if (c.kind == BoxKind::oriented) {
            const bool got = exact::integer::intersects_parallelepiped(as_parallelepiped(c.oriented), c.cylinder);
            ++judged_parallelepiped;
            if (got != want && ++wrong <= 10)
                ADD_FAILURE() << where << ": parallelepiped stage answered " << got << ", oracle " << want << "\n  "
                              << describe(c);
        }
        const std::optional<bool> along =
            with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return exact::decide_along_an_axis(b, cyl); });
        axis_decided += along.has_value();
        if (along && *along != want && ++wrong <= 10)
            ADD_FAILURE() << where << ": decide_along_an_axis answered " << *along << ", oracle " << want << "\n  "
                          << describe(c);
        const bool point_hit =
            with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return exact::hit_at_a_point(b, cyl); });
        point_hits += point_hit;
        if (point_hit && !want && ++wrong <= 10)
            ADD_FAILURE() << where << ": hit_at_a_point claimed a hit, oracle a miss\n  " << describe(c);
        const filtered::Result r =
            with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::query(b, cyl); });
        exact_stage += r.exact_used;
        if (r.intersect != want && ++wrong <= 10)
            ADD_FAILURE() << where << ": filtered::query answered " << r.intersect << ", oracle " << want << "\n  "
                          << describe(c);
    }
    void print(const char* what) const {
        std::printf("%s: %ld cases, %ld judged by §4 in integers, %ld by the parallelepiped test, %ld decided along a "
                    "coordinate axis in double, %ld hits (%ld proved by one point in double), %ld reached the exact "
                    "stage, %ld wrong\n",
                    what, cases, judged, judged_parallelepiped, axis_decided, hits, point_hits, exact_stage, wrong);
    }
};

TEST(ExactStage, TouchingCasesAgreeWithOracle) {
    const std::uint64_t seed = 2101;
    TouchingGenerator gen(seed);
    StageTally t;
    const long n = scaled(6000);
    for (long i = 0; i < n; ++i) {
        const Case c = gen.next();
        ASSERT_TRUE(with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return validate(b).ok() && validate(cyl).ok(); }))
            << describe(c);
        t.check(c, "touching seed " + std::to_string(seed) + " case " + std::to_string(i));
    }
    t.print("touching");
    EXPECT_EQ(t.wrong, 0);
    EXPECT_GT(t.judged, n * 3 / 4);  // every box kind but the turned oriented boxes
    EXPECT_GT(t.judged_parallelepiped, n / 10);
}

TEST(ExactStage, RandomAndDegenerateAgreeWithOracle) {
    for (const Profile profile : {Profile::mixed, Profile::degenerate}) {
        const std::uint64_t seed = profile == Profile::mixed ? 2102 : 2103;
        CaseGenerator gen(seed, profile);
        StageTally t;
        const long n = scaled(3000);
        for (long i = 0; i < n; ++i)
            t.check(gen.next(), std::string(profile == Profile::mixed ? "mixed" : "degenerate") + " seed " +
                                    std::to_string(seed) + " case " + std::to_string(i));
        t.print(profile == Profile::mixed ? "random" : "degenerate");
        EXPECT_EQ(t.wrong, 0);
    }
}

// One-ulp boundary pairs of the random generator (both profiles): the two queries of a pair straddle a
// touching configuration, so a candidate of §4.3 — a box edge whose line passes within r of the axis,
// its nearest point between the clipped ends or beyond one of them, or a face cut likewise — is often
// within an ulp of r. Every query goes through each integer stage directly, not only the few that
// filtered::query sends there.
TEST(ExactStage, BoundaryPairsAgreeWithOracle) {
    for (const Profile profile : {Profile::mixed, Profile::uniform}) {
        const std::uint64_t seed = profile == Profile::mixed ? 2110 : 2111;
        CaseGenerator gen(seed, profile);
        StageTally t;
        const long pairs = scaled(150);
        for (long n = 0; n < pairs;) {
            Case first, second;
            Parameter which{};
            if (!boundary_pair(gen, first, second, which)) continue;
            const std::string where = std::string(profile == Profile::mixed ? "mixed" : "uniform") + " boundary seed " +
                                      std::to_string(seed) + " pair " + std::to_string(n);
            t.check(first, where + " (first)");
            t.check(second, where + " (second)");
            ++n;
        }
        t.print(profile == Profile::mixed ? "boundary pairs" : "uniform boundary pairs");
        EXPECT_EQ(t.wrong, 0);
        EXPECT_EQ(t.hits, pairs);  // one query of each pair meets the cylinder, the other does not
    }
}

// Touching cases whose parts are moved to the ends of the double range: the whole scene by 2^±1000 (the
// exponents stay within one query), the axis by its own power of two down to subnormals, and a
// subnormal axis component beside 1 — every number is still an integer times one power of two.
TEST(ExactStage, ExtremeMagnitudesAgreeWithOracle) {
    const std::uint64_t seed = 2104;
    TouchingGenerator gen(seed);
    std::mt19937_64 rng(seed);
    StageTally t;
    const long n = scaled(1500);
    for (long i = 0; i < n; ++i) {
        Case c = gen.next();
        const int scene = std::uniform_int_distribution<int>(-1000, 990)(rng);
        auto sc = [&](double& x) { x = std::ldexp(x, scene); };
        for (int k = 0; k < 3; ++k) {
            sc(c.aligned.min[k]), sc(c.aligned.max[k]), sc(c.oriented.center[k]), sc(c.oriented.extents[k]);
            sc(c.canonical.extents[k]), sc(c.cylinder.center[k]);
        }
        sc(c.cylinder.radius), sc(c.cylinder.height);
        const int ax = std::uniform_int_distribution<int>(-1070, 1000)(rng);
        for (int k = 0; k < 3; ++k) c.cylinder.axis[k] = std::ldexp(c.cylinder.axis[k], ax);
        if (i % 4 == 0) {  // a subnormal component beside the others
            const int k = static_cast<int>(rng() % 3);
            const double tiny = std::numeric_limits<double>::denorm_min() * static_cast<double>(1 + rng() % 5);
            c.cylinder.axis[k] = (rng() & 1) ? tiny : -tiny;
            if (c.cylinder.axis[(k + 1) % 3] == 0 && c.cylinder.axis[(k + 2) % 3] == 0) c.cylinder.axis[(k + 1) % 3] = 1;
        }
        t.check(c, "extreme seed " + std::to_string(seed) + " case " + std::to_string(i));
    }
    t.print("extreme");
    EXPECT_EQ(t.wrong, 0);
}

// Hand-made touching cases with their answers, each also one ulp in (hit) and out (miss).
TEST(ExactStage, HandMadeTouchingCases) {
    const AlignedBox<double> unit{{0, 0, 0}, {1, 1, 1}};
    const double out = std::nextafter(1.0, 0.0), in = std::nextafter(1.0, 2.0);
    struct Known {
        const char* what;
        Cylinder<double> cyl;
        bool hit;
    };
    const Known known[] = {
        // Side tangent to the face x = 1 (axis z, centre 1 + r away).
        {"side on face", {{2, 0.5, 0.5}, {0, 0, 1}, 1, 1}, true},
        {"side off face", {{2, 0.5, 0.5}, {0, 0, 1}, out, 1}, false},
        {"side into face", {{2, 0.5, 0.5}, {0, 0, 1}, in, 1}, true},
        // Cap flush with the face z = 1.
        {"cap on face", {{0.5, 0.5, 2}, {0, 0, 3}, 0.25, 2}, true},
        {"cap off face", {{0.5, 0.5, 2}, {0, 0, 3}, 0.25, std::nextafter(2.0, 0.0)}, false},
        // Side through the edge x = 1, y = 1 (axis z): offset (3, 4), r = 5.
        {"side on edge", {{4, 5, 0.5}, {0, 0, 1}, 5, 1}, true},
        {"side off edge", {{4, 5, 0.5}, {0, 0, 1}, std::nextafter(5.0, 0.0), 1}, false},
        // Oblique rational axis (3,4,0)/5: the side tangent to the face z = 1.
        {"(3,4,0) side on face", {{0.5, 0.5, 3}, {3, 4, 0}, 2, 4}, true},
        {"(3,4,0) side off face", {{0.5, 0.5, 3}, {3, 4, 0}, std::nextafter(2.0, 0.0), 4}, false},
        // Irrational axis (1,1,0): the side through the vertex (1, 0, 1) at offset (2,−2,1), r = 3.
        {"(1,1,0) side on vertex", {{3, -2, 2}, {1, 1, 0}, 3, 2}, true},
        {"(1,1,0) side off vertex", {{3, -2, 2}, {1, 1, 0}, std::nextafter(3.0, 0.0), 2}, false},
        // Segment (r = 0) along (2,1,2)/3 ending on the face x = 1 at (1, 0.5, 0.5): centre = end + u·h/2.
        {"segment ends on face", {{3, 1.5, 2.5}, {2, 1, 2}, 0, 6}, true},
        {"segment short of face", {{3, 1.5, 2.5}, {2, 1, 2}, 0, std::nextafter(6.0, 0.0)}, false},
        // Disk (h = 0) in the plane z = 1 touching the edge y = 1 from outside.
        {"disk on edge", {{0.5, 1.5, 1}, {0, 0, 1}, 0.5, 0}, true},
        {"disk off edge", {{0.5, 1.5, 1}, {0, 0, 1}, std::nextafter(0.5, 0.0), 0}, false},
        // Cap plane of the axis (2,3,6)/7 through the vertex (0,0,0): centre −(2,3,6), h/2 = 7.
        {"(2,3,6) cap on vertex", {{-2, -3, -6}, {2, 3, 6}, 1, 14}, true},
        {"(2,3,6) cap short of vertex", {{-2, -3, -6}, {2, 3, 6}, 1, std::nextafter(14.0, 0.0)}, false},
    };
    for (const Known& k : known) {
        Case c;
        c.kind = BoxKind::aligned;
        c.aligned = unit;
        c.cylinder = k.cyl;
        ASSERT_EQ(oracle_answer(c), k.hit) << k.what << " (the case itself is wrong): " << describe(c);
        EXPECT_EQ(exact::integer::answer(unit, k.cyl), k.hit) << k.what << ": " << describe(c);
        EXPECT_EQ(filtered::intersects(unit, k.cyl), k.hit) << k.what << ": " << describe(c);
        if (exact::hit_at_a_point(unit, k.cyl)) {
            EXPECT_TRUE(k.hit) << k.what << ": hit_at_a_point";
        }
        // The same as a canonical box (centre moved by −(0.5, 0.5, 0.5), exact) and a signed permutation.
        Cylinder<double> moved = k.cyl;
        for (int i = 0; i < 3; ++i) moved.center[i] -= 0.5;
        EXPECT_EQ(exact::integer::answer(CanonicalBox<double>{{0.5, 0.5, 0.5}}, moved), k.hit) << k.what << " canonical";
        const OrientedBox<double> turned{{0.5, 0.5, 0.5},
                                         {Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, -1}, Vec3<double>{-1, 0, 0}},
                                         {0.5, 0.5, 0.5}};
        EXPECT_EQ(exact::integer::answer(turned, k.cyl), std::optional<bool>(k.hit)) << k.what << " oriented";
    }
}

// One point tested exactly in double (exact/point.hpp): points on the surface of a cylinder decided
// in every rounding mode, points a short step off it too, and inputs too wide for the test declined.
TEST(ExactPoint, InsideExactlyDecidesSurfacePoints) {
    const Cylinder<double> z_axis{{0, 0, 0}, {0, 0, 1}, 8, 16};
    // Axis (3,4,0)/5, r = 5, h = 10: (3,4,0) is the top cap's centre, (7,1,0) on its rim.
    const Cylinder<double> oblique{{0, 0, 0}, {3, 4, 0}, 5, 10};
    const Cylinder<double> far{{1e6, -2e6, 4096}, {0, 0, 1}, 0.5, 3};
    const Cylinder<double> tiny_axis{{-0x1.cp+743, 0x1.4p+743, -0x1p+740}, {0, 0x1p-517, 0}, 0x1p+742, 0x1p+743};
    struct Known {
        const char* what;
        Vec3<double> p;
        const Cylinder<double>& c;
        std::optional<bool> inside;
    };
    const Known known[] = {
        {"side", {8, 0, 5}, z_axis, true},
        {"rim", {8, 0, 8}, z_axis, true},
        {"cap centre", {0, 0, -8}, z_axis, true},
        {"cap, a half off", {0, 0, 8.5}, z_axis, false},
        {"side, a half off", {8, 0.5, 0}, z_axis, false},
        {"oblique cap centre", {3, 4, 0}, oblique, true},
        {"oblique rim", {7, 1, 0}, oblique, true},
        {"oblique rim, 2^-10 off", {7 + 0x1p-10, 1, 0}, oblique, false},
        {"oblique rim, 2^-10 in", {7 - 0x1p-10, 1, 0}, oblique, true},
        {"far rim", {1e6 + 0.5, -2e6, 4096 + 1.5}, far, true},
        {"far, past the rim", {1e6 + 0.5, -2e6 + 0.25, 4096}, far, false},
        // One ulp off the rim: 53 bits, too wide for exact double arithmetic.
        {"rim, one ulp off", {std::nextafter(8.0, 9.0), 0, 8}, z_axis, std::nullopt},
        {"rim, a subnormal off", {8, 0x1p-1074, 8}, z_axis, std::nullopt},
        // A tiny axis beside huge lengths: |a|² would underflow, |v|² overflow.
        {"axis 2^-517, lengths 2^743", {0x1.8p+742, 0x1.8p+742, -0x1.4p+743}, tiny_axis, std::nullopt},
    };
    for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        const RoundingMode guard(mode);
        for (const Known& k : known)
            EXPECT_EQ(exact::inside_exactly(k.p, k.c), k.inside) << k.what << " in " << mode_name(mode);
    }
}

// Against exact rationals: points and cylinders of small integers times one power of two, half of them
// moved far from the origin (random, fixed seed), each answer the test gives equal to the rational one,
// in every rounding mode.
TEST(ExactPoint, InsideExactlyAgreesWithRationals) {
    const std::uint64_t seed = 2131;
    std::mt19937_64 rng(seed);
    auto small = [&](int bits) {
        const std::int64_t m = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits)) - (std::int64_t{1} << (bits - 1));
        return static_cast<double>(m);
    };
    auto rational_inside = [](const Vec3<double>& p, const Cylinder<double>& c) {
        using Q = Rational;
        Vec3<Q> a, v;
        for (int i = 0; i < 3; ++i) a[i] = Q(c.axis[i]), v[i] = Q(p[i]) - Q(c.center[i]);
        const Q aa = dot(a, a), av = dot(a, v), h(c.height), r(c.radius);
        return Q(4) * av * av <= h * h * aa && aa * dot(v, v) - av * av <= r * r * aa;
    };
    long decided = 0, inside = 0;
    const long n = scaled(20000);
    for (long i = 0; i < n; ++i) {
        const int bits = 2 + static_cast<int>(rng() % 10);
        const double unit = std::ldexp(1.0, static_cast<int>(rng() % 41) - 20);
        Cylinder<double> c{{small(bits) * unit, small(bits) * unit, small(bits) * unit},
                           {small(3), small(3), small(3)},
                           std::abs(small(bits)) * unit,
                           std::abs(small(bits)) * unit};
        if (c.axis[0] == 0 && c.axis[1] == 0 && c.axis[2] == 0) c.axis[2] = 1;
        Vec3<double> p{small(bits) * unit, small(bits) * unit, small(bits) * unit};
        if (i % 2 == 1)  // half of them far from the origin: only the offsets p − C count
            for (int j = 0; j < 3; ++j) {
                const double shift = small(30) * unit;
                p[j] += shift, c.center[j] += shift;
            }
        const bool want = rational_inside(p, c);
        for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
            const RoundingMode guard(mode);
            const std::optional<bool> got = exact::inside_exactly(p, c);
            if (!got) continue;
            decided += mode == FE_TONEAREST;
            inside += mode == FE_TONEAREST && *got;
            ASSERT_EQ(*got, want) << "seed " << seed << " case " << i << " in " << mode_name(mode)
                                  << ": exact::inside_exactly(Vec3<double>" << hex(p) << ", Cylinder<double>{"
                                  << hex(c.center) << ", " << hex(c.axis) << ", " << hex(c.radius) << ", "
                                  << hex(c.height) << "})";
        }
    }
    std::printf("inside_exactly: %ld of %ld decided, %ld inside\n", decided, n, inside);
    EXPECT_GT(decided, n * 9 / 10);
    EXPECT_GT(inside, decided / 40);
}

// The voxels beside a cylinder whose caps and side touch cell faces exactly (the unit cells of
// [-10, 11]³, radius 8, height 16, axis z at the grid node 0): each cell the point proves is a hit by
// the oracle, and the cells touching a cap, the side or a rim are proved.
const Cylinder<double> kVoxelCylinder{{0, 0, 0}, {0, 0, 1}, 8, 16};
std::vector<Case> voxel_cases() {
    std::vector<Case> out;
    for (int i = -10; i < 11; ++i)
        for (int j = -10; j < 11; ++j)
            for (int k = -10; k < 11; ++k) {
                Case q;
                q.kind = BoxKind::aligned;
                q.aligned = {{double(i), double(j), double(k)}, {i + 1.0, j + 1.0, k + 1.0}};
                q.cylinder = kVoxelCylinder;
                out.push_back(q);
            }
    return out;
}

TEST(ExactPoint, HitsTouchingVoxels) {
    const Cylinder<double>& c = kVoxelCylinder;
    long proved = 0;
    for (const Case& q : voxel_cases()) {
        if (!exact::hit_at_a_point(q.aligned, c)) continue;
        ++proved;
        ASSERT_TRUE(oracle_answer(q)) << describe(q);
    }
    std::printf("hit_at_a_point: %ld voxels proved\n", proved);
    const AlignedBox<double> cap{{2, 3, 8}, {3, 4, 9}}, side{{8, 0, 3}, {9, 1, 4}}, rim{{8, 0, 8}, {9, 1, 9}},
        below_rim{{8, -1, -9}, {9, 0, -8}};
    for (const AlignedBox<double>& b : {cap, side, rim, below_rim}) EXPECT_TRUE(exact::hit_at_a_point(b, c));
    EXPECT_TRUE(exact::hit_at_a_point(CanonicalBox<double>{{1, 1, 1}}, Cylinder<double>{{9, 0, 0}, {0, 0, 1}, 8, 2}));
    EXPECT_FALSE(exact::hit_at_a_point(AlignedBox<double>{{9, 0, 0}, {10, 1, 1}}, c));
}

// A cylinder along a coordinate axis beside an aligned box, decided whole in double: every voxel of the
// touching voxel set (hits and misses), in every rounding mode, against the oracle; hand-made cases along
// each axis, with a negative or longer axis vector, far from the origin, and operands too wide.
TEST(ExactPoint, AlongAnAxisDecidesEveryVoxel) {
    const Cylinder<double>& c = kVoxelCylinder;
    long cells = 0;
    for (const Case& q : voxel_cases()) {
        const bool want = oracle_answer(q);
        ++cells;
        for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
            const RoundingMode guard(mode);
            ASSERT_EQ(exact::decide_along_an_axis(q.aligned, c), std::optional<bool>(want))
                << mode_name(mode) << ": " << describe(q);
        }
    }
    EXPECT_EQ(cells, 9261);
    struct Known {
        const char* what;
        AlignedBox<double> box;
        Cylinder<double> cyl;
        std::optional<bool> answer;
    };
    const AlignedBox<double> unit{{0, 0, 0}, {1, 1, 1}};
    const Known known[] = {
        {"side on face, axis -3z", unit, {{3, 0.5, 0.5}, {0, 0, -3}, 2, 1}, true},
        {"side on face, axis 2x", unit, {{0.5, 2.5, 0.5}, {2, 0, 0}, 1.5, 1}, true},
        {"side a quarter off, axis 2x", unit, {{0.5, 2.5, 0.5}, {2, 0, 0}, 1.25, 1}, false},
        {"apart along the axis y", unit, {{4, 5, 0.5}, {0, 1, 0}, 5, 1}, false},
        {"rim on vertex, axis y", unit, {{4, 0.5, 5}, {0, 1, 0}, 5, 1}, true},
        {"rim short of vertex, axis y", unit, {{4, 0.5, 5}, {0, 1, 0}, 4.5, 1}, false},
        {"cap on face", unit, {{0.5, 0.5, 2}, {0, 0, 1}, 0.25, 2}, true},
        {"cap a quarter off", unit, {{0.5, 0.5, 2.25}, {0, 0, 1}, 0.25, 2}, false},
        {"segment through the box", unit, {{0.5, 0.5, 0.5}, {0, 0, 1}, 0, 4}, true},
        {"segment beside the box", unit, {{1.5, 0.5, 0.5}, {0, 0, 1}, 0, 4}, false},
        {"drill hole in a UTM block", {{500000, 4200000, 1190}, {500001, 4200001, 1191}},
         {{500000.5, 4200000.25, 1200}, {0, 0, 1}, 0.0625, 20}, true},
        {"drill hole beside a UTM block", {{500001, 4200000, 1190}, {500002, 4200001, 1191}},
         {{500000.5, 4200000.25, 1200}, {0, 0, 1}, 0.0625, 20}, false},
        {"tilted axis", unit, {{0.5, 0.5, 2}, {0, 0x1p-30, 1}, 0.25, 2}, std::nullopt},
        {"radius one ulp off", unit, {{3, 0.5, 0.5}, {0, 0, 1}, std::nextafter(2.0, 3.0), 1}, std::nullopt},
    };
    for (const Known& k : known) {
        Case q;
        q.kind = BoxKind::aligned;
        q.aligned = k.box;
        q.cylinder = k.cyl;
        if (k.answer) {
            ASSERT_EQ(oracle_answer(q), *k.answer) << k.what << " (the case itself is wrong): " << describe(q);
        }
        for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
            const RoundingMode guard(mode);
            EXPECT_EQ(exact::decide_along_an_axis(k.box, k.cyl), k.answer) << k.what << " in " << mode_name(mode);
        }
    }
}

TEST(ExactStage, DyadicDecompositionIsExact) {
    const double values[] = {1.0, -1.0, 3.0, 0.1, -1e-300, 1e308, std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
                             -3 * std::numeric_limits<double>::denorm_min(), 6.0, 0.75, 1099511627776.0};
    for (double x : values) {
        const exact::integer::Dyadic d = exact::integer::dyadic(x);
        EXPECT_NE(d.m % 2, 0) << x;  // odd: the smallest integer for x
        EXPECT_EQ(Rational(mpz_class(static_cast<long>(d.m))) *
                      (d.e >= 0 ? Rational(mpz_class(1) << static_cast<unsigned>(d.e))
                                : Rational(mpz_class(1), mpz_class(1) << static_cast<unsigned>(-d.e))),
                  to_rational(x))
            << x;
    }
    EXPECT_EQ(exact::integer::dyadic(0.0).m, 0);
    EXPECT_EQ(exact::integer::dyadic(-0.0).m, 0);
}

TEST(ExactStage, QuadraticIntegerSignMatchesQField) {
    std::mt19937_64 rng(2105);
    std::uniform_int_distribution<long> small(-30, 30);
    for (int i = 0; i < 20000; ++i) {
        const long d = i % 7 == 0 ? small(rng) * small(rng) % 37 + 37 : std::abs(small(rng));  // squares too
        const long dd = i % 5 == 0 ? (small(rng) % 6) * (small(rng) % 6) : d;
        const long a = small(rng), b = small(rng);
        const QuadraticRing<mpz_class> ring{mpz_class(std::abs(dd))};
        const QuadraticField<Rational> field{Rational(std::abs(dd))};
        const QFRational ref(Rational(a), Rational(b), field);
        EXPECT_EQ(ring.sign(mpz_class(a), mpz_class(b)), ref.sign()) << a << " + " << b << "*sqrt(" << std::abs(dd) << ")";
    }
}

// The sign of a + b√d for wide a, b, d, where it compares approximations of a² and b²·d before the
// exact squares: a = ⌊b·√d⌋ + k for small k (a² − b²·d of either sign, tiny beside a²), and a moved
// from there by 2^−s of itself (s up to 70, around the approximations' 2^−40 threshold), in mpz_class,
// FixedInt and EpsilonSeries (a, b, d each c·ε^v, of different orders v), against exact integers.
TEST(ExactStage, QuadraticSignOfWideValuesIsExact) {
    std::mt19937_64 rng(2110);
    auto random_int = [&](int bits) -> mpz_class {  // not auto: z + 1 would refer to z after return
        mpz_class z(0);
        for (int b = 0; b < bits; b += 50) z = (z << 50) + static_cast<long>(rng() >> 14);
        z >>= static_cast<unsigned>((bits + 49) / 50 * 50 - bits);
        return z + 1;
    };
    using F = FixedInt<32>;
    using S = EpsilonSeries<F, 2>;
    auto to_fixed = [](const mpz_class& z) {
        F f(0);
        const std::size_t words = mpz_sizeinbase(z.get_mpz_t(), 2) / 62 + 1;
        for (std::size_t w = words; w-- > 0;) {
            f <<= 62u;
            const mpz_class part = (z >> static_cast<unsigned>(62 * w)) & ((mpz_class(1) << 62) - 1);
            f = f + F(static_cast<long>(part.get_ui()));
        }
        return f;
    };
    const int E = 400;
    SeriesContext& ctx = SeriesContext::get();
    ctx.E = E;
    ctx.order = 2;
    long checked = 0, close = 0;
    for (int i = 0; i < 4000; ++i) {
        const mpz_class d = random_int(1 + static_cast<int>(rng() % 200));
        const mpz_class b = random_int(1 + static_cast<int>(rng() % 500));
        const mpz_class bbd = b * b * d;
        mpz_class a = sqrt(bbd);  // not of a temporary: gmpxx's sqrt() would keep a reference to it
        if (i % 2 == 0) {
            a += static_cast<long>(rng() % 5) - 2;
        } else {
            const auto shift = static_cast<unsigned>(rng() % 70);
            const mpz_class step = a >> shift;
            a += (rng() & 1) ? step : mpz_class(-step);
        }
        if (sgn(a) <= 0) continue;
        const mpz_class diff = a * a - bbd;
        const int want = sgn(diff);  // the sign of a − b√d
        close += abs(diff) * (mpz_class(1) << 40) < a * a;
        // a − b√d and −a + b√d, in each type.
        const QuadraticRing<mpz_class> zring{d};
        EXPECT_EQ(zring.sign(a, mpz_class(-b)), want) << a << " - " << b << "*sqrt(" << d << ")";
        EXPECT_EQ(zring.sign(mpz_class(-a), b), -want) << a << " - " << b << "*sqrt(" << d << ")";
        if (mpz_sizeinbase(a.get_mpz_t(), 2) < 32 * 64 - 64) {
            FixedOverflow::flag() = false;
            const QuadraticRing<F> fring{to_fixed(d)};
            const int got = fring.sign(to_fixed(a), F(-to_fixed(b)));
            if (!FixedOverflow::flag()) {
                EXPECT_EQ(got, want) << a << " - " << b << "*sqrt(" << d << ")";
            }
            // The same values at powers of ε: a·ε^(va), b·ε^(vb), d·ε^(2(va − vb)), so that the
            // orders match and only the coefficients decide.
            const int vb = static_cast<int>(rng() % 2), va = vb + static_cast<int>(rng() % 2);
            ctx.undecided = false;
            const QuadraticRing<S> sring{S::term(to_fixed(d), 2 * (va - vb))};
            const int sgot = sring.sign(S::term(to_fixed(a), va), S::term(F(-to_fixed(b)), vb));
            if (!FixedOverflow::flag() && !ctx.undecided) {
                EXPECT_EQ(sgot, want) << a << " - " << b << "*sqrt(" << d << ") at orders " << va << ", " << vb;
            }
        }
        ++checked;
    }
    EXPECT_GT(checked, 3500);
    EXPECT_GT(close, 2000);  // where the approximations cannot decide
}

// The ring's dot product, squared norm and square (each with one product by d) against Q(√d).
TEST(ExactStage, QuadraticRingProductsMatchQField) {
    std::mt19937_64 rng(2108);
    std::uniform_int_distribution<long> small(-1000, 1000);
    for (int i = 0; i < 2000; ++i) {
        const long d = std::abs(small(rng));
        const QuadraticRing<mpz_class> ring{mpz_class(d)};
        const QuadraticField<Rational> field{Rational(d)};
        Vec3<QuadInt<mpz_class>> x, y;
        QFRational dot_ref(Rational(0), Rational(0), field), norm_ref = dot_ref;
        for (std::size_t n = 0; n < 3; ++n) {
            x[n] = {mpz_class(small(rng)), mpz_class(small(rng))};
            y[n] = {mpz_class(small(rng)), mpz_class(small(rng))};
            const QFRational xn(Rational(x[n].a), Rational(x[n].b), field), yn(Rational(y[n].a), Rational(y[n].b), field);
            dot_ref += xn * yn;
            norm_ref += xn * xn;
        }
        auto in_field = [&field](const QuadInt<mpz_class>& q) { return QFRational(Rational(q.a), Rational(q.b), field); };
        const QFRational x0(Rational(x[0].a), Rational(x[0].b), field);
        EXPECT_TRUE(in_field(ring.dot(x, y)) == dot_ref) << "d = " << d << ", case " << i;
        EXPECT_TRUE(in_field(ring.norm2(x)) == norm_ref) << "d = " << d << ", case " << i;
        EXPECT_TRUE(in_field(ring.square(x[0])) == x0 * x0) << "d = " << d << ", case " << i;
    }
}

}  // namespace
}  // namespace boxcyl

namespace boxcyl {
namespace {

// FixedInt against mpz_class on random operands of 0–5 limbs (sums and differences also in place, and
// onto the operand itself): every result equals mpz's while the overflow flag stays down, and the flag
// rises exactly when a result needs more limbs than it has.
TEST(ExactStage, FixedIntMatchesMpz) {
    using F = FixedInt<6>;
    std::mt19937_64 rng(2106);
    auto random_pair = [&] {
        const int limbs = static_cast<int>(rng() % 5);  // up to 4 limbs: products of 8 overflow 6
        F f(0);
        mpz_class z(0);
        for (int i = 0; i < limbs; ++i) {
            const auto part = static_cast<long>(rng() >> 1);
            f <<= 63u;
            f = f + F(part);
            z = (z << 63) + part;
        }
        if (rng() & 1) f = -f, z = -z;
        return std::pair<F, mpz_class>{f, z};
    };
    long checked = 0, overflows = 0;
    for (int i = 0; i < 30000; ++i) {
        FixedOverflow::flag() = false;
        auto [a, za] = random_pair();
        auto [b, zb] = random_pair();
        ASSERT_FALSE(FixedOverflow::flag());
        // 4–7: in place, also onto the operand itself (x += x, x −= x).
        const int op = static_cast<int>(rng() % 8);
        F r;
        mpz_class zr;
        switch (op) {
            case 0: r = a + b, zr = za + zb; break;
            case 1: r = a - b, zr = za - zb; break;
            case 2: r = a * b, zr = za * zb; break;
            case 4: r = a, r += b, zr = za + zb; break;
            case 5: r = a, r -= b, zr = za - zb; break;
            case 6: r = a, r += r, zr = za + za; break;
            case 7: r = a, r -= r, zr = 0; break;
            default: {
                const unsigned k = static_cast<unsigned>(rng() % 200);
                r = a, zr = za;
                r <<= k;
                zr <<= k;
            }
        }
        const bool fits = mpz_sizeinbase(zr.get_mpz_t(), 2) <= std::size_t{384};  // 6 limbs
        if (FixedOverflow::flag()) {
            ++overflows;
            // Multiplication may refuse a product of n + m limbs that would have fit in n + m − 1.
            EXPECT_TRUE(!fits || op == 2) << "op " << op << ": " << za << ", " << zb;
            continue;
        }
        ASSERT_TRUE(fits) << "op " << op << " overflowed silently: " << za << ", " << zb;
        ++checked;
        EXPECT_EQ(r.to_mpz(), zr) << "op " << op << ": " << za << ", " << zb;
        EXPECT_EQ(sgn(r), sgn(zr));
        EXPECT_EQ(cmp(r, a), cmp(zr, za));
    }
    EXPECT_GT(checked, 15000);
    EXPECT_GT(overflows, 100);
}

// EpsilonSeries against exact rationals: straight-line programs of sums, differences and products of
// values c_0 + c_1·ε and c_1·ε + c_2·ε² (ε = 2^−E) with coefficients of up to 150 bits, many of them
// equal at order 0 so that differences cancel there, and products of the small ones of order ε² and
// beyond. Every sign the series gives while its undecided flag stays down is the
// exact sign; the flag rises when a sign hangs beyond the kept order (and on such a cancellation at
// order 0 and 1 alike, which the programs make common).
TEST(ExactStage, EpsilonSeriesSignsAreExact) {
    using S = EpsilonSeries<FixedInt<16>, 2>;
    std::mt19937_64 rng(2108);
    auto random_int = [&](int bits) {
        mpz_class z(0);
        for (int b = 0; b < bits; b += 50) z = (z << 50) + static_cast<long>(rng() >> 14);
        z >>= static_cast<unsigned>((bits + 49) / 50 * 50 - bits);
        return (rng() & 1) ? mpz_class(-z) : z;
    };
    auto to_fixed = [](const mpz_class& z) {
        FixedInt<16> f(0);
        const mpz_class mag = abs(z);
        const std::size_t words = mpz_sizeinbase(mag.get_mpz_t(), 2) / 62 + 1;
        for (std::size_t w = words; w-- > 0;) {
            f <<= 62u;
            const mpz_class part = (mag >> static_cast<unsigned>(62 * w)) & ((mpz_class(1) << 62) - 1);
            f = f + FixedInt<16>(static_cast<long>(part.get_ui()));
        }
        return sgn(z) < 0 ? FixedInt<16>(-f) : f;
    };
    long decided = 0, undecided = 0;
    for (int program = 0; program < 400; ++program) {
        const int E = 200 + static_cast<int>(rng() % 200);
        const Rational eps(mpz_class(1), mpz_class(1) << static_cast<unsigned>(E));
        SeriesContext& ctx = SeriesContext::get();
        ctx.E = E;
        ctx.order = 2;
        std::vector<S> s;
        std::vector<Rational> q;
        const mpz_class base = random_int(100);
        for (int i = 0; i < 8; ++i) {  // atoms: base or random at order 0, plus a tiny part
            if (i >= 6) {  // or of order ε alone (a tiny axis component), with an ε² part
                const mpz_class c1 = random_int(static_cast<int>(1 + rng() % 60));
                const mpz_class c2 = (rng() % 2 == 0) ? mpz_class(0) : random_int(static_cast<int>(1 + rng() % 60));
                s.push_back(S::term(to_fixed(c1), 1) + S::term(to_fixed(c2), 2));
                q.push_back(Rational(c1) * eps + Rational(c2) * eps * eps);
                continue;
            }
            const mpz_class c0 = (i % 2 == 0) ? base : random_int(static_cast<int>(1 + rng() % 100));
            const mpz_class c1 = (rng() % 3 == 0) ? mpz_class(0) : random_int(static_cast<int>(1 + rng() % 50));
            s.push_back(S::term(to_fixed(c0), 0) + S::term(to_fixed(c1), 1));
            q.push_back(Rational(c0) + Rational(c1) * eps);
        }
        for (int step = 0; step < 12; ++step) {
            const std::size_t a = rng() % s.size(), b = rng() % s.size(), c = rng() % s.size();
            const int op = static_cast<int>(rng() % 5);
            FixedOverflow::flag() = false;
            ctx.undecided = false;
            // op 3: (a·b)·c − a·(b·c), exactly 0, with different dropped terms on each side. op 4: an
            // integer times a series (its own product path), on either side.
            const mpz_class k = random_int(static_cast<int>(1 + rng() % 60));
            const S r = op == 0   ? S(s[a] + s[b])
                        : op == 1 ? S(s[a] - s[b])
                        : op == 2 ? S(s[a] * s[b])
                        : op == 3 ? S(S(s[a] * s[b]) * s[c] - s[a] * S(s[b] * s[c]))
                        : (step % 2 == 0) ? S(S::term(to_fixed(k), 0) * s[a])
                                          : S(s[a] * S::term(to_fixed(k), 0));
            const Rational rq = op == 0   ? Rational(q[a] + q[b])
                                : op == 1 ? Rational(q[a] - q[b])
                                : op == 2 ? Rational(q[a] * q[b])
                                : op == 3 ? Rational(0)
                                          : Rational(Rational(k) * q[a]);
            if (FixedOverflow::flag()) break;  // coefficients past 16 limbs: the program ends
            const int sign = sgn(r);
            if (ctx.undecided) {
                ++undecided;
            } else {
                ++decided;
                ASSERT_EQ(sign, sgn(rq)) << "program " << program << " step " << step << " op " << op << " E " << E;
            }
            s.push_back(r);
            q.push_back(rq);
        }
    }
    std::printf("EpsilonSeries: %ld signs decided, %ld undecided\n", decided, undecided);
    EXPECT_GT(decided, 3000);
    EXPECT_GT(undecided, 300);
}

// Inputs of two scales (a tiny axis component beside the others, tiny lengths beside the others, both)
// decided in EpsilonSeries: the answer agrees with the oracle, and nearly every such query is decided
// there. The touching generator's cases get a tiny tilt (a zero axis component made 2^−k·m, k from 300
// to 1074) and, in a third of them, a zero length made tiny; the adversarial set's subnormal tilts
// come as generated.
TEST(ExactStage, TwoScaleInputsAgreeWithOracle) {
    const std::uint64_t seed = 2109;
    TouchingGenerator gen(seed);
    std::mt19937_64 rng(seed);
    long tried = 0, decided = 0, wrong = 0;
    auto check = [&](const Case& c, const std::string& where) {
        const std::optional<bool> got = with_box(c, [](const auto& b, const Cylinder<double>& cyl) -> std::optional<bool> {
            if constexpr (std::is_same_v<std::decay_t<decltype(b)>, OrientedBox<double>>) {
                if (!signed_permutation(b.axes)) return std::nullopt;
            }
            return exact::integer::answer_two_scale(b, cyl);
        });
        ++tried;
        if (!got) return;
        ++decided;
        const bool want = oracle_answer(c);
        if (*got != want && ++wrong <= 10)
            ADD_FAILURE() << where << ": EpsilonSeries stage answered " << *got << ", oracle " << want << "\n  "
                          << describe(c);
    };
    const long n = scaled(1500);
    for (long i = 0; i < n; ++i) {
        Case c = gen.next();
        if (c.kind == BoxKind::oriented) {
            if (!signed_permutation(c.oriented.axes)) continue;
        }
        Vec3<double>& axis = c.cylinder.axis;
        int zero = -1;
        for (int k = 0; k < 3; ++k)
            if (axis[k] == 0) zero = k;
        if (zero < 0) continue;
        const int k = 300 + static_cast<int>(rng() % 775);
        const double tiny = std::ldexp(static_cast<double>(1 + rng() % 1000), -k);
        axis[zero] = (rng() & 1) ? tiny : -tiny;
        if (i % 3 == 0) {  // a zero centre coordinate made tiny too
            for (int j = 0; j < 3; ++j)
                if (c.cylinder.center[j] == 0) {
                    c.cylinder.center[j] = std::ldexp(static_cast<double>(1 + rng() % 7), -1000 - static_cast<int>(rng() % 70));
                    break;
                }
        }
        check(c, "touching seed " + std::to_string(seed) + " case " + std::to_string(i) + " tilted");
    }
    std::mt19937_64 adv(0xb0c5c706);
    for (int i = 0; i < 2048; ++i) {
        const Case c = adversarial_case(adv);
        if (c.kind == BoxKind::oriented) continue;
        const Vec3<double>& a = c.cylinder.axis;
        const bool subnormal = (a[0] != 0 && std::fabs(a[0]) < 0x1p-1022) || (a[1] != 0 && std::fabs(a[1]) < 0x1p-1022) ||
                               (a[2] != 0 && std::fabs(a[2]) < 0x1p-1022);
        if (subnormal) check(c, "adversarial seed 0xb0c5c706 case " + std::to_string(i));
    }
    std::printf("two scales: %ld queries, %ld decided in EpsilonSeries, %ld wrong\n", tried, decided, wrong);
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(tried, 300);
    EXPECT_GT(decided, tried * 9 / 10);
}

// Narrow inputs of two scales go to the series run before the middle stage: a cylinder lying on the
// face y = 1 of the cube [−1, 1]³ (axis along x, radius ½ at height 1.5), its axis tilted by a few
// subnormals either way, its radius and height moved by an ulp; and a cylinder of 2^−1000 on a box of
// 2^1000.
TEST(ExactStage, NarrowTwoScaleInputsAnswerBeforeTheMiddleStage) {
    const double denorm = std::numeric_limits<double>::denorm_min();
    long checked = 0;
    for (int k = 1; k <= 3; ++k)
        for (const double side : {-1.0, 1.0})
            for (const double r : {0.5, std::nextafter(0.5, 0.0), std::nextafter(0.5, 1.0)})
                for (const double h : {1.0, std::nextafter(1.0, 2.0)}) {
                    Case c;
                    c.kind = BoxKind::aligned;
                    c.aligned = AlignedBox<double>{{-1, -1, -1}, {1, 1, 1}};
                    c.cylinder = Cylinder<double>{{0, 1.5, 0}, {1, side * k * denorm, 0}, r, h};
                    const bool want = oracle_answer(c);
                    ASSERT_TRUE(exact::integer::narrow_two_scale(c.aligned, c.cylinder)) << describe(c);
                    EXPECT_EQ(exact::answer(c.aligned, c.cylinder, exact::Tier::series), std::optional<bool>(want))
                        << describe(c);
                    const filtered::Result got = filtered::query(c.aligned, c.cylinder);
                    EXPECT_EQ(got.intersect, want) << describe(c);
                    ++checked;
                }
    // A cylinder of 2^−1000 against the face x = 0 of a box of 2^1000: its side on the face (exactly
    // touching, which only exact arithmetic decides), or an ulp of its radius off it either way.
    const double s = 0x1p-1000, B = 0x1p+1000;
    for (const double r : {s, std::nextafter(s, 0.0), std::nextafter(s, 1.0)}) {
        Case c;
        c.kind = BoxKind::aligned;
        c.aligned = AlignedBox<double>{{0, 0, 0}, {B, B, B}};
        c.cylinder = Cylinder<double>{{-s, s, s}, {0, 0, 1}, r, s};
        const bool want = oracle_answer(c);
        EXPECT_EQ(want, r >= s) << describe(c);
        ASSERT_TRUE(exact::integer::narrow_two_scale(c.aligned, c.cylinder)) << describe(c);
        EXPECT_EQ(exact::answer(c.aligned, c.cylinder, exact::Tier::series), std::optional<bool>(want))
            << describe(c);
        const filtered::Result got = filtered::query(c.aligned, c.cylinder);
        EXPECT_EQ(got.intersect, want) << describe(c);
        if (r == s) {
            EXPECT_TRUE(got.exact_used) << describe(c);
        }
        ++checked;
    }
    EXPECT_EQ(checked, 39);
}

// Runs f(arg) on a thread with a stack of `bytes`, allocated and painted here; returns the bytes of it
// used (the high-water mark: the bytes no longer holding the paint).
std::size_t used_stack(std::size_t bytes, void* (*f)(void*), void* arg) {
    constexpr unsigned char kPaint = 0xa5;
    void* memory = nullptr;
    EXPECT_EQ(posix_memalign(&memory, 1 << 16, bytes), 0);
    std::memset(memory, kPaint, bytes);
    pthread_attr_t attr;
    EXPECT_EQ(pthread_attr_init(&attr), 0);
    EXPECT_EQ(pthread_attr_setstack(&attr, memory, bytes), 0);
    pthread_t thread;
    EXPECT_EQ(pthread_create(&thread, &attr, f, arg), 0);
    EXPECT_EQ(pthread_join(thread, nullptr), 0);
    pthread_attr_destroy(&attr);
    const auto* painted = static_cast<const unsigned char*>(memory);
    std::size_t untouched = 0;
    while (untouched < bytes && painted[untouched] == kPaint) ++untouched;
    std::free(memory);
    return bytes - untouched;
}

// The stack the exact stage needs, on its deepest path: a two-scale query whose signs hang beyond the
// series' order 2 (two tiny axis components 104 binary orders apart beside a large one, integer lengths),
// so that it runs both series runs, the order-4 one deciding.
struct DeepestQuery {
    CanonicalBox<double> box{{0x1.8p+13, 0x1.8p+13, 0x1p+12}};
    Cylinder<double> cyl{{0x1.cp+14, -0x1.8p+13, -0x1p+12}, {-0x1.338p-408, 0x1p+0, 0x1.a28p-512}, 0x1p+14, 0x1.8p+14};
    bool series_answered = false, answer = false, room_known = false;

    static void* run(void* self) {
        auto& q = *static_cast<DeepestQuery*>(self);
        q.room_known = exact::stack_room() != std::numeric_limits<std::size_t>::max();
        q.series_answered = exact::integer::answer_two_scale(q.box, q.cyl).has_value();
        q.answer = filtered::intersects(q.box, q.cyl);
        return nullptr;
    }
    bool oracle() const {
        Case c;
        c.kind = BoxKind::canonical;
        c.canonical = box;
        c.cylinder = cyl;
        return oracle_answer(c);
    }
    std::size_t on_stack_of(std::size_t bytes) { return used_stack(bytes, &run, this); }
};

TEST(ExactStage, StackHighWaterMark) {
    DeepestQuery q;
    const std::size_t used = q.on_stack_of(std::size_t{8} << 20);
    std::printf("exact stage, deepest path: %zu KB of stack\n", used >> 10);
    // The path: the order-2 run hangs, the order-4 run answers.
    const exact::integer::TwoScale<8> L(exact::integer::lengths(q.box, q.cyl));
    const exact::integer::TwoScale<3> D({q.cyl.axis[0], q.cyl.axis[1], q.cyl.axis[2]});
    ASSERT_LT(L.gap(), 0);
    bool overflow = false;
    EXPECT_FALSE((exact::integer::answer_series<exact::integer::kSeriesLimbs, 2>(q.box, q.cyl, D.gap(), overflow)));
    EXPECT_FALSE(overflow);
    EXPECT_TRUE(q.room_known);
    EXPECT_TRUE(q.series_answered);
    EXPECT_EQ(q.answer, q.oracle());
    EXPECT_GT(used, std::size_t{64} << 10);  // the series runs ran (mpz_class alone takes about 11 KB)
    EXPECT_LT(used, std::size_t{2} << 20);
}

// With less stack left than the series runs need, the stage skips them: a 128 KB stack (musl's
// default) answers the deepest query, in mpz_class.
TEST(ExactStage, SmallStackSkipsTheSeriesRuns) {
    DeepestQuery q;
    const std::size_t used = q.on_stack_of(std::size_t{128} << 10);
    std::printf("exact stage on a 128 KB stack: %zu KB used\n", used >> 10);
    EXPECT_TRUE(q.room_known);
    EXPECT_FALSE(q.series_answered);
    EXPECT_EQ(q.answer, q.oracle());
    EXPECT_LT(used, std::size_t{64} << 10);  // not the series runs' hundreds of KB
}

// A rounded rotation whose exact test runs every clipped edge and face cut (a miss) with values beyond
// 16 limbs: a unit box beside the side of a cylinder of radius 2^349, so that the lengths span about
// 400 bits. The parallelepiped route's deepest path, in 64 limbs with room for them, else in 16 limbs
// and then mpz_class.
struct DeepestParallelepiped {
    Parallelepiped<double> box{{-0x1.7b0efe198ce7p-1, 0x1.80925c54491ep-2, 0x1.2d07bb2d46a5cp-1},
                               {Vec3<double>{0x1.3a10894ca2c2fp-2, -0x1.a2c07a541df08p-1, -0x1.f28656101c4cdp-2},
                                Vec3<double>{-0x1.b2966037eb342p-6, 0x1.02058f46bb397p-1, -0x1.ba05e4e4d181ep-1},
                                Vec3<double>{0x1.e722894857c3cp-1, 0x1.1c5d16682cd0ep-2, 0x1.101d77df0e8f8p-3}},
                               {0x1.1f2c64cd04434p-1, 0x1.cac931a548d05p-1, 0x1.25991cad8911p-3}};
    Cylinder<double> cyl{{0x1.2126ed61b5bf7p+348, 0x1.62afbc8df6c17p+348, 0x1.c9a8b00501c8ep+347},
                         {0x1.b2b457f4e83acp-1, -0x1.bc8b46be234f4p-2, -0x1.998d608812b6ap-2}, 0x1.ffa38ce052955p+348,
                         0x1p+351};
    bool answer = true, fixed_answered = false;

    static void* run(void* self) {
        auto& q = *static_cast<DeepestParallelepiped*>(self);
        q.fixed_answered = exact::integer::parallelepiped_small(q.box, q.cyl).has_value();
        q.answer = exact::integer::intersects_parallelepiped(q.box, q.cyl);
        return nullptr;
    }
    std::size_t on_stack_of(std::size_t bytes) { return used_stack(bytes, &run, this); }
};

TEST(ExactStage, ParallelepipedStack) {
    DeepestParallelepiped q;
    FixedOverflow::flag() = false;
    (void)exact::integer::detail::run_turned<exact::integer::Small>(q.box, q.cyl);
    ASSERT_TRUE(FixedOverflow::flag()) << "the case must outgrow 16 limbs";
    const bool want = exact::integer::detail::run_turned<mpz_class>(q.box, q.cyl);
    EXPECT_FALSE(want);
    Case c;
    c.kind = BoxKind::oriented;
    c.oriented = {q.box.center, q.box.axes, q.box.extents};
    c.cylinder = q.cyl;
    EXPECT_EQ(oracle_answer(c), want);

    const std::size_t used = q.on_stack_of(std::size_t{8} << 20);
    std::printf("parallelepiped route, deepest path in 64 limbs: %zu KB of stack\n", used >> 10);
    EXPECT_TRUE(q.fixed_answered);
    EXPECT_EQ(q.answer, want);
    EXPECT_LT(used, exact::integer::kParallelepipedStackRoom);

    DeepestParallelepiped small;
    const std::size_t used_small = small.on_stack_of(std::size_t{128} << 10);
    std::printf("the same on a 128 KB stack: %zu KB used\n", used_small >> 10);
    EXPECT_FALSE(small.fixed_answered);  // 16 limbs: overflowed
    EXPECT_EQ(small.answer, want);
}

// The stage's two integer types give the same answers wherever the fixed one does not overflow.
TEST(ExactStage, FixedAndMpzStagesAgree) {
    TouchingGenerator gen(2107);
    long compared = 0;
    for (int i = 0; i < 3000; ++i) {
        const Case c = gen.next();
        with_box(c, [&](const auto& b, const Cylinder<double>& cyl) {
            FixedOverflow::flag() = false;
            auto small = exact::integer::problem<exact::integer::Small>(b, cyl);
            auto big = exact::integer::problem<mpz_class>(b, cyl);
            if constexpr (std::is_same_v<decltype(small), exact::integer::Problem<exact::integer::Small>>) {
                const bool s = exact::integer::intersects(small), m = exact::integer::intersects(big);
                if (!FixedOverflow::flag()) {
                    ++compared;
                    EXPECT_EQ(s, m) << describe(c);
                }
            } else if (small) {
                const bool s = exact::integer::intersects(*small), m = exact::integer::intersects(*big);
                if (!FixedOverflow::flag()) {
                    ++compared;
                    EXPECT_EQ(s, m) << describe(c);
                }
            }
            return 0;
        });
    }
    EXPECT_GT(compared, 2000);
}

}  // namespace
}  // namespace boxcyl

namespace boxcyl {
namespace {

// Frames perturbed by up to 2e-6 (far from orthonormal next to rounding, still valid), and turned
// boxes with a cap flush with a face, one ulp off, and the parallelepiped test in both integer types.
TEST(ExactStage, ParallelepipedAgreesWithOracle) {
    const std::uint64_t seed = 2108;
    CaseGenerator gen(seed);
    StageTally t;
    const long n = scaled(1500);
    for (long i = 0; i < n; ++i) t.check(perturbed_frame(gen), "perturbed frame seed " + std::to_string(seed) + " case " + std::to_string(i));
    t.print("perturbed frames");
    EXPECT_EQ(t.wrong, 0);
    EXPECT_GT(t.judged_parallelepiped, n / 2);

    // A box turned about z by a rounded 0.3 rad, top face z = 1 exactly; a cap flush with it, then one
    // ulp above it; and the same box flat (zero height), a disk in its plane and one ulp above.
    const double cs = std::cos(0.3), sn = std::sin(0.3);
    const OrientedBox<double> box{{0, 0, 0.5}, {Vec3<double>{cs, sn, 0}, Vec3<double>{-sn, cs, 0}, Vec3<double>{0, 0, 1}},
                                  {1, 2, 0.5}};
    const Cylinder<double> flush{{0.25, -0.5, 2}, {0, 0, 1}, 0.5, 2};
    Cylinder<double> above = flush;
    above.center[2] = std::nextafter(2.0, 3.0);
    OrientedBox<double> flat = box;
    flat.center[2] = 1;
    flat.extents[2] = 0;
    const Cylinder<double> disk{{0.5, 0.25, 1}, {0, 1, 1}, 0.5, 0};
    Cylinder<double> disk_above = disk;
    disk_above.center[2] = std::nextafter(1.0, 2.0);
    const Cylinder<double> piercing{{0.5, 0.25, 1}, {1, 2, 3}, 0, 0.5};  // a short segment through the flat box
    for (const auto& [b, cyl, hit] : {std::tuple{box, flush, true}, std::tuple{box, above, false}, std::tuple{flat, disk, true},
                                      std::tuple{flat, disk_above, true}, std::tuple{flat, piercing, true}}) {
        Case c;
        c.kind = BoxKind::oriented;
        c.oriented = b;
        c.cylinder = cyl;
        ASSERT_EQ(oracle_answer(c), hit) << describe(c);
        EXPECT_EQ(exact::integer::intersects_parallelepiped(as_parallelepiped(b), cyl), hit) << describe(c);
        EXPECT_EQ(filtered::intersects(b, cyl), hit) << describe(c);
    }

    // FixedInt and mpz_class agree wherever FixedInt did not overflow.
    TouchingGenerator touching(2109);
    long compared = 0;
    for (int i = 0; i < 4000; ++i) {
        const Case c = touching.next();
        if (c.kind != BoxKind::oriented) continue;
        FixedOverflow::flag() = false;
        const bool small = exact::integer::detail::run_turned<exact::integer::Small>(as_parallelepiped(c.oriented), c.cylinder);
        if (FixedOverflow::flag()) continue;
        ++compared;
        EXPECT_EQ(small, exact::integer::detail::run_turned<mpz_class>(as_parallelepiped(c.oriented), c.cylinder)) << describe(c);
    }
    EXPECT_GT(compared, 500);
}

}  // namespace
}  // namespace boxcyl
