// Parallelepipeds in the batch API: one cylinder against a span of boxcyl::Parallelepiped<T>.
//
// No SIMD filter: each box is answered by the scalar default query (filtered.hpp, its
// own certified stages and exact fallback), in contiguous 64-box blocks over the threads of
// Options::threads (batch/split.hpp). That is the header's own code, one box at a time: Stats::kernel
// is Kernel::compiled with Stats::lanes = 1, for Options::kernel automatic or compiled. There is no
// AVX2 or AVX-512 kernel for parallelepipeds: asking for one throws std::invalid_argument, as asking
// for a kernel that is not available does, rather than run something else. Stats::exact_lanes counts
// the boxes that reached the exact stage (as filtered::Result::exact_used). The answers are those of
// boxcyl::intersects(box, cyl). The clearance form (batch::within_distance) answers each box by the
// scalar within_distance_unchecked, and counts every box in Stats::exact_lanes.
#pragma once

#if !defined(BOXCYL_HAS_EXACT)
#error "boxcyl/batch/parallelepiped.hpp answers exactly and needs the exact backend: link boxcyl::exact (GMP)"
#endif

#include <algorithm>  // std::min
#include <cstddef>    // std::size_t
#include <cstdint>    // std::uint64_t
#include <span>       // inputs and outputs
#include <stdexcept>  // std::invalid_argument for short outputs and SIMD kernels
#include <string>     // its message
#include <vector>     // per-thread counts

#include "boxcyl/batch/split.hpp"
#include "boxcyl/batch/types.hpp"
#include "boxcyl/clearance.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"  // Options::check_boxes

namespace boxcyl::batch::parallelepipeds {

template <class T>
Parallelepiped<double> widened(const Parallelepiped<T>& b) {
    auto d = [](const Vec3<T>& v) { return Vec3<double>{double(v[0]), double(v[1]), double(v[2])}; };
    return {d(b.center), {d(b.axes[0]), d(b.axes[1]), d(b.axes[2])}, d(b.extents)};
}

// One box's answer, and whether the exact stage (or, for the clearance query, the scalar clearance
// query: every box) answered it, for query q (a cylinder: intersects; a Clearance: within_distance).
struct Answer {
    bool yes, exact;
};
inline Answer answer_one(const Parallelepiped<double>& box, const Cylinder<double>& cyl) {
    const filtered::Result r = filtered::query(box, cyl);
    return {r.intersect, r.exact_used};
}
inline Answer answer_one(const Parallelepiped<double>& box, const Clearance& q) {
    return {within_distance_unchecked(box, q.cylinder, q.margin), true};
}

// emit(block, bits, count) for each 64-box block.
template <class Query, class T, class Emit>
Stats run(const Query& q, std::span<const Parallelepiped<T>> boxes, const Options& opt, Emit&& emit) {
    if (opt.kernel != Kernel::automatic && opt.kernel != Kernel::compiled)
        throw std::invalid_argument(std::string("boxcyl::batch: kernel '") + name(opt.kernel) +
                                    "' does not exist for parallelepipeds: they are answered one at a time by the "
                                    "scalar query (Kernel::compiled, or Kernel::automatic)");
    const std::size_t n = boxes.size(), blocks = (n + 63) / 64;
    const unsigned threads = split::thread_count(opt.threads, n);
    std::vector<std::size_t> exact(threads, 0);
    split::for_each_range(blocks, threads, [&](std::size_t first, std::size_t last, unsigned t) {
        for (std::size_t blk = first; blk < last; ++blk) {
            if (opt.stop.stop_requested()) throw Stopped();
            const std::size_t begin = blk * 64, count = std::min<std::size_t>(64, n - begin);
            std::uint64_t bits = 0;
            if (opt.check_boxes)
                for (std::size_t l = 0; l < count; ++l)
                    if (!is_valid(boxes[begin + l])) throw InvalidBox(begin + l);
            for (std::size_t l = 0; l < count; ++l) {
                const Answer a = answer_one(widened(boxes[begin + l]), q);
                bits |= std::uint64_t(a.yes) << l;
                exact[t] += a.exact;
            }
            emit(blk, bits, count);
        }
    });
    Stats st;
    st.boxes = n;
    st.lanes = 1;
    st.kernel = Kernel::compiled;
    for (std::size_t e : exact) st.exact_lanes += e;
    return st;
}

template <class Query, class T>
Stats answer(const Query& q, std::span<const Parallelepiped<T>> boxes, std::span<std::uint64_t> mask,
             const Options& opt) {
    if (mask.size() < mask_words(boxes.size())) throw std::invalid_argument("boxcyl::batch: mask has too few words");
    return run(q, boxes, opt, [&](std::size_t blk, std::uint64_t bits, std::size_t) { mask[blk] = bits; });
}
template <class Query, class T>
Stats answer(const Query& q, std::span<const Parallelepiped<T>> boxes, std::span<bool> out, const Options& opt) {
    if (out.size() < boxes.size())
        throw std::invalid_argument("boxcyl::batch: output has fewer elements than boxes");
    return run(q, boxes, opt, [&](std::size_t blk, std::uint64_t bits, std::size_t count) {
        for (std::size_t l = 0; l < count; ++l) out[blk * 64 + l] = (bits >> l) & 1u;
    });
}

}  // namespace boxcyl::batch::parallelepipeds

namespace boxcyl::batch {

// (Overloads rather than a template, so that a std::vector of boxes converts to the span.)
inline Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return parallelepipeds::answer(cyl, boxes, mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<double>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return parallelepipeds::answer(cyl, boxes, out, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return parallelepipeds::answer(cyl, boxes, mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const Parallelepiped<float>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return parallelepipeds::answer(cyl, boxes, out, opt);
}

}  // namespace boxcyl::batch
