// Issue #3's proof: every specification algorithm, run in exact arithmetic through the front door
// (Arithmetic::exact: rationals and a + b·√d), agrees with the oracle on 100% of the random, boundary
// (one ulp apart) and degenerate sets. Oriented boxes with rounded rotations go through §3 exactly;
// §2/§4 need an exactly orthonormal frame and must refuse the others (std::domain_error).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>

#include "boxcyl/query.hpp"
#include "support/cases.hpp"
#include "support/runner.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

bool run(const Case& c, const QueryOptions& opt) {
    switch (c.kind) {
        case BoxKind::aligned: return intersects(c.aligned, c.cylinder, opt);
        case BoxKind::oriented: return intersects(c.oriented, c.cylinder, opt);
        case BoxKind::canonical: return intersects(c.canonical, c.cylinder, opt);
    }
    return false;
}

bool exactly_orthonormal(const Case& c) {
    return c.kind != BoxKind::oriented || exact::detail::exactly_orthonormal(to_exact(c.oriented));
}

const char* name(Algorithm a) {
    switch (a) {
        case Algorithm::inequalities: return "§4 inequalities";
        case Algorithm::hull: return "§3 hull";
        case Algorithm::lcp: return "§2 lcp";
        case Algorithm::oracle: return "oracle";
    }
    return "?";
}

// Runs one case exactly: a refused oriented box (§2/§4, axes not exactly orthonormal) must throw
// domain_error and is counted apart; every answer must equal the oracle's.
template <class Want>
void check_exact(Tally& t, long& refused, Algorithm a, const Case& c, Want&& want, const std::string& where) {
    const QueryOptions opt{a, Arithmetic::exact};
    if (a != Algorithm::hull && !exactly_orthonormal(c)) {
        EXPECT_THROW(run(c, opt), std::domain_error) << where << "\n  " << describe(c);
        ++refused;
        return;
    }
    check_case(t, c, want(), [&](const Case& k) { return run(k, opt); }, 0.0, where);
}

class ExactRandom : public ::testing::TestWithParam<std::tuple<Algorithm, std::uint64_t>> {};

TEST_P(ExactRandom, AgreesWithOracle) {
    const auto [alg, seed] = GetParam();
    CaseGenerator gen(seed);
    Tally t;
    long refused = 0;
    const long n = scaled(10000);  // answered cases; refused ones do not count
    for (long i = 0; t.cases < n; ++i) {
        const Case c = gen.next();
        check_exact(t, refused, alg, c, [&] { return oracle_answer(c); },
                    "seed " + std::to_string(seed) + " case " + std::to_string(i));
    }
    print_tally((std::string("exact random, ") + name(alg) + ", seed " + std::to_string(seed)).c_str(), t);
    std::printf("  (%ld oriented boxes without an exactly orthonormal frame refused, as documented)\n", refused);
    EXPECT_EQ(t.disagreements, 0);
    EXPECT_GT(t.hits, n / 5);
    EXPECT_LT(t.hits, n * 4 / 5);
}

// 2 seeds × 10,000 = 20,000 cases per algorithm in CI (×50 under ctest -L long: 1,000,000).
INSTANTIATE_TEST_SUITE_P(Algorithms, ExactRandom,
                         ::testing::Combine(::testing::Values(Algorithm::inequalities, Algorithm::hull, Algorithm::lcp),
                                            ::testing::Values(5001u, 5002u)),
                         [](const auto& info) {
                             const Algorithm a = std::get<0>(info.param);
                             const char* n = a == Algorithm::inequalities ? "inequalities" : a == Algorithm::hull ? "hull" : "lcp";
                             return std::string(n) + "_" + std::to_string(std::get<1>(info.param));
                         });

TEST(ExactDegenerate, EveryAlgorithmAgreesWithOracle) {
    const std::uint64_t seed = 6006;
    CaseGenerator gen(seed, Profile::degenerate);
    Tally t[3];
    long refused = 0;
    const Algorithm algs[3] = {Algorithm::inequalities, Algorithm::hull, Algorithm::lcp};
    const long n = scaled(1500);
    for (long i = 0; i < n; ++i) {
        const Case c = gen.next();
        const bool want = oracle_answer(c);
        for (int k = 0; k < 3; ++k)
            check_exact(t[k], refused, algs[k], c, [&] { return want; }, "degenerate seed 6006 case " + std::to_string(i));
    }
    for (int k = 0; k < 3; ++k) {
        print_tally((std::string("exact degenerate, ") + name(algs[k])).c_str(), t[k]);
        EXPECT_EQ(t[k].disagreements, 0);
    }
}

TEST(ExactBoundary, EveryAlgorithmAgreesWithOracleOnUlpPairs) {
    const std::uint64_t seed = 7007;
    CaseGenerator gen(seed);
    Tally t[3];
    long refused = 0;
    const Algorithm algs[3] = {Algorithm::inequalities, Algorithm::hull, Algorithm::lcp};
    const long pairs = scaled(150);
    long made = 0;
    while (made < pairs) {
        Case a, b;
        Parameter which;
        if (!boundary_pair(gen, a, b, which)) continue;
        ++made;
        const bool wa = oracle_answer(a), wb = oracle_answer(b);
        ASSERT_NE(wa, wb);
        const std::string where = "boundary seed 7007 pair " + std::to_string(made) + " (" + name(which) + ")";
        for (int k = 0; k < 3; ++k) {
            check_exact(t[k], refused, algs[k], a, [&] { return wa; }, where);
            check_exact(t[k], refused, algs[k], b, [&] { return wb; }, where);
        }
    }
    for (int k = 0; k < 3; ++k) {
        print_tally((std::string("exact boundary pairs, ") + name(algs[k])).c_str(), t[k]);
        EXPECT_EQ(t[k].disagreements, 0);
    }
}

}  // namespace
}  // namespace boxcyl
