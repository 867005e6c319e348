// The grid query (boxcyl/grid.hpp) on a 1000³-cell grid (10^9 cells): time per query, the
// cells found, and the exact box-cylinder queries it made (its cost model: blocks pruned, cells tested).
// Brute force would make 10^9 exact queries; `cell_query/random` times one exact query on random cells
// of the grid (mostly far from the cylinder, as brute force's would be), so that its cost can be
// estimated from the same run (10^9 × that time); `cell_query/near` on the cells near the cylinder.
//
// Build: cmake -DCMAKE_BUILD_TYPE=Release -DBOXCYL_BUILD_BENCHMARKS=ON ...; target bench_grid.
// Run:   bench_grid --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Counters (per grid query): cells = cells found; queries = exact queries made (blocks, cells and the
// bounding-box range checks); cell_queries = those on single cells; queries/cell = queries ÷ cells;
// corner_inside = queries settled by a box corner inside the cylinder (no general query needed);
// blocks_inside = blocks of several cells reported whole (inside the cylinder); range_widened must be 0.
// margin_2.5_cells: for_each_cell_within, every cell within 2.5 cells of the same cylinder.
#include <benchmark/benchmark.h>

#include <cstddef>  // std::size_t
#include <cstdint>  // std::int64_t
#include <random>   // random cells for cell_query
#include <vector>   // the cells for cell_query

#include "boxcyl/grid.hpp"

namespace {

using namespace boxcyl;

const Grid kGrid{{0, 0, 0}, {1, 1, 1}, {1000, 1000, 1000}};

// Thin long cylinders: radius 2 cells, 1000 cells long, through the middle of the grid.
const Cylinder<double> kThinDiagonal{{500, 500, 500}, {1, 1, 1}, 2, 1000};             // along (1,1,1)
const Cylinder<double> kThinOblique{{500.3, 499.7, 500.1}, {0.8, 0.5, 0.33}, 2, 1000};  // a generic direction
const Cylinder<double> kThinAxisAligned{{500.5, 500.5, 500}, {0, 0, 1}, 2, 1000};       // along z, centred in a column
// For scale: a fat one (radius 20 cells, 200 long), whose inside is most of its cells.
const Cylinder<double> kFatOblique{{500.3, 499.7, 500.1}, {0.8, 0.5, 0.33}, 20, 200};

// margin > 0: the clearance form, for_each_cell_within (every cell within `margin` of the cylinder).
void grid_query(benchmark::State& state, const Cylinder<double>& c, double margin = 0) {
    GridStats last;
    for (auto _ : state) {
        GridStats s;
        std::int64_t found = 0;
        auto count = [&](std::int64_t, std::int64_t, std::int64_t) { ++found; };
        if (margin > 0)
            for_each_cell_within(kGrid, c, margin, count, &s);
        else
            for_each_cell(kGrid, c, count, &s);
        benchmark::DoNotOptimize(found);
        last = s;
    }
    state.counters["cells"] = static_cast<double>(last.cells);
    state.counters["queries"] = static_cast<double>(last.queries);
    state.counters["cell_queries"] = static_cast<double>(last.cell_queries);
    state.counters["queries/cell"] = static_cast<double>(last.queries) / static_cast<double>(last.cells);
    state.counters["corner_inside"] = static_cast<double>(last.corner_inside);
    state.counters["blocks_inside"] = static_cast<double>(last.blocks_inside);
    state.counters["range_widened"] = static_cast<double>(last.range_widened);
}

// The same, through cells(): a vector sorted lexicographically (what the CLI writes).
void grid_cells_sorted(benchmark::State& state, const Cylinder<double>& c) {
    std::size_t n = 0;
    for (auto _ : state) {
        const std::vector<CellIndex> v = cells(kGrid, c);
        n = v.size();
        benchmark::DoNotOptimize(v.data());
    }
    state.counters["cells"] = static_cast<double>(n);
}

// One exact query on a cell box. near: the found cells and their 6 face neighbours (about half hit),
// in order. random: 2^16 cells drawn uniformly from the grid (fixed seed): brute force pays this 10^9 times.
void cell_query(benchmark::State& state, const Cylinder<double>& c, bool near) {
    std::vector<AlignedBox<double>> boxes;
    if (near) {
        for (const CellIndex& cell : cells(kGrid, c))
            for (int d = 0; d < 7; ++d) {
                CellIndex n = cell;
                if (d > 0) n[static_cast<std::size_t>((d - 1) / 2)] += (d % 2) ? 1 : -1;
                boxes.push_back(cell_box(kGrid, n));
            }
    } else {
        std::mt19937_64 rng(0x6d1d0501u);
        std::uniform_int_distribution<std::int64_t> index(0, 999);
        for (int n = 0; n < (1 << 16); ++n) boxes.push_back(cell_box(kGrid, {index(rng), index(rng), index(rng)}));
    }
    std::size_t i = 0;
    std::int64_t hits = 0;
    for (auto _ : state) {
        hits += intersects(boxes[i], c);
        if (++i == boxes.size()) i = 0;
    }
    benchmark::DoNotOptimize(hits);
}

BENCHMARK_CAPTURE(grid_query, thin_diagonal, kThinDiagonal)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(grid_query, thin_oblique, kThinOblique)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(grid_query, thin_axis_aligned, kThinAxisAligned)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(grid_query, fat_oblique, kFatOblique)->Unit(benchmark::kMillisecond);
// The clearance form on the same cylinders, at a margin of 2.5 cells (beside the runs above).
BENCHMARK_CAPTURE(grid_query, thin_oblique/margin_2.5_cells, kThinOblique, 2.5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(grid_query, fat_oblique/margin_2.5_cells, kFatOblique, 2.5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(grid_cells_sorted, thin_diagonal, kThinDiagonal)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cell_query, near/thin_diagonal, kThinDiagonal, true)->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(cell_query, near/thin_oblique, kThinOblique, true)->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(cell_query, random/thin_oblique, kThinOblique, false)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
