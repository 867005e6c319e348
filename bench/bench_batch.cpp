// The batch API (boxcyl/batch.hpp): per-box cost of the batch against the scalar exact
// default on the same data, single- and multi-threaded, the fraction of lanes that went to the scalar
// path, and the throughput on 10 million double aligned boxes beside the memory bandwidth measured on
// the same arrays in the same run.
//
// Data (generated before any timing, fixed seeds; tests/support/batch_cases.hpp, from the tests'
// CaseGenerator): for each of 32 cylinders, 2048 aligned and 2048 oriented boxes around it, about
// half hitting.
//   mixed:   the CaseGenerator cylinders as they come (1/12 segments, 1/12 disks, tiny axis components)
//   regular: the first 32 seeds whose cylinder has r > 0 and h > 0
//   10M:     10,000,000 aligned boxes (structure of arrays, 480 MB) around one regular cylinder:
//            `voxels` (sides 1/64 of the cylinder's reach, uniform in its bounding box grown by half)
//            and `random` (the batch_cases distribution: boxes up to the cylinder's size).
// prepare: the per-call cylinder constants alone (ns_per_box is per cylinder there).
// small_batch: the first 8 or 64 boxes of each mixed aligned set per call (the per-call cost shows).
// large_scalar: the scalar default on the first million boxes of each 10M set (the per-box ratio).
// Counters: ns_per_box (time per box — CPU time, real time for the 10M runs; Google Benchmark prints
// it as seconds: "108.5s" is 108.5 ns),
// exact_pct (% of lanes answered by the scalar path), second_pass_pct (10M runs: % of the aligned
// boxes that the first pass left to the whole filter), hit_pct, boxes_per_s and GB_per_s of box data
// (48 bytes per box) on real time, and for `stream_sum` the bandwidth of summing the same six arrays
// (one thread, and all threads split like the batch). The 10M runs also measure that bandwidth
// themselves (stream_GB_per_s, the fastest of five passes with the same threads) and report
// bandwidth_share_pct: the batch's throughput as a share of it, the goal being ≥ 50.
//
// margin_3_voxels: the clearance form, batch::within_distance, on the same 10M sets at a margin of three
// voxel sides (3/64 of the cylinder's reach): beside voxels/threads_1/automatic etc., the cost of the
// margin is one run's ratio; exact_pct there is the share left to the scalar clearance query.
// margin_pair: the same two calls paired, one thread: each iteration times batch::intersects and
// batch::within_distance (3 voxel sides) on the same set back to back, in alternating order, so that
// both see the same minute of a shared machine; counters plain_ns_per_box, margin_ns_per_box and their
// ratio (the total times'), the figure scripts/bench.sh reports.
//
// Aligned boxes are timed in both forms of the batch API: `aligned` the six arrays, `aligned_rows` an
// array of AlignedBox<double> (the [min, max] rows, read in place) holding the same boxes.
//
// Kernels: each batch run twice, `automatic` (boxcyl::batch_dispatch's choice for this CPU, named in
// the label) and `compiled` (the header's portable kernel).
//
// Run: build-batch/bench/bench_batch --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>  // std::min
#include <chrono>     // the bandwidth share's own timing
#include <cstdint>    // std::uint64_t
#include <cstdio>     // std::printf
#include <thread>     // hardware_concurrency
#include <vector>     // data

#include "boxcyl/batch.hpp"
#include "boxcyl/query.hpp"
#include "support/batch_cases.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::BatchSet;

constexpr std::size_t kSets = 32;
constexpr std::size_t kBoxesPerSet = 2048;
constexpr std::size_t kLarge = 10'000'000;

struct Soa {
    std::vector<double> v[6];
    void add(const AlignedBox<double>& b) {
        for (int j = 0; j < 3; ++j) v[j].push_back(b.min[j]), v[3 + j].push_back(b.max[j]);
    }
    batch::AlignedBoxes<double> view() const { return {v[0], v[1], v[2], v[3], v[4], v[5]}; }
    std::size_t size() const { return v[0].size(); }
};

struct Set {
    BatchSet boxes;
    Soa soa;
};

bool regular(const Cylinder<double>& c) { return c.radius > 0 && c.height > 0; }

std::vector<Set> make_sets(bool only_regular) {
    std::vector<Set> sets;
    for (std::uint64_t seed = 0xBE7C0000; sets.size() < kSets; ++seed) {
        Set s{testing::random_batch(seed, kBoxesPerSet), {}};
        if (only_regular && !regular(s.boxes.cylinder)) continue;
        for (const AlignedBox<double>& b : s.boxes.aligned) s.soa.add(b);
        sets.push_back(std::move(s));
    }
    return sets;
}

const std::vector<Set>& data(bool only_regular) {
    static const std::vector<Set> mixed = make_sets(false), reg = make_sets(true);
    return only_regular ? reg : mixed;
}

void report(benchmark::State& state, std::size_t boxes_per_pass, std::size_t exact) {
    const double n = static_cast<double>(state.iterations()) * static_cast<double>(boxes_per_pass);
    state.counters["ns_per_box"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["exact_pct"] = 100.0 * static_cast<double>(exact) / n;
    state.SetItemsProcessed(static_cast<std::int64_t>(n));
}

// The scalar exact default over every box of every set.
void scalar(benchmark::State& state, bool only_regular, bool oriented) {
    const std::vector<Set>& sets = data(only_regular);
    std::size_t per_pass = 0;
    for (auto _ : state) {
        per_pass = 0;
        for (const Set& s : sets) {
            if (oriented) {
                for (const OrientedBox<double>& b : s.boxes.oriented) benchmark::DoNotOptimize(boxcyl::intersects(b, s.boxes.cylinder));
                per_pass += s.boxes.oriented.size();
            } else {
                for (const AlignedBox<double>& b : s.boxes.aligned) benchmark::DoNotOptimize(boxcyl::intersects(b, s.boxes.cylinder));
                per_pass += s.boxes.aligned.size();
            }
        }
    }
    report(state, per_pass, 0);
}

enum class Form { arrays, rows, oriented };

// The batch, one call per cylinder.
void batched(benchmark::State& state, bool only_regular, Form form, unsigned threads, batch::Kernel kernel) {
    if (!batch::available(kernel)) return state.SkipWithError("kernel not available on this machine");
    const std::vector<Set>& sets = data(only_regular);
    std::vector<std::uint64_t> mask(batch::mask_words(kBoxesPerSet));
    std::size_t per_pass = 0, exact = 0;
    batch::Kernel ran = kernel;
    for (auto _ : state) {
        per_pass = 0;
        for (const Set& s : sets) {
            const batch::Options opt{threads, kernel};
            const std::span<std::uint64_t> out(mask);
            const batch::Stats st =
                form == Form::oriented ? batch::intersects(s.boxes.cylinder, std::span<const OrientedBox<double>>(s.boxes.oriented), out, opt)
                : form == Form::rows   ? batch::intersects(s.boxes.cylinder, std::span<const AlignedBox<double>>(s.boxes.aligned), out, opt)
                                       : batch::intersects(s.boxes.cylinder, s.soa.view(), out, opt);
            benchmark::DoNotOptimize(mask.data());
            per_pass += st.boxes;
            exact += st.exact_lanes;
            ran = st.kernel;
        }
    }
    report(state, per_pass, exact);
    state.SetLabel(batch::name(ran));
}

// The per-call cost alone: the cylinder's certified constants (batch::detail::prepare) for the 4096
// cylinders of bench_query's random set (segments, disks, tiny axis components included).
void prepare(benchmark::State& state) {
    static const std::vector<Cylinder<double>> cylinders = [] {
        std::vector<Cylinder<double>> v;
        v.reserve(4096);
        testing::CaseGenerator gen(0xb0c5c701);
        for (int i = 0; i < 4096; ++i) v.push_back(gen.next().cylinder);
        return v;
    }();
    for (auto _ : state) {
        double sum = 0;
        for (const Cylinder<double>& c : cylinders) sum += batch::detail::prepare(c).rho_u;
        benchmark::DoNotOptimize(sum);
    }
    report(state, cylinders.size(), 0);  // ns_per_box: per cylinder here
}

// Small batches: the first n aligned boxes of each mixed set per call, so the per-batch cost (the
// cylinder's constants, certified once per call) counts n times less than in a big batch.
void small_batch(benchmark::State& state, std::size_t n) {
    const std::vector<Set>& sets = data(false);
    std::vector<std::uint64_t> mask(batch::mask_words(n));
    std::size_t exact = 0;
    for (auto _ : state)
        for (const Set& s : sets) {
            const batch::AlignedBoxes<double> all = s.soa.view();
            const batch::AlignedBoxes<double> first{all.min_x.first(n), all.min_y.first(n), all.min_z.first(n),
                                                    all.max_x.first(n), all.max_y.first(n), all.max_z.first(n)};
            exact += batch::intersects(s.boxes.cylinder, first, std::span<std::uint64_t>(mask)).exact_lanes;
            benchmark::DoNotOptimize(mask.data());
        }
    report(state, n * sets.size(), exact);
}

// ---- 10 million aligned boxes. ----

struct Large {
    Cylinder<double> cylinder;
    Soa soa;
};

const Large& large(bool voxels) {
    static const Large v = [] {
        Large l;
        BatchSet s;
        for (std::uint64_t seed = 0xBE7C1000;; ++seed) {
            s = testing::random_batch(seed, 0);
            if (regular(s.cylinder)) break;
        }
        l.cylinder = s.cylinder;
        const Cylinder<double>& c = l.cylinder;
        const double reach = c.radius + c.height * 0.5;
        testing::CaseGenerator gen(0xBE7C2000);
        const double side = reach / 64;
        for (std::size_t i = 0; i < kLarge; ++i) {
            AlignedBox<double> b;
            for (int j = 0; j < 3; ++j) {
                b.min[j] = c.center[j] + 1.5 * reach * gen.uniform(-1, 1);
                b.max[j] = b.min[j] + side;
            }
            l.soa.add(b);
        }
        return l;
    }();
    static const Large r = [] {
        Large l;
        for (std::uint64_t seed = 0xBE7C1000;; ++seed) {
            if (!regular(testing::random_batch(seed, 0).cylinder)) continue;
            const BatchSet t = testing::random_batch(seed, kLarge, testing::Profile::mixed, false);
            l.cylinder = t.cylinder;
            for (const AlignedBox<double>& b : t.aligned) l.soa.add(b);
            return l;
        }
    }();
    return voxels ? v : r;
}

constexpr double kBytesPerBox = 6 * sizeof(double);

// One streaming pass over the six arrays (their sum), split over the threads like the batch: what the
// memory bandwidth allows for reading the boxes.
double stream_pass(const Large& l, unsigned threads) {
    const unsigned t = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<double> partial(std::size_t{t} * 8);  // a cache line apart
    batch::split::for_each_range(kLarge / 64, t, [&](std::size_t b, std::size_t e, unsigned k) {
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        for (int a = 0; a < 6; ++a) {
            const double* p = l.soa.v[a].data();
            for (std::size_t i = b * 64; i < e * 64; i += 4) s0 += p[i], s1 += p[i + 1], s2 += p[i + 2], s3 += p[i + 3];
        }
        partial[std::size_t{k} * 8] = (s0 + s1) + (s2 + s3);
    });
    double sum = 0;
    for (double x : partial) sum += x;
    return sum;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The same boxes as an array of AlignedBox<double> (built on first use: 480 MB more).
const std::vector<AlignedBox<double>>& large_rows(bool voxels) {
    auto make = [](const Large& l) {
        std::vector<AlignedBox<double>> rows(kLarge);
        for (std::size_t i = 0; i < kLarge; ++i)
            rows[i] = {{l.soa.v[0][i], l.soa.v[1][i], l.soa.v[2][i]}, {l.soa.v[3][i], l.soa.v[4][i], l.soa.v[5][i]}};
        return rows;
    };
    if (voxels) {
        static const std::vector<AlignedBox<double>> v = make(large(true));
        return v;
    }
    static const std::vector<AlignedBox<double>> r = make(large(false));
    return r;
}

// rows: the batch reads large_rows() instead of the six arrays (the bandwidth is still the arrays').
// margin_voxels > 0: the clearance form, batch::within_distance at a margin of that many voxel sides
// (the cylinder's reach / 64), on either set.
void large_batch(benchmark::State& state, bool voxels, unsigned threads, batch::Kernel kernel, bool rows = false,
                 double margin_voxels = 0) {
    if (!batch::available(kernel)) return state.SkipWithError("kernel not available on this machine");
    const Large& l = large(voxels);
    const std::span<const AlignedBox<double>> row_view = rows ? std::span<const AlignedBox<double>>(large_rows(voxels))
                                                              : std::span<const AlignedBox<double>>();
    // The bandwidth, in this run, with the same threads: the fastest of five streaming passes (so the
    // share below errs low).
    double stream_s = 1e300;
    for (int k = 0; k < 5; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(stream_pass(l, threads));
        stream_s = std::min(stream_s, seconds_since(t0));
    }
    std::vector<std::uint64_t> mask(batch::mask_words(kLarge));
    std::size_t exact = 0, hits = 0, second = 0;
    batch::Kernel ran = kernel;
    const auto t0 = std::chrono::steady_clock::now();
    const double margin = margin_voxels * (l.cylinder.radius + l.cylinder.height * 0.5) / 64;
    for (auto _ : state) {
        const batch::Options opt{threads, kernel};
        const std::span<std::uint64_t> out(mask);
        const batch::Stats st = margin > 0 ? (rows ? batch::within_distance(l.cylinder, row_view, margin, out, opt)
                                                   : batch::within_distance(l.cylinder, l.soa.view(), margin, out, opt))
                                : rows     ? batch::intersects(l.cylinder, row_view, out, opt)
                                           : batch::intersects(l.cylinder, l.soa.view(), out, opt);
        benchmark::DoNotOptimize(mask.data());
        ran = st.kernel;
        exact += st.exact_lanes;
        second += st.second_pass;
    }
    const double batch_s = seconds_since(t0) / static_cast<double>(state.iterations());
    for (std::uint64_t w : mask) hits += static_cast<std::size_t>(__builtin_popcountll(w));
    const double n = static_cast<double>(state.iterations()) * kLarge;
    state.counters["boxes_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
    state.counters["ns_per_box"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["GB_per_s"] = benchmark::Counter(n * kBytesPerBox * 1e-9, benchmark::Counter::kIsRate);
    state.counters["stream_GB_per_s"] = kLarge * kBytesPerBox * 1e-9 / stream_s;
    state.counters["bandwidth_share_pct"] = 100.0 * stream_s / batch_s;  // the goal: ≥ 50
    state.counters["exact_pct"] = 100.0 * static_cast<double>(exact) / n;
    state.counters["second_pass_pct"] = 100.0 * static_cast<double>(second) / n;
    state.counters["hit_pct"] = 100.0 * static_cast<double>(hits) / kLarge;
    state.SetLabel(batch::name(ran));
}

// batch::within_distance beside batch::intersects on the same set (see margin_pair above), one thread.
void margin_pair(benchmark::State& state, bool voxels) {
    const Large& l = large(voxels);
    std::vector<std::uint64_t> mask(batch::mask_words(kLarge));
    const double margin = 3.0 * (l.cylinder.radius + l.cylinder.height * 0.5) / 64;
    const batch::Options opt{1u, batch::Kernel::automatic};
    double plain_s = 0, margin_s = 0;
    std::size_t exact = 0;
    batch::Kernel ran = opt.kernel;
    bool margin_first = false;
    // Untimed, once each: the first pass over freshly generated arrays ran many times slower.
    batch::intersects(l.cylinder, l.soa.view(), std::span<std::uint64_t>(mask), opt);
    batch::within_distance(l.cylinder, l.soa.view(), margin, std::span<std::uint64_t>(mask), opt);
    for (auto _ : state) {
        for (int k = 0; k < 2; ++k) {
            const bool with_margin = (k == 0) == margin_first;
            const auto t0 = std::chrono::steady_clock::now();
            const batch::Stats st = with_margin ? batch::within_distance(l.cylinder, l.soa.view(), margin, std::span<std::uint64_t>(mask), opt)
                                                : batch::intersects(l.cylinder, l.soa.view(), std::span<std::uint64_t>(mask), opt);
            benchmark::DoNotOptimize(mask.data());
            (with_margin ? margin_s : plain_s) += seconds_since(t0);
            if (with_margin) exact += st.exact_lanes;
            ran = st.kernel;
        }
        margin_first = !margin_first;
    }
    const double n = static_cast<double>(state.iterations()) * kLarge;
    state.counters["plain_ns_per_box"] = plain_s * 1e9 / n;
    state.counters["margin_ns_per_box"] = margin_s * 1e9 / n;
    state.counters["ratio"] = margin_s / plain_s;
    state.counters["exact_pct"] = 100.0 * static_cast<double>(exact) / n;
    state.SetLabel(batch::name(ran));
}

// The scalar exact default on the first million boxes of the same 10M set, one thread: the goal
// "batch ≤ 1/4 of the scalar per box" on these data, against large_batch/.../threads_1's ns_per_box.
void large_scalar(benchmark::State& state, bool voxels) {
    const Large& l = large(voxels);
    constexpr std::size_t n = 1'000'000;
    for (auto _ : state)
        for (std::size_t i = 0; i < n; ++i) {
            const AlignedBox<double> b{{l.soa.v[0][i], l.soa.v[1][i], l.soa.v[2][i]}, {l.soa.v[3][i], l.soa.v[4][i], l.soa.v[5][i]}};
            benchmark::DoNotOptimize(boxcyl::intersects(b, l.cylinder));
        }
    report(state, n, 0);
}

// The memory bandwidth on the same arrays alone, timed by the benchmark library.
void stream_sum(benchmark::State& state, bool voxels, unsigned threads) {
    const Large& l = large(voxels);
    for (auto _ : state) benchmark::DoNotOptimize(stream_pass(l, threads));
    const double n = static_cast<double>(state.iterations()) * kLarge;
    state.counters["GB_per_s"] = benchmark::Counter(n * kBytesPerBox * 1e-9, benchmark::Counter::kIsRate);
}

}  // namespace

// Batch runs name their kernel: `automatic` (what a program linked with boxcyl::batch_dispatch gets:
// the widest this CPU runs, printed as the label) and `compiled` (the header's own, at this build's
// flags: 2 doubles on plain x86-64).
constexpr batch::Kernel kAuto = batch::Kernel::automatic, kPortable = batch::Kernel::compiled;
BENCHMARK_CAPTURE(scalar, mixed/aligned, false, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, mixed/aligned/automatic, false, Form::arrays, 1u, kAuto)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, mixed/aligned/compiled, false, Form::arrays, 1u, kPortable)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, mixed/aligned_rows/automatic, false, Form::rows, 1u, kAuto)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, mixed/aligned_rows/compiled, false, Form::rows, 1u, kPortable)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(scalar, mixed/oriented, false, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, mixed/oriented/automatic, false, Form::oriented, 1u, kAuto)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, mixed/oriented/compiled, false, Form::oriented, 1u, kPortable)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(scalar, regular/aligned, true, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, regular/aligned/automatic, true, Form::arrays, 1u, kAuto)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, regular/aligned/compiled, true, Form::arrays, 1u, kPortable)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, regular/aligned_rows/automatic, true, Form::rows, 1u, kAuto)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, regular/aligned_rows/compiled, true, Form::rows, 1u, kPortable)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(scalar, regular/oriented, true, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, regular/oriented/automatic, true, Form::oriented, 1u, kAuto)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(batched, regular/oriented/compiled, true, Form::oriented, 1u, kPortable)->Unit(benchmark::kMillisecond);
BENCHMARK(prepare)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(small_batch, mixed/aligned/n_8, std::size_t{8})->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(small_batch, mixed/aligned/n_64, std::size_t{64})->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(large_batch, voxels/threads_1/automatic, true, 1u, kAuto)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, voxels/threads_all/automatic, true, 0u, kAuto)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, voxels/threads_1/compiled, true, 1u, kPortable)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, voxels/threads_all/compiled, true, 0u, kPortable)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(stream_sum, voxels/threads_1, true, 1u)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(stream_sum, voxels/threads_all, true, 0u)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_scalar, voxels/first_1M, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(large_scalar, random/first_1M, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(large_batch, random/threads_1/automatic, false, 1u, kAuto)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random/threads_all/automatic, false, 0u, kAuto)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random/threads_1/compiled, false, 1u, kPortable)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random/threads_all/compiled, false, 0u, kPortable)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random_rows/threads_1/automatic, false, 1u, kAuto, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random_rows/threads_all/automatic, false, 0u, kAuto, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random_rows/threads_1/compiled, false, 1u, kPortable, true)->Unit(benchmark::kMillisecond)->UseRealTime();

// The clearance form beside the runs above (same sets, same kernel): a margin of three voxel sides.
BENCHMARK_CAPTURE(large_batch, voxels/margin_3_voxels/threads_1/automatic, true, 1u, kAuto, false, 3.0)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, voxels/margin_3_voxels/threads_all/automatic, true, 0u, kAuto, false, 3.0)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random/margin_3_voxels/threads_1/automatic, false, 1u, kAuto, false, 3.0)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(large_batch, random/margin_3_voxels/threads_all/automatic, false, 0u, kAuto, false, 3.0)
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(margin_pair, voxels, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(margin_pair, random, false)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
