// boxcyl._core: the pybind11 bindings behind the Python package `boxcyl` (python/boxcyl/__init__.py
// adds the numpy-friendly argument handling and the docs users read first).
//
// Objects: AlignedBox, OrientedBox, Cylinder (double precision, immutable, validated when built so
// that an invalid one never exists). Queries: intersects(box, cylinder[, algorithm, arithmetic]) and
// the batch forms _intersects_aligned / _intersects_oriented over float64 arrays whose leading length
// is N or 1 (broadcast). Batches validate every element first (a ValueError names field and index,
// "boxes[17].max[0]: is less than boxes[17].min[0]"), then run boxcyl::intersects with the GIL
// released — through the batch API (boxcyl/batch.hpp: SIMD filter, all cores) when one cylinder meets
// many boxes with the default exact query. The default is the library's exact query.
#include <pybind11/numpy.h>     // float64 input arrays, bool output arrays
#include <pybind11/pybind11.h>  // the bindings
#include <pybind11/stl.h>       // std::array <-> Python sequences

#include <array>             // Vec3 <-> std::array
#include <initializer_list>  // the fields of one batch
#include <stdexcept>         // std::domain_error, std::invalid_argument (mapped to ValueError)
#include <string>            // element names in messages
#include <vector>            // the batch API's box arrays

#include "boxcyl/batch.hpp"            // one cylinder against many boxes: SIMD filter + exact fallback
#include "boxcyl/number/interval.hpp"  // fp_environment_ok
#include "boxcyl/query.hpp"
#include "boxcyl/version.hpp"

#if !defined(BOXCYL_HAS_EXACT)
#error "the boxcyl Python module needs the exact backend (GMP): link boxcyl::exact / define BOXCYL_HAS_EXACT"
#endif

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using Vec = boxcyl::Vec3<double>;
using Array3 = std::array<double, 3>;
using Cylinder = boxcyl::Cylinder<double>;
using AlignedBox = boxcyl::AlignedBox<double>;
using OrientedBox = boxcyl::OrientedBox<double>;
// float64 arrays, converted (exactly for float32 and small integers) and made C-contiguous if needed.
using F64Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

Vec vec(const Array3& a) { return {a[0], a[1], a[2]}; }
py::tuple tuple(const Vec& v) { return py::make_tuple(v[0], v[1], v[2]); }

template <class Object>
Object validated(Object x, const char* name) {
    if (auto v = boxcyl::validate(x, name); !v) throw py::value_error(v.message());
    return x;
}

// The filter's exactness assumes gradual underflow; a library loaded into the same process may have
// set flush-to-zero (e.g. one built with -ffast-math). Checked on the thread that runs the query.
void require_fp_environment() {
    if (!boxcyl::fp_environment_ok())
        throw std::runtime_error(
            "boxcyl: the floating-point environment flushes subnormals to zero (FTZ/DAZ, often set by a "
            "library built with -ffast-math); exact answers cannot be guaranteed in it");
}

template <class Box>
bool query(const Box& box, const Cylinder& cyl, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    require_fp_environment();
    return boxcyl::intersects(box, cyl, boxcyl::QueryOptions{algorithm, arithmetic});
}

// Rows of an (M, ...) float64 array whose leading length M is the batch length or 1 (broadcast).
// Reads raw memory only, so it may be used while the GIL is released (the caller keeps the arrays).
struct Rows {
    const double* data;
    py::ssize_t count;
    py::ssize_t row_size;

    Rows(const F64Array& a, py::ssize_t row) : data(a.data()), count(a.shape(0)), row_size(row) {}
    const double* operator[](py::ssize_t i) const { return data + (count == 1 ? 0 : i) * row_size; }
};

// The common leading length (1 broadcasts; the package checks this first with better messages).
py::ssize_t batch_length(std::initializer_list<const F64Array*> arrays) {
    py::ssize_t n = 1;
    for (const F64Array* a : arrays) {
        const py::ssize_t m = a->shape(0);
        if (m != 1) {
            if (n != 1 && m != n) throw py::value_error("boxcyl: batch fields have different lengths");
            n = m;
        }
    }
    return n;
}

void require_shape(const F64Array& a, const char* name, std::initializer_list<py::ssize_t> tail) {
    bool ok = a.ndim() == static_cast<py::ssize_t>(tail.size()) + 1;
    py::ssize_t d = 1;
    for (py::ssize_t t : tail) ok = ok && a.shape(d++) == t;
    if (!ok) throw py::value_error(std::string("boxcyl: ") + name + " has the wrong shape");
}

Cylinder cylinder_at(const Rows& center, const Rows& axis, const Rows& radius, const Rows& height,
                     py::ssize_t i) {
    const double* c = center[i];
    const double* a = axis[i];
    return {{c[0], c[1], c[2]}, {a[0], a[1], a[2]}, radius[i][0], height[i][0]};
}

// "boxes[17]" for an element of an array argument, "box" for a single object broadcast.
std::string element_name(const char* singular, const char* plural, bool single, py::ssize_t i) {
    return single ? std::string(singular) : std::string(plural) + "[" + std::to_string(i) + "]";
}

// The batch loop shared by both box kinds: box_at(i) builds box i. All of it runs without the GIL.
// With one cylinder (broadcast) and the default exact query, batched(cylinder, result) answers through
// boxcyl::batch (the same exact answers, SIMD filter and threads); otherwise the scalar loop does.
template <class BoxAt, class Batched>
py::array_t<bool> run_batch(py::ssize_t n, BoxAt box_at, bool box_single, const Rows& center, const Rows& axis,
                            const Rows& radius, const Rows& height, bool cylinder_single,
                            boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic, Batched batched) {
    py::array_t<bool> out(n);
    bool* result = out.mutable_data();
    {
        py::gil_scoped_release release;
        require_fp_environment();
        // Validate every element before answering any: a short prefix keeps the field names in the
        // small-string buffer (no allocation per element); a failure is re-validated under its full name.
        for (py::ssize_t i = 0; i < n; ++i) {
            if (!boxcyl::validate(box_at(i), "").ok())
                validated(box_at(i), element_name("box", "boxes", box_single, i).c_str());
            const Cylinder cyl = cylinder_at(center, axis, radius, height, i);
            if (!boxcyl::validate(cyl, "").ok())
                validated(cyl, element_name("cylinder", "cylinders", cylinder_single, i).c_str());
        }
        if (cylinder_single && !box_single && n > 0 && algorithm == boxcyl::Algorithm::inequalities &&
            arithmetic == boxcyl::Arithmetic::filtered) {
            batched(cylinder_at(center, axis, radius, height, 0), result);
            return out;
        }
        const boxcyl::QueryOptions opt{algorithm, arithmetic};
        py::ssize_t i = 0;
        try {
            for (; i < n; ++i)
                result[i] = boxcyl::intersects(box_at(i), cylinder_at(center, axis, radius, height, i), opt);
        } catch (const std::domain_error& e) {  // e.g. exact lcp/inequalities asked for a frame not exactly orthonormal
            throw std::domain_error(element_name("box", "boxes", box_single, i) + ": " + e.what());
        }
    }
    return out;
}

py::array_t<bool> intersects_aligned(const F64Array& min, const F64Array& max, bool box_single, const F64Array& center,
                                     const F64Array& axis, const F64Array& radius, const F64Array& height,
                                     bool cylinder_single, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    require_shape(min, "min", {3});
    require_shape(max, "max", {3});
    require_shape(center, "center", {3});
    require_shape(axis, "axis", {3});
    require_shape(radius, "radius", {});
    require_shape(height, "height", {});
    const py::ssize_t n = batch_length({&min, &max, &center, &axis, &radius, &height});
    const Rows lo(min, 3), hi(max, 3);
    auto box_at = [&](py::ssize_t i) {
        const double* a = lo[i];
        const double* b = hi[i];
        return AlignedBox{{a[0], a[1], a[2]}, {b[0], b[1], b[2]}};
    };
    // The batch API takes aligned boxes as six arrays.
    auto batched = [&](const Cylinder& cyl, bool* result) {
        std::vector<double> v[6];
        for (auto& a : v) a.resize(static_cast<std::size_t>(n));
        for (py::ssize_t i = 0; i < n; ++i)
            for (int j = 0; j < 3; ++j) {
                v[j][static_cast<std::size_t>(i)] = lo[i][j];
                v[3 + j][static_cast<std::size_t>(i)] = hi[i][j];
            }
        boxcyl::batch::intersects(cyl, boxcyl::batch::AlignedBoxes<double>{v[0], v[1], v[2], v[3], v[4], v[5]},
                                  std::span<bool>(result, static_cast<std::size_t>(n)), {0});
    };
    return run_batch(n, box_at, box_single, Rows(center, 3), Rows(axis, 3), Rows(radius, 1), Rows(height, 1),
                     cylinder_single, algorithm, arithmetic, batched);
}

py::array_t<bool> intersects_oriented(const F64Array& box_center, const F64Array& axes, const F64Array& extents,
                                      bool box_single, const F64Array& center, const F64Array& axis,
                                      const F64Array& radius, const F64Array& height, bool cylinder_single,
                                      boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    require_shape(box_center, "box center", {3});
    require_shape(axes, "axes", {3, 3});
    require_shape(extents, "extents", {3});
    require_shape(center, "center", {3});
    require_shape(axis, "axis", {3});
    require_shape(radius, "radius", {});
    require_shape(height, "height", {});
    const py::ssize_t n = batch_length({&box_center, &axes, &extents, &center, &axis, &radius, &height});
    const Rows c(box_center, 3), u(axes, 9), e(extents, 3);
    auto box_at = [&](py::ssize_t i) {
        const double* p = c[i];
        const double* a = u[i];  // row k is axes[k]
        const double* x = e[i];
        return OrientedBox{{p[0], p[1], p[2]},
                           {Vec{a[0], a[1], a[2]}, Vec{a[3], a[4], a[5]}, Vec{a[6], a[7], a[8]}},
                           {x[0], x[1], x[2]}};
    };
    auto batched = [&](const Cylinder& cyl, bool* result) {
        std::vector<OrientedBox> boxes;
        boxes.reserve(static_cast<std::size_t>(n));
        for (py::ssize_t i = 0; i < n; ++i) boxes.push_back(box_at(i));
        boxcyl::batch::intersects(cyl, std::span<const OrientedBox>(boxes),
                                  std::span<bool>(result, static_cast<std::size_t>(n)), {0});
    };
    return run_batch(n, box_at, box_single, Rows(center, 3), Rows(axis, 3), Rows(radius, 1), Rows(height, 1),
                     cylinder_single, algorithm, arithmetic, batched);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "boxcyl's compiled core; use the package `boxcyl`, which re-exports it.";
    m.attr("__version__") = BOXCYL_VERSION_STRING;

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

    py::class_<OrientedBox>(m, "OrientedBox",
                            "The closed solid { center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= "
                            "extents[i] } for the axes exactly as given; they must be orthonormal to within "
                            "1e-4 (a rotation rounded to double is fine). Immutable; validated when built.")
        .def(py::init([](const Array3& center, const std::array<Array3, 3>& axes, const Array3& extents) {
                 return validated(OrientedBox{vec(center), {vec(axes[0]), vec(axes[1]), vec(axes[2])}, vec(extents)},
                                  "box");
             }),
             "center"_a, "axes"_a, "extents"_a)
        .def_property_readonly("center", [](const OrientedBox& b) { return tuple(b.center); })
        .def_property_readonly("axes",
                               [](const OrientedBox& b) {
                                   return py::make_tuple(tuple(b.axes[0]), tuple(b.axes[1]), tuple(b.axes[2]));
                               })
        .def_property_readonly("extents", [](const OrientedBox& b) { return tuple(b.extents); })
        .def("__repr__", [](const OrientedBox& b) {
            return py::str("OrientedBox(center={!r}, axes={!r}, extents={!r})")
                .format(tuple(b.center), py::make_tuple(tuple(b.axes[0]), tuple(b.axes[1]), tuple(b.axes[2])),
                        tuple(b.extents));
        });

    // The query; the package's intersects() wraps it (option names as strings, the docs).
    const char* intersects_doc = "intersects(box, cylinder, algorithm, arithmetic) -> bool, with the GIL released.";
    m.def("intersects", &query<AlignedBox>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(), intersects_doc);
    m.def("intersects", &query<OrientedBox>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(), intersects_doc);

    // Batch kernels: the package's intersects_aligned / intersects_oriented shape the arguments.
    m.def("_intersects_aligned", &intersects_aligned, "min"_a, "max"_a, "box_single"_a, "center"_a, "axis"_a,
          "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a, "arithmetic"_a);
    m.def("_intersects_oriented", &intersects_oriented, "box_center"_a, "axes"_a, "extents"_a, "box_single"_a,
          "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a, "arithmetic"_a);
    m.def("_fp_environment_ok", &boxcyl::fp_environment_ok,
          "Whether this thread's floating-point environment keeps subnormals (no FTZ/DAZ).");
}
