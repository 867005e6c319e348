// Poses and sizes (geometry/pose.hpp), one test per row of the README's peer table: each peer's
// documented convention is written into the case, built with the boxcyl call the table names, and
// checked on probes whose answers the usual mistakes (full vs half sizes, rows vs columns, quaternion
// order, the cylinder's local axis) change — each test also builds the mistaken shape and shows that
// its answer differs.
#include <gmpxx.h>  // exact squares: the heights of cylinder_between
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "boxcyl/boxcyl.hpp"

namespace boxcyl {
namespace {

using V = Vec3<double>;

// A rotation by θ about z with cos θ = 3/5, sin θ = 4/5: local x → (0.6, 0.8, 0), local y → (−0.8, 0.6, 0).
// Written row by row, as the peers print it; its transpose turns the other way.
const RotationMatrix<double> R{{{{0.6, -0.8, 0}, {0.8, 0.6, 0}, {0, 0, 1}}}};
const RotationMatrix<double> R_transposed{{{{0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1}}}};
// The same rotation as a unit quaternion: cos(θ/2) = 2/√5, sin(θ/2) = 1/√5 about z.
const double qw = 2 / std::sqrt(5.0), qz = 1 / std::sqrt(5.0);
const V origin{1, 2, 3};

// A thin probe cylinder at a point, and a tiny probe box at a point.
Cylinder<double> probe_point(const V& p) { return {p, {0, 0, 1}, 0.01, 0.02}; }
AlignedBox<double> probe_box(const V& p) { return {{p[0] - 0.01, p[1] - 0.01, p[2] - 0.01}, {p[0] + 0.01, p[1] + 0.01, p[2] + 0.01}}; }
V local(const RotationMatrix<double>& r, double x, double y, double z) {
    return origin + x * r.column(0) + y * r.column(1) + z * r.column(2);
}

// A box 10 × 1 × 1 (half 5 × 0.5 × 0.5) in pose (origin, R): probes at local x = 4 (inside) and 7
// (outside; inside a box read twice as large); at 4 along the transposed rotation's x (outside).
void expect_box_10_1_1(const OrientedBox<double>& b) {
    ASSERT_TRUE(validate(b).ok()) << validate(b).message();
    EXPECT_TRUE(intersects(b, probe_point(local(R, 4, 0, 0))));
    EXPECT_FALSE(intersects(b, probe_point(local(R, 7, 0, 0))));
    EXPECT_FALSE(intersects(b, probe_point(local(R_transposed, 4, 0, 0))));
}
bool box_answers_as_10_1_1(const OrientedBox<double>& b) {
    return intersects(b, probe_point(local(R, 4, 0, 0))) && !intersects(b, probe_point(local(R, 7, 0, 0))) &&
           !intersects(b, probe_point(local(R_transposed, 4, 0, 0)));
}
// A cylinder of radius 0.2 and full length 2 along the pose's local `axis` (0 = x, 1 = y, 2 = z): a
// probe at local 0.9 along the axis is inside, at 1.5 outside (inside when the length is misread as
// half), and 0.9 along another local axis is outside.
void expect_cylinder_r02_len2(const Cylinder<double>& c, int axis) {
    ASSERT_TRUE(validate(c).ok()) << validate(c).message();
    double at[3] = {0, 0, 0};
    at[axis] = 0.9;
    EXPECT_TRUE(intersects(probe_box(local(R, at[0], at[1], at[2])), c));
    at[axis] = 1.5;
    EXPECT_FALSE(intersects(probe_box(local(R, at[0], at[1], at[2])), c));
    double off[3] = {0, 0, 0};
    off[(axis + 1) % 3] = 0.9;
    EXPECT_FALSE(intersects(probe_box(local(R, off[0], off[1], off[2])), c));
}
bool cylinder_answers_as_r02_len2(const Cylinder<double>& c, int axis) {
    double at[3] = {0, 0, 0}, far[3] = {0, 0, 0}, off[3] = {0, 0, 0};
    at[axis] = 0.9, far[axis] = 1.5, off[(axis + 1) % 3] = 0.9;
    return intersects(probe_box(local(R, at[0], at[1], at[2])), c) &&
           !intersects(probe_box(local(R, far[0], far[1], far[2])), c) &&
           !intersects(probe_box(local(R, off[0], off[1], off[2])), c);
}

// FCL / Coal: Box(10, 1, 1) takes full side lengths; Cylinder(radius, lz) is centred, lz the full
// length along local z; Transform3's linear() is R (columns = local axes).
TEST(PeerConventions, FclCoal) {
    expect_box_10_1_1(oriented_box(origin, R, Size<double>{10, 1, 1}));
    expect_cylinder_r02_len2(cylinder(origin, R, 0.2, Height<double>{2}), 2);
    // The mistakes: full lengths as half extents, R's rows as the axes, lz as a half height.
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, R, HalfExtents<double>{10, 1, 1})));
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, R_transposed, Size<double>{10, 1, 1})));
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(origin, R, 0.2, HalfHeight<double>{2}), 2));
}

// MuJoCo: box size = half sizes; cylinder size = (radius, half height) along local z; quat is
// (w, x, y, z); xmat is R row-major.
TEST(PeerConventions, MuJoCo) {
    const double quat[4] = {qw, 0, 0, qz};  // as in <geom quat="...">
    const Quaternion<double> q{.w = quat[0], .x = quat[1], .y = quat[2], .z = quat[3]};
    expect_box_10_1_1(oriented_box(origin, q, HalfExtents<double>{5, 0.5, 0.5}));
    expect_cylinder_r02_len2(cylinder(origin, q, 0.2, HalfHeight<double>{1}), 2);
    const double xmat[9] = {0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1};  // row-major
    const RotationMatrix<double> from_xmat{{{{xmat[0], xmat[1], xmat[2]}, {xmat[3], xmat[4], xmat[5]}, {xmat[6], xmat[7], xmat[8]}}}};
    expect_box_10_1_1(oriented_box(origin, from_xmat, HalfExtents<double>{5, 0.5, 0.5}));
    // The mistakes: half sizes as full lengths, the quaternion read as (x, y, z, w), the half height as the height.
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, q, Size<double>{5, 0.5, 0.5})));
    const Quaternion<double> scalar_last{.w = quat[3], .x = quat[0], .y = quat[1], .z = quat[2]};
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, scalar_last, HalfExtents<double>{5, 0.5, 0.5})));
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(origin, q, 0.2, Height<double>{1}), 2));
}

// Bullet: btBoxShape(halfExtents); btCylinderShape(halfExtents) runs along local Y with halfExtents =
// (radius, half height, radius), btCylinderShapeZ along Z with (radius, radius, half height);
// btQuaternion(x, y, z, w); btMatrix3x3's rows are R's rows.
TEST(PeerConventions, Bullet) {
    const double bt_quat[4] = {0, 0, qz, qw};  // btQuaternion(x, y, z, w)
    const Quaternion<double> q{.w = bt_quat[3], .x = bt_quat[0], .y = bt_quat[1], .z = bt_quat[2]};
    expect_box_10_1_1(oriented_box(origin, q, HalfExtents<double>{5, 0.5, 0.5}));
    const double cyl_y[3] = {0.2, 1, 0.2};  // btCylinderShape half extents
    expect_cylinder_r02_len2(cylinder(origin, q, cyl_y[0], HalfHeight<double>{cyl_y[1]}, LocalAxis::y), 1);
    const double cyl_z[3] = {0.2, 0.2, 1};  // btCylinderShapeZ half extents
    expect_cylinder_r02_len2(cylinder(origin, R, cyl_z[0], HalfHeight<double>{cyl_z[2]}, LocalAxis::z), 2);
    // The mistakes: the quaternion's first number taken as w, btCylinderShape placed along z.
    const Quaternion<double> w_first{.w = bt_quat[0], .x = bt_quat[1], .y = bt_quat[2], .z = bt_quat[3]};
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, w_first, HalfExtents<double>{5, 0.5, 0.5})));
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(origin, q, cyl_y[0], HalfHeight<double>{cyl_y[1]}), 1));
}

// Jolt: BoxShape(half extent); CylinderShape(half height, radius) — half height FIRST — along local Y;
// Quat(x, y, z, w). (Jolt rounds the cylinder's rims by its convex radius; boxcyl answers for the
// sharp cylinder.)
TEST(PeerConventions, Jolt) {
    const double jolt_quat[4] = {0, 0, qz, qw};  // Quat(x, y, z, w)
    const Quaternion<double> q{.w = jolt_quat[3], .x = jolt_quat[0], .y = jolt_quat[1], .z = jolt_quat[2]};
    expect_box_10_1_1(oriented_box(origin, q, HalfExtents<double>{5, 0.5, 0.5}));
    const double half_height = 1, radius = 0.2;  // CylinderShape(half_height, radius)
    expect_cylinder_r02_len2(cylinder(origin, q, radius, HalfHeight<double>{half_height}, LocalAxis::y), 1);
    // The mistakes: along z, and the arguments' order (radius taken as the half height).
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(origin, q, radius, HalfHeight<double>{half_height}), 1));
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(origin, q, half_height, HalfHeight<double>{radius}, LocalAxis::y), 1));
}

// trimesh: creation.box(extents=full lengths, transform=4×4); creation.cylinder(radius, height,
// transform) is centred along local z with the full height; transforms are homogeneous, column vectors.
TEST(PeerConventions, Trimesh) {
    const RigidTransform<double> t{{{{0.6, -0.8, 0, origin[0]}, {0.8, 0.6, 0, origin[1]}, {0, 0, 1, origin[2]}, {0, 0, 0, 1}}}};
    expect_box_10_1_1(oriented_box(t, Size<double>{10, 1, 1}));
    expect_cylinder_r02_len2(cylinder(t, 0.2, Height<double>{2}), 2);
    // The mistakes: extents as half extents; the transform transposed (row vectors).
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(t, HalfExtents<double>{10, 1, 1})));
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, R_transposed, Size<double>{10, 1, 1})));
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(t, 0.2, HalfHeight<double>{2}), 2));
}

// ODE: dCreateBox(space, lx, ly, lz) takes full side lengths; dCreateCylinder(space, radius, length)
// the full length along local z; dGeomSetRotation takes a dMatrix3, 12 numbers: R row by row, each
// row padded to 4 (R(i, j) = m[4·i + j], the 4th of each row unused); dQuaternion is (w, x, y, z).
TEST(PeerConventions, Ode) {
    const double dmatrix3[12] = {0.6, -0.8, 0, 0, 0.8, 0.6, 0, 0, 0, 0, 1, 0};  // as dRFromAxisAndAngle fills it
    const RotationMatrix<double> r{{{{dmatrix3[0], dmatrix3[1], dmatrix3[2]},
                                     {dmatrix3[4], dmatrix3[5], dmatrix3[6]},
                                     {dmatrix3[8], dmatrix3[9], dmatrix3[10]}}}};
    const double lengths[3] = {10, 1, 1};  // dCreateBox(space, 10, 1, 1)
    expect_box_10_1_1(oriented_box(origin, r, Size<double>{lengths[0], lengths[1], lengths[2]}));
    const double radius = 0.2, length = 2;  // dCreateCylinder(space, 0.2, 2)
    expect_cylinder_r02_len2(cylinder(origin, r, radius, Height<double>{length}), 2);
    const double dquat[4] = {qw, 0, 0, qz};  // dQuaternion: w first
    const Quaternion<double> q{.w = dquat[0], .x = dquat[1], .y = dquat[2], .z = dquat[3]};
    expect_box_10_1_1(oriented_box(origin, q, Size<double>{lengths[0], lengths[1], lengths[2]}));
    // The mistakes: the lengths as half extents; the 12 numbers read as a packed 3×3 (no padding),
    // which is no rotation; the length as a half height; the quaternion read as (x, y, z, w).
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, r, HalfExtents<double>{lengths[0], lengths[1], lengths[2]})));
    const RotationMatrix<double> packed{{{{dmatrix3[0], dmatrix3[1], dmatrix3[2]},
                                          {dmatrix3[3], dmatrix3[4], dmatrix3[5]},
                                          {dmatrix3[6], dmatrix3[7], dmatrix3[8]}}}};
    EXPECT_THROW(oriented_box(origin, packed, Size<double>{lengths[0], lengths[1], lengths[2]}), std::invalid_argument);
    EXPECT_FALSE(cylinder_answers_as_r02_len2(cylinder(origin, r, radius, HalfHeight<double>{length}), 2));
    const Quaternion<double> scalar_last{.w = dquat[3], .x = dquat[0], .y = dquat[1], .z = dquat[2]};
    EXPECT_FALSE(box_answers_as_10_1_1(oriented_box(origin, scalar_last, Size<double>{lengths[0], lengths[1], lengths[2]})));
}

// A trimesh box (extents = full lengths) under a transform with scale: the parallelepiped spanned by
// the transform's columns. The unit cube under diag(3, 4, 5)·R (R the 3-4-5 rotation) is the box of
// half sizes 1.5, 2, 2.5 in R's frame; reading the size as half extents doubles it.
TEST(Pose, ScaledTransformGivesTheParallelepiped) {
    const AffineTransform<double> t{{{{0.6 * 3, -0.8 * 4, 0, origin[0]}, {0.8 * 3, 0.6 * 4, 0, origin[1]},
                                      {0, 0, 5, origin[2]}, {0, 0, 0, 1}}}};
    const Parallelepiped<double> p = parallelepiped(t, Size<double>{1, 1, 1});
    EXPECT_EQ(p.center, origin);
    EXPECT_EQ(p.axes[2], (V{0, 0, 5}));
    EXPECT_EQ(p.extents, (V{0.5, 0.5, 0.5}));
    ASSERT_TRUE(validate(p).ok());
    EXPECT_TRUE(intersects(p, probe_point(local(R, 1.4, 0, 0))));
    EXPECT_FALSE(intersects(p, probe_point(local(R, 1.6, 0, 0))));
    EXPECT_TRUE(intersects(parallelepiped(t, HalfExtents<double>{1, 1, 1}), probe_point(local(R, 1.6, 0, 0))));
    EXPECT_FALSE(intersects(p, probe_point(local(R, 0, 2.1, 0))));
    EXPECT_TRUE(intersects(p, probe_point(local(R, 0, 0, 2.4))));
    AffineTransform<double> bad = t;
    bad.m[3][3] = 2;
    EXPECT_THROW(parallelepiped(bad, Size<double>{1, 1, 1}), std::invalid_argument);
}

TEST(Pose, FactoriesProduceTheStatedSolid) {
    const OrientedBox<double> b = oriented_box(origin, R, Size<double>{2, 4, 6});
    EXPECT_EQ(b.center, origin);
    EXPECT_EQ(b.axes[0], (V{0.6, 0.8, 0}));
    EXPECT_EQ(b.axes[1], (V{-0.8, 0.6, 0}));
    EXPECT_EQ(b.axes[2], (V{0, 0, 1}));
    EXPECT_EQ(b.extents, (V{1, 2, 3}));
    const Cylinder<double> c = cylinder(origin, R, 0.5, HalfHeight<double>{1.5}, LocalAxis::x);
    EXPECT_EQ(c.axis, (V{0.6, 0.8, 0}));
    EXPECT_EQ(c.height, 3);
    EXPECT_EQ(c.radius, 0.5);
    // The identity quaternion is exactly the identity; a rounded one is orthonormal within the contract.
    const OrientedBox<double> id = oriented_box(origin, Quaternion<double>{.w = 1, .x = 0, .y = 0, .z = 0}, HalfExtents<double>{1, 1, 1});
    EXPECT_EQ(id.axes[0], (V{1, 0, 0}));
    EXPECT_EQ(id.axes[1], (V{0, 1, 0}));
    EXPECT_EQ(id.axes[2], (V{0, 0, 1}));
    const double h = std::sqrt(0.5);
    EXPECT_TRUE(validate(oriented_box(origin, Quaternion<double>{.w = h, .x = h, .y = 0, .z = 0}, HalfExtents<double>{1, 1, 1})).ok());
    EXPECT_THROW(rotation(Quaternion<double>{0, 0, 0, 0}), std::invalid_argument);
    RigidTransform<double> bad{{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, 1}}}};
    EXPECT_THROW(oriented_box(bad, Size<double>{1, 1, 1}), std::invalid_argument);
}

// A rotation given as a matrix or a rigid transform must be one (within OrientedBox's 1e-4): a scaled
// or sheared one would otherwise be read as a rotation, and for a cylinder its scale silently dropped.
TEST(Pose, ScaledRotationsAreRefusedWithTheRightAdvice) {
    const RigidTransform<double> doubled{{{{2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
    try {
        (void)cylinder(doubled, 1.0, Height<double>{1});
        FAIL() << "a scaled transform gave a cylinder";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()),
                  "boxcyl: cylinder: transform: is not a rotation (column 0 has squared length 4; its columns must be "
                  "orthonormal within 1e-4): a scaled transform changes a cylinder's radius and height (a non-uniform "
                  "scale makes an elliptic cylinder, which is not a cylinder), so boxcyl takes them explicitly: pass "
                  "the unscaled rotation and the scaled radius and height");
    }
    try {
        (void)oriented_box(doubled, Size<double>{1, 1, 1});
        FAIL() << "a scaled transform gave an oriented box";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()),
                  "boxcyl: oriented_box: transform: is not a rotation (column 0 has squared length 4; its columns must "
                  "be orthonormal within 1e-4): a box under a transform with scale or shear is "
                  "parallelepiped(AffineTransform{...}, sizes)");
    }
    // A uniform scale is refused as well (the radius would change too); so is a shear, and a scaled matrix.
    const RigidTransform<double> uniform{{{{3, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, 3, 0}, {0, 0, 0, 1}}}};
    EXPECT_THROW(cylinder(uniform, 1.0, HalfHeight<double>{1}), std::invalid_argument);
    const RotationMatrix<double> shear{{{{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}}}};
    try {
        (void)cylinder(origin, shear, 1.0, Height<double>{1}, LocalAxis::y);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("cylinder: rotation: is not a rotation (columns 0 and 1 have dot product 0.5;"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_NO_THROW(cylinder(origin, Quaternion<double>{3, 0, 0, 0}, 1.0, Height<double>{1}));  // not unit: still a rotation
}

TEST(Pose, RotationsWithinTheToleranceAreAccepted) {
    // A rotation rounded to a few digits (as printed in a file) is still one; a reflection too (same solids).
    const RotationMatrix<double> rounded{{{{0.70711, -0.70711, 0}, {0.70711, 0.70711, 0}, {0, 0, 1}}}};
    EXPECT_TRUE(is_rotation(rounded));
    EXPECT_NO_THROW(cylinder(origin, rounded, 1.0, Height<double>{1}));
    const RotationMatrix<double> mirror{{{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}};
    EXPECT_TRUE(is_rotation(mirror));
    EXPECT_FALSE(is_rotation(RotationMatrix<double>{{{{1.0002, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}));
}

// A quaternion of any finite non-zero size gives its rotation: scaled by 2^±1000 it gives exactly the
// matrix of the unscaled one (a power of two is factored out exactly), not NaN or a "zero" quaternion.
TEST(Pose, QuaternionsOfAnyMagnitudeNormalise) {
    const Quaternion<double> q{.w = qw, .x = 0, .y = 0, .z = qz};
    const RotationMatrix<double> expected = rotation(q);
    for (double scale : {0x1p-1000, 1e-300, 1e-160, 1e160, 1e300, 0x1p1000, 1.7e308}) {
        const RotationMatrix<double> r = rotation(Quaternion<double>{q.w * scale, q.x * scale, q.y * scale, q.z * scale});
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.m[i][j], expected.m[i][j], 4e-16) << scale;
        EXPECT_TRUE(is_rotation(r));
    }
    const RotationMatrix<double> p2 = rotation(Quaternion<double>{qw * 0x1p1000, 0, 0, qz * 0x1p1000});
    EXPECT_EQ(p2.m, expected.m);
    // The smallest subnormal alone is a rotation by π about its axis.
    const RotationMatrix<double> flip = rotation(Quaternion<double>{0, 0, 0, std::numeric_limits<double>::denorm_min()});
    EXPECT_EQ(flip.m, (RotationMatrix<double>{{{{-1, 0, 0}, {0, -1, 0}, {0, 0, 1}}}}.m));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto message = [](const Quaternion<double>& bad) {
        try {
            (void)rotation(bad);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    EXPECT_EQ(message({0, 0, 0, 0}), "boxcyl: quaternion: is zero");
    EXPECT_EQ(message({1, nan, 0, 0}), "boxcyl: quaternion: is NaN");
    EXPECT_EQ(message({1, 0, -inf, 0}), "boxcyl: quaternion: is infinite");
    const RotationMatrix<float> f = rotation(Quaternion<float>{1e30f, 0, 0, 1e30f});  // float: the same scaling
    EXPECT_NEAR(f.m[0][1], -1.0f, 1e-6f);
}

// height = the smallest double ≥ |p1 − p0|, checked exactly with rationals: h² ≥ |d|² > prev(h)².
void expect_height_rounded_up(const Cylinder<double>& c) {
    const mpq_class d2 = mpq_class(c.axis[0]) * c.axis[0] + mpq_class(c.axis[1]) * c.axis[1] + mpq_class(c.axis[2]) * c.axis[2];
    const double h = c.height, below = std::nextafter(h, 0.0);
    EXPECT_GE(mpq_class(h) * h, d2) << c.axis[0] << " " << c.axis[1] << " " << c.axis[2];
    EXPECT_LT(mpq_class(below) * below, d2) << c.axis[0] << " " << c.axis[1] << " " << c.axis[2];
}

TEST(Pose, CylinderBetweenTwoPoints) {
    // MuJoCo <geom type="cylinder" fromto="1 2 3  1 2 7" size="0.5">: along z, centred at (1, 2, 5), length 4.
    const Cylinder<double> c = cylinder_between(V{1, 2, 3}, V{1, 2, 7}, 0.5);
    EXPECT_EQ(c.center, (V{1, 2, 5}));
    EXPECT_EQ(c.axis, (V{0, 0, 4}));
    EXPECT_EQ(c.radius, 0.5);
    EXPECT_EQ(c.height, 4);
    ASSERT_TRUE(validate(c).ok());
    EXPECT_TRUE(intersects(probe_box(V{1, 2, 7.005}), c));   // touches the end disk at p1
    EXPECT_FALSE(intersects(probe_box(V{1, 2, 7.02}), c));
    // An integer length is exact: (3, 4, 12) has length 13, so the segment is exactly p0 p1.
    const Cylinder<double> p = cylinder_between(V{-1, -1, -1}, V{2, 3, 11}, 0.25);
    EXPECT_EQ(p.center, (V{0.5, 1, 5}));
    EXPECT_EQ(p.axis, (V{3, 4, 12}));
    EXPECT_EQ(p.height, 13);
    // An irrational length rounds up: √3 to nearest is below it, so the height is the next double;
    // √2 to nearest is above it already.
    const Cylinder<double> s3 = cylinder_between(V{0, 0, 0}, V{1, 1, 1}, 1.0);
    EXPECT_EQ(s3.height, std::nextafter(std::sqrt(3.0), 2.0));
    expect_height_rounded_up(s3);
    const Cylinder<double> s2 = cylinder_between(V{0, 0, 0}, V{1, 1, 0}, 1.0);
    EXPECT_EQ(s2.height, std::sqrt(2.0));
    expect_height_rounded_up(s2);
    // No intermediate overflow: the midpoint and the length of a segment spanning the whole range.
    const double big = std::numeric_limits<double>::max();
    const Cylinder<double> huge = cylinder_between(V{-big, 0, 0}, V{big, 0, 0}, 1.0);
    EXPECT_EQ(huge.center, (V{0, 0, 0}));
    EXPECT_EQ(huge.axis, (V{big, 0, 0}));  // p1/2 − p0/2: the direction, at half the length
    EXPECT_EQ(huge.height, std::numeric_limits<double>::infinity());  // 2·DBL_MAX: validate() refuses it
    EXPECT_FALSE(validate(huge).ok());
    const Cylinder<double> wide = cylinder_between(V{big / 2, big / 4, 0}, V{big, big / 2, 0}, 1.0);
    EXPECT_EQ(wide.center, (V{big * 0.75, big * 0.375, 0}));
    expect_height_rounded_up(wide);
    const double tiny = std::numeric_limits<double>::denorm_min();
    const Cylinder<double> t = cylinder_between(V{0, 0, 0}, V{3 * tiny, 4 * tiny, 0}, 0.0);
    EXPECT_EQ(t.height, 5 * tiny);
    EXPECT_EQ(t.center, (V{2 * tiny, 2 * tiny, 0}));  // 1.5 and 2 ulps: rounded once, to even
    // The same point twice: no axis, which validate() names.
    EXPECT_EQ(validate(cylinder_between(V{1, 2, 3}, V{1, 2, 3}, 1.0)).message(), "cylinder.axis: is the zero vector");
    // Random segments of every scale and of mixed scales: always the smallest double ≥ the length.
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-1070, 1020), spread(0, 60);
    for (int n = 0; n < 20000; ++n) {
        const int e = exponent(rng);
        V a{std::ldexp(unit(rng), e), std::ldexp(unit(rng), e - spread(rng)), std::ldexp(unit(rng), e - spread(rng))};
        if (n % 3 == 0) a = V{std::round(unit(rng) * 0x1p20), std::round(unit(rng) * 0x1p20), 0};  // many exact lengths
        const Cylinder<double> r = cylinder_between(V{0, 0, 0}, a, 1.0);
        if (r.axis == V{0, 0, 0}) continue;
        expect_height_rounded_up(r);
    }
    // Components more than 2^484 apart: the tiny one is not tested exactly, and the height is one ulp up.
    const Cylinder<double> mixed = cylinder_between(V{0, 0, 0}, V{1, 0x1p-600, 0}, 1.0);
    EXPECT_EQ(mixed.height, std::nextafter(1.0, 2.0));
    const Cylinder<float> f = cylinder_between(Vec3<float>{0, 0, 0}, Vec3<float>{3, 4, 0}, 1.0f);
    EXPECT_EQ(f.height, 5.0f);
}

}  // namespace
}  // namespace boxcyl
