// The certified distance, boxcyl::distance, beside the peers' distance queries on the same pairs, and
// the signed distance, boxcyl::signed_distance, beside the peers' penetration queries on overlapping
// pairs. Sets (fixed seeds, built before any timing, from the tests' generator support/cases.hpp):
// separated pairs, where every library's distance is defined the same way:
//   random:        2048 pairs of the mixed profile
//   near:          512 pairs one ulp from touching (the separated member of a boundary pair): distances
//                  far below the shapes
//   georeferenced: 1024 pairs of the georeferenced profile (coordinates of 1e5–1e7, shapes of 1e-3–10)
// and overlapping pairs, intersecting and more than 1e-3 of the shapes' largest length deep (signed
// distance upper < −1e-3·query_size, peers.hpp), so that every peer's penetration query is defined (the
// solids overlap, not merely touch; on the mixed profile's smallest shapes the depth may still be below
// the peers' absolute tolerances, FCL's 1e-6):
//   overlapping:        1024 pairs of the mixed profile
//   deep_georeferenced: 512 pairs of the georeferenced profile
// Benchmarks: boxcyl::distance on each separated set, boxcyl::signed_distance on each overlapping set,
// and the exact intersects() on the same pairs (the yes/no question's cost, for scale); batch::distance
// of the random set's oriented boxes against one cylinder over 1 and 2 threads (wall time). Built with
// -DBOXCYL_BENCH_PEERS=ON, also FCL's distance() (both solvers) and Bullet's two GJK distances on the
// separated sets, and FCL's signed distance (both solvers) and Bullet's btGjkPairDetector and
// btGjkEpaSolver2::SignedDistance on the overlapping sets (peers.hpp), timed in the same run; a peer's
// query that aborts the process (FCL's assertions, found untimed in a child process) is left out of its
// timing and counted as giving no distance.
// The table that follows the output: time per query and its ratio to boxcyl::distance's (the
// overlapping sets: to boxcyl::signed_distance's; the batch rows: to one thread's); for boxcyl the
// width of its enclosures (separated: how many are one double wide, the widest; overlapping: relative
// to the depth, median and widest); for each peer, how many of its (signed) distances fall outside
// boxcyl's proved enclosure, and by how much (relative to the distance or depth: median and largest),
// and how many it gave no distance for.
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
#include <utility>    // std::move
#include <vector>     // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/distance.hpp"
#include "boxcyl/signed_distance.hpp"
#include "peers.hpp"  // query_size(); the peers themselves only with BOXCYL_BENCH_PEERS
#include "summary.hpp"
#include "support/cases.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::CaseGenerator;
using boxcyl::testing::Profile;
using boxcyl::testing::with_box;

Distance distance_of(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return distance(box, cyl); });
}
SignedDistance signed_distance_of(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return signed_distance(box, cyl); });
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

struct OverlapSet {
    std::string name;
    std::vector<Case> cases;
    std::vector<SignedDistance> answers;  // boxcyl::signed_distance of each, computed once before timing
};
// n intersecting pairs deeper than 1e-3 of their shapes' largest length.
OverlapSet overlapping(std::string name, Profile p, std::uint64_t seed, std::size_t n) {
    OverlapSet r{std::move(name), {}, {}};
    CaseGenerator gen(seed, p);
    while (r.cases.size() < n) {
        const Case c = gen.next();
        if (!touching(c)) continue;
        if (const SignedDistance sd = signed_distance_of(c); sd.upper < -1e-3 * boxcyl::bench::query_size(c)) {
            r.cases.push_back(c);
            r.answers.push_back(sd);
        }
    }
    return r;
}
std::vector<OverlapSet>& overlap_sets() {
    static std::vector<OverlapSet> s{overlapping("overlapping", Profile::mixed, 0xd157a004, 1024),
                                     overlapping("deep_georeferenced", Profile::georeferenced, 0xd157a005, 512)};
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
// Overlapping: the enclosures' widths relative to the depth (|upper|, the shallowest it can be).
std::string widths(const OverlapSet& s) {
    std::vector<double> rel;
    for (const SignedDistance& d : s.answers) rel.push_back((d.upper - d.lower) / std::abs(d.upper));
    std::sort(rel.begin(), rel.end());
    char b[160];
    std::snprintf(b, sizeof b, "enclosures: width relative to the depth median %.2g, widest %.2g", rel[rel.size() / 2],
                  rel.back());
    return b;
}

#ifdef BOXCYL_BENCH_PEERS
std::vector<std::unique_ptr<boxcyl::bench::PeerDistances>> g_peers;

// A peer's (signed) distances against boxcyl's enclosures: outside how often, and by how much relative
// to the distance or depth (|upper|: the distance, or the shallowest depth); distances it did not give.
template <class S>
std::string quality(const S& s, const boxcyl::bench::PeerDistances& p) {
    std::size_t outside = 0, none = 0, failed = 0;
    std::vector<double> rel;
    for (std::size_t i = 0; i < s.cases.size(); ++i) {
        failed += p.failed(i);
        const std::optional<double> d = p.distance(i);
        if (!d) {
            ++none;
            continue;
        }
        const auto& e = s.answers[i];
        const double off = *d < e.lower ? e.lower - *d : *d > e.upper ? *d - e.upper : 0.0;
        if (off > 0) ++outside;
        rel.push_back(off / std::abs(e.upper));
    }
    std::sort(rel.begin(), rel.end());
    char b[260];
    std::snprintf(b, sizeof b, "outside: %zu of %zu (%.1f%%); relative error median %.2g, largest %.2g; no distance: %zu",
                  outside, s.cases.size(), 100.0 * static_cast<double>(outside) / static_cast<double>(s.cases.size()),
                  rel.empty() ? 0.0 : rel[rel.size() / 2], rel.empty() ? 0.0 : rel.back(), none);
    std::string text = b;
    if (failed > 0) text += ", of them " + std::to_string(failed) + " where the library aborts (not timed)";
    return text;
}
#endif

void print_summary() {
    std::printf("\n| set | query | time per query | ratio to boxcyl::distance (overlapping sets: signed_distance) | accuracy |\n"
                "| --- | --- | ---: | ---: | --- |\n");
    for (const Row& r : g_rows) {
        const double ns = g_reporter.median(r.name);
        if (ns < 0) continue;
        double base = -1;
        for (const Row& b : g_rows)
            if (b.set == r.set && (b.name.rfind("BM_distance_", 0) == 0 || b.name.rfind("BM_signed_distance_", 0) == 0 ||
                                   b.name.find("threads:1") != std::string::npos))
                base = g_reporter.median(b.name);  // the overlapping sets: to signed_distance; the batch rows: to one thread
        std::printf("| %s (%zu) | %s | %s | %.3g× | %s |\n", r.set.c_str(), r.queries, r.label.c_str(), boxcyl::bench::ns_text(ns).c_str(),
                    base > 0 ? ns / base : 0.0, r.quality.c_str());
    }
}

// The exact intersects() on a set's pairs: the yes/no question's cost, for scale.
void add_intersects_row(const std::string& set, const std::vector<Case>* cases) {
    const std::string name = "BM_intersects_" + set;
    benchmark::RegisterBenchmark(name.c_str(), [cases](benchmark::State& state) {
        long hits = 0;
        for (auto _ : state)
            for (const Case& c : *cases) hits += touching(c);
        benchmark::DoNotOptimize(hits);
        set_ns_per_query(state, cases->size());
    });
    g_rows.push_back({set, name, "boxcyl intersects(), exact (yes/no only)", cases->size(), "—"});
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
        add_intersects_row(s.name, cases);
#ifdef BOXCYL_BENCH_PEERS
        for (const boxcyl::bench::ClearancePeerInfo& info : boxcyl::bench::kClearancePeers) {
            if (!boxcyl::bench::has_distance(info.peer)) continue;
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
    for (const OverlapSet& s : overlap_sets()) {
        const std::vector<Case>* cases = &s.cases;
        std::string name = "BM_signed_distance_" + s.name;
        benchmark::RegisterBenchmark(name.c_str(), [cases](benchmark::State& state) {
            double sum = 0;
            for (auto _ : state)
                for (const Case& c : *cases) sum += signed_distance_of(c).upper;
            benchmark::DoNotOptimize(sum);
            set_ns_per_query(state, cases->size());
        });
        g_rows.push_back({s.name, name, "boxcyl::signed_distance (proved enclosure)", s.cases.size(), widths(s)});
        add_intersects_row(s.name, cases);
#ifdef BOXCYL_BENCH_PEERS
        for (const boxcyl::bench::SignedPeerInfo& info : boxcyl::bench::kSignedPeers) {
            g_peers.push_back(std::make_unique<boxcyl::bench::PeerDistances>(info.peer, s.cases));
            const boxcyl::bench::PeerDistances* p = g_peers.back().get();
            const std::size_t n = s.cases.size();
            std::size_t timed = n;  // the queries where the library aborts are left out
            for (std::size_t i = 0; i < n; ++i) timed -= p->failed(i);
            name = std::string("BM_") + info.key + "_" + s.name;
            benchmark::RegisterBenchmark(name.c_str(), [p, n, timed](benchmark::State& state) {
                double sum = 0;
                for (auto _ : state) sum += p->pass(n);
                benchmark::DoNotOptimize(sum);
                set_ns_per_query(state, timed);
            });
            g_rows.push_back({s.name, name, info.label, timed, quality(s, *p)});
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
