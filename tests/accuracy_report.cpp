// Measures how often each algorithm disagrees with the exact oracle in float and double arithmetic, on
// the random set and on one-ulp boundary pairs, and prints docs/accuracy.md's table (Markdown).
// Run by scripts/accuracy.sh. Not a test: the assertions live in the test suites; this reports rates.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "boxcyl/algo/lcp_solver.hpp"
#include "boxcyl/algo/quadratic_programming.hpp"
#include "boxcyl/algo/slab_cull.hpp"
#include "boxcyl/query.hpp"
#include "support/cases.hpp"
#include "support/tolerance.hpp"

namespace {

using namespace boxcyl;
using namespace boxcyl::testing;

// The LCP method exactly as published (the slab cull, the 8×8 LCP with the sign of b corrected, d² at
// the minimiser; docs/algorithms.md), without this library's robustness steps — to test the published
// note's warning that the LCP approach is not robust in floating point.
template <class U>
std::optional<bool> spec_form_lcp(const CanonicalQuery<U>& q) {
    if (algo::box_outside_slab(q.box, q.cylinder)) return false;
    const auto lcp = algo::make_qp_lcp(q.box, q.cylinder);
    const auto res = algo::solve_lcp(lcp.q, lcp.M);
    if (res.status != algo::LcpStatus::solved) return std::nullopt;
    const Vec3<U>& w = q.cylinder.direction;
    Vec3<U> v;  // x − k with x = z − ℓ… in the canonical frame: x_canon = z − ℓ, k_canon = c
    for (int i = 0; i < 3; ++i) v[i] = (res.z[i] - q.box.extents[i]) - q.cylinder.center[i];
    const U t = dot(w, v);
    const U d2 = dot(v, v) - t * t;
    return d2 <= q.cylinder.radius * q.cylinder.radius;
}

template <class U>
std::optional<bool> answer(int alg, const Case& c) {
    auto go = [&](const auto& box) -> std::optional<bool> {
        if (alg == 3) return spec_form_lcp(to_canonical(boxcyl::detail::cast<U>(box), to_unit(boxcyl::detail::cast<U>(c.cylinder))));
        const Algorithm a = alg == 0 ? Algorithm::inequalities : alg == 1 ? Algorithm::hull : Algorithm::lcp;
        return boxcyl::detail::rounded<U>(a, box, c.cylinder);
    };
    switch (c.kind) {
        case BoxKind::aligned: return go(c.aligned);
        case BoxKind::oriented: return go(c.oriented);
        case BoxKind::canonical: return go(c.canonical);
    }
    return std::nullopt;
}

bool in_float_range(const Case& c) {
    if (problem_scale(c) > 1e30) return false;
    for (int k = 0; k < 3; ++k)
        if (c.cylinder.axis[k] != 0 && std::abs(c.cylinder.axis[k]) < 1e-30) return false;
    return true;
}

struct Row {
    long cases = 0, wrong = 0, within = 0, failures = 0;
};

template <class U>
Row measure(int alg, const std::vector<Case>& cases, const std::vector<unsigned char>& want, double tau) {
    Row r;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (sizeof(U) == sizeof(float) && !in_float_range(cases[i])) continue;
        ++r.cases;
        const std::optional<bool> got = answer<U>(alg, cases[i]);
        if (!got) {
            ++r.failures;
            continue;
        }
        if (*got != (want[i] != 0)) {
            ++r.wrong;
            r.within += near_touching(cases[i], tau, *got);
        }
    }
    return r;
}

std::string rate(long k, long n) {
    char b[32];
    if (k == 0) return "0";
    std::snprintf(b, sizeof b, "%.2e", double(k) / double(n));
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    const long n_random = argc > 1 ? std::atol(argv[1]) : 20000;
    const long n_pairs = argc > 2 ? std::atol(argv[2]) : 300;
    std::vector<Case> random, boundary;
    std::vector<unsigned char> want_random, want_boundary;
    CaseGenerator gen(424242);
    for (long i = 0; i < n_random; ++i) {
        random.push_back(gen.next());
        want_random.push_back(oracle_answer(random.back()) ? 1 : 0);
    }
    CaseGenerator bgen(434343);
    while (static_cast<long>(boundary.size()) < 2 * n_pairs) {
        Case a, b;
        Parameter p;
        if (!boundary_pair(bgen, a, b, p)) continue;
        boundary.push_back(a);
        want_boundary.push_back(oracle_answer(a) ? 1 : 0);
        boundary.push_back(b);
        want_boundary.push_back(oracle_answer(b) ? 1 : 0);
    }
    const char* names[4] = {"linear inequalities", "convex hull", "LCP (boxcyl)", "LCP as published"};
    std::printf("| algorithm | arithmetic | set | cases | wrong | rate | wrong, far from touching | solver failures |\n");
    std::printf("| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |\n");
    for (int alg = 0; alg < 4; ++alg)
        for (int ari = 0; ari < 2; ++ari)
            for (int set = 0; set < 2; ++set) {
                const auto& cases = set == 0 ? random : boundary;
                const auto& want = set == 0 ? want_random : want_boundary;
                const Row r = ari == 0 ? measure<float>(alg, cases, want, float_tolerance)
                                       : measure<double>(alg, cases, want, double_tolerance);
                std::printf("| %s | %s | %s | %ld | %ld | %s | %ld | %ld |\n", names[alg], ari == 0 ? "float" : "double",
                            set == 0 ? "random" : "boundary", r.cases, r.wrong, rate(r.wrong, r.cases).c_str(),
                            r.wrong - r.within, r.failures);
                std::fflush(stdout);
            }
    return 0;
}
