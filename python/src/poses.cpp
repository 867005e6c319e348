// Shapes from poses and sizes as other libraries hold them (boxcyl/geometry/pose.hpp): what the
// package's named constructors (OrientedBox.from_rotation etc.) call, with its advice in its terms.
#include "common.hpp"

namespace boxcyl_python {

namespace {

using Rotation = boxcyl::RotationMatrix<double>;

boxcyl::Quaternion<double> quaternion(const std::array<double, 4>& wxyz) { return {wxyz[0], wxyz[1], wxyz[2], wxyz[3]}; }
boxcyl::RigidTransform<double> rigid(const Matrix4& t) { return {t}; }

// The library refuses a matrix that is not a rotation with advice in C++ terms; here the same, in the
// package's terms: what the argument is called and which constructor takes a scaled pose.
void require_rotation(const Rotation& r, const char* what, const char* otherwise) {
    if (const std::string d = boxcyl::detail::rotation_defect(r); !d.empty())
        throw std::invalid_argument(std::string(what) + " (" + d + "; its columns must be orthonormal within 1e-4): " +
                                    otherwise);
}
constexpr const char* kRotation = "rotation: is not a rotation matrix";
constexpr const char* kTransform = "transform: its top-left 3×3 block is not a rotation";
constexpr const char* kBoxAdvice =
    "a box under a transform with scale or shear is a parallelepiped: use Parallelepiped.from_transform";
constexpr const char* kCylinderAdvice =
    "a scaled transform changes the cylinder's radius and height (a non-uniform scale makes an elliptic "
    "cylinder, which is not a cylinder), and boxcyl takes them explicitly: pass the unscaled pose with the "
    "scaled radius= and height=";

OrientedBox box_from(const Vec& center, const Rotation& r, const Array3& sizes, bool full) {
    if (full) return validated(boxcyl::oriented_box(center, r, boxcyl::Size<double>{sizes[0], sizes[1], sizes[2]}), "box");
    return validated(boxcyl::oriented_box(center, r, boxcyl::HalfExtents<double>{sizes[0], sizes[1], sizes[2]}), "box");
}

Cylinder cylinder_from(const Vec& center, const Rotation& r, double radius, double length, bool half, int along) {
    const auto axis = static_cast<boxcyl::LocalAxis>(along);
    if (half) return validated(boxcyl::cylinder(center, r, radius, boxcyl::HalfHeight<double>{length}, axis), "cylinder");
    return validated(boxcyl::cylinder(center, r, radius, boxcyl::Height<double>{length}, axis), "cylinder");
}

}  // namespace

OrientedBox box_from_rotation(const Array3& center, const Matrix3& rows, const Array3& sizes, bool full) {
    const Rotation r{rows};
    require_rotation(r, kRotation, kBoxAdvice);
    return box_from(vec(center), r, sizes, full);
}

OrientedBox box_from_quaternion(const Array3& center, const std::array<double, 4>& wxyz, const Array3& sizes, bool full) {
    return box_from(vec(center), boxcyl::rotation(quaternion(wxyz)), sizes, full);
}

OrientedBox box_from_transform(const Matrix4& t, const Array3& sizes, bool full) {
    const Rotation r = boxcyl::rotation(rigid(t));  // checks the bottom row
    require_rotation(r, kTransform, kBoxAdvice);
    return box_from(boxcyl::translation(rigid(t)), r, sizes, full);
}

Parallelepiped parallelepiped_from_transform(const Matrix4& t, const Array3& sizes, bool full) {
    const boxcyl::AffineTransform<double> a{t};
    if (full) return validated(boxcyl::parallelepiped(a, boxcyl::Size<double>{sizes[0], sizes[1], sizes[2]}), "box");
    return validated(boxcyl::parallelepiped(a, boxcyl::HalfExtents<double>{sizes[0], sizes[1], sizes[2]}), "box");
}

Cylinder cylinder_from_rotation(const Array3& center, const Matrix3& rows, double radius, double length, bool half,
                                int along) {
    const Rotation r{rows};
    require_rotation(r, kRotation, kCylinderAdvice);
    return cylinder_from(vec(center), r, radius, length, half, along);
}

Cylinder cylinder_from_quaternion(const Array3& center, const std::array<double, 4>& wxyz, double radius,
                                  double length, bool half, int along) {
    return cylinder_from(vec(center), boxcyl::rotation(quaternion(wxyz)), radius, length, half, along);
}

Cylinder cylinder_from_transform(const Matrix4& t, double radius, double length, bool half, int along) {
    const Rotation r = boxcyl::rotation(rigid(t));
    require_rotation(r, kTransform, kCylinderAdvice);
    return cylinder_from(boxcyl::translation(rigid(t)), r, radius, length, half, along);
}

Cylinder cylinder_between(const Array3& p0, const Array3& p1, double radius) {
    return validated(boxcyl::cylinder_between(vec(p0), vec(p1), radius), "cylinder");
}

}  // namespace boxcyl_python
