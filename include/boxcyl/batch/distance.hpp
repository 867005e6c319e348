// The distance queries in the batch API: one cylinder against N boxes, one answer per box.
//
//   boxcyl::batch::distance(cylinder, boxes, out[, Options]) -> Stats
//   boxcyl::batch::distance_within(cylinder, boxes, margin, out[, Options]) -> Stats
//   boxcyl::batch::signed_distance(cylinder, boxes, out[, Options]) -> Stats
//
// distance: out[i] is boxcyl::distance(boxes[i], cylinder), bit for bit (boxcyl/distance.hpp: a proved
// enclosure of the exact distance, at most 4 doubles wide, and a nearest pair). The same box layouts as
// intersects() (structure of arrays, rows of AlignedBox, OrientedBox, Parallelepiped; float or double).
// distance_within: only the boxes within `margin` of the cylinder get their distance; the clearance
// filter (batch::within_distance, SIMD) answers the others first, and they get the enclosure its "no"
// proves, [margin, +∞], with NaN witnesses. For a drill hole's buffer in a block model, where few boxes
// are near, that costs about a clearance query per box instead of a distance query.
// signed_distance: out[i] is boxcyl::signed_distance(boxes[i], cylinder), bit for bit
// (boxcyl/signed_distance.hpp: the distance's enclosure where they are apart, minus the penetration
// depth's where they overlap, with a normal and witnesses).
//
// Options: threads (0: all cores) over contiguous 64-box blocks — unlike the filter's batches, already
// worth it from a few hundred boxes, as each distance costs microseconds; stop (checked before each
// block); check_boxes (an invalid box throws InvalidBox). The kernel option applies to
// distance_within's filter only. Stats::boxes is N, Stats::exact_lanes the boxes whose distance was
// computed. An invalid cylinder throws std::invalid_argument naming the field; out must have N elements.
#pragma once

#include <algorithm>  // std::min
#include <cstddef>    // std::size_t
#include <cstdint>    // std::uint64_t
#include <limits>     // infinity, NaN
#include <span>       // inputs and outputs
#include <stdexcept>  // std::invalid_argument
#include <thread>     // hardware_concurrency
#include <vector>     // the filter's mask

#include "boxcyl/batch/split.hpp"
#include "boxcyl/batch/types.hpp"
#include "boxcyl/distance.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/query.hpp"  // detail::cast: float boxes widened
#include "boxcyl/signed_distance.hpp"

namespace boxcyl::batch {

namespace distances {

template <class T>
AlignedBox<double> box_at(const AlignedBoxes<T>& b, std::size_t i) {
    return {{b.min_x[i], b.min_y[i], b.min_z[i]}, {b.max_x[i], b.max_y[i], b.max_z[i]}};
}
template <class Box>
const Box& box_at(std::span<const Box> b, std::size_t i) {
    return b[i];
}

// answer(box, i, out[i]) for every box (widened to double): true where it computed the box's answer.
template <class Out, class Boxes, class Answer>
Stats run(const Cylinder<double>& cyl, const Boxes& boxes, std::span<Out> out, const Options& opt, Answer&& answer) {
    if (const Validity v = validate(cyl); !v.ok()) throw std::invalid_argument(v.message());
    const std::size_t n = boxes.size(), blocks = (n + 63) / 64;
    if (out.size() < n) throw std::invalid_argument("boxcyl::batch::distance: output has fewer elements than boxes");
    unsigned threads = opt.threads != 0 ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, blocks)));
    std::vector<std::size_t> computed(threads, 0);
    split::for_each_range(blocks, threads, [&](std::size_t first, std::size_t last, unsigned t) {
        for (std::size_t blk = first; blk < last; ++blk) {
            if (opt.stop.stop_requested()) throw Stopped();
            const std::size_t begin = blk * 64, end = std::min(n, begin + 64);
            for (std::size_t i = begin; i < end; ++i) {
                const auto& box = box_at(boxes, i);
                if (opt.check_boxes && !is_valid(box)) throw InvalidBox(i);
                computed[t] += answer(boxcyl::detail::cast<double>(box), i, out[i]) ? 1 : 0;
            }
        }
    });
    Stats st;
    st.boxes = n;
    st.lanes = 1;
    st.kernel = Kernel::compiled;
    for (std::size_t c : computed) st.exact_lanes += c;
    return st;
}

// The distance of every box for which wanted(i) holds; the others get [margin, +∞] and NaN witnesses.
template <class Boxes, class Wanted>
Stats run(const Cylinder<double>& cyl, const Boxes& boxes, std::span<Distance> out, const Options& opt, double margin,
          Wanted&& wanted) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    return run(cyl, boxes, out, opt, [&](const auto& box, std::size_t i, Distance& d) {
        if (!wanted(i)) {
            d = {margin, std::numeric_limits<double>::infinity(), {nan, nan, nan}, {nan, nan, nan}};
            return false;
        }
        d = distance_unchecked(box, cyl);
        return true;
    });
}

template <class Boxes>
Stats all(const Cylinder<double>& cyl, const Boxes& boxes, std::span<Distance> out, const Options& opt) {
    return run(cyl, boxes, out, opt, 0.0, [](std::size_t) { return true; });
}

// The clearance filter first (its own validation of the margin and, with check_boxes, of the boxes).
template <class Boxes>
Stats within(const Cylinder<double>& cyl, const Boxes& boxes, double margin, std::span<Distance> out,
             const Options& opt) {
    std::vector<std::uint64_t> mask(mask_words(boxes.size()));
    detail::within(cyl, boxes, margin, std::span<std::uint64_t>(mask), opt);  // qualified: the header's own, not a compiled overload
    return run(cyl, boxes, out, opt, margin, [&](std::size_t i) { return (mask[i / 64] >> (i % 64)) & 1u; });
}

template <class Boxes>
Stats signed_all(const Cylinder<double>& cyl, const Boxes& boxes, std::span<SignedDistance> out, const Options& opt) {
    return run(cyl, boxes, out, opt, [&](const auto& box, std::size_t, SignedDistance& d) {
        d = signed_distance_unchecked(box, cyl);
        return true;
    });
}

}  // namespace distances

// ---- Every box's distance. ----
template <class T>
Stats distance(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, std::span<Distance> out, const Options& opt = {}) {
    detail::check_lengths(boxes);
    return distances::all(cyl, boxes, out, opt);
}
// (Overloads rather than a template, so that a std::vector of boxes converts to the span.)
inline Stats distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::all(cyl, boxes, out, opt);
}
inline Stats distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::all(cyl, boxes, out, opt);
}
inline Stats distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::all(cyl, boxes, out, opt);
}
inline Stats distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::all(cyl, boxes, out, opt);
}
inline Stats distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::all(cyl, boxes, out, opt);
}
inline Stats distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::all(cyl, boxes, out, opt);
}

// ---- The distance of the boxes within `margin`; [margin, +∞] for the others. ----
template <class T>
Stats distance_within(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, double margin, std::span<Distance> out,
                      const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}
inline Stats distance_within(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes, double margin,
                             std::span<Distance> out, const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}
inline Stats distance_within(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes, double margin,
                             std::span<Distance> out, const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}
inline Stats distance_within(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, double margin,
                             std::span<Distance> out, const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}
inline Stats distance_within(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, double margin,
                             std::span<Distance> out, const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}
inline Stats distance_within(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, double margin,
                             std::span<Distance> out, const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}
inline Stats distance_within(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, double margin,
                             std::span<Distance> out, const Options& opt = {}) {
    return distances::within(cyl, boxes, margin, out, opt);
}

// ---- Every box's signed distance. ----
template <class T>
Stats signed_distance(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, std::span<SignedDistance> out,
                      const Options& opt = {}) {
    detail::check_lengths(boxes);
    return distances::signed_all(cyl, boxes, out, opt);
}
inline Stats signed_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<double>> boxes,
                             std::span<SignedDistance> out, const Options& opt = {}) {
    return distances::signed_all(cyl, boxes, out, opt);
}
inline Stats signed_distance(const Cylinder<double>& cyl, std::span<const AlignedBox<float>> boxes,
                             std::span<SignedDistance> out, const Options& opt = {}) {
    return distances::signed_all(cyl, boxes, out, opt);
}
inline Stats signed_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes,
                             std::span<SignedDistance> out, const Options& opt = {}) {
    return distances::signed_all(cyl, boxes, out, opt);
}
inline Stats signed_distance(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes,
                             std::span<SignedDistance> out, const Options& opt = {}) {
    return distances::signed_all(cyl, boxes, out, opt);
}
inline Stats signed_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes,
                             std::span<SignedDistance> out, const Options& opt = {}) {
    return distances::signed_all(cyl, boxes, out, opt);
}
inline Stats signed_distance(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes,
                             std::span<SignedDistance> out, const Options& opt = {}) {
    return distances::signed_all(cyl, boxes, out, opt);
}

// A float cylinder is widened to double exactly, like the boxes.
template <class Boxes>
Stats distance(const Cylinder<float>& cyl, const Boxes& boxes, std::span<Distance> out, const Options& opt = {}) {
    return distance(detail::widen(cyl), boxes, out, opt);
}
template <class Boxes>
Stats distance_within(const Cylinder<float>& cyl, const Boxes& boxes, double margin, std::span<Distance> out,
                      const Options& opt = {}) {
    return distance_within(detail::widen(cyl), boxes, margin, out, opt);
}

template <class Boxes>
Stats signed_distance(const Cylinder<float>& cyl, const Boxes& boxes, std::span<SignedDistance> out,
                      const Options& opt = {}) {
    return signed_distance(detail::widen(cyl), boxes, out, opt);
}

}  // namespace boxcyl::batch
