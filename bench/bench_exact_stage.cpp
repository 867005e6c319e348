// The default query's exact stage alone (exact/answer.hpp), on the queries that reach
// exact arithmetic, beside the exact stage it replaced (§4, or §3 for turned frames, generically on
// GMP rationals in Q(√d): exact/paths.hpp) on the same queries (docs/robustness/exact-stage.md). Sets:
//   touching:       support/touching.hpp's exactly touching queries (seed 0x21e7, 4096 of them), those
//                   that reach exact arithmetic — split into integer (aligned, canonical,
//                   signed-permutation frames: §4 in integers) and turned (frames orthonormal only up
//                   to rounding: the parallelepiped test in integers)
//   boundary:       one-ulp boundary pairs of the random generator (support/cases.hpp, seed 0xb0c5c702,
//                   1024 pairs as in bench_pipeline, both members), those that reach exact arithmetic,
//                   integer frames (subnormal axis components beside full 53-bit mantissas)
//   turned route:   the parallelepiped route alone on random boxes turned by rounded rotations (seed
//                   0x7e57, 2048 of them, a third with values beyond 16 limbs), in each integer type
// and, for the ratio the goals are stated in, the default query and plain double §4
// ({Algorithm::inequalities, Arithmetic::float64}) on the whole touching set.
// Counter ns_per_query: CPU time per query (Google Benchmark prints it in seconds: "2.1us" is 2.1 µs).
// Run: bench_exact_stage --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>    // rotations
#include <cstdint>  // seeds
#include <optional>  // a frame without an exact canonical form
#include <random>   // the adversarial set
#include <type_traits>  // per box kind
#include <vector>   // the sets

#include "boxcyl/query.hpp"
#include "support/cases.hpp"
#include "support/near_touching.hpp"
#include "support/touching.hpp"

namespace {

using namespace boxcyl;
using boxcyl::testing::BoxKind;
using boxcyl::testing::Case;
using boxcyl::testing::with_box;

bool reaches_exact_stage(const Case& c) {
    return with_box(c, [](const auto& b, const Cylinder<double>& cyl) { return filtered::query(b, cyl).exact_used; });
}
bool integer_frame(const Case& c) {
    return c.kind != BoxKind::oriented || signed_permutation(c.oriented.axes).has_value();
}

struct Sets {
    std::vector<Case> touching_all, touching_integer, touching_turned, boundary_integer, adversarial_integer;
};

const Sets& sets() {
    static const Sets s = [] {
        Sets r;
        boxcyl::testing::TouchingGenerator gen(0x21e7);
        for (int i = 0; i < 4096; ++i) {
            const Case c = gen.next();
            r.touching_all.push_back(c);
            if (!reaches_exact_stage(c)) continue;
            (integer_frame(c) ? r.touching_integer : r.touching_turned).push_back(c);
        }
        boxcyl::testing::CaseGenerator bgen(0xb0c5c702);
        for (int found = 0; found < 1024;) {
            Case a, b;
            boxcyl::testing::Parameter which{};
            if (!boxcyl::testing::boundary_pair(bgen, a, b, which)) continue;
            ++found;
            for (const Case& c : {a, b})
                if (integer_frame(c) && reaches_exact_stage(c)) r.boundary_integer.push_back(c);
        }
        std::mt19937_64 arng(0xb0c5c706);
        for (int i = 0; i < 2048; ++i) {
            const Case c = boxcyl::testing::adversarial_case(arng);
            if (integer_frame(c) && reaches_exact_stage(c)) r.adversarial_integer.push_back(c);
        }
        return r;
    }();
    return s;
}

enum class Set { touching_integer, touching_turned, boundary_integer, adversarial_integer, touching_all };
const std::vector<Case>& set(Set which) {
    switch (which) {
        case Set::touching_integer: return sets().touching_integer;
        case Set::touching_turned: return sets().touching_turned;
        case Set::boundary_integer: return sets().boundary_integer;
        case Set::adversarial_integer: return sets().adversarial_integer;
        case Set::touching_all: break;
    }
    return sets().touching_all;
}

void counters(benchmark::State& state, std::size_t per_pass) {
    const double n = static_cast<double>(state.iterations()) * static_cast<double>(per_pass);
    state.counters["ns_per_query"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["queries"] = static_cast<double>(per_pass);
}

// A stage over one set: every query answered in order, hits counted.
template <class Stage>
void over(benchmark::State& state, Set which, Stage&& stage) {
    const std::vector<Case>& cases = set(which);
    for (auto _ : state) {
        long hits = 0;
        for (const Case& c : cases) hits += with_box(c, stage);
        benchmark::DoNotOptimize(hits);
    }
    counters(state, cases.size());
}

// The exact stage as it is now.
void exact_stage(benchmark::State& state, Set which) {
    over(state, which, [](const auto& b, const Cylinder<double>& cyl) { return *exact::answer(b, cyl); });
}

// The exact stage in integers without EpsilonSeries: FixedInt, then mpz_class.
template <class Box>
bool plain_integer(const Box& b, const Cylinder<double>& c) {
    if (const std::optional<bool> r = exact::integer::answer_small(b, c)) return *r;
    auto p = exact::integer::problem<mpz_class>(b, c);
    if constexpr (std::is_same_v<Box, OrientedBox<double>>) {
        if (!p) return *exact::answer(b, c);  // a turned frame: the parallelepiped test
        return exact::integer::intersects(*p);
    } else {
        return exact::integer::intersects(p);
    }
}
void plain_integer_stage(benchmark::State& state, Set which) {
    over(state, which, [](const auto& b, const Cylinder<double>& cyl) { return plain_integer(b, cyl); });
}

// The exact stage it replaced: §4 in Q(√d) where the canonical frame is exact, §3 in Q(√d) otherwise.
template <class Box>
bool rational_stage(const Box& b, const Cylinder<double>& c) {
    if constexpr (std::is_same_v<Box, OrientedBox<double>>) {
        const OrientedBox<Rational> eb = to_exact(b);
        const exact::Method m = exact::detail::exactly_orthonormal(eb) ? exact::Method::inequalities : exact::Method::hull;
        return exact::intersects(m, eb, to_exact(c));
    } else {
        return exact::intersects(exact::Method::inequalities, to_exact(b), to_exact(c));
    }
}
void rational_exact_stage(benchmark::State& state, Set which) {
    over(state, which, [](const auto& b, const Cylinder<double>& cyl) { return rational_stage(b, cyl); });
}

// The parallelepiped route on random rounded rotations: a box turned by two rounded angles, a cylinder
// of any direction, both of sizes 0.1–2 near the origin.
const std::vector<std::pair<Parallelepiped<double>, Cylinder<double>>>& turned_route_set() {
    static const auto s = [] {
        std::vector<std::pair<Parallelepiped<double>, Cylinder<double>>> r;
        std::mt19937_64 rng(0x7e57);
        std::uniform_real_distribution<double> u(-1, 1), size(0.1, 2);
        for (int i = 0; i < 2048; ++i) {
            const double a = 3 * u(rng), b = 3 * u(rng);
            const Vec3<double> x{std::cos(a), std::sin(a), 0};
            const Vec3<double> y{-std::sin(a) * std::cos(b), std::cos(a) * std::cos(b), std::sin(b)};
            const Parallelepiped<double> box{{u(rng), u(rng), u(rng)}, {x, y, cross(x, y)}, {size(rng), size(rng), size(rng)}};
            const Cylinder<double> cyl{{3 * u(rng), 3 * u(rng), 3 * u(rng)}, {u(rng), u(rng), u(rng)}, size(rng), size(rng)};
            r.emplace_back(box, cyl);
        }
        return r;
    }();
    return s;
}
enum class Route { stage, small_then_mpz, mpz };
void turned_route(benchmark::State& state, Route route) {
    const auto& cases = turned_route_set();
    for (auto _ : state) {
        long hits = 0;
        for (const auto& [b, c] : cases) {
            switch (route) {
                case Route::stage: hits += exact::integer::intersects_parallelepiped(b, c); break;
                case Route::small_then_mpz: {  // 16 limbs, then mpz_class
                    FixedOverflow::flag() = false;
                    const bool r = exact::integer::detail::run_turned<exact::integer::Small>(b, c);
                    hits += FixedOverflow::flag() ? exact::integer::detail::run_turned<mpz_class>(b, c) : r;
                    break;
                }
                case Route::mpz: hits += exact::integer::detail::run_turned<mpz_class>(b, c); break;
            }
        }
        benchmark::DoNotOptimize(hits);
    }
    counters(state, cases.size());
}

void query(benchmark::State& state, QueryOptions opt) {
    const std::vector<Case>& cases = set(Set::touching_all);
    for (auto _ : state) {
        long hits = 0;
        for (const Case& c : cases)
            hits += with_box(c, [&opt](const auto& b, const Cylinder<double>& cyl) { return intersects(b, cyl, opt); });
        benchmark::DoNotOptimize(hits);
    }
    counters(state, cases.size());
}

}  // namespace

BENCHMARK_CAPTURE(exact_stage, touching_integer, Set::touching_integer);
BENCHMARK_CAPTURE(rational_exact_stage, touching_integer, Set::touching_integer);
BENCHMARK_CAPTURE(exact_stage, touching_turned, Set::touching_turned);
BENCHMARK_CAPTURE(rational_exact_stage, touching_turned, Set::touching_turned);
BENCHMARK_CAPTURE(exact_stage, boundary_integer, Set::boundary_integer);
BENCHMARK_CAPTURE(plain_integer_stage, boundary_integer, Set::boundary_integer);
BENCHMARK_CAPTURE(rational_exact_stage, boundary_integer, Set::boundary_integer);
BENCHMARK_CAPTURE(exact_stage, adversarial_integer, Set::adversarial_integer);
BENCHMARK_CAPTURE(plain_integer_stage, adversarial_integer, Set::adversarial_integer);
BENCHMARK_CAPTURE(rational_exact_stage, adversarial_integer, Set::adversarial_integer);
BENCHMARK_CAPTURE(turned_route, stage, Route::stage);
BENCHMARK_CAPTURE(turned_route, fixed16_then_mpz, Route::small_then_mpz);
BENCHMARK_CAPTURE(turned_route, mpz, Route::mpz);
BENCHMARK_CAPTURE(query, touching_default, QueryOptions{});
BENCHMARK_CAPTURE(query, touching_float64, QueryOptions{Algorithm::inequalities, Arithmetic::float64});

BENCHMARK_MAIN();
