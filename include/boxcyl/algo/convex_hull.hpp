// The convex-hull method (docs/algorithms.md): clip the box by the two slab planes, project the clipped
// polyhedron onto the plane through C orthogonal to D, take the 2-D convex hull of the projected
// points and compare the distance from the projected centre (the origin) to that polygon with r.
// One implementation, on any parallelepiped in world coordinates (convex_hull(Parallelepiped, ...));
// the canonical-box overload (the published note's setting) calls it. Oriented boxes go through it directly,
// without the oriented-box rotation, so their answer is exact for the axes exactly as given.
//
// Generic over T (float, double, Rational, QFRational). Nothing here normalises or takes a square
// root: the projection uses two unnormalised, orthogonal vectors of equal length L (see
// projection_frame), so every projected length is L times the true one and the radius test compares
// δ²·L² with r²·L². Every decision is a sign of an expression built from + − × ÷, so for exact T (with
// an exactly unit direction, e.g. from to_unit(Cylinder<Rational>, field)) the answer is exact; for
// float/double it is rounded. Touching counts as intersecting: every boundary comparison is inclusive.
#pragma once

#include <algorithm>    // std::sort, std::unique
#include <array>        // the 8 box vertices
#include <cstddef>      // std::size_t
#include <type_traits>  // std::type_identity_t: r2 deduced from the points only
#include <utility>      // std::move
#include <vector>       // point sets and hulls

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/traits.hpp"

namespace boxcyl::algo {

// The 2-D part: points, Andrew's monotone chain, and the distance from the origin to the hull.
namespace hull2d {

template <class T>
struct Point {
    T x{};
    T y{};
};

// Orientation of (a, b, c): > 0 left turn (counter-clockwise), 0 collinear, < 0 right turn.
template <class T>
int orientation(const Point<T>& a, const Point<T>& b, const Point<T>& c) {
    const T bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    return sign_of(T(bx * cy - by * cx));
}

// Lexicographic order (x, then y), decided by exact signs of differences.
template <class T>
int compare(const Point<T>& a, const Point<T>& b) {
    const int sx = sign_of(T(a.x - b.x));
    return sx != 0 ? sx : sign_of(T(a.y - b.y));
}

// Andrew's monotone chain. Returns the hull vertices in counter-clockwise order, without duplicates
// and without collinear (non-extreme) points, starting at the lexicographically smallest point:
//   0 points for empty input, 1 for all-equal points, 2 (the extremes) for collinear points,
//   otherwise a strictly convex polygon with >= 3 vertices.
// Exactness: sorting, deduplication and the turn tests are all exact signs for exact T, so
// collinear and repeated points are classified exactly (a turn of exactly 0 is popped: it is not a
// vertex). For float/double the turn signs are rounded.
template <class T>
std::vector<Point<T>> monotone_chain(std::vector<Point<T>> p) {
    std::sort(p.begin(), p.end(), [](const Point<T>& a, const Point<T>& b) { return compare(a, b) < 0; });
    p.erase(std::unique(p.begin(), p.end(), [](const Point<T>& a, const Point<T>& b) { return compare(a, b) == 0; }),
            p.end());
    const std::size_t n = p.size();
    if (n <= 2) return p;  // a point or a segment: its own hull (chains below would double it)

    std::vector<Point<T>> h;
    h.reserve(2 * n);
    // Lower chain, left to right: keep only strict left turns.
    for (std::size_t i = 0; i < n; ++i) {
        while (h.size() >= 2 && orientation(h[h.size() - 2], h[h.size() - 1], p[i]) <= 0) h.pop_back();
        h.push_back(p[i]);
    }
    // Upper chain, right to left; it may not pop into the lower chain (size floor `lower`).
    const std::size_t lower = h.size() + 1;
    for (std::size_t i = n - 1; i-- > 0;) {
        while (h.size() >= lower && orientation(h[h.size() - 2], h[h.size() - 1], p[i]) <= 0) h.pop_back();
        h.push_back(p[i]);
    }
    h.pop_back();  // the last point repeats the first
    // All points collinear: both chains are the two extremes, so h = {first, last}.
    return h;
}

// Whether the squared distance from the origin O to the segment [a, b] is <= r2 (a == b allowed).
// Division-free: with v = b − a and λ* = −a·v/|v|² the parameter of the foot of O on the line,
//   λ* <= 0 : nearest point a,   λ* >= 1 : nearest point b,
//   else     : δ² = (a × v)²/|v|²   (Lagrange: |a|²|v|² − (a·v)² = (a × v)²),
// and the last test is (a × v)² <= r2·|v|² (|v|² > 0 there).
// (The published note's Listing 6 ComputeSqrDistance writes the foot as Q0 + s·direction with
// s = direction·Q0/|v|²; the foot is Q0 − s·direction. Not used here; the form above is derived
// independently.)
template <class T>
bool segment_within(const Point<T>& a, const Point<T>& b, const std::type_identity_t<T>& r2) {
    const T vx = b.x - a.x, vy = b.y - a.y;
    const T along = -(a.x * vx + a.y * vy);  // λ*·|v|²
    if (along <= T(0)) return a.x * a.x + a.y * a.y <= r2;
    const T len2 = vx * vx + vy * vy;
    if (along >= len2) return b.x * b.x + b.y * b.y <= r2;
    const T c = a.x * vy - a.y * vx;
    return c * c <= r2 * len2;
}

// Whether the distance from the origin to the solid convex polygon `hull` (as monotone_chain returns
// it: counter-clockwise, strictly convex, or a degenerate point/segment) is <= √r2.
template <class T>
bool origin_within(const std::vector<Point<T>>& hull, const std::type_identity_t<T>& r2) {
    const std::size_t n = hull.size();
    if (n == 0) return false;
    if (n == 1) return segment_within(hull[0], hull[0], r2);
    if (n == 2) return segment_within(hull[0], hull[1], r2);
    // Inside or on a counter-clockwise convex polygon ⇔ O is on the left of or on every edge line:
    // cross(b − a, O − a) = a × (b − a) >= 0 for every edge (a, b).
    bool inside = true;
    for (std::size_t i = 0; i < n && inside; ++i) {
        const Point<T>& a = hull[i];
        const Point<T>& b = hull[(i + 1) % n];
        if (sign_of(T(a.x * (b.y - a.y) - a.y * (b.x - a.x))) < 0) inside = false;
    }
    if (inside) return true;
    // Outside: the distance to the solid polygon is the distance to its boundary, the minimum over the
    // edges; δ² <= r2 ⇔ some edge is within r2.
    for (std::size_t i = 0; i < n; ++i)
        if (segment_within(hull[i], hull[(i + 1) % n], r2)) return true;
    return false;
}

}  // namespace hull2d

// The projection along the axis without normalisation. k is the axis with the smallest |d_k| (chosen
// by comparisons; |d_k|² <= 1/3 for a unit D, so W0 ≠ 0), and
//   W0 = D × U_k,   W1 = D × W0  (= d_k·D − U_k for |D| = 1).
// W0 ⊥ D, W1 ⊥ D, W0 ⊥ W1, and |W1| = |D|·|W0| = |W0| = L with L² = |W0|² = 1 − d_k² >= 2/3 (the sum
// of the other two squared components, exact for exact T). So (W0·Y, W1·Y) is L times the
// orthonormal-frame coordinates of the projection of Y onto the plane ⊥ D; distances scale by L.
template <class T>
struct ProjectionFrame {
    Vec3<T> w0, w1;
    T length2;  // L² = |W0|² = |W1|²
};

template <class T>
ProjectionFrame<T> projection_frame(const Vec3<T>& d) {
    auto abs = [](const T& x) { return x < T(0) ? T(-x) : x; };
    const T a0 = abs(d[0]), a1 = abs(d[1]), a2 = abs(d[2]);
    const int k = (a0 <= a1) ? (a0 <= a2 ? 0 : 2) : (a1 <= a2 ? 1 : 2);
    Vec3<T> u{T(0), T(0), T(0)};
    u[k] = T(1);
    ProjectionFrame<T> f;
    f.w0 = cross(d, u);  // components are ±d_j or 0: exact even in floating point
    f.w1 = cross(d, f.w0);
    f.length2 = dot(f.w0, f.w0);
    return f;
}

// ---------------------------------------------------------------------------------------------
// The convex-hull method on any parallelepiped, in world coordinates.
//
// Why not the canonical frame: an oriented box is the solid { K + Σ ξᵢAᵢ : |ξᵢ| ≤ eᵢ } for the axes
// exactly as given, and rounded rotations are never exactly orthonormal, so the oriented-box reduction
// to a canonical box (a rotation only for orthonormal axes) changes the solid. Nothing in this method
// needs the canonical frame: it needs the 8 vertices, the 12 edges and the slab, and those exist for any
// parallelepiped (even a degenerate one).

// The solid { center + Σ ξᵢ·half_edges[i] : |ξᵢ| ≤ 1 }. Any three vectors: linearly dependent ones and
// zero vectors (flat, segment or point boxes) are fine — the algorithm works in ξ-space (see
// convex_hull below), where the solid is always the cube [−1, 1]³.
template <class T>
struct Parallelepiped {
    Vec3<T> center;
    std::array<Vec3<T>, 3> half_edges;
};

// The box as a parallelepiped, generic over T (no conversion of number type happens here).
//   Oriented: aᵢ = eᵢ·Aᵢ, the axes exactly as given (exact for exact T; one rounding per component in
//             floating point). For the exact path build it in Rational and lift:
//               Parallelepiped<Rational> p = algo::as_parallelepiped(to_exact(box));   // aᵢ exact
//               Parallelepiped<QFRational> q{lift(p.center), {lift(p.half_edges[0]), ...}};
//             or lift the OrientedBox<Rational> to OrientedBox<QFRational> first (same numbers).
//   Aligned:  K = (min + max)/2, aᵢ = ((max − min)/2)·Uᵢ, as in the reduction (exact for exact T).
//   Canonical: K = 0, aᵢ = eᵢ·Uᵢ.
// Call these qualified (algo::as_parallelepiped): oracle.hpp declares boxcyl::as_parallelepiped for
// Rational boxes, returning OrientedBox<Rational>, which ADL would prefer for T = Rational.
template <class T>
Parallelepiped<T> as_parallelepiped(const OrientedBox<T>& b) {
    Parallelepiped<T> p;
    p.center = b.center;
    for (int i = 0; i < 3; ++i) p.half_edges[i] = b.extents[i] * b.axes[i];
    return p;
}

template <class T>
Parallelepiped<T> as_parallelepiped(const boxcyl::Parallelepiped<T>& b) {
    Parallelepiped<T> p;
    p.center = b.center;
    for (int i = 0; i < 3; ++i) p.half_edges[i] = b.extents[i] * b.axes[i];
    return p;
}

template <class T>
Parallelepiped<T> as_parallelepiped(const AlignedBox<T>& b) {
    Parallelepiped<T> p;
    for (int i = 0; i < 3; ++i) {
        p.center[i] = (b.max[i] + b.min[i]) / T(2);
        p.half_edges[i] = Vec3<T>{T(0), T(0), T(0)};
        p.half_edges[i][i] = (b.max[i] - b.min[i]) / T(2);
    }
    return p;
}

template <class T>
Parallelepiped<T> as_parallelepiped(const CanonicalBox<T>& b) {
    Parallelepiped<T> p;
    p.center = Vec3<T>{T(0), T(0), T(0)};
    for (int i = 0; i < 3; ++i) {
        p.half_edges[i] = Vec3<T>{T(0), T(0), T(0)};
        p.half_edges[i][i] = b.extents[i];
    }
    return p;
}

namespace detail::ch {  // own sub-namespace: other algo headers have detail helpers too

template <class T>
T abs_of(const T& x) {
    return x < T(0) ? T(-x) : x;
}

// The slab cull for a parallelepiped. The axial parameter of K + Σ ξᵢaᵢ is
// t = D·(K − C) + Σ ξᵢ(D·aᵢ) with |ξᵢ| ≤ 1, so the box projects to [γ − ρ, γ + ρ] with
//   γ = D·(K − C)   (= −D·C of the slab cull when K = 0: same convention),   ρ = Σ |D·aᵢ|,
// and it misses the slab [−h/2, h/2] iff |γ| > ρ + h/2 (strict: touching the slab plane is not
// outside).
template <class T>
bool outside_slab(const T& gamma, const std::array<T, 3>& da, const T& half_height) {
    const T rho = abs_of(da[0]) + abs_of(da[1]) + abs_of(da[2]);
    return abs_of(gamma) > rho + half_height;
}

}  // namespace detail::ch

// True when the parallelepiped lies strictly outside the cylinder's slab (the slab cull generalised), so
// it cannot meet the cylinder. Same frame for both; |cyl.direction| == 1.
template <class T>
bool parallelepiped_outside_slab(const Parallelepiped<T>& box, const UnitCylinder<T>& cyl) {
    const Vec3<T>& d = cyl.direction;
    const std::array<T, 3> da{dot(d, box.half_edges[0]), dot(d, box.half_edges[1]), dot(d, box.half_edges[2])};
    return detail::ch::outside_slab(T(dot(d, Vec3<T>(box.center - cyl.center))), da, cyl.half_height);
}

// The convex-hull method for any parallelepiped; box and cylinder in the same frame. Precondition:
// |cyl.direction| == 1 (exactly, for exact T); radius, half height >= 0.
//
// Why it is right for any half-edges, degenerate ones included: with ξ ∈ [−1, 1]³ the box point is the
// affine image X(ξ) = K + Σ ξᵢaᵢ, and t(ξ) = D·(X(ξ) − C) is affine in ξ. So P = {ξ in the cube, −h/2 ≤
// t(ξ) ≤ h/2} is a polytope of ξ-space whose vertices are cube vertices in the slab and strict
// crossings of cube edges with the two planes (t constant on an edge never crosses strictly); the
// projection of box ∩ slab is the image of P under a linear map, i.e. the hull of the images of
// those points. Rank of the aᵢ plays no part. Then, as for the canonical box: inside the slab the
// nearest axis point lies on the axis segment, so the cylinder meets the box iff the projected centre is
// within r of the hull.
template <class T>
bool convex_hull(const Parallelepiped<T>& box, const UnitCylinder<T>& cyl) {
    const Vec3<T>& d = cyl.direction;
    const T& hh = cyl.half_height;
    const Vec3<T> g = box.center - cyl.center;  // K − C

    // Axial parameter t(ξ) = γ + Σ ξᵢ·(D·aᵢ).
    const T gamma = dot(d, g);
    const std::array<T, 3> da{dot(d, box.half_edges[0]), dot(d, box.half_edges[1]), dot(d, box.half_edges[2])};
    // Slab cull: a box outside the slab cannot meet the cylinder; afterwards box ∩ slab is non-empty.
    if (detail::ch::outside_slab(gamma, da, hh)) return false;

    // Projection onto the plane ⊥ D in frame units (see projection_frame): linear, so the projection
    // of vertex s is that of K − C plus ± those of the aᵢ. Fewer products than projecting 8 vertices.
    const ProjectionFrame<T> frame = projection_frame(d);
    const hull2d::Point<T> qg{dot(frame.w0, g), dot(frame.w1, g)};
    std::array<hull2d::Point<T>, 3> qa;
    for (int i = 0; i < 3; ++i) qa[i] = {dot(frame.w0, box.half_edges[i]), dot(frame.w1, box.half_edges[i])};

    // Vertices V_s = K + Σ ±aᵢ (bit i of s set ⇔ +aᵢ; eq. 2 for the canonical box), their axial
    // parameters t_s = D·(V_s − C) and their projections q_s.
    std::array<T, 8> t;
    std::array<hull2d::Point<T>, 8> q;
    for (int s = 0; s < 8; ++s) {
        T ts = gamma, qx = qg.x, qy = qg.y;
        for (int i = 0; i < 3; ++i) {
            if ((s >> i) & 1) {
                ts = ts + da[i], qx = qx + qa[i].x, qy = qy + qa[i].y;
            } else {
                ts = ts - da[i], qx = qx - qa[i].x, qy = qy - qa[i].y;
            }
        }
        t[s] = ts;
        q[s] = {qx, qy};
    }

    // S = box vertices inside or on the slab, plus crossings of the 12 box edges with the slab
    // planes t = ±h/2; projected. The projection is linear, so a crossing at λ along edge (a, b)
    // projects to q_a + λ(q_b − q_a).
    std::vector<hull2d::Point<T>> pts;
    pts.reserve(32);
    for (int s = 0; s < 8; ++s)
        if (-hh <= t[s] && t[s] <= hh) pts.push_back(q[s]);
    const bool one_plane = sign_of(hh) == 0;  // h = 0: the slab is one plane; don't add crossings twice
    for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 8; ++a) {
            if ((a >> k) & 1) continue;
            const int b = a | (1 << k);  // the edge from a to b runs along +2a_k
            for (int side = 0; side < (one_plane ? 1 : 2); ++side) {
                const T plane = side == 0 ? hh : T(-hh);
                const T ua = t[a] - plane, ub = t[b] - plane;
                const int sa = sign_of(ua), sb = sign_of(ub);
                // Strict crossing only: an endpoint on the plane is a vertex already in S.
                if (!((sa < 0 && sb > 0) || (sa > 0 && sb < 0))) continue;
                // λ = ua/(ua − ub) ∈ (0, 1); ua − ub = t_a − t_b (= −2·D·a_k exactly for exact T) is
                // non-zero as ua, ub have opposite signs (also after rounding). Interpolating keeps
                // floating-point results bounded.
                const T lambda = ua / T(ua - ub);
                pts.push_back({q[a].x + lambda * T(q[b].x - q[a].x), q[a].y + lambda * T(q[b].y - q[a].y)});
            }
        }
    if (pts.empty()) return false;  // box ∩ slab empty (only reachable through rounding in float)

    // The projected centre is the origin. In frame units the radius test δ² <= r² reads
    // δ_frame² <= r²·L².
    const std::vector<hull2d::Point<T>> hull = hull2d::monotone_chain(std::move(pts));
    const T r2 = cyl.radius * cyl.radius * frame.length2;
    return hull2d::origin_within(hull, r2);
}

// The convex-hull method on the canonical box (cylinder in the box frame): the canonical box is the
// parallelepiped with K = 0, aᵢ = eᵢUᵢ, so this is the world-frame algorithm above — one implementation.
template <class T>
bool convex_hull(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl) {
    return algo::convex_hull(algo::as_parallelepiped(box), cyl);
}

}  // namespace boxcyl::algo
