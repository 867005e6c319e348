// Boxes and cylinders from poses and sizes as other libraries hold them, with the convention named at
// the call site: a rotation matrix (its COLUMNS are the local axes in world coordinates, the usual
// x_world = R·x_local + t), a unit quaternion (w, x, y, z), or a 4×4 rigid transform; box sizes as
// HalfExtents or Size (full side lengths); cylinder lengths as Height (full) or HalfHeight.
//
//   oriented_box(center, RotationMatrix<double>{{{...}, {...}, {...}}}, Size<double>{2, 4, 6})
//   oriented_box(center, Quaternion<double>{.w = 1, .x = 0, .y = 0, .z = 0}, HalfExtents<double>{1, 2, 3})
//   oriented_box(RigidTransform<double>{...}, Size<double>{...})
//   cylinder(center, rotation, radius, Height<double>{2})                 // along the local z axis
//   cylinder(center, rotation, radius, HalfHeight<double>{1}, LocalAxis::y)  // Bullet's and Jolt's default
//   parallelepiped(AffineTransform<double>{...}, Size<double>{...})  // a box under scale or shear
//
// The solid each factory produces, exactly: the OrientedBox {center, axes = the columns of R as
// stored (rounded values taken as given), extents}, with extents = HalfExtents, or Size·0.5 (exact for
// every double above the subnormal range); the Cylinder {center, axis = the column of R for the local
// axis (z unless named), radius, height}, with height = Height, or 2·HalfHeight (exact unless it
// overflows). A quaternion is first turned into R in T's arithmetic (rounded, so orthonormal to about
// 1e-16, which OrientedBox's contract accepts); the formula divides by w² + x² + y² + z², so a
// quaternion that is unit only up to rounding still gives a rotation. The answer is then exact for
// those rounded axes, as for any OrientedBox. Factories check nothing but the transform's shape
// (see below); run validate() on the result as on any shape.
#pragma once

#include <array>      // matrices
#include <stdexcept>  // std::invalid_argument
#include <type_traits>  // std::type_identity_t: the radius does not take part in deducing T

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// Half side lengths (MuJoCo box size, Bullet btBoxShape, Jolt BoxShape, boxcyl's `extents`).
template <class T>
struct HalfExtents {
    T x, y, z;
};
// Full side lengths (FCL/Coal Box, trimesh box extents).
template <class T>
struct Size {
    T x, y, z;
};
// The cylinder's full length along its axis (FCL/Coal lz, trimesh height, boxcyl's `height`).
template <class T>
struct Height {
    T value;
};
// Half of it (MuJoCo's second size, Bullet's and Jolt's half height).
template <class T>
struct HalfHeight {
    T value;
};

// A rotation matrix written row by row, m[row][column]; its columns are the local x, y, z axes in
// world coordinates (x_world = R·x_local). This is the matrix of FCL/Coal (Eigen), MuJoCo's xmat (9
// numbers, row-major), Bullet's btMatrix3x3 rows, scipy's as_matrix() and trimesh's transform[:3, :3].
template <class T>
struct RotationMatrix {
    std::array<std::array<T, 3>, 3> m;
    Vec3<T> column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
};
// A rotation quaternion in the order (w, x, y, z): w is the scalar part. MuJoCo and trimesh use this
// order; Eigen's constructor Quaternion(w, x, y, z) too (its coeffs() are (x, y, z, w)); Bullet's
// btQuaternion(x, y, z, w), Jolt's Quat(x, y, z, w) and scipy's as_quat() put w last — name the
// fields (Quaternion<double>{.w = qw, .x = qx, .y = qy, .z = qz}) to be sure.
template <class T>
struct Quaternion {
    T w, x, y, z;
};
// A 4×4 homogeneous rigid transform, m[row][column]: the rotation in the top-left 3×3 block (columns
// = local axes), the translation — the world position of the local origin — in column 3, bottom row
// (0, 0, 0, 1). trimesh's transforms and Eigen's Isometry3d::matrix() are this matrix.
template <class T>
struct RigidTransform {
    std::array<std::array<T, 4>, 4> m;
};

// A 4×4 homogeneous affine transform, m[row][column]: any linear part (scale, shear, reflection) in
// the top-left 3×3 block, the translation in column 3, bottom row (0, 0, 0, 1). A box under it is a
// parallelepiped (below), exactly.
template <class T>
struct AffineTransform {
    std::array<std::array<T, 4>, 4> m;
};

// Which local axis a cylinder runs along: z for FCL/Coal, MuJoCo and trimesh (the default), y for
// Bullet's btCylinderShape and Jolt's CylinderShape, x for btCylinderShapeX.
enum class LocalAxis { x = 0, y = 1, z = 2 };

// R(q) = I + s·(w[v]× + [v]×²), s = 2/(w² + x² + y² + z²): the rotation of q/|q| for any q ≠ 0.
template <class T>
RotationMatrix<T> rotation(const Quaternion<T>& q) {
    const T n = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    if (!(n > T(0))) throw std::invalid_argument("boxcyl: quaternion: is zero (or not finite)");
    const T s = T(2) / n;
    const T xx = q.x * q.x * s, yy = q.y * q.y * s, zz = q.z * q.z * s;
    const T xy = q.x * q.y * s, xz = q.x * q.z * s, yz = q.y * q.z * s;
    const T wx = q.w * q.x * s, wy = q.w * q.y * s, wz = q.w * q.z * s;
    return {{{{T(1) - (yy + zz), xy - wz, xz + wy}, {xy + wz, T(1) - (xx + zz), yz - wx},
              {xz - wy, yz + wx, T(1) - (xx + yy)}}}};
}
template <class T>
RotationMatrix<T> rotation(const RigidTransform<T>& t) {
    if (!(t.m[3][0] == T(0) && t.m[3][1] == T(0) && t.m[3][2] == T(0) && t.m[3][3] == T(1)))
        throw std::invalid_argument("boxcyl: transform: the bottom row is not (0, 0, 0, 1)");
    return {{{{t.m[0][0], t.m[0][1], t.m[0][2]}, {t.m[1][0], t.m[1][1], t.m[1][2]}, {t.m[2][0], t.m[2][1], t.m[2][2]}}}};
}
template <class T>
Vec3<T> translation(const RigidTransform<T>& t) {
    return {t.m[0][3], t.m[1][3], t.m[2][3]};
}

template <class T>
Vec3<T> half_of(const Size<T>& s) {
    return {s.x * T(0.5), s.y * T(0.5), s.z * T(0.5)};
}

// ---- Oriented boxes ----
template <class T>
OrientedBox<T> oriented_box(const Vec3<T>& center, const RotationMatrix<T>& r, const HalfExtents<T>& h) {
    return {center, {r.column(0), r.column(1), r.column(2)}, {h.x, h.y, h.z}};
}
template <class T>
OrientedBox<T> oriented_box(const Vec3<T>& center, const RotationMatrix<T>& r, const Size<T>& s) {
    return {center, {r.column(0), r.column(1), r.column(2)}, half_of(s)};
}
template <class T, class Sizes>
OrientedBox<T> oriented_box(const Vec3<T>& center, const Quaternion<T>& q, const Sizes& sizes) {
    return oriented_box(center, rotation(q), sizes);
}
template <class T, class Sizes>
OrientedBox<T> oriented_box(const RigidTransform<T>& pose, const Sizes& sizes) {
    return oriented_box(translation(pose), rotation(pose), sizes);
}

// ---- Parallelepipeds: a box of the given size under an affine transform ----
// The Parallelepiped {center = the translation, axes = the columns of the linear part as stored,
// extents = HalfExtents or Size·0.5}: exactly the image of the box under the transform (e.g. a
// trimesh box with a scaled transform, a block of a rotated, scaled block model).
template <class T>
Parallelepiped<T> parallelepiped(const AffineTransform<T>& t, const HalfExtents<T>& h) {
    if (!(t.m[3][0] == T(0) && t.m[3][1] == T(0) && t.m[3][2] == T(0) && t.m[3][3] == T(1)))
        throw std::invalid_argument("boxcyl: transform: the bottom row is not (0, 0, 0, 1)");
    auto column = [&t](int j) { return Vec3<T>{t.m[0][j], t.m[1][j], t.m[2][j]}; };
    return {column(3), {column(0), column(1), column(2)}, {h.x, h.y, h.z}};
}
template <class T>
Parallelepiped<T> parallelepiped(const AffineTransform<T>& t, const Size<T>& s) {
    const Vec3<T> h = half_of(s);
    return parallelepiped(t, HalfExtents<T>{h[0], h[1], h[2]});
}

// ---- Cylinders (centred at the pose's origin, along its local `along` axis) ----
template <class T>
Cylinder<T> cylinder(const Vec3<T>& center, const RotationMatrix<T>& r, std::type_identity_t<T> radius, const Height<T>& h,
                     LocalAxis along = LocalAxis::z) {
    return {center, r.column(static_cast<int>(along)), radius, h.value};
}
template <class T>
Cylinder<T> cylinder(const Vec3<T>& center, const RotationMatrix<T>& r, std::type_identity_t<T> radius, const HalfHeight<T>& h,
                     LocalAxis along = LocalAxis::z) {
    return {center, r.column(static_cast<int>(along)), radius, T(2) * h.value};
}
template <class T, class Length>
Cylinder<T> cylinder(const Vec3<T>& center, const Quaternion<T>& q, std::type_identity_t<T> radius, const Length& length,
                     LocalAxis along = LocalAxis::z) {
    return cylinder(center, rotation(q), radius, length, along);
}
template <class T, class Length>
Cylinder<T> cylinder(const RigidTransform<T>& pose, std::type_identity_t<T> radius, const Length& length, LocalAxis along = LocalAxis::z) {
    return cylinder(translation(pose), rotation(pose), radius, length, along);
}

}  // namespace boxcyl
