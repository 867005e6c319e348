// The grid query: the cells of a regular axis-aligned grid that a cylinder intersects, exactly
// (boxcyl/grid.hpp defines the cells: closed boxes with bounds fma(i, cell_size, origin)), in
// lexicographic order — the cells of C++'s boxcyl::cells and the CLI's `boxcyl grid`.
#include <algorithm>  // std::sort

#include "common.hpp"

namespace boxcyl_python {

namespace {
// Thrown out of the walk when the answer would exceed max_cells.
struct TooManyCells {};
}  // namespace

std::vector<boxcyl::CellIndex> grid_cells(const boxcyl::Grid& grid, const Cylinder& cylinder, double margin,
                                          std::int64_t max_cells, const std::stop_token& stop) {
    if (const boxcyl::Validity v = boxcyl::validate(grid); !v.ok()) throw std::invalid_argument(v.message());
    std::vector<boxcyl::CellIndex> cells;
    try {
        auto keep = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
            if (stop.stop_requested()) throw boxcyl::batch::Stopped();
            if (max_cells >= 0 && static_cast<std::int64_t>(cells.size()) == max_cells) throw TooManyCells();
            cells.push_back({i, j, k});
        };
        if (margin == 0)
            boxcyl::for_each_cell(grid, cylinder, keep);
        else
            boxcyl::for_each_cell_within(grid, cylinder, margin, keep);  // refuses a bad margin
    } catch (const TooManyCells&) {
        throw std::invalid_argument("grid_cells: the answer has more than max_cells = " + std::to_string(max_cells) +
                                    " cells");
    }
    std::sort(cells.begin(), cells.end());
    return cells;
}

}  // namespace boxcyl_python
