// boxcyl::boxcyl: the grid query of boxcyl/compiled.hpp, that of boxcyl/grid.hpp compiled once here.
#include "boxcyl/grid.hpp"

// The calls into boxcyl/grid.hpp come before boxcyl/compiled.hpp is included: after it, a call
// naming boxcyl::for_each_cell or boxcyl::cells would also find the compiled ones (same signatures).
namespace {

using Callback = void (*)(void*, std::int64_t, std::int64_t, std::int64_t);

void header_for_each_cell(const boxcyl::Grid& g, const boxcyl::Cylinder<double>& c, Callback f, void* context,
                          boxcyl::GridStats* stats) {
    boxcyl::for_each_cell(
        g, c, [&](std::int64_t i, std::int64_t j, std::int64_t k) { f(context, i, j, k); }, stats);
}

std::vector<boxcyl::CellIndex> header_cells(const boxcyl::Grid& g, const boxcyl::Cylinder<double>& c,
                                            boxcyl::GridStats* stats) {
    return boxcyl::cells(g, c, stats);
}

void header_for_each_cell_within(const boxcyl::Grid& g, const boxcyl::Cylinder<double>& c, double margin, Callback f,
                                 void* context, boxcyl::GridStats* stats) {
    boxcyl::for_each_cell_within(
        g, c, margin, [&](std::int64_t i, std::int64_t j, std::int64_t k) { f(context, i, j, k); }, stats);
}

std::vector<boxcyl::CellIndex> header_cells_within(const boxcyl::Grid& g, const boxcyl::Cylinder<double>& c,
                                                   double margin, boxcyl::GridStats* stats) {
    return boxcyl::cells_within(g, c, margin, stats);
}

}  // namespace

#include "boxcyl/compiled.hpp"

namespace boxcyl::inline compiled {  // inline, as compiled.hpp declares it

void for_each_cell_erased(const Grid& g, const Cylinder<double>& c, CellCallback f, void* context,
                          GridStats* stats) {
    header_for_each_cell(g, c, f, context, stats);
}

std::vector<CellIndex> cells(const Grid& g, const Cylinder<double>& c, GridStats* stats) {
    return header_cells(g, c, stats);
}

void for_each_cell_within_erased(const Grid& g, const Cylinder<double>& c, double margin, CellCallback f,
                                 void* context, GridStats* stats) {
    header_for_each_cell_within(g, c, margin, f, context, stats);
}

std::vector<CellIndex> cells_within(const Grid& g, const Cylinder<double>& c, double margin, GridStats* stats) {
    return header_cells_within(g, c, margin, stats);
}

}  // namespace boxcyl::compiled
