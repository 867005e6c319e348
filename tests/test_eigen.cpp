// boxcyl/eigen.hpp: Eigen's pose types converted to boxcyl's keep their convention. The rotation by θ
// about z with cos θ = 3/5 (test_pose.cpp's R), held as Eigen holds it — a Matrix3d, a Quaterniond
// made by Eigen's (w, x, y, z) constructor, an Isometry3d, an Affine3d with scale, a Projective3d —
// gives the same boxes and cylinders as the same numbers written for boxcyl by hand. Built only where
// Eigen is found.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "boxcyl/eigen.hpp"
#include "boxcyl/geometry/validate.hpp"

namespace boxcyl {
namespace {

using V = Vec3<double>;

const RotationMatrix<double> R{{{{0.6, -0.8, 0}, {0.8, 0.6, 0}, {0, 0, 1}}}};
const V origin{1, 2, 3};

Eigen::Matrix3d eigen_R() {
    Eigen::Matrix3d m;
    m << 0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1;  // row by row
    return m;
}

TEST(Eigen, VectorsAndMatricesKeepTheirElements) {
    EXPECT_EQ(eigen::vec3(Eigen::Vector3d(1, 2, 3)), origin);
    EXPECT_EQ(eigen::rotation(eigen_R()).m, R.m);
    EXPECT_EQ(eigen::rotation(eigen_R()).column(0), (V{0.6, 0.8, 0}));  // columns are the local axes
    const Eigen::Matrix3f f = eigen_R().cast<float>();
    EXPECT_EQ(eigen::rotation(f).m[1][0], 0.8f);
    // Expressions too: a block of a 4×4 matrix, a product.
    Eigen::Matrix4d h = Eigen::Matrix4d::Identity();
    h.topLeftCorner<3, 3>() = eigen_R();
    EXPECT_EQ(eigen::rotation(h.topLeftCorner<3, 3>()).m, R.m);
    EXPECT_EQ(eigen::vec3(2.0 * Eigen::Vector3d(0.5, 1, 1.5)), origin);
}

TEST(Eigen, QuaternionsAreReadScalarFirstWhateverTheirStorage) {
    const double c = 2 / std::sqrt(5.0), s = 1 / std::sqrt(5.0);  // cos, sin of θ/2
    const Eigen::Quaterniond q(c, 0, 0, s);                       // Eigen's constructor: (w, x, y, z)
    const Quaternion<double> b = eigen::quaternion(q);
    EXPECT_EQ(b.w, c);
    EXPECT_EQ(b.z, s);
    EXPECT_EQ(q.coeffs()(0), 0.0);  // coeffs() is (x, y, z, w): reading it in order would be wrong
    const OrientedBox<double> box = oriented_box(origin, b, Size<double>{10, 1, 1});
    const OrientedBox<double> by_hand = oriented_box(origin, Quaternion<double>{.w = c, .x = 0, .y = 0, .z = s}, Size<double>{10, 1, 1});
    EXPECT_EQ(box.axes, by_hand.axes);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(box.axes[j][i], R.m[i][j], 1e-15);
    // Eigen's own matrix of q is the same rotation.
    EXPECT_NEAR(eigen::rotation(q.toRotationMatrix()).m[0][1], -0.8, 1e-15);
    EXPECT_EQ(eigen::quaternion(Eigen::Quaternionf(1, 0, 0, 0)).w, 1.0f);
}

TEST(Eigen, IsometriesAreRigidTransforms) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = eigen_R();
    t.translation() = Eigen::Vector3d(1, 2, 3);
    const RigidTransform<double> r = eigen::rigid_transform(t);
    EXPECT_EQ(r.m[0][3], 1.0);
    EXPECT_EQ(r.m[3][3], 1.0);
    const OrientedBox<double> box = oriented_box(r, Size<double>{10, 1, 1});
    const OrientedBox<double> by_hand = oriented_box(origin, R, Size<double>{10, 1, 1});
    EXPECT_EQ(box.center, by_hand.center);
    EXPECT_EQ(box.axes, by_hand.axes);
    EXPECT_EQ(box.extents, by_hand.extents);
    const Cylinder<double> c = cylinder(r, 0.2, Height<double>{2}, LocalAxis::x);
    EXPECT_EQ(c.center, origin);
    EXPECT_EQ(c.axis, (V{0.6, 0.8, 0}));
    // The same from Eigen's translation-times-rotation expression.
    const Eigen::Isometry3d u = Eigen::Translation3d(1, 2, 3) * Eigen::Isometry3d(eigen_R());
    EXPECT_EQ(eigen::rigid_transform(u).m, r.m);
}

TEST(Eigen, ScaledAffineTransformsGiveParallelepipedsAndNoRotation) {
    Eigen::Affine3d a = Eigen::Affine3d::Identity();
    a.linear() = eigen_R() * Eigen::Vector3d(3, 4, 5).asDiagonal();
    a.translation() = Eigen::Vector3d(1, 2, 3);
    const Parallelepiped<double> p = parallelepiped(eigen::affine_transform(a), Size<double>{1, 1, 1});
    EXPECT_EQ(p.center, origin);
    EXPECT_EQ(p.axes[0], (V{0.6 * 3, 0.8 * 3, 0}));
    EXPECT_EQ(p.axes[2], (V{0, 0, 5}));
    EXPECT_EQ(p.extents, (V{0.5, 0.5, 0.5}));
    EXPECT_TRUE(validate(p).ok());
    // Read as a rigid transform, the scale is refused, not dropped.
    EXPECT_THROW(cylinder(eigen::rigid_transform(a), 1.0, Height<double>{1}), std::invalid_argument);
    EXPECT_THROW(oriented_box(eigen::rigid_transform(a), Size<double>{1, 1, 1}), std::invalid_argument);
}

TEST(Eigen, ProjectiveTransformsKeepTheirBottomRow) {
    Eigen::Projective3d t = Eigen::Projective3d::Identity();
    EXPECT_NO_THROW(oriented_box(eigen::rigid_transform(t), HalfExtents<double>{1, 1, 1}));
    t.matrix()(3, 2) = 0.5;
    EXPECT_EQ(eigen::rigid_transform(t).m[3][2], 0.5);
    EXPECT_THROW(oriented_box(eigen::rigid_transform(t), HalfExtents<double>{1, 1, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace boxcyl
