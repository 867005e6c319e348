// The compiled library boxcyl::boxcyl (libboxcyl): the double and float queries, declared here and
// compiled once in the library (src/), so that a file using them includes only the shapes, the
// options and validation. <boxcyl/boxcyl.hpp> includes this header unless BOXCYL_HEADER_ONLY is
// defined (by boxcyl::header_only and boxcyl::exact), in which case it gives the header-only templates.
//
// The answers are those of the header-only templates for T = double or float (boxcyl/query.hpp,
// boxcyl/batch.hpp, boxcyl/grid.hpp, where each is documented): the same exact default, options,
// preconditions and exceptions. The library is built with the exact backend (GMP, linked privately)
// and with boxcyl::batch_dispatch, so the batch calls use the widest SIMD kernel the CPU runs.
// Other number types (rationals, intervals, long double) need the header-only templates.
//
// Everything here is in the inline namespace boxcyl::compiled, so that it is boxcyl::intersects etc.
// to its users and does not collide with the templates' definitions at link time. One file should use
// either this header or boxcyl/batch.hpp and boxcyl/grid.hpp: with both, the batch and grid calls
// that exist in both forms are ambiguous.
#pragma once

#include <cstddef>  // std::size_t
#include <cstdint>  // std::int64_t, std::uint64_t
#include <span>     // batch inputs and outputs
#include <type_traits>  // std::remove_reference_t
#include <utility>  // std::forward
#include <vector>   // cells()

#include "boxcyl/batch/types.hpp"
#include "boxcyl/distance_types.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/pose.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/grid_types.hpp"
#include "boxcyl/options.hpp"
#include "boxcyl/version.hpp"

namespace boxcyl {
inline namespace compiled {

// ---- One box, one cylinder (boxcyl/query.hpp). Default options: the exact answer. ----
// Invalid input throws std::invalid_argument naming the field (validate()'s message); the _unchecked
// forms skip that check for callers who validated once.
bool intersects(const AlignedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects(const OrientedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects(const CanonicalBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects(const Parallelepiped<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects(const AlignedBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects(const OrientedBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects(const CanonicalBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects(const Parallelepiped<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const CanonicalBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const AlignedBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const OrientedBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const CanonicalBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});
bool intersects_unchecked(const Parallelepiped<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt = {});

// ---- Clearance: is the box within distance `margin` of the cylinder? (boxcyl/clearance.hpp) ----
// Exact; margin finite and ≥ 0 (else std::invalid_argument, like invalid shapes).
bool within_distance(const AlignedBox<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance(const OrientedBox<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance(const CanonicalBox<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance(const Parallelepiped<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance(const AlignedBox<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance(const OrientedBox<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance(const CanonicalBox<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance(const Parallelepiped<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance_unchecked(const CanonicalBox<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl, double margin);
bool within_distance_unchecked(const AlignedBox<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance_unchecked(const OrientedBox<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance_unchecked(const CanonicalBox<float>& box, const Cylinder<float>& cyl, float margin);
bool within_distance_unchecked(const Parallelepiped<float>& box, const Cylinder<float>& cyl, float margin);

// ---- Distance: how far apart, proved (boxcyl/distance.hpp). ----
// An enclosure [lower, upper] of the exact distance, at most 4 doubles wide, and a nearest pair.
Distance distance(const AlignedBox<double>& box, const Cylinder<double>& cyl);
Distance distance(const OrientedBox<double>& box, const Cylinder<double>& cyl);
Distance distance(const CanonicalBox<double>& box, const Cylinder<double>& cyl);
Distance distance(const Parallelepiped<double>& box, const Cylinder<double>& cyl);
Distance distance(const AlignedBox<float>& box, const Cylinder<float>& cyl);
Distance distance(const OrientedBox<float>& box, const Cylinder<float>& cyl);
Distance distance(const CanonicalBox<float>& box, const Cylinder<float>& cyl);
Distance distance(const Parallelepiped<float>& box, const Cylinder<float>& cyl);
Distance distance_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl);
Distance distance_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl);
Distance distance_unchecked(const CanonicalBox<double>& box, const Cylinder<double>& cyl);
Distance distance_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl);
Distance distance_unchecked(const AlignedBox<float>& box, const Cylinder<float>& cyl);
Distance distance_unchecked(const OrientedBox<float>& box, const Cylinder<float>& cyl);
Distance distance_unchecked(const CanonicalBox<float>& box, const Cylinder<float>& cyl);
Distance distance_unchecked(const Parallelepiped<float>& box, const Cylinder<float>& cyl);

// ---- Signed distance: apart, or how deep, proved (boxcyl/signed_distance.hpp). ----
// An enclosure [lower, upper] of the distance, or of minus the penetration depth where the solids
// overlap; a unit normal from the box towards the cylinder and a witness pair.
SignedDistance signed_distance(const AlignedBox<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance(const OrientedBox<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance(const CanonicalBox<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance(const Parallelepiped<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance(const AlignedBox<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance(const OrientedBox<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance(const CanonicalBox<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance(const Parallelepiped<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance_unchecked(const CanonicalBox<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl);
SignedDistance signed_distance_unchecked(const AlignedBox<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance_unchecked(const OrientedBox<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance_unchecked(const CanonicalBox<float>& box, const Cylinder<float>& cyl);
SignedDistance signed_distance_unchecked(const Parallelepiped<float>& box, const Cylinder<float>& cyl);

// ---- The grid query (boxcyl/grid.hpp). ----
// for_each_cell's compiled part: f(context, i, j, k) for every cell.
using CellCallback = void (*)(void* context, std::int64_t i, std::int64_t j, std::int64_t k);
void for_each_cell_erased(const Grid& g, const Cylinder<double>& c, CellCallback f, void* context,
                          GridStats* stats);

// Calls f(i, j, k) (std::int64_t each) once for every cell of g that the closed cylinder c meets.
template <class F>
void for_each_cell(const Grid& g, const Cylinder<double>& c, F&& f, GridStats* stats = nullptr) {
    using Fn = std::remove_reference_t<F>;
    for_each_cell_erased(
        g, c, [](void* context, std::int64_t i, std::int64_t j, std::int64_t k) { (*static_cast<Fn*>(context))(i, j, k); },
        const_cast<void*>(static_cast<const void*>(&f)), stats);
}

// The cells of for_each_cell, in lexicographic order of (i, j, k).
std::vector<CellIndex> cells(const Grid& g, const Cylinder<double>& c, GridStats* stats = nullptr);

// The cells within distance `margin` of the cylinder (boxcyl/grid.hpp's for_each_cell_within; a bad
// margin throws std::invalid_argument).
void for_each_cell_within_erased(const Grid& g, const Cylinder<double>& c, double margin, CellCallback f,
                                 void* context, GridStats* stats);
template <class F>
void for_each_cell_within(const Grid& g, const Cylinder<double>& c, double margin, F&& f, GridStats* stats = nullptr) {
    using Fn = std::remove_reference_t<F>;
    for_each_cell_within_erased(
        g, c, margin,
        [](void* context, std::int64_t i, std::int64_t j, std::int64_t k) { (*static_cast<Fn*>(context))(i, j, k); },
        const_cast<void*>(static_cast<const void*>(&f)), stats);
}
std::vector<CellIndex> cells_within(const Grid& g, const Cylinder<double>& c, double margin, GridStats* stats = nullptr);

}  // namespace compiled

// ---- One cylinder, many boxes (boxcyl/batch.hpp). ----
namespace batch {
inline namespace compiled {

// Whether intersects() can run kernel k here.
bool available(Kernel k);

Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, std::span<std::uint64_t> mask,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, std::span<bool> out,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, std::span<std::uint64_t> mask,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, std::span<bool> out,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes,
                 std::span<std::uint64_t> mask, const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, std::span<bool> out,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes,
                 std::span<std::uint64_t> mask, const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, std::span<bool> out,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes,
                 std::span<std::uint64_t> mask, const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<bool> out,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes,
                 std::span<std::uint64_t> mask, const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, std::span<bool> out,
                 const Options& opt = {});
// Parallelepipeds: the scalar default query per box over the threads (no SIMD filter): Stats::kernel is
// Kernel::compiled, lanes 1; Options::kernel avx2 or avx512 throws std::invalid_argument.
Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes,
                 std::span<std::uint64_t> mask, const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, std::span<bool> out,
                 const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes,
                 std::span<std::uint64_t> mask, const Options& opt = {});
Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, std::span<bool> out,
                 const Options& opt = {});

// A float cylinder is widened to double exactly, like the boxes.
inline Cylinder<double> widened(const Cylinder<float>& cyl) {
    auto d = [](const Vec3<float>& v) { return Vec3<double>{v[0], v[1], v[2]}; };
    return {d(cyl.center), d(cyl.axis), cyl.radius, cyl.height};
}
template <class Boxes, class Out>
Stats intersects(const Cylinder<float>& cyl, const Boxes& boxes, Out&& out, const Options& opt = {}) {
    return intersects(widened(cyl), boxes, std::forward<Out>(out), opt);
}

// Clearance: is each box within distance `margin` of the cylinder? (boxcyl/batch.hpp's
// within_distance: margin finite and ≥ 0, else std::invalid_argument; margin 0 is intersects().)
Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {});
Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, double margin, std::span<bool> out,
                      const Options& opt = {});
template <class Boxes, class Out>
Stats within_distance(const Cylinder<float>& cyl, const Boxes& boxes, double margin, Out&& out, const Options& opt = {}) {
    return within_distance(widened(cyl), boxes, margin, std::forward<Out>(out), opt);
}

// ---- Distance (boxcyl/batch/distance.hpp): one boxcyl::Distance per box, over the threads; ----
// distance_within: only the boxes within `margin` (the clearance filter first), [margin, +∞] for the others.
Stats distance(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
Stats distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, std::span<Distance> out, const Options& opt = {});
Stats distance_within(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, double margin, std::span<Distance> out,
                      const Options& opt = {});
// ---- Signed distance (boxcyl/batch/distance.hpp): one boxcyl::SignedDistance per box, over the threads. ----
Stats signed_distance(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, const AlignedBoxes<float>& boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes,
                      std::span<SignedDistance> out, const Options& opt = {});
Stats signed_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, std::span<SignedDistance> out,
                      const Options& opt = {});
template <class Boxes>
Stats distance(const Cylinder<float>& cyl, const Boxes& boxes, std::span<Distance> out, const Options& opt = {}) {
    return distance(widened(cyl), boxes, out, opt);
}
template <class Boxes>
Stats signed_distance(const Cylinder<float>& cyl, const Boxes& boxes, std::span<SignedDistance> out, const Options& opt = {}) {
    return signed_distance(widened(cyl), boxes, out, opt);
}
template <class Boxes>
Stats distance_within(const Cylinder<float>& cyl, const Boxes& boxes, double margin, std::span<Distance> out,
                      const Options& opt = {}) {
    return distance_within(widened(cyl), boxes, margin, out, opt);
}

}  // namespace compiled
}  // namespace batch
}  // namespace boxcyl
