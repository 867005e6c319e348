// The batch API's types (boxcyl/batch.hpp), the same for every kernel whatever instruction set it was
// compiled for: the box arrays, the options, the statistics and the table of a kernel's entry points.
#pragma once

#include <cstddef>    // std::size_t
#include <cstdint>    // std::uint64_t
#include <span>       // inputs and outputs
#include <stdexcept>  // InvalidBox, Stopped
#include <stop_token>  // Options::stop
#include <string>     // its message

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"

namespace boxcyl::batch {

// Aligned boxes as six arrays (all the same length).
template <class T>
struct AlignedBoxes {
    std::span<const T> min_x, min_y, min_z, max_x, max_y, max_z;
    std::size_t size() const { return min_x.size(); }
};

// Which SIMD kernel answers. Every kernel gives the same answers (exact: only the speed differs).
//   automatic  the fastest this CPU runs: with boxcyl::batch_dispatch linked, AVX-512 or AVX2 when the
//              CPU has them and they are wider than `compiled`; otherwise `compiled`.
//   compiled   the kernel of the header itself, at the width the includer's compile flags give (2
//              doubles with the default x86-64 flags: it runs on any x86-64).
//   avx2       4 doubles (AVX2 + FMA), from boxcyl::batch_dispatch.
//   avx512     8 doubles (AVX-512 F/DQ/VL/BW), from boxcyl::batch_dispatch.
// Asking for avx2 or avx512 where it is not available throws std::invalid_argument (see available()),
// and so does asking for them with parallelepipeds, which have no SIMD kernel (batch/parallelepiped.hpp).
enum class Kernel { automatic, compiled, avx2, avx512 };

constexpr const char* name(Kernel k) {
    switch (k) {
        case Kernel::automatic: return "automatic";
        case Kernel::compiled: return "compiled";
        case Kernel::avx2: return "avx2";
        case Kernel::avx512: return "avx512";
    }
    return "?";
}

struct Options {
    unsigned threads = 1;               // 0: std::thread::hardware_concurrency()
    Kernel kernel = Kernel::automatic;  // which SIMD kernel (answers do not depend on it)
    // Check every box (boxcyl::is_valid) before answering it, instead of assuming it valid: an invalid
    // box throws InvalidBox. For aligned and oriented boxes a few vector operations in the filter's
    // first pass, on the numbers it loads anyway (bounds ordered and finite; for oriented boxes finite
    // numbers, extents ≥ 0, the axes' Gram matrix in double); a block they cannot clear is judged by
    // is_valid. Parallelepipeds call is_valid per box.
    bool check_boxes = false;
    // Cancellation: every thread looks at it before each group of up to 32 blocks of 64 boxes (whose
    // filter passes run together) and before each block's scalar work, and once a stop is requested the
    // call throws Stopped (the answers written so far are of whole blocks; the others are unspecified).
    // Parallelepipeds: before each block. A default token never stops; looking costs a load.
    std::stop_token stop = {};
};

// Thrown with Options::check_boxes for an invalid box: `index` is the first invalid box of the
// lowest-numbered 64-box block that has one (with one thread: the first invalid box of the batch).
// No box of that block was answered; the output is otherwise unspecified.
struct InvalidBox : std::invalid_argument {
    std::size_t index;
    explicit InvalidBox(std::size_t i)
        : std::invalid_argument("boxcyl::batch::intersects: boxes[" + std::to_string(i) +
                                "] is invalid (see boxcyl::validate)"),
          index(i) {}
};

// Thrown when Options::stop was requested before the batch was answered.
struct Stopped : std::runtime_error {
    Stopped() : std::runtime_error("boxcyl::batch::intersects: stopped (Options::stop)") {}
};

struct Stats {
    std::size_t boxes = 0;        // N
    std::size_t exact_lanes = 0;  // boxes the SIMD filter could not decide: answered by the scalar query
    std::size_t second_pass = 0;  // aligned boxes that the first pass left to the whole filter (diagnostic)
    Kernel kernel = Kernel::compiled;  // the kernel that ran (never automatic)
    std::size_t lanes = 0;             // its vector width in doubles
};

// Words of a bit mask for n boxes.
constexpr std::size_t mask_words(std::size_t n) { return (n + 63) / 64; }

// The clearance query of one batch (boxcyl::batch::within_distance, margin > 0): the filter tries the
// probe cylinders in order (boxcyl/clearance.hpp's detail::clearance::probes, in batch.hpp's
// kBatchProbeOrder), and a lane it proves to
// meet probe k exactly when decides_when[k] says is answered decides_when[k]; the lanes no probe
// decides go to the scalar query within_distance_unchecked through `aligned` or `oriented`. Through
// pointers, so that the AVX2 and AVX-512 kernels (src/batch/) call the includer's plain x86-64 copy and
// do not compile the clearance query themselves.
struct Clearance {
    Cylinder<double> cylinder;
    double margin = 0;
    Cylinder<double> probe[3];
    bool decides_when[3] = {};
    std::size_t probes = 0;
    bool (*aligned)(const AlignedBox<double>&, const Cylinder<double>&, double) = nullptr;
    bool (*oriented)(const OrientedBox<double>&, const Cylinder<double>&, double) = nullptr;
};

// A kernel's entry points for one element type T of the boxes (float or double) and one query Q (a
// Cylinder<double>: intersects; a Clearance: within_distance): aligned boxes (six arrays, or an array
// of AlignedBox<T>) or oriented boxes, into a bit mask or a bool per box. Preconditions as
// boxcyl::batch::intersects; the lengths are checked by the caller.
template <class T, class Q>
struct QueryEntries {
    Stats (*aligned_mask)(const Q&, const AlignedBoxes<T>&, std::span<std::uint64_t>, const Options&);
    Stats (*aligned_bools)(const Q&, const AlignedBoxes<T>&, std::span<bool>, const Options&);
    Stats (*rows_mask)(const Q&, std::span<const AlignedBox<T>>, std::span<std::uint64_t>, const Options&);
    Stats (*rows_bools)(const Q&, std::span<const AlignedBox<T>>, std::span<bool>, const Options&);
    Stats (*oriented_mask)(const Q&, std::span<const OrientedBox<T>>, std::span<std::uint64_t>, const Options&);
    Stats (*oriented_bools)(const Q&, std::span<const OrientedBox<T>>, std::span<bool>, const Options&);
};

template <class T>
struct KernelEntries {
    QueryEntries<T, Cylinder<double>> intersects;
    QueryEntries<T, Clearance> within;

    const QueryEntries<T, Cylinder<double>>& of(const Cylinder<double>&) const { return intersects; }
    const QueryEntries<T, Clearance>& of(const Clearance&) const { return within; }
};

// One kernel: its name, its width, its entry points.
struct KernelTable {
    Kernel kernel;
    std::size_t lanes;
    KernelEntries<float> f;
    KernelEntries<double> d;

    template <class T>
    const KernelEntries<T>& entries() const {
        if constexpr (sizeof(T) == sizeof(float))
            return f;
        else
            return d;
    }
};

}  // namespace boxcyl::batch
