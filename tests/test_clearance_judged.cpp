// The clearance query, boxcyl::within_distance, judged by the independent clearance oracle
// (tests/clearance/: exact algebraic numbers, a different method) on
//   - random pairs of every generator profile (mixed, degenerate, uniform, georeferenced, magnitudes) at
//     random margins from subnormal to 2^20 times the shapes;
//   - the same pairs at their flip margin: the least double m the query says is within, and the double
//     below it — the distance lies between them, so both are at-margin queries one ulp apart;
//   - a lattice of small integer shapes (aligned boxes and parallelepipeds with integer axes, dependent
//     ones too; integer axis directions of any length) at margins k/2 and their one-ulp neighbours, where
//     the distance often equals the margin exactly.
// A disagreement prints the case as C++ to paste into a regression test.
#include <gtest/gtest.h>

#include <chrono>   // slow cases reported
#include <cfenv>    // rounding modes
#include <cmath>    // std::nextafter, std::ldexp
#include <cstdlib>  // std::getenv
#include <cstdint>  // seeds, bit patterns
#include <cstdio>   // std::printf
#include <cstring>  // std::memcpy
#include <optional> // the centre ball's undecided
#include <random>   // fixed-seed generators
#include <string>   // describe()
#include <vector>   // margins

#include "boxcyl/clearance.hpp"
#include "boxcyl/filtered/centre_ball.hpp"
#include "clearance/clearance_oracle.hpp"
#include "clearance/exact_case.hpp"
#include "clearance/lattice.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"  // RoundingMode

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

bool judged(const Case& c, double m) { return clearance_oracle::within(exact_box(c), to_exact(c.cylinder), to_rational(m)); }
bool answered(const Case& c, double m) {
    return with_box(c, [m](const auto& box, const Cylinder<double>& cyl) { return within_distance(box, cyl, m); });
}

// The least double m ≥ 0 with answered(c, m), by bisection on the doubles' order (answers are monotone).
double flip_margin(const Case& c) {
    if (answered(c, 0.0)) return 0.0;
    double hi = 1.0;
    while (!answered(c, hi)) hi *= 4;  // ends: a finite margin covers any pair of finite shapes
    std::int64_t lo_bits = 0;         // answered(0) is false
    std::int64_t hi_bits = ordered_bits(hi);
    while (hi_bits - lo_bits > 1) {
        const std::int64_t mid = lo_bits + (hi_bits - lo_bits) / 2;
        (answered(c, from_ordered_bits(mid)) ? hi_bits : lo_bits) = mid;
    }
    return from_ordered_bits(hi_bits);
}

void expect_agreement(const Case& c, double m, int& disagreements) {
    const bool a = answered(c, m);
    const bool j = judged(c, m);
    if (a != j && ++disagreements <= 5)
        ADD_FAILURE() << "within_distance " << a << ", oracle " << j << " at margin " << hex(m) << " for\n"
                      << describe(c);
}

double size_of(const Case& c) { return c.cylinder.radius + c.cylinder.height + 0x1p-1000; }

TEST(ClearanceJudged, RandomPairsAtRandomMarginsEveryProfile) {
    int disagreements = 0;
    long checked = 0;
    for (Profile p : {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        const std::uint64_t seed = 0xc1ea0100 + static_cast<std::uint64_t>(p);
        CaseGenerator gen(seed, p);
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const int count = std::getenv("BOXCYL_JUDGED_COUNT") ? std::atoi(std::getenv("BOXCYL_JUDGED_COUNT")) : 60;
        for (int i = 0; i < count; ++i) {
            const Case c = gen.next();
            const auto t0 = std::chrono::steady_clock::now();
            if (std::getenv("BOXCYL_JUDGED_TRACE")) std::fprintf(stderr, "profile %d case %d: %s\n", static_cast<int>(p), i, describe(c).c_str());
            for (double f : {0x1p-1074, std::ldexp(unit(rng), -20), unit(rng), 4 * unit(rng), std::ldexp(unit(rng), 20)}) {
                expect_agreement(c, f == 0x1p-1074 ? f : f * size_of(c), disagreements);
                ++checked;
            }
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (ms > 200) std::printf("slow (%.0f ms) profile %d case %d\n", ms, static_cast<int>(p), i);
        }
    }
    std::printf("random pairs: %ld queries judged, %d disagreements\n", checked, disagreements);
    EXPECT_EQ(disagreements, 0);
}

TEST(ClearanceJudged, FlipMarginsAreOneUlpApartAtTheDistance) {
    int disagreements = 0;
    long pairs = 0;
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        CaseGenerator gen(0xc1ea0200 + static_cast<std::uint64_t>(p), p);
        // The bisection asks ~60 margins near the distance; where the refined bounds cannot decide (on
        // mixed magnitudes, numbers of 2000 bits) the exact decision takes up to ~0.1 s each: fewer pairs there.
        for (int i = 0; i < (p == Profile::magnitudes ? 10 : 400); ++i) {
            const Case c = gen.next();
            const auto t0 = std::chrono::steady_clock::now();
            const double m = flip_margin(c);
            const auto t1 = std::chrono::steady_clock::now();
            if (std::getenv("BOXCYL_JUDGED_TRACE"))
                std::fprintf(stderr, "profile %d case %d: bisection %.0f ms\n", static_cast<int>(p), i,
                             std::chrono::duration<double, std::milli>(t1 - t0).count());
            if (m == 0.0) continue;  // they touch: margin 0 is covered above
            expect_agreement(c, m, disagreements);
            expect_agreement(c, std::nextafter(m, 0.0), disagreements);
            ++pairs;
        }
    }
    std::printf("flip margins: %ld pairs at one ulp, %d disagreements\n", pairs, disagreements);
    EXPECT_GT(pairs, 60);
    EXPECT_EQ(disagreements, 0);
}

TEST(ClearanceJudged, IntegerLatticeAtHalfIntegerMarginsAndNeighbours) {
    std::mt19937_64 rng(0xc1ea0300);
    const Integers integer{rng};
    int disagreements = 0;
    long checked = 0;
    long exactly_at_margin = 0;
    for (int i = 0; i < 500; ++i) {
        Case c;
        // Axis directions: half along a coordinate axis or a Pythagorean one (distances are then often
        // rational), the rest any small integer vector.
        static const Vec3<double> kAxes[] = {{0, 0, 1}, {0, 2, 0}, {-1, 0, 0}, {3, 4, 0}, {0, -3, 4}, {4, 0, 3}};
        const Vec3<double> axis = integer(0, 1) == 0 ? kAxes[static_cast<int>(integer(0, 5))]
                                                     : Vec3<double>{integer(-2, 2), integer(-2, 2), integer(-2, 2)};
        c.cylinder = {{integer(-3, 3), integer(-3, 3), integer(-3, 3)}, axis, integer(0, 3), 2 * integer(0, 3)};
        if (c.cylinder.axis == Vec3<double>{0, 0, 0}) c.cylinder.axis = {0, 0, 1};
        lattice_box(c, i, integer);
        const Parallelepiped<Rational> box = exact_box(c);
        const Cylinder<Rational> cyl = to_exact(c.cylinder);
        for (int k = 0; k <= 12; ++k) {
            const double m = k / 2.0;
            for (double mm : {m, std::nextafter(m, 0.0), std::nextafter(m, 8.0)}) {
                const bool j = clearance_oracle::within(box, cyl, to_rational(mm));
                const bool a = c.kind == BoxKind::aligned
                                   ? within_distance(c.aligned, c.cylinder, mm)
                                   : within_distance(Parallelepiped<double>{c.oriented.center, c.oriented.axes, c.oriented.extents},
                                                     c.cylinder, mm);
                ++checked;
                if (a != j && ++disagreements <= 5)
                    ADD_FAILURE() << "within_distance " << a << ", oracle " << j << " at margin " << hex(mm) << " for\n"
                                  << describe(c) << (c.kind == BoxKind::oriented ? "\n(box as a Parallelepiped)" : "");
            }
            if (k > 0 && clearance_oracle::compare_squared_distance(box, cyl, Rational(Rational(k * k) / 4)) == 0) ++exactly_at_margin;
        }
    }
    std::printf("lattice: %ld queries judged, %ld exactly at a half-integer margin, %d disagreements\n", checked,
                exactly_at_margin, disagreements);
    EXPECT_GT(exactly_at_margin, 50);
    EXPECT_EQ(disagreements, 0);
}

// Every IEEE rounding mode: the probes' sum bounds and the interval stage hold in each (the oracle's
// verdict is taken in round to nearest). Pairs near their flip margin (one ulp either side, where the
// interval stage and the exact decision answer) and random margins, every profile but magnitudes.
TEST(ClearanceJudged, EveryRoundingMode) {
    int disagreements = 0;
    long checked = 0;
    std::mt19937_64 rng(0xc1ea0400);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::degenerate}) {
        CaseGenerator gen(0xc1ea0400 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < 12; ++i) {
            const Case c = gen.next();
            std::vector<double> margins{unit(rng) * size_of(c), 4 * unit(rng) * size_of(c)};
            if (p != Profile::degenerate) {
                const double m = flip_margin(c);
                if (m > 0) margins.insert(margins.end(), {m, std::nextafter(m, 0.0)});
            }
            for (const double m : margins) {
                const bool j = judged(c, m);
                for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
                    const RoundingMode scope(mode);
                    const bool a = answered(c, m);
                    ++checked;
                    if (a != j && ++disagreements <= 5)
                        ADD_FAILURE() << "rounding mode " << mode_name(mode) << ": within_distance " << a << ", oracle " << j
                                      << " at margin " << hex(m) << " for\n" << describe(c);
                }
            }
        }
    }
    std::printf("rounding modes: %ld queries judged, %d disagreements\n", checked, disagreements);
    EXPECT_EQ(disagreements, 0);
}

// The centre ball's answers (filtered/centre_ball.hpp) at the edges of its error allowance: for each
// pair, the least margin its "yes" test answers and the greatest its "no" test answers (bisected on
// the doubles' order: both tests are monotone in m), judged by the oracle in every rounding mode. Random
// pairs of every profile; small cubes near a cylinder's rim (the boxes a batch leaves to the scalar
// query), whose centre decides most often; and points there, near the origin and far from it, whose
// distance is their centre's, so that only the error allowance separates the edge margin from it.
std::optional<bool> ball_says(const Case& c, double m) {
    return with_box(c, [m](const auto& box, const Cylinder<double>& cyl) { return filtered::centre_ball::decide(box, cyl, m); });
}
double ball_edge(const Case& c, bool yes) {  // the least m it says yes at (yes), the greatest it says no at (!yes); -1: none
    std::int64_t lo = 0, hi = ordered_bits(0x1p300);
    auto says = [&](std::int64_t i) { return ball_says(c, from_ordered_bits(i)) == yes; };
    if (yes ? !says(hi) : !says(lo)) return -1;
    if (yes && says(lo)) return 0.0;
    if (!yes && says(hi)) return -1;
    while (hi - lo > 1) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        (says(mid) == yes ? hi : lo) = mid;
    }
    return from_ordered_bits(yes ? hi : lo);
}
TEST(ClearanceJudged, CentreBallAtTheEdgesOfItsAllowance) {
    std::vector<Case> cases;
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::degenerate, Profile::magnitudes}) {
        CaseGenerator gen(0xc1ea0500 + static_cast<std::uint64_t>(p), p);
        for (int i = 0; i < 40; ++i) cases.push_back(gen.next());
    }
    std::mt19937_64 rng(0xc1ea0501);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {  // cubes of 1/64 of the reach within 1.5 reaches of a tilted cylinder
        Case c;
        c.cylinder = {{0.3, -0.2, 0.1}, {0.3, 0.5, 0.8}, 1.7, 2.9};
        const double reach = 1.7 + 1.45, side = reach / 64;
        for (int j = 0; j < 3; ++j) {
            c.aligned.min[j] = c.cylinder.center[j] + 1.5 * reach * unit(rng);
            c.aligned.max[j] = c.aligned.min[j] + side;
        }
        cases.push_back(c);
        c.aligned.max = c.aligned.min;  // a point: its distance is the centre's, the allowance all that is left
        cases.push_back(c);
        c.cylinder.center = c.cylinder.center + Vec3<double>{4e5, 7e6, 1e3};  // the same far from the origin
        c.aligned.min = c.aligned.max = c.aligned.min + Vec3<double>{4e5, 7e6, 1e3};
        cases.push_back(c);
    }
    int disagreements = 0, edges = 0;
    for (const Case& c : cases)
        for (const bool yes : {true, false}) {
            const double m = ball_edge(c, yes);
            if (m < 0) continue;
            ++edges;
            const bool j = judged(c, m);
            for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
                const RoundingMode scope(mode);
                const std::optional<bool> a = ball_says(c, m);
                if (a && *a != j && ++disagreements <= 5)
                    ADD_FAILURE() << "rounding mode " << mode_name(mode) << ": centre ball " << (a ? (*a ? "yes" : "no") : "undecided")
                                  << ", oracle " << j << " at margin " << hex(m) << " for\n" << describe(c);
            }
        }
    std::printf("centre ball: %d edge margins of %zu pairs judged, %d disagreements\n", edges, cases.size(), disagreements);
    EXPECT_GT(edges, 100);
    EXPECT_EQ(disagreements, 0);
}

}  // namespace
}  // namespace boxcyl
