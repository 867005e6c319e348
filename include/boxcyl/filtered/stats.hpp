// Where the exact default's time goes, on the caller's own data: for each row of the pipeline's
// schedule (filtered/schedule.hpp), how often it ran, how often it decided (hit or miss) and the time it
// took. Pass a Stats to the query (`QueryOptions::stats`, or filtered::query(box, cyl, stats)) to
// fill it; without one nothing is counted and nothing is timed. Each counted row reads a steady clock
// twice (tens of ns), so a counted query is slower than an uncounted one: compare rows with each
// other, not with uncounted timings.
//
// A light header (no arithmetic): the compiled library's declarations include it through options.hpp.
#pragma once

#include <array>        // the rows
#include <cstddef>      // std::size_t
#include <cstdint>      // std::uint64_t, std::uint8_t
#include <cstdio>       // std::snprintf
#include <string>       // table()
#include <string_view>  // row names

namespace boxcyl::filtered {

// Every row of every schedule, in the order the schedules run them (docs/pipeline.md describes each).
enum class RowId : std::uint8_t {
    slabs, semi_static, exact_narrow, search, inequalities_bounded, exact_series_narrow, clipped, tiny_sizes,
    inequalities_dd, clipped_flat, exact_series, inequalities_bounded_late, inequalities_interval, thorough_search,
    pp_fixed, pp_frame, pp_search, pp_frame_interval, pp_candidates_interval, exact,
};
inline constexpr std::size_t row_count = static_cast<std::size_t>(RowId::exact) + 1;

// The name the docs and the statistics table use for a row.
constexpr std::string_view name(RowId row) {
    constexpr std::string_view names[row_count] = {
        "slabs",           "semi_static",     "exact_narrow",         "search",          "inequalities_bounded",
        "exact_series_narrow", "clipped",          "tiny_sizes",      "inequalities_dd",
        "clipped_flat",    "exact_series",         "inequalities_bounded_late", "inequalities_interval",
        "thorough_search", "pp_fixed",             "pp_frame",
        "pp_search",       "pp_frame_interval",    "pp_candidates_interval", "exact"};
    return names[static_cast<std::size_t>(row)];
}

struct Stats {
    static constexpr bool enabled = true;  // the pipeline's runner counts into it
    struct Row {
        std::uint64_t tried = 0;        // the row's certifier ran
        std::uint64_t hits = 0;         // ... and certified an intersection
        std::uint64_t misses = 0;       // ... and certified a separation
        std::uint64_t nanoseconds = 0;  // time spent in the certifier (steady clock)
    };
    std::array<Row, row_count> rows{};
    std::uint64_t queries = 0;

    const Row& operator[](RowId r) const { return rows[static_cast<std::size_t>(r)]; }
    Row& operator[](RowId r) { return rows[static_cast<std::size_t>(r)]; }
    Stats& operator+=(const Stats& o) {
        queries += o.queries;
        for (std::size_t i = 0; i < row_count; ++i) {
            rows[i].tried += o.rows[i].tried;
            rows[i].hits += o.rows[i].hits;
            rows[i].misses += o.rows[i].misses;
            rows[i].nanoseconds += o.rows[i].nanoseconds;
        }
        return *this;
    }

    // A Markdown table of the rows that ran: tried, decided (share of all queries), ns per try, and the
    // share of the total time.
    std::string table() const;
};

inline std::string Stats::table() const {
    std::uint64_t total_ns = 0;
    for (const Row& r : rows) total_ns += r.nanoseconds;
    auto share = [](double part, double whole) { return whole > 0 ? 100.0 * part / whole : 0.0; };
    std::string out = "| row | tried | decided | of all queries | ns per try | share of time |\n"
                      "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (std::size_t i = 0; i < row_count; ++i) {
        const Row& r = rows[i];
        if (r.tried == 0) continue;
        const std::uint64_t decided = r.hits + r.misses;
        char line[160];
        std::snprintf(line, sizeof line, "| %s | %llu | %llu | %.2f%% | %.0f | %.1f%% |\n",
                      std::string(name(static_cast<RowId>(i))).c_str(), static_cast<unsigned long long>(r.tried),
                      static_cast<unsigned long long>(decided), share(double(decided), double(queries)),
                      double(r.nanoseconds) / double(r.tried), share(double(r.nanoseconds), double(total_ns)));
        out += line;
    }
    return out;
}

}  // namespace boxcyl::filtered
