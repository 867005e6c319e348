// Does the cylinder's axis segment meet the box? The shared early exit of the linear-inequalities
// method's three direction classes (the published note's eqs. (17), (21), …: there stated per direction
// class, with sign-normalised dᵢ > 0, and the two-zero-component case leaving the axial interval to the
// slab cull), written once as a 1-D interval intersection for any
// direction, so that it stands on its own without the cull.
//
// The segment C + tD, −h/2 ≤ t ≤ h/2, meets the canonical box |xᵢ| ≤ eᵢ iff some t satisfies
//     −h/2 ≤ t ≤ h/2   and, for each i,   −eᵢ ≤ cᵢ + t·dᵢ ≤ eᵢ.
// For dᵢ ≠ 0 the i-th condition is the t-interval between (−eᵢ − cᵢ)/dᵢ and (eᵢ − cᵢ)/dᵢ (ordered by
// the sign of dᵢ); for dᵢ = 0 it does not involve t and is simply |cᵢ| ≤ eᵢ. The segment meets the box
// iff the intersection of these intervals is non-empty: max(lower ends) ≤ min(upper ends). Closed
// intervals throughout (touching counts). A true answer means the solids meet (the axis segment lies
// inside the cylinder for every r ≥ 0); a false answer decides nothing by itself.
//
// Arithmetic: exact for exact T (the divisions are exact in an ordered field). In floating point the
// only operations are one subtraction and one division per bound, each rounded once, so the answer is
// the exact one for a box whose faces moved by a few ulps of max(|eᵢ|, |cᵢ|). A subnormal dᵢ can make
// a quotient overflow to ±∞; that is harmless: an ∞ is only compared, never added or multiplied, and
// an overflowed bound lies on the right side of ±h/2 (its true magnitude exceeds the largest finite
// value, hence h/2). NaN cannot appear: 0/0 is excluded by treating dᵢ = 0 separately, a finite
// non-zero dᵢ never divides to NaN, and no ∞ is subtracted from another. (Were eᵢ − cᵢ itself to
// overflow, near the top of the range, the quotient is again a correctly signed ∞ for |dᵢ| ≤ 1.)
#pragma once

#include <cstddef>  // std::size_t
#include <utility>  // std::swap

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"

namespace boxcyl::algo {

// True iff the axis segment {C + tD : |t| ≤ h/2} of `cyl` meets the closed canonical box.
template <class T>
bool axis_segment_meets_box(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl) {
    const T zero(0);
    T lo = -cyl.half_height;  // running max of the lower ends
    T hi = cyl.half_height;   // running min of the upper ends
    for (std::size_t i = 0; i < 3; ++i) {
        const T& d = cyl.direction[i];
        const T& c = cyl.center[i];
        const T& e = box.extents[i];
        if (d == zero) {
            // The segment is parallel to the slab |xᵢ| ≤ eᵢ: all inside it or all outside.
            if (c < -e || c > e) return false;
            continue;
        }
        // cᵢ + t·dᵢ = ±eᵢ at t = (±eᵢ − cᵢ)/dᵢ; which one is the lower end depends on the sign of dᵢ.
        T t_minus = (-e - c) / d;  // where the segment crosses xᵢ = −eᵢ
        T t_plus = (e - c) / d;    // where it crosses xᵢ = +eᵢ
        if (d < zero) {
            using std::swap;
            swap(t_minus, t_plus);
        }
        if (t_minus > lo) lo = t_minus;
        if (t_plus < hi) hi = t_plus;
        if (lo > hi) return false;
    }
    return lo <= hi;
}

}  // namespace boxcyl::algo
