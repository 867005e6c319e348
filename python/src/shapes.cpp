// The option enums and the shapes: AlignedBox, OrientedBox, Parallelepiped, Cylinder (double
// precision, immutable, validated when built so that an invalid one never exists). They take plain
// floats; the package subclasses them for argument conversion, equality and pickling.
#include <pybind11/stl.h>  // std::array <-> Python sequences

#include "bindings.hpp"

namespace boxcyl_python {

using namespace pybind11::literals;

namespace {

py::tuple axes_tuple(const std::array<Vec, 3>& a) { return py::make_tuple(tuple(a[0]), tuple(a[1]), tuple(a[2])); }

// OrientedBox and Parallelepiped: the same fields, the same Python face.
template <class Box>
void def_frame_box(py::module_& m, const char* name, const char* doc) {
    py::class_<Box>(m, name, doc)
        .def(py::init([](const Array3& center, const Matrix3& axes, const Array3& extents) {
                 return validated(Box{vec(center), {vec(axes[0]), vec(axes[1]), vec(axes[2])}, vec(extents)}, "box");
             }),
             "center"_a, "axes"_a, "extents"_a)
        .def_property_readonly("center", [](const Box& b) { return tuple(b.center); })
        .def_property_readonly("axes", [](const Box& b) { return axes_tuple(b.axes); })
        .def_property_readonly("extents", [](const Box& b) { return tuple(b.extents); })
        .def("__repr__", [name](const Box& b) {
            return py::str("{}(center={!r}, axes={!r}, extents={!r})")
                .format(name, tuple(b.center), axes_tuple(b.axes), tuple(b.extents));
        });
}

}  // namespace

void def_shapes(py::module_& m) {
    py::enum_<boxcyl::Algorithm>(m, "Algorithm",
                                 "Which algorithm answers: linear inequalities (default), convex hull, LCP, "
                                 "or the exact oracle (docs/algorithms.md).")
        .value("inequalities", boxcyl::Algorithm::inequalities, "the linear-inequalities method (the default)")
        .value("hull", boxcyl::Algorithm::hull, "the convex-hull method: clip, project, 2-D hull")
        .value("lcp", boxcyl::Algorithm::lcp, "convex quadratic programming as an LCP (Lemke's method)")
        .value("oracle", boxcyl::Algorithm::oracle, "the exact reference");
    py::enum_<boxcyl::Arithmetic>(m, "Arithmetic",
                                  "Which arithmetic: filtered (default: the exact answer, fast), exact, or "
                                  "plain rounded float64/float32.")
        .value("float32", boxcyl::Arithmetic::float32, "rounded single precision")
        .value("float64", boxcyl::Arithmetic::float64, "rounded double precision (plain, fastest)")
        .value("exact", boxcyl::Arithmetic::exact, "rationals and a + b*sqrt(d) throughout")
        .value("filtered", boxcyl::Arithmetic::filtered,
               "the exact answer: certified interval filter, exact fallback (the default)");

    py::class_<Cylinder>(m, "Cylinder",
                         "A closed finite cylinder: the points within `radius` of the axis segment "
                         "center ± (height/2)·axis/|axis|. `axis` need not be unit length; radius 0 is a "
                         "segment, height 0 a disk. Immutable; validated when built (ValueError naming "
                         "the bad field).")
        .def(py::init([](const Array3& center, const Array3& axis, double radius, double height) {
                 return validated(Cylinder{vec(center), vec(axis), radius, height}, "cylinder");
             }),
             "center"_a, "axis"_a, "radius"_a, "height"_a)
        .def_property_readonly("center", [](const Cylinder& c) { return tuple(c.center); })
        .def_property_readonly("axis", [](const Cylinder& c) { return tuple(c.axis); })
        .def_property_readonly("radius", [](const Cylinder& c) { return c.radius; })
        .def_property_readonly("height", [](const Cylinder& c) { return c.height; })
        .def("__repr__", [](const Cylinder& c) {
            return py::str("Cylinder(center={!r}, axis={!r}, radius={!r}, height={!r})")
                .format(tuple(c.center), tuple(c.axis), c.radius, c.height);
        });

    py::class_<AlignedBox>(m, "AlignedBox",
                           "The closed axis-aligned box min <= X <= max (componentwise); equal bounds give a "
                           "flat box or a point. Immutable; validated when built.")
        .def(py::init([](const Array3& min, const Array3& max) {
                 return validated(AlignedBox{vec(min), vec(max)}, "box");
             }),
             "min"_a, "max"_a)
        .def_property_readonly("min", [](const AlignedBox& b) { return tuple(b.min); })
        .def_property_readonly("max", [](const AlignedBox& b) { return tuple(b.max); })
        .def("__repr__", [](const AlignedBox& b) {
            return py::str("AlignedBox(min={!r}, max={!r})").format(tuple(b.min), tuple(b.max));
        });

    def_frame_box<OrientedBox>(m, "OrientedBox",
                               "The closed solid { center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= "
                               "extents[i] } for the axes exactly as given; they must be orthonormal to within "
                               "1e-4 (a rotation rounded to double is fine). Immutable; validated when built.");
    def_frame_box<Parallelepiped>(m, "Parallelepiped",
                                  "The closed solid { center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= "
                                  "extents[i] } for ANY three axes exactly as given (any lengths and angles; "
                                  "parallel or zero axes give flat solids). Immutable; validated when built.");
}

}  // namespace boxcyl_python
