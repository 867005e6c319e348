// boxcyl._core: the pybind11 module behind the Python package `boxcyl` (python/boxcyl/__init__.py
// adds the numpy-friendly argument handling, the input policy and the docs users read first).
//
// By area: shapes.cpp (the option enums and the shape classes), poses.cpp (shapes from rotations,
// quaternions, transforms and end points), batch.cpp (the batch forms over float64 arrays), grid.cpp
// (the grid query); common.hpp is what they share, library.cpp the library code they call
// (boxcyl/compiled.hpp's double queries). This file is the module: its functions, each a thin layer
// over those areas — the scalar query, distance and signed distance, the named constructors, the
// arrays of the batch forms and batch distances, the grid — with long work run interruptibly
// (bindings.hpp).
#include <pybind11/numpy.h>  // input arrays, bool and int64 output arrays
#include <pybind11/stl.h>    // std::array <-> Python sequences

#include <algorithm>         // std::max
#include <initializer_list>  // the fields of a batch
#include <optional>          // a batch's margin
#include <thread>            // std::thread::hardware_concurrency

#include "bindings.hpp"
#include "boxcyl/margin.hpp"
#include "boxcyl/version.hpp"

namespace boxcyl_python {

using namespace pybind11::literals;

namespace {

// ---- The scalar query; the package's intersects() checks the argument types and wraps it. ----

template <class Box>
bool query(const Box& box, const Cylinder& cyl, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    require_fp_environment();
    return boxcyl::intersects(box, cyl, boxcyl::QueryOptions{algorithm, arithmetic});
}

template <class Box>
bool clearance(const Box& box, const Cylinder& cyl, double margin) {
    require_fp_environment();
    return boxcyl::within_distance(box, cyl, margin);
}

// (lower, upper, on_box, on_cylinder); the package's distance() names them.
template <class Box>
py::tuple distance(const Box& box, const Cylinder& cyl) {
    boxcyl::Distance d;
    {
        py::gil_scoped_release release;
        require_fp_environment();
        d = boxcyl::distance(box, cyl);
    }
    return py::make_tuple(d.lower, d.upper, tuple(d.on_box), tuple(d.on_cylinder));
}

// (lower, upper, normal, on_box, on_cylinder); the package's signed_distance() names them.
template <class Box>
py::tuple signed_distance(const Box& box, const Cylinder& cyl) {
    boxcyl::SignedDistance d;
    {
        py::gil_scoped_release release;
        require_fp_environment();
        d = boxcyl::signed_distance(box, cyl);
    }
    return py::make_tuple(d.lower, d.upper, tuple(d.normal), tuple(d.on_box), tuple(d.on_cylinder));
}

template <class Box>
void def_intersects(py::module_& m) {
    m.def("intersects", &query<Box>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(),
          "intersects(box, cylinder, algorithm, arithmetic) -> bool, with the GIL released.");
    m.def("within_distance", &clearance<Box>, "box"_a, "cylinder"_a, "margin"_a, py::call_guard<py::gil_scoped_release>(),
          "within_distance(box, cylinder, margin) -> bool (exact), with the GIL released.");
    m.def("distance", &distance<Box>, "box"_a, "cylinder"_a,
          "distance(box, cylinder) -> (lower, upper, on_box, on_cylinder), proved bounds, with the GIL released.");
    m.def("signed_distance", &signed_distance<Box>, "box"_a, "cylinder"_a,
          "signed_distance(box, cylinder) -> (lower, upper, normal, on_box, on_cylinder), proved bounds, with the "
          "GIL released.");
}

// ---- The batch forms' arrays: float64, shape (M, *tail), M = N or 1; the package shapes them. ----

Field field(const py::array& a, const char* name, std::initializer_list<Index> tail) {
    // The package passes float64 arrays of these shapes; anything else is its bug, said plainly.
    bool ok = py::isinstance<py::array_t<double>>(a) && a.ndim() == static_cast<Index>(tail.size()) + 1;
    Index d = 1;
    for (Index t : tail) ok = ok && a.shape(d++) == t;
    if (!ok) throw py::value_error(std::string("boxcyl: internal: ") + name + " is not a float64 array of the expected shape");
    Field f;
    f.base = static_cast<const char*>(a.data());
    f.count = a.shape(0);
    f.step = f.count == 1 ? 0 : a.strides(0);
    if (tail.size() == 1) {
        for (Index k = 0; k < a.shape(1); ++k) f.offset[static_cast<std::size_t>(k)] = k * a.strides(1);
    } else if (tail.size() == 2) {
        for (Index r = 0; r < a.shape(1); ++r)
            for (Index c = 0; c < a.shape(2); ++c)
                f.offset[static_cast<std::size_t>(r * a.shape(2) + c)] = r * a.strides(1) + c * a.strides(2);
    }
    return f;
}

// The common leading length (1 broadcasts; the package checks this first with better messages).
Index batch_length(std::initializer_list<const Field*> fields) {
    Index n = 1;
    for (const Field* f : fields)
        if (f->count != 1) {
            if (n != 1 && f->count != n) throw py::value_error("boxcyl: internal: batch fields have different lengths");
            n = f->count;
        }
    return n;
}

CylinderFields cylinder_fields(const py::array& center, const py::array& axis, const py::array& radius,
                               const py::array& height) {
    return {field(center, "center", {3}), field(axis, "axis", {3}), field(radius, "radius", {}),
            field(height, "height", {})};
}

template <class Boxes>
py::array_t<bool> run_batch(const Boxes& boxes, const CylinderFields& cylinders, Index n, bool box_single,
                            bool cylinder_single, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic,
                            unsigned threads, std::optional<double> margin) {
    if (margin && !boxcyl::is_valid_margin(*margin)) throw py::value_error(boxcyl::validate_margin(*margin).message());
    if (box_single) validated(boxes(0), "box");
    if (cylinder_single) validated(cylinders(0), "cylinder");
    py::array_t<bool> out(n);
    const Batch b{n, box_single, cylinder_single, {algorithm, arithmetic}, threads, out.mutable_data(), margin};
    std::string failure;
    run_interruptibly(brief(b), [&](const std::stop_token& stop) { failure = intersects(boxes, cylinders, b, stop); });
    if (!failure.empty()) throw py::value_error(failure);
    return out;
}

py::array_t<bool> intersects_aligned(const py::array& min, const py::array& max, bool box_single,
                                     const py::array& center, const py::array& axis, const py::array& radius,
                                     const py::array& height, bool cylinder_single, boxcyl::Algorithm algorithm,
                                     boxcyl::Arithmetic arithmetic, unsigned threads, std::optional<double> margin) {
    const AlignedFields boxes{field(min, "min", {3}), field(max, "max", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length({&boxes.min, &boxes.max, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    return run_batch(boxes, cyls, n, box_single, cylinder_single, algorithm, arithmetic, threads, margin);
}

template <class Box>
py::array_t<bool> intersects_frames(const py::array& box_center, const py::array& axes, const py::array& extents,
                                    bool box_single, const py::array& center, const py::array& axis,
                                    const py::array& radius, const py::array& height, bool cylinder_single,
                                    boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic, unsigned threads,
                                    std::optional<double> margin) {
    const FrameFields<Box> boxes{field(box_center, "box center", {3}), field(axes, "axes", {3, 3}),
                                 field(extents, "extents", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length(
        {&boxes.center, &boxes.axes, &boxes.extents, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    return run_batch(boxes, cyls, n, box_single, cylinder_single, algorithm, arithmetic, threads, margin);
}

// ---- The batch distances: (lower, upper, on_box, on_cylinder) arrays of shapes (N,), (N,), (N, 3), (N, 3); ----
// ---- signed (Signed = true): (lower, upper, normal, on_box, on_cylinder), normal of shape (N, 3). ----

template <bool Signed, class Boxes>
py::tuple run_distances(const Boxes& boxes, const CylinderFields& cylinders, Index n, bool box_single,
                        bool cylinder_single, unsigned threads) {
    if (box_single) validated(boxes(0), "box");
    if (cylinder_single) validated(cylinders(0), "cylinder");
    py::array_t<double> lower(n), upper(n), on_box({n, Index{3}}), on_cylinder({n, Index{3}});
    py::array_t<double> normal({Signed ? n : Index{0}, Index{3}});
    const DistanceBatch b{n,
                          box_single,
                          cylinder_single,
                          threads,
                          lower.mutable_data(),
                          upper.mutable_data(),
                          on_box.mutable_data(),
                          on_cylinder.mutable_data(),
                          Signed ? normal.mutable_data() : nullptr};
    std::string failure;
    run_interruptibly(brief(b), [&](const std::stop_token& stop) { failure = distances(boxes, cylinders, b, stop); });
    if (!failure.empty()) throw py::value_error(failure);
    if constexpr (Signed)
        return py::make_tuple(lower, upper, normal, on_box, on_cylinder);
    else
        return py::make_tuple(lower, upper, on_box, on_cylinder);
}

template <bool Signed>
py::tuple distances_aligned(const py::array& min, const py::array& max, bool box_single, const py::array& center,
                            const py::array& axis, const py::array& radius, const py::array& height,
                            bool cylinder_single, unsigned threads) {
    const AlignedFields boxes{field(min, "min", {3}), field(max, "max", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length({&boxes.min, &boxes.max, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    return run_distances<Signed>(boxes, cyls, n, box_single, cylinder_single, threads);
}

template <bool Signed, class Box>
py::tuple distances_frames(const py::array& box_center, const py::array& axes, const py::array& extents,
                           bool box_single, const py::array& center, const py::array& axis, const py::array& radius,
                           const py::array& height, bool cylinder_single, unsigned threads) {
    const FrameFields<Box> boxes{field(box_center, "box center", {3}), field(axes, "axes", {3, 3}),
                                 field(extents, "extents", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length(
        {&boxes.center, &boxes.axes, &boxes.extents, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    return run_distances<Signed>(boxes, cyls, n, box_single, cylinder_single, threads);
}

// ---- The grid query: an (M, 3) int64 array of cell indices. ----

py::array_t<std::int64_t> cells_of(const Array3& origin, const Array3& cell_size, const std::array<std::int64_t, 3>& counts,
                                   const Cylinder& cylinder, double margin, std::int64_t max_cells) {
    const boxcyl::Grid grid{vec(origin), vec(cell_size), counts};
    std::vector<boxcyl::CellIndex> cells;
    // A walk is short when the grid has few cells (a few exact queries each at most).
    const double total = static_cast<double>(counts[0]) * static_cast<double>(counts[1]) * static_cast<double>(counts[2]);
    run_interruptibly(total <= 4096, [&](const std::stop_token& stop) { cells = grid_cells(grid, cylinder, margin, max_cells, stop); });
    py::array_t<std::int64_t> out({static_cast<py::ssize_t>(cells.size()), py::ssize_t{3}});
    auto o = out.mutable_unchecked<2>();
    for (std::size_t n = 0; n < cells.size(); ++n)
        for (py::ssize_t a = 0; a < 3; ++a) o(static_cast<py::ssize_t>(n), a) = cells[n][static_cast<std::size_t>(a)];
    return out;
}

}  // namespace

}  // namespace boxcyl_python

PYBIND11_MODULE(_core, m) {
    using namespace boxcyl_python;
    m.doc() = "boxcyl's compiled core; use the package `boxcyl`, which re-exports it.";
    m.attr("__version__") = BOXCYL_VERSION_STRING;
    def_shapes(m);  // the classes first, so that the functions' signatures name them

    def_intersects<AlignedBox>(m);
    def_intersects<OrientedBox>(m);
    def_intersects<Parallelepiped>(m);

    // The named constructors' cores (the package's classmethods convert and name the arguments).
    m.def("_box_from_rotation", &box_from_rotation);
    m.def("_box_from_quaternion", &box_from_quaternion);
    m.def("_box_from_transform", &box_from_transform);
    m.def("_parallelepiped_from_transform", &parallelepiped_from_transform);
    m.def("_cylinder_from_rotation", &cylinder_from_rotation);
    m.def("_cylinder_from_quaternion", &cylinder_from_quaternion);
    m.def("_cylinder_from_transform", &cylinder_from_transform);
    m.def("_cylinder_between", &cylinder_between);

    // The batch kernels: the package's intersects_aligned etc. shape the arguments.
    m.def("_intersects_aligned", &intersects_aligned, "min"_a, "max"_a, "box_single"_a, "center"_a, "axis"_a,
          "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a, "arithmetic"_a, "threads"_a, "margin"_a);
    m.def("_intersects_oriented", &intersects_frames<OrientedBox>, "box_center"_a, "axes"_a, "extents"_a,
          "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a,
          "arithmetic"_a, "threads"_a, "margin"_a);
    m.def("_intersects_parallelepiped", &intersects_frames<Parallelepiped>, "box_center"_a, "axes"_a, "extents"_a,
          "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a,
          "arithmetic"_a, "threads"_a, "margin"_a);

    // The batch distances and signed distances: the package's distances_aligned etc. shape the arguments.
    m.def("_distances_aligned", &distances_aligned<false>, "min"_a, "max"_a, "box_single"_a, "center"_a, "axis"_a,
          "radius"_a, "height"_a, "cylinder_single"_a, "threads"_a);
    m.def("_distances_oriented", &distances_frames<false, OrientedBox>, "box_center"_a, "axes"_a, "extents"_a,
          "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "threads"_a);
    m.def("_distances_parallelepiped", &distances_frames<false, Parallelepiped>, "box_center"_a, "axes"_a,
          "extents"_a, "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "threads"_a);
    m.def("_signed_distances_aligned", &distances_aligned<true>, "min"_a, "max"_a, "box_single"_a, "center"_a,
          "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "threads"_a);
    m.def("_signed_distances_oriented", &distances_frames<true, OrientedBox>, "box_center"_a, "axes"_a, "extents"_a,
          "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "threads"_a);
    m.def("_signed_distances_parallelepiped", &distances_frames<true, Parallelepiped>, "box_center"_a, "axes"_a,
          "extents"_a, "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "threads"_a);

    m.def("_grid_cells", &cells_of, "origin"_a, "cell_size"_a, "counts"_a, "cylinder"_a, "margin"_a, "max_cells"_a,
          "The cells (i, j, k) of the grid within `margin` of the cylinder (0: that it meets), sorted; "
          "max_cells < 0: no limit.");

    m.def("_hardware_threads", [] { return std::max(1u, std::thread::hardware_concurrency()); },
          "The number of threads `threads=None` (or 0) uses at most.");
    m.def("_fp_environment_ok", &boxcyl::fp_environment_ok,
          "Whether this thread's floating-point environment keeps subnormals (no FTZ/DAZ).");
}
