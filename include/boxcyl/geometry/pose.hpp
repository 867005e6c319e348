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
// those rounded axes, as for any OrientedBox. The quaternion is scaled by a power of two first
// (exactly), so that any finite non-zero quaternion gives its rotation, however large or small.
//
// Checks: a rotation given as a RotationMatrix or a RigidTransform must be one, its columns orthonormal
// within OrientedBox's tolerance (|ci·cj − δij| ≤ 1e-4, as validate() checks a box's axes), else the
// factory throws std::invalid_argument. A scaled or sheared transform is not read as a rotation: a box
// under it is parallelepiped(AffineTransform, ...), exactly; a cylinder under it has another radius or
// height (under a non-uniform scale it is an elliptic cylinder, which is no Cylinder), so its radius and
// height must be given explicitly with the unscaled pose. A zero, NaN or infinite quaternion and a
// transform whose bottom row is not (0, 0, 0, 1) throw too. Nothing else is checked: run validate() on
// the result as on any shape.
//
//   cylinder_between(p0, p1, radius)   // MuJoCo's fromto, trimesh's segment=: the axis from p0 to p1
//
// gives the Cylinder {center = (p0 + p1)/2 rounded once to nearest, axis = p1 − p0 rounded once to
// nearest, radius, height = |p1 − p0| rounded up}: the midpoint and the difference are exact when they
// are doubles (coordinates on a common grid of moderate size, e.g. integers below 2^52), and the height
// is the smallest double ≥ the length of the axis as stored (exact when that length is a double, as for a
// segment along a coordinate axis or with integer length), so that when center and axis are exact the
// cylinder's segment contains the segment p0 p1 and exceeds it by less than one ulp of the length
// (half at each end); it is exactly p0 p1 when the length is a double as well. (One ulp more when the
// differences' components span more than 2^484 in magnitude, where the exact test is not made.)
#pragma once

#include <algorithm>    // std::max
#include <array>        // matrices
#include <cmath>        // std::fma, std::ldexp, std::ilogb, std::nextafter: quaternion scaling, lengths
#include <concepts>     // std::floating_point
#include <cstddef>      // std::size_t
#include <cstdio>       // std::snprintf: the Gram entry in messages
#include <limits>       // the exponent range
#include <stdexcept>    // std::invalid_argument
#include <string>       // messages
#include <type_traits>  // std::type_identity_t: the radius does not take part in deducing T

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"  // the orthonormality tolerance and check
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

namespace detail {

// Why r is not a rotation within OrientedBox's tolerance ("column 0 has squared length 4"), or empty:
// the Gram entries of its columns as validate() judges a box's axes.
template <class T>
std::string rotation_defect(const RotationMatrix<T>& r) {
    const std::array<Vec3<T>, 3> c{r.column(0), r.column(1), r.column(2)};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j)
            if (!gram_entry_ok(c, i, j)) {
                char g[32];
                std::snprintf(g, sizeof g, "%.6Lg", gram(c, i, j));
                return i == j ? "column " + std::to_string(i) + " has squared length " + g
                              : "columns " + std::to_string(i) + " and " + std::to_string(j) + " have dot product " + g;
            }
    return {};
}

// Checked for floating-point T (as validate() checks boxes); other number types are taken as given.
template <class T>
void require_rotation(const RotationMatrix<T>& r, const char* what, const char* otherwise) {
    if constexpr (std::is_floating_point_v<T>) {
        if (const std::string d = rotation_defect(r); !d.empty())
            throw std::invalid_argument(std::string("boxcyl: ") + what + ": is not a rotation (" + d +
                                        "; its columns must be orthonormal within 1e-4): " + otherwise);
    }
}

inline constexpr const char* box_under_scale =
    "a box under a transform with scale or shear is parallelepiped(AffineTransform{...}, sizes)";
inline constexpr const char* cylinder_under_scale =
    "a scaled transform changes a cylinder's radius and height (a non-uniform scale makes an elliptic "
    "cylinder, which is not a cylinder), so boxcyl takes them explicitly: pass the unscaled rotation and "
    "the scaled radius and height";

}  // namespace detail

// Whether r is a rotation as the factories require: columns orthonormal within 1e-4.
template <std::floating_point T>
bool is_rotation(const RotationMatrix<T>& r) {
    const std::array<Vec3<T>, 3> c{r.column(0), r.column(1), r.column(2)};
    return detail::gram_ok(c);
}

// R(q) = I + s·(w[v]× + [v]×²), s = 2/(w² + x² + y² + z²): the rotation of q/|q| for any q ≠ 0. A
// floating-point q is first scaled by a power of two so that its largest component is in [1, 2):
// exact, and the squares can neither overflow nor underflow (components below 2^-1000 of the largest
// may lose bits, which moves R by far less than its own rounding).
template <class T>
RotationMatrix<T> rotation(Quaternion<T> q) {
    if constexpr (std::is_floating_point_v<T>) {
        const T w[4] = {q.w, q.x, q.y, q.z};
        T m = 0;
        for (T c : w) {
            if (std::isnan(c)) throw std::invalid_argument("boxcyl: quaternion: is NaN");
            m = std::max(m, std::fabs(c));
        }
        if (!(m <= std::numeric_limits<T>::max())) throw std::invalid_argument("boxcyl: quaternion: is infinite");
        if (m == T(0)) throw std::invalid_argument("boxcyl: quaternion: is zero");
        const int e = std::ilogb(m);
        q = {std::ldexp(q.w, -e), std::ldexp(q.x, -e), std::ldexp(q.y, -e), std::ldexp(q.z, -e)};
    }
    const T n = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    if (!(n > T(0))) throw std::invalid_argument("boxcyl: quaternion: is zero (or not finite)");
    const T s = T(2) / n;
    const T xx = q.x * q.x * s, yy = q.y * q.y * s, zz = q.z * q.z * s;
    const T xy = q.x * q.y * s, xz = q.x * q.z * s, yz = q.y * q.z * s;
    const T wx = q.w * q.x * s, wy = q.w * q.y * s, wz = q.w * q.z * s;
    return {{{{T(1) - (yy + zz), xy - wz, xz + wy}, {xy + wz, T(1) - (xx + zz), yz - wx},
              {xz - wy, yz + wx, T(1) - (xx + yy)}}}};
}
// The rotation block of t, its bottom row checked; whether the block is a rotation the factories
// check, naming in the message what they build.
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
    detail::require_rotation(r, "oriented_box: rotation", detail::box_under_scale);
    return {center, {r.column(0), r.column(1), r.column(2)}, {h.x, h.y, h.z}};
}
template <class T>
OrientedBox<T> oriented_box(const Vec3<T>& center, const RotationMatrix<T>& r, const Size<T>& s) {
    const Vec3<T> h = half_of(s);
    return oriented_box(center, r, HalfExtents<T>{h[0], h[1], h[2]});
}
template <class T, class Sizes>
OrientedBox<T> oriented_box(const Vec3<T>& center, const Quaternion<T>& q, const Sizes& sizes) {
    return oriented_box(center, rotation(q), sizes);
}
template <class T, class Sizes>
OrientedBox<T> oriented_box(const RigidTransform<T>& pose, const Sizes& sizes) {
    const RotationMatrix<T> r = rotation(pose);
    detail::require_rotation(r, "oriented_box: transform", detail::box_under_scale);
    return oriented_box(translation(pose), r, sizes);
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
    detail::require_rotation(r, "cylinder: rotation", detail::cylinder_under_scale);
    return {center, r.column(static_cast<int>(along)), radius, h.value};
}
template <class T>
Cylinder<T> cylinder(const Vec3<T>& center, const RotationMatrix<T>& r, std::type_identity_t<T> radius, const HalfHeight<T>& h,
                     LocalAxis along = LocalAxis::z) {
    return cylinder(center, r, radius, Height<T>{T(2) * h.value}, along);
}
template <class T, class Length>
Cylinder<T> cylinder(const Vec3<T>& center, const Quaternion<T>& q, std::type_identity_t<T> radius, const Length& length,
                     LocalAxis along = LocalAxis::z) {
    return cylinder(center, rotation(q), radius, length, along);
}
template <class T, class Length>
Cylinder<T> cylinder(const RigidTransform<T>& pose, std::type_identity_t<T> radius, const Length& length, LocalAxis along = LocalAxis::z) {
    const RotationMatrix<T> r = rotation(pose);
    detail::require_rotation(r, "cylinder: transform", detail::cylinder_under_scale);
    return cylinder(translation(pose), r, radius, length, along);
}

// ---- Cylinders between two points (see the header comment for what is exact) ----
namespace detail {

// x rounded to T and read back: a product stored here cannot be fused with the sum that uses it
// (-ffp-contract=fast), which would break the error-free transformations below.
template <class T>
T stored(T x) {
    volatile T v = x;
    return v;
}

// The sign of the exact sum of the values: Shewchuk's grow-expansion (Knuth's TwoSum, exact in round to
// nearest, subnormals included) keeps the sum as non-overlapping components of increasing magnitude,
// whose largest non-zero one has the sum's sign.
template <class T, std::size_t N>
int sign_of_sum(const std::array<T, N>& values) {
    std::array<T, N> e{};
    std::size_t m = 0;
    for (T q : values) {
        std::size_t k = 0;
        for (std::size_t j = 0; j < m; ++j) {
            const T s = q + e[j];
            const T bb = s - q;
            const T err = (q - (s - bb)) + (e[j] - bb);
            if (err != T(0)) e[k++] = err;
            q = s;
        }
        e[k++] = q;
        m = k;
    }
    for (std::size_t j = m; j-- > 0;)
        if (e[j] != T(0)) return e[j] > T(0) ? 1 : -1;
    return 0;
}

// The smallest T ≥ |d| (the Euclidean length, exactly), or ∞ beyond the range; NaN for NaN input.
// On d scaled by a power of two (largest component in [1, 2)), each square is c² = q + r exactly (an
// FMA) and a candidate h is tested by the exact sign of h² − Σ c²; the rounded root starts the search
// a few ulps away. Components below 2^((min_exponent + digits)/2) after scaling (more than 2^484 below
// the largest, for double) would make r underflow: they are left out of the test and the result is
// raised by one ulp, which covers them.
template <std::floating_point T>
T length_rounded_up(const Vec3<T>& d) {
    T m = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        if (std::isnan(d[k])) return d[k];
        m = std::max(m, std::fabs(d[k]));
    }
    if (m == T(0) || !(m <= std::numeric_limits<T>::max())) return m;
    const int e = std::ilogb(m);
    const T tiny = std::ldexp(T(1), (std::numeric_limits<T>::min_exponent + std::numeric_limits<T>::digits) / 2);
    std::array<T, 8> terms{};  // h², h²'s error, then −q, −r of each component
    bool left_out = false;
    T sum = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const T c = std::ldexp(d[k], -e);
        if (std::fabs(c) < tiny) {
            left_out |= d[k] != T(0);
            continue;
        }
        const T q = stored(c * c);
        terms[2 + 2 * k] = -q;
        terms[3 + 2 * k] = -std::fma(c, c, -q);
        sum += q;
    }
    auto at_least = [&](T h) {  // h² ≥ Σ c² (the components kept), exactly
        std::array<T, 8> t = terms;
        t[0] = stored(h * h);
        t[1] = std::fma(h, h, -t[0]);
        return sign_of_sum(t) >= 0;
    };
    constexpr T inf = std::numeric_limits<T>::infinity();
    T h = std::sqrt(sum);
    while (!at_least(h)) h = std::nextafter(h, inf);
    for (T lower = std::nextafter(h, T(0)); at_least(lower); lower = std::nextafter(h, T(0))) h = lower;
    if (left_out) h = std::nextafter(h, inf);
    T scaled = std::ldexp(h, e);  // exact, unless it overflows (∞) or falls below the normal range
    if (std::ldexp(scaled, -e) < h) scaled = std::nextafter(scaled, inf);
    return scaled;
}

}  // namespace detail

// The cylinder of the given radius whose axis segment runs from p0 to p1 (MuJoCo's fromto, trimesh's
// cylinder(segment=...)): center (p0 + p1)/2 and axis p1 − p0, each rounded once to nearest (computed
// without intermediate overflow), height the smallest double ≥ the axis's length (the header comment
// says what is exact). p0 == p1 gives a zero axis, which validate() refuses.
template <std::floating_point T>
Cylinder<T> cylinder_between(const Vec3<T>& p0, const Vec3<T>& p1, std::type_identity_t<T> radius) {
    Vec3<T> center, axis;
    bool halves = false;
    for (std::size_t k = 0; k < 3; ++k) {
        const T s = p0[k] + p1[k];
        center[k] = std::isinf(s) ? p0[k] * T(0.5) + p1[k] * T(0.5) : s * T(0.5);
        axis[k] = p1[k] - p0[k];
        halves |= std::isinf(axis[k]) && std::isfinite(p0[k]) && std::isfinite(p1[k]);
    }
    if (halves) {  // the difference overflows: the same direction at half the length
        for (std::size_t k = 0; k < 3; ++k) axis[k] = p1[k] * T(0.5) - p0[k] * T(0.5);
        return {center, axis, radius, T(2) * detail::length_rounded_up(axis)};
    }
    return {center, axis, radius, detail::length_rounded_up(axis)};
}

}  // namespace boxcyl
