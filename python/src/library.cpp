// The library code the module calls, compiled here in one translation unit so that the exact query's
// templates are instantiated once: the double-precision functions of boxcyl/compiled.hpp that the
// binding files use (as src/lib defines them all for the compiled library boxcyl::boxcyl) — the scalar
// queries, the distance and the signed distance, the batch API with its header kernel (intersects and within_distance), the
// grid query — and the scalar exact default that the AVX2 and AVX-512 kernels (src/batch) call
// (src/batch/pipeline.cpp's explicit instantiations).
#include "boxcyl/batch.hpp"
#include "boxcyl/clearance.hpp"
#include "boxcyl/distance.hpp"
#include "boxcyl/grid.hpp"
#include "boxcyl/query.hpp"
#include "boxcyl/signed_distance.hpp"

// The calls into the templates come before boxcyl/compiled.hpp is included: after it, a call naming
// boxcyl::batch::intersects or boxcyl::for_each_cell would also find the compiled declarations.
namespace {

using boxcyl::Cylinder;
using boxcyl::batch::Options;
using boxcyl::batch::Stats;
using Bools = std::span<bool>;

Stats header_aligned(const Cylinder<double>& c, const boxcyl::batch::AlignedBoxes<double>& b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_rows(const Cylinder<double>& c, std::span<const boxcyl::AlignedBox<double>> b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_oriented(const Cylinder<double>& c, std::span<const boxcyl::OrientedBox<double>> b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_parallelepiped(const Cylinder<double>& c, std::span<const boxcyl::Parallelepiped<double>> b, Bools out,
                            const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
template <class Boxes>
Stats header_within(const Cylinder<double>& c, const Boxes& b, double m, Bools out, const Options& o) {
    return boxcyl::batch::within_distance(c, b, m, out, o);
}
void header_for_each_cell(const boxcyl::Grid& g, const Cylinder<double>& c,
                          void (*f)(void*, std::int64_t, std::int64_t, std::int64_t), void* context,
                          boxcyl::GridStats* stats) {
    boxcyl::for_each_cell(g, c, [&](std::int64_t i, std::int64_t j, std::int64_t k) { f(context, i, j, k); }, stats);
}

void header_for_each_cell_within(const boxcyl::Grid& g, const Cylinder<double>& c, double margin,
                                 void (*f)(void*, std::int64_t, std::int64_t, std::int64_t), void* context,
                                 boxcyl::GridStats* stats) {
    boxcyl::for_each_cell_within(g, c, margin, [&](std::int64_t i, std::int64_t j, std::int64_t k) { f(context, i, j, k); },
                                 stats);
}

}  // namespace

#include "boxcyl/compiled.hpp"

namespace boxcyl::compiled {

bool intersects(const AlignedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    boxcyl::detail::require_valid(box, cyl);
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const OrientedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    boxcyl::detail::require_valid(box, cyl);
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const Parallelepiped<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    boxcyl::detail::require_valid(box, cyl);
    return boxcyl::detail::dispatch(box, cyl, opt);
}

// The clearance query calls intersects_unchecked and within_distance_unchecked: defined here, whichever
// form (template or compiled declaration) a call resolves to.
bool intersects_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool within_distance_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl, double margin) {
    return boxcyl::within_distance_unchecked<AlignedBox<double>, double>(box, cyl, margin);
}
bool within_distance_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl, double margin) {
    return boxcyl::within_distance_unchecked<OrientedBox<double>, double>(box, cyl, margin);
}
bool within_distance_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl, double margin) {
    return boxcyl::within_distance_unchecked<Parallelepiped<double>, double>(box, cyl, margin);
}
bool within_distance(const AlignedBox<double>& box, const Cylinder<double>& cyl, double margin) {
    return boxcyl::within_distance<AlignedBox<double>, double>(box, cyl, margin);
}
bool within_distance(const OrientedBox<double>& box, const Cylinder<double>& cyl, double margin) {
    return boxcyl::within_distance<OrientedBox<double>, double>(box, cyl, margin);
}
bool within_distance(const Parallelepiped<double>& box, const Cylinder<double>& cyl, double margin) {
    return boxcyl::within_distance<Parallelepiped<double>, double>(box, cyl, margin);
}

// The distance's templates by name (a plain call here would find these functions themselves).
Distance distance_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::distance_unchecked<AlignedBox<double>, double>(box, cyl);
}
Distance distance_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::distance_unchecked<OrientedBox<double>, double>(box, cyl);
}
Distance distance_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::distance_unchecked<Parallelepiped<double>, double>(box, cyl);
}
Distance distance(const AlignedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::distance<AlignedBox<double>, double>(box, cyl);
}
Distance distance(const OrientedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::distance<OrientedBox<double>, double>(box, cyl);
}
Distance distance(const Parallelepiped<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::distance<Parallelepiped<double>, double>(box, cyl);
}

// The signed distance's templates by name, as the distance's.
SignedDistance signed_distance_unchecked(const AlignedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::signed_distance_unchecked<AlignedBox<double>, double>(box, cyl);
}
SignedDistance signed_distance_unchecked(const OrientedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::signed_distance_unchecked<OrientedBox<double>, double>(box, cyl);
}
SignedDistance signed_distance_unchecked(const Parallelepiped<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::signed_distance_unchecked<Parallelepiped<double>, double>(box, cyl);
}
SignedDistance signed_distance(const AlignedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::signed_distance<AlignedBox<double>, double>(box, cyl);
}
SignedDistance signed_distance(const OrientedBox<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::signed_distance<OrientedBox<double>, double>(box, cyl);
}
SignedDistance signed_distance(const Parallelepiped<double>& box, const Cylinder<double>& cyl) {
    return boxcyl::signed_distance<Parallelepiped<double>, double>(box, cyl);
}

void for_each_cell_erased(const Grid& g, const Cylinder<double>& c, CellCallback f, void* context, GridStats* stats) {
    header_for_each_cell(g, c, f, context, stats);
}
void for_each_cell_within_erased(const Grid& g, const Cylinder<double>& c, double margin, CellCallback f, void* context,
                                 GridStats* stats) {
    header_for_each_cell_within(g, c, margin, f, context, stats);
}

}  // namespace boxcyl::compiled

namespace boxcyl::batch::compiled {

Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, std::span<bool> out, const Options& opt) {
    return header_aligned(cyl, boxes, out, opt);
}
Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, std::span<bool> out,
                 const Options& opt) {
    return header_rows(cyl, boxes, out, opt);
}
Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<bool> out,
                 const Options& opt) {
    return header_oriented(cyl, boxes, out, opt);
}
Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, std::span<bool> out,
                 const Options& opt) {
    return header_parallelepiped(cyl, boxes, out, opt);
}

Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<double>& boxes, double margin, std::span<bool> out,
                      const Options& opt) {
    return header_within(cyl, boxes, margin, out, opt);
}
Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin,
                      std::span<bool> out, const Options& opt) {
    return header_within(cyl, boxes, margin, out, opt);
}
Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin,
                      std::span<bool> out, const Options& opt) {
    return header_within(cyl, boxes, margin, out, opt);
}
Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin,
                      std::span<bool> out, const Options& opt) {
    return header_within(cyl, boxes, margin, out, opt);
}

}  // namespace boxcyl::batch::compiled

#if defined(BOXCYL_BATCH_DISPATCH)
// The kernels' scalar exact default, boxcyl::batch_dispatch's own definition: included rather than
// compiled apart, since the query is instantiated here already.
#include "../../src/batch/pipeline.cpp"
#endif
