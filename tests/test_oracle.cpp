// The oracle is the judge of everything else, so it is checked three ways: hand cases with exact
// expected answers (each touching case with its one-ulp neighbour), exact invariances (rigid motions
// with rational rotations, reflections, permutations, D → −D, axis scaling), and agreement with an
// independent numeric method on cases that are not near touching.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "boxcyl/oracle/oracle.hpp"
#include "support/cases.hpp"
#include "support/numeric.hpp"

namespace boxcyl {
namespace {

using testing::BoxKind;
using testing::Case;
using testing::CaseGenerator;
using testing::describe;

const AlignedBox<double> unit_box{{-1, -1, -1}, {1, 1, 1}};

double below(double x) { return std::nextafter(x, -INFINITY); }
double above(double x) { return std::nextafter(x, INFINITY); }

bool hit(const Cylinder<double>& c, const AlignedBox<double>& b = unit_box) { return oracle::intersects(b, c); }

TEST(OracleHand, SideTouchesFace) {
    EXPECT_TRUE(hit({{3, 0, 0}, {0, 0, 1}, 2, 1}));
    EXPECT_FALSE(hit({{3, 0, 0}, {0, 0, 1}, below(2), 1}));
    EXPECT_FALSE(hit({{above(3), 0, 0}, {0, 0, 1}, 2, 1}));
}

TEST(OracleHand, SideTouchesEdge) {
    // Axis ∥ z through (4, 5): distance to the edge x = y = 1 is |(3, 4)| = 5.
    EXPECT_TRUE(hit({{4, 5, 0}, {0, 0, 7}, 5, 1}));
    EXPECT_FALSE(hit({{4, 5, 0}, {0, 0, 7}, below(5), 1}));
}

TEST(OracleHand, SideTouchesVertex) {
    // Axis (1,−1,0) through (3,3,2) = (1,1,1) + (2,2,1), with n = (2,2,1) ⊥ axis and |n| = 3. Along n̂ the
    // box reaches at most n̂·(1,1,1) = 5/3, only at the vertex (1,1,1); the line sits at n̂·(3,3,2) = 14/3;
    // along m = axis × n = (−1,−1,4) line and vertex coincide (m·(3,3,2) = m·(1,1,1) = 2). So the
    // distance is exactly 3, attained only at the vertex.
    EXPECT_TRUE(hit({{3, 3, 2}, {1, -1, 0}, 3, 10}));
    EXPECT_FALSE(hit({{3, 3, 2}, {1, -1, 0}, below(3), 10}));
    EXPECT_FALSE(hit({{3, 3, above(2)}, {1, -1, 0}, 3, 10}));
}

TEST(OracleHand, EndDiskTouchesFace) {
    EXPECT_TRUE(hit({{0, 0, 2}, {0, 0, 1}, 0.5, 2}));
    EXPECT_FALSE(hit({{0, 0, above(2)}, {0, 0, 1}, 0.5, 2}));
    EXPECT_FALSE(hit({{0, 0, 2}, {0, 0, 1}, 0.5, below(2)}));
    // The same with a non-unit, reversed axis.
    EXPECT_TRUE(hit({{0, 0, 2}, {0, 0, -1e-300}, 0.5, 2}));
    EXPECT_FALSE(hit({{0, 0, 2}, {0, 0, -1e-300}, 0.5, below(2)}));
}

TEST(OracleHand, EndDiskTouchesEdgeAndVertex) {
    // Axis ∥ x, bottom disk in the plane x = 1, centre (1, 0, 1 + r): its lowest point is on the edge.
    EXPECT_TRUE(hit({{2, 0, 1.5}, {1, 0, 0}, 0.5, 2}));
    EXPECT_FALSE(hit({{2, 0, above(1.5)}, {1, 0, 0}, 0.5, 2}));
    // Disk in the plane z = 1 centred at (1+3, 1+4, 1) with r = 5 touches only the vertex (1, 1, 1).
    EXPECT_TRUE(hit({{4, 5, 2}, {0, 0, 1}, 5, 2}));
    EXPECT_FALSE(hit({{4, 5, 2}, {0, 0, 1}, below(5), 2}));
    EXPECT_FALSE(hit({{4, 5, above(2)}, {0, 0, 1}, 5, 2}));
}

TEST(OracleHand, RimTouchesEdge) {
    // Axis ∥ z, h = 2, centre (6, 0, 2): the bottom rim is the circle of radius 5 about (6, 0, 1) in the
    // plane z = 1, passing through (1, 0, 1) on the top-face edge x = 1, z = 1.
    EXPECT_TRUE(hit({{6, 0, 2}, {0, 0, 1}, 5, 2}));
    EXPECT_FALSE(hit({{6, 0, 2}, {0, 0, 1}, below(5), 2}));
    EXPECT_FALSE(hit({{6, 0, above(2)}, {0, 0, 1}, 5, 2}));
}

TEST(OracleHand, AxisInFaceAndContainment) {
    EXPECT_TRUE(hit({{1, 0, 0}, {0, 0, 1}, 0, 0.5}));          // a segment lying in the face x = 1
    EXPECT_FALSE(hit({{above(1), 0, 0}, {0, 0, 1}, 0, 0.5}));
    EXPECT_TRUE(hit({{0, 0, 0}, {1, 2, 3}, 100, 100}));       // box inside the cylinder
    EXPECT_TRUE(hit({{0.1, 0.2, 0.3}, {1, 2, 3}, 0.01, 0.01}));  // cylinder inside the box
    EXPECT_TRUE(hit({{0.5, 0.5, 0.5}, {1, 1, 1}, 0, 0}));       // a point inside
    EXPECT_TRUE(hit({{1, 1, 1}, {1, 1, 1}, 0, 0}));             // a point on the vertex
    EXPECT_FALSE(hit({{1, 1, above(1)}, {1, 1, 1}, 0, 0}));
}

TEST(OracleHand, DegenerateBoxes) {
    const AlignedBox<double> point{{1, 2, 3}, {1, 2, 3}};
    EXPECT_TRUE(hit({{1, 2, 0}, {0, 0, 1}, 0, 6}, point));  // segment z ∈ [−3, 3] reaches z = 3
    EXPECT_FALSE(hit({{1, 2, 0}, {0, 0, 1}, 0, below(6)}, point));
    const AlignedBox<double> flat{{-1, -1, 0}, {1, 1, 0}};
    EXPECT_TRUE(hit({{3, 0, 0}, {0, 1, 0}, 2, 1}, flat));
    EXPECT_FALSE(hit({{3, 0, 0}, {0, 1, 0}, below(2), 1}, flat));
    EXPECT_TRUE(hit({{0, 0, 5}, {1, 0, 0}, 5, 0}, flat));     // a disk touching the flat square
    EXPECT_FALSE(hit({{0, 0, 5}, {1, 0, 0}, below(5), 0}, flat));
}

TEST(OracleHand, TiltedSlabCut) {
    // Axis (1,1,1) through (3,3,3): the slab reaches the box only if h/2 ≥ distance from C to the plane
    // x+y+z = 3 through the vertex (1,1,1), i.e. h/2 ≥ 6/√3 = 2√3 ⇔ h² ≥ 48. A long thin cylinder.
    EXPECT_FALSE(hit({{3, 3, 3}, {1, 1, 1}, 1e-3, 6.928203230275509}));   // 6.9282032302755092 < 4√3
    EXPECT_TRUE(hit({{3, 3, 3}, {1, 1, 1}, 1e-3, 6.9282032302755097}));   // next double above 4√3
}

// ---- Invariances, in exact rationals ----

using RCyl = Cylinder<Rational>;
using RBox = OrientedBox<Rational>;

// The rational rotation from the Pythagorean quadruple-like quaternion (1, 2, 2, 4)/5 — entries with
// denominator 25, exactly orthonormal.
std::array<Vec3<Rational>, 3> rational_rotation() {
    const Rational w(1), x(2), y(2), z(4), n2(25);
    return {Vec3<Rational>{(w * w + x * x - y * y - z * z) / n2, 2 * (x * y + w * z) / n2, 2 * (x * z - w * y) / n2},
            Vec3<Rational>{2 * (x * y - w * z) / n2, (w * w - x * x + y * y - z * z) / n2, 2 * (y * z + w * x) / n2},
            Vec3<Rational>{2 * (x * z + w * y) / n2, 2 * (y * z - w * x) / n2, (w * w - x * x - y * y + z * z) / n2}};
}
Vec3<Rational> rotate(const std::array<Vec3<Rational>, 3>& R, const Vec3<Rational>& v) {
    // Rows of the matrix are R[0..2]ᵀ columns: v' = Σ vᵢ R[i] (R[i] is the image of eᵢ).
    return v[0] * R[0] + v[1] * R[1] + v[2] * R[2];
}

TEST(OracleInvariance, RationalRotationIsOrthonormal) {
    const auto R = rational_rotation();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_EQ(dot(R[i], R[j]), Rational(i == j ? 1 : 0));
}

TEST(OracleInvariance, RigidMotionsReflectionsPermutationsAxisSign) {
    CaseGenerator gen(20261121);
    const auto R = rational_rotation();
    const Vec3<Rational> shift{Rational(1, 3), Rational(-7, 5), Rational(22, 7)};
    int hits = 0;
    const int n = 600;
    for (int it = 0; it < n; ++it) {
        Case c = gen.next();
        const bool want = testing::oracle_answer(c);
        hits += want;
        RBox box = c.kind == BoxKind::aligned    ? as_oriented_box(to_exact(c.aligned))
                   : c.kind == BoxKind::oriented ? to_exact(c.oriented)
                                                 : as_oriented_box(to_exact(c.canonical));
        const RCyl cyl = to_exact(c.cylinder);
        SCOPED_TRACE(describe(c));

        // Rigid motion: X ↦ R X + shift applied to both shapes.
        RBox mb = box;
        RCyl mc = cyl;
        mb.center = rotate(R, box.center) + shift;
        for (int i = 0; i < 3; ++i) mb.axes[i] = rotate(R, box.axes[i]);
        mc.center = rotate(R, cyl.center) + shift;
        mc.axis = rotate(R, cyl.axis);
        EXPECT_EQ(oracle::intersects(mb, mc), want) << "rigid motion";

        // Reflection of x: a left-handed frame is fine for the parallelepiped.
        RBox rb = box;
        RCyl rc = cyl;
        rb.center[0] = -rb.center[0];
        for (int i = 0; i < 3; ++i) rb.axes[i][0] = -rb.axes[i][0];
        rc.center[0] = -rc.center[0];
        rc.axis[0] = -rc.axis[0];
        EXPECT_EQ(oracle::intersects(rb, rc), want) << "reflection";

        // Cyclic permutation of coordinates.
        auto perm = [](const Vec3<Rational>& v) { return Vec3<Rational>{v[1], v[2], v[0]}; };
        RBox pb = box;
        RCyl pc = cyl;
        pb.center = perm(box.center);
        for (int i = 0; i < 3; ++i) pb.axes[i] = perm(box.axes[i]);
        pc.center = perm(cyl.center);
        pc.axis = perm(cyl.axis);
        EXPECT_EQ(oracle::intersects(pb, pc), want) << "permutation";

        // D → −D, D → 3D/7, and the box axes reversed / reordered.
        RCyl nc = cyl;
        nc.axis = -cyl.axis;
        EXPECT_EQ(oracle::intersects(box, nc), want) << "D -> -D";
        RCyl sc = cyl;
        sc.axis = Rational(3, 7) * cyl.axis;
        EXPECT_EQ(oracle::intersects(box, sc), want) << "D -> 3D/7";
        RBox ob = box;
        std::swap(ob.axes[0], ob.axes[2]);
        std::swap(ob.extents[0], ob.extents[2]);
        ob.axes[1] = -ob.axes[1];
        EXPECT_EQ(oracle::intersects(ob, cyl), want) << "box axes reordered";
    }
    // The generator must be representative: neither almost all hits nor almost all misses.
    EXPECT_GT(hits, n / 5);
    EXPECT_LT(hits, n * 4 / 5);
}

// ---- Agreement with the independent numeric method away from touching ----

TEST(OracleNumeric, AgreesWithProjectedGradientAwayFromTouching) {
    const std::uint64_t seed = 77;
    CaseGenerator gen(seed);
    int checked_true = 0, checked_false = 0;
    for (int it = 0; it < 1500; ++it) {
        const Case c = gen.next();
        // The numeric method assumes a well-scaled axis; skip subnormal directions (covered elsewhere).
        const double S = testing::problem_scale(c);
        const testing::LD dist = testing::numeric_distance(c, c.cylinder.radius, c.cylinder.height);
        const bool want = testing::oracle_answer(c);
        if (dist > 1e-7L * S) {
            ++checked_false;
            EXPECT_FALSE(want) << "seed " << seed << " case " << it << " numeric distance " << double(dist)
                               << "\n" << describe(c);
        } else {
            // Clearly intersecting: the cylinder shrunk by 1e-4·S still touches numerically.
            const testing::LD shrunk = testing::numeric_distance(
                c, std::max(0.0, c.cylinder.radius - 1e-4 * S), std::max(0.0, c.cylinder.height - 2e-4 * S));
            if (shrunk < 1e-12L * S && c.cylinder.radius > 1e-4 * S && c.cylinder.height > 2e-4 * S) {
                ++checked_true;
                EXPECT_TRUE(want) << "seed " << seed << " case " << it << "\n" << describe(c);
            }
        }
    }
    std::printf("numeric cross-check: %d clearly separate, %d clearly intersecting\n", checked_false, checked_true);
    EXPECT_GT(checked_false, 300);
    EXPECT_GT(checked_true, 100);
}

TEST(OraclePreconditions, RejectsWhatItCannotDecide) {
    EXPECT_THROW(oracle::intersects(unit_box, Cylinder<double>{{0, 0, 0}, {0, 0, 0}, 1, 1}), std::invalid_argument);
    RBox flat = as_oriented_box(to_exact(unit_box));
    flat.axes[2] = flat.axes[0];
    EXPECT_THROW(oracle::intersects(flat, to_exact(Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 1})), std::invalid_argument);
}

}  // namespace
}  // namespace boxcyl
