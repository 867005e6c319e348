// boxcyl._core: the pybind11 bindings behind the Python package `boxcyl` (python/boxcyl/__init__.py
// adds the numpy-friendly argument handling, the input policy and the docs users read first).
//
// Objects: AlignedBox, OrientedBox, Parallelepiped, Cylinder (double precision, immutable, validated
// when built so that an invalid one never exists; the package subclasses them for argument conversion,
// equality and pickling), and the pose factories (boxcyl/geometry/pose.hpp). Queries:
// intersects(box, cylinder[, algorithm, arithmetic]) and the batch forms _intersects_aligned /
// _intersects_oriented / _intersects_parallelepiped over float64 arrays of any strides whose leading
// length is N or 1 (broadcast).
//
// A batch runs in chunks on worker threads with the GIL released, while the calling thread checks for
// signals every few milliseconds (Ctrl-C raises KeyboardInterrupt promptly; the workers stop after
// their current chunk). Every element is checked with a few comparisons (an element that fails is then
// named by boxcyl::validate: "boxes[17].max[0]: is less than boxes[17].min[0]"), and the batch reports
// the first invalid element by index. One cylinder against many boxes with the default query goes
// through the batch API per chunk (boxcyl/batch.hpp: SIMD filter + exact fallback), which checks the
// boxes as its filter loads them (Options::check_boxes): aligned boxes in a C-contiguous (N, 2, 3)
// array are read in place (its AlignedBox rows form), oriented boxes copied into OrientedBox structs,
// other aligned layouts gathered into its six arrays and checked on the way. Anything else goes
// through the scalar query, checked element by element.
#include <pybind11/numpy.h>     // input arrays, bool output arrays
#include <pybind11/pybind11.h>  // the bindings
#include <pybind11/stl.h>       // std::array <-> Python sequences

#if defined(__SSE2__)
#include <emmintrin.h>  // the aligned boxes' gather, two at a time
#include <xmmintrin.h>  // _mm_prefetch
#endif

#include <algorithm>           // std::min
#include <array>               // Vec3 <-> std::array
#include <atomic>              // the chunk counter, the stop flag, the first failure's index
#include <chrono>              // the signal-check period; the timed raw batch
#include <cmath>               // std::fabs
#include <condition_variable>  // the caller waits for the workers with a timeout
#include <cstdint>             // std::uintptr_t: the rows' alignment
#include <cstring>             // std::memcpy: array elements need not be aligned
#include <ctime>               // clock_gettime: the timed raw batch's CPU time
#include <exception>           // a worker's unexpected exception, rethrown by the caller
#include <initializer_list>    // the shape of a field
#include <limits>              // DBL_MAX, the "no failure" index
#include <memory>              // std::unique_ptr: scratch buffers
#include <mutex>               // the first failure, the finished-workers count
#include <stdexcept>           // std::domain_error (mapped to ValueError)
#include <string>              // element names in messages
#include <thread>              // the workers
#include <type_traits>         // std::is_same_v: batches without a batch API
#include <vector>              // per-worker scratch buffers

#include "boxcyl/batch.hpp"            // one cylinder against many boxes: SIMD filter + exact fallback
#include "boxcyl/geometry/pose.hpp"    // boxes and cylinders from rotations, quaternions, transforms
#include "boxcyl/number/interval.hpp"  // fp_environment_ok
#include "boxcyl/query.hpp"
#include "boxcyl/version.hpp"

#if !defined(BOXCYL_HAS_EXACT)
#error "the boxcyl Python module needs the exact backend (GMP): link boxcyl::exact / define BOXCYL_HAS_EXACT"
#endif

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using Vec = boxcyl::Vec3<double>;
using Array3 = std::array<double, 3>;
using Cylinder = boxcyl::Cylinder<double>;
using AlignedBox = boxcyl::AlignedBox<double>;
using OrientedBox = boxcyl::OrientedBox<double>;
using Parallelepiped = boxcyl::Parallelepiped<double>;
using Index = py::ssize_t;

Vec vec(const Array3& a) { return {a[0], a[1], a[2]}; }
py::tuple tuple(const Vec& v) { return py::make_tuple(v[0], v[1], v[2]); }

template <class Object>
Object validated(Object x, const char* name) {
    if (auto v = boxcyl::validate(x, name); !v) throw py::value_error(v.message());
    return x;
}

// The filter's exactness assumes gradual underflow; a library loaded into the same process may have
// set flush-to-zero (e.g. one built with -ffast-math). Checked on the thread that runs the query.
void require_fp_environment() {
    if (!boxcyl::fp_environment_ok())
        throw std::runtime_error(
            "boxcyl: the floating-point environment flushes subnormals to zero (FTZ/DAZ, often set by a "
            "library built with -ffast-math); exact answers cannot be guaranteed in it");
}

template <class Box>
bool query(const Box& box, const Cylinder& cyl, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    require_fp_environment();
    return boxcyl::intersects(box, cyl, boxcyl::QueryOptions{algorithm, arithmetic});
}

// ---- Cheap checks: true only for input that boxcyl::validate accepts. ----
// They build no strings; an element they do not pass is then judged (and named) by validate().

bool is_finite(double x) { return std::fabs(x) <= std::numeric_limits<double>::max(); }

bool plausible(const AlignedBox& b) {
    bool ok = true;
    for (std::size_t j = 0; j < 3; ++j) ok &= is_finite(b.min[j]) & is_finite(b.max[j]) & (b.min[j] <= b.max[j]);
    return ok;
}

bool plausible(const Cylinder& c) {
    bool ok = is_finite(c.radius) & is_finite(c.height) & (c.radius >= 0) & (c.height >= 0);
    for (std::size_t j = 0; j < 3; ++j) ok &= is_finite(c.center[j]) & is_finite(c.axis[j]);
    return ok & ((c.axis[0] != 0) | (c.axis[1] != 0) | (c.axis[2] != 0));
}

// The Gram matrix in double: for axes of length about 1 its rounding error is below 1e-15, so a margin
// of 1e-12 under validate()'s tolerance (computed in long double) never passes an axis it refuses.
bool plausible(const OrientedBox& b) {
    constexpr double tol = boxcyl::orthonormality_tolerance - 1e-12;
    bool ok = true;
    for (std::size_t j = 0; j < 3; ++j) {
        ok &= is_finite(b.center[j]) & is_finite(b.extents[j]) & (b.extents[j] >= 0);
        for (std::size_t k = 0; k < 3; ++k) ok &= is_finite(b.axes[j][k]);
    }
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j) {
            const Vec& u = b.axes[i];
            const Vec& v = b.axes[j];
            const double g = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
            ok &= std::fabs(g - (i == j ? 1.0 : 0.0)) <= tol;  // false for NaN (overflowed products)
        }
    return ok;
}

// Any axes are valid; only the numbers' finiteness and the extents' sign are checked.
bool plausible(const Parallelepiped& b) {
    bool ok = true;
    for (std::size_t j = 0; j < 3; ++j) {
        ok &= is_finite(b.center[j]) & is_finite(b.extents[j]) & (b.extents[j] >= 0);
        for (std::size_t k = 0; k < 3; ++k) ok &= is_finite(b.axes[j][k]);
    }
    return ok;
}

// ---- Array arguments. ----

// A float64 array argument of shape (M, *tail), any strides: row i (i < M, or row 0 when M == 1:
// broadcast) and element k of the flattened tail. Reads raw memory only, so it may be used while the
// GIL is released (the caller keeps the arrays alive).
struct Field {
    const char* base = nullptr;
    Index count = 1;
    Index step = 0;                 // bytes from one row to the next; 0 when broadcast
    std::array<Index, 9> offset{};  // bytes from a row's start to each tail element

    double operator()(Index i, std::size_t k) const {
        double x;
        std::memcpy(&x, base + i * step + offset[k], sizeof x);
        return x;
    }
};

Field field(const py::array& a, const char* name, std::initializer_list<Index> tail) {
    // The package passes float64 arrays of these shapes; anything else is its bug, said plainly.
    bool ok = py::isinstance<py::array_t<double>>(a) && a.ndim() == static_cast<Index>(tail.size()) + 1;
    Index d = 1;
    for (Index t : tail) ok = ok && a.shape(d++) == t;
    if (!ok) throw py::value_error(std::string("boxcyl: internal: ") + name + " is not a float64 array of the expected shape");
    Field f;
    f.base = static_cast<const char*>(a.data());
    f.count = a.shape(0);
    f.step = f.count == 1 ? 0 : a.strides(0);
    if (tail.size() == 0) {
        f.offset[0] = 0;
    } else if (tail.size() == 1) {
        for (Index k = 0; k < a.shape(1); ++k) f.offset[static_cast<std::size_t>(k)] = k * a.strides(1);
    } else {
        for (Index r = 0; r < a.shape(1); ++r)
            for (Index c = 0; c < a.shape(2); ++c)
                f.offset[static_cast<std::size_t>(r * a.shape(2) + c)] = r * a.strides(1) + c * a.strides(2);
    }
    return f;
}

// The common leading length (1 broadcasts; the package checks this first with better messages).
Index batch_length(std::initializer_list<const Field*> fields) {
    Index n = 1;
    for (const Field* f : fields)
        if (f->count != 1) {
            if (n != 1 && f->count != n) throw py::value_error("boxcyl: internal: batch fields have different lengths");
            n = f->count;
        }
    return n;
}

struct CylinderFields {
    Field center, axis, radius, height;
    Cylinder operator()(Index i) const {
        return {{center(i, 0), center(i, 1), center(i, 2)}, {axis(i, 0), axis(i, 1), axis(i, 2)}, radius(i, 0),
                height(i, 0)};
    }
};

struct AlignedFields {
    Field min, max;
    AlignedBox operator()(Index i) const {
        return {{min(i, 0), min(i, 1), min(i, 2)}, {max(i, 0), max(i, 1), max(i, 2)}};
    }
};

// Oriented boxes and parallelepipeds: center, axes (rows), extents.
template <class Box>
struct FrameFields {
    Field center, axes, extents;
    Box operator()(Index i) const {
        const Field& a = axes;  // row k is axes[k]
        return {{center(i, 0), center(i, 1), center(i, 2)},
                {Vec{a(i, 0), a(i, 1), a(i, 2)}, Vec{a(i, 3), a(i, 4), a(i, 5)}, Vec{a(i, 6), a(i, 7), a(i, 8)}},
                {extents(i, 0), extents(i, 1), extents(i, 2)}};
    }
};
using OrientedFields = FrameFields<OrientedBox>;

// "boxes[17]" for an element of an array argument, "box" for a single object broadcast.
std::string element_name(const char* singular, const char* plural, bool single, Index i) {
    return single ? std::string(singular) : std::string(plural) + "[" + std::to_string(i) + "]";
}

// ---- Chunks on worker threads, interruptible. ----

// The batch's first failure by element order: key 2i for box i (or its query), 2i + 1 for cylinder i.
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

// How often the calling thread looks for signals (Ctrl-C) while the threads run.
constexpr auto kSignalPeriod = std::chrono::milliseconds(10);

// Chunk sizes: a chunk lasts about a millisecond, whatever one element costs (from a few nanoseconds in
// the batch API's filter to a fraction of a millisecond for an exactly touching pair answered by the
// exact fallback), so that Ctrl-C is prompt and the gathered boxes stay in the core's cache. Each thread
// starts at `first`, then doubles or shrinks its chunk from the time the last one took.
struct ChunkSizes {
    Index first, min, max;
};
constexpr auto kChunkFast = std::chrono::microseconds(500);  // below: double the chunk
constexpr auto kChunkSlow = std::chrono::milliseconds(2);    // above: shrink it to about kChunkFast

// Runs work(scratch, begin, end) over [0, n) in chunks on `threads` threads (the calling one and
// threads - 1 more, each with its own Scratch), with the GIL released. Called with the GIL held. Every
// kSignalPeriod the calling thread takes the GIL and runs Python's signal handlers; when one raises
// (KeyboardInterrupt for Ctrl-C), the threads stop after their current chunk and the exception
// propagates. Chunks are taken in order, so those after a recorded failure are skipped.
template <class Scratch, class Work>
void run_chunks(Index n, ChunkSizes sizes, unsigned threads, FirstFailure& failure, Work work) {
    threads = static_cast<unsigned>(std::min<Index>(std::max(1u, threads), std::max<Index>(1, n / sizes.min)));
    std::atomic<Index> next{0};
    std::atomic<bool> stop{false};
    std::mutex mutex;
    std::condition_variable finished_cv;
    unsigned finished = 0;  // helper threads done
    std::vector<std::exception_ptr> errors(threads);
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        auto take_chunks = [&](unsigned t, auto&& between_chunks) {
            try {
                require_fp_environment();
                Scratch scratch;
                Index size = sizes.first;
                while (!stop.load(std::memory_order_relaxed)) {
                    const Index begin = next.fetch_add(size);
                    if (begin >= n || failure.before(begin)) break;
                    const auto t0 = std::chrono::steady_clock::now();
                    work(scratch, begin, std::min(n, begin + size));
                    const auto took = std::chrono::steady_clock::now() - t0;
                    if (took < kChunkFast)
                        size = std::min(sizes.max, 2 * size);
                    else if (took > kChunkSlow)
                        size = std::max(sizes.min, static_cast<Index>(static_cast<double>(size) *
                                                                      (std::chrono::duration<double>(kChunkFast) / took)));
                    between_chunks();
                }
            } catch (...) {
                errors[t] = std::current_exception();
                stop.store(true);
            }
        };
        auto helper = [&](unsigned t) {
            take_chunks(t, [] {});
            const std::lock_guard<std::mutex> lock(mutex);
            ++finished;
            finished_cv.notify_one();
        };
        std::vector<std::thread> helpers;
        helpers.reserve(threads - 1);
        for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(helper, t);

        auto last_check = std::chrono::steady_clock::now();
        auto check_signals = [&] {
            if (interrupted) return;
            last_check = std::chrono::steady_clock::now();
            const py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) {  // the handler's exception stays set on this thread
                interrupted = true;
                stop.store(true);
            }
        };
        take_chunks(0, [&] {
            if (std::chrono::steady_clock::now() - last_check >= kSignalPeriod) check_signals();
        });
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                if (finished_cv.wait_for(lock, kSignalPeriod, [&] { return finished == threads - 1; })) break;
            }
            check_signals();
        }
        for (std::thread& h : helpers) h.join();
    }
    if (interrupted) throw py::error_already_set();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

// Thread count: `requested` (0: all cores), but no more than one per `min_per_thread` elements.
unsigned thread_count(unsigned requested, Index n, Index min_per_thread) {
    const unsigned all = std::max(1u, std::thread::hardware_concurrency());
    const Index t = std::min<Index>(requested != 0 ? requested : all, std::max<Index>(1, n / min_per_thread));
    return static_cast<unsigned>(t);
}

constexpr ChunkSizes kAlignedChunks{256, 16, 16384};   // batch API: 48 bytes per box gathered
constexpr ChunkSizes kOrientedChunks{256, 16, 4096};   // batch API: 120 bytes per box gathered
constexpr ChunkSizes kScalarChunks{16, 1, 4096};       // scalar query
constexpr Index kScalarPerThread = 2048;               // below this many elements per thread, fewer threads

bool is_default(boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic) {
    return algorithm == boxcyl::Algorithm::inequalities && arithmetic == boxcyl::Arithmetic::filtered;
}

// Validates a single (broadcast) box or cylinder before any element: it is named "box" / "cylinder".
template <class Object>
void validate_single(const Object& x, const char* name) {
    if (!plausible(x)) validated(x, name);
}

// The scalar loop, for per-element cylinders or options other than the default.
template <class BoxAt>
void scalar_chunk(const BoxAt& box_at, bool box_single, const CylinderFields& cyl_at, bool cylinder_single,
                  const boxcyl::QueryOptions& opt, bool* result, FirstFailure& failure, Index begin, Index end) {
    for (Index i = begin; i < end; ++i) {
        const auto box = box_at(i);
        if (!box_single && !plausible(box))
            if (auto v = boxcyl::validate(box, element_name("box", "boxes", false, i)); !v) {
                failure.record(2 * i, v.message());
                return;
            }
        const Cylinder cyl = cyl_at(i);
        if (!cylinder_single && !plausible(cyl))
            if (auto v = boxcyl::validate(cyl, element_name("cylinder", "cylinders", false, i)); !v) {
                failure.record(2 * i + 1, v.message());
                return;
            }
        try {
            result[i] = boxcyl::intersects(box, cyl, opt);
        } catch (const std::domain_error& e) {  // e.g. exact §2/§4 asked for a frame not exactly orthonormal
            failure.record(2 * i, element_name("box", "boxes", box_single, i) + ": " + e.what());
            return;
        }
    }
}

template <class BoxAt, class BatchChunk>
py::array_t<bool> run_batch(Index n, const BoxAt& box_at, bool box_single, const CylinderFields& cyl_at,
                            bool cylinder_single, boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic,
                            unsigned threads, ChunkSizes batch_chunks, BatchChunk batch_chunk_work) {
    if (box_single) validate_single(box_at(0), "box");
    if (cylinder_single) validate_single(cyl_at(0), "cylinder");
    py::array_t<bool> out(n);
    bool* result = out.mutable_data();
    FirstFailure failure;
    constexpr bool batch_api = !std::is_same_v<BatchChunk, std::nullptr_t>;
    if (batch_api && cylinder_single && !box_single && is_default(algorithm, arithmetic)) {
        const Cylinder cyl = cyl_at(0);
        if constexpr (batch_api)
            run_chunks<typename BatchChunk::Scratch>(
                n, batch_chunks, thread_count(threads, n, boxcyl::batch::split::kMinBoxesPerThread), failure,
                [&](typename BatchChunk::Scratch& scratch, Index begin, Index end) {
                    batch_chunk_work(scratch, cyl, result, failure, begin, end);
                });
    } else {
        const boxcyl::QueryOptions opt{algorithm, arithmetic};
        struct None {};
        run_chunks<None>(n, kScalarChunks, thread_count(threads, n, kScalarPerThread), failure,
                         [&](None&, Index begin, Index end) {
                             scalar_chunk(box_at, box_single, cyl_at, cylinder_single, opt, result, failure, begin, end);
                         });
    }
    if (failure.any()) throw py::value_error(failure.message());
    return out;
}

CylinderFields cylinder_fields(const py::array& center, const py::array& axis, const py::array& radius,
                               const py::array& height) {
    return {field(center, "center", {3}), field(axis, "axis", {3}), field(radius, "radius", {}),
            field(height, "height", {})};
}

// Scratch memory of a worker, allocated on first use (uninitialised: every element is written first).
template <class T>
struct Buffer {
    std::unique_ptr<T[]> data;
    Index size = 0;
    T* get(Index need) {
        if (need > size) data.reset(new T[static_cast<std::size_t>(need)]), size = need;
        return data.get();
    }
};

// Copies aligned boxes [begin, begin + m) into six arrays of stride m (the batch API's layout) and
// returns whether every one certainly passes validate(): max - min in [0, DBL_MAX] for each axis is
// false for NaN, ±Inf and min > max (and for bounds so far apart that the difference overflows, which
// the caller then judges exactly). With SSE2, two boxes at a time when each row's three numbers are
// adjacent (the usual layouts: (N, 2, 3) and (N, 3) arrays, also strided views of them). It reads the
// caller's arrays once; a C-contiguous (N, 2, 3) array skips this copy (AlignedRowsChunk).
bool gather_aligned(const AlignedFields& b, Index begin, Index m, double* v) {
    constexpr double big = std::numeric_limits<double>::max();
    auto adjacent = [](const Field& f) { return f.offset[0] == 0 && f.offset[1] == 8 && f.offset[2] == 16; };
    Index i = 0;
    bool ok = true;
#if defined(__SSE2__)
    if (adjacent(b.min) && adjacent(b.max)) {
        const __m128d zero = _mm_setzero_pd(), top = _mm_set1_pd(big);
        __m128d good = _mm_cmpeq_pd(zero, zero);
        const char* pmin = b.min.base + begin * b.min.step;
        const char* pmax = b.max.base + begin * b.max.step;
        auto load2 = [](const char* r) { return _mm_loadu_pd(reinterpret_cast<const double*>(r)); };
        auto load1 = [](const char* r) { return _mm_load_sd(reinterpret_cast<const double*>(r)); };
        auto check = [&](__m128d lo, __m128d hi) {
            const __m128d d = _mm_sub_pd(hi, lo);
            good = _mm_and_pd(good, _mm_and_pd(_mm_cmpge_pd(d, zero), _mm_cmple_pd(d, top)));
        };
        for (; i + 2 <= m; i += 2) {
            const char* a0 = pmin + i * b.min.step;
            const char* a1 = a0 + b.min.step;
            const char* c0 = pmax + i * b.max.step;
            const char* c1 = c0 + b.max.step;
            _mm_prefetch(a0 + 8 * b.min.step, _MM_HINT_T0);  // a little ahead of the hardware's own prefetch
            _mm_prefetch(c0 + 8 * b.max.step, _MM_HINT_T0);
            __m128d x = load2(a0), y = load2(a1);
            const __m128d lo0 = _mm_unpacklo_pd(x, y), lo1 = _mm_unpackhi_pd(x, y);
            const __m128d lo2 = _mm_unpacklo_pd(load1(a0 + 16), load1(a1 + 16));
            x = load2(c0), y = load2(c1);
            const __m128d hi0 = _mm_unpacklo_pd(x, y), hi1 = _mm_unpackhi_pd(x, y);
            const __m128d hi2 = _mm_unpacklo_pd(load1(c0 + 16), load1(c1 + 16));
            _mm_storeu_pd(v + 0 * m + i, lo0);
            _mm_storeu_pd(v + 1 * m + i, lo1);
            _mm_storeu_pd(v + 2 * m + i, lo2);
            _mm_storeu_pd(v + 3 * m + i, hi0);
            _mm_storeu_pd(v + 4 * m + i, hi1);
            _mm_storeu_pd(v + 5 * m + i, hi2);
            check(lo0, hi0);
            check(lo1, hi1);
            check(lo2, hi2);
        }
        ok = _mm_movemask_pd(good) == 3;
    }
#endif
    for (; i < m; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            const double lo = b.min(begin + i, j), hi = b.max(begin + i, j), d = hi - lo;
            v[static_cast<Index>(j) * m + i] = lo;
            v[static_cast<Index>(3 + j) * m + i] = hi;
            ok &= (d >= 0) & (d <= big);
        }
    return ok;
}

// Aligned boxes with one cylinder: a chunk is gathered into six arrays (the batch API's layout) and
// checked on the way, then answered by boxcyl::batch::intersects on this thread.
struct AlignedBatchChunk {
    const AlignedFields& boxes;
    using Scratch = Buffer<double>;

    void operator()(Scratch& s, const Cylinder& cyl, bool* result, FirstFailure& failure, Index begin,
                    Index end) const {
        const Index m = end - begin;
        double* v = s.get(6 * m);
        if (!gather_aligned(boxes, begin, m, v)) {
            for (Index i = begin; i < end; ++i)
                if (!plausible(boxes(i)))
                    if (auto val = boxcyl::validate(boxes(i), element_name("box", "boxes", false, i)); !val) {
                        failure.record(2 * i, val.message());
                        return;
                    }
        }
        auto span = [&](Index j) { return std::span<const double>(v + j * m, static_cast<std::size_t>(m)); };
        boxcyl::batch::intersects(cyl, boxcyl::batch::AlignedBoxes<double>{span(0), span(1), span(2), span(3), span(4), span(5)},
                                  std::span<bool>(result + begin, static_cast<std::size_t>(m)), {1});
    }
};

// Copies oriented boxes [begin, begin + m) into OrientedBox structs. When each field's numbers are
// adjacent in a row (C-contiguous (N, 3) and (N, 3, 3) arrays, also row views of bigger ones), three
// copies of 24, 72 and 24 bytes a box, with the rows a little ahead prefetched (the gather runs
// between the batch's chunks, so nothing else hides the memory's latency).
void gather_oriented(const OrientedFields& b, Index begin, Index m, OrientedBox* v) {
    auto dense = [](const Field& f, std::size_t k) {
        for (std::size_t j = 0; j < k; ++j)
            if (f.offset[j] != static_cast<Index>(8 * j)) return false;
        return f.step != 0;
    };
    if (!(dense(b.center, 3) && dense(b.axes, 9) && dense(b.extents, 3))) {
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

// Oriented boxes with one cylinder: a chunk is gathered into OrientedBox structs and answered by the
// batch API, which checks each box on the numbers it loads (Options::check_boxes); an invalid box is
// then named by validate().
struct OrientedBatchChunk {
    const OrientedFields& boxes;
    using Scratch = Buffer<OrientedBox>;

    void operator()(Scratch& s, const Cylinder& cyl, bool* result, FirstFailure& failure, Index begin,
                    Index end) const {
        const Index m = end - begin;
        OrientedBox* v = s.get(m);
        gather_oriented(boxes, begin, m, v);
        try {
            boxcyl::batch::intersects(cyl, std::span<const OrientedBox>(v, static_cast<std::size_t>(m)),
                                      std::span<bool>(result + begin, static_cast<std::size_t>(m)),
                                      {1, boxcyl::batch::Kernel::automatic, true});
        } catch (const boxcyl::batch::InvalidBox& e) {
            const Index i = begin + static_cast<Index>(e.index);
            failure.record(2 * i, boxcyl::validate(v[e.index], element_name("box", "boxes", false, i)).message());
        }
    }
};

// Aligned boxes with one cylinder, as the rows of a C-contiguous (N, 2, 3) array (min and max of box i
// are the six numbers at 48i bytes): no copy; the batch API reads the rows in place, and checks each
// box on the numbers it loads (Options::check_boxes) — a chunk that holds an invalid box is answered
// no further, and the box is named by validate().
struct AlignedRowsChunk {
    const AlignedFields& boxes;
    const AlignedBox* rows;
    struct Scratch {};

    void operator()(Scratch&, const Cylinder& cyl, bool* result, FirstFailure& failure, Index begin, Index end) const {
        const auto m = static_cast<std::size_t>(end - begin);
        try {
            boxcyl::batch::intersects(cyl, std::span<const AlignedBox>(rows + begin, m),
                                      std::span<bool>(result + begin, m), {1, boxcyl::batch::Kernel::automatic, true});
        } catch (const boxcyl::batch::InvalidBox& e) {
            const Index i = begin + static_cast<Index>(e.index);
            failure.record(2 * i, boxcyl::validate(boxes(i), element_name("box", "boxes", false, i)).message());
        }
    }
};

// The rows of a C-contiguous (N, 2, 3) float64 array, when min and max are its two halves (the
// package passes boxes[:, 0] and boxes[:, 1]); else nullptr.
const AlignedBox* aligned_rows(const AlignedFields& b) {
    auto adjacent = [](const Field& f) { return f.offset[0] == 0 && f.offset[1] == 8 && f.offset[2] == 16; };
    const bool rows = adjacent(b.min) && adjacent(b.max) && b.min.step == 48 && b.max.step == 48 &&
                      b.max.base == b.min.base + 24 &&
                      reinterpret_cast<std::uintptr_t>(b.min.base) % alignof(AlignedBox) == 0;
    return rows ? reinterpret_cast<const AlignedBox*>(b.min.base) : nullptr;
}

py::array_t<bool> intersects_aligned(const py::array& min, const py::array& max, bool box_single,
                                     const py::array& center, const py::array& axis, const py::array& radius,
                                     const py::array& height, bool cylinder_single, boxcyl::Algorithm algorithm,
                                     boxcyl::Arithmetic arithmetic, unsigned threads) {
    const AlignedFields boxes{field(min, "min", {3}), field(max, "max", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length({&boxes.min, &boxes.max, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    if (const AlignedBox* rows = box_single ? nullptr : aligned_rows(boxes))
        return run_batch(n, boxes, box_single, cyls, cylinder_single, algorithm, arithmetic, threads, kAlignedChunks,
                         AlignedRowsChunk{boxes, rows});
    return run_batch(n, boxes, box_single, cyls, cylinder_single, algorithm, arithmetic, threads, kAlignedChunks,
                     AlignedBatchChunk{boxes});
}

py::array_t<bool> intersects_oriented(const py::array& box_center, const py::array& axes, const py::array& extents,
                                      bool box_single, const py::array& center, const py::array& axis,
                                      const py::array& radius, const py::array& height, bool cylinder_single,
                                      boxcyl::Algorithm algorithm, boxcyl::Arithmetic arithmetic, unsigned threads) {
    const OrientedFields boxes{field(box_center, "box center", {3}), field(axes, "axes", {3, 3}),
                               field(extents, "extents", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length(
        {&boxes.center, &boxes.axes, &boxes.extents, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    return run_batch(n, boxes, box_single, cyls, cylinder_single, algorithm, arithmetic, threads, kOrientedChunks,
                     OrientedBatchChunk{boxes});
}

// Parallelepipeds: the scalar query for each (the batch API takes aligned and oriented boxes).
py::array_t<bool> intersects_parallelepiped(const py::array& box_center, const py::array& axes,
                                            const py::array& extents, bool box_single, const py::array& center,
                                            const py::array& axis, const py::array& radius, const py::array& height,
                                            bool cylinder_single, boxcyl::Algorithm algorithm,
                                            boxcyl::Arithmetic arithmetic, unsigned threads) {
    const FrameFields<Parallelepiped> boxes{field(box_center, "box center", {3}), field(axes, "axes", {3, 3}),
                                            field(extents, "extents", {3})};
    const CylinderFields cyls = cylinder_fields(center, axis, radius, height);
    const Index n = batch_length(
        {&boxes.center, &boxes.axes, &boxes.extents, &cyls.center, &cyls.axis, &cyls.radius, &cyls.height});
    return run_batch(n, boxes, box_single, cyls, cylinder_single, algorithm, arithmetic, threads, kScalarChunks,
                     nullptr);
}

// ---- Poses and sizes (boxcyl/geometry/pose.hpp): the package's named constructors call these. ----

using Matrix3 = std::array<Array3, 3>;
using Matrix4 = std::array<std::array<double, 4>, 4>;

boxcyl::RotationMatrix<double> rotation_matrix(const Matrix3& rows) { return {rows}; }
boxcyl::Quaternion<double> quaternion(const std::array<double, 4>& wxyz) {
    return {wxyz[0], wxyz[1], wxyz[2], wxyz[3]};
}

// `full`: sizes are full side lengths (Size), else half (HalfExtents).
OrientedBox box_from(const Vec& center, const boxcyl::RotationMatrix<double>& r, const Array3& sizes, bool full) {
    if (full) return validated(boxcyl::oriented_box(center, r, boxcyl::Size<double>{sizes[0], sizes[1], sizes[2]}), "box");
    return validated(boxcyl::oriented_box(center, r, boxcyl::HalfExtents<double>{sizes[0], sizes[1], sizes[2]}), "box");
}

// `half`: length is half the height (HalfHeight), else the full height (Height).
Cylinder cylinder_from(const Vec& center, const boxcyl::RotationMatrix<double>& r, double radius, double length,
                       bool half, int along) {
    const auto axis = static_cast<boxcyl::LocalAxis>(along);
    if (half) return validated(boxcyl::cylinder(center, r, radius, boxcyl::HalfHeight<double>{length}, axis), "cylinder");
    return validated(boxcyl::cylinder(center, r, radius, boxcyl::Height<double>{length}, axis), "cylinder");
}

void def_poses(py::module_& m) {
    m.def("_box_from_rotation", [](const Array3& center, const Matrix3& r, const Array3& sizes, bool full) {
        return box_from(vec(center), rotation_matrix(r), sizes, full);
    });
    m.def("_box_from_quaternion", [](const Array3& center, const std::array<double, 4>& wxyz, const Array3& sizes,
                                     bool full) { return box_from(vec(center), boxcyl::rotation(quaternion(wxyz)), sizes, full); });
    m.def("_box_from_transform", [](const Matrix4& t, const Array3& sizes, bool full) {
        const boxcyl::RigidTransform<double> pose{t};
        return box_from(boxcyl::translation(pose), boxcyl::rotation(pose), sizes, full);
    });
    m.def("_cylinder_from_rotation", [](const Array3& center, const Matrix3& r, double radius, double length, bool half,
                                        int along) {
        return cylinder_from(vec(center), rotation_matrix(r), radius, length, half, along);
    });
    m.def("_cylinder_from_quaternion", [](const Array3& center, const std::array<double, 4>& wxyz, double radius,
                                          double length, bool half, int along) {
        return cylinder_from(vec(center), boxcyl::rotation(quaternion(wxyz)), radius, length, half, along);
    });
    m.def("_cylinder_from_transform", [](const Matrix4& t, double radius, double length, bool half, int along) {
        const boxcyl::RigidTransform<double> pose{t};
        return cylinder_from(boxcyl::translation(pose), boxcyl::rotation(pose), radius, length, half, along);
    });
}

// ---- The C++ batch alone, timed: what the batch forms wrap (bench/python_batch.py compares). ----

using F64Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Wall-clock seconds and the process's CPU seconds (all threads) from construction to stop(): on a
// shared machine the CPU time is the steadier measure (time.process_time() is its Python side).
struct Timer {
    static double cpu_now() {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    std::chrono::steady_clock::time_point wall0 = std::chrono::steady_clock::now();
    double cpu0 = cpu_now();
    double wall = 0, cpu = 0;
    void stop() {
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        cpu = cpu_now() - cpu0;
    }
};

// soa: (6, N) rows min_x, min_y, min_z, max_x, max_y, max_z. Returns (answers, wall seconds, CPU seconds of the call).
py::tuple timed_batch_aligned(const F64Array& soa, const Cylinder& cyl, unsigned threads) {
    if (soa.ndim() != 2 || soa.shape(0) != 6) throw py::value_error("soa: expected shape (6, N)");
    const auto n = static_cast<std::size_t>(soa.shape(1));
    const double* d = soa.data();
    auto row = [&](std::size_t j) { return std::span<const double>(d + j * n, n); };
    py::array_t<bool> out(static_cast<Index>(n));
    std::span<bool> result(out.mutable_data(), n);
    Timer timer;
    {
        py::gil_scoped_release release;
        boxcyl::batch::intersects(cyl, boxcyl::batch::AlignedBoxes<double>{row(0), row(1), row(2), row(3), row(4), row(5)},
                                  result, {threads});
        timer.stop();
    }
    return py::make_tuple(out, timer.wall, timer.cpu);
}

// boxes: (N, 2, 3) rows [min, max], read in place as AlignedBox<double>.
py::tuple timed_batch_aligned_rows(const F64Array& boxes, const Cylinder& cyl, unsigned threads) {
    if (boxes.ndim() != 3 || boxes.shape(1) != 2 || boxes.shape(2) != 3) throw py::value_error("boxes: expected shape (N, 2, 3)");
    const auto n = static_cast<std::size_t>(boxes.shape(0));
    const auto* rows = reinterpret_cast<const AlignedBox*>(boxes.data());
    py::array_t<bool> out(static_cast<Index>(n));
    std::span<bool> result(out.mutable_data(), n);
    Timer timer;
    {
        py::gil_scoped_release release;
        boxcyl::batch::intersects(cyl, std::span<const AlignedBox>(rows, n), result, {threads});
        timer.stop();
    }
    return py::make_tuple(out, timer.wall, timer.cpu);
}

// boxes: (N, 15) rows center, axes[0..2], extents (OrientedBox's members in order), copied into an
// array of OrientedBox before the timed call.
py::tuple timed_batch_oriented(const F64Array& rows, const Cylinder& cyl, unsigned threads) {
    if (rows.ndim() != 2 || rows.shape(1) != 15) throw py::value_error("boxes: expected shape (N, 15)");
    const auto n = static_cast<std::size_t>(rows.shape(0));
    std::vector<OrientedBox> boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double* r = rows.data() + 15 * i;
        boxes[i] = {{r[0], r[1], r[2]},
                    {Vec{r[3], r[4], r[5]}, Vec{r[6], r[7], r[8]}, Vec{r[9], r[10], r[11]}},
                    {r[12], r[13], r[14]}};
    }
    py::array_t<bool> out(static_cast<Index>(n));
    std::span<bool> result(out.mutable_data(), n);
    Timer timer;
    {
        py::gil_scoped_release release;
        boxcyl::batch::intersects(cyl, std::span<const OrientedBox>(boxes), result, {threads});
        timer.stop();
    }
    return py::make_tuple(out, timer.wall, timer.cpu);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "boxcyl's compiled core; use the package `boxcyl`, which re-exports it.";
    m.attr("__version__") = BOXCYL_VERSION_STRING;

    py::enum_<boxcyl::Algorithm>(m, "Algorithm",
                                 "Which algorithm answers: linear inequalities (default), convex hull, LCP, "
                                 "or the exact oracle (docs/algorithms.md).")
        .value("inequalities", boxcyl::Algorithm::inequalities, "the linear-inequalities method (the default)")
        .value("hull", boxcyl::Algorithm::hull, "the convex-hull method: clip, project, 2-D hull")
        .value("lcp", boxcyl::Algorithm::lcp, "convex quadratic programming as an LCP (Lemke's method)")
        .value("oracle", boxcyl::Algorithm::oracle, "the exact reference");
    py::enum_<boxcyl::Arithmetic>(m, "Arithmetic",
                                  "Which arithmetic: filtered (default: the exact answer, fast), exact, or "
                                  "plain rounded float64/float32.")
        .value("float32", boxcyl::Arithmetic::float32, "rounded single precision")
        .value("float64", boxcyl::Arithmetic::float64, "rounded double precision (plain, fastest)")
        .value("exact", boxcyl::Arithmetic::exact, "rationals and a + b*sqrt(d) throughout")
        .value("filtered", boxcyl::Arithmetic::filtered,
               "the exact answer: certified interval filter, exact fallback (the default)");

    // The classes take plain floats here; the package's subclasses convert and name bad arguments.
    py::class_<Cylinder>(m, "Cylinder",
                         "A closed finite cylinder: the points within `radius` of the axis segment "
                         "center ± (height/2)·axis/|axis|. `axis` need not be unit length; radius 0 is a "
                         "segment, height 0 a disk. Immutable; validated when built (ValueError naming "
                         "the bad field).")
        .def(py::init([](const Array3& center, const Array3& axis, double radius, double height) {
                 return validated(Cylinder{vec(center), vec(axis), radius, height}, "cylinder");
             }),
             "center"_a, "axis"_a, "radius"_a, "height"_a)
        .def_property_readonly("center", [](const Cylinder& c) { return tuple(c.center); })
        .def_property_readonly("axis", [](const Cylinder& c) { return tuple(c.axis); })
        .def_property_readonly("radius", [](const Cylinder& c) { return c.radius; })
        .def_property_readonly("height", [](const Cylinder& c) { return c.height; })
        .def("__repr__", [](const Cylinder& c) {
            return py::str("Cylinder(center={!r}, axis={!r}, radius={!r}, height={!r})")
                .format(tuple(c.center), tuple(c.axis), c.radius, c.height);
        });

    py::class_<AlignedBox>(m, "AlignedBox",
                           "The closed axis-aligned box min <= X <= max (componentwise); equal bounds give a "
                           "flat box or a point. Immutable; validated when built.")
        .def(py::init([](const Array3& min, const Array3& max) {
                 return validated(AlignedBox{vec(min), vec(max)}, "box");
             }),
             "min"_a, "max"_a)
        .def_property_readonly("min", [](const AlignedBox& b) { return tuple(b.min); })
        .def_property_readonly("max", [](const AlignedBox& b) { return tuple(b.max); })
        .def("__repr__", [](const AlignedBox& b) {
            return py::str("AlignedBox(min={!r}, max={!r})").format(tuple(b.min), tuple(b.max));
        });

    py::class_<OrientedBox>(m, "OrientedBox",
                            "The closed solid { center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= "
                            "extents[i] } for the axes exactly as given; they must be orthonormal to within "
                            "1e-4 (a rotation rounded to double is fine). Immutable; validated when built.")
        .def(py::init([](const Array3& center, const std::array<Array3, 3>& axes, const Array3& extents) {
                 return validated(OrientedBox{vec(center), {vec(axes[0]), vec(axes[1]), vec(axes[2])}, vec(extents)},
                                  "box");
             }),
             "center"_a, "axes"_a, "extents"_a)
        .def_property_readonly("center", [](const OrientedBox& b) { return tuple(b.center); })
        .def_property_readonly("axes",
                               [](const OrientedBox& b) {
                                   return py::make_tuple(tuple(b.axes[0]), tuple(b.axes[1]), tuple(b.axes[2]));
                               })
        .def_property_readonly("extents", [](const OrientedBox& b) { return tuple(b.extents); })
        .def("__repr__", [](const OrientedBox& b) {
            return py::str("OrientedBox(center={!r}, axes={!r}, extents={!r})")
                .format(tuple(b.center), py::make_tuple(tuple(b.axes[0]), tuple(b.axes[1]), tuple(b.axes[2])),
                        tuple(b.extents));
        });

    py::class_<Parallelepiped>(m, "Parallelepiped",
                               "The closed solid { center + x0*axes[0] + x1*axes[1] + x2*axes[2] : |xi| <= "
                               "extents[i] } for ANY three axes exactly as given (any lengths and angles; parallel "
                               "or zero axes give flat solids). Immutable; validated when built.")
        .def(py::init([](const Array3& center, const std::array<Array3, 3>& axes, const Array3& extents) {
                 return validated(
                     Parallelepiped{vec(center), {vec(axes[0]), vec(axes[1]), vec(axes[2])}, vec(extents)}, "box");
             }),
             "center"_a, "axes"_a, "extents"_a)
        .def_property_readonly("center", [](const Parallelepiped& b) { return tuple(b.center); })
        .def_property_readonly("axes",
                               [](const Parallelepiped& b) {
                                   return py::make_tuple(tuple(b.axes[0]), tuple(b.axes[1]), tuple(b.axes[2]));
                               })
        .def_property_readonly("extents", [](const Parallelepiped& b) { return tuple(b.extents); })
        .def("__repr__", [](const Parallelepiped& b) {
            return py::str("Parallelepiped(center={!r}, axes={!r}, extents={!r})")
                .format(tuple(b.center), py::make_tuple(tuple(b.axes[0]), tuple(b.axes[1]), tuple(b.axes[2])),
                        tuple(b.extents));
        });
    def_poses(m);

    // The query; the package's intersects() checks the argument types and wraps it.
    const char* intersects_doc = "intersects(box, cylinder, algorithm, arithmetic) -> bool, with the GIL released.";
    m.def("intersects", &query<AlignedBox>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(), intersects_doc);
    m.def("intersects", &query<OrientedBox>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(), intersects_doc);
    m.def("intersects", &query<Parallelepiped>, "box"_a, "cylinder"_a, "algorithm"_a = boxcyl::Algorithm::inequalities,
          "arithmetic"_a = boxcyl::Arithmetic::filtered, py::call_guard<py::gil_scoped_release>(), intersects_doc);

    // Batch kernels: the package's intersects_aligned / intersects_oriented shape the arguments.
    m.def("_intersects_aligned", &intersects_aligned, "min"_a, "max"_a, "box_single"_a, "center"_a, "axis"_a,
          "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a, "arithmetic"_a, "threads"_a);
    m.def("_intersects_oriented", &intersects_oriented, "box_center"_a, "axes"_a, "extents"_a, "box_single"_a,
          "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a, "arithmetic"_a,
          "threads"_a);
    m.def("_intersects_parallelepiped", &intersects_parallelepiped, "box_center"_a, "axes"_a, "extents"_a,
          "box_single"_a, "center"_a, "axis"_a, "radius"_a, "height"_a, "cylinder_single"_a, "algorithm"_a,
          "arithmetic"_a, "threads"_a);
    m.def("_timed_batch_aligned", &timed_batch_aligned, "soa"_a, "cylinder"_a, "threads"_a,
          "boxcyl::batch::intersects alone on (6, N) arrays: (answers, wall seconds, CPU seconds). For benchmarks.");
    m.def("_timed_batch_aligned_rows", &timed_batch_aligned_rows, "boxes"_a, "cylinder"_a, "threads"_a,
          "boxcyl::batch::intersects alone on (N, 2, 3) [min, max] rows: (answers, wall seconds, CPU seconds). For benchmarks.");
    m.def("_timed_batch_oriented", &timed_batch_oriented, "boxes"_a, "cylinder"_a, "threads"_a,
          "boxcyl::batch::intersects alone on (N, 15) oriented boxes: (answers, wall seconds, CPU seconds). For benchmarks.");
    m.def("_hardware_threads", [] { return std::max(1u, std::thread::hardware_concurrency()); },
          "The number of threads `threads=None` uses at most.");
    m.def("_fp_environment_ok", &boxcyl::fp_environment_ok,
          "Whether this thread's floating-point environment keeps subnormals (no FTZ/DAZ).");
}
