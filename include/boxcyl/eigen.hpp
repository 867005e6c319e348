// Eigen interop: boxcyl's pose types (geometry/pose.hpp) from Eigen's, so that poses held as Eigen
// types (FCL/Coal's Transform3, robotics code) go to boxcyl's factories with the convention kept.
// Header-only and separate: boxcyl itself does not depend on Eigen; a file that includes this header
// needs Eigen's include path (CMake: find_package(Eigen3 NO_MODULE), link Eigen3::Eigen).
//
//   #include <boxcyl/eigen.hpp>
//   Eigen::Isometry3d pose = ...;
//   auto box = boxcyl::oriented_box(boxcyl::eigen::rigid_transform(pose), boxcyl::Size<double>{2, 4, 6});
//   auto cyl = boxcyl::cylinder(boxcyl::eigen::vec3(p), boxcyl::eigen::quaternion(q), 0.5, boxcyl::Height<double>{2});
//
// The conversions, T being the Eigen scalar (double or float), values copied as they are:
//   vec3(v)             a 3-vector expression          -> Vec3<T>
//   rotation(m)         a 3×3 matrix expression        -> RotationMatrix<T>: element (i, j) as is, so
//                                                          the columns stay the local axes, as in Eigen
//   quaternion(q)       Eigen::Quaternion<T>            -> Quaternion<T>{.w = q.w(), .x = q.x(), ...}
//                                                          (not coeffs(), whose order is x, y, z, w)
//   rigid_transform(t)  Eigen::Transform<T, 3, Mode>    -> RigidTransform<T>: linear() and translation()
//   affine_transform(t) Eigen::Transform<T, 3, Mode>    -> AffineTransform<T> (for parallelepiped())
// For Isometry, Affine and AffineCompact transforms the bottom row is (0, 0, 0, 1) by Eigen's
// definition and is not read (an Affine transform need not store it); a Projective transform's is
// read, and the factories refuse it unless it is (0, 0, 0, 1). The factories also refuse a rigid
// transform whose linear part is not a rotation (geometry/pose.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "boxcyl/geometry/pose.hpp"
#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl::eigen {

template <class Derived>
Vec3<typename Derived::Scalar> vec3(const Eigen::MatrixBase<Derived>& v) {
    static_assert(Derived::RowsAtCompileTime == 3 && Derived::ColsAtCompileTime == 1, "boxcyl::eigen::vec3: a 3-vector");
    return {v(0), v(1), v(2)};
}

template <class Derived>
RotationMatrix<typename Derived::Scalar> rotation(const Eigen::MatrixBase<Derived>& m) {
    static_assert(Derived::RowsAtCompileTime == 3 && Derived::ColsAtCompileTime == 3, "boxcyl::eigen::rotation: a 3×3 matrix");
    return {{{{m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}}}};
}

template <class T, int Options>
Quaternion<T> quaternion(const Eigen::Quaternion<T, Options>& q) {
    return {.w = q.w(), .x = q.x(), .y = q.y(), .z = q.z()};
}

namespace detail {

// The 4×4 matrix of t: its linear part and translation, and the bottom row (0, 0, 0, 1) unless t is
// Projective, whose own bottom row is kept.
template <class T, int Mode, int Options>
std::array<std::array<T, 4>, 4> homogeneous(const Eigen::Transform<T, 3, Mode, Options>& t) {
    std::array<std::array<T, 4>, 4> m{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = t.linear()(i, j);
        m[i][3] = t.translation()(i);
    }
    if constexpr (Mode == Eigen::Projective) {
        for (int j = 0; j < 4; ++j) m[3][j] = t.matrix()(3, j);
    } else {
        m[3] = {T(0), T(0), T(0), T(1)};
    }
    return m;
}

}  // namespace detail

template <class T, int Mode, int Options>
RigidTransform<T> rigid_transform(const Eigen::Transform<T, 3, Mode, Options>& t) {
    return {detail::homogeneous(t)};
}

template <class T, int Mode, int Options>
AffineTransform<T> affine_transform(const Eigen::Transform<T, 3, Mode, Options>& t) {
    return {detail::homogeneous(t)};
}

}  // namespace boxcyl::eigen
