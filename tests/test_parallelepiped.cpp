// boxcyl::Parallelepiped: the default query against the oracle on exactly touching integer-vertex
// parallelepipeds (each with its miss one ulp away), flat and degenerate ones, and random ones (fixed
// seeds); the oracle's own entry for flat solids against exact §3; the explicit options; validate().
#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <vector>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "boxcyl/batch.hpp"
#include "boxcyl/boxcyl.hpp"
#include "boxcyl/exact/answer.hpp"
#include "boxcyl/exact/paths.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/oracle/oracle.hpp"
#include "support/fp.hpp"

namespace boxcyl {
namespace {

using P = Parallelepiped<double>;
using C = Cylinder<double>;

std::string hex(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
std::string hex(const Vec3<double>& v) { return "{" + hex(v[0]) + ", " + hex(v[1]) + ", " + hex(v[2]) + "}"; }
// The case as copy-pasteable C++.
std::string describe(const P& b, const C& c) {
    return "Parallelepiped<double>{" + hex(b.center) + ", {Vec3<double>" + hex(b.axes[0]) + ", Vec3<double>" +
           hex(b.axes[1]) + ", Vec3<double>" + hex(b.axes[2]) + "}, " + hex(b.extents) + "}, Cylinder<double>{" +
           hex(c.center) + ", " + hex(c.axis) + ", " + hex(c.radius) + ", " + hex(c.height) + "}";
}

double below(double x) { return std::nextafter(x, -INFINITY); }
double above(double x) { return std::nextafter(x, INFINITY); }

bool oracle_answer(const P& b, const C& c) { return oracle::intersects(to_exact(b), to_exact(c)); }

// The default query agrees with the oracle; returns the answer. Counts the exact fallbacks.
struct Checker {
    int cases = 0, exact = 0;
    bool operator()(const P& b, const C& c) {
        EXPECT_TRUE(validate(b).ok()) << describe(b, c);
        const filtered::Result r = filtered::query(b, c);
        const bool want = oracle_answer(b, c);
        EXPECT_EQ(r.intersect, want) << describe(b, c);
        EXPECT_EQ(intersects(b, c), want) << describe(b, c);
        ++cases;
        exact += r.exact_used;
        return want;
    }
};

const P integer_box{{0, 0, 0}, {Vec3<double>{3, 4, 0}, Vec3<double>{-4, 3, 0}, Vec3<double>{0, 0, 5}}, {1, 1, 1}};

TEST(ParallelepipedHand, IntegerVertexBoxTouchingFaceSide) {
    // The face W0·X = 25 (x0 = 1) is at distance 5 from the centre along (3,4,0)/5; a cylinder of
    // radius 5 along z centred at (6,8,0) (distance 10) touches it.
    Checker check;
    EXPECT_TRUE(check(integer_box, {{6, 8, 0}, {0, 0, 1}, 5, 2}));
    EXPECT_FALSE(check(integer_box, {{6, 8, 0}, {0, 0, 1}, below(5), 2}));
    EXPECT_FALSE(check(integer_box, {{above(6), 8, 0}, {0, 0, 1}, 5, 2}));
}

TEST(ParallelepipedHand, IntegerVertexBoxTouchingCap) {
    // The top face z = 5 and a disk of any radius whose centre is at height 5 + h/2.
    Checker check;
    EXPECT_TRUE(check(integer_box, {{1, 2, 6}, {0, 0, 3}, 0.5, 2}));
    EXPECT_FALSE(check(integer_box, {{1, 2, above(6)}, {0, 0, 3}, 0.5, 2}));
    EXPECT_FALSE(check(integer_box, {{1, 2, 6}, {0, 0, 3}, 0.5, below(2)}));
    // A disk (h = 0) lying in the face plane.
    EXPECT_TRUE(check(integer_box, {{20, 0, 5}, {0, 0, -1}, 19, 0}));
}

TEST(ParallelepipedHand, IntegerVertexBoxTouchingVertex) {
    // Vertex V = W0 + W1 + W2 = (−1, 7, 5); the outward normal m = (−2, 6, 3) (|m| = 7) has m·V = 59 and
    // m·(other vertices) < 59, so the plane m·X = 59 touches the box at V only. A cylinder whose axis
    // ⊥ m passes through V + 7·m/7 = V + m touches it with radius 7.
    Checker check;
    const Vec3<double> v{-1, 7, 5}, m{-2, 6, 3};
    const Vec3<double> axis = cross(m, Vec3<double>{1, 0, 0});
    EXPECT_TRUE(check(integer_box, {v + m, axis, 7, 3}));
    EXPECT_FALSE(check(integer_box, {v + m, axis, below(7), 3}));
}

TEST(ParallelepipedHand, OrthonormalAxesAnswerAsTheOrientedBox) {
    const OrientedBox<double> o{{0.5, -1, 2}, {Vec3<double>{0, 1, 0}, Vec3<double>{-1, 0, 0}, Vec3<double>{0, 0, 1}},
                                {1, 2, 0.5}};
    const P p{o.center, o.axes, o.extents};
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-4, 4), pos(0, 2);
    for (int i = 0; i < 300; ++i) {
        const C c{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, pos(rng), pos(rng)};
        EXPECT_EQ(intersects(p, c), intersects(o, c)) << describe(p, c);
    }
}

// Random exactly touching integer parallelepipeds: the plane through the vertex V that maximises m·X
// (|m| an integer: a Pythagorean quadruple) touches the box; a cylinder of radius k·|m| whose axis is
// ⊥ m through V + k·m touches the box at V (or along the edge or face where m·X is maximal too); a radius
// one ulp smaller misses.
TEST(ParallelepipedRandom, ExactlyTouchingIntegerParallelepipeds) {
    std::mt19937_64 rng(2024);
    std::uniform_int_distribution<int> small(-6, 6), ext(0, 3), sign(0, 1), pick(0, 5), kk(1, 3);
    const int quads[6][4] = {{1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9}, {4, 4, 7, 9}, {2, 6, 9, 11}, {6, 6, 7, 11}};
    Checker check;
    int hits = 0;
    for (int n = 0; n < 400; ++n) {
        P b;
        b.center = {double(small(rng)), double(small(rng)), double(small(rng))};
        for (int i = 0; i < 3; ++i) {
            b.axes[i] = {double(small(rng)), double(small(rng)), double(small(rng))};
            b.extents[i] = ext(rng);
        }
        if (n % 3 == 0) {  // orthogonal integer axes of equal length, from an integer quaternion
            const double w = small(rng), x = small(rng), y = small(rng), z = small(rng);
            b.axes[0] = {w * w + x * x - y * y - z * z, 2 * (x * y + w * z), 2 * (x * z - w * y)};
            b.axes[1] = {2 * (x * y - w * z), w * w - x * x + y * y - z * z, 2 * (y * z + w * x)};
            b.axes[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), w * w - x * x - y * y + z * z};
        }
        const int* q = quads[pick(rng)];
        Vec3<double> m{double(q[0]), double(q[1]), double(q[2])};
        std::shuffle(m.c.begin(), m.c.end(), rng);
        for (int i = 0; i < 3; ++i)
            if (sign(rng)) m[i] = -m[i];
        // V: the vertex maximising m·X.
        Vec3<double> v = b.center;
        for (int i = 0; i < 3; ++i) {
            const double s = dot(m, b.axes[i]) >= 0 ? b.extents[i] : -b.extents[i];
            v = v + s * b.axes[i];
        }
        Vec3<double> axis = cross(m, Vec3<double>{double(small(rng)), double(small(rng)), double(small(rng))});
        if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) axis = cross(m, Vec3<double>{1, 0, 0});
        if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) axis = cross(m, Vec3<double>{0, 1, 0});
        const double k = kk(rng), r = k * q[3];
        const C c{v + k * m, axis, r, double(ext(rng))};
        ASSERT_TRUE(check(b, c)) << "expected touching: " << describe(b, c);
        ++hits;
        EXPECT_FALSE(check(b, {c.center, c.axis, below(r), c.height}));
    }
    EXPECT_EQ(hits, 400);
    std::printf("exactly touching: %d cases, %d answered by the exact stage\n", check.cases, check.exact);
}

// Touching constructions (a vertex maximising m·X, the cylinder's side tangent there) moved off
// touching by a relative 2^(k−52) of the radius (k = 0..40, both ways) and by a relative 1e-9..1e-3 of the centre: the filter's certificates decide many of these
// close calls, and every answer must still be the oracle's.
TEST(ParallelepipedRandom, NearTouchingAgainstOracle) {
    std::mt19937_64 rng(77);
    std::uniform_int_distribution<int> small(-6, 6), ext(1, 3), kk(0, 40), sign(0, 1);
    std::uniform_real_distribution<double> u(-1, 1), mag(-9, -3);
    Checker check;
    for (int n = 0; n < 600; ++n) {
        P b;
        b.center = {double(small(rng)), double(small(rng)), double(small(rng))};
        for (int i = 0; i < 3; ++i) {
            b.axes[i] = {double(small(rng)), double(small(rng)), double(small(rng))};
            b.extents[i] = ext(rng);
        }
        if (n % 2 == 0) {  // orthogonal integer axes (the frame stage)
            const double w = small(rng), x = small(rng), y = small(rng), z = small(rng) + 0.5;
            b.axes[0] = {w * w + x * x - y * y - z * z, 2 * (x * y + w * z), 2 * (x * z - w * y)};
            b.axes[1] = {2 * (x * y - w * z), w * w - x * x + y * y - z * z, 2 * (y * z + w * x)};
            b.axes[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), w * w - x * x - y * y + z * z};
        }
        const Vec3<double> m{u(rng), u(rng), u(rng)};
        Vec3<double> v = b.center;
        for (int i = 0; i < 3; ++i) v = v + (dot(m, b.axes[i]) >= 0 ? b.extents[i] : -b.extents[i]) * b.axes[i];
        const double len = std::sqrt(dot(m, m));
        const double r = 1 + ext(rng);
        Vec3<double> axis = cross(m, Vec3<double>{u(rng), u(rng), u(rng)});
        C c{v + (r / len) * m, axis, r, double(ext(rng))};
        if (n % 3 == 0) {
            c.radius = r * (1 + (sign(rng) ? 1 : -1) * std::ldexp(1.0, kk(rng) - 52));
        } else {
            const double eps = std::pow(10.0, mag(rng));
            c.center = c.center + eps * Vec3<double>{u(rng), u(rng), u(rng)};
        }
        check(b, c);
    }
    std::printf("near touching: %d cases, %d answered by the exact stage\n", check.cases, check.exact);
}

P random_box(std::mt19937_64& rng, int flavour) {
    std::uniform_real_distribution<double> u(-2, 2), pos(0, 1.5);
    P b{{u(rng), u(rng), u(rng)}, {Vec3<double>{u(rng), u(rng), u(rng)}, Vec3<double>{u(rng), u(rng), u(rng)},
                                   Vec3<double>{u(rng), u(rng), u(rng)}},
        {pos(rng), pos(rng), pos(rng)}};
    switch (flavour) {
        case 1: b.axes[2] = {0, 0, 0}; break;                                   // zero axis: a parallelogram
        case 2: b.axes[1] = 3.0 * b.axes[0]; break;                            // parallel axes
        case 3: b.axes[2] = b.axes[0] + b.axes[1]; break;                      // coplanar: a hexagon (mostly)
        case 4: b.extents[1] = 0; break;                                        // a zero extent
        case 5: b.axes[1] = {0, 0, 0}, b.axes[2] = -0.5 * b.axes[0]; break;     // a segment
        case 6: b.axes = {Vec3<double>{0, 0, 0}, Vec3<double>{0, 0, 0}, Vec3<double>{0, 0, 0}}; break;  // a point
        default: break;
    }
    return b;
}

TEST(ParallelepipedRandom, GeneralAndFlatAgainstOracle) {
    for (int flavour = 0; flavour <= 6; ++flavour) {
        std::mt19937_64 rng(100 + flavour);
        std::uniform_real_distribution<double> u(-3, 3), pos(0, 1.5);
        Checker check;
        int hits = 0;
        for (int n = 0; n < 300; ++n) {
            const P b = random_box(rng, flavour);
            C c{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, pos(rng), pos(rng)};
            if (n % 10 == 0) c.radius = 0;
            if (n % 10 == 1) c.height = 0;
            hits += check(b, c);
        }
        EXPECT_GT(hits, 0) << "flavour " << flavour;
        EXPECT_LT(hits, check.cases) << "flavour " << flavour;
        std::printf("flavour %d: %d cases, %d hits, %d answered by the exact stage\n", flavour, check.cases, hits,
                    check.exact);
    }
}

// Extreme magnitudes: the same random queries with every length scaled by 2^k (k from −1060 to
// +1000: subnormal to near overflow) and the axes by 2^j independently (any scale: only their span
// with the extents counts), and tiny or huge components mixed in. Enclosures that overflow or
// underflow must leave the query to the exact stage, never answer wrongly.
TEST(ParallelepipedRandom, ExtremeMagnitudesAgainstOracle) {
    std::mt19937_64 rng(909);
    std::uniform_real_distribution<double> u(-3, 3), pos(0, 1.5);
    std::uniform_int_distribution<int> scale(-1060, 1000), axis_scale(-600, 600), flavour(0, 6), coin(0, 3);
    Checker check;
    for (int n = 0; n < 400; ++n) {
        P b = random_box(rng, flavour(rng));
        C c{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, pos(rng), pos(rng)};
        const int k = scale(rng), j = axis_scale(rng);
        auto sc = [](const Vec3<double>& v, int e) { return Vec3<double>{std::ldexp(v[0], e), std::ldexp(v[1], e), std::ldexp(v[2], e)}; };
        b.center = sc(b.center, k);
        for (auto& a : b.axes) a = sc(a, j);
        b.extents = sc(b.extents, k - j);
        c.center = sc(c.center, k);
        c.radius = std::ldexp(c.radius, k);
        c.height = std::ldexp(c.height, k);
        if (coin(rng) == 0) c.axis[n % 3] = std::ldexp(c.axis[n % 3], -1000);  // a tiny axis component
        if (coin(rng) == 0) b.axes[n % 3][(n + 1) % 3] = std::ldexp(1.0, j - 1070);  // a subnormal one
        if (!validate(b).ok() || !validate(c).ok()) continue;
        check(b, c);
    }
    EXPECT_GT(check.cases, 300);
    std::printf("extreme magnitudes: %d cases, %d answered by the exact stage\n", check.cases, check.exact);
}

// Cases a miss certificate once answered wrongly under FE_DOWNWARD and FE_TOWARDZERO (a direction
// with components of 1e±150: a product overflowed to DBL_MAX, not ∞, and its bound stayed finite).
// Each touches or overlaps; checked in all four rounding modes.
TEST(ParallelepipedRounding, OverflowingDirectionsInEveryMode) {
    const std::pair<P, C> cases[] = {
        {P{{0, -4.9406564584124654e-324, 4.9406564584124654e-324},
           {Vec3<double>{-0.68227875108545266, 0.72091449881347014, -0.12156476141463826},
            Vec3<double>{-0.47260296877030877, -0.56177374899954369, -0.67901155280634817},
            Vec3<double>{-0.55780116504608113, -0.40582328707889681, 0.7239926242288065}},
           {3.6089003384982234e-301, 9.0762124284405636e+299, 1.6112416652099546e-308}},
         C{{2.0233407193507405e+298, -7.188936880858356e+298, -8.5405110461029434e+298},
           {0, 0, -1.1214514137522989e-150}, 7.9686236068831041e+298, 1.4889937858051201e+150}},
        {P{{0.024839784160300252, -0.0047518628500305962, -0.00042219540060848171},
           {Vec3<double>{-0.20037956890320052, 0.25902284278879173, 0.94485723539579269},
            Vec3<double>{-0.94154905003272349, 0.21565870035516627, -0.25879859223650431},
            Vec3<double>{-0.27080143047746885, -0.94148738274855992, 0.2006691141571697}},
           {0.049189536902308414, 0.0090369985841786647, 0.022195153142456698}},
         C{{0.0036118793205844844, 0.0040194735049174828, -0.05164410799292396},
           {2.8118211215894977e-40, -8.435369454295869e-160, -2.8118211215894977e+160}, 0.01423872717594162,
           0.095396628490688362}},
    };
    for (const auto& [b, c] : cases) {
        ASSERT_TRUE(oracle_answer(b, c)) << describe(b, c);
        for (int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
            const testing::RoundingMode guard(mode);
            EXPECT_TRUE(filtered::query(b, c).intersect) << "mode " << mode << ": " << describe(b, c);
            EXPECT_TRUE(intersects(b, c)) << "mode " << mode << ": " << describe(b, c);
        }
    }
}

// The oracle's entry for flat solids against exact §3 (two independent exact methods).
TEST(ParallelepipedOracle, FlatSolidsAgreeWithExactHull) {
    for (int flavour = 1; flavour <= 6; ++flavour) {
        std::mt19937_64 rng(300 + flavour);
        std::uniform_real_distribution<double> u(-3, 3), pos(0, 1.5);
        for (int n = 0; n < 150; ++n) {
            const P b = random_box(rng, flavour);
            const C c{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, n % 7 == 0 ? 0.0 : pos(rng), pos(rng)};
            EXPECT_EQ(oracle_answer(b, c), exact::intersects(exact::Method::hull, to_exact(b), to_exact(c))) << describe(b, c);
        }
    }
}

// The integer route, exact §3 in Q(√d) and the default query each answer (b, q) as the oracle does, for
// every q of `queries` with valid sizes (the first one's are); counts them in `cases`. Returns whether
// some answer differs from the first one's: (b, queries[0]) touches exactly when the others are its
// one-ulp misses.
bool three_exact_methods_agree(const P& b, std::initializer_list<C> queries, int& cases) {
    const bool hit = oracle_answer(b, *queries.begin());
    bool touches = false;
    for (const C& q : queries) {
        if (!(q.radius >= 0) || !(q.height >= 0)) continue;
        const bool want = oracle_answer(b, q);
        touches |= want != hit;
        ++cases;
        EXPECT_EQ(exact::integer::intersects_parallelepiped(b, q), want) << describe(b, q);
        EXPECT_EQ(exact::intersects(exact::Method::hull, to_exact(b), to_exact(q)), want) << describe(b, q);
        EXPECT_EQ(filtered::query(b, q).intersect, want) << describe(b, q);
    }
    return touches;
}

// Dependent axes (a zonogon, a parallelogram, a segment, a point) with small integer coordinates, where
// many queries touch exactly (axes along a coordinate half the time): the exact stage's integer route,
// the oracle and exact §3 in Q(√d) (three independent exact methods) agree, on each case and with the
// radius or the height one ulp smaller.
TEST(ParallelepipedOracle, DependentAxesOnALatticeThreeExactMethodsAgree) {
    std::mt19937_64 rng(4242);
    std::uniform_int_distribution<int> small(-3, 3), ext(0, 2), flavour(0, 4), size(0, 6), coord(0, 5);
    int cases = 0, touching = 0;
    for (int n = 0; n < 3000; ++n) {
        auto v = [&] { return Vec3<double>{double(small(rng)), double(small(rng)), double(small(rng))}; };
        P b{v(), {v(), v(), v()}, {double(ext(rng)), double(ext(rng)), 1}};
        switch (flavour(rng)) {
            case 0: b.axes[2] = b.axes[0] + b.axes[1]; break;        // a zonogon (mostly a hexagon)
            case 1: b.axes[2] = b.axes[0] - 2.0 * b.axes[1]; break;  // another
            case 2: b.axes[2] = {0, 0, 0}; break;                      // a parallelogram
            case 3: b.axes[1] = 2.0 * b.axes[0], b.axes[2] = -1.0 * b.axes[0]; break;  // a segment
            default: b.axes[1] = b.axes[0], b.extents[2] = 0; break;   // a segment or parallelogram
        }
        Vec3<double> axis = v();
        if (const int k = coord(rng); k < 3) axis = {0, 0, 0}, axis[k] = 1;
        if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) axis = {0, 0, 1};
        C c{v(), axis, 0.5 * size(rng), 0.5 * size(rng)};
        if (n % 2 == 0) {  // a cap on the vertex farthest along a coordinate, the rim through it or not
            const int k = coord(rng) % 3;
            const double sk = small(rng) < 0 ? -1.0 : 1.0;
            Vec3<double> top = b.center;
            for (int i = 0; i < 3; ++i) top = top + (sk * b.axes[i][k] >= 0 ? b.extents[i] : -b.extents[i]) * b.axes[i];
            c.axis = {0, 0, 0}, c.axis[k] = sk;
            c.center = top, c.center[k] += sk * 0.5 * c.height;
            if (coord(rng) < 3) c.center[(k + 1) % 3] += 1.5, c.center[(k + 2) % 3] -= 2, c.radius = 2.5;
        }
        if (!validate(b).ok() || !validate(c).ok()) continue;
        touching += three_exact_methods_agree(
            b, {c, C{c.center, c.axis, below(c.radius), c.height}, C{c.center, c.axis, c.radius, below(c.height)}}, cases);
    }
    EXPECT_GT(cases, 6000);
    EXPECT_GT(touching, 1000);
    std::printf("dependent axes on a lattice: %d cases, %d queries touching exactly\n", cases, touching);
}

// Cylinders of radius 0 (segments), which the integer route answers by the axis tests alone where B is
// solid or crossed at one point: small integer parallelepipeds (solid, flat, a segment) and segments
// that end on a vertex, an edge point or a face point of B, or pass through one, with the height one ulp
// shorter; then the same at extreme scales. The integer route, the oracle and exact §3 agree.
TEST(ParallelepipedOracle, SegmentCylindersThreeExactMethodsAgree) {
    std::mt19937_64 rng(5150);
    std::uniform_int_distribution<int> small(-3, 3), ext(0, 2), flavour(0, 3), coord(0, 2), lambda(-2, 2),
        size(1, 8), scale(-1000, 960), coin(0, 1);
    int cases = 0, touching = 0;
    for (int n = 0; n < 2400; ++n) {
        auto v = [&] { return Vec3<double>{double(small(rng)), double(small(rng)), double(small(rng))}; };
        P b{v(), {v(), v(), v()}, {double(1 + ext(rng)), double(ext(rng)), 1}};
        switch (flavour(rng)) {
            case 0: b.axes[2] = b.axes[0] + b.axes[1]; break;  // flat
            case 1: b.axes[1] = 2.0 * b.axes[0], b.axes[2] = {0, 0, 0}; break;  // a segment
            default: break;  // mostly solid
        }
        // A point of B: each coordinate −1, −½, 0, ½ or 1 of its extent (a vertex, an edge, a face point).
        Vec3<double> on = b.center;
        for (int i = 0; i < 3; ++i) on = on + (0.5 * lambda(rng) * b.extents[i]) * b.axes[i];
        const int k = coord(rng);
        const double sk = coin(rng) ? 1.0 : -1.0;
        Vec3<double> axis{0, 0, 0};
        axis[k] = sk;
        const double height = size(rng);
        C c{on, axis, 0, height};
        if (n % 3 == 0) c.center[k] += sk * 0.5 * height;     // the segment ends on `on`
        else if (n % 3 == 1) c.axis = v(), c.center = v();     // any segment
        if (c.axis[0] == 0 && c.axis[1] == 0 && c.axis[2] == 0) c.axis = {1, 2, 2};
        if (n >= 1800) {  // the same shapes at an extreme scale (exact: small integers)
            const int e = scale(rng);
            auto sc = [e](const Vec3<double>& x) { return Vec3<double>{std::ldexp(x[0], e), std::ldexp(x[1], e), std::ldexp(x[2], e)}; };
            b.center = sc(b.center), c.center = sc(c.center);
            for (auto& a : b.axes) a = sc(a);
            c.height = std::ldexp(c.height, e);
        }
        if (!validate(b).ok() || !validate(c).ok()) continue;
        touching += three_exact_methods_agree(b, {c, C{c.center, c.axis, 0, below(c.height)}}, cases);
    }
    EXPECT_GT(cases, 4000);
    EXPECT_GT(touching, 300);
    std::printf("segment cylinders: %d cases, %d queries touching exactly\n", cases, touching);
}

TEST(ParallelepipedOracle, FlatHandCases) {
    // The unit square in z = 0 spanned by two parallel pairs: W0 = (1,0,0), W1 = (2,0,0), W2 = (0,1,0),
    // extents (0.25, 0.375, 1): x ∈ [−1, 1], y ∈ [−1, 1].
    const P square{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{2, 0, 0}, Vec3<double>{0, 1, 0}}, {0.25, 0.375, 1}};
    Checker check;
    EXPECT_TRUE(check(square, {{0, 0, 0}, {1, 1, 1}, 0, 0}));                 // a point at the centre
    EXPECT_TRUE(check(square, {{1, 1, 0}, {0, 0, 1}, 0, 0}));                 // the corner point
    EXPECT_FALSE(check(square, {{above(1), 1, 0}, {0, 0, 1}, 0, 0}));
    EXPECT_TRUE(check(square, {{3, 0, 1}, {0, 0, 1}, 2, 2}));                 // side touches the edge x = 1
    EXPECT_FALSE(check(square, {{3, 0, 1}, {0, 0, 1}, below(2), 2}));
    EXPECT_FALSE(check(square, {{3, 0, 1}, {0, 0, 1}, 2, below(2)}));         // bottom cap above z = 0
    EXPECT_TRUE(check(square, {{0, 0, 3}, {0, 0, 1}, 0, 6}));                 // a segment ending on it
    EXPECT_FALSE(check(square, {{0, 0, 3}, {0, 0, 1}, 0, below(6)}));
    // A segment (W0 ∥ W1, W2 = 0) from (−1,−1,−1) to (1,1,1), and a point.
    const P seg{{0, 0, 0}, {Vec3<double>{1, 1, 1}, Vec3<double>{0, 0, 0}, Vec3<double>{0, 0, 0}}, {1, 5, 5}};
    EXPECT_TRUE(check(seg, {{3, 4, 0}, {0, 0, 1}, 5, 0}));  // the disk z = 0 through the origin
    EXPECT_FALSE(check(seg, {{3, 4, 0}, {0, 0, 1}, below(5), 0}));
    const P point{{1, 2, 3}, {Vec3<double>{0, 0, 0}, Vec3<double>{0, 0, 0}, Vec3<double>{0, 0, 0}}, {1, 1, 1}};
    EXPECT_TRUE(check(point, {{1, 2, 4}, {0, 0, 1}, 0, 2}));
    EXPECT_FALSE(check(point, {{1, 2, 4}, {0, 0, 1}, 7, below(2)}));
}

// The batch API: a span of parallelepipeds, double and float, mask and bools, one and several
// threads: the answers of the scalar default query.
TEST(ParallelepipedBatch, SameAnswersAsTheScalarQuery) {
    std::mt19937_64 rng(55);
    std::uniform_real_distribution<double> u(-3, 3), pos(0, 1.5);
    const C cyl{{0.5, -0.25, 0.125}, {1, 2, 2}, 1.25, 2.5};
    std::vector<P> boxes;
    std::vector<Parallelepiped<float>> fboxes;
    for (int n = 0; n < 70000; ++n) {  // above split::kMinBoxesPerThread · 2: two threads do run
        P b = random_box(rng, n % 7);
        b.center = {u(rng), u(rng), u(rng)};
        auto f = [](const Vec3<double>& v) { return Vec3<float>{float(v[0]), float(v[1]), float(v[2])}; };
        fboxes.push_back({f(b.center), {f(b.axes[0]), f(b.axes[1]), f(b.axes[2])}, f(b.extents)});
        boxes.push_back(b);
    }
    for (unsigned threads : {1u, 2u}) {
        std::vector<std::uint64_t> mask(batch::mask_words(boxes.size()), ~std::uint64_t{0});
        const batch::Stats st = batch::intersects(cyl, boxes, std::span<std::uint64_t>(mask), {threads});
        EXPECT_EQ(st.boxes, boxes.size());
        std::unique_ptr<bool[]> bools(new bool[fboxes.size()]);
        batch::intersects(cyl, fboxes, std::span<bool>(bools.get(), fboxes.size()), {threads});
        std::size_t exact = 0;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const filtered::Result r = filtered::query(boxes[i], cyl);
            exact += r.exact_used;
            ASSERT_EQ(bool((mask[i / 64] >> (i % 64)) & 1), r.intersect) << i << ": " << describe(boxes[i], cyl);
            ASSERT_EQ(bools[i], intersects(batch::parallelepipeds::widened(fboxes[i]), cyl)) << i;
        }
        EXPECT_EQ(st.exact_lanes, exact);
        EXPECT_EQ(mask.back() >> (boxes.size() % 64), 0u);  // unused high bits cleared
    }
    std::vector<std::uint64_t> short_mask(1);
    EXPECT_THROW(batch::intersects(cyl, boxes, std::span<std::uint64_t>(short_mask)), std::invalid_argument);
}

TEST(ParallelepipedOptions, HullAndOracleOnAnyAxesSection4NeedsOrthonormal) {
    const C c{{6, 8, 0}, {0, 0, 1}, 5, 2};
    for (Arithmetic a : {Arithmetic::filtered, Arithmetic::exact})
        for (Algorithm g : {Algorithm::hull, Algorithm::oracle}) EXPECT_TRUE(intersects(integer_box, c, {g, a}));
    EXPECT_TRUE(intersects(integer_box, c, {Algorithm::inequalities, Arithmetic::filtered}));
    EXPECT_TRUE(intersects(integer_box, c, {Algorithm::lcp, Arithmetic::filtered}));
    const C far{{16, 8, 0}, {0, 0, 1}, 5, 2};
    EXPECT_FALSE(intersects(integer_box, far, {Algorithm::hull, Arithmetic::float64}));
    EXPECT_FALSE(intersects(integer_box, far, {Algorithm::hull, Arithmetic::float32}));
    EXPECT_FALSE(intersects(integer_box, far, {Algorithm::oracle, Arithmetic::float64}));
    for (Arithmetic a : {Arithmetic::float32, Arithmetic::float64, Arithmetic::exact})
        for (Algorithm g : {Algorithm::inequalities, Algorithm::lcp})
            EXPECT_THROW(intersects(integer_box, c, {g, a}), std::domain_error);
    // Orthonormal axes are the oriented box, with its rules.
    const P unit{{0, 0, 0}, {Vec3<double>{0, 1, 0}, Vec3<double>{1, 0, 0}, Vec3<double>{0, 0, 1}}, {5, 5, 5}};
    EXPECT_TRUE(intersects(unit, Cylinder<double>{{10, 0, 0}, {0, 0, 1}, 5, 2}, {Algorithm::inequalities, Arithmetic::exact}));
    EXPECT_FALSE(intersects(unit, Cylinder<double>{{10, 0, 0}, {0, 0, 1}, below(5), 2}, {Algorithm::lcp, Arithmetic::exact}));
}

TEST(ParallelepipedValidate, FieldsNamed) {
    EXPECT_TRUE(validate(integer_box).ok());
    P b = integer_box;
    b.axes = {Vec3<double>{0, 0, 0}, Vec3<double>{1, 1, 1}, Vec3<double>{2, 2, 2}};
    EXPECT_TRUE(validate(b).ok());  // any axes
    b.extents[2] = -1;
    EXPECT_EQ(validate(b).message(), "box.extents[2]: is negative");
    b = integer_box;
    b.axes[1][2] = NAN;
    EXPECT_EQ(validate(b).message(), "box.axes[1][2]: is NaN");
    b = integer_box;
    b.center[0] = INFINITY;
    EXPECT_EQ(validate(b, "boxes[3]").message(), "boxes[3].center[0]: is +Inf");
}

}  // namespace
}  // namespace boxcyl
