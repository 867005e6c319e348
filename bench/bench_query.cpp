// Time per query of boxcyl's default exact query and of each algorithm in each arithmetic,
// on random inputs and on one-ulp boundary inputs, with a summary from the same run: each query's
// time relative to the plain double linear-inequalities query on the same inputs, and the fraction of queries that needed the
// exact fallback. scripts/bench.sh runs it and writes docs/performance.md.
// Built with -DBOXCYL_BENCH_PEERS=ON, it also times the same queries through FCL, Bullet and ODE
// (peers.cpp), checks their answers against the oracle, and reports every time relative
// to the default exact query as well.
//
// Method: the inputs are generated once, before any timing, with fixed seeds (tests/support/cases.hpp).
// One timed pass answers every query of a pre-generated array in order (4096 random queries; 1024
// boundary queries, which are costly to find; the exact path and the oracle, ~10^3× slower, the first
// 256), so branch predictors cannot learn one case, and the time includes the front door's work
// (reduction to the canonical frame, conversions). Time per query = CPU time of a pass / queries in
// it, the median over repetitions (default 5). Answers are checked against the oracle, untimed.
//
// Usage: bench_query [--markdown=FILE] [--boundary-pairs=N] [--quick] [--no-checks] [benchmark flags...]
//   --markdown=FILE     also write the summary as Markdown (scripts/bench.sh puts it in docs/performance.md)
//   --boundary-pairs=N  size of the boundary set (default 512 pairs; each costs ~50 ms to find)
//   --quick             1 repetition, short minimum time: a smoke run, not a measurement
//   --no-checks         skip the oracle answers and the untimed checks: less set-up, for profiling, e.g.
//                       perf record bench_query --no-checks --boundary-pairs=1
//                                   --benchmark_filter=random_decided/default --benchmark_min_time=5
#include <benchmark/benchmark.h>

#include <algorithm>    // std::sort, std::min
#include <array>        // box frames
#include <cstdint>      // std::uint64_t
#include <cstdio>       // std::printf, std::snprintf, std::FILE
#include <exception>    // std::exception
#include <map>          // results by benchmark name
#include <memory>       // std::unique_ptr
#include <string>       // names, formatting
#include <type_traits>  // std::is_same_v
#include <vector>       // data sets

#include "boxcyl/filtered.hpp"
#include "boxcyl/query.hpp"
#include "command_line.hpp"
#include "support/cases.hpp"
#ifdef BOXCYL_BENCH_PEERS
#include "peers.hpp"
#endif

namespace {

using namespace boxcyl;
using boxcyl::testing::BoxKind;
using boxcyl::testing::Case;

constexpr std::size_t kQueries = 4096;      // queries per timed pass
constexpr std::size_t kSlowQueries = 256;   // exact path and oracle: the first 256 of the same array
constexpr std::size_t kBoundaryPairs = 512;  // boundary set: 1024 queries (each pair costs ~50 ms to find)
constexpr long kFractionSample = 100000;    // random queries over which the fallback rate is counted
constexpr std::uint64_t kRandomSeed = 0xB0C5C701;
constexpr std::uint64_t kBoundarySeed = 0xB0C5C702;
constexpr std::uint64_t kKindSeed = 0xB0C5C703;
constexpr std::uint64_t kFractionSeed = 0xB0C5C704;

enum class Method { default_query, double_s4, double_s3, double_s2, float_s4, exact_path, oracle };

struct MethodInfo {
    Method method;
    const char* key;    // benchmark name part
    const char* label;  // summary row
    bool slow;          // timed on the short prefix
};

constexpr MethodInfo kMethods[] = {
    {Method::default_query, "default", "default exact query (boxcyl::intersects)", false},
    {Method::double_s4, "double_s4", "§4 linear inequalities, double", false},
    {Method::double_s3, "double_s3", "§3 convex hull, double", false},
    {Method::double_s2, "double_s2", "§2 LCP, double", false},
    {Method::float_s4, "float_s4", "§4 linear inequalities, float", false},
    {Method::exact_path, "exact_path", "exact path alone (one fallback)", true},
    {Method::oracle, "oracle", "exact oracle", true},
};

// One query of method M; M is a template parameter so that each timed loop is specialised.
template <Method M, class Box>
bool query(const Box& box, const Cylinder<double>& cyl) {
    if constexpr (M == Method::default_query) {
        return intersects(box, cyl);  // the front door, as users call it (query.hpp → filtered.hpp)
    } else if constexpr (M == Method::double_s4) {
        return intersects(box, cyl, {Algorithm::inequalities, Arithmetic::float64});
    } else if constexpr (M == Method::double_s3) {
        return intersects(box, cyl, {Algorithm::hull, Arithmetic::float64});
    } else if constexpr (M == Method::double_s2) {
        return intersects(box, cyl, {Algorithm::lcp, Arithmetic::float64});
    } else if constexpr (M == Method::float_s4) {
        return intersects(box, cyl, {Algorithm::inequalities, Arithmetic::float32});
    } else if constexpr (M == Method::exact_path) {
        // What one exact answer costs in rationals and Q(√d): exact linear inequalities
        // where the canonical frame is exact (aligned and canonical boxes, signed-permutation frames),
        // the exact convex-hull method on any other oriented box.
        Algorithm a = Algorithm::inequalities;
        if constexpr (std::is_same_v<Box, OrientedBox<double>>)
            if (!signed_permutation(box.axes)) a = Algorithm::hull;  // geometry/box.hpp
        return intersects(box, cyl, {a, Arithmetic::exact});
    } else {
        return oracle::intersects(box, cyl);
    }
}

template <Method M>
bool answer_or_throw(const Case& c) {
    switch (c.kind) {
        case BoxKind::aligned: return query<M>(c.aligned, c.cylinder);
        case BoxKind::oriented: return query<M>(c.oriented, c.cylinder);
        case BoxKind::canonical: return query<M>(c.canonical, c.cylinder);
    }
    return false;
}

// The LCP method in double falls back to exact LCP when its solver fails, and exact LCP throws
// std::domain_error on an oriented box whose axes are not exactly orthonormal: such queries count as
// errors (answer false) rather than end the run.
template <Method M>
bool answer(const Case& c) {
    if constexpr (M == Method::double_s2) {
        try {
            return answer_or_throw<M>(c);
        } catch (const std::exception&) {
            return false;
        }
    } else {
        return answer_or_throw<M>(c);
    }
}

bool needs_exact(const Case& c) {
    switch (c.kind) {
        case BoxKind::aligned: return filtered::query(c.aligned, c.cylinder).exact_used;
        case BoxKind::oriented: return filtered::query(c.oriented, c.cylinder).exact_used;
        case BoxKind::canonical: return filtered::query(c.canonical, c.cylinder).exact_used;
    }
    return false;
}

std::string hex_seed(std::uint64_t seed) {
    char b[32];
    std::snprintf(b, sizeof b, "%#llx", static_cast<unsigned long long>(seed));
    return b;
}

struct DataSet {
    std::string name;           // in benchmark names
    std::string title;          // in the summary
    std::vector<Case> cases;
    std::vector<char> want;     // the oracle's answers (empty: not computed)
    std::vector<char> exact;    // whether the default query needs its exact fallback
    double exact_fraction = 0;  // of the default query, over `cases`
};

DataSet make_random(std::string name, std::string title, std::uint64_t seed, int kind = -1) {
    DataSet s{std::move(name), std::move(title), {}, {}, {}, 0};
    boxcyl::testing::CaseGenerator gen(seed);
    while (s.cases.size() < kQueries) {
        const Case c = gen.next();
        if (kind < 0 || static_cast<int>(c.kind) == kind) s.cases.push_back(c);
    }
    return s;
}

// Each pair costs one bisection with the oracle (~60 oracle calls, ~50 ms), hence fewer than kQueries.
DataSet make_boundary(std::uint64_t seed, std::size_t pairs) {
    DataSet s{"boundary", "", {}, {}, {}, 0};
    s.title = "boundary: " + std::to_string(pairs) + " pairs of inputs one ulp apart with opposite exact answers (seed " +
              hex_seed(seed) + ")";
    boxcyl::testing::CaseGenerator gen(seed);
    while (s.cases.size() < 2 * pairs) {
        Case a, b;
        boxcyl::testing::Parameter p;
        if (!boxcyl::testing::boundary_pair(gen, a, b, p)) continue;
        s.cases.push_back(a);
        s.cases.push_back(b);
    }
    return s;
}

void annotate(DataSet& s, bool with_oracle) {
    long exact = 0;
    for (const Case& c : s.cases) {
        if (with_oracle) s.want.push_back(static_cast<char>(boxcyl::testing::oracle_answer(c)));
        s.exact.push_back(static_cast<char>(needs_exact(c)));
        exact += s.exact.back();
    }
    s.exact_fraction = static_cast<double>(exact) / static_cast<double>(s.cases.size());
}

// The queries of `s` that the filter decides alone: the default query's cost without fallbacks.
DataSet filter_decided(const DataSet& s) {
    DataSet d{s.name + "_decided", "", {}, {}, {}, 0};
    for (std::size_t i = 0; i < s.cases.size(); ++i) {
        if (s.exact[i]) continue;
        d.cases.push_back(s.cases[i]);
        d.exact.push_back(0);
        if (!s.want.empty()) d.want.push_back(s.want[i]);
    }
    d.title = s.name + ", the " + std::to_string(d.cases.size()) + " decided by the filter";
    return d;
}

struct Check {
    long wrong = -1;                 // answers that differ from the oracle's (-1: not checked)
    long errors = 0;                 // queries that threw (a peer: that failed)
    const char* error_verb = "threw";
};

// One untimed pass: compares with the oracle where its answers are known, counts and reports throws.
template <Method M>
Check check(const DataSet& s, std::size_t n, const char* key) {
    Check r;
    if (!s.want.empty()) r.wrong = 0;
    for (std::size_t i = 0; i < n; ++i) {
        try {
            const bool got = answer_or_throw<M>(s.cases[i]);
            if (!s.want.empty()) r.wrong += got != bool(s.want[i]);
        } catch (const std::exception& e) {
            if (r.errors++ == 0)
                std::fprintf(stderr, "%s/%s: query %zu threw: %s\n  %s\n", s.name.c_str(), key, i, e.what(),
                             boxcyl::testing::describe(s.cases[i]).c_str());
            if (!s.want.empty()) r.wrong += bool(s.want[i]);  // the timed loop answers false
        }
    }
    return r;
}

// ---- registry of what was registered, for the summary ----

// A peer library's disagreements with the oracle, split.
struct PeerDetail {
    bool present = false;
    long false_pos = 0, false_neg = 0;
    long small = 0, small_wrong = 0;  // queries below bench::kSmallSize, and the wrong answers among them
};

struct Entry {
    std::string set, method_key, label;
    std::size_t queries = 0;
    Check check;
    double exact_fraction = -1;  // only for the default query
    // Filled by the reporter:
    double ns_median = -1, cv = -1;
    std::vector<double> ns_reps;  // per-repetition times, when no median aggregate is reported
    PeerDetail peer{};            // only for a peer library
};
std::vector<Entry> g_entries;
bool g_checks = true;  // --no-checks: no oracle answers, no untimed check passes (for profiling)
std::map<std::string, std::size_t> g_by_name;

template <Method M>
void timed_pass(benchmark::State& state, const DataSet* s, std::size_t n) {
    long hits = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i) hits += answer<M>(s->cases[i]);
        benchmark::DoNotOptimize(hits);
        benchmark::ClobberMemory();  // the cases are re-read on every pass
    }
    state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(n));
}

template <Method M>
void add(const DataSet& s, const MethodInfo& info) {
    const std::size_t n = info.slow ? std::min(kSlowQueries, s.cases.size()) : s.cases.size();
    Entry e{s.name, info.key, info.label, n, g_checks ? check<M>(s, n, info.key) : Check{}, -1, -1, -1, {}};
    const std::string name = s.name + "/" + info.key;
    if (M == Method::default_query) e.exact_fraction = s.exact_fraction;
    g_by_name[name] = g_entries.size();
    g_entries.push_back(e);
    benchmark::RegisterBenchmark(name.c_str(), [&s, n](benchmark::State& st) { timed_pass<M>(st, &s, n); });
}

void add_method(const DataSet& s, Method m) {
    for (const MethodInfo& info : kMethods) {
        if (info.method != m) continue;
        switch (m) {
            case Method::default_query: add<Method::default_query>(s, info); break;
            case Method::double_s4: add<Method::double_s4>(s, info); break;
            case Method::double_s3: add<Method::double_s3>(s, info); break;
            case Method::double_s2: add<Method::double_s2>(s, info); break;
            case Method::float_s4: add<Method::float_s4>(s, info); break;
            case Method::exact_path: add<Method::exact_path>(s, info); break;
            case Method::oracle: add<Method::oracle>(s, info); break;
        }
    }
}

#ifdef BOXCYL_BENCH_PEERS
using bench::kSmallSize;
using bench::query_size;

// The peers' queries, converted once per data set; the registered benchmarks point into them.
std::vector<std::unique_ptr<bench::PeerQueries>> g_peer_queries;

// One peer library on the whole of `s`: converted and checked against the oracle untimed, then timed
// as boxcyl's queries are (one pass answers every query in order).
void add_peer(const DataSet& s, const bench::PeerInfo& info) {
    g_peer_queries.push_back(std::make_unique<bench::PeerQueries>(info.peer, s.cases));
    const bench::PeerQueries* q = g_peer_queries.back().get();
    const std::size_t n = s.cases.size();
    Check c;
    c.error_verb = "failed, not timed";
    std::size_t timed = n;
    for (std::size_t i = 0; i < n; ++i)
        if (q->failed(i)) ++c.errors, --timed;
    PeerDetail d;
    d.present = true;
    if (!s.want.empty()) {
        c.wrong = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const bool got = q->answer(i), want = s.want[i], small = query_size(s.cases[i]) < kSmallSize;
            d.small += small;
            if (got == want) continue;
            ++c.wrong;
            ++(got ? d.false_pos : d.false_neg);
            d.small_wrong += small;
        }
    }
    const std::string name = s.name + "/" + info.key;
    g_by_name[name] = g_entries.size();
    g_entries.push_back(Entry{s.name, info.key, info.label, n, c, -1, -1, -1, {}, d});
    benchmark::RegisterBenchmark(name.c_str(), [q, n, timed](benchmark::State& st) {
        long hits = 0;
        for (auto _ : st) {
            hits += q->pass(n);
            benchmark::DoNotOptimize(hits);
            benchmark::ClobberMemory();
        }
        st.SetItemsProcessed(st.iterations() * static_cast<benchmark::IterationCount>(timed));
    });
}
#endif

// ---- the summary: the console output as usual, then per data set the table from the same run ----

double median(std::vector<double> v) {
    if (v.empty()) return -1;
    std::sort(v.begin(), v.end());
    const std::size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : (v[k - 1] + v[k]) / 2;
}

class SummaryReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            if (r.error_occurred) continue;
            const auto it = g_by_name.find(r.run_name.str());
            if (it == g_by_name.end()) continue;
            Entry& e = g_entries[it->second];
            const auto ips = r.counters.find("items_per_second");
            if (ips == r.counters.end()) continue;
            if (r.run_type == Run::RT_Iteration) {
                if (ips->second.value > 0) e.ns_reps.push_back(1e9 / ips->second.value);
            } else if (r.aggregate_name == "median" && ips->second.value > 0) {
                e.ns_median = 1e9 / ips->second.value;
            } else if (r.aggregate_name == "cv") {
                e.cv = ips->second.value;  // of the rate = of the time, to first order
            }
        }
    }
};

std::string fmt(const char* f, double x) {
    char b[64];
    std::snprintf(b, sizeof b, f, x);
    return b;
}

std::string ns_text(double ns) {
    if (ns < 0) return "—";
    if (ns >= 1e6) return fmt("%.2f ms", ns / 1e6);
    if (ns >= 1e4) return fmt("%.1f µs", ns / 1e3);
    if (ns >= 100) return fmt("%.0f ns", ns);
    return fmt("%.1f ns", ns);
}

std::string ratio_text(double r) {
    if (r < 0) return "—";
    if (r >= 100) return fmt("%.0f×", r);
    if (r >= 0.01) return fmt("%.2f×", r);
    return fmt("%.2g×", r);  // far faster than the reference: two significant digits
}

const Entry* find(const std::string& set, const char* key) {
    for (const Entry& e : g_entries)
        if (e.set == set && e.method_key == key && e.ns_median >= 0) return &e;
    return nullptr;
}

std::string fraction_text(double f) { return f < 0 ? "" : f == 0 ? "0" : fmt("%.3g", f); }

// Writes the summary as Markdown to `out` (stdout, and the --markdown file): one table per full data
// set, then the default query against its baseline on subsets (where its time goes), then the
// default query's speed goals.
void print_summary(std::FILE* out, const std::vector<DataSet>& sets, long sample, long sample_exact) {
    for (Entry& e : g_entries)
        if (e.ns_median < 0) e.ns_median = median(e.ns_reps);
    std::vector<const DataSet*> parts;
    for (const DataSet& s : sets) {
        if (s.name != "random" && s.name != "boundary") {
            parts.push_back(&s);
            continue;
        }
        bool measured = false;
        for (const Entry& e : g_entries) measured |= e.set == s.name && e.ns_median >= 0;
        if (!measured) continue;
        const Entry* base = find(s.name, "double_s4");
        const Entry* dflt = find(s.name, "default");
        std::fprintf(out, "\n**%s**\n\n", s.title.c_str());
        std::fprintf(out, "| query | time per query | cv | ratio to default | ratio to double §4 | exact fallbacks | wrong vs oracle |\n");
        std::fprintf(out, "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
        for (const Entry& e : g_entries) {
            if (e.set != s.name || e.ns_median < 0) continue;
            std::string wrong = e.check.wrong < 0 ? "—" : std::to_string(e.check.wrong) + " / " + std::to_string(e.queries);
            if (e.check.errors) wrong += " (" + std::to_string(e.check.errors) + " " + e.check.error_verb + ")";
            std::fprintf(out, "| %s | %s | %s | %s | %s | %s | %s |\n", e.label.c_str(), ns_text(e.ns_median).c_str(),
                         e.cv < 0 ? "—" : fmt("%.1f%%", 100 * e.cv).c_str(),
                         ratio_text(dflt ? e.ns_median / dflt->ns_median : -1).c_str(),
                         ratio_text(base ? e.ns_median / base->ns_median : -1).c_str(),
                         fraction_text(e.exact_fraction).c_str(), wrong.c_str());
        }
    }
#ifdef BOXCYL_BENCH_PEERS
    bool peers = false;
    for (const Entry& e : g_entries) peers |= e.peer.present && e.check.wrong >= 0;
    if (peers) {
        std::fprintf(out, "\n**Where the peer libraries disagree with the oracle** (a failed query counts as the answer false; "
                          "*small*: every length of the query — box sides, cylinder diameter and height — below %g)\n\n",
                     kSmallSize);
        std::fprintf(out, "| data | library | wrong vs oracle | false positives | false negatives | failed | wrong among the small queries |\n");
        std::fprintf(out, "| --- | --- | ---: | ---: | ---: | ---: | ---: |\n");
        for (const Entry& e : g_entries) {
            if (!e.peer.present || e.check.wrong < 0) continue;
            std::fprintf(out, "| %s | %s | %ld / %zu | %ld | %ld | %ld | %ld / %ld |\n", e.set.c_str(), e.label.c_str(),
                         e.check.wrong, e.queries, e.peer.false_pos, e.peer.false_neg, e.check.errors,
                         e.peer.small_wrong, e.peer.small);
        }
    }
#endif
    if (!parts.empty()) {
        std::fprintf(out, "\n**Where the default query's time goes** (random queries; each row's ratio is to double §4 on the same queries)\n\n");
        std::fprintf(out, "| queries | default query | double §4 | ratio | exact fallbacks |\n");
        std::fprintf(out, "| --- | ---: | ---: | ---: | ---: |\n");
        for (const DataSet* s : parts) {
            const Entry* d = find(s->name, "default");
            const Entry* b = find(s->name, "double_s4");
            if (!d || !b) continue;
            std::fprintf(out, "| %s | %s | %s | %s | %s |\n", s->title.c_str(), ns_text(d->ns_median).c_str(),
                         ns_text(b->ns_median).c_str(), ratio_text(d->ns_median / b->ns_median).c_str(),
                         fraction_text(d->exact_fraction).c_str());
        }
    }
    if (!g_checks) return;  // the goal needs the fallback count
    const double f = static_cast<double>(sample_exact) / static_cast<double>(sample);
    std::fprintf(out, "\nExact fallbacks of the default query over %ld further random queries (seed %s): %ld (%s).\n",
                 sample, hex_seed(kFractionSeed).c_str(), sample_exact, fraction_text(f).c_str());

    const Entry* d = find("random", "default");
    const Entry* b = find("random", "double_s4");
    const Entry* x = find("random", "exact_path");
    if (d && b) {
        const double r = d->ns_median / b->ns_median;
        std::fprintf(out, "\nRandom queries: the default query takes **%s** the time of a plain double linear-inequalities "
                          "query; exact fallback fraction %s here and %s over the %ld further queries.\n",
                     ratio_text(r).c_str(), fraction_text(d->exact_fraction).c_str(), fraction_text(f).c_str(), sample);
        if (x)
            std::fprintf(out, "One fallback costs %s double §4 queries, so a fallback fraction f adds about %s·f to the "
                              "ratio: ≤ 1.25× leaves room for f ≤ %s even with a free filter.\n",
                         fmt("%.0f", x->ns_median / b->ns_median).c_str(), fmt("%.0f", x->ns_median / b->ns_median).c_str(),
                         fmt("%.1e", 0.25 * b->ns_median / x->ns_median).c_str());
    }
    // FCL on the random queries: its GJK box–cylinder test against the default query.
    // FCL's GJK is GST_INDEP: for a yes/no query (no contact data) FCL's default solver GST_LIBCCD
    // does not run GJK at all but libccd's MPR (fcl/narrowphase/detail/convexity_based_algorithm/
    // gjk_libccd-inl.h, GJKCollide: `if (!contact_points) return ccdMPRIntersect(...)`). Both are
    // reported; GST_INDEP is the GJK comparison.
    const Entry* gjk = find("random", "fcl_indep");
    if (d && gjk) {
        const Entry* mpr = find("random", "fcl_libccd");
        const Entry* bd = find("boundary", "default");
        const Entry* bg = find("boundary", "fcl_indep");
        const double r = gjk->ns_median / d->ns_median;
        std::fprintf(out, "\nAgainst FCL on random queries: FCL's GJK box–cylinder test (solver GST_INDEP) takes **%s** "
                          "the default query's time%s; on the boundary set, where the default query needs its "
                          "costlier stages, %s.\n",
                     ratio_text(r).c_str(),
                     mpr ? ("; FCL's default solver GST_LIBCCD, whose yes/no test is libccd's MPR, not GJK: " +
                            ratio_text(mpr->ns_median / d->ns_median)).c_str()
                         : "",
                     bd && bg ? ratio_text(bg->ns_median / bd->ns_median).c_str() : "—");
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string markdown;
    std::size_t pairs = kBoundaryPairs;
    const bool ok = boxcyl::bench::initialize(argc, argv, [&](const std::string& a) {
        if (a.rfind("--markdown=", 0) == 0) markdown = a.substr(11);
        else if (a.rfind("--boundary-pairs=", 0) == 0) pairs = std::stoul(a.substr(17));
        else if (a == "--no-checks") g_checks = false;
        else return false;
        return true;
    });
    if (!ok) return 1;

    // All inputs, the oracle's answers, the fallback counts and the checks, before any timing.
    std::fprintf(stderr, "generating inputs (about a minute: boundary pairs are found by bisection with the oracle)...\n");
    std::vector<DataSet> sets;
    sets.reserve(6);  // the benchmarks keep references into it
    sets.push_back(make_random("random", "random: " + std::to_string(kQueries) +
                                             " mixed queries (CaseGenerator, all box kinds, seed " + hex_seed(kRandomSeed) + ")",
                               kRandomSeed));
    sets.push_back(make_boundary(kBoundarySeed, pairs));
    sets.push_back(make_random("random_aligned", "aligned boxes only", kKindSeed, static_cast<int>(BoxKind::aligned)));
    sets.push_back(make_random("random_oriented", "oriented boxes only", kKindSeed, static_cast<int>(BoxKind::oriented)));
    sets.push_back(make_random("random_canonical", "canonical boxes only", kKindSeed, static_cast<int>(BoxKind::canonical)));
    for (std::size_t k = 0; k < sets.size(); ++k) annotate(sets[k], g_checks && k < 2);
    sets.insert(sets.begin() + 2, filter_decided(sets[0]));
    long sample_exact = 0;
    if (g_checks) {
        boxcyl::testing::CaseGenerator gen(kFractionSeed);
        for (long i = 0; i < kFractionSample; ++i) sample_exact += needs_exact(gen.next());
    }

    for (std::size_t k = 0; k < 2; ++k)
        for (const MethodInfo& info : kMethods) add_method(sets[k], info.method);
#ifdef BOXCYL_BENCH_PEERS
    for (std::size_t k = 0; k < 2; ++k)
        for (const bench::PeerInfo& info : bench::kPeers) add_peer(sets[k], info);
#endif
    // Where the default query's time goes (without fallbacks, by box kind): the default and its baseline.
    for (std::size_t k = 2; k < sets.size(); ++k) {
        add_method(sets[k], Method::default_query);
        add_method(sets[k], Method::double_s4);
    }

    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();

    std::printf("\n## Summary (time per query: CPU time of a pass / queries in it, median of the repetitions)\n");
    print_summary(stdout, sets, kFractionSample, sample_exact);
    if (!markdown.empty()) {
        std::FILE* f = std::fopen(markdown.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "cannot write %s\n", markdown.c_str());
            return 1;
        }
        print_summary(f, sets, kFractionSample, sample_exact);
        std::fclose(f);
    }
    return 0;
}
