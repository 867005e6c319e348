// The convex-hull method (clip – project – convex hull): the 2-D monotone chain; hand-built touching
// configurations for every direction class with one-ulp neighbours; degenerate solids; the world-frame
// parallelepiped form (construction, the generalised slab cull, sheared boxes with exact touches, dependent
// and zero half-edges); and randomized exact differentials against the oracle: generated oriented boxes with
// rounded rotations (the parallelepiped of the axes exactly as given), aligned and canonical boxes,
// one-ulp boundary pairs. The exact path is T = QFRational (to_unit(Cylinder<Rational>, field)); T =
// Rational is checked where the unit direction is rational; double is measured, not asserted, on the
// random cases.
#include "boxcyl/algo/convex_hull.hpp"

#include <gtest/gtest.h>

#include <array>      // permutations
#include <cmath>      // std::nextafter
#include <cstdint>    // seeds
#include <cstdio>     // std::printf for the measured double disagreement
#include <initializer_list>  // point-list literals
#include <limits>     // infinity, denorm_min
#include <optional>   // "not applicable" results
#include <random>     // rational-rotation generator
#include <string>     // messages
#include <type_traits>  // std::is_same_v
#include <utility>    // std::pair
#include <vector>     // point lists

#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/exact/reduce.hpp"
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"
#include "boxcyl/oracle/oracle.hpp"
#include "support/cases.hpp"

namespace {

using boxcyl::AlignedBox;
using boxcyl::CanonicalBox;
using boxcyl::Cylinder;
using boxcyl::OrientedBox;
using boxcyl::QFRational;
using boxcyl::QuadraticField;
using boxcyl::Rational;
using boxcyl::UnitCylinder;
using boxcyl::Vec3;
using boxcyl::algo::convex_hull;
using boxcyl::algo::Parallelepiped;
using boxcyl::testing::BoxKind;
using boxcyl::testing::Case;
using boxcyl::testing::describe;
namespace algo = boxcyl::algo;
namespace hull2d = boxcyl::algo::hull2d;

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double tiny = std::numeric_limits<double>::denorm_min();
double up(double x) { return std::nextafter(x, inf); }
double down(double x) { return std::nextafter(x, -inf); }

// ---------------------------------------------------------------------------------------------
// Running the convex-hull method exactly.

// T = QFRational: the unit axis D/|D| is exact in Q(√(D·D)).
bool hull_qf(const CanonicalBox<Rational>& b, const Cylinder<Rational>& c) {
    const QuadraticField<Rational> field(dot(c.axis, c.axis));
    const UnitCylinder<QFRational> u = boxcyl::to_unit(c, field);
    return convex_hull(CanonicalBox<QFRational>{boxcyl::lift(b.extents)}, u);
}
// World frame, any parallelepiped: aᵢ computed in Rational (exact), lifted into the field.
bool hull_qf(const Parallelepiped<Rational>& p, const Cylinder<Rational>& c) {
    const QuadraticField<Rational> field(dot(c.axis, c.axis));
    const UnitCylinder<QFRational> u = boxcyl::to_unit(c, field);
    const Parallelepiped<QFRational> q{boxcyl::lift(p.center),
                                       {boxcyl::lift(p.half_edges[0]), boxcyl::lift(p.half_edges[1]),
                                        boxcyl::lift(p.half_edges[2])}};
    return convex_hull(q, u);
}
// Through the aligned-box reduction (exact for aligned boxes).
bool hull_qf_reduced(const AlignedBox<Rational>& b, const Cylinder<Rational>& c) {
    const QuadraticField<Rational> field(dot(c.axis, c.axis));
    const UnitCylinder<QFRational> u = boxcyl::to_unit(c, field);
    const auto q = boxcyl::to_canonical(AlignedBox<QFRational>{boxcyl::lift(b.min), boxcyl::lift(b.max)}, u);
    return convex_hull(q.box, q.cylinder);
}
// Through the oriented-box reduction: exact only for exactly orthonormal axes (then it is a rotation).
bool hull_qf_reduced(const OrientedBox<Rational>& b, const Cylinder<Rational>& c) {
    const QuadraticField<Rational> field(dot(c.axis, c.axis));
    const UnitCylinder<QFRational> u = boxcyl::to_unit(c, field);
    const OrientedBox<QFRational> ob{boxcyl::lift(b.center),
                                     {boxcyl::lift(b.axes[0]), boxcyl::lift(b.axes[1]), boxcyl::lift(b.axes[2])},
                                     boxcyl::lift(b.extents)};
    const auto q = boxcyl::to_canonical(ob, u);
    return convex_hull(q.box, q.cylinder);
}

bool exactly_orthonormal(const OrientedBox<Rational>& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j)
            if (dot(b.axes[i], b.axes[j]) != Rational(i == j ? 1 : 0)) return false;
    return true;
}

// The exact convex-hull answer for a generated case. Aligned and oriented boxes run in the world frame as
// parallelepipeds (algo::as_parallelepiped, qualified: boxcyl::as_oriented_box from oracle.hpp
// would win ADL for Rational boxes), canonical boxes through the canonical overload.
bool hull_exact(const Case& c) {
    const Cylinder<Rational> cyl = boxcyl::to_exact(c.cylinder);
    switch (c.kind) {
        case BoxKind::canonical: return hull_qf(boxcyl::to_exact(c.canonical), cyl);
        case BoxKind::aligned: return hull_qf(algo::as_parallelepiped(boxcyl::to_exact(c.aligned)), cyl);
        case BoxKind::oriented: return hull_qf(algo::as_parallelepiped(boxcyl::to_exact(c.oriented)), cyl);
    }
    return false;
}

// The convex-hull method in double, world frame for aligned and oriented boxes (rounded: normalised axis,
// aᵢ = eᵢAᵢ and arithmetic rounded).
bool hull_double(const Case& c) {
    const UnitCylinder<double> u = boxcyl::to_unit(c.cylinder);
    switch (c.kind) {
        case BoxKind::canonical: return convex_hull(c.canonical, u);
        case BoxKind::aligned: return convex_hull(algo::as_parallelepiped(c.aligned), u);
        case BoxKind::oriented: return convex_hull(algo::as_parallelepiped(c.oriented), u);
    }
    return false;
}

// The convex-hull method in double through the reductions to the canonical box (for comparison only).
bool hull_double_reduced(const Case& c) {
    const UnitCylinder<double> u = boxcyl::to_unit(c.cylinder);
    switch (c.kind) {
        case BoxKind::canonical: return convex_hull(c.canonical, u);
        case BoxKind::aligned: {
            const auto q = boxcyl::to_canonical(c.aligned, u);
            return convex_hull(q.box, q.cylinder);
        }
        case BoxKind::oriented: {
            const auto q = boxcyl::to_canonical(c.oriented, u);
            return convex_hull(q.box, q.cylinder);
        }
    }
    return false;
}

// The kind of the case gen.next() will return, without advancing gen (the generator is a value).
BoxKind peek_kind(const boxcyl::testing::CaseGenerator& gen) {
    boxcyl::testing::CaseGenerator copy = gen;
    return copy.next().kind;
}

// √q for a rational square q, else nullopt.
std::optional<Rational> rational_sqrt(const Rational& q) {
    if (sgn(q) < 0) return std::nullopt;
    const mpz_class& n = q.get_num();
    const mpz_class& m = q.get_den();
    if (mpz_perfect_square_p(n.get_mpz_t()) == 0 || mpz_perfect_square_p(m.get_mpz_t()) == 0) return std::nullopt;
    return Rational(mpz_class(sqrt(n)), mpz_class(sqrt(m)));
}

// T = Rational, possible when |axis| is rational (so D/|D| is an exactly unit rational vector).
std::optional<bool> hull_rational(const CanonicalBox<Rational>& b, const Cylinder<Rational>& c) {
    const std::optional<Rational> len = rational_sqrt(dot(c.axis, c.axis));
    if (!len) return std::nullopt;
    UnitCylinder<Rational> u;
    u.center = c.center;
    for (int i = 0; i < 3; ++i) u.direction[i] = c.axis[i] / *len;
    u.radius = c.radius;
    u.half_height = c.height / 2;
    return convex_hull(b, u);
}

std::string str(const Vec3<Rational>& v) {
    return "{" + v[0].get_str() + ", " + v[1].get_str() + ", " + v[2].get_str() + "}";
}

// ---------------------------------------------------------------------------------------------
// 2-D hull (Andrew's monotone chain), in Rational arithmetic.

using P = hull2d::Point<Rational>;

std::vector<P> pts(std::initializer_list<std::pair<Rational, Rational>> xs) {
    std::vector<P> v;
    for (const auto& [x, y] : xs) v.push_back({x, y});
    return v;
}

void expect_hull(const std::vector<P>& in, const std::vector<P>& want) {
    const std::vector<P> got = hull2d::monotone_chain(in);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].x, want[i].x) << "vertex " << i;
        EXPECT_EQ(got[i].y, want[i].y) << "vertex " << i;
    }
}

TEST(MonotoneChain, Empty) { expect_hull({}, {}); }

TEST(MonotoneChain, SquareWithInteriorPointsAndDuplicates) {
    // Counter-clockwise from the lexicographically smallest vertex.
    expect_hull(pts({{2, 2}, {0, 0}, {1, 1}, {2, 0}, {0, 2}, {0, 0}, {2, 2}, {Rational(1, 3), Rational(5, 3)}}),
                pts({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
}

TEST(MonotoneChain, CollinearPointsOnEdgesAreNotVertices) {
    expect_hull(pts({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {Rational(1, 2), 0}}),
                pts({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
}

TEST(MonotoneChain, AllCollinearGivesTheTwoExtremes) {
    expect_hull(pts({{1, 1}, {3, 3}, {0, 0}, {2, 2}, {1, 1}, {3, 3}}), pts({{0, 0}, {3, 3}}));
    expect_hull(pts({{0, 2}, {0, 0}, {0, 1}, {0, 2}}), pts({{0, 0}, {0, 2}}));      // vertical
    expect_hull(pts({{5, -1}, {-3, -1}, {0, -1}}), pts({{-3, -1}, {5, -1}}));      // horizontal
    expect_hull(pts({{2, -2}, {0, 0}, {-1, 1}, {1, -1}}), pts({{-1, 1}, {2, -2}})); // descending
}

TEST(MonotoneChain, AllEqualGivesOnePoint) {
    const Rational x(1, 3), y(-2, 7);
    expect_hull(pts({{x, y}, {x, y}, {x, y}, {x, y}}), pts({{x, y}}));
    expect_hull(pts({{x, y}}), pts({{x, y}}));
}

TEST(MonotoneChain, TwoPoints) {
    expect_hull(pts({{3, 1}, {-1, 4}}), pts({{-1, 4}, {3, 1}}));
    expect_hull(pts({{3, 1}, {3, 1}, {-1, 4}}), pts({{-1, 4}, {3, 1}}));
}

TEST(MonotoneChain, ClockwiseTriangleComesOutCounterClockwise) {
    expect_hull(pts({{0, 0}, {0, 1}, {1, 0}}), pts({{0, 0}, {1, 0}, {0, 1}}));
}

TEST(MonotoneChain, NearlyCollinearIsDecidedExactly) {
    const Rational eps(1, mpz_class("1000000000000000000000000000000000000000"));
    // Moving one point of a collinear triple by ε makes a (very thin) triangle; without it, the middle
    // point is dropped.
    expect_hull(pts({{0, 0}, {1, 1}, {2, 2 + eps}}), pts({{0, 0}, {1, 1}, {2, 2 + eps}}));
    expect_hull(pts({{0, 0}, {1, 1}, {2, 2}}), pts({{0, 0}, {2, 2}}));
    expect_hull(pts({{0, 0}, {1, 1 - eps}, {2, 2}}), pts({{0, 0}, {1, 1 - eps}, {2, 2}}));
}

TEST(MonotoneChain, QuadraticFieldCoordinates) {
    const QuadraticField<Rational> f(Rational(2));
    const QFRational s2 = QFRational::root(f);  // √2
    using PQ = hull2d::Point<QFRational>;
    // A square with vertices (±√2, 0), (0, ±√2) and points on its edges and inside.
    const std::vector<PQ> in{{s2, 0}, {0, s2}, {-s2, 0}, {0, -s2}, {s2 / 2, s2 / 2}, {0, 0}, {QFRational(1) / 2, 0}};
    const std::vector<PQ> h = hull2d::monotone_chain(in);
    ASSERT_EQ(h.size(), 4u);
    EXPECT_TRUE(h[0].x == -s2 && h[0].y == QFRational(0));
    EXPECT_TRUE(h[1].x == QFRational(0) && h[1].y == -s2);
    EXPECT_TRUE(h[2].x == s2 && h[2].y == QFRational(0));
    EXPECT_TRUE(h[3].x == QFRational(0) && h[3].y == s2);
    // 1 and √2/2·√2 = 1: (1, 1) vs (√2·√2/2, 1): equal points deduplicate exactly.
    const std::vector<PQ> dup{{QFRational(1), 1}, {s2 * s2 / 2, 1}, {QFRational(2), 1}};
    EXPECT_EQ(hull2d::monotone_chain(dup).size(), 2u);
}

TEST(MonotoneChain, DoubleAndFloatInstantiate) {
    const std::vector<hull2d::Point<double>> d{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {1, 0}};
    EXPECT_EQ(hull2d::monotone_chain(d).size(), 4u);
    const std::vector<hull2d::Point<float>> f{{0, 0}, {1, 1}, {2, 2}};
    EXPECT_EQ(hull2d::monotone_chain(f).size(), 2u);
}

TEST(OriginWithin, SegmentDistances) {
    // Foot inside the segment: the line y = 1 is at distance 1.
    EXPECT_TRUE(hull2d::segment_within(P{-1, 1}, P{1, 1}, Rational(1)));
    EXPECT_FALSE(hull2d::segment_within(P{-1, 1}, P{1, 1}, Rational(1) - Rational(1, 1 << 30)));
    // Foot beyond b: nearest point b = (2, 1), distance² 5.
    EXPECT_TRUE(hull2d::segment_within(P{3, 1}, P{2, 1}, Rational(5)));
    EXPECT_FALSE(hull2d::segment_within(P{3, 1}, P{2, 1}, Rational(4)));
    EXPECT_TRUE(hull2d::segment_within(P{2, 1}, P{3, 1}, Rational(5)));
    EXPECT_FALSE(hull2d::segment_within(P{2, 1}, P{3, 1}, Rational(5) - Rational(1, 1000)));
    // Degenerate segment (a point), and the origin on a segment with r = 0.
    EXPECT_TRUE(hull2d::segment_within(P{3, 4}, P{3, 4}, Rational(25)));
    EXPECT_FALSE(hull2d::segment_within(P{3, 4}, P{3, 4}, Rational(24)));
    EXPECT_TRUE(hull2d::segment_within(P{-1, -1}, P{2, 2}, Rational(0)));
    // Slanted: the line x + y = 2 is at distance √2 from the origin.
    EXPECT_TRUE(hull2d::segment_within(P{2, 0}, P{0, 2}, Rational(2)));
    EXPECT_FALSE(hull2d::segment_within(P{2, 0}, P{0, 2}, Rational(2) - Rational(1, 1 << 30)));
}

TEST(OriginWithin, Polygons) {
    const Rational z(0);
    // Origin strictly inside, on an edge, at a vertex: inside with r = 0.
    EXPECT_TRUE(hull2d::origin_within(hull2d::monotone_chain(pts({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})), z));
    EXPECT_TRUE(hull2d::origin_within(hull2d::monotone_chain(pts({{0, -1}, {2, -1}, {2, 1}, {0, 1}})), z));
    EXPECT_TRUE(hull2d::origin_within(hull2d::monotone_chain(pts({{0, 0}, {2, 0}, {0, 2}})), z));
    // Outside: triangle (1,1),(3,1),(1,3): nearest point (1,1), distance² 2.
    const auto tri = hull2d::monotone_chain(pts({{1, 1}, {3, 1}, {1, 3}}));
    EXPECT_TRUE(hull2d::origin_within(tri, Rational(2)));
    EXPECT_FALSE(hull2d::origin_within(tri, Rational(2) - Rational(1, 1 << 30)));
    // Outside, nearest point inside an edge: square [1,2]×[−1,1]: distance 1.
    const auto sq = hull2d::monotone_chain(pts({{1, -1}, {2, -1}, {2, 1}, {1, 1}}));
    EXPECT_TRUE(hull2d::origin_within(sq, Rational(1)));
    EXPECT_FALSE(hull2d::origin_within(sq, Rational(1) - Rational(1, 1 << 30)));
    // Empty set never within.
    EXPECT_FALSE(hull2d::origin_within(std::vector<P>{}, Rational(100)));
}

TEST(ProjectionFrame, OrthogonalEqualLengthsExact) {
    // Rational unit directions: W0, W1 ⊥ D, W0 ⊥ W1, |W0|² = |W1|² = L² = 1 − d_k².
    const std::vector<Vec3<Rational>> dirs{{1, 0, 0},
                                          {0, -1, 0},
                                          {Rational(3, 5), Rational(-4, 5), 0},
                                          {Rational(1, 3), Rational(2, 3), Rational(-2, 3)},
                                          {Rational(-3, 13), Rational(4, 13), Rational(12, 13)}};
    for (const auto& d : dirs) {
        const auto f = boxcyl::algo::projection_frame(d);
        EXPECT_EQ(dot(f.w0, d), 0) << str(d);
        EXPECT_EQ(dot(f.w1, d), 0) << str(d);
        EXPECT_EQ(dot(f.w0, f.w1), 0) << str(d);
        EXPECT_EQ(dot(f.w0, f.w0), f.length2) << str(d);
        EXPECT_EQ(dot(f.w1, f.w1), f.length2) << str(d);
        Rational m = d[0] * d[0];  // the smallest d_k²
        for (int i = 1; i < 3; ++i)
            if (d[i] * d[i] < m) m = d[i] * d[i];
        EXPECT_EQ(f.length2, 1 - m) << str(d);
    }
}

// ---------------------------------------------------------------------------------------------
// Hand cases: exact touching configurations and one-ulp neighbours. Each one is checked in all 48
// signed coordinate permutations (the canonical box is symmetric under them) and with the axis
// negated, so every direction class is also run with negative components and in every axis order.

struct Hand {
    const char* name;
    Vec3<double> extents;
    Cylinder<double> cyl;
    bool expected;
};

Cylinder<double> cyl(Vec3<double> c, Vec3<double> axis, double r, double h) { return {c, axis, r, h}; }
const Vec3<double> unit_box{1, 1, 1};

// Three extents, a cylinder (centre, axis, radius, height), the exact answer.
const std::vector<Hand>& hand_cases() {
    static const std::vector<Hand> cases{
        // ---- (+,0,0): axis (1,0,0), box [−1,1]³.
        {"x: side touches face y=1", unit_box, cyl({0, 1.5, 0}, {1, 0, 0}, 0.5, 1), true},
        {"x: side face, r-ulp", unit_box, cyl({0, 1.5, 0}, {1, 0, 0}, down(0.5), 1), false},
        {"x: side face, c_y+ulp", unit_box, cyl({0, up(1.5), 0}, {1, 0, 0}, 0.5, 1), false},
        {"x: side face, c_y-ulp", unit_box, cyl({0, down(1.5), 0}, {1, 0, 0}, 0.5, 1), true},
        // |(1.75, 2) − (1, 1)| = 1.25: the side touches the edge {y=1, z=1}.
        {"x: side touches edge", unit_box, cyl({0, 1.75, 2}, {1, 0, 0}, 1.25, 1), true},
        {"x: side edge, r-ulp", unit_box, cyl({0, 1.75, 2}, {1, 0, 0}, down(1.25), 1), false},
        {"x: side edge, c_z+ulp", unit_box, cyl({0, 1.75, up(2)}, {1, 0, 0}, 1.25, 1), false},
        // End disk (x = 1) on the face x = 1.
        {"x: end disk on face", unit_box, cyl({1.5, 0, 0}, {1, 0, 0}, 0.25, 1), true},
        {"x: end face, c_x+ulp", unit_box, cyl({up(1.5), 0, 0}, {1, 0, 0}, 0.25, 1), false},
        {"x: end face, h-ulp", unit_box, cyl({1.5, 0, 0}, {1, 0, 0}, 0.25, down(1)), false},
        // Rim of the end disk (centre (1, 1.25, 0), r 0.25) touches the edge {x=1, y=1}.
        {"x: rim touches edge", unit_box, cyl({1.5, 1.25, 0}, {1, 0, 0}, 0.25, 1), true},
        {"x: rim edge, r-ulp", unit_box, cyl({1.5, 1.25, 0}, {1, 0, 0}, down(0.25), 1), false},
        {"x: rim edge, c_x+ulp", unit_box, cyl({up(1.5), 1.25, 0}, {1, 0, 0}, 0.25, 1), false},
        {"x: rim edge, c_y+ulp", unit_box, cyl({1.5, up(1.25), 0}, {1, 0, 0}, 0.25, 1), false},
        // Rim (centre (1, 1.75, 2), r 1.25) touches the vertex (1, 1, 1).
        {"x: rim touches vertex", unit_box, cyl({1.5, 1.75, 2}, {1, 0, 0}, 1.25, 1), true},
        {"x: rim vertex, r-ulp", unit_box, cyl({1.5, 1.75, 2}, {1, 0, 0}, down(1.25), 1), false},
        {"x: rim vertex, c_z+ulp", unit_box, cyl({1.5, 1.75, up(2)}, {1, 0, 0}, 1.25, 1), false},
        {"x: axis through box", unit_box, cyl({0, 0.5, -0.5}, {1, 0, 0}, 0.01, 0.5), true},

        // ---- (+,+,0): axis (3,4,0), D = (3,4,0)/5; in-plane normal (4,−3,0)/5.
        // C = (−1, 1, 0) + 1.25·(−4, 3, 0)/5: the side touches the edge {x=−1, y=1} at z = 0.
        {"xy: side touches edge", unit_box, cyl({-2, 1.75, 0}, {3, 4, 0}, 1.25, 1), true},
        {"xy: side edge, r-ulp", unit_box, cyl({-2, 1.75, 0}, {3, 4, 0}, down(1.25), 1), false},
        {"xy: side edge, c_y+ulp", unit_box, cyl({-2, up(1.75), 0}, {3, 4, 0}, 1.25, 1), false},
        {"xy: side touches face z=1", unit_box, cyl({0, 0, 1.5}, {3, 4, 0}, 0.5, 1), true},
        {"xy: side face, r-ulp", unit_box, cyl({0, 0, 1.5}, {3, 4, 0}, down(0.5), 1), false},
        {"xy: side face, c_z+ulp", unit_box, cyl({0, 0, up(1.5)}, {3, 4, 0}, 0.5, 1), false},
        // C = (1,1,0) + 2.5·D: the edge {x=1, y=1} lies in the lower end plane, through its centre.
        {"xy: end disk contains edge", unit_box, cyl({2.5, 3, 0}, {3, 4, 0}, 0.5, 5), true},
        {"xy: end edge, c_x+ulp", unit_box, cyl({up(2.5), 3, 0}, {3, 4, 0}, 0.5, 5), false},
        {"xy: end edge, h-ulp", unit_box, cyl({2.5, 3, 0}, {3, 4, 0}, 0.5, down(5)), false},
        // Lower disk centre (2, 0.25, 0), r 1.25: its rim is tangent to the edge {x=1, y=1}.
        {"xy: rim tangent to edge", unit_box, cyl({3.5, 2.25, 0}, {3, 4, 0}, 1.25, 5), true},
        {"xy: rim edge, r-ulp", unit_box, cyl({3.5, 2.25, 0}, {3, 4, 0}, down(1.25), 5), false},
        {"xy: rim edge, c_y+ulp", unit_box, cyl({3.5, up(2.25), 0}, {3, 4, 0}, 1.25, 5), false},
        {"xy: rim edge, c_x-ulp", unit_box, cyl({down(3.5), 2.25, 0}, {3, 4, 0}, 1.25, 5), true},

        // ---- (+,+,+): axis (1,2,2), D = (1,2,2)/3; (2,1,−2)/3 ⊥ D.
        // Lower disk centre (0.5, 0.75, 1.5) = V − 0.75·(2,1,−2)/3, V = (1,1,1) the D-extreme vertex.
        {"xyz: rim touches vertex", unit_box, cyl({1, 1.75, 2.5}, {1, 2, 2}, 0.75, 3), true},
        {"xyz: rim vertex, r-ulp", unit_box, cyl({1, 1.75, 2.5}, {1, 2, 2}, down(0.75), 3), false},
        {"xyz: rim vertex, c_x+ulp", unit_box, cyl({up(1), 1.75, 2.5}, {1, 2, 2}, 0.75, 3), false},
        {"xyz: rim vertex, h-ulp", unit_box, cyl({1, 1.75, 2.5}, {1, 2, 2}, 0.75, down(3)), false},
        {"xyz: end disk centre at vertex", unit_box, cyl({1.5, 2, 2}, {1, 2, 2}, 0.25, 3), true},
        {"xyz: end vertex, c_y+ulp", unit_box, cyl({1.5, up(2), 2}, {1, 2, 2}, 0.25, 3), false},
        // Axis (3,4,12)/13, perpendicular (4,−3,0)/5 is in the normal cone of the edge {x=1, y=−1}:
        // the side touches that edge at (1, −1, 0).
        {"xyz: side touches edge", unit_box, cyl({2, -1.75, 0}, {3, 4, 12}, 1.25, 2), true},
        {"xyz: side edge, r-ulp", unit_box, cyl({2, -1.75, 0}, {3, 4, 12}, down(1.25), 2), false},
        {"xyz: side edge, c_x+ulp", unit_box, cyl({up(2), -1.75, 0}, {3, 4, 12}, 1.25, 2), false},
        {"xyz: far miss", unit_box, cyl({10, 10, 10}, {1, 2, 2}, 1, 1), false},
        {"xyz: centre inside", unit_box, cyl({0.25, -0.5, 0.75}, {1, 2, 2}, 0.01, 0.01), true},
        {"xyz: box inside cylinder", unit_box, cyl({0, 0, 0}, {1, 2, 2}, 10, 10), true},
        {"xyz: non-unit extents", {0.5, 2, 0.25}, cyl({0.5, 2.5, 0}, {1, 2, 2}, 0.75, 1), true},

        // ---- Degenerate solids.
        // Point box at the origin on the side of an x cylinder.
        {"point box on side", {0, 0, 0}, cyl({0, 0.5, 0}, {1, 0, 0}, 0.5, 1), true},
        {"point box, r-ulp", {0, 0, 0}, cyl({0, 0.5, 0}, {1, 0, 0}, down(0.5), 1), false},
        {"point box on rim", {0, 0, 0}, cyl({0.5, 0.5, 0}, {1, 0, 0}, 0.5, 1), true},
        {"point box, rim h-ulp", {0, 0, 0}, cyl({0.5, 0.5, 0}, {1, 0, 0}, 0.5, down(1)), false},
        // Segment box (x only) and a z cylinder touching it at (0, 0, 0).
        {"segment box touched", {1, 0, 0}, cyl({0, 0.25, 0}, {0, 0, 1}, 0.25, 1), true},
        {"segment box, r-ulp", {1, 0, 0}, cyl({0, 0.25, 0}, {0, 0, 1}, down(0.25), 1), false},
        {"segment box crossed", {1, 0, 0}, cyl({0.5, 0, 0.75}, {0, 0, 1}, 0.1, 3), true},
        // Flat box z = 0 and a coplanar disk (h = 0) touching its edge x = 1.
        {"flat box, coplanar disk", {1, 1, 0}, cyl({1.5, 0, 0}, {0, 0, 1}, 0.5, 0), true},
        {"flat box, disk r-ulp", {1, 1, 0}, cyl({1.5, 0, 0}, {0, 0, 1}, down(0.5), 0), false},
        {"flat box, disk lifted", {1, 1, 0}, cyl({0, 0, tiny}, {0, 0, 1}, 0.5, 0), false},
        {"flat box, tilted disk", {1, 1, 0}, cyl({0, 0, 0}, {1, 2, 2}, 0.5, 0), true},
        // Radius 0: a segment along the edge line {y=1, z=1}.
        {"segment cylinder on edge", unit_box, cyl({0, 1, 1}, {1, 0, 0}, 0, 1), true},
        {"segment on edge, c_y+ulp", unit_box, cyl({0, up(1), 1}, {1, 0, 0}, 0, 1), false},
        // Radius 0, tilted: the segment's endpoint is the vertex (1,1,1).
        {"segment ends at vertex", unit_box, cyl({1.5, 2, 2}, {1, 2, 2}, 0, 3), true},
        {"segment at vertex, c_x+ulp", unit_box, cyl({up(1.5), 2, 2}, {1, 2, 2}, 0, 3), false},
        {"segment through box", unit_box, cyl({0, 0, 0}, {1, 2, 2}, 0, 0.5), true},
        // Height 0: a disk with normal (1,2,2)/3 whose rim passes through the vertex (1,1,1).
        {"disk rim at vertex", unit_box, cyl({0.5, 0.75, 1.5}, {1, 2, 2}, 0.75, 0), true},
        {"disk rim vertex, r-ulp", unit_box, cyl({0.5, 0.75, 1.5}, {1, 2, 2}, down(0.75), 0), false},
        {"disk rim vertex, c_z+ulp", unit_box, cyl({0.5, 0.75, up(1.5)}, {1, 2, 2}, 0.75, 0), false},
        // Both 0: a point.
        {"point cylinder on face", unit_box, cyl({1, 0.5, -0.25}, {1, 2, 2}, 0, 0), true},
        {"point cylinder, c_x+ulp", unit_box, cyl({up(1), 0.5, -0.25}, {1, 2, 2}, 0, 0), false},
        {"point vs point", {0, 0, 0}, cyl({0, 0, 0}, {3, 4, 12}, 0, 0), true},
        {"point vs point, c_x=denorm", {0, 0, 0}, cyl({tiny, 0, 0}, {3, 4, 12}, 0, 0), false},
        // Subnormal extent and height: the end disk (x = C_x − denorm_min) on the face x = denorm_min.
        {"subnormal extent, end face touch", {tiny, 1, 1}, cyl({2 * tiny, 0, 0}, {1, 0, 0}, 1, 2 * tiny), true},
        {"subnormal extent, end face c_x+ulp", {tiny, 1, 1}, cyl({3 * tiny, 0, 0}, {1, 0, 0}, 1, 2 * tiny), false},
        // Tiny axis components: the tilt by denorm_min/1e-300 turns a touch into a true overlap at the
        // far end, but far less than one ulp of r.
        {"subnormal tilt, side", unit_box, cyl({0, 1.5, 0}, {1, tiny, 0}, 0.5, 4), true},
        {"subnormal tilt, r-ulp", unit_box, cyl({0, 1.5, 0}, {1, tiny, 0}, down(0.5), 4), false},
        {"1e-300 tilt, side", unit_box, cyl({0, 1.5, 0}, {1, 1e-300, 0}, 0.5, 4), true},
        {"1e-300 tilt, r-ulp", unit_box, cyl({0, 1.5, 0}, {1, 1e-300, 0}, down(0.5), 4), false},
        {"subnormal tilt, end", unit_box, cyl({up(1.5), 0, 0}, {1, tiny, tiny}, 0.25, 1), false},
        {"subnormal tilt, end touch", unit_box, cyl({1.5, 0, 0}, {1, tiny, tiny}, 0.25, 1), true},
        {"two subnormal components", unit_box, cyl({0, 0, 1.5}, {1, tiny, tiny}, 0.5, 4), true},
    };
    return cases;
}

// The case with coordinates permuted (new axis i = old axis perm[i]) and reflected (sign bit i).
Hand transformed(const Hand& h, const std::array<int, 3>& perm, int signs, bool flip_axis) {
    Hand t = h;
    for (int i = 0; i < 3; ++i) {
        const double s = (signs >> i) & 1 ? -1.0 : 1.0;
        t.extents[i] = h.extents[perm[i]];
        t.cyl.center[i] = s * h.cyl.center[perm[i]];
        t.cyl.axis[i] = (flip_axis ? -s : s) * h.cyl.axis[perm[i]];
    }
    return t;
}

std::string describe(const Hand& h) {
    using boxcyl::testing::hex;
    return std::string(h.name) + ": extents " + hex(h.extents) + ", Cylinder<double>{" + hex(h.cyl.center) + ", " +
           hex(h.cyl.axis) + ", " + hex(h.cyl.radius) + ", " + hex(h.cyl.height) + "}";
}

TEST(ConvexHullHand, ExpectedAnswersInEveryOrientation) {
    const std::array<std::array<int, 3>, 6> perms{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    int checked = 0;
    for (const Hand& h : hand_cases()) {
        for (const auto& perm : perms)
            for (int signs = 0; signs < 8; ++signs)
                for (bool flip : {false, true}) {
                    const Hand t = transformed(h, perm, signs, flip);
                    const CanonicalBox<Rational> box{boxcyl::to_exact(t.extents)};
                    const Cylinder<Rational> c = boxcyl::to_exact(t.cyl);
                    if (signs == 0 && !flip) {  // the oracle's own invariances are tested in test_oracle
                        ASSERT_EQ(boxcyl::oracle::intersects(box, c), h.expected) << "oracle: " << describe(t);
                    }
                    ASSERT_EQ(hull_qf(box, c), h.expected) << "hull QFRational: " << describe(t);
                    if (const auto r = hull_rational(box, c)) {
                        ASSERT_EQ(*r, h.expected) << "hull Rational: " << describe(t);
                    }
                    ++checked;
                }
    }
    EXPECT_EQ(checked, static_cast<int>(hand_cases().size()) * 96);
}

// T = Rational with exactly unit directions, directly (not via the quadratic field).
TEST(ConvexHullHand, RationalUnitDirections) {
    int rational = 0;
    for (const Hand& h : hand_cases()) {
        const auto r = hull_rational(CanonicalBox<Rational>{boxcyl::to_exact(h.extents)}, boxcyl::to_exact(h.cyl));
        if (!r) continue;
        EXPECT_EQ(*r, h.expected) << describe(h);
        ++rational;
    }
    EXPECT_GE(rational, 50);  // all hand axes except the tiny tilts have rational length
}

// float/double: rounded, so only clear-cut cases are asserted.
template <class T>
bool hull_fp(const Vec3<double>& e, const Cylinder<double>& c) {
    const Cylinder<T> ct{{T(c.center[0]), T(c.center[1]), T(c.center[2])},
                         {T(c.axis[0]), T(c.axis[1]), T(c.axis[2])},
                         T(c.radius),
                         T(c.height)};
    return convex_hull(CanonicalBox<T>{{T(e[0]), T(e[1]), T(e[2])}}, boxcyl::to_unit(ct));
}

TEST(ConvexHullFloatingPoint, ClearCutCases) {
    struct C {
        Vec3<double> e;
        Cylinder<double> c;
        bool expected;
    };
    const std::vector<C> cases{
        {unit_box, cyl({0, 1.6, 0}, {1, 0, 0}, 0.5, 1), false},
        {unit_box, cyl({0, 1.4, 0}, {1, 0, 0}, 0.5, 1), true},
        {unit_box, cyl({1, 1.75, 2.5}, {1, 2, 2}, 0.5, 3.2), false},
        {unit_box, cyl({1, 1.75, 2.5}, {1, 2, 2}, 0.8, 3.2), true},
        {unit_box, cyl({-2, 1.75, 0}, {3, 4, 0}, 1.2, 1), false},
        {unit_box, cyl({-2, 1.75, 0}, {3, 4, 0}, 1.3, 1), true},
        {unit_box, cyl({3.5, 2.25, 0}, {-3, -4, 0}, 1.3, 5.4), true},
        {unit_box, cyl({3.5, 2.25, 0}, {-3, -4, 0}, 0.8, 5.4), false},
        {unit_box, cyl({0, 0, 0}, {0.3, -0.2, 0.9}, 0, 0), true},
        {{0, 0, 0}, cyl({0, 0.4, 0}, {1, 0, 0}, 0.5, 1), true},
        {{1, 1, 0}, cyl({1.4, 0, 0}, {0, 0, 1}, 0.5, 0), true},
        {{1, 1, 0}, cyl({1.6, 0, 0}, {0, 0, 1}, 0.5, 0), false},
        {unit_box, cyl({0, 1.5, 0}, {1, 1e-300, 0}, 0.6, 4), true},
        {unit_box, cyl({0, 1.5, 0}, {1, tiny, 0}, 0.4, 4), false},
    };
    for (const C& c : cases) {
        const Hand h{"fp", c.e, c.c, c.expected};
        EXPECT_EQ(boxcyl::oracle::intersects(CanonicalBox<double>{c.e}, c.c), c.expected) << describe(h);
        EXPECT_EQ(hull_fp<double>(c.e, c.c), c.expected) << "double: " << describe(h);
        EXPECT_EQ(hull_fp<float>(c.e, c.c), c.expected) << "float: " << describe(h);
    }
}

// ---------------------------------------------------------------------------------------------
// Parallelepipeds in the world frame: construction, the generalised slab cull, sheared boxes with
// exact touches, dependent and zero half-edges.

std::string str(const Parallelepiped<Rational>& p) {
    return "Parallelepiped<Rational>{" + str(p.center) + ", {" + str(p.half_edges[0]) + ", " + str(p.half_edges[1]) +
           ", " + str(p.half_edges[2]) + "}}";
}
std::string str(const Cylinder<Rational>& c) {
    return "Cylinder<Rational>{" + str(c.center) + ", " + str(c.axis) + ", " + c.radius.get_str() + ", " +
           c.height.get_str() + "}";
}

TEST(AsParallelepiped, OrientedAlignedCanonical) {
    const OrientedBox<double> ob{{1, 2, 3}, {Vec3<double>{0.6, 0.8, 0}, Vec3<double>{-0.8, 0.6, 0}, Vec3<double>{0, 0, 1}},
                                 {2, 0.5, 0}};
    const Parallelepiped<double> p = algo::as_parallelepiped(ob);
    EXPECT_EQ(p.center, (Vec3<double>{1, 2, 3}));
    EXPECT_EQ(p.half_edges[0], (Vec3<double>{2 * 0.6, 2 * 0.8, 0}));
    EXPECT_EQ(p.half_edges[1], (Vec3<double>{0.5 * -0.8, 0.5 * 0.6, 0}));
    EXPECT_EQ(p.half_edges[2], (Vec3<double>{0, 0, 0}));  // zero extent: zero half-edge

    const AlignedBox<Rational> ab{{-1, 2, Rational(1, 3)}, {3, 2, 1}};
    const auto q = algo::as_parallelepiped(ab);
    static_assert(std::is_same_v<decltype(q), const Parallelepiped<Rational>>);
    EXPECT_EQ(q.center, (Vec3<Rational>{1, 2, Rational(2, 3)}));
    EXPECT_EQ(q.half_edges[0], (Vec3<Rational>{2, 0, 0}));
    EXPECT_EQ(q.half_edges[1], (Vec3<Rational>{0, 0, 0}));
    EXPECT_EQ(q.half_edges[2], (Vec3<Rational>{0, 0, Rational(1, 3)}));

    const auto c = algo::as_parallelepiped(CanonicalBox<float>{{1, 2, 3}});
    EXPECT_EQ(c.center, (Vec3<float>{0, 0, 0}));
    EXPECT_EQ(c.half_edges[1], (Vec3<float>{0, 2, 0}));
}

// The generalised slab cull in exact arithmetic: touching the slab plane is not outside.
TEST(ParallelepipedSlabCull, TouchingIsNotOutside) {
    // Sheared box: a0 = (1,0,0), a1 = (1,1,0), a2 = (0,0,1), K = (0,0,5). Axis z: ρ = 1, γ = 5 − c_z.
    const Parallelepiped<Rational> p{{0, 0, 5}, {Vec3<Rational>{1, 0, 0}, Vec3<Rational>{1, 1, 0}, Vec3<Rational>{0, 0, 1}}};
    const Rational eps(1, mpz_class(1) << 80);
    auto cyl_at = [](const Rational& cz, const Rational& hh) {
        return UnitCylinder<Rational>{{7, -3, cz}, {0, 0, 1}, 0, hh};
    };
    // Top of the slab at c_z + 1 touches the bottom face z = 4.
    EXPECT_FALSE(algo::parallelepiped_outside_slab(p, cyl_at(3, 1)));
    EXPECT_TRUE(algo::parallelepiped_outside_slab(p, cyl_at(3 - eps, 1)));
    // Bottom of the slab at c_z − 1 touches the top face z = 6 (|γ| with γ < 0).
    EXPECT_FALSE(algo::parallelepiped_outside_slab(p, cyl_at(7, 1)));
    EXPECT_TRUE(algo::parallelepiped_outside_slab(p, cyl_at(7 + eps, 1)));
    // Axis (0,3,4)/5 through the origin: γ = D·(K − C) = 4, ρ = |D·a0| + |D·a1| + |D·a2| = 0 + 3/5 + 4/5,
    // so the slab reaches the box exactly when h/2 = 4 − 7/5 = 13/5.
    auto tilted = [](const Rational& hh) {
        return UnitCylinder<Rational>{{0, 0, 0}, {0, Rational(3, 5), Rational(4, 5)}, 1, hh};
    };
    EXPECT_FALSE(algo::parallelepiped_outside_slab(p, tilted(Rational(13, 5))));
    EXPECT_TRUE(algo::parallelepiped_outside_slab(p, tilted(Rational(13, 5) - eps)));
    // convex_hull uses the same cull.
    EXPECT_FALSE(convex_hull(p, tilted(Rational(13, 5) - eps)));
}

// A sheared box: a0 = (1,0,0), a1 = (3/5,4/5,0), a2 = (0,0,1), K = 0. The face ξ0 = +1 lies in the
// plane n·X = 4/5 with the unit outward normal n = (4/5,−3/5,0) (n ⊥ a1, a2; n·a0 = 4/5). The
// horizontal cross-section is the parallelogram ±a0 ± a1, with the vertex V = a0 + a1 = (8/5,4/5)
// whose outward normal cone (between n and (0,1)) contains (1,0).
struct ShearedHand {
    const char* name;
    Cylinder<Rational> cyl;
    bool expected;
};

const Parallelepiped<Rational> sheared{
    {0, 0, 0}, {Vec3<Rational>{1, 0, 0}, Vec3<Rational>{Rational(3, 5), Rational(4, 5), 0}, Vec3<Rational>{0, 0, 1}}};

std::vector<ShearedHand> sheared_cases() {
    const Rational e(1, mpz_class(1) << 70), h(1, 2), q(1, 4);
    const Rational v0(8, 5), v1(4, 5);  // the vertex V in the cross-section
    auto c = [](const Vec3<Rational>& cc, const Vec3<Rational>& ax, const Rational& r, const Rational& hh) {
        return Cylinder<Rational>{cc, ax, r, hh};
    };
    const Vec3<Rational> z{0, 0, 1};
    return {
        // Axis z, side tangent to the slanted face along the line through a0: C = a0 + r·n.
        {"z: side on slanted face", c({Rational(7, 5), Rational(-3, 10), 0}, z, h, 1), true},
        {"z: slanted face, r-e", c({Rational(7, 5), Rational(-3, 10), 0}, z, h - e, 1), false},
        {"z: slanted face, C+e·n", c({Rational(7, 5) + 4 * e, Rational(-3, 10) - 3 * e, 0}, z, h, 1), false},
        {"z: slanted face, C-e·n", c({Rational(7, 5) - 4 * e, Rational(-3, 10) + 3 * e, 0}, z, h, 1), true},
        // Axis z, side tangent to the vertical edge through V: C = V + r·(1,0).
        {"z: side on edge", c({v0 + h, v1, 0}, z, h, 1), true},
        {"z: edge, r-e", c({v0 + h, v1, 0}, z, h - e, 1), false},
        {"z: edge, C_x+e", c({v0 + h + e, v1, 0}, z, h, 1), false},
        {"z: edge, C_y+e", c({v0 + h, v1 + e, 0}, z, h, 1), false},  // still only V is nearest
        // Axis z above the box: the lower rim (z = 1) touches the vertex (8/5, 4/5, 1).
        {"z: rim on vertex", c({v0 + h, v1, Rational(3, 2)}, z, h, 1), true},
        {"z: rim vertex, C_z+e", c({v0 + h, v1, Rational(3, 2) + e}, z, h, 1), false},
        {"z: rim vertex, h-e", c({v0 + h, v1, Rational(3, 2)}, z, h, 1 - e), false},
        // Axis (3,4,0) ∥ a1, in the slanted face's direction: C = a0 + r·n, r = 1/4, side tangent.
        {"a1: side on slanted face", c({Rational(6, 5), Rational(-3, 20), 0}, {3, 4, 0}, q, 1), true},
        {"a1: slanted face, r-e", c({Rational(6, 5), Rational(-3, 20), 0}, {3, 4, 0}, q - e, 1), false},
        // Irrational unit axis (1,1,1)/√3 through the centre: certainly inside.
        {"(1,1,1): through centre", c({0, 0, 0}, {1, 1, 1}, 0, 0), true},
        // Axis (1,2,2), u = (1,2,2)/3: the box's maximum of u·X is u·(a0 + a1 + a2) = 26/15, only at the
        // vertex (8/5,4/5,1). The lower end plane there: C = (26/15)u + (h/2)u with h = 6.
        {"(1,2,2): end plane at vertex", c({Rational(71, 45), Rational(142, 45), Rational(142, 45)}, {1, 2, 2}, 5, 6),
         true},
        {"(1,2,2): end plane, C_x+e", c({Rational(71, 45) + e, Rational(142, 45), Rational(142, 45)}, {1, 2, 2}, 5, 6),
         false},
        {"(1,2,2): end plane, h-e", c({Rational(71, 45), Rational(142, 45), Rational(142, 45)}, {1, 2, 2}, 5, 6 - e),
         false},
    };
}

TEST(ConvexHullParallelepiped, ShearedHandCases) {
    const std::array<std::array<int, 3>, 6> perms{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    const Vec3<Rational> shift{Rational(-7, 3), Rational(5, 11), 13};
    for (const ShearedHand& hc : sheared_cases()) {
        // Invariances: order of the half-edges, their signs, the axis sign, a translation of both.
        for (const auto& perm : perms)
            for (int signs = 0; signs < 8; ++signs)
                for (bool flip : {false, true}) {
                    Parallelepiped<Rational> p;
                    p.center = sheared.center + shift;
                    for (int i = 0; i < 3; ++i)
                        p.half_edges[i] = (signs >> i) & 1 ? -sheared.half_edges[perm[i]] : sheared.half_edges[perm[i]];
                    Cylinder<Rational> c = hc.cyl;
                    c.center = c.center + shift;
                    if (flip) c.axis = -c.axis;
                    ASSERT_EQ(hull_qf(p, c), hc.expected) << hc.name << "\n  " << str(p) << "\n  " << str(c);
                    if (perm == perms[0] && signs == 0) {
                        // The oracle agrees (it takes axes and extents: extents 1).
                        const OrientedBox<Rational> ob{p.center, p.half_edges, {1, 1, 1}};
                        ASSERT_EQ(boxcyl::oracle::intersects(ob, c), hc.expected) << "oracle: " << hc.name;
                        if (const auto len = rational_sqrt(dot(c.axis, c.axis))) {
                            const UnitCylinder<Rational> u{c.center, Rational(1 / *len) * c.axis, c.radius, Rational(c.height / 2)};
                            ASSERT_EQ(convex_hull(p, u), hc.expected) << "Rational: " << hc.name;
                        }
                    }
                }
    }
}

// float/double on the sheared box, clear-cut versions (r ± 0.1) of the hand cases.
template <class T>
bool sheared_fp(const Vec3<double>& center, const Vec3<double>& axis, double r, double h) {
    auto v = [](const Vec3<double>& x) { return Vec3<T>{T(x[0]), T(x[1]), T(x[2])}; };
    const Parallelepiped<T> p{{T(0), T(0), T(0)}, {Vec3<T>{1, 0, 0}, Vec3<T>{T(0.6), T(0.8), 0}, Vec3<T>{0, 0, 1}}};
    return convex_hull(p, boxcyl::to_unit(Cylinder<T>{v(center), v(axis), T(r), T(h)}));
}

TEST(ConvexHullParallelepiped, FloatAndDoubleClearCut) {
    struct C {
        Vec3<double> center, axis;
        double r, h;
        bool expected;
    };
    const std::vector<C> cases{
        {{1.4, -0.3, 0}, {0, 0, 1}, 0.6, 1, true},   {{1.4, -0.3, 0}, {0, 0, 1}, 0.4, 1, false},
        {{2.1, 0.8, 0}, {0, 0, 1}, 0.6, 1, true},    {{2.1, 0.8, 0}, {0, 0, 1}, 0.4, 1, false},
        {{2.1, 0.8, 1.5}, {0, 0, -2}, 0.6, 1.2, true}, {{2.1, 0.8, 1.5}, {0, 0, 1}, 0.6, 0.8, false},
        {{1.2, -0.15, 0}, {3, 4, 0}, 0.35, 1, true}, {{1.2, -0.15, 0}, {3, 4, 0}, 0.15, 1, false},
        {{0, 0, 0}, {1, 1, 1}, 0, 0, true},           {{5, 5, 5}, {1, 1, 1}, 1, 1, false},
    };
    for (const C& c : cases) {
        const Cylinder<Rational> exact{boxcyl::to_exact(c.center), boxcyl::to_exact(c.axis), boxcyl::to_rational(c.r),
                                       boxcyl::to_rational(c.h)};
        const OrientedBox<Rational> ob{sheared.center, sheared.half_edges, {1, 1, 1}};
        ASSERT_EQ(boxcyl::oracle::intersects(ob, exact), c.expected) << str(exact);
        EXPECT_EQ(sheared_fp<double>(c.center, c.axis, c.r, c.h), c.expected) << "double " << str(exact);
        EXPECT_EQ(sheared_fp<float>(c.center, c.axis, c.r, c.h), c.expected) << "float " << str(exact);
    }
}

// Random sheared (non-orthogonal, linearly independent) parallelepipeds with small rational entries
// against the oracle (which takes any independent axes). Rational entries with small denominators make
// exact ties (touching, vertices on slab planes, collinear projections) common.
TEST(ConvexHullParallelepiped, RandomShearedAgreesWithOracle) {
    constexpr std::uint64_t seed = 0x5eed'5bea'0003ULL;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> small(-4, 4), coord(-12, 12), positive(0, 12), pick(0, 9);
    auto rat = [](int v, int den) -> Rational { return Rational(v) / den; };
    int hits = 0, failures = 0, evaluated = 0;
    const int n = 400;
    while (evaluated < n) {
        OrientedBox<Rational> b;
        for (int i = 0; i < 3; ++i) b.axes[i] = {rat(small(rng), 2), rat(small(rng), 2), rat(small(rng), 2)};
        if (sgn(dot(b.axes[0], cross(b.axes[1], b.axes[2]))) == 0) continue;  // the oracle needs independence
        for (int k = 0; k < 3; ++k) b.extents[k] = pick(rng) == 0 ? Rational(0) : rat(positive(rng), 4);
        b.center = {rat(coord(rng), 4), rat(coord(rng), 4), rat(coord(rng), 4)};
        Cylinder<Rational> c;
        for (int k = 0; k < 3; ++k) c.center[k] = b.center[k] + rat(coord(rng), 2);
        do {
            for (int k = 0; k < 3; ++k) c.axis[k] = pick(rng) < 3 ? Rational(0) : rat(small(rng), 1);
        } while (sgn(dot(c.axis, c.axis)) == 0);
        c.radius = pick(rng) == 0 ? Rational(0) : rat(positive(rng), 4);
        c.height = pick(rng) == 0 ? Rational(0) : rat(positive(rng), 2);
        const Parallelepiped<Rational> p = algo::as_parallelepiped(b);
        const bool o = boxcyl::oracle::intersects(b, c);
        const bool h = hull_qf(p, c);
        ++evaluated;
        hits += o;
        if (o != h && ++failures <= 20)
            ADD_FAILURE() << "seed " << seed << " case #" << evaluated - 1 << ": oracle " << o << ", hull " << h << "\n  "
                          << str(p) << "\n  " << str(c);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, n / 10);
    EXPECT_LT(hits, n - n / 10);
}

// Linearly dependent and zero half-edges: the convex-hull method works in ξ-space, so they need no special
// case. Each is compared with the oracle on the same solid written with independent axes: [−a, a] + [−a, a] =
// [−2a, 2a] (a Minkowski sum of parallel segments), etc.; the third axis c only completes the basis.
TEST(ConvexHullParallelepiped, DependentAndZeroHalfEdges) {
    constexpr std::uint64_t seed = 0x5eed'de9e'0003ULL;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> small(-4, 4), coord(-12, 12), positive(0, 12), pick(0, 9);
    auto rat = [](int v, int den) -> Rational { return Rational(v) / den; };
    const Vec3<Rational> zero{0, 0, 0};
    int hits = 0, failures = 0, evaluated = 0;
    const int n = 300;
    while (evaluated < n) {
        Vec3<Rational> a, b, c3;
        for (int k = 0; k < 3; ++k) a[k] = rat(small(rng), 2), b[k] = rat(small(rng), 2), c3[k] = rat(small(rng), 2);
        if (sgn(dot(a, cross(b, c3))) == 0) continue;
        const Vec3<Rational> K{rat(coord(rng), 4), rat(coord(rng), 4), rat(coord(rng), 4)};
        // The degenerate parallelepiped and the same solid as {a, b, c3} with extents.
        Parallelepiped<Rational> p{K, {}};
        Vec3<Rational> ext;
        switch (evaluated % 5) {
            case 0: p.half_edges = {a, a, b}, ext = {2, 1, 0}; break;
            case 1: p.half_edges = {a, Rational(-2) * a, b}, ext = {3, 1, 0}; break;
            case 2: p.half_edges = {Rational(2) * a, a, -a}, ext = {4, 0, 0}; break;
            case 3: p.half_edges = {zero, b, a}, ext = {1, 1, 0}; break;
            case 4: p.half_edges = {zero, zero, zero}, ext = {0, 0, 0}; break;
        }
        const OrientedBox<Rational> ob{K, {a, b, c3}, ext};
        Cylinder<Rational> c;
        for (int k = 0; k < 3; ++k) c.center[k] = K[k] + rat(coord(rng), evaluated % 5 == 4 ? 8 : 2);
        do {
            for (int k = 0; k < 3; ++k) c.axis[k] = pick(rng) < 3 ? Rational(0) : rat(small(rng), 1);
        } while (sgn(dot(c.axis, c.axis)) == 0);
        c.radius = rat(positive(rng), 4);
        c.height = rat(positive(rng), 2);
        const bool o = boxcyl::oracle::intersects(ob, c);
        const bool h = hull_qf(p, c);
        ++evaluated;
        hits += o;
        if (o != h && ++failures <= 20)
            ADD_FAILURE() << "seed " << seed << " case #" << evaluated - 1 << ": oracle " << o << ", hull " << h << "\n  "
                          << str(p) << "\n  " << str(c);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, n / 10);
    EXPECT_LT(hits, n - n / 10);
}

// ---------------------------------------------------------------------------------------------
// Randomized exact differential against the oracle, on generated double inputs.

constexpr std::uint64_t kRandomSeed = 0x5eed'3c0f'fee0'0003ULL;
constexpr int kRandomOriented = 3000;  // oriented cases from one generator stream ...
constexpr int kRandomOtherCap = 500;   // ... and the first 500 aligned and 500 canonical ones met on the way
constexpr std::uint64_t kBoundarySeed = 0x5eed'b0d7'0003ULL;
constexpr int kBoundaryOrientedPairs = 150;
constexpr int kBoundaryOtherPairs = 50;

struct KindTally {
    int cases = 0, hits = 0, failures = 0, double_world = 0, double_reduced = 0;
};

const char* kind_name(BoxKind k) {
    switch (k) {
        case BoxKind::aligned: return "aligned";
        case BoxKind::oriented: return "oriented";
        case BoxKind::canonical: return "canonical";
    }
    return "?";
}

// Checks one case exactly (and, for aligned boxes, through the aligned-box reduction too), counts the double
// disagreements (world frame and through the reductions). `where` locates it for a failure message.
void check_exact(KindTally& t, const Case& c, bool want, const std::string& where) {
    ++t.cases;
    t.hits += want;
    const bool got = hull_exact(c);
    if (got != want && ++t.failures <= 10)
        ADD_FAILURE() << where << ": oracle " << want << ", hull (world frame) " << got << "\n  " << describe(c);
    if (c.kind == BoxKind::aligned) {
        const bool reduced = hull_qf_reduced(boxcyl::to_exact(c.aligned), boxcyl::to_exact(c.cylinder));
        if (reduced != want && ++t.failures <= 10)
            ADD_FAILURE() << where << ": oracle " << want << ", hull (aligned-box reduction) " << reduced << "\n  " << describe(c);
    }
    t.double_world += hull_double(c) != want;
    t.double_reduced += hull_double_reduced(c) != want;
}

void print_tallies(const char* label, std::uint64_t seed, const std::array<KindTally, 3>& tallies) {
    for (int k = 0; k < 3; ++k) {
        const KindTally& t = tallies[k];
        if (t.cases == 0) continue;
        std::printf("[ convex_hull ] %s seed %llu, %-9s: %5d exact cases (%5d hits), exact failures %d; double "
                    "disagreements: world frame %d, via canonical reduction %d\n",
                    label, static_cast<unsigned long long>(seed), kind_name(static_cast<BoxKind>(k)), t.cases, t.hits,
                    t.failures, t.double_world, t.double_reduced);
    }
}

TEST(ConvexHullRandom, ExactAgreesWithOracle) {
    boxcyl::testing::CaseGenerator gen(kRandomSeed);
    std::array<KindTally, 3> tallies{};
    KindTally& oriented = tallies[static_cast<int>(BoxKind::oriented)];
    for (int index = 0; oriented.cases < kRandomOriented; ++index) {
        const Case c = gen.next();
        if (c.kind != BoxKind::oriented && tallies[static_cast<int>(c.kind)].cases >= kRandomOtherCap) continue;
        check_exact(tallies[static_cast<int>(c.kind)], c, boxcyl::testing::oracle_answer(c),
                    "seed " + std::to_string(kRandomSeed) + " case #" + std::to_string(index));
    }
    print_tallies("random", kRandomSeed, tallies);
    for (const KindTally& t : tallies) {
        EXPECT_EQ(t.failures, 0);
        EXPECT_GT(t.hits, t.cases / 10);
        EXPECT_LT(t.hits, t.cases - t.cases / 10);
    }
    EXPECT_EQ(tallies[static_cast<int>(BoxKind::aligned)].cases, kRandomOtherCap);
    EXPECT_EQ(tallies[static_cast<int>(BoxKind::canonical)].cases, kRandomOtherCap);
}

// One-ulp boundary pairs (boundary_pair: two inputs one ulp apart in one parameter, opposite exact
// answers). `oriented` selects oriented starts or the other kinds: the generator is peeked (it is a
// value) so that only the wanted kind pays for the bisection.
void boundary_pairs(bool oriented, int wanted, const char* label) {
    boxcyl::testing::CaseGenerator gen(kBoundarySeed);
    std::array<KindTally, 3> tallies{};
    int pairs = 0;
    for (int attempt = 0; pairs < wanted; ++attempt) {
        if ((peek_kind(gen) == BoxKind::oriented) != oriented) {
            gen.next();
            continue;
        }
        Case first, second;
        boxcyl::testing::Parameter which{};
        if (!boxcyl::testing::boundary_pair(gen, first, second, which)) continue;
        ++pairs;
        const bool o1 = boxcyl::testing::oracle_answer(first), o2 = boxcyl::testing::oracle_answer(second);
        EXPECT_NE(o1, o2) << "boundary_pair gave equal answers: " << describe(first);
        const std::string where = "seed " + std::to_string(kBoundarySeed) + " attempt " + std::to_string(attempt) +
                                  " (" + boxcyl::testing::name(which) + ")";
        check_exact(tallies[static_cast<int>(first.kind)], first, o1, where + " first");
        check_exact(tallies[static_cast<int>(second.kind)], second, o2, where + " second");
    }
    print_tallies(label, kBoundarySeed, tallies);
    std::printf("[ convex_hull ] %s seed %llu: %d one-ulp pairs\n", label, static_cast<unsigned long long>(kBoundarySeed),
                pairs);
    int cases = 0;
    for (const KindTally& t : tallies) {
        EXPECT_EQ(t.failures, 0);
        cases += t.cases;
    }
    EXPECT_EQ(cases, 2 * wanted);
}

TEST(ConvexHullRandom, BoundaryPairsOrientedExact) { boundary_pairs(true, kBoundaryOrientedPairs, "boundary"); }
TEST(ConvexHullRandom, BoundaryPairsAlignedCanonicalExact) { boundary_pairs(false, kBoundaryOtherPairs, "boundary"); }

// Regression: an oriented start from the boundary seed with a single 1e-299 axis component. Its
// rotation made boundary_pair throw (|a|² underflowed to 0, the rotated axis was NaN) until cases.hpp
// prescaled it. With the axis as given, the convex-hull method must be exact, and double must not go NaN
// (to_unit prescales by a power of two); the answers here are clear-cut.
TEST(ConvexHullRandom, RegressionTinyAxisOrientedBox) {
    Case c{BoxKind::oriented, {},
           OrientedBox<double>{{-0x1.ebe196806242p-21, 0x1.d712b72f00a48p-17, 0x1.42ecfad47eb18p-19},
                               {Vec3<double>{0x1.93ade2517e9cp-1, 0x1.ee0ce96564858p-2, 0x1.86b86f49ca264p-2},
                                Vec3<double>{0x1.3a58d0f5a46ap-1, -0x1.4f82c7d6546dcp-1, -0x1.c29c4c1f205d6p-2},
                                Vec3<double>{0x1.350b27158a988p-5, 0x1.2994f929596b7p-1, -0x1.a03131c8a419cp-1}},
                               {0x1.63f61246d7a8dp-18, 0x1.94b5f54d96e2dp-18, 0x1.44c98b28ce5e2p-22}},
           {},
           Cylinder<double>{{0x1.5d9a394c89aa7p-19, 0x1.17bc23ca9a63p-17, -0x1.ab788aab454cp-24},
                            {0x0p+0, 0x1.56e1fc2f8f359p-994, 0x0p+0},
                            0x1.b0276fd24cd3ep-19,
                            0x0p+0}};
    for (const double r : {c.cylinder.radius, 0.0, 1e-3, 1e-7}) {
        c.cylinder.radius = r;
        const bool o = boxcyl::testing::oracle_answer(c);
        EXPECT_EQ(hull_exact(c), o) << describe(c);
        EXPECT_EQ(hull_double(c), o) << "double (clear-cut here): " << describe(c);
    }
}

// Oriented boxes with exactly orthonormal rational axes: the rotation of an integer quaternion
// (a, b, c, d), entries integer/(a²+b²+c²+d²). Built in Rational directly, so the oriented-box reduction is
// exact and the world-frame path and the reduced path must both agree with the oracle.
std::array<Vec3<Rational>, 3> rational_rotation(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> q(-6, 6);
    int a, b, c, d;
    do {
        a = q(rng), b = q(rng), c = q(rng), d = q(rng);
    } while (a == 0 && b == 0 && c == 0 && d == 0);
    const Rational n(a * a + b * b + c * c + d * d);
    auto e = [&](int v) -> Rational { return Rational(v) / n; };  // not an expression template
    return {Vec3<Rational>{e(a * a + b * b - c * c - d * d), e(2 * (b * c + a * d)), e(2 * (b * d - a * c))},
            Vec3<Rational>{e(2 * (b * c - a * d)), e(a * a - b * b + c * c - d * d), e(2 * (c * d + a * b))},
            Vec3<Rational>{e(2 * (b * d + a * c)), e(2 * (c * d - a * b)), e(a * a - b * b - c * c + d * d)}};
}

TEST(ConvexHullRandom, RationalOrientedBoxes) {
    constexpr std::uint64_t seed = 0x5eed'0a1e'0003ULL;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> small(-40, 40), positive(0, 40), pick(0, 9);
    auto rat = [](int v, int den) -> Rational { return Rational(v) / den; };  // canonical
    int hits = 0, failures = 0;
    const int n = 300;
    for (int i = 0; i < n; ++i) {
        OrientedBox<Rational> b;
        b.axes = rational_rotation(rng);
        ASSERT_TRUE(exactly_orthonormal(b));
        b.center = {rat(small(rng), 8), rat(small(rng), 8), rat(small(rng), 8)};
        for (int k = 0; k < 3; ++k) b.extents[k] = pick(rng) == 0 ? Rational(0) : rat(positive(rng), 16);
        Cylinder<Rational> c;
        for (int k = 0; k < 3; ++k) c.center[k] = b.center[k] + rat(small(rng), 10);
        do {
            for (int k = 0; k < 3; ++k) c.axis[k] = pick(rng) < 2 ? Rational(0) : rat(small(rng), 7);
        } while (sgn(dot(c.axis, c.axis)) == 0);
        c.radius = pick(rng) == 0 ? Rational(0) : rat(positive(rng), 16);
        c.height = pick(rng) == 0 ? Rational(0) : rat(positive(rng), 8);
        const bool o = boxcyl::oracle::intersects(b, c);
        const bool reduced = hull_qf_reduced(b, c);
        const bool world = hull_qf(algo::as_parallelepiped(b), c);
        hits += o;
        if ((o != reduced || o != world) && ++failures <= 20)
            ADD_FAILURE() << "seed " << seed << " case #" << i << ": oracle " << o << ", hull reduced " << reduced
                          << ", hull world " << world << "\n  box center " << str(b.center) << " axes " << str(b.axes[0])
                          << " " << str(b.axes[1]) << " " << str(b.axes[2]) << " extents " << str(b.extents) << "\n  "
                          << str(c);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, n / 10);
    EXPECT_LT(hits, n - n / 10);
}

}  // namespace
