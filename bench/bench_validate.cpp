// What the precondition checks cost: validate() and is_valid() per box + cylinder pair on valid input
// (and validate() on invalid input, where it builds its message), and the default query
// boxcyl::intersects() on the same pairs. Built twice from this file: bench_validate as configured
// (-DNDEBUG in Release and RelWithDebInfo) and bench_validate_asserts with -UNDEBUG, where the query
// asserts its preconditions; bench/assert_ratio.sh runs both and prints the ratio.
//
// Method: 4096 random valid pairs per box kind (tests/support/cases.hpp, fixed seed), generated before
// any timing; each benchmark iteration handles the next pair of the array, cycling, so the reported
// time is per pair (per query).
//
// Usage: bench_validate [benchmark flags...], e.g. --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstddef>  // std::size_t
#include <cstdint>  // std::uint64_t
#include <limits>   // quiet_NaN
#include <type_traits>  // std::is_same_v
#include <vector>   // data sets

#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/query.hpp"
#include "support/cases.hpp"

#if defined(BOXCYL_BENCH_WANT_ASSERTS) && defined(NDEBUG)
#error "bench_validate_asserts must be compiled without NDEBUG (-UNDEBUG)"
#endif

namespace {

using namespace boxcyl;
using boxcyl::testing::BoxKind;
using boxcyl::testing::Case;

constexpr std::size_t kPairs = 4096;  // a power of two: the index wraps by a mask
constexpr std::uint64_t kSeed = 0xB0C5C705;

template <class Box>
struct Pair {
    Box box;
    Cylinder<double> cylinder;
};

struct Data {
    std::vector<Pair<AlignedBox<double>>> aligned;
    std::vector<Pair<OrientedBox<double>>> oriented;
    std::vector<Case> mixed;  // all three box kinds, as bench_query's random set
};

const Data& data() {
    static const Data d = [] {
        Data s;
        boxcyl::testing::CaseGenerator gen(kSeed);
        while (s.aligned.size() < kPairs || s.oriented.size() < kPairs || s.mixed.size() < kPairs) {
            const Case c = gen.next();
            if (s.mixed.size() < kPairs) s.mixed.push_back(c);
            if (c.kind == BoxKind::aligned && s.aligned.size() < kPairs) s.aligned.push_back({c.aligned, c.cylinder});
            if (c.kind == BoxKind::oriented && s.oriented.size() < kPairs) s.oriented.push_back({c.oriented, c.cylinder});
        }
        return s;
    }();
    return d;
}

template <class Box>
const std::vector<Pair<Box>>& pairs() {
    if constexpr (std::is_same_v<Box, AlignedBox<double>>)
        return data().aligned;
    else
        return data().oriented;
}

template <class Box>
void validate_pair(benchmark::State& state) {
    const auto& p = pairs<Box>();
    std::size_t i = 0, bad = 0;
    for (auto _ : state) {
        const auto& q = p[i++ & (kPairs - 1)];
        const bool ok = validate(q.box).ok() && validate(q.cylinder).ok();
        benchmark::DoNotOptimize(ok);
        bad += !ok;
    }
    if (bad != 0) state.SkipWithError("an input pair was invalid");
}

template <class Box>
void is_valid_pair(benchmark::State& state) {
    const auto& p = pairs<Box>();
    std::size_t i = 0, bad = 0;
    for (auto _ : state) {
        const auto& q = p[i++ & (kPairs - 1)];
        const bool ok = is_valid(q.box) && is_valid(q.cylinder);
        benchmark::DoNotOptimize(ok);
        bad += !ok;
    }
    if (bad != 0) state.SkipWithError("an input pair was invalid");
}

// The failure path, for scale: a NaN in the box's last field, the message built and returned.
void validate_invalid_aligned(benchmark::State& state) {
    std::vector<Pair<AlignedBox<double>>> p = pairs<AlignedBox<double>>();
    for (auto& q : p) q.box.max[2] = std::numeric_limits<double>::quiet_NaN();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& q = p[i++ & (kPairs - 1)];
        Validity v = validate(q.box);
        benchmark::DoNotOptimize(v);
    }
}

template <class Box>
void query_default(benchmark::State& state) {
    const auto& p = pairs<Box>();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& q = p[i++ & (kPairs - 1)];
        benchmark::DoNotOptimize(intersects(q.box, q.cylinder));
    }
}

void query_default_mixed(benchmark::State& state) {
    const auto& p = data().mixed;
    std::size_t i = 0;
    for (auto _ : state) {
        const Case& c = p[i++ & (kPairs - 1)];
        benchmark::DoNotOptimize(
            boxcyl::testing::with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return intersects(box, cyl); }));
    }
}

BENCHMARK(validate_pair<AlignedBox<double>>)->Name("validate_pair/aligned");
BENCHMARK(validate_pair<OrientedBox<double>>)->Name("validate_pair/oriented");
BENCHMARK(is_valid_pair<AlignedBox<double>>)->Name("is_valid_pair/aligned");
BENCHMARK(is_valid_pair<OrientedBox<double>>)->Name("is_valid_pair/oriented");
BENCHMARK(validate_invalid_aligned)->Name("validate_invalid/aligned");
BENCHMARK(query_default<AlignedBox<double>>)->Name("query_default/aligned");
BENCHMARK(query_default<OrientedBox<double>>)->Name("query_default/oriented");
BENCHMARK(query_default_mixed)->Name("query_default/mixed");

}  // namespace

int main(int argc, char** argv) {
#ifdef NDEBUG
    benchmark::AddCustomContext("asserts", "off (NDEBUG)");
#else
    benchmark::AddCustomContext("asserts", "on (no NDEBUG)");
#endif
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    data();  // generated before any timing
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
