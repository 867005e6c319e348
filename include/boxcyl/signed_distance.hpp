// The signed distance: boxcyl::signed_distance(box, cylinder) — how far apart the solids are, or, where
// they overlap, how deep: minus the length of the shortest translation of the box that separates them
// (the penetration depth). The answer is an enclosure [lower, upper] PROVED to hold it for the inputs as
// given (each double the rational it denotes, the axis D/|D| exact), in every rounding mode:
//   - apart: the distance's enclosure (boxcyl/distance.hpp), at most 4 doubles wide;
//   - overlapping: −depth, with upper − lower ≤ 2⁻⁴³·L, L the largest of the box centre's offset from
//     the cylinder's centre (each coordinate), the components of the box's half axes, the radius and
//     the half height.
// With it come a unit normal n from the box towards the cylinder and a witness pair with
// on_cylinder − on_box ≈ signed distance · n: moving the box by on_cylinder − on_box brings the solids
// to touching (approximate, not proved). Invalid input throws std::invalid_argument naming the field;
// signed_distance_unchecked() skips that check. Needs the exact backend (boxcyl::exact).
//
// How (docs/distance.md has the argument): the exact distance query; if the solids meet, the depth's
// bounds by branch and bound over the directions where the depth can be attained (filtered/depth.hpp),
// on the shapes scaled by a power of two to lengths near 1.
#pragma once

#include <algorithm>    // std::clamp, std::max
#include <cmath>        // std::sqrt, std::abs, std::ldexp, std::ilogb
#include <limits>       // infinity
#include <type_traits>  // std::is_same_v
#include <vector>       // the circles searched

#include "boxcyl/distance.hpp"
#include "boxcyl/distance_types.hpp"
#include "boxcyl/filtered/depth.hpp"
#include "boxcyl/filtered/rim.hpp"
#include "boxcyl/filtered/separation.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/query.hpp"

namespace boxcyl {

#if defined(BOXCYL_HAS_EXACT)
namespace detail::signed_distance {

// The box's edge directions as doubles (the planes perpendicular to them are searched).
inline std::vector<Vec3<double>> edges(const AlignedBox<double>&) { return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }
inline std::vector<Vec3<double>> edges(const CanonicalBox<double>&) { return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }
template <class Box>
std::vector<Vec3<double>> edges(const Box& b) {
    std::vector<Vec3<double>> out;
    for (const Vec3<double>& a : b.axes)
        if (a[0] != 0 || a[1] != 0 || a[2] != 0) out.push_back(filtered::rim::scaled_axis(a));
    return out;
}

// The box's centre relative to the cylinder's, enclosed. An aligned box's is ((min − C) + (max − C))/2:
// far from the origin each difference is exact (or nearly) and their sum is of the box's size, where
// (min + max)/2 − C would carry the rounding of the coordinates' size.
inline Vec3<Interval> offset(const AlignedBox<double>& b, const Vec3<Interval>& C) {
    Vec3<Interval> z;
    for (int i = 0; i < 3; ++i) z[i] = ((Interval(b.min[i]) - C[i]) + (Interval(b.max[i]) - C[i])) * Interval(0.5);
    return z;
}
template <class Box>
Vec3<Interval> offset(const Box& b, const Vec3<Interval>& C) {
    return filtered::rim::enclose(b).center - C;
}

// v / |v| without overflow or underflow (v scaled by a power of two first); {} when v is 0 or not finite.
inline Vec3<double> unit(const Vec3<double>& v) {
    const double m = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    if (!(m > 0) || !std::isfinite(m)) return {};
    const double s = std::ldexp(1.0, -std::ilogb(m));
    const Vec3<double> w = s * v;
    return (1 / std::sqrt(dot(w, w))) * w;
}

// The box moved by t (in double: the witnesses need no proof). A canonical box becomes the oriented box
// it is.
inline AlignedBox<double> moved(const AlignedBox<double>& b, const Vec3<double>& t) { return {b.min + t, b.max + t}; }
inline OrientedBox<double> moved(const OrientedBox<double>& b, const Vec3<double>& t) { return {b.center + t, b.axes, b.extents}; }
inline Parallelepiped<double> moved(const Parallelepiped<double>& b, const Vec3<double>& t) { return {b.center + t, b.axes, b.extents}; }
inline OrientedBox<double> moved(const CanonicalBox<double>& b, const Vec3<double>& t) {
    return {t, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, b.extents};
}

// A witness pair for overlapping shapes (scaled to lengths near 1): the box moved along −n by the depth
// and 2⁻¹² of the shapes' size more, a nearest pair of the then separate shapes, the box point moved
// back. The box point is then on the box's feature that supports it along n, the cylinder point on the
// cylinder's along −n, and their difference about −depth·n. The pair needs no proof: the distance's
// search and Newton's steps in double, without its certified bounds.
template <class Box>
void witnesses(const Box& box, const Cylinder<double>& cyl, const Vec3<double>& n, double depth, Vec3<double>& on_box,
               Vec3<double>& on_cylinder) {
    distance::Magnitude size;
    size(box), size(cyl);
    const double step = depth + std::ldexp(1.0, size.e - 12);
    const filtered::separation::Approximate a =
        clearance::search_in_double(moved(box, -step * n), cyl, -1, distance::search_gap);
    const auto [X, Y] = filtered::separation::nearest_pair(a, cyl, distance::newton_steps);
    on_box = X + step * n;
    on_cylinder = Y;
}

// For solids apart whose nearest pair coincides in doubles (a distance below the coordinates' rounding):
// the direction that best separates them (filtered/separation.hpp's search), on the shapes scaled to
// lengths near 1.
template <class Box>
Vec3<double> separating_direction(const Box& box, const Cylinder<double>& cyl) {
    distance::Magnitude size;
    size(box), size(cyl);
    distance::Scale scale{size.e == std::numeric_limits<int>::min() ? 0 : std::clamp(-size.e, -1000, 1000)};
    const Box b = scale(box);
    const Cylinder<double> c = scale(cyl);
    const filtered::rim::Rims f(c, 0.0);
    if (!f.valid) return {};
    return unit(filtered::separation::approximate(filtered::rim::enclose(b), f, c, -1).direction);
}

template <class Box>
SignedDistance signed_distance(const Box& box, const Cylinder<double>& cyl) {
    SignedDistance out;
    if (!intersects_unchecked(box, cyl)) {  // they do not meet: the distance
        const Distance apart = distance::distance(box, cyl);
        out.lower = apart.lower, out.upper = apart.upper;
        out.on_box = apart.on_box, out.on_cylinder = apart.on_cylinder;
        out.normal = unit(out.on_cylinder - out.on_box);
        if (out.normal == Vec3<double>{}) out.normal = separating_direction(box, cyl);  // the pair coincides in doubles
        return out;
    }
    distance::Magnitude size;
    size(box), size(cyl);
    distance::Scale scale{size.e == std::numeric_limits<int>::min() ? 0 : std::clamp(-size.e, -1000, 1000)};
    const Box sbox = scale(box);
    const Cylinder<double> scyl = scale(cyl);
    const bool scaled = scale.exact;
    const Box& b = scaled ? sbox : box;
    const Cylinder<double>& c = scaled ? scyl : cyl;

    const filtered::rim::Box enclosed = filtered::rim::enclose(b);
    const filtered::rim::Rims f(c, 0.0);
    filtered::depth::Bounds depth;  // [0, ∞] unless the search runs
    if (f.valid) {
        namespace fd = filtered::depth;
        const fd::Problem p{fd::enclose(offset(b, f.C)),
                            {fd::enclose(enclosed.half[0]), fd::enclose(enclosed.half[1]), fd::enclose(enclosed.half[2])},
                            fd::enclose(f.u), fd::enclose(f.r), fd::enclose(f.half_h)};
        std::vector<Vec3<double>> circles = edges(b);
        circles.push_back(filtered::rim::scaled_axis(c.axis));
        depth = filtered::depth::bounds(p, circles);
    }
    double lower = depth.lower, upper = depth.upper;
    if (scaled && scale.e != 0) {  // back to the input's scale, rounded outward where that is not exact
        distance::Scale back{-scale.e};
        const double lo = back(lower), up = back(upper);
        lower = std::ldexp(lo, scale.e) == lower ? lo : std::max(0.0, boxcyl::detail::next_down(lo));
        upper = std::ldexp(up, scale.e) == upper ? up : boxcyl::detail::next_up(up);
    }
    out.lower = -upper, out.upper = lower == 0 ? 0.0 : -lower;  // touching: +0, not −0
    out.normal = unit(depth.normal);
    if (out.normal != Vec3<double>{} && std::isfinite(depth.upper)) {  // the witnesses, at the scale searched
        witnesses(b, c, out.normal, 0.5 * depth.lower + 0.5 * depth.upper, out.on_box, out.on_cylinder);
        if (scaled && scale.e != 0) {
            distance::Scale back{-scale.e};
            out.on_box = back(out.on_box), out.on_cylinder = back(out.on_cylinder);
        }
    }
    return out;
}

}  // namespace detail::signed_distance
#endif

// The certified signed distance. Preconditions: a valid box and cylinder.
template <class Box, class T>
SignedDistance signed_distance_unchecked(const Box& box, const Cylinder<T>& cyl) {
#if defined(BOXCYL_HAS_EXACT)
    if constexpr (std::is_same_v<T, double>)
        return detail::signed_distance::signed_distance(box, cyl);
    else
        return detail::signed_distance::signed_distance(detail::cast<double>(box), detail::cast<double>(cyl));
#else
    static_assert(detail::dependent_false<T>, "boxcyl::signed_distance is certified by the exact queries and needs "
                                              "the exact backend: link boxcyl::exact (GMP, FLINT)");
    return {};
#endif
}

template <class Box, class T>
SignedDistance signed_distance(const Box& box, const Cylinder<T>& cyl) {
    detail::require_valid(box, cyl);
    return signed_distance_unchecked(box, cyl);
}

}  // namespace boxcyl
