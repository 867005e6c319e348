// The grid query: the cells of a regular axis-aligned grid that a cylinder intersects, exactly
// (boxcyl/grid.hpp defines the cells: closed boxes with bounds fma(i, cell_size, origin)), as an
// (M, 3) int64 array in lexicographic order — the cells of C++'s boxcyl::cells and the CLI's
// `boxcyl grid`.
#include <pybind11/numpy.h>  // the cells' array
#include <pybind11/stl.h>    // std::array <-> Python sequences

#include <algorithm>  // std::sort
#include <cstdint>    // std::int64_t
#include <vector>     // the cells as they are found

#include "common.hpp"

namespace boxcyl_python {

using namespace pybind11::literals;

namespace {

// Thrown out of the walk when the answer would exceed max_cells.
struct TooManyCells {};
// Thrown out of the walk when a stop is requested (Ctrl-C).
struct Stopped {};

py::array_t<std::int64_t> grid_cells(const Array3& origin, const Array3& cell_size, const std::array<std::int64_t, 3>& counts,
                                     const Cylinder& cylinder, std::int64_t max_cells) {
    const boxcyl::Grid grid{vec(origin), vec(cell_size), counts};
    if (const boxcyl::Validity v = boxcyl::validate(grid); !v.ok()) throw py::value_error(v.message());
    std::vector<boxcyl::CellIndex> cells;
    bool too_many = false;
    // A walk is short when the grid has few cells (a few exact queries each at most).
    const bool brief = static_cast<double>(counts[0]) * static_cast<double>(counts[1]) * static_cast<double>(counts[2]) <= 4096;
    run_interruptibly(brief, [&](std::stop_token stop) {
        try {
            boxcyl::for_each_cell(grid, cylinder, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
                if (stop.stop_requested()) throw Stopped();
                if (max_cells >= 0 && static_cast<std::int64_t>(cells.size()) == max_cells) throw TooManyCells();
                cells.push_back({i, j, k});
            });
        } catch (const TooManyCells&) {
            too_many = true;
        }
    });
    if (too_many)
        throw py::value_error("grid_cells: the answer has more than max_cells = " + std::to_string(max_cells) + " cells");
    std::sort(cells.begin(), cells.end());
    py::array_t<std::int64_t> out({static_cast<Index>(cells.size()), Index{3}});
    auto o = out.mutable_unchecked<2>();
    for (std::size_t n = 0; n < cells.size(); ++n)
        for (Index a = 0; a < 3; ++a) o(static_cast<Index>(n), a) = cells[n][static_cast<std::size_t>(a)];
    return out;
}

}  // namespace

void def_grid(py::module_& m) {
    m.def("_grid_cells", &grid_cells, "origin"_a, "cell_size"_a, "counts"_a, "cylinder"_a, "max_cells"_a,
          "The cells (i, j, k) of the grid that the cylinder meets, sorted; max_cells < 0: no limit.");
}

}  // namespace boxcyl_python
