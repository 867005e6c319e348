// The one place that maps command-line option values to boxcyl::QueryOptions. Adding an algorithm or
// an arithmetic to the tool means adding one row here (help text and validation follow from it).
#pragma once

#include <array>        // the tables
#include <cstddef>      // std::size_t
#include <optional>     // lookups that may fail
#include <string>       // help text
#include <string_view>  // names

#include "boxcyl/query.hpp"

namespace boxcyl::cli {

struct AlgorithmChoice {
    std::string_view name;        // the --algorithm value
    Algorithm value;
    bool uses_arithmetic;         // false: --arithmetic does not apply (exact algorithms)
    std::string_view description; // one line for --help
};

struct ArithmeticChoice {
    std::string_view name;        // the --arithmetic value
    Arithmetic value;
    std::string_view description; // one line for --help
};

inline constexpr std::array<AlgorithmChoice, 4> algorithm_choices{{
    {"inequalities", Algorithm::inequalities, true,
     "the linear-inequalities method (default)"},
    {"hull", Algorithm::hull, true,
     "the convex-hull method (clip, project, hull); takes any parallelepiped; exact with --arithmetic exact"},
    {"lcp", Algorithm::lcp, true,
     "the LCP method (convex quadratic programming solved as an LCP by Lemke's method); a "
     "floating-point failure is answered exactly"},
    {"oracle", Algorithm::oracle, false,
     "the exact oracle, the reference; slow; exact for the inputs as given; ignores --arithmetic"},
}};

inline constexpr std::array<ArithmeticChoice, 4> arithmetic_choices{{
    {"filtered", Arithmetic::filtered,
     "the exact answer (default): a certified double-interval filter decides most queries, exact "
     "arithmetic the rest; with hull and lcp it means exact"},
    {"float", Arithmetic::float32,
     "32-bit floats: inputs are rounded to float first; otherwise as double (axes beyond 2^-20 of "
     "orthonormal: the convex-hull method)"},
    {"double", Arithmetic::float64,
     "plain 64-bit doubles, unfiltered (may misjudge inputs within a tiny gap of touching); a box whose "
     "axes are further than 2^-49 from orthonormal (|Ai.Aj - delta_ij|) is answered by the convex-hull "
     "method, for the parallelepiped its axes span, whatever --algorithm says"},
    {"exact", Arithmetic::exact,
     "rationals and a + b*sqrt(d): exact for the inputs as given; the inequalities and lcp methods "
     "refuse oriented boxes whose axes are not exactly orthonormal (use hull or oracle)"},
}};

inline constexpr std::string_view default_algorithm = "inequalities";
inline constexpr std::string_view default_arithmetic = "filtered";

inline const AlgorithmChoice* find_algorithm(std::string_view name) {
    for (const auto& c : algorithm_choices)
        if (c.name == name) return &c;
    return nullptr;
}

inline const ArithmeticChoice* find_arithmetic(std::string_view name) {
    for (const auto& c : arithmetic_choices)
        if (c.name == name) return &c;
    return nullptr;
}

// The longest input line the tool keeps (--max-line-bytes; see read_line in jsonl_query.hpp).
inline constexpr std::size_t default_max_line_bytes = std::size_t{16} << 20;  // 16 MiB

// What the tool runs with: the library's options plus whether the chosen algorithm rounds its inputs
// to float (then inputs must survive that rounding, see check_arithmetic in jsonl_query.hpp).
struct RunOptions {
    QueryOptions query;
    bool rounds_to_float = false;
    std::size_t max_line_bytes = default_max_line_bytes;  // --max-line-bytes
};

// Both names must be table entries (the command line checks that first).
inline RunOptions make_run_options(std::string_view algorithm, std::string_view arithmetic) {
    const AlgorithmChoice* alg = find_algorithm(algorithm);
    const ArithmeticChoice* ari = find_arithmetic(arithmetic);
    RunOptions o;
    if (alg) o.query.algorithm = alg->value;
    if (ari) o.query.arithmetic = ari->value;
    o.rounds_to_float = alg && alg->uses_arithmetic && ari && ari->value == Arithmetic::float32;
    return o;
}

}  // namespace boxcyl::cli
