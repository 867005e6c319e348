// The ninth session's experiments (docs/performance.md, ninth-session section; run.sh builds this
// against a commit's headers with and without one of the patches beside it). Times, best of 30
// passes of 20 rounds each over bench_query's random set (CaseGenerator seed 0xb0c5c701, 4096 queries):
//   stage0:      semi_static::filter on every query
//   default:     boxcyl::intersects on every query
//   left:        boxcyl::intersects on the queries stage 0 leaves
//   0b:          witness_search::decide alone on those
// -DNORMALISE_AXES: every axis of the set divided by its length first (for no_unit_division.diff).
// -DCLASSES_STAGE0 / -DCLASSES_STAGE0B (with count_stage0_tests.diff / count_stage0b_steps.diff): the
// queries grouped by the test or search step that decides them, each group timed on its own.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "boxcyl/query.hpp"
#include "support/cases.hpp"

using namespace boxcyl;
using boxcyl::testing::Case;
using boxcyl::testing::with_box;

namespace {

template <class F>
double best_ns(const std::vector<Case>& set, F f) {
    double best = 1e300;
    for (int rep = 0; rep < 30; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        long sum = 0;
        for (int k = 0; k < 20; ++k)
            for (const Case& c : set) sum += f(c);
        const auto t1 = std::chrono::steady_clock::now();
        asm volatile("" : : "r"(sum));
        best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / 20 / double(set.size()));
    }
    return best;
}
long stage0(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::semi_static::filter(b, cyl); }).has_value();
}
long stage0b(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::witness_search::decide(b, cyl); }).has_value();
}
long query(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return intersects(b, cyl); });
}
void print_classes(const std::map<int, std::vector<Case>>& classes) {
    for (const auto& [k, set] : classes)
        std::printf("class %2d: %4zu queries, default %.1f ns, stage 0 alone %.1f ns\n", k, set.size(), best_ns(set, query),
                    best_ns(set, stage0));
}

}  // namespace

int main() {
    boxcyl::testing::CaseGenerator gen(0xb0c5c701);
    std::vector<Case> all, left;
    for (int i = 0; i < 4096; ++i) {
        Case c = gen.next();
#if defined(NORMALISE_AXES)
        Vec3<double>& a = c.cylinder.axis;
        const double m = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])});
        if (m >= 0x1p-250 && m <= 0x1p250) {
            const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            a = {a[0] / len, a[1] / len, a[2] / len};
        }
#endif
        all.push_back(c);
    }
    for (const Case& c : all)
        if (!stage0(c)) left.push_back(c);
#if defined(CLASSES_STAGE0)
    // 0 face/axis, 1 C inside, 2 witness 0, 3 d × E_i, 4 witnesses 1–2, 5 cylinder points, 6 left
    std::map<int, std::vector<Case>> classes;
    for (const Case& c : all) {
        g_c0 = 6;
        stage0(c);
        classes[g_c0].push_back(c);
    }
    print_classes(classes);
#elif defined(CLASSES_STAGE0B)
    // 0 separated before any projection, 1 hit there, 2 + 20·phase + step, 60 undecided
    std::map<int, std::vector<Case>> classes;
    for (const Case& c : left) {
        g_last = -1;
        stage0b(c);
        classes[g_last].push_back(c);
    }
    print_classes(classes);
#else
    std::printf("stage0 %.1f default %.1f left %.1f 0b %.1f (left %zu)\n", best_ns(all, stage0), best_ns(all, query),
                best_ns(left, query), best_ns(left, stage0b), left.size());
#endif
}
