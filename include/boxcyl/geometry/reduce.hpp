// The reductions to the canonical frame: aligned and oriented boxes become the canonical box, the cylinder is
// moved into the box's frame. Generic over T: exact for exact T, rounded (once per operation) for
// float/double (the exact default bounds that rounding: docs/robustness/enclosures.md).
#pragma once

#include <algorithm>  // std::max
#include <cmath>      // std::fabs, std::ilogb, std::scalbn
#include <limits>     // the largest finite value

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/number/traits.hpp"

namespace boxcyl {

// A canonical box and a unit-axis cylinder in the box's frame: the input of the three methods.
template <class T>
struct CanonicalQuery {
    CanonicalBox<T> box;
    UnitCylinder<T> cylinder;
};

// Floating point only: normalise the axis. It is first scaled by a power of two (exact) that brings its
// largest component to [1, 2), so that D·D can neither underflow (all-subnormal axes) nor overflow;
// then one rounding per component plus the sqrt.
template <class T>
UnitCylinder<T> to_unit(const Cylinder<T>& c) {
    T m = T(0);
    for (int i = 0; i < 3; ++i) m = std::max(m, std::fabs(c.axis[i]));
    // A zero (or NaN) axis violates the precondition; ilogb would return INT_MIN (negating it is UB),
    // so it is left unscaled and gives a NaN direction instead.
    const int e = (m > T(0) && m <= std::numeric_limits<T>::max()) ? std::ilogb(m) : 0;
    const Vec3<T> a{std::scalbn(c.axis[0], -e), std::scalbn(c.axis[1], -e), std::scalbn(c.axis[2], -e)};
    const T len = inexact_sqrt(dot(a, a));
    return {c.center, {a[0] / len, a[1] / len, a[2] / len}, c.radius, c.height / T(2)};
}

// Aligned box: subtract the centre K = (min + max)/2; extents E = (max − min)/2.
template <class T>
CanonicalQuery<T> to_canonical(const AlignedBox<T>& b, const UnitCylinder<T>& c) {
    CanonicalQuery<T> q;
    for (int i = 0; i < 3; ++i) {
        const T k = (b.max[i] + b.min[i]) / T(2);
        q.box.extents[i] = (b.max[i] - b.min[i]) / T(2);
        q.cylinder.center[i] = c.center[i] - k;
    }
    q.cylinder.direction = c.direction;
    q.cylinder.radius = c.radius;
    q.cylinder.half_height = c.half_height;
    return q;
}

// Oriented box: C' = Rᵀ(C − K), D' = Rᵀ D with R = [W0 W1 W2]. Exact only for exactly orthonormal W.
template <class T>
CanonicalQuery<T> to_canonical(const OrientedBox<T>& b, const UnitCylinder<T>& c) {
    CanonicalQuery<T> q;
    const Vec3<T> delta = c.center - b.center;
    for (int i = 0; i < 3; ++i) {
        q.box.extents[i] = b.extents[i];
        q.cylinder.center[i] = dot(b.axes[i], delta);
        q.cylinder.direction[i] = dot(b.axes[i], c.direction);
    }
    q.cylinder.radius = c.radius;
    q.cylinder.half_height = c.half_height;
    return q;
}

template <class T>
CanonicalQuery<T> to_canonical(const CanonicalBox<T>& b, const UnitCylinder<T>& c) {
    return {b, c};
}

}  // namespace boxcyl
