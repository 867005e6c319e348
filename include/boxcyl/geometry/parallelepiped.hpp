// Any parallelepiped: a box kind for solids spanned by three vectors exactly as given.
#pragma once

#include <array>  // Parallelepiped::axes

#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// The closed solid { center + x0·axes[0] + x1·axes[1] + x2·axes[2] : |xi| ≤ extents[i] } for ANY three
// vectors, exactly as given: any lengths, any angles. Orthogonal axes of integer length (e.g.
// (3,4,0), (−4,3,0), (0,0,5)) give boxes with exact vertices; parallel or zero axes, or zero extents,
// give flat solids (a parallelogram, a hexagon, a segment, a point), still answered exactly.
// OrientedBox is the special case whose axes are orthonormal (up to rounding); it keeps that contract.
template <class T>
struct Parallelepiped {
    Vec3<T> center;
    std::array<Vec3<T>, 3> axes;
    Vec3<T> extents;
};

}  // namespace boxcyl
