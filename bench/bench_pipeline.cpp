// The default exact query against plain double §4 on eight sets, side by side in one run, and where
// its time goes by pipeline row (docs/performance.md; scripts/bench.sh runs it):
//   random       4096 mixed queries (CaseGenerator, seed 0xb0c5c701, bench_query's random set)
//   boundary     512 pairs one ulp apart with opposite exact answers (seed 0xb0c5c702)
//   touching     2048 exactly touching shapes and one-ulp neighbours (touching_case, seed 0xb0c5c705)
//   adversarial  2048 near-touching cases (adversarial_case, seed 0xb0c5c706)
//   voxels       the 21³ unit cells of [−10, 11]³ against a cylinder of radius 8 and height 16 centred on
//                a grid node, axis z: its side and caps touch cell faces exactly (per box: scalar
//                queries; the batch API and the grid query over the same cells, timed back to back)
//   degenerate   4096 random queries of CaseGenerator's degenerate profile (seed 0xb0c5c707: scales
//                2^±600, zero sizes, sizes 2^±40 apart), where stage 0 leaves many queries far from
//                touching to the later rows
//   uniform      4096 random queries of CaseGenerator's uniform profile (seed 0xb0c5c708: plain data,
//                no zero sizes or tiny components), and 512 one-ulp boundary pairs of it (seed
//                0xb0c5c709): a second generator's mix, for the ratios not to rest on one
//   geo_*        CaseGenerator's georeferenced profile (seeds 0xb0c5c70a, 0xb0c5c70b): shapes of 1e-3 to 10
//                at UTM-like coordinates, aligned and oriented boxes apart, and 256 one-ulp boundary pairs
//   magnitudes_* its magnitudes profile (seeds 0xb0c5c70c, 0xb0c5c70d): sizes of very different
//                magnitudes in one query (1e-3 beside 1e4, 1e-300 and subnormal sizes, axis components
//                hundreds of binary orders apart), likewise
// Columns per set: the default query (`intersects(box, cyl)`, which checks its inputs), the same
// unchecked (`intersects_unchecked`), and plain double §4 (`{Algorithm::inequalities,
// Arithmetic::float64}`). Per row of the pipeline (filtered/schedule.hpp): the queries it decides and its
// statistics, read from the library (filtered::Stats), and the default query's mean time on the queries
// each row decides, timed on their own without statistics.
//
// Usage: bench_pipeline [--markdown=FILE] [--quick] [benchmark flags...]
#include <benchmark/benchmark.h>

#include <algorithm>  // std::sort
#include <chrono>     // the paired voxel timing
#include <array>      // stage counts
#include <cstdint>    // seeds
#include <cstdio>     // std::printf
#include <map>        // results by name
#include <random>     // std::mt19937_64
#include <string>     // names
#include <tuple>      // the profiles
#include <vector>     // sets

#include "boxcyl/batch.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/grid.hpp"
#include "boxcyl/query.hpp"
#include "command_line.hpp"
#include "support/cases.hpp"
#include "support/near_touching.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::with_box;

// The methods timed: the default query (its front door checks the inputs), the same without the check,
// and plain double §4 (also checked).
enum class Method { default_query, unchecked, double_s4 };
constexpr const char* kMethodKey[] = {"default", "unchecked", "double_s4"};

template <Method M>
bool answer(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) {
        if constexpr (M == Method::default_query)
            return intersects(b, cyl);
        else if constexpr (M == Method::unchecked)
            return intersects_unchecked(b, cyl);
        else
            return intersects(b, cyl, {Algorithm::inequalities, Arithmetic::float64});
    });
}

// The row that decided a query, from the library's statistics of that one query.
filtered::RowId deciding_row(const Case& c, filtered::Stats& total) {
    filtered::Stats one;
    with_box(c, [&one](const auto& b, const Cylinder<double>& cyl) { return filtered::query(b, cyl, one).intersect; });
    total += one;
    for (std::size_t i = 0; i < filtered::row_count; ++i)
        if (one.rows[i].hits + one.rows[i].misses > 0) return static_cast<filtered::RowId>(i);
    return filtered::RowId::exact;
}

struct Set {
    std::string name, title;
    std::vector<Case> cases;
    std::array<std::vector<Case>, filtered::row_count> by_row;
    filtered::Stats stats;  // one pass of the default query with statistics
    long wrong_default = 0;
};

std::map<std::string, double> g_ns;  // median ns per query, by benchmark name

template <Method M>
void timed(benchmark::State& state, const std::vector<Case>* cases) {
    long hits = 0;
    for (auto _ : state) {
        for (const Case& c : *cases) hits += answer<M>(c);
        benchmark::DoNotOptimize(hits);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(cases->size()));
}

void add(const std::string& name, Method m, const std::vector<Case>* cases) {
    if (cases->empty()) return;
    switch (m) {
        case Method::default_query: benchmark::RegisterBenchmark(name.c_str(), timed<Method::default_query>, cases); break;
        case Method::unchecked: benchmark::RegisterBenchmark(name.c_str(), timed<Method::unchecked>, cases); break;
        case Method::double_s4: benchmark::RegisterBenchmark(name.c_str(), timed<Method::double_s4>, cases); break;
    }
}

// ---- the voxel workload: per-box cost through the three interfaces ----
constexpr int kLo = -10, kHi = 11;  // cells [i, i+1] for i in [kLo, kHi)
const Cylinder<double> kVoxelCylinder{{0, 0, 0}, {0, 0, 1}, 8, 16};
constexpr std::size_t kVoxelCells = std::size_t(kHi - kLo) * (kHi - kLo) * (kHi - kLo);

struct Voxels {
    std::vector<double> min_x, min_y, min_z, max_x, max_y, max_z;
    std::vector<Case> cases;
};
const Voxels& voxels() {
    static const Voxels v = [] {
        Voxels r;
        for (int i = kLo; i < kHi; ++i)
            for (int j = kLo; j < kHi; ++j)
                for (int k = kLo; k < kHi; ++k) {
                    r.min_x.push_back(i), r.min_y.push_back(j), r.min_z.push_back(k);
                    r.max_x.push_back(i + 1), r.max_y.push_back(j + 1), r.max_z.push_back(k + 1);
                    Case c;
                    c.aligned = {{double(i), double(j), double(k)}, {double(i + 1), double(j + 1), double(k + 1)}};
                    c.cylinder = kVoxelCylinder;
                    r.cases.push_back(c);
                }
        return r;
    }();
    return v;
}
// The batch API over every cell and the grid query over the same grid, paired: each iteration times
// both back to back, in alternating order, so that both see the same minute of a shared machine (their
// difference is a few per cent, less than this machine's speed moves between minutes). Counters
// batch_ns_per_cell and grid_ns_per_cell, from the total times.
void voxel_pair(benchmark::State& state) {
    const Voxels& v = voxels();
    std::vector<std::uint64_t> mask(batch::mask_words(kVoxelCells));
    const batch::AlignedBoxes<double> boxes{v.min_x, v.min_y, v.min_z, v.max_x, v.max_y, v.max_z};
    const Grid g{{double(kLo), double(kLo), double(kLo)}, {1, 1, 1}, {kHi - kLo, kHi - kLo, kHi - kLo}};
    double batch_s = 0, grid_s = 0;
    bool grid_first = false;
    for (auto _ : state) {
        for (int k = 0; k < 2; ++k) {
            const bool grid = (k == 0) == grid_first;
            const auto t0 = std::chrono::steady_clock::now();
            if (grid) {
                std::int64_t found = 0;
                for_each_cell(g, kVoxelCylinder, [&](std::int64_t, std::int64_t, std::int64_t) { ++found; });
                benchmark::DoNotOptimize(found);
            } else {
                batch::intersects(kVoxelCylinder, boxes, std::span<std::uint64_t>(mask), {1});
                benchmark::DoNotOptimize(mask.data());
            }
            (grid ? grid_s : batch_s) += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
        grid_first = !grid_first;
    }
    const double cells = static_cast<double>(state.iterations()) * static_cast<double>(kVoxelCells);
    state.counters["batch_ns_per_cell"] = batch_s * 1e9 / cells;
    state.counters["grid_ns_per_cell"] = grid_s * 1e9 / cells;
}

class Reporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            // The paired voxel run: its two counters, under the names of the two interfaces.
            for (const char* c : {"batch", "grid"}) {
                const auto it = r.counters.find(std::string(c) + "_ns_per_cell");
                if (it == r.counters.end() || r.error_occurred) continue;
                const std::string key = std::string("voxels/") + c;
                if (r.run_type == Run::RT_Iteration) reps_[key].push_back(it->second.value);
                else if (r.aggregate_name == "median") g_ns[key] = it->second.value;
            }
            const auto ips = r.counters.find("items_per_second");
            if (r.error_occurred || ips == r.counters.end() || !(ips->second.value > 0)) continue;
            const std::string name = r.run_name.str();
            if (r.run_type == Run::RT_Iteration) reps_[name].push_back(1e9 / ips->second.value);
            else if (r.aggregate_name == "median") g_ns[name] = 1e9 / ips->second.value;
        }
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        for (auto& [name, v] : reps_) {
            if (g_ns.count(name) || v.empty()) continue;
            std::sort(v.begin(), v.end());
            g_ns[name] = v[v.size() / 2];
        }
    }

private:
    std::map<std::string, std::vector<double>> reps_;
};

std::string fmt(const char* f, double x) {
    char b[64];
    std::snprintf(b, sizeof b, f, x);
    return b;
}
std::string ns_text(double ns) {
    if (!(ns >= 0)) return "—";
    if (ns >= 1e6) return fmt("%.2f ms", ns / 1e6);
    if (ns >= 1e4) return fmt("%.1f µs", ns / 1e3);
    if (ns >= 1e3) return fmt("%.2f µs", ns / 1e3);
    if (ns >= 100) return fmt("%.0f ns", ns);
    return fmt("%.1f ns", ns);
}
std::string ratio_text(double r) {
    if (!(r >= 0)) return "—";
    if (r >= 100) return fmt("%.0f×", r);
    if (r >= 10) return fmt("%.1f×", r);
    return fmt("%.2f×", r);
}
double ns(const std::string& name) {
    const auto it = g_ns.find(name);
    return it == g_ns.end() ? -1 : it->second;
}

// The benchmark of a set's queries that row k decides.
std::string row_key(const std::string& set, std::size_t k) {
    return set + "/row/" + std::string(filtered::name(static_cast<filtered::RowId>(k)));
}

void summary(std::FILE* out, const std::vector<Set>& sets) {
    std::fprintf(out, "\n**The sets** (time per query, median of the repetitions; ratios from this run)\n\n");
    std::fprintf(out, "| set | queries | default | unchecked | double §4 | default / double §4 | wrong (default vs oracle) |\n");
    std::fprintf(out, "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const Set& s : sets) {
        const double d = ns(s.name + "/default"), u = ns(s.name + "/unchecked"), b = ns(s.name + "/double_s4");
        std::fprintf(out, "| %s | %zu | %s | %s | %s | %s | %ld |\n", s.title.c_str(), s.cases.size(),
                     ns_text(d).c_str(), ns_text(u).c_str(), ns_text(b).c_str(), ratio_text(d / b).c_str(),
                     s.wrong_default);
    }
    std::fprintf(out, "\n**By deciding row** (the queries each row of the pipeline decides, and the default query's "
                      "mean time on them, timed on their own; their share of the set's total time)\n\n");
    std::fprintf(out, "| set | row | queries | share of queries | default, per query | share of time |\n");
    std::fprintf(out, "| --- | --- | ---: | ---: | ---: | ---: |\n");
    for (const Set& s : sets) {
        double total = 0;
        for (std::size_t k = 0; k < filtered::row_count; ++k) {
            const double t = ns(row_key(s.name, k));
            if (t > 0) total += t * double(s.by_row[k].size());
        }
        for (std::size_t k = 0; k < filtered::row_count; ++k) {
            const std::size_t n = s.by_row[k].size();
            if (n == 0) continue;
            const double t = ns(row_key(s.name, k));
            std::fprintf(out, "| %s | `%s` | %zu | %s | %s | %s |\n", s.name.c_str(),
                         std::string(filtered::name(static_cast<filtered::RowId>(k))).c_str(), n,
                         fmt("%.2f%%", 100.0 * double(n) / double(s.cases.size())).c_str(), ns_text(t).c_str(),
                         total > 0 && t > 0 ? fmt("%.1f%%", 100.0 * t * double(n) / total).c_str() : "—");
        }
    }
    std::fprintf(out, "\n**Per-row statistics from the library** (`filtered::Stats`, one pass over each set: how often "
                      "each row ran and decided, and the time in its certifier; the counted query reads a steady clock "
                      "around each row, so compare rows with each other, not with the timings above)\n");
    for (const Set& s : sets) std::fprintf(out, "\n%s:\n\n%s", s.name.c_str(), s.stats.table().c_str());
    std::fprintf(out, "\n**Voxels touching a cylinder** (%zu unit cells of [%d, %d]³, cylinder radius 8, height 16, centre on "
                      "the grid node 0, axis z; time per box, one thread)\n\n",
                 kVoxelCells, kLo, kHi);
    std::fprintf(out, "| interface | per box |\n| --- | ---: |\n");
    std::fprintf(out, "| scalar default query, every cell | %s |\n", ns_text(ns("voxels/default")).c_str());
    std::fprintf(out, "| scalar double §4 | %s |\n", ns_text(ns("voxels/double_s4")).c_str());
    std::fprintf(out, "| batch API (`batch::intersects`, aligned boxes; paired with the grid) | %s |\n", ns_text(ns("voxels/batch")).c_str());
    std::fprintf(out, "| grid query (`for_each_cell`, per cell of the grid; paired with the batch) | %s |\n", ns_text(ns("voxels/grid")).c_str());
    const double b = ns("voxels/batch"), gq = ns("voxels/grid");
    std::fprintf(out, "\nThe grid query per cell against the batch API over every cell, timed back to back in one benchmark: %s.\n",
                 b > 0 && gq > 0 ? ratio_text(gq / b).c_str() : "—");
}

}  // namespace

int main(int argc, char** argv) {
    std::string markdown;
    const bool ok = boxcyl::bench::initialize(argc, argv, [&](const std::string& a) {
        if (a.rfind("--markdown=", 0) != 0) return false;
        markdown = a.substr(11);
        return true;
    });
    if (!ok) return 1;

    std::fprintf(stderr, "generating the sets (the boundary pairs are found by bisection with the oracle: about a minute)...\n");
    std::vector<Set> sets(14);
    sets[0].name = "random", sets[0].title = "random (seed 0xb0c5c701)";
    sets[1].name = "boundary", sets[1].title = "one-ulp boundary pairs (seed 0xb0c5c702)";
    sets[2].name = "touching", sets[2].title = "exactly touching and one-ulp neighbours (seed 0xb0c5c705)";
    sets[3].name = "adversarial", sets[3].title = "adversarial near-touching mix (seed 0xb0c5c706)";
    sets[4].name = "voxels", sets[4].title = "voxels touching a cylinder (radius 8, unit cells)";
    sets[5].name = "degenerate", sets[5].title = "random, degenerate profile (seed 0xb0c5c707)";
    sets[6].name = "uniform", sets[6].title = "random, uniform profile (seed 0xb0c5c708)";
    sets[7].name = "uniform_boundary", sets[7].title = "one-ulp boundary pairs, uniform profile (seed 0xb0c5c709)";
    sets[8].name = "geo_aligned", sets[8].title = "geo-referenced, aligned boxes (seed 0xb0c5c70a)";
    sets[9].name = "geo_oriented", sets[9].title = "geo-referenced, oriented boxes (seed 0xb0c5c70a)";
    sets[10].name = "geo_boundary", sets[10].title = "one-ulp boundary pairs, geo-referenced (seed 0xb0c5c70b)";
    sets[11].name = "magnitudes_aligned", sets[11].title = "mixed magnitudes, aligned boxes (seed 0xb0c5c70c)";
    sets[12].name = "magnitudes_oriented", sets[12].title = "mixed magnitudes, oriented boxes (seed 0xb0c5c70c)";
    sets[13].name = "magnitudes_boundary", sets[13].title = "one-ulp boundary pairs, mixed magnitudes (seed 0xb0c5c70d)";
    {
        boxcyl::testing::CaseGenerator gen(0xb0c5c701);
        for (int i = 0; i < 4096; ++i) sets[0].cases.push_back(gen.next());
    }
    {
        boxcyl::testing::CaseGenerator gen(0xb0c5c702);
        sets[1].cases = boxcyl::testing::boundary_pairs(gen, 512);
    }
    {
        std::mt19937_64 rng(0xb0c5c705);
        for (int i = 0; i < 2048; ++i) sets[2].cases.push_back(boxcyl::testing::touching_case(rng));
    }
    {
        std::mt19937_64 rng(0xb0c5c706);
        for (int i = 0; i < 2048; ++i) sets[3].cases.push_back(boxcyl::testing::adversarial_case(rng));
    }
    sets[4].cases = voxels().cases;
    {
        boxcyl::testing::CaseGenerator gen(0xb0c5c707, boxcyl::testing::Profile::degenerate);
        for (int i = 0; i < 4096; ++i) sets[5].cases.push_back(gen.next());
    }
    {
        boxcyl::testing::CaseGenerator gen(0xb0c5c708, boxcyl::testing::Profile::uniform);
        for (int i = 0; i < 4096; ++i) sets[6].cases.push_back(gen.next());
    }
    {
        boxcyl::testing::CaseGenerator gen(0xb0c5c709, boxcyl::testing::Profile::uniform);
        sets[7].cases = boxcyl::testing::boundary_pairs(gen, 512);
    }
    // Coordinates as users have them: far from the origin, and sizes of very different magnitudes; 4096
    // random queries each, reported by box kind, and their one-ulp boundary pairs.
    for (const auto& [profile, seed, first] :
         {std::tuple{boxcyl::testing::Profile::georeferenced, 0xb0c5c70aULL, 8},
          std::tuple{boxcyl::testing::Profile::magnitudes, 0xb0c5c70cULL, 11}}) {
        boxcyl::testing::CaseGenerator gen(seed, profile);
        for (int i = 0; i < 4096; ++i) {
            const Case c = gen.next();
            sets[static_cast<std::size_t>(first + (c.kind == boxcyl::testing::BoxKind::oriented ? 1 : 0))].cases.push_back(c);
        }
        boxcyl::testing::CaseGenerator pairs(seed + 1, profile);
        sets[static_cast<std::size_t>(first + 2)].cases = boxcyl::testing::boundary_pairs(pairs, 256);
    }
    for (Set& s : sets) {
        for (const Case& c : s.cases) {
            s.by_row[static_cast<std::size_t>(deciding_row(c, s.stats))].push_back(c);
            s.wrong_default += answer<Method::default_query>(c) != boxcyl::testing::oracle_answer(c);
        }
    }

    for (const Set& s : sets) {
        for (int m = 0; m < 3; ++m) add(s.name + "/" + kMethodKey[m], Method(m), &s.cases);
        for (std::size_t k = 0; k < filtered::row_count; ++k)
            add(row_key(s.name, k), Method::default_query, &s.by_row[k]);
    }
    benchmark::RegisterBenchmark("voxels/pair", voxel_pair);

    Reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    summary(stdout, sets);
    if (!markdown.empty()) {
        std::FILE* f = std::fopen(markdown.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "cannot write %s\n", markdown.c_str());
            return 1;
        }
        summary(f, sets);
        std::fclose(f);
    }
    return 0;
}
