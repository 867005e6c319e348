// The batch API (issue #5): one cylinder against N boxes, exactly, with a SIMD filter and threads.
//
//   boxcyl::batch::intersects(cylinder, boxes, out[, Options{threads}]) -> Stats
//
// Answers are those of the scalar exact default boxcyl::intersects(box, cylinder) for every box, bit for
// bit: each double is the rational it denotes, u = axis/|axis| exactly, closed solids (touching
// intersects). Float inputs are widened to double (exactly) first, so a float box means what the same
// box in double means.
//
// Boxes:
//   AlignedBoxes<T>   structure of arrays: box i is [min_x[i], max_x[i]] × [min_y[i], max_y[i]] ×
//                     [min_z[i], max_z[i]]; six spans of the same length, T = float or double.
//   OrientedBox<T>    array of structures (std::span<const OrientedBox<T>>), T = float or double: the
//                     library's own struct, so existing arrays need no copy; the filter gathers each
//                     vector of lanes from it.
// Output: a bit mask (bit i of word i/64 is box i; the unused high bits of the last word are cleared;
// at least (N + 63)/64 words) or one bool per box. Stats::exact_lanes counts the boxes that the filter
// left to the scalar query.
//
// How: batch/filter.hpp decides each lane that it can prove (certain miss by a separating direction,
// certain hit by a box point inside the cylinder, with proven error bounds: docs/robustness.md §8);
// every undecided lane is answered by the scalar exact default (filtered::query). Aligned boxes take
// two passes: a cheap one over every box (bounding boxes, then the box's centre and a ball around it:
// §8a), then the whole filter on the few lanes it left, gathered into full vectors. SIMD width: that of
// std::experimental::simd's native ABI under the compile flags (2 doubles with the default x86-64
// flags; -mavx2 gives 4, -march=native on an AVX-512 machine 8). Threads: contiguous ranges of 64-box
// blocks (batch/split.hpp); Options::threads = 0 uses std::thread::hardware_concurrency(), and a
// batch smaller than 32768 boxes per thread uses fewer threads (one below 65536 boxes).
//
// Preconditions: validate() holds for the cylinder and every box (asserted in debug builds); the
// floating-point environment is the default one (round to nearest, no flush-to-zero: see
// boxcyl::fp_environment_ok()). Needs the exact backend (link boxcyl::exact), like the default query.
#pragma once

#if !defined(BOXCYL_HAS_EXACT)
#error "boxcyl/batch.hpp answers exactly and needs the exact backend: link boxcyl::exact (GMP)"
#endif

#include <algorithm>  // std::min
#include <bit>        // std::countr_zero, std::popcount
#include <cassert>    // debug-build precondition checks
#include <cstddef>    // std::size_t
#include <cstdint>    // std::uint64_t
#include <span>       // inputs and outputs
#include <stdexcept>  // std::invalid_argument for mismatched lengths
#include <utility>    // std::forward
#include <vector>     // per-thread counters

#include "boxcyl/batch/filter.hpp"
#include "boxcyl/batch/split.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/validate.hpp"

namespace boxcyl::batch {

// Aligned boxes as six arrays (all the same length).
template <class T>
struct AlignedBoxes {
    std::span<const T> min_x, min_y, min_z, max_x, max_y, max_z;
    std::size_t size() const { return min_x.size(); }
};

struct Options {
    unsigned threads = 1;  // 0: std::thread::hardware_concurrency()
};

struct Stats {
    std::size_t boxes = 0;        // N
    std::size_t exact_lanes = 0;  // boxes the SIMD filter could not decide: answered by the scalar query
    std::size_t second_pass = 0;  // aligned boxes that the first pass left to the whole filter (diagnostic)
};

// Words of a bit mask for n boxes.
constexpr std::size_t mask_words(std::size_t n) { return (n + 63) / 64; }

namespace detail {

// Loads lanes [i, i + valid) into full vectors; a short tail repeats its last box (its lanes are
// computed and ignored).
template <class T>
BOXCYL_BATCH_INLINE void load(const T* p, std::size_t i, std::size_t valid, Lanes& out) {
    if (valid == lane_count) {
        out.copy_from(p + i, stdx::element_aligned);  // converting load for float: exact
        return;
    }
    alignas(64) double buf[lane_count];
    for (std::size_t k = 0; k < lane_count; ++k) buf[k] = static_cast<double>(p[i + std::min(k, valid - 1)]);
    out.copy_from(buf, stdx::element_aligned);
}

// Lanes p[idx[0]], …, p[idx[count − 1]], the last repeated to fill the vector. Built from the scalars
// (the simd generator constructor): written to a buffer lane by lane and loaded as one vector, they
// stalled store forwarding, a tenth of the 10M random-box run.
template <class T>
BOXCYL_BATCH_INLINE Lanes gather(const T* p, const std::size_t* idx, std::size_t count) {
    return Lanes([&](auto l) { return static_cast<double>(p[idx[std::min<std::size_t>(l, count - 1)]]); });
}

template <class T>
struct AlignedSource {
    const AlignedBoxes<T>& b;

    // First pass: lanes [i, i + valid), the centre-and-ball tests.
    BOXCYL_BATCH_INLINE LaneResult lanes(const CylinderFilter& f, std::size_t i, std::size_t valid) const {
        Lanes lo[3], hi[3];
        load(b.min_x.data(), i, valid, lo[0]);
        load(b.min_y.data(), i, valid, lo[1]);
        load(b.min_z.data(), i, valid, lo[2]);
        load(b.max_x.data(), i, valid, hi[0]);
        load(b.max_y.data(), i, valid, hi[1]);
        load(b.max_z.data(), i, valid, hi[2]);
        return aligned_ball_lanes(f, lo, hi);
    }
    // Second pass: the boxes idx[0, count) (count ≤ lane_count) that the first left, gathered, through
    // the whole filter.
    LaneResult gathered(const CylinderFilter& f, const std::size_t* idx, std::size_t count) const {
        const T* arrays[6] = {b.min_x.data(), b.min_y.data(), b.min_z.data(), b.max_x.data(), b.max_y.data(), b.max_z.data()};
        Lanes lo[3], hi[3];
        for (int j = 0; j < 3; ++j) {
            lo[j] = gather(arrays[j], idx, count);
            hi[j] = gather(arrays[3 + j], idx, count);
        }
        return aligned_lanes(f, lo, hi);
    }
    AlignedBox<double> box(std::size_t i) const {
        return {{double(b.min_x[i]), double(b.min_y[i]), double(b.min_z[i])},
                {double(b.max_x[i]), double(b.max_y[i]), double(b.max_z[i])}};
    }
};

template <class T>
struct OrientedSource {
    std::span<const OrientedBox<T>> b;

    // One pass: the whole filter.
    LaneResult lanes(const CylinderFilter& f, std::size_t i, std::size_t valid) const {
        // The array of structures as 15 lane vectors, each built from its lanes' scalars.
        const OrientedBox<T>* x = b.data() + i;
        auto lane = [x, valid](std::size_t l) -> const OrientedBox<T>& { return x[std::min(l, valid - 1)]; };
        Lanes k[3], A[3][3], e[3];
        for (int j = 0; j < 3; ++j) {
            k[j] = Lanes([&](auto l) { return static_cast<double>(lane(l).center[j]); });
            e[j] = Lanes([&](auto l) { return static_cast<double>(lane(l).extents[j]); });
            for (int a = 0; a < 3; ++a) A[a][j] = Lanes([&](auto l) { return static_cast<double>(lane(l).axes[a][j]); });
        }
        return oriented_lanes(f, k, A, e);
    }
    OrientedBox<double> box(std::size_t i) const {
        const OrientedBox<T>& x = b[i];
        auto d = [](const Vec3<T>& v) { return Vec3<double>{double(v[0]), double(v[1]), double(v[2])}; };
        return {d(x.center), {d(x.axes[0]), d(x.axes[1]), d(x.axes[2])}, d(x.extents)};
    }
};

// The lanes of two masks as bits 0..lane_count−1 of two words: through a sum of powers of two over
// the lanes (exact), a few vector instructions; testing lane by lane made the 10M random-box run about
// a tenth slower (voxels, whose vectors mostly skip this, the same).
struct LaneBits {
    std::uint64_t hit, open;
};
BOXCYL_BATCH_INLINE LaneBits to_bits(const LaneResult& r) {
    static_assert(lane_count <= 16, "the weights below must stay exact sums");
    const Lanes weight([](auto l) { return static_cast<double>(1u << l); });
    Lanes z = 0;
    stdx::where(r.hit, z) = weight;
    stdx::where(!r.decided, z) = weight * 65536.0;  // hit ⊂ decided: no lane gets both
    const auto sum = static_cast<std::uint64_t>(stdx::reduce(z));
    return {sum & 0xFFFF, sum >> 16};
}

// Answers for boxes [begin, begin + count), count ≤ 64, as bits 0..count−1: the first pass over every
// vector of boxes without a branch per lane; a source with a second pass (aligned boxes) sends the
// lanes the first left undecided through it, gathered into full vectors; what is still undecided goes
// to the scalar exact default, one box at a time.
template <class Source>
std::uint64_t block_bits(const CylinderFilter& f, const Cylinder<double>& cyl, const Source& s, std::size_t begin,
                         std::size_t count, Stats& st) {
#ifndef NDEBUG
    for (std::size_t i = begin; i < begin + count; ++i)
        assert(validate(s.box(i)).ok() && "boxcyl::batch::intersects: invalid box (see boxcyl::validate)");
#endif
    std::uint64_t bits = 0, open = 0;
    for (std::size_t k = 0; k < count; k += lane_count) {
        const std::size_t valid = std::min(lane_count, count - k);
        const LaneResult r = s.lanes(f, begin + k, valid);
        if (stdx::all_of(r.decided) && stdx::none_of(r.hit)) continue;  // certain misses: the common case
        static_assert(lane_count < 64);
        const std::uint64_t in_range = (std::uint64_t{1} << valid) - 1;
        const LaneBits b = to_bits(r);
        bits |= (b.hit & in_range) << k;
        open |= (b.open & in_range) << k;
    }
    if constexpr (requires(const std::size_t* p) { s.gathered(f, p, std::size_t{1}); }) {
        if (open != 0) {
            st.second_pass += static_cast<std::size_t>(std::popcount(open));
            std::size_t idx[64], n = 0;
            for (std::uint64_t o = open; o != 0; o &= o - 1) idx[n++] = begin + static_cast<std::size_t>(std::countr_zero(o));
            for (std::size_t g = 0; g < n; g += lane_count) {
                const std::size_t m = std::min(lane_count, n - g);
                const LaneResult r = s.gathered(f, idx + g, m);
                for (std::size_t l = 0; l < m; ++l)
                    if (r.decided[l]) {
                        const std::uint64_t bit = std::uint64_t{1} << (idx[g + l] - begin);
                        open &= ~bit;
                        if (r.hit[l]) bits |= bit;
                    }
            }
        }
    }
    for (std::uint64_t o = open; o != 0; o &= o - 1) {
        const std::size_t i = begin + static_cast<std::size_t>(std::countr_zero(o));
        if (filtered::query(s.box(i), cyl).intersect) bits |= std::uint64_t{1} << (i - begin);
        ++st.exact_lanes;
    }
    return bits;
}

// Runs the blocks over the threads; emit(block, bits, count) stores one block's answers.
template <class Source, class Emit>
Stats run(const Cylinder<double>& cyl, const Source& s, std::size_t n, const Options& opt, Emit&& emit) {
    assert(validate(cyl).ok() && "boxcyl::batch::intersects: invalid cylinder (see boxcyl::validate)");
    const CylinderFilter f = prepare(cyl);
    const std::size_t blocks = mask_words(n);
    const unsigned threads = thread_count(opt.threads, n);
    std::vector<Stats> per_thread(threads);
    for_each_range(blocks, threads, [&](std::size_t first, std::size_t last, unsigned t) {
        Stats x;
        for (std::size_t blk = first; blk < last; ++blk) {
            const std::size_t begin = blk * 64, count = std::min<std::size_t>(64, n - begin);
            emit(blk, block_bits(f, cyl, s, begin, count, x), count);
        }
        per_thread[t] = x;
    });
    Stats st;
    st.boxes = n;
    for (const Stats& x : per_thread) st.exact_lanes += x.exact_lanes, st.second_pass += x.second_pass;
    return st;
}

template <class Source>
Stats to_mask(const Cylinder<double>& cyl, const Source& s, std::size_t n, std::span<std::uint64_t> mask,
              const Options& opt) {
    if (mask.size() < mask_words(n)) throw std::invalid_argument("boxcyl::batch::intersects: mask has too few words");
    return run(cyl, s, n, opt, [&](std::size_t blk, std::uint64_t bits, std::size_t) { mask[blk] = bits; });
}

template <class Source>
Stats to_bools(const Cylinder<double>& cyl, const Source& s, std::size_t n, std::span<bool> out, const Options& opt) {
    if (out.size() < n) throw std::invalid_argument("boxcyl::batch::intersects: output has fewer elements than boxes");
    return run(cyl, s, n, opt, [&](std::size_t blk, std::uint64_t bits, std::size_t count) {
        for (std::size_t l = 0; l < count; ++l) out[blk * 64 + l] = (bits >> l) & 1u;
    });
}

template <class T>
void check_lengths(const AlignedBoxes<T>& b) {
    const std::size_t n = b.min_x.size();
    if (b.min_y.size() != n || b.min_z.size() != n || b.max_x.size() != n || b.max_y.size() != n ||
        b.max_z.size() != n)
        throw std::invalid_argument("boxcyl::batch::intersects: the six box arrays have different lengths");
}

inline Cylinder<double> widen(const Cylinder<float>& c) {
    auto d = [](const Vec3<float>& v) { return Vec3<double>{v[0], v[1], v[2]}; };
    return {d(c.center), d(c.axis), c.radius, c.height};
}

}  // namespace detail

// ---- Aligned boxes (structure of arrays), T = float or double. ----
template <class T>
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, std::span<std::uint64_t> mask,
                 const Options& opt = {}) {
    detail::check_lengths(boxes);
    return detail::to_mask(cyl, detail::AlignedSource<T>{boxes}, boxes.size(), mask, opt);
}
template <class T>
Stats intersects(const Cylinder<double>& cyl, const AlignedBoxes<T>& boxes, std::span<bool> out,
                 const Options& opt = {}) {
    detail::check_lengths(boxes);
    return detail::to_bools(cyl, detail::AlignedSource<T>{boxes}, boxes.size(), out, opt);
}

// ---- Oriented boxes (array of OrientedBox<T>), T = float or double. ----
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::to_mask(cyl, detail::OrientedSource<double>{boxes}, boxes.size(), mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<double>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return detail::to_bools(cyl, detail::OrientedSource<double>{boxes}, boxes.size(), out, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes,
                        std::span<std::uint64_t> mask, const Options& opt = {}) {
    return detail::to_mask(cyl, detail::OrientedSource<float>{boxes}, boxes.size(), mask, opt);
}
inline Stats intersects(const Cylinder<double>& cyl, std::span<const OrientedBox<float>> boxes, std::span<bool> out,
                        const Options& opt = {}) {
    return detail::to_bools(cyl, detail::OrientedSource<float>{boxes}, boxes.size(), out, opt);
}

// A float cylinder is widened to double exactly, like the boxes.
template <class Boxes, class Out>
Stats intersects(const Cylinder<float>& cyl, const Boxes& boxes, Out&& out, const Options& opt = {}) {
    return intersects(detail::widen(cyl), boxes, std::forward<Out>(out), opt);
}

}  // namespace boxcyl::batch
