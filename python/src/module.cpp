// boxcyl._core: the pybind11 bindings behind the Python package `boxcyl` (python/boxcyl/__init__.py
// adds the numpy-friendly argument handling, the input policy and the docs users read first).
//
// By area: shapes.cpp (the option enums and the shapes), poses.cpp (shapes from rotations,
// quaternions, transforms and end points), this file (the scalar query), batch.cpp (the batch forms
// over float64 arrays), grid.cpp (the grid query); common.hpp is what they share, library.cpp the
// library code they call (boxcyl/compiled.hpp's double queries).
#include <algorithm>  // std::max
#include <thread>     // std::thread::hardware_concurrency

#include "boxcyl/version.hpp"
#include "common.hpp"

namespace boxcyl_python {

using namespace pybind11::literals;

namespace {

template <class Box>
bool query(const Box& box, const Cylinder& cyl, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    require_fp_environment();
    return boxcyl::intersects(box, cyl, boxcyl::QueryOptions{algorithm, arithmetic});
}

template <class Box>
void def_intersects(py::module_& m) {
    m.def("intersects", &query<Box>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(),
          "intersects(box, cylinder, algorithm, arithmetic) -> bool, with the GIL released.");
}

}  // namespace

// The package's intersects() checks the argument types and wraps these.
void def_query(py::module_& m) {
    def_intersects<AlignedBox>(m);
    def_intersects<OrientedBox>(m);
    def_intersects<Parallelepiped>(m);
}

}  // namespace boxcyl_python

PYBIND11_MODULE(_core, m) {
    using namespace boxcyl_python;
    m.doc() = "boxcyl's compiled core; use the package `boxcyl`, which re-exports it.";
    m.attr("__version__") = BOXCYL_VERSION_STRING;
    def_shapes(m);
    def_poses(m);
    def_query(m);
    def_batch(m);
    def_grid(m);
    m.def("_hardware_threads", [] { return std::max(1u, std::thread::hardware_concurrency()); },
          "The number of threads `threads=None` (or 0) uses at most.");
    m.def("_fp_environment_ok", &boxcyl::fp_environment_ok,
          "Whether this thread's floating-point environment keeps subnormals (no FTZ/DAZ).");
}
