// The finite cylinder as users give it, and the unit-axis form the algorithms take.
#pragma once

#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// A closed finite cylinder: all points X with |u·(X − center)| ≤ height/2 and distance from X to the
// axis line ≤ radius, where u = axis/|axis|. `axis` need NOT be unit length; only its direction
// counts. radius == 0 is a segment, height == 0 a disk, both 0 a point.
template <class T>
struct Cylinder {
    Vec3<T> center;
    Vec3<T> axis;
    T radius{};
    T height{};
};

// The cylinder as the three methods state it: a unit-length direction and half the height. Produced by the
// reductions in reduce.hpp; in floating point the unit direction is rounded, in quadratic-field
// arithmetic it is exact.
template <class T>
struct UnitCylinder {
    Vec3<T> center;
    Vec3<T> direction;  // |direction| == 1 (exactly, for exact T)
    T radius{};
    T half_height{};
};

}  // namespace boxcyl
