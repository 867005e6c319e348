// The grid of the grid query (boxcyl/grid.hpp, whose header comment defines the cells exactly): its
// type, its cell bounds and its validation, apart from the query so that the compiled library's
// declarations (boxcyl/compiled.hpp) need nothing heavier.
#pragma once

#include <array>    // cell indices
#include <cmath>    // std::fma, std::isfinite
#include <cstddef>  // std::size_t
#include <cstdint>  // std::int64_t
#include <string>   // validation messages

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// A regular axis-aligned grid of counts[0] × counts[1] × counts[2] cells (see the header comment
// for the exact cell bounds). Valid when validate(grid).ok().
struct Grid {
    Vec3<double> origin;
    Vec3<double> cell_size;                    // > 0 per axis
    std::array<std::int64_t, 3> counts{};      // ≥ 0 per axis (0: no cells)
};

// (i, j, k): 0 ≤ index[axis] < counts[axis].
using CellIndex = std::array<std::int64_t, 3>;

// Counts up to 2^53, so that every index i (and counts itself) converts to double exactly.
inline constexpr std::int64_t max_grid_count = std::int64_t{1} << 53;

// bound(axis, i) as defined above, for 0 ≤ i ≤ counts[axis].
inline double grid_bound(const Grid& g, std::size_t axis, std::int64_t i) {
    return std::fma(static_cast<double>(i), g.cell_size[axis], g.origin[axis]);
}

// The union of the cells lo ≤ index < hi (componentwise; hi exclusive, lo < hi): one aligned box.
inline AlignedBox<double> block_box(const Grid& g, const CellIndex& lo, const CellIndex& hi) {
    return {{grid_bound(g, 0, lo[0]), grid_bound(g, 1, lo[1]), grid_bound(g, 2, lo[2])},
            {grid_bound(g, 0, hi[0]), grid_bound(g, 1, hi[1]), grid_bound(g, 2, hi[2])}};
}

// Cell (i, j, k) as a closed box.
inline AlignedBox<double> cell_box(const Grid& g, const CellIndex& c) {
    return block_box(g, c, {c[0] + 1, c[1] + 1, c[2] + 1});
}

// Names the first bad field: origin finite, cell_size finite and > 0, 0 ≤ counts ≤ 2^53, and the far
// bound origin + counts·cell_size (rounded) finite, so that every cell is a valid finite box.
inline Validity validate(const Grid& g, const std::string& prefix = "grid") {
    Validity v;
    if (!detail::check_finite(v, prefix + ".origin", g.origin)) return v;
    for (std::size_t a = 0; a < 3; ++a) {
        const std::string field = prefix + ".cell_size[" + std::to_string(a) + "]";
        if (!detail::check_finite(v, field, g.cell_size[a])) return v;
        if (!(g.cell_size[a] > 0)) return {field, "is not positive"};
    }
    for (std::size_t a = 0; a < 3; ++a) {
        const std::string field = prefix + ".counts[" + std::to_string(a) + "]";
        if (g.counts[a] < 0) return {field, "is negative"};
        if (g.counts[a] > max_grid_count) return {field, "exceeds 2^53"};
        if (!std::isfinite(grid_bound(g, a, g.counts[a])))
            return {field, "makes the far bound origin + counts*cell_size overflow the double range"};
    }
    return v;
}

// What a grid query did (for benchmarks and tests).
struct GridStats {
    std::int64_t queries = 0;         // exact box-cylinder queries made, all kinds together
    std::int64_t cell_queries = 0;    // of which on single cells
    std::int64_t cells = 0;           // cells reported
    std::int64_t range_widened = 0;   // bounding-box index ranges that the exact check had to widen
                                      // (0 unless the bounding box's margin was too small)
    std::int64_t corner_inside = 0;   // queries settled by a box corner inside the cylinder
    std::int64_t blocks_inside = 0;   // blocks of several cells found inside the cylinder, reported whole
    std::int64_t batched_cells = 0;   // cells of small blocks answered through the batch API's filter
};

}  // namespace boxcyl
