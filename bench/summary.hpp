// The tables the benchmarks print after Google Benchmark's output: the counter ns_per_query of each
// benchmark, collected as the runs are reported (one value per repetition, or the median aggregate
// alone when only aggregates are reported), and how to print a time.
#pragma once

#include <algorithm>  // std::sort
#include <cstdio>     // std::snprintf
#include <map>        // timings by name
#include <string>     // names, text
#include <vector>     // values

#include <benchmark/benchmark.h>

namespace boxcyl::bench {

// Sets the counter ns_per_query: the time of one iteration over `queries` queries, per query.
inline void set_ns_per_query(benchmark::State& state, std::size_t queries) {
    state.counters["ns_per_query"] = benchmark::Counter(
        static_cast<double>(queries) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

struct Timing {
    std::vector<double> ns;  // ns_per_query of each repetition, or the median aggregate alone
    bool median_aggregate = false;
};

class TimingReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, Timing> timings;  // by the benchmark's reported name

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            const auto c = run.counters.find("ns_per_query");
            if (run.error_occurred || c == run.counters.end()) continue;
            Timing& t = timings[run.run_name.str()];
            if (t.median_aggregate) continue;
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
                t.ns = {c->second.value};
                t.median_aggregate = true;
            } else if (run.run_type == Run::RT_Iteration) {
                t.ns.push_back(c->second.value);
            }
        }
    }
    // The median time per query of benchmark `name`; −1 when it did not run.
    double median(const std::string& name) const {
        const auto it = timings.find(name);
        if (it == timings.end() || it->second.ns.empty()) return -1;
        std::vector<double> v = it->second.ns;
        std::sort(v.begin(), v.end());
        const std::size_t k = v.size() / 2;
        return v.size() % 2 ? v[k] : (v[k - 1] + v[k]) / 2;
    }
};

inline std::string ns_text(double ns) {
    char b[32];
    if (ns >= 1e6) std::snprintf(b, sizeof b, "%.2f ms", ns / 1e6);
    else if (ns >= 1e4) std::snprintf(b, sizeof b, "%.1f µs", ns / 1e3);
    else std::snprintf(b, sizeof b, "%.0f ns", ns);
    return b;
}

}  // namespace boxcyl::bench
