// Shapes from poses and sizes as other libraries hold them (boxcyl/geometry/pose.hpp): the package's
// named constructors (OrientedBox.from_rotation etc.) call these with plain floats.
#include <pybind11/stl.h>  // std::array <-> Python sequences

#include "common.hpp"

namespace boxcyl_python {

namespace {

using Rotation = boxcyl::RotationMatrix<double>;

Rotation rotation_matrix(const Matrix3& rows) { return {rows}; }
boxcyl::Quaternion<double> quaternion(const std::array<double, 4>& wxyz) { return {wxyz[0], wxyz[1], wxyz[2], wxyz[3]}; }

// The library refuses a matrix that is not a rotation with advice in C++ terms; here the same, in the
// package's terms: what the argument is called and which constructor takes a scaled pose.
void require_rotation(const Rotation& r, const char* what, const char* otherwise) {
    if (const std::string d = boxcyl::detail::rotation_defect(r); !d.empty())
        throw py::value_error(std::string(what) + " (" + d + "; its columns must be orthonormal within 1e-4): " +
                              otherwise);
}
constexpr const char* box_advice =
    "a box under a transform with scale or shear is a parallelepiped: use Parallelepiped.from_transform";
constexpr const char* cylinder_advice =
    "a scaled transform changes the cylinder's radius and height (a non-uniform scale makes an elliptic "
    "cylinder, which is not a cylinder), and boxcyl takes them explicitly: pass the unscaled pose with the "
    "scaled radius= and height=";

boxcyl::RigidTransform<double> rigid(const Matrix4& t) { return {t}; }

// `full`: sizes are full side lengths (Size), else half (HalfExtents).
OrientedBox box_from(const Vec& center, const Rotation& r, const Array3& sizes, bool full) {
    if (full) return validated(boxcyl::oriented_box(center, r, boxcyl::Size<double>{sizes[0], sizes[1], sizes[2]}), "box");
    return validated(boxcyl::oriented_box(center, r, boxcyl::HalfExtents<double>{sizes[0], sizes[1], sizes[2]}), "box");
}

// `half`: length is half the height (HalfHeight), else the full height (Height).
Cylinder cylinder_from(const Vec& center, const Rotation& r, double radius, double length, bool half, int along) {
    const auto axis = static_cast<boxcyl::LocalAxis>(along);
    if (half) return validated(boxcyl::cylinder(center, r, radius, boxcyl::HalfHeight<double>{length}, axis), "cylinder");
    return validated(boxcyl::cylinder(center, r, radius, boxcyl::Height<double>{length}, axis), "cylinder");
}

}  // namespace

void def_poses(py::module_& m) {
    m.def("_box_from_rotation", [](const Array3& center, const Matrix3& rows, const Array3& sizes, bool full) {
        const Rotation r = rotation_matrix(rows);
        require_rotation(r, "rotation: is not a rotation matrix", box_advice);
        return box_from(vec(center), r, sizes, full);
    });
    m.def("_box_from_quaternion", [](const Array3& center, const std::array<double, 4>& wxyz, const Array3& sizes,
                                     bool full) { return box_from(vec(center), boxcyl::rotation(quaternion(wxyz)), sizes, full); });
    m.def("_box_from_transform", [](const Matrix4& t, const Array3& sizes, bool full) {
        const Rotation r = boxcyl::rotation(rigid(t));  // checks the bottom row
        require_rotation(r, "transform: its top-left 3×3 block is not a rotation", box_advice);
        return box_from(boxcyl::translation(rigid(t)), r, sizes, full);
    });
    m.def("_parallelepiped_from_transform", [](const Matrix4& t, const Array3& sizes, bool full) {
        const boxcyl::AffineTransform<double> a{t};
        if (full) return validated(boxcyl::parallelepiped(a, boxcyl::Size<double>{sizes[0], sizes[1], sizes[2]}), "box");
        return validated(boxcyl::parallelepiped(a, boxcyl::HalfExtents<double>{sizes[0], sizes[1], sizes[2]}), "box");
    });
    m.def("_cylinder_from_rotation", [](const Array3& center, const Matrix3& rows, double radius, double length, bool half,
                                        int along) {
        const Rotation r = rotation_matrix(rows);
        require_rotation(r, "rotation: is not a rotation matrix", cylinder_advice);
        return cylinder_from(vec(center), r, radius, length, half, along);
    });
    m.def("_cylinder_from_quaternion", [](const Array3& center, const std::array<double, 4>& wxyz, double radius,
                                          double length, bool half, int along) {
        return cylinder_from(vec(center), boxcyl::rotation(quaternion(wxyz)), radius, length, half, along);
    });
    m.def("_cylinder_from_transform", [](const Matrix4& t, double radius, double length, bool half, int along) {
        const Rotation r = boxcyl::rotation(rigid(t));
        require_rotation(r, "transform: its top-left 3×3 block is not a rotation", cylinder_advice);
        return cylinder_from(boxcyl::translation(rigid(t)), r, radius, length, half, along);
    });
    m.def("_cylinder_between", [](const Array3& p0, const Array3& p1, double radius) {
        return validated(boxcyl::cylinder_between(vec(p0), vec(p1), radius), "cylinder");
    });
}

}  // namespace boxcyl_python
