// The batch forms: whether each box intersects its cylinder, over float64 array fields of any strides
// whose leading length is N or 1 (broadcast); module.cpp turns the package's arrays into the fields
// and runs these interruptibly.
//
// With one cylinder and the default query the boxes go to the library's batch API
// (boxcyl::batch::intersects: SIMD filter, exact fallback), which checks each box on the numbers its
// filter loads (Options::check_boxes): a C-contiguous (N, 2, 3) array of aligned boxes in place (its
// AlignedBox rows form), on the batch's own threads (Options::threads); other layouts a chunk at a time,
// gathered into the batch API's layout (six arrays; OrientedBox or Parallelepiped structs) on the
// threads of the library's split (batch/split.hpp). With a margin the same, through the clearance
// form boxcyl::batch::within_distance (exact whatever the options). Anything else (a cylinder per
// element, other options, one box against many cylinders) is the scalar query (with a margin the
// scalar clearance query) per element on those threads, each element checked by boxcyl::is_valid. An element that fails a check is named by boxcyl::validate
// ("boxes[17].max[0]: is less than boxes[17].min[0]"), and the batch reports the first by index.
// Every loop looks at the stop token (Ctrl-C): the batch API before each group of 64-box blocks and
// each block's exact work, the others before each element. The distances (distances()) are the scalar boxcyl::distance (or
// boxcyl::signed_distance) per element, on those threads, each element checked as above.
#if defined(__SSE2__)
#include <emmintrin.h>  // the aligned boxes' gather, two at a time
#include <xmmintrin.h>  // _mm_prefetch
#endif

#include <algorithm>    // std::min
#include <atomic>       // the first failure's index
#include <cstddef>      // std::size_t
#include <cstdint>      // std::uintptr_t: the rows' alignment
#include <limits>       // the "no failure" index
#include <memory>       // std::unique_ptr: scratch buffers
#include <mutex>        // the first failure's message
#include <optional>     // the margin
#include <span>         // the batch API's arguments
#include <thread>       // std::thread::hardware_concurrency

#include "boxcyl/batch/split.hpp"  // the library's thread split
#include "common.hpp"

namespace boxcyl_python {

namespace batch = boxcyl::batch;

namespace {

// ---- The batch's first failure, by element order: key 2i for box i (or its query), 2i + 1 for cylinder i. ----

class FirstFailure {
public:
    static constexpr Index none = std::numeric_limits<Index>::max();
    void record(Index key, std::string message) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (key < key_.load()) {
            key_.store(key);
            message_ = std::move(message);
        }
    }
    // Whether a failure was recorded before element i (then nothing from i on needs doing).
    bool before(Index i) const { return key_.load(std::memory_order_relaxed) < 2 * i; }
    bool any() const { return key_.load() != none; }
    const std::string& message() const { return message_; }

private:
    std::mutex mutex_;
    std::atomic<Index> key_{none};
    std::string message_;
};

template <class Box>
void record_invalid(FirstFailure& failure, Index i, const Box& box) {
    failure.record(2 * i, boxcyl::validate(box, element_name("box", "boxes", false, i)).message());
}

// ---- Threads and chunks. ----

// A batch is run on this thread, uninterrupted, when it is this short: at most a few milliseconds even
// when every box goes to the exact fallback (a few microseconds each), while starting a runner thread
// would cost more than answering it on the fast path.
constexpr Index kBriefBatch = 4096;
constexpr Index kBriefScalar = 64;
// Gathered chunks: the scratch stays in the core's cache (48 bytes an aligned box, 120 an oriented one).
constexpr Index kAlignedChunk = 4096;
constexpr Index kFrameChunk = 2048;
// The scalar loop's blocks, and how many elements a thread must have at least.
constexpr Index kScalarBlock = 64;
constexpr Index kScalarPerThread = 2048;

unsigned hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Scratch memory of a thread, allocated on first use (uninitialised: every element is written first).
template <class T>
struct Buffer {
    std::unique_ptr<T[]> data;
    Index size = 0;
    T* get(Index need) {
        if (need > size) data.reset(new T[static_cast<std::size_t>(need)]), size = need;
        return data.get();
    }
};

// Runs chunk(scratch, begin, end) over [0, n) in chunks of `size`, in order, on the split's threads
// (contiguous ranges of chunks, the calling thread taking the first), each with its own Scratch.
// Chunks after a recorded failure are skipped.
template <class Scratch, class Chunk>
void for_each_chunk(Index n, Index size, unsigned threads, const FirstFailure& failure, Chunk&& chunk) {
    const auto chunks = static_cast<std::size_t>((n + size - 1) / size);
    batch::split::for_each_range(chunks, threads, [&](std::size_t first, std::size_t last, unsigned) {
        Scratch scratch;
        for (std::size_t c = first; c < last; ++c) {
            const Index begin = static_cast<Index>(c) * size;
            if (failure.before(begin)) return;
            chunk(scratch, begin, std::min(n, begin + size));
        }
    });
}

// The gathered chunks' threads: the batch API's own rule (no more than one per 32768 boxes).
unsigned batch_threads(unsigned requested, Index n) {
    return batch::split::thread_count(requested, static_cast<std::size_t>(n));
}

batch::Options checked(const std::stop_token& stop, unsigned threads = 1) {
    return {threads, batch::Kernel::automatic, true, stop};
}

// ---- Gathering a chunk into the batch API's layout. ----

// Copies aligned boxes [begin, begin + m) into six arrays of stride m (the batch API's AlignedBoxes).
// With SSE2, two boxes at a time when each row's three numbers are adjacent (the usual layouts: (N, 2,
// 3) and (N, 3) arrays, also strided views of them). A C-contiguous (N, 2, 3) array skips this copy.
void gather_aligned(const AlignedFields& b, Index begin, Index m, double* v) {
    Index i = 0;
#if defined(__SSE2__)
    if (b.min.dense(3) && b.max.dense(3)) {
        const char* pmin = b.min.base + begin * b.min.step;
        const char* pmax = b.max.base + begin * b.max.step;
        auto load2 = [](const char* r) { return _mm_loadu_pd(reinterpret_cast<const double*>(r)); };
        auto load1 = [](const char* r) { return _mm_load_sd(reinterpret_cast<const double*>(r)); };
        for (; i + 2 <= m; i += 2) {
            const char* a0 = pmin + i * b.min.step;
            const char* a1 = a0 + b.min.step;
            const char* c0 = pmax + i * b.max.step;
            const char* c1 = c0 + b.max.step;
            _mm_prefetch(a0 + 8 * b.min.step, _MM_HINT_T0);  // a little ahead of the hardware's own prefetch
            _mm_prefetch(c0 + 8 * b.max.step, _MM_HINT_T0);
            __m128d x = load2(a0), y = load2(a1);
            _mm_storeu_pd(v + 0 * m + i, _mm_unpacklo_pd(x, y));
            _mm_storeu_pd(v + 1 * m + i, _mm_unpackhi_pd(x, y));
            _mm_storeu_pd(v + 2 * m + i, _mm_unpacklo_pd(load1(a0 + 16), load1(a1 + 16)));
            x = load2(c0), y = load2(c1);
            _mm_storeu_pd(v + 3 * m + i, _mm_unpacklo_pd(x, y));
            _mm_storeu_pd(v + 4 * m + i, _mm_unpackhi_pd(x, y));
            _mm_storeu_pd(v + 5 * m + i, _mm_unpacklo_pd(load1(c0 + 16), load1(c1 + 16)));
        }
    }
#endif
    for (; i < m; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            v[static_cast<Index>(j) * m + i] = b.min(begin + i, j);
            v[static_cast<Index>(3 + j) * m + i] = b.max(begin + i, j);
        }
}

// Copies oriented boxes or parallelepipeds [begin, begin + m) into the library's structs: when each
// field's numbers are adjacent in a row (C-contiguous (N, 3) and (N, 3, 3) arrays, also row views of
// bigger ones), three copies of 24, 72 and 24 bytes a box, with the rows a little ahead prefetched
// (the gather runs between the batch's chunks, so nothing else hides the memory's latency).
template <class Box>
void gather_frames(const FrameFields<Box>& b, Index begin, Index m, Box* v) {
    const bool dense = b.center.dense(3) && b.axes.dense(9) && b.extents.dense(3) && b.center.step != 0 &&
                       b.axes.step != 0 && b.extents.step != 0;
    if (!dense) {
        for (Index i = 0; i < m; ++i) v[i] = b(begin + i);
        return;
    }
    const char* c = b.center.base + begin * b.center.step;
    const char* a = b.axes.base + begin * b.axes.step;
    const char* e = b.extents.base + begin * b.extents.step;
    constexpr Index ahead = 8;
    for (Index i = 0; i < m; ++i) {
#if defined(__GNUC__)
        if (i + ahead < m) {
            __builtin_prefetch(c + (i + ahead) * b.center.step);
            __builtin_prefetch(a + (i + ahead) * b.axes.step);
            __builtin_prefetch(a + (i + ahead) * b.axes.step + 64);
            __builtin_prefetch(e + (i + ahead) * b.extents.step);
        }
#endif
        std::memcpy(&v[i].center, c + i * b.center.step, sizeof(Vec));
        std::memcpy(&v[i].axes, a + i * b.axes.step, 3 * sizeof(Vec));
        std::memcpy(&v[i].extents, e + i * b.extents.step, sizeof(Vec));
    }
}

// The rows of a C-contiguous (N, 2, 3) float64 array, when min and max are its two halves (the
// package passes boxes[:, 0] and boxes[:, 1]); else nullptr.
const AlignedBox* aligned_rows(const AlignedFields& b) {
    const bool rows = b.min.dense(3) && b.max.dense(3) && b.min.step == 48 && b.max.step == 48 &&
                      b.max.base == b.min.base + 24 &&
                      reinterpret_cast<std::uintptr_t>(b.min.base) % alignof(AlignedBox) == 0;
    return rows ? reinterpret_cast<const AlignedBox*>(b.min.base) : nullptr;
}

// ---- The two ways through a batch. ----

// The batch API's question: intersects, or with a margin the clearance form.
template <class Boxes>
void ask(const Cylinder& cyl, const std::optional<double>& margin, const Boxes& boxes, std::span<bool> out,
         const batch::Options& opt) {
    if (margin)
        batch::within_distance(cyl, boxes, *margin, out, opt);
    else
        batch::intersects(cyl, boxes, out, opt);
}

// One cylinder, many boxes, the default query: the batch API, in place or a gathered chunk at a time.
void one_cylinder(const AlignedFields& boxes, Index n, const Cylinder& cyl, const std::optional<double>& margin,
                  unsigned threads, bool* result, FirstFailure& failure, const std::stop_token& stop) {
    if (const AlignedBox* rows = aligned_rows(boxes)) {
        const auto count = static_cast<std::size_t>(n);
        try {
            ask(cyl, margin, std::span<const AlignedBox>(rows, count), std::span<bool>(result, count),
                checked(stop, threads));
        } catch (const batch::InvalidBox& e) {
            const auto i = static_cast<Index>(e.index);
            record_invalid(failure, i, boxes(i));
        }
        return;
    }
    for_each_chunk<Buffer<double>>(n, kAlignedChunk, batch_threads(threads, n), failure,
                                   [&](Buffer<double>& scratch, Index begin, Index end) {
        const Index m = end - begin;
        double* v = scratch.get(6 * m);
        gather_aligned(boxes, begin, m, v);
        auto column = [&](Index j) { return std::span<const double>(v + j * m, static_cast<std::size_t>(m)); };
        try {
            ask(cyl, margin, batch::AlignedBoxes<double>{column(0), column(1), column(2), column(3), column(4), column(5)},
                std::span<bool>(result + begin, static_cast<std::size_t>(m)), checked(stop));
        } catch (const batch::InvalidBox& e) {
            const Index i = begin + static_cast<Index>(e.index);
            record_invalid(failure, i, boxes(i));
        }
    });
}

template <class Box>
void one_cylinder(const FrameFields<Box>& boxes, Index n, const Cylinder& cyl, const std::optional<double>& margin,
                  unsigned threads, bool* result, FirstFailure& failure, const std::stop_token& stop) {
    for_each_chunk<Buffer<Box>>(n, kFrameChunk, batch_threads(threads, n), failure,
                                [&](Buffer<Box>& scratch, Index begin, Index end) {
        const Index m = end - begin;
        Box* v = scratch.get(m);
        gather_frames(boxes, begin, m, v);
        try {
            ask(cyl, margin, std::span<const Box>(v, static_cast<std::size_t>(m)),
                std::span<bool>(result + begin, static_cast<std::size_t>(m)), checked(stop));
        } catch (const batch::InvalidBox& e) {
            record_invalid(failure, begin + static_cast<Index>(e.index), v[e.index]);
        }
    });
}

// Any boxes, any cylinders, any options: the scalar query per element, each element checked first.
template <class BoxAt>
void per_element(const BoxAt& box_at, bool box_single, const CylinderFields& cyl_at, bool cylinder_single, Index n,
                 const boxcyl::QueryOptions& opt, const std::optional<double>& margin, unsigned threads, bool* result,
                 FirstFailure& failure, const std::stop_token& stop) {
    const unsigned requested = threads != 0 ? threads : hardware_threads();
    const auto count = static_cast<unsigned>(std::min<Index>(requested, std::max<Index>(1, n / kScalarPerThread)));
    for_each_chunk<char>(n, kScalarBlock, count, failure, [&](char&, Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            if (stop.stop_requested()) throw batch::Stopped();
            const auto box = box_at(i);
            if (!box_single && !boxcyl::is_valid(box)) return record_invalid(failure, i, box);
            const Cylinder cyl = cyl_at(i);
            if (!cylinder_single && !boxcyl::is_valid(cyl)) {
                failure.record(2 * i + 1, boxcyl::validate(cyl, element_name("cylinder", "cylinders", false, i)).message());
                return;
            }
            try {
                result[i] = margin ? boxcyl::within_distance(box, cyl, *margin) : boxcyl::intersects(box, cyl, opt);
            } catch (const std::domain_error& e) {  // e.g. exact §2/§4 asked for a frame not exactly orthonormal
                failure.record(2 * i, element_name("box", "boxes", box_single, i) + ": " + e.what());
                return;
            }
        }
    });
}

bool is_default(const boxcyl::QueryOptions& o) {
    return o.algorithm == boxcyl::Algorithm::inequalities && o.arithmetic == boxcyl::Arithmetic::filtered;
}

// The clearance query is exact whatever the options: it takes the batch API with any of them.
bool one_cylinder_path(const Batch& b) {
    return b.cylinder_single && !b.box_single && (is_default(b.options) || b.margin);
}

template <class Boxes>
std::string run(const Boxes& boxes, const CylinderFields& cylinders, const Batch& b, const std::stop_token& stop) {
    FirstFailure failure;
    if (one_cylinder_path(b))
        one_cylinder(boxes, b.n, cylinders(0), b.margin, b.threads, b.result, failure, stop);
    else
        per_element(boxes, b.box_single, cylinders, b.cylinder_single, b.n, b.options, b.margin, b.threads, b.result,
                    failure, stop);
    return failure.any() ? failure.message() : std::string();
}

// The distances: the scalar query per element on the split's threads, as per_element. A distance
// takes tens of microseconds (up to milliseconds where the exact bisection decides), so fewer elements
// make a thread worth starting.
constexpr Index kDistancePerThread = 64;

// Element i's bounds and witness pair.
void store(const DistanceBatch& b, Index i, double lower, double upper, const Vec& on_box, const Vec& on_cylinder) {
    b.lower[i] = lower;
    b.upper[i] = upper;
    for (std::size_t k = 0; k < 3; ++k) {
        b.on_box[3 * i + static_cast<Index>(k)] = on_box[k];
        b.on_cylinder[3 * i + static_cast<Index>(k)] = on_cylinder[k];
    }
}

template <class BoxAt>
std::string distances_of(const BoxAt& box_at, const CylinderFields& cyl_at, const DistanceBatch& b,
                         const std::stop_token& stop) {
    FirstFailure failure;
    const unsigned requested = b.threads != 0 ? b.threads : hardware_threads();
    const auto count = static_cast<unsigned>(std::min<Index>(requested, std::max<Index>(1, b.n / kDistancePerThread)));
    for_each_chunk<char>(b.n, kScalarBlock, count, failure, [&](char&, Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            if (stop.stop_requested()) throw batch::Stopped();
            const auto box = box_at(i);
            if (!b.box_single && !boxcyl::is_valid(box)) return record_invalid(failure, i, box);
            const Cylinder cyl = cyl_at(i);
            if (!b.cylinder_single && !boxcyl::is_valid(cyl)) {
                failure.record(2 * i + 1, boxcyl::validate(cyl, element_name("cylinder", "cylinders", false, i)).message());
                return;
            }
            if (b.normal != nullptr) {
                const boxcyl::SignedDistance d = boxcyl::signed_distance_unchecked(box, cyl);
                store(b, i, d.lower, d.upper, d.on_box, d.on_cylinder);
                for (std::size_t k = 0; k < 3; ++k) b.normal[3 * i + static_cast<Index>(k)] = d.normal[k];
            } else {
                const boxcyl::Distance d = boxcyl::distance_unchecked(box, cyl);
                store(b, i, d.lower, d.upper, d.on_box, d.on_cylinder);
            }
        }
    });
    return failure.any() ? failure.message() : std::string();
}

}  // namespace

// A distance can take milliseconds where the exact bisection decides: only a few run uninterrupted.
bool brief(const DistanceBatch& b) { return b.n <= 8; }

std::string distances(const AlignedFields& boxes, const CylinderFields& cylinders, const DistanceBatch& b,
                      const std::stop_token& stop) {
    return distances_of(boxes, cylinders, b, stop);
}
std::string distances(const FrameFields<OrientedBox>& boxes, const CylinderFields& cylinders, const DistanceBatch& b,
                      const std::stop_token& stop) {
    return distances_of(boxes, cylinders, b, stop);
}
std::string distances(const FrameFields<Parallelepiped>& boxes, const CylinderFields& cylinders,
                      const DistanceBatch& b, const std::stop_token& stop) {
    return distances_of(boxes, cylinders, b, stop);
}

// With a margin, a box the filter leaves can take the scalar clearance query milliseconds: only a
// batch the scalar loop would run briefly stays uninterruptible.
bool brief(const Batch& b) { return b.n <= (one_cylinder_path(b) && !b.margin ? kBriefBatch : kBriefScalar); }

std::string intersects(const AlignedFields& boxes, const CylinderFields& cylinders, const Batch& b,
                       const std::stop_token& stop) {
    return run(boxes, cylinders, b, stop);
}
std::string intersects(const FrameFields<OrientedBox>& boxes, const CylinderFields& cylinders, const Batch& b,
                       const std::stop_token& stop) {
    return run(boxes, cylinders, b, stop);
}
std::string intersects(const FrameFields<Parallelepiped>& boxes, const CylinderFields& cylinders, const Batch& b,
                       const std::stop_token& stop) {
    return run(boxes, cylinders, b, stop);
}

}  // namespace boxcyl_python
