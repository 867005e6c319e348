// The clearance oracle (tests/clearance/clearance_oracle.hpp) on constructions whose distance is known by
// hand, exactly at the margin and one double ulp below it, and on random cases against the m = 0
// oracle, monotonicity in m, and sampled points of the box.
#include "clearance/clearance_oracle.hpp"

#include <gtest/gtest.h>

#include <algorithm>  // std::sort, std::min
#include <chrono>     // per-query timing
#include <cmath>      // std::nextafter, std::sqrt
#include <cstdio>     // std::printf
#include <random>     // std::mt19937_64
#include <string>     // describe()
#include <utility>    // std::pair
#include <vector>     // timings

#include "boxcyl/oracle/oracle.hpp"

namespace {

using boxcyl::Cylinder;
using boxcyl::Parallelepiped;
using boxcyl::Rational;
using boxcyl::Vec3;
namespace co = boxcyl::clearance_oracle;

using P = Parallelepiped<Rational>;
using Cyl = Cylinder<Rational>;
using V = Vec3<Rational>;

// The aligned box [lo, hi] as a parallelepiped with the standard axes.
P aligned(const V& lo, const V& hi) {
    P b;
    for (int i = 0; i < 3; ++i) {
        b.center[i] = (lo[i] + hi[i]) / 2;
        b.extents[i] = (hi[i] - lo[i]) / 2;
        b.axes[i] = V{Rational(i == 0), Rational(i == 1), Rational(i == 2)};
    }
    return b;
}
Cyl along_z(const Rational& r, const Rational& h, const V& axis = V{0, 0, 1}) { return {V{0, 0, 0}, axis, r, h}; }

// dist == m exactly: within at m, not at the double just below m, within at the double just above; the
// squared distance compares equal to m².
void expect_distance(const P& b, const Cyl& c, double m) {
    const Rational mq = boxcyl::to_rational(m);
    EXPECT_EQ(co::compare_squared_distance(b, c, mq * mq), 0) << "m = " << m;
    EXPECT_TRUE(co::within(b, c, mq)) << "m = " << m;
    EXPECT_FALSE(co::within(b, c, boxcyl::to_rational(std::nextafter(m, 0.0)))) << "m = " << m;
    EXPECT_TRUE(co::within(b, c, boxcyl::to_rational(std::nextafter(m, 1e300)))) << "m = " << m;
}

TEST(ClearanceByHand, FaceVsSide) {
    // [2,3]×[−1,1]×[−1,1] against r = 1, h = 2 along z: the face x = 2 is 1 from the side.
    expect_distance(aligned({2, -1, -1}, {3, 1, 1}), along_z(1, 2), 1.0);
    // A face parallel to the axis but longer than the cylinder: still the side.
    expect_distance(aligned({2, -1, -5}, {3, 1, 5}), along_z(1, 2), 1.0);
}

TEST(ClearanceByHand, FaceVsCap) {
    expect_distance(aligned({-1, -1, 3}, {1, 1, 4}), along_z(1, 2), 2.0);      // a face over the cap
    expect_distance(aligned({-5, -5, -4}, {5, 5, -3}), along_z(1, 2), 2.0);    // a face wider than the cap
    expect_distance(aligned({Rational(1, 2), -1, 3}, {4, 1, 4}), along_z(1, 2), 2.0);  // overhanging the rim
}

TEST(ClearanceByHand, VertexVsRim) {
    // Rim point (3, 0, 1) of r = 3, h = 2; vertex (6, 0, 5) = (3+3, 0, 1+4): distance 5.
    expect_distance(aligned({6, 0, 5}, {8, 2, 7}), along_z(3, 2), 5.0);
    expect_distance(aligned({-8, -2, -7}, {-6, 0, -5}), along_z(3, 2), 5.0);  // the lower rim
}

TEST(ClearanceByHand, EdgeVsRim) {
    // The edge x = 6, z = 5, y ∈ [−1, 3] passes (6, 0, 5): distance 5 at an interior rational point.
    expect_distance(aligned({6, -1, 5}, {8, 3, 7}), along_z(3, 2), 5.0);
    // A tilted box whose edge {(6, y, 5)} lies in the plane 3x + 4z = 38 and the box beyond it:
    // X = (6, y, 5) + α(3, 0, 4) + β(4, 0, −3), |y| ≤ 2, α ∈ [0, 1], β ∈ [−1, 0]. The cylinder's support
    // value along n = (3, 0, 4)/5 is 3·3/5 + 1·4/5 = 13/5 and the plane is at 38/5: the gap is 5, met
    // only at (6, 0, 5) (foot (3, 0, 1)), an interior point of that edge.
    P b;
    b.axes = {V{0, 1, 0}, V{3, 0, 4}, V{4, 0, -3}};
    b.extents = V{2, Rational(1, 2), Rational(1, 2)};
    b.center = V{Rational(11, 2), 0, Rational(17, 2)};  // (6, 0, 5) + ½(3, 0, 4) − ½(4, 0, −3)
    expect_distance(b, along_z(3, 2), 5.0);
}

// The nearest point is inside an edge that neither is ⊥ u nor lies in a facet whose plane holds the
// plane's own nearest point: only the edge's own candidates find it.
TEST(ClearanceByHand, SkewEdgeOnly) {
    // Rim: the edge (6, 0, 5) + s(4, 5, −3) lies in the tangent plane 3x + 4z = 38 (gap 5 from the
    // cylinder r = 3, h = 2); the box (6, 0, 5) + s·v + α(7, 0, 1) + β(−1, 0, 7), α, β ∈ [0, 1], lies
    // beyond that plane (3·7 + 4·1 > 0, 3·(−1) + 4·7 > 0) and touches it only along the edge.
    P rim{V{9, 0, 9}, {V{4, 5, -3}, V{7, 0, 1}, V{-1, 0, 7}}, V{1, Rational(1, 2), Rational(1, 2)}};
    expect_distance(rim, along_z(3, 2), 5.0);
    // Side: the edge (2, s, s) with the box (2, 0, 0) + s(0, 1, 1) + α(1, 1, −1) + β(1, −1, 1), α, β ∈ [0, 1]:
    // every point has x ≥ 2 (so ρ ≥ 2), and x = 2, y = 0 only at (2, 0, 0): distance 1 from r = 1, h = 2.
    P side{V{3, 0, 0}, {V{0, 1, 1}, V{1, 1, -1}, V{1, -1, 1}}, V{1, Rational(1, 2), Rational(1, 2)}};
    expect_distance(side, along_z(1, 2), 1.0);
}

TEST(ClearanceByHand, TiltedFaceVsRim) {
    // The plane 3x + 4z = 38 is tangent to the distance-5 offset of the rim at (6, 0, 5) (foot (3, 0, 1));
    // a box whose facet lies in it, with (6, 0, 5) inside the facet, and the box beyond it.
    P b;
    b.axes = {V{4, 0, -3}, V{0, 1, 0}, V{3, 0, 4}};
    b.extents = V{Rational(1, 2), 1, Rational(1, 2)};
    b.center = V{6 + Rational(3, 2), 0, 5 + 2};  // (6, 0, 5) + ½(3, 0, 4)
    expect_distance(b, along_z(3, 2), 5.0);
    // The same, scaled down by 8 (non-integer coordinates): distance 5/8.
    P s = b;
    for (int i = 0; i < 3; ++i) {
        s.center[i] /= 8;
        s.extents[i] /= 8;
    }
    expect_distance(s, Cyl{V{0, 0, 0}, V{0, 0, 1}, Rational(3, 8), Rational(2, 8)}, 5.0 / 8);
}

TEST(ClearanceByHand, AxisNotUnitLength) {
    for (const V& axis : {V{0, 0, 2}, V{0, 0, -3}, V{0, 0, Rational(1, 7)}}) {
        expect_distance(aligned({2, -1, -1}, {3, 1, 1}), along_z(1, 2, axis), 1.0);
        expect_distance(aligned({-1, -1, 3}, {1, 1, 4}), along_z(1, 2, axis), 2.0);
        expect_distance(aligned({6, 0, 5}, {8, 2, 7}), along_z(3, 2, axis), 5.0);
    }
    // A slanted axis of length 5: D = (3, 4, 0) (u = (3/5, 4/5, 0)), r = 1, h = 2; box beyond the cap along
    // u at distance 2: the face through C + 3u = (9/5, 12/5, 0) ⊥ u, as a box with axes u·5, (−4,3,0), z.
    P b;
    b.axes = {V{3, 4, 0}, V{-4, 3, 0}, V{0, 0, 1}};
    b.extents = V{Rational(1, 10), Rational(1, 10), 1};
    b.center = V{Rational(9, 5) + Rational(3, 10), Rational(12, 5) + Rational(4, 10), 0};
    expect_distance(b, Cyl{V{0, 0, 0}, V{3, 4, 0}, 1, 2}, 2.0);
}

TEST(ClearanceByHand, ZeroRadius) {
    // The segment (0,0,±1): the edge x = 3, y = 4 is 5 away (side); the vertex (3, 0, 5) is 5 from (0,0,1).
    expect_distance(aligned({3, 4, -1}, {4, 5, 1}), along_z(0, 2), 5.0);
    expect_distance(aligned({3, 0, 5}, {5, 2, 6}), along_z(0, 2), 5.0);
    expect_distance(aligned({-2, -1, 5}, {3, 2, 6}), along_z(0, 2), 4.0);  // a face over the end point
}

TEST(ClearanceByHand, ZeroHeight) {
    // The disk r = 3 in z = 0.
    expect_distance(aligned({-1, -1, 2}, {1, 1, 3}), along_z(3, 0), 2.0);
    expect_distance(aligned({6, -1, -1}, {7, 1, 1}), along_z(3, 0), 3.0);
    expect_distance(aligned({6, 0, 4}, {7, 1, 5}), along_z(3, 0), 5.0);  // rim (3, 0, 0), vertex (6, 0, 4)
    // r = 0 and h = 0: a point.
    expect_distance(aligned({3, 4, 0}, {5, 6, 1}), along_z(0, 0), 5.0);
}

TEST(ClearanceByHand, FlatBoxes) {
    // A segment x ∈ [3, 5] (two parallel axes, one zero extent) 2 from r = 1.
    P seg{V{4, 0, 0}, {V{1, 0, 0}, V{2, 0, 0}, V{0, 0, 0}}, V{Rational(1, 2), Rational(1, 4), 7}};
    expect_distance(seg, along_z(1, 2), 2.0);
    // A point (all extents 0) at (6, 0, 5): 5 from the rim of r = 3, h = 2.
    P pt{V{6, 0, 5}, {V{1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}}, V{0, 0, 0}};
    expect_distance(pt, along_z(3, 2), 5.0);
    // A parallelogram in the plane y = 0 (coplanar axes) whose corner region holds (6, 0, 5).
    P par{V{7, 0, 6}, {V{1, 0, 0}, V{0, 0, 1}, V{1, 0, 1}}, V{Rational(1, 2), Rational(1, 2), Rational(1, 2)}};
    expect_distance(par, along_z(3, 2), 5.0);
}

TEST(ClearanceByHand, Intersecting) {
    const P b = aligned({0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(co::compare_squared_distance(b, along_z(1, 2), 0), 0);
    EXPECT_TRUE(co::within(b, along_z(1, 2), 0));
    EXPECT_EQ(co::compare_squared_distance(b, along_z(1, 2), Rational(1, 1000)), -1);
    EXPECT_THROW(co::within(b, along_z(1, 2), -1), std::invalid_argument);
}

// ---- Random cases (fixed seeds) -----------------------------------------------------------------
struct RandomCase {
    Parallelepiped<double> box;
    Cylinder<double> cyl;
};

std::string hex(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
std::string hex(const Vec3<double>& v) { return "{" + hex(v[0]) + ", " + hex(v[1]) + ", " + hex(v[2]) + "}"; }
// Copy-pasteable C++ for the case and margin.
std::string describe(const RandomCase& c, double m) {
    return "Parallelepiped<double> box{" + hex(c.box.center) + ", {" + hex(c.box.axes[0]) + ", " +
           hex(c.box.axes[1]) + ", " + hex(c.box.axes[2]) + "}, " + hex(c.box.extents) + "};\n" +
           "Cylinder<double> cyl{" + hex(c.cyl.center) + ", " + hex(c.cyl.axis) + ", " + hex(c.cyl.radius) +
           ", " + hex(c.cyl.height) + "};\ndouble m = " + hex(m) + ";";
}

RandomCase random_case(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> pos(-3, 3), dir(-1, 1), len(0, 2);
    std::uniform_int_distribution<int> kind(0, 9);
    RandomCase c;
    auto vec = [&](auto& dist) { return Vec3<double>{dist(rng), dist(rng), dist(rng)}; };
    c.box.center = vec(pos);
    for (auto& a : c.box.axes) a = vec(dir);
    c.box.extents = vec(len);
    const int k = kind(rng);
    if (k == 0) c.box.axes[2] = c.box.axes[0];            // dependent axes
    if (k == 1) c.box.extents[1] = 0;                     // a zero extent
    c.cyl.center = vec(dir);
    c.cyl.axis = vec(dir);
    c.cyl.radius = k == 2 ? 0.0 : len(rng);
    c.cyl.height = k == 3 ? 0.0 : len(rng);
    return c;
}

P exact(const Parallelepiped<double>& b) {
    P p;
    auto q = [](double x) { return boxcyl::to_rational(x); };
    p.center = boxcyl::convert<Rational>(b.center, q);
    for (int i = 0; i < 3; ++i) p.axes[i] = boxcyl::convert<Rational>(b.axes[i], q);
    p.extents = boxcyl::convert<Rational>(b.extents, q);
    return p;
}
Cyl exact(const Cylinder<double>& c) {
    auto q = [](double x) { return boxcyl::to_rational(x); };
    return {boxcyl::convert<Rational>(c.center, q), boxcyl::convert<Rational>(c.axis, q), q(c.radius), q(c.height)};
}

// dist(X, cyl) in double, for sampled points.
double point_distance(const Vec3<double>& x, const Cylinder<double>& c) {
    const Vec3<double> y = x - c.center;
    const double dl = std::sqrt(dot(c.axis, c.axis));
    const double t = dot(c.axis, y) / dl;
    const double rho = std::sqrt(std::max(0.0, dot(y, y) - t * t));
    const double a = std::max(std::abs(t) - c.height / 2, 0.0), b = std::max(rho - c.radius, 0.0);
    return std::sqrt(a * a + b * b);
}

TEST(ClearanceRandom, ZeroMarginIsTheIntersectionOracle) {
    std::mt19937_64 rng(20240611);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const RandomCase c = random_case(rng);
        const bool expect = boxcyl::oracle::intersects(exact(c.box), exact(c.cyl));
        hits += expect;
        ASSERT_EQ(co::within(exact(c.box), exact(c.cyl), 0), expect) << describe(c, 0.0);
    }
    EXPECT_GT(hits, 20);
    EXPECT_LT(hits, 280);
}

TEST(ClearanceRandom, MonotoneInMargin) {
    std::mt19937_64 rng(7);
    const std::vector<double> margins{0.0, 0.01, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0};
    for (int i = 0; i < 150; ++i) {
        const RandomCase c = random_case(rng);
        const P b = exact(c.box);
        const Cyl cy = exact(c.cyl);
        bool prev = false;
        for (double m : margins) {
            const bool now = co::within(b, cy, boxcyl::to_rational(m));
            ASSERT_TRUE(!prev || now) << describe(c, m);
            prev = now;
        }
    }
}

// No sampled point of B is nearer than the oracle's distance; and the densest sampling's nearest point is
// not much farther (the sampling is coarse: a tolerance in the test only, never in the oracle).
TEST(ClearanceRandom, AgreesWithSampledPoints) {
    std::mt19937_64 rng(99);
    const int n = 12;
    for (int i = 0; i < 60; ++i) {
        const RandomCase c = random_case(rng);
        double best = 1e300;
        for (int a = 0; a <= n; ++a)
            for (int b = 0; b <= n; ++b)
                for (int k = 0; k <= n; ++k) {
                    Vec3<double> x = c.box.center;
                    const double s[3] = {2.0 * a / n - 1, 2.0 * b / n - 1, 2.0 * k / n - 1};
                    for (int j = 0; j < 3; ++j) x = x + (s[j] * c.box.extents[j]) * c.box.axes[j];
                    best = std::min(best, point_distance(x, c.cyl));
                }
        const P b = exact(c.box);
        const Cyl cy = exact(c.cyl);
        // best ≥ d*: within at best (rounded up a little for the double evaluation of the sample).
        ASSERT_TRUE(co::within(b, cy, boxcyl::to_rational(best * (1 + 1e-12) + 1e-12))) << describe(c, best);
        // d* ≥ best − (the sampling's reach): the grid's cell diagonal bounds how far a minimiser is from a sample.
        double diag = 0;
        for (int j = 0; j < 3; ++j) diag += c.box.extents[j] * std::sqrt(dot(c.box.axes[j], c.box.axes[j])) * 2.0 / n;
        const double lower = best - diag;
        if (lower > 0) {
            ASSERT_FALSE(co::within(b, cy, boxcyl::to_rational(lower * (1 - 1e-9)))) << describe(c, lower);
        }
    }
}

// Mixed magnitudes (a box 2^17 long but 2^-6 thin, 2^22 from the origin; a cylinder of subnormal height):
// the edge equations have huge integer coefficients. Each query must be answered quickly (it once took
// minutes isolating every complex root), and the answers must be monotone in the margin.
TEST(ClearanceMixedMagnitudes, SubnormalHeightAnswersQuickly) {
    const Parallelepiped<double> box{{-0x1.1285cb0589344p+17, -0x1.09f522bd70a3dp+22, 0x1.491be76c8b439p+8},
                                     {Vec3<double>{-0x1.e828428e96088p-1, -0x1.246ab6749b882p-2, -0x1.8d8f1cdd51d23p-4},
                                      Vec3<double>{-0x1.05708e2c5916p-8, 0x1.55bb2162dceb8p-2, -0x1.e2a4c0cfe1358p-1},
                                      Vec3<double>{0x1.34d1b1de53d8cp-2, -0x1.cbf83b2c5e4e4p-1, -0x1.46fbdc3a3b304p-2}},
                                     {0x1.6092f8e75df81p-6, 0x1.30061b6000a83p+17, 0x1.75ccb44a87ac7p-7}};
    const Cylinder<double> cyl{{-0x1.29019b6bc43b2p+18, -0x1.0d2ff1abb3db5p+22, 0x1.008cc979023acp+17},
                               {0x1.209f1d41de0c2p-1, 0x1.b3ed3f9551aa2p-1, 0x1.7367c11d55164p-1},
                               0x1.addeb2d2e2298p+17,
                               0x0.00000000631a9p-1022};
    const P b = exact(box);
    const Cyl cy = exact(cyl);
    const double size = cyl.radius + cyl.height;
    bool prev = false;
    for (double f : {0.0, 0x1p-20, 0.5, 1.0, 1.5, 2.0, 4.0, 0x1p10, 0x1p20}) {
        const Rational m = boxcyl::to_rational(f * size);
        const auto t0 = std::chrono::steady_clock::now();
        const bool now = co::within(b, cy, m);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        EXPECT_LT(ms, 5000) << "margin " << f << " × (r + h)";
        EXPECT_TRUE(!prev || now) << "margin " << f << " × (r + h)";
        EXPECT_EQ(co::compare_squared_distance(b, cy, m * m) <= 0, now) << "margin " << f << " × (r + h)";
        prev = now;
    }
    EXPECT_TRUE(prev);  // 2^20 (r + h) is far more than the distance
}

// A thin aligned box 2^23 long against a cylinder of radius 2^-30 and height 2^-997, at its flip margin (the
// least double the production query accepts) and the double below: the distance lies between them, so the
// rim-stationary roots must be told apart from their neighbours 2^-997 away.
TEST(ClearanceMixedMagnitudes, FlipMarginOfATinyCylinder) {
    const Vec3<double> lo{0x1.38f70ab960486p+18, -0x1.18262250e5604p+23, 0x1.d73aef7b27ec2p+10};
    const Vec3<double> hi{0x1.38f74f9db22d1p+18, 0x1.8d55422d0e56p+19, 0x1.d7b2613a4034ap+10};
    const P b = aligned(boxcyl::to_exact(lo), boxcyl::to_exact(hi));
    const Cyl cy = exact(Cylinder<double>{{-0x1.99e88fbd4966p+15, -0x1.8040db4082fc7p+21, 0x1.0c58baa126b0fp+20},
                                          {0x1.b7d4d3c0320bap-1, 0x1.51032b50eafep-2, 0x1.a8fd5bac0ca48p-1},
                                          0x1.77d4a1574ff7ep-30,
                                          0x1.56e1fc2f8f359p-997});
    for (const auto& [m, expect] : {std::pair{0x1.1aefc892228fp+20, true}, std::pair{0x1.1aefc892228efp+20, false}}) {
        const auto t0 = std::chrono::steady_clock::now();
        EXPECT_EQ(co::within(b, cy, boxcyl::to_rational(m)), expect) << hex(m);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        EXPECT_LT(ms, 5000) << hex(m);
    }
}

// A cylinder of subnormal radius and height 2^-997 against a box 2^20 long, 2^-997 thin, at its flip margin:
// an edge equation whose values are far below its coefficients over all of [-1, 1] (the isolation must
// raise its precision rather than return thousands of undecided blocks).
TEST(ClearanceMixedMagnitudes, FlipMarginOfASubnormalCylinder) {
    const Parallelepiped<double> box{{-0x1.a9ce7126e978dp+17, -0x1.01f6e9072b021p+23, 0x1.2e531a9fbe76dp+12},
                                     {Vec3<double>{-0x1.dfb2359301ba8p-2, 0x1.7c139ef8ffd67p-2, 0x1.9a7d88b947df2p-1},
                                      Vec3<double>{0x1.c2c757ccc5ed6p-1, 0x1.161e5f605e86cp-2, 0x1.8e0540d27ef0ep-2},
                                      Vec3<double>{-0x1.2cfbbe76075f4p-4, 0x1.c6a24441901e3p-1, -0x1.d0ea557863214p-2}},
                                     {0x1.b3c489354a8a4p+19, 0x1.56e1fc2f8f359p-997, 0x1.82e92d64d72b6p-4}};
    const Cylinder<double> cyl{{-0x1.d39f47e05b2eap+18, -0x1.05f8ab9551548p+23, -0x1.4358c109816b4p+18},
                               {0x1.24eaba8157d64p-1, -0x1.fcfef8ddb70fcp-2, 0x1.6854e42db597cp-2},
                               0x0.000000004619dp-1022,
                               0x1.56e1fc2f8f359p-997};
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_TRUE(co::within(exact(box), exact(cyl), boxcyl::to_rational(0x1.8654efbd795cbp+18)));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(ms, 5000);
}

TEST(ClearanceRandom, TimePerQuery) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> margin(0, 2);
    std::vector<double> us;
    for (int i = 0; i < 300; ++i) {
        const RandomCase c = random_case(rng);
        const P b = exact(c.box);
        const Cyl cy = exact(c.cyl);
        const Rational m = boxcyl::to_rational(margin(rng));
        const auto t0 = std::chrono::steady_clock::now();
        (void)co::within(b, cy, m);
        us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(us.begin(), us.end());
    std::printf("clearance oracle: median %.0f us, 90th percentile %.0f us, max %.0f us per query (%zu random)\n",
                us[us.size() / 2], us[us.size() * 9 / 10], us.back(), us.size());
}

}  // namespace
