// Certificates for the clearance query's rim tori in interval arithmetic (boxcyl/clearance.hpp): the
// same three tests as the exact decision (exact/clearance.hpp: a box vertex within m of a rim circle;
// every edge and every facet farther than m from both rim circles), evaluated on outward-rounded
// intervals, so that each answers only when the enclosures prove it; otherwise the exact decision does.
//
//   yes  some vertex V has (ρ − r)² + a² ≤ m² for a rim circle (ρ its distance from the axis, a its
//        height over the rim plane): V is within m of that circle, a subset of the cylinder. Sound alone.
//        The same for points along the edges, tried while their bounds are refined (below).
//   no   the box misses fat and tall (the caller proves it) and, for both rim circles Γ, every edge is
//        proved farther than m from Γ and every facet's candidate contact (the rim points critical for
//        its plane distance) is proved farther than m from the facet's plane or its foot outside the
//        facet, or the facet's whole plane farther than m from Γ. By the exact decision's completeness
//        argument the box is then not within m.
// An edge's lower bound: dist(X, Γ)² = (ρ − r)² + a² and the minimum of a sum is at least the sum of
// the minima; a is linear along the edge and ρ convex (the distance to a line), so a's extremes are at
// the ends, ρ's maximum too, and ρ's minimum is that of the quadratic ρ² (at its vertex or an end).
#pragma once

#include <algorithm>  // std::min, std::max
#include <array>      // vertices, edges
#include <cmath>      // std::ilogb, std::isfinite
#include <optional>   // undecided

#include "boxcyl/filtered/prepared.hpp"  // times_two_to
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/interval.hpp"

namespace boxcyl::filtered::rim {

using I = Interval;
using V = Vec3<Interval>;

inline V lift(const Vec3<double>& v) { return {I(v[0]), I(v[1]), I(v[2])}; }

// A NaN bound (after an overflow) proves nothing; the clamps below (std::max) would hide it.
inline bool is_nan(const I& x) { return x.lo() != x.lo() || x.hi() != x.hi(); }

// The box as intervals: centre and half axes eᵢ·Aᵢ.
struct Box {
    V center;
    std::array<V, 3> half;
};

// D scaled by a power of two, exactly, to a largest component in [1, 2) where that is exact (always
// for short axes: scaling up is exact short of overflow), so that |D|² neither underflows nor
// overflows; otherwise D itself. The direction, all that counts, is unchanged.
inline Vec3<double> scaled_axis(const Vec3<double>& D) {
    const double big = std::max({std::abs(D[0]), std::abs(D[1]), std::abs(D[2])});
    if (!(big > 0) || !std::isfinite(big)) return D;
    const int k = -std::ilogb(big);
    Vec3<double> s;
    for (int i = 0; i < 3; ++i) {
        s[i] = times_two_to(D[i], k);  // bit steps, not libm's ldexp (a tenth of a rim-region query)
        if (times_two_to(s[i], -k) != D[i]) return D;  // a component would lose bits
    }
    return s;
}

// Component i of u = d/|d| enclosed, d the axis as scaled_axis returns it and len enclosing |d|. d's
// largest component is at least 1 (scaled to [1, 2), or left as given, which happens only to a largest
// one of 2 or more, whose scaling down would lose a tiny component's bits), so |u_i| ≤ |d_i|. A component below 2^-900 (beside one of at
// least 1) is enclosed by [0, 2^-900] with its sign instead of the quotient: the wider enclosure is as
// sound, costs every bound that uses it an error of at most 2^-900 of the lengths it multiplies (far
// below their roundings), and keeps the products with it out of the subnormal range, which x86 runs in
// microcode (an axis like (1e-300, 0.6, 0.8), or a subnormal one: the distance bounds took twice as
// long on such axes).
inline Interval unit_component(const Vec3<double>& d, int i, const Interval& len) {
    constexpr double tiny = 0x1p-900;
    if (d[i] == 0 || std::abs(d[i]) >= tiny) return Interval(d[i]) / len;
    return d[i] > 0 ? Interval(0, tiny) : Interval(-tiny, 0);
}

// The cylinder and margin in intervals: u = D/|D| enclosed. `valid` is false when the enclosure is not
// finite (then nothing is proved with it).
struct Rims {
    Rims(const Cylinder<double>& c, double m) : C(lift(c.center)), r(c.radius), half_h(I(c.height) * I(0.5)), m2(I(m) * I(m)) {
        const Vec3<double> d = scaled_axis(c.axis);
        const V D = lift(d);
        const I len = sqrt(dot(D, D));
        for (int i = 0; i < 3; ++i) u[i] = unit_component(d, i, len);
        for (int i = 0; i < 3; ++i) valid = valid && std::isfinite(u[i].lo()) && std::isfinite(u[i].hi());
    }
    V C, u;
    I r, half_h, m2;
    bool valid = true;
};

// Lower bound of x² over x in [lo(x0, x1) .. ] for x linear between x0 and x1 (its extremes at the ends).
inline double min_square_linear(const I& x0, const I& x1) {
    if (x0.lo() > 0 && x1.lo() > 0) {
        const double v = std::min(x0.lo(), x1.lo());
        return (I(v) * I(v)).lo();
    }
    if (x0.hi() < 0 && x1.hi() < 0) {
        const double v = std::min(-x0.hi(), -x1.hi());
        return (I(v) * I(v)).lo();
    }
    return 0;
}

// dist(V, Γ_eps)² − m² enclosed, Γ_eps the rim circle at centre + eps·(h/2)·u.
inline I vertex_excess(const Rims& f, const V& X, int eps) {
    const V Z = X - f.C;
    const I t = dot(Z, f.u);
    const I rho2 = dot(Z, Z) - t * t;
    if (is_nan(rho2)) return rho2;
    const I rho = sqrt(I(std::max(0.0, rho2.lo()), std::max(0.0, rho2.hi())));
    const I a = t - I(eps) * f.half_h;
    const I d = rho - f.r;
    return d * d + a * a - f.m2;
}

// A lower bound of the squared distance from the edge X0 + s·E (0 ≤ s ≤ 1) to Γ_eps.
inline double edge_lower_bound(const Rims& f, const V& X0, const V& E, int eps) {
    const V Z0 = X0 - f.C;
    const V Z1 = Z0 + E;
    const I t0 = dot(Z0, f.u), t1 = dot(Z1, f.u);
    const double min_a2 = min_square_linear(t0 - I(eps) * f.half_h, t1 - I(eps) * f.half_h);
    // ρ² = A s² + B s + C0 along the edge.
    const I tE = dot(E, f.u);
    const I A = dot(E, E) - tE * tE;
    const I B = I(2) * (dot(Z0, E) - t0 * tE);
    const I C0 = dot(Z0, Z0) - t0 * t0;
    const I q1 = A + B + C0;
    if (is_nan(t0) || is_nan(t1) || is_nan(A) || is_nan(B) || is_nan(C0) || is_nan(q1)) return 0;  // nothing proved
    double min_q = std::min(C0.lo(), q1.lo());
    if (A.lo() > 0) {
        const I s = -B / (I(2) * A);
        if (!(s.hi() < 0 || s.lo() > 1)) {
            const double vertex = (C0 - B * B / (I(4) * A)).lo();
            if (vertex != vertex) return 0;  // NaN: nothing proved
            min_q = std::min(min_q, vertex);
        }
    } else {
        min_q = std::min(min_q, 0.0);  // A may vanish: no vertex bound; ρ ≥ 0 still
    }
    const double rho_min = sqrt(I(std::max(0.0, min_q))).lo();
    const double rho_max = std::max(sqrt(I(std::max(0.0, C0.lo()), std::max(0.0, C0.hi()))).hi(),
                                    sqrt(I(std::max(0.0, q1.lo()), std::max(0.0, q1.hi()))).hi());
    double min_d2 = 0;
    if (rho_min > f.r.hi()) min_d2 = ((I(rho_min) - f.r) * (I(rho_min) - f.r)).lo();
    else if (rho_max < f.r.lo()) min_d2 = ((f.r - I(rho_max)) * (f.r - I(rho_max))).lo();
    return (I(min_a2) + I(min_d2)).lo();
}

enum class Edge { far, near, unknown };

// Whether the edge X0 + s·E (0 ≤ s ≤ 1) is proved farther than m from Γ_eps (far), has a point proved
// within m (near), or neither: the lower bound above, on halves of the edge down to `depth` levels
// (the bound of a sum by its parts' minima tightens as the pieces shorten), each split point tried as
// a near point.
inline Edge edge_far(const Rims& f, const V& X0, const V& E, int eps, int depth) {
    if (edge_lower_bound(f, X0, E, eps) > f.m2.hi()) return Edge::far;
    if (depth == 0) return Edge::unknown;
    const V half{E[0] * I(0.5), E[1] * I(0.5), E[2] * I(0.5)};
    const V mid = X0 + half;
    if (vertex_excess(f, mid, eps).hi() <= 0) return Edge::near;
    const Edge a = edge_far(f, X0, half, eps, depth - 1);
    if (a != Edge::far) return a;
    return edge_far(f, mid, half, eps, depth - 1);
}

// Whether the facet { X_F + μj·Aj + μk·Ak : |μ| ≤ 1 } (half axes Aj, Ak) is proved to have no contact
// within m with Γ_eps: both critical rim points are farther than m from its plane, or have their foot
// outside it.
inline bool facet_far(const Rims& f, const V& XF, const V& Aj, const V& Ak, int eps) {
    const V n = cross(Aj, Ak);
    const I nn = dot(n, n);
    const I nu = dot(n, f.u);
    const V nperp = n - V{nu * f.u[0], nu * f.u[1], nu * f.u[2]};
    const I np2 = dot(nperp, nperp);
    if (!(nn.lo() > 0) || is_nan(np2)) return false;  // nothing proved (a degenerate facet, or NaN)
    const V c = f.C + V{I(eps) * f.half_h * f.u[0], I(eps) * f.half_h * f.u[1], I(eps) * f.half_h * f.u[2]};
    // The whole plane far from Γ: |n·(P − X_F)| ≥ |n·(c − X_F)| − r·|n⊥| for every P on Γ.
    const double gap = enclosure_abs(dot(n, c - XF)).lo() - (f.r * sqrt(I(0.0, std::max(0.0, np2.hi())))).hi();
    if (gap > 0 && (I(gap) * I(gap)).lo() > (f.m2 * nn).hi()) return true;
    if (!(np2.lo() > 0)) return false;  // the critical points are not enclosed
    const I np = sqrt(np2);
    const std::array<V, 2> lambda{cross(Ak, n), cross(n, Aj)};  // λ·(X − X_F) = μ·|n|²
    for (int tau : {1, -1}) {
        const I k = I(tau) * f.r / np;
        const V P = c + V{k * nperp[0], k * nperp[1], k * nperp[2]};
        const V PX = P - XF;
        const I L = dot(n, PX);  // plane distance · |n|
        if ((L * L).lo() > (f.m2 * nn).hi()) continue;
        bool outside = false;
        for (const V& l : lambda) {
            const I mu = dot(l, PX);
            if (mu.lo() > nn.hi() || mu.hi() < -nn.hi()) outside = true;
        }
        if (!outside) return false;
    }
    return true;
}

// true: within m (a vertex in a rim torus); false: not within m, given that the box misses the exact
// fat and tall cylinders; nullopt: the enclosures prove neither.
// The box kinds as enclosures (interval arithmetic's inclusion property makes every bound below hold
// for the exact box inside).
inline Box enclose(const Parallelepiped<double>& b) {
    Box box{lift(b.center), {}};
    for (int i = 0; i < 3; ++i) {
        const V a = lift(b.axes[i]);
        const I e(b.extents[i]);
        box.half[i] = {e * a[0], e * a[1], e * a[2]};
    }
    return box;
}
inline Box enclose(const OrientedBox<double>& b) { return enclose(Parallelepiped<double>{b.center, b.axes, b.extents}); }
inline Box enclose(const CanonicalBox<double>& b) {
    return enclose(Parallelepiped<double>{{0, 0, 0}, {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}, b.extents});
}
inline Box enclose(const AlignedBox<double>& b) {
    Box box;
    for (int i = 0; i < 3; ++i) {
        box.center[i] = (I(b.min[i]) + I(b.max[i])) * I(0.5);
        box.half[i] = {I(0), I(0), I(0)};
        box.half[i][i] = (I(b.max[i]) - I(b.min[i])) * I(0.5);
    }
    return box;
}

// What the enclosures proved, per edge and facet (indexed as exact::clearance::Known), for the exact
// decision to skip.
struct Proved {
    std::array<bool, 24> edge_far{};
    std::array<bool, 6> facet_far{};
};

template <class AnyBox>
std::optional<bool> decide(const AnyBox& b, const Cylinder<double>& c, double m, Proved* proved = nullptr) {
    const Rims f(c, m);
    Proved local;
    Proved& p = proved ? *proved : local;
    if (!f.valid) return std::nullopt;  // nothing proved
    const Box box = enclose(b);
    std::array<V, 8> vertex;
    for (int bits = 0; bits < 8; ++bits) {
        V v = box.center;
        for (int i = 0; i < 3; ++i) v = (bits >> i & 1) ? V(v + box.half[i]) : V(v - box.half[i]);
        vertex[static_cast<std::size_t>(bits)] = v;
    }
    bool far = true;
    for (const V& v : vertex)
        for (int eps : {1, -1}) {
            const I x = vertex_excess(f, v, eps);
            if (x.hi() <= 0) return true;
            far = far && x.lo() > 0;
        }
    // Every edge and facet is tried (a later one may still be proved near, and what is proved far
    // spares the exact decision); the answer is "no" only when all are far.
    bool all_far = far;
    for (int i = 0; i < 3; ++i) {
        const V E = box.half[i] + box.half[i];
        for (int bits = 0; bits < 8; ++bits) {
            if (bits >> i & 1) continue;
            bool edge_far_both = true;
            for (int eps : {1, -1}) {
                const Edge e = edge_far(f, vertex[static_cast<std::size_t>(bits)], E, eps, 12);
                if (e == Edge::near) return true;
                edge_far_both = edge_far_both && e == Edge::far;
            }
            p.edge_far[8 * static_cast<std::size_t>(i) + static_cast<std::size_t>(bits)] = edge_far_both;
            all_far = all_far && edge_far_both;
        }
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        for (int sigma : {1, -1}) {
            const V XF = sigma > 0 ? V(box.center + box.half[i]) : V(box.center - box.half[i]);
            const bool facet = facet_far(f, XF, box.half[j], box.half[k], 1) && facet_far(f, XF, box.half[j], box.half[k], -1);
            p.facet_far[2 * static_cast<std::size_t>(i) + (sigma > 0 ? 1U : 0U)] = facet;
            all_far = all_far && facet;
        }
    }
    if (!all_far) return std::nullopt;
    return false;
}

}  // namespace boxcyl::filtered::rim
