// The slab cull, an early exit: project the canonical box onto the cylinder axis,
// [γ − ρ, γ + ρ] with γ = −D·C and ρ = Σ|dᵢ|eᵢ, and compare with [−h/2, h/2].
#pragma once

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/number/traits.hpp"

namespace boxcyl::algo {

// True when the box lies strictly outside the slab −h/2 ≤ D·(X − C) ≤ h/2 (|γ| > ρ + h/2), so it
// cannot meet the cylinder. Touching the slab plane is not outside (closed solids).
template <class T>
bool box_outside_slab(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl) {
    const Vec3<T>& d = cyl.direction;
    const Vec3<T>& e = box.extents;
    auto abs = [](const T& x) { return abs_value(x); };  // no sign decision for enclosures
    const T rho = abs(d[0]) * e[0] + abs(d[1]) * e[1] + abs(d[2]) * e[2];
    const T gamma = -dot(d, cyl.center);
    return abs(gamma) > rho + cyl.half_height;
}

}  // namespace boxcyl::algo
