// _boxcyl_bench: the C++ batch API alone, timed in C++, for bench/python_batch.py to compare the
// Python batch forms with. A module of its own (python/CMakeLists.txt: boxcyl_python_bench), built
// against the compiled library; never part of the Python package.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // the cylinder's vectors

#include <array>    // the cylinder's vectors

#include <chrono>   // wall time
#include <ctime>    // clock_gettime: the process's CPU time
#include <span>     // the batch API's arguments
#include <vector>   // oriented boxes copied into OrientedBox structs

#include "boxcyl/compiled.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using Cylinder = boxcyl::Cylinder<double>;
using AlignedBox = boxcyl::AlignedBox<double>;
using OrientedBox = boxcyl::OrientedBox<double>;
using Vec = boxcyl::Vec3<double>;
using F64Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Wall-clock seconds and the process's CPU seconds (all threads) from construction to stop(): on a
// shared machine the CPU time is the steadier measure (time.process_time() is its Python side).
struct Timer {
    static double cpu_now() {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    std::chrono::steady_clock::time_point wall0 = std::chrono::steady_clock::now();
    double cpu0 = cpu_now();
    double wall = 0, cpu = 0;
    void stop() {
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        cpu = cpu_now() - cpu0;
    }
};

// The cylinder as plain numbers: boxcyl._core registers boxcyl::Cylinder<double> already (pybind11
// shares registered types between modules), and this module must not depend on it.
using Array3 = std::array<double, 3>;
Cylinder cylinder(const Array3& center, const Array3& axis, double radius, double height) {
    return {{center[0], center[1], center[2]}, {axis[0], axis[1], axis[2]}, radius, height};
}

// Runs call(result) with the GIL released and times it: (answers, wall seconds, CPU seconds).
template <class Call>
py::tuple timed(std::size_t n, Call&& call) {
    py::array_t<bool> out(static_cast<py::ssize_t>(n));
    const std::span<bool> result(out.mutable_data(), n);
    Timer timer;
    {
        py::gil_scoped_release release;
        call(result);
        timer.stop();
    }
    return py::make_tuple(out, timer.wall, timer.cpu);
}

// soa: (6, N) rows min_x, min_y, min_z, max_x, max_y, max_z.
py::tuple aligned(const F64Array& soa, const Array3& center, const Array3& axis, double radius, double height,
                  unsigned threads) {
    const Cylinder cyl = cylinder(center, axis, radius, height);
    if (soa.ndim() != 2 || soa.shape(0) != 6) throw py::value_error("soa: expected shape (6, N)");
    const auto n = static_cast<std::size_t>(soa.shape(1));
    auto row = [&](std::size_t j) { return std::span<const double>(soa.data() + j * n, n); };
    return timed(n, [&](std::span<bool> result) {
        boxcyl::batch::intersects(cyl, boxcyl::batch::AlignedBoxes<double>{row(0), row(1), row(2), row(3), row(4), row(5)},
                                  result, {threads});
    });
}

// boxes: (N, 2, 3) rows [min, max], read in place as AlignedBox<double>.
py::tuple aligned_rows(const F64Array& boxes, const Array3& center, const Array3& axis, double radius, double height,
                       unsigned threads) {
    const Cylinder cyl = cylinder(center, axis, radius, height);
    if (boxes.ndim() != 3 || boxes.shape(1) != 2 || boxes.shape(2) != 3) throw py::value_error("boxes: expected shape (N, 2, 3)");
    const auto n = static_cast<std::size_t>(boxes.shape(0));
    const auto* rows = reinterpret_cast<const AlignedBox*>(boxes.data());
    return timed(n, [&](std::span<bool> result) {
        boxcyl::batch::intersects(cyl, std::span<const AlignedBox>(rows, n), result, {threads});
    });
}

// rows: (N, 15) center, axes[0..2], extents (OrientedBox's members in order), copied into an array of
// OrientedBox before the timed call.
py::tuple oriented(const F64Array& rows, const Array3& center, const Array3& axis, double radius, double height,
                   unsigned threads) {
    const Cylinder cyl = cylinder(center, axis, radius, height);
    if (rows.ndim() != 2 || rows.shape(1) != 15) throw py::value_error("boxes: expected shape (N, 15)");
    const auto n = static_cast<std::size_t>(rows.shape(0));
    std::vector<OrientedBox> boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double* r = rows.data() + 15 * i;
        boxes[i] = {{r[0], r[1], r[2]}, {Vec{r[3], r[4], r[5]}, Vec{r[6], r[7], r[8]}, Vec{r[9], r[10], r[11]}},
                    {r[12], r[13], r[14]}};
    }
    return timed(n, [&](std::span<bool> result) {
        boxcyl::batch::intersects(cyl, std::span<const OrientedBox>(boxes), result, {threads});
    });
}

}  // namespace

PYBIND11_MODULE(_boxcyl_bench, m) {
    m.doc() = "boxcyl::batch::intersects alone, timed in C++ (bench/python_batch.py); not part of the package.";
    m.def("aligned", &aligned, "soa"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "threads"_a,
          "On (6, N) arrays: (answers, wall seconds, CPU seconds).");
    m.def("aligned_rows", &aligned_rows, "boxes"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "threads"_a,
          "On (N, 2, 3) [min, max] rows: (answers, wall seconds, CPU seconds).");
    m.def("oriented", &oriented, "boxes"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "threads"_a,
          "On (N, 15) oriented boxes: (answers, wall seconds, CPU seconds).");
}
