// What a picture of one query shows: the convex-hull method's construction in double, for people (boxcyl
// explain).
//
// Seen along the cylinder's axis, the cylinder is a disk of radius r, and only the part of the box
// inside the slab |u·(X − C)| ≤ h/2 can meet it. So the picture is: the vertices of box ∩ slab, their
// projection onto the plane ⊥ u through C (2-D, origin on the axis), its convex hull, the hull point
// nearest to the origin and its distance d compared with r (algo/convex_hull.hpp).
//
// Everything here is rounded double arithmetic and is for drawing only. The verdict is NOT the
// picture's: it comes from the exact default query boxcyl::intersects (or is handed in), and when the
// double picture disagrees with it — inputs within rounding of touching — the explanation says so
// (Case::touching_within_rounding) instead of drawing a wrong answer.
//
// With a margin m the question is the clearance one (boxcyl::within_distance: is the box within
// distance m of the cylinder?), whose exact answer becomes the verdict; the construction above still
// explains whether the box meets the cylinder itself, and the picture adds the cylinder grown by m.
//
// With the distance question's answer (boxcyl::distance) the picture also marks its nearest pair: the
// proved bounds of the distance and the two approximate witness points, one on each solid. Where the
// solids overlap, the signed distance's answer (boxcyl::signed_distance) marks how deep instead: the
// proved bounds of the penetration depth and the deepest point of each solid along its normal.
#pragma once

#include <algorithm>  // std::min, std::max
#include <array>    // box vertices
#include <cmath>    // std::sqrt, std::fabs, std::hypot
#include <cstddef>  // std::size_t
#include <initializer_list>  // loops over point sets
#include <optional>  // the margin
#include <utility>  // std::pair
#include <vector>   // point sets

#include "boxcyl/algo/convex_hull.hpp"  // hull2d::monotone_chain, as_parallelepiped
#include "boxcyl/distance_types.hpp"   // the nearest pair
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/reduce.hpp"  // to_unit
#include "boxcyl/geometry/vec3.hpp"
#if defined(BOXCYL_HAS_EXACT)
#include "boxcyl/clearance.hpp"  // the exact verdict with a margin
#include "boxcyl/distance.hpp"   // the nearest pair
#include "boxcyl/query.hpp"      // the exact verdict
#include "boxcyl/signed_distance.hpp"  // the depth pair
#endif

namespace boxcyl::explain {

using Point2 = algo::hull2d::Point<double>;

// The one sentence a picture can say, decided by the exact verdict and the double picture together.
enum class Case {
    axis_through,              // intersects: the axis meets box ∩ slab (distance 0)
    overlap,                   // intersects: 0 < d < r
    touching,                  // intersects: d == r (in double)
    touching_end_plane,        // intersects: box ∩ slab lies in an end plane (the box touches a cap's plane)
    touching_within_rounding,  // the exact verdict and the double picture disagree: |d − r| is rounding
    gap,                       // does not intersect: d > r
    outside_slab,              // does not intersect: box ∩ slab is empty (the slab cull decides)
    not_drawable,              // coordinates overflow double in the picture (|values| near 1e308)
};

// The 12 edges of a parallelepiped with vertices numbered as in box_vertices (bit i of the index set
// ⇔ +aᵢ): each edge joins a and a | (1 << k) for a without bit k.
inline constexpr std::array<std::pair<int, int>, 12> box_edges{{
    {0, 1}, {2, 3}, {4, 5}, {6, 7},  // along a0
    {0, 2}, {1, 3}, {4, 6}, {5, 7},  // along a1
    {0, 4}, {1, 5}, {2, 6}, {3, 7},  // along a2
}};

struct Explanation {
    // The cylinder frame: unit axis u and an orthonormal basis (e1, e2) of the plane ⊥ u, with
    // (e1, e2, u) right-handed, so the 2-D view looks at the plane from the +u end.
    Vec3<double> center;
    Vec3<double> direction;  // u = axis/|axis| (rounded)
    Vec3<double> e1, e2;
    double radius = 0;
    double half_height = 0;

    std::array<Vec3<double>, 8> box_vertices;  // world coordinates, numbered as box_edges says
    double box_axial_min = 0, box_axial_max = 0;  // range of u·(X − C) over the box

    std::vector<Vec3<double>> section;  // vertices of box ∩ slab (box vertices in it, edge crossings)
    std::vector<Point2> box_shadow;     // hull of the whole box projected (context for the picture)
    std::vector<Point2> polygon;        // hull of the projected section: counter-clockwise, strictly
                                        // convex, or 1–2 points when degenerate; empty ⇔ slab_empty
    bool slab_empty = false;
    bool drawable = true;  // false: a projected coordinate overflowed; nothing but the verdict is shown

    Point2 closest;       // the polygon point nearest to the origin (the axis); origin when inside
    double distance = 0;  // |closest|: distance from the axis to box ∩ slab, in the plane ⊥ u (+∞ when it
                          // exceeds the double range)

    bool exact_intersects = false;    // the verdict (exact)
    bool picture_intersects = false;  // what the double picture alone would say: !slab_empty && d ≤ r
    Case what = Case::gap;

    // The clearance question, when asked (with_margin): the margin m and the exact answer of
    // within_distance. exact_intersects and `what` still describe the cylinder itself.
    std::optional<double> margin;
    bool exact_within = false;

    // The distance question's answer, when given (with_nearest) and the picture is drawable: the proved
    // enclosure [lower, upper] of the distance (both 0 when the solids intersect) and the nearest pair.
    std::optional<Distance> nearest;
    // Where the solids overlap (nearest's upper is 0), the signed distance's answer when given
    // (with_depth): minus the penetration depth's proved enclosure, the normal and the deepest pair.
    std::optional<SignedDistance> depth;

    // The picture's verdict: within the margin when one is given, else intersects.
    bool verdict() const { return margin ? exact_within : exact_intersects; }
    // d − r: > 0 a gap between the disk and the polygon, < 0 an overlap (radial depth).
    double gap() const { return distance - radius; }
    // Along the axis: > 0 how far the box lies beyond the nearer end plane, ≤ 0 it reaches the slab.
    double axial_gap() const { return std::max(box_axial_min - half_height, -half_height - box_axial_max); }
};

namespace detail {

inline Vec3<double> normalized(const Vec3<double>& v) {
    const double n = std::sqrt(dot(v, v));
    return {v[0] / n, v[1] / n, v[2] / n};
}

// e1, e2 ⊥ u. Chosen for readability: for a near-vertical axis e1 follows +x (so the plane view of a
// vertical cylinder is the top view: x right, y up); otherwise e1 is horizontal and e2 points up-ish
// (+z), so a horizontal cylinder is seen with "up" up.
inline void plane_basis(const Vec3<double>& u, Vec3<double>& e1, Vec3<double>& e2) {
    if (std::fabs(u[2]) >= 0.9) {
        const Vec3<double> x{1, 0, 0};
        e1 = normalized(x - dot(x, u) * u);
    } else {
        e1 = normalized(cross(Vec3<double>{0, 0, 1}, u));
    }
    e2 = cross(u, e1);
}

inline Point2 nearest_on_segment(const Point2& a, const Point2& b) {
    const double vx = b.x - a.x, vy = b.y - a.y;
    const double len2 = vx * vx + vy * vy;
    if (len2 == 0) return a;
    double t = -(a.x * vx + a.y * vy) / len2;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return {a.x + t * vx, a.y + t * vy};
}

// The point of the solid convex polygon (as monotone_chain returns it) nearest to the origin. The
// arithmetic below takes differences and products of coordinates: for a polygon scaled to coordinates
// of about 1 (nearest_to_origin_scaled) none overflows or underflows.
inline Point2 nearest_to_origin_unscaled(const std::vector<Point2>& poly) {
    const std::size_t n = poly.size();
    if (n == 1) return poly[0];
    if (n >= 3) {
        bool inside = true;  // left of or on every counter-clockwise edge
        for (std::size_t i = 0; i < n && inside; ++i) {
            const Point2& a = poly[i];
            const Point2& b = poly[(i + 1) % n];
            if (a.x * (b.y - a.y) - a.y * (b.x - a.x) < 0) inside = false;
        }
        if (inside) return {0, 0};
    }
    Point2 best = nearest_on_segment(poly[0], poly[1 % n]);
    for (std::size_t i = 1; i < n; ++i) {
        const Point2 p = nearest_on_segment(poly[i], poly[(i + 1) % n]);
        if (std::hypot(p.x, p.y) < std::hypot(best.x, best.y)) best = p;
    }
    return best;
}

// The nearest point and its distance from the origin, computed on the polygon scaled by a power of two
// (exactly) so that its largest coordinate is in [0.5, 1): coordinates near the double range would
// otherwise overflow in the differences (∞ − ∞ = NaN), subnormal ones underflow in the products. The
// point is scaled back exactly; the distance is +∞ only when it exceeds the double range.
struct Nearest {
    Point2 point;
    double distance = 0;
};
inline Nearest nearest_to_origin(const std::vector<Point2>& poly) {
    double m = 0;
    for (const Point2& p : poly) m = std::max({m, std::fabs(p.x), std::fabs(p.y)});
    if (m == 0) return {{0, 0}, 0};
    const int e = std::ilogb(m) + 1;
    std::vector<Point2> scaled;
    scaled.reserve(poly.size());
    for (const Point2& p : poly) scaled.push_back({std::scalbn(p.x, -e), std::scalbn(p.y, -e)});
    const Point2 q = nearest_to_origin_unscaled(scaled);
    return {{std::scalbn(q.x, e), std::scalbn(q.y, e)}, std::scalbn(std::hypot(q.x, q.y), e)};
}

inline Case classify(const Explanation& e) {
    if (!e.drawable) return Case::not_drawable;
    if (e.exact_intersects != e.picture_intersects) return Case::touching_within_rounding;
    if (!e.exact_intersects) return e.slab_empty ? Case::outside_slab : Case::gap;
    if (e.box_axial_max == -e.half_height || e.box_axial_min == e.half_height) return Case::touching_end_plane;
    if (e.distance == 0) return Case::axis_through;
    return e.distance == e.radius ? Case::touching : Case::overlap;
}

}  // namespace detail

// The picture of (box, cyl) with the verdict given: `exact_intersects` must be the exact answer for
// these inputs (boxcyl::intersects(box, cyl)); the overload below computes it. Box: AlignedBox<double>
// or OrientedBox<double>. Inputs must satisfy validate().
template <class Box>
Explanation compute(const Box& box, const Cylinder<double>& cyl, bool exact_intersects) {
    Explanation e;
    const UnitCylinder<double> uc = to_unit(cyl);
    e.center = cyl.center;
    e.direction = uc.direction;
    e.radius = cyl.radius;
    e.half_height = uc.half_height;
    detail::plane_basis(e.direction, e.e1, e.e2);

    const algo::Parallelepiped<double> p = algo::as_parallelepiped(box);
    std::array<double, 8> t{};  // axial parameter u·(V − C) of each vertex
    for (int s = 0; s < 8; ++s) {
        Vec3<double> v = p.center;
        for (int i = 0; i < 3; ++i) v = ((s >> i) & 1) ? v + p.half_edges[i] : v - p.half_edges[i];
        e.box_vertices[s] = v;
        t[s] = dot(e.direction, Vec3<double>(v - e.center));
    }
    e.box_axial_min = e.box_axial_max = t[0];
    for (double ts : t) e.box_axial_min = std::min(e.box_axial_min, ts), e.box_axial_max = std::max(e.box_axial_max, ts);

    // box ∩ slab: the vertices inside or on the slab, and the strict crossings of the 12 edges with
    // the two end planes t = ±h/2 (one plane when h = 0), as in the convex-hull method.
    const double hh = e.half_height;
    for (int s = 0; s < 8; ++s)
        if (-hh <= t[s] && t[s] <= hh) e.section.push_back(e.box_vertices[s]);
    for (const auto& [a, b] : box_edges)
        for (int side = 0; side < (hh == 0 ? 1 : 2); ++side) {
            const double plane = side == 0 ? hh : -hh;
            const double ua = t[a] - plane, ub = t[b] - plane;
            if (!((ua < 0 && ub > 0) || (ua > 0 && ub < 0))) continue;
            const double lambda = ua / (ua - ub);
            e.section.push_back(e.box_vertices[a] + lambda * Vec3<double>(e.box_vertices[b] - e.box_vertices[a]));
        }

    auto project = [&](const Vec3<double>& x) {
        const Vec3<double> r = x - e.center;
        return Point2{dot(e.e1, r), dot(e.e2, r)};
    };
    std::vector<Point2> all, cut;
    for (const auto& v : e.box_vertices) all.push_back(project(v));
    for (const auto& v : e.section) cut.push_back(project(v));
    // Inputs near the double range can overflow here; a hull of ±Inf/NaN would be meaningless (and
    // NaN breaks the sort's ordering), so such a query gets its verdict and no picture.
    for (const auto* pts : {&all, &cut})
        for (const Point2& q : *pts)
            if (!std::isfinite(q.x) || !std::isfinite(q.y)) e.drawable = false;
    for (double ts : t)
        if (!std::isfinite(ts)) e.drawable = false;
    if (e.drawable) {
        e.box_shadow = algo::hull2d::monotone_chain(std::move(all));
        e.polygon = algo::hull2d::monotone_chain(std::move(cut));
    }

    e.slab_empty = e.drawable && e.polygon.empty();
    if (!e.polygon.empty()) {
        const detail::Nearest n = detail::nearest_to_origin(e.polygon);
        e.closest = n.point;
        e.distance = n.distance;
    }
    e.picture_intersects = e.drawable && !e.slab_empty && e.distance <= e.radius;
    e.exact_intersects = exact_intersects;
    e.what = detail::classify(e);
    return e;
}

// The clearance question on top of a picture: `exact_within` must be the exact answer of
// within_distance(box, cyl, margin) for the picture's inputs, and `margin` valid (validate_margin).
inline Explanation with_margin(Explanation e, double margin, bool exact_within) {
    e.margin = margin;
    e.exact_within = exact_within;
    return e;
}

// The nearest pair on top of a picture: `d` must be boxcyl::distance(box, cyl) for the picture's
// inputs. Kept only where the picture is drawable: a picture that shows nothing cannot mark points.
inline Explanation with_nearest(Explanation e, const Distance& d) {
    if (e.drawable) e.nearest = d;
    return e;
}

// The depth pair on top of a picture with its nearest pair: `sd` must be boxcyl::signed_distance(box,
// cyl) for the picture's inputs. Kept only where the solids overlap (sd.upper < 0): touching solids
// have no depth to show, and apart the nearest pair is the same answer.
inline Explanation with_depth(Explanation e, const SignedDistance& sd) {
    if (e.nearest && sd.upper < 0) e.depth = sd;
    return e;
}

#if defined(BOXCYL_HAS_EXACT)
// The same with the exact verdict of the default query.
template <class Box>
Explanation compute(const Box& box, const Cylinder<double>& cyl) {
    return compute(box, cyl, boxcyl::intersects(box, cyl));
}

// The picture of the clearance question: both exact answers computed (intersects, within_distance).
template <class Box>
Explanation compute_within(const Box& box, const Cylinder<double>& cyl, double margin) {
    return with_margin(compute(box, cyl), margin, boxcyl::within_distance(box, cyl, margin));
}

// The picture with the nearest pair: the exact verdict and boxcyl::distance computed, and where the
// solids overlap boxcyl::signed_distance's depth pair.
template <class Box>
Explanation compute_nearest(const Box& box, const Cylinder<double>& cyl) {
    Explanation e = compute(box, cyl);
    if (!e.drawable) return e;
    e = with_nearest(e, boxcyl::distance(box, cyl));
    return e.nearest->upper == 0 ? with_depth(e, boxcyl::signed_distance(box, cyl)) : e;
}
#endif

}  // namespace boxcyl::explain
