// The linear-inequalities method (algo/linear_inequalities.hpp) against the exact oracle.
//
// Every case runs four ways: the oracle (asserted, so the hand-made expectations are checked too), the
// linear-inequalities method in QFRational (exact: asserted always), the linear-inequalities method in
// Rational when the axis has a rational length (asserted), and the linear-inequalities method in double/float
// (rounded). Double is asserted strictly where the rounded unit direction is the exact one (axis-aligned
// axes); elsewhere a disagreement must be near touching within the documented tolerance
// (support/tolerance.hpp) and is reported, not failed.
//
// Hand cases use the box |x| ≤ 1, |y| ≤ 2, |z| ≤ 3 and are run in all 8 reflections (negative axis
// components) and as a shifted aligned box. Every touching case comes with its one-ulp neighbour on
// the other side of the answer.
#include <gtest/gtest.h>

#include <chrono>    // runtime report
#include <cmath>     // std::nextafter, std::ldexp
#include <cstdint>   // std::uint64_t
#include <cstdio>    // std::printf
#include <limits>    // denorm_min, infinity
#include <optional>  // rational_li
#include <random>    // std::mt19937_64
#include <string>    // case names
#include <vector>    // case lists

#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/exact/reduce.hpp"
#include "boxcyl/oracle/oracle.hpp"
#include "support/cases.hpp"
#include "support/tolerance.hpp"

namespace boxcyl {
namespace {

using testing::BoxKind;
using testing::Case;
using testing::describe;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();

// ---------------------------------------------------------------- the four ways to answer a case

// The linear-inequalities method in QFRational: the exact unit axis u = A/|A| in Q(√(A·A)), the aligned-box
// reduction in exact arithmetic.
bool exact_li(const Case& c) {
    const Cylinder<Rational> cyl = to_exact(c.cylinder);
    const QuadraticField<Rational> field(dot(cyl.axis, cyl.axis));
    const UnitCylinder<QFRational> u = to_unit(cyl, field);
    if (c.kind == BoxKind::aligned) {
        const AlignedBox<Rational> b = to_exact(c.aligned);
        const CanonicalQuery<QFRational> q = to_canonical(AlignedBox<QFRational>{lift(b.min), lift(b.max)}, u);
        return algo::linear_inequalities(q.box, q.cylinder);
    }
    const CanonicalQuery<QFRational> q = to_canonical(CanonicalBox<QFRational>{lift(to_exact(c.canonical.extents))}, u);
    return algo::linear_inequalities(q.box, q.cylinder);
}

std::optional<Rational> exact_sqrt(const Rational& q) {
    const mpz_class& n = q.get_num();
    const mpz_class& d = q.get_den();
    if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
    return Rational(mpz_class(sqrt(n)), mpz_class(sqrt(d)));
}

// The linear-inequalities method in Rational, possible when |A| is rational (axis-aligned or Pythagorean axes
// such as (3,4,12)).
std::optional<bool> rational_li(const Case& c) {
    const Cylinder<Rational> cyl = to_exact(c.cylinder);
    const std::optional<Rational> len = exact_sqrt(dot(cyl.axis, cyl.axis));
    if (!len) return std::nullopt;
    const UnitCylinder<Rational> u{cyl.center,
                                   {cyl.axis[0] / *len, cyl.axis[1] / *len, cyl.axis[2] / *len},
                                   cyl.radius,
                                   cyl.height / 2};
    if (c.kind == BoxKind::aligned) {
        const CanonicalQuery<Rational> q = to_canonical(to_exact(c.aligned), u);
        return algo::linear_inequalities(q.box, q.cylinder);
    }
    return algo::linear_inequalities(to_exact(c.canonical), u);
}

template <class F>
Vec3<F> cast3(const Vec3<double>& v) {
    return {static_cast<F>(v[0]), static_cast<F>(v[1]), static_cast<F>(v[2])};
}

// The linear-inequalities method in float or double, as the front door runs it (to_unit rounds the axis).
template <class F>
bool rounded_li(const Case& c) {
    const Cylinder<F> cyl{cast3<F>(c.cylinder.center), cast3<F>(c.cylinder.axis), static_cast<F>(c.cylinder.radius),
                          static_cast<F>(c.cylinder.height)};
    const UnitCylinder<F> u = to_unit(cyl);
    if (c.kind == BoxKind::aligned) {
        const CanonicalQuery<F> q = to_canonical(AlignedBox<F>{cast3<F>(c.aligned.min), cast3<F>(c.aligned.max)}, u);
        return algo::linear_inequalities(q.box, q.cylinder);
    }
    return algo::linear_inequalities(CanonicalBox<F>{cast3<F>(c.canonical.extents)}, u);
}

// True when to_unit() in double yields exactly A/|A| (then double sees the same cylinder as the oracle).
bool double_direction_exact(const Case& c) {
    const UnitCylinder<double> u = to_unit(Cylinder<double>{{}, c.cylinder.axis, 0, 0});
    const Vec3<Rational> d = to_exact(u.direction);
    const Vec3<Rational> a = to_exact(c.cylinder.axis);
    if (dot(d, d) != 1) return false;
    const Vec3<Rational> x = cross(d, a);
    return sgn(x[0]) == 0 && sgn(x[1]) == 0 && sgn(x[2]) == 0 && sgn(dot(d, a)) > 0;
}

// ---------------------------------------------------------------- hand cases

struct RoundedTally {
    long checked = 0, tolerated = 0;
};
RoundedTally g_hand_double, g_hand_float;

// Asserts the oracle and the exact linear-inequalities method. Double is asserted strictly when
// `strict_double` and its rounded direction is exact; otherwise a double disagreement must be near touching
// (and is reported). `strict_double` is off for one-ulp neighbours whose flip the double pipeline cannot
// resolve even for axis-aligned axes: a height nudge (the slab cull rounds ρ + h/2) and shifted aligned boxes
// (the aligned-box reduction rounds C − K).
void expect_answer(const std::string& name, const Case& c, bool want, bool strict_double = true) {
    SCOPED_TRACE(name + "\n  " + describe(c));
    EXPECT_EQ(testing::oracle_answer(c), want) << "oracle";
    EXPECT_EQ(exact_li(c), want) << "inequalities in QFRational";
    if (const std::optional<bool> r = rational_li(c)) {
        EXPECT_EQ(*r, want) << "inequalities in Rational";
    }

    ++g_hand_double.checked;
    const bool d = rounded_li<double>(c);
    if (strict_double && double_direction_exact(c)) {
        EXPECT_EQ(d, want) << "inequalities in double (direction exact in double)";
    } else if (d != want) {
        EXPECT_TRUE(testing::near_touching(c, testing::double_tolerance)) << "inequalities in double, NOT near touching";
        ++g_hand_double.tolerated;
        std::printf("  [double, tolerated] %s: got %d want %d\n", name.c_str(), d, want);
    }
    ++g_hand_float.checked;
    if (rounded_li<float>(c) != want) {
        EXPECT_TRUE(testing::near_touching(c, testing::float_tolerance)) << "inequalities in float, NOT near touching";
        ++g_hand_float.tolerated;
    }
}

Case canonical_case(Vec3<double> ext, Vec3<double> center, Vec3<double> axis, double r, double h) {
    Case c;
    c.kind = BoxKind::canonical;
    c.canonical.extents = ext;
    c.cylinder = {center, axis, r, h};
    return c;
}

const Vec3<double> E123{1, 2, 3};
Case box123(Vec3<double> center, Vec3<double> axis, double r, double h) {
    return canonical_case(E123, center, axis, r, h);
}

// What a one-ulp nudge moves.
enum class Knob { radius, height, cx, cy, cz };

Case nudged(Case c, Knob k, int dir) {
    const double to = dir > 0 ? kInf : -kInf;
    switch (k) {
        case Knob::radius: c.cylinder.radius = std::nextafter(c.cylinder.radius, to); break;
        case Knob::height: c.cylinder.height = std::nextafter(c.cylinder.height, to); break;
        case Knob::cx: c.cylinder.center[0] = std::nextafter(c.cylinder.center[0], to); break;
        case Knob::cy: c.cylinder.center[1] = std::nextafter(c.cylinder.center[1], to); break;
        case Knob::cz: c.cylinder.center[2] = std::nextafter(c.cylinder.center[2], to); break;
    }
    return c;
}

// The canonical case reflected in the coordinates of `mask` (the box is symmetric).
Case reflected(Case c, int mask) {
    for (int i = 0; i < 3; ++i)
        if (mask >> i & 1) {
            c.cylinder.center[i] = -c.cylinder.center[i];
            c.cylinder.axis[i] = -c.cylinder.axis[i];
        }
    return c;
}

// The canonical case as an aligned box centred at K, if every sum is exact in double.
std::optional<Case> shifted(const Case& c) {
    const Vec3<double> K{0.5, -0.25, 2};
    Case s = c;
    s.kind = BoxKind::aligned;
    for (int i = 0; i < 3; ++i) {
        const double e = c.canonical.extents[i], x = c.cylinder.center[i];
        s.aligned.min[i] = K[i] - e;
        s.aligned.max[i] = K[i] + e;
        s.cylinder.center[i] = x + K[i];
        if (to_rational(s.aligned.min[i]) != to_rational(K[i]) - to_rational(e) ||
            to_rational(s.aligned.max[i]) != to_rational(K[i]) + to_rational(e) ||
            to_rational(s.cylinder.center[i]) != to_rational(x) + to_rational(K[i]))
            return std::nullopt;
    }
    return s;
}

// Runs `check(name, case, dir_sign, shifted)` on all reflections and their shifted aligned forms.
// dir_sign says how a nudge of knob `k` must be flipped so that it still points the same way.
template <class Check>
void for_variants(const std::string& name, const Case& c, Knob k, Check&& check) {
    for (int mask = 0; mask < 8; ++mask) {
        const Case r = reflected(c, mask);
        int flip = 1;
        if ((k == Knob::cx && (mask & 1)) || (k == Knob::cy && (mask & 2)) || (k == Knob::cz && (mask & 4))) flip = -1;
        const std::string tag = name + " [reflect " + std::to_string(mask) + "]";
        check(tag, r, flip, false);
        if (const std::optional<Case> s = shifted(r)) check(tag + " [shifted aligned]", *s, flip, true);
    }
}

// A touching case (answer true) and its one-ulp neighbour (knob nudged in `dir`, answer false).
void expect_touching(const std::string& name, const Case& c, Knob k, int dir) {
    for_variants(name, c, k, [&](const std::string& tag, const Case& v, int flip, bool shift) {
        expect_answer(tag + " touching", v, true);
        expect_answer(tag + " one ulp off", nudged(v, k, dir * flip), false, !shift && k != Knob::height);
    });
}

// A case whose exact answer flips between `c` (answer `at`) and its one-ulp neighbour.
void expect_flip(const std::string& name, const Case& c, bool at, Knob k, int dir) {
    for_variants(name, c, k, [&](const std::string& tag, const Case& v, int flip, bool shift) {
        expect_answer(tag, v, at);
        expect_answer(tag + " one ulp off", nudged(v, k, dir * flip), !at, !shift && k != Knob::height);
    });
}

void expect_plain(const std::string& name, const Case& c, bool want) {
    for_variants(name, c, Knob::radius, [&](const std::string& tag, const Case& v, int, bool) { expect_answer(tag, v, want); });
}

// ---- (+,0,0), (0,+,0), (0,0,+): two zero components ----

TEST(LinearInequalitiesHand, TwoZeroComponentsX) {
    expect_touching("x: side vs face", box123({0, 5, 0}, {1, 0, 0}, 3, 4), Knob::radius, -1);
    expect_touching("x: side vs face (centre)", box123({0, 5, 0}, {1, 0, 0}, 3, 4), Knob::cy, +1);
    expect_touching("x: side vs edge", box123({0, 5, 7}, {2, 0, 0}, 5, 4), Knob::radius, -1);
    expect_touching("x: end disk vs face", box123({4, 0, 0}, {1, 0, 0}, 1, 6), Knob::height, -1);
    expect_touching("x: end disk vs face (centre)", box123({4, 0, 0}, {0.25, 0, 0}, 1, 6), Knob::cx, +1);
    expect_touching("x: rim vs edge (r)", box123({4, 5, 0}, {1, 0, 0}, 3, 6), Knob::radius, -1);
    expect_touching("x: rim vs edge (h)", box123({4, 5, 0}, {1, 0, 0}, 3, 6), Knob::height, -1);
    expect_touching("x: rim vs vertex (r)", box123({4, 5, 7}, {1, 0, 0}, 5, 6), Knob::radius, -1);
    expect_touching("x: rim vs vertex (h)", box123({4, 5, 7}, {1, 0, 0}, 5, 6), Knob::height, -1);
    expect_touching("x: axis segment ends on face (r = 0)", box123({3, 0.5, 0.5}, {1, 0, 0}, 0, 4), Knob::height, -1);
    expect_plain("x: axis through face", box123({3, 0.5, 0.5}, {1, 0, 0}, 0, 6), true);
    expect_plain("x: box inside cylinder", box123({0, 0, 0}, {1, 0, 0}, 10, 10), true);
    expect_plain("x: cylinder inside box", box123({0.25, 0.5, 0.5}, {1, 0, 0}, 0.5, 1), true);
    expect_plain("x: clear miss beside", box123({0, 5, 7}, {1, 0, 0}, 4.5, 100), false);
}

TEST(LinearInequalitiesHand, TwoZeroComponentsY) {
    expect_touching("y: side vs face", box123({3, 0, 0}, {0, 3, 0}, 2, 2), Knob::radius, -1);
    expect_touching("y: side vs edge", box123({4, 0, 7}, {0, 1, 0}, 5, 2), Knob::radius, -1);
    expect_touching("y: end disk vs face", box123({0, 4, 0}, {0, 1, 0}, 1, 4), Knob::height, -1);
    expect_touching("y: rim vs vertex", box123({4, 3, 7}, {0, 1, 0}, 5, 2), Knob::radius, -1);
    expect_plain("y: cylinder inside box", box123({0.25, 0.5, 0.5}, {0, 1, 0}, 0.5, 1), true);
}

TEST(LinearInequalitiesHand, TwoZeroComponentsZ) {
    expect_touching("z: side vs face", box123({0, 3, 0}, {0, 0, 1}, 1, 2), Knob::radius, -1);
    expect_touching("z: side vs edge", box123({4, 6, 0}, {0, 0, 1}, 5, 2), Knob::radius, -1);
    expect_touching("z: end disk vs face", box123({0, 0, 5}, {0, 0, 0.5}, 1, 4), Knob::height, -1);
    expect_touching("z: rim vs edge", box123({0, 3.5, 4}, {0, 0, 1}, 1.5, 2), Knob::radius, -1);
    expect_touching("z: disk (h = 0) lying on face", box123({0.5, 0.5, 3}, {0, 0, 1}, 0.25, 0), Knob::cz, +1);
    expect_plain("z: box inside cylinder", box123({0, 0, 0}, {0, 0, 1}, 10, 10), true);
}

// ---- (+,+,0), (+,0,+), (0,+,+): one zero component. Axes (3,4,0)-type: rational unit directions. ----

TEST(LinearInequalitiesHand, OneZeroComponentXY) {
    // D = (0.6, 0.8, 0), n = (0.8, −0.6, 0): the box reaches n·X ≤ 2 (edge x = 1, y = −2); n·C = 7.
    expect_touching("xy: side vs edge", box123({5, -5, 0}, {3, 4, 0}, 5, 200), Knob::radius, -1);
    expect_touching("xy: side vs face", box123({0, 0, 5}, {3, 4, 0}, 2, 2), Knob::radius, -1);
    // Bottom disk centre C − 5D = (1, 2, 0) on the edge x = 1, y = 2, where t is the box maximum.
    expect_touching("xy: end disk vs edge", box123({4, 6, 0}, {3, 4, 0}, 0.5, 10), Knob::height, -1);
    // Bottom disk centre M = C − 5D = (5, −3, 0); its lowest-x rim point M + 5(−0.8, 0.6, 0) = (1, 0, 0).
    expect_touching("xy: rim vs face", box123({8, 1, 0}, {3, 4, 0}, 5, 10), Knob::radius, -1);
    expect_touching("xy: rim vs face (centre)", box123({8, 1, 0}, {3, 4, 0}, 5, 10), Knob::cx, +1);
    expect_touching("xy: rim vs edge", box123({8, 3, 0}, {3, 4, 0}, 5, 10), Knob::radius, -1);
    expect_touching("xy: rim vs vertex", box123({8, 3, 3}, {3, 4, 0}, 5, 10), Knob::radius, -1);
    expect_plain("xy: axis through box", box123({0, 0, 0}, {3, 4, 0}, 0, 1), true);
    expect_plain("xy: box inside cylinder", box123({0, 0, 0}, {3, 4, 0}, 10, 20), true);
    expect_plain("xy: clear miss", box123({5, -5, 0}, {3, 4, 0}, 4.75, 200), false);
}

TEST(LinearInequalitiesHand, OneZeroComponentXZ) {
    // D = (0.6, 0, 0.8), n = (0.8, 0, −0.6): box max n·X = 2.6 on the edge x = 1, z = −3; n·C = 7.6.
    expect_touching("xz: side vs edge", box123({5, 0, -6}, {3, 0, 4}, 5, 200), Knob::radius, -1);
    expect_touching("xz: side vs face", box123({0, 4, 0}, {3, 0, 4}, 2, 2), Knob::radius, -1);
    expect_touching("xz: end disk vs edge", box123({4, 0, 7}, {3, 0, 4}, 0.5, 10), Knob::height, -1);
    expect_plain("xz: cylinder inside box", box123({0.25, 0.5, 0.5}, {3, 0, 4}, 0.25, 0.5), true);
}

TEST(LinearInequalitiesHand, OneZeroComponentYZ) {
    // D = (0, 0.6, 0.8), n = (0, 0.8, −0.6): box max n·X = 3.4 on the edge y = 2, z = −3; n·C = 8.4.
    expect_touching("yz: side vs edge", box123({0, 6, -6}, {0, 3, 4}, 5, 200), Knob::radius, -1);
    expect_touching("yz: side vs face", box123({3, 0, 0}, {0, 3, 4}, 2, 2), Knob::radius, -1);
    // Bottom disk M = (0.5, 6, −3); lowest-y rim point M + 5(0, −0.8, 0.6) = (0.5, 2, 0).
    expect_touching("yz: rim vs face", box123({0.5, 9, 1}, {0, 3, 4}, 5, 10), Knob::radius, -1);
    expect_touching("yz: end disk vs edge", box123({0, 5, 7}, {0, 3, 4}, 0.5, 10), Knob::height, -1);
    expect_plain("yz: box inside cylinder", box123({0, 0, 0}, {0, 3, 4}, 10, 20), true);
}

// ---- (+,+,+): no zero component. Axes (3,4,12)/13 (|D × U2| = 5/13 rational) and (1,2,2)/3. ----

TEST(LinearInequalitiesHand, NoZeroComponents) {
    // n = (4, −3, 0)/5 ⊥ D: the box reaches n·X ≤ 2 only on the edge x = 1, y = −2; n·C = 7; the
    // common perpendicular meets the edge at z = 0.
    expect_touching("xyz: side vs edge", box123({5, -5, 0}, {3, 4, 12}, 5, 200), Knob::radius, -1);
    // w = (12, 3, −4)/13 ⊥ D is maximised over the box only at V3 = (1, 2, −3); C = V3 + (13/4)w.
    expect_touching("xyz: side vs vertex", box123({4, 2.75, -4}, {3, 4, 12}, 3.25, 200), Knob::radius, -1);
    // Lowest rim point: bottom centre M = C − (13/2)D, direction (36, 48, −25)/65, r = 65/64: the
    // cylinder's lowest point M + r(36, 48, −25)/65 is (0.25, 0.5, 3) / (1, 0.5, 3) / (1, 2, 3).
    expect_touching("xyz: rim vs face", box123({1.1875, 1.75, 9.390625}, {3, 4, 12}, 1.015625, 13), Knob::radius, -1);
    expect_touching("xyz: rim vs face (centre)", box123({1.1875, 1.75, 9.390625}, {3, 4, 12}, 1.015625, 13), Knob::cz,
                    +1);
    expect_touching("xyz: rim vs edge", box123({1.9375, 1.75, 9.390625}, {3, 4, 12}, 1.015625, 13), Knob::radius, -1);
    expect_touching("xyz: rim vs vertex", box123({1.9375, 3.25, 9.390625}, {3, 4, 12}, 1.015625, 13), Knob::radius,
                    -1);
    // D = (1, 2, 2)/3, V7 = (1, 2, 3) has the largest t; C = V7 + 3D puts the bottom disk on V7.
    expect_touching("xyz: end disk vs vertex", box123({2, 4, 5}, {1, 2, 2}, 0.5, 6), Knob::height, -1);
    // Bottom disk centre M = V7 + 0.75·(2, 1, −2)/3; r = 1 covers V7, r = 0.75 passes through it.
    expect_touching("xyz: end disk (off centre) vs vertex", box123({2.5, 4.25, 4.5}, {1, 2, 2}, 1, 6), Knob::height, -1);
    expect_touching("xyz: rim through vertex (r)", box123({2.5, 4.25, 4.5}, {1, 2, 2}, 0.75, 6), Knob::radius, -1);
    expect_touching("xyz: rim through vertex (h)", box123({2.5, 4.25, 4.5}, {1, 2, 2}, 0.75, 6), Knob::height, -1);
    expect_touching("xyz: axis segment ends at vertex (r = 0)", box123({2, 4, 5}, {1, 2, 2}, 0, 6), Knob::height, -1);
    expect_plain("xyz: axis through face", box123({0.5, 0.5, 4}, {1, 2, 2}, 0, 6), true);
    expect_plain("xyz: box inside cylinder", box123({0, 0, 0}, {2, 3, 6}, 10, 20), true);
    expect_plain("xyz: cylinder inside box", box123({0.125, 0.25, 0.5}, {2, 3, 6}, 0.25, 0.5), true);
    expect_plain("xyz: clear miss", box123({5, -5, 0}, {3, 4, 12}, 4.9375, 200), false);
    expect_plain("xyz: far miss", box123({10, 10, 10}, {1, 2, 2}, 1, 2), false);
    expect_plain("xyz: slab miss, huge radius", box123({0, 0, 10}, {1, 2, 2}, 100, 2), false);
}

// ---- Degenerate inputs ----

TEST(LinearInequalitiesHand, ZeroExtents) {
    expect_touching("point box, axis-aligned", canonical_case({0, 0, 0}, {0, 3, 4}, {1, 0, 0}, 5, 2), Knob::radius, -1);
    expect_touching("point box, tilted (C·D = 0, |C| = 5)", canonical_case({0, 0, 0}, {4, -3, 0}, {3, 4, 12}, 5, 2),
                    Knob::radius, -1);
    expect_touching("flat box e2 = 0: side vs edge", canonical_case({1, 2, 0}, {5, -5, 0}, {3, 4, 12}, 5, 200),
                    Knob::radius, -1);
    expect_touching("flat box e2 = 0: disk (h = 0) in its plane", canonical_case({1, 2, 0}, {0, 0, 0}, {0, 0, 1}, 0.5, 0),
                    Knob::cz, +1);
    expect_touching("segment box: side", canonical_case({1, 0, 0}, {0, 3, 0}, {0, 0, 1}, 3, 2), Knob::radius, -1);
    // Segment box along z; n = (4, −3, 0)/5 is the common perpendicular, meeting the segment at 0.
    expect_touching("segment box along z, tilted axis", canonical_case({0, 0, 3}, {4, -3, 0}, {3, 4, 12}, 5, 200),
                    Knob::radius, -1);
    expect_plain("flat box inside cylinder", canonical_case({1, 2, 0}, {0, 0, 0}, {1, 2, 2}, 5, 5), true);
}

TEST(LinearInequalitiesHand, ZeroRadiusAndHeight) {
    // The line through the edge point (1, −2, 0) with D = (3,4,12)/13 leaves the box at once on both sides.
    expect_touching("segment (r = 0) through edge point", box123({1, -2, 0}, {3, 4, 12}, 0, 2), Knob::cx, +1);
    expect_touching("disk (h = 0) through vertex", box123({1, 2, 3}, {1, 2, 2}, 1, 0), Knob::cz, +1);
    expect_touching("point cylinder (r = h = 0) on face", box123({1, 0.5, 0.5}, {1, 2, 2}, 0, 0), Knob::cx, +1);
    expect_touching("segment (r = 0) along face", box123({1, 0, 0}, {0, 3, 4}, 0, 1), Knob::cx, +1);
    expect_plain("point cylinder inside", box123({0.5, 0.5, 0.5}, {1, 2, 2}, 0, 0), true);
    expect_plain("point cylinder outside", box123({1.5, 0.5, 0.5}, {1, 2, 2}, 0, 0), false);
}

// Axis components 1e-300, subnormal and 2^-40. In exact arithmetic the tiny tilt decides touching
// cases; double may differ only within rounding (checked with the tolerance) and must never produce
// NaN/inf garbage (the published note's Listings 4/6 divide by the tiny component and use the overflowing
// quotient).
TEST(LinearInequalitiesHand, TinyAxisComponents) {
    // Axis tilted towards the face y = 2 by 1e-300: nearest at x = −1, distance 3 − 1e-300 < 3.
    expect_touching("tiny y: side vs face", box123({0, 5, 0}, {1, 1e-300, 0}, 3, 4), Knob::radius, -1);
    expect_touching("subnormal y: side vs face", box123({0, 5, 0}, {1, 3 * kDenormMin, 0}, 3, 4), Knob::radius, -1);
    expect_touching("subnormal x, z: side vs face x = 1", box123({3, 0, 0}, {kDenormMin, 1, kDenormMin}, 2, 2),
                    Knob::radius, -1);
    // The lower slab plane (≈ x = 0.5) cuts the box; the (U1, −D) cut and the edges along y and z
    // need quotients by 1e-300 that overflow unless clamped.
    expect_touching("tiny y, z: slab cuts box, side vs face", box123({3, 3.5, 0}, {1, 1e-300, 1e-300}, 1.5, 5),
                    Knob::radius, -1);
    // Tilted away: only x = −1 is in the slab, where the axis is 2 + 2e-300 from the face z = 3.
    expect_flip("tiny z tilted away: r = 2 misses", box123({-3, 0, 5}, {1, 0, 1e-300}, 2, 4), false, Knob::radius, +1);
    expect_flip("subnormal z tilted away", box123({-3, 0, 5}, {1, 0, kDenormMin}, 2, 4), false, Knob::radius, +1);
    // 2^-40 tilt: distance 3 − 2^-40 + O(2^-80).
    expect_plain("2^-40 y: inside margin", box123({0, 5, 0}, {1, 0x1p-40, 0}, 0x1.7ffffffffffp+1, 4), true);
    expect_plain("2^-40 y: outside margin", box123({0, 5, 0}, {1, 0x1p-40, 0}, 0x1.7fffffffffp+1, 4), false);
    // Clear answers with tiny components in every class position.
    expect_plain("tiny all: inside", box123({0.5, 0.5, 0.5}, {1e-300, 1e-300, 1}, 0.25, 0.5), true);
    expect_plain("tiny all: beside", box123({0, 5, 0}, {1, 1e-300, 1e-300}, 2.5, 4), false);
    expect_plain("tiny: far along the axis", box123({1000, 0, 0}, {1, 1e-300, 1e-300}, 5, 10), false);
    expect_plain("tiny: long cylinder reaching the box", box123({1000, 0, 0}, {1, 1e-300, 1e-300}, 0.5, 2000), true);
    expect_plain("subnormal: edge cases of the extreme-edge clamp",
                 box123({3, 2.5, 3.5}, {1, kDenormMin, kDenormMin}, 0.75, 5), true);
}

// Regressions for the clamps of the slab-plane crossings (found by running a variant without them
// against the oracle): axis components 2^-26…2^-48 and a slab plane through a box vertex, where the
// rounded (τ − t)/d overshoots the edge by ~ulp(t)/d and the candidate point leaves the box. Exact
// answer: miss, far from touching (the tolerance does not excuse double here).
TEST(LinearInequalitiesRegression, ClampKeepsCrossingsOnTheBox) {
    const Case cases[] = {
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.11f32c15aa802p+1, 0x1.45eb33ad3263ep-2, 0x1.23861030904b8p-2}},
             Cylinder<double>{{0x1.69f8631f674cep+1, 0x1.02febcdb6aae4p+0, 0x1.c467f1f61371p+0},
                              {-0x1.2f04db2c49912p-47, -0x1.367688bc1f77ap-26, -0x1p+0}, 0x1.ed6fadec372d6p-1,
                              0x1.06a4bb1c04c18p+2}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.79d7d75d5618cp-2, 0x1.2d7b8c5b39a91p+1, 0x1.1a16d7506eb72p+1}},
             Cylinder<double>{{-0x1.6a19025f23948p-1, 0x1.d5cf7628066cp+1, 0x1.c2291064b1f96p+1},
                              {-0x1.9ac94b603dfb6p-33, -0x1.a33182c6d5159p-47, -0x1p+0}, 0x1.5855d2106cfe2p+0,
                              0x1.5024722841104p+1}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.830e4f3e448f3p+0, 0x1.d7e9e76baabdp-2, 0x1.ba6e498ed7e1p+0}},
             Cylinder<double>{{-0x1.44087f6af8efcp+1, 0x1.cdafa16ee813p-1, -0x1.d0e7938b2c6f5p+1},
                              {0x1p+0, -0x1.727e7707b6b81p-40, -0x1.d074adc989d78p-48}, 0x1.df8d66e4033dcp+0,
                              0x1.02c7d3850dc3bp+3}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.4aee6730907b2p-1, 0x1.7c4deafa7b305p+1, 0x1.48be8944ab1bcp-1}},
             Cylinder<double>{{0x1.6c86506dce998p+0, -0x1.dc7a38b2f362p-2, 0x1.2d5717a253dcp+0},
                              {0x1.457faed5128c9p-47, 0x1p+0, 0x1.0d9a7193f9afbp-47}, 0x1.df97b7787bdd7p-1,
                              0x1.40bea3e41cc5ap+2}},
        Case{BoxKind::canonical, {}, {}, CanonicalBox<double>{{0x1.9d9b8f5685776p+0, 0x1.0f1262f8cd865p+1, 0x1.d84add2539c9cp-1}},
             Cylinder<double>{{-0x1.305fab3406128p+1, 0x1.7c5dd99393ac2p+1, 0x1.73e97128d7c8cp+1},
                              {-0x1.0e1c169af7438p-46, 0x1.7f9ab9d3b4acp-27, -0x1p+0}, 0x1.23f58eb85e44dp+0,
                              0x1.fbad7396212c4p+1}},
    };
    int n = 0;
    for (const Case& c : cases) {
        const std::string name = "clamp regression " + std::to_string(n++);
        expect_answer(name, c, false);
        EXPECT_FALSE(testing::near_touching(c, testing::double_tolerance)) << name;
        EXPECT_FALSE(rounded_li<double>(c)) << name << "\n  " << describe(c);
    }
}

TEST(LinearInequalitiesHand, RoundedSummary) {
    std::printf("hand cases: double checked %ld, tolerated (near touching, tilted axis) %ld; float checked %ld, "
                "tolerated %ld\n",
                g_hand_double.checked, g_hand_double.tolerated, g_hand_float.checked, g_hand_float.tolerated);
}

// ---------------------------------------------------------------- randomized exact differential test

// Rational-ish random queries: small-integer and Pythagorean axes (all 7 sign classes after
// reflection, with negative components), occasional tiny components, dyadic sizes, canonical and
// aligned boxes, zero extents / radius / height.
class RationalishGenerator {
public:
    explicit RationalishGenerator(std::uint64_t seed) : rng_(seed) {}

    Case next() {
        Case c;
        const bool aligned = uniform_int(0, 1) == 1;
        Vec3<double> ext, ctr{0, 0, 0};
        for (int i = 0; i < 3; ++i) {
            ext[i] = uniform_int(0, 9) == 0 ? 0.0 : grid(0.25, 3, 0.25);
            if (aligned) ctr[i] = grid(-4, 4, 0.125);
        }
        if (aligned) {
            c.kind = BoxKind::aligned;
            for (int i = 0; i < 3; ++i) {
                c.aligned.min[i] = ctr[i] - ext[i];
                c.aligned.max[i] = ctr[i] + ext[i];
            }
        } else {
            c.kind = BoxKind::canonical;
            c.canonical.extents = ext;
        }
        c.cylinder.axis = axis();
        c.cylinder.radius = uniform_int(0, 9) == 0 ? 0.0 : grid(0.0625, 3, 0.0625);
        c.cylinder.height = uniform_int(0, 9) == 0 ? 0.0 : grid(0.125, 8, 0.125);
        for (int i = 0; i < 3; ++i) {
            const double reach = ext[i] + 0.5 * (c.cylinder.radius + 0.5 * c.cylinder.height) + 0.5;
            c.cylinder.center[i] = ctr[i] + grid(-1.2 * reach, 1.2 * reach, 1.0 / 64);
        }
        return c;
    }

    int uniform_int(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }

private:
    double grid(double lo, double hi, double step) {
        const long a = static_cast<long>(std::ceil(lo / step)), b = static_cast<long>(std::floor(hi / step));
        return static_cast<double>(std::uniform_int_distribution<long>(a, b)(rng_)) * step;
    }
    double sign() { return uniform_int(0, 1) ? 1.0 : -1.0; }

    Vec3<double> axis() {
        Vec3<double> a;
        const int kind = uniform_int(0, 19);
        if (kind < 3) {
            // Rational unit directions (Pythagorean quadruples), permuted, random signs.
            static const int quads[][3] = {{1, 2, 2}, {2, 3, 6}, {1, 4, 8}, {3, 4, 12}, {2, 6, 9},
                                           {0, 3, 4}, {0, 5, 12}, {0, 0, 1}, {4, 4, 7}};
            const auto& q = quads[uniform_int(0, 8)];
            const int p = uniform_int(0, 5);
            static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
            for (int i = 0; i < 3; ++i) a[i] = q[perms[p][i]] * sign();
        } else {
            const int zeros = kind < 11 ? 0 : kind < 17 ? 1 : 2;
            const int skip = uniform_int(0, 2);
            for (int i = 0; i < 3; ++i) a[i] = uniform_int(1, 6) * sign();
            if (zeros >= 1) a[skip] = 0;
            if (zeros == 2) a[(skip + 1) % 3] = 0;
            if (uniform_int(0, 9) == 0) {
                // One non-zero component becomes tiny (the others keep |a_i| ≥ 1).
                static const double tiny[] = {1e-300, 3 * kDenormMin, 0x1p-40, 1e-12};
                int i = uniform_int(0, 2);
                while (a[i] == 0) i = (i + 1) % 3;
                if (zeros < 2) a[i] = tiny[uniform_int(0, 3)] * sign();
            }
        }
        const double s = std::ldexp(1.0, uniform_int(-2, 2));  // non-unit on purpose
        return {a[0] * s, a[1] * s, a[2] * s};
    }

    std::mt19937_64 rng_;
};

Case with_knob(Case c, Knob k, double v) {
    (k == Knob::radius ? c.cylinder.radius : c.cylinder.height) = v;
    return c;
}

// The exact touching value of the radius (or height) ± 1 ulp: bisection with the linear-inequalities method
// in double to the rounded flip, widened until the oracle brackets it, then bisection with the oracle over
// adjacent doubles. False when there is no flip (the axis meets the box, or the box misses the slab for every
// radius, or the flip is at 0).
bool touching_pair(const Case& base, Knob k, Case& miss, Case& hit) {
    const double top = 64.0 * (1.0 + testing::problem_scale(base));
    auto dbl = [&](double v) { return rounded_li<double>(with_knob(base, k, v)); };
    auto ora = [&](double v) { return testing::oracle_answer(with_knob(base, k, v)); };
    if (dbl(0.0) || !dbl(top)) return false;
    const auto [a, b] = testing::bisect_ulp(0.0, top, dbl);
    std::int64_t lo = testing::ordered_bits(a), hi = testing::ordered_bits(b);
    for (std::int64_t step = 1; ora(testing::from_ordered_bits(lo)); step *= 2) {
        if (lo == 0 || step > (std::int64_t{1} << 40)) return false;
        lo = lo > step ? lo - step : 0;
    }
    for (std::int64_t step = 1; !ora(testing::from_ordered_bits(hi)); step *= 2) {
        if (step > (std::int64_t{1} << 40)) return false;
        hi += step;
    }
    const auto [x, y] = testing::bisect_ulp(testing::from_ordered_bits(lo), testing::from_ordered_bits(hi), ora);
    miss = with_knob(base, k, x);
    hit = with_knob(base, k, y);
    return true;
}

struct DiffTally {
    long cases = 0, hits = 0, rational_checked = 0, double_disagree = 0, double_far = 0, touching_pairs = 0;
};

void check_random_case(DiffTally& t, const Case& c, std::uint64_t seed, long index, const char* tag) {
    ++t.cases;
    const bool want = testing::oracle_answer(c);
    t.hits += want;
    const bool got = exact_li(c);
    if (got != want)
        ADD_FAILURE() << "seed " << seed << " case " << index << " (" << tag << "): inequalities in QFRational says " << got
                      << ", oracle " << want << "\n  " << describe(c);
    if (const std::optional<bool> r = rational_li(c)) {
        ++t.rational_checked;
        if (*r != want)
            ADD_FAILURE() << "seed " << seed << " case " << index << " (" << tag << "): inequalities in Rational says " << *r
                          << ", oracle " << want << "\n  " << describe(c);
    }
    if (rounded_li<double>(c) != want) {
        ++t.double_disagree;
        if (!testing::near_touching(c, testing::double_tolerance)) {
            ++t.double_far;
            std::printf("  [double disagrees, not near touching] seed %llu case %ld (%s)\n  %s\n",
                        static_cast<unsigned long long>(seed), index, tag, describe(c).c_str());
        }
    }
}

TEST(LinearInequalitiesRandom, ExactDifferentialAgainstOracle) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t seed = 0x4a11e9u;
    RationalishGenerator gen(seed);
    DiffTally t;
    long index = 0;
    for (int n = 0; n < 2000; ++n, ++index) {
        const Case c = gen.next();
        check_random_case(t, c, seed, index, "random");
        // Near-touching pairs: radius for 2 in 5 cases, height for 1 in 10.
        const int pick = gen.uniform_int(0, 9);
        if (pick < 5) {
            Case miss, hit;
            const Knob k = pick < 4 ? Knob::radius : Knob::height;
            if (touching_pair(c, k, miss, hit)) {
                ++t.touching_pairs;
                check_random_case(t, miss, seed, index, k == Knob::radius ? "touching radius - 1 ulp" : "touching height - 1 ulp");
                check_random_case(t, hit, seed, index, k == Knob::radius ? "touching radius" : "touching height");
            }
        }
    }
    // The shared generator too (aligned and canonical kinds only: the linear-inequalities method takes
    // oriented boxes through a rounded rotation, which the exact comparison cannot use).
    const std::uint64_t seed2 = 0x5eed02u;
    testing::CaseGenerator shared(seed2);
    for (int n = 0; n < 600; ++n, ++index) {
        const Case c = shared.next();
        if (c.kind == BoxKind::oriented) continue;
        check_random_case(t, c, seed2, index, "CaseGenerator");
    }
    int pairs = 0;
    for (int tries = 0; tries < 200 && pairs < 40; ++tries, ++index) {
        Case a, b;
        testing::Parameter which = testing::Parameter::radius;
        if (!testing::boundary_pair(shared, a, b, which)) continue;
        if (a.kind == BoxKind::oriented || which == testing::Parameter::rotation) continue;
        ++pairs;
        check_random_case(t, a, seed2, index, testing::name(which));
        check_random_case(t, b, seed2, index, testing::name(which));
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("random: %ld cases (%.1f%% hits), %ld touching pairs from r/h, %d boundary pairs, %ld also in Rational; "
                "inequalities QFRational disagreements: reported above as failures\n",
                t.cases, 100.0 * static_cast<double>(t.hits) / static_cast<double>(t.cases), t.touching_pairs, pairs,
                t.rational_checked);
    std::printf("random: inequalities in double disagrees with the oracle on %ld of %ld cases (%ld NOT near touching at "
                "tau = 2^-40); %.1f s\n",
                t.double_disagree, t.cases, t.double_far, secs);
    EXPECT_GE(t.cases, 3000);
}

// Disks (h = 0): no_zero_components checks only the six face cuts then (the six clipped box edges are
// points of them). The exact linear-inequalities method against the oracle over every direction class,
// canonical boxes with and without flat sides, and radii one ulp either side of touching.
TEST(LinearInequalitiesRandom, DisksAgainstOracle) {
    const std::uint64_t seed = 0xd15c5u;
    RationalishGenerator gen(seed);
    DiffTally t;
    long by_zeros[3] = {0, 0, 0};  // cases by the number of zero axis components
    long flat = 0, index = 0;
    for (int n = 0; n < 2000; ++n, ++index) {
        Case c = gen.next();
        if (c.kind == BoxKind::aligned) {  // the same box as a canonical one (centre moved to the origin)
            for (int i = 0; i < 3; ++i) {
                const double k = 0.5 * (c.aligned.min[i] + c.aligned.max[i]);
                c.canonical.extents[i] = 0.5 * (c.aligned.max[i] - c.aligned.min[i]);
                c.cylinder.center[i] -= k;
            }
            c.kind = BoxKind::canonical;
        }
        if (gen.uniform_int(0, 3) == 0) c.canonical.extents[gen.uniform_int(0, 2)] = 0.0;  // a flat box
        c.cylinder.height = 0.0;
        int zeros = 0;
        for (int i = 0; i < 3; ++i) zeros += c.cylinder.axis[i] == 0.0;
        ++by_zeros[zeros];
        flat += c.canonical.extents[0] == 0.0 || c.canonical.extents[1] == 0.0 || c.canonical.extents[2] == 0.0;
        check_random_case(t, c, seed, index, "disk");
        if (gen.uniform_int(0, 9) < 3) {
            Case miss, hit;
            if (touching_pair(c, Knob::radius, miss, hit)) {
                ++t.touching_pairs;
                check_random_case(t, miss, seed, index, "disk, touching radius - 1 ulp");
                check_random_case(t, hit, seed, index, "disk, touching radius");
            }
        }
    }
    std::printf("disks: %ld cases (%.1f%% hits; axis with 0/1/2 zero components: %ld/%ld/%ld; %ld flat boxes), "
                "%ld touching radius pairs; inequalities in double disagrees on %ld (%ld NOT near touching)\n",
                t.cases, 100.0 * static_cast<double>(t.hits) / static_cast<double>(t.cases), by_zeros[0], by_zeros[1],
                by_zeros[2], flat, t.touching_pairs, t.double_disagree, t.double_far);
    EXPECT_GE(t.cases, 2000);
    EXPECT_GE(by_zeros[0], 500);
    EXPECT_GE(by_zeros[1], 200);
    EXPECT_GE(by_zeros[2], 100);
    EXPECT_GE(flat, 300);
    EXPECT_GE(t.touching_pairs, 100);
}

}  // namespace
}  // namespace boxcyl
