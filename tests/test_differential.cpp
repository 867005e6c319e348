// Randomized differential tests of the default query paths against the exact oracle: mixed random
// cases and boundary (one-ulp-apart) pairs, for every box kind. Rounded arithmetic may disagree only
// on near-touching cases (support/tolerance.hpp); anything else fails with a copy-pasteable case.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "boxcyl/query.hpp"
#include "support/cases.hpp"
#include "support/runner.hpp"
#include "support/tolerance.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

bool run(const Case& c, QueryOptions opt) {
    switch (c.kind) {
        case BoxKind::aligned: return intersects(c.aligned, c.cylinder, opt);
        case BoxKind::oriented: return intersects(c.oriented, c.cylinder, opt);
        case BoxKind::canonical: return intersects(c.canonical, c.cylinder, opt);
    }
    return false;
}

const QueryOptions linear_double{Algorithm::inequalities, Arithmetic::float64};
const QueryOptions linear_float{Algorithm::inequalities, Arithmetic::float32};

// Cases that once failed: kept forever. (Filled as failures are found.)
const std::vector<Case> regressions = {
};

TEST(Differential, Regressions) {
    Tally t;
    for (const Case& c : regressions) {
        check_case(t, c, oracle_answer(c), [](const Case& k) { return run(k, linear_double); }, double_tolerance,
                   "regression");
    }
}

// 4 shards × 25,000 = 100,000 random cases in CI (ctest runs shards in parallel).
class RandomShard : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(RandomShard, LinearInequalitiesDoubleAgreesWithOracle) {
    const std::uint64_t seed = GetParam();
    CaseGenerator gen(seed);
    Tally t;
    const long n = scaled(25000);
    for (long i = 0; i < n; ++i) {
        const Case c = gen.next();
        check_case(t, c, oracle_answer(c), [](const Case& k) { return run(k, linear_double); }, double_tolerance,
                   "seed " + std::to_string(seed) + " case " + std::to_string(i));
    }
    print_tally(("random, inequalities double, seed " + std::to_string(seed)).c_str(), t);
    // The generator must be representative: a healthy mix of hits and misses.
    EXPECT_GT(t.hits, n / 5);
    EXPECT_LT(t.hits, n * 4 / 5);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomShard, ::testing::Values(1001u, 1002u, 1003u, 1004u));

TEST(Differential, LinearInequalitiesFloatAgreesWithOracle) {
    // float arithmetic on double inputs rounds the inputs too; tolerance 2^-16 of the scale.
    CaseGenerator gen(2002);
    Tally t;
    const long n = scaled(10000);
    for (long i = 0; i < n; ++i) {
        Case c = gen.next();
        // Keep to float's range: tiny axis components and huge scales are a double-only concern.
        bool representable = problem_scale(c) < 1e30;
        for (int k = 0; k < 3; ++k)
            if (c.cylinder.axis[k] != 0 && std::abs(c.cylinder.axis[k]) < 1e-30) representable = false;
        if (!representable) continue;
        check_case(t, c, oracle_answer(c), [](const Case& k) { return run(k, linear_float); }, float_tolerance,
                   "seed 2002 case " + std::to_string(i));
    }
    print_tally("random, inequalities float", t);
}

// Boundary pairs: two inputs one ulp apart with opposite exact answers. Every disagreement here is by
// construction near touching; the test prints the rate and still fails on anything outside tolerance.
TEST(Differential, BoundaryPairsLinearInequalitiesDouble) {
    const std::uint64_t seed = 3003;
    CaseGenerator gen(seed);
    Tally t;
    auto answer = [](const Case& k) { return run(k, linear_double); };
    for_each_boundary_pair(gen, seed, scaled(400), [&](const Case& a, bool wa, const Case& b, bool wb, const std::string& where) {
        check_case(t, a, wa, answer, double_tolerance, where);
        check_case(t, b, wb, answer, double_tolerance, where);
    });
    print_tally("boundary pairs, inequalities double", t);
}

}  // namespace
}  // namespace boxcyl
