// The clearance query, boxcyl::within_distance, beside intersects() on the same pairs. Sets (fixed
// seeds, built before any timing, from the tests' generator support/cases.hpp, mixed profile):
//   random:     4096 pairs at a margin of U(0, 1)·(r + h)
//   at_margin:  256 pairs at their flip margin (the least double the query answers "within" for) and
//               the double below it: the distance lies between, so every query is within one ulp of
//               its margin (found by bisection with the query itself, before timing)
// Benchmarks: within_distance on each set; the exact default intersects() on the random pairs (the
// margin's cost over the plain question); plain double §4 ({inequalities, float64}) intersects() on
// the at-margin pairs (a rounded query's cost on the same shapes).
// Built with -DBOXCYL_BENCH_PEERS=ON, also the peer libraries' answers to the same question on both
// sets (peers.hpp: FCL's and Bullet's distance ≤ m), checked against within_distance once before any
// timing (counter wrong: the answers that differ) and timed in the same run.
// Counter ns_per_query: time per query in nanoseconds (Google Benchmark prints it with a unit
// suffix read as a plain number: "1.5k" is 1,500 ns). A table from the same run follows the output:
// time per query, its ratio to within_distance's on the same set, and the wrong answers (also among the
// small queries, every length below 0.01, where the peers' absolute tolerances of about 1e-6 are not small),
// then the share of each set's queries each stage of within_distance's table answers.
// Run: bench_clearance --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>  // std::sort
#include <cmath>      // std::nextafter
#include <cstdint>    // seeds, bit patterns
#include <cstdio>     // the summary: std::printf, std::snprintf
#include <memory>     // the peers' queries
#include <random>     // margins
#include <string>     // names
#include <vector>     // the sets

#include "boxcyl/clearance.hpp"
#include "summary.hpp"
#include "support/cases.hpp"
#ifdef BOXCYL_BENCH_PEERS
#include "peers.hpp"
#endif

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

using boxcyl::bench::set_ns_per_query;

template <class F>
void run(benchmark::State& state, const std::vector<Query>& set, F&& f) {
    std::size_t hits = 0;
    for (auto _ : state)
        for (const Query& q : set) hits += f(q);
    benchmark::DoNotOptimize(hits);
    set_ns_per_query(state, set.size());
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

// ---- the summary: per set, each benchmark's time per query beside within_distance's ----

struct Row {
    std::string set, name, label;
    long wrong = -1, false_pos = 0, false_neg = 0;  // against within_distance; -1: not the same question
    long small = 0, small_wrong = 0;  // queries below bench::kSmallSize, and the wrong answers among them
    std::size_t queries = 0;
};
std::vector<Row> g_rows;

Row& add_row(std::string set, std::string name, std::string label, std::size_t queries) {
    g_rows.push_back(Row{std::move(set), std::move(name), std::move(label), -1, 0, 0, 0, 0, queries});
    return g_rows.back();
}

#ifdef BOXCYL_BENCH_PEERS
std::vector<std::unique_ptr<boxcyl::bench::PeerQueries>> g_peer_queries;

// Each peer on `set`: converted and compared with within_distance once, untimed, then registered to be
// timed as within_distance is (one pass answers every query in order).
void add_peers(const std::string& set_name, const std::vector<Query>& set) {
    std::vector<Case> cases;
    std::vector<double> margins;
    std::vector<char> want;
    for (const Query& q : set) {
        cases.push_back(q.c);
        margins.push_back(q.margin);
        want.push_back(within(q));
    }
    for (const boxcyl::bench::ClearancePeerInfo& info : boxcyl::bench::kClearancePeers) {
        g_peer_queries.push_back(std::make_unique<boxcyl::bench::PeerQueries>(info.peer, cases, margins));
        const boxcyl::bench::PeerQueries* q = g_peer_queries.back().get();
        const std::string name = std::string("BM_") + info.key + "_" + set_name;
        Row& r = add_row(set_name, name, info.label, set.size());
        r.wrong = 0;
        for (std::size_t i = 0; i < set.size(); ++i) {
            const bool got = q->answer(i), small = boxcyl::bench::query_size(cases[i]) < boxcyl::bench::kSmallSize;
            r.small += small;
            if (got == bool(want[i])) continue;
            ++r.wrong;
            ++(got ? r.false_pos : r.false_neg);
            r.small_wrong += small;
        }
        const std::size_t n = set.size();
        const double wrong = static_cast<double>(r.wrong);
        benchmark::RegisterBenchmark(name.c_str(), [q, n, wrong](benchmark::State& state) {
            long hits = 0;
            for (auto _ : state) hits += q->pass(n);
            benchmark::DoNotOptimize(hits);
            set_ns_per_query(state, n);
            state.counters["wrong"] = wrong;
        });
    }
}
#endif

boxcyl::bench::TimingReporter g_reporter;

void print_summary() {
    std::printf("\n| set | query | time per query | ratio to within_distance | wrong vs within_distance "
                "(false yes, false no) | wrong among the small queries |\n| --- | --- | ---: | ---: | ---: | ---: |\n");
    for (const Row& r : g_rows) {
        const double ns = g_reporter.median(r.name);
        if (ns < 0) continue;
        double base = -1;
        for (const Row& b : g_rows)
            if (b.set == r.set && b.name.rfind("BM_within_", 0) == 0) base = g_reporter.median(b.name);
        std::printf("| %s (%zu) | %s | %s | ", r.set.c_str(), r.queries, r.label.c_str(), boxcyl::bench::ns_text(ns).c_str());
        if (base > 0) std::printf("%.3g× | ", ns / base);
        else std::printf("— | ");
        if (r.wrong < 0) std::printf("— | — |\n");
        else
            std::printf("%ld (%.2f%%; %ld, %ld) | %ld / %ld |\n", r.wrong,
                        100.0 * static_cast<double>(r.wrong) / static_cast<double>(r.queries), r.false_pos, r.false_neg,
                        r.small_wrong, r.small);
    }
}

}  // namespace

// Which stage of the query's table answers, per set: counted once, untimed.
void print_stage_shares(const char* set_name, const std::vector<Query>& set) {
    constexpr auto& names = detail::clearance::stage_names;
    std::vector<long> count(names.size() + 1);
    for (const Query& q : set) {
        if (q.margin == 0) continue;  // intersects() itself
        ++count[with_box(q.c, [&](const auto& box, const Cylinder<double>& cyl) {
            return detail::clearance::answering_stage(box, cyl, q.margin);
        })];
    }
    std::printf("stages answering the %s set (%zu queries):", set_name, set.size());
    for (std::size_t i = 0; i < names.size(); ++i)
        std::printf(" %s %.1f%%%s", names[i], 100.0 * static_cast<double>(count[i]) / static_cast<double>(set.size()),
                    i + 1 < names.size() ? "," : "\n");
}

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    // Both sets before any timing (the at-margin set's bisections take a while).
    const std::vector<Query>& rs = random_set();
    const std::vector<Query>& as = at_margin_set();
    benchmark::RegisterBenchmark("BM_within_random", BM_within_random);
    add_row("random", "BM_within_random", "boxcyl within_distance (exact)", rs.size());
    benchmark::RegisterBenchmark("BM_intersects_random", BM_intersects_random);
    add_row("random", "BM_intersects_random", "boxcyl intersects(), exact default (margin ignored)", rs.size());
    benchmark::RegisterBenchmark("BM_within_at_margin", BM_within_at_margin);
    add_row("at_margin", "BM_within_at_margin", "boxcyl within_distance (exact)", as.size());
    benchmark::RegisterBenchmark("BM_float64_at_margin", BM_float64_at_margin);
    add_row("at_margin", "BM_float64_at_margin", "boxcyl intersects(), plain double §4 (margin ignored)", as.size());
#ifdef BOXCYL_BENCH_PEERS
    add_peers("random", rs);
    add_peers("at_margin", as);
#endif
    benchmark::RunSpecifiedBenchmarks(&g_reporter);
    benchmark::Shutdown();
    print_summary();
    print_stage_shares("random", rs);
    print_stage_shares("at_margin", as);
    return 0;
}
