// The clearance query, boxcyl::within_distance, beside intersects() on the same pairs. Sets (fixed
// seeds, built before any timing, from the tests' generator support/cases.hpp, mixed profile):
//   random:     4096 pairs at a margin of U(0, 1)·(r + h)
//   at_margin:  256 pairs at their flip margin (the least double the query answers "within" for) and
//               the double below it: the distance lies between, so every query is within one ulp of
//               its margin (found by bisection with the query itself, before timing)
// Benchmarks: within_distance on each set; the exact default intersects() on the random pairs (the
// margin's cost over the plain question); plain double §4 ({inequalities, float64}) intersects() on
// the at-margin pairs (a rounded query's cost on the same shapes).
// Counter ns_per_query: time per query in nanoseconds (Google Benchmark prints it with a unit
// suffix read as a plain number: "1.5k" is 1,500 ns).
// Run: bench_clearance --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>    // std::nextafter
#include <cstdint>  // seeds, bit patterns
#include <random>   // margins
#include <vector>   // the sets

#include "boxcyl/clearance.hpp"
#include "support/cases.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::CaseGenerator;
using boxcyl::testing::with_box;

struct Query {
    Case c;
    double margin;
};

bool within(const Query& q) {
    return with_box(q.c, [&](const auto& box, const Cylinder<double>& cyl) { return within_distance(box, cyl, q.margin); });
}

double flip_margin(const Case& c) {
    auto answered = [&](double m) { return within({c, m}); };
    if (answered(0.0)) return 0.0;
    double hi = 1.0;
    while (!answered(hi)) hi *= 4;
    std::int64_t lo = 0, up = boxcyl::testing::ordered_bits(hi);
    while (up - lo > 1) {
        const std::int64_t mid = lo + (up - lo) / 2;
        (answered(boxcyl::testing::from_ordered_bits(mid)) ? up : lo) = mid;
    }
    return boxcyl::testing::from_ordered_bits(up);
}

const std::vector<Query>& random_set() {
    static const std::vector<Query> s = [] {
        std::vector<Query> r;
        CaseGenerator gen(0xc1ea5001);
        std::mt19937_64 rng(0xc1ea5001);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int i = 0; i < 4096; ++i) {
            const Case c = gen.next();
            r.push_back({c, unit(rng) * (c.cylinder.radius + c.cylinder.height)});
        }
        return r;
    }();
    return s;
}

const std::vector<Query>& at_margin_set() {
    static const std::vector<Query> s = [] {
        std::vector<Query> r;
        CaseGenerator gen(0xc1ea5002);
        while (r.size() < 512) {
            const Case c = gen.next();
            const double m = flip_margin(c);
            if (m == 0.0) continue;
            r.push_back({c, m});
            r.push_back({c, std::nextafter(m, 0.0)});
        }
        return r;
    }();
    return s;
}

template <class F>
void run(benchmark::State& state, const std::vector<Query>& set, F&& f) {
    std::size_t hits = 0;
    for (auto _ : state)
        for (const Query& q : set) hits += f(q);
    benchmark::DoNotOptimize(hits);
    state.counters["ns_per_query"] = benchmark::Counter(
        static_cast<double>(set.size()) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_within_random(benchmark::State& state) { run(state, random_set(), within); }
void BM_intersects_random(benchmark::State& state) {
    run(state, random_set(), [](const Query& q) {
        return with_box(q.c, [](const auto& box, const Cylinder<double>& cyl) { return intersects(box, cyl); });
    });
}
void BM_within_at_margin(benchmark::State& state) { run(state, at_margin_set(), within); }
void BM_float64_at_margin(benchmark::State& state) {
    run(state, at_margin_set(), [](const Query& q) {
        return with_box(q.c, [](const auto& box, const Cylinder<double>& cyl) {
            return intersects(box, cyl, QueryOptions{Algorithm::inequalities, Arithmetic::float64});
        });
    });
}

BENCHMARK(BM_within_random);
BENCHMARK(BM_intersects_random);
BENCHMARK(BM_within_at_margin);
BENCHMARK(BM_float64_at_margin);

}  // namespace

BENCHMARK_MAIN();
