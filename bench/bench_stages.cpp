// Where the default query's time goes, stage by stage (docs/performance.md, *Analysis*): on
// bench_query's random set (the same 4096 queries, CaseGenerator seed 0xb0c5c701, all box kinds),
//   problem:           semi_static::problem() alone (the canonical problem, with the unit axis)
//   stage0/all:        stage 0 (problem and decision), on every query
//   stage0/tiny_axis:  the same on the queries whose axis has a component below 1e-200 (a third)
//   default:           boxcyl::intersects (the front door), on every query
//   default_on_left:   boxcyl::intersects on the queries stage 0 leaves undecided only
//   default_on_stage0 / _on_0b / _beyond_0b: the same on the queries stage 0 decides, on those stage 0b
//                      decides, and on those both leave (stage 1 and after): the mean's budget by stage
//   stage0/left:       stage 0 on the queries it leaves (what failing every test costs)
// Counters: ns_per_query (CPU time per query of the set timed; Google Benchmark prints it as seconds:
// "55.1s" is 55.1 ns), left_pct (the share of the set that stage 0 leaves), left and left_after_0b (how
// many queries of the set stage 0 leaves, and how many of those stage 0b leaves too) and, for the
// subsets, ns_per_random_query: what those queries add to the mean over the whole set. A subset is timed
// on its own, so its branches are more predictable than in the mixed set: the shares add up to a little
// less than default_query/default.
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
#include "support/stages.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::with_box;

constexpr std::uint64_t kRandomSeed = 0xb0c5c701;  // bench_query's random set
constexpr std::size_t kQueries = 4096;

struct Sets {
    std::vector<Case> all, left;  // left: the queries stage 0 does not decide
    std::vector<Case> stage0;     // the others: those stage 0 decides
    std::vector<Case> by_0b, beyond_0b;  // the queries of `left` that stage 0b decides, and the rest
    std::size_t left_0b = 0;      // beyond_0b.size()
    std::vector<Case> tiny;       // the queries whose axis has a non-zero component below 1e-200
};

const Sets& sets() {
    static const Sets s = [] {
        Sets r;
        boxcyl::testing::CaseGenerator gen(kRandomSeed);
        for (std::size_t i = 0; i < kQueries; ++i) r.all.push_back(gen.next());
        for (const Case& c : r.all)
            (with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return boxcyl::testing::stage0(b, cyl); })
                 ? r.stage0
                 : r.left)
                .push_back(c);
        for (const Case& c : r.left)
            (with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return boxcyl::testing::stage0b(b, cyl); })
                 ? r.by_0b
                 : r.beyond_0b)
                .push_back(c);
        r.left_0b = r.beyond_0b.size();
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

enum class Subset { all, tiny, left, stage0, by_0b, beyond_0b };
const std::vector<Case>& subset(Subset s) {
    switch (s) {
        case Subset::tiny: return sets().tiny;
        case Subset::left: return sets().left;
        case Subset::stage0: return sets().stage0;
        case Subset::by_0b: return sets().by_0b;
        case Subset::beyond_0b: return sets().beyond_0b;
        case Subset::all: break;
    }
    return sets().all;
}
// What a subset adds to the mean over the whole random set.
void share_counter(benchmark::State& state) {
    const double n = static_cast<double>(state.iterations()) * static_cast<double>(kQueries);
    state.counters["ns_per_random_query"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void stage0(benchmark::State& state, Subset which) {
    const std::vector<Case>& all = subset(which);
    for (auto _ : state) {
        long decided = 0;
        for (const Case& c : all)
            decided += with_box(c, [](const auto& b, const Cylinder<double>& cyl) {
                           return boxcyl::testing::stage0(b, cyl);
                       }).has_value();
        benchmark::DoNotOptimize(decided);
    }
    counters(state, all.size());
    if (which == Subset::left) share_counter(state);
}

void default_query(benchmark::State& state, Subset which) {
    const std::vector<Case>& set = subset(which);
    for (auto _ : state) {
        long hits = 0;
        for (const Case& c : set) hits += with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return intersects(b, cyl); });
        benchmark::DoNotOptimize(hits);
    }
    counters(state, set.size());
    if (which != Subset::all) share_counter(state);
}

}  // namespace

BENCHMARK(problem);
BENCHMARK_CAPTURE(stage0, all, Subset::all);
BENCHMARK_CAPTURE(stage0, tiny_axis, Subset::tiny);
BENCHMARK_CAPTURE(stage0, left, Subset::left);
BENCHMARK_CAPTURE(default_query, default, Subset::all);
BENCHMARK_CAPTURE(default_query, default_on_left, Subset::left);
BENCHMARK_CAPTURE(default_query, default_on_stage0, Subset::stage0);
BENCHMARK_CAPTURE(default_query, default_on_0b, Subset::by_0b);
BENCHMARK_CAPTURE(default_query, default_beyond_0b, Subset::beyond_0b);

BENCHMARK_MAIN();
