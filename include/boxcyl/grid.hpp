// Grid query: every cell of a regular axis-aligned grid that a cylinder intersects, exactly.
//
// The grid's cells are closed boxes whose bounds are doubles, defined once here and used everywhere:
//
//   bound(axis, i) = origin[axis] + i·cell_size[axis], rounded ONCE to the nearest double
//                    (std::fma(i, cell_size, origin): the product is not rounded separately),
//   cell (i, j, k) = the closed AlignedBox [bound(0,i), bound(0,i+1)] × [bound(1,j), bound(1,j+1)]
//                                         × [bound(2,k), bound(2,k+1)],   0 ≤ i < counts[0], ...
//
// Rounding is monotone, so the bounds never decrease with i, adjacent cells share their face exactly
// and the cells tile the grid's box [bound(·,0), bound(·,counts)] without gaps. (A cell may be flat
// where cell_size is below the spacing of the doubles near origin; it is then a flat box.) "Exact"
// means: a cell is reported if and only if boxcyl::intersects(cell_box(grid, cell), cylinder) — the
// exact default query, closed solids, touching counts — is true for that box.
//
// Cost: the query walks a subdivision of the cell index ranges, starting from the cells that can
// meet the cylinder's bounding box, and discards a whole block of cells with one exact query when the
// block's box (the union of its cells, itself an aligned box with the same bounds) misses the
// cylinder. That is exact: a cylinder that misses the union misses every cell of it. A block that
// meets the cylinder is halved along its longest side, down to single cells; when its lower half
// misses, its upper half meets the cylinder without asking (the halves tile the block). A block whose
// eight corners all lie in the closed cylinder (an exact test: plain double where its operands make it
// exact, else intervals, else rationals) lies inside it, cylinder and box being convex, and all its
// cells are reported without descending. A block of at most 512 cells, or of up to 8192 that the
// cylinder may fill half of, is answered cell by cell through the batch API (batch.hpp), whose SIMD
// filter decides most cells near the surface far cheaper than exact queries would. The number of exact queries
// therefore grows with the number of cells near the cylinder's surface (times a logarithmic factor for
// the descent), not with the grid's size nor with the cylinder's volume.
//
// The bounding box is computed in double with a generous margin, and the index range it gives is
// then confirmed by exact queries on the excluded slabs of cells (at most six), so a rounding slip in
// the bounding box could cost time (GridStats::range_widened), never a missed cell.
//
// The query needs the exact backend (link boxcyl::exact, which defines BOXCYL_HAS_EXACT), like the
// default query; the grid itself (Grid, grid_bound, cell_box, validate: boxcyl/grid_types.hpp) does not.
#pragma once

// With the compiled library (boxcyl::boxcyl, which defines neither macro) this header is its
// declarations of the same grid query: the same calls, compiled in libboxcyl.
#if !defined(BOXCYL_HAS_EXACT) && !defined(BOXCYL_HEADER_ONLY)
#include "boxcyl/compiled.hpp"
#else

#include <algorithm>  // std::max, std::sort, std::fill_n, std::copy_n
#include <bit>        // std::countr_zero
#include <array>      // cell indices
#include <cassert>    // debug-build precondition checks
#include <cmath>      // std::fma, std::hypot, std::ldexp, std::nextafter, std::ilogb
#include <cstddef>    // std::size_t
#include <cstdint>    // std::int64_t
#include <cstring>    // std::memcpy
#include <numbers>    // std::numbers::pi
#include <limits>     // infinities, denorm_min
#include <optional>   // exact::inside_exactly's answer
#include <span>       // the batch API's columns
#include <stdexcept>  // a bad margin
#include <string>     // validation messages
#include <type_traits>  // std::remove_reference_t
#include <utility>    // std::forward
#include <vector>     // cells()

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/grid_types.hpp"
#include "boxcyl/batch.hpp"
#include "boxcyl/query.hpp"
#include "boxcyl/clearance.hpp"  // for_each_cell_within
#include "boxcyl/number/interval.hpp"
#if defined(BOXCYL_HAS_EXACT)
#include "boxcyl/exact/point.hpp"
#include "boxcyl/number/rational.hpp"
#endif

namespace boxcyl {

namespace detail {

// Smallest i in [lo, hi) with pred(i), or hi if none; pred must be monotone (false…false true…true).
template <class Pred>
std::int64_t first_true(std::int64_t lo, std::int64_t hi, Pred pred) {
    while (lo < hi) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        if (pred(mid))
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

// Per axis, an interval [lo, hi] of doubles containing the cylinder (its bounding box, enlarged).
// The exact half-extent along axis i is h/2·|u_i| + r·sqrt(1 − u_i²) with u = axis/|axis|; it is
// evaluated without cancellation (sqrt(1 − u_i²) = |(a_j, a_k)|/|a|), on the axis scaled by a power of
// two (exact, except for components below 2^-1074 of the largest, whose share is below the absolute
// margin), so every term has a relative error of a few ulps: the factor 1 + 2^-40, the absolute
// margin and the outward nextafter cover that many times over. An overflow gives ±Inf: no clipping.
inline std::array<std::array<double, 2>, 3> cylinder_bounds(const Cylinder<double>& c) {
    const double m = std::max({std::fabs(c.axis[0]), std::fabs(c.axis[1]), std::fabs(c.axis[2])});
    const int e = std::ilogb(m);
    const Vec3<double> a{std::ldexp(c.axis[0], -e), std::ldexp(c.axis[1], -e), std::ldexp(c.axis[2], -e)};
    const double n = std::hypot(a[0], a[1], a[2]);
    const double margin = std::ldexp(c.radius, -1000) + std::ldexp(c.height, -1000) +
                          std::numeric_limits<double>::denorm_min();
    std::array<std::array<double, 2>, 3> b{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double along = std::fabs(a[i]) / n;
        const double across = std::hypot(a[(i + 1) % 3], a[(i + 2) % 3]) / n;
        double ext = 0.5 * c.height * along + c.radius * across;
        ext = ext * (1 + 0x1p-40) + margin;
        constexpr double inf = std::numeric_limits<double>::infinity();
        b[i] = {std::nextafter(c.center[i] - ext, -inf), std::nextafter(c.center[i] + ext, inf)};
        if (std::isnan(b[i][0]) || std::isnan(b[i][1])) b[i] = {-inf, inf};
    }
    return b;
}

// Whether the point p lies in the closed cylinder, in double, by a relative margin of 2^-20 on each
// comparison: a cheap screen (it may say false for points inside; never relied on for a true).
inline bool likely_inside(const Vec3<double>& p, const Cylinder<double>& c) {
    const Vec3<double> d = p - c.center;
    const double n2 = dot(c.axis, c.axis);
    const double ad = dot(c.axis, d);
    const double slack = 1 - 0x1p-20;
    // |u·d| ≤ h/2 and |d|² − (u·d)² ≤ r², multiplied by |a|² (no division, no sqrt).
    return 4 * ad * ad <= slack * (c.height * c.height * n2) &&
           n2 * dot(d, d) - ad * ad <= slack * (c.radius * c.radius * n2);
}

}  // namespace detail

#if defined(BOXCYL_HAS_EXACT)  // the query itself needs the exact backend

namespace detail {

// The same test in number type N (Interval: certified bounds; Rational: exact) on the values the
// doubles denote.
template <class N>
bool inside_in(const Vec3<double>& p, const Cylinder<double>& c) {
    const Vec3<N> a{N(c.axis[0]), N(c.axis[1]), N(c.axis[2])};
    const Vec3<N> d{N(p[0]) - N(c.center[0]), N(p[1]) - N(c.center[1]), N(p[2]) - N(c.center[2])};
    const N n2 = dot(a, a);
    const N ad = dot(a, d);
    const N h(c.height);
    const N r(c.radius);
    return N(4) * ad * ad <= h * h * n2 && n2 * dot(d, d) - ad * ad <= r * r * n2;
}

// Whether p lies in the closed cylinder, exactly: plain double where the operands make it exact (a
// grid's corners touching the cylinder, exact/point.hpp), else intervals where they decide, else
// rationals.
inline bool inside(const Vec3<double>& p, const Cylinder<double>& c) {
    if (const std::optional<bool> r = exact::inside_exactly(p, c)) return *r;
    {
        UncertaintyScope scope;
        const bool r = inside_in<Interval>(p, c);
        if (scope.certain()) return r;
    }
    return inside_in<Rational>(p, c);
}

// What a walk reports: the cells that meet `cylinder` (margin 0) or come within `margin` of it. The
// walk descends on `bound`, a cylinder holding every point it reports (the cylinder itself, or the
// clearance query's outer probe: a block that misses it has nothing to report), and reports a block
// whole when its corners lie in `inside`, a cylinder held by what it reports (the cylinder itself, or
// the fat probe, inside the rounded cylinder). Small blocks are answered by the batch API's form of the
// same question.
struct GridTarget {
    const Cylinder<double>& cylinder;
    double margin;
    const Cylinder<double>& bound;
    const Cylinder<double>& inside;
};

template <class F>
class GridWalk {
public:
    GridWalk(const Grid& g, const GridTarget& t, F& f, GridStats& s) : g_(g), t_(t), c_(t.bound), f_(f), s_(s) {}

    void run() {
        for (std::size_t a = 0; a < 3; ++a)
            if (g_.counts[a] == 0) return;
        const CellIndex all = g_.counts;
        // Candidate cells per axis: those whose extent along the axis meets the bounding box's.
        const auto bb = cylinder_bounds(c_);
        CellIndex lo{}, hi{};
        for (std::size_t a = 0; a < 3; ++a) {
            const std::int64_t n = all[a];
            // Cell i is a candidate iff bound(i+1) ≥ bb.lo and bound(i) ≤ bb.hi.
            lo[a] = first_true(0, n, [&](std::int64_t i) { return grid_bound(g_, a, i + 1) >= bb[a][0]; });
            hi[a] = first_true(0, n, [&](std::int64_t i) { return grid_bound(g_, a, i) > bb[a][1]; });
        }
        // Confirm exactly that the cells left out meet nothing; otherwise keep them (see the top).
        for (std::size_t a = 0; a < 3; ++a) {
            if (lo[a] > 0) {
                CellIndex h = all;
                h[a] = lo[a];
                if (hits({0, 0, 0}, h)) {
                    lo[a] = 0;
                    ++s_.range_widened;
                }
            }
            if (hi[a] < all[a]) {
                CellIndex l{0, 0, 0};
                l[a] = hi[a];
                if (hits(l, all)) {
                    hi[a] = all[a];
                    ++s_.range_widened;
                }
            }
        }
        for (std::size_t a = 0; a < 3; ++a)
            if (lo[a] >= hi[a]) return;
        if (hits(lo, hi)) walk(lo, hi);
    }

private:
    // One exact query on the block lo ≤ index < hi. A corner of the box inside the cylinder settles it
    // (exactly, see inside()) for a fraction of the general query's cost; most cells and blocks that
    // meet a cylinder a few cells thick have one, and the general query is slowest on exactly those
    // degenerate cells whose corners lie on the cylinder's axis.
    bool hits(const CellIndex& lo, const CellIndex& hi) {
        ++s_.queries;
        if (hi[0] - lo[0] == 1 && hi[1] - lo[1] == 1 && hi[2] - lo[2] == 1) ++s_.cell_queries;
        const AlignedBox<double> b = block_box(g_, lo, hi);
        for (std::size_t m = 0; m < 8; ++m) {
            const Vec3<double> p = corner(b, m);
            if (likely_inside(p, c_) && inside(p, c_)) {
                ++s_.corner_inside;
                return true;
            }
        }
        // The exact default itself (what intersects_unchecked(b, c_) runs), called directly: blocks of a
        // valid grid are valid (checked once, up front), and a translation unit that compiles the grid
        // query then instantiates the pipeline alone, not every algorithm the options could choose.
        return filtered::query(b, c_).intersect;
    }

    static Vec3<double> corner(const AlignedBox<double>& b, std::size_t m) {
        return {(m & 1) ? b.max[0] : b.min[0], (m & 2) ? b.max[1] : b.min[1], (m & 4) ? b.max[2] : b.min[2]};
    }

    // Whether the block lo ≤ index < hi lies inside the target's `inside` cylinder: its 8 corners do
    // (both are convex).
    bool block_inside(const CellIndex& lo, const CellIndex& hi) const {
        const AlignedBox<double> b = block_box(g_, lo, hi);
        std::array<Vec3<double>, 8> corners;
        for (std::size_t m = 0; m < 8; ++m) {
            corners[m] = corner(b, m);
            if (!likely_inside(corners[m], t_.inside)) return false;
        }
        for (const Vec3<double>& p : corners)
            if (!inside(p, t_.inside)) return false;
        return true;
    }

    // Whether the cylinder (`bound`) may fill half the block or more: the volume of a piece of it as long
    // as the block's diagonal (or the whole, if shorter) against the block's, on blocks at least
    // kDenseSide cells thick (a thin cylinder along a grid axis fills its narrow blocks, whose halves
    // are then often inside it whole). A speed hint only.
    bool dense(const CellIndex& lo, const CellIndex& hi) const {
        double volume = 1, diagonal2 = 0;
        for (std::size_t a = 0; a < 3; ++a)
            if (hi[a] - lo[a] < kDenseSide) return false;
        for (std::size_t a = 0; a < 3; ++a) {
            const double side = static_cast<double>(hi[a] - lo[a]) * g_.cell_size[a];
            volume *= side, diagonal2 += side * side;
        }
        const double piece = std::numbers::pi * c_.radius * c_.radius * std::min(c_.height, std::sqrt(diagonal2));
        return piece >= 0.5 * volume;
    }

    // Precondition: the block is non-empty and its box meets the cylinder.
    void walk(const CellIndex& lo, const CellIndex& hi) {
        // Halve the side that is longest in space (ties: the lower axis), so blocks stay compact.
        std::size_t axis = 3;
        double longest = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const std::int64_t n = hi[a] - lo[a];
            if (n < 2) continue;
            const double len = static_cast<double>(n) * g_.cell_size[a];
            if (axis == 3 || len > longest) {
                axis = a;
                longest = len;
            }
        }
        if (axis == 3) {  // a single cell, and it meets `bound`: for a margin, asked
            if (t_.margin > 0) {
                ++s_.queries, ++s_.cell_queries;
                if (!within_distance_unchecked(block_box(g_, lo, hi), t_.cylinder, t_.margin)) return;
            }
            ++s_.cells;
            f_(lo[0], lo[1], lo[2]);
            return;
        }
        const std::int64_t n0 = hi[0] - lo[0], n1 = hi[1] - lo[1], n2 = hi[2] - lo[2];
        const bool small = n0 <= kBatchSide && n1 <= kBatchSide && n2 <= kBatchSide;  // n0·n1·n2 cannot overflow
        const std::int64_t n = small ? n0 * n1 * n2 : 0;
        if (small && n <= kBatchAlways) {
            batched(lo, hi, n);
            return;
        }
        if (block_inside(lo, hi)) {
            ++s_.blocks_inside;
            for (std::int64_t i = lo[0]; i < hi[0]; ++i)
                for (std::int64_t j = lo[1]; j < hi[1]; ++j)
                    for (std::int64_t k = lo[2]; k < hi[2]; ++k) {
                        ++s_.cells;
                        f_(i, j, k);
                    }
            return;
        }
        if (small && (n <= kBatchCells || (n <= kBatchDense && dense(lo, hi)))) {
            batched(lo, hi, n);
            return;
        }
        const std::int64_t mid = lo[axis] + (hi[axis] - lo[axis]) / 2;
        CellIndex lower_hi = hi;
        lower_hi[axis] = mid;
        CellIndex upper_lo = lo;
        upper_lo[axis] = mid;
        const bool lower = hits(lo, lower_hi);
        if (lower) walk(lo, lower_hi);
        // The halves tile the block, whose box meets the cylinder: if the lower misses, the upper meets it.
        if (!lower || hits(upper_lo, hi)) walk(upper_lo, hi);
    }

    // A block of at most kBatchCells cells meeting the cylinder is answered cell by cell through the
    // batch API, whose SIMD filter decides most cells near the surface at a fraction of an exact query
    // each (the rest go to the same exact query), where subdividing further would cost an exact query
    // per half, and blocks lying across the surface rarely have halves the cylinder misses or covers.
    // Blocks of more than kBatchAlways cells are first tested for lying inside (eight corner tests,
    // cheaper than a batch over them). A block of up to kBatchDense cells that the cylinder may fill
    // half of (dense()) is batched whole too: its halves would all meet the cylinder, and each would
    // cost an exact query. Measured on bench/bench_grid.cpp's cylinders and the voxels of
    // bench/bench_pipeline.cpp: 512 rather than 64 made every one faster (by a fifth to two fifths),
    // and 4096 for every block doubled the thin cylinders' time; the dense blocks took a seventh off the
    // voxels' time and a tenth off the cylinders' with a margin, and left the others as they were (on
    // blocks thinner than kDenseSide they slowed the thin cylinder along a grid axis by a quarter).
    static constexpr std::int64_t kBatchAlways = 64;
    static constexpr std::int64_t kBatchCells = 512;
    static constexpr std::int64_t kBatchDense = 8192;
    static constexpr std::int64_t kDenseSide = 8;
    static constexpr std::int64_t kBatchSide = 64;  // no side longer (the per-axis bound tables below)
    void batched(const CellIndex& lo, const CellIndex& hi, std::int64_t n) {
        // The cells' bounds, one table per axis: each bound rounded once (grid_bound), shared by the
        // cells on either side of it.
        std::array<double, kBatchSide + 1> bound[3];
        for (std::size_t a = 0; a < 3; ++a)
            for (std::int64_t i = lo[a]; i <= hi[a]; ++i) bound[a][static_cast<std::size_t>(i - lo[a])] = grid_bound(g_, a, i);
        const std::size_t cells = static_cast<std::size_t>(n);
        if (column_.size() < 6 * cells) column_.resize(6 * cells);
        if (mask_.size() < batch::mask_words(cells)) mask_.resize(batch::mask_words(cells));
        double* col[6];
        for (std::size_t a = 0; a < 6; ++a) col[a] = column_.data() + a * cells;
        // The columns by copies (a batched block's cells cost about as much to lay out one store at a
        // time as the filter costs them): the y and z bounds repeat in every x-slab, the x bounds are
        // constant over one.
        const auto ni = static_cast<std::size_t>(hi[0] - lo[0]), nj = static_cast<std::size_t>(hi[1] - lo[1]),
                   nk = static_cast<std::size_t>(hi[2] - lo[2]), slab = nj * nk;
        for (std::size_t y = 0; y < nj; ++y) {
            std::fill_n(col[1] + y * nk, nk, bound[1][y]);
            std::fill_n(col[4] + y * nk, nk, bound[1][y + 1]);
            std::copy_n(bound[2].data(), nk, col[2] + y * nk);
            std::copy_n(bound[2].data() + 1, nk, col[5] + y * nk);
        }
        for (std::size_t x = 1; x < ni; ++x)
            for (const std::size_t a : {1, 2, 4, 5}) std::memcpy(col[a] + x * slab, col[a], slab * sizeof(double));
        for (std::size_t x = 0; x < ni; ++x)
            for (const std::size_t a : {0, 3}) fill_by_doubling(col[a] + x * slab, slab, bound[0][x + (a == 3)]);
        const std::span<std::uint64_t> mask(mask_.data(), batch::mask_words(cells));
        const batch::AlignedBoxes<double> boxes{{col[0], cells}, {col[1], cells}, {col[2], cells},
                                                {col[3], cells}, {col[4], cells}, {col[5], cells}};
        const batch::Stats st = t_.margin > 0 ? batch::within_distance(t_.cylinder, boxes, t_.margin, mask, {1})
                                              : batch::intersects(t_.cylinder, boxes, mask, {1});
        s_.queries += static_cast<std::int64_t>(st.exact_lanes);
        s_.cell_queries += static_cast<std::int64_t>(st.exact_lanes);
        s_.batched_cells += n;
        // The answers row by row, each row's bits read a word at a time.
        std::size_t m = 0;
        for (std::int64_t i = lo[0]; i < hi[0]; ++i)
            for (std::int64_t j = lo[1]; j < hi[1]; ++j, m += nk)
                for (std::size_t k = 0; k < nk;) {
                    const std::size_t at = m + k, shift = at % 64, take = std::min<std::size_t>(64 - shift, nk - k);
                    std::uint64_t bits = mask[at / 64] >> shift;
                    if (take < 64) bits &= (std::uint64_t{1} << take) - 1;
                    for (; bits != 0; bits &= bits - 1) {
                        ++s_.cells;
                        f_(i, j, lo[2] + static_cast<std::int64_t>(k) + std::countr_zero(bits));
                    }
                    k += take;
                }
    }

    // p[0, n) = v: a few stores, then copies of what is already there.
    static void fill_by_doubling(double* p, std::size_t n, double v) {
        std::size_t done = std::min<std::size_t>(n, 8);
        std::fill_n(p, done, v);
        while (done < n) {
            const std::size_t more = std::min(done, n - done);
            std::memcpy(p + done, p, more * sizeof(double));
            done += more;
        }
    }

    // The batched blocks' columns and answers, kept from one block to the next.
    std::vector<double> column_;
    std::vector<std::uint64_t> mask_;
    const Grid& g_;
    const GridTarget& t_;
    const Cylinder<double>& c_;  // t_.bound: the cylinder of the exact block queries
    F& f_;
    GridStats& s_;
};

}  // namespace detail

// Calls f(i, j, k) (std::int64_t each) once for every cell of `g` that the closed cylinder `c`
// intersects, exactly (see the top of this file). Order: deterministic, depth-first over the
// subdivision (a block's lower half before its upper half; a block inside the cylinder, or one answered
// through the batch API, in lexicographic order), not lexicographic overall — cells() sorts.
// Preconditions: validate(g).ok() and validate(c).ok() (asserted in debug builds).
template <class F>
void for_each_cell(const Grid& g, const Cylinder<double>& c, F&& f, GridStats* stats = nullptr) {
    assert(validate(g).ok() && "boxcyl::for_each_cell: invalid grid (see boxcyl::validate)");
    assert(validate(c).ok() && "boxcyl::for_each_cell: invalid cylinder (see boxcyl::validate)");
    GridStats local;
    const detail::GridTarget target{c, 0, c, c};
    detail::GridWalk<std::remove_reference_t<F>> walk(g, target, f, stats ? *stats : local);
    walk.run();
}

// The cells of for_each_cell, in lexicographic order of (i, j, k).
inline std::vector<CellIndex> cells(const Grid& g, const Cylinder<double>& c, GridStats* stats = nullptr) {
    std::vector<CellIndex> out;
    for_each_cell(g, c, [&](std::int64_t i, std::int64_t j, std::int64_t k) { out.push_back({i, j, k}); }, stats);
    std::sort(out.begin(), out.end());
    return out;
}

namespace detail {
// for_each_cell_within itself; named apart because the compiled library's sources see both forms of
// the public calls.
template <class F>
void cells_within_walk(const Grid& g, const Cylinder<double>& c, double margin, F& f, GridStats* stats) {
    if (!is_valid_margin(margin)) throw std::invalid_argument(validate_margin(margin).message());
    GridStats local;
    auto walk = [&](const detail::GridTarget& target) {
        detail::GridWalk<F> w(g, target, f, stats ? *stats : local);
        w.run();
    };
    if (margin == 0) return walk({c, 0, c, c});
    const detail::clearance::Grown grown = detail::clearance::grown(c, margin);
    if (grown.outer_valid) return walk({c, margin, grown.outer, grown.fat});
    // Sizes beyond the double range: every cell is asked.
    for (std::int64_t i = 0; i < g.counts[0]; ++i)
        for (std::int64_t j = 0; j < g.counts[1]; ++j)
            for (std::int64_t k = 0; k < g.counts[2]; ++k)
                if (within_distance_unchecked(cell_box(g, {i, j, k}), c, margin)) f(i, j, k);
}
}  // namespace detail

// Calls f(i, j, k) once for every cell of `g` within distance `margin` of the closed cylinder `c`:
// exactly the cells for which within_distance(cell_box(g, cell), c, margin) holds (clearance.hpp).
// The walk of for_each_cell, on the clearance query's probes: it descends on the outer one (a block
// that misses it has no cell within the margin), reports a block whole when its corners lie in the fat
// one (inside the rounded cylinder), and answers small blocks through batch::within_distance; margin 0
// is for_each_cell. Order as for_each_cell's.
// Preconditions: validate(g).ok() and validate(c).ok(); a margin that is negative, NaN or infinite
// throws std::invalid_argument.
template <class F>
void for_each_cell_within(const Grid& g, const Cylinder<double>& c, double margin, F&& f, GridStats* stats = nullptr) {
    detail::cells_within_walk(g, c, margin, f, stats);
}

// The cells of for_each_cell_within, in lexicographic order of (i, j, k).
inline std::vector<CellIndex> cells_within(const Grid& g, const Cylinder<double>& c, double margin,
                                           GridStats* stats = nullptr) {
    std::vector<CellIndex> out;
    auto keep = [&](std::int64_t i, std::int64_t j, std::int64_t k) { out.push_back({i, j, k}); };
    detail::cells_within_walk(g, c, margin, keep, stats);
    std::sort(out.begin(), out.end());
    return out;
}

#else

// Without the exact backend the grid query is unavailable (it is exact, like the default query).
template <class F>
void for_each_cell(const Grid&, const Cylinder<double>&, F&&, GridStats* = nullptr) {
    static_assert(detail::dependent_false<F>,
                  "boxcyl::for_each_cell is exact and needs the exact backend: link boxcyl::exact (GMP) or the "
                  "compiled boxcyl::boxcyl");
}
template <class G = Grid>
std::vector<CellIndex> cells(const G&, const Cylinder<double>&, GridStats* = nullptr) {
    static_assert(detail::dependent_false<G>,
                  "boxcyl::cells is exact and needs the exact backend: link boxcyl::exact (GMP) or the compiled "
                  "boxcyl::boxcyl");
    return {};
}

#endif  // BOXCYL_HAS_EXACT

}  // namespace boxcyl

#endif  // the templates
