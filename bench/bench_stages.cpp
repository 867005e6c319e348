// Where the default query's time goes, stage by stage (docs/performance.md, *Analysis*): on
// bench_query's random set (the same 4096 queries, CaseGenerator seed 0xb0c5c701, all box kinds),
//   problem:           semi_static::problem() alone (the canonical problem, with the unit axis)
//   stage0/all:        semi_static::filter() (problem and decision), on every query
//   stage0/tiny_axis:  the same on the queries whose axis has a component below 1e-200 (a third)
//   default:           boxcyl::intersects (the front door), on every query
//   default_on_left:   boxcyl::intersects on the queries stage 0 leaves undecided only
// Counters: ns_per_query (CPU time per query of the set timed; Google Benchmark prints it as seconds:
// "55.1s" is 55.1 ns), left_pct (the share of the set that stage 0 leaves), left and left_after_0b (how
// many queries of the set stage 0 leaves, and how many of those stage 0b leaves too) and, for default_on_left,
// ns_per_random_query: what those queries add to the mean over the whole set.
//
// Each pass sums the answers and hands only the sum to DoNotOptimize (per query, it forced every
// std::optional answer through memory: stage 0 read 97 instead of 67 ns).
//
// Run: bench_stages --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>     // std::fabs
#include <cstdint>   // seeds
#include <optional>  // stage 0's answer
#include <vector>    // the set

#include "boxcyl/query.hpp"
#include "support/cases.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::with_box;

constexpr std::uint64_t kRandomSeed = 0xb0c5c701;  // bench_query's random set
constexpr std::size_t kQueries = 4096;

struct Sets {
    std::vector<Case> all, left;  // left: the queries stage 0 does not decide
    std::size_t left_0b = 0;      // of those, the queries stage 0b does not decide either
    std::vector<Case> tiny;       // the queries whose axis has a non-zero component below 1e-200
};

const Sets& sets() {
    static const Sets s = [] {
        Sets r;
        boxcyl::testing::CaseGenerator gen(kRandomSeed);
        for (std::size_t i = 0; i < kQueries; ++i) r.all.push_back(gen.next());
        for (const Case& c : r.all)
            if (!with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::semi_static::filter(b, cyl); }))
                r.left.push_back(c);
        for (const Case& c : r.left)
            r.left_0b += !with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::witness_search::decide(b, cyl); });
        for (const Case& c : r.all)
            for (int j = 0; j < 3; ++j)
                if (c.cylinder.axis[j] != 0 && std::fabs(c.cylinder.axis[j]) < 1e-200) {
                    r.tiny.push_back(c);
                    break;
                }
        return r;
    }();
    return s;
}

void counters(benchmark::State& state, std::size_t per_pass) {
    const double n = static_cast<double>(state.iterations()) * static_cast<double>(per_pass);
    state.counters["ns_per_query"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["left_pct"] = 100.0 * static_cast<double>(sets().left.size()) / static_cast<double>(kQueries);
    state.counters["left"] = static_cast<double>(sets().left.size());
    state.counters["left_after_0b"] = static_cast<double>(sets().left_0b);
}

void problem(benchmark::State& state) {
    const std::vector<Case>& all = sets().all;
    for (auto _ : state) {
        double sum = 0;
        for (const Case& c : all) {
            filtered::semi_static::Problem p;
            if (with_box(c, [&p](const auto& b, const Cylinder<double>& cyl) { return filtered::semi_static::problem(b, cyl, p); }))
                sum += p.d[0];
        }
        benchmark::DoNotOptimize(sum);
    }
    counters(state, all.size());
}

void stage0(benchmark::State& state, bool tiny_only) {
    const std::vector<Case>& all = tiny_only ? sets().tiny : sets().all;
    for (auto _ : state) {
        long decided = 0;
        for (const Case& c : all)
            decided += with_box(c, [](const auto& b, const Cylinder<double>& cyl) {
                           return filtered::semi_static::filter(b, cyl);
                       }).has_value();
        benchmark::DoNotOptimize(decided);
    }
    counters(state, all.size());
}

void default_query(benchmark::State& state, bool left_only) {
    const std::vector<Case>& set = left_only ? sets().left : sets().all;
    for (auto _ : state) {
        long hits = 0;
        for (const Case& c : set) hits += with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return intersects(b, cyl); });
        benchmark::DoNotOptimize(hits);
    }
    counters(state, set.size());
    if (left_only) {
        const double n = static_cast<double>(state.iterations()) * static_cast<double>(kQueries);
        state.counters["ns_per_random_query"] =
            benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    }
}

}  // namespace

BENCHMARK(problem);
BENCHMARK_CAPTURE(stage0, all, false);
BENCHMARK_CAPTURE(stage0, tiny_axis, true);
BENCHMARK_CAPTURE(default_query, default, false);
BENCHMARK_CAPTURE(default_query, default_on_left, true);

BENCHMARK_MAIN();
