// The grid query (boxcyl/grid.hpp) against brute force: the exact default query on every
// cell of small grids, for random cylinders (fixed seeds) that include touching configurations —
// cylinders tangent to cell faces, along grid lines, through grid vertices, disks and segments in grid
// planes, oriented axes with exactly rational directions, cylinders partly or wholly outside the grid —
// and grids whose cell bounds round. On a 1000³-cell grid, where brute force is out of reach, the
// answer is checked locally instead (see LargeGrid below). Every failure prints the seed and the case
// as copy-pasteable C++.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "boxcyl/grid.hpp"
#include "boxcyl/number/rational.hpp"

namespace boxcyl {
namespace {

std::string hex(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
std::string hex(const Vec3<double>& v) { return "{" + hex(v[0]) + ", " + hex(v[1]) + ", " + hex(v[2]) + "}"; }

// The case as C++ that rebuilds it bit for bit.
std::string describe(const Grid& g, const Cylinder<double>& c) {
    return "Grid{" + hex(g.origin) + ", " + hex(g.cell_size) + ", {" + std::to_string(g.counts[0]) + ", " +
           std::to_string(g.counts[1]) + ", " + std::to_string(g.counts[2]) + "}}, Cylinder<double>{" +
           hex(c.center) + ", " + hex(c.axis) + ", " + hex(c.radius) + ", " + hex(c.height) + "}";
}

std::string str(const CellIndex& c) {
    return "(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + ")";
}

// Every cell, the exact default query on each: the definition of the answer.
std::vector<CellIndex> brute_force(const Grid& g, const Cylinder<double>& c) {
    std::vector<CellIndex> out;
    for (std::int64_t i = 0; i < g.counts[0]; ++i)
        for (std::int64_t j = 0; j < g.counts[1]; ++j)
            for (std::int64_t k = 0; k < g.counts[2]; ++k)
                if (intersects(cell_box(g, {i, j, k}), c)) out.push_back({i, j, k});
    return out;
}

// Compares cells() with brute force; on a mismatch names the seed, the case and the first differences.
// Returns the number of cells found (for the generators' hit-rate checks).
std::size_t check(const Grid& g, const Cylinder<double>& c, const std::string& where) {
    SCOPED_TRACE(where + "\n  " + describe(g, c));
    EXPECT_TRUE(validate(g).ok()) << validate(g).message();
    EXPECT_TRUE(validate(c).ok()) << validate(c).message();
    GridStats stats;
    const std::vector<CellIndex> got = cells(g, c, &stats);
    const std::vector<CellIndex> want = brute_force(g, c);
    if (got != want) {
        std::vector<CellIndex> missing, extra;
        std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
        std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
        std::string m = "missing:";
        for (std::size_t i = 0; i < missing.size() && i < 8; ++i) m += " " + str(missing[i]);
        m += "  extra:";
        for (std::size_t i = 0; i < extra.size() && i < 8; ++i) m += " " + str(extra[i]);
        ADD_FAILURE() << "grid query != brute force (" << got.size() << " vs " << want.size() << " cells) " << m;
    }
    EXPECT_EQ(stats.cells, static_cast<std::int64_t>(got.size()));
    EXPECT_EQ(stats.range_widened, 0) << "the bounding box excluded a cell that the exact check kept";
    return want.size();
}

// ---- Definitions: cell bounds, validation ----

TEST(GridBounds, RoundedOnceToNearest) {
    // origin + i·size rounded once (fma), not twice; 0.1 and 0.3 are not dyadic, so bounds round.
    const Grid g{{0.1, -0.3, 1e16}, {0.1, 0.3, 0.7}, {1000, 1000, 1000}};
    for (std::size_t a = 0; a < 3; ++a)
        for (std::int64_t i = 0; i <= g.counts[a]; ++i) {
            const double b = grid_bound(g, a, i);
            const Rational exact = to_rational(g.origin[a]) + Rational(static_cast<long>(i)) * to_rational(g.cell_size[a]);
            const Rational err = abs(to_rational(b) - exact);
            // Nearest: no neighbouring double is closer.
            ASSERT_LE(err, abs(to_rational(std::nextafter(b, -1e300)) - exact)) << "axis " << a << " i " << i;
            ASSERT_LE(err, abs(to_rational(std::nextafter(b, 1e300)) - exact)) << "axis " << a << " i " << i;
        }
    // Where two roundings differ from one: 0.1 + 3·0.1 with the product rounded first is 0.4 + 1 ulp.
    int differs = 0;
    for (std::int64_t i = 0; i <= 1000; ++i)
        differs += grid_bound(g, 0, i) != g.origin[0] + static_cast<double>(i) * g.cell_size[0];
    EXPECT_GT(differs, 0) << "the example should show why the single rounding is specified";
    // Adjacent cells share their face exactly; bounds never decrease (flat cells near 1e16 with 0.7).
    for (std::int64_t i = 0; i + 1 < 1000; ++i) {
        EXPECT_EQ(cell_box(g, {i, i, i}).max[0], cell_box(g, {i + 1, i, i}).min[0]);
        EXPECT_EQ(cell_box(g, {i, i, i}).max[2], cell_box(g, {i, i, i + 1}).min[2]);
        EXPECT_LE(grid_bound(g, 2, i), grid_bound(g, 2, i + 1));
    }
}

TEST(GridValidate, NamesTheBadField) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const Grid ok{{0, 0, 0}, {1, 1, 1}, {2, 3, 4}};
    EXPECT_TRUE(validate(ok).ok());
    EXPECT_TRUE(validate(Grid{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}}).ok());  // no cells is a valid grid
    Grid g = ok;
    g.origin[1] = nan;
    EXPECT_EQ(validate(g).message(), "grid.origin[1]: is NaN");
    g = ok;
    g.cell_size[2] = 0;
    EXPECT_EQ(validate(g).message(), "grid.cell_size[2]: is not positive");
    g = ok;
    g.cell_size[0] = -1;
    EXPECT_EQ(validate(g).message(), "grid.cell_size[0]: is not positive");
    g = ok;
    g.cell_size[0] = inf;
    EXPECT_EQ(validate(g).message(), "grid.cell_size[0]: is +Inf");
    g = ok;
    g.counts[1] = -1;
    EXPECT_EQ(validate(g).message(), "grid.counts[1]: is negative");
    g = ok;
    g.counts[2] = max_grid_count + 1;
    EXPECT_EQ(validate(g).message(), "grid.counts[2]: exceeds 2^53");
    g = ok;
    g.counts[2] = max_grid_count;
    EXPECT_TRUE(validate(g).ok());
    g = ok;
    g.cell_size[0] = 1e300;
    g.counts[0] = 1000000000;  // 1e309
    EXPECT_EQ(validate(g, "q.grid").field, "q.grid.counts[0]");
}

// ---- Hand cases with answers worked out by hand (and brute force agreeing) ----

using Cells = std::vector<CellIndex>;

TEST(GridHand, SegmentAlongAGridLineTouchesFourCellsPerStep) {
    // Unit cells, origin 0, 4×4×4. The segment y = 2, z = 2, 0.5 ≤ x ≤ 1.5 lies on the edge shared by
    // the cells j, k ∈ {1, 2}, for i ∈ {0, 1}.
    const Grid g{{0, 0, 0}, {1, 1, 1}, {4, 4, 4}};
    const Cylinder<double> seg{{1, 2, 2}, {1, 0, 0}, 0, 1};
    Cells want;
    for (std::int64_t i : {0, 1})
        for (std::int64_t j : {1, 2})
            for (std::int64_t k : {1, 2}) want.push_back({i, j, k});
    EXPECT_EQ(cells(g, seg), want);
    check(g, seg, "hand");
    // A segment that ends exactly on the face x = 1 (0 ≤ x ≤ 1) touches the cells i = 1 too; one that
    // stops short of it does not.
    const Cylinder<double> to_face{{0.5, 2, 2}, {1, 0, 0}, 0, 1};  // 0 ≤ x ≤ 1
    EXPECT_EQ(cells(g, to_face), want);
    const Cylinder<double> short_of_face{{0.5, 2, 2}, {1, 0, 0}, 0, 0.875};
    EXPECT_EQ(cells(g, short_of_face).size(), 4u);
}

TEST(GridHand, TangentCylinderIncludesTheTouchedCells) {
    // Axis along z through the vertex line x = y = 2, radius 1: tangent to the planes x = 1, x = 3,
    // y = 1, y = 3, so the rings of cells beyond them (i = 0 or 3, j ∈ [1, 2]) are touched; the corner
    // cells (0, 0) etc. are at distance √2 > 1. Height 2 centred at z = 2: k ∈ {1, 2}, and the disks
    // touch the faces z = 1 and z = 3, so k = 0 and k = 3 too.
    const Grid g{{0, 0, 0}, {1, 1, 1}, {4, 4, 4}};
    const Cylinder<double> c{{2, 2, 2}, {0, 0, 3}, 1, 2};
    Cells want;
    for (std::int64_t i = 0; i < 4; ++i)
        for (std::int64_t j = 0; j < 4; ++j) {
            const bool corner = (i == 0 || i == 3) && (j == 0 || j == 3);
            if (corner) continue;
            for (std::int64_t k = 0; k < 4; ++k) want.push_back({i, j, k});
        }
    EXPECT_EQ(cells(g, c), want);
    // One ulp thinner, the side no longer reaches the planes x = 1, 3 and y = 1, 3.
    Cylinder<double> thinner = c;
    thinner.radius = std::nextafter(1.0, 0.0);
    Cells inner;
    for (std::int64_t i : {1, 2})
        for (std::int64_t j : {1, 2})
            for (std::int64_t k = 0; k < 4; ++k) inner.push_back({i, j, k});
    EXPECT_EQ(cells(g, thinner), inner);
    check(g, c, "hand");
    check(g, thinner, "hand");
}

TEST(GridHand, DiskInAGridPlaneAndPointsOnVertices) {
    const Grid g{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
    // The disk z = 1, centre (1.5, 1.5), radius 0.5: inside the face between k = 0 and k = 1 of the
    // middle column, touching the edges of its neighbours at (1.5, 1) etc.
    const Cylinder<double> disk{{1.5, 1.5, 1}, {0, 0, -2}, 0.5, 0};
    Cells want;
    for (const auto& ij : {std::array<std::int64_t, 2>{0, 1}, {1, 0}, {1, 1}, {1, 2}, {2, 1}})
        for (std::int64_t k : {0, 1}) want.push_back({ij[0], ij[1], k});
    std::sort(want.begin(), want.end());
    EXPECT_EQ(cells(g, disk), want);
    // A point (r = h = 0) on a grid vertex touches the 8 cells around it; on the grid's corner, one.
    const Cylinder<double> vertex{{1, 2, 1}, {1, 1, 1}, 0, 0};
    EXPECT_EQ(cells(g, vertex).size(), 8u);
    const Cylinder<double> corner{{3, 3, 3}, {1, 1, 1}, 0, 0};
    EXPECT_EQ(cells(g, corner), (Cells{{2, 2, 2}}));
    check(g, disk, "hand");
    check(g, vertex, "hand");
    check(g, corner, "hand");
}

TEST(GridHand, OutsideEmptyAndDegenerateGrids) {
    const Grid g{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
    // Tangent to the grid's face x = 3 from outside: only the cells of the last slab that it reaches.
    const Cylinder<double> outside_touching{{4, 1.5, 1.5}, {0, 0, 1}, 1, 1};
    Cells want;
    for (std::int64_t k : {0, 1, 2}) want.push_back({2, 1, k});
    EXPECT_EQ(cells(g, outside_touching), want);
    const Cylinder<double> outside{{4, 1.5, 1.5}, {0, 0, 1}, std::nextafter(1.0, 0.0), 1};
    GridStats s;
    EXPECT_TRUE(cells(g, outside, &s).empty());
    EXPECT_LE(s.queries, 6) << "a miss is settled by the range checks alone";
    EXPECT_TRUE(cells(Grid{{0, 0, 0}, {1, 1, 1}, {3, 0, 3}}, outside_touching).empty());
    // A huge grid (2^53 cells per axis) and a cylinder far outside: a handful of queries.
    const Grid huge{{0, 0, 0}, {1, 1, 1}, {max_grid_count, max_grid_count, max_grid_count}};
    GridStats hs;
    EXPECT_TRUE(cells(huge, Cylinder<double>{{-10, -10, -10}, {1, 2, 3}, 1, 1}, &hs).empty());
    EXPECT_LE(hs.queries, 6);
    check(g, outside_touching, "hand");
    check(g, outside, "hand");
}

TEST(GridHand, SegmentEndingOnARoundedBound) {
    // Non-dyadic grid: the bounds are rounded, and the answer is exact for the rounded cell boxes. A
    // segment along x that starts exactly at bound(0, i) touches cell i − 1; one ulp later it does not.
    const Grid g{{0.1, 0.1, 0.1}, {0.1, 0.1, 0.1}, {10, 10, 10}};
    for (std::int64_t i = 1; i < 10; ++i) {
        const double x = grid_bound(g, 0, i);
        const double y = 0.5 * (grid_bound(g, 1, 4) + grid_bound(g, 1, 5));  // inside row j = 4
        const double z = 0.5 * (grid_bound(g, 2, 6) + grid_bound(g, 2, 7));  // inside layer k = 6
        const Cylinder<double> from{{x, y, z}, {1, 0, 0}, 0, 0};               // the point at x
        EXPECT_EQ(cells(g, from), (Cells{{i - 1, 4, 6}, {i, 4, 6}})) << "i " << i;
        const Cylinder<double> after{{std::nextafter(x, 2.0), y, z}, {1, 0, 0}, 0, 0};
        EXPECT_EQ(cells(g, after), (Cells{{i, 4, 6}})) << "i " << i;
    }
}

// The bounding box decides which cells are candidates; the exact check behind it must never have to
// widen it (GridStats::range_widened == 0). The sharpest inputs are cylinders whose extreme point along
// an axis lies exactly on a grid plane: oblique axes with rational directions and rational extents —
// (p, q, 0)/n for Pythagorean triples, where h/2·|u_x| + r·sqrt(1 − u_x²) = (h/2·p + r·q)/n, and
// segments along (1, 2, 2)/3 or (2, 3, 6)/7 — placed on grid vertices.
TEST(GridBoundingBox, ExtremesOnGridPlanes) {
    std::mt19937_64 rng(0x6d1d0301u);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const std::array<std::array<double, 4>, 5> directions{{  // (p, q, w) and n = |(p, q, w)|
        {3, 4, 0, 5}, {5, 12, 0, 13}, {8, 15, 0, 17}, {1, 2, 2, 3}, {2, 3, 6, 7}}};
    std::size_t touching = 0;
    for (int n = 0; n < 300; ++n) {
        const Grid g{{-2, -1.5, 0}, {0.5, 0.5, 0.5}, {8, 8, 8}};
        const auto& d = directions[static_cast<std::size_t>(pick(0, 4))];
        Vec3<double> axis{d[0], d[1], d[2]};
        const int r0 = pick(0, 2);  // a random signed permutation
        axis = {axis[static_cast<std::size_t>(r0)], axis[static_cast<std::size_t>((r0 + 1) % 3)],
                axis[static_cast<std::size_t>((r0 + 2) % 3)]};
        for (std::size_t i = 0; i < 3; ++i)
            if (pick(0, 1)) axis[i] = -axis[i];
        const bool planar = d[2] == 0;
        // Extents (h/2·p + r·q)/n, (h/2·q + r·p)/n, r for planar directions; h/2·(p, q, w)/n for segments:
        // multiples of a half cell when h/2 = n·α/2 and r = n·β/2 (α, β small integers).
        const double half_h = d[3] * 0.5 * pick(0, 3);
        const double r = planar ? d[3] * 0.5 * pick(0, 2) : 0;
        Cylinder<double> c{{}, axis, r, 2 * half_h};
        if (c.height == 0 && c.radius == 0) c.height = 2 * d[3];
        for (std::size_t a = 0; a < 3; ++a) c.center[a] = grid_bound(g, a, pick(-2, 10));
        touching += check(g, c, "ExtremesOnGridPlanes case " + std::to_string(n)) > 0;
    }
    EXPECT_GE(touching, 100u);
}

// ---- Random cases against brute force ----

// Cylinders built from the grid's own half-cell lattice so that touching is common: centres on
// vertices, edges, faces and cell centres (also outside the grid), axes along the grid or with exactly
// rational directions ((1,2,2)/3, (2,3,6)/7, (1,1,0)/√2…), radii and heights in half cells.
class SnappedGenerator {
public:
    explicit SnappedGenerator(std::uint64_t seed) : rng_(seed) {}

    Grid grid(std::int64_t max_count) {
        Grid g;
        for (std::size_t a = 0; a < 3; ++a) {
            g.origin[a] = 0.25 * static_cast<double>(pick(-12, 12));
            g.cell_size[a] = std::ldexp(1.0, static_cast<int>(pick(-2, 1)));
            g.counts[a] = pick(1, max_count);
        }
        if (pick(0, 2) == 0) g.cell_size[1] = g.cell_size[2] = g.cell_size[0];  // cubic cells
        return g;
    }

    Cylinder<double> cylinder(const Grid& g) {
        Cylinder<double> c;
        const double s = std::min({g.cell_size[0], g.cell_size[1], g.cell_size[2]});
        const bool outside = pick(0, 3) == 0;  // centre up to 2 cells outside the grid (else inside)
        for (std::size_t a = 0; a < 3; ++a)  // on the half-cell lattice
            c.center[a] = g.origin[a] + 0.5 * g.cell_size[a] *
                                            static_cast<double>(outside ? pick(-4, 2 * g.counts[a] + 4)
                                                                        : pick(0, 2 * g.counts[a]));
        c.axis = axis();
        switch (pick(0, 3)) {
            case 0: c.radius = 0; break;  // segment
            case 1: c.radius = std::uniform_real_distribution<double>(0, 3 * s)(rng_); break;
            default: c.radius = 0.5 * s * static_cast<double>(pick(1, 6)); break;
        }
        switch (pick(0, 3)) {
            case 0: c.height = 0; break;  // disk
            case 1: c.height = std::uniform_real_distribution<double>(0, 8 * s)(rng_); break;
            default: c.height = 0.5 * s * static_cast<double>(pick(1, 12)); break;
        }
        // With a direction (1,2,2)/3 or (2,3,6)/7 this puts the ends on the quarter-cell lattice.
        if (pick(0, 3) == 0) c.height = 0.5 * s * static_cast<double>(pick(1, 3)) * std::sqrt(dot(c.axis, c.axis));
        return c;
    }

    std::int64_t pick(std::int64_t lo, std::int64_t hi) {
        return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng_);
    }

private:
    Vec3<double> axis() {
        static const std::array<Vec3<double>, 8> rational{{
            {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 2, 2}, {2, 3, 6}, {3, 4, 0}, {1, -1, 0}, {0, 0, 5}}};
        Vec3<double> a;
        if (pick(0, 4) == 0) {
            std::normal_distribution<double> n;
            a = {n(rng_), n(rng_), n(rng_)};
        } else {
            a = rational[static_cast<std::size_t>(pick(0, rational.size() - 1))];
            // A random signed permutation of the components keeps the direction rational.
            const std::int64_t r = pick(0, 2);
            a = {a[static_cast<std::size_t>(r)], a[static_cast<std::size_t>((r + 1) % 3)],
                 a[static_cast<std::size_t>((r + 2) % 3)]};
            if (pick(0, 1)) std::swap(a[0], a[1]);
            for (std::size_t i = 0; i < 3; ++i)
                if (pick(0, 1)) a[i] = -a[i];
        }
        if (a[0] == 0 && a[1] == 0 && a[2] == 0) a = {0, 0, 1};
        return a;
    }

    std::mt19937_64 rng_;
};

class GridSnapped : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(GridSnapped, MatchesBruteForce) {
    const std::uint64_t seed = GetParam();
    SnappedGenerator gen(seed);
    std::size_t hits = 0;
    constexpr int kCases = 150;
    for (int n = 0; n < kCases; ++n) {
        const Grid g = gen.grid(n % 10 == 0 ? 16 : 8);
        const Cylinder<double> c = gen.cylinder(g);
        hits += check(g, c, "seed " + std::to_string(seed) + " case " + std::to_string(n)) > 0;
    }
    // The generator is meant to produce mostly hits, including partial ones.
    EXPECT_GE(hits, kCases / 2u) << "seed " << seed;
}

// cells_within against every cell asked within_distance, on snapped grids (where many cells lie at an
// exact distance from the cylinder) at margins of a fraction to a few cells, and a bad margin refused.
TEST(GridWithin, MatchesEveryCellAsked) {
    SnappedGenerator gen(0x6d1d0100);
    std::mt19937_64 rng(0x6d1d0100);
    std::size_t grown = 0;
    for (int n = 0; n < 60; ++n) {
        const Grid g = gen.grid(8);
        const Cylinder<double> c = gen.cylinder(g);
        const double margin = g.cell_size[0] * std::array<double, 4>{0.5, 1, 2.5, 0x1p-30}[rng() % 4];
        SCOPED_TRACE("case " + std::to_string(n) + " margin " + std::to_string(margin) + "\n  " + describe(g, c));
        std::vector<CellIndex> want;
        for (std::int64_t i = 0; i < g.counts[0]; ++i)
            for (std::int64_t j = 0; j < g.counts[1]; ++j)
                for (std::int64_t k = 0; k < g.counts[2]; ++k)
                    if (within_distance(cell_box(g, {i, j, k}), c, margin)) want.push_back({i, j, k});
        EXPECT_EQ(cells_within(g, c, margin), want);
        EXPECT_EQ(cells_within(g, c, 0.0), cells(g, c));
        grown += want.size() > cells(g, c).size();
    }
    EXPECT_GT(grown, 30u);
    const Grid g{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    EXPECT_THROW(cells_within(g, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 1}, -1.0), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Seeds, GridSnapped, ::testing::Values(0x6d1d0001u, 0x6d1d0002u, 0x6d1d0003u, 0x6d1d0004u));

// Grids whose bounds round (origins and sizes that are not dyadic, anisotropic cells) and cylinders of
// any orientation and size around them, many partly outside.
class GridRounded : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(GridRounded, MatchesBruteForce) {
    const std::uint64_t seed = GetParam();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::normal_distribution<double> normal;
    std::size_t hits = 0;
    constexpr int kCases = 60;
    for (int n = 0; n < kCases; ++n) {
        Grid g;
        for (std::size_t a = 0; a < 3; ++a) {
            g.origin[a] = 10 * u(rng);
            g.cell_size[a] = 0.1 * std::exp2(2 * u(rng));  // 0.025 … 0.4
            g.counts[a] = std::uniform_int_distribution<std::int64_t>(1, n % 10 == 0 ? 20 : 10)(rng);
        }
        Cylinder<double> c;
        for (std::size_t a = 0; a < 3; ++a)  // anywhere from a cell before the grid to a cell after it
            c.center[a] = g.origin[a] + g.cell_size[a] * (static_cast<double>(g.counts[a]) + 2) * (0.5 + 0.5 * u(rng)) -
                          g.cell_size[a];
        c.axis = {normal(rng), normal(rng), normal(rng)};
        if (n % 7 == 0) c.axis[static_cast<std::size_t>(n % 3)] = 0;  // axis in a grid plane
        const double s = g.cell_size[0];
        c.radius = n % 11 == 0 ? 0 : s * 3 * (0.5 + 0.5 * u(rng));
        c.height = n % 13 == 0 ? 0 : s * 10 * (0.5 + 0.5 * u(rng));
        hits += check(g, c, "seed " + std::to_string(seed) + " case " + std::to_string(n)) > 0;
    }
    EXPECT_GE(hits, kCases / 2u) << "seed " << seed;
}

INSTANTIATE_TEST_SUITE_P(Seeds, GridRounded, ::testing::Values(0x6d1d0101u, 0x6d1d0102u, 0x6d1d0103u));

// Tiny and huge scales: a grid of 2^-500-sized cells and one of 2^500-sized cells, same shapes.
TEST(GridScales, MatchesBruteForceAtExtremeScales) {
    SnappedGenerator gen(0x6d1d0201u);
    for (int e : {-500, 500, -1000}) {
        for (int n = 0; n < 20; ++n) {
            Grid g = gen.grid(6);
            Cylinder<double> c = gen.cylinder(g);
            for (std::size_t a = 0; a < 3; ++a) {
                g.origin[a] = std::ldexp(g.origin[a], e);
                g.cell_size[a] = std::ldexp(g.cell_size[a], e);
                c.center[a] = std::ldexp(c.center[a], e);
            }
            c.radius = std::ldexp(c.radius, e);
            c.height = std::ldexp(c.height, e);
            check(g, c, "scale 2^" + std::to_string(e) + " case " + std::to_string(n));
        }
    }
}

// Cylinders many cells thick, so that whole blocks (larger than the 64 cells that always go to the batch filter)
// lie inside and are reported without descending (GridStats::blocks_inside), including blocks whose
// corners lie exactly on the side or on a disk: radius 20 about a vertex line of unit cells has the
// corners (±12, ±16) and (±20, 0) on its side.
TEST(GridFat, WholeBlocksInsideMatchBruteForce) {
    std::mt19937_64 rng(0x6d1d0401u);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    std::normal_distribution<double> normal;
    std::int64_t inside_blocks = 0;
    for (int n = 0; n < 40; ++n) {
        const Grid g{{-32, -32, -24}, {1, 1, 1}, {64, 64, 48}};
        Cylinder<double> c;
        if (n % 2 == 0) {  // along a grid axis through a vertex line, ends on grid planes
            const std::size_t a = static_cast<std::size_t>(pick(0, 2));
            c.axis = {0, 0, 0};
            c.axis[a] = pick(0, 1) ? 1 : -3;
            c.center = {static_cast<double>(pick(-8, 8)), static_cast<double>(pick(-8, 8)), static_cast<double>(pick(-8, 8))};
            c.radius = pick(0, 1) ? 20 : 18.5;
            c.height = 8 * pick(1, 5);
        } else {
            c.axis = {normal(rng), normal(rng), normal(rng)};
            c.center = {4 * normal(rng), 4 * normal(rng), 4 * normal(rng)};
            c.radius = 12 + 12 * std::abs(normal(rng));
            c.height = 16 + 32 * std::abs(normal(rng));
        }
        GridStats s;
        cells(g, c, &s);
        inside_blocks += s.blocks_inside;
        check(g, c, "GridFat case " + std::to_string(n));
    }
    EXPECT_GT(inside_blocks, 20) << "the cases should exercise whole-block acceptance";
}

// Counts whose product overflows 64-bit integers (4·10^20 cells): block sizes are compared per axis
// first, so the walk descends to the one cell the small cylinder meets.
TEST(GridScale, HugeCountsDoNotOverflowBlockSizes) {
    const Grid g{{0, 0, 0}, {1, 1, 1}, {10000000, 10000000, 4000000}};
    const Cylinder<double> c{{5000000.5, 5000000.5, 2000000.5}, {0, 0, 1}, 0.25, 0.5};
    const std::vector<CellIndex> got = cells(g, c);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0], (CellIndex{5000000, 5000000, 2000000}));
}

// ---- Scale: a 1000³-cell grid, where brute force (10^9 queries) is out of reach ----
//
// Local check instead: every reported cell intersects (exact query), no cell is reported twice, and
// every 26-neighbour of a reported cell that is not reported misses. That proves the answer complete:
// the cells meeting a convex solid form one 26-connected set (the solid ∩ the grid's box is convex,
// hence connected, and is covered by those closed cells), so a missed cell would be the neighbour of a
// reported one. Also checks the cost claim: queries grow with the cells found, not with 10^9.
TEST(LargeGrid, ThinLongCylinderIsCompleteAndCheap) {
    const Grid g{{-500, -500, -500}, {1, 1, 1}, {1000, 1000, 1000}};
    const std::array<Cylinder<double>, 3> cases{{
        {{0.3, -0.2, 0.1}, {1, 1.1, 0.9}, 2, 1000},   // diagonal, radius 2 cells, ~1000 cells long
        {{0, 0.5, 0}, {0, 0, 1}, 2, 2000},            // along z through the whole grid, tangent to faces
        {{10, 20, 30}, {3, -2, 6}, 1.5, 600},         // rational direction (3,-2,6)/7
    }};
    for (const auto& c : cases) {
        SCOPED_TRACE(describe(g, c));
        GridStats s;
        std::vector<CellIndex> got;
        for_each_cell(g, c, [&](std::int64_t i, std::int64_t j, std::int64_t k) { got.push_back({i, j, k}); }, &s);
        ASSERT_FALSE(got.empty());
        std::sort(got.begin(), got.end());
        EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << "a cell reported twice";
        EXPECT_EQ(s.cells, static_cast<std::int64_t>(got.size()));
        EXPECT_EQ(s.range_widened, 0);
        const std::set<CellIndex> found(got.begin(), got.end());
        std::set<CellIndex> checked;
        for (const CellIndex& cell : got) {
            ASSERT_TRUE(intersects(cell_box(g, cell), c)) << str(cell);
            for (std::int64_t di = -1; di <= 1; ++di)
                for (std::int64_t dj = -1; dj <= 1; ++dj)
                    for (std::int64_t dk = -1; dk <= 1; ++dk) {
                        const CellIndex n{cell[0] + di, cell[1] + dj, cell[2] + dk};
                        bool inside = true;
                        for (std::size_t a = 0; a < 3; ++a) inside = inside && n[a] >= 0 && n[a] < g.counts[a];
                        if (!inside || found.count(n) || !checked.insert(n).second) continue;
                        ASSERT_FALSE(intersects(cell_box(g, n), c)) << "missed neighbour " << str(n);
                    }
        }
        EXPECT_LE(s.queries, 8 * s.cells + 200) << "cells " << s.cells;
        std::printf("[ grid ] %zu cells, %lld exact queries (%lld on single cells)\n", got.size(),
                    static_cast<long long>(s.queries), static_cast<long long>(s.cell_queries));
    }
}

}  // namespace
}  // namespace boxcyl
