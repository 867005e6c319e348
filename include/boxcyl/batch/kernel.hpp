// The batch kernel (boxcyl/batch.hpp): one cylinder against the boxes of one call, at the vector width
// of batch/filter.hpp's Lanes — the SIMD filter over every vector of boxes, a second pass for aligned
// boxes over the lanes the first left (gathered into full vectors), for oriented boxes the hit search
// over the lanes the first left (gathered), the scalar exact default for what is still undecided, the
// blocks split over threads. The clearance form (batch::within_distance) runs the same filter on its
// probe cylinders and leaves what they do not decide to the scalar clearance query. Everything here lives in filter.hpp's instruction-set namespace
// (BOXCYL_BATCH_ISA), so that the kernel can be compiled once per instruction set into one program
// (src/batch/: AVX2, AVX-512) beside the header's own.
#pragma once

#include <algorithm>  // std::min
#include <bit>        // std::countr_zero, std::popcount
#include <cassert>    // debug-build precondition checks
#include <cstddef>    // std::size_t, std::nullptr_t
#include <cstdint>    // std::uint64_t
#include <limits>       // DBL_MAX: the boxes' cheap check
#include <span>         // inputs and outputs
#include <stdexcept>    // std::invalid_argument for short outputs
#include <type_traits>  // std::is_same_v: the rows' in-register transpose is for doubles
#include <vector>       // per-thread counters

#if defined(__AVX2__)
#include <immintrin.h>  // gather(): _mm512_set_pd; AlignedRowsSource's column gathers
#endif

#include "boxcyl/batch/filter.hpp"
#include "boxcyl/batch/split.hpp"
#include "boxcyl/batch/types.hpp"
#if defined(BOXCYL_BATCH_SCALAR_APART)
#include "boxcyl/batch/dispatch.hpp"  // scalar_intersects
#else
#include "boxcyl/filtered.hpp"
#endif
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/validate.hpp"

namespace boxcyl::batch {
inline namespace BOXCYL_BATCH_ISA {
namespace detail {

// Loads lanes [i, i + valid) into full vectors; a short tail repeats its last box (its lanes are
// computed and ignored).
template <class T>
BOXCYL_FORCE_INLINE inline void load(const T* p, std::size_t i, std::size_t valid, Lanes& out) {
    if (valid == lane_count) {
        out.copy_from(p + i, stdx::element_aligned);  // converting load for float: exact
        return;
    }
    alignas(64) double buf[lane_count];
    for (std::size_t k = 0; k < lane_count; ++k) buf[k] = static_cast<double>(p[i + std::min(k, valid - 1)]);
    out.copy_from(buf, stdx::element_aligned);
}

// Lanes value(idx[0]), …, value(idx[count − 1]), the last repeated to fill the vector. Built from the
// scalars: written to a buffer lane by lane and loaded as one vector, they stalled store forwarding
// (a tenth of the 10M random-box run). With AVX-512 by _mm512_set_pd: GCC kept the simd generator
// constructor, the portable form, out of line in that kernel only (a call per gathered vector; 10M
// random boxes 10.3 → 9.2 ns per box, near-surface aligned sets 7% faster). It inlines it for SSE2
// and AVX2, where the set intrinsics were no faster.
template <class Value>
BOXCYL_FORCE_INLINE inline Lanes gather(const Value& value, const std::size_t* idx, std::size_t count) {
    auto at = [&](std::size_t l) { return static_cast<double>(value(idx[std::min(l, count - 1)])); };
#if defined(__AVX512F__)
    if constexpr (lane_count == 8)
        return Lanes(_mm512_set_pd(at(7), at(6), at(5), at(4), at(3), at(2), at(1), at(0)));
#endif
    return Lanes([&](auto l) { return at(l); });
}

// Whether every lane certainly passes is_valid (Options::check_boxes), for oriented boxes: every number
// finite, extents ≥ 0, and the Gram matrix of the axes in double within 10^-12 inside validate()'s
// tolerance (for axes of length about 1 its rounding error is below 10^-15, and an axis much longer
// fails its diagonal entry whatever the rounding; NaN and ∞ fail every comparison).
BOXCYL_FORCE_INLINE inline bool plausible(const Lanes k[3], const Lanes A[3][3], const Lanes e[3]) {
    constexpr double top = std::numeric_limits<double>::max(), tol = orthonormality_tolerance - 1e-12;
    LaneMask ok = stdx::abs(k[0]) <= top && stdx::abs(k[1]) <= top && stdx::abs(k[2]) <= top && e[0] >= 0 &&
                  e[0] <= top && e[1] >= 0 && e[1] <= top && e[2] >= 0 && e[2] <= top;
    for (int a = 0; a < 3; ++a)
        for (int c = a; c < 3; ++c) {
            const Lanes g = A[a][0] * A[c][0] + A[a][1] * A[c][1] + A[a][2] * A[c][2];
            ok = ok && stdx::abs(g - (a == c ? 1.0 : 0.0)) <= tol;  // finite axes follow from these
        }
    return stdx::all_of(ok);
}

// Whether every lane certainly passes is_valid (Options::check_boxes): hi − lo in [0, DBL_MAX] is false
// for NaN, ±∞ and lo > hi (and for bounds whose difference overflows: is_valid judges those).
BOXCYL_FORCE_INLINE inline bool plausible(const Lanes lo[3], const Lanes hi[3]) {
    constexpr double top = std::numeric_limits<double>::max();
    const Lanes d0 = hi[0] - lo[0], d1 = hi[1] - lo[1], d2 = hi[2] - lo[2];
    return stdx::all_of(d0 >= 0 && d0 <= top && d1 >= 0 && d1 <= top && d2 >= 0 && d2 <= top);
}

template <class T>
struct AlignedSource {
    const AlignedBoxes<T>& b;

    // First pass: lanes [i, i + valid) (filter_block runs the centre-and-ball tests on them).
    BOXCYL_FORCE_INLINE inline void load_lanes(std::size_t i, std::size_t valid, Lanes lo[3], Lanes hi[3]) const {
        load(b.min_x.data(), i, valid, lo[0]);
        load(b.min_y.data(), i, valid, lo[1]);
        load(b.min_z.data(), i, valid, lo[2]);
        load(b.max_x.data(), i, valid, hi[0]);
        load(b.max_y.data(), i, valid, hi[1]);
        load(b.max_z.data(), i, valid, hi[2]);
    }
    // Second pass: the boxes idx[0, count) (count ≤ lane_count) that the first left, gathered, through
    // the whole filter.
    LaneResult gathered(const CylinderFilter& f, const std::size_t* idx, std::size_t count) const {
        const T* arrays[6] = {b.min_x.data(), b.min_y.data(), b.min_z.data(), b.max_x.data(), b.max_y.data(), b.max_z.data()};
        Lanes lo[3], hi[3];
        for (int j = 0; j < 3; ++j) {
            const T* lo_j = arrays[j];
            const T* hi_j = arrays[3 + j];
            lo[j] = gather([lo_j](std::size_t k) { return lo_j[k]; }, idx, count);
            hi[j] = gather([hi_j](std::size_t k) { return hi_j[k]; }, idx, count);
        }
        return aligned_lanes(f, lo, hi);
    }
    AlignedBox<double> box(std::size_t i) const {
        return {{double(b.min_x[i]), double(b.min_y[i]), double(b.min_z[i])},
                {double(b.max_x[i]), double(b.max_y[i]), double(b.max_z[i])}};
    }
};

// Aligned boxes as an array of AlignedBox<T> (rows of six numbers: min, max), read in place: each
// vector of lanes is taken from the rows in registers, so the caller's array is read once and no
// structure-of-arrays copy exists.
template <class T>
struct AlignedRowsSource {
    std::span<const AlignedBox<T>> b;
    static_assert(sizeof(AlignedBox<T>) == 6 * sizeof(T), "AlignedBox<T> must be six packed numbers");
    // Rows prefetched this many boxes ahead of the vector being loaded. One stream of rows, with the
    // filter's work between its loads, got less from the hardware prefetcher than six arrays do: at
    // 10^6 random boxes (AVX-512) the rows ran ≈15% slower than the six arrays without it, the same
    // speed with it (64 and 256 boxes alike: bench/python_batch.py, aligned c++ rows against c++).
    static constexpr std::size_t kAhead = 64;

    BOXCYL_FORCE_INLINE inline void load_lanes(std::size_t i, std::size_t valid, Lanes lo[3], Lanes hi[3]) const {
#if defined(__GNUC__)
        if (i + kAhead + lane_count <= b.size()) {
            const char* ahead = reinterpret_cast<const char*>(b.data() + i + kAhead);
            for (std::size_t line = 0; line < lane_count * sizeof(AlignedBox<T>); line += 64) __builtin_prefetch(ahead + line);
        }
#endif
#if defined(__AVX2__)
        // A full vector of double rows: each column by one gather instruction (element c of row r
        // is 6r + c doubles from the first row). Beside the six arrays, the filter's first pass
        // here costs 5–8% more (bench_batch: batched/regular/aligned_rows against aligned, AVX-512);
        // an in-register transpose of the six loads (vpermt2pd, three a column) was no faster
        // (bench/python_batch.py's boxes; bench_batch's 10M random boxes) and takes more code.
        if constexpr (std::is_same_v<T, double> && (lane_count == 8 || lane_count == 4)) {
            if (valid == lane_count) {
                const char* p = reinterpret_cast<const char*>(b.data() + i);
                lo[0] = column(p), lo[1] = column(p + 8), lo[2] = column(p + 16);
                hi[0] = column(p + 24), hi[1] = column(p + 32), hi[2] = column(p + 40);
                return;
            }
        }
#endif
        const AlignedBox<T>* x = b.data() + i;
        const std::size_t last = valid - 1;
        for (std::size_t j = 0; j < 3; ++j) {
            lo[j] = Lanes([&](auto l) { return static_cast<double>(x[std::min<std::size_t>(l, last)].min[j]); });
            hi[j] = Lanes([&](auto l) { return static_cast<double>(x[std::min<std::size_t>(l, last)].max[j]); });
        }
    }
#if defined(__AVX2__)
    // Lanes p[0], p[6], p[12], … (doubles): one column of lane_count rows. L is Lanes, as a template
    // parameter: each branch's construction is then dependent and checked only where it is taken (clang
    // checks a non-dependent discarded one, and no 4-lane Lanes takes an __m512d or the reverse).
    template <class L = Lanes>
    BOXCYL_FORCE_INLINE inline static L column(const char* p) {
#if defined(__AVX512F__)
        if constexpr (lane_count == 8)
            return L(_mm512_i64gather_pd(_mm512_set_epi64(42, 36, 30, 24, 18, 12, 6, 0), p, 8));
#endif
        if constexpr (lane_count == 4)
            return L(_mm256_i64gather_pd(reinterpret_cast<const double*>(p), _mm256_set_epi64x(18, 12, 6, 0), 8));
        return L();
    }
#endif
    LaneResult gathered(const CylinderFilter& f, const std::size_t* idx, std::size_t count) const {
        const AlignedBox<T>* x = b.data();
        Lanes lo[3], hi[3];
        for (std::size_t j = 0; j < 3; ++j) {
            lo[j] = gather([x, j](std::size_t k) { return x[k].min[j]; }, idx, count);
            hi[j] = gather([x, j](std::size_t k) { return x[k].max[j]; }, idx, count);
        }
        return aligned_lanes(f, lo, hi);
    }
    AlignedBox<double> box(std::size_t i) const {
        const AlignedBox<T>& x = b[i];
        return {{double(x.min[0]), double(x.min[1]), double(x.min[2])}, {double(x.max[0]), double(x.max[1]), double(x.max[2])}};
    }
};

template <class T>
struct OrientedSource {
    std::span<const OrientedBox<T>> b;

    // First pass: lanes [i, i + valid) (filter_block runs the whole filter but its hit search on them).
    BOXCYL_FORCE_INLINE inline void load_frames(std::size_t i, std::size_t valid, Lanes k[3], Lanes A[3][3], Lanes e[3]) const {
        const OrientedBox<T>* x = b.data() + i;
        load([x, valid](std::size_t l) -> const OrientedBox<T>& { return x[std::min(l, valid - 1)]; }, k, A, e);
    }
    // Last pass: the hit search, on the boxes idx[0, count) that the first left, gathered.
    LaneResult searched(const CylinderFilter& f, const std::size_t* idx, std::size_t count) const {
        const OrientedBox<T>* x = b.data();
        Lanes k[3], A[3][3], e[3];
        load([x, idx, count](std::size_t l) -> const OrientedBox<T>& { return x[idx[std::min(l, count - 1)]]; }, k, A, e);
        return oriented_search_lanes(f, k, A, e);
    }
    // The array of structures as 15 lane vectors, each built from its lanes' scalars.
    template <class Lane>
    BOXCYL_FORCE_INLINE inline static void load(Lane&& lane, Lanes k[3], Lanes A[3][3], Lanes e[3]) {
        for (int j = 0; j < 3; ++j) {
            k[j] = Lanes([&](auto l) { return static_cast<double>(lane(l).center[j]); });
            e[j] = Lanes([&](auto l) { return static_cast<double>(lane(l).extents[j]); });
            for (int a = 0; a < 3; ++a) A[a][j] = Lanes([&](auto l) { return static_cast<double>(lane(l).axes[a][j]); });
        }
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
BOXCYL_FORCE_INLINE inline LaneBits to_bits(const LaneResult& r) {
    static_assert(lane_count <= 16, "the weights below must stay exact sums");
    const Lanes weight([](auto l) { return static_cast<double>(1u << l); });
    Lanes z = 0;
    stdx::where(r.hit, z) = weight;
    stdx::where(!r.decided, z) = weight * 65536.0;  // hit ⊂ decided: no lane gets both
    // The sum by a lambda of this file, not std::plus: a kernel compiled for AVX-512 under a `#pragma
    // GCC target` (src/batch/) cannot inline the vector addition into std::plus, defined before it.
    const auto sum = static_cast<std::uint64_t>(stdx::reduce(z, [](const auto& a, const auto& b) { return a + b; }));
    return {sum & 0xFFFF, sum >> 16};
}

struct BlockFilter {
    std::uint64_t hit, open;
};

// The most blocks whose open lanes one gathered pass takes together (group_bits below). Near the
// surface a block leaves one or two lanes open to each later pass; 32 blocks fill most of their vectors
// (on bench_batch's 10M voxels at a margin, the clearance form's later passes ran in fewer than half as many
// vectors as with 8 blocks; 64 were no faster).
inline constexpr std::size_t kGroupBlocks = 32;

// A pass over the lanes `open[b]` of the blocks b = 0, 1, … at begin + 64·b, gathered into full
// vectors: pass(idx, m) filters the boxes idx[0, m), m ≤ lane_count. The lanes it decides leave
// `open`; its hits join `bits`.
template <class Pass>
BOXCYL_FORCE_INLINE inline void gathered_pass(std::size_t begin, std::span<std::uint64_t> bits, std::span<std::uint64_t> open,
                                              Pass&& pass) {
    assert(open.size() <= kGroupBlocks && bits.size() == open.size());
    std::size_t idx[64 * kGroupBlocks], n = 0;
    for (std::size_t b = 0; b < open.size(); ++b)
        for (std::uint64_t o = open[b]; o != 0; o &= o - 1) idx[n++] = begin + 64 * b + static_cast<std::size_t>(std::countr_zero(o));
    for (std::size_t g = 0; g < n; g += lane_count) {
        const std::size_t m = std::min(lane_count, n - g);
        const LaneResult r = pass(idx + g, m);
        for (std::size_t l = 0; l < m; ++l)
            if (r.decided[l]) {
                const std::size_t at = idx[g + l] - begin;
                const std::uint64_t bit = std::uint64_t{1} << (at % 64);
                open[at / 64] &= ~bit;
                if (r.hit[l]) bits[at / 64] |= bit;
            }
    }
}

// Whether the source's second pass is the whole filter on gathered lanes (aligned boxes).
template <class Source>
inline constexpr bool gathers_whole_filter =
    requires(const Source& s, const CylinderFilter& f, const std::size_t* p) { s.gathered(f, p, std::size_t{1}); };

// The passes after the first (filter_block's) on the blocks at `begin` (as gathered_pass): the lanes
// `open` gathered through the source's second pass (aligned boxes: the whole filter), then through its
// hit search (oriented boxes), where it has them.
template <class Source>
void later_passes(const CylinderFilter& f, const Source& s, std::size_t begin, std::span<std::uint64_t> bits,
                  std::span<std::uint64_t> open, Stats& st) {
    auto any = [&] {
        for (const std::uint64_t o : open)
            if (o != 0) return true;
        return false;
    };
    if constexpr (gathers_whole_filter<Source>) {
        if (any()) {
            for (const std::uint64_t o : open) st.second_pass += static_cast<std::size_t>(std::popcount(o));
            gathered_pass(begin, bits, open, [&](const std::size_t* idx, std::size_t m) { return s.gathered(f, idx, m); });
        }
    }
    if constexpr (requires(const std::size_t* p) { s.searched(f, p, std::size_t{1}); }) {
        if (any()) gathered_pass(begin, bits, open, [&](const std::size_t* idx, std::size_t m) { return s.searched(f, idx, m); });
    }
}

// The clearance form's later probes whose hit answers yes (fat and tall), answered in the first pass
// where their own ball test proves the hit: they share the first probe's centre and axis, so the ball's
// terms and the box point's (filter.hpp's ball_terms, point_terms) are computed once and each further
// cylinder costs a few operations per lane. Otherwise the lanes inside the outer cylinder (its hits, which answer nothing: on the voxel
// set one box in twenty) all went through the later probes' whole filter, gathered. `says`: the lanes
// one of them proves to be hits.
struct LaterBalls {
    const CylinderFilter* filter[2]{};
    std::size_t count = 0;
    std::uint64_t says = 0;
};

// filter_block's `later` for a caller that runs the later passes itself, over a group of blocks
// (group_bits): the first pass alone.
struct FirstPassOnly {};

// The filter's answers for boxes [begin, begin + count), count ≤ 64, as bits 0..count−1: `hit` for the
// lanes it proves to meet the cylinder, `open` for those it leaves undecided (the others it proves to
// miss). The first pass runs over every vector of boxes without a branch per lane (aligned sources load
// the lanes, and the centre-and-ball tests run here); a source with a second pass (aligned boxes: the
// whole filter) sends the lanes the first left undecided through it, gathered into full vectors; a
// source whose first pass stops before the hit search (oriented boxes) sends the lanes it left through
// that search (filter.hpp's search_hits), gathered.
// check (Options::check_boxes): every box of the block is known valid before any is answered — for
// aligned and oriented sources by a few vector operations on the loaded lanes (is_valid over the block
// only when they cannot clear a vector), else by is_valid per box; the first invalid one throws
// InvalidBox.
// later: nullptr, every pass here; FirstPassOnly, the first pass alone (the caller, group_bits, runs
// the later passes over the lanes of a whole group of blocks); LaterBalls*, the same for the clearance
// form, whose later probes the first pass answers on the way where it can.
template <class Source, class Later = std::nullptr_t>
BlockFilter filter_block(const CylinderFilter& f, const Source& s, std::size_t begin, std::size_t count, bool check,
                         Stats& st, Later later = nullptr) {
    constexpr bool loads = requires(Lanes* v) { s.load_lanes(std::size_t{0}, std::size_t{1}, v, v); };
    constexpr bool frames = requires(Lanes* v, Lanes (*m)[3]) { s.load_frames(std::size_t{0}, std::size_t{1}, v, m, v); };
    std::uint64_t bits = 0, open = 0;
    bool suspect = check && !loads && !frames;
    for (std::size_t k = 0; k < count; k += lane_count) {
        const std::size_t valid = std::min(lane_count, count - k);
        LaneResult r;
        if constexpr (loads) {
            Lanes lo[3], hi[3];
            s.load_lanes(begin + k, valid, lo, hi);
            if (check && !plausible(lo, hi)) suspect = true;
            if constexpr (std::is_same_v<Later, LaterBalls*>) {
                FirstPassTerms t;
                r = aligned_ball_lanes(f, lo, hi, &t);
                const std::uint64_t in_range = (std::uint64_t{1} << valid) - 1;
                // Only where the first probe proves a hit (its other lanes it answers itself, or its
                // whole filter takes them up): the later probes' ball tests, then, where the first
                // probe's box point nearest to C was inside it and no ball answered, that point.
                if (t.computed && later->count > 0 && stdx::any_of(r.hit)) {
                    LaneMask says(false);
                    for (std::size_t i = 0; i < later->count; ++i)
                        if (later->filter[i]->usable) says = says || ball_inside(later->filter[i]->ball, t.x);
                    if (t.tried && stdx::any_of(t.by_point && !says))
                        for (std::size_t i = 0; i < later->count; ++i)
                            if (later->filter[i]->usable) says = says || (t.by_point && point_inside(*later->filter[i], t.w, t.w_ok));
                    if (stdx::any_of(says)) later->says |= (to_bits({says, says}).hit & in_range) << k;
                }
            } else {
                r = aligned_ball_lanes(f, lo, hi);  // NaN or ∞ lanes of an invalid box: harmless, never used
            }
        } else if constexpr (frames) {
            Lanes c[3], A[3][3], e[3];
            s.load_frames(begin + k, valid, c, A, e);
            if (check && !plausible(c, A, e)) suspect = true;
            r = oriented_lanes(f, c, A, e);
        } else {
            r = s.lanes(f, begin + k, valid);
        }
        if (stdx::all_of(r.decided) && stdx::none_of(r.hit)) continue;  // certain misses: the common case
        static_assert(lane_count < 64);
        const std::uint64_t in_range = (std::uint64_t{1} << valid) - 1;
        const LaneBits b = to_bits(r);
        bits |= (b.hit & in_range) << k;
        open |= (b.open & in_range) << k;
    }
    if (suspect)
        for (std::size_t i = begin; i < begin + count; ++i)
            if (!is_valid(s.box(i))) throw InvalidBox(i);
    if constexpr (std::is_same_v<Later, std::nullptr_t>)
        later_passes(f, s, begin, std::span<std::uint64_t>(&bits, 1), std::span<std::uint64_t>(&open, 1), st);
    return {bits, open};
}

// What one call asks of every box, prepared once per batch: whether it meets the cylinder
// (batch::intersects) or whether it is within the margin (Clearance: batch::within_distance).
struct Meets {
    Cylinder<double> cylinder;
    CylinderFilter filter;
};
struct Within {
    const Clearance& query;
    CylinderFilter filter[3];
    bool shared_terms = false;  // every probe's filter has the first's C, û, δ_u and κ (LaterBalls)
};
inline Meets prepare_query(const Cylinder<double>& cyl) {
    assert(is_valid(cyl) && "boxcyl::batch::intersects: invalid cylinder (see boxcyl::validate)");
    return {cyl, prepare(cyl)};
}
inline Within prepare_query(const Clearance& q) {
    assert(is_valid(q.cylinder) && "boxcyl::batch::within_distance: invalid cylinder (see boxcyl::validate)");
    Within w{q, {}};
    for (std::size_t k = 0; k < q.probes; ++k) w.filter[k] = prepare(q.probe[k]);
    // The probes share the cylinder's centre and axis, so prepare() gives them the same C, û, δ_u and κ;
    // the check keeps LaterBalls sound should that ever change.
    w.shared_terms = q.probes > 0;
    for (std::size_t k = 1; k < q.probes; ++k)
        for (int j = 0; j < 3; ++j)
            w.shared_terms = w.shared_terms && w.filter[k].c[j] == w.filter[0].c[j] && w.filter[k].u[j] == w.filter[0].u[j] &&
                             w.filter[k].du == w.filter[0].du && w.filter[k].kappa == w.filter[0].kappa;
    return w;
}

template <class Source>
void assert_valid(const Source& s, std::size_t begin, std::size_t count, bool check) {
#ifndef NDEBUG
    if (!check)
        for (std::size_t i = begin; i < begin + count; ++i)
            assert(is_valid(s.box(i)) && "boxcyl::batch: invalid box (see boxcyl::validate)");
#else
    (void)s, (void)begin, (void)count, (void)check;
#endif
}

// A stop requested (Options::stop) before a block's scalar work ends the call: that work, at up to
// microseconds a box, is what a group of blocks can spend beyond its filter's few microseconds.
inline void stop_if_requested(const Options& opt, std::uint64_t open) {
    if (open != 0 && opt.stop.stop_requested()) throw Stopped();
}

// Answers for up to kGroupBlocks blocks of 64 boxes from `begin` (n boxes in all), block b's as the bits
// of `bits[b]`: the filter's first pass block by block (checking the boxes), its later passes over the
// lanes the first left in all the group's blocks, gathered into full vectors (near the surface a block
// leaves a lane or two: a vector per block would run mostly empty), then the scalar exact default for
// each lane still undecided, one box at a time.
template <class Source>
void group_bits(const Meets& q, const Source& s, std::size_t begin, std::size_t n, std::size_t blocks, const Options& opt,
                Stats& st, std::uint64_t* bits) {
    std::uint64_t open[kGroupBlocks];
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::size_t at = begin + 64 * b, count = std::min<std::size_t>(64, n - at);
        assert_valid(s, at, count, opt.check_boxes);
        const BlockFilter r = filter_block(q.filter, s, at, count, opt.check_boxes, st, FirstPassOnly{});
        bits[b] = r.hit, open[b] = r.open;
    }
    later_passes(q.filter, s, begin, std::span<std::uint64_t>(bits, blocks), std::span<std::uint64_t>(open, blocks), st);
    for (std::size_t b = 0; b < blocks; ++b) {
        stop_if_requested(opt, open[b]);
        for (std::uint64_t o = open[b]; o != 0; o &= o - 1) {
            const auto l = static_cast<std::size_t>(std::countr_zero(o));
            if (filtered::query(s.box(begin + 64 * b + l), q.cylinder).intersect) bits[b] |= std::uint64_t{1} << l;
            ++st.exact_lanes;
        }
    }
}

inline bool scalar_within(const Clearance& q, const AlignedBox<double>& b) { return q.aligned(b, q.cylinder, q.margin); }
inline bool scalar_within(const Clearance& q, const OrientedBox<double>& b) { return q.oriented(b, q.cylinder, q.margin); }

// The clearance form, on up to kGroupBlocks blocks at once: the first probe's first pass over every box
// of each block (checking them), its later passes over the lanes that pass left in all the group's
// blocks, gathered into full vectors (near the cylinder a block keeps a few lanes open: a vector per
// block would run mostly empty), then each later probe over the lanes still open — for a source whose
// second pass is the whole filter (aligned boxes) gathered in the same way, for any other through
// filter_block per block, its answers for the other lanes dropped. A lane is
// answered by the first probe that decides it the way that probe can answer; the scalar clearance
// query answers the lanes none decides. `bits[b]` receives block b's answers.
template <class Source>
void group_bits(const Within& w, const Source& s, std::size_t begin, std::size_t n, std::size_t blocks, const Options& opt,
                Stats& st, std::uint64_t* bits) {
    const Clearance& q = w.query;
    const bool check = opt.check_boxes;
    std::uint64_t open[kGroupBlocks], first_hit[kGroupBlocks] = {}, first_left[kGroupBlocks] = {};
    auto count_of = [&](std::size_t b) { return std::min<std::size_t>(64, n - (begin + 64 * b)); };
    // Lanes of block b that probe k decides its deciding way (of those in `before`) leave `open`.
    auto take = [&](std::size_t k, std::size_t b, std::uint64_t before, const BlockFilter& r) {
        const std::uint64_t decided = before & ~r.open, says = decided & (q.decides_when[k] ? r.hit : ~r.hit);
        if (q.decides_when[k]) bits[b] |= says;
        open[b] &= ~says;
    };
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::size_t count = count_of(b), at = begin + 64 * b;
        assert_valid(s, at, count, check);
        bits[b] = 0;
        open[b] = count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
        if (q.probes == 0) continue;
        LaterBalls later;
        if (w.shared_terms)
            for (std::size_t k = 1; k < q.probes; ++k)
                if (q.decides_when[k]) later.filter[later.count++] = &w.filter[k];
        const BlockFilter r = filter_block(w.filter[0], s, at, count, check, st, &later);
        first_hit[b] = r.hit, first_left[b] = r.open;
        // The later probes' ball hits lie among the first probe's hits, which answer nothing.
        bits[b] |= later.says & open[b];
        open[b] &= ~later.says;
    }
    if (q.probes > 0) {
        later_passes(w.filter[0], s, begin, std::span<std::uint64_t>(first_hit, blocks),
                     std::span<std::uint64_t>(first_left, blocks), st);
        for (std::size_t b = 0; b < blocks; ++b) take(0, b, open[b], {first_hit[b], first_left[b]});
    }
    for (std::size_t k = 1; k < q.probes; ++k) {
        if constexpr (gathers_whole_filter<Source>) {
            std::uint64_t hit[kGroupBlocks] = {}, left[kGroupBlocks];
            std::copy(open, open + blocks, left);
            later_passes(w.filter[k], s, begin, std::span<std::uint64_t>(hit, blocks), std::span<std::uint64_t>(left, blocks), st);
            for (std::size_t b = 0; b < blocks; ++b) take(k, b, open[b], {hit[b], left[b]});
        } else {
            for (std::size_t b = 0; b < blocks; ++b)
                if (open[b] != 0) take(k, b, open[b], filter_block(w.filter[k], s, begin + 64 * b, count_of(b), false, st));
        }
    }
    for (std::size_t b = 0; b < blocks; ++b) {
        stop_if_requested(opt, open[b]);
        for (std::uint64_t o = open[b]; o != 0; o &= o - 1) {
            const auto l = static_cast<std::size_t>(std::countr_zero(o));
            if (scalar_within(q, s.box(begin + 64 * b + l))) bits[b] |= std::uint64_t{1} << l;
            ++st.exact_lanes;
        }
    }
}

// Runs the blocks of query q (a cylinder or a Clearance) over the threads; emit(block, bits, count)
// stores one block's answers.
template <class Query, class Source, class Emit>
Stats run(const Query& query, const Source& s, std::size_t n, const Options& opt, Emit&& emit) {
    const auto q = prepare_query(query);
    const std::size_t blocks = mask_words(n);
    const unsigned threads = split::thread_count(opt.threads, n);
    std::vector<Stats> per_thread(threads);
    split::for_each_range(blocks, threads, [&](std::size_t first, std::size_t last, unsigned t) {
        Stats x;
        std::uint64_t bits[kGroupBlocks];
        for (std::size_t blk = first; blk < last; blk += kGroupBlocks) {
            if (opt.stop.stop_requested()) throw Stopped();
            const std::size_t m = std::min(kGroupBlocks, last - blk);
            group_bits(q, s, blk * 64, n, m, opt, x, bits);
            for (std::size_t b = 0; b < m; ++b) emit(blk + b, bits[b], std::min<std::size_t>(64, n - (blk + b) * 64));
        }
        per_thread[t] = x;
    });
    Stats st;
    st.boxes = n;
    st.lanes = lane_count;
    for (const Stats& x : per_thread) st.exact_lanes += x.exact_lanes, st.second_pass += x.second_pass;
    return st;
}

template <class Query, class Source>
Stats to_mask(const Query& q, const Source& s, std::size_t n, std::span<std::uint64_t> mask, const Options& opt) {
    if (mask.size() < mask_words(n)) throw std::invalid_argument("boxcyl::batch: mask has too few words");
    return run(q, s, n, opt, [&](std::size_t blk, std::uint64_t bits, std::size_t) { mask[blk] = bits; });
}

template <class Query, class Source>
Stats to_bools(const Query& q, const Source& s, std::size_t n, std::span<bool> out, const Options& opt) {
    if (out.size() < n) throw std::invalid_argument("boxcyl::batch: output has fewer elements than boxes");
    return run(q, s, n, opt, [&](std::size_t blk, std::uint64_t bits, std::size_t count) {
        for (std::size_t l = 0; l < count; ++l) out[blk * 64 + l] = (bits >> l) & 1u;
    });
}

}  // namespace detail

// The entry points (types.hpp's QueryEntries) for query Q (a cylinder, or a Clearance), and this
// kernel's table.
template <class T, class Q>
Stats aligned_mask(const Q& q, const AlignedBoxes<T>& b, std::span<std::uint64_t> mask, const Options& opt) {
    return detail::to_mask(q, detail::AlignedSource<T>{b}, b.size(), mask, opt);
}
template <class T, class Q>
Stats aligned_bools(const Q& q, const AlignedBoxes<T>& b, std::span<bool> out, const Options& opt) {
    return detail::to_bools(q, detail::AlignedSource<T>{b}, b.size(), out, opt);
}
template <class T, class Q>
Stats rows_mask(const Q& q, std::span<const AlignedBox<T>> b, std::span<std::uint64_t> mask, const Options& opt) {
    return detail::to_mask(q, detail::AlignedRowsSource<T>{b}, b.size(), mask, opt);
}
template <class T, class Q>
Stats rows_bools(const Q& q, std::span<const AlignedBox<T>> b, std::span<bool> out, const Options& opt) {
    return detail::to_bools(q, detail::AlignedRowsSource<T>{b}, b.size(), out, opt);
}
template <class T, class Q>
Stats oriented_mask(const Q& q, std::span<const OrientedBox<T>> b, std::span<std::uint64_t> mask, const Options& opt) {
    return detail::to_mask(q, detail::OrientedSource<T>{b}, b.size(), mask, opt);
}
template <class T, class Q>
Stats oriented_bools(const Q& q, std::span<const OrientedBox<T>> b, std::span<bool> out, const Options& opt) {
    return detail::to_bools(q, detail::OrientedSource<T>{b}, b.size(), out, opt);
}

template <class T, class Q>
constexpr QueryEntries<T, Q> query_entries() {
    return {&aligned_mask<T, Q>, &aligned_bools<T, Q>, &rows_mask<T, Q>,
            &rows_bools<T, Q>,   &oriented_mask<T, Q>, &oriented_bools<T, Q>};
}
template <class T>
constexpr KernelEntries<T> entries() {
    return {query_entries<T, Cylinder<double>>(), query_entries<T, Clearance>()};
}

// kernel: the name this table answers to (Kernel::compiled for the header's own).
constexpr KernelTable kernel_table(Kernel kernel) { return {kernel, lane_count, entries<float>(), entries<double>()}; }

}  // namespace BOXCYL_BATCH_ISA
}  // namespace boxcyl::batch
