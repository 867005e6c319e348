// The three box kinds (aligned, oriented, canonical; docs/algorithms.md).
#pragma once

#include <array>  // OrientedBox::axes

#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// Aligned box: the closed box min ≤ X ≤ max (componentwise). min == max in a component is a flat box.
template <class T>
struct AlignedBox {
    Vec3<T> min;
    Vec3<T> max;
};

// Oriented box: the closed solid { center + x0·axes[0] + x1·axes[1] + x2·axes[2] : |xi| ≤ extents[i] }.
// The axes are meant to be orthonormal; the exact semantics are "the parallelepiped the axes span,
// exactly as given" (docs in README), so an axis frame that is orthonormal only up to rounding is
// still an exact, well-defined solid.
template <class T>
struct OrientedBox {
    Vec3<T> center;
    std::array<Vec3<T>, 3> axes;
    Vec3<T> extents;
};

// Canonical box: centred at the origin, aligned with the coordinate axes: |xi| ≤ extents[i].
template <class T>
struct CanonicalBox {
    Vec3<T> extents;
};

}  // namespace boxcyl
