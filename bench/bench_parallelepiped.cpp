// Time per query of the default exact query on boxcyl::Parallelepiped (filtered.hpp),
// beside plain double §3 on the same parallelepipeds, the exact stage alone, and the oriented-box
// default query on the same solids where they are oriented boxes; and the fraction of queries that
// reach the exact stage. Data sets (fixed seeds, generated before timing, answers checked against the
// oracle untimed):
//   integer    orthogonal axes of equal integer length from integer quaternions (e.g. (3,4,0),
//              (−4,3,0), (0,0,5)), integer centres and extents: rotated, scaled block models
//   general    random axes in [−2, 2]³ (skewed, any lengths)
//   flat       as general with one axis the sum of the other two (a hexagon in a plane)
//   rotated    rotation matrices rounded to double, as Parallelepiped and as OrientedBox
// Cylinders: random centres, axes, radii and heights at the boxes' scale.
// Run: bench_parallelepiped --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>    // std::sqrt, std::cos, std::sin
#include <cstdint>  // std::int64_t
#include <cstdio>   // std::printf
#include <map>      // the data sets by kind
#include <random>   // std::mt19937_64
#include <string>   // names
#include <vector>   // data sets

#include "boxcyl/exact/answer.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/oracle/oracle.hpp"
#include "boxcyl/query.hpp"

namespace {

using namespace boxcyl;
using P = Parallelepiped<double>;
using C = Cylinder<double>;

constexpr std::size_t kQueries = 4096;
constexpr std::size_t kSlow = 128;  // the exact stage alone: the first 128

struct Set {
    std::vector<P> boxes;
    std::vector<C> cylinders;
};

Set make(const std::string& kind, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1), pos(0, 1);
    std::uniform_int_distribution<int> small(-3, 3), ext(1, 4), coord(-10, 10);
    Set s;
    for (std::size_t n = 0; n < kQueries; ++n) {
        P b;
        double scale = 1;
        if (kind == "integer") {
            double w = 0, x = 0, y = 0, z = 0;
            while (w == 0 && x == 0 && y == 0 && z == 0) w = small(rng), x = small(rng), y = small(rng), z = small(rng);
            b.axes[0] = {w * w + x * x - y * y - z * z, 2 * (x * y + w * z), 2 * (x * z - w * y)};
            b.axes[1] = {2 * (x * y - w * z), w * w - x * x + y * y - z * z, 2 * (y * z + w * x)};
            b.axes[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), w * w - x * x - y * y + z * z};
            b.center = {double(coord(rng)), double(coord(rng)), double(coord(rng))};
            b.extents = {double(ext(rng)), double(ext(rng)), double(ext(rng))};
            scale = (w * w + x * x + y * y + z * z) * 4;
        } else if (kind == "rotated") {
            const double a = std::acos(u(rng)), phi = 3.14159 * u(rng), psi = 3.14159 * u(rng);
            const Vec3<double> k{std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi), std::cos(a)};
            const double c = std::cos(psi), s1 = std::sin(psi);
            for (int i = 0; i < 3; ++i) {  // Rodrigues: R e_i
                Vec3<double> e{0, 0, 0};
                e[i] = 1;
                b.axes[i] = c * e + s1 * cross(k, e) + ((1 - c) * dot(k, e)) * k;
            }
            b.center = {u(rng), u(rng), u(rng)};
            b.extents = {pos(rng), pos(rng), pos(rng)};
            scale = 2;
        } else {
            for (auto& a : b.axes) a = {2 * u(rng), 2 * u(rng), 2 * u(rng)};
            if (kind == "flat") b.axes[2] = b.axes[0] + b.axes[1];
            b.center = {u(rng), u(rng), u(rng)};
            b.extents = {pos(rng), pos(rng), pos(rng)};
            scale = 3;
        }
        s.boxes.push_back(b);
        s.cylinders.push_back({{scale * u(rng), scale * u(rng), scale * u(rng)}, {u(rng), u(rng), u(rng)},
                               0.5 * scale * pos(rng), scale * pos(rng)});
    }
    return s;
}

const char* kKinds[] = {"integer", "general", "flat", "rotated"};

const Set& set_of(const std::string& kind) {
    static std::map<std::string, Set> sets;
    auto it = sets.find(kind);
    if (it == sets.end()) it = sets.emplace(kind, make(kind, 0xB0C5C710 + kind.size())).first;
    return it->second;
}

void default_query(benchmark::State& st, const std::string& kind) {
    const Set& s = set_of(kind);
    for (auto _ : st)
        for (std::size_t i = 0; i < kQueries; ++i) benchmark::DoNotOptimize(intersects(s.boxes[i], s.cylinders[i]));
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(kQueries));
}
void double_hull(benchmark::State& st, const std::string& kind) {
    const Set& s = set_of(kind);
    const QueryOptions opt{Algorithm::hull, Arithmetic::float64};
    for (auto _ : st)
        for (std::size_t i = 0; i < kQueries; ++i) benchmark::DoNotOptimize(intersects(s.boxes[i], s.cylinders[i], opt));
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(kQueries));
}
void exact_stage(benchmark::State& st, const std::string& kind) {
    const Set& s = set_of(kind);
    for (auto _ : st)
        for (std::size_t i = 0; i < kSlow; ++i)
            benchmark::DoNotOptimize(*exact::answer(s.boxes[i], s.cylinders[i]));
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(kSlow));
}
void as_oriented_box(benchmark::State& st) {
    const Set& s = set_of("rotated");
    std::vector<OrientedBox<double>> o;
    for (const P& b : s.boxes) o.push_back({b.center, b.axes, b.extents});
    for (auto _ : st)
        for (std::size_t i = 0; i < kQueries; ++i) benchmark::DoNotOptimize(intersects(o[i], s.cylinders[i]));
    st.SetItemsProcessed(st.iterations() * static_cast<std::int64_t>(kQueries));
}

// Untimed: every default answer against the oracle, and the exact-stage fraction.
bool check() {
    bool ok = true;
    for (const char* kind : kKinds) {
        const Set& s = set_of(kind);
        std::size_t exact = 0, hits = 0;
        for (std::size_t i = 0; i < kQueries; ++i) {
            const filtered::Result r = filtered::query(s.boxes[i], s.cylinders[i]);
            const bool want = oracle::intersects(to_exact(s.boxes[i]), to_exact(s.cylinders[i]));
            if (r.intersect != want) {
                std::printf("MISMATCH %s #%zu\n", kind, i);
                ok = false;
            }
            exact += r.exact_used;
            hits += want;
        }
        std::printf("%-8s %zu queries, %zu hits, %zu (%.2f%%) answered by the exact stage\n", kind, kQueries, hits,
                    exact, 100.0 * double(exact) / kQueries);
    }
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (!check()) return 1;
    for (const char* kind : kKinds) {
        benchmark::RegisterBenchmark((std::string("default/") + kind).c_str(), default_query, std::string(kind));
        benchmark::RegisterBenchmark((std::string("double_hull/") + kind).c_str(), double_hull, std::string(kind));
        benchmark::RegisterBenchmark((std::string("exact_stage/") + kind).c_str(), exact_stage, std::string(kind));
    }
    benchmark::RegisterBenchmark("oriented_box_default/rotated", as_oriented_box);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
