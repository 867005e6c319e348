// The answer of the distance query (boxcyl/distance.hpp), apart from the query so that the compiled
// library's declarations (boxcyl/compiled.hpp) need nothing heavier.
#pragma once

#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// lower ≤ dist(box, cylinder) ≤ upper, proved for the inputs as given; at most 4 doubles apart (so
// upper − lower ≤ 4 ulp(upper), subnormal distances included); both exactly 0 when the solids
// intersect. A distance beyond the largest double has upper = +∞.
// on_box and on_cylinder: a nearest pair (approximate, not proved): each lies within
// ‖p‖∞·2⁻⁵¹ + 2⁻¹⁰⁶⁰ of its solid (an AlignedBox's witness lies in the box exactly), and their distance
// is the distance to within the two bounds where the refinement converged (every case of the test sets
// in round to nearest). For intersecting solids they are near a common point.
struct Distance {
    double lower = 0, upper = 0;
    Vec3<double> on_box{}, on_cylinder{};
};

// lower ≤ sd(box, cylinder) ≤ upper, proved for the inputs as given, where sd is the distance when the
// solids are apart and minus the penetration depth (the length of the shortest translation of the box
// that separates them) when they overlap; 0 when they touch. Apart: the Distance's enclosure. Overlapping:
// upper − lower ≤ 2⁻⁴³·L, L the largest of the box centre's offset from the cylinder's centre (each
// coordinate), the components of the box's half axes, the radius and the half height.
// normal: a unit vector from the box towards the cylinder (the box moves along −normal to separate);
// on_box, on_cylinder: a witness pair, on_cylinder − on_box ≈ sd·normal (approximate, not proved).
struct SignedDistance {
    double lower = 0, upper = 0;
    Vec3<double> normal{}, on_box{}, on_cylinder{};
};

}  // namespace boxcyl
