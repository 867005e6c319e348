// The batch API: one cylinder against N boxes, exactly, with a SIMD filter and threads.
//
//   boxcyl::batch::intersects(cylinder, boxes, out[, Options{threads}]) -> Stats
//   boxcyl::batch::within_distance(cylinder, boxes, margin, out[, Options]) -> Stats
//   boxcyl::batch::distance(cylinder, boxes, out[, Options]) -> Stats        (batch/distance.hpp)
//   boxcyl::batch::signed_distance(cylinder, boxes, out[, Options]) -> Stats (batch/distance.hpp)
//
// within_distance answers the clearance query dist(box, cylinder) ≤ margin (boxcyl/clearance.hpp) for
// every box, bit for bit as the scalar within_distance(box, cylinder, margin); the same layouts,
// outputs and options. A negative, NaN or infinite margin throws std::invalid_argument ("margin: is
// negative"); margin 0 is intersects(). The filter runs on the scalar query's probe cylinders — one
// holding the rounded cylinder (a certain miss answers no), then two it holds (a certain hit answers
// yes) — and Stats::exact_lanes counts the boxes left to the scalar clearance query.
//
// Answers are those of the scalar exact default boxcyl::intersects(box, cylinder) for every box, bit for
// bit: each double is the rational it denotes, u = axis/|axis| exactly, closed solids (touching
// intersects). Float inputs are widened to double (exactly) first, so a float box means what the same
// box in double means.
//
// Boxes:
//   AlignedBoxes<T>   structure of arrays: box i is [min_x[i], max_x[i]] × [min_y[i], max_y[i]] ×
//                     [min_z[i], max_z[i]]; six spans of the same length, T = float or double.
//   AlignedBox<T>     array of structures (std::span<const AlignedBox<T>>), T = float or double: box i
//                     is the six numbers min, max — the layout of an (N, 2, 3) array of [min, max] rows,
//                     read in place (each column of a vector of lanes gathered): the answers are those
//                     of the six arrays; on data the first pass decides cheaply it costs more than
//                     them (bench_batch: up to about 30% on random boxes with AVX-512), since the
//                     gathers cost more than contiguous loads.
//   OrientedBox<T>    array of structures (std::span<const OrientedBox<T>>), T = float or double: the
//                     library's own struct, so existing arrays need no copy; the filter gathers each
//                     vector of lanes from it.
//   Parallelepiped<T> any axes (std::span<const Parallelepiped<T>>), T = float or double: no SIMD filter,
//                     the scalar default query per box, over the threads (batch/parallelepiped.hpp):
//                     Stats::kernel is Kernel::compiled with Stats::lanes = 1, and Options::kernel
//                     avx2 or avx512 throws std::invalid_argument (there is no such kernel for them).
// Output: a bit mask (bit i of word i/64 is box i; the unused high bits of the last word are cleared;
// at least (N + 63)/64 words) or one bool per box. Stats::exact_lanes counts the boxes that the filter
// left to the scalar query.
//
// How: batch/filter.hpp decides each lane that it can prove (certain miss by a separating direction,
// certain hit by a box point inside the cylinder, with proven error bounds: docs/robustness/batch.md);
// every undecided lane is answered by the scalar exact default (filtered::query). Aligned boxes take
// two passes: a cheap one over every box (bounding boxes, then the box's centre and a ball around it:
// §8a), then the whole filter on the few lanes it left, gathered into full vectors (batch/kernel.hpp).
// Oriented boxes take the filter but its hit search over every box, then the search on the lanes it
// left, gathered.
// SIMD width (Options::kernel, types.hpp): the header's own kernel has that of std::experimental::simd's
// native ABI under the includer's compile flags (2 doubles with the default x86-64 flags, so it runs on
// any x86-64; -mavx2 gives 4, -march=native on an AVX-512 machine 8). Linking boxcyl::batch_dispatch
// (src/batch/) adds kernels compiled for AVX2 (4) and AVX-512 (8), chosen at run time from what the CPU
// has: one portable binary that uses the machine's full width. Threads: contiguous ranges of 64-box
// blocks (batch/split.hpp); Options::threads = 0 uses std::thread::hardware_concurrency(), and a
// batch smaller than 32768 boxes per thread uses fewer threads (one below 65536 boxes).
// Cancellation: Options::stop, a std::stop_token each thread looks at before each group of up to 32
// blocks of 64 boxes and before each block's scalar work; a requested stop ends the call with
// batch::Stopped within a group's filtering or a block's scalar work per thread.
//
// Preconditions: validate() holds for the cylinder and every box (asserted in debug builds; with
// Options::check_boxes the boxes are checked instead, and an invalid one throws InvalidBox); the
// floating-point environment is the default one (round to nearest, no flush-to-zero: see
// boxcyl::fp_environment_ok()). Needs the exact backend (link boxcyl::exact), like the default query.
#pragma once

// With the compiled library (boxcyl::boxcyl, which defines neither macro) this header is its
// declarations of the same batch queries (double and float): the same calls, compiled in libboxcyl.
#if !defined(BOXCYL_HAS_EXACT) && !defined(BOXCYL_HEADER_ONLY)
#include "boxcyl/compiled.hpp"
#else
#if !defined(BOXCYL_HAS_EXACT)
#error "boxcyl/batch.hpp answers exactly and needs the exact backend: link boxcyl::exact (GMP), or the compiled boxcyl::boxcyl"
#endif

#include <array>             // the probes' order
#include <cstddef>           // std::size_t
#include <cstdint>           // std::uint64_t
#include <initializer_list>  // the kernels `automatic` tries
#include <span>              // inputs and outputs
#include <stdexcept>         // std::invalid_argument for an unavailable kernel
#include <string>            // its message
#include <utility>           // std::forward

#include "boxcyl/batch/kernel.hpp"
#include "boxcyl/batch/parallelepiped.hpp"
#include "boxcyl/batch/types.hpp"
#include "boxcyl/clearance.hpp"
#include "boxcyl/filtered/centre_ball.hpp"  // the lanes left to the scalar query: their centre first
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/margin.hpp"

#if defined(BOXCYL_BATCH_DISPATCH)
#include "boxcyl/batch/dispatch.hpp"
#endif

namespace boxcyl::batch {

// Whether intersects() can run kernel k here: `automatic` and `compiled` always; avx2 and avx512 when
// boxcyl::batch_dispatch is linked, was built with them (GCC on x86-64), and this CPU and its operating
// system run them.
inline bool available(Kernel k) {
    if (k == Kernel::automatic || k == Kernel::compiled) return true;
#if defined(BOXCYL_BATCH_DISPATCH)
    return dispatch::find(k) != nullptr;
#else
    return false;
#endif
}

// The helpers below are in the header kernel's namespace (kernel.hpp), as that kernel is: no other
// boxcyl::batch::detail may exist beside its inline one.
inline namespace BOXCYL_BATCH_ISA {
namespace detail {

template <class T>
void check_lengths(const AlignedBoxes<T>& b) {
    const std::size_t n = b.min_x.size();
    if (b.min_y.size() != n || b.min_z.size() != n || b.max_x.size() != n || b.max_y.size() != n ||
        b.max_z.size() != n)
        throw std::invalid_argument("boxcyl::batch::intersects: the six box arrays have different lengths");
}

inline constexpr KernelTable compiled_table = kernel_table(Kernel::compiled);

// The table of the kernel that opt.kernel names (automatic: the widest available).
inline const KernelTable& select(Kernel k) {
    if (k == Kernel::compiled) return compiled_table;
#if defined(BOXCYL_BATCH_DISPATCH)
    if (k == Kernel::automatic) {
        const KernelTable* best = &compiled_table;
        for (Kernel c : {Kernel::avx512, Kernel::avx2})
            if (const KernelTable* t = dispatch::find(c); t != nullptr && t->lanes > best->lanes) best = t;
        return *best;
    }
    if (const KernelTable* t = dispatch::find(k)) return *t;
#else
    if (k == Kernel::automatic) return compiled_table;
#endif
    throw std::invalid_argument(std::string("boxcyl::batch::intersects: kernel '") + name(k) +
                                "' is not available here (boxcyl::batch::available): it needs boxcyl::batch_dispatch "
                                "linked, built by GCC for x86-64, and a CPU that runs it");
}

inline Stats stamped(Stats st, const KernelTable& t) {
    st.kernel = t.kernel;
    return st;
}

inline Cylinder<double> widen(const Cylinder<float>& c) {
    auto d = [](const Vec3<float>& v) { return Vec3<double>{v[0], v[1], v[2]}; };
    return {d(c.center), d(c.axis), c.radius, c.height};
}

}  // namespace detail
}  // namespace BOXCYL_BATCH_ISA

inline namespace BOXCYL_BATCH_ISA {
namespace detail {

// The kernel entry that answers query q (a cylinder: intersects; a Clearance: within_distance) for
// each box layout and output, on the kernel that opt.kernel names.
template <class Q, class T>
Stats answer(const Q& q, const AlignedBoxes<T>& b, std::span<std::uint64_t> out, const Options& opt) {
    check_lengths(b);
    const KernelTable& t = select(opt.kernel);
    return stamped(t.template entries<T>().of(q).aligned_mask(q, b, out, opt), t);
}
template <class Q, class T>
Stats answer(const Q& q, const AlignedBoxes<T>& b, std::span<bool> out, const Options& opt) {
    check_lengths(b);
    const KernelTable& t = select(opt.kernel);
    return stamped(t.template entries<T>().of(q).aligned_bools(q, b, out, opt), t);
}
template <class Q, class T>
Stats answer(const Q& q, std::span<const AlignedBox<T>> b, std::span<std::uint64_t> out, const Options& opt) {
    const KernelTable& t = select(opt.kernel);
    return stamped(t.template entries<T>().of(q).rows_mask(q, b, out, opt), t);
}
template <class Q, class T>
Stats answer(const Q& q, std::span<const AlignedBox<T>> b, std::span<bool> out, const Options& opt) {
    const KernelTable& t = select(opt.kernel);
    return stamped(t.template entries<T>().of(q).rows_bools(q, b, out, opt), t);
}
template <class Q, class T>
Stats answer(const Q& q, std::span<const OrientedBox<T>> b, std::span<std::uint64_t> out, const Options& opt) {
    const KernelTable& t = select(opt.kernel);
    return stamped(t.template entries<T>().of(q).oriented_mask(q, b, out, opt), t);
}
template <class Q, class T>
Stats answer(const Q& q, std::span<const OrientedBox<T>> b, std::span<bool> out, const Options& opt) {
    const KernelTable& t = select(opt.kernel);
    return stamped(t.template entries<T>().of(q).oriented_bools(q, b, out, opt), t);
}
template <class Q, class T, class Out>
Stats answer(const Q& q, std::span<const Parallelepiped<T>> b, Out out, const Options& opt) {
    return parallelepipeds::answer(q, b, out, opt);
}

// The scalar clearance query for the lanes the filter leaves (types.hpp's Clearance says why through a
// pointer). Those lanes lie near the rim tori, where the box's centre ball (the scalar query's stage
// after its probes' stage 0) decides most of them alone, at a fraction of stage 0's cost: the ball
// first (the scalar query asks it again after stage 0 for the rest, a few dozen flops).
template <class Box>
bool scalar_within(const Box& box, const Cylinder<double>& cyl, double m) {
    if (const std::optional<bool> v = filtered::centre_ball::decide(box, cyl, m)) return *v;
    return boxcyl::within_distance_unchecked(box, cyl, m);
}

// The order of the scalar query's probes (boxcyl/clearance.hpp's probes(): fat, outer, tall) in the
// batch: the outer cylinder's miss first. A batch is mostly boxes far from the cylinder (a voxel grid,
// a block model around a drill hole: 96% of bench_batch's voxels miss the outer cylinder), which that
// pass answers alone, where the fat cylinder's pass answers only the few inside and leaves every far
// box to a second pass. (The scalar query's random pairs lie near the cylinder and mostly hit fat: it
// asks fat first.)
inline constexpr std::array<std::size_t, 3> kBatchProbeOrder{1, 0, 2};

// The clearance query at margin m > 0: the probes of the scalar query in kBatchProbeOrder; one whose
// sizes overflow is left out.
inline Clearance clearance(const Cylinder<double>& cyl, double m) {
    Clearance q{cyl, m, {}, {}, 0, &scalar_within<AlignedBox<double>>, &scalar_within<OrientedBox<double>>};
    const boxcyl::detail::clearance::Grown grown = boxcyl::detail::clearance::grown(cyl, m);
    const auto probes = boxcyl::detail::clearance::probes(grown);
    for (const std::size_t k : kBatchProbeOrder)
        if (const boxcyl::detail::clearance::Probe& p = probes[k]; p.valid) {
            q.probe[q.probes] = *p.cylinder;
            q.decides_when[q.probes++] = p.decides_when;
        }
    return q;
}

// within_distance: the margin checked, then margin 0 (or −0) is intersects, as in the scalar query.
template <class Boxes, class Out>
Stats within(const Cylinder<double>& cyl, const Boxes& boxes, double margin, Out out, const Options& opt) {
    if (!is_valid_margin(margin)) [[unlikely]]
        throw std::invalid_argument(validate_margin(margin).message());
    if (margin == 0) return answer(cyl, boxes, out, opt);
    return answer(clearance(cyl, margin), boxes, out, opt);
}

}  // namespace detail
}  // namespace BOXCYL_BATCH_ISA

// ---- Aligned boxes (structure of arrays), T = float or double. ----
template <class T>
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, std::span<std::uint64_t> mask,
                 const Options& opt = {}) {
    return detail::answer(cyl, boxes, mask, opt);
}
template <class T>
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, std::span<bool> out,
                 const Options& opt = {}) {
    return detail::answer(cyl, boxes, out, opt);
}

// ---- Aligned boxes (array of AlignedBox<T>), T = float or double. ----
// (Overloads rather than a template, so that a std::vector of boxes converts to the span.)
inline Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::answer(cyl, boxes, mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return detail::answer(cyl, boxes, out, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::answer(cyl, boxes, mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return detail::answer(cyl, boxes, out, opt);
}

// ---- Oriented boxes (array of OrientedBox<T>), T = float or double. ----
// (Overloads rather than a template, so that a std::vector of boxes converts to the span.)
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::answer(cyl, boxes, mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return detail::answer(cyl, boxes, out, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::answer(cyl, boxes, mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return detail::answer(cyl, boxes, out, opt);
}

// A float cylinder is widened to double exactly, like the boxes.
template <class Boxes, class Out>
Stats intersects(const Cylinder<float>& cyl, const Boxes& boxes, Out&& out, const Options& opt = {}) {
    return intersects(detail::widen(cyl), boxes, std::forward<Out>(out), opt);
}

// ---- Clearance: is each box within distance `margin` of the cylinder? ----
// The same layouts, outputs and options as intersects(); margin finite and ≥ 0 (else
// std::invalid_argument: "margin: is negative"); margin 0 is intersects().
template <class T>
Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, double margin,
                      std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
template <class T>
Stats within_distance(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, double margin, std::span<bool> out,
                      const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}
// (Overloads rather than a template, so that a std::vector of boxes converts to the span.)
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin,
                             std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin,
                             std::span<bool> out, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, double margin,
                             std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, double margin,
                             std::span<bool> out, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin,
                             std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin,
                             std::span<bool> out, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, double margin,
                             std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, double margin,
                             std::span<bool> out, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin,
                             std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin,
                             std::span<bool> out, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, double margin,
                             std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, mask, opt);
}
inline Stats within_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, double margin,
                             std::span<bool> out, const Options& opt = {}) {
    return detail::within(cyl, boxes, margin, out, opt);
}

template <class Boxes, class Out>
Stats within_distance(const Cylinder<float>& cyl, const Boxes& boxes, double margin, Out&& out, const Options& opt = {}) {
    return within_distance(detail::widen(cyl), boxes, margin, std::forward<Out>(out), opt);
}

}  // namespace boxcyl::batch

#include "boxcyl/batch/distance.hpp"  // batch::distance, batch::distance_within

#endif  // the templates
