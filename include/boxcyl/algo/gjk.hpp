// Approximate closest points of a box (any parallelepiped) and a cylinder, by the Gilbert–Johnson–
// Keerthi algorithm (GJK: "A fast procedure for computing the distance between complex objects in
// three-dimensional space", IEEE J. Robotics and Automation, 1988) on their support functions, in
// double. Nothing here is certified: it finds a point of the box and a direction that are nearly
// optimal, and filtered/separation.hpp proves what they show (a distance bound each way) in interval
// arithmetic. A poor or NaN result only leaves a pair undecided, so the iteration is kept simple and
// bounded instead of robust to every degenerate simplex.
#pragma once

#include <array>    // the simplex
#include <cmath>    // std::sqrt, std::abs
#include <cstddef>  // std::size_t

#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl::algo::gjk {

using V = Vec3<double>;

// The box as centre and half axes: { c + Σ μi·half[i] : |μi| ≤ 1 }.
struct Box {
    V c;
    std::array<V, 3> half;
};

// The cylinder with a unit axis u (rounded) and half height.
struct Cylinder {
    V c, u;
    double r, half_h;
};

// The result: the box point c + Σ μi·half[i] (|μi| ≤ 1), the cylinder point q, and whether the
// iteration ended with the origin inside its simplex (the solids overlap, up to rounding).
struct Closest {
    V mu;
    V q;
    bool overlap;
};

namespace detail {

inline V support_mu(const Box& b, const V& d) {
    return {dot(d, b.half[0]) >= 0 ? 1.0 : -1.0, dot(d, b.half[1]) >= 0 ? 1.0 : -1.0,
            dot(d, b.half[2]) >= 0 ? 1.0 : -1.0};
}
inline V box_point(const Box& b, const V& mu) {
    return b.c + mu[0] * b.half[0] + mu[1] * b.half[1] + mu[2] * b.half[2];
}
inline V support(const Cylinder& k, const V& d) {
    const double s = dot(d, k.u);
    const V perp = cross(k.u, cross(d, k.u));  // d's part across the axis; d − s·u cancels when d ∥ u
    const double len = std::sqrt(dot(perp, perp));
    V p = k.c + (s >= 0 ? k.half_h : -k.half_h) * k.u;
    if (len > 0) p = p + (k.r / len) * perp;
    return p;
}

// One vertex of the simplex in the Minkowski difference box − cylinder, with where it came from.
struct Vertex {
    V w, mu, q;
};

// Closest point to the origin of the simplex s[0..n): its barycentric weights replace the simplex by
// the face that holds it (Ericson, "Real-Time Collision Detection", 5.1.2 and 5.1.6, for the
// triangle's and tetrahedron's Voronoi regions). Returns false when the origin is inside a tetrahedron.
struct Reduced {
    std::array<Vertex, 4> s;
    std::array<double, 4> lambda;
    std::size_t n;
};

inline Reduced segment(const Vertex& a, const Vertex& b) {
    const V ab = b.w - a.w;
    const double den = dot(ab, ab);
    const double t = den > 0 ? -dot(a.w, ab) / den : 0;
    if (!(t > 0)) return {{a}, {1}, 1};
    if (t >= 1) return {{b}, {1}, 1};
    return {{a, b}, {1 - t, t}, 2};
}

inline Reduced triangle(const Vertex& A, const Vertex& B, const Vertex& C) {
    const V ab = B.w - A.w, ac = C.w - A.w;
    const double d1 = -dot(ab, A.w), d2 = -dot(ac, A.w);
    if (d1 <= 0 && d2 <= 0) return {{A}, {1}, 1};
    const double d3 = -dot(ab, B.w), d4 = -dot(ac, B.w);
    if (d3 >= 0 && d4 <= d3) return {{B}, {1}, 1};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {{A, B}, {1 - v, v}, 2};
    }
    const double d5 = -dot(ab, C.w), d6 = -dot(ac, C.w);
    if (d6 >= 0 && d5 <= d6) return {{C}, {1}, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {{A, C}, {1 - w, w}, 2};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {{B, C}, {1 - w, w}, 2};
    }
    const double den = 1 / (va + vb + vc);
    const double v = vb * den, w = vc * den;
    return {{A, B, C}, {1 - v - w, v, w}, 3};
}

inline V weighted(const Reduced& r, V Vertex::*field) {
    V x{0, 0, 0};
    for (std::size_t i = 0; i < r.n; ++i) x = x + r.lambda[i] * (r.s[i].*field);
    return x;
}

// The tetrahedron: the origin is inside when it lies on the inner side of all four faces; otherwise
// the closest of the faces it is outside of.
inline Reduced tetrahedron(const Vertex& A, const Vertex& B, const Vertex& C, const Vertex& D, bool& inside) {
    const std::array<std::array<const Vertex*, 4>, 4> faces{{{&A, &B, &C, &D}, {&A, &C, &D, &B},
                                                             {&A, &D, &B, &C}, {&B, &D, &C, &A}}};
    Reduced best{};
    double best_d2 = -1;
    inside = true;
    for (const auto& f : faces) {
        const V n = cross(f[1]->w - f[0]->w, f[2]->w - f[0]->w);
        const double origin_side = -dot(n, f[0]->w), opposite_side = dot(n, f[3]->w - f[0]->w);
        if (origin_side * opposite_side >= 0) continue;  // the origin is on the tetrahedron's side
        inside = false;
        const Reduced r = triangle(*f[0], *f[1], *f[2]);
        const V x = weighted(r, &Vertex::w);
        const double d2 = dot(x, x);
        if (best_d2 < 0 || d2 < best_d2) best = r, best_d2 = d2;
    }
    if (!inside) return best;
    // Barycentric weights of the origin (Cramer's rule on the edge vectors from A).
    const V b = B.w - A.w, c = C.w - A.w, d = D.w - A.w;
    const double vol = dot(b, cross(c, d));
    if (vol == 0) {  // flat: take the best face
        inside = false;
        return triangle(A, B, C);
    }
    const double x1 = dot(-A.w, cross(c, d)) / vol, x2 = dot(b, cross(-A.w, d)) / vol,
                 x3 = dot(b, cross(c, -A.w)) / vol;
    return {{A, B, C, D}, {1 - x1 - x2 - x3, x1, x2, x3}, 4};
}

}  // namespace detail

// At most `iterations` GJK steps; stops when the support point gains less than `rel_gap` of |v|² (the
// distance is then known to that relative accuracy), or the simplex stops shrinking, or the distance
// is clearly on one side of `decide_at` (≥ 0; a relative gap of 2⁻²⁰ leaves the certified bounds room
// to prove that side). The distance lies between v·w/|v| and |v| (w the support point in −v).
inline Closest closest(const Box& box, const Cylinder& cyl, double decide_at = -1, int iterations = 48,
                       double rel_gap = 0x1p-44) {
    const double below = decide_at * (1 - 0x1p-20), above = decide_at * (1 + 0x1p-20);
    using detail::Vertex;
    auto vertex = [&](const V& d) {  // the support point of box − cylinder in direction d
        const V mu = detail::support_mu(box, d);
        const V q = detail::support(cyl, -d);
        return Vertex{detail::box_point(box, mu) - q, mu, q};
    };
    detail::Reduced simplex{};
    simplex.s[0] = vertex(cyl.c - box.c);
    simplex.lambda[0] = 1;
    simplex.n = 1;
    V v = simplex.s[0].w;
    double v2 = dot(v, v);
    bool overlap = false;
    for (int it = 0; it < iterations && v2 > 0; ++it) {
        const Vertex w = vertex(-v);
        const double vw = dot(v, w.w);
        if (v2 - vw <= rel_gap * v2) break;  // v·w/|v| bounds the distance from below: converged
        if (decide_at >= 0 && (v2 <= below * below || (vw > 0 && vw * vw >= v2 * (above * above)))) break;
        detail::Reduced next;
        switch (simplex.n) {
            case 1: next = detail::segment(simplex.s[0], w); break;
            case 2: next = detail::triangle(simplex.s[0], simplex.s[1], w); break;
            default: {
                bool inside = false;
                next = detail::tetrahedron(simplex.s[0], simplex.s[1], simplex.s[2], w, inside);
                if (inside) {
                    simplex = next;
                    overlap = true;
                }
            }
        }
        if (overlap) break;
        const V nv = detail::weighted(next, &Vertex::w);
        const double nv2 = dot(nv, nv);
        if (!(nv2 < v2)) break;  // no progress (rounding, or a NaN): keep the last simplex
        simplex = next;
        v = nv;
        v2 = nv2;
    }
    Closest out{detail::weighted(simplex, &Vertex::mu), detail::weighted(simplex, &Vertex::q), overlap || v2 == 0};
    for (int i = 0; i < 3; ++i) out.mu[i] = out.mu[i] > 1 ? 1 : out.mu[i] < -1 ? -1 : out.mu[i];
    return out;
}

}  // namespace boxcyl::algo::gjk
