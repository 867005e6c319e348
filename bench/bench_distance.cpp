// The certified distance, boxcyl::distance, beside the peers' distance queries on the same pairs. Sets
// (fixed seeds, built before any timing, from the tests' generator support/cases.hpp; separated pairs
// only, where every library's distance is defined the same way):
//   random:        2048 pairs of the mixed profile
//   near:          512 pairs one ulp from touching (the separated member of a boundary pair): distances
//                  far below the shapes
//   georeferenced: 1024 pairs of the georeferenced profile (coordinates of 1e5–1e7, shapes of 1e-3–10)
// Benchmarks: boxcyl::distance on each set, and the exact intersects() on the same pairs (the yes/no
// question's cost, for scale); batch::distance of the random set's oriented boxes against one
// cylinder over 1 and 2 threads (wall time). Built with -DBOXCYL_BENCH_PEERS=ON, also FCL's distance() (both solvers)
// and Bullet's two GJK distances (peers.hpp), timed in the same run.
// The table that follows the output: time per query and its ratio to boxcyl::distance's (the batch
// rows: to one thread's); for boxcyl
// the width of its enclosures (how many are one double wide; the widest); for each peer, how many of
// its distances fall outside boxcyl's proved enclosure, and by how much (relative to the distance:
// median and largest), and how many it gave no distance for.
// Counter ns_per_query: time per query in nanoseconds ("1.5k" is 1,500 ns).
// Run: bench_distance --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>  // std::sort, std::max
#include <bit>        // std::bit_cast: widths in doubles
#include <cmath>      // std::abs
#include <cstdint>    // seeds
#include <cstdio>     // the summary
#include <memory>     // the peers
#include <string>     // names
#include <vector>     // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/distance.hpp"
#include "summary.hpp"
#include "support/cases.hpp"
#ifdef BOXCYL_BENCH_PEERS
#include "peers.hpp"
#endif

namespace {

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::CaseGenerator;
using boxcyl::testing::Profile;
using boxcyl::testing::with_box;

Distance distance_of(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return distance(box, cyl); });
}
bool touching(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return intersects(box, cyl); });
}

std::vector<Case> separated(Profile p, std::uint64_t seed, std::size_t n) {
    std::vector<Case> r;
    CaseGenerator gen(seed, p);
    while (r.size() < n)
        if (Case c = gen.next(); !touching(c)) r.push_back(c);
    return r;
}
std::vector<Case> near_set() {
    std::vector<Case> r;
    CaseGenerator gen(0xd157a002);
    for (const Case& c : boxcyl::testing::boundary_pairs(gen, 512))
        if (r.size() < 512 && !touching(c)) r.push_back(c);
    return r;
}

struct Set {
    std::string name;
    std::vector<Case> cases;
    std::vector<Distance> answers;  // boxcyl::distance of each, computed once before timing
};
std::vector<Set>& sets() {
    static std::vector<Set> s = [] {
        std::vector<Set> v{{"random", separated(Profile::mixed, 0xd157a001, 2048), {}},
                           {"near", near_set(), {}},
                           {"georeferenced", separated(Profile::georeferenced, 0xd157a003, 1024), {}}};
        for (Set& set : v)
            for (const Case& c : set.cases) set.answers.push_back(distance_of(c));
        return v;
    }();
    return s;
}

using boxcyl::bench::set_ns_per_query;

// ---- the summary ----

struct Row {
    std::string set, name, label;
    std::size_t queries = 0;
    std::string quality;  // the accuracy columns, computed before timing
};
std::vector<Row> g_rows;

boxcyl::bench::TimingReporter g_reporter;

// boxcyl's own column: how wide its enclosures are, in doubles.
std::string widths(const Set& s) {
    std::size_t one = 0;
    std::uint64_t widest = 0;
    for (const Distance& d : s.answers) {
        const std::uint64_t w = std::bit_cast<std::uint64_t>(d.upper) - std::bit_cast<std::uint64_t>(d.lower);
        one += w <= 1;
        widest = std::max(widest, w);
    }
    char b[160];
    std::snprintf(b, sizeof b, "enclosures: %zu of %zu one double wide, the widest %llu doubles", one, s.answers.size(),
                  static_cast<unsigned long long>(widest));
    return b;
}

#ifdef BOXCYL_BENCH_PEERS
std::vector<std::unique_ptr<boxcyl::bench::PeerDistances>> g_peers;

// A peer's distances against boxcyl's enclosures: outside how often, and by how much relative to the
// distance (upper); distances it did not give.
std::string quality(const Set& s, const boxcyl::bench::PeerDistances& p) {
    std::size_t outside = 0, none = 0;
    std::vector<double> rel;
    for (std::size_t i = 0; i < s.cases.size(); ++i) {
        const std::optional<double> d = p.distance(i);
        if (!d) {
            ++none;
            continue;
        }
        const Distance& e = s.answers[i];
        const double off = *d < e.lower ? e.lower - *d : *d > e.upper ? *d - e.upper : 0.0;
        if (off > 0) ++outside;
        rel.push_back(off / e.upper);
    }
    std::sort(rel.begin(), rel.end());
    char b[200];
    std::snprintf(b, sizeof b, "outside: %zu of %zu (%.1f%%); relative error median %.2g, largest %.2g; no distance: %zu",
                  outside, s.cases.size(), 100.0 * static_cast<double>(outside) / static_cast<double>(s.cases.size()),
                  rel.empty() ? 0.0 : rel[rel.size() / 2], rel.empty() ? 0.0 : rel.back(), none);
    return b;
}
#endif

void print_summary() {
    std::printf("\n| set | query | time per query | ratio to boxcyl::distance | accuracy |\n| --- | --- | ---: | ---: | --- |\n");
    for (const Row& r : g_rows) {
        const double ns = g_reporter.median(r.name);
        if (ns < 0) continue;
        double base = -1;
        for (const Row& b : g_rows)
            if (b.set == r.set && (b.name.rfind("BM_distance_", 0) == 0 || b.name.find("threads:1") != std::string::npos))
                base = g_reporter.median(b.name);  // the batch rows: the ratio to one thread
        std::printf("| %s (%zu) | %s | %s | %.3g× | %s |\n", r.set.c_str(), r.queries, r.label.c_str(), boxcyl::bench::ns_text(ns).c_str(),
                    base > 0 ? ns / base : 0.0, r.quality.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    for (const Set& s : sets()) {
        const std::vector<Case>* cases = &s.cases;
        std::string name = "BM_distance_" + s.name;
        benchmark::RegisterBenchmark(name.c_str(), [cases](benchmark::State& state) {
            double sum = 0;
            for (auto _ : state)
                for (const Case& c : *cases) sum += distance_of(c).upper;
            benchmark::DoNotOptimize(sum);
            set_ns_per_query(state, cases->size());
        });
        g_rows.push_back({s.name, name, "boxcyl::distance (proved enclosure)", s.cases.size(), widths(s)});
        name = "BM_intersects_" + s.name;
        benchmark::RegisterBenchmark(name.c_str(), [cases](benchmark::State& state) {
            long hits = 0;
            for (auto _ : state)
                for (const Case& c : *cases) hits += touching(c);
            benchmark::DoNotOptimize(hits);
            set_ns_per_query(state, cases->size());
        });
        g_rows.push_back({s.name, name, "boxcyl intersects(), exact (yes/no only)", s.cases.size(), "—"});
#ifdef BOXCYL_BENCH_PEERS
        for (const boxcyl::bench::ClearancePeerInfo& info : boxcyl::bench::kClearancePeers) {
            g_peers.push_back(std::make_unique<boxcyl::bench::PeerDistances>(info.peer, s.cases));
            const boxcyl::bench::PeerDistances* p = g_peers.back().get();
            const std::size_t n = s.cases.size();
            name = std::string("BM_") + info.key + "_" + s.name;
            benchmark::RegisterBenchmark(name.c_str(), [p, n](benchmark::State& state) {
                double sum = 0;
                for (auto _ : state) sum += p->pass(n);
                benchmark::DoNotOptimize(sum);
                set_ns_per_query(state, n);
            });
            std::string label = info.label;
            label = label.substr(0, label.find(" ≤ m"));  // "FCL distance() ≤ m, solver …" → the distance call
            g_rows.push_back({s.name, name, label + (info.peer == boxcyl::bench::ClearancePeer::fcl_libccd ? ", GST_LIBCCD"
                                                     : info.peer == boxcyl::bench::ClearancePeer::fcl_indep ? ", GST_INDEP" : ""),
                              n, quality(s, *p)});
        }
#endif
    }
    // The batch form on the random set's boxes (their own cylinders differ: one cylinder, the first
    // case's, for all), over 1 and 2 threads: how it scales.
    static std::vector<OrientedBox<double>> batch_boxes;
    static Cylinder<double> batch_cylinder = sets()[0].cases[0].cylinder;
    for (const Case& c : sets()[0].cases)
        if (c.kind == boxcyl::testing::BoxKind::oriented) batch_boxes.push_back(c.oriented);
    for (const unsigned threads : {1u, 2u}) {
        const std::string name = "BM_batch_distance_random/threads:" + std::to_string(threads);
        benchmark::RegisterBenchmark(name.c_str(), [threads](benchmark::State& state) {
            std::vector<Distance> out(batch_boxes.size());
            for (auto _ : state)
                batch::distance(batch_cylinder, std::span<const OrientedBox<double>>(batch_boxes), std::span<Distance>(out),
                                batch::Options{threads});
            benchmark::DoNotOptimize(out.data());
            set_ns_per_query(state, batch_boxes.size());
        })->UseRealTime();
        g_rows.push_back({"batch", name + "/real_time", "boxcyl batch::distance, oriented boxes, " + std::to_string(threads) + " thread(s), wall time",
                          batch_boxes.size(), "—"});
    }
    benchmark::RunSpecifiedBenchmarks(&g_reporter);
    benchmark::Shutdown();
    print_summary();
    return 0;
}
