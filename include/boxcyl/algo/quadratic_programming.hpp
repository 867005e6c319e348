// The LCP method (docs/algorithms.md): the box–cylinder test as the convex QP
//     minimise f(x) = ½ xᵀA x + bᵀx   subject to  x ≥ 0,  D x ≥ e,
// solved through its KKT linear complementarity problem (the published note's eq. (8)) by Lemke's method
// (lcp_solver.hpp). Generic over T; exact for exact T whose cylinder direction is exactly unit
// (QFRational from exact/reduce.hpp's to_unit, or Rational for rational unit directions).
//
// Beyond the published note (each exact, so exact answers are those of the published method; each for
// floating point's sake):
// the axis-segment pre-step, fixed coordinates for zero extents, the plane parametrisation for h = 0,
// and d² evaluated without cancellation. See quadratic_programming() below.
#pragma once

#include <array>      // LCP data
#include <cassert>    // the unit-direction precondition, in debug builds
#include <cstddef>    // std::size_t
#include <optional>   // std::nullopt when the floating-point solver fails
#include <stdexcept>  // std::logic_error: an exact solve can only fail by a bug

#include "boxcyl/algo/axis_segment.hpp"
#include "boxcyl/algo/lcp_solver.hpp"
#include "boxcyl/algo/slab_cull.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/traits.hpp"

namespace boxcyl::algo {

// A convex QP of the LCP method's kind in m variables y ≥ 0: the point x = p0 + Σ y_r·P[r] (in the frame
// where the box is 0 ≤ x ≤ 2ℓ and the cylinder centre is k = c + ℓ) and
//     minimise ½(x − k)ᵀA(x − k)   subject to   G y ≥ g   (R rows),
// with A = I − wwᵀ, or A = I when every feasible x has x − k ⊥ w (then the two agree exactly).
// The published problem is P = the unit vectors, p0 = 0, G = the box and slab rows (spec_qp below).
template <class T, std::size_t m, std::size_t R>
struct ReducedQp {
    Vec3<T> k;
    Vec3<T> p0;
    std::array<Vec3<T>, m> P;
    std::array<std::array<T, m>, R> G;
    std::array<T, R> g;
    bool in_plane = false;  // use A = I
};

// The LCP of a ReducedQp: z = (y, multipliers of the G rows). For the published problem this is its
// 8×8 LCP. Exposed for tests.
template <class T, std::size_t N>
struct QpLcp {
    std::array<T, N> q;
    LcpMatrix<T, N> M;
};

template <class T, std::size_t m, std::size_t R>
QpLcp<T, m + R> make_lcp(const ReducedQp<T, m, R>& qp, const Vec3<T>& w) {
    // f(y) = ½(Py + p0 − k)ᵀA(Py + p0 − k) = ½yᵀ(PᵀAP)y + (PᵀA(p0 − k))ᵀy + const.
    // The note's eq. (11)–(12) (P = I, p0 = 0): b = −A k. Its eq. (12) states b = (I − wwᵀ)k, the wrong sign
    // (it would minimise the distance to the reflected centre −k); derivation: expand the quadratic
    // form, as here. PᵀAP and PᵀA(p0 − k) are formed through A v = v − (w·v)w.
    auto apply_A = [&](const Vec3<T>& v) { return qp.in_plane ? v : Vec3<T>(v - dot(w, v) * w); };
    std::array<Vec3<T>, m> AP;
    for (std::size_t r = 0; r < m; ++r) AP[r] = apply_A(qp.P[r]);
    const Vec3<T> Ad0 = apply_A(qp.p0 - qp.k);

    // The note's eq. (8): q = [b; −g], M = [[PᵀAP, −Gᵀ], [G, 0]] from the KKT conditions of the QP with
    // multipliers μ ≥ 0 for G y ≥ g: u = PᵀAP y + b − Gᵀμ ≥ 0 ⊥ y ≥ 0 and v = G y − g ≥ 0 ⊥ μ ≥ 0.
    // M is positive semidefinite (zᵀMz = (Py)ᵀA(Py) ≥ 0), hence copositive-plus.
    QpLcp<T, m + R> p;
    for (auto& row : p.M)
        for (auto& x : row) x = T(0);
    for (std::size_t r = 0; r < m; ++r) {
        p.q[r] = dot(qp.P[r], Ad0);
        for (std::size_t s = 0; s < m; ++s) p.M[r][s] = dot(qp.P[r], AP[s]);
        for (std::size_t t = 0; t < R; ++t) {
            p.M[r][m + t] = -qp.G[t][r];
            p.M[m + t][r] = qp.G[t][r];
        }
    }
    for (std::size_t t = 0; t < R; ++t) p.q[m + t] = -qp.g[t];
    return p;
}

// The LCP method's QP over the box coordinates listed in `axis` (n = 3: the published problem; a
// coordinate left out is fixed at xᵢ = 0, exact when ℓᵢ = 0). The note's eq. (9), checked: the
// constraints D x ≥ e are
//     −xᵢ ≥ −2ℓᵢ           (box: xᵢ ≤ 2ℓᵢ; xᵢ ≥ 0 is the QP's own x ≥ 0)
//     w·x ≥ w·k − h/2      (slab, lower plane:  w·(x − k) ≥ −h/2)
//    −w·x ≥ −w·k − h/2     (slab, upper plane:  w·(x − k) ≤ +h/2)
// which is exactly the note's D and e (rows and signs agree).
template <std::size_t n, class T>
ReducedQp<T, n, n + 2> spec_qp(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl,
                               const std::array<std::size_t, n>& axis) {
    const Vec3<T>& l = box.extents;
    const Vec3<T>& w = cyl.direction;
    ReducedQp<T, n, n + 2> qp;
    // Shift the box to 0 ≤ x ≤ 2ℓ (x = ξ + ℓ), and the cylinder centre with it: k = c + ℓ.
    qp.k = cyl.center + l;
    qp.p0 = Vec3<T>{T(0), T(0), T(0)};
    const T wk = dot(w, qp.k);
    for (std::size_t r = 0; r < n; ++r) {
        const std::size_t i = axis[r];
        qp.P[r] = Vec3<T>{T(0), T(0), T(0)};
        qp.P[r][i] = T(1);
        for (std::size_t s = 0; s < n; ++s) qp.G[r][s] = T(r == s ? -1 : 0);
        qp.g[r] = -(l[i] + l[i]);
        qp.G[n][r] = w[i];
        qp.G[n + 1][r] = -w[i];
    }
    qp.g[n] = wk - cyl.half_height;
    qp.g[n + 1] = -wk - cyl.half_height;
    return qp;
}

// h = 0: the slab is the plane w·(x − k) = 0. Solved for the free coordinate j (|w_j| largest among
// the free ones, so |β| ≤ 1 below): x_j = α − Σ β_i x_i with α = w·k / w_j, β_i = w_i / w_j, the
// other free coordinates are the variables, and 0 ≤ x_j ≤ 2ℓ_j become two rows. In the plane x − k ⊥ w,
// so A acts as I and the objective ½|x − k|² has matrix PᵀP = I + ββᵀ (positive definite).
// `axis` lists the free coordinates other than j.
template <std::size_t m, class T>
ReducedQp<T, m, m + 2> plane_qp(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl,
                                const std::array<std::size_t, m>& axis, std::size_t j) {
    const Vec3<T>& l = box.extents;
    const Vec3<T>& w = cyl.direction;
    ReducedQp<T, m, m + 2> qp;
    qp.in_plane = true;
    qp.k = cyl.center + l;
    const T alpha = dot(w, qp.k) / w[j];
    qp.p0 = Vec3<T>{T(0), T(0), T(0)};
    qp.p0[j] = alpha;
    for (std::size_t r = 0; r < m; ++r) {
        const std::size_t i = axis[r];
        const T beta = w[i] / w[j];
        qp.P[r] = Vec3<T>{T(0), T(0), T(0)};
        qp.P[r][i] = T(1);
        qp.P[r][j] = -beta;
        for (std::size_t s = 0; s < m; ++s) qp.G[r][s] = T(r == s ? -1 : 0);
        qp.g[r] = -(l[i] + l[i]);
        qp.G[m][r] = -beta;      // x_j ≥ 0:      −β·y ≥ −α
        qp.G[m + 1][r] = beta;   // x_j ≤ 2ℓ_j:    β·y ≥ α − 2ℓ_j
    }
    qp.g[m] = -alpha;
    qp.g[m + 1] = alpha - (l[j] + l[j]);
    return qp;
}

// The published 8×8 LCP (the note's eq. (8)) for all three box coordinates. Exposed for tests.
template <class T>
QpLcp<T, 8> make_qp_lcp(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl) {
    return make_lcp(spec_qp<3>(box, cyl, std::array<std::size_t, 3>{0, 1, 2}), cyl.direction);
}

namespace detail {

template <class T, std::size_t m, std::size_t R>
std::optional<bool> solve_qp(const ReducedQp<T, m, R>& qp, const UnitCylinder<T>& cyl) {
    std::array<T, m + R> z{};
    if constexpr (m + R > 0) {
        const QpLcp<T, m + R> p = make_lcp(qp, cyl.direction);
        const auto sol = solve_lcp(p.q, p.M);
        if (sol.status != LcpStatus::solved) {
            if constexpr (is_exact_v<T>) {
                throw std::logic_error("boxcyl::algo::quadratic_programming: exact LCP not solved (bug)");
            } else {
                return std::nullopt;
            }
        }
        z = sol.z;
    }
    // d² = (x − k)ᵀA(x − k) at the minimiser x = p0 + Σ y_r P[r]. Evaluated as |p|² with
    // p = δ − (w·δ)w the component of δ = x − k perpendicular to the axis: equal to |δ|² − (w·δ)²
    // when |w| = 1 (exactly so for exact T), but without that form's cancellation, which in floating
    // point loses d² entirely (error ~ ε|δ|²) whenever the box lies far along the axis from the centre.
    Vec3<T> x = qp.p0;
    for (std::size_t r = 0; r < m; ++r) x = x + z[r] * qp.P[r];
    const Vec3<T> delta = x - qp.k;
    const Vec3<T> perp = delta - dot(cyl.direction, delta) * cyl.direction;
    return dot(perp, perp) <= cyl.radius * cyl.radius;
}

template <std::size_t n, class T>
std::optional<bool> solve_over(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl,
                               const std::array<std::size_t, n>& axis) {
    if (!(cyl.half_height == T(0))) return solve_qp(spec_qp<n>(box, cyl, axis), cyl);
    // h = 0: pick the free coordinate with the largest |w_j| to solve the plane equation for.
    const Vec3<T>& w = cyl.direction;
    auto abs = [](const T& v) { return v < T(0) ? T(-v) : v; };
    std::size_t best = n;
    for (std::size_t r = 0; r < n; ++r)
        if (!(w[axis[r]] == T(0)) && (best == n || abs(w[axis[r]]) > abs(w[axis[best]]))) best = r;
    if (best == n) {
        // The plane does not involve the free coordinates: w·(x − k) is the same for the whole box,
        // and the slab cull has found it to be 0. Only the box rows remain.
        ReducedQp<T, n, n + 2> spec = spec_qp<n>(box, cyl, axis);
        ReducedQp<T, n, n> qp;
        qp.k = spec.k;
        qp.p0 = spec.p0;
        qp.P = spec.P;
        for (std::size_t r = 0; r < n; ++r) {
            qp.G[r] = spec.G[r];
            qp.g[r] = spec.g[r];
        }
        return solve_qp(qp, cyl);
    }
    if constexpr (n > 0) {
        std::array<std::size_t, n - 1> others{};
        for (std::size_t r = 0, s = 0; r < n; ++r)
            if (r != best) others[s++] = axis[r];
        return solve_qp(plane_qp<n - 1>(box, cyl, others, axis[best]), cyl);
    }
    return std::nullopt;  // unreachable: best < n needs n > 0
}

}  // namespace detail

// True iff the closed box and the closed cylinder intersect. std::nullopt only when the
// floating-point LCP solve fails (rounding broke a tie the wrong way and the path ended on a ray);
// for exact T it always answers. Precondition: cyl.direction is unit length (exactly, for exact T).
//
// Floating point (as the published note warns, pivoting is not robust there): the answers that are returned
// are right unless the case is near touching (tests/test_quadratic_programming.cpp measures it); the
// remaining solver failures come from near-degeneracy that rounding perturbs — boxes thin relative
// to the precision, tiny direction components — where a near-tie in the ratio test is broken the
// wrong way and Lemke's path ends on a spurious ray. No tolerance is used to hide that: a failure is
// reported (std::nullopt) and the caller decides exactly.
template <class T>
std::optional<bool> quadratic_programming(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl) {
    if constexpr (is_exact_v<T>) {
        assert(dot(cyl.direction, cyl.direction) == T(1) && "quadratic_programming: direction must be exactly unit");
    }
    // Slab cull: outside the slab there is nothing to test, and inside it the QP below is feasible.
    if (box_outside_slab(box, cyl)) return false;

    // Pre-step, not in the published method: if the axis segment meets the box, the minimum below is
    // d² = 0 and the answer is true for every r ≥ 0. This is the same exact test as the
    // linear-inequalities method's axis early exits (axis_segment.hpp), so exact results do not change. It
    // matters in rounded arithmetic: there the LCP's minimiser and d² carry rounding, so a minimum that is
    // exactly 0 comes out as a tiny positive number and a segment (r = 0) through the box would be missed —
    // far from touching, since the segment may cross the box's middle. The interval test has no such
    // cancellation: its rounding only moves the box faces by a few ulps of the inputs.
    if (axis_segment_meets_box(box, cyl)) return true;

    // The QP minimises ½·dist² to the axis LINE over box ∩ slab; inside the slab the nearest axis
    // point lies on the axis segment, so min dist² ≤ r² ⇔ the solids meet. f ≥ 0 is bounded below
    // on a non-empty polyhedron, so a minimiser and KKT multipliers exist: the LCP is solvable, and
    // its matrix is positive semidefinite, hence copositive-plus, so Lemke's method finds a solution
    // in exact arithmetic. A is only semidefinite (zero along w): the minimiser need not be unique,
    // but its value is, and that is all we use. r = 0 needs no special case.
    //
    // Two exact reformulations, not in the published method, remove constraint pairs that are exactly
    // opposite. Such a pair ties in every ratio test where it is active: harmless in exact arithmetic (the
    // lexicographic rule), but in floating point rounding breaks the tie at random and most of those
    // solves ended on a spurious ray (on the randomized tests, double: 3.9% of the queries before,
    // 1 in 20,000 after; float: 7% before, 2.4% after, the rest mostly boxes thin relative to float).
    //  - Zero extent ℓᵢ = 0: xᵢ ≥ 0 and xᵢ ≤ 0. The coordinate is fixed, xᵢ = 0, and dropped from the
    //    QP with its box row — the same problem, smaller.
    //  - h = 0: the slab rows w·(x − k) ≥ 0 and ≤ 0. The plane equation is solved for one coordinate
    //    (plane_qp); what remains is a strictly convex QP in the others.
    std::array<std::size_t, 3> free{};
    std::size_t count = 0;
    for (std::size_t i = 0; i < 3; ++i)
        if (!(box.extents[i] == T(0))) free[count++] = i;
    switch (count) {
        case 3: return detail::solve_over<3>(box, cyl, free);
        case 2: return detail::solve_over<2>(box, cyl, std::array<std::size_t, 2>{free[0], free[1]});
        case 1: return detail::solve_over<1>(box, cyl, std::array<std::size_t, 1>{free[0]});
        default: return detail::solve_over<0>(box, cyl, std::array<std::size_t, 0>{});
    }
}

}  // namespace boxcyl::algo
