// The command line of the benchmark programs that write a report: Google Benchmark starts with the
// project's defaults (aggregates only; 5 repetitions of at least 0.2 s, or with --quick one short
// repetition, a smoke run rather than a measurement), then the flags given, which override them.
#pragma once

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace boxcyl::bench {

// `own(flag)` takes the program's own flags (returns true for one it consumed); the rest go to
// Google Benchmark. Returns false when a flag is recognised by neither (benchmark has said which).
template <class Own>
bool initialize(int argc, char** argv, Own&& own) {
    static std::vector<std::string> args;  // Google Benchmark keeps pointers into its argv
    bool quick = false;
    std::vector<std::string> user;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") quick = true;
        else if (!own(a)) user.push_back(a);
    }
    args = {argv[0], "--benchmark_display_aggregates_only=true"};
    args.push_back(quick ? "--benchmark_repetitions=1" : "--benchmark_repetitions=5");
    args.push_back(quick ? "--benchmark_min_time=0.01" : "--benchmark_min_time=0.2");
    args.insert(args.end(), user.begin(), user.end());
    static std::vector<char*> cargs;
    cargs.clear();
    for (std::string& a : args) cargs.push_back(a.data());
    int cargc = static_cast<int>(cargs.size());
    benchmark::Initialize(&cargc, cargs.data());
    return !benchmark::ReportUnrecognizedArguments(cargc, cargs.data());
}

}  // namespace boxcyl::bench
