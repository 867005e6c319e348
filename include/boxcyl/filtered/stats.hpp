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
#include <string>       // table()
#include <string_view>  // row names

namespace boxcyl::filtered {

// Every row of every schedule, in the order the schedules run them (docs/pipeline.md describes each).
enum class RowId : std::uint8_t {
    semi_static,             // stage 0: plain-double tests with error bounds computed at compile time
    exact_narrow,            // the exact stage in fixed-width integers, for narrow inputs
    search,                  // searched separating directions and witness points (stage 0's bounds)
    inequalities_bounded,    // linear inequalities on a double with a running error bound
    exact_series_narrow,     // the exact stage in powers of ε, for narrow inputs of two scales
    clipped,                 // clipped edges and face cuts on double-double enclosures (turned frames)
    hull_double_double,      // the convex-hull method on double-double enclosures (turned frames)
    inequalities_dd,         // linear inequalities on double-double enclosures
    clipped_flat,            // clipped edges and face cuts for flat shapes (disks, segments, flat boxes)
    exact_series,            // the exact stage in powers of ε, for flat shapes with a two-scale axis
    inequalities_bounded_late,   // linear inequalities on Bounded, for flat shapes with a two-scale axis
    inequalities_interval,   // linear inequalities on outward-rounded intervals
    thorough_search,         // a long search for a witness point deep in both solids
    pp_fixed,                // parallelepipeds: fixed separating directions and witness points (Bounded)
    pp_frame,                // parallelepipeds: linear inequalities in the unit frame, widened (Bounded)
    pp_search,               // parallelepipeds: searched directions and points (Bounded)
    pp_frame_interval,       // parallelepipeds: the frame row on intervals
    pp_candidates_interval,  // parallelepipeds: every candidate again on intervals
    exact,                   // the exact stage: always decides
};
inline constexpr std::size_t row_count = static_cast<std::size_t>(RowId::exact) + 1;

// The name the docs and the statistics table use for a row.
constexpr std::string_view name(RowId row) {
    constexpr std::string_view names[row_count] = {
        "semi_static",     "exact_narrow",         "search",          "inequalities_bounded",
        "exact_series_narrow", "clipped",          "hull_double_double", "inequalities_dd",
        "clipped_flat",    "exact_series",         "inequalities_bounded_late", "inequalities_interval",
        "thorough_search", "pp_fixed",             "pp_frame",        "pp_search",
        "pp_frame_interval", "pp_candidates_interval", "exact"};
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
    auto fixed = [](double x, int decimals) {
        std::string s = std::to_string(static_cast<long long>(x * (decimals == 1 ? 10 : decimals == 2 ? 100 : 1) + 0.5));
        if (decimals == 0) return s;
        while (s.size() <= static_cast<std::size_t>(decimals)) s.insert(0, "0");
        s.insert(s.size() - static_cast<std::size_t>(decimals), ".");
        return s;
    };
    std::string out = "| row | tried | decided | of all queries | ns per try | share of time |\n"
                      "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (std::size_t i = 0; i < row_count; ++i) {
        const Row& r = rows[i];
        if (r.tried == 0) continue;
        const std::uint64_t decided = r.hits + r.misses;
        out += "| " + std::string(name(static_cast<RowId>(i))) + " | " + std::to_string(r.tried) + " | " +
               std::to_string(decided) + " | " +
               fixed(queries ? 100.0 * static_cast<double>(decided) / static_cast<double>(queries) : 0.0, 2) +
               "% | " + fixed(static_cast<double>(r.nanoseconds) / static_cast<double>(r.tried), 0) + " | " +
               fixed(total_ns ? 100.0 * static_cast<double>(r.nanoseconds) / static_cast<double>(total_ns) : 0.0, 1) +
               "% |\n";
    }
    return out;
}

}  // namespace boxcyl::filtered
