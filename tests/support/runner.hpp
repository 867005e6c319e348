// Shared driver for differential tests: run an algorithm over generated cases, compare with the
// oracle, classify disagreements as within tolerance (near touching) or bugs, print a summary.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>  // std::uint64_t
#include <cstdio>   // std::printf
#include <cstdlib>  // std::getenv, std::strtod
#include <string>   // labels

#include "support/cases.hpp"
#include "support/tolerance.hpp"

namespace boxcyl::testing {

// Case counts scale with BOXCYL_TEST_SCALE (default 1): CI runs the default, `ctest -L long` runs
// the same tests with a large multiplier.
inline long scaled(long n) {
    const char* s = std::getenv("BOXCYL_TEST_SCALE");
    const double f = s ? std::strtod(s, nullptr) : 1.0;
    return f > 0 ? static_cast<long>(static_cast<double>(n) * f) : n;
}

struct Tally {
    long cases = 0, hits = 0, disagreements = 0, tolerated = 0;
};

// Compares `answer(case)` with the oracle. A disagreement is tolerated only when near_touching(c, tau)
// (tau = 0 for exact arithmetic: then every disagreement fails). Failures print seed, index and case.
template <class Answer>
void check_case(Tally& t, const Case& c, bool want, Answer&& answer, double tau, const std::string& where) {
    ++t.cases;
    t.hits += want;
    const bool got = answer(c);
    if (got == want) return;
    ++t.disagreements;
    if (tau > 0 && near_touching(c, tau, got)) {
        ++t.tolerated;
        return;
    }
    char tol[96] = "";
    if (tau > 0) std::snprintf(tol, sizeof tol, " and no input within %a of the scale has that answer", tau);
    ADD_FAILURE() << where << ": algorithm says " << got << ", exact answer " << want << tol << "\n  " << describe(c);
}

// Calls fn(a, want_a, b, want_b, where) for `pairs` boundary pairs (two inputs one ulp apart with
// opposite exact answers) drawn from gen; `seed` only labels the messages. Checks that each pair
// really is one.
template <class Fn>
void for_each_boundary_pair(CaseGenerator& gen, std::uint64_t seed, long pairs, Fn&& fn) {
    for (long made = 0; made < pairs;) {
        Case a, b;
        Parameter which;
        if (!boundary_pair(gen, a, b, which)) continue;
        ++made;
        const bool wa = oracle_answer(a), wb = oracle_answer(b);
        EXPECT_NE(wa, wb) << "boundary generator produced a non-boundary pair\n  " << describe(a) << "\n  " << describe(b);
        fn(a, wa, b, wb,
           "boundary seed " + std::to_string(seed) + " pair " + std::to_string(made) + " (" + name(which) + ")");
    }
}

inline void print_tally(const char* label, const Tally& t) {
    std::printf("%-44s cases %8ld  hits %5.1f%%  disagreements %6ld (%.2e)  within tolerance %6ld\n", label,
                t.cases, t.cases ? 100.0 * double(t.hits) / double(t.cases) : 0.0, t.disagreements,
                t.cases ? double(t.disagreements) / double(t.cases) : 0.0, t.tolerated);
}

}  // namespace boxcyl::testing
