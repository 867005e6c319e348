// validate() names the first bad field and why; zeros are valid degenerate solids.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "boxcyl/geometry/validate.hpp"

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

}  // namespace
}  // namespace boxcyl
