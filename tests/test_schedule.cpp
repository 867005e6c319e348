// The exact default's schedules (filtered/schedule.hpp), row by row: every certifier is run alone —
// whatever its row's "when" says — on the near-touching, adversarial, boundary and random sets, in
// every IEEE rounding mode its row runs in, and each decision it makes must equal the oracle's. So each
// row's soundness is a property of its own, not of the rows before it; the order stays free to change.
// Also the schedules' shape (at most 15 rows per rounding mode, the exact stage last) and the
// statistics the pipeline reports.
#include <gtest/gtest.h>

#include <array>      // a frame
#include <cfenv>      // rounding modes
#include <cmath>      // std::nextafter
#include <cstdio>     // std::printf
#include <limits>     // NaN
#include <optional>   // the slabs' verdicts
#include <random>     // std::mt19937_64
#include <string>     // labels
#include <tuple>      // the schedules
#include <type_traits>  // which table
#include <utility>    // std::pair
#include <vector>     // the sets

#include "boxcyl/filtered.hpp"
#include "boxcyl/query.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"
#include "support/near_touching.hpp"
#include "support/runner.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;
using filtered::Modes;

bool runs_in(Modes modes, int mode) {
    return modes == Modes::any || (modes == Modes::nearest) == (mode == FE_TONEAREST);
}

struct Tally {
    long tried = 0, decided = 0, wrong = 0;
};

// Runs every row of `schedule` alone on (box, cylinder), in `mode`; counts into tallies by row. The rows
// of given_schedule read the query as given, the others the prepared query.
template <class Schedule, class Box>
void check_rows(const Schedule& schedule, const Box& box, const Cylinder<double>& cyl, bool want, int mode,
                std::vector<Tally>& tallies, const std::string& where) {
    std::apply(
        [&](const auto&... row) {
            (
                [&] {
                    if (!runs_in(row.modes, mode)) return;
                    std::optional<bool> got;
                    {
                        const RoundingMode guard(mode);
                        if constexpr (std::is_same_v<Schedule, std::remove_cv_t<decltype(filtered::given_schedule)>>) {
                            const filtered::Given<Box> q{box, cyl};
                            got = row.certify(q);
                        } else {
                            filtered::Prepared<Box> q(box, cyl);
                            got = row.certify(q);
                        }
                    }
                    Tally& t = tallies[static_cast<std::size_t>(row.id)];
                    ++t.tried;
                    if (!got) return;
                    ++t.decided;
                    if (*got != want && ++t.wrong <= 5)
                        ADD_FAILURE() << "row " << filtered::name(row.id) << " (" << mode_name(mode) << ") answered "
                                      << *got << ", oracle " << want << ": " << where;
                }(),
                ...);
        },
        schedule);
}

struct Sets {
    std::vector<Case> boxes;                                     // aligned, oriented, canonical
    std::vector<std::pair<Parallelepiped<double>, Cylinder<double>>> parallelepipeds;
    std::vector<bool> box_want, pp_want;
};

const Sets& sets() {
    static const Sets s = [] {
        Sets r;
        std::mt19937_64 touching(7301), adversarial(7302);
        for (long i = 0; i < scaled(600); ++i) r.boxes.push_back(touching_case(touching));
        for (long i = 0; i < scaled(600); ++i) r.boxes.push_back(adversarial_case(adversarial));
        CaseGenerator boundary(7303), random(7304), degenerate(7305, Profile::degenerate);
        CaseGenerator geo(7307, Profile::georeferenced), magnitudes(7308, Profile::magnitudes);
        CaseGenerator geo_boundary(7309, Profile::georeferenced);
        for (const Case& c : boundary_pairs(boundary, static_cast<std::size_t>(scaled(60)))) r.boxes.push_back(c);
        for (const Case& c : boundary_pairs(geo_boundary, static_cast<std::size_t>(scaled(40)))) r.boxes.push_back(c);
        for (long i = 0; i < scaled(600); ++i) r.boxes.push_back(random.next());
        for (long i = 0; i < scaled(300); ++i) r.boxes.push_back(degenerate.next());
        for (long i = 0; i < scaled(300); ++i) r.boxes.push_back(geo.next());
        for (long i = 0; i < scaled(300); ++i) r.boxes.push_back(magnitudes.next());
        for (const Case& c : r.boxes) r.box_want.push_back(oracle_answer(c));
        // Parallelepipeds: the oriented cases as the parallelepipeds they are, and the same with their
        // axes scaled and sheared (any lengths and angles), near touching or not.
        std::mt19937_64 rng(7306);
        std::uniform_real_distribution<double> shear(-0.5, 0.5);
        for (const Case& c : r.boxes) {
            if (c.kind != BoxKind::oriented) continue;
            const OrientedBox<double>& o = c.oriented;
            r.parallelepipeds.push_back({{o.center, o.axes, o.extents}, c.cylinder});
            Parallelepiped<double> p{o.center, o.axes, o.extents};
            p.axes[0] = 3.0 * p.axes[0];
            p.axes[1] = p.axes[1] + shear(rng) * p.axes[2];
            if (validate(p).ok()) r.parallelepipeds.push_back({p, c.cylinder});
        }
        for (const auto& [p, c] : r.parallelepipeds) r.pp_want.push_back(oracle::intersects(to_exact(p), to_exact(c)));
        return r;
    }();
    return s;
}

void report(const char* what, int mode, const std::vector<Tally>& tallies) {
    for (std::size_t i = 0; i < tallies.size(); ++i) {
        const Tally& t = tallies[i];
        if (t.tried == 0) continue;
        std::printf("  %-12s %-12s %-26s tried %6ld  decided %6ld  wrong %ld\n", what, mode_name(mode),
                    std::string(filtered::name(static_cast<filtered::RowId>(i))).c_str(), t.tried, t.decided, t.wrong);
    }
}

class ScheduleRows : public ::testing::TestWithParam<int> {};

TEST_P(ScheduleRows, EveryRowIsSoundAlone) {
    const int mode = GetParam();
    const Sets& s = sets();
    std::vector<Tally> boxes(filtered::row_count), pps(filtered::row_count);
    for (std::size_t i = 0; i < s.boxes.size(); ++i)
        with_box(s.boxes[i], [&](const auto& b, const Cylinder<double>& c) {
            check_rows(filtered::given_schedule, b, c, s.box_want[i], mode, boxes, describe(s.boxes[i]));
            check_rows(filtered::box_schedule, b, c, s.box_want[i], mode, boxes, describe(s.boxes[i]));
            return 0;
        });
    for (std::size_t i = 0; i < s.parallelepipeds.size(); ++i) {
        const auto& [p, c] = s.parallelepipeds[i];
        check_rows(filtered::given_schedule, p, c, s.pp_want[i], mode, pps,
                   filtered::detail::describe(p) + ", " + filtered::detail::describe(c));
        check_rows(filtered::parallelepiped_schedule, p, c, s.pp_want[i], mode, pps,
                   filtered::detail::describe(p) + ", " + filtered::detail::describe(c));
    }
    report("boxes", mode, boxes);
    report("parallelepipeds", mode, pps);
    // Every row that ran decided something: the sets reach every certificate (the test has teeth).
    for (std::size_t r = 0; r < filtered::row_count; ++r) {
        for (const std::vector<Tally>* t : {&boxes, &pps}) {
            const Tally& x = (*t)[r];
            EXPECT_EQ(x.wrong, 0) << filtered::name(static_cast<filtered::RowId>(r));
            if (x.tried > 0) {
                EXPECT_GT(x.decided, 0) << filtered::name(static_cast<filtered::RowId>(r)) << " never decided";
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(RoundingModes, ScheduleRows,
                         ::testing::Values(FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO),
                         [](const auto& info) { return std::string(mode_name(info.param)); });

// The tables' shape: at most 15 rows in each rounding mode, the exact stage last in both.
template <class Schedule>
void check_shape(const Schedule& schedule, const char* what) {
    for (const Modes mode : {Modes::nearest, Modes::directed}) {
        int rows = 0;
        filtered::RowId last{};
        std::apply(
            [&](const auto&... row) {
                ((row.modes == Modes::any || row.modes == mode ? (++rows, last = row.id) : last), ...);
            },
            schedule);
        EXPECT_LE(rows, 15) << what;
        EXPECT_EQ(last, filtered::RowId::exact) << what;
    }
}
TEST(Schedule, AtMostFifteenRowsPerModeExactLast) {
    check_shape(filtered::box_schedule, "boxes");
    check_shape(filtered::parallelepiped_schedule, "parallelepipeds");
}

// The facts the rows' conditions read: a rotated frame is turned, a signed permutation is not, nor is any
// other box kind; flat shapes and two-scale axes are recognised.
TEST(Schedule, FactsOfThePreparedQuery) {
    const Cylinder<double> cyl{{0.5, 0, 0}, {0, 0, 1}, 1, 2};
    const OrientedBox<double> rotated{{0, 0, 0}, {Vec3<double>{0.6, 0.8, 0}, Vec3<double>{-0.8, 0.6, 0}, Vec3<double>{0, 0, 1}},
                                      {1, 1, 1}};
    const OrientedBox<double> permuted{{0, 0, 0}, {Vec3<double>{0, 1, 0}, Vec3<double>{-1, 0, 0}, Vec3<double>{0, 0, 1}},
                                       {1, 1, 0}};
    filtered::Prepared<OrientedBox<double>> a(rotated, cyl), b(permuted, cyl);
    EXPECT_TRUE(filtered::turned(a));
    EXPECT_FALSE(filtered::turned(b));
    EXPECT_FALSE(a.facts().flat);
    EXPECT_TRUE(b.facts().flat);
    // (The prepared query refers to the caller's shapes: they must outlive it.)
    const AlignedBox<double> cube{{-1, -1, -1}, {1, 1, 1}};
    const Cylinder<double> two_scale{{0, 0, 0}, {0x1p-300, 0, 1}, 1, 2};
    filtered::Prepared<AlignedBox<double>> c(cube, two_scale);
    EXPECT_FALSE(filtered::turned(c));
    EXPECT_TRUE(c.facts().two_scale_axis);
    // Beyond stage 0's range, rescaled exactly by a power of two.
    const AlignedBox<double> huge{{-0x1p500, -1, -1}, {1, 1, 1}};
    filtered::Prepared<AlignedBox<double>> far(huge, cyl);
    EXPECT_TRUE(far.in_range);
    EXPECT_EQ(far.box.min[0], -1.0);
    // Far from the origin for its size (UTM coordinates, a millimetre box): moved near it, exactly.
    const AlignedBox<double> block{{512345.125, 6712345.5, 1234.25}, {512345.126, 6712345.501, 1234.251}};
    const Cylinder<double> hole{{512345.1255, 6712345.5005, 1234.2}, {0, 0, 1}, 0.0002, 0.5};
    filtered::Prepared<AlignedBox<double>> moved(block, hole);
    EXPECT_EQ(moved.box.min, (Vec3<double>{0, 0, 0}));
    EXPECT_EQ(moved.box.max[0], block.max[0] - block.min[0]);  // exact: Sterbenz
    EXPECT_EQ(moved.cyl.center[2], hole.center[2] - block.min[2]);
    EXPECT_EQ(moved.cyl.radius, hole.radius);
    // Stage 0's problem is the moved query's.
    filtered::semi_static::Problem p;
    ASSERT_TRUE(filtered::semi_static::problem(moved.box, moved.cyl, p));
    EXPECT_TRUE(moved.in_range);
    EXPECT_EQ(moved.p.c, p.c);
    EXPECT_EQ(moved.p.l, p.l);
    // Moved even where that leaves stage 0's range (shapes of 2^-230 at 2^-180), not rescaled.
    const AlignedBox<double> speck{{0x1p-180, 0, 0}, {0x1p-180 + 0x1p-229, 0x1p-229, 0x1p-229}};
    const Cylinder<double> beside{{0x1p-180 + 0x1p-228, 0, 0}, {0, 0, 1}, 0x1p-229, 0x1p-229};
    filtered::Prepared<AlignedBox<double>> tiny(speck, beside);
    EXPECT_EQ(tiny.box.min, (Vec3<double>{0, 0, 0}));
    EXPECT_FALSE(tiny.in_range);
    EXPECT_FALSE(tiny.rescaled());
    EXPECT_TRUE(intersects(speck, beside));  // the box's face x = 2^-229 touches the side
    // Not when a difference would round: a position of 2^-60 beside one of 2^40 on the same axis.
    const AlignedBox<double> at_2_40{{0x1p40, 0, 0}, {0x1p40 + 1, 1, 1}};
    const Cylinder<double> near_0{{0x1p-60, 0.5, 0.5}, {0, 0, 1}, 0.001, 0.002};
    filtered::Prepared<AlignedBox<double>> kept(at_2_40, near_0);
    EXPECT_EQ(kept.box.min[0], 0x1p40);
}

// The exact translation: every difference it makes is the exact one (rationals), in every rounding
// mode, and it happens exactly when all of them are doubles; the answer never changes.
TEST(Schedule, TranslationNearTheOriginIsExact) {
    std::mt19937_64 rng(7310);
    std::uniform_real_distribution<double> offset(1e5, 1e7), size(1e-3, 10), unit(-1, 1);
    long moved = 0, kept = 0;
    for (int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        for (int n = 0; n < 2000; ++n) {
            const Vec3<double> k{offset(rng), -offset(rng), offset(rng) * (n % 3 == 0 ? 1e-9 : 1)};
            const double s = size(rng);
            OrientedBox<double> box{k, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {s, s / 2, s}};
            Cylinder<double> cyl{{k[0] + s * unit(rng), k[1] + s * unit(rng), k[2] + s * unit(rng)},
                                 {unit(rng), unit(rng), 1}, s * 0.3, s};
            if (n % 7 == 0) cyl.center[0] = 0x1p-70;  // a difference that cannot be a double
            OrientedBox<double> b = box;
            Cylinder<double> c = cyl;
            bool ok;
            {
                const RoundingMode guard(mode);
                ok = filtered::translated_exactly(b, c);
            }
            if (!ok) {
                EXPECT_EQ(b.center, box.center);
                ++kept;
                continue;
            }
            ++moved;
            for (int i = 0; i < 3; ++i) {
                ASSERT_EQ(to_rational(b.center[i]), to_rational(box.center[i]) - to_rational(box.center[i]));
                ASSERT_EQ(to_rational(c.center[i]), to_rational(cyl.center[i]) - to_rational(box.center[i]))
                    << mode_name(mode) << " axis " << i;
            }
            if (n % 50 == 0) {
                const RoundingMode guard(mode);
                EXPECT_EQ(intersects(box, cyl), oracle::intersects(to_exact(box), to_exact(cyl)));
            }
        }
    }
    EXPECT_GT(moved, 4000);
    EXPECT_GT(kept, 500);
}

// Tiny sizes: the pairs shrunk to 0 and grown to τ = 2^-120 of the scale, with nothing tiny left in
// them (the row's recursion is one level deep).
TEST(Schedule, TinySizesShrinkAndGrow) {
    const double tau = 0x1p-118;  // for a scale of 4
    const OrientedBox<double> box{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}},
                                  {0x1p-1000, 1, 0x1p-118}};
    const Cylinder<double> cyl{{2, 0, 0}, {0, 0, 1}, 0x1p-1074, 4};
    const auto p = filtered::sandwich::pairs(box, cyl, 4.0);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->inner_box.extents, (Vec3<double>{0, 1, 0x1p-118}));  // τ itself is not tiny
    EXPECT_EQ(p->outer_box.extents, (Vec3<double>{tau, 1, 0x1p-118}));
    EXPECT_EQ(p->inner_cyl.radius, 0.0);
    EXPECT_EQ(p->outer_cyl.radius, tau);
    EXPECT_EQ(p->inner_cyl.height, 4.0);
    EXPECT_FALSE(filtered::sandwich::pairs(p->inner_box, p->inner_cyl, 4.0));
    EXPECT_FALSE(filtered::sandwich::pairs(p->outer_box, p->outer_cyl, 4.0));
    // An aligned box's width: [min, min] inside, [−τ, τ] outside, only where both ends lie within τ.
    const AlignedBox<double> thin{{-0x1p-1074, -1, 0x1p-200}, {0, 1, 0x1.0000000000001p-200}};
    const auto a = filtered::sandwich::pairs(thin, Cylinder<double>{{0, 0, 0}, {1, 0, 0}, 1, 1}, 4.0);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->inner_box.min, thin.min);
    EXPECT_EQ(a->inner_box.max, (Vec3<double>{-0x1p-1074, 1, 0x1p-200}));
    EXPECT_EQ(a->outer_box.min, (Vec3<double>{-tau, -1, -tau}));
    EXPECT_EQ(a->outer_box.max, (Vec3<double>{tau, 1, tau}));
    EXPECT_FALSE(filtered::sandwich::pairs(a->outer_box, Cylinder<double>{{0, 0, 0}, {1, 0, 0}, 1, 1}, 4.0));
    // Nothing tiny, or a scale whose τ is not normal: no pairs.
    EXPECT_FALSE(filtered::sandwich::pairs(OrientedBox<double>{box.center, box.axes, {1, 1, 1}},
                                           Cylinder<double>{{2, 0, 0}, {0, 0, 1}, 1, 4}, 4.0));
    EXPECT_FALSE(filtered::sandwich::pairs(box, cyl, 0x1p-903));
}

// Queries of the magnitudes profile's one-ulp pairs that only the exact stage decided (50 to 400 µs),
// now decided by the tiny sizes' pairs in round to nearest; the answers are the oracle's in every mode.
TEST(Schedule, TinySizesDecideTwoScaleBoundaryPairs) {
    const std::array<Vec3<double>, 3> axes0{Vec3<double>{-0x1.66d09039c9f9p-3, -0x1.205c2dad96825p-2, 0x1.e30565c7e17acp-1},
                                            Vec3<double>{0x1.9163f19aaf54p-1, -0x1.3d367dba67f84p-1, -0x1.424a584c55fd8p-5},
                                            Vec3<double>{0x1.30ee5e70e671ep-1, 0x1.77248e9d488dp-1, 0x1.5137a45f91286p-2}};
    const OrientedBox<double> miss_box{{0, 0, 0}, axes0, {0x1.66b405f8225f2p-32, 0x1.8568e755aa122p-9, 0x0.00000000993abp-1022}};
    const Cylinder<double> miss_cyl{{0x1.149364f4fe991p-9, 0x1.b59daa2cee24fp-13, -0x1.7503aaa01a9d9p-9},
                                    {0x1.cd35cc7dc078ep-1, -0x1.0fc54b017255p-1, -0x1.d89d6b0f1ef9ap-2},
                                    0x1.26d9b9d18613ep-9, 0x1.6f3e4316b330bp-8};
    const std::array<Vec3<double>, 3> axes1{Vec3<double>{0x1.f47f6cc8b2a16p-2, 0x1.34107f443544ap-6, -0x1.be928255ce53ap-1},
                                            Vec3<double>{0x1.fac40514692c2p-6, 0x1.ff5e379b660c9p-1, 0x1.3e5f1fbcaa504p-5},
                                            Vec3<double>{0x1.be652e3872496p-1, -0x1.789cf24734042p-5, 0x1.f348d1b34cdc8p-2}};
    const OrientedBox<double> hit_box{{0, 0, 0}, axes1, {0x0.0000000050eep-1022, 0x1.56e1fc2f8f359p-997, 0x0.0000000099c59p-1022}};
    const Cylinder<double> hit_cyl{{0x1.16d3b5849b009p+0, 0x1.bb1eb5af1e4d8p+0, -0x1.f4af90aba4ba3p+1},
                                   {0x1.bdd9a1d773bbep-1, 0x1.3b20956d5f538p-1, -0x1.a7ced7dacf31p-1},
                                   0x1.0aea59891b503p+1, 0x1.3ed9d967ac844p+3};
    ASSERT_FALSE(oracle::intersects(to_exact(miss_box), to_exact(miss_cyl)));
    ASSERT_TRUE(oracle::intersects(to_exact(hit_box), to_exact(hit_cyl)));
    {
        filtered::Stats stats;
        EXPECT_FALSE(filtered::query(miss_box, miss_cyl, stats).intersect);
        EXPECT_TRUE(filtered::query(hit_box, hit_cyl, stats).intersect);
        EXPECT_EQ(stats[filtered::RowId::tiny_sizes].misses, 1u);
        EXPECT_EQ(stats[filtered::RowId::tiny_sizes].hits, 1u);
        EXPECT_EQ(stats[filtered::RowId::exact].tried, 0u);
        EXPECT_FALSE(filtered::query(miss_box, miss_cyl).exact_used);
    }
    // The directed modes have no double-double rows: where the pairs' other rows cannot decide, the
    // exact stage answers the given query.
    for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        const RoundingMode guard(mode);
        EXPECT_FALSE(filtered::query(miss_box, miss_cyl).intersect) << mode_name(mode);
        EXPECT_TRUE(filtered::query(hit_box, hit_cyl).intersect) << mode_name(mode);
    }
    // Exactly touching with a tiny width: the inner pair touches exactly too, which no finite-precision
    // row decides, and the exact stage answers.
    const AlignedBox<double> thin{{0, 0, -0x1p-1074}, {1, 1, 0}};
    const Cylinder<double> touching{{3, 0.5, 0}, {0, 0, 1}, 2, 1};
    const filtered::Result r = filtered::query(thin, touching);
    EXPECT_TRUE(r.intersect);
    EXPECT_TRUE(r.exact_used);
}

// The row slabs on hand-made queries far from the origin: it decides a clear gap, a centre inside the
// box and a clear gap along the cylinder's axis; it leaves exactly touching shapes and a gap of one ulp
// (below its margin) undecided, as it does an axis whose largest component is subnormal and a NaN; in
// every rounding mode.
TEST(Slabs, DecideClearCasesLeaveTheRest) {
    const double x0 = 1e6;  // a block model's easting
    const AlignedBox<double> box{{x0, 0, 0}, {x0 + 1, 1, 1}};
    const OrientedBox<double> turned{{x0 + 0.5, 0.5, 0.5},
                                     {Vec3<double>{0x1.6a09e667f3bcdp-1, 0x1.6a09e667f3bcdp-1, 0},
                                      Vec3<double>{-0x1.6a09e667f3bcdp-1, 0x1.6a09e667f3bcdp-1, 0}, Vec3<double>{0, 0, 1}},
                                     {0.5, 0.5, 0.5}};
    const Vec3<double> z{0, 0, 1};
    const double one_ulp_short = std::nextafter(1.0, 0.0);
    struct Expect {
        Cylinder<double> cyl;
        std::optional<bool> aligned, oriented;
        const char* what;
    };
    const Expect cases[] = {
        {{{x0 + 3, 0.5, 0.5}, z, 1, 1}, false, false, "2 beyond a face, radius 1"},
        {{{x0 + 2, 0.5, 0.5}, z, 1, 1}, std::nullopt, std::nullopt, "touching a face (the aligned box's)"},
        {{{x0 + 2, 0.5, 0.5}, z, one_ulp_short, 1}, std::nullopt, std::nullopt, "one ulp short of a face"},
        {{{x0 + 0.5, 0.5, 0.5}, z, 0.1, 0.1}, true, true, "centre inside"},
        {{{x0 + 0.5, 0.5, 9}, z, 0.1, 2}, false, false, "beyond the top along the axis"},
        {{{x0 + 0.5, 0.5, 9}, {0x1p-1060, 0, 0x1p-1070}, 0.1, 2}, std::nullopt, std::nullopt, "subnormal axis"},
        {{{x0 + 3, 0.5, std::numeric_limits<double>::quiet_NaN()}, z, 1, 1}, std::nullopt, std::nullopt, "NaN"},
    };
    for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        for (const Expect& e : cases) {
            std::optional<bool> a, o;
            {
                const RoundingMode guard(mode);
                a = filtered::slabs::decide(box, e.cyl);
                o = filtered::slabs::decide(turned, e.cyl);
            }
            EXPECT_EQ(a, e.aligned) << e.what << " (" << mode_name(mode) << ")";
            EXPECT_EQ(o, e.oriented) << e.what << " (" << mode_name(mode) << ")";
            if (o) {
                EXPECT_EQ(*o, oracle::intersects(to_exact(turned), to_exact(e.cyl))) << e.what;
            }
        }
    }
}

// The statistics: a query through the front door with QueryOptions::stats counts one query, one
// deciding row and the rows tried before it.
TEST(Schedule, StatisticsCountWhatRan) {
    filtered::Stats stats;
    const AlignedBox<double> box{{-1, -1, -1}, {1, 1, 1}};
    // Near the origin: stage 0 on its direct path (the slabs do not run).
    EXPECT_FALSE(intersects(box, Cylinder<double>{{5, 0, 0}, {0, 0, 1}, 1, 1}, {.stats = &stats}));
    EXPECT_EQ(stats.queries, 1u);
    EXPECT_EQ(stats[filtered::RowId::semi_static].misses, 1u);
    EXPECT_EQ(stats[filtered::RowId::semi_static].tried, 1u);
    EXPECT_EQ(stats[filtered::RowId::slabs].tried, 0u);
    // The same far from the origin for its size: the slabs, on the query as given, before the exact move.
    const AlignedBox<double> far{{1e6 - 1, -1, -1}, {1e6 + 1, 1, 1}};
    EXPECT_FALSE(intersects(far, Cylinder<double>{{1e6 + 5, 0, 0}, {0, 0, 1}, 1, 1}, {.stats = &stats}));
    EXPECT_EQ(stats[filtered::RowId::slabs].misses, 1u);
    EXPECT_EQ(stats[filtered::RowId::slabs].tried, 1u);
    EXPECT_EQ(stats[filtered::RowId::semi_static].tried, 1u);
    // Exactly touching, integer coordinates: the exact stage for narrow inputs decides, after stage 0.
    EXPECT_TRUE(intersects(box, Cylinder<double>{{3, 0, 0}, {0, 0, 1}, 2, 1}, {.stats = &stats}));
    EXPECT_EQ(stats.queries, 3u);
    EXPECT_EQ(stats[filtered::RowId::semi_static].tried, 2u);
    EXPECT_EQ(stats[filtered::RowId::exact_narrow].hits, 1u);
    std::uint64_t decided = 0;
    for (const auto& r : stats.rows) decided += r.hits + r.misses;
    EXPECT_EQ(decided, 3u);
    const std::string table = stats.table();
    EXPECT_NE(table.find("| slabs | 1 | 1 |"), std::string::npos) << table;
    EXPECT_NE(table.find("| semi_static | 2 | 1 |"), std::string::npos) << table;
    EXPECT_NE(table.find("| exact_narrow | 1 | 1 |"), std::string::npos) << table;
    // Float inputs count too (widened exactly).
    filtered::Stats f;
    EXPECT_FALSE(intersects(AlignedBox<float>{{-1, -1, -1}, {1, 1, 1}}, Cylinder<float>{{5, 0, 0}, {0, 0, 1}, 1, 1},
                            {.stats = &f}));
    EXPECT_EQ(f.queries, 1u);
}

}  // namespace
}  // namespace boxcyl
