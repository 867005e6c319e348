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

// Closest point to the origin of a simplex of the vertices s[·]: the barycentric weights of the face
// that holds it, by the vertices' indices into s (Ericson, "Real-Time Collision Detection", 5.1.2 and
// 5.1.6, for the triangle's and tetrahedron's Voronoi regions). Indices, not copies: the vertices are
// 72 bytes each, and the iteration reduces its simplex every step.
struct Reduced {
    std::array<std::size_t, 4> at;
    std::array<double, 4> lambda;
    std::size_t n;
};

inline Reduced segment(const Vertex* s, std::size_t a, std::size_t b) {
    const V ab = s[b].w - s[a].w;
    const double den = dot(ab, ab);
    const double t = den > 0 ? -dot(s[a].w, ab) / den : 0;
    if (!(t > 0)) return {{a}, {1}, 1};
    if (t >= 1) return {{b}, {1}, 1};
    return {{a, b}, {1 - t, t}, 2};
}

inline Reduced triangle(const Vertex* s, std::size_t a, std::size_t b, std::size_t c) {
    const V& A = s[a].w;
    const V& B = s[b].w;
    const V& C = s[c].w;
    const V ab = B - A, ac = C - A;
    const double d1 = -dot(ab, A), d2 = -dot(ac, A);
    if (d1 <= 0 && d2 <= 0) return {{a}, {1}, 1};
    const double d3 = -dot(ab, B), d4 = -dot(ac, B);
    if (d3 >= 0 && d4 <= d3) return {{b}, {1}, 1};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {{a, b}, {1 - v, v}, 2};
    }
    const double d5 = -dot(ab, C), d6 = -dot(ac, C);
    if (d6 >= 0 && d5 <= d6) return {{c}, {1}, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {{a, c}, {1 - w, w}, 2};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {{b, c}, {1 - w, w}, 2};
    }
    const double den = 1 / (va + vb + vc);
    const double v = vb * den, w = vc * den;
    return {{a, b, c}, {1 - v - w, v, w}, 3};
}

inline V weighted(const Vertex* s, const Reduced& r, V Vertex::*field) {
    V x{0, 0, 0};
    for (std::size_t i = 0; i < r.n; ++i) x = x + r.lambda[i] * (s[r.at[i]].*field);
    return x;
}

// The tetrahedron s[0..4): the origin is inside when it lies on the inner side of all four faces;
// otherwise the closest of the faces it is outside of.
inline Reduced tetrahedron(const Vertex* s, bool& inside) {
    static constexpr std::array<std::array<std::size_t, 4>, 4> faces{{{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}}};
    Reduced best{};
    double best_d2 = -1;
    inside = true;
    for (const auto& f : faces) {
        const V n = cross(s[f[1]].w - s[f[0]].w, s[f[2]].w - s[f[0]].w);
        const double origin_side = -dot(n, s[f[0]].w), opposite_side = dot(n, s[f[3]].w - s[f[0]].w);
        if (origin_side * opposite_side >= 0) continue;  // the origin is on the tetrahedron's side
        inside = false;
        const Reduced r = triangle(s, f[0], f[1], f[2]);
        const V x = weighted(s, r, &Vertex::w);
        const double d2 = dot(x, x);
        if (best_d2 < 0 || d2 < best_d2) best = r, best_d2 = d2;
    }
    if (!inside) return best;
    // Barycentric weights of the origin (Cramer's rule on the edge vectors from A).
    const V& A = s[0].w;
    const V b = s[1].w - A, c = s[2].w - A, d = s[3].w - A;
    const double vol = dot(b, cross(c, d));
    if (vol == 0) {  // flat: take the best face
        inside = false;
        return triangle(s, 0, 1, 2);
    }
    const double x1 = dot(-A, cross(c, d)) / vol, x2 = dot(b, cross(-A, d)) / vol, x3 = dot(b, cross(c, -A)) / vol;
    return {{0, 1, 2, 3}, {1 - x1 - x2 - x3, x1, x2, x3}, 4};
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
    // The simplex is s[0..n) with weights lambda; a new support point goes to s[n], and the reduced
    // simplex is gathered back to the front.
    std::array<Vertex, 4> s;
    std::array<double, 4> lambda{1, 0, 0, 0};
    std::size_t n = 1;
    s[0] = vertex(cyl.c - box.c);
    V v = s[0].w;
    double v2 = dot(v, v);
    bool overlap = false;
    for (int it = 0; it < iterations && v2 > 0; ++it) {
        const Vertex w = vertex(-v);
        const double vw = dot(v, w.w);
        if (v2 - vw <= rel_gap * v2) break;  // v·w/|v| bounds the distance from below: converged
        if (decide_at >= 0 && (v2 <= below * below || (vw > 0 && vw * vw >= v2 * (above * above)))) break;
        s[n] = w;
        detail::Reduced next;
        switch (n) {
            case 1: next = detail::segment(s.data(), 0, 1); break;
            case 2: next = detail::triangle(s.data(), 0, 1, 2); break;
            default: {
                bool inside = false;
                next = detail::tetrahedron(s.data(), inside);
                overlap = inside;
            }
        }
        const V nv = detail::weighted(s.data(), next, &Vertex::w);
        const double nv2 = dot(nv, nv);
        if (!overlap && !(nv2 < v2)) break;  // no progress (rounding, or a NaN): keep the last simplex
        const std::array<Vertex, 4> kept = s;  // a tetrahedron's face may list its vertices out of order
        for (std::size_t i = 0; i < next.n; ++i) s[i] = kept[next.at[i]];
        lambda = next.lambda;
        n = next.n;
        if (overlap) break;
        v = nv;
        v2 = nv2;
    }
    const detail::Reduced last{{0, 1, 2, 3}, lambda, n};
    Closest out{detail::weighted(s.data(), last, &Vertex::mu), detail::weighted(s.data(), last, &Vertex::q), overlap || v2 == 0};
    for (int i = 0; i < 3; ++i) out.mu[i] = out.mu[i] > 1 ? 1 : out.mu[i] < -1 ? -1 : out.mu[i];
    return out;
}

}  // namespace boxcyl::algo::gjk
