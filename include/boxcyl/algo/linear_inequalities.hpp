// The linear-inequalities method (docs/algorithms.md): the test-intersection query of a canonical box
// and a finite cylinder. "Listing N" and "eq. (N)" below are the numbered pseudocode listings and
// equations of the published note (Eberly, "Intersection of a Box and a Finite Cylinder"); this is
// Listing 7 and the functions it calls. Generic over T: exact for exact T (the
// direction must then be exactly unit length, e.g. QFRational from to_unit(Cylinder<Rational>, field)),
// rounded for float/double.
//
// What differs from the published pseudocode, and why (each derived again; the exact oracle
// judges):
//  * Division-free decisions. The axis early exits (one and no zero components) compare the bounds of
//    eq. (21)/(32) pairwise after multiplying by the positive direction components, and the
//    extreme-edge distances are compared as cross-multiplied squares. No orthonormal basis is built
//    (Listing 6's ComputeOrthonormalBasis normalises with a sqrt): with unit D the vector
//    q = D × (P − C) has the length and the inner products of the projection of P − C onto the plane
//    ⊥ D.
//  * The only divisions left are by a positive direction component, to locate the point where a box
//    edge crosses a slab plane. For subnormal or tiny components the note's quotients overflow to ±inf
//    (Listing 4's sMin/sMax, Listing 6's endpoints such as E1 − s3p/D1) and the endpoints then feed
//    inf − inf and 0·inf (= NaN) into the distance, or a point far outside the box; the note's claim
//    that overflow is harmless holds only for the max/min comparisons of Listings 3 and 5. Here every
//    such coordinate is clamped to its box edge: in exact arithmetic the clamp never acts (the
//    crossing lies on the edge whenever the candidate is non-empty); in floating point it keeps every
//    candidate point on the box, finite, and within rounding of the slab plane.
//  * Errors of the note fixed (see the comments at each place; docs/algorithms.md lists them with
//    their confirmation): Listing 4 sMin for tHat > h/2 uses e1 + c1 (must be e0 + c0, eq. 26 is
//    right); Listing 6 ComputeSqrDistance has the wrong sign of the closest-point parameter; Listing 6
//    blocks (U2, −D) and (D, −U2) divide by D[2] in lower/upper (must be D[1], eq. 65/68 are right);
//    Listing 6 block (U1, −D) has −E[1] in one P1 (must be +E[1], eq. 60 is right) and a misplaced
//    brace; eq. (57) X(μ) divides by d1 (must be d2).
#pragma once

#include <array>    // index permutations, vertex projections
#include <cstddef>  // std::size_t

#include "boxcyl/algo/slab_cull.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl::algo {

namespace detail::li {

// Never std::abs/std::max on T (T may be an exact number type); for enclosure types (the certified
// filter) these decide no sign (number/traits.hpp).
template <class T>
T abs_of(const T& x) {
    return abs_value(x);
}

// x clamped to [−e, e] (e ≥ 0).
template <class T>
T clamp_sym(const T& x, const T& e) {
    return clamp_symmetric(x, e);
}

// Axis early exit, eq. (21) (one zero component) / eq. (32) (none): does the axis segment C + tD,
// |t| ≤ H, stay inside the slabs |x_a| ≤ e_a for every a in idx (all with d_a > 0) for some common t?
// The condition
//     max_a{(−e_a − c_a)/d_a, −H} ≤ min_b{(e_b − c_b)/d_b, H}
// holds iff every term of the max is ≤ every term of the min. Multiplying each pairwise comparison by
// the positive d's makes it division-free (no overflow to ±inf for subnormal d, exact for exact T).
// The pairs (a, a) and (−H, H) hold trivially because e_a ≥ 0 and H ≥ 0.
template <class T, std::size_t N>
bool axis_meets_slabs(const std::array<int, N>& idx, const Vec3<T>& C, const Vec3<T>& D, const T& H,
                      const Vec3<T>& E) {
    for (int a : idx) {
        const T lo = -E[a] - C[a];  // d_a·t ≥ lo
        const T hi = E[a] - C[a];   // d_a·t ≤ hi
        const T dH = D[a] * H;
        if (dH < lo || hi < -dH) return false;  // lo/d_a ≤ H and −H ≤ hi/d_a
        for (int b : idx) {
            if (b == a) continue;
            const T hi_b = E[b] - C[b];
            if (D[a] * hi_b < D[b] * lo) return false;  // lo/d_a ≤ hi_b/d_b
        }
    }
    return true;
}

// No zero component, one candidate: is the distance from the axis line {C + τD} to the segment
// [P0, P1] at most r (r2 = r²)?
// With unit D, q = D × (P − C) is the projection of P − C onto the plane ⊥ D turned by 90° about D,
// so |q|² is the squared distance of P to the axis line and q·q' are the projected inner products.
// w = q1 − q0 = D × (P1 − P0). Nearest point of the projected segment to the origin:
//   q1·w ≤ 0 → q1;  q0·w ≥ 0 → q0;  otherwise interior, dist² = |q0 × w|²/|w|², and
//   q0 × w = (D·((P0 − C) × (P1 − P0)))·D (identity (a×b)×(a×c) = (a·(b×c))a), so
//   dist² ≤ r² ⇔ (D·((P0 − C) × (P1 − P0)))² ≤ r²|w|² — no division.
// (The note's Listing 6 ComputeSqrDistance computes closest = Q0 + s·direction with s = +Q0·dir/|dir|²;
// the minimiser of |Q0 + s·dir| is s = −Q0·dir/|dir|²: sign error, fixed here by not dividing.)
// A degenerate segment (P0 == P1, w == 0) takes the first branch.
template <class T>
bool segment_within(const Vec3<T>& P0, const Vec3<T>& P1, const Vec3<T>& C, const Vec3<T>& D, const T& r2) {
    const Vec3<T> y0 = P0 - C;
    const Vec3<T> y1 = P1 - C;
    const Vec3<T> delta = P1 - P0;
    const Vec3<T> q0 = cross(D, y0);
    const Vec3<T> q1 = cross(D, y1);
    const Vec3<T> w = cross(D, delta);
    if (!(T(0) < dot(q1, w))) return dot(q1, q1) <= r2;
    if (!(dot(q0, w) < T(0))) return dot(q0, q0) <= r2;
    const T n = dot(D, cross(y0, delta));
    return n * n <= r2 * dot(w, w);
}

// The no-zero-component case's data for D in the open first octant: vertex projections
// t_v = D·(V_v − C) with the vertex numbering of eq. (1)–(2) (v = b2b1b0, x_i = +e_i when bit i is
// set), and the two kinds of candidate extreme edges. Both return whether the candidate is within
// distance r of the axis.
template <class T>
class ExtremeEdges {
public:
    ExtremeEdges(const Vec3<T>& C, const Vec3<T>& D, const T& r, const T& H, const Vec3<T>& E)
        : C_(C), D_(D), E_(E), H_(H), r2_(r * r) {
        // As in Listing 6: t_v = ±d0e0 ± d1e1 ± d2e2 − D·C.
        const T dc = dot(D, C);
        const std::array<T, 3> de{D[0] * E[0], D[1] * E[1], D[2] * E[2]};
        for (int v = 0; v < 8; ++v) {
            T t = -dc;
            for (int i = 0; i < 3; ++i) t = (v >> i & 1) ? T(t + de[i]) : T(t - de[i]);
            t_[v] = t;
        }
    }

    // Pair (U_i, −U_j): the box edge x_i = +e_i, x_j = −e_j running along axis k from vertex a
    // (x_k = −e_k) to b = a + 2e_k·U_k, clipped to the slab |t| ≤ H (eq. 34–51). t grows by d_k per
    // unit of x_k, so it is non-empty iff t_a ≤ H and t_b ≥ −H; below −H the lower end moves to
    // x_k = −e_k + (−H − t_a)/d_k (the note: −e_k − s_a⁺/d_k), above H the upper end to
    // x_k = e_k − (t_b − H)/d_k (the note: e_k − s_b⁻/d_k).
    bool box_edge(int i, [[maybe_unused]] int j, int k) const {
        const int a = 1 << i;  // x_i = +e_i; bits j and k clear: x_j = −e_j, x_k = −e_k
        const int b = a | (1 << k);
        if (H_ < t_[a] || t_[b] < -H_) return false;
        Vec3<T> p0 = vertex(a), p1 = vertex(b);
        if (t_[a] < -H_) p0[k] = clamp_sym(T(-E_[k] + T(-H_ - t_[a]) / D_[k]), E_[k]);
        if (H_ < t_[b]) p1[k] = clamp_sym(T(E_[k] - T(t_[b] - H_) / D_[k]), E_[k]);
        return segment_within(p0, p1, C_, D_, r2_);
    }

    // Pairs (U_i, −D) and (D, −U_i): the face x_i = +e_i cut by the lower slab plane t = −H, or the
    // face x_i = −e_i cut by the upper slab plane t = +H (eq. 52–69). On the face, t is smallest at
    // vertex m and largest at M = m + 2e_j·U_j + 2e_k·U_k, so the cut is non-empty iff t_m ≤ τ ≤ t_M.
    // Its two ends lie on the two monotone vertex paths m → m+U_j → M and m → m+U_k → M.
    bool face_cut(int i, bool plus_face) const {
        const int m = plus_face ? (1 << i) : 0;
        const int M = plus_face ? 7 : (7 & ~(1 << i));
        const T tau = plus_face ? T(-H_) : H_;
        if (tau < t_[m] || t_[M] < tau) return false;
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        return segment_within(cut_point(m, j, k, tau), cut_point(m, k, j, tau), C_, D_, r2_);
    }

private:
    Vec3<T> vertex(int v) const {
        Vec3<T> p;
        for (int n = 0; n < 3; ++n) p[n] = (v >> n & 1) ? E_[n] : T(-E_[n]);
        return p;
    }

    // Where t = τ crosses the path m → mid = m + 2e_j·U_j → mid + 2e_k·U_k (t_m ≤ τ ≤ t_M given).
    // First edge (x_j from −e_j): x_j = −e_j + (τ − t_m)/d_j; second (x_k from −e_k):
    // x_k = −e_k + (τ − t_mid)/d_k. (The note's eq. 54: e.g. (e0, e1 − s3⁺/d1, −e2) for s3⁺ ≥ 0 is
    // the first form measured from the other end of the edge; the same point.)
    Vec3<T> cut_point(int m, int j, int k, const T& tau) const {
        const int mid = m | (1 << j);
        if (!(t_[mid] < tau)) {
            Vec3<T> p = vertex(m);
            p[j] = clamp_sym(T(-E_[j] + T(tau - t_[m]) / D_[j]), E_[j]);
            return p;
        }
        Vec3<T> p = vertex(mid);
        p[k] = clamp_sym(T(-E_[k] + T(tau - t_[mid]) / D_[k]), E_[k]);
        return p;
    }

    const Vec3<T>& C_;
    const Vec3<T>& D_;
    const Vec3<T>& E_;
    const T& H_;
    T r2_;
    std::array<T, 8> t_;
};

// ---- The three direction classes (after the reflections of the top level every d_i ≥ 0). ----

// Two zero components (Listing 2): d_{i0} > 0 (= 1), d_{i1} = d_{i2} = 0. With the slab cull done the
// box meets the slab, and the polyhedron projects along D onto the whole rectangle |x_{i1}| ≤ e_{i1},
// |x_{i2}| ≤ e_{i2}; the axis projects to the point (c_{i1}, c_{i2}).
template <class T>
bool two_zero_components(const std::array<int, 3>& i, const Vec3<T>& C, const T& r, const Vec3<T>& E) {
    const T abs_c1 = abs_of(C[i[1]]), abs_c2 = abs_of(C[i[2]]);
    const T& e1 = E[i[1]];
    const T& e2 = E[i[2]];
    // Axis early exit, eq. (17): the axis meets the box.
    if (abs_c1 <= e1 && abs_c2 <= e2) return true;
    // Squared distance from the point to the rectangle.
    T sqr_distance(0);
    if (e1 < abs_c1) {
        const T delta = abs_c1 - e1;
        sqr_distance += delta * delta;
    }
    if (e2 < abs_c2) {
        const T delta = abs_c2 - e2;
        sqr_distance += delta * delta;
    }
    return sqr_distance <= r * r;
}

// One zero component (Listing 3): the axis early exit when d_{i0}, d_{i1} > 0 and d_{i2} = 0.
template <class T>
bool axis_meets_box_one_zero(const std::array<int, 3>& i, const Vec3<T>& C, const Vec3<T>& D, const T& H,
                             const Vec3<T>& E) {
    if (E[i[2]] < abs_of(C[i[2]])) return false;
    return axis_meets_slabs(std::array<int, 2>{i[0], i[1]}, C, D, H, E);
}

// One zero component (Listing 4): d_{i0}, d_{i1} > 0, d_{i2} = 0. Write 0, 1, 2 for i0, i1, i2. In the plane of
// x0, x1 use t = d0·y0 + d1·y1 and s = d1·y0 − d0·y1 (y = x − c; a rotation since d0² + d1² = 1). The
// projection of the polyhedron is [s_min, s_max] × [−e2, e2]; the axis projects to (0, c2).
//   s_min: s is least over the rectangle at the vertex V = (−e0, +e1), t̂ = t(V) (eq. 26). If t̂ is in
//     [−H, H] then s_min = s(V). If t̂ < −H the minimum over the slab is where t = −H crosses the edge
//     x1 = e1 (t grows with x0 there); if t̂ > H, where t = H crosses the edge x0 = −e0 (t falls as
//     x1 falls). The crossings exist because the slab cull passed.
//   s_max: likewise at W = (+e0, −e1), t̄ = t(W) (eq. 27), edges x0 = +e0 (t < −H) and x1 = −e1 (t > H).
// The crossing coordinate is clamped to its edge (no-op in exact arithmetic; in floating point it
// stops (t − H)/d from overflowing for tiny d and keeps the point on the box).
// The note's Listing 4 for t̂ > h/2 has sMin = −(e1pc1 + d0·hDiv2)/d1; eq. (26) and the derivation
// s = d1(−e0 − c0) − d0(x1 − c1) with d1(x1 − c1) = H − d0(−e0 − c0) give −(e0 + c0 + d0·H)/d1.
template <class T>
bool one_zero_component(const std::array<int, 3>& i, const Vec3<T>& C, const Vec3<T>& D, const T& r, const T& H,
                        const Vec3<T>& E) {
    if (axis_meets_box_one_zero(i, C, D, H, E)) return true;  // axis early exit

    const T& c0 = C[i[0]];
    const T& c1 = C[i[1]];
    const T& d0 = D[i[0]];
    const T& d1 = D[i[1]];
    const T& e0 = E[i[0]];
    const T& e1 = E[i[1]];
    const T& e2 = E[i[2]];
    const T me0 = -e0, me1 = -e1, mH = -H;
    auto t_at = [&](const T& x0, const T& x1) -> T { return d0 * (x0 - c0) + d1 * (x1 - c1); };
    auto s_at = [&](const T& x0, const T& x1) -> T { return d1 * (x0 - c0) - d0 * (x1 - c1); };

    T s_min;
    const T t_hat = t_at(me0, e1);
    if (t_hat < mH) {
        s_min = s_at(clamp_sym(T(me0 + T(mH - t_hat) / d0), e0), e1);
    } else if (H < t_hat) {
        s_min = s_at(me0, clamp_sym(T(e1 - T(t_hat - H) / d1), e1));
    } else {
        s_min = s_at(me0, e1);
    }

    T s_max;
    const T t_bar = t_at(e0, me1);
    if (t_bar < mH) {
        s_max = s_at(e0, clamp_sym(T(me1 + T(mH - t_bar) / d1), e1));
    } else if (H < t_bar) {
        s_max = s_at(clamp_sym(T(e0 - T(t_bar - H) / d0), e0), me1);
    } else {
        s_max = s_at(e0, me1);
    }

    // Squared distance from (0, c2) to the rectangle.
    T sqr_distance(0);
    if (T(0) < s_min) {
        sqr_distance += s_min * s_min;
    } else if (s_max < T(0)) {
        sqr_distance += s_max * s_max;
    }
    const T abs_c2 = abs_of(C[i[2]]);
    if (e2 < abs_c2) {
        const T delta = abs_c2 - e2;
        sqr_distance += delta * delta;
    }
    return sqr_distance <= r * r;
}

// No zero component (Listing 5): the axis early exit when every d_i > 0.
template <class T>
bool axis_meets_box_no_zero(const Vec3<T>& C, const Vec3<T>& D, const T& H, const Vec3<T>& E) {
    return axis_meets_slabs(std::array<int, 3>{0, 1, 2}, C, D, H, E);
}

// No zero component (Listing 6): every d_i > 0. After the axis early exit, the projection of the
// polyhedron (box ∩ slab) is bounded by projected edges between a face whose outer normal N has D·N > 0 and one
// with D·N < 0: the 6 box edges (U_i, −U_j) clipped to the slab and the 6 cuts (U_i, −D),
// (D, −U_i) of a face by a slab plane. Every candidate lies in the polyhedron, so the polygon is within
// r of the axis iff one of them is. The order is the note's.
//
// A disk (H == 0) needs only the six face cuts. The slab is then the plane t = 0 and, as every
// d_k > 0, it meets each box edge (U_i, −U_j) — parallel to U_k — in at most one point: box_edge()
// returns that point as a segment of length zero (both ends equal, or vertex a when t_a = 0, or
// a = b for a flat box). The point lies on the face x_i = +e_i and in the plane t = −H = 0, so it is a
// point of face_cut(i, true), which is the whole face ∩ plane. The distance to a segment is at most
// the distance to any of its points, so box_edge(i, j, k) ⇒ face_cut(i, true) in exact arithmetic and
// the answer is unchanged. For interval T this matters: on the zero-length clipped edge
// w = D × (P1 − P0) is exactly 0 but its enclosure straddles 0, so segment_within cannot decide its
// branch and the certified filter (filtered.hpp) would fall back to exact arithmetic.
template <class T>
bool no_zero_components(const Vec3<T>& C, const Vec3<T>& D, const T& r, const T& H, const Vec3<T>& E) {
    if (axis_meets_box_no_zero(C, D, H, E)) return true;  // axis early exit

    const ExtremeEdges<T> x(C, D, r, H, E);
    if (H == T(0)) {  // a disk: the face cuts contain every clipped box edge (see above)
        return x.face_cut(0, true) || x.face_cut(0, false) || x.face_cut(1, true) || x.face_cut(1, false) ||
               x.face_cut(2, true) || x.face_cut(2, false);
    }
    return x.box_edge(0, 1, 2)       // (U0, −U1): V1–V5
           || x.box_edge(1, 0, 2)    // (U1, −U0): V2–V6
           || x.box_edge(0, 2, 1)    // (U0, −U2): V1–V3
           || x.box_edge(2, 0, 1)    // (U2, −U0): V4–V6
           || x.box_edge(1, 2, 0)    // (U1, −U2): V2–V3
           || x.box_edge(2, 1, 0)    // (U2, −U1): V4–V5
           || x.face_cut(0, true)    // (U0, −D)
           || x.face_cut(0, false)   // (D, −U0)
           || x.face_cut(1, true)    // (U1, −D)
           || x.face_cut(1, false)   // (D, −U1)
           || x.face_cut(2, true)    // (U2, −D)
           || x.face_cut(2, false);  // (D, −U2)
}

}  // namespace detail::li

// The linear-inequalities method's top level (Listing 7): true iff the closed box |x_i| ≤ e_i meets
// the closed cylinder. Preconditions:
// |direction| == 1 (exactly for exact T, rounded for float/double); extents, radius and
// half_height ≥ 0 (zeros are the flat box, segment and disk they denote).
template <class T>
bool linear_inequalities(const CanonicalBox<T>& box, const UnitCylinder<T>& cyl) {
    // Slab cull: a box outside the slab cannot meet the cylinder; the direction classes assume it ran.
    if (box_outside_slab(box, cyl)) return false;

    // Reflect into the first octant; the box is symmetric in every coordinate plane.
    Vec3<T> C = cyl.center;
    Vec3<T> D = cyl.direction;
    for (int n = 0; n < 3; ++n) {
        if (D[n] < T(0)) {
            C[n] = T(-C[n]);
            D[n] = T(-D[n]);
        }
    }
    const T& r = cyl.radius;
    const T& H = cyl.half_height;
    const Vec3<T>& E = box.extents;

    const bool p0 = T(0) < D[0], p1 = T(0) < D[1], p2 = T(0) < D[2];
    if (p0) {
        if (p1) {
            if (p2) return detail::li::no_zero_components(C, D, r, H, E);  // (+,+,+)
            return detail::li::one_zero_component({0, 1, 2}, C, D, r, H, E);  // (+,+,0)
        }
        if (p2) return detail::li::one_zero_component({2, 0, 1}, C, D, r, H, E);  // (+,0,+)
        return detail::li::two_zero_components({0, 1, 2}, C, r, E);              // (+,0,0)
    }
    if (p1) {
        if (p2) return detail::li::one_zero_component({1, 2, 0}, C, D, r, H, E);  // (0,+,+)
        return detail::li::two_zero_components({1, 2, 0}, C, r, E);              // (0,+,0)
    }
    if (p2) return detail::li::two_zero_components({2, 0, 1}, C, r, E);  // (0,0,+)
    return false;  // (0,0,0): violates |direction| == 1
}

}  // namespace boxcyl::algo
