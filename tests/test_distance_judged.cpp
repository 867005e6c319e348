// The certified distance, boxcyl::distance, judged by the independent clearance oracle
// (tests/clearance/: exact algebraic numbers, a different method). For every case:
//   - the enclosure holds: the box comes within `upper` of the cylinder and not within the double below
//     `lower` (the oracle decides dist ≤ m exactly);
//   - it is narrow: at most 4 doubles from `lower` to `upper` (so upper − lower ≤ 4 ulp(upper));
//   - it is [0, 0] exactly when the oracle says the solids meet;
//   - the witnesses lie within their stated bound of their solids (an aligned box's exactly in it), and
//     (in round to nearest) their distance lies in the enclosure up to those bounds.
// On random pairs of every generator profile, near-touching pairs one ulp apart, a lattice of small
// integer shapes (touching exactly, rational distances), float inputs, subnormal and huge distances,
// and every rounding mode. A violation prints the case as C++ to paste into a regression test.
#include <gtest/gtest.h>

#include <algorithm>  // std::max
#include <bit>        // std::bit_cast
#include <cfenv>      // rounding modes
#include <cmath>      // std::nextafter, std::isfinite, std::abs
#include <cstdint>    // seeds
#include <cstdio>     // std::printf
#include <random>     // fixed-seed generators
#include <string>     // messages

#include "boxcyl/distance.hpp"
#include "clearance/clearance_oracle.hpp"
#include "clearance/exact_case.hpp"
#include "clearance/lattice.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"  // RoundingMode

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

Distance distance_of(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return distance(box, cyl); });
}

// The witnesses' stated bound, ‖p‖∞·2⁻⁵¹ + 2⁻¹⁰⁶⁰, exactly.
Rational witness_bound(const Vec3<double>& p) {
    const double m = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    return Rational(m) * Rational(std::ldexp(1.0, -51)) + Rational(std::ldexp(1.0, -1060));
}
Parallelepiped<Rational> point_box(const Vec3<double>& p) {
    return {to_exact(p), {Vec3<Rational>{1, 0, 0}, Vec3<Rational>{0, 1, 0}, Vec3<Rational>{0, 0, 1}}, {0, 0, 0}};
}
Cylinder<Rational> point_cylinder(const Vec3<double>& p) { return {to_exact(p), {0, 0, 1}, 0, 0}; }

struct Tally {
    long checked = 0, separated = 0, one_ulp = 0;
    int violations = 0;
};

// Judges one answer; `witness_distance` also checks the witnesses' distance against the enclosure.
void judge(const Case& c, const Distance& d, Tally& t, bool witness_distance, const std::string& where) {
    const Parallelepiped<Rational> box = exact_box(c);
    const Cylinder<Rational> cyl = to_exact(c.cylinder);
    ++t.checked;
    std::string why;
    const std::uint64_t steps = std::bit_cast<std::uint64_t>(d.upper) - std::bit_cast<std::uint64_t>(d.lower);
    if (!(d.lower >= 0 && d.lower <= d.upper)) why += " not an interval;";
    else if (steps > 4) why += " wider than 4 doubles;";
    if (std::isfinite(d.upper) && !clearance_oracle::within(box, cyl, to_rational(d.upper))) why += " upper below the distance;";
    if (d.lower > 0 && clearance_oracle::within(box, cyl, to_rational(std::nextafter(d.lower, 0.0))))
        why += " lower above the distance;";
    const bool meet = clearance_oracle::within(box, cyl, Rational(0));
    if (meet && d.upper != 0) why += " they meet, upper is not 0;";
    const Rational b1 = witness_bound(d.on_box), b2 = witness_bound(d.on_cylinder);
    if (!clearance_oracle::within(box, point_cylinder(d.on_box), b1)) why += " on_box too far from the box;";
    if (!clearance_oracle::within(point_box(d.on_cylinder), cyl, b2)) why += " on_cylinder too far from the cylinder;";
    if (c.kind == BoxKind::aligned)
        for (int i = 0; i < 3; ++i)
            if (!(c.aligned.min[i] <= d.on_box[i] && d.on_box[i] <= c.aligned.max[i])) why += " on_box outside the aligned box;";
    if (witness_distance) {
        const Vec3<Rational> w = to_exact(d.on_box) - to_exact(d.on_cylinder);
        const Rational w2 = dot(w, w), slack = b1 + b2;
        if (std::isfinite(d.upper)) {
            const Rational hi = to_rational(d.upper) + slack;
            if (w2 > hi * hi) why += " witnesses farther apart than upper;";
        }
        const Rational lo = to_rational(d.lower) - slack;
        if (lo > 0 && w2 < lo * lo) why += " witnesses nearer than lower;";
    }
    if (!meet) {
        ++t.separated;
        if (steps <= 1) ++t.one_ulp;
    }
    if (!why.empty() && ++t.violations <= 5)
        ADD_FAILURE() << where << ":" << why << " distance [" << hex(d.lower) << ", " << hex(d.upper) << "], on_box "
                      << hex(d.on_box) << ", on_cylinder " << hex(d.on_cylinder) << " for\n" << describe(c);
}

void report(const char* set, const Tally& t) {
    std::printf("%s: %ld judged, %ld separated (%ld of them within one ulp), %d violations\n", set, t.checked,
                t.separated, t.one_ulp, t.violations);
}

TEST(DistanceJudged, RandomPairsEveryProfile) {
    Tally t;
    for (Profile p : {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        CaseGenerator gen(0xd15a0100 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < (p == Profile::magnitudes ? 20 : 150); ++i) {
            const Case c = gen.next();
            judge(c, distance_of(c), t, true, "profile " + std::to_string(static_cast<int>(p)));
        }
    }
    report("random pairs", t);
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(t.separated, 200);
}

TEST(DistanceJudged, NearTouchingPairsOneUlpApart) {
    Tally t;
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced}) {
        CaseGenerator gen(0xd15a0200 + static_cast<std::uint64_t>(p), p);
        for (const Case& c : boundary_pairs(gen, 40)) judge(c, distance_of(c), t, true, "near touching");
    }
    report("near-touching pairs", t);
    EXPECT_EQ(t.violations, 0);
}

// Small integer shapes: touching exactly, and distances that are often rational (faces, edges and
// vertices against caps and sides) or roots of the rim's equations.
TEST(DistanceJudged, IntegerLattice) {
    std::mt19937_64 rng(0xd15a0300);
    const Integers integer{rng};
    Tally t;
    for (int i = 0; i < 400; ++i) {
        Case c;
        c.cylinder = {{integer(-3, 3), integer(-3, 3), integer(-3, 3)},
                      {integer(-2, 2), integer(-2, 2), integer(-2, 2)}, integer(0, 3), 2 * integer(0, 3)};
        if (c.cylinder.axis == Vec3<double>{0, 0, 0}) c.cylinder.axis = {0, 0, 1};
        lattice_box(c, i, integer);
        const Distance d = c.kind == BoxKind::aligned
                               ? distance(c.aligned, c.cylinder)
                               : distance(Parallelepiped<double>{c.oriented.center, c.oriented.axes, c.oriented.extents}, c.cylinder);
        judge(c, d, t, true, "lattice");
    }
    report("lattice", t);
    EXPECT_EQ(t.violations, 0);
}

// Distances of known value, exactly: a vertex facing a cap, an edge facing the side, and a subnormal and
// an astronomically large distance, where the bound is 4 ulps of those values.
TEST(DistanceJudged, KnownDistances) {
    Tally t;
    struct Known {
        Case c;
        double value;  // the exact distance, a double
    };
    const double tiny = 0x1p-1074;
    const Known known[] = {
        // The box [0,1]³ and a cylinder along z standing 3 above it: the cap at distance 3 − 0 = 2.
        {{BoxKind::aligned, AlignedBox<double>{{0, 0, 0}, {1, 1, 1}}, {}, {}, Cylinder<double>{{0.5, 0.5, 5}, {0, 0, 1}, 0.25, 4}}, 2.0},
        // The side of a vertical cylinder of radius 1 whose axis is 4 from the face x = 1: 3 − 0 = 3... at x = 5.
        {{BoxKind::aligned, AlignedBox<double>{{0, 0, 0}, {1, 1, 1}}, {}, {}, Cylinder<double>{{5, 0.5, 0.5}, {0, 0, 1}, 1, 1}}, 3.0},
        // A subnormal gap: the face x = 0 and a cylinder of radius 2^-1074 whose axis is at x = 3·2^-1074.
        {{BoxKind::aligned, AlignedBox<double>{{-1, -1, -1}, {0, 1, 1}}, {}, {}, Cylinder<double>{{3 * tiny, 0, 0}, {0, 0, 1}, tiny, 1}}, 2 * tiny},
        // A gap of 2^1020 between a face and a cap.
        {{BoxKind::aligned, AlignedBox<double>{{0, 0, -0x1p1020}, {1, 1, 0}}, {}, {}, Cylinder<double>{{0.5, 0.5, 0x1.8p1020}, {0, 0, 1}, 1, 0x1p1020}}, 0x1p1020},
    };
    for (const Known& k : known) {
        const Distance d = distance_of(k.c);
        judge(k.c, d, t, true, "known");
        EXPECT_LE(d.lower, k.value) << describe(k.c);
        EXPECT_GE(d.upper, k.value) << describe(k.c);
    }
    // The README's example: a corner exactly 5 from the rim, enclosed exactly, with the exact nearest pair.
    const Distance readme = distance(AlignedBox<double>{{6, 0, 5}, {7, 1, 6}}, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 3, 2});
    EXPECT_EQ(readme.lower, 5.0);
    EXPECT_EQ(readme.upper, 5.0);
    EXPECT_EQ(readme.on_box, (Vec3<double>{6, 0, 5}));
    EXPECT_EQ(readme.on_cylinder, (Vec3<double>{3, 0, 1}));
    // A distance beyond the largest double: the enclosure's upper end is +∞.
    const Case far{BoxKind::aligned, AlignedBox<double>{{-0x1p1023, 0, 0}, {-0x1p1023, 0, 0}}, {}, {},
                   Cylinder<double>{{0x1p1023, 0, 0}, {0, 0, 1}, 0, 0}};
    const Distance d = distance_of(far);
    EXPECT_EQ(d.upper, std::numeric_limits<double>::infinity());
    EXPECT_GT(d.lower, 0x1.fffffffffffffp1023 / 2);
    report("known distances", t);
    EXPECT_EQ(t.violations, 0);
}

// Narrowed out of line: GCC 12.2 at -O2 (its SLP vectorizer) otherwise forwards the unrounded double
// to the widening copy below, as if (double)(float)x were x.
[[gnu::noinline]] float narrow(double x) { return static_cast<float>(x); }

TEST(DistanceJudged, FloatInputs) {
    Tally t;
    CaseGenerator gen(0xd15a0500, Profile::uniform);
    for (int i = 0; i < 100; ++i) {
        Case c = gen.next();
        if (c.kind != BoxKind::aligned) continue;
        AlignedBox<float> fb;
        for (int k = 0; k < 3; ++k) {
            fb.min[k] = narrow(c.aligned.min[k]);
            fb.max[k] = std::max(fb.min[k], narrow(c.aligned.max[k]));
        }
        Cylinder<float> fc;
        for (int k = 0; k < 3; ++k) {
            fc.center[k] = narrow(c.cylinder.center[k]);
            fc.axis[k] = narrow(c.cylinder.axis[k]);
        }
        if (fc.axis == Vec3<float>{0, 0, 0}) fc.axis = {0, 0, 1};
        fc.radius = narrow(c.cylinder.radius);
        fc.height = narrow(c.cylinder.height);
        Case widened;  // the same float inputs, judged as the doubles they equal
        widened.kind = BoxKind::aligned;
        for (int k = 0; k < 3; ++k) {
            widened.aligned.min[k] = fb.min[k];
            widened.aligned.max[k] = fb.max[k];
            widened.cylinder.center[k] = fc.center[k];
            widened.cylinder.axis[k] = fc.axis[k];
        }
        widened.cylinder.radius = fc.radius;
        widened.cylinder.height = fc.height;
        judge(widened, distance(fb, fc), t, true, "float");
    }
    report("float inputs", t);
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(t.checked, 20);
}

// In the directed modes the double-double stage declines and the exact bisection narrows the bounds;
// the enclosure's guarantees hold the same (the witnesses are the double search's, unjudged for distance).
TEST(DistanceJudged, EveryRoundingMode) {
    Tally t;
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::degenerate}) {
        CaseGenerator gen(0xd15a0400 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < 8; ++i) {
            const Case c = gen.next();
            for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
                Distance d;
                {
                    const RoundingMode scope(mode);
                    d = distance_of(c);
                }
                judge(c, d, t, false, mode_name(mode));
            }
        }
    }
    report("rounding modes", t);
    EXPECT_EQ(t.violations, 0);
}

TEST(DistanceJudged, InvalidInputIsRefused) {
    const Cylinder<double> cyl{{0, 0, 0}, {0, 0, 0}, 1, 1};
    EXPECT_THROW((void)distance(AlignedBox<double>{{0, 0, 0}, {1, 1, 1}}, cyl), std::invalid_argument);
    const Cylinder<double> ok{{0, 0, 0}, {0, 0, 1}, 1, 1};
    EXPECT_THROW((void)distance(AlignedBox<double>{{0, 0, 0}, {std::nan(""), 1, 1}}, ok), std::invalid_argument);
}

}  // namespace
}  // namespace boxcyl
