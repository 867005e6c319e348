// The batch clearance query, boxcyl::batch::within_distance (boxcyl/batch.hpp), against the scalar
// within_distance(box, cylinder, margin), bit for bit: random sets around CaseGenerator cylinders at
// random margins, for every box layout (six arrays, AlignedBox rows, OrientedBox, Parallelepiped),
// double and float inputs, both outputs; margin 0 is batch::intersects; boxes exactly at the margin
// (face against side and cap, a corner against the rim) answer true at the margin and false one ulp
// below; threads; a refused margin; checked boxes and the stop. Through every kernel this machine runs.
// Every failure prints the case as copy-pasteable C++ (hex floats); each set's share of boxes left to
// the scalar query (Stats::exact_lanes) is printed.
#include <gtest/gtest.h>

#include <array>      // frames
#include <cmath>      // std::nextafter, std::ldexp
#include <cstddef>    // std::size_t
#include <cstdint>    // std::uint64_t
#include <cstdio>     // std::printf
#include <limits>     // NaN, infinity
#include <memory>     // std::unique_ptr<bool[]>
#include <random>     // margins
#include <stdexcept>  // std::invalid_argument
#include <stop_token>  // Options::stop
#include <string>     // labels
#include <vector>     // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/clearance.hpp"
#include "support/batch_cases.hpp"
#include "support/batch_kernels.hpp"
#include "support/runner.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

batch::Kernel g_kernel = batch::Kernel::compiled;

// The case as C++: the scalar call whose answer the batch must give.
std::string show(const AlignedBox<double>& b, const Cylinder<double>& c, double m) {
    Case k;
    k.kind = BoxKind::aligned, k.aligned = b, k.cylinder = c;
    return describe(k) + "  margin " + hex(m);
}
std::string show(const OrientedBox<double>& b, const Cylinder<double>& c, double m) {
    Case k;
    k.kind = BoxKind::oriented, k.oriented = b, k.cylinder = c;
    return describe(k) + "  margin " + hex(m);
}
std::string show(const Parallelepiped<double>& b, const Cylinder<double>& c, double m) {
    return "Parallelepiped<double>{" + hex(b.center) + ", {" + hex(b.axes[0]) + ", " + hex(b.axes[1]) + ", " +
           hex(b.axes[2]) + "}, " + hex(b.extents) + "}, Cylinder<double>{" + hex(c.center) + ", " + hex(c.axis) + ", " +
           hex(c.radius) + ", " + hex(c.height) + "}, margin " + hex(m);
}

Parallelepiped<double> as_parallelepiped(const OrientedBox<double>& o) { return {o.center, o.axes, o.extents}; }
Parallelepiped<double> as_parallelepiped(const AlignedBox<double>& a) {
    const Vec3<double> c{(a.min[0] + a.max[0]) / 2, (a.min[1] + a.max[1]) / 2, (a.min[2] + a.max[2]) / 2};
    const Vec3<double> e{(a.max[0] - a.min[0]) / 2, (a.max[1] - a.min[1]) / 2, (a.max[2] - a.min[2]) / 2};
    return {c, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, e};
}

template <class T>
struct Soa {
    std::vector<T> v[6];
    explicit Soa(const std::vector<AlignedBox<T>>& boxes) {
        for (const AlignedBox<T>& b : boxes)
            for (int j = 0; j < 3; ++j) v[j].push_back(b.min[j]), v[3 + j].push_back(b.max[j]);
    }
    batch::AlignedBoxes<T> view() const { return {v[0], v[1], v[2], v[3], v[4], v[5]}; }
};

// Widening and narrowing, as the scalar float forms do it.
template <class T, class Shape>
auto to(const Shape& x) {
    return boxcyl::detail::cast<T>(x);
}

struct Count {
    long boxes = 0, exact = 0;
    void print(const char* label) const {
        std::printf("%-46s %7ld boxes, to the scalar clearance query %6.2f%%\n", label, boxes,
                    boxes ? 100.0 * double(exact) / double(boxes) : 0.0);
    }
};

// Runs the batch (mask and bools) and compares every answer with want[i]; boxes are the double boxes
// (the widened inputs) for the message.
template <class Cyl, class View, class Box>
void compare(const Cyl& cyl, const View& view, double m, const std::vector<Box>& boxes, const std::vector<bool>& want,
             unsigned threads, const std::string& where, Count& count) {
    const std::size_t n = boxes.size();
    const batch::Options opt{threads, g_kernel};
    std::vector<std::uint64_t> mask(batch::mask_words(n) + 1, ~std::uint64_t{0});
    const batch::Stats st = batch::within_distance(cyl, view, m, std::span<std::uint64_t>(mask), opt);
    std::unique_ptr<bool[]> bools(new bool[n + 1]);
    const batch::Stats sb = batch::within_distance(cyl, view, m, std::span<bool>(bools.get(), n), opt);
    EXPECT_EQ(st.boxes, n) << where;
    EXPECT_EQ(st.exact_lanes, sb.exact_lanes) << where;
    EXPECT_LE(st.exact_lanes, n) << where;
    count.boxes += static_cast<long>(n);
    count.exact += static_cast<long>(st.exact_lanes);
    int failures = 0;
    for (std::size_t i = 0; i < n && failures < 5; ++i) {
        const bool got = (mask[i / 64] >> (i % 64)) & 1u;
        if (got != want[i] || bools[i] != want[i]) {
            ++failures;
            ADD_FAILURE() << where << " box " << i << " of " << n << " (kernel " << batch::name(g_kernel) << ", threads "
                          << threads << "): batch::within_distance says " << got << " (bools " << bools[i]
                          << "), scalar within_distance " << want[i] << "\n  " << show(boxes[i], to<double>(cyl), m);
        }
    }
    if (n % 64 != 0) {
        EXPECT_EQ(mask[n / 64] >> (n % 64), 0u) << where << ": bits beyond the last box must be 0";
    }
    EXPECT_EQ(mask[batch::mask_words(n)], ~std::uint64_t{0}) << where << ": wrote past the mask";
}

template <class Box>
std::vector<bool> scalar(const Cylinder<double>& cyl, const std::vector<Box>& boxes, double m) {
    std::vector<bool> want;
    want.reserve(boxes.size());
    for (const Box& b : boxes) want.push_back(within_distance(b, cyl, m));
    return want;
}

// Every layout of one set, double inputs: six arrays, rows, oriented boxes, parallelepipeds (those of
// the oriented boxes, and of the aligned ones).
void check_set(const Cylinder<double>& cyl, const std::vector<AlignedBox<double>>& aligned,
               const std::vector<OrientedBox<double>>& oriented, double m, const std::string& where, Count& ca,
               Count& co, Count& cp, unsigned threads = 1) {
    const std::vector<bool> wa = scalar(cyl, aligned, m), wo = scalar(cyl, oriented, m);
    const Soa<double> soa(aligned);
    compare(cyl, soa.view(), m, aligned, wa, threads, where + " aligned", ca);
    compare(cyl, std::span<const AlignedBox<double>>(aligned), m, aligned, wa, threads, where + " aligned rows", ca);
    compare(cyl, std::span<const OrientedBox<double>>(oriented), m, oriented, wo, threads, where + " oriented", co);
    if (g_kernel != batch::Kernel::compiled) return;  // parallelepipeds have the scalar kernel only
    std::vector<Parallelepiped<double>> p;
    p.reserve(oriented.size() + aligned.size());
    for (const OrientedBox<double>& o : oriented) p.push_back(as_parallelepiped(o));
    for (const AlignedBox<double>& a : aligned) p.push_back(as_parallelepiped(a));
    compare(cyl, std::span<const Parallelepiped<double>>(p), m, p, scalar(cyl, p, m), threads,
            where + " parallelepipeds", cp);
}

// The same set in float (cylinder and margin too): the answers are those of the widened values. Boxes
// that rounding made invalid (an oriented frame) are left out.
void check_float(const BatchSet& s, double m, const std::string& where, Count& ca, Count& co, Count& cp) {
    const Cylinder<float> cf = to<float>(s.cylinder);
    const Cylinder<double> cd = to<double>(cf);
    const float mf = static_cast<float>(m);
    if (!validate(cd).ok() || !is_valid_margin(mf)) return;
    std::vector<AlignedBox<float>> af;
    std::vector<AlignedBox<double>> ad;
    for (const AlignedBox<double>& a : s.aligned)
        if (validate(to<double>(to<float>(a))).ok()) af.push_back(to<float>(a)), ad.push_back(to<double>(af.back()));
    std::vector<OrientedBox<float>> of;
    std::vector<OrientedBox<double>> od;
    for (const OrientedBox<double>& o : s.oriented)
        if (validate(to<double>(to<float>(o))).ok()) of.push_back(to<float>(o)), od.push_back(to<double>(of.back()));
    const std::vector<bool> wa = scalar(cd, ad, mf), wo = scalar(cd, od, mf);
    // The scalar float form means the same: every value widened exactly.
    for (std::size_t i = 0; i < af.size() && i < 8; ++i) EXPECT_EQ(within_distance(af[i], cf, mf), wa[i]) << where;
    const Soa<float> soa(af);
    compare(cf, soa.view(), mf, ad, wa, 1, where + " float aligned", ca);
    compare(cf, std::span<const AlignedBox<float>>(af), mf, ad, wa, 1, where + " float aligned rows", ca);
    compare(cf, std::span<const OrientedBox<float>>(of), mf, od, wo, 1, where + " float oriented", co);
    if (g_kernel != batch::Kernel::compiled) return;
    std::vector<Parallelepiped<float>> pf;
    std::vector<Parallelepiped<double>> pd;
    for (const OrientedBox<float>& o : of) pf.push_back({o.center, o.axes, o.extents}), pd.push_back(to<double>(pf.back()));
    compare(cf, std::span<const Parallelepiped<float>>(pf), mf, pd, scalar(cd, pd, mf), 1, where + " float parallelepipeds",
            cp);
}

// A margin for a set around a cylinder of reach `reach`: from 2^-20 to 2 times it, a few tiny ones.
double random_margin(std::mt19937_64& rng, double reach) {
    std::uniform_real_distribution<double> e(-8.0, 1.0), u(1.0, 2.0);
    std::uniform_int_distribution<int> pick(0, 9);
    if (!(reach > 0)) reach = 1;
    if (pick(rng) == 0) return reach * std::ldexp(u(rng), -20);
    return reach * std::ldexp(u(rng), static_cast<int>(e(rng)));
}

double reach_of(const Cylinder<double>& c) { return c.radius + c.height * 0.5; }

class BatchClearance : public ::testing::TestWithParam<batch::Kernel> {
protected:
    void SetUp() override { g_kernel = GetParam(); }
    void TearDown() override { g_kernel = batch::Kernel::compiled; }
};

INSTANTIATE_TEST_SUITE_P(Kernels, BatchClearance, ::testing::ValuesIn(runnable_kernels()),
                         [](const ::testing::TestParamInfo<batch::Kernel>& info) { return std::string(batch::name(info.param)); });

// Random sets: 40 cylinders × 64 boxes of each kind, each at two random margins; float inputs for a third.
TEST_P(BatchClearance, RandomSetsAgreeWithScalar) {
    Count ca, co, cp, fa, fo, fp;
    const long sets = scaled(40);
    std::mt19937_64 rng(0xC1EA);
    for (long k = 0; k < sets; ++k) {
        const std::uint64_t seed = 0xBA7C5000 + static_cast<std::uint64_t>(k);
        const BatchSet s = random_batch(seed, 64, k % 4 == 3 ? Profile::degenerate : Profile::mixed);
        for (int r = 0; r < 2; ++r) {
            const double m = random_margin(rng, reach_of(s.cylinder));
            const std::string where = "random seed " + std::to_string(seed) + " margin " + hex(m);
            check_set(s.cylinder, s.aligned, s.oriented, m, where, ca, co, cp);
            if (k % 3 == 0 && r == 0) check_float(s, m, where, fa, fo, fp);
        }
    }
    ca.print("random sets, aligned (double)");
    co.print("random sets, oriented (double)");
    cp.print("random sets, parallelepipeds (double)");
    fa.print("random sets, aligned (float)");
    fo.print("random sets, oriented (float)");
}

// Batches of more blocks than one group takes (kernel.hpp's kGroupBlocks), the last one partial (37
// boxes), so that the passes after the first gather the open lanes of a group of blocks, a second group
// follows, and it ends on a short block.
TEST_P(BatchClearance, GroupsOfBlocksAgreeWithScalar) {
    Count ca, co, cp;
    std::mt19937_64 rng(0xC1EB);
    for (long k = 0; k < scaled(6); ++k) {
        const std::uint64_t seed = 0xBA7C6000 + static_cast<std::uint64_t>(k);
        const BatchSet s = random_batch(seed, (batch::detail::kGroupBlocks + 1) * 64 + 37, k % 3 == 2 ? Profile::degenerate : Profile::mixed);
        const double m = random_margin(rng, reach_of(s.cylinder));
        check_set(s.cylinder, s.aligned, s.oriented, m, "groups, seed " + std::to_string(seed) + " margin " + hex(m), ca, co, cp);
    }
    ca.print("groups of blocks, aligned");
    co.print("groups of blocks, oriented");
    cp.print("groups of blocks, parallelepipeds");
}

// Margin 0 (and −0) is batch::intersects, answers and statistics alike.
TEST_P(BatchClearance, MarginZeroIsIntersects) {
    for (std::uint64_t seed = 0xBA7C6000; seed < 0xBA7C6000 + 20; ++seed) {
        const BatchSet s = random_batch(seed, 100);
        const batch::Options opt{1, g_kernel};
        for (double zero : {0.0, -0.0}) {
            std::vector<std::uint64_t> want(batch::mask_words(s.aligned.size())), got(want.size());
            const batch::Stats a = batch::intersects(s.cylinder, std::span<const AlignedBox<double>>(s.aligned),
                                                     std::span<std::uint64_t>(want), opt);
            const batch::Stats b = batch::within_distance(s.cylinder, std::span<const AlignedBox<double>>(s.aligned), zero,
                                                          std::span<std::uint64_t>(got), opt);
            EXPECT_EQ(got, want) << "seed " << seed;
            EXPECT_EQ(a.exact_lanes, b.exact_lanes) << "seed " << seed;
            std::vector<std::uint64_t> wo(batch::mask_words(s.oriented.size())), go(wo.size());
            batch::intersects(s.cylinder, std::span<const OrientedBox<double>>(s.oriented), std::span<std::uint64_t>(wo), opt);
            batch::within_distance(s.cylinder, std::span<const OrientedBox<double>>(s.oriented), zero,
                                   std::span<std::uint64_t>(go), opt);
            EXPECT_EQ(go, wo) << "seed " << seed;
        }
    }
}

// Boxes at exactly the margin from the side, the cap and the rim, each beside the same box one ulp of
// the margin below (false) and at the margin (true), among far and near boxes so that they share
// vectors with lanes the filter decides.
TEST_P(BatchClearance, BoxesExactlyAtTheMargin) {
    const Cylinder<double> unit{{0, 0, 0}, {0, 0, 1}, 1, 2};  // r = 1, caps at z = ±1
    const Cylinder<double> hole{{0, 0, 0}, {0, 0, 1}, 3, 2};  // the README's: rim circle at radius 3, z = 1
    const Cylinder<double> wide{{0, 0, 0}, {0, 0, 1}, 7, 2};  // rim circle at radius 7, z = 1
    struct Construction {
        Cylinder<double> cyl;
        AlignedBox<double> box;
        double dist;
        const char* what;
    };
    const std::vector<Construction> cs{
        {unit, {{1.25, -0.5, -0.5}, {2, 0.5, 0.5}}, 0.25, "face 0.25 from the side"},
        {unit, {{-0.5, -0.5, 1.5}, {0.5, 0.5, 2}}, 0.5, "face 0.5 above the cap"},
        {unit, {{-2, -0.5, -0.5}, {-1 - 0x1p-30, 0.5, 0.5}}, 0x1p-30, "face 2^-30 from the side"},
        {hole, {{6, 0, 5}, {7, 1, 6}}, 5.0, "corner 5 from the rim"},
        {wide, {{6, 8, 5}, {7, 9, 6}}, 5.0, "corner 5 from the rim at an azimuth (ρ − r = 3, 4 above)"},
    };
    for (const Construction& c : cs) {
        for (double m : {c.dist, std::nextafter(c.dist, 0.0)}) {
            const bool want = m == c.dist;
            ASSERT_EQ(within_distance(c.box, c.cyl, m), want) << c.what;  // the construction itself
            std::vector<AlignedBox<double>> a;
            std::vector<OrientedBox<double>> o;
            const std::array<Vec3<double>, 3> id{Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}};
            for (int i = 0; i < 21; ++i) {
                // Far boxes, boxes inside, and the construction at lanes 0, 7, 13, 20.
                AlignedBox<double> b = c.box;
                if (i % 7 == 1) b = {{100, 100, 100}, {101, 101, 101}};
                if (i % 7 == 2) b = {{-0.25, -0.25, -0.25}, {0.25, 0.25, 0.25}};
                if (i % 7 >= 3 && i % 7 <= 5) b = {{-50, -50, 40.0 + i}, {50, 50, 41.0 + i}};
                a.push_back(b);
                const Parallelepiped<double> p = as_parallelepiped(b);
                o.push_back({p.center, id, p.extents});
            }
            Count ca, co, cp;
            check_set(c.cyl, a, o, m, std::string(c.what) + (want ? " at the margin" : " one ulp below"), ca, co, cp);
            // The first box is the construction: its answer stated here, not only the scalar one.
            std::unique_ptr<bool[]> b1(new bool[1]);
            batch::within_distance(c.cyl, std::span<const AlignedBox<double>>(&c.box, 1), m, std::span<bool>(b1.get(), 1),
                                   {1, g_kernel});
            EXPECT_EQ(b1[0], want) << c.what << " margin " << hex(m);
        }
    }
}

// Threads: a voxel grid around a tilted cylinder, large enough for 4 threads, at a margin of three
// voxels: the same answers with 1, 2 and 4 threads, and those of the scalar query.
TEST_P(BatchClearance, ThreadsGiveTheSameAnswers) {
    const Cylinder<double> c{{0.3, -0.2, 0.1}, {0.8, 0.5, 0.33}, 2, 8};
    const double voxel = 0.25, m = 3 * voxel;
    std::vector<AlignedBox<double>> a;
    for (int i = -32; i < 32; ++i)
        for (int j = -32; j < 32; ++j)
            for (int k = -16; k < 16; ++k)
                a.push_back({{i * voxel, j * voxel, k * voxel}, {(i + 1) * voxel, (j + 1) * voxel, (k + 1) * voxel}});
    ASSERT_GE(a.size(), 4 * batch::split::kMinBoxesPerThread);
    const std::vector<bool> want = scalar(c, a, m);
    const Soa<double> soa(a);
    Count count;
    for (unsigned threads : {1u, 2u, 4u}) {
        compare(c, soa.view(), m, a, want, threads, "voxels, threads " + std::to_string(threads), count);
        compare(c, std::span<const AlignedBox<double>>(a), m, a, want, threads, "voxel rows, threads " + std::to_string(threads),
                count);
    }
    count.print("voxels at a margin of three voxels");
}

// Voxels around a tilted cylinder at margins from a thousandth of a voxel to ten voxels, and at 1e308,
// where the outer cylinder's height overflows and the fat cylinder's probe runs first: the first pass
// answers the voxels inside the margin's band from the later probes' own ball tests, the rest go on.
TEST_P(BatchClearance, VoxelsAtSeveralMarginsAgreeWithScalar) {
    const Cylinder<double> c{{0.3, -0.2, 0.1}, {0.8, 0.5, 0.33}, 1.5, 5};
    const double voxel = 0.25;
    std::vector<AlignedBox<double>> a;
    for (int i = -16; i < 16; ++i)
        for (int j = -16; j < 16; ++j)
            for (int k = -12; k < 12; ++k)
                a.push_back({{i * voxel, j * voxel, k * voxel}, {(i + 1) * voxel, (j + 1) * voxel, (k + 1) * voxel}});
    const Soa<double> soa(a);
    Count count;
    for (const double m : {voxel / 1024, voxel, 10 * voxel, 1e308}) {
        const std::vector<bool> want = scalar(c, a, m);
        compare(c, soa.view(), m, a, want, 1, "voxels, margin " + hex(m), count);
        compare(c, std::span<const AlignedBox<double>>(a), m, a, want, 1, "voxel rows, margin " + hex(m), count);
    }
    count.print("voxels at margins from 1/1024 voxel to 1e308");
}

// A refused margin: std::invalid_argument with validate_margin's message, for every layout.
TEST(BatchClearanceRefusals, BadMarginThrows) {
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 1, 2};
    const std::vector<AlignedBox<double>> a{{{-1, -1, -1}, {1, 1, 1}}};
    const std::vector<OrientedBox<double>> o{
        {{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}}};
    const std::vector<Parallelepiped<double>> p{
        {{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}}};
    const Soa<double> soa(a);
    std::vector<std::uint64_t> mask(1);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const std::vector<std::pair<double, std::string>> bad{
        {-1.0, "margin: is negative"}, {nan, "margin: is NaN"}, {inf, "margin: is +Inf"}, {-inf, "margin: is -Inf"}};
    for (const auto& entry : bad) {
        const double m = entry.first;  // a plain variable: lambdas below capture it
        const std::string& message = entry.second;
        auto expect = [&](auto&& call) {
            try {
                call();
                ADD_FAILURE() << "margin " << m << " was accepted";
            } catch (const std::invalid_argument& e) {
                EXPECT_EQ(std::string(e.what()), validate_margin(m).message());
                EXPECT_EQ(std::string(e.what()).rfind(message.substr(0, 11), 0), 0u) << e.what();
            }
        };
        expect([&] { batch::within_distance(c, soa.view(), m, std::span<std::uint64_t>(mask)); });
        expect([&] { batch::within_distance(c, std::span<const AlignedBox<double>>(a), m, std::span<std::uint64_t>(mask)); });
        expect([&] { batch::within_distance(c, std::span<const OrientedBox<double>>(o), m, std::span<std::uint64_t>(mask)); });
        expect([&] { batch::within_distance(c, std::span<const Parallelepiped<double>>(p), m, std::span<std::uint64_t>(mask)); });
        expect([&] {
            batch::within_distance(Cylinder<float>{{0, 0, 0}, {0, 0, 1}, 1, 2}, soa.view(), m, std::span<std::uint64_t>(mask));
        });
    }
}

// Options::check_boxes names the first invalid box, Options::stop ends the call, short outputs throw,
// and a SIMD kernel is refused for parallelepipeds — as in batch::intersects.
TEST(BatchClearanceRefusals, OptionsAsIntersects) {
    const Cylinder<double> c{{0, 0, 0}, {0, 0, 1}, 1, 2};
    std::vector<AlignedBox<double>> a(100, AlignedBox<double>{{2, 2, 2}, {3, 3, 3}});
    a[70] = {{1, 0, 0}, {0, 1, 1}};  // min > max
    std::vector<std::uint64_t> mask(2);
    batch::Options opt;
    opt.check_boxes = true;
    try {
        batch::within_distance(c, std::span<const AlignedBox<double>>(a), 0.5, std::span<std::uint64_t>(mask), opt);
        ADD_FAILURE() << "the invalid box was accepted";
    } catch (const batch::InvalidBox& e) {
        EXPECT_EQ(e.index, 70u);
    }
    a[70] = a[0];
    std::stop_source stop;
    stop.request_stop();
    opt.stop = stop.get_token();
    EXPECT_THROW(batch::within_distance(c, std::span<const AlignedBox<double>>(a), 0.5, std::span<std::uint64_t>(mask), opt),
                 batch::Stopped);
    std::vector<std::uint64_t> short_mask(1);
    EXPECT_THROW(batch::within_distance(c, std::span<const AlignedBox<double>>(a), 0.5, std::span<std::uint64_t>(short_mask)),
                 std::invalid_argument);
    const std::vector<Parallelepiped<double>> p{as_parallelepiped(a[0])};
    for (batch::Kernel k : {batch::Kernel::avx2, batch::Kernel::avx512})
        EXPECT_THROW(batch::within_distance(c, std::span<const Parallelepiped<double>>(p), 0.5,
                                            std::span<std::uint64_t>(mask), {1, k}),
                     std::invalid_argument);
}

}  // namespace
}  // namespace boxcyl
