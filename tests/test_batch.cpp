// The batch API (boxcyl/batch.hpp) against the scalar exact default boxcyl::intersects(box,
// cylinder), bit for bit: random sets around CaseGenerator cylinders (segments, disks, tiny axis
// components included), boxes one ulp from touching, degenerate boxes and cylinders, huge and tiny
// magnitudes, float inputs (widened exactly), every batch length 0..3·lanes+1 (all remainders), both
// outputs (bit mask, bools), and 1/2/4 threads on a large N — each through every kernel this machine
// runs (the header's own and boxcyl::batch_dispatch's AVX2 and AVX-512 ones: BatchKernels/…/compiled,
// …/avx2, …/avx512). Every failure prints the case as copy-pasteable C++ (hex floats). The filter's
// undecided fraction of each set is printed.
#include <gtest/gtest.h>

#include <algorithm>  // std::max
#include <array>    // frames
#include <cfenv>    // rounding modes
#include <chrono>   // the stop's latency
#include <cmath>    // std::ldexp, std::nextafter
#include <cstddef>  // std::size_t, std::ptrdiff_t
#include <cstdint>  // std::uint64_t
#include <cstdio>   // std::printf
#include <iterator>  // std::size
#include <limits>   // NaN and infinity for the checked boxes
#include <memory>   // std::unique_ptr<bool[]>
#include <ostream>  // PrintTo
#include <stdexcept>  // unavailable kernels
#include <random>   // voxel placement
#include <stop_token>  // Options::stop
#include <string>   // labels
#include <thread>   // a stop requested from another thread
#include <vector>   // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"
#include "boxcyl/query.hpp"
#include "support/batch_cases.hpp"
#include "support/batch_kernels.hpp"
#include "support/fp.hpp"
#include "support/runner.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

std::string show(const AlignedBox<double>& b, const Cylinder<double>& c) {
    Case k;
    k.kind = BoxKind::aligned, k.aligned = b, k.cylinder = c;
    return describe(k);
}
std::string show(const OrientedBox<double>& b, const Cylinder<double>& c) {
    Case k;
    k.kind = BoxKind::oriented, k.oriented = b, k.cylinder = c;
    return describe(k);
}

// The six arrays of a set of aligned boxes, in T (double, or float when the boxes are floats).
template <class T>
struct Soa {
    std::vector<T> v[6];
    explicit Soa(const std::vector<AlignedBox<double>>& boxes) {
        for (const AlignedBox<double>& b : boxes)
            for (int j = 0; j < 3; ++j) v[j].push_back(static_cast<T>(b.min[j])), v[3 + j].push_back(static_cast<T>(b.max[j]));
    }
    batch::AlignedBoxes<T> view() const { return {v[0], v[1], v[2], v[3], v[4], v[5]}; }
};

template <class T, class U>
std::vector<OrientedBox<T>> narrowed(const std::vector<OrientedBox<U>>& boxes) {
    std::vector<OrientedBox<T>> out;
    out.reserve(boxes.size());
    auto n = [](const Vec3<U>& v) { return Vec3<T>{static_cast<T>(v[0]), static_cast<T>(v[1]), static_cast<T>(v[2])}; };
    for (const OrientedBox<U>& b : boxes) out.push_back({n(b.center), {n(b.axes[0]), n(b.axes[1]), n(b.axes[2])}, n(b.extents)});
    return out;
}

// The kernel the BatchKernels tests run (set by the fixture); Kernel::compiled for the plain tests.
batch::Kernel g_kernel = batch::Kernel::compiled;

struct Count {
    long boxes = 0, exact = 0;
};

// Runs the batch (mask and bools) on boxes[0, n) and compares every answer with want[i].
Cylinder<double> as_double(const Cylinder<double>& c) { return c; }
Cylinder<double> as_double(const Cylinder<float>& c) { return batch::detail::widen(c); }

template <class Cyl, class Boxes, class Box>
void compare(const Cyl& cyl, const Boxes& view, const std::vector<Box>& boxes, const std::vector<bool>& want,
             std::size_t n, unsigned threads, const std::string& where, Count& count) {
    std::vector<std::uint64_t> mask(batch::mask_words(n) + 1, ~std::uint64_t{0});
    const batch::Options opt{threads, g_kernel};
    const batch::Stats st = batch::intersects(cyl, view, std::span<std::uint64_t>(mask), opt);
    std::unique_ptr<bool[]> bools(new bool[n + 1]);
    const batch::Stats sb = batch::intersects(cyl, view, std::span<bool>(bools.get(), n), opt);
    EXPECT_EQ(st.boxes, n);
    EXPECT_EQ(st.kernel, g_kernel) << where;
    EXPECT_EQ(sb.kernel, g_kernel) << where;
    EXPECT_EQ(st.exact_lanes, sb.exact_lanes) << where;
    count.boxes += static_cast<long>(n);
    count.exact += static_cast<long>(st.exact_lanes);
    int failures = 0;
    for (std::size_t i = 0; i < n && failures < 5; ++i) {
        const bool got = (mask[i / 64] >> (i % 64)) & 1u;
        if (got != want[i] || bools[i] != want[i]) {
            ++failures;
            ADD_FAILURE() << where << " box " << i << " of " << n << " (kernel " << batch::name(g_kernel) << ", threads "
                          << threads << "): batch says " << got
                          << " (bools " << bools[i] << "), scalar default " << want[i] << "\n  " << show(boxes[i], as_double(cyl));
        }
    }
    if (n % 64 != 0) {
        EXPECT_EQ(mask[n / 64] >> (n % 64), 0u) << where << ": bits beyond the last box must be 0";
    }
    EXPECT_EQ(mask[batch::mask_words(n)], ~std::uint64_t{0}) << where << ": wrote past the mask";
}

template <class Box>
std::vector<bool> scalar_answers(const Cylinder<double>& cyl, const std::vector<Box>& boxes) {
    std::vector<bool> want;
    want.reserve(boxes.size());
    for (const Box& b : boxes) want.push_back(boxcyl::intersects(b, cyl));
    return want;
}

// Every check of one set: double and float inputs, both box kinds, both outputs.
void check_set(const Cylinder<double>& cyl, const std::vector<AlignedBox<double>>& aligned,
               const std::vector<OrientedBox<double>>& oriented, const std::string& where, Count& ca, Count& co,
               unsigned threads = 1) {
    const std::vector<bool> wa = scalar_answers(cyl, aligned), wo = scalar_answers(cyl, oriented);
    const Soa<double> sa(aligned);
    compare(cyl, sa.view(), aligned, wa, aligned.size(), threads, where + " aligned", ca);
    compare(cyl, std::span<const AlignedBox<double>>(aligned), aligned, wa, aligned.size(), threads,
            where + " aligned rows", ca);
    const std::vector<OrientedBox<double>>& od = oriented;
    compare(cyl, std::span<const OrientedBox<double>>(od), oriented, wo, oriented.size(), threads, where + " oriented", co);
}

// The same set with every input rounded to float (cylinder too): the answers are those of the
// widened values.
void check_float(const BatchSet& s, const std::string& where, Count& ca, Count& co) {
    const Cylinder<float> cf{{float(s.cylinder.center[0]), float(s.cylinder.center[1]), float(s.cylinder.center[2])},
                             {float(s.cylinder.axis[0]), float(s.cylinder.axis[1]), float(s.cylinder.axis[2])},
                             float(s.cylinder.radius), float(s.cylinder.height)};
    const Cylinder<double> cd = batch::detail::widen(cf);
    if (!validate(cd).ok()) return;  // e.g. an axis whose components all round to 0 in float
    const Soa<float> sf(s.aligned);
    std::vector<AlignedBox<double>> aw;
    for (std::size_t i = 0; i < s.aligned.size(); ++i)
        aw.push_back({{double(sf.v[0][i]), double(sf.v[1][i]), double(sf.v[2][i])},
                      {double(sf.v[3][i]), double(sf.v[4][i]), double(sf.v[5][i])}});
    const std::vector<OrientedBox<float>> of = narrowed<float>(s.oriented);
    const std::vector<OrientedBox<double>> ow = narrowed<double>(narrowed<float>(s.oriented));
    std::vector<AlignedBox<double>> av;
    std::vector<bool> wa;
    std::vector<OrientedBox<double>> ov;
    std::vector<bool> wo;
    // Rounding to float may break validity (an axis frame, min ≤ max cannot break): keep valid boxes.
    Soa<float> keep_a(std::vector<AlignedBox<double>>{});
    std::vector<OrientedBox<float>> keep_o;
    for (std::size_t i = 0; i < aw.size(); ++i)
        if (validate(aw[i]).ok()) {
            av.push_back(aw[i]);
            for (int j = 0; j < 6; ++j) keep_a.v[j].push_back(sf.v[j][i]);
        }
    for (std::size_t i = 0; i < ow.size(); ++i)
        if (validate(ow[i]).ok()) ov.push_back(ow[i]), keep_o.push_back(of[i]);
    wa = scalar_answers(cd, av);
    wo = scalar_answers(cd, ov);
    compare(cf, keep_a.view(), av, wa, av.size(), 1, where + " float aligned", ca);
    std::vector<AlignedBox<float>> rows;
    for (std::size_t i = 0; i < av.size(); ++i)
        rows.push_back({{keep_a.v[0][i], keep_a.v[1][i], keep_a.v[2][i]}, {keep_a.v[3][i], keep_a.v[4][i], keep_a.v[5][i]}});
    compare(cf, std::span<const AlignedBox<float>>(rows), av, wa, av.size(), 1, where + " float aligned rows", ca);
    compare(cf, std::span<const OrientedBox<float>>(keep_o), ov, wo, ov.size(), 1, where + " float oriented", co);
}

void print(const char* label, const Count& a, const Count& o) {
    std::printf("%-40s aligned %7ld boxes, to the scalar path %5.2f%%   oriented %7ld, %5.2f%%\n", label, a.boxes,
                a.boxes ? 100.0 * double(a.exact) / double(a.boxes) : 0.0, o.boxes,
                o.boxes ? 100.0 * double(o.exact) / double(o.boxes) : 0.0);
}

TEST(Batch, EnvironmentIsDefault) { EXPECT_TRUE(fp_environment_ok()); }

class BatchKernels : public ::testing::TestWithParam<batch::Kernel> {
protected:
    void SetUp() override { g_kernel = GetParam(); }
    void TearDown() override { g_kernel = batch::Kernel::compiled; }
};

INSTANTIATE_TEST_SUITE_P(Kernels, BatchKernels, ::testing::ValuesIn(runnable_kernels()),
                         [](const ::testing::TestParamInfo<batch::Kernel>& info) { return std::string(batch::name(info.param)); });

// The run-time choice: a kernel is offered exactly when this CPU runs it (GCC's own CPUID/XGETBV
// reading, as dispatch.cpp's), `automatic` takes the widest, and asking for one this machine lacks
// throws rather than running something else.
TEST(Batch, KernelChoiceFollowsTheCpu) {
    std::string ran;
    for (batch::Kernel k : runnable_kernels()) ran += std::string(" ") + batch::name(k);
    std::printf("[ info ] kernels run here:%s\n", ran.c_str());
    EXPECT_TRUE(batch::available(batch::Kernel::compiled));
    EXPECT_TRUE(batch::available(batch::Kernel::automatic));
#if defined(BOXCYL_TEST_EXPECT_KERNELS)
    __builtin_cpu_init();
    const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
    const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw");
    EXPECT_EQ(batch::available(batch::Kernel::avx2), avx2);
    EXPECT_EQ(batch::available(batch::Kernel::avx512), avx512);
#endif
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 1, 2};
    const std::vector<double> lo{-0.5, 3}, hi{0.5, 4};
    const batch::AlignedBoxes<double> boxes{lo, lo, lo, hi, hi, hi};
    std::vector<std::uint64_t> mask(1);
    std::size_t widest = 0;
    for (batch::Kernel k : {batch::Kernel::compiled, batch::Kernel::avx2, batch::Kernel::avx512}) {
        if (!batch::available(k)) {
            EXPECT_THROW(batch::intersects(c, boxes, std::span<std::uint64_t>(mask), {1, k}), std::invalid_argument)
                << batch::name(k);
            continue;
        }
        const batch::Stats st = batch::intersects(c, boxes, std::span<std::uint64_t>(mask), {1, k});
        EXPECT_EQ(mask[0], 1u) << batch::name(k);  // box 0 holds the centre; box 1 is above the top
        EXPECT_EQ(st.kernel, k);
        const std::size_t want = k == batch::Kernel::avx512 ? 8 : k == batch::Kernel::avx2 ? 4 : batch::lane_count;
        EXPECT_EQ(st.lanes, want) << batch::name(k);
        widest = std::max(widest, st.lanes);
    }
    const batch::Stats st = batch::intersects(c, boxes, std::span<std::uint64_t>(mask));
    EXPECT_EQ(st.lanes, widest) << "automatic must take the widest kernel";
    EXPECT_NE(st.kernel, batch::Kernel::automatic);
}

// Random sets: 150 cylinders × 150 boxes of each kind, double and float.
TEST_P(BatchKernels, RandomSetsAgreeWithScalar) {
    Count ca, co, fa, fo;
    const long sets = scaled(150);
    for (long k = 0; k < sets; ++k) {
        const std::uint64_t seed = 0xBA7C4000 + static_cast<std::uint64_t>(k);
        const BatchSet s = random_batch(seed, 150, k % 4 == 3 ? Profile::degenerate : Profile::mixed);
        check_set(s.cylinder, s.aligned, s.oriented, "random seed " + std::to_string(seed), ca, co);
        if (k % 3 == 0) check_float(s, "random seed " + std::to_string(seed), fa, fo);
    }
    print("random sets (double)", ca, co);
    print("random sets (float inputs)", fa, fo);
}

// Every length 0..3·8 + 1 (every remainder modulo each kernel's width — 2, 4 or 8 — and short tails),
// from several offsets into a set so that different boxes land in the tail.
TEST_P(BatchKernels, EveryLengthAndRemainder) {
    Count ca, co;
    const std::size_t max_len = 3 * 8 + 1;  // the widest kernel's 8 lanes
    for (std::uint64_t seed : {0xBA7C5001ull, 0xBA7C5002ull, 0xBA7C5003ull}) {
        const BatchSet s = random_batch(seed, 64 + max_len);
        for (std::size_t offset : {std::size_t{0}, std::size_t{5}, std::size_t{64}}) {
            for (std::size_t len = 0; len <= max_len; ++len) {
                const auto from = static_cast<std::ptrdiff_t>(offset), to = static_cast<std::ptrdiff_t>(offset + len);
                const std::vector<AlignedBox<double>> a(s.aligned.begin() + from, s.aligned.begin() + to);
                const std::vector<OrientedBox<double>> o(s.oriented.begin() + from, s.oriented.begin() + to);
                check_set(s.cylinder, a, o,
                          "seed " + std::to_string(seed) + " offset " + std::to_string(offset) + " length " + std::to_string(len),
                          ca, co);
            }
        }
    }
    print("every length 0..3*8+1", ca, co);
}

// Boxes one ulp from touching, on both sides (40 pairs of each kind per cylinder).
TEST_P(BatchKernels, BoundaryPairsAgreeWithScalar) {
    Count ca, co;
    const long sets = scaled(6);
    for (long k = 0; k < sets; ++k) {
        const std::uint64_t seed = 0xBA7C6000 + static_cast<std::uint64_t>(k);
        const BatchSet s = random_batch(seed, 200);
        std::vector<AlignedBox<double>> a;
        std::vector<OrientedBox<double>> o;
        append_boundary(s.cylinder, s.aligned, 40, a);
        append_boundary(s.cylinder, s.oriented, 40, o);
        check_set(s.cylinder, a, o, "boundary seed " + std::to_string(seed), ca, co);
    }
    print("one-ulp boundary boxes", ca, co);
}

// Degenerate boxes and cylinders, with exactly touching configurations.
TEST_P(BatchKernels, DegenerateAndTouching) {
    Count ca, co;
    const std::array<Vec3<double>, 3> id{Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}};
    const std::vector<Cylinder<double>> cyls{
        {{0, 0, 0}, {0, 0, 1}, 1, 2},        // axis-aligned: touching faces are exact
        {{0, 0, 0}, {0, 0, 1}, 0, 2},        // segment
        {{0, 0, 0}, {0, 0, 1}, 1, 0},        // disk
        {{0, 0, 0}, {1, 1, 1}, 0, 0},        // point
        {{0.5, -0.25, 3}, {3, 4, 0}, 2, 5},  // exactly rational unit axis (3/5, 4/5, 0)
        {{1, 2, 3}, {1, 1e-300, 0}, 1, 1},   // tiny axis component
    };
    for (std::size_t ci = 0; ci < cyls.size(); ++ci) {
        const Cylinder<double>& c = cyls[ci];
        std::vector<AlignedBox<double>> a;
        std::vector<OrientedBox<double>> o;
        for (double x : {-3.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 3.0})
            for (double z : {-2.0, -1.0, 0.0, 1.0, 2.0}) {
                const Vec3<double> p{c.center[0] + x, c.center[1], c.center[2] + z};
                for (double w : {0.0, 0.5, 1.0}) {
                    a.push_back({{p[0], p[1] - w, p[2]}, {p[0] + w, p[1] + w, p[2] + w}});  // flat, point, cube
                    a.push_back({{std::nextafter(p[0], 9.0), p[1], p[2] - w}, {p[0] + 1, p[1] + w, p[2]}});
                    o.push_back({p, id, {w, 0.5 * w, 0}});
                    o.push_back({p, {Vec3<double>{0.6, 0.8, 0}, Vec3<double>{-0.8, 0.6, 0}, Vec3<double>{0, 0, 1}}, {w, w, w}});
                }
            }
        a.push_back({{-1e6, -1e6, -1e6}, {1e6, 1e6, 1e6}});  // contains the cylinder
        o.push_back({c.center, id, {1e6, 1e6, 1e6}});
        check_set(c, a, o, "degenerate cylinder " + std::to_string(ci), ca, co);
    }
    print("degenerate and touching", ca, co);
}

// Small cubes (voxels) whose bounding ball just touches the cylinder's lateral surface from outside
// or inside — the threshold of the aligned filter's ball test — and a regular voxel grid around thin
// cylinders: every answer must equal the scalar one.
TEST_P(BatchKernels, VoxelsNearTheSurface) {
    Count ca, co;
    const std::array<Vec3<double>, 3> id{Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}};
    const std::vector<Cylinder<double>> cyls{
        {{0.3, -0.2, 0.1}, {0.8, 0.5, 0.33}, 2, 40},
        {{0, 0, 0}, {1, 1, 1}, 0.5, 10},
        {{1, 2, 3}, {0, 0, 1}, 3, 5},
    };
    std::mt19937_64 rng(7101);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (std::size_t ci = 0; ci < cyls.size(); ++ci) {
        const Cylinder<double>& c = cyls[ci];
        const double len = std::sqrt(dot(c.axis, c.axis));
        const Vec3<double> u{c.axis[0] / len, c.axis[1] / len, c.axis[2] / len};
        std::vector<AlignedBox<double>> a;
        std::vector<OrientedBox<double>> o;
        for (double half : {0.0625, 0.25}) {
            const double delta = half * std::sqrt(3.0);
            for (int n = 0; n < 60; ++n) {
                // w: a random unit vector perpendicular to the axis.
                Vec3<double> w{unit(rng), unit(rng), unit(rng)};
                const double along = dot(w, u);
                w = w - along * u;
                const double wl = std::sqrt(dot(w, w));
                w = Vec3<double>{w[0] / wl, w[1] / wl, w[2] / wl};
                const double t = unit(rng) * 0.6 * c.height;
                for (double f : {-1e-3, -1e-9, -1e-15, 0.0, 1e-15, 1e-9, 1e-3, -1.0, 1.0}) {
                    const double rho = c.radius + delta * (1 + f);
                    const Vec3<double> p = c.center + t * u + rho * w;
                    a.push_back({{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}});
                    o.push_back({p, id, {half, half, half}});
                }
            }
        }
        // A voxel grid over the cylinder's neighbourhood (cells of side 1/8).
        for (int i = -24; i <= 24; ++i)
            for (int j = -24; j <= 24; j += 3)
                for (int k = -24; k <= 24; k += 3) {
                    const Vec3<double> p{c.center[0] + i * 0.125, c.center[1] + j * 0.125, c.center[2] + k * 0.125};
                    a.push_back({p, {p[0] + 0.125, p[1] + 0.125, p[2] + 0.125}});
                }
        check_set(c, a, o, "voxels near cylinder " + std::to_string(ci), ca, co);
    }
    print("voxels near the surface", ca, co);
}

// The first pass alone (detail::aligned_ball_lanes: bounding boxes, then the box's centre and a ball
// around it, then the box point nearest to C), on the boxes at its thresholds: point boxes a few ulps
// from the lateral surface and the end planes, and cubes whose 1-norm ball (radius 3·half in the
// doubled test), whose centre or whose corner nearest C is at the threshold, from both sides. Every
// lane it decides must agree with the scalar exact default; with the ball's allowance κ set to 0 some
// of these decisions must come out wrong (the test has teeth; the nearest point's tests are
// point_tests, whose thresholds the one-ulp boundary sets probe).
TEST(Batch, BallPassDecisionsAreExact) {
    const std::vector<Cylinder<double>> cyls{
        {{0.3, -0.2, 0.1}, {0.8, 0.5, 0.33}, 2, 40},
        {{1e3, -7.25, 3}, {1, 1, 1}, 0.5, 10},
        {{1, 2, 3}, {0, 0, 1}, 3, 5},
        {{-346274.5, 157055.25, 134998}, {-1.18576e-322, -0.662192, 0}, 79239, 117936},  // tiny axis component
        {{0x1.41d4ce5ebfd3fp+426, 0x1.9791a7df4cb9cp+429, 0x1.eabc95b8739d9p+428}, {0, -0x1.2e97f346c8d9p-2, 0},
         0x1.49cddb1c1ef17p+428, 0x1.4a0bbbc271c88p+429},  // beyond 2^200: not filtered (once missed wrongly)
    };
    std::mt19937_64 rng(7102);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<std::pair<std::size_t, AlignedBox<double>>> boxes;  // (cylinder, box)
    for (std::size_t ci = 0; ci < cyls.size(); ++ci) {
        const Cylinder<double>& c = cyls[ci];
        const double len = std::sqrt(dot(c.axis, c.axis));
        const Vec3<double> u{c.axis[0] / len, c.axis[1] / len, c.axis[2] / len};
        const double H = c.height / 2, r = c.radius;
        for (int n = 0; n < 150; ++n) {
            Vec3<double> w{unit(rng), unit(rng), unit(rng)};
            w = w - dot(w, u) * u;
            const double wl = std::sqrt(dot(w, w));
            w = Vec3<double>{w[0] / wl, w[1] / wl, w[2] / wl};
            const double t = unit(rng) * H, half = std::ldexp(1.0, -4 - n % 12) * (r + H);
            // (radial offset, axial position, half side) of the box's centre, or with corner = 1 of the box's
            // corner nearest C (the box reaches away from C by twice the half side along each axis)
            const double ends = (n % 2 ? 1 : -1) * H;
            const double probes[][4] = {
                {r, t, 0, 0}, {r, ends * 0.5, 0, 0}, {r * 0.5, ends, 0, 0},  // points on the surface
                {r + 3 * half, t, half, 0}, {r * 0.5, ends + (n % 2 ? 3 : -3) * half, half, 0},  // 1-norm balls touching
                {r, t, half, 0}, {r * 0.25, ends, half, 0},                  // centres on the surface
                {r, t, half, 1}, {r * 0.5, ends, half, 1},                   // nearest corners on the surface
            };
            for (const auto& pr : probes) {
                const Vec3<double> p = c.center + pr[1] * u + pr[0] * w;
                for (int k = -3; k <= 3; ++k) {
                    Vec3<double> q = p;
                    for (int j = 0; j < 3; ++j)
                        for (int step = 0; step < (k < 0 ? -k : k); ++step) q[j] = std::nextafter(q[j], k < 0 ? -1e300 : 1e300);
                    AlignedBox<double> b{{q[0] - pr[2], q[1] - pr[2], q[2] - pr[2]}, {q[0] + pr[2], q[1] + pr[2], q[2] + pr[2]}};
                    if (pr[3] != 0)
                        for (int j = 0; j < 3; ++j) {
                            const bool away = q[j] >= c.center[j];
                            b.min[j] = away ? q[j] : q[j] - 2 * pr[2];
                            b.max[j] = away ? q[j] + 2 * pr[2] : q[j];
                        }
                    boxes.push_back({ci, b});
                }
            }
        }
    }
    auto run = [&](bool zero_kappa, long& decided, long& wrong) {
        decided = wrong = 0;
        for (const auto& [ci, b] : boxes) {
            batch::detail::CylinderFilter f = batch::detail::prepare(cyls[ci]);
            if (zero_kappa) f.kappa = 0, f.ball.kappa = 0;
            batch::Lanes lo[3], hi[3];
            for (int j = 0; j < 3; ++j) lo[j] = b.min[j], hi[j] = b.max[j];
            const batch::detail::LaneResult r = batch::detail::aligned_ball_lanes(f, lo, hi);
            if (!r.decided[0]) continue;
            ++decided;
            const bool want = boxcyl::intersects(b, cyls[ci]);
            if (r.hit[0] != want) {
                ++wrong;
                if (!zero_kappa && wrong <= 5)
                    ADD_FAILURE() << "first pass says " << r.hit[0] << ", scalar " << want << "\n  " << show(b, cyls[ci]);
            }
        }
    };
    long decided = 0, wrong = 0;
    run(false, decided, wrong);
    std::printf("first pass: %zu boxes at its thresholds, %ld decided, %ld wrong\n", boxes.size(), decided, wrong);
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(decided, 1000) << "the first pass decides the probes a few ulps clear of its thresholds (10821 of 47250 when written)";
    run(true, decided, wrong);
    std::printf("first pass with kappa = 0: %ld decided, %ld wrong\n", decided, wrong);
    EXPECT_GT(wrong, 0) << "with no error allowance some threshold boxes must be decided wrongly: the data lacks teeth";
}

// Whole sets scaled by 2^k (exact in the normal range; the answers are the scalar's either way), and
// sets mixing huge and tiny boxes with an ordinary cylinder.
TEST_P(BatchKernels, HugeAndTinyMagnitudes) {
    Count ca, co;
    for (int k : {-1060, -1000, -700, -300, 300, 700, 1000}) {
        BatchSet s = random_batch(0xBA7C7000 + static_cast<std::uint64_t>(k + 2000), 120);
        auto sc = [k](double x) { return std::ldexp(x, k); };
        auto sv = [&](Vec3<double>& v) { v = {sc(v[0]), sc(v[1]), sc(v[2])}; };
        sv(s.cylinder.center), s.cylinder.radius = sc(s.cylinder.radius), s.cylinder.height = sc(s.cylinder.height);
        if (!validate(s.cylinder).ok()) continue;
        for (AlignedBox<double>& b : s.aligned) sv(b.min), sv(b.max);
        for (OrientedBox<double>& b : s.oriented) sv(b.center), sv(b.extents);
        check_set(s.cylinder, s.aligned, s.oriented, "scaled by 2^" + std::to_string(k), ca, co);
    }
    BatchSet s = random_batch(0xBA7C7100, 200);
    for (std::size_t i = 0; i < s.aligned.size(); i += 3) {
        const int k = (i % 2) ? 900 : -900;
        for (int j = 0; j < 3; ++j) {
            s.aligned[i].min[j] = std::ldexp(s.aligned[i].min[j], k), s.aligned[i].max[j] = std::ldexp(s.aligned[i].max[j], k);
            s.oriented[i].center[j] = std::ldexp(s.oriented[i].center[j], k);
            s.oriented[i].extents[j] = std::ldexp(s.oriented[i].extents[j], k);
        }
    }
    s.aligned.push_back({{-dmax, -dmax, -dmax}, {dmax, dmax, dmax}});
    s.aligned.push_back({{dmax, dmax, dmax}, {dmax, dmax, dmax}});
    s.aligned.push_back({{denorm, 0, -denorm}, {2 * denorm, denorm, 0}});
    check_set(s.cylinder, s.aligned, s.oriented, "mixed huge and tiny boxes", ca, co);
    print("huge and tiny magnitudes", ca, co);
}

// The cylinder side of the filter (prepare): the exact unit axis u = a/|a| lies within δ_u of û, checked
// exactly in Q(√|a|²) for random axes of every kind — zero, tiny (1e-300, subnormal) and ordinary
// components, magnitudes 2^-1074 … 2^1000 (the scaled and unscaled paths), one or more non-zero
// components — and the half-height and radius constants are the inputs' (H exact, R2 ≤ r²).
TEST(Batch, CylinderConstantsEncloseTheExactAxis) {
    constexpr std::uint64_t seed = 0xBA7C7300;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    const double pick[] = {0.0, 1e-300, -1e-300, 3 * denorm, -3 * denorm, 1e-12, 0.5, -1.0, 1.0};
    long checked = 0;
    for (int n = 0; n < 3000; ++n) {
        Vec3<double> a;
        for (int j = 0; j < 3; ++j) a[j] = (rng() % 3 == 0) ? pick[rng() % std::size(pick)] : unit(rng);
        if (a[0] == 0 && a[1] == 0 && a[2] == 0) continue;
        const int k = static_cast<int>(rng() % 2100) - 1074;  // 2^-1074 … 2^1025 before the range check
        for (int j = 0; j < 3; ++j) a[j] = std::ldexp(a[j], k);
        const Cylinder<double> cyl{{1, 2, 3}, a, 0.75, 2.5};
        if (!validate(cyl).ok()) continue;
        const batch::detail::CylinderFilter f = batch::detail::prepare(cyl);
        if (!f.usable) continue;  // the filter then decides nothing: the scalar path answers
        const Rational s2 = to_rational(a[0]) * to_rational(a[0]) + to_rational(a[1]) * to_rational(a[1]) +
                            to_rational(a[2]) * to_rational(a[2]);
        const QuadraticField<Rational> field(s2);
        const QFRational len = QFRational::root(field);
        for (int j = 0; j < 3; ++j) {
            const Rational lo = to_rational(f.u[j]) - to_rational(f.du), hi = to_rational(f.u[j]) + to_rational(f.du);
            const QFRational aj(to_rational(a[j]));
            ASSERT_TRUE(QFRational(lo) * len <= aj && aj <= QFRational(hi) * len)
                << "seed " << std::hex << seed << std::dec << " case " << n << ": axis " << hex(a) << ", component " << j
                << ": u_j not within du = " << hex(f.du) << " of " << hex(f.u[j]);
        }
        ASSERT_EQ(f.h, cyl.height * 0.5);
        ASSERT_LE(to_rational(f.r2), to_rational(cyl.radius) * to_rational(cyl.radius));
        ++checked;
    }
    std::printf("[ info ] %ld axes checked exactly\n", checked);
    EXPECT_GT(checked, 1000);
}

// 140,000 boxes with 1, 2 and 4 threads: the same answers as the scalar query, bit for bit.
TEST_P(BatchKernels, ThreadsGiveTheSameAnswers) {
    const BatchSet s = random_batch(0xBA7C8000, 140000);
    const std::vector<bool> wa = scalar_answers(s.cylinder, s.aligned);
    const std::vector<bool> wo = scalar_answers(s.cylinder, s.oriented);
    const Soa<double> sa(s.aligned);
    Count ca, co;
    for (unsigned t : {1u, 2u, 4u, 0u}) {
        compare(s.cylinder, sa.view(), s.aligned, wa, s.aligned.size(), t, "large N", ca);
        compare(s.cylinder, std::span<const AlignedBox<double>>(s.aligned), s.aligned, wa, s.aligned.size(), t,
                "large N rows", ca);
        compare(s.cylinder, std::span<const OrientedBox<double>>(s.oriented), s.oriented, wo, s.oriented.size(), t,
                "large N", co);
    }
    print("140,000 boxes, threads 1/2/4/0", ca, co);
}

// The filter's bounds are derived for every IEEE rounding mode (one-ulp error terms); check a set in each.
TEST_P(BatchKernels, RoundingModes) {
    Count ca, co;
    for (int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        const BatchSet s = random_batch(0xBA7C9000 + static_cast<std::uint64_t>(mode), 300);
        std::vector<bool> wa, wo;
        {
            RoundingMode guard(mode);
            wa = scalar_answers(s.cylinder, s.aligned);
            wo = scalar_answers(s.cylinder, s.oriented);
        }
        const Soa<double> sa(s.aligned);
        RoundingMode guard(mode);
        compare(s.cylinder, sa.view(), s.aligned, wa, s.aligned.size(), 1, std::string("mode ") + mode_name(mode), ca);
        compare(s.cylinder, std::span<const AlignedBox<double>>(s.aligned), s.aligned, wa, s.aligned.size(), 1,
                std::string("mode ") + mode_name(mode) + " rows", ca);
        compare(s.cylinder, std::span<const OrientedBox<double>>(s.oriented), s.oriented, wo, s.oriented.size(), 1,
                std::string("mode ") + mode_name(mode), co);
    }
    print("rounding modes", ca, co);
}

// Options::check_boxes: valid sets give the same answers as without it (the rows and the six arrays,
// including valid boxes whose extent overflows a double, which the cheap check cannot clear); an
// invalid box — NaN, ±∞, min > max in one coordinate — throws InvalidBox naming it, wherever it lies
// in its vector and block, and the first of two invalid boxes is the one named. The same for oriented
// boxes and parallelepipeds.
TEST_P(BatchKernels, CheckedBoxes) {
    const BatchSet s = random_batch(0xBA7CA000, 300);
    std::vector<AlignedBox<double>> boxes = s.aligned;
    boxes.push_back({{-1e308, -1e308, -1e308}, {1e308, 1e308, 1e308}});  // valid; hi − lo overflows
    boxes.push_back({{0, 0, 0}, {0, 0, 0}});                               // a point
    const std::vector<bool> want = scalar_answers(s.cylinder, boxes);
    const batch::Options checked{1, g_kernel, true};
    std::vector<std::uint64_t> mask(batch::mask_words(boxes.size()));
    std::unique_ptr<bool[]> bools(new bool[boxes.size()]);
    const Soa<double> soa(boxes);
    batch::intersects(s.cylinder, std::span<const AlignedBox<double>>(boxes), std::span<std::uint64_t>(mask), checked);
    batch::intersects(s.cylinder, soa.view(), std::span<bool>(bools.get(), boxes.size()), checked);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        EXPECT_EQ(((mask[i / 64] >> (i % 64)) & 1u) != 0, want[i]) << "rows, box " << i;
        EXPECT_EQ(bools[i], want[i]) << "arrays, box " << i;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    struct Bad {
        int coordinate;  // 0..5: min x, y, z, max x, y, z
        double value;
    };
    for (const Bad bad : {Bad{0, nan}, Bad{4, nan}, Bad{2, inf}, Bad{3, -inf}, Bad{5, -1e9}, Bad{1, 1e9}}) {
        for (std::size_t at : {std::size_t{0}, std::size_t{3}, std::size_t{7}, std::size_t{64}, std::size_t{130},
                               boxes.size() - 1}) {
            std::vector<AlignedBox<double>> b = boxes;
            (bad.coordinate < 3 ? b[at].min : b[at].max)[static_cast<std::size_t>(bad.coordinate % 3)] = bad.value;
            if (at + 2 < b.size()) b[at + 2].min[0] = nan;  // a later invalid box is not the one named
            const Soa<double> bs(b);
            for (unsigned threads : {1u, 2u}) {
                std::size_t rows_index = 0, arrays_index = 0;
                try {
                    batch::intersects(s.cylinder, std::span<const AlignedBox<double>>(b), std::span<std::uint64_t>(mask),
                                      {threads, g_kernel, true});
                    ADD_FAILURE() << "rows: no InvalidBox for box " << at;
                } catch (const batch::InvalidBox& e) {
                    rows_index = e.index;
                }
                try {
                    batch::intersects(s.cylinder, bs.view(), std::span<bool>(bools.get(), b.size()), {threads, g_kernel, true});
                    ADD_FAILURE() << "arrays: no InvalidBox for box " << at;
                } catch (const batch::InvalidBox& e) {
                    arrays_index = e.index;
                }
                EXPECT_EQ(rows_index, at) << "coordinate " << bad.coordinate << " threads " << threads;
                EXPECT_EQ(arrays_index, at) << "coordinate " << bad.coordinate << " threads " << threads;
            }
        }
    }
    // Oriented boxes: valid ones (an axis 1e-5 off unit length included) answer as without the check;
    // a non-finite number, a negative extent, an axis off unit length or two axes not orthogonal
    // beyond validate()'s tolerance throw, the first of two named.
    std::vector<OrientedBox<double>> o = s.oriented;
    o[5].axes[0] = {1 + 1e-5, 0, 0};
    if (!is_valid(o[5])) o[5] = s.oriented[5];
    const std::vector<bool> wo = scalar_answers(s.cylinder, o);
    batch::intersects(s.cylinder, std::span<const OrientedBox<double>>(o), std::span<bool>(bools.get(), o.size()), checked);
    for (std::size_t i = 0; i < o.size(); ++i) EXPECT_EQ(bools[i], wo[i]) << "oriented, box " << i;
    using Spoil = void (*)(OrientedBox<double>&);
    const Spoil spoils[] = {
        [](OrientedBox<double>& b) { b.center[1] = std::numeric_limits<double>::quiet_NaN(); },
        [](OrientedBox<double>& b) { b.extents[2] = -0.5; },
        [](OrientedBox<double>& b) { b.extents[0] = std::numeric_limits<double>::infinity(); },
        [](OrientedBox<double>& b) { b.axes[1] = {b.axes[1][0] * 2, b.axes[1][1] * 2, b.axes[1][2] * 2}; },
        [](OrientedBox<double>& b) { b.axes[2] = b.axes[0]; },
    };
    for (std::size_t k = 0; k < std::size(spoils); ++k)
        for (std::size_t at : {std::size_t{0}, std::size_t{6}, std::size_t{70}, o.size() - 1}) {
            std::vector<OrientedBox<double>> b = o;
            spoils[k](b[at]);
            if (at + 3 < b.size()) spoils[0](b[at + 3]);
            std::size_t index = b.size();
            try {
                batch::intersects(s.cylinder, std::span<const OrientedBox<double>>(b), std::span<std::uint64_t>(mask), checked);
            } catch (const batch::InvalidBox& e) {
                index = e.index;
            }
            EXPECT_EQ(index, at) << "oriented, spoil " << k;
        }
    // Parallelepipeds: is_valid per box (with the scalar kernel, the only one they have).
    std::vector<Parallelepiped<double>> p;
    for (const OrientedBox<double>& b : s.oriented) p.push_back({b.center, b.axes, b.extents});
    p[90].extents[1] = -1;
    try {
        batch::intersects(s.cylinder, std::span<const Parallelepiped<double>>(p), std::span<std::uint64_t>(mask),
                          {1, batch::Kernel::compiled, true});
        ADD_FAILURE() << "parallelepipeds: no InvalidBox";
    } catch (const batch::InvalidBox& e) {
        EXPECT_EQ(e.index, 90u);
    }
}

// The rows form reads AlignedBox<T> in place, from any start: offsets 0..8 into a set, so that every
// vector's rows start at every alignment and the in-register transpose sees every position.
TEST_P(BatchKernels, RowsAtEveryOffset) {
    Count ca, co;
    const BatchSet s = random_batch(0xBA7CB000, 200);
    const std::vector<bool> wa = scalar_answers(s.cylinder, s.aligned);
    for (std::size_t offset = 0; offset <= 8; ++offset) {
        const std::span<const AlignedBox<double>> rows = std::span<const AlignedBox<double>>(s.aligned).subspan(offset);
        const std::vector<AlignedBox<double>> boxes(rows.begin(), rows.end());
        const std::vector<bool> want(wa.begin() + static_cast<std::ptrdiff_t>(offset), wa.end());
        compare(s.cylinder, rows, boxes, want, rows.size(), 1, "offset " + std::to_string(offset), ca);
    }
    print("rows at offsets 0..8", ca, co);
}

// Parallelepipeds have no SIMD kernel: Stats says what ran (the header's scalar query, one lane),
// automatic and compiled run it, and asking for AVX2 or AVX-512 throws rather than run something else,
// whether or not this CPU has them.
TEST(Batch, ParallelepipedsReportTheScalarKernelAndRefuseSimdOnes) {
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 1, 2};
    const std::vector<Parallelepiped<double>> boxes{
        {{0, 0, 0}, {{{1, 0, 0}, {1, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}},
        {{0, 0, 5}, {{{1, 0, 0}, {0, 1, 0}, {0, 1, 1}}}, {0.5, 0.5, 0.5}},
    };
    const std::vector<Parallelepiped<float>> fboxes{
        {{0, 0, 0}, {{{1, 0, 0}, {1, 1, 0}, {0, 0, 1}}}, {0.5f, 0.5f, 0.5f}},
        {{0, 0, 5}, {{{1, 0, 0}, {0, 1, 0}, {0, 1, 1}}}, {0.5f, 0.5f, 0.5f}},
    };
    std::vector<std::uint64_t> mask(1);
    std::unique_ptr<bool[]> bools(new bool[2]);
    for (batch::Kernel k : {batch::Kernel::automatic, batch::Kernel::compiled}) {
        mask[0] = 0;
        const batch::Stats st =
            batch::intersects(c, std::span<const Parallelepiped<double>>(boxes), std::span<std::uint64_t>(mask), {1, k});
        EXPECT_EQ(mask[0], 1u) << batch::name(k);  // box 0 holds the centre; box 1 is above the top
        EXPECT_EQ(st.kernel, batch::Kernel::compiled) << batch::name(k);
        EXPECT_EQ(st.lanes, 1u) << batch::name(k);
        EXPECT_EQ(st.boxes, 2u);
        const batch::Stats sf =
            batch::intersects(c, std::span<const Parallelepiped<float>>(fboxes), std::span<bool>(bools.get(), 2), {2, k});
        EXPECT_TRUE(bools[0]);
        EXPECT_FALSE(bools[1]);
        EXPECT_EQ(sf.kernel, batch::Kernel::compiled) << batch::name(k);
        EXPECT_EQ(sf.lanes, 1u) << batch::name(k);
    }
    for (batch::Kernel k : {batch::Kernel::avx2, batch::Kernel::avx512}) {
        EXPECT_THROW(batch::intersects(c, std::span<const Parallelepiped<double>>(boxes), std::span<std::uint64_t>(mask),
                                       {1, k}),
                     std::invalid_argument)
            << batch::name(k);
        EXPECT_THROW(batch::intersects(c, std::span<const Parallelepiped<double>>(boxes), std::span<bool>(bools.get(), 2),
                                       {1, k}),
                     std::invalid_argument)
            << batch::name(k);
        EXPECT_THROW(batch::intersects(c, std::span<const Parallelepiped<float>>(fboxes), std::span<std::uint64_t>(mask),
                                       {1, k}),
                     std::invalid_argument)
            << batch::name(k);
        EXPECT_THROW(batch::intersects(c, std::span<const Parallelepiped<double>>(), std::span<std::uint64_t>(), {1, k}),
                     std::invalid_argument)
            << batch::name(k) << " (empty batch)";
    }
}

// Options::stop: a stop requested before the call ends it at the first block, for every kind of box; one
// requested while the call runs (from another thread, on boxes that all touch the cylinder and so all
// go to the scalar exact query) ends it within a block per thread. Either way the call throws Stopped.
TEST_P(BatchKernels, StopEndsTheCall) {
    const Cylinder<double> c{{3, 0, 0}, {0, 0, 5}, 2, 1};  // its side touches the face x = 1 of each box
    const std::size_t n = std::size_t{1} << 20;
    const std::vector<AlignedBox<double>> rows(n, AlignedBox<double>{{-1, -1, -1}, {1, 1, 1}});
    const std::vector<double> lo(n, -1.0), hi(n, 1.0);
    const std::vector<OrientedBox<double>> oriented(
        n, OrientedBox<double>{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}});
    const std::vector<Parallelepiped<double>> skew(
        n, Parallelepiped<double>{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}});
    std::unique_ptr<bool[]> out(new bool[n]);
    const std::span<bool> result(out.get(), n);
    std::stop_source stopped;
    stopped.request_stop();
    const batch::Options before{1, GetParam(), false, stopped.get_token()};
    EXPECT_THROW(batch::intersects(c, std::span<const AlignedBox<double>>(rows), result, before), batch::Stopped);
    EXPECT_THROW(batch::intersects(c, batch::AlignedBoxes<double>{lo, lo, lo, hi, hi, hi}, result, before), batch::Stopped);
    EXPECT_THROW(batch::intersects(c, std::span<const OrientedBox<double>>(oriented), result, before), batch::Stopped);
    // Parallelepipeds have no SIMD filter (asking for one is refused), so they stop in the compiled kernel.
    const bool simd = GetParam() == batch::Kernel::avx2 || GetParam() == batch::Kernel::avx512;
    const batch::Options skew_before{1, simd ? batch::Kernel::compiled : GetParam(), false, stopped.get_token()};
    EXPECT_THROW(batch::intersects(c, std::span<const Parallelepiped<double>>(skew), result, skew_before), batch::Stopped);
    for (unsigned threads : {1u, 2u}) {
        std::stop_source running;
        std::chrono::steady_clock::time_point requested{};
        std::thread stopper([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            requested = std::chrono::steady_clock::now();
            running.request_stop();
        });
        const auto start = std::chrono::steady_clock::now();
        EXPECT_THROW(batch::intersects(c, std::span<const AlignedBox<double>>(rows), result,
                                       {threads, GetParam(), true, running.get_token()}),
                     batch::Stopped)
            << "the batch ended before the stop";
        const auto end = std::chrono::steady_clock::now();
        stopper.join();
        std::printf("[ info ] %u thread(s): stopped %.2f ms after the request (%.0f ms into the batch)\n", threads,
                    std::chrono::duration<double, std::milli>(end - requested).count(),
                    std::chrono::duration<double, std::milli>(end - start).count());
        EXPECT_LT(end - requested, std::chrono::milliseconds(500));
    }
}

TEST(Batch, MismatchedLengthsAndShortOutputsThrow) {
    const std::vector<double> a(3, 0.0), b(2, 0.0);
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 1, 1};
    std::vector<std::uint64_t> mask(1);
    EXPECT_THROW(batch::intersects(c, batch::AlignedBoxes<double>{a, a, a, a, a, b}, std::span<std::uint64_t>(mask)),
                 std::invalid_argument);
    std::vector<double> big(65, 0.0);
    EXPECT_THROW(batch::intersects(c, batch::AlignedBoxes<double>{big, big, big, big, big, big}, std::span<std::uint64_t>(mask)),
                 std::invalid_argument);
}

}  // namespace
}  // namespace boxcyl
