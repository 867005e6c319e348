// validate() names the first bad field and why; zeros are valid degenerate solids. The input policy
// (validate.hpp's header, README "What the answer means") field by field, and the default query on
// the inputs it accepts at the edges of the double range, against the oracle and hand-derived answers.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>  // field setters
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/query.hpp"

namespace boxcyl {
namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

TEST(Validate, Cylinder) {
    EXPECT_TRUE(validate(Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 1}).ok());
    EXPECT_TRUE(validate(Cylinder<double>{{0, 0, 0}, {0, 0, 1e-320}, 0, 0}).ok());  // segment/disk/point ok
    EXPECT_EQ(validate(Cylinder<double>{{0, nan, 0}, {0, 0, 1}, 1, 1}).message(), "cylinder.center[1]: is NaN");
    EXPECT_EQ(validate(Cylinder<double>{{0, 0, 0}, {0, 0, -inf}, 1, 1}).message(), "cylinder.axis[2]: is -Inf");
    EXPECT_EQ(validate(Cylinder<double>{{0, 0, 0}, {0, -0.0, 0}, 1, 1}).message(), "cylinder.axis: is the zero vector");
    EXPECT_EQ(validate(Cylinder<double>{{0, 0, 0}, {1, 0, 0}, -1, 1}).message(), "cylinder.radius: is negative");
    EXPECT_EQ(validate(Cylinder<double>{{0, 0, 0}, {1, 0, 0}, 1, inf}).message(), "cylinder.height: is +Inf");
    EXPECT_EQ(validate(Cylinder<double>{{0, 0, 0}, {1, 0, 0}, 1, -0.5}, "cylinders[3]").message(),
              "cylinders[3].height: is negative");
}

TEST(Validate, AlignedBox) {
    EXPECT_TRUE(validate(AlignedBox<double>{{1, 2, 3}, {1, 2, 3}}).ok());  // a point is a box
    EXPECT_EQ(validate(AlignedBox<double>{{0, 0, 0}, {1, 1, nan}}).message(), "box.max[2]: is NaN");
    EXPECT_EQ(validate(AlignedBox<double>{{0, 2, 0}, {1, 1, 1}}).message(), "box.max[1]: is less than box.min[1]");
}

TEST(Validate, OrientedBox) {
    OrientedBox<double> b{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 0, 2}};
    EXPECT_TRUE(validate(b).ok());
    auto bad = b;
    bad.extents[1] = -1;
    EXPECT_EQ(validate(bad).message(), "box.extents[1]: is negative");
    bad = b;
    bad.axes[2] = {0, 0, 0};
    EXPECT_EQ(validate(bad).message(), "box.axes[2]: is the zero vector");
    bad = b;
    bad.axes[1] = {0, 2, 0};
    EXPECT_EQ(validate(bad).field, "box.axes[1]");
    bad = b;
    bad.axes[1] = {0.1, 1, 0};
    EXPECT_EQ(validate(bad).field, "box.axes");
    // A rotation rounded to double is well within the tolerance.
    const double c = std::cos(0.3), s = std::sin(0.3);
    bad = b;
    bad.axes = {Vec3<double>{c, s, 0}, Vec3<double>{-s, c, 0}, Vec3<double>{0, 0, 1}};
    EXPECT_TRUE(validate(bad).ok());
}

TEST(Validate, CanonicalBox) {
    EXPECT_TRUE(validate(CanonicalBox<double>{{0, 0, 0}}).ok());
    EXPECT_EQ(validate(CanonicalBox<double>{{0, -1, 0}}).message(), "box.extents[1]: is negative");
}


// --- the input policy, field by field ---

const double max_d = std::numeric_limits<double>::max();
const double min_sub = std::numeric_limits<double>::denorm_min();

const Cylinder<double> unit_cyl{{0, 0, 0}, {0, 0, 1}, 1, 1};
const AlignedBox<double> unit_box{{0, 0, 0}, {1, 1, 1}};
const OrientedBox<double> unit_obox{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}};

template <class Shape>
struct Field {
    std::string name;
    std::function<void(Shape&, double)> set;
};

std::vector<Field<Cylinder<double>>> cylinder_fields() {
    std::vector<Field<Cylinder<double>>> f;
    for (std::size_t i = 0; i < 3; ++i) {
        f.push_back({"cylinder.center[" + std::to_string(i) + "]", [i](Cylinder<double>& c, double x) { c.center[i] = x; }});
        f.push_back({"cylinder.axis[" + std::to_string(i) + "]", [i](Cylinder<double>& c, double x) { c.axis[i] = x; }});
    }
    f.push_back({"cylinder.radius", [](Cylinder<double>& c, double x) { c.radius = x; }});
    f.push_back({"cylinder.height", [](Cylinder<double>& c, double x) { c.height = x; }});
    return f;
}

std::vector<Field<AlignedBox<double>>> aligned_fields() {
    std::vector<Field<AlignedBox<double>>> f;
    for (std::size_t i = 0; i < 3; ++i) {
        f.push_back({"box.min[" + std::to_string(i) + "]", [i](AlignedBox<double>& b, double x) { b.min[i] = x; }});
        f.push_back({"box.max[" + std::to_string(i) + "]", [i](AlignedBox<double>& b, double x) { b.max[i] = x; }});
    }
    return f;
}

std::vector<Field<OrientedBox<double>>> oriented_fields() {
    std::vector<Field<OrientedBox<double>>> f;
    for (std::size_t i = 0; i < 3; ++i) {
        f.push_back({"box.center[" + std::to_string(i) + "]", [i](OrientedBox<double>& b, double x) { b.center[i] = x; }});
        f.push_back({"box.extents[" + std::to_string(i) + "]", [i](OrientedBox<double>& b, double x) { b.extents[i] = x; }});
        for (std::size_t j = 0; j < 3; ++j)
            f.push_back({"box.axes[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                         [i, j](OrientedBox<double>& b, double x) { b.axes[i][j] = x; }});
    }
    return f;
}

template <class Shape>
void expect_non_finite_rejected(const Shape& good, const std::vector<Field<Shape>>& fields) {
    ASSERT_TRUE(validate(good).ok());
    for (const auto& f : fields) {
        for (const auto& [x, why] : {std::pair{nan, "is NaN"}, std::pair{-nan, "is NaN"}, std::pair{inf, "is +Inf"},
                                     std::pair{-inf, "is -Inf"}}) {
            Shape s = good;
            f.set(s, x);
            EXPECT_EQ(validate(s).message(), f.name + ": " + why);
        }
    }
}

TEST(InputPolicy, NaNAndInfAreRejectedInEveryField) {
    expect_non_finite_rejected(unit_cyl, cylinder_fields());
    expect_non_finite_rejected(unit_box, aligned_fields());
    expect_non_finite_rejected(unit_obox, oriented_fields());
}

TEST(InputPolicy, NegativeSizesAreRejectedNegativeZeroIsZero) {
    for (const double neg : {-1.0, -min_sub, -max_d}) {
        Cylinder<double> c = unit_cyl;
        c.radius = neg;
        EXPECT_EQ(validate(c).message(), "cylinder.radius: is negative");
        c = unit_cyl;
        c.height = neg;
        EXPECT_EQ(validate(c).message(), "cylinder.height: is negative");
        for (std::size_t i = 0; i < 3; ++i) {
            OrientedBox<double> b = unit_obox;
            b.extents[i] = neg;
            EXPECT_EQ(validate(b).message(), "box.extents[" + std::to_string(i) + "]: is negative");
        }
    }
    Cylinder<double> c = unit_cyl;
    c.radius = -0.0;
    c.height = -0.0;
    EXPECT_TRUE(validate(c).ok());
    OrientedBox<double> b = unit_obox;
    b.extents = {-0.0, -0.0, -0.0};
    EXPECT_TRUE(validate(b).ok());
}

TEST(InputPolicy, MinAboveMaxIsRejectedByOneUlp) {
    for (std::size_t i = 0; i < 3; ++i) {
        AlignedBox<double> b = unit_box;
        b.min[i] = std::nextafter(1.0, 2.0);
        EXPECT_EQ(validate(b).message(), "box.max[" + std::to_string(i) + "]: is less than box.min[" + std::to_string(i) + "]");
        b.min[i] = 1.0;  // min == max: a flat box
        EXPECT_TRUE(validate(b).ok());
    }
    EXPECT_TRUE(validate(AlignedBox<double>{{-0.0, 0, 0}, {0.0, 0, 0}}).ok());  // -0 == +0
}

TEST(InputPolicy, ZeroAxisIsRejectedTinyAxisIsNot) {
    Cylinder<double> c = unit_cyl;
    c.axis = {-0.0, 0.0, -0.0};
    EXPECT_EQ(validate(c).message(), "cylinder.axis: is the zero vector");
    c.axis = {0, min_sub, 0};  // a direction, whatever its length
    EXPECT_TRUE(validate(c).ok());
    c.axis = {max_d, max_d, -max_d};  // |axis|² overflows double; the direction is still exact
    EXPECT_TRUE(validate(c).ok());
}

// Oriented-box frames: accepted within 1e-4 of orthonormal (then the exact parallelepiped), refused
// beyond with a message naming the axis or the pair.
TEST(InputPolicy, OrientedAxesWithinToleranceAreAcceptedBeyondAreRejected) {
    OrientedBox<double> b = unit_obox;
    b.axes[1] = {orthonormality_tolerance, 1, 0};  // axes[0]·axes[1] = 1e-4 exactly at the tolerance
    EXPECT_TRUE(validate(b).ok());
    b.axes[1] = {2 * orthonormality_tolerance, 1, 0};
    EXPECT_EQ(validate(b).message(), "box.axes: are not orthogonal (axes[0]·axes[1] = 0.000200, tolerance 1e-4)");
    b = unit_obox;
    b.axes[2] = {0, 0, 1.001};
    EXPECT_EQ(validate(b).message(), "box.axes[2]: is not unit length (|axes[2]|² = 1.002001, tolerance 1e-4)");
    b.axes[2] = {0, 0, -1};  // a left-handed frame is fine: the solid does not care
    EXPECT_TRUE(validate(b).ok());
    b.axes[2] = {0, 0, max_d};  // no overflow inside the check
    EXPECT_EQ(validate(b).field, "box.axes[2]");
    b.axes[2] = {min_sub, 0, 0};  // tiny is not unit
    EXPECT_EQ(validate(b).field, "box.axes[2]");
}

// A value just beyond the tolerance is printed with the decimals it takes to read as beyond it.
TEST(InputPolicy, OrthonormalityMessagesShowTheValueBeyondTheTolerance) {
    OrientedBox<double> b = unit_obox;
    b.axes[1] = {std::nextafter(orthonormality_tolerance, 1.0), 1, 0};  // axes[0]·axes[1] = 1e-4 + 1 ulp
    EXPECT_EQ(validate(b).message(),
              "box.axes: are not orthogonal (axes[0]·axes[1] = 0.00010000000000000002, tolerance 1e-4)");
    b.axes[1] = {-1.0000001e-4, 1, 0};
    EXPECT_EQ(validate(b).message(), "box.axes: are not orthogonal (axes[0]·axes[1] = -0.00010000001, tolerance 1e-4)");
    b = unit_obox;
    b.axes[2] = {0, 0, 1.00005000001};  // |axes[2]|² ≈ 1.00010000025, "1.000100" to six decimals
    EXPECT_EQ(validate(b).message(), "box.axes[2]: is not unit length (|axes[2]|² = 1.000100003, tolerance 1e-4)");
    b.axes[2] = {0, 0, max_d};  // beyond double: printed in long double
    EXPECT_EQ(validate(b).message(), "box.axes[2]: is not unit length (|axes[2]|² = 3.2317e+616, tolerance 1e-4)");
}

// is_valid() is validate().ok() without the text, on valid input, on every field's bad values and on
// frames on both sides of the tolerance.
TEST(InputPolicy, IsValidAgreesWithValidate) {
    const auto agree = [](const auto& shape) { EXPECT_EQ(is_valid(shape), validate(shape).ok()) << validate(shape).message(); };
    agree(unit_cyl);
    agree(unit_box);
    agree(unit_obox);
    agree(CanonicalBox<double>{{1, 0, -0.0}});
    agree(CanonicalBox<double>{{1, -1, 0}});
    for (const double x : {nan, inf, -inf, -1.0, -0.0, 0.0, min_sub, -min_sub, max_d, -max_d, 1.0}) {
        for (const auto& f : cylinder_fields()) {
            Cylinder<double> c = unit_cyl;
            f.set(c, x);
            agree(c);
        }
        for (const auto& f : aligned_fields()) {
            AlignedBox<double> b = unit_box;
            f.set(b, x);
            agree(b);
        }
        for (const auto& f : oriented_fields()) {
            OrientedBox<double> b = unit_obox;
            f.set(b, x);
            agree(b);
        }
    }
    // Off-diagonal and diagonal Gram entries stepping across 1e-4 one ulp at a time, in double and float.
    for (const double t : {orthonormality_tolerance, 0.9 * orthonormality_tolerance}) {
        double x = std::nextafter(t, 0.0);
        for (int k = 0; k < 3; ++k, x = std::nextafter(x, 1.0)) {
            OrientedBox<double> b = unit_obox;
            b.axes[1] = {x, 1, 0};
            agree(b);
            b.axes[1] = {-x, 1, 0};
            agree(b);
            OrientedBox<float> bf{{0, 0, 0}, {Vec3<float>{1, 0, 0}, Vec3<float>{static_cast<float>(x), 1, 0}, Vec3<float>{0, 0, 1}}, {1, 1, 1}};
            agree(bf);
        }
    }
    const double s = std::sqrt(1 + orthonormality_tolerance);
    for (double z = std::nextafter(s, 0.0), k = 0; k < 5; ++k, z = std::nextafter(z, 2.0)) {
        OrientedBox<double> b = unit_obox;
        b.axes[2] = {0, 0, z};
        agree(b);
    }
    EXPECT_TRUE(is_valid(unit_obox));
    EXPECT_FALSE(is_valid(Cylinder<double>{{0, 0, 0}, {0, 0, 0}, 1, 1}));
}

// --- the default query on what the policy accepts: the oracle's answer, and the hand-derived one ---

const QueryOptions oracle_options{Algorithm::oracle, Arithmetic::exact};

template <class Box>
void expect_answer(const Box& box, const Cylinder<double>& cyl, bool want, const char* what) {
    ASSERT_TRUE(validate(box).ok()) << what;
    ASSERT_TRUE(validate(cyl).ok()) << what;
    EXPECT_EQ(intersects(box, cyl, oracle_options), want) << what << " (oracle)";
    EXPECT_EQ(intersects(box, cyl), want) << what << " (default query)";
}

// is_valid reads finiteness off the bits of floats and doubles: every non-finite value of either type is
// refused in every field, and every finite one (subnormals, ±max, −0) accepted where the field allows it.
template <class T>
void expect_bitwise_finiteness() {
    const T values[] = {std::numeric_limits<T>::quiet_NaN(), -std::numeric_limits<T>::quiet_NaN(),
                        std::numeric_limits<T>::signaling_NaN(), std::numeric_limits<T>::infinity(),
                        -std::numeric_limits<T>::infinity(), std::numeric_limits<T>::denorm_min(),
                        std::numeric_limits<T>::max(), -T(0), T(2)};
    for (const T x : values) {
        const bool finite = std::isfinite(x);
        for (int f = 0; f < 8; ++f) {
            Cylinder<T> c{{0, 0, 0}, {0, 0, 1}, 1, 1};
            if (f < 3) c.center[f] = x;
            else if (f < 6) c.axis[f - 3] = x == T(0) ? T(1) : x;
            else if (f == 6) c.radius = x;
            else c.height = x;
            EXPECT_EQ(is_valid(c), finite) << "field " << f << " = " << x;
            Parallelepiped<T> p{{0, 0, 0}, {Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}, Vec3<T>{0, 0, 1}}, {1, 1, 1}};
            if (f < 3) p.center[f] = x;
            else if (f < 6) p.axes[1][f - 3] = x;
            else p.extents[f - 6] = x;
            EXPECT_EQ(is_valid(p), finite) << "field " << f << " = " << x;
            AlignedBox<T> b{{-std::numeric_limits<T>::max(), 0, 0}, {std::numeric_limits<T>::max(), 1, 1}};
            if (f < 6) (f < 3 ? b.min : b.max)[f % 3] = (f < 3 ? -std::fabs(x) : std::fabs(x));
            EXPECT_EQ(is_valid(b), f >= 6 || finite) << "field " << f << " = " << x;
        }
    }
}

TEST(InputPolicy, FinitenessIsReadOffTheBitsOfFloatsAndDoubles) {
    expect_bitwise_finiteness<float>();
    expect_bitwise_finiteness<double>();
}

TEST(InputPolicy, ZeroSizesAreTheExactDegenerateSolids) {
    const double above1 = std::nextafter(1.0, 2.0);
    // radius 0 and height 0: a point, touching the box's corner, then one ulp off.
    expect_answer(unit_box, Cylinder<double>{{1, 1, 1}, {0, 0, 1}, 0, 0}, true, "point at a corner");
    expect_answer(unit_box, Cylinder<double>{{1, 1, above1}, {0, 0, 1}, 0, 0}, false, "point one ulp above a corner");
    // radius 0: a segment ending exactly on the face z = 1.
    expect_answer(unit_box, Cylinder<double>{{0.5, 0.5, 2}, {0, 0, 1}, 0, 2}, true, "segment ending on a face");
    expect_answer(unit_box, Cylinder<double>{{0.5, 0.5, 2}, {0, 0, -3}, 0, std::nextafter(2.0, 0.0)}, false,
                  "segment one ulp short of a face");
    // height 0: a disk in the plane x = 2 (beside the box whatever its radius), a disk reaching a face.
    expect_answer(unit_box, Cylinder<double>{{2, 0.5, 0.5}, {1, 0, 0}, 5, 0}, false, "disk beside the box");
    expect_answer(unit_box, Cylinder<double>{{0.5, 3, 0.5}, {0, 0, 1}, 2, 0}, true, "disk reaching a face");
    // Zero-width boxes: a flat box and a point box.
    expect_answer(AlignedBox<double>{{0, 0, 1}, {1, 1, 1}}, Cylinder<double>{{0.5, 0.5, 2}, {0, 0, 1}, 0.25, 2}, true,
                  "flat box under a cylinder's cap");
    expect_answer(AlignedBox<double>{{0, 0, 0.5}, {0, 0, 0.5}}, Cylinder<double>{{1, 0, 0.5}, {0, 0, 1}, 1, 0}, true,
                  "point box on a disk's rim");
    expect_answer(AlignedBox<double>{{0, 0, 0.5}, {0, 0, 0.5}},
                  Cylinder<double>{{1, 0, 0.5}, {0, 0, 1}, std::nextafter(1.0, 0.0), 0}, false,
                  "point box one ulp outside a disk's rim");
    OrientedBox<double> flat = unit_obox;
    flat.extents = {0, 0, 0};
    expect_answer(flat, Cylinder<double>{{0, 0, 0}, {1, 1, 1}, 0, 0}, true, "point cylinder on a point box");
}

TEST(InputPolicy, NearlyOrthonormalAxesMeanTheExactParallelepiped) {
    // axes[1] sheared by 2^-17 (within the tolerance): the corner center + a0 + a1 is (1 + 2^-17, 1, 0).
    OrientedBox<double> b{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0x1p-17, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}};
    const double corner = 1 + 0x1p-17;
    expect_answer(b, Cylinder<double>{{corner, 1, 0}, {0, 0, 1}, 0, 0}, true, "point at the sheared corner");
    expect_answer(b, Cylinder<double>{{std::nextafter(corner, 2.0), 1, 0}, {0, 0, 1}, 0, 0}, false,
                  "point one ulp beyond the sheared corner");
    // The same point is outside the unit cube: the solid is the parallelepiped, not a cube.
    expect_answer(unit_obox, Cylinder<double>{{corner, 1, 0}, {0, 0, 1}, 0, 0}, false, "the point and the unsheared cube");
}

TEST(InputPolicy, MagnitudesAtTheEdgesOfTheDoubleRangeAreAnsweredExactly) {
    const double below_max = std::nextafter(max_d, 0.0);
    // A box spanning the whole double range contains every cylinder (its width overflows double).
    const AlignedBox<double> everything{{-max_d, -max_d, -max_d}, {max_d, max_d, max_d}};
    expect_answer(everything, Cylinder<double>{{max_d, -max_d, 0}, {1, 2, 3}, max_d, max_d}, true, "everything box");
    // The axis segment of a cylinder with |axis|² beyond double: the half height max/2 along
    // (1, 1, 1)/√3 reaches max/(2√3) ≈ 0.2887·max in each coordinate.
    const Cylinder<double> diagonal{{0, 0, 0}, {max_d, max_d, max_d}, 1, max_d};
    expect_answer(AlignedBox<double>{{0.28 * max_d, 0.28 * max_d, 0.28 * max_d}, {max_d, max_d, max_d}}, diagonal, true,
                  "huge diagonal cylinder reaching a far box");
    expect_answer(AlignedBox<double>{{0.29 * max_d, 0.29 * max_d, 0.29 * max_d}, {max_d, max_d, max_d}}, diagonal, false,
                  "huge diagonal cylinder short of a far box");
    // A cylinder centred at (max, 0, 0) with axis y: its nearest point to the unit cube is at distance
    // max − 1, so radius max reaches it and radius max − ulp(max) (= max − 2^971) does not.
    expect_answer(unit_box, Cylinder<double>{{max_d, 0.5, 0.5}, {0, 1, 0}, max_d, 1}, true, "radius max");
    expect_answer(unit_box, Cylinder<double>{{max_d, 0.5, 0.5}, {0, 1, 0}, below_max, 1}, false, "radius max − ulp");
    // Subnormal sizes: a cylinder of radius 2·2^-1074 touching the face x = 4·2^-1074 of a subnormal box.
    const AlignedBox<double> tiny{{0, 0, 0}, {4 * min_sub, 4 * min_sub, 4 * min_sub}};
    expect_answer(tiny, Cylinder<double>{{6 * min_sub, 2 * min_sub, 2 * min_sub}, {0, 0, 1}, 2 * min_sub, min_sub}, true,
                  "subnormal cylinder touching a subnormal box");
    expect_answer(tiny, Cylinder<double>{{6 * min_sub, 2 * min_sub, 2 * min_sub}, {0, 0, 1}, min_sub, min_sub}, false,
                  "subnormal cylinder one subnormal short");
    // Huge and subnormal together: a cylinder of length max along x, x in [0, max], its cap on the face
    // x = 0 of a subnormal box; with height max − ulp its cap is at x = 2^970 instead.
    const AlignedBox<double> tiny_left{{-4 * min_sub, 0, 0}, {0, 4 * min_sub, 4 * min_sub}};
    expect_answer(tiny_left, Cylinder<double>{{max_d / 2, min_sub, min_sub}, {-1, 0, 0}, min_sub, max_d}, true,
                  "huge cylinder whose cap touches a subnormal box");
    expect_answer(tiny_left, Cylinder<double>{{max_d / 2, min_sub, min_sub}, {-1, 0, 0}, min_sub, below_max}, false,
                  "huge cylinder short of a subnormal box");
    // An oriented box with a rounded rotation and extents near max/2: its x and y reach at most
    // (max/2)(0.6 + 0.8) = 0.7·max, z at most max/2.
    const OrientedBox<double> turned{{0, 0, 0}, {Vec3<double>{0.6, 0.8, 0}, Vec3<double>{-0.8, 0.6, 0}, Vec3<double>{0, 0, 1}},
                                     {max_d / 2, max_d / 2, max_d / 2}};
    expect_answer(turned, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 1}, true, "huge rotated box around a cylinder");
    expect_answer(turned, Cylinder<double>{{max_d, max_d, max_d}, {0, 0, 1}, 1, 1}, false, "huge rotated box, far cylinder");
}

// The front door refuses invalid input in every build type, with validate()'s message naming the
// field, for every box kind, float and double, with and without options; the _unchecked forms assert
// it in debug builds only.
template <class F>
std::string thrown(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(nothing thrown)";
}
TEST(InputPolicy, TheQueryRefusesInvalidInputNamingTheField) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    AlignedBox<double> nan_max = unit_box;
    nan_max.max[0] = nan;
    EXPECT_EQ(thrown([&] { (void)intersects(nan_max, unit_cyl); }), "box.max[0]: is NaN");
    EXPECT_EQ(thrown([&] { (void)intersects(nan_max, unit_cyl, {Algorithm::hull, Arithmetic::float64}); }),
              "box.max[0]: is NaN");
    const Cylinder<double> zero_axis{{0, 0, 0}, {0, 0, 0}, 1, 1};
    EXPECT_EQ(thrown([&] { (void)intersects(unit_box, zero_axis); }), "cylinder.axis: is the zero vector");
    const AlignedBox<double> flipped{{1, 0, 0}, {0, 1, 1}};
    EXPECT_EQ(thrown([&] { (void)intersects(flipped, unit_cyl, {Algorithm::inequalities, Arithmetic::float64}); }),
              "box.max[0]: is less than box.min[0]");
    const OrientedBox<double> skewed{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0.1, 1, 0}, Vec3<double>{0, 0, 1}}, {1, 1, 1}};
    EXPECT_NE(thrown([&] { (void)intersects(skewed, unit_cyl); }).find("box.axes"), std::string::npos);
    const Parallelepiped<double> negative{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}},
                                          {1, -1, 1}};
    EXPECT_EQ(thrown([&] { (void)intersects(negative, unit_cyl); }), "box.extents[1]: is negative");
    const CanonicalBox<float> inf_extent{{1, std::numeric_limits<float>::infinity(), 1}};
    EXPECT_EQ(thrown([&] { (void)intersects(inf_extent, Cylinder<float>{{0, 0, 0}, {0, 0, 1}, 1, 1}); }),
              "box.extents[1]: is +Inf");
    // Valid input is answered; the unchecked form answers the same.
    EXPECT_TRUE(intersects(unit_box, unit_cyl));
    EXPECT_EQ(intersects_unchecked(unit_box, unit_cyl), intersects(unit_box, unit_cyl));
}

#ifndef NDEBUG
// The unchecked forms assert their preconditions in debug builds (assertions stay on in scripts/test.sh).
TEST(InputPolicyDeathTest, TheUncheckedQueryAssertsValidInputInDebugBuilds) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const Cylinder<double> bad{{0, 0, 0}, {0, 0, 0}, 1, 1};
    EXPECT_DEATH(intersects_unchecked(unit_box, bad), "invalid cylinder");
    const AlignedBox<double> flipped{{1, 0, 0}, {0, 1, 1}};
    EXPECT_DEATH(intersects_unchecked(flipped, unit_cyl, {Algorithm::inequalities, Arithmetic::float64}), "invalid box");
}
#endif

}  // namespace
}  // namespace boxcyl
